/* engine_restraint.c: joint restraints: per-dof spring-damper with a tabulated nonlinear
 * load-deflection curve, optional hysteresis (unloading curve scaled through the largest
 * deflection reached), end stops, or an elastic-plastic hinge (kinematic hardening, optional
 * fracture, after which the hinge carries no moment and its joint releases: engine_fracture.c). Spherical joints use the rotation-vector components of
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


// kinematic hardening's back-moment slope: the tangent beyond mp is k b / (k + b) = kh
double uru_back_slope(const urRestraint* r) {
  return r->kh > 0 && r->kh < r->k ? r->k * r->kh / (r->k - r->kh) : 0;
}


// elastic-plastic hinge moment at deflection x from the committed plastic deflection xp
// (return mapping of 1-D linear kinematic hardening: |M - b xp| <= mp); *dxp: the plastic
// increment this deflection would commit
static double plastic(const urRestraint* r, double x, double xp, double* dxp) {
  double b = uru_back_slope(r), m = r->k * (x - xp), over = fabs(m - b * xp) - r->mp;
  *dxp = 0;
  if (over > 0) {
    *dxp = (m - b * xp > 0 ? over : -over) / (r->k + b);
    m = r->k * (x - xp - *dxp);
  }
  return m;
}


// elastic generalised force at deflection x with extremes st = (max, min) reached so far
// (a plastic hinge: st = (plastic deflection, broken))
static double elastic(const urRestraint* r, double x, const double st[2]) {
  if (r->mp > 0) {
    double dxp;
    return st[1] != 0 ? 0 : plastic(r, x, st[0], &dxp);
  }
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
  double f = elastic(r, x, st) + (r->mp > 0 && st[1] != 0 ? 0 : r->c * xd);
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
  ur_restraints_kin_joints(m, d->qpos, d->rkin);
}


// whether the lanes compute body i's restraint forces over the vectors (engine_lanes.c's
// restraints4): a revolute, prismatic, universal or spherical joint whose active dofs are linear
// springs (no curve, no saturation) or plastic hinges, with dampers and stops
int ur_restraint_vec(const urModel* m, int i) {
  const urBody* b = m->body + i;
  if (b->jtype != urJNT_REVOLUTE && b->jtype != urJNT_PRISMATIC && b->jtype != urJNT_UNIVERSAL &&
      b->jtype != urJNT_SPHERICAL) {
    return 0;
  }
  for (int k = 0; k < 3; k++) {
    const urRestraint* r = b->rst + k;
    if (r->active && !(r->mp > 0) && (r->sat > 0 || r->load.n > 0)) {
      return 0;
    }
  }
  return 1;
}


// generalised restraint forces of the bodies rstb[0..n-1] (m->rstb: all) into d->qfrc
// (subtracted); the spherical ones need ur_restraints_kin
void ur_restraints(const urModel* m, urData* d, const int* rstb, int nrstb) {
  for (int j = 0; j < nrstb; j++) {
    int i = rstb[j];
    const urBody* b = m->body + i;
    double x[3], f[3] = {0, 0, 0};
    int n = b->jtype == urJNT_SPHERICAL ? 3 : deflection(m, d, i, x);
    const double* xs = b->jtype == urJNT_SPHERICAL ? d->rkin + 12 * i : x;
    if (!n) {
      continue;
    }
    const double* qd = d->qvel + b->vadr;
    double* qf = d->qfrc + b->vadr;
    int sph = b->jtype == urJNT_SPHERICAL;

    // elastic and viscous force per dof, subtracted at once where it is the dof's own (each
    // force on its own: f[] read back as a pair of the scalar stores just made stalled the
    // store forwarding)
    for (int k = 0; k < n; k++) {
      if (b->rst[k].active) {
        const double* st = d->rst + 2 * (b->vadr + k);
        f[k] = rforce(b->rst + k, xs[k], sph ? 0 : qd[k], st);
      }
      if (!sph) {
        qf[k] -= f[k];
      }
    }

    // spherical: map rotation-vector forces to body torques, damping on omega
    if (sph) {
      double t[3];
      uru_mulmat3tvec(t, xs + 3, f);
      for (int k = 0; k < 3; k++) {
        const double* st = d->rst + 2 * (b->vadr + k);
        int broken = b->rst[k].mp > 0 && st[1] != 0;
        qf[k] -= t[k] + (b->rst[k].active && !broken ? b->rst[k].c * qd[k] : 0);
      }
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
      const urRestraint* r = b->rst + k;
      if (r->active && r->mp > 0 && st[1] == 0) {
        // plastic hinge: commit the plastic deflection; fracture once |M| reaches mfrac
        double dxp, mo = plastic(r, x[k], st[0], &dxp);
        st[0] += dxp;
        if (r->mfrac > 0 && fabs(mo) >= r->mfrac) {
          st[1] = d->time > 0 ? d->time : 1e-300;
        }
        continue;
      }
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


int ur_hinge_state(const urModel* m, const urData* d, int body, int dof, double* xp,
                   double* tbreak) {
  if (body < 0 || body >= m->nbody || dof < 0 || dof >= m->body[body].nv || dof > 2 ||
      m->body[body].jtype == urJNT_FREE || !m->body[body].rst[dof].active ||
      !(m->body[body].rst[dof].mp > 0)) {
    return -1;
  }
  const double* st = d->rst + 2 * (m->body[body].vadr + dof);
  *xp = st[0];
  *tbreak = st[1];
  return 0;
}
