/* engine.h: multibody impact engine (rigid bodies in reduced coordinates, articulated-body
 * algorithm, ellipsoid contact, uniform-pressure airbag, sensors). MuJoCo-style split: a constant
 * compiled model urModel and per-run data urData; any number of urData per model may run in
 * parallel threads (no globals, no locks, no allocation inside ur_step).
 *
 * Conventions: SI units; world frame z up, gravity along -z by default. Rotation matrices are
 * row-major, local -> world. Quaternions are (w, x, y, z), unit, local -> world. Spatial vectors
 * are (angular, linear). Every body has exactly one joint to its parent (or to the world);
 * body frame origin = joint anchor. Joint id = body id. Bodies are added parents first, so the
 * body order is a topological order of the forest; each tree's root joins the world.
 *
 * Use:
 *   urModel* m = ur_model_new();
 *   int b = ur_model_add_body(m, "head", neck, urJNT_SPHERICAL, pos_in_neck, NULL);
 *   ur_model_set_inertia(m, b, 4.5, com, I6);         // also set_joint, set_restraint
 *   int g = ur_model_add_ellipsoid(m, "skull", b, centre, NULL, semiaxes);
 *   ur_model_add_pair(m, "frame_skull", g, frame, &law); // law from contact.h
 *   ur_model_add_sensor(m, "neck", urSENS_JOINTLOAD, b, 0, NULL, NULL);
 *   ur_model_compile(m);                               // m is constant from here on
 *   urData* d = ur_data_new(m);
 *   for (...) ur_step(m, d);                           // e.g. settle the standing person
 *   urData* run = ur_data_new(m);  ur_data_history(m, run, NULL, rows);
 *   ur_data_copy(m, run, d);                           // start each run from the settled state
 *   ur_run_impact(m, run, drone, pos, quat, vel);      // jump, step until the end, status > 0
 *   run->peakmax[m->sensor[s].adr + k], run->hist[row * (1 + m->nsensordata) + 1 + adr + k]
 */
#ifndef UASIMPACT_ENGINE_H
#define UASIMPACT_ENGINE_H

#include <stddef.h>
#include "uasimpact/contact.h"
#include "uasimpact/membrane.h"

#ifdef __cplusplus
extern "C" {
#endif

#define urNAMELEN   32   /* bytes in a name, including the terminating 0 */
#define urMAXBAGTGT 32   /* target ellipsoids per airbag */
#define urMSGLEN    160  /* bytes in error / status messages */
#define urNOTELEN   1024 /* bytes of a model's notes */
#define urWHYLEN    160  /* bytes in the reason of a parameter's range */

//---------------------------------- enums ---------------------------------------------------------

typedef enum {
  urJNT_FREE = 0,  /* 6 dof: qpos = CoM position in parent (3) + quat (4);
                                      qvel = CoM velocity in parent frame (3) + omega in body (3) */
  urJNT_FIXED,     /* 0 dof */
  urJNT_REVOLUTE,  /* 1 dof: angle about axis[0] (body frame), rad */
  urJNT_UNIVERSAL, /* 2 dof: R = Rot(axis[0], q0) Rot(axis[1], q1) (Cardan) */
  urJNT_SPHERICAL, /* 3 dof: qpos = quat (4), qvel = relative omega in body (3) */
  urJNT_PRISMATIC  /* 1 dof: translation along axis[0] (body frame), m */
} urJointType;

typedef enum {
  urINT_EULER = 0, /* semi-implicit (symplectic) Euler: v += dt a; q += dt v */
  urINT_RK4        /* classical Runge-Kutta 4 (accuracy cross-check) */
} urIntegrator;

typedef enum {
  urSENS_ACCEL = 0, /* 3: kinematic acceleration of a body point (gravity not
                                      included: 0 at rest), world frame, m/s^2 */
  urSENS_JOINTLOAD, /* 6: force (3) and moment (3) that the parent exerts on the
                                      child through the joint, at the joint anchor, in the child
                                      frame rotated by quat, N, N m (all loads: restraint, contact
                                      transmitted, inertial); a head resting on its neck reads
                                      Fz = +m g, i.e. SAE J211 tension-positive Fz is -Fz here */
  urSENS_JOINTPOS,  /* 1: joint coordinate qpos[qadr + dof] (rad or m) */
  urSENS_JOINTVEL,  /* 1: joint velocity dof (rad/s or m/s) */
  urSENS_CONTACT,   /* 3: normal force N, penetration m, friction force N */
  urSENS_AIRBAG,    /* 4: absolute pressure Pa, gas volume m^3, normal force on
                                      the targets N, largest yarn strain (Green, warp or weft) (Green;
                                      membrane bags, else 0) */
  urSENS_BODYPOS,   /* 3: world position of a body point, m */
  urSENS_BODYVEL,   /* 3: world velocity of a body point, m/s */
  urSENS_HINGE      /* 2: an elastic-plastic hinge on joint dof: its plastic deflection (rad
                                      or m) and the time it broke (s; 0 intact) */
} urSensorType;

typedef enum {
  urSTAT_OK = 0,         /* running (or not started) */
  urSTAT_SEPARATED = 1,  /* ended: contact over for opt.t_quiet */
  urSTAT_SETTLED = 2,    /* ended: kinetic energy below opt.ke_settle for opt.t_quiet */
  urSTAT_TMAX = 3,       /* ended: opt.tmax reached */
  urSTAT_NONFINITE = -1, /* failed: NaN or Inf in the state */
  urSTAT_EXPLODE = -2,   /* failed: a velocity beyond opt.vmax */
  urSTAT_BADARG = -3,    /* failed: bad call (message says which) */
  urSTAT_STOPPED = -4    /* failed: stopped on request (opt.stop, e.g. Ctrl-C) */
} urStatus;

typedef enum {
  urBAG_UNIFORM = 0, /* analytic uniform-pressure bag (contact sheet 4.2) */
  urBAG_MEMBRANE     /* finite-element fabric membrane with uniform-pressure gas
                                      (membrane.h); its ellipsoid is compiled into a bound of
                                      the inflated bag */
} urAirbagType;

//---------------------------------- model elements ------------------------------------------------

/* one restraint acting on one joint dof: M = k x + load(x) [+ hysteresis] + c xdot + stops
   (k x saturating as sat tanh(k x / sat) when sat > 0),
   x = q - x0. Revolute, prismatic, universal: x is the joint coordinate (per Cardan axis).
   Spherical: x is the k-th component of the rotation vector of the relative rotation (body
   frame); the elastic moments are mapped to body torques exactly (inverse right Jacobian), so
   the linear part is conservative; damping acts on the relative angular velocity, stop damping
   is not applied. Free joints take no restraint. */
typedef struct {
  int active;          /* 0: no restraint on this dof */
  double k;            /* linear stiffness, N m/rad or N/m */
  double sat;          /* > 0: k x saturates at this force, as sat tanh(k x / sat) */
  urCurve load;        /* loading curve (x -> generalised force); if all x >= 0 it is
                                      extended odd-symmetrically to x < 0 */
  urCurve unload;      /* optional unloading curve: scaled through (xmax, load(xmax)) */
  double c;            /* viscous damping, N m s/rad or N s/m */
  double lo, hi;       /* end stops (lo < hi; lo == hi: none), rad or m */
  double kstop, cstop; /* stop stiffness and damping beyond lo/hi */
  double x0;           /* neutral position (deflection = q - x0) */
  double mp;           /* > 0: elastic-plastic hinge in place of k, sat and the curves: the
                                      moment k (x - xp) yields at mp (plastic moment, N m) and
                                      hardens kinematically with slope kh; xp, the plastic
                                      deflection, is kept per run (uasimpact-model(5), hinge) */
  double kh;           /* hardening slope beyond mp, N m/rad (< k) */
  double mfrac;        /* > 0 (with mp): the hinge breaks when |M| reaches mfrac (N m): at
                                      the next step its joint releases and the body flies
                                      on free (fracture; ur_data_model) */
} urRestraint;

typedef struct {
  char name[urNAMELEN];  /* body name */
  char jname[urNAMELEN]; /* joint name (defaults to the body name) */
  int parent;            /* parent body, -1 = world */
  int tree;              /* root body of this body's tree */
  int react;             /* 1: its net force reaches a joint-load sensor (the sensed
                                      body or one below it): ur_reactions computes it (compiled) */
  double pos[3];         /* body frame origin (= joint anchor) in the parent frame, m */
  double quat[4];        /* body frame orientation in the parent frame at q = 0 */
  double mass;           /* kg */
  double com[3];         /* centre of mass in the body frame, m */
  double inertia[9];     /* inertia about the CoM in body axes, kg m^2 (3x3) */
  double gravity;        /* 1: gravity acts, 0: compensated (e.g. parachute-borne) */
  urJointType jtype;     /* joint to the parent */
  double axis[2][3];     /* joint axes in the body frame (unit) */
  int qadr, nq;          /* first index and count in qpos */
  int vadr, nv;          /* first index and count in qvel */
  urRestraint rst[3];    /* restraint per rotational/translational dof (not free) */
  // compiled
  double sinert[36]; /* spatial inertia at the body origin, body frame (6x6) */
  double iinv[9];    /* inverse of the inertia about the CoM (3x3) */
  double bmat[9];    /* rotation matrix of quat */
  int fqadr, fvadr;  /* a joint that can break (a hinge with fracture): its free joint's block
                        in qpos (7) and qvel (6), used once it breaks; -1: none */
} urBody;

typedef struct {
  char name[urNAMELEN];
  int body;       /* body it is attached to */
  double pos[3];  /* centre in the body frame, m */
  double quat[4]; /* orientation in the body frame */
  double size[3]; /* semi-axes, m */
  double degree;  /* 2: ellipsoid; > 2: superellipsoid (contact.h urEllipsoid.p) */
  double rbound;  /* bounding-sphere radius (max semi-axis for an ellipsoid), m */
  double gmat[9]; /* rotation matrix of quat (compiled) */
} urGeom;

typedef struct {
  char name[urNAMELEN];
  int geom1; /* ellipsoid A */
  int geom2; /* ellipsoid B, or -1 for the ground plane z = 0 */
  urLaw law; /* force law (contact.h); foam uses the section area of A */
} urPair;

typedef struct {
  char name[urNAMELEN];
  urAirbagType type;
  int geom;         /* bag ellipsoid (attached to the carrying body) */
  urGas gas;        /* gas law (contact.h) */
  double kappa;     /* volume-loss factor: dV = kappa * sum of cap volumes */
  double thickness; /* bag thickness: depth beyond it is ignored (bottoming), m */
  double fabric_k;  /* optional penalty/fabric stiffness on depth, N/m */
  double fabric_c;  /* optional damping on depth rate, N s/m */
  double mu, v_eps; /* friction on the targets (regularised Coulomb) */
  int ntarget;
  int target[urMAXBAGTGT]; /* ellipsoids that can indent the bag */
  double tk[urMAXBAGTGT];  /* membrane: a target's soft layer's foundation stiffness E_oed / h,
                              N/m^3 (derived from its layer; 0: none, the bag's kc_alpha) */
  /* membrane (type urBAG_MEMBRANE): the declaration, the carrier's own ellipsoids the fabric
     presses against, and (compiled) the inflated bag and its state's place in urData.mem */
  urMemSpec mspec;
  int nsupport;
  int support[urMAXBAGTGT];
  urMembrane* mem; /* built by ur_model_compile (mesh, not inflated), inflated by
                      ur_model_inflate (or copied from opt.memcache), constant after */
  int inflated;    /* membrane: 1 once mem is the inflated bag (ur_model_inflate) */
  int madr;        /* first double of its run state in urData.mem */
  int nsub;        /* membrane sub-steps per step (its stable step is smaller) */
  int liverule;    /* membrane: when it stops riding rigidly (engine_membrane.c; the model
                      language's live=, default 0): 0 once a target's bounding sphere comes
                      within 0.05 m of its bound's, 1 once that holds and a target comes
                      within a margin of its nodes or edge midpoints or its carrier's tree is
                      jolted (never before rule 0) */
  double nbox[6];  /* membrane, inflated: the box of its inflated nodes in the carrier's frame
                      (lo, hi; set with the bound by ur_model_inflate) */
} urAirbag;

typedef struct {
  char name[urNAMELEN];
  urSensorType type;
  int obj;        /* body, joint (= body), pair or airbag id */
  int dof;        /* joint dof for JOINTPOS / JOINTVEL */
  double pos[3];  /* point in the body frame (ACCEL, BODYPOS, BODYVEL) */
  double quat[4]; /* output frame relative to the child frame (JOINTLOAD) */
  int dim;        /* number of values */
  int adr;        /* first index in sensordata */
} urSensor;

typedef struct {
  char name[urNAMELEN];
  double value;
  char unit[urNAMELEN]; /* SI unit from its param line (N/m, Pa; "": none given) */
  double lo, hi;        /* the values it accepts, SI, both ends included (param ... range=;
                           -inf, inf: any) */
  char why[urWHYLEN];   /* the physical reason of that range (why=; "": none given) */
  int from;             /* the parameter it follows (param NAME $OTHER [UNIT]): OTHER's index,
                           value = from_f * OTHER's; -1: its own value (a number, or set) */
  double from_f;        /* that line's unit factor (1: none or SI) */
} urParam;

/* the roles an impact needs, declared by the model's role statements (uasimpact-model(5)), and
   the drone's design handles; -1: not declared */
typedef struct {
  int drone;                     /* root body of the drone (free joint) */
  int head;                      /* head ellipsoid: its top sets the start height, its centre
                                      is the aim point */
  int head_acc, neck, head_pos;  /* sensors: head CG acceleration, upper-neck load, head CG */
  int chest, abdomen;            /* sensors: thorax and abdomen deflections (optional) */
  int mass_param, size_param;    /* parameters the drone tree is scaled by (role mass=$P,
                                      size=$P) */
  double mass0;                  /* the drone tree's total mass as written, kg (0: no drone) */
  double mass_scale, size_scale; /* the factors applied (1: as written) */
} urRoles;

/* a case preset (preset statement): values for model parameters (SI) and workbench settings */
#define urMAXPRESET 24
typedef struct {
  char name[urNAMELEN];
  int n;
  char key[urMAXPRESET][urNAMELEN];
  double value[urMAXPRESET];
  int param[urMAXPRESET]; /* index of a model parameter, or -1: a workbench setting */
} urPreset;

#define urMAXADAPT 16 /* the longest coarse step, in steps dt (urOption.adapt) */

typedef struct {
  double dt;               /* time step, s (default 1e-5) */
  double gravity[3];       /* m/s^2 (default 0, 0, -9.81) */
  urIntegrator integrator; /* default urINT_EULER */
  int implicit_damping;    /* Euler: linear joint-restraint damping taken at the new
                                      velocity, (M + dt C) qacc = f (as MuJoCo); default 1 */
  double sample_dt;        /* longest history sampling interval, s (default 1e-4: 10 kHz);
                                      rows every floor(sample_dt / dt) steps */
  double tmax;             /* maximum simulated time after the jump, s (default 0.2) */
  double t_quiet;          /* end when contact has been over this long, s (default 0.02) */
  double t_clear;          /* or over this long (<= t_quiet) with the projectile provably
                                      clear of the rest until t_quiet (default: t_quiet, off) */
  double a_clear;          /* relative acceleration bound of that proof, m/s^2 (100) */
  double ke_settle;        /* or kinetic energy below this for t_quiet, J (default 1e-3) */
  double vmax;             /* failure beyond this joint speed, m/s or rad/s (default 1e4) */
  double jump_margin;      /* free-flight jump stops this far from contact, m (1e-3) */
  int adapt;               /* K >= 2: a run steps K dt at once while its projectile is
                                      provably clear of the rest (ur_step); 1: every step dt
                                      (default) */
  const _Atomic int* stop; /* optional (not part of the model text): a step fails with
                                      urSTAT_STOPPED while *stop != 0 (an interrupt flag) */
  urMemCache* memcache;    /* optional (not part of the model text): ur_model_inflate takes
                                      its membrane bags inflated from this cache (membrane.h:
                                      ur_mem_cache_inflate; the same bits), which must outlive
                                      the model's inflation; NULL: each inflated afresh */
} urOption;

typedef struct {
  // sizes
  int nbody, ngeom, npair, nbag, nsensor, nparam;
  int nq, nv;      /* generalised coordinates and velocities */
  int nsensordata; /* sum of sensor dims */
  int compiled;    /* 1 after ur_model_compile succeeded */
  int cap[6];      /* builder capacities (internal) */
  urOption opt;
  // elements
  urBody* body;     /* nbody */
  urGeom* geom;     /* ngeom */
  urPair* pair;     /* npair */
  urAirbag* bag;    /* nbag */
  urSensor* sensor; /* nsensor */
  urParam* param;   /* nparam */
  urRoles roles;    /* role statements */
  urPreset* preset; /* npreset, in the order of the text */
  int npreset;
  double* qpos0; /* nq: reference configuration */
  int nmemd;     /* doubles of the membrane bags' run states (urData.mem) */
  int nraw;      /* membrane bags compiled but not yet inflated: runs refuse until
                    ur_model_inflate */
  int nfrac;     /* joints that can break (urBody.fqadr; 0: a run's topology never changes) */
  int mirror;    /* 1: the model is its own mirror image in the plane y = 0 (ur_model_mirror,
                    set by ur_model_compile); 0: nomirror says why not */
  char nomirror[urMSGLEN];
  // compiled lists of bodies, for the per-step loops: gravity compensated (gravity != 1), with
  // an active restraint, with a load curve (its extremes are tracked), whose reaction is needed
  // (react)
  int *grav, *rstb, *hyst, *reactb;
  int ngrav, nrstb, nhyst, nreactb;
  char err[urMSGLEN];   /* last builder / compile error */
  char note[urNOTELEN]; /* what the model language notes without failing (e.g. a drone's own law
                           overriding the one derived from the materials), lines joined by
                           '\n'; "" none; a host shows it when the model loads */
  char* derived;        /* the values the model language derived from materials and sections (hinges
                    from beam theory, contact laws, layers, shell springs and crush loads), one
                    line each with its formula and inputs, joined by '\n'; NULL: none */
} urModel;

//---------------------------------- data ----------------------------------------------------------

/* what the narrow phase reads or writes for a pair (rate to ls.dmax) shares one cache line (the
   first member's C11 alignment aligns the whole struct to 64 bytes); a pair culled by its
   bounding spheres is not touched (its depth is in urData.pdepth) */
typedef struct {
  _Alignas(64) double rate; /* penetration rate, m/s */
  double fn;                /* normal force, N */
  double ft;                /* friction force magnitude, N */
  double area;              /* section area used (foam), m^2 */
  int active;               /* 1 if a force acts */
  urLawState ls;            /* law history (committed on accepted steps) */
  double u[3];              /* warm-start direction */
  double n[3];              /* normal A -> B, world */
  double p[3];              /* contact point, world, m */
  double radius;            /* Hertz radius from the shapes' curvature at the contact, m
                                      (a law with urHERTZ_CURVATURE; else unused) */
} urPairData;

typedef struct {
  double pressure;           /* absolute pressure, Pa */
  double volume;             /* gas volume, m^3 */
  double dv;                 /* volume loss, m^3 */
  double force;              /* sum of normal forces on the targets, N */
  double depth[urMAXBAGTGT]; /* depth of each target, m (< 0 separated) */
  double rate[urMAXBAGTGT];  /* depth rate of each target, m/s */
  double ftgt[urMAXBAGTGT];  /* normal force on each target, N */
  double u[urMAXBAGTGT][3];  /* warm-start directions */
  int active;                /* 1 if some target indents the bag */
  double strain;             /* membrane: largest yarn strain (Green, warp or weft) (Green) */
  int placed;                /* membrane: state initialised (0 after a reset); its nodes are
                                placed on the carrier again when it goes live */
  int live;                  /* membrane: integrated (a target came near, or its carrier
                                      was jolted: urAirbag.liverule), else carried rigidly
                                      in its inflated state */
} urBagData;

typedef struct {
  // state
  double time;  /* simulated time, s */
  double* qpos; /* nq */
  double* qvel; /* nv */
  double* qacc; /* nv: accelerations from the last ur_forward */
  double* qfrc; /* nv: passive generalised forces (restraints) */
  double* rst;  /* nv x 2: restraint hysteresis (max +, max - deflection) */
  double* rkin; /* nbody x 12: spherical restraints' deflection (rotation
                                      vector minus x0) and its inverse right Jacobian (3x3) */
  // kinematics (per body)
  double* xpos;  /* nbody x 3: body origin, world */
  double* xmat;  /* nbody x 9: body orientation, world */
  double* xcom;  /* nbody x 3: centre of mass, world */
  double* gxpos; /* ngeom x 3: ellipsoid centre, world */
  double* gxmat; /* ngeom x 9: ellipsoid orientation, world (where gmat_ok) */
  // dynamics scratch (per body, body coordinates)
  double* Xe;     /* nbody x 9: rotation parent -> child */
  double* Xr;     /* nbody x 3: child origin in the parent frame */
  double* S;      /* nbody x 36: motion subspace (the first 6 x nv) */
  double* cvel;   /* nbody x 6: spatial velocity */
  double* cbias;  /* nbody x 6: velocity-product acceleration */
  double* cacc;   /* nbody x 6: spatial acceleration (incl. -gravity) */
  double* IA;     /* nbody x 36: ABA scratch (articulated inertia, then the
                                      part passed on to the parent) */
  double* pA;     /* nbody x 6: ABA scratch (articulated bias force, then the
                                      part passed on) */
  double* U;      /* nbody x 36 */
  double* Dinv;   /* nbody x 36 */
  double* uu;     /* nbody x 6 */
  double* fext;   /* nbody x 6: external force at the origin, body coords */
  double* freact; /* nbody x 6: joint reaction on the child, body coords (only
                                      at joint-load sensors and below them) */
  // contacts and airbags
  urPairData* pair;       /* npair */
  double* pdepth;         /* npair: penetration, m (< 0 separated: minus a lower bound
                                      of the distance; -inf before any contact pass) */
  urBagData* bag;         /* nbag */
  double* mem;            /* nmemd: membrane bags' states (membrane.h) */
  int* plist;             /* 2 npair: of the last contact pass, the pairs to commit
                                      (penetrating or touching; only they can carry a force or
                                      a touching history), then the active ones (supersets once
                                      pairs are reset) */
  int npcommit, npactive; /* lengths of the two lists */
  unsigned char* gmat_ok; /* ngeom: gxmat is current (steps, alone or in lanes, compute an
                                      ellipsoid's orientation on first use: ur_geom_xmat;
                                      ur_kinematics computes all) */
  // sensors and outputs
  double* sensordata; /* nsensordata: values at the last ur_forward */
  double* peakmax;    /* nsensordata: largest value since the run start */
  double* peakmin;    /* nsensordata: smallest value since the run start */
  double* tpeak;      /* nsensordata: time of the largest |value| */
  double* hist;       /* nhist_cap x (1 + nsensordata) rows (time, values), or NULL */
  int nhist;          /* rows written */
  int nhist_cap;      /* rows available */
  int hist_own;       /* 1 if the engine allocated hist */
  // run control
  int status;         /* urStatus */
  char msg[urMSGLEN]; /* reason for the status */
  long nstep;         /* steps taken since the run start */
  int proj;           /* projectile tree root (ur_run_start), -1 none */
  double t_jump;      /* free-flight time skipped analytically, s */
  double t_first;     /* time of first projectile contact, s (-1 none) */
  double t_last;      /* last time a projectile contact was active, s */
  double t_calm;      /* time since kinetic energy fell below ke_settle, s */
  int clear_hint;     /* the pair or airbag target that last kept the projectile
                                      from being proved clear (tried first) */
  double energy;      /* kinetic energy at the last ur_forward, J */
  // coarse steps (urOption.adapt)
  int coarse;    /* the next step is coarse: adapt dt (decided at the end of the last step) */
  int pend;      /* the last step was coarse: its interior history rows are written at the
                     next accepted state, interpolated towards it (engine_sensor.c) */
  long ncoarse;  /* coarse steps of this run */
  long ntouch;   /* of them, those whose start state had a projectile contact active (the
                     proof that took them failed: none expected) */
  long nprev;    /* nstep at the start of the last coarse step */
  double tprev;  /* time at the start of the last coarse step, s */
  double* sprev; /* nsensordata: sensor values at the start of the last coarse step */
  // topology (models with urModel.nfrac > 0)
  urModel* topo; /* the run's own copy of the model once a joint has broken (the broken
                    bodies fly free: ur_data_model), allocated with the data */
  int nreleased; /* joints released so far (0: the run steps with the model itself) */
  // integrator scratch
  double* scratch; /* 2 nq + 8 nv */
  // memory
  void* buffer; /* one allocation holding the arrays above (64-byte aligned) */
} urData;

//---------------------------------- model builder -------------------------------------------------

/* New empty model with default options; NULL on allocation failure. */
urModel* ur_model_new(void);

/* Free a model (NULL allowed). */
void ur_model_free(urModel* m);

/* Add a body and its joint to parent (-1: world); pos/quat: body frame in the parent frame at
   q = 0 (quat NULL: identity). Parents must be added first. Returns the body id or -1. */
int ur_model_add_body(urModel* m, const char* name, int parent, urJointType type,
                      const double pos[3], const double quat[4]);

/* Mass, centre of mass (body frame) and inertia about the CoM: I = (xx, yy, zz, xy, xz, yz). */
int ur_model_set_inertia(urModel* m, int body, double mass, const double com[3],
                         const double inertia[6]);

/* Joint axes in the body frame (a2 only for universal joints; NULL allowed); optional joint
   name (NULL: keep). */
int ur_model_set_joint(urModel* m, int body, const char* jname, const double a1[3],
                       const double a2[3]);

/* Restraint on joint dof of body (copied). */
int ur_model_set_restraint(urModel* m, int body, int dof, const urRestraint* r);

/* Add an ellipsoid to a body (pos/quat in the body frame, quat NULL: identity). Returns id. */
int ur_model_add_ellipsoid(urModel* m, const char* name, int body, const double pos[3],
                           const double quat[4], const double semiaxes[3]);

/* Make ellipsoid g a superellipsoid of degree p in [2, urMAXDEGREE] (2: the ellipsoid, the
   default); refused for the ellipsoid a of a foam-law pair and for airbag targets (their
   section areas and cap volumes are those of ellipsoids). Returns 0 or -1. */
int ur_model_set_degree(urModel* m, int g, double p);

/* Add a contact pair; geom2 = -1 means the ground plane z = 0. Returns the pair id or -1. */
int ur_model_add_pair(urModel* m, const char* name, int geom1, int geom2, const urLaw* law);

/* Add an airbag (copied; name taken from bag->name). Returns the airbag id or -1. */
int ur_model_add_airbag(urModel* m, const urAirbag* bag);

/* Add a sensor; obj is a body, joint (= body), pair or airbag id depending on type; pos is a point
   in the body frame (NULL: origin); quat is the output frame for JOINTLOAD (NULL: identity).
   Returns the sensor id or -1. */
int ur_model_add_sensor(urModel* m, const char* name, urSensorType type, int obj, int dof,
                        const double pos[3], const double quat[4]);

/* Named parameter (set or overwrite; a new one accepts any value; either holds its own value:
   from -1). */
int ur_model_set_param(urModel* m, const char* name, double value);

/* The range of a named parameter, SI, both ends included, and its reason (NULL: none); the
   value must lie in it. Returns the parameter id, or -1 (absent, compiled, lo > hi, a NaN, the
   value outside, a reason of urWHYLEN bytes or more). */
int ur_model_set_param_range(urModel* m, const char* name, double lo, double hi, const char* why);

/* 1 if v is a value parameter p accepts (within its range, not NaN), else 0. */
int ur_param_accepts(const urParam* p, double v);

/* The total mass of the tree rooted at body root (before or after compiling), kg. */
double ur_model_tree_mass(const urModel* m, int root);

/* Before compiling: scale the tree rooted at root (a design change): masses and inertias by
   fmass, and its size by fsize (joint anchors below the root, centres of mass, ellipsoids,
   sensor points, airbag thicknesses; airbag volumes by fsize^3, inertias by fsize^2). Laws,
   restraints and the root's own placement are kept. 0, or -1 (compiled, bad arguments). */
int ur_model_scale_tree(urModel* m, int root, double fmass, double fsize);

/* Compile: check, assign addresses, reference configuration. 0 on success, else -1 and m->err.
   A membrane airbag's declaration is checked and its mesh built here, but not inflated (seconds
   to a minute of CPU at fine meshes): that is ur_model_inflate's. */
int ur_model_compile(urModel* m);

/* whether a compiled model is its own mirror image in the plane y = 0 (x forward, z up; the
   plane of the course through the head at face 0 or 180, so the impacts at dperp and -dperp
   are mirror images): its bodies, ellipsoids, contact pairs and airbags (a membrane's mesh)
   pair off with mirrored data, the drone's root and the head lie on the plane and the injury
   sensors read what the mirror keeps (engine_mirror.c). 1, or 0 with one line in why (n bytes)
   naming the first part that breaks the symmetry. ur_model_compile keeps it in m->mirror. */
int ur_model_mirror(const urModel* m, char* why, size_t n);

/* Inflate the compiled model's membrane airbags that are not yet (ur_model_inflate_bag: bag i
   alone), through opt.memcache when there is one; idempotent. The model's owner calls it before
   the model is shared with threads (it writes the model: the contract that a compiled model is
   constant holds from here on; no lock, so no once-guard in the runs: a run must never write
   the model it shares). Every run refuses a model with a bag not inflated (urModel.nraw: a step
   fails with urSTAT_BADARG, ur_impact_setup, _prepare and _balance fail), so none can run an
   uninflated bag silently. Polls opt.stop: a stop request leaves the bag uninflated. 0, or -1
   with one line in err ("airbag 'NAME': ..."). */
int ur_model_inflate(urModel* m, char* err, size_t n);
int ur_model_inflate_bag(urModel* m, int i, char* err, size_t n);

/* the refusal of a run on a model with a bag not inflated, naming the first such bag */
void ur_model_raw_text(const urModel* m, char* msg, size_t n);

/* Look-up by name; -1 if absent. */
int ur_name_body(const urModel* m, const char* name);
int ur_name_joint(const urModel* m, const char* name);
int ur_name_geom(const urModel* m, const char* name);
int ur_name_pair(const urModel* m, const char* name);
int ur_name_airbag(const urModel* m, const char* name);
int ur_name_sensor(const urModel* m, const char* name);
int ur_name_param(const urModel* m, const char* name);

/* A membrane bag's penalty on its target t (t < 0: on its supports), as the kc_alpha the contact
   uses at the model's step: a target's layer gives tk dk^2 / rhot (dk = max(dt, kc_dt)), at most
   max(1, kc_alpha) (what the explicit step carries, or the stiff law the bag asks for); else the
   bag's kc_alpha. Its stiffness per area is kc_alpha rhot / dk^2 (N/m^3). */
double ur_bag_penalty(const urModel* m, const urAirbag* b, int t);

/* Value of a named parameter, or dflt if absent. */
double ur_model_param(const urModel* m, const char* name, double dflt);

//---------------------------------- data ----------------------------------------------------------

/* New data for a compiled model, reset to the reference configuration; NULL on failure. */
urData* ur_data_new(const urModel* m);

/* Free data (and an engine-allocated history). */
void ur_data_free(urData* d);

/* Reset state, histories, peaks and status to the reference configuration. */
void ur_data_reset(const urModel* m, urData* d);

/* Copy the whole state and run data of src into dst (same model); the history buffer of dst is
   kept (not copied). */
void ur_data_copy(const urModel* m, urData* dst, const urData* src);

/* Record full time histories: buf (caller-owned, rows x (1 + nsensordata) doubles) or, with
   buf NULL, an engine-allocated buffer of rows rows; rows = 0 turns recording off.
   Returns 0 or -1 on allocation failure. */
int ur_data_history(const urModel* m, urData* d, double* buf, int rows);

//---------------------------------- simulation ----------------------------------------------------

/* Kinematics, forces (restraints, contacts, airbags), accelerations (articulated-body algorithm),
   joint reactions and sensors at the current state. Returns d->status. */
int ur_forward(const urModel* m, urData* d);

/* Kinematics only (body and ellipsoid poses). */
void ur_kinematics(const urModel* m, urData* d);

/* One step of opt.dt: forward, record outputs, commit contact histories, integrate, check the
   state; after ur_run_start also check the end of the run (status > 0, stepping may go on).
   With opt.adapt = K >= 2 (Euler, no membrane bag) a step of a run is K dt long where its
   projectile was provably clear of the rest for it (d->coarse); d->time and d->nstep advance
   as by K steps, and the history keeps a row every sample_dt (engine_sensor.c).
   Returns d->status (< 0: failed run, nothing more is done). No allocation. */
int ur_step(const urModel* m, urData* d);

/* Place the tree rooted at body root (free joint) with its CoM at pos, orientation quat, and
   velocity vel (world, m/s; all its joints at rest), reset peaks/histories/contacts, then jump
   analytically along the straight line to just before the first possible contact (swept bounding
   spheres against every pair and airbag target involving the tree). Other trees are assumed to
   be at rest during the jump. Returns d->status. */
int ur_run_start(const urModel* m, urData* d, int root, const double pos[3], const double quat[4],
                 const double vel[3]);

/* Step until the run ends (separated / settled / tmax) or fails. Returns d->status (> 0 ended,
   < 0 failed). */
int ur_run(const urModel* m, urData* d);

/* ur_run_start then ur_run. */
int ur_run_impact(const urModel* m, urData* d, int root, const double pos[3], const double quat[4],
                  const double vel[3]);

/* Kinetic energy of the system at the last ur_forward (velocities of that call), J. */
double ur_energy_kinetic(const urModel* m, const urData* d);

/* Potential energy of gravity and of the linear part (k) of the restraints (positions of the
   last ur_forward or ur_kinematics), J. */
double ur_energy_potential(const urModel* m, const urData* d);

/* The state of an elastic-plastic hinge (a restraint with mp > 0) on dof of body: its plastic
   deflection (rad or m) and the time it broke (s; 0: intact). Returns 0, or -1 when that dof
   has no such hinge. */
int ur_hinge_state(const urModel* m, const urData* d, int body, int dof, double* xp,
                   double* tbreak);

/* The model a run steps with: m itself, or once a hinge with fracture has broken, the run's own
   copy in which each broken body is a free body of the world (its joint released: it flies on
   with the velocity it had; its qpos and qvel at urBody.fqadr, fvadr of m). Poses computed for
   that run (ur_kinematics, drawing) use it; its sizes and names are m's. */
const urModel* ur_data_model(const urModel* m, const urData* d);

/* Total linear (3) and angular (3, about the world origin) momentum at the last ur_forward. */
void ur_momentum(const urModel* m, const urData* d, double p[3], double L[3]);

/* Set a free joint from the pose of its CoM and velocities (omega about the CoM); world frame
   for a root body, parent frame otherwise; NULL arguments are left unchanged. */
void ur_set_free(const urModel* m, urData* d, int body, const double pos[3], const double quat[4],
                 const double vel[3], const double omega[3]);

/* World position / velocity of a point given in the body frame (after ur_forward). */
void ur_point_pos(const urModel* m, const urData* d, int body, const double p[3], double out[3]);
void ur_point_vel(const urModel* m, const urData* d, int body, const double p[3], double out[3]);

/* Laws and restraint curves used beyond their data in the run so far (a pair's largest depth
   beyond ur_law_range, a crushing shell that bottomed, a curve restraint's extreme deflection
   beyond its curve's abscissae):
   the count, and in msg (if len > 0) the one furthest beyond, as a phrase. */
int ur_extrapolated(const urModel* m, const urData* d, char* msg, int len);

/* Human-readable name of a status. */
const char* ur_status_str(int status);

#ifdef __cplusplus
}
#endif
#endif
