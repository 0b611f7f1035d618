/* contact_curv.c: the Hertz radius of two ellipsoids from their curvature at the contact: the
 * principal relative curvatures are the eigenvalues of K_A + K_B, each body's curvature tensor
 * in the common tangent plane, and the equivalent radius R_e = 1 / sqrt(det(K_A + K_B)) (the
 * geometric mean of the principal relative radii; for two spheres 1/R = 1/R1 + 1/R2) */
#include <math.h>
#include "uasimpact/contact.h"

/* curvature tensor of ellipsoid e at its surface point x (world) in the tangent basis t1, t2:
   for |R^T (x - c) / r|^2 = 1, kappa(t) = t' D t / |D y| with y local, D = diag(1/r^2) */
static void curvature(const urEllipsoid* e, const double x[3], const double t1[3],
                      const double t2[3], double k[3]) {
  double y[3], a[3], b[3], D[3];
  for (int i = 0; i < 3; i++) {
    double s = 0, u = 0, v = 0;
    for (int j = 0; j < 3; j++) {
      s += e->R[3 * j + i] * (x[j] - e->c[j]); /* R^T (x - c) */
      u += e->R[3 * j + i] * t1[j];
      v += e->R[3 * j + i] * t2[j];
    }
    y[i] = s;
    a[i] = u;
    b[i] = v;
    D[i] = 1 / (e->r[i] * e->r[i]);
  }
  double g =
      sqrt(D[0] * D[0] * y[0] * y[0] + D[1] * D[1] * y[1] * y[1] + D[2] * D[2] * y[2] * y[2]);
  k[0] = k[1] = k[2] = 0;
  if (!(g > 0)) return;
  for (int i = 0; i < 3; i++) {
    k[0] += D[i] * a[i] * a[i] / g;
    k[1] += D[i] * a[i] * b[i] / g;
    k[2] += D[i] * b[i] * b[i] / g;
  }
}

double ur_contact_radius(const urEllipsoid* a, const urEllipsoid* b, const urGeomContact* gc) {
  /* a tangent basis of the contact plane */
  const double* n = gc->n;
  double h[3] = {1, 0, 0};
  if (fabs(n[0]) > 0.6) {
    h[0] = 0;
    h[1] = 1;
  }
  double t1[3] = {n[1] * h[2] - n[2] * h[1], n[2] * h[0] - n[0] * h[2], n[0] * h[1] - n[1] * h[0]};
  double l = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (int i = 0; i < 3; i++) t1[i] /= l;
  double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                  n[0] * t1[1] - n[1] * t1[0]};
  double ka[3], kb[3] = {0, 0, 0};
  curvature(a, gc->pa, t1, t2, ka);
  if (b) curvature(b, gc->pb, t1, t2, kb);
  double k11 = ka[0] + kb[0], k12 = ka[1] + kb[1], k22 = ka[2] + kb[2];
  double det = k11 * k22 - k12 * k12;
  double r = det > 0 ? 1 / sqrt(det) : urHERTZ_RMAX;
  return r < urHERTZ_RMAX ? r : urHERTZ_RMAX;
}
