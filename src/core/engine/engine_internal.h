/* engine_internal.h: functions shared between the engine source files (not public API). */
#ifndef UASIMPACT_ENGINE_INTERNAL_H
#define UASIMPACT_ENGINE_INTERNAL_H

#include "uasimpact/engine.h"

// unroll the small fixed-size loops of the 3x3 / 6x6 kernels (GCC and clang)
#if defined(__GNUC__)
#define urUNROLL _Pragma("GCC unroll 6")
#else
#define urUNROLL
#endif

//---------------------------------- vector and quaternion utilities (engine_util.c) --------------
#include "engine_util_inline.h"

int uru_normalize3(double a[3]);
void uru_normalizequat(double q[4]);
void uru_axisangle2quat(double q[4], const double axis[3], double angle);
void uru_quatintegrate(double q[4], const double omega[3], double dt);
void uru_addpos(const urModel* m, double* qpos, const double* qvel, double h);
void uru_restraints_kin(const urModel* m, const double* qpos, double* rkin);
void uru_quat2rotvec(double v[3], const double q[4]);
void uru_rotvec_jrinv(double J[9], const double v[3]);

//---------------------------------- spatial algebra (engine_util.c) ------------------------------

void uru_rbi(double I[36], double mass, const double com[3], const double Ic[9]);
void uru_xinertia_t_add(double r[36], const double E[9], const double p[3], const double I[36]);
int uru_invsym(double* Ainv, const double* A, int n);

//---------------------------------- engine passes -------------------------------------------------

void ur_kinematics_bodies(const urModel* m, urData* d);
void ur_kinematics_geoms(const urModel* m, urData* d);
void ur_kinematics_gpos(const urModel* m, urData* d);
const double* ur_geom_xmat(const urModel* m, urData* d, int g);
void ur_velocities(const urModel* m, urData* d);
void ur_restraints_commit(const urModel* m, urData* d);
void ur_aba(const urModel* m, urData* d);
void ur_forward_pre(const urModel* m, urData* d);
void ur_forward_loads(const urModel* m, urData* d, const int* rstb, int nrstb);
int ur_forward_post(const urModel* m, urData* d);
int ur_step_begin(const urModel* m, urData* d);
int ur_step_euler(const urModel* m, urData* d);
void ur_step_accept(const urModel* m, urData* d);
int ur_step_end(const urModel* m, urData* d);
// a sufficient test for the coarse-step proof's gap along a centre line, without square root or
// division (engine_run.c): 1 only where the exact test passes too
int ur_gap_quick(const double dc[3], double ce, double r, double A, double T);

// the length of the step under way: adapt dt for a coarse step (urData.coarse), else dt
static inline double ur_step_h(const urModel* m, const urData* d) {
  return d->coarse ? m->opt.dt * m->opt.adapt : m->opt.dt;
}
void ur_reactions(const urModel* m, urData* d);
void ur_restraints_kin(const urModel* m, urData* d);
void ur_restraints(const urModel* m, urData* d, const int* rstb, int nrstb);
int ur_restraint_vec(const urModel* m, int i);
double uru_back_slope(const urRestraint* r);
void ur_contacts(const urModel* m, urData* d);
void ur_contacts_broad(const urModel* m, urData* d);
void ur_contacts_narrow(const urModel* m, urData* d);
void ur_contacts_relist(const urModel* m, urData* d);
void ur_contacts_commit(const urModel* m, urData* d);
void ur_airbags(const urModel* m, urData* d);
void ur_sensors(const urModel* m, urData* d);
void ur_outputs(const urModel* m, urData* d);
void ur_apply_force(const urModel* m, urData* d, int body, const double f[3], const double p[3]);
void ur_point_acc(const urModel* m, const urData* d, int body, const double p[3], double out[3]);
void ur_set_status(urData* d, int status, const char* msg);
void ur_geom_ellipsoid(const urModel* m, urData* d, int g, urEllipsoid* e);
void ur_relvel(const urModel* m, const urData* d, int a, int b, const double p[3], double v[3]);
double ur_contact_apply(const urModel* m, urData* d, int a, int b, const double n[3],
                        const double p[3], const double v[3], double fn, double rate,
                        const urLaw* law, double mu, double v_eps);
//---------------------------------- trees -------------------------------------------------------
// whether body b, or the body of ellipsoid g, belongs to the kinematic tree rooted at body root
// (urBody.tree); -1 (no body, the ground) belongs to none
static inline int ur_body_intree(const urModel* m, int b, int root) {
  return b >= 0 && m->body[b].tree == root;
}
static inline int ur_geom_intree(const urModel* m, int g, int root) {
  return g >= 0 && ur_body_intree(m, m->geom[g].body, root);
}

//---------------------------------- contact candidates (engine_contact.c) ----------------------
// The one enumeration of the ellipsoid pairs a force can act through: the model's contact pairs
// in order, then each airbag's targets in order. Candidate k (0 <= k < ur_cand_count) is dense;
// src names its force's slot: k for a pair, npair + airbag * urMAXBAGTGT + target for an airbag
// target (the encoding of urImpactSetup.cand_src; slots below ur_cand_slots).
typedef struct {
  int g1, g2; // ellipsoids (g2 -1: the ground; for a target: bag, target)
  int bag;    // the airbag, -1 for a contact pair
  int idx;    // the pair's index, or the target's index in its airbag
  int src;    // the slot
} urCand;
int ur_cand_count(const urModel* m);
int ur_cand_at(const urModel* m, int k, urCand* c); // 0, or -1 when k is out of range
static inline int ur_cand_bag_slot(const urModel* m, int bag, int target) {
  return m->npair + bag * urMAXBAGTGT + target;
}
static inline int ur_cand_slots(const urModel* m) {
  return ur_cand_bag_slot(m, m->nbag, 0);
}

//---------------------------------- lanes (engine_lanes.c) --------------------------------------
// up to urNLANE runs of one model stepped in lock-step, their poses, velocities and the
// articulated-body algorithm computed over vectors of lanes; each run's bits are those of
// ur_step. A lane run's S, cbias and ABA scratch (IA, U, Dinv, pA, uu) live here only, and so
// do Xe, Xr, cacc and freact of the bodies that no joint-load or acceleration sensor reads, and
// rkin of the bodies whose restraint forces the vectors compute (ur_restraint_vec): its urData
// keeps the poses, velocities, accelerations and the joint loads and accelerations read.
// The ellipsoids' orientations are computed lane by lane where first used (ur_geom_xmat):
// most ellipsoids are culled by their bounding spheres in most steps.

#define urNLANE 4
typedef double urV4 __attribute__((vector_size(4 * sizeof(double))));
typedef long long urV4I __attribute__((vector_size(4 * sizeof(long long))));

typedef struct {
  urV4 *S, *IA, *U, *Dinv, *pA, *uu, *cbias, *cvel, *cacc, *fext, *freact, *Xe, *Xr, *qfrc, *qacc;
  urV4 *qpos, *qvel, *xmat, *xpos, *xcom, *gxpos;
  urV4* gxmat;      // unused (NULL): each lane computes the orientations it needs
  urV4* gap;        // npair: bounding-sphere gaps, then depths (broad phase)
  urV4* rkin;       // nbody x 12: as urData.rkin
  urV4* energy;     // kinetic energy of each lane ([0])
  urV4* h;          // each lane's step ([0]; ur_step_h: dt, or adapt dt for a coarse step)
  int fail;         // lanes whose joint-space inertia was singular (bits)
  double* spare;    // max(nq, nv): where a lane that does not step scatters
  int* outb;        // the bodies whose Xe, Xr, cacc, freact a run reads (joint
  int nout;         // loads: urBody.react; acceleration sensors)
  int *rstv, nrstv; // the restraint bodies whose forces the vectors compute (ur_restraint_vec)
  int *rsts, nrsts; // the others (lane by lane); a lane run keeps rkin of these only
  void* mem;
  // NULL, or urLANE_NPROF tick counters that ur_step_lanes adds each stage's time to (make
  // bench: the per-stage split; the ticks are the processor's time-stamp counter on x86-64,
  // nanoseconds elsewhere); set after ur_lanes_init, owned by the caller
  unsigned long long* prof;
} urLanes;

// the stages of ur_step_lanes that urLanes.prof times
enum {
  urLANE_KIN,     // state gathered, poses, ellipsoid centres, velocities (vectors)
  urLANE_BROAD,   // broad phase (vectors)
  urLANE_RKIN,    // restraint kinematics (vectors)
  urLANE_COPYKIN, // poses, velocities, depths, restraint kinematics back to each run
  urLANE_LOADS,   // applied forces: gravity, restraints, narrow phase, airbags (per run)
  urLANE_RESTR,   // restraint forces (vectors, ur_restraint_vec's bodies)
  urLANE_COPYF,   // the forces into the vectors, the accelerations back (4x4 transposes)
  urLANE_ABA,     // articulated-body algorithm (vectors)
  urLANE_POST,    // joint loads, sensors, histories, contact bookkeeping (per run)
  urLANE_EULER,   // the update (vectors) and the state back to each run
  urLANE_END,     // time, state checks and the end of each run (per run)
  urLANE_NPROF
};

int ur_lanes_init(const urModel* m, urLanes* L);
// uru_sincos and uru_atan2q of urNLANE arguments at once over the vectors (tests)
void ur_lanes_trig(const double x[urNLANE], double s[urNLANE], double c[urNLANE],
                   const double y[urNLANE], const double w[urNLANE], double a[urNLANE]);
void ur_lanes_free(urLanes* L);
// uru_restraints_kin and uru_addpos of a run alone, bitwise, its quaternion joints four at a
// time over the vectors
void ur_restraints_kin_joints(const urModel* m, const double* qpos, double* rkin);
void ur_addpos_joints(const urModel* m, double* qpos, const double* qvel, double h);
// the rotations of a run alone's revolute and universal joints about their axes (jcalc's
// axisrot) four at a time over the vectors, into slot 0 (first axis) and 1 (second) of each
// body's stash: the tail of its S (6 x nv <= 18 values read; S + 18 and S + 27 are free)
static inline double* ur_jrot_slot(urData* d, int body, int slot) {
  return d->S + 36 * body + 18 + 9 * slot;
}
void ur_axisrot_joints(const urModel* m, urData* d);
// one step of each of the runs d[0..n-1] (urNLANE at a time), bitwise as ur_step on each
int ur_step_lanes(const urModel* m, urData* const* d, int n, urLanes* L);

// How fast spin can widen ellipsoid ge along a fixed unit direction while its body turns at the
// constant angular velocity wb (rad/s, in the body's frame): its half-width grows within time t
// by at most o + k t, and by at most kr t (m, m/s; engine_run.c says why). The end-of-run proof
// (t_clear) uses it: a sphere, or a flat round ellipsoid that yaws, hardly widens.
typedef struct {
  double o, k, kr;
} urSpinBound;
urSpinBound ur_spin_bound(const urGeom* ge, const double wb[3]);

#if !(defined(__x86_64__) && defined(__GNUC__))
#include <time.h>
#endif
// a tick of the stage timers: the processor's time-stamp counter on x86-64, nanoseconds elsewhere
static inline unsigned long long uru_ticks(void) {
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_ia32_rdtsc();
#else
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (unsigned long long)t.tv_sec * 1000000000ull + (unsigned long long)t.tv_nsec;
#endif
}

// the stages of a step alone (ur_step) that its stage timer times
enum {
  urSTEP_KIN,    // poses, ellipsoid centres, velocities
  urSTEP_RKIN,   // restraint kinematics
  urSTEP_BROAD,  // broad phase
  urSTEP_GRAV,   // forces cleared, gravity compensation
  urSTEP_RESTR,  // restraint forces
  urSTEP_NARROW, // narrow phase and contact forces
  urSTEP_BAG,    // airbags
  urSTEP_ABA,    // articulated-body algorithm
  urSTEP_POST,   // joint loads, sensors, finiteness
  urSTEP_EULER,  // bookkeeping (histories, commits), update, time, checks, end of run
  urSTEP_NPROF
};

#ifdef urSTEP_PROF
// The stage timer of a step alone, compiled in only where engine_run.c is built with
// urSTEP_PROF (make bench: tests/bench_step links such an object before the library): NULL, or
// urSTEP_NPROF tick counters to which each ur_step of this thread adds its stages' times.
// The library is built without it: its step has no timer and pays nothing for one.
void ur_step_prof(unsigned long long* prof);
#endif

/* joints that break (engine_fracture.c) */
void ur_fracture_compile(urModel* m);                       /* reserve the free blocks */
void ur_fracture_qpos0(const urModel* m, double* qpos0);    /* their reference coordinates */
int ur_fracture_pending(const urModel* m, const urData* d); /* 1: the run steps alone */
int ur_fracture_release(const urModel* m, urData* d);       /* release the broken joints */

int ur_tree_active(const urModel* m, const urData* d, int tree);
double ur_depth_bound(const urModel* m, urData* d, int ga, int gb, const double u[3]);
/* the same where only a negative bound is used: equal when negative, else some value >= 0 */
double ur_depth_cull(const urModel* m, urData* d, int ga, int gb, const double u[3]);
double ur_geom_halfwidth(const urModel* m, urData* d, int g, const double u[3]);

/* the membrane airbags (engine_membrane.c, on the membrane room's fabric, gas and contact) */
int urm_model_compile(urModel* m);                       /* build and inflate the membrane bags */
void urm_model_free(urModel* m);                         /* release them */
void urm_bag_loads(const urModel* m, urData* d, int ib); /* forces of bag ib this step */
void urm_bags_advance(const urModel* m, urData* d);      /* move the membranes one step */

#endif
