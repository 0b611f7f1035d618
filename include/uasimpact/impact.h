/* impact.h: one drone-on-person impact at a horizontal offset, as the paper's section 4.2.
 *
 * Delta = (dpar, dperp) is the horizontal offset of the drone's centre from the head CG at a
 * moment tau, dpar along the drone's course and dperp across it (to the left of the course).
 * Which moment is urImpactCond.tau (urTau):
 *   urTAU_RMAX (the default) the paper's text (4.2, Fig. 7): tau is the first moment the drone's
 *              centre is R_max above the top of the head (R_max: largest distance from the
 *              drone's centre of mass to its surface);
 *   urTAU_TOP  tau is the moment the drone's centre reaches the level of the head top, that is
 *              R_max / tan(psi) further along the course on the same straight path. It exists
 *              because the paper's printed 10 m/s grids (Tables 8-10, 15, 16) behave as if their
 *              Delta were taken there: under the first definition their footprints lie about
 *              R_max / tan(psi) downstream of ours. At psi = 90 deg both are the same moment.
 * Either way the run starts with the drone's centre R_max above the head top (no part of the
 * drone below it), so the definitions differ only in where a path is labelled: a path's offset
 * under urTAU_TOP is its offset under urTAU_RMAX plus ur_impact_tau_shift along the course.
 * Until its first contact the drone keeps its speed, descent angle and attitude. The person stands in a stance settled once under gravity; the face
 * direction phi turns the course instead of the person (the ground is isotropic), so the stance
 * is computed only once. phi = 0: the person faces the incoming drone; phi = 90 deg: the drone
 * comes from the person's right.
 *
 * A urImpactSetup is constant after ur_impact_setup (or ur_impact_prepare) and shared by all
 * threads; each thread owns a urImpactWork.
 */
#ifndef UASIMPACT_IMPACT_H
#define UASIMPACT_IMPACT_H

#include "uasimpact/engine.h"
#include "uasimpact/injury.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the settled person of a model, kept with its set-up to be given to another model with the same
   person (ur_impact_prepare); opaque */
typedef struct urStance urStance;

/* the roles the impact needs, as the model declares them (urModel.roles) */
typedef struct {
  const urModel* m;
  int drone;           /* root body of the drone (free joint) */
  int head_geom;       /* head ellipsoid whose top defines the start height */
  int s_head_acc;      /* sensor: head CG acceleration (3) */
  int s_neck;          /* sensor: upper-neck joint load (6) */
  int s_chest, s_abd;  /* sensors: plate joint positions (deflections), or -1 */
  int ncand;           /* ellipsoid pairs the drone can act through (contact pairs
                                      and airbag targets, the ground excluded): */
  int (*cand)[2];      /* ncand x (drone ellipsoid, person ellipsoid) */
  int* cand_src;       /* ncand: where the force of each is: a contact pair (< npair),
                                      or npair + airbag * urMAXBAGTGT + target */
  int* cand_of;        /* the inverse: npair + nbag * urMAXBAGTGT, -1 where none */
  double rmax;         /* R_max, m */
  double head_cg[3];   /* settled head CG, world, m */
  double head_top;     /* settled height of the head top, m */
  double overlap;      /* how far the highest person ellipsoid the drone can touch reaches
                                      above the head top, m (> 0: a drone started R_max above the
                                      head top may already overlap it; 0: none) */
  int overlap_geom;    /* that ellipsoid, or -1 */
  double neck_preload; /* settled upper-neck axial force, N (tension > 0) */
  double window;       /* a run ends this long after its first contact, s (model
                                      parameter "window"; none: until the engine ends it) */
  int endrun;          /* 1: a run also ends once every criterion's value is final (model
                                      parameter "endrun"; 0, the default: by the window) */
  urData* rest;        /* the settled stance (drone parked far away) */
  urStance* stance;    /* what another model with the same person can take (owned;
                                      NULL: none, e.g. after ur_impact_setup) */
  int shared;          /* 1: balance and stance were taken from another model */
  char err[160];
} urImpactSetup;

/* the moment tau at which Delta is taken (see the top of this file) */
typedef enum {
  urTAU_RMAX = 0, /* the drone's centre R_max above the head top (paper 4.2) */
  urTAU_TOP = 1   /* the drone's centre at the level of the head top */
} urTau;

/* the conditions of an impact */
typedef struct {
  double speed;            /* impact speed, m/s */
  double angle;            /* descent angle psi from the horizontal, deg */
  double face;             /* face direction phi, deg */
  double pitch, roll, yaw; /* drone attitude relative to upright on its course, deg */
  int tau;                 /* urTau: the moment Delta is taken (0: the paper's text) */
  int aim;                 /* 1: (dpar, dperp) are not an offset at tau but the
                                      eccentricity (up, side) of the drone's line of travel from
                                      the head's centre (aim mode, below); any angle 0-90 deg */
} urImpactCond;

/* what one of the pairs through which the drone acts (urImpactSetup.cand) did during an impact */
typedef struct {
  double t_first, t_last; /* first and last time with a normal force, s from tau (-1:
                                      never) */
  double fmax;            /* largest normal force, N */
  double t_fmax;          /* its time, s */
} urContactRec;

/* per-thread work space */
typedef struct {
  urData* d;
  int rows;                  /* history rows */
  double* chan;              /* channel buffers */
  double* work;              /* injury work space */
  urContactRec* crec;        /* ncand: the contacts of the last ur_impact_run (not of lane
                                      runs) */
  struct urImpactFinal* fin; /* the end on final values (endrun 1): the run's signals
                                      (internal) */
} urImpactWork;

typedef struct {
  int status; /* engine status (< 0: failed) */
  char reason[urMSGLEN];
  int contact;           /* the drone touched the person */
  double t_first;        /* time of first contact from tau, s (-1: none) */
  urInjuryResult inj;    /* criteria and PoFs */
  double p;              /* P{F | Delta} */
  int nextrap;           /* laws and restraint curves used beyond their data
                                      (ur_extrapolated): the result rests partly on extrapolation */
  char extrap[urMSGLEN]; /* the one furthest beyond, as a phrase */
} urImpactResult;

/* Balance the standing posture: a passive stance under gravity is an inverted-pendulum chain
   that sags and leans; real standing holds it with muscle tone. This shifts the neutral positions
   x0 of the person's restraints (every tree but the drone's) by fixed-point iteration so that
   the posture settled from the model's reference configuration is that configuration. Stiffness
   and damping stay as modelled; the drone waits parked far above, held at rest. residual:
   largest joint deflection of the last settling, rad or m. 0, or -1 if the settling failed (or
   a membrane airbag is not inflated: ur_model_inflate). */
int ur_impact_balance(urModel* m, double settle_time, int iters, double* residual);

/* whether a compiled model can run impacts, before anything is settled: the roles it declares
   (role drone=, head=, head_acc=, neck=, head_pos=), at least one contact pair or airbag target
   between the drone and the person (without one every impact gives P = 0), the bounds of the
   simulation options,
   each with its reason: dt in (0, 1e-3] s, tmax in (0, 1] s, at most 1e5 steps (tmax/dt),
   settle_dt (when the model defines it) in [dt, 0.01] s, window (when defined) > 0. 0, or -1
   with one line in err (n bytes) saying what was wrong and what is accepted. ur_impact_prepare
   and ur_impact_setup fail on such a model too, later. */
int ur_impact_check(const urModel* m, char* err, size_t n);

/* take the roles the model declares (urModel.roles: drone, head, head_acc, neck, head_pos,
   chest, abdomen), compute R_max, settle the stance (settle_time s of gravity)
   and check it; 0 or -1 with s->err (also when a membrane airbag is not inflated: the model's
   owner calls ur_model_inflate first, engine.h). The stance is a state of rest: the person as settled, every
   velocity zero, the drone parked far above in its reference posture with no restraint or contact
   history (while the person settles, the drone is held there at rest). */
int ur_impact_setup(urImpactSetup* s, const urModel* m, double settle_time);

/* ur_impact_balance (iters) then ur_impact_setup, keeping in s->stance what settling gave; or,
   when one of the donors (set-ups made by this function for other models; NULL entries skipped)
   has the same person, its balanced neutral positions and settled person instead of settling:
   m and s are then bitwise what settling would give (s->shared = 1). The same person: every body
   off the drone's tree, with its joint, restraints (neutral positions before balancing),
   reference coordinates, ellipsoids and the pairs among them or with the ground, at the same
   indices, and the same settling options (step, gravity, integrator, implicit damping, vmax),
   settle_time and iters, compared byte for byte. Also needed, so that the trees cannot have
   touched: in both models no airbag rides on the person and the drone has no pair or airbag
   target but the person's, the donor's person never rose while settling to its drone's parked
   bounding spheres nor to this drone's, and this drone takes one held settling step without
   failing. 0; -1 if the balancing failed, -2 if the set-up did (s->err; ur_impact_free either
   way). */
int ur_impact_prepare(urImpactSetup* s, urModel* m, double settle_time, int iters,
                      const urImpactSetup* const* donors, int ndonor);
void ur_impact_free(urImpactSetup* s);

int ur_impact_work_init(const urImpactSetup* s, urImpactWork* w);
void ur_impact_work_free(urImpactWork* w);

/* how far along the course Delta is taken after the drone's centre is R_max above the head
   top: 0 for urTAU_RMAX, R_max / tan(psi) for urTAU_TOP (exactly 0 at psi >= 90 deg), m */
double ur_impact_tau_shift(const urImpactSetup* s, const urImpactCond* c);

/* drone pose and velocity at the start of a run for an offset: its centre R_max above the head
   top, at the offset Delta - ur_impact_tau_shift along the course (the offset needs a descent,
   angle > 0: at 0 the path stays R_max above the head top).
   Aim mode (c->aim): the drone's line of travel (through its centre of mass, along its velocity
   v) passes the centre of the head ellipsoid (urRoles.head, settled) at the eccentricity
   up * u + side * l, with l the horizontal left of the course and u = v x l (upward for a
   horizontal flight, forward along the course for a vertical descent). The drone starts on that
   line R_max before the person's nearest point along it: its centre at the line's point whose
   distance along v is the least (c_g . v - rbound_g) over the person's ellipsoids g, less R_max
   (a plane then separates the drone from the person); tau is that start. */
void ur_impact_start(const urImpactSetup* s, const urImpactCond* c, double dpar, double dperp,
                     double pos[3], double quat[4], double vel[3]);

/* 1 if the straight path of the drone's bounding spheres can reach the person's (conservative) */
int ur_impact_may_contact(const urImpactSetup* s, const urImpactCond* c, double dpar, double dperp);

/* run one impact; the run's histories stay in w->d and what each pair through which the drone
   acts did in w->crec; 0, or -1 if the simulation failed */
int ur_impact_run(const urImpactSetup* s, urImpactWork* w, const urImpactCond* c,
                  const urInjuryParams* ip, double dpar, double dperp, urImpactResult* r);

/* many impacts on one thread, urIMPACT_LANES at a time stepped in lock-step (the engine computes
   their accelerations together over vectors of lanes): offsets come from next (return 0 when
   none is left; tag is handed back to done), results go to done as runs finish (rc as
   ur_impact_run's; w: the lane's work space, the run's histories included, valid during the
   call), each result and history bitwise what ur_impact_run gives for that offset (in w->d,
   the motion subspaces, bias accelerations and articulated-body scratch are not kept). The
   lanes belong to one thread at a time. */
#define urIMPACT_LANES 4
typedef struct urImpactLanes urImpactLanes;
typedef int (*urImpactNextFn)(void* ctx, double* dpar, double* dperp, void** tag);
typedef void (*urImpactDoneFn)(void* ctx, void* tag, int rc, const urImpactResult* r,
                               const urImpactWork* w);
urImpactLanes* ur_impact_lanes_new(const urImpactSetup* s); /* NULL: no memory */
void ur_impact_lanes_free(urImpactLanes* L);
void ur_impact_run_many(const urImpactSetup* s, urImpactLanes* L, const urImpactCond* c,
                        const urInjuryParams* ip, urImpactNextFn next, urImpactDoneFn done,
                        void* ctx);

/* a channel of the last run of w: sensor id, component; n rows into out (caller: w->rows) */
int ur_impact_channel(const urImpactSetup* s, const urImpactWork* w, int sensor, int comp,
                      double* out);

#ifdef __cplusplus
}
#endif
#endif
