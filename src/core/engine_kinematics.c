/* engine_kinematics.c: joint transforms and motion subspaces (jcalc), world poses of bodies and
 * ellipsoids, point positions, velocities and accelerations. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- joints --------------------------------------------------------

// rotation matrix about a unit axis
static void axisrot(double R[9], const double a[3], double ang) {
  double q[4];
  uru_axisangle2quat(q, a, ang);
  uru_quat2mat(R, q);
}


// joint transform (Xe, Xr), motion subspace S (6 x nv, row-major) and S-dot qdot (in cbias)
void ur_jcalc(const urModel* m, urData* d, int i) {
  const urBody* b = m->body + i;
  const double* q = d->qpos + b->qadr;
  const double* qd = d->qvel + b->vadr;
  double R[9], T[9], p[3];
  const double* Rb = b->bmat;
  double* S = d->S + 36*i;
  double* cj = d->cbias + 6*i;
  int nv = b->nv;

  // relative pose and subspace by joint type
  memset(S, 0, 36*sizeof(double));
  memset(cj, 0, 6*sizeof(double));
  memcpy(p, b->pos, sizeof(p));
  switch (b->jtype) {
  case urJNT_FREE: {
    // qpos: CoM in parent + quat; qvel: CoM velocity in parent + omega in body
    double rc[3], vb[3], t[3];
    uru_quat2mat(R, q+3);
    uru_mulmat3vec(rc, R, b->com);
    for (int k = 0; k < 3; k++) {
      p[k] = q[k] - rc[k];
    }
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        S[nv*(3+r) + c] = R[3*c + r];
      }
      S[nv*r + 3 + r] = 1;
    }
    const double* c = b->com;
    S[nv*3 + 4] = -c[2];
    S[nv*3 + 5] = c[1];
    S[nv*4 + 3] = c[2];
    S[nv*4 + 5] = -c[0];
    S[nv*5 + 3] = -c[1];
    S[nv*5 + 4] = c[0];
    uru_mulmat3tvec(vb, R, qd);
    uru_cross3(t, qd+3, vb);
    cj[3] = -t[0];
    cj[4] = -t[1];
    cj[5] = -t[2];
    break;
  }
  case urJNT_FIXED:
    memcpy(R, Rb, 9*sizeof(double));
    break;
  case urJNT_REVOLUTE:
    axisrot(T, b->axis[0], q[0]);
    uru_mulmat3(R, Rb, T);
    S[0] = b->axis[0][0];
    S[1] = b->axis[0][1];
    S[2] = b->axis[0][2];
    break;
  case urJNT_UNIVERSAL: {
    // R = Rb Rot(a1, q0) Rot(a2, q1); s1 = Rot(a2, q1)^T a1, s2 = a2
    double T2[9], s1[3], t[3];
    axisrot(T, b->axis[0], q[0]);
    axisrot(T2, b->axis[1], q[1]);
    uru_mulmat3(R, Rb, T);
    uru_mulmat3(R, R, T2);
    uru_mulmat3tvec(s1, T2, b->axis[0]);
    for (int k = 0; k < 3; k++) {
      S[nv*k] = s1[k];
      S[nv*k + 1] = b->axis[1][k];
    }
    uru_cross3(t, s1, b->axis[1]);
    for (int k = 0; k < 3; k++) {
      cj[k] = qd[0]*qd[1]*t[k];
    }
    break;
  }
  case urJNT_SPHERICAL:
    uru_quat2mat(T, q);
    uru_mulmat3(R, Rb, T);
    S[0] = S[nv + 1] = S[2*nv + 2] = 1;
    break;
  case urJNT_PRISMATIC: {
    double t[3];
    memcpy(R, Rb, 9*sizeof(double));
    uru_mulmat3vec(t, Rb, b->axis[0]);
    for (int k = 0; k < 3; k++) {
      p[k] += q[0]*t[k];
      S[3+k] = b->axis[0][k];
    }
    break;
  }
  }

  // store the transform parent -> child
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) {
      d->Xe[9*i + 3*r + c] = R[3*c + r];
    }
  }
  memcpy(d->Xr + 3*i, p, sizeof(p));
}

//---------------------------------- world poses ---------------------------------------------------

void ur_kinematics(const urModel* m, urData* d) {
  // bodies, in tree order
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    double* xm = d->xmat + 9*i;
    double* xp = d->xpos + 3*i;
    double R[9];
    ur_jcalc(m, d, i);
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        R[3*r + c] = d->Xe[9*i + 3*c + r];
      }
    }
    if (b->parent < 0) {
      memcpy(xm, R, sizeof(R));
      memcpy(xp, d->Xr + 3*i, 3*sizeof(double));
    } else {
      const double* pm = d->xmat + 9*b->parent;
      const double* pp = d->xpos + 3*b->parent;
      double t[3];
      uru_mulmat3(xm, pm, R);
      uru_mulmat3vec(t, pm, d->Xr + 3*i);
      for (int k = 0; k < 3; k++) {
        xp[k] = pp[k] + t[k];
      }
    }
    double c[3];
    uru_mulmat3vec(c, xm, b->com);
    for (int k = 0; k < 3; k++) {
      d->xcom[3*i + k] = xp[k] + c[k];
    }
  }

  // ellipsoids
  for (int g = 0; g < m->ngeom; g++) {
    const urGeom* ge = m->geom + g;
    const double* xm = d->xmat + 9*ge->body;
    double t[3];
    uru_mulmat3(d->gxmat + 9*g, xm, ge->gmat);
    uru_mulmat3vec(t, xm, ge->pos);
    for (int k = 0; k < 3; k++) {
      d->gxpos[3*g + k] = d->xpos[3*ge->body + k] + t[k];
    }
  }
}

//---------------------------------- points --------------------------------------------------------

void ur_point_pos(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  double t[3];
  uru_mulmat3vec(t, d->xmat + 9*body, p);
  for (int k = 0; k < 3; k++) {
    out[k] = d->xpos[3*body + k] + t[k];
  }
}


void ur_point_vel(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  const double* v = d->cvel + 6*body;
  double t[3];
  uru_cross3(t, v, p);
  for (int k = 0; k < 3; k++) {
    t[k] += v[3+k];
  }
  uru_mulmat3vec(out, d->xmat + 9*body, t);
}


// kinematic acceleration of a body point, world (cacc holds the -gravity base acceleration)
void ur_point_acc(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  const double* v = d->cvel + 6*body;
  const double* a = d->cacc + 6*body;
  double t[3], u[3], w[3];
  uru_cross3(t, a, p);
  uru_cross3(u, v, p);
  for (int k = 0; k < 3; k++) {
    u[k] += v[3+k];
  }
  uru_cross3(w, v, u);
  for (int k = 0; k < 3; k++) {
    t[k] += a[3+k] + w[k];
  }
  uru_mulmat3vec(out, d->xmat + 9*body, t);
  for (int k = 0; k < 3; k++) {
    out[k] += m->opt.gravity[k];
  }
}

//---------------------------------- velocities ----------------------------------------------------

// velocity of body i with nv dofs and nonzero rows k0..k1-1 of S (inlined, constant sizes)
static inline __attribute__((always_inline))
void bodyvel(const urModel* m, urData* d, int i, const int nv, const int k0, const int k1) {
  const urBody* b = m->body + i;
  const double* S = d->S + 36*i;
  const double* qd = d->qvel + b->vadr;
  double vJ[6] = {0, 0, 0, 0, 0, 0}, t[6];
  double* v = d->cvel + 6*i;

  // joint velocity
urUNROLL
  for (int r = k0; r < k1; r++) {
urUNROLL
    for (int c = 0; c < nv; c++) {
      vJ[r] += S[nv*r + c]*qd[c];
    }
  }

  // add the parent's velocity
  if (b->parent >= 0) {
    uru_xmotion(v, d->Xe + 9*i, d->Xr + 3*i, d->cvel + 6*b->parent);
  } else {
    memset(v, 0, 6*sizeof(double));
  }
  for (int k = 0; k < 6; k++) {
    v[k] += vJ[k];
  }

  // bias acceleration
  uru_crossmotion(t, v, vJ);
  for (int k = 0; k < 6; k++) {
    d->cbias[6*i + k] += t[k];
  }
}


// spatial body velocities (cvel) and velocity-product accelerations (cbias += v x vJ)
void ur_velocities(const urModel* m, urData* d) {
  for (int i = 0; i < m->nbody; i++) {
    switch (m->body[i].jtype) {
    case urJNT_FREE:
      bodyvel(m, d, i, 6, 0, 6);
      break;
    case urJNT_FIXED:
      bodyvel(m, d, i, 0, 0, 0);
      break;
    case urJNT_REVOLUTE:
      bodyvel(m, d, i, 1, 0, 3);
      break;
    case urJNT_UNIVERSAL:
      bodyvel(m, d, i, 2, 0, 3);
      break;
    case urJNT_SPHERICAL:
      bodyvel(m, d, i, 3, 0, 3);
      break;
    case urJNT_PRISMATIC:
      bodyvel(m, d, i, 1, 3, 6);
      break;
    }
  }
}
