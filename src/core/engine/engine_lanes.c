/* engine_lanes.c: up to urNLANE runs of one model stepped in lock-step. Their joint transforms,
 * body poses, ellipsoid positions, velocities, contact broad phase, spherical restraints'
 * kinematics, restraint forces (springs, dampers, stops, plastic hinges), articulated-body
 * algorithm and Euler update are computed once over vectors of lanes (engine_kin.h,
 * engine_aba.h, engine_quat.h and engine_trig.h instantiated for urV4). Every lane takes the
 * same path through the tree, so the vector code is the scalar code with each operation done
 * for all lanes at once (a branch that depends on a lane's values: both sides, then selected):
 * each run's bits are those of ur_step on its own. The per-run parts (restraint forces with
 * curves or saturation, contact narrow phase and laws, airbags, joint loads, sensors,
 * bookkeeping, end of run) stay scalar, fed by 4x4 transposes. On x86-64 the vector
 * kernels are also compiled for AVX2 and picked at load time; both evaluate the same IEEE
 * operations (no contraction: ISO C mode), so the bits do not depend on the machine either. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

// the vector helpers are static: the AVX calling convention (-Wpsabi) does not concern them
#pragma GCC diagnostic ignored "-Wpsabi"

//---------------------------------- vector kernels ------------------------------------------------

// sanitizer builds of the unrolled vector kernels take minutes (GCC, make check-san) or over ten
// minutes (clang, make fuzz); there they are built without the unrolling (same operations)
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define urNO_UNROLL 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(urNO_UNROLL)
#undef urUNROLL
#define urUNROLL
#endif

// the hot vector functions also compiled for AVX2, the clone picked at load time (GCC on x86-64;
// clang builds only the fuzzers and takes the default; urNO_CLONES: the default only, as make
// check-san builds it to test that path)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(urNO_CLONES)
#define urCLONES __attribute__((target_clones("avx2", "default")))
#define urAVX2   1
#else
#define urCLONES
#define urAVX2 0
#endif

// a double broadcast to every lane (for clang a macro: it refuses to return 256-bit vectors by
// value where AVX is not enabled, even from functions it inlines)
#if defined(__clang__)
#define bc4(x) ((urV4){(x), (x), (x), (x)})
#else
static inline __attribute__((always_inline)) urV4 bc4(double x) {
  return (urV4){x, x, x, x};
}
#endif

// the lane instances of the templates (src/README, "Templates"): the parameters every instance
// here shares are defined once, those of one template around its include; all are undefined at
// the end of the block (engine_template_check.h)
#define urT        urV4
#define urK(name)  urv_##name
#define urFN(name) urv_##name
#define urD        urLanes
#define urBC(x)    bc4(x)
#include "kernels/engine_spatial.h"
#define urSTORAGE static inline __attribute__((always_inline))
#include "kernels/engine_spatial_inertia.h"
#undef urSTORAGE


// uru_invsym over the vectors (the same expressions; square roots lane by lane)
static inline __attribute__((always_inline)) int all4(urV4I c) {
  return c[0] & c[1] & c[2] & c[3];
}

#define urSTORAGE static inline __attribute__((always_inline))
#define urALL(c)  all4(c)
#define urSQRT(x)                                                                                  \
  ({                                                                                               \
    urV4 r_ = (x);                                                                                 \
    for (int l_ = 0; l_ < urNLANE; l_++) r_[l_] = sqrt(r_[l_]);                                    \
    r_;                                                                                            \
  })
#include "kernels/engine_invsym.h"
#undef urSTORAGE
#undef urALL
#undef urSQRT


// inverse of a joint-space inertia per lane; if some lane's matrix is singular, every lane goes
// through uru_invsym on its own (a failed lane gets a zero inverse and its bit in L->fail)
static inline __attribute__((always_inline)) void invsym4(urLanes* L, urV4* Ainv, const urV4* A,
                                                          int n) {
  if (urv_invsym(Ainv, A, n) == 0) {
    return;
  }
  for (int l = 0; l < urNLANE; l++) {
    double a[36], ai[36];
    for (int k = 0; k < n * n; k++) {
      a[k] = A[k][l];
    }
    if (uru_invsym(ai, a, n)) {
      memset(ai, 0, sizeof(ai));
      L->fail |= 1 << l;
    }
    for (int k = 0; k < n * n; k++) {
      Ainv[k][l] = ai[k];
    }
  }
}

#define urSETENERGY(d, ke)       ((d)->energy[0] = (ke))
#define urSTEPH(d)               ((d)->h[0])
#define urINVSYM(d, Dinv, D, nv) invsym4(d, Dinv, D, nv)
#define urABA_ATTR               urCLONES
#include "kernels/engine_aba.h"
#undef urSETENERGY
#undef urSTEPH
#undef urINVSYM

// sincos and the first-quadrant atan2 over the vectors (engine_trig.h)
typedef unsigned long long urV4U __attribute__((vector_size(4 * sizeof(long long))));
#define urM            urV4I
#define urU            urV4U
#define urSEL(m, a, b) ((urV4)(((urV4I)(a) & (m)) | ((urV4I)(b) & ~(m))))
#define urANY(m)       ((m)[0] | (m)[1] | (m)[2] | (m)[3])
#define urNEL          urNLANE
#define urEL(x, l)     ((x)[l])
#define urASI(x)       ((urV4U)(x))
#define urAST(i)       ((urV4)(i))
#include "kernels/engine_trig.h"
#undef urM
#undef urU
#undef urSEL
#undef urANY
#undef urNEL
#undef urEL
#undef urASI
#undef urAST

// sine, cosine and atan2q of four arguments over the vectors (for tests/core/engine/test_engine_trig.c)
void ur_lanes_trig(const double x[urNLANE], double s[urNLANE], double c[urNLANE],
                   const double y[urNLANE], const double w[urNLANE], double a[urNLANE]) {
  urV4 xv, yv, wv, sv, cv, av;
  memcpy(&xv, x, sizeof(xv));
  memcpy(&yv, y, sizeof(yv));
  memcpy(&wv, w, sizeof(wv));
  urv_sincos(xv, &sv, &cv);
  av = urv_atan2q(yv, wv);
  memcpy(s, &sv, sizeof(sv));
  memcpy(c, &cv, sizeof(cv));
  memcpy(a, &av, sizeof(av));
}

// rotation about a unit axis over the vectors: the scalar axisrot's quaternion and matrix
static inline __attribute__((always_inline)) void axisrot4(urV4 R[9], const urV4 a[3],
                                                           const urV4* ang) {
  urV4 s, c;
  urv_sincos(bc4(0.5) * (*ang), &s, &c);
  urV4 q[4] = {c, s * a[0], s * a[1], s * a[2]};
  urv_quat2mat(R, q);
}

// quatintegrate, quat2rotvec and rotvec_jrinv over the vectors (engine_quat.h)
#define urM            urV4I
#define urSTORAGE      static inline __attribute__((always_inline))
#define urSEL(m, a, b) ((urV4)(((urV4I)(a) & (m)) | ((urV4I)(b) & ~(m))))
#define urSQRT(x)                                                                                  \
  ({                                                                                               \
    urV4 r_ = (x);                                                                                 \
    for (int l_ = 0; l_ < urNLANE; l_++) r_[l_] = sqrt(r_[l_]);                                    \
    r_;                                                                                            \
  })
#include "kernels/engine_quat.h"
#undef urM
#undef urSTORAGE
#undef urSEL
#undef urSQRT

#define urAXISROT(R, axis, angle, slot) axisrot4(R, axis, &(angle))
#define urKIN_ATTR                      urCLONES
#include "kernels/engine_kin.h"
#undef urAXISROT
#undef urT
#undef urK
#undef urFN
#undef urD
#undef urBC
#include "kernels/engine_template_check.h"

// the broad phase of ur_contacts_broad over the vectors, in one pass over the pairs: the same
// expressions (IEEE square roots are exact, so one instruction for four lanes gives each lane's
// bits); L->gap ends as the pairs' depths (minus the gaps). SQRT4 is the square root of a vector,
// lane by lane or in one instruction.
#define BROAD4(SQRT4)                                                                              \
  for (int i = 0; i < m->npair; i++) {                                                             \
    const urPair* pr = m->pair + i;                                                                \
    const urV4* ca = L->gxpos + 3 * pr->geom1;                                                     \
    urV4 gap;                                                                                      \
    if (pr->geom2 < 0) {                                                                           \
      gap = ca[2] - bc4(m->geom[pr->geom1].rbound);                                                \
    } else {                                                                                       \
      const urV4* cb = L->gxpos + 3 * pr->geom2;                                                   \
      urV4 dx0 = cb[0] - ca[0], dx1 = cb[1] - ca[1], dx2 = cb[2] - ca[2];                          \
      urV4 d2 = dx0 * dx0 + dx1 * dx1 + dx2 * dx2;                                                 \
      gap = SQRT4(d2) - bc4(m->geom[pr->geom1].rbound) - bc4(m->geom[pr->geom2].rbound);           \
    }                                                                                              \
    L->gap[i] = -gap;                                                                              \
  }

// (macros: clang refuses 256-bit vectors by value where AVX is not enabled, as for bc4)
#define sqrt4_lanes(v) ((urV4){sqrt((v)[0]), sqrt((v)[1]), sqrt((v)[2]), sqrt((v)[3])})
static void broad4_default(const urModel* m, urLanes* L) {
  BROAD4(sqrt4_lanes)
}
#undef sqrt4_lanes

#if urAVX2
#include <immintrin.h>
#define sqrt4_avx2(v) ((urV4)_mm256_sqrt_pd((__m256d)(v)))
__attribute__((target("avx2"))) static void broad4_avx2(const urModel* m, urLanes* L) {
  BROAD4(sqrt4_avx2)
}
#undef sqrt4_avx2
#endif
#undef BROAD4

static void broad4(const urModel* m, urLanes* L) {
#if urAVX2
  if (__builtin_cpu_supports("avx2")) {
    broad4_avx2(m, L);
    return;
  }
#endif
  broad4_default(m, L);
}

// ur_restraints_kin over the vectors
urCLONES static void restraints_kin4(const urModel* m, urLanes* L) {
  urv_restraints_kin(m, L->qpos, L->rkin);
}

//---------------------------------- a run alone's joints over the lanes ---------------------------

// A run alone spends the vector width on its joints instead: the quaternion kernels of
// engine_quat.h take four joints of one run at a time, each lane with the scalar kernel's bits
// (the lanes' rule), lanes beyond the joints repeating the first.

// the spherical restraints' kinematics (uru_restraints_kin) of the bodies js[0..n-1]
static inline __attribute__((always_inline)) void rkin_joints4(const urModel* m, const double* qpos,
                                                               double* rkin, const int* js, int n) {
  const urBody* b[urNLANE];
  for (int l = 0; l < urNLANE; l++) {
    b[l] = m->body + js[l < n ? l : 0];
  }
  urV4 q[4], x[12];
  for (int k = 0; k < 4; k++) {
    double t[urNLANE] = {qpos[b[0]->qadr + k], qpos[b[1]->qadr + k], qpos[b[2]->qadr + k],
                         qpos[b[3]->qadr + k]};
    memcpy(q + k, t, sizeof(t));
  }
  urv_quat2rotvec(x, q);
  for (int k = 0; k < 3; k++) {
    x[k] = x[k] - (urV4){b[0]->rst[k].x0, b[1]->rst[k].x0, b[2]->rst[k].x0, b[3]->rst[k].x0};
  }
  urv_rotvec_jrinv(x + 3, x);
  for (int l = 0; l < n; l++) {
    for (int k = 0; k < 12; k++) {
      rkin[12 * js[l] + k] = x[k][l];
    }
  }
}

urCLONES void ur_restraints_kin_joints(const urModel* m, const double* qpos, double* rkin) {
  int js[urNLANE], n = 0;
  for (int j = 0; j < m->nrstb; j++) {
    int i = m->rstb[j];
    if (m->body[i].jtype == urJNT_SPHERICAL) {
      js[n++] = i;
      if (n == urNLANE) {
        rkin_joints4(m, qpos, rkin, js, n);
        n = 0;
      }
    }
  }
  if (n) {
    rkin_joints4(m, qpos, rkin, js, n);
  }
}

// the quaternions at qpos + qa[l], rotated by qvel + va[l] over h (uru_quatintegrate), l < n
static inline __attribute__((always_inline)) void quat_joints4(double* qpos, const double* qvel,
                                                               double h, const int* qa,
                                                               const int* va, int n) {
  int l1 = n > 1, l2 = n > 2 ? 2 : 0, l3 = n > 3 ? 3 : 0;
  urV4 q[4], w[3];
  for (int k = 0; k < 4; k++) {
    double t[urNLANE] = {qpos[qa[0] + k], qpos[qa[l1] + k], qpos[qa[l2] + k], qpos[qa[l3] + k]};
    memcpy(q + k, t, sizeof(t));
  }
  for (int k = 0; k < 3; k++) {
    double t[urNLANE] = {qvel[va[0] + k], qvel[va[l1] + k], qvel[va[l2] + k], qvel[va[l3] + k]};
    memcpy(w + k, t, sizeof(t));
  }
  urv_quatintegrate(q, w, bc4(h));
  for (int l = 0; l < n; l++) {
    for (int k = 0; k < 4; k++) {
      qpos[qa[l] + k] = q[k][l];
    }
  }
}

urCLONES void ur_addpos_joints(const urModel* m, double* qpos, const double* qvel, double h) {
  int qa[urNLANE], va[urNLANE], n = 0;
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    double* q = qpos + b->qadr;
    const double* v = qvel + b->vadr;
    switch (b->jtype) {
    case urJNT_FREE:
      for (int k = 0; k < 3; k++) {
        q[k] += h * v[k];
      }
      qa[n] = b->qadr + 3;
      va[n++] = b->vadr + 3;
      break;
    case urJNT_SPHERICAL:
      qa[n] = b->qadr;
      va[n++] = b->vadr;
      break;
    case urJNT_FIXED: break;
    default:
      for (int k = 0; k < b->nv; k++) {
        q[k] += h * v[k];
      }
    }
    if (n == urNLANE) {
      quat_joints4(qpos, qvel, h, qa, va, n);
      n = 0;
    }
  }
  if (n) {
    quat_joints4(qpos, qvel, h, qa, va, n);
  }
}

// the rotations about the revolute and universal joints' axes (jcalc's urAXISROT, axisrot)
// into each body's stash (engine_kinematics.c: the tail of d->S, slots 0 and 1)
static inline __attribute__((always_inline)) void axisrot_joints4(double* const* dst,
                                                                  const double* const* ax,
                                                                  const double* ang, int n) {
  int l1 = n > 1, l2 = n > 2 ? 2 : 0, l3 = n > 3 ? 3 : 0;
  urV4 a[3], t, R[9];
  for (int k = 0; k < 3; k++) {
    double e[urNLANE] = {ax[0][k], ax[l1][k], ax[l2][k], ax[l3][k]};
    memcpy(a + k, e, sizeof(e));
  }
  double e[urNLANE] = {ang[0], ang[l1], ang[l2], ang[l3]};
  memcpy(&t, e, sizeof(e));
  axisrot4(R, a, &t);
  for (int l = 0; l < n; l++) {
    for (int k = 0; k < 9; k++) {
      dst[l][k] = R[k][l];
    }
  }
}

urCLONES void ur_axisrot_joints(const urModel* m, urData* d) {
  double* dst[urNLANE];
  const double* ax[urNLANE];
  double ang[urNLANE];
  int n = 0;
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    int na = b->jtype == urJNT_REVOLUTE ? 1 : b->jtype == urJNT_UNIVERSAL ? 2 : 0;
    for (int s = 0; s < na; s++) {
      dst[n] = ur_jrot_slot(d, i, s);
      ax[n] = b->axis[s];
      ang[n++] = d->qpos[b->qadr + s];
      if (n == urNLANE) {
        axisrot_joints4(dst, ax, ang, n);
        n = 0;
      }
    }
  }
  if (n) {
    axisrot_joints4(dst, ax, ang, n);
  }
}

// x ? a : b lane by lane (x a comparison's mask)
#define sel4(x, a, b) ((urV4)(((urV4I)(a) & (x)) | ((urV4I)(b) & ~(x))))

// rforce (engine_restraint.c) over the vectors for a restraint that ur_restraint_vec admits:
// deflection x, rate xd, and where r is a plastic hinge each lane's plastic deflection xp and
// whether it broke (br); the same operations as the scalar branches, their results selected
static inline __attribute__((always_inline)) urV4 rforce4(const urRestraint* r, urV4 x, urV4 xd,
                                                          urV4 xp, urV4I br) {
  urV4 f;
  if (r->mp > 0) {
    // plastic(): the return map where the trial moment is over mp
    double b = uru_back_slope(r);
    urV4 m0 = bc4(r->k) * (x - xp), mb = m0 - bc4(b) * xp;
    urV4 over = (urV4)((urV4I)mb & ~(urV4I)bc4(-0.0)) - bc4(r->mp), mm = m0;
    urV4I yield = over > 0;
    if (yield[0] | yield[1] | yield[2] | yield[3]) {
      urV4 dxp = sel4(mb > 0, over, -over) / bc4(r->k + b);
      mm = sel4(yield, bc4(r->k) * (x - xp - dxp), m0);
    }
    f = sel4(br, bc4(0), mm) + sel4(br, bc4(0), bc4(r->c) * xd);
  } else {
    f = bc4(r->k) * x + bc4(r->c) * xd;
  }
  if (r->hi > r->lo) {
    urV4 fh = f + (bc4(r->kstop) * (x - bc4(r->hi)) + bc4(r->cstop) * xd);
    urV4 fl = f + (bc4(r->kstop) * (x - bc4(r->lo)) + bc4(r->cstop) * xd);
    f = sel4(x > bc4(r->hi), fh, sel4(x < bc4(r->lo), fl, f));
  }
  return f;
}

// the restraint forces of body i (nd dofs; sph: spherical) over the vectors, subtracted from
// L->qfrc (inlined with constant sizes so that the dof loops unroll)
static inline __attribute__((always_inline)) void restraint4(const urModel* m, urLanes* L,
                                                             urData* const* d, int n, int i,
                                                             const int nd, const int sph) {
  const urBody* b = m->body + i;
  urV4 x[3], f[3] = {bc4(0), bc4(0), bc4(0)};
  urV4I br[3] = {{0}, {0}, {0}};
  const urV4* xs = sph ? L->rkin + 12 * i : x;
  const urV4* qd = L->qvel + b->vadr;
  urV4* qf = L->qfrc + b->vadr;
  urUNROLL for (int k = 0; k < nd; k++) {
    const urRestraint* r = b->rst + k;
    if (!sph) {
      x[k] = L->qpos[b->qadr + k] - bc4(r->x0);
    }
    if (r->active) {
      urV4 xp = bc4(0);
      if (r->mp > 0) {
        urV4 st1;
        for (int l = 0; l < urNLANE; l++) {
          const double* st = d[l < n ? l : 0]->rst + 2 * (b->vadr + k);
          xp[l] = st[0];
          st1[l] = st[1];
        }
        br[k] = st1 != bc4(0);
      }
      f[k] = rforce4(r, xs[k], sph ? bc4(0) : qd[k], xp, br[k]);
    }
    if (!sph) {
      qf[k] = qf[k] - f[k];
    }
  }
  if (sph) {
    urV4 t[3];
    urv_mulmat3tvec(t, xs + 3, f);
    urUNROLL for (int k = 0; k < 3; k++) {
      const urRestraint* r = b->rst + k;
      urV4 c = r->active ? sel4(br[k], bc4(0), bc4(r->c) * qd[k]) : bc4(0);
      qf[k] = qf[k] - (t[k] + c);
    }
  }
}

// ur_restraints over the vectors for the bodies L->rstv: subtracted from L->qfrc, which holds the
// runs' own (zero on these bodies' dofs, as ur_restraints starts from); the hinges' plastic
// deflections are each run's (lanes beyond n repeat lane 0)
urCLONES static void restraints4(const urModel* m, urLanes* L, urData* const* d, int n) {
  for (int j = 0; j < L->nrstv; j++) {
    int i = L->rstv[j];
    switch (m->body[i].jtype) {
    case urJNT_SPHERICAL: restraint4(m, L, d, n, i, 3, 1); break;
    case urJNT_UNIVERSAL: restraint4(m, L, d, n, i, 2, 0); break;
    default: restraint4(m, L, d, n, i, 1, 0); break; // revolute, prismatic
    }
  }
}


// the update of ur_step_euler over the vectors: velocities, then positions with them (addpos),
// each lane by its own step L->h
urCLONES static void euler4(const urModel* m, urLanes* L) {
  urV4 h = L->h[0];
  for (int k = 0; k < m->nv; k++) {
    L->qvel[k] += h * L->qacc[k];
  }
  urv_addpos(m, L->qpos, L->qvel, h);
}

//---------------------------------- lane data -----------------------------------------------------

int ur_lanes_init(const urModel* m, urLanes* L) {
  memset(L, 0, sizeof(*L));
  size_t nb = (size_t)m->nbody, nv = (size_t)m->nv;
  size_t nq = (size_t)m->nq;
  size_t ng = (size_t)m->ngeom, np = (size_t)m->npair;
  size_t n = nb * (36 * 4 + 6 * 7 + 9 + 3 + 9 + 3 + 3 + 12) + 2 * nv + 2 + nq + nv + 3 * ng + np;
  L->mem = aligned_alloc(sizeof(urV4), (n ? n : 1) * sizeof(urV4));
  L->spare = malloc((nq > nv ? nq : nv) * sizeof(double) + 1);
  L->outb = malloc(3 * nb * sizeof(int) + 1);
  if (!L->mem || !L->spare || !L->outb) {
    ur_lanes_free(L);
    return -1;
  }
  for (int i = 0; i < m->nbody; i++) {
    int read = m->body[i].react;
    for (int k = 0; k < m->nsensor; k++) {
      read |= m->sensor[k].type == urSENS_ACCEL && m->sensor[k].obj == i;
    }
    if (read) {
      L->outb[L->nout++] = i;
    }
  }
  L->rstv = L->outb + nb;
  L->rsts = L->rstv + nb;
  for (int j = 0; j < m->nrstb; j++) {
    int i = m->rstb[j];
    if (ur_restraint_vec(m, i)) {
      L->rstv[L->nrstv++] = i;
    } else {
      L->rsts[L->nrsts++] = i;
    }
  }
  memset(L->mem, 0, n * sizeof(urV4));
  urV4* p = L->mem;
  urV4** f[] = {&L->S,    &L->IA,     &L->U,    &L->Dinv,   &L->pA,   &L->uu,   &L->cbias,
                &L->cvel, &L->cacc,   &L->fext, &L->freact, &L->Xe,   &L->Xr,   &L->qfrc,
                &L->qacc, &L->energy, &L->h,    &L->qpos,   &L->qvel, &L->xmat, &L->xpos,
                &L->xcom, &L->gxpos,  &L->gap,  &L->rkin};
  size_t len[] = {36 * nb, 36 * nb, 36 * nb, 36 * nb, 6 * nb, 6 * nb, 6 * nb, 6 * nb, 6 * nb,
                  6 * nb,  6 * nb,  9 * nb,  3 * nb,  nv,     nv,     1,      1,      nq,
                  nv,      9 * nb,  3 * nb,  3 * nb,  3 * ng, np,     12 * nb};
  for (size_t k = 0; k < sizeof(len) / sizeof(len[0]); k++) {
    *f[k] = p;
    p += len[k];
  }
  return 0;
}


void ur_lanes_free(urLanes* L) {
  free(L->mem);
  free(L->spare);
  free(L->outb);
  memset(L, 0, sizeof(*L));
}


// 4 x 4 transposes: four consecutive values of each lane <-> four vectors of lanes
#if defined(__clang__)
#define SHUF(a, b, i, j, k, l) __builtin_shufflevector(a, b, i, j, k, l)
#else
#define SHUF(a, b, i, j, k, l) __builtin_shuffle(a, b, (urV4I){i, j, k, l})
#endif
#define transpose4(r, a_, b_, c_, e_)                                                              \
  do {                                                                                             \
    urV4 a = (a_), b = (b_), c = (c_), e = (e_);                                                   \
    urV4 t0 = SHUF(a, b, 0, 4, 2, 6), t1 = SHUF(a, b, 1, 5, 3, 7);                                 \
    urV4 t2 = SHUF(c, e, 0, 4, 2, 6), t3 = SHUF(c, e, 1, 5, 3, 7);                                 \
    (r)[0] = SHUF(t0, t2, 0, 1, 4, 5);                                                             \
    (r)[1] = SHUF(t1, t3, 0, 1, 4, 5);                                                             \
    (r)[2] = SHUF(t0, t2, 2, 3, 6, 7);                                                             \
    (r)[3] = SHUF(t1, t3, 2, 3, 6, 7);                                                             \
  } while (0)
#define load4(p)                                                                                   \
  ({                                                                                               \
    urV4 v_;                                                                                       \
    memcpy(&v_, (p), sizeof(v_));                                                                  \
    v_;                                                                                            \
  })

// x[0..n-1] of each lane (lanes beyond nl repeating lane 0) into the vectors v
urCLONES static void gather(urV4* v, const double* const* x, size_t n) {
  size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    transpose4(v + k, load4(x[0] + k), load4(x[1] + k), load4(x[2] + k), load4(x[3] + k));
  }
  for (; k < n; k++) {
    v[k] = (urV4){x[0][k], x[1][k], x[2][k], x[3][k]};
  }
}

// the vectors v back into x[0..n-1] of lanes 0..nl-1
urCLONES static void scatter(double* const* x, int nl, const urV4* v, size_t n) {
  size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    urV4 r[4];
    transpose4(r, v[k], v[k + 1], v[k + 2], v[k + 3]);
    for (int l = 0; l < nl; l++) {
      memcpy(x[l] + k, r + l, sizeof(r[l]));
    }
  }
  for (; k < n; k++) {
    for (int l = 0; l < nl; l++) {
      x[l][k] = v[k][l];
    }
  }
}

// one array of the lanes' data to or from the vectors: lane l is d[l], lanes beyond n repeat
// lane 0 when gathering
#define GATHER(field, len)                                                                         \
  do {                                                                                             \
    const double* x_[urNLANE];                                                                     \
    for (int l_ = 0; l_ < urNLANE; l_++) x_[l_] = d[l_ < n ? l_ : 0]->field;                       \
    gather(L->field, x_, (size_t)(len));                                                           \
  } while (0)
#define SCATTER(field, len)                                                                        \
  do {                                                                                             \
    double* x_[urNLANE];                                                                           \
    for (int l_ = 0; l_ < n; l_++) x_[l_] = d[l_]->field;                                          \
    scatter(x_, n, L->field, (size_t)(len));                                                       \
  } while (0)
// the same into the lanes whose bit is set in ok; the others into L->spare
#define SCATTER_OK(field, len, ok)                                                                 \
  do {                                                                                             \
    double* x_[urNLANE];                                                                           \
    for (int l_ = 0; l_ < n; l_++) x_[l_] = (ok) & (1 << l_) ? d[l_]->field : L->spare;            \
    scatter(x_, n, L->field, (size_t)(len));                                                       \
  } while (0)

// the state, for the poses and velocities
static void gather_state(const urModel* m, urLanes* L, urData* const* d, int n) {
  GATHER(qpos, m->nq);
  GATHER(qvel, m->nv);
}


// the poses, velocities and broad phase back to each lane's data
static void scatter_kin(const urModel* m, const urLanes* L, urData* const* d, int n) {
  size_t nb = (size_t)m->nbody, ng = (size_t)m->ngeom;
  SCATTER(xmat, 9 * nb);
  SCATTER(xpos, 3 * nb);
  SCATTER(xcom, 3 * nb);
  SCATTER(cvel, 6 * nb);
  for (int j = 0; j < L->nout; j++) {
    int i = L->outb[j];
    SCATTER(Xe + 9 * i, 9);
    SCATTER(Xr + 3 * i, 3);
  }
  SCATTER(gxpos, 3 * ng);
  for (int l = 0; l < n; l++) {
    memset(d[l]->gmat_ok, 0, ng); // orientations on first use (ur_geom_xmat)
  }
  double* dep[urNLANE];
  for (int l = 0; l < n; l++) {
    dep[l] = d[l]->pdepth;
  }
  scatter(dep, n, L->gap, (size_t)m->npair);
  for (int j = 0; j < L->nrsts; j++) {
    int i = L->rsts[j];
    if (m->body[i].jtype == urJNT_SPHERICAL) {
      SCATTER(rkin + 12 * i, 12);
    }
  }
}


// the applied forces, for the ABA. Of qfrc only the dofs of the bodies whose restraint forces
// were computed lane by lane (L->rsts): ur_forward_loads zeroes the rest, and only restraints
// write it.
static void gather_forces(const urModel* m, urLanes* L, urData* const* d, int n) {
  GATHER(fext, 6 * (size_t)m->nbody);
  memset(L->qfrc, 0, (size_t)m->nv * sizeof(urV4));
  for (int j = 0; j < L->nrsts; j++) {
    const urBody* b = m->body + L->rsts[j];
    for (int k = b->vadr; k < b->vadr + b->nv; k++) {
      for (int l = 0; l < urNLANE; l++) {
        L->qfrc[k][l] = d[l < n ? l : 0]->qfrc[k];
      }
    }
  }
  L->fail = 0;
}


// the outputs of the ABA, and the generalised forces it took, back to each lane's data
static void scatter_acc(const urModel* m, const urLanes* L, urData* const* d, int n) {
  SCATTER(qacc, m->nv);
  SCATTER(qfrc, m->nv);
  for (int j = 0; j < L->nout; j++) {
    int i = L->outb[j];
    SCATTER(cacc + 6 * i, 6);
    SCATTER(freact + 6 * i, 6);
  }
  for (int l = 0; l < n; l++) {
    d[l]->energy = L->energy[0][l];
    if (L->fail & (1 << l)) {
      ur_set_status(d[l], urSTAT_NONFINITE, "singular joint-space inertia");
    }
  }
}

// the updated state back to the lanes in ok (bits)
static void scatter_state(const urModel* m, urLanes* L, urData* const* d, int n, int ok) {
  SCATTER_OK(qpos, m->nq, ok);
  SCATTER_OK(qvel, m->nv, ok);
}

//---------------------------------- lock-step -----------------------------------------------------

// the time since *t0 to stage k of L->prof (when it is set), and *t0 to now
static inline void lap(urLanes* L, int k, unsigned long long* t0) {
  if (L->prof) {
    unsigned long long t = uru_ticks();
    L->prof[k] += t - *t0;
    *t0 = t;
  }
}

int ur_step_lanes(const urModel* m, urData* const* d, int n, urLanes* L) {
  // more runs than lanes: urNLANE at a time
  if (n > urNLANE) {
    for (int c = 0; c < n; c += urNLANE) {
      ur_step_lanes(m, d + c, n - c < urNLANE ? n - c : urNLANE, L);
    }
    return 0;
  }

  // one run, or an integrator with stages: each run on its own
  if (n < 2 || m->opt.integrator == urINT_RK4) {
    for (int l = 0; l < n; l++) {
      ur_step(m, d[l]);
    }
    return 0;
  }

  // the runs that may step
  urData* run[urNLANE];
  int k = 0;
  for (int l = 0; l < n; l++) {
    if (ur_fracture_pending(m, d[l])) {
      ur_step(m, d[l]); // a joint broke: its topology is its own (engine_fracture.c)
    } else if (ur_step_begin(m, d[l]) >= 0) {
      run[k++] = d[l];
    }
  }
  if (k == 0) {
    return 0;
  }

  // each lane's step (dt, or adapt dt where its run takes a coarse step; lanes beyond k
  // repeat lane 0)
  for (int l = 0; l < urNLANE; l++) {
    L->h[0][l] = ur_step_h(m, run[l < k ? l : 0]);
  }

  // ur_forward_pre's stages: poses, velocities, broad phase and restraint kinematics for all
  // lanes at once, the applied forces lane by lane
  unsigned long long t0 = L->prof ? uru_ticks() : 0;
  gather_state(m, L, run, k);
  urv_kinematics_bodies(m, L);
  urv_kinematics_gpos(m, L);
  urv_velocities(m, L);
  lap(L, urLANE_KIN, &t0);
  broad4(m, L);
  lap(L, urLANE_BROAD, &t0);
  restraints_kin4(m, L);
  lap(L, urLANE_RKIN, &t0);
  scatter_kin(m, L, run, k);
  lap(L, urLANE_COPYKIN, &t0);
  for (int l = 0; l < k; l++) {
    ur_forward_loads(m, run[l], L->rsts, L->nrsts);
  }
  lap(L, urLANE_LOADS, &t0);

  // the rest of the restraint forces, and accelerations, for all lanes at once
  gather_forces(m, L, run, k);
  lap(L, urLANE_COPYF, &t0);
  restraints4(m, L, run, k);
  lap(L, urLANE_RESTR, &t0);
  urv_aba(m, L);
  lap(L, urLANE_ABA, &t0);
  scatter_acc(m, L, run, k);
  lap(L, urLANE_COPYF, &t0);

  // the rest of each step: joint loads, sensors and bookkeeping lane by lane, the update over
  // the vectors (ur_step_euler), the end checks lane by lane
  int ok = 0;
  for (int l = 0; l < k; l++) {
    if (ur_forward_post(m, run[l]) >= 0) {
      ur_step_accept(m, run[l]);
      ok |= 1 << l;
    }
  }
  lap(L, urLANE_POST, &t0);
  euler4(m, L);
  scatter_state(m, L, run, k, ok);
  lap(L, urLANE_EULER, &t0);
  for (int l = 0; l < k; l++) {
    if (ok & (1 << l)) {
      ur_step_end(m, run[l]);
    }
  }
  lap(L, urLANE_END, &t0);
  return 0;
}
