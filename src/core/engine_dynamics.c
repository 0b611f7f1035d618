/* engine_dynamics.c: Featherstone's articulated-body algorithm over a forest of trees, joint
 * reaction loads by a Newton-Euler backward pass, energies and momenta. All spatial quantities in
 * body coordinates at the body origin (the joint anchor). */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- articulated-body algorithm ------------------------------------

// base acceleration (-gravity) expressed in root body i
static void baseacc(const urModel* m, const urData* d, int i, double a[6]) {
  double a0[6] = {0, 0, 0, -m->opt.gravity[0], -m->opt.gravity[1], -m->opt.gravity[2]};
  uru_xmotion(a, d->Xe + 9*i, d->Xr + 3*i, a0);
}


// pass 2 of the ABA for body i with nv dofs and nonzero rows k0..k1-1 of S (inlined with
// constant sizes so that the small loops unroll)
static inline __attribute__((always_inline))
void pass2(const urModel* m, urData* d, int i, const int nv, const int k0, const int k1) {
  const urBody* b = m->body + i;
  const double* S = d->S + 36*i;
  double* IA = d->IA + 36*i;
  double* pA = d->pA + 6*i;
  double* U = d->U + 36*i;
  double* Dinv = d->Dinv + 36*i;
  double* u = d->uu + 6*i;
  double Ia[36], pa[6], D[36], UD[36], t[6];

  // U = IA S, D = S^T U, u = tau - S^T pA (spherical: S = [1; 0], so U = IA[:, 0:3])
  if (nv == 3 && k1 == 3) {
    urUNROLL
    for (int r = 0; r < 6; r++) {
      urUNROLL
      for (int c = 0; c < 3; c++) {
        U[3*r + c] = IA[6*r + c];
      }
    }
    urUNROLL
    for (int r = 0; r < 3; r++) {
      u[r] = d->qfrc[b->vadr + r] - pA[r];
      urUNROLL
      for (int c = 0; c < 3; c++) {
        D[3*r + c] = IA[6*r + c];
      }
    }
  } else {
    urUNROLL
    for (int r = 0; r < 6; r++) {
      urUNROLL
      for (int c = 0; c < nv; c++) {
        double s = 0;
        urUNROLL
        for (int k = k0; k < k1; k++) {
          s += IA[6*r + k]*S[nv*k + c];
        }
        U[nv*r + c] = s;
      }
    }
    urUNROLL
    for (int r = 0; r < nv; r++) {
      double s = d->qfrc[b->vadr + r];
      urUNROLL
      for (int k = k0; k < k1; k++) {
        s -= S[nv*k + r]*pA[k];
      }
      u[r] = s;
      urUNROLL
      for (int c = 0; c < nv; c++) {
        double e = 0;
        urUNROLL
        for (int k = k0; k < k1; k++) {
          e += S[nv*k + r]*U[nv*k + c];
        }
        D[nv*r + c] = e;
      }
    }
  }
  // implicit joint damping: the restraint's linear damper acts at the new velocity, so the
  // joint-space inertia gains dt c on its diagonal (an armature; exact for M + dt C)
  if (m->opt.implicit_damping && m->opt.integrator == urINT_EULER) {
    for (int r = 0; r < nv && r < 3; r++) {
      if (b->rst[r].active) {
        D[nv*r + r] += m->opt.dt*b->rst[r].c;
      }
    }
  }
  if (nv && uru_invsym(Dinv, D, nv)) {
    ur_set_status(d, urSTAT_NONFINITE, "singular joint-space inertia");
    memset(Dinv, 0, 36*sizeof(double));
  }
  if (b->parent < 0) {
    return;
  }

  // Ia = IA - U Dinv U^T (symmetric), pa = pA + Ia c + U Dinv u
  memcpy(Ia, IA, sizeof(Ia));
  memcpy(pa, pA, sizeof(pa));
  if (nv) {
    double Du[6];
    urUNROLL
    for (int r = 0; r < 6; r++) {
      urUNROLL
      for (int c = 0; c < nv; c++) {
        double s = 0;
        urUNROLL
        for (int k = 0; k < nv; k++) {
          s += U[nv*r + k]*Dinv[nv*k + c];
        }
        UD[nv*r + c] = s;
      }
    }
    urUNROLL
    for (int r = 0; r < 6; r++) {
      urUNROLL
      for (int c = r; c < 6; c++) {
        double s = 0;
        urUNROLL
        for (int k = 0; k < nv; k++) {
          s += UD[nv*r + k]*U[nv*c + k];
        }
        Ia[6*r + c] -= s;
        if (c != r) {
          Ia[6*c + r] -= s;
        }
      }
    }
    urUNROLL
    for (int r = 0; r < nv; r++) {
      double s = 0;
      urUNROLL
      for (int k = 0; k < nv; k++) {
        s += Dinv[nv*r + k]*u[k];
      }
      Du[r] = s;
    }
    urUNROLL
    for (int r = 0; r < 6; r++) {
      urUNROLL
      for (int k = 0; k < nv; k++) {
        pa[r] += U[nv*r + k]*Du[k];
      }
    }
  }
  uru_mul6(t, Ia, d->cbias + 6*i);
  urUNROLL
  for (int k = 0; k < 6; k++) {
    pa[k] += t[k];
  }

  // accumulate into the parent
  uru_xinertia_t_add(d->IA + 36*b->parent, d->Xe + 9*i, d->Xr + 3*i, Ia);
  uru_xforce_t(t, d->Xe + 9*i, d->Xr + 3*i, pa);
  urUNROLL
  for (int k = 0; k < 6; k++) {
    d->pA[6*b->parent + k] += t[k];
  }
}


// pass 3 of the ABA for body i with nv dofs (inlined with constant nv)
static inline __attribute__((always_inline))
void pass3(const urModel* m, urData* d, int i, const int nv) {
  const urBody* b = m->body + i;
  const double* S = d->S + 36*i;
  const double* U = d->U + 36*i;
  const double* Dinv = d->Dinv + 36*i;
  const double* u = d->uu + 6*i;
  double* a = d->cacc + 6*i;
  double* qdd = d->qacc + b->vadr;
  double r[6];

  // parent acceleration plus bias
  if (b->parent >= 0) {
    uru_xmotion(a, d->Xe + 9*i, d->Xr + 3*i, d->cacc + 6*b->parent);
  } else {
    baseacc(m, d, i, a);
  }
  urUNROLL
  for (int k = 0; k < 6; k++) {
    a[k] += d->cbias[6*i + k];
  }

  // joint accelerations: qdd = Dinv (u - U^T a), then a += S qdd
  urUNROLL
  for (int c = 0; c < nv; c++) {
    double s = u[c];
    urUNROLL
    for (int k = 0; k < 6; k++) {
      s -= U[nv*k + c]*a[k];
    }
    r[c] = s;
  }
  urUNROLL
  for (int c = 0; c < nv; c++) {
    double s = 0;
    urUNROLL
    for (int k = 0; k < nv; k++) {
      s += Dinv[nv*c + k]*r[k];
    }
    qdd[c] = s;
  }
  urUNROLL
  for (int k = 0; k < 6; k++) {
    urUNROLL
    for (int c = 0; c < nv; c++) {
      a[k] += S[nv*k + c]*qdd[c];
    }
  }
}


// needs ur_kinematics, ur_velocities, joint forces d->qfrc and external forces d->fext
void ur_aba(const urModel* m, urData* d) {
  int nb = m->nbody;

  // pass 1: rigid-body inertias and bias forces (velocities from ur_velocities); the bias
  // force is kept in freact for ur_reactions, the kinetic energy in d->energy
  double ke = 0;
  for (int i = 0; i < nb; i++) {
    const double* v = d->cvel + 6*i;
    double Iv[6];
    memcpy(d->IA + 36*i, m->body[i].sinert, 36*sizeof(double));
    uru_mul6(Iv, d->IA + 36*i, v);
    uru_crossforce(d->pA + 6*i, v, Iv);
    for (int k = 0; k < 6; k++) {
      d->pA[6*i + k] -= d->fext[6*i + k];
      ke += 0.5*v[k]*Iv[k];
    }
    memcpy(d->freact + 6*i, d->pA + 6*i, 6*sizeof(double));
  }
  d->energy = ke;

  // pass 2: articulated inertias and bias forces, leaves to roots
  for (int i = nb - 1; i >= 0; i--) {
    switch (m->body[i].jtype) {
    case urJNT_FREE:
      pass2(m, d, i, 6, 0, 6);
      break;
    case urJNT_FIXED:
      pass2(m, d, i, 0, 0, 0);
      break;
    case urJNT_REVOLUTE:
      pass2(m, d, i, 1, 0, 3);
      break;
    case urJNT_UNIVERSAL:
      pass2(m, d, i, 2, 0, 3);
      break;
    case urJNT_SPHERICAL:
      pass2(m, d, i, 3, 0, 3);
      break;
    case urJNT_PRISMATIC:
      pass2(m, d, i, 1, 3, 6);
      break;
    }
  }

  // pass 3: accelerations, roots to leaves
  for (int i = 0; i < nb; i++) {
    switch (m->body[i].jtype) {
    case urJNT_FREE:
      pass3(m, d, i, 6);
      break;
    case urJNT_FIXED:
      pass3(m, d, i, 0);
      break;
    case urJNT_REVOLUTE:
    case urJNT_PRISMATIC:
      pass3(m, d, i, 1);
      break;
    case urJNT_UNIVERSAL:
      pass3(m, d, i, 2);
      break;
    case urJNT_SPHERICAL:
      pass3(m, d, i, 3);
      break;
    }
  }
}

//---------------------------------- joint reactions -----------------------------------------------

// force the parent exerts on each child at the joint anchor (body coordinates), by Newton-Euler;
// needs ur_aba (freact holds v x* I v - fext from its first pass). Only the joints that a
// joint-load sensor reads, and the subtrees below them (urBody.react), are computed (the rest of
// freact is left as the first pass of ur_aba wrote it).
void ur_reactions(const urModel* m, urData* d) {
  // net force of each body: I a + v x* I v - fext
  for (int i = 0; i < m->nbody; i++) {
    if (!m->body[i].react) {
      continue;
    }
    double Ia[6];
    double* f = d->freact + 6*i;
    uru_mul6(Ia, m->body[i].sinert, d->cacc + 6*i);
    for (int k = 0; k < 6; k++) {
      f[k] += Ia[k];
    }
  }

  // children transmit through their parents
  for (int i = m->nbody - 1; i >= 0; i--) {
    int p = m->body[i].parent;
    if (p >= 0 && m->body[i].react && m->body[p].react) {
      double t[6];
      uru_xforce_t(t, d->Xe + 9*i, d->Xr + 3*i, d->freact + 6*i);
      for (int k = 0; k < 6; k++) {
        d->freact[6*p + k] += t[k];
      }
    }
  }
}

//---------------------------------- external forces -----------------------------------------------

// add a world force f acting at the world point p on body
void ur_apply_force(const urModel* m, urData* d, int body, const double f[3], const double p[3]) {
  const double* R = d->xmat + 9*body;
  const double* x = d->xpos + 3*body;
  double fb[3], r[3], rb[3], n[3];
  uru_mulmat3tvec(fb, R, f);
  for (int k = 0; k < 3; k++) {
    r[k] = p[k] - x[k];
  }
  uru_mulmat3tvec(rb, R, r);
  uru_cross3(n, rb, fb);
  for (int k = 0; k < 3; k++) {
    d->fext[6*body + k] += n[k];
    d->fext[6*body + 3 + k] += fb[k];
  }
}

//---------------------------------- energy and momentum -------------------------------------------

double ur_energy_kinetic(const urModel* m, const urData* d) {
  double e = 0;
  for (int i = 0; i < m->nbody; i++) {
    double Iv[6];
    const double* v = d->cvel + 6*i;
    uru_mul6(Iv, m->body[i].sinert, v);
    for (int k = 0; k < 6; k++) {
      e += 0.5*v[k]*Iv[k];
    }
  }
  return e;
}


double ur_energy_potential(const urModel* m, const urData* d) {
  double e = 0;
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    e -= b->gravity*b->mass*uru_dot3(m->opt.gravity, d->xcom + 3*i);
    if (b->jtype == urJNT_REVOLUTE || b->jtype == urJNT_UNIVERSAL ||
        b->jtype == urJNT_PRISMATIC || b->jtype == urJNT_SPHERICAL) {
      // linear springs on the joint coordinates (rotation vector for spherical joints)
      double x[3];
      if (b->jtype == urJNT_SPHERICAL) {
        uru_quat2rotvec(x, d->qpos + b->qadr);
      } else {
        for (int k = 0; k < b->nv; k++) {
          x[k] = d->qpos[b->qadr + k];
        }
      }
      for (int k = 0; k < b->nv; k++) {
        if (b->rst[k].active) {
          e += 0.5*b->rst[k].k*(x[k] - b->rst[k].x0)*(x[k] - b->rst[k].x0);
        }
      }
    }
  }
  return e;
}


void ur_momentum(const urModel* m, const urData* d, double p[3], double L[3]) {
  memset(p, 0, 3*sizeof(double));
  memset(L, 0, 3*sizeof(double));
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    const double* R = d->xmat + 9*i;
    const double* v = d->cvel + 6*i;
    double vc[3], vw[3], w[3], Iw[3], t[3], h[3];

    // CoM velocity and angular velocity, world
    uru_cross3(vc, v, b->com);
    for (int k = 0; k < 3; k++) {
      vc[k] += v[3+k];
    }
    uru_mulmat3vec(vw, R, vc);
    uru_mulmat3vec(Iw, b->inertia, v);
    uru_mulmat3vec(w, R, Iw);

    // sum
    for (int k = 0; k < 3; k++) {
      h[k] = b->mass*vw[k];
      p[k] += h[k];
    }
    uru_cross3(t, d->xcom + 3*i, h);
    for (int k = 0; k < 3; k++) {
      L[k] += t[k] + w[k];
    }
  }
}
