/* engine_dynamics.c: Featherstone's articulated-body algorithm over a forest of trees, joint
 * reaction loads by a Newton-Euler backward pass, energies and momenta. All spatial quantities in
 * body coordinates at the body origin (the joint anchor). */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

// the vector helpers of engine_xinertia_rows.h are inlined: the AVX calling convention
// (-Wpsabi) does not concern them
#pragma GCC diagnostic ignored "-Wpsabi"

//---------------------------------- articulated-body algorithm ------------------------------------

// the kernels ur_aba calls, for doubles, inlined into it (urd_: the templates of uru_'s, so
// that the congruence and each joint type's inverse, its size constant, unroll in place, as in
// the lanes' urv_aba; the same expressions in the same order)
#define urT       double
#define urK(name) urd_##name
#define urBC(x)   (x)
#include "kernels/engine_spatial.h"
#include "kernels/engine_xinertia_rows.h"
#define urSTORAGE   static inline __attribute__((always_inline))
#define urALL(c)    (c)
#define urSQRT(x)   sqrt(x)
#define urINVUNROLL urUNROLL
#include "kernels/engine_invsym.h"
#undef urINVUNROLL
#undef urSTORAGE
#undef urALL
#undef urSQRT

// ur_aba for doubles, from its template
#define urFN(name)         ur_##name
#define urD                urData
#define urSETENERGY(d, ke) ((d)->energy = (ke))
#define urSTEPH(d)         ur_step_h(m, d)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(urNO_CLONES)
#define urABA_ATTR __attribute__((target_clones("avx2", "default")))
#endif
#define urINVSYM(d, Dinv, D, nv)                                                                   \
  if (urd_invsym(Dinv, D, nv)) {                                                                   \
    ur_set_status(d, urSTAT_NONFINITE, "singular joint-space inertia");                            \
    memset(Dinv, 0, 36 * sizeof(double));                                                          \
  }
#include "kernels/engine_aba.h"
#undef urT
#undef urBC
#undef urK
#undef urFN
#undef urD
#undef urSETENERGY
#undef urSTEPH
#undef urINVSYM
#include "kernels/engine_template_check.h"

//---------------------------------- joint reactions -----------------------------------------------

// force the parent exerts on each child at the joint anchor (body coordinates), by Newton-Euler;
// needs ur_aba (freact holds v x* I v - fext from its first pass). Only the joints that a
// joint-load sensor reads, and the subtrees below them (urBody.react), are computed (the rest of
// freact is left as the first pass of ur_aba wrote it).
void ur_reactions(const urModel* m, urData* d) {
  // net force of each body: I a + v x* I v - fext
  for (int j = 0; j < m->nreactb; j++) {
    int i = m->reactb[j];
    double Ia[6];
    double* f = d->freact + 6 * i;
    uru_mul6(Ia, m->body[i].sinert, d->cacc + 6 * i);
    for (int k = 0; k < 6; k++) {
      f[k] += Ia[k];
    }
  }

  // children transmit through their parents
  for (int j = m->nreactb - 1; j >= 0; j--) {
    int i = m->reactb[j];
    int p = m->body[i].parent;
    if (p >= 0 && m->body[p].react) {
      double t[6];
      uru_xforce_t(t, d->Xe + 9 * i, d->Xr + 3 * i, d->freact + 6 * i);
      for (int k = 0; k < 6; k++) {
        d->freact[6 * p + k] += t[k];
      }
    }
  }
}

//---------------------------------- external forces -----------------------------------------------

// add a world force f acting at the world point p on body
void ur_apply_force(const urModel* m, urData* d, int body, const double f[3], const double p[3]) {
  const double* R = d->xmat + 9 * body;
  const double* x = d->xpos + 3 * body;
  double fb[3], r[3], rb[3], n[3];
  uru_mulmat3tvec(fb, R, f);
  for (int k = 0; k < 3; k++) {
    r[k] = p[k] - x[k];
  }
  uru_mulmat3tvec(rb, R, r);
  uru_cross3(n, rb, fb);
  for (int k = 0; k < 3; k++) {
    d->fext[6 * body + k] += n[k];
    d->fext[6 * body + 3 + k] += fb[k];
  }
}

//---------------------------------- energy and momentum -------------------------------------------

double ur_energy_kinetic(const urModel* m, const urData* d) {
  double e = 0;
  for (int i = 0; i < m->nbody; i++) {
    double Iv[6];
    const double* v = d->cvel + 6 * i;
    uru_mul6(Iv, m->body[i].sinert, v);
    for (int k = 0; k < 6; k++) {
      e += 0.5 * v[k] * Iv[k];
    }
  }
  return e;
}


double ur_energy_potential(const urModel* m, const urData* d) {
  m = ur_data_model(m, d); // a run whose joint broke: its own topology
  double e = 0;
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    e -= b->gravity * b->mass * uru_dot3(m->opt.gravity, d->xcom + 3 * i);
    if (b->jtype == urJNT_REVOLUTE || b->jtype == urJNT_UNIVERSAL || b->jtype == urJNT_PRISMATIC ||
        b->jtype == urJNT_SPHERICAL) {
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
        const urRestraint* r = b->rst + k;
        double xk = x[k] - r->x0;
        const double* st = d->rst + 2 * (b->vadr + k);
        if (r->active && r->mp > 0) {
          // plastic hinge: the elastic part k (x - xp)^2 / 2, none once broken
          double xe = xk - st[0];
          e += st[1] != 0 ? 0 : 0.5 * r->k * xe * xe;
        } else if (r->active && r->sat > 0 && r->k > 0) {
          e += r->sat * r->sat / r->k * log(cosh(r->k * xk / r->sat));
        } else if (r->active) {
          e += 0.5 * r->k * xk * xk;
        }
      }
    }
  }
  return e;
}


void ur_momentum(const urModel* m, const urData* d, double p[3], double L[3]) {
  memset(p, 0, 3 * sizeof(double));
  memset(L, 0, 3 * sizeof(double));
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    const double* R = d->xmat + 9 * i;
    const double* v = d->cvel + 6 * i;
    double vc[3], vw[3], w[3], Iw[3], t[3], h[3];

    // CoM velocity and angular velocity, world
    uru_cross3(vc, v, b->com);
    for (int k = 0; k < 3; k++) {
      vc[k] += v[3 + k];
    }
    uru_mulmat3vec(vw, R, vc);
    uru_mulmat3vec(Iw, b->inertia, v);
    uru_mulmat3vec(w, R, Iw);

    // sum
    for (int k = 0; k < 3; k++) {
      h[k] = b->mass * vw[k];
      p[k] += h[k];
    }
    uru_cross3(t, d->xcom + 3 * i, h);
    for (int k = 0; k < 3; k++) {
      L[k] += t[k] + w[k];
    }
  }
}
