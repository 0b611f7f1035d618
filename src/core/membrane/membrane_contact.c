/* membrane_contact.c: penalty contact of the membrane with an ellipsoid or superellipsoid (the
 * person's and the carrier's own bodies). A point is inside when the shape's gauge
 * s = ||diag(1/r) R^T (x - c)||_p is below 1; its depth is the first-order distance
 * (1 - s) / |grad s| along the outward normal grad s (negative outside: the gap). The contact is
 * a pressure on the fabric's surface, k_a times the depth (a Winkler foundation), acting on the
 * penetrated part of each triangle: the depth is interpolated linearly over a triangle between
 * points where it is evaluated, the triangle is clipped at the zero contour and the pressure
 * integrated exactly against the linear shape functions (urm_contact_clip), so the contact force
 * is the integral of a contact pressure over the contact patch and the patch is where that
 * pressure acts. The stiffness comes from stability, not from a material: per area
 * k_a = alpha rhot / max(dt, kc_dt)^2 (materials-membrane C.4: a node of mass m = rhot A feels at
 * most k_a A, stable at the step dt for alpha <= 1 and the same at every step below kc_dt, so
 * that halving dt leaves the contact as it was; a stiffer alpha is made implicit along the normal
 * by the engine, engine_membrane.c), with damping 2 zeta sqrt(k_a rhot) per area on the approach
 * rate and regularised Coulomb friction on the sliding velocity (its viscous slope capped at the
 * share's whole mass over max(dt, kc_dt), which stops the sliding in one step at most and is the
 * same at every dt below kc_dt). */
#include <math.h>

#include "membrane_internal.h"

double urm_contact_gap(const urEllipsoid* e, const double x[3], int full, double n[3]) {
  // local coordinates, gauge and its gradient
  double d[3], xl[3], gl[3];
  urm_sub(d, x, e->c);
  for (int k = 0; k < 3; k++) {
    xl[k] = (e->R[k] * d[0] + e->R[3 + k] * d[1] + e->R[6 + k] * d[2]) / e->r[k];
  }
  // outside the box around the shape: its gauge is at least the largest |xl| (what follows would
  // find s >= 1 too; this spares a superellipsoid's powers)
  if (!full && (fabs(xl[0]) >= 1 || fabs(xl[1]) >= 1 || fabs(xl[2]) >= 1)) {
    return -INFINITY;
  }
  double p = e->p > 2 ? e->p : 2, sg;
  if (p == 2) {
    sg = sqrt(urm_dot(xl, xl));
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
    double q = sg > 0 ? pow(sg, 1 - p) : 0;
    for (int k = 0; k < 3; k++) {
      gl[k] = sg > 0 ? q * copysign(a[k], xl[k]) / e->r[k] : (k == 2) / e->r[k];
    }
  }
  if (!full && !(sg < 1)) {
    return -INFINITY;
  }
  for (int k = 0; k < 3; k++) {
    n[k] = e->R[3 * k] * gl[0] + e->R[3 * k + 1] * gl[1] + e->R[3 * k + 2] * gl[2];
  }
  double gn = sqrt(urm_dot(n, n));
  if (!(gn > 0) || !isfinite(sg)) {
    return -INFINITY;
  }
  for (int k = 0; k < 3; k++) {
    n[k] /= gn;
  }
  return (1 - sg) / gn;
}


double urm_contact_force(const urMemSpec* s, double dt, const double n[3], const double vr[3],
                         double I, double A, double ac, double f[3]) {
  f[0] = f[1] = f[2] = 0;
  double dk = fmax(dt, s->kc_dt), ka = s->kc_alpha * s->rhot / (dk * dk);
  double ca = 2 * s->zeta_c * sqrt(ka * s->rhot);
  double vn = urm_dot(vr, n);
  double fn = ka * I - ca * A * vn;
  if (!(fn > 0)) {
    return 0;
  }
  double vt[3];
  for (int k = 0; k < 3; k++) {
    vt[k] = vr[k] - vn * n[k];
  }
  double st = sqrt(urm_dot(vt, vt));
  // at most what stops the share's mass sliding in one step of the penalty (explicit stability
  // of the regularised law: rhot ac / dk <= its mass over dt since dk >= dt); over the share's
  // whole area and kc_dt, not its penetrated part and dt, so that neither the step nor how deep
  // flat facets dip into a curved body sets the grip (tests/core/membrane/test_membrane_engine.c)
  double ff = fmin(s->mu * fn / fmax(st, s->v_eps), s->rhot * ac / dk);
  for (int k = 0; k < 3; k++) {
    f[k] = fn * n[k] - ff * vt[k];
  }
  return fn;
}


/* the integrals over one triangle of area a (corners' depths d, at barycentric coordinates mu of
   the clipped triangle) added to I, A, E: int d N_u, int N_u, int d^2 */
static void clip_add(const double d[3], const double mu[3][3], double a, double I[3], double A[3],
                     double* E) {
  double sd = d[0] + d[1] + d[2];
  for (int u = 0; u < 3; u++) {
    double dn = 0, sn = 0;
    for (int w = 0; w < 3; w++) {
      dn += d[w] * mu[w][u];
      sn += mu[w][u];
    }
    // int f g = a / 12 (sum f_w g_w + sum f_w sum g_w) for linear f, g
    I[u] += a / 12 * (dn + sd * sn);
    A[u] += a / 3 * sn;
  }
  *E += a / 6 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
}


void urm_contact_clip(const double d[3], double I[3], double A[3], double* E) {
  I[0] = I[1] = I[2] = A[0] = A[1] = A[2] = *E = 0;
  // the polygon where the interpolated depth is positive: corners inside and the edges' zeros,
  // in order around the triangle (3 or 4 corners), then a fan from its first corner
  double mu[4][3], dp[4];
  int np = 0;
  for (int k = 0; k < 3; k++) {
    int l = (k + 1) % 3;
    if (d[k] > 0) {
      mu[np][0] = mu[np][1] = mu[np][2] = 0;
      mu[np][k] = 1;
      dp[np++] = d[k];
    }
    if ((d[k] > 0) != (d[l] > 0)) {
      double t = d[k] / (d[k] - d[l]);
      mu[np][0] = mu[np][1] = mu[np][2] = 0;
      mu[np][k] = 1 - t;
      mu[np][l] = t;
      dp[np++] = 0;
    }
  }
  for (int j = 1; j + 1 < np; j++) {
    const double* q[3] = {mu[0], mu[j], mu[j + 1]};
    // the area of a triangle of barycentric corners q is |det q| of the whole
    double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                 q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                 q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    double m3[3][3], d3[3] = {dp[0], dp[j], dp[j + 1]};
    for (int w = 0; w < 3; w++) {
      for (int u = 0; u < 3; u++) {
        m3[w][u] = q[w][u];
      }
    }
    clip_add(d3, (const double(*)[3])m3, fabs(det), I, A, E);
  }
}


double urm_contact_node(const urMemSpec* s, double dt, const urEllipsoid* e, const double o[3],
                        const double vo[3], const double w[3], const double x[3], const double v[3],
                        double m, double f[3]) {
  f[0] = f[1] = f[2] = 0;
  double n[3];
  double depth = urm_contact_gap(e, x, 0, n);
  if (!(depth > 0)) {
    return 0;
  }
  // relative velocity of the node against the body's surface point
  double r[3], wr[3], vr[3];
  urm_sub(r, x, o);
  urm_cross(wr, w, r);
  for (int k = 0; k < 3; k++) {
    vr[k] = v[k] - vo[k] - wr[k];
  }
  // a node of mass m stands for the area m / rhot at its depth
  double A = m / s->rhot;
  urm_contact_force(s, dt, n, vr, A * depth, A, A, f);
  return depth;
}


void urm_shape_box(const urEllipsoid* e, double gh[3]) {
  for (int k = 0; k < 3; k++) {
    double w[3] = {e->r[0] * e->R[3 * k], e->r[1] * e->R[3 * k + 1], e->r[2] * e->R[3 * k + 2]};
    // a superellipsoid's q-norm (q < 2) bounded by the 1-norm: no calls of pow
    double h = e->p > 2 ? fabs(w[0]) + fabs(w[1]) + fabs(w[2]) : sqrt(urm_dot(w, w));
    gh[k] = h * (1 + 1e-9) + 1e-9;
  }
}
