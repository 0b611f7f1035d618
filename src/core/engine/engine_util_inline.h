/* engine_util_inline.h: the small vector, matrix and spatial-algebra kernels of engine_util.c
 * that run many times per step, inlined into their callers (included by engine_internal.h). */
#ifndef UASIMPACT_ENGINE_UTIL_INLINE_H
#define UASIMPACT_ENGINE_UTIL_INLINE_H

#include <math.h>
#include <string.h>

static inline double uru_dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// the templated kernels for doubles (uru_cross3, uru_mulmat3vec, ..., uru_mul6)
#define urT       double
#define urK(name) uru_##name
#include "kernels/engine_spatial.h"
#undef urT
#undef urK
#include "kernels/engine_template_check.h"

static inline double uru_norm3(const double a[3]) {
  return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// r = A^T B
static inline void uru_mulmat3ta(double r[9], const double A[9], const double B[9]) {
  double t[9];
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      t[3 * i + j] = A[i] * B[j] + A[3 + i] * B[3 + j] + A[6 + i] * B[6 + j];
    }
  }
  memcpy(r, t, sizeof(t));
}

// r = A B^T
static inline void uru_mulmat3tb(double r[9], const double A[9], const double B[9]) {
  double t[9];
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      t[3 * i + j] =
          A[3 * i] * B[3 * j] + A[3 * i + 1] * B[3 * j + 1] + A[3 * i + 2] * B[3 * j + 2];
    }
  }
  memcpy(r, t, sizeof(t));
}

// motion vector child -> parent: w = E^T w', v = E^T v' + p x w
static inline void uru_xmotion_inv(double r[6], const double E[9], const double p[3],
                                   const double v[6]) {
  double w[3], l[3], t[3];
  uru_mulmat3tvec(w, E, v);
  uru_mulmat3tvec(l, E, v + 3);
  uru_cross3(t, p, w);
  r[0] = w[0];
  r[1] = w[1];
  r[2] = w[2];
  r[3] = l[0] + t[0];
  r[4] = l[1] + t[1];
  r[5] = l[2] + t[2];
}

// sincos and the first-quadrant atan2 for doubles (uru_sincos, uru_atan2q), from their template
static inline unsigned long long uru_asi(double x) {
  unsigned long long i;
  memcpy(&i, &x, sizeof(i));
  return i;
}

static inline double uru_ast(unsigned long long i) {
  double x;
  memcpy(&x, &i, sizeof(x));
  return x;
}

#define urT            double
#define urM            int
#define urU            unsigned long long
#define urK(name)      uru_##name
#define urBC(x)        (x)
#define urSEL(m, a, b) ((m) ? (a) : (b))
#define urANY(m)       (m)
#define urNEL          1
#define urEL(x, l)     (x)
#define urASI(x)       uru_asi(x)
#define urAST(i)       uru_ast(i)
#include "kernels/engine_trig.h"
#undef urT
#undef urM
#undef urU
#undef urK
#undef urBC
#undef urSEL
#undef urANY
#undef urNEL
#undef urEL
#undef urASI
#undef urAST
#include "kernels/engine_template_check.h"

#endif
