/* engine_util.c: self-contained vector, quaternion and spatial-algebra helpers (uru_ prefix).
 * Spatial vectors are (angular, linear); a transform (E, p) maps parent to child coordinates with
 * E the rotation parent -> child and p the child origin in parent coordinates. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- 3-vectors and 3x3 matrices ----------------------------------

int uru_normalize3(double a[3]) {
  double n = uru_norm3(a);
  if (n <= 0 || !isfinite(n)) {
    return -1;
  }
  a[0] /= n;
  a[1] /= n;
  a[2] /= n;
  return 0;
}


//---------------------------------- quaternions (w, x, y, z) -------------------------------------

void uru_normalizequat(double q[4]) {
  double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0 && isfinite(n)) {
    urUNROLL for (int i = 0; i < 4; i++) {
      q[i] /= n;
    }
  } else {
    q[0] = 1;
    q[1] = q[2] = q[3] = 0;
  }
}


void uru_axisangle2quat(double q[4], const double axis[3], double angle) {
  double a[3] = {axis[0], axis[1], axis[2]}, s, c;
  uru_sincos(0.5 * angle, &s, &c);
  uru_normalize3(a);
  q[0] = c;
  q[1] = s * a[0];
  q[2] = s * a[1];
  q[3] = s * a[2];
}


// uru_quatintegrate, uru_quat2rotvec and uru_rotvec_jrinv for doubles, from their template
#define urT       double
#define urM       int
#define urK(name) uru_##name
#define urSTORAGE
#define urBC(x)        (x)
#define urSEL(m, a, b) ((m) ? (a) : (b))
#define urSQRT(x)      sqrt(x)
#include "kernels/engine_quat.h"
#undef urT
#undef urM
#undef urK
#undef urSTORAGE
#undef urBC
#undef urSEL
#undef urSQRT
#include "kernels/engine_template_check.h"


//---------------------------------- spatial algebra -----------------------------------------------

// spatial inertia (6x6 row-major) at the body origin from mass, CoM and inertia about the CoM
void uru_rbi(double I[36], double mass, const double com[3], const double Ic[9]) {
  double cc = uru_dot3(com, com);
  double cx[9] = {0, -com[2], com[1], com[2], 0, -com[0], -com[1], com[0], 0};
  memset(I, 0, 36 * sizeof(double));
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      I[6 * i + j] = Ic[3 * i + j] + mass * ((i == j) * cc - com[i] * com[j]);
      I[6 * i + 3 + j] = mass * cx[3 * i + j];
      I[6 * (i + 3) + j] = -mass * cx[3 * i + j];
    }
    I[6 * (i + 3) + 3 + i] = mass;
  }
}


// the congruence X^T I X for doubles (uru_xinertia_t_add), from its template
#define urT       double
#define urK(name) uru_##name
#define urSTORAGE
#include "kernels/engine_spatial_inertia.h"
#undef urT
#undef urK
#undef urSTORAGE
#include "kernels/engine_template_check.h"


// uru_invsym for doubles, from its template
#define urT       double
#define urK(name) uru_##name
#define urSTORAGE
#define urBC(x)   (x)
#define urALL(c)  (c)
#define urSQRT(x) sqrt(x)
#include "kernels/engine_invsym.h"
#undef urT
#undef urK
#undef urSTORAGE
#undef urBC
#undef urALL
#undef urSQRT
#include "kernels/engine_template_check.h"
