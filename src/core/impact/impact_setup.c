/* impact_setup.c: the set-up of impacts on one model: the person balanced and settled under
 * gravity with the drone parked far above, the roles the model declares, R_max, the rest state; and
 * the stance shared with a model whose person is the same (ur_impact_prepare) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "uasimpact/impact.h"
#include "../engine/engine_internal.h"
#include "impact_internal.h"

/* height of the top of an ellipsoid in the world */
static double ellipsoid_top(const urModel* m, urData* d, int g) {
  const double* R = ur_geom_xmat(m, d, g);
  double s = 0;
  for (int k = 0; k < 3; k++) {
    double v = R[6 + k] * m->geom[g].size[k];
    s += v * v;
  }
  return d->gxpos[3 * g + 2] + sqrt(s);
}

/* ---- set-up ---- */

/* joint deflections of body b (spherical: rotation vector); returns the count */
static int deflections(const urModel* m, const urData* d, int b, double x[3]) {
  const urBody* bd = m->body + b;
  const double* q = d->qpos + bd->qadr;
  if (bd->jtype == urJNT_SPHERICAL) {
    uru_quat2rotvec(x, q);
    return 3;
  }
  if (bd->jtype == urJNT_REVOLUTE || bd->jtype == urJNT_PRISMATIC || bd->jtype == urJNT_UNIVERSAL) {
    for (int k = 0; k < bd->nq; k++) x[k] = q[k];
    return bd->nq;
  }
  return 0;
}

#define SETTLE_DT    2e-4 /* default step of the settling, s (model parameter settle_dt) */
#define BALANCE_GAIN 0.5  /* fixed-point gain of the balancing */
/* where the drone waits while the person settles */
static const double PARK[3] = {0, 0, 1e4}, QID[4] = {1, 0, 0, 0}, ZERO3[3] = {0, 0, 0};

/* the step of the settling */
static double settle_step(const urModel* m) {
  return fmax(m->opt.dt, ur_model_param(m, "settle_dt", SETTLE_DT));
}

/* the drone back in its reference posture, parked, at rest, without restraint history
   (kinematics not updated) */
static void hold(const urModel* m, urData* d, int drone) {
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    if (!ur_body_intree(m, b, drone)) continue;
    memcpy(d->qpos + bd->qadr, m->qpos0 + bd->qadr, bd->nq * sizeof(double));
    memset(d->qvel + bd->vadr, 0, bd->nv * sizeof(double));
    memset(d->rst + 2 * bd->vadr, 0, 2 * bd->nv * sizeof(double));
  }
  if (m->body[drone].jtype == urJNT_FREE) {
    memcpy(d->qpos + m->body[drone].qadr, PARK, sizeof PARK);
    memcpy(d->qpos + m->body[drone].qadr + 3, QID, sizeof QID);
  }
}

/* highest point of the person's bounding spheres (every ellipsoid off the drone's tree) and
   lowest point of the drone's, at the last kinematics of d */
static double person_top(const urModel* m, const urData* d, int drone) {
  double top = -INFINITY;
  for (int g = 0; g < m->ngeom; g++) {
    if (!ur_geom_intree(m, g, drone)) {
      top = fmax(top, d->gxpos[3 * g + 2] + m->geom[g].rbound);
    }
  }
  return top;
}

static double drone_low(const urModel* m, const urData* d, int drone) {
  double low = INFINITY;
  for (int g = 0; g < m->ngeom; g++) {
    if (ur_geom_intree(m, g, drone)) {
      low = fmin(low, d->gxpos[3 * g + 2] - m->geom[g].rbound);
    }
  }
  return low;
}

/* the lowest point of the drone's ellipsoids that can touch the person (the contact
   candidates), by the box around each: below it a parked drone may push the settling person */
static double parked_reach(const urModel* m, urData* d, int drone) {
  double low = INFINITY;
  urCand cd;
  for (int k = 0; ur_cand_at(m, k, &cd) == 0; k++) {
    if (cd.g2 < 0) continue;
    int a = ur_geom_intree(m, cd.g1, drone), b = ur_geom_intree(m, cd.g2, drone);
    if (a == b) continue;
    int g = a ? cd.g1 : cd.g2;
    const double* R = ur_geom_xmat(m, d, g);
    double h = 0;
    for (int j = 0; j < 3; j++) h += fabs(R[6 + j]) * m->geom[g].size[j];
    low = fmin(low, d->gxpos[3 * g + 2] - h);
  }
  return low;
}

/* d reset to the reference configuration with the drone parked */
static void park(const urModel* m, urData* d, int drone) {
  ur_data_reset(m, d);
  ur_set_free(m, d, drone, PARK, QID, ZERO3, ZERO3);
}

/* the largest deflection of the person's joints from their neutral positions */
static double deflection_max(const urModel* m, const urData* d, int drone) {
  double dmax = 0, x[3];
  for (int b = 0; b < m->nbody; b++) {
    if (ur_body_intree(m, b, drone)) continue;
    int n = deflections(m, d, b, x);
    for (int k = 0; k < n; k++) dmax = fmax(dmax, fabs(x[k] - m->body[b].rst[k].x0));
  }
  return dmax;
}

/* the settling's nstep steps taken by p, the person alone (impact_person.c), from d parked: the
   same person to the bit as stepping the whole model with the drone held, when the drone's held
   step succeeds (it is the same at every step) and the person's bounding spheres stay below the
   parked drone's in every state evaluated (then no pair or airbag between the trees acts). 0:
   the settled person in d, the drone parked, top raised as settle does; -1: d as it came, to
   be settled whole (a step failed, the person rose too close, or out of memory) */
static int settle_alone(const urModel* m, urData* d, int drone, const urModel* p, long nstep,
                        double* top) {
  urData* d0 = ur_data_new(m); /* d as it came: the whole settling starts from it on failure */
  if (!d0) return -1;
  ur_data_copy(m, d0, d);
  if (ur_step(m, d) < 0) {
    ur_data_copy(m, d, d0);
    ur_data_free(d0);
    return -1;
  }
  double low = drone_low(m, d, drone), ptop = -INFINITY;
  urData* dp = ur_data_new(p);
  int ok = dp != NULL;
  for (long k = 0; ok && k < nstep; k++) {
    ok = ur_step(p, dp) >= 0;
    for (int g = 0; ok && g < p->ngeom; g++) {
      ptop = fmax(ptop, dp->gxpos[3 * g + 2] + p->geom[g].rbound);
    }
    ok = ok && ptop < low;
  }
  park(m, d, drone);
  if (ok) {
    ur_impact_person_state(m, d, drone, p, dp);
    if (top) *top = fmax(*top, ptop);
  } else {
    ur_data_copy(m, d, d0);
  }
  ur_data_free(dp);
  ur_data_free(d0);
  return ok ? 0 : -1;
}

/* settle the person from the reference posture for t seconds; the largest joint deflection.
   The stance has no stiff contact, so it settles with a step of at least settle_dt (model
   parameter, default SETTLE_DT): a state of rest of the Euler step does not depend on the step,
   and P{F|(0,0)} changes by < 1e-4 between a 1e-4 s and a 2e-4 s settling, at a quarter of the
   set-up time. The drone waits far above, held at rest in its reference posture (put back after
   every step), so the settled person does not depend on it as long as the trees do not touch
   (ur_impact_prepare checks that before it shares a stance). top (NULL: none) rises to the
   highest point of the person's bounding spheres in every state the steps evaluated. */
static double settle(const urModel* m0, urData* d, int drone, double t, double* top) {
  urModel mc = *m0, *m = &mc;
  mc.opt.dt = settle_step(m0);
  park(m, d, drone);
  long nstep = (long)ceil(t / m->opt.dt);
  urModel* p = nstep > 1 ? ur_impact_person_model(m, drone) : NULL;
  if (p) {
    int done = settle_alone(m, d, drone, p, nstep, top) == 0;
    ur_model_free(p);
    if (done) return deflection_max(m, d, drone);
  }
  for (long k = 0; k < nstep; k++) {
    if (ur_step(m, d) < 0) return INFINITY;
    hold(m, d, drone);
    if (top) *top = fmax(*top, person_top(m, d, drone));
  }
  return deflection_max(m, d, drone);
}

/* the person's posture under gravity with the springs' neutral positions shifted by the
   deflections of the last settling: x0 <- x0 - (x - x0) */
static int balance(urModel* m, int drone, double settle_time, int iters, double* residual,
                   double* top) {
  urData* d = ur_data_new(m);
  if (!d) return -1;
  double res = INFINITY;
  for (int it = 0; it < iters; it++) {
    res = settle(m, d, drone, settle_time, top);
    if (!isfinite(res)) break;
    for (int b = 0; b < m->nbody; b++) {
      double x[3];
      if (ur_body_intree(m, b, drone)) continue;
      int n = deflections(m, d, b, x);
      for (int k = 0; k < n; k++) {
        urRestraint* r = &m->body[b].rst[k];
        if (r->active) r->x0 -= BALANCE_GAIN * (x[k] - r->x0);
      }
    }
  }
  if (residual) *residual = res;
  ur_data_free(d);
  return isfinite(res) ? 0 : -1;
}

int ur_impact_balance(urModel* m, double settle_time, int iters, double* residual) {
  int drone = m->roles.drone;
  if (drone < 0 || m->body[drone].jtype != urJNT_FREE || m->nraw) return -1;
  return balance(m, drone, settle_time, iters, residual, NULL);
}

/* ---- the stance shared between models with the same person ---- */

/* Everything the settling of the person depends on, as bytes: every body off the drone's tree
   (index, names, parent and tree, pose, inertia, gravity flag, joint, addresses, reference
   coordinates, restraints with every field and x0 before balancing, compiled inertia), every
   ellipsoid on them, every pair between two of them or with the ground (with its law), the
   options of the settling (its step, gravity, integrator, implicit damping, vmax) and the
   settling time and balancing iterations. Indices are absolute: a person placed differently
   among the drone's elements is another person (refused, not mapped). Then what the settling
   gave: the balanced x0 of the person's restraints and the person's settled coordinates,
   restraint extremes and pair histories (velocities are zeroed at rest). */
struct urStance {
  unsigned char* key;
  size_t nkey, capkey;
  uint64_t hash; /* FNV-1a of key: a quick rejection before the full compare */
  int ok;        /* the key is complete (no allocation failed) */
  int shareable; /* settled, with no airbag on the person, clear of the drone */
  double top;    /* highest point of the person's bounding spheres while
                                      settling (balancing included), m */
  int nx0, nq, nrst, npair;
  double* x0;       /* 3 per person body, body order */
  double* qpos;     /* the person's coordinates, body order */
  double* rst;      /* restraint extremes, 2 per person dof */
  urPairData* pair; /* the person's pairs, pair order */
};

/* the key names the fields one by one: a field added to one of these structs must be added to
   its put_ function below too (urOption: stance_new); sizes of LP64 targets (amd64, arm64) */
#define urLP64_SIZE(T, n)                                                                          \
  _Static_assert(sizeof(void*) != 8 || sizeof(T) == (n), #T " changed: update its put_ function")
urLP64_SIZE(urRestraint, 1648);
urLP64_SIZE(urLaw, 3280);
urLP64_SIZE(urBody, 5704);
urLP64_SIZE(urGeom, 208);
urLP64_SIZE(urOption, 128);

static void put(urStance* st, const void* v, size_t n) {
  if (!st->ok) return;
  if (st->nkey + n > st->capkey) {
    size_t cap = 2 * (st->nkey + n);
    unsigned char* k = realloc(st->key, cap);
    if (!k) {
      st->ok = 0;
      return;
    }
    st->key = k;
    st->capkey = cap;
  }
  memcpy(st->key + st->nkey, v, n);
  st->nkey += n;
}
#define PUT(st, x) put(st, &(x), sizeof(x))

static void put_str(urStance* st, const char* s) {
  int n = (int)strnlen(s, urNAMELEN);
  PUT(st, n);
  put(st, s, (size_t)n);
}

static void put_curve(urStance* st, const urCurve* c) {
  PUT(st, c->n);
  PUT(st, c->x);
  PUT(st, c->y);
}

static void put_restraint(urStance* st, const urRestraint* r) {
  PUT(st, r->active);
  PUT(st, r->k);
  PUT(st, r->sat);
  put_curve(st, &r->load);
  put_curve(st, &r->unload);
  PUT(st, r->c);
  PUT(st, r->lo);
  PUT(st, r->hi);
  PUT(st, r->kstop);
  PUT(st, r->cstop);
  PUT(st, r->x0);
  if (r->mp > 0) { // hinges only: a model without them keeps its stance key
    PUT(st, r->mp);
    PUT(st, r->kh);
    PUT(st, r->mfrac);
  }
}

static void put_law(urStance* st, const urLaw* l) {
  int type = (int)l->type;
  PUT(st, type);
  PUT(st, l->estar);
  PUT(st, l->radius);
  PUT(st, l->sy);
  PUT(st, l->nu);
  PUT(st, l->plastic);
  put_curve(st, &l->load);
  put_curve(st, &l->unload);
  put_curve(st, &l->stress);
  PUT(st, l->thickness);
  PUT(st, l->unload_r);
  PUT(st, l->unload_p);
  PUT(st, l->lock);
  PUT(st, l->backing_k);
  PUT(st, l->damping);
  PUT(st, l->chi);
  PUT(st, l->mu);
  PUT(st, l->v_eps);
  if (l->layer_h > 0 || l->shell_k > 0) { // layered or shell laws only: old keys stay
    PUT(st, l->layer_h);
    PUT(st, l->bone_k);
    PUT(st, l->shell_k);
  }
  if (l->backing_estar > 0 || l->backing.n > 0) { // derived backings only: old keys stay
    PUT(st, l->backing_estar);
    PUT(st, l->backing_r);
    put_curve(st, &l->backing);
  }
  if (l->crush_f > 0) { // crushing shells only: old keys stay
    PUT(st, l->crush_f);
    PUT(st, l->crush_h);
  }
}

static void put_body(urStance* st, const urModel* m, int b) {
  const urBody* bd = m->body + b;
  int jtype = (int)bd->jtype;
  PUT(st, b);
  put_str(st, bd->name);
  put_str(st, bd->jname);
  PUT(st, bd->parent);
  PUT(st, bd->tree);
  PUT(st, bd->react);
  PUT(st, bd->pos);
  PUT(st, bd->quat);
  PUT(st, bd->mass);
  PUT(st, bd->com);
  PUT(st, bd->inertia);
  PUT(st, bd->gravity);
  PUT(st, jtype);
  PUT(st, bd->axis);
  PUT(st, bd->qadr);
  PUT(st, bd->nq);
  PUT(st, bd->vadr);
  PUT(st, bd->fqadr);
  PUT(st, bd->fvadr);
  PUT(st, bd->nv);
  for (int k = 0; k < 3; k++) put_restraint(st, bd->rst + k);
  PUT(st, bd->sinert);
  PUT(st, bd->iinv);
  PUT(st, bd->bmat);
  put(st, m->qpos0 + bd->qadr, bd->nq * sizeof(double));
}

static void put_geom(urStance* st, const urModel* m, int g) {
  const urGeom* ge = m->geom + g;
  PUT(st, g);
  put_str(st, ge->name);
  PUT(st, ge->body);
  PUT(st, ge->pos);
  PUT(st, ge->quat);
  PUT(st, ge->size);
  PUT(st, ge->degree);
  PUT(st, ge->rbound);
  PUT(st, ge->gmat);
}

/* a pair of the person: both ellipsoids off the drone (or the ground) */
static int person_pair(const urModel* m, int i, int drone) {
  const urPair* p = m->pair + i;
  return !ur_geom_intree(m, p->geom1, drone) &&
         (p->geom2 < 0 || !ur_geom_intree(m, p->geom2, drone));
}

static void stance_free(urStance* st) {
  if (!st) return;
  free(st->key);
  free(st->x0);
  free(st->qpos);
  free(st->rst);
  free(st->pair);
  free(st);
}

/* room for the settled state of st's counts (every pointer replaced); 0, or -1 */
static int stance_room(urStance* st) {
  st->x0 = malloc((st->nx0 + 1) * sizeof(double));
  st->qpos = malloc((st->nq + 1) * sizeof(double));
  st->rst = malloc((st->nrst + 1) * sizeof(double));
  st->pair = malloc((st->npair + 1) * sizeof(urPairData));
  return st->x0 && st->qpos && st->rst && st->pair ? 0 : -1;
}

/* the key of m's person (before balancing) and room for its settled state; NULL: no memory */
static urStance* stance_new(const urModel* m, int drone, double settle_time, int iters) {
  urStance* st = calloc(1, sizeof *st);
  if (!st) return NULL;
  st->ok = 1;
  st->top = -INFINITY;
  double h = settle_step(m);
  int integ = (int)m->opt.integrator;
  PUT(st, settle_time);
  PUT(st, iters);
  PUT(st, h);
  PUT(st, m->opt.gravity);
  PUT(st, integ);
  PUT(st, m->opt.implicit_damping);
  PUT(st, m->opt.vmax); /* stop and memcache change no result, nor adapt the settling's (it
                           has no projectile): not in the key */
  for (int b = 0; b < m->nbody; b++) {
    if (ur_body_intree(m, b, drone)) continue;
    put_body(st, m, b);
    st->nx0 += 3;
    st->nq += m->body[b].nq;
    st->nrst += 2 * m->body[b].nv;
  }
  for (int g = 0; g < m->ngeom; g++) {
    if (!ur_geom_intree(m, g, drone)) put_geom(st, m, g);
  }
  for (int i = 0; i < m->npair; i++) {
    if (!person_pair(m, i, drone)) continue;
    PUT(st, i);
    put_str(st, m->pair[i].name);
    PUT(st, m->pair[i].geom1);
    PUT(st, m->pair[i].geom2);
    put_law(st, &m->pair[i].law);
    st->npair++;
  }
  uint64_t hash = 14695981039346656037ULL;
  for (size_t k = 0; k < st->nkey; k++) hash = (hash ^ st->key[k]) * 1099511628211ULL;
  st->hash = hash;
  if (!st->ok || stance_room(st)) {
    stance_free(st);
    return NULL;
  }
  return st;
}

/* the same person: the same key, to the byte */
static int stance_same(const urStance* a, const urStance* b) {
  return a->hash == b->hash && a->nkey == b->nkey && !memcmp(a->key, b->key, a->nkey);
}

static urStance* stance_copy(const urStance* a) {
  urStance* st = malloc(sizeof *st);
  if (!st) return NULL;
  *st = *a;
  st->key = malloc(a->nkey + 1);
  st->capkey = a->nkey + 1;
  if (stance_room(st) || !st->key) {
    stance_free(st);
    return NULL;
  }
  memcpy(st->key, a->key, a->nkey);
  memcpy(st->x0, a->x0, a->nx0 * sizeof(double));
  memcpy(st->qpos, a->qpos, a->nq * sizeof(double));
  memcpy(st->rst, a->rst, a->nrst * sizeof(double));
  memcpy(st->pair, a->pair, a->npair * sizeof(urPairData));
  return st;
}

/* the balanced x0 of the person's restraints: from m into st (save), or from st into m */
static void stance_x0(urStance* st, urModel* m, int drone, int save) {
  int ix = 0;
  for (int b = 0; b < m->nbody; b++) {
    if (ur_body_intree(m, b, drone)) continue;
    for (int k = 0; k < 3; k++, ix++) {
      if (save)
        st->x0[ix] = m->body[b].rst[k].x0;
      else
        m->body[b].rst[k].x0 = st->x0[ix];
    }
  }
}

/* the person's settled coordinates, restraint extremes and pair histories: from the settled
   state d into st (save), or from st into d (layouts equal: the keys are) */
static void stance_state(urStance* st, const urModel* m, urData* d, int drone, int save) {
  int iq = 0, ir = 0, ip = 0;
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    if (ur_body_intree(m, b, drone)) continue;
    double* q = d->qpos + bd->qadr;
    double* r = d->rst + 2 * bd->vadr;
    size_t nq = bd->nq * sizeof(double), nr = 2 * bd->nv * sizeof(double);
    memcpy(save ? st->qpos + iq : q, save ? q : st->qpos + iq, nq);
    memcpy(save ? st->rst + ir : r, save ? r : st->rst + ir, nr);
    iq += bd->nq;
    ir += 2 * bd->nv;
  }
  for (int i = 0; i < m->npair; i++) {
    if (!person_pair(m, i, drone)) continue;
    memcpy(save ? st->pair + ip : d->pair + i, save ? d->pair + i : st->pair + ip,
           sizeof(urPairData));
    ip++;
  }
  if (!save) ur_contacts_relist(m, d);
}

/* ---- the set-up ---- */

/* the stance as a state of rest: every motion stopped, the drone parked in its reference posture
   without restraint or contact history, no run under way (ur_run_start resets the same), then
   the forward pass. What remains of the settling is the person's coordinates, restraint
   extremes and pair histories. */
static void rest(const urModel* m, urData* d, int drone) {
  memset(d->qvel, 0, m->nv * sizeof(double));
  hold(m, d, drone);
  for (int i = 0; i < m->npair; i++) {
    if (person_pair(m, i, drone)) continue;
    memset(d->pair + i, 0, sizeof(urPairData));
    d->pdepth[i] = -INFINITY;
  }
  memset(d->bag, 0, m->nbag * sizeof(urBagData));
  for (int k = 0; k < m->nsensordata; k++) {
    d->peakmax[k] = -INFINITY;
    d->peakmin[k] = INFINITY;
    d->tpeak[k] = 0;
  }
  memset(d->scratch, 0, (2 * (size_t)m->nq + 8 * (size_t)m->nv) * sizeof(double));
  d->time = 0;
  d->nstep = 0;
  d->t_calm = 0;
  ur_set_free(m, d, drone, PARK, QID, ZERO3, ZERO3);
  ur_forward(m, d);
}

/* the roles an impact needs, declared by the model: 0, or -1 with the missing one in err */
static int roles_check(const urModel* m, char* err, size_t n) {
  const urRoles* ro = &m->roles;
  if (ro->drone < 0 || m->body[ro->drone].jtype != urJNT_FREE) {
    snprintf(err, n,
             "the model declares no drone: add 'role drone=BODY' (its root body, free "
             "joint)");
    return -1;
  }
  if (ro->head < 0 || ro->head_acc < 0 || ro->neck < 0 || ro->head_pos < 0) {
    snprintf(err, n,
             "the model declares no %s: add 'role head=ELLIPSOID head_acc=SENSOR "
             "neck=SENSOR head_pos=SENSOR'",
             ro->head < 0       ? "head"
             : ro->head_acc < 0 ? "head_acc"
             : ro->neck < 0     ? "neck"
                                : "head_pos");
    return -1;
  }
  return 0;
}

/* the contact candidates (pairs and airbag targets, the ground excluded) between the drone's
   tree and the person's */
static int drone_person_cands(const urModel* m, int drone) {
  urCand cd;
  int n = 0;
  for (int k = 0; ur_cand_at(m, k, &cd) == 0; k++) {
    if (cd.g2 >= 0) n += ur_geom_intree(m, cd.g1, drone) != ur_geom_intree(m, cd.g2, drone);
  }
  return n;
}

int ur_impact_check(const urModel* m, char* err, size_t n) {
  double dt = m->opt.dt, tmax = m->opt.tmax;
  double settle_dt = ur_model_param(m, "settle_dt", NAN), window = ur_model_param(m, "window", 1);
  if (roles_check(m, err, n)) {
    return -1;
  } else if (drone_person_cands(m, m->roles.drone) == 0) {
    snprintf(err, n,
             "the model has no contact pair between the drone and the person (every impact "
             "would pass through the person and give P = 0); accepted: a model with a pair, "
             "pairs or airbag targets= joining an ellipsoid of the drone to one of the person "
             "(uasimpact-model(5))");
  } else if (!(dt > 0 && dt <= 1e-3)) {
    snprintf(err, n,
             "dt %g s is out of range; accepted: (0, 1e-3] s (a contact pulse lasts "
             "about 1 ms: a coarser step cannot follow it)",
             dt);
  } else if (!(tmax > 0 && tmax <= 1)) {
    snprintf(err, n,
             "tmax %g s is out of range; accepted: (0, 1] s (an impact is over within "
             "0.15 s; a longer run only fills memory with its histories)",
             tmax);
  } else if (!(tmax / dt <= 1e5)) {
    snprintf(err, n,
             "tmax/dt = %.3g steps; accepted: at most 1e5 steps of one impact (each "
             "impact keeps its histories in memory, about 30 MB at 1e5 steps)",
             tmax / dt);
  } else if (!isnan(settle_dt) && !(settle_dt >= dt && settle_dt <= 0.01)) {
    snprintf(err, n,
             "settle_dt %g s is out of range; accepted: [dt, 0.01] s = [%g, 0.01] s "
             "(the stance never settles with a finer step than the impact's, and 1 s of settling "
             "needs at least 100 steps)",
             settle_dt, dt);
  } else if (!(window > 0)) {
    snprintf(err, n,
             "window %g s is out of range; accepted: > 0 s (an impact ends this long "
             "after its first contact)",
             window);
  } else {
    if (n) err[0] = 0;
    return 0;
  }
  return -1;
}

/* the roles, R_max and the stance: settled (from NULL; the person's settled state saved into
   keep if given, top raised as settle does), or the settled state of from, whose person is m's */
static int setup(urImpactSetup* s, const urModel* m, double settle_time, const urStance* from,
                 urStance* keep, double* top) {
  memset(s, 0, sizeof *s);
  s->m = m;
  if (m->nraw) {
    ur_model_raw_text(m, s->err, sizeof s->err);
    return -1;
  }

  /* the roles the model declares (role statements, uasimpact-model(5)) */
  const urRoles* ro = &m->roles;
  s->drone = ro->drone;
  s->head_geom = ro->head;
  s->s_head_acc = ro->head_acc;
  s->s_neck = ro->neck;
  s->s_chest = ro->chest;
  s->s_abd = ro->abdomen;
  if (roles_check(m, s->err, sizeof s->err)) {
    return -1;
  }

  /* the ellipsoid pairs through which the drone can act on the person */
  int nslot = ur_cand_slots(m);
  s->cand = malloc((size_t)(ur_cand_count(m) + 1) * sizeof *s->cand);
  s->cand_src = malloc((size_t)(ur_cand_count(m) + 1) * sizeof *s->cand_src);
  s->cand_of = malloc((size_t)(nslot + 1) * sizeof *s->cand_of);
  if (!s->cand || !s->cand_src || !s->cand_of) {
    snprintf(s->err, sizeof s->err, "out of memory");
    return -1;
  }
  for (int i = 0; i < nslot; i++) s->cand_of[i] = -1;
  urCand cd;
  for (int k = 0; ur_cand_at(m, k, &cd) == 0; k++) {
    if (cd.g2 < 0) continue;
    int ina = ur_geom_intree(m, cd.g1, s->drone), inb = ur_geom_intree(m, cd.g2, s->drone);
    if (ina == inb) continue;
    s->cand[s->ncand][0] = ina ? cd.g1 : cd.g2;
    s->cand[s->ncand][1] = ina ? cd.g2 : cd.g1;
    s->cand_src[s->ncand] = cd.src;
    s->cand_of[cd.src] = s->ncand;
    s->ncand++;
  }

  /* R_max: farthest surface point of the drone's ellipsoids from its centre of mass */
  urData* d = ur_data_new(m);
  if (!d) {
    snprintf(s->err, sizeof s->err, "out of memory");
    return -1;
  }
  ur_kinematics(m, d);
  const double* cm = d->xcom + 3 * s->drone;
  for (int g = 0; g < m->ngeom; g++) {
    if (!ur_geom_intree(m, g, s->drone)) continue;
    double r = 0, *c = d->gxpos + 3 * g;
    for (int k = 0; k < 3; k++) r += (c[k] - cm[k]) * (c[k] - cm[k]);
    r = sqrt(r) + m->geom[g].rbound;
    if (r > s->rmax) s->rmax = r;
  }

  /* settle the stance under gravity with the drone parked far above, or take a settled one */
  if (from) {
    park(m, d, s->drone);
    stance_state((urStance*)from, m, d, s->drone, 0);
  } else if (!isfinite(settle(m, d, s->drone, settle_time, top))) {
    snprintf(s->err, sizeof s->err, "the stance did not settle: %.120s", d->msg);
    ur_data_free(d);
    return -1;
  } else if (keep) {
    stance_state(keep, m, d, s->drone, 1);
  }

  /* a state of rest */
  rest(m, d, s->drone);
  if (top) *top = fmax(*top, person_top(m, d, s->drone));
  const double* sd = d->sensordata;
  memcpy(s->head_cg, sd + m->sensor[m->roles.head_pos].adr, 3 * sizeof(double));
  s->head_top = ellipsoid_top(m, d, s->head_geom);
  s->overlap = 0;
  s->overlap_geom = -1;
  for (int k = 0; k < s->ncand; k++) { /* the drone starts with no part below the head top */
    int g = s->cand[k][1];
    double above = ellipsoid_top(m, d, g) - s->head_top;
    if (above > s->overlap) {
      s->overlap = above;
      s->overlap_geom = g;
    }
  }
  s->neck_preload = -sd[m->sensor[s->s_neck].adr + 2];
  s->rest = d;
  s->window = ur_model_param(m, "window", INFINITY);
  s->endrun = ur_model_param(m, "endrun", 0) != 0;
  return 0;
}

int ur_impact_setup(urImpactSetup* s, const urModel* m, double settle_time) {
  return setup(s, m, settle_time, NULL, NULL, NULL);
}

/* no airbag on the person (its gas state would be part of the stance), and nothing the drone
   touches but the person (no pair between two of its ellipsoids or with the ground, no airbag
   target on it): held at rest, the drone then takes the same step every time */
static int trees_apart(const urModel* m, int drone) {
  for (int i = 0; i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    if (!ur_geom_intree(m, b->geom, drone)) return 0;
    for (int t = 0; t < b->ntarget; t++) {
      if (ur_geom_intree(m, b->target[t], drone)) return 0;
    }
  }
  for (int i = 0; i < m->npair; i++) {
    const urPair* p = m->pair + i;
    int in1 = ur_geom_intree(m, p->geom1, drone);
    int in2 = p->geom2 < 0 || ur_geom_intree(m, p->geom2, drone);
    if (in1 && in2) return 0;
  }
  return 1;
}

int ur_impact_prepare(urImpactSetup* s, urModel* m, double settle_time, int iters,
                      const urImpactSetup* const* donors, int ndonor) {
  memset(s, 0, sizeof *s);
  s->m = m;
  int drone = m->roles.drone;
  if (m->nraw) {
    ur_model_raw_text(m, s->err, sizeof s->err);
    return -2;
  }
  if (drone < 0 || m->body[drone].jtype != urJNT_FREE || m->body[drone].parent >= 0) {
    snprintf(s->err, sizeof s->err,
             "the model declares no drone: add 'role drone=BODY' (its "
             "root body, free joint)");
    return -2;
  }
  urData* d = ur_data_new(m);
  if (!d) {
    snprintf(s->err, sizeof s->err, "out of memory");
    return -2;
  }
  urStance* st = stance_new(m, drone, settle_time, iters); /* before balancing */
  park(m, d, drone);
  double low = drone_low(m, d, drone);
  int apart = trees_apart(m, drone);
  double ptop = person_top(m, d, drone), reach = parked_reach(m, d, drone);
  if (!(reach > ptop)) {
    snprintf(s->err, sizeof s->err,
             "the drone is too large to wait clear of the person while the stance settles: "
             "parked %.3g km up it reaches down to %.3g m (the person's top %.3g m)",
             PARK[2] / 1000, reach, ptop);
    stance_free(st);
    ur_data_free(d);
    return -2;
  }

  /* a donor with the same person, whose settling stayed below this drone's parked spheres (so
     the trees never touch), and this drone takes its held step without failing (as it would at
     every step of a settling): the donor's balanced x0 and settled person are what settling
     would give */
  const urStance* from = NULL;
  for (int i = 0; st && apart && i < ndonor && !from; i++) {
    const urStance* a = donors[i] ? donors[i]->stance : NULL;
    if (a && a->shareable && stance_same(st, a) && low > a->top) from = a;
  }
  if (from && isfinite(settle(m, d, drone, settle_step(m), NULL))) {
    urStance* mine = stance_copy(from);
    if (mine) {
      stance_free(st);
      ur_data_free(d);
      stance_x0(mine, m, drone, 0);
      int rc = setup(s, m, settle_time, mine, NULL, NULL);
      s->stance = mine;
      s->shared = 1;
      return rc ? -2 : 0;
    }
  }
  ur_data_free(d);

  /* settle: balance, then the stance */
  double top = -INFINITY;
  if (balance(m, drone, settle_time, iters, NULL, &top)) {
    stance_free(st);
    snprintf(s->err, sizeof s->err, "the standing posture cannot be balanced (it falls)");
    return -1;
  }
  if (setup(s, m, settle_time, NULL, st, &top)) {
    stance_free(st);
    return -2;
  }
  if (st) {
    stance_x0(st, m, drone, 1);
    st->top = top;
    st->shareable = apart && low > top;
  }
  s->stance = st;
  return 0;
}

void ur_impact_free(urImpactSetup* s) {
  ur_data_free(s->rest);
  stance_free(s->stance);
  free(s->cand);
  free(s->cand_src);
  free(s->cand_of);
  memset(s, 0, sizeof *s);
}
