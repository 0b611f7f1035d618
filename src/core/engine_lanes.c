/* engine_lanes.c: up to urNLANE runs of one model stepped in lock-step, their articulated-body
 * algorithm computed once over vectors of lanes (engine_aba.h instantiated for urV4). Every lane
 * takes the same path through the tree, so the vector code is the scalar code with each
 * operation done for all lanes at once: each run's bits are those of ur_step on its own. The
 * per-run parts (contacts, restraints, airbags, sensors, integration, end of run) stay scalar.
 * On x86-64 the vector kernels are also compiled for AVX2 and picked at load time; both clones
 * evaluate the same IEEE operations (no contraction: ISO C mode), so the bits do not depend on
 * the machine either. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

// the vector helpers are static: the AVX calling convention (-Wpsabi) does not concern them
#pragma GCC diagnostic ignored "-Wpsabi"
// square roots without errno (the same values), so that lanes of them can be one instruction
#pragma GCC optimize("no-math-errno")

//---------------------------------- vector kernels ------------------------------------------------

static inline urV4 bc4(double x) {
  return (urV4){x, x, x, x};
}

#define urT urV4
#define urK(name) urv_##name
#include "engine_spatial.h"
#define urSTORAGE static inline __attribute__((always_inline))
#include "engine_spatial_inertia.h"
#undef urSTORAGE


// uru_invsym's Cholesky inverse (n > 3) over the vectors, the square roots lane by lane; -1 if a
// lane's matrix is not positive definite
static inline __attribute__((always_inline))
int chol4(urV4* Ainv, const urV4* A, int n) {
  urV4 L[36] = {0}, Li[36] = {0};
  for (int j = 0; j < n; j++) {
    urV4 s = A[n*j + j];
    for (int k = 0; k < j; k++) {
      s -= L[6*j + k]*L[6*j + k];
    }
    urV4I pos = s > 0;
    if (!(pos[0] & pos[1] & pos[2] & pos[3])) {
      return -1;
    }
    for (int l = 0; l < urNLANE; l++) {
      L[6*j + j][l] = sqrt(s[l]);
    }
    for (int i = j + 1; i < n; i++) {
      urV4 t = A[n*i + j];
      for (int k = 0; k < j; k++) {
        t -= L[6*i + k]*L[6*j + k];
      }
      L[6*i + j] = t/L[6*j + j];
    }
  }
  for (int j = 0; j < n; j++) {
    Li[6*j + j] = 1/L[6*j + j];
    for (int i = j + 1; i < n; i++) {
      urV4 t = bc4(0);
      for (int k = j; k < i; k++) {
        t -= L[6*i + k]*Li[6*k + j];
      }
      Li[6*i + j] = t/L[6*i + i];
    }
  }
  for (int i = 0; i < n; i++) {
    for (int j = i; j < n; j++) {
      urV4 t = bc4(0);
      for (int k = j; k < n; k++) {
        t += Li[6*k + i]*Li[6*k + j];
      }
      Ainv[n*i + j] = t;
      Ainv[n*j + i] = t;
    }
  }
  return 0;
}


// inverse of a joint-space inertia per lane: the closed forms of uru_invsym for n <= 3 and its
// Cholesky beyond, over the vectors (the same expressions); if some lane's matrix is singular,
// every lane goes through uru_invsym on its own (a failed lane gets a zero inverse and its bit
// in L->fail)
static inline __attribute__((always_inline))
void invsym4(urLanes* L, urV4* Ainv, const urV4* A, int n) {
  if (n <= 3) {
    urV4 det;
    if (n == 1) {
      det = A[0];
    } else if (n == 2) {
      det = A[0]*A[3] - A[1]*A[2];
    } else {
      urV4 c0 = A[4]*A[8] - A[5]*A[7], c1 = A[5]*A[6] - A[3]*A[8], c2 = A[3]*A[7] - A[4]*A[6];
      det = A[0]*c0 + A[1]*c1 + A[2]*c2;
      urV4 id = 1/det;
      Ainv[0] = c0*id;
      Ainv[1] = (A[2]*A[7] - A[1]*A[8])*id;
      Ainv[2] = (A[1]*A[5] - A[2]*A[4])*id;
      Ainv[3] = c1*id;
      Ainv[4] = (A[0]*A[8] - A[2]*A[6])*id;
      Ainv[5] = (A[2]*A[3] - A[0]*A[5])*id;
      Ainv[6] = c2*id;
      Ainv[7] = (A[1]*A[6] - A[0]*A[7])*id;
      Ainv[8] = (A[0]*A[4] - A[1]*A[3])*id;
    }
    if (n == 1) {
      Ainv[0] = 1/A[0];
    } else if (n == 2) {
      Ainv[0] = A[3]/det;
      Ainv[1] = -A[1]/det;
      Ainv[2] = -A[2]/det;
      Ainv[3] = A[0]/det;
    }
    urV4I ok = det != 0;
    if (ok[0] & ok[1] & ok[2] & ok[3]) {
      return;
    }
  } else if (chol4(Ainv, A, n) == 0) {
    return;
  }

  // lane by lane
  for (int l = 0; l < urNLANE; l++) {
    double a[36], ai[36];
    for (int k = 0; k < n*n; k++) {
      a[k] = A[k][l];
    }
    if (uru_invsym(ai, a, n)) {
      memset(ai, 0, sizeof(ai));
      L->fail |= 1 << l;
    }
    for (int k = 0; k < n*n; k++) {
      Ainv[k][l] = ai[k];
    }
  }
}

#define urT urV4
#define urBC(x) bc4(x)
#define urFN(name) urv_##name
#define urD urLanes
#define urSETENERGY(d, ke) ((d)->energy[0] = (ke))
#define urINVSYM(d, Dinv, D, nv) invsym4(d, Dinv, D, nv)
#if defined(__x86_64__) && defined(__GNUC__)
#define urABA_ATTR __attribute__((target_clones("avx2", "default")))
#endif
#include "engine_aba.h"

// rotation about a unit axis per lane: the scalar axisrot's quaternion (uru_axisangle2quat, one
// sincos per lane), then its matrix over the vectors
static inline __attribute__((always_inline))
void axisrot4(urV4 R[9], const urV4 a[3], urV4 ang) {
  urV4 q[4];
  for (int l = 0; l < urNLANE; l++) {
    double ax[3] = {a[0][l], a[1][l], a[2][l]}, ql[4];
    uru_axisangle2quat(ql, ax, ang[l]);
    for (int k = 0; k < 4; k++) {
      q[k][l] = ql[k];
    }
  }
  urv_quat2mat(R, q);
}

#define urAXISROT(R, axis, angle) axisrot4(R, axis, angle)
#if defined(__x86_64__) && defined(__GNUC__)
#define urKIN_ATTR __attribute__((target_clones("avx2", "default")))
#endif
#include "engine_kin.h"

// the broad phase of ur_contacts_broad over the vectors (the same expressions; square roots
// lane by lane, which the compiler may vectorise: no errno is needed)
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
static void broad4(const urModel* m, urLanes* L) {
  for (int i = 0; i < m->npair; i++) {
    const urPair* pr = m->pair + i;
    const urV4* ca = L->gxpos + 3*pr->geom1;
    double ra = m->geom[pr->geom1].rbound;
    urV4 gap;
    if (pr->geom2 < 0) {
      gap = ca[2] - bc4(ra);
    } else {
      const urV4* cb = L->gxpos + 3*pr->geom2;
      urV4 dx0 = cb[0] - ca[0], dx1 = cb[1] - ca[1], dx2 = cb[2] - ca[2];
      urV4 s = dx0*dx0 + dx1*dx1 + dx2*dx2, r = s;
      for (int l = 0; l < urNLANE; l++) {
        r[l] = __builtin_sqrt(s[l]);
      }
      gap = r - bc4(ra) - bc4(m->geom[pr->geom2].rbound);
    }
    L->gap[i] = gap;
  }
}

//---------------------------------- lane data -----------------------------------------------------

int ur_lanes_init(const urModel* m, urLanes* L) {
  memset(L, 0, sizeof(*L));
  size_t nb = (size_t)m->nbody, nv = (size_t)m->nv;
  size_t nq = (size_t)m->nq;
  size_t ng = (size_t)m->ngeom, np = (size_t)m->npair;
  size_t n = nb*(36*4 + 6*7 + 9 + 3 + 9 + 3 + 3) + 2*nv + 1 + nq + nv + 12*ng + np;
  L->mem = aligned_alloc(sizeof(urV4), (n ? n : 1)*sizeof(urV4));
  if (!L->mem) {
    return -1;
  }
  memset(L->mem, 0, n*sizeof(urV4));
  urV4* p = L->mem;
  urV4** f[] = {&L->S, &L->IA, &L->U, &L->Dinv, &L->pA, &L->uu, &L->cbias, &L->cvel, &L->cacc,
                &L->fext, &L->freact, &L->Xe, &L->Xr, &L->qfrc, &L->qacc, &L->energy,
                &L->qpos, &L->qvel, &L->xmat, &L->xpos, &L->xcom, &L->gxmat, &L->gxpos,
                &L->gap};
  size_t len[] = {36*nb, 36*nb, 36*nb, 36*nb, 6*nb, 6*nb, 6*nb, 6*nb, 6*nb, 6*nb, 6*nb, 9*nb,
                  3*nb, nv, nv, 1, nq, nv, 9*nb, 3*nb, 3*nb, 9*ng, 3*ng, np};
  for (size_t k = 0; k < sizeof(len)/sizeof(len[0]); k++) {
    *f[k] = p;
    p += len[k];
  }
  return 0;
}


void ur_lanes_free(urLanes* L) {
  free(L->mem);
  memset(L, 0, sizeof(*L));
}


// a vector from one array of each lane's data
#define GATHER(field, n)                                                          \
  for (size_t k = 0; k < (size_t)(n); k++) {                                      \
    L->field[k] = (urV4){d0->field[k], d1->field[k], d2->field[k], d3->field[k]}; \
  }

// the lanes' data: lane l of d[l], lanes beyond n repeating lane 0
#define LANES(n)                                  \
  const urData* d0 = d[0];                        \
  const urData* d1 = d[(n) > 1 ? 1 : 0];          \
  const urData* d2 = d[(n) > 2 ? 2 : 0];          \
  const urData* d3 = d[(n) > 3 ? 3 : 0]

// one array of each lane's data back from the vectors
#define SCATTER(field, len)                       \
  for (size_t k = 0; k < (size_t)(len); k++) {    \
    dl->field[k] = L->field[k][l];                \
  }

// the state, for the poses and velocities
static void gather_state(const urModel* m, urLanes* L, urData* const* d, int n) {
  LANES(n);
  GATHER(qpos, m->nq);
  GATHER(qvel, m->nv);
}


// the poses, velocities and broad phase back to each lane's data
static void scatter_kin(const urModel* m, const urLanes* L, urData* const* d, int n) {
  size_t nb = (size_t)m->nbody;
  for (int l = 0; l < n; l++) {
    urData* dl = d[l];
    SCATTER(xmat, 9*nb);
    SCATTER(xpos, 3*nb);
    SCATTER(xcom, 3*nb);
    SCATTER(Xe, 9*nb);
    SCATTER(Xr, 3*nb);
    SCATTER(cvel, 6*nb);
    SCATTER(gxmat, 9*(size_t)m->ngeom);
    SCATTER(gxpos, 3*(size_t)m->ngeom);
    for (int i = 0; i < m->npair; i++) {
      dl->pair[i].depth = -L->gap[i][l];
    }
  }
}


// the applied forces, for the ABA
static void gather_forces(const urModel* m, urLanes* L, urData* const* d, int n) {
  LANES(n);
  GATHER(fext, 6*(size_t)m->nbody);
  GATHER(qfrc, m->nv);
  L->fail = 0;
}


// the outputs of the ABA back to each lane's data
static void scatter_acc(const urModel* m, const urLanes* L, urData* const* d, int n) {
  size_t nb = (size_t)m->nbody;
  for (int l = 0; l < n; l++) {
    urData* dl = d[l];
    SCATTER(qacc, m->nv);
    SCATTER(cacc, 6*nb);
    SCATTER(freact, 6*nb);
    dl->energy = L->energy[0][l];
    if (L->fail & (1 << l)) {
      ur_set_status(dl, urSTAT_NONFINITE, "singular joint-space inertia");
    }
  }
}

//---------------------------------- lock-step -----------------------------------------------------

int ur_step_lanes(const urModel* m, urData* const* d, int n, urLanes* L) {
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
  for (int l = 0; l < n && l < urNLANE; l++) {
    if (ur_step_begin(m, d[l]) >= 0) {
      run[k++] = d[l];
    }
  }
  if (k == 0) {
    return 0;
  }

  // poses and velocities for all lanes at once, the applied forces lane by lane
  gather_state(m, L, run, k);
  urv_kinematics_bodies(m, L);
  urv_kinematics_geoms(m, L);
  urv_velocities(m, L);
  broad4(m, L);
  scatter_kin(m, L, run, k);
  for (int l = 0; l < k; l++) {
    ur_forward_forces(m, run[l], 0);
  }

  // accelerations for all lanes at once
  gather_forces(m, L, run, k);
  urv_aba(m, L);
  scatter_acc(m, L, run, k);

  // the rest of each step
  for (int l = 0; l < k; l++) {
    if (ur_forward_post(m, run[l]) >= 0) {
      ur_step_euler(m, run[l]);
    }
  }
  return 0;
}
