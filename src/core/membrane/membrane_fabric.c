/* membrane_fabric.c: the fabric's constant-strain triangles (total Lagrangian): Green strain in
 * the warp/weft axes of the reference metric, the orthotropic plane-stress law (membrane
 * stiffnesses E t), the woven fabric's shear (soft until the locking angle, stiff after:
 * the shape of the paper's Fig. 5, bilinear as OpenRadioss LAW58 without its curve option), the
 * tension-field reduction of the compressive principal stress (wrinkling, LAW19's rule with the
 * factor RE), stiffness-proportional material damping; and the uniform gas pressure on every
 * triangle. Sources: materials-membrane sheet C.1, C.2, A.3, C.3. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "membrane_internal.h"

//---------------------------------- law -----------------------------------------------------------

/* shear resultant and energy density at engineering Green shear g = 2 E12 (= sin of the
   warp-weft angle change for unstretched yarns): G0 until sin(lock), GT beyond */
static double shear(const urMemSpec* s, double gl, double g, double* w) {
  double ag = fabs(g);
  if (ag <= gl) {
    *w = 0.5 * s->g0t * g * g;
    return s->g0t * g;
  }
  double d = ag - gl;
  *w = 0.5 * s->g0t * gl * gl + s->g0t * gl * d + 0.5 * s->gtt * d * d;
  return copysign(s->g0t * gl + s->gtt * d, g);
}


/* the law's constants, computed once per force evaluation */
typedef struct {
  double c11, c12, c21, c22; /* S11 = c11 E11 + c12 E22, S22 = c21 E11 + c22 E22 */
  double gl;                 /* sine of the lock angle */
} lawk;

static lawk law_constants(const urMemSpec* s) {
  double nu21 = s->nu12 * s->e2t / s->e1t, q = 1 / (1 - s->nu12 * nu21);
  return (lawk){q * s->e1t, q * s->e1t * nu21, q * s->e2t * s->nu12, q * s->e2t, sin(s->lock)};
}


/* the taut orthotropic law, then the tension field; the energy density in *w */
static inline void stress(const urMemSpec* s, const lawk* k, const double e[3], double S[3],
                          double* w) {
  double ws;
  S[0] = k->c11 * e[0] + k->c12 * e[1];
  S[1] = k->c21 * e[0] + k->c22 * e[1];
  S[2] = shear(s, k->gl, e[2], &ws);
  double wn = 0.5 * (S[0] * e[0] + S[1] * e[1]);

  // tension field: scale the compressive principal stress by RE, keep the axes
  double m = 0.5 * (S[0] + S[1]), h = 0.5 * (S[0] - S[1]);
  double r = sqrt(h * h + S[2] * S[2]), p1 = m - r, p2 = m + r;
  double f = 1;
  if (p2 <= 0) {
    S[0] *= s->re;
    S[1] *= s->re;
    S[2] *= s->re;
    f = s->re;
  } else if (p1 < 0) {
    double beta = 0.5 * ((1 - s->re) * m / r + 1 + s->re);
    S[0] = beta * (S[0] - p2) + p2;
    S[1] = beta * (S[1] - p2) + p2;
    S[2] = beta * S[2];
    f = 0.5 * (1 + s->re);
  }
  *w = f * (wn + ws);
}


void urm_fabric_stress(const urMemSpec* s, const double e[3], double S[3], double* w) {
  lawk k = law_constants(s);
  double ww;
  stress(s, &k, e, S, &ww);
  if (w) {
    *w = ww;
  }
}


//---------------------------------- law over 4 triangles ------------------------------------------

// the same law as stress() over 4 triangles at once (GCC vector extensions), branch-free: both
// sides of each branch computed and the lane's side selected, every operation the scalar one's
// in the same order, so each lane's bits are stress()'s (test_membrane_fabric checks it; a
// change of the law goes into both). ISO C mode: no contraction into FMA in either.
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double urm4 __attribute__((vector_size(32)));
typedef long long urm4i __attribute__((vector_size(32)));
typedef double urm4u __attribute__((vector_size(32), aligned(8))); /* unaligned load, store */

#define AI static inline __attribute__((always_inline))

/* a where the mask is set, else b */
AI urm4 sel4(urm4i mask, urm4 a, urm4 b) {
  return (urm4)(((urm4i)a & mask) | ((urm4i)b & ~mask));
}
AI urm4 bc4(double x) {
  return (urm4){x, x, x, x};
}
#define urmSIGN ((urm4i){INT64_MIN, INT64_MIN, INT64_MIN, INT64_MIN})
AI urm4 fabs4(urm4 x) {
  return (urm4)((urm4i)x & ~urmSIGN);
}
/* copysign: the magnitude of a, the sign of b */
AI urm4 copysign4(urm4 a, urm4 b) {
  return (urm4)(((urm4i)a & ~urmSIGN) | ((urm4i)b & urmSIGN));
}
AI urm4 sqrt4(urm4 x) {
  for (int l = 0; l < 4; l++) {
    x[l] = sqrt(x[l]);
  }
  return x;
}

/* shear() over 4 lanes */
AI urm4 shear4(const urMemSpec* s, double gl, urm4 g, urm4* w) {
  urm4 ag = fabs4(g);
  urm4i lin = ag <= bc4(gl);
  urm4 wl = bc4(0.5 * s->g0t) * g * g, sl = bc4(s->g0t) * g;
  urm4 d = ag - bc4(gl);
  urm4 wk = bc4(0.5 * s->g0t * gl * gl) + bc4(s->g0t * gl) * d + bc4(0.5 * s->gtt) * d * d;
  urm4 sk = copysign4(bc4(s->g0t * gl) + bc4(s->gtt) * d, g);
  *w = sel4(lin, wl, wk);
  return sel4(lin, sl, sk);
}

/* stress() over 4 lanes */
AI void stress4(const urMemSpec* s, const lawk* k, const urm4 e[3], urm4 S[3], urm4* w) {
  urm4 ws;
  S[0] = bc4(k->c11) * e[0] + bc4(k->c12) * e[1];
  S[1] = bc4(k->c21) * e[0] + bc4(k->c22) * e[1];
  S[2] = shear4(s, k->gl, e[2], &ws);
  urm4 wn = bc4(0.5) * (S[0] * e[0] + S[1] * e[1]);

  urm4 m = bc4(0.5) * (S[0] + S[1]), h = bc4(0.5) * (S[0] - S[1]);
  urm4 r = sqrt4(h * h + S[2] * S[2]), p1 = m - r, p2 = m + r;
  urm4i slack = p2 <= bc4(0), wrinkled = ~slack & (p1 < bc4(0));
  urm4 re = bc4(s->re);
  urm4 beta = bc4(0.5) * (bc4(1 - s->re) * m / r + bc4(1) + re);
  urm4 f = sel4(slack, re, sel4(wrinkled, bc4(0.5 * (1 + s->re)), bc4(1)));
  for (int j = 0; j < 2; j++) {
    S[j] = sel4(slack, S[j] * re, sel4(wrinkled, beta * (S[j] - p2) + p2, S[j]));
  }
  S[2] = sel4(slack, S[2] * re, sel4(wrinkled, beta * S[2], S[2]));
  *w = f * (wn + ws);
}


void urm_fabric_stress4(const urMemSpec* s, const double e[12], double S[12], double w[4]) {
  lawk k = law_constants(s);
  urm4 ev[3], Sv[3], wv;
  for (int j = 0; j < 3; j++) {
    ev[j] = *(const urm4u*)(e + 4 * j);
  }
  stress4(s, &k, ev, Sv, &wv);
  for (int j = 0; j < 3; j++) {
    *(urm4u*)(S + 4 * j) = Sv[j];
  }
  *(urm4u*)w = wv;
}


/* deformation gradient and Green strain of triangle t */
static inline void tri_strain(const urMembrane* mb, const double* x, int t, double F[6],
                              double e[3]) {
  const int* v = mb->tri + 3 * t;
  const double* Di = mb->dminv + 4 * t;
  const double *x1 = x + 3 * v[0], *x2 = x + 3 * v[1], *x3 = x + 3 * v[2];
  double d1[3], d2[3];
  urm_sub(d1, x2, x1);
  urm_sub(d2, x3, x1);
  for (int k = 0; k < 3; k++) {
    F[k] = d1[k] * Di[0] + d2[k] * Di[2];
    F[3 + k] = d1[k] * Di[1] + d2[k] * Di[3];
  }
  e[0] = 0.5 * (urm_dot(F, F) - 1);
  e[1] = 0.5 * (urm_dot(F + 3, F + 3) - 1);
  e[2] = urm_dot(F, F + 3);
}


void urm_tri_strain(const urMembrane* mb, const double* x, int t, double F[6], double e[3]) {
  tri_strain(mb, x, t, F, e);
}


void ur_mem_tri_state(const urMembrane* mb, const double* x, int t, double e[3], double S[3]) {
  double F[6];
  urm_tri_strain(mb, x, t, F, e);
  urm_fabric_stress(&mb->spec, e, S, NULL);
}

//---------------------------------- forces --------------------------------------------------------

// the triangle pass also compiled for AVX2, the clone picked at load time (as the engine's lane
// kernels: GCC on x86-64; urNO_CLONES the default only); both give the same bits
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(urNO_CLONES)
#define urmCLONES __attribute__((target_clones("avx2", "default")))
#else
#define urmCLONES
#endif

/* the scratch of a block of 4 triangles, 4 lanes of each: the nodal forces' fabric parts h0
   and h1 (node 2 gets -h0, node 3 -h1, node 1 h0 + h1) and the normal d1 x d2 (twice the area),
   3 components each, which tri_forces turns into the three nodes' forces (urMembrane.ntb
   blocks: ur_mem_state_size's 36 ntb) */
enum {
  urmH0 = 0,
  urmH1 = 3,
  urmNRM = 6,
  urmSCR = 9
};

/* blocks per chunk of the triangle pass: its deformation gradients and strains (9 x 4 doubles a
   block) stay in the first-level cache between the chunk's three loops */
#define urmCHUNK 8

/* the positions (or velocities) of 4 nodes, coordinate by coordinate: each node's 3 doubles read
   as 4 (the fourth belongs to the next node or, for the last, to the next array of the state),
   then transposed */
AI void rows3(const double* x, const int* n, urm4 o[3]) {
  urm4 r0 = *(const urm4u*)(x + 3 * n[0]), r1 = *(const urm4u*)(x + 3 * n[1]);
  urm4 r2 = *(const urm4u*)(x + 3 * n[2]), r3 = *(const urm4u*)(x + 3 * n[3]);
  urm4 t0 = __builtin_shuffle(r0, r1, (urm4i){0, 4, 2, 6});
  urm4 t1 = __builtin_shuffle(r0, r1, (urm4i){1, 5, 3, 7});
  urm4 t2 = __builtin_shuffle(r2, r3, (urm4i){0, 4, 2, 6});
  urm4 t3 = __builtin_shuffle(r2, r3, (urm4i){1, 5, 3, 7});
  o[0] = __builtin_shuffle(t0, t2, (urm4i){0, 1, 4, 5});
  o[1] = __builtin_shuffle(t1, t3, (urm4i){0, 1, 4, 5});
  o[2] = __builtin_shuffle(t0, t2, (urm4i){2, 3, 6, 7});
}


/* the fabric of every triangle, 4 at a time, in triangle order: the scratch (sc, urmSCR doubles
   of 4 lanes per block), the volume sum *vol and energy sum *wsum in triangle order (as one
   triangle at a time would add them), the largest yarn strain in *emax. By chunks of blocks,
   three loops each (geometry, law, forces): short enough for the next blocks' work to overlap
   the law's square root and division. */
static urmCLONES void tri_pass(const urMembrane* mb, const double* x, const double* v, double* sc,
                               double* vol, double* wsum, double* emax) {
  const urMemSpec* s = &mb->spec;
  lawk lk = law_constants(s);
  double V = 0, W = 0;
  urm4 em = bc4(0);
  for (int b0 = 0; b0 < mb->ntb; b0 += urmCHUNK) {
    int nb = mb->ntb - b0 < urmCHUNK ? mb->ntb - b0 : urmCHUNK;
    urm4 Fc[urmCHUNK][6], Ec[urmCHUNK][3]; /* deformation gradients; strains, then stresses */

    // deformation gradient and Green strain (tri_strain), the normal, the volume term
    for (int q = 0; q < nb; q++) {
      int b = b0 + q;
      const int* n4 = mb->tri4 + 12 * b;
      const double* k4 = mb->tk4 + 24 * b;
      double* o = sc + 4 * urmSCR * b;
      urm4 X[3][3]; /* node, coordinate */
      for (int j = 0; j < 3; j++) {
        rows3(x, n4 + 4 * j, X[j]);
      }
      urm4 Di[4];
      for (int j = 0; j < 4; j++) {
        Di[j] = *(const urm4u*)(k4 + 4 * j);
      }
      urm4 d1[3], d2[3], *F = Fc[q];
      for (int c = 0; c < 3; c++) {
        d1[c] = X[1][c] - X[0][c];
        d2[c] = X[2][c] - X[0][c];
      }
      for (int c = 0; c < 3; c++) {
        F[c] = d1[c] * Di[0] + d2[c] * Di[2];
        F[3 + c] = d1[c] * Di[1] + d2[c] * Di[3];
      }
      Ec[q][0] = bc4(0.5) * ((F[0] * F[0] + F[1] * F[1] + F[2] * F[2]) - bc4(1));
      Ec[q][1] = bc4(0.5) * ((F[3] * F[3] + F[4] * F[4] + F[5] * F[5]) - bc4(1));
      Ec[q][2] = F[0] * F[3] + F[1] * F[4] + F[2] * F[5];
      *(urm4u*)(o + 4 * urmNRM) = d1[1] * d2[2] - d1[2] * d2[1];
      *(urm4u*)(o + 4 * urmNRM + 4) = d1[2] * d2[0] - d1[0] * d2[2];
      *(urm4u*)(o + 4 * urmNRM + 8) = d1[0] * d2[1] - d1[1] * d2[0];
      urm4 c0 = X[1][1] * X[2][2] - X[1][2] * X[2][1];
      urm4 c1 = X[1][2] * X[2][0] - X[1][0] * X[2][2];
      urm4 c2 = X[1][0] * X[2][1] - X[1][1] * X[2][0];
      urm4 vt = X[0][0] * c0 + X[0][1] * c1 + X[0][2] * c2;
      int nl = mb->nt - 4 * b < 4 ? mb->nt - 4 * b : 4; /* the padding's lanes left out */
      for (int l = 0; l < nl; l++) {
        V += vt[l];
      }
    }

    // the law: the stress in place of the strain, the energy, the largest yarn strain
    for (int q = 0; q < nb; q++) {
      int b = b0 + q;
      urm4 S[3], w;
      stress4(s, &lk, Ec[q], S, &w);
      em = sel4(Ec[q][0] > em, Ec[q][0], em);
      em = sel4(Ec[q][1] > em, Ec[q][1], em);
      for (int c = 0; c < 3; c++) {
        Ec[q][c] = S[c];
      }
      urm4 wa = w * *(const urm4u*)(mb->tk4 + 24 * b + 16);
      int nl = mb->nt - 4 * b < 4 ? mb->nt - 4 * b : 4;
      for (int l = 0; l < nl; l++) {
        W += wa[l];
      }
    }

    // material damping where beta > 0, the nodal forces' fabric parts
    for (int q = 0; q < nb; q++) {
      int b = b0 + q;
      const int* n4 = mb->tri4 + 12 * b;
      const double* k4 = mb->tk4 + 24 * b;
      double* o = sc + 4 * urmSCR * b;
      urm4 Vn[3][3], Di[4], *F = Fc[q], *S = Ec[q];
      for (int j = 0; j < 3; j++) {
        rows3(v, n4 + 4 * j, Vn[j]);
      }
      for (int j = 0; j < 4; j++) {
        Di[j] = *(const urm4u*)(k4 + 4 * j);
      }
      urm4 A0 = *(const urm4u*)(k4 + 16), bt = *(const urm4u*)(k4 + 20);
      urm4 dv1[3], dv2[3], L[6];
      for (int c = 0; c < 3; c++) {
        dv1[c] = Vn[1][c] - Vn[0][c];
        dv2[c] = Vn[2][c] - Vn[0][c];
      }
      for (int c = 0; c < 3; c++) {
        L[c] = dv1[c] * Di[0] + dv2[c] * Di[2];
        L[3 + c] = dv1[c] * Di[1] + dv2[c] * Di[3];
      }
      urm4i damped = bt > bc4(0);
      urm4 FL = F[0] * L[0] + F[1] * L[1] + F[2] * L[2];
      urm4 FL33 = F[3] * L[3] + F[4] * L[4] + F[5] * L[5];
      urm4 FL03 = F[0] * L[3] + F[1] * L[4] + F[2] * L[5];
      urm4 FL30 = F[3] * L[0] + F[4] * L[1] + F[5] * L[2];
      S[0] = sel4(damped, S[0] + bt * bc4(s->e1t) * FL, S[0]);
      S[1] = sel4(damped, S[1] + bt * bc4(s->e2t) * FL33, S[1]);
      S[2] = sel4(damped, S[2] + bt * bc4(s->gtt) * (FL03 + FL30), S[2]);
      for (int c = 0; c < 3; c++) {
        urm4 P0 = A0 * (F[c] * S[0] + F[3 + c] * S[2]);
        urm4 P1 = A0 * (F[c] * S[2] + F[3 + c] * S[1]);
        *(urm4u*)(o + 4 * (urmH0 + c)) = P0 * Di[0] + P1 * Di[1];
        *(urm4u*)(o + 4 * (urmH1 + c)) = P0 * Di[2] + P1 * Di[3];
      }
    }
  }
  double m = 0;
  for (int l = 0; l < 4; l++) {
    if (em[l] > m) {
      m = em[l];
    }
  }
  *vol = V;
  *wsum = W;
  *emax = m;
}


/* each triangle's nodal forces at the gas pressure's pg6 = (p - patm) / 6, in place of its
   scratch: node 1's force fp + h0 + h1 (fp = pg6 d1 x d2) where the normal was, node 2's fp - h0
   where h0 was, node 3's fp - h1 where h1 was (the offsets membrane_mesh.c's adj names) */
static urmCLONES void tri_forces(const urMembrane* mb, double pg6, double* sc) {
  urm4 pg = bc4(pg6);
  for (int b = 0; b < mb->ntb; b++) {
    double* o = sc + 4 * urmSCR * b;
    for (int c = 0; c < 3; c++) {
      urm4 h0 = *(urm4u*)(o + 4 * (urmH0 + c)), h1 = *(urm4u*)(o + 4 * (urmH1 + c));
      urm4 fp = pg * *(urm4u*)(o + 4 * (urmNRM + c));
      *(urm4u*)(o + 4 * (urmH0 + c)) = fp - h0;
      *(urm4u*)(o + 4 * (urmH1 + c)) = fp - h1;
      *(urm4u*)(o + 4 * (urmNRM + c)) = fp + h0 + h1;
    }
  }
}


void ur_mem_forces(const urMembrane* mb, double* st, double* f, urMemInfo* info) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn;
  const double *x = st, *v = st + 3 * nn;
  double *sc = st + 18 * nn, *scr = sc + urMEMS_N;

  // the fabric of every triangle, the enclosed volume (divergence theorem, ur_mem_volume's sum)
  double V, wsum, emax;
  tri_pass(mb, x, v, scr, &V, &wsum, &emax);
  V /= 6;

  // gas: the pressure of the remaining mass; each triangle's nodal forces, summed on every node
  // in triangle order
  double p = ur_mem_pressure(mb, V, sc[urMEMS_MGAS]);
  tri_forces(mb, (p - s->patm) / 6, scr);
  for (int i = 0; i < nn; i++) {
    double a0 = 0, a1 = 0, a2 = 0;
    for (int j = mb->adj0[i]; j < mb->adj0[i + 1]; j++) {
      const double* o = scr + mb->adj[j];
      a0 += o[0];
      a1 += o[4];
      a2 += o[8];
    }
    f[3 * i] = a0;
    f[3 * i + 1] = a1;
    f[3 * i + 2] = a2;
  }
  sc[urMEMS_P] = p;
  sc[urMEMS_V] = V;
  sc[urMEMS_STRAIN] = emax;
  sc[urMEMS_EFAB] = wsum;
  if (info) {
    info->pressure = p;
    info->volume = V;
    info->strain = emax;
    info->efabric = wsum;
  }
}
