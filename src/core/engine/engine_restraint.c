/* engine_restraint.c: joint restraints: per-dof spring-damper with a tabulated nonlinear
 * load-deflection curve, optional hysteresis (unloading curve scaled through the largest
 * deflection reached), and end stops. Spherical joints use the rotation-vector components of
 * the relative rotation, with the exact map to body-frame torques. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- elastic force -------------------------------------------------

// curve value, odd-symmetric extension if the curve has no negative abscissae
static double curve(const urCurve* c, double x) {
  if (c->n <= 0) {
    return 0;
  }
  if (c->x[0] >= 0 && x < 0) {
    return -ur_curve_eval(c, -x);
  }
  return ur_curve_eval(c, x);
}


// elastic generalised force at deflection x with extremes st = (max, min) reached so far
static double elastic(const urRestraint* r, double x, const double st[2]) {
  double f = r->sat > 0 ? r->sat * tanh(r->k * x / r->sat) : r->k * x;
  if (r->load.n <= 0) {
    return f;
  }

  // loading beyond the extreme of this side, or no hysteresis
  double xm = x >= 0 ? st[0] : st[1];
  if (r->unload.n <= 0 || fabs(x) >= fabs(xm)) {
    return f + curve(&r->load, x);
  }

  // unloading: the unloading curve scaled through (xm, load(xm))
  double um = curve(&r->unload, xm);
  if (um == 0) {
    return f + curve(&r->load, x);
  }
  return f + curve(&r->load, xm) * curve(&r->unload, x) / um;
}


// total restraint force on one dof at deflection x, rate xd
static double rforce(const urRestraint* r, double x, double xd, const double st[2]) {
  double f = elastic(r, x, st) + r->c * xd;
  if (r->hi > r->lo) {
    if (x > r->hi) {
      f += r->kstop * (x - r->hi) + r->cstop * xd;
    } else if (x < r->lo) {
      f += r->kstop * (x - r->lo) + r->cstop * xd;
    }
  }
  return f;
}


// deflections of a joint (rotation vector for spherical joints); returns the count
static int deflection(const urModel* m, const urData* d, int i, double x[3]) {
  const urBody* b = m->body + i;
  const double* q = d->qpos + b->qadr;
  switch (b->jtype) {
  case urJNT_REVOLUTE:
  case urJNT_PRISMATIC:
  case urJNT_UNIVERSAL:
    for (int k = 0; k < b->nv; k++) {
      x[k] = q[k] - b->rst[k].x0;
    }
    return b->nv;
  case urJNT_SPHERICAL:
    uru_quat2rotvec(x, q);
    for (int k = 0; k < 3; k++) {
      x[k] -= b->rst[k].x0;
    }
    return 3;
  default: return 0;
  }
}

//---------------------------------- passes --------------------------------------------------------

// the deflections and inverse Jacobians of the spherical restraints into d->rkin (the lanes
// compute the same over vectors: engine_lanes.c)
void ur_restraints_kin(const urModel* m, urData* d) {
  uru_restraints_kin(m, d->qpos, d->rkin);
}


// generalised restraint forces into d->qfrc (subtracted); the spherical ones need
// ur_restraints_kin
void ur_restraints(const urModel* m, urData* d) {
  for (int j = 0; j < m->nrstb; j++) {
    int i = m->rstb[j];
    const urBody* b = m->body + i;
    double x[3], f[3] = {0, 0, 0};
    int n = b->jtype == urJNT_SPHERICAL ? 3 : deflection(m, d, i, x);
    const double* xs = b->jtype == urJNT_SPHERICAL ? d->rkin + 12 * i : x;
    if (!n) {
      continue;
    }
    const double* qd = d->qvel + b->vadr;

    // elastic and viscous force per dof
    for (int k = 0; k < n; k++) {
      if (b->rst[k].active) {
        const double* st = d->rst + 2 * (b->vadr + k);
        if (b->jtype == urJNT_SPHERICAL) {
          f[k] = rforce(b->rst + k, xs[k], 0, st);
        } else {
          f[k] = rforce(b->rst + k, xs[k], qd[k], st);
        }
      }
    }

    // spherical: map rotation-vector forces to body torques, damping on omega
    if (b->jtype == urJNT_SPHERICAL) {
      double t[3];
      uru_mulmat3tvec(t, xs + 3, f);
      for (int k = 0; k < 3; k++) {
        f[k] = t[k] + (b->rst[k].active ? b->rst[k].c * qd[k] : 0);
      }
    }
    for (int k = 0; k < n; k++) {
      d->qfrc[b->vadr + k] -= f[k];
    }
  }
}


// record the extreme deflections reached (accepted steps only) on every dof with a curve: the
// unloading curves start there, and ur_extrapolated compares them with the curves' data
void ur_restraints_commit(const urModel* m, urData* d) {
  for (int j = 0; j < m->nhyst; j++) {
    int i = m->hyst[j];
    const urBody* b = m->body + i;
    double x[3];
    int n = deflection(m, d, i, x);
    for (int k = 0; k < n; k++) {
      double* st = d->rst + 2 * (b->vadr + k);
      if (b->rst[k].active && b->rst[k].load.n > 0) {
        if (x[k] > st[0]) {
          st[0] = x[k];
        }
        if (x[k] < st[1]) {
          st[1] = x[k];
        }
      }
    }
  }
}
