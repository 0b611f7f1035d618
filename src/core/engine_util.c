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
  double n = sqrt(q[0]*q[0] + q[1]*q[1] + q[2]*q[2] + q[3]*q[3]);
  if (n > 0 && isfinite(n)) {
    urUNROLL
    for (int i = 0; i < 4; i++) {
      q[i] /= n;
    }
  } else {
    q[0] = 1;
    q[1] = q[2] = q[3] = 0;
  }
}


void uru_axisangle2quat(double q[4], const double axis[3], double angle) {
  double a[3] = {axis[0], axis[1], axis[2]};
  double s = sin(0.5*angle);
  uru_normalize3(a);
  q[0] = cos(0.5*angle);
  q[1] = s*a[0];
  q[2] = s*a[1];
  q[3] = s*a[2];
}


// q <- q * exp(omega dt / 2), omega in the local frame
void uru_quatintegrate(double q[4], const double omega[3], double dt) {
  double w = uru_norm3(omega);
  double th = w*dt, dq[4];
  if (th < 1e-300) {
    return;
  }
  double s = sin(0.5*th)/w;
  dq[0] = cos(0.5*th);
  dq[1] = s*omega[0];
  dq[2] = s*omega[1];
  dq[3] = s*omega[2];
  uru_mulquat(q, q, dq);
  uru_normalizequat(q);
}


// rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion
void uru_quat2rotvec(double v[3], const double q[4]) {
  double w = q[0], x = q[1], y = q[2], z = q[3];
  if (w < 0) {
    w = -w;
    x = -x;
    y = -y;
    z = -z;
  }
  double s = sqrt(x*x + y*y + z*z);
  double ang = 2*atan2(s, w);
  double f = s > 1e-12 ? ang/s : 2.0/(w > 0 ? w : 1.0);
  v[0] = f*x;
  v[1] = f*y;
  v[2] = f*z;
}


// inverse right Jacobian of SO(3): d(rotvec)/dt = Jrinv * omega_local
void uru_rotvec_jrinv(double J[9], const double v[3]) {
  double th = uru_norm3(v), c2;
  if (th < 1e-4) {
    c2 = 1.0/12.0 + th*th/720.0;
  } else {
    c2 = 1.0/(th*th) - (1 + cos(th))/(2*th*sin(th));
  }
  double K[9] = {0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0}, K2[9];
  uru_mulmat3(K2, K, K);
  urUNROLL
  for (int i = 0; i < 9; i++) {
    J[i] = 0.5*K[i] + c2*K2[i];
  }
  J[0] += 1;
  J[4] += 1;
  J[8] += 1;
}

//---------------------------------- spatial algebra -----------------------------------------------

// spatial inertia (6x6 row-major) at the body origin from mass, CoM and inertia about the CoM
void uru_rbi(double I[36], double mass, const double com[3], const double Ic[9]) {
  double cc = uru_dot3(com, com);
  double cx[9] = {0, -com[2], com[1], com[2], 0, -com[0], -com[1], com[0], 0};
  memset(I, 0, 36*sizeof(double));
  urUNROLL
  for (int i = 0; i < 3; i++) {
    urUNROLL
    for (int j = 0; j < 3; j++) {
      I[6*i+j] = Ic[3*i+j] + mass*((i == j)*cc - com[i]*com[j]);
      I[6*i+3+j] = mass*cx[3*i+j];
      I[6*(i+3)+j] = -mass*cx[3*i+j];
    }
    I[6*(i+3)+3+i] = mass;
  }
}


// the congruence X^T I X for doubles (uru_xinertia_t_add), from its template
#define urT double
#define urK(name) uru_##name
#define urSTORAGE
#include "engine_spatial_inertia.h"
#undef urT
#undef urK
#undef urSTORAGE


// uru_invsym for doubles, from its template
#define urT double
#define urK(name) uru_##name
#define urSTORAGE
#define urBC(x) (x)
#define urALL(c) (c)
#define urSQRT(x) sqrt(x)
#include "engine_invsym.h"
#undef urT
#undef urK
#undef urSTORAGE
#undef urBC
#undef urALL
#undef urSQRT
