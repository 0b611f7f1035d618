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


// inverse of a small n x n symmetric matrix (closed forms up to 3, Cholesky beyond, which
// needs positive definiteness); -1 if singular
int uru_invsym(double* Ainv, const double* A, int n) {
  // closed forms for 1 x 1 and 2 x 2
  if (n == 1) {
    if (!(A[0] != 0)) {
      return -1;
    }
    Ainv[0] = 1/A[0];
    return 0;
  }
  if (n == 2) {
    double det = A[0]*A[3] - A[1]*A[2];
    if (!(det != 0)) {
      return -1;
    }
    Ainv[0] = A[3]/det;
    Ainv[1] = -A[1]/det;
    Ainv[2] = -A[2]/det;
    Ainv[3] = A[0]/det;
    return 0;
  }
  if (n == 3) {
    double c0 = A[4]*A[8] - A[5]*A[7], c1 = A[5]*A[6] - A[3]*A[8], c2 = A[3]*A[7] - A[4]*A[6];
    double det = A[0]*c0 + A[1]*c1 + A[2]*c2;
    if (!(det != 0)) {
      return -1;
    }
    double id = 1/det;
    Ainv[0] = c0*id;
    Ainv[1] = (A[2]*A[7] - A[1]*A[8])*id;
    Ainv[2] = (A[1]*A[5] - A[2]*A[4])*id;
    Ainv[3] = c1*id;
    Ainv[4] = (A[0]*A[8] - A[2]*A[6])*id;
    Ainv[5] = (A[2]*A[3] - A[0]*A[5])*id;
    Ainv[6] = c2*id;
    Ainv[7] = (A[1]*A[6] - A[0]*A[7])*id;
    Ainv[8] = (A[0]*A[4] - A[1]*A[3])*id;
    return 0;
  }
  // Cholesky A = L L^T, then A^-1 = L^-T L^-1 (A symmetric positive definite)
  double L[36] = {0}, Li[36] = {0};
  for (int j = 0; j < n; j++) {
    double s = A[n*j + j];
    for (int k = 0; k < j; k++) {
      s -= L[6*j + k]*L[6*j + k];
    }
    if (!(s > 0)) {
      return -1;
    }
    L[6*j + j] = sqrt(s);
    for (int i = j + 1; i < n; i++) {
      double t = A[n*i + j];
      for (int k = 0; k < j; k++) {
        t -= L[6*i + k]*L[6*j + k];
      }
      L[6*i + j] = t/L[6*j + j];
    }
  }

  // invert the triangle
  for (int j = 0; j < n; j++) {
    Li[6*j + j] = 1/L[6*j + j];
    for (int i = j + 1; i < n; i++) {
      double t = 0;
      for (int k = j; k < i; k++) {
        t -= L[6*i + k]*Li[6*k + j];
      }
      Li[6*i + j] = t/L[6*i + i];
    }
  }

  // A^-1 = Li^T Li
  for (int i = 0; i < n; i++) {
    for (int j = i; j < n; j++) {
      double t = 0;
      for (int k = j; k < n; k++) {
        t += Li[6*k + i]*Li[6*k + j];
      }
      Ainv[n*i + j] = t;
      Ainv[n*j + i] = t;
    }
  }
  return 0;
}
