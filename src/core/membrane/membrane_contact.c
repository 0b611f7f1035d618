/* membrane_contact.c: penalty contact of one membrane node with an ellipsoid or superellipsoid
 * (the person's and the carrier's own bodies): the node is inside when the shape's gauge
 * s = ||diag(1/r) R^T (x - c)||_p is below 1; the depth is the first-order distance
 * (1 - s) / |grad s| along the outward normal grad s; the stiffness comes from stability, not
 * from a material (k = alpha m / max(dt, kc_dt)^2, materials-membrane C.4: stable at the step dt,
 * and the same at every step below kc_dt, so that halving dt leaves the contact as it was), with
 * damping 2 zeta sqrt(k m) on
 * the approach rate and regularised Coulomb friction on the sliding velocity (its viscous
 * slope capped at m / dt, which stops the sliding in one step at most). */
#include <math.h>

#include "membrane_internal.h"

double urm_contact_node(const urMemSpec* s, double dt, const urEllipsoid* e, const double o[3],
                        const double vo[3], const double w[3], const double x[3], const double v[3],
                        double m, double f[3]) {
  f[0] = f[1] = f[2] = 0;

  // local coordinates, gauge and its gradient
  double d[3], xl[3], gl[3];
  urm_sub(d, x, e->c);
  for (int k = 0; k < 3; k++) {
    xl[k] = (e->R[k] * d[0] + e->R[3 + k] * d[1] + e->R[6 + k] * d[2]) / e->r[k];
  }
  // outside the box around the shape: its gauge is at least the largest |xl| (what follows would
  // find s >= 1 too; this spares a superellipsoid's powers)
  if (fabs(xl[0]) >= 1 || fabs(xl[1]) >= 1 || fabs(xl[2]) >= 1) {
    return 0;
  }
  double p = e->p > 2 ? e->p : 2, sg;
  if (p == 2) {
    sg = sqrt(urm_dot(xl, xl));
    if (!(sg < 1)) {
      return 0;
    }
    for (int k = 0; k < 3; k++) {
      gl[k] = sg > 0 ? xl[k] / (sg * e->r[k]) : (k == 2) / e->r[k];
    }
  } else {
    double a[3], sum = 0;
    for (int k = 0; k < 3; k++) {
      a[k] = pow(fabs(xl[k]), p - 1);
      sum += a[k] * fabs(xl[k]);
    }
    sg = pow(sum, 1 / p);
    if (!(sg < 1)) {
      return 0;
    }
    double q = sg > 0 ? pow(sg, 1 - p) : 0;
    for (int k = 0; k < 3; k++) {
      gl[k] = sg > 0 ? q * copysign(a[k], xl[k]) / e->r[k] : (k == 2) / e->r[k];
    }
  }
  double n[3];
  for (int k = 0; k < 3; k++) {
    n[k] = e->R[3 * k] * gl[0] + e->R[3 * k + 1] * gl[1] + e->R[3 * k + 2] * gl[2];
  }
  double gn = sqrt(urm_dot(n, n));
  if (!(gn > 0)) {
    return 0;
  }
  for (int k = 0; k < 3; k++) {
    n[k] /= gn;
  }
  double depth = (1 - sg) / gn;

  // relative velocity of the node against the body's surface point
  double r[3], wr[3], vr[3];
  urm_sub(r, x, o);
  urm_cross(wr, w, r);
  for (int k = 0; k < 3; k++) {
    vr[k] = v[k] - vo[k] - wr[k];
  }
  double vn = urm_dot(vr, n);
  double dk = fmax(dt, s->kc_dt), kc = s->kc_alpha * m / (dk * dk);
  double cc = 2 * s->zeta_c * sqrt(kc * m);
  double fn = kc * depth - cc * vn;
  if (!(fn > 0)) {
    return depth;
  }
  double vt[3];
  for (int k = 0; k < 3; k++) {
    vt[k] = vr[k] - vn * n[k];
  }
  double st = sqrt(urm_dot(vt, vt));
  // at most what stops the sliding in one step (explicit stability of the regularised law)
  double ff = fmin(s->mu * fn / fmax(st, s->v_eps), m / dt);
  for (int k = 0; k < 3; k++) {
    f[k] = fn * n[k] - ff * vt[k];
  }
  return depth;
}
