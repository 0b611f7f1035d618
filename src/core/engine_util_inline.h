/* engine_util_inline.h: the small vector, matrix and spatial-algebra kernels of engine_util.c
 * that run many times per step, inlined into their callers (included by engine_internal.h). */
#ifndef UASRISK_ENGINE_UTIL_INLINE_H
#define UASRISK_ENGINE_UTIL_INLINE_H

#include <math.h>

static inline double uru_dot3(const double a[3], const double b[3]) {
  return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

static inline void uru_cross3(double r[3], const double a[3], const double b[3]) {
  double t0 = a[1]*b[2] - a[2]*b[1];
  double t1 = a[2]*b[0] - a[0]*b[2];
  double t2 = a[0]*b[1] - a[1]*b[0];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

static inline double uru_norm3(const double a[3]) {
  return sqrt(a[0]*a[0] + a[1]*a[1] + a[2]*a[2]);
}

static inline void uru_mulmat3vec(double r[3], const double M[9], const double v[3]) {
  double t0 = M[0]*v[0] + M[1]*v[1] + M[2]*v[2];
  double t1 = M[3]*v[0] + M[4]*v[1] + M[5]*v[2];
  double t2 = M[6]*v[0] + M[7]*v[1] + M[8]*v[2];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

static inline void uru_mulmat3tvec(double r[3], const double M[9], const double v[3]) {
  double t0 = M[0]*v[0] + M[3]*v[1] + M[6]*v[2];
  double t1 = M[1]*v[0] + M[4]*v[1] + M[7]*v[2];
  double t2 = M[2]*v[0] + M[5]*v[1] + M[8]*v[2];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

static inline void uru_mulmat3(double r[9], const double A[9], const double B[9]) {
  double t[9];
  urUNROLL
  for (int i = 0; i < 3; i++) {
    urUNROLL
    for (int j = 0; j < 3; j++) {
      t[3*i+j] = A[3*i]*B[j] + A[3*i+1]*B[3+j] + A[3*i+2]*B[6+j];
    }
  }
  memcpy(r, t, sizeof(t));
}

// r = A^T B
static inline void uru_mulmat3ta(double r[9], const double A[9], const double B[9]) {
  double t[9];
  urUNROLL
  for (int i = 0; i < 3; i++) {
    urUNROLL
    for (int j = 0; j < 3; j++) {
      t[3*i+j] = A[i]*B[j] + A[3+i]*B[3+j] + A[6+i]*B[6+j];
    }
  }
  memcpy(r, t, sizeof(t));
}

// r = A B^T
static inline void uru_mulmat3tb(double r[9], const double A[9], const double B[9]) {
  double t[9];
  urUNROLL
  for (int i = 0; i < 3; i++) {
    urUNROLL
    for (int j = 0; j < 3; j++) {
      t[3*i+j] = A[3*i]*B[3*j] + A[3*i+1]*B[3*j+1] + A[3*i+2]*B[3*j+2];
    }
  }
  memcpy(r, t, sizeof(t));
}

static inline void uru_quat2mat(double R[9], const double q[4]) {
  double w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2*(y*y + z*z);
  R[1] = 2*(x*y - w*z);
  R[2] = 2*(x*z + w*y);
  R[3] = 2*(x*y + w*z);
  R[4] = 1 - 2*(x*x + z*z);
  R[5] = 2*(y*z - w*x);
  R[6] = 2*(x*z - w*y);
  R[7] = 2*(y*z + w*x);
  R[8] = 1 - 2*(x*x + y*y);
}

static inline void uru_mulquat(double r[4], const double a[4], const double b[4]) {
  double t[4];
  t[0] = a[0]*b[0] - a[1]*b[1] - a[2]*b[2] - a[3]*b[3];
  t[1] = a[0]*b[1] + a[1]*b[0] + a[2]*b[3] - a[3]*b[2];
  t[2] = a[0]*b[2] - a[1]*b[3] + a[2]*b[0] + a[3]*b[1];
  t[3] = a[0]*b[3] + a[1]*b[2] - a[2]*b[1] + a[3]*b[0];
  memcpy(r, t, sizeof(t));
}

// motion vector parent -> child: w' = E w, v' = E (v - p x w)
static inline void uru_xmotion(double r[6], const double E[9], const double p[3], const double v[6]) {
  double t[3];
  uru_cross3(t, p, v);
  t[0] = v[3] - t[0];
  t[1] = v[4] - t[1];
  t[2] = v[5] - t[2];
  uru_mulmat3vec(r, E, v);
  uru_mulmat3vec(r+3, E, t);
}

// motion vector child -> parent: w = E^T w', v = E^T v' + p x w
static inline void uru_xmotion_inv(double r[6], const double E[9], const double p[3], const double v[6]) {
  double w[3], l[3], t[3];
  uru_mulmat3tvec(w, E, v);
  uru_mulmat3tvec(l, E, v+3);
  uru_cross3(t, p, w);
  r[0] = w[0];
  r[1] = w[1];
  r[2] = w[2];
  r[3] = l[0] + t[0];
  r[4] = l[1] + t[1];
  r[5] = l[2] + t[2];
}

// force vector child -> parent (X^T f): f = E^T f', n = E^T n' + p x f
static inline void uru_xforce_t(double r[6], const double E[9], const double p[3], const double f[6]) {
  double n[3], l[3], t[3];
  uru_mulmat3tvec(n, E, f);
  uru_mulmat3tvec(l, E, f+3);
  uru_cross3(t, p, l);
  r[0] = n[0] + t[0];
  r[1] = n[1] + t[1];
  r[2] = n[2] + t[2];
  r[3] = l[0];
  r[4] = l[1];
  r[5] = l[2];
}

// motion cross product v x m
static inline void uru_crossmotion(double r[6], const double v[6], const double m[6]) {
  double a[3], b[3], c[3];
  uru_cross3(a, v, m);
  uru_cross3(b, v, m+3);
  uru_cross3(c, v+3, m);
  r[0] = a[0];
  r[1] = a[1];
  r[2] = a[2];
  r[3] = b[0] + c[0];
  r[4] = b[1] + c[1];
  r[5] = b[2] + c[2];
}

// force cross product v x* f
static inline void uru_crossforce(double r[6], const double v[6], const double f[6]) {
  double a[3], b[3], c[3];
  uru_cross3(a, v, f);
  uru_cross3(b, v+3, f+3);
  uru_cross3(c, v, f+3);
  r[0] = a[0] + b[0];
  r[1] = a[1] + b[1];
  r[2] = a[2] + b[2];
  r[3] = c[0];
  r[4] = c[1];
  r[5] = c[2];
}

static inline void uru_mul6(double r[6], const double I[36], const double v[6]) {
  double t[6];
  urUNROLL
  for (int i = 0; i < 6; i++) {
    const double* row = I + 6*i;
    t[i] = row[0]*v[0] + row[1]*v[1] + row[2]*v[2] + row[3]*v[3] + row[4]*v[4] + row[5]*v[5];
  }
  memcpy(r, t, sizeof(t));
}

#endif
