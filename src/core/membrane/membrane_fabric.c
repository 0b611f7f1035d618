/* membrane_fabric.c: the fabric's constant-strain triangles (total Lagrangian): Green strain in
 * the warp/weft axes of the reference metric, the orthotropic plane-stress law (membrane
 * stiffnesses E t), the woven fabric's shear (soft until the locking angle, stiff after:
 * the shape of the paper's Fig. 5, bilinear as OpenRadioss LAW58 without its curve option), the
 * tension-field reduction of the compressive principal stress (wrinkling, LAW19's rule with the
 * factor RE), stiffness-proportional material damping; and the uniform gas pressure on every
 * triangle. Sources: materials-membrane sheet C.1, C.2, A.3, C.3. */
#include <math.h>
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

void ur_mem_forces(const urMembrane* mb, double* st, double* f, urMemInfo* info) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn;
  const double *x = st, *v = st + 3 * nn;
  double* sc = st + 18 * nn;
  memset(f, 0, 3 * (size_t)nn * sizeof(double));

  // gas: volume of the closed surface, pressure of the remaining mass
  double V = ur_mem_volume(mb, x);
  double p = ur_mem_pressure(mb, V, sc[urMEMS_MGAS]);
  double pg6 = (p - s->patm) / 6;

  double emax = 0, wsum = 0;
  lawk lk = law_constants(s);
  for (int t = 0; t < mb->nt; t++) {
    const int* n3 = mb->tri + 3 * t;
    const double* Di = mb->dminv + 4 * t;
    double F[6], e[3], S[3], w;
    tri_strain(mb, x, t, F, e);
    stress(s, &lk, e, S, &w);
    wsum += w * mb->area0[t];

    // largest yarn strain (warp or weft; trellising shear is not a yarn strain)
    double e1 = fmax(e[0], e[1]);
    if (e1 > emax) {
      emax = e1;
    }

    // material damping: beta times the stiffness on the Green strain rate
    if (mb->beta[t] > 0) {
      const double *v1 = v + 3 * n3[0], *v2 = v + 3 * n3[1], *v3 = v + 3 * n3[2];
      double dv1[3], dv2[3], L[6];
      urm_sub(dv1, v2, v1);
      urm_sub(dv2, v3, v1);
      for (int k = 0; k < 3; k++) {
        L[k] = dv1[k] * Di[0] + dv2[k] * Di[2];
        L[3 + k] = dv1[k] * Di[1] + dv2[k] * Di[3];
      }
      double b = mb->beta[t];
      S[0] += b * s->e1t * urm_dot(F, L);
      S[1] += b * s->e2t * urm_dot(F + 3, L + 3);
      S[2] += b * s->gtt * (urm_dot(F, L + 3) + urm_dot(F + 3, L));
    }

    // nodal forces: H = A0 F S Dm^-T, f2 = -H[:,0], f3 = -H[:,1], f1 = -(f2 + f3)
    double A0 = mb->area0[t], P0[3], P1[3];
    for (int k = 0; k < 3; k++) {
      P0[k] = A0 * (F[k] * S[0] + F[3 + k] * S[2]);
      P1[k] = A0 * (F[k] * S[2] + F[3 + k] * S[1]);
    }
    double *f1 = f + 3 * n3[0], *f2 = f + 3 * n3[1], *f3 = f + 3 * n3[2];
    const double *x1 = x + 3 * n3[0], *x2 = x + 3 * n3[1], *x3 = x + 3 * n3[2];
    double d1[3], d2[3], nrm[3];
    urm_sub(d1, x2, x1);
    urm_sub(d2, x3, x1);
    urm_cross(nrm, d1, d2);
    for (int k = 0; k < 3; k++) {
      double h0 = P0[k] * Di[0] + P1[k] * Di[1];
      double h1 = P0[k] * Di[2] + P1[k] * Di[3];
      double fp = pg6 * nrm[k];
      f2[k] += fp - h0;
      f3[k] += fp - h1;
      f1[k] += fp + h0 + h1;
    }
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
