/* membrane_fabric.c: the fabric's constant-strain triangles (total Lagrangian): Green strain in
 * the warp/weft axes of the reference metric, the orthotropic plane-stress law (membrane
 * stiffnesses E t), the woven fabric's shear (soft until the locking angle, stiff after:
 * the shape of the paper's Fig. 5, bilinear as OpenRadioss LAW58 without its curve option),
 * wrinkling by the tension-field theory's relaxed energy (Pipkin 1986, "The relaxed energy
 * density for isotropic elastic membranes", IMA J. Appl. Math. 36:85-99; Steigmann 1990, Proc.
 * R. Soc. A 429:141-173): W_r(E) = min over D >= 0 of W(E + D), taut, wrinkled (uniaxial stress)
 * or slack, never a compressive principal stress, and its stress is exactly dW_r/dE, so the
 * undamped bag conserves energy; a share RE of the taut law is kept (a potential too),
 * stiffness-proportional material damping; and the uniform gas pressure on every triangle.
 * Sources: materials-membrane sheet C.1, C.2, A.3, C.3. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_internal.h"

//---------------------------------- law -----------------------------------------------------------

/* the law's constants, computed once per force evaluation: the taut law's stiffnesses, its
   compliance (for the wrinkled state), the shear law (stiffnesses kept above 1e-6 of the tensile
   one so that its inverse exists) */
typedef struct {
  double c11, c12, c22; /* S11 = c11 E11 + c12 E22, S22 = c12 E11 + c22 E22 */
  double a11, a12, a22; /* and back: E11 = a11 S11 + a12 S22, E22 = a12 S11 + a22 S22 */
  double g0, gt, gl;    /* shear stiffness before and after the lock, sine of the lock angle */
  double re;            /* share of the taut law kept (its compression) */
} lawk;

static lawk law_constants(const urMemSpec* s) {
  double nu21 = s->nu12 * s->e2t / s->e1t, q = 1 / (1 - s->nu12 * nu21);
  double gmin = 1e-6 * fmax(s->e1t, s->e2t);
  return (lawk){q * s->e1t, q * s->e1t * nu21,  q * s->e2t,         1 / s->e1t,   -s->nu12 / s->e1t,
                1 / s->e2t, fmax(s->g0t, gmin), fmax(s->gtt, gmin), sin(s->lock), s->re};
}


/* shear resultant and energy density at engineering Green shear g = 2 E12 (= sin of the
   warp-weft angle change for unstretched yarns): G0 until sin(lock), GT beyond */
static inline double shear(const lawk* k, double g, double* w) {
  double ag = fabs(g), gl = k->gl;
  if (ag <= gl) {
    *w = 0.5 * k->g0 * g * g;
    return k->g0 * g;
  }
  double d = ag - gl;
  *w = 0.5 * k->g0 * gl * gl + k->g0 * gl * d + 0.5 * k->gt * d * d;
  return copysign(k->g0 * gl + k->gt * d, g);
}


/* the shear law's inverse: the engineering shear strain at shear resultant tau, its slope in *c */
static inline double shear_inv(const lawk* k, double tau, double* c) {
  double at = fabs(tau), tl = k->g0 * k->gl;
  if (at <= tl) {
    *c = 1 / k->g0;
    return tau / k->g0;
  }
  *c = 1 / k->gt;
  return copysign(k->gl + (at - tl) / k->gt, tau);
}


/* the complementary energy W*(S) of the taut law (S11, S22, S12) */
static inline double wstar(const lawk* k, double S11, double S22, double S12) {
  double w = 0.5 * (k->a11 * S11 * S11 + 2 * k->a12 * S11 * S22 + k->a22 * S22 * S22);
  double at = fabs(S12), tl = k->g0 * k->gl;
  if (at <= tl) {
    return w + 0.5 * S12 * S12 / k->g0;
  }
  return w + 0.5 * tl * k->gl + k->gl * (at - tl) + 0.5 * (at - tl) * (at - tl) / k->gt;
}


/* the largest S:E - W*(S) over the uniaxial stresses S = sigma m m^T along m = (c, sn): sigma in
   *sig (the strain along m, lam, equals the fabric's own there) */
static double uniaxial(const lawk* k, const double E[3], double c, double sn, double* sig) {
  double lam = c * c * E[0] + sn * sn * E[1] + 2 * c * sn * E[2];
  if (!(lam > 0)) {
    *sig = 0;
    return 0;
  }
  double cs = fabs(c * sn), c2 = c * c, s2 = sn * sn;
  double q = c2 * c2 * k->a11 + 2 * c2 * s2 * k->a12 + s2 * s2 * k->a22;
  double sg = lam / (q + cs * cs / k->g0);
  if (sg * cs > k->g0 * k->gl) {
    sg = (lam - cs * k->gl + cs * k->g0 * k->gl / k->gt) / (q + cs * cs / k->gt);
  }
  *sig = sg;
  return sg * lam - wstar(k, sg * c2, sg * s2, sg * c * sn);
}


/* the wrinkled state of Green strain e (one positive principal strain, the taut stress not
   positive): the relaxed energy W_r(E) = min over D >= 0 of W(E + D) (Pipkin 1986), by duality
   the maximum over stresses S >= 0 of G(S) = S:E - W*(S) (W* the taut law's complementary
   energy). The maximum lies on the uniaxial stresses S = u u^T: the best of five directions
   (the major principal strain's, the yarns', the bias, each with its best sigma), then Newton on u
   (2 unknowns, kept ascending) until G is stationary, i.e. (E - E_m) u = 0 with E_m the
   gradient of W* at S, the fabric's own strain (E_m - E = a n n^T, n normal to u: the wrinkles'
   slack). S is the gradient of W_r (envelope theorem), W_r = G(S). */
static void wrinkled(const lawk* k, const double e[3], double S[3], double* w) {
  // candidates: the yarns, the bias directions and the major principal strain (half-angle
  // formulas: no trigonometry)
  double E[3] = {e[0], e[1], 0.5 * e[2]}, sig, best = -1, bc = 1, bs = 0;
  double hd = 0.5 * (E[0] - E[1]), rr = sqrt(hd * hd + E[2] * E[2]), c2 = rr > 0 ? hd / rr : 1;
  double cp = sqrt(0.5 * (1 + c2)), sp = copysign(sqrt(fmax(0, 0.5 * (1 - c2))), E[2]);
  const double h2 = 0.70710678118654752;
  const double cand[5][2] = {{cp, sp}, {1, 0}, {0, 1}, {h2, h2}, {h2, -h2}};
  for (int j = 0; j < 5; j++) {
    double c = cand[j][0], sn = cand[j][1];
    double g = uniaxial(k, E, c, sn, &sig);
    if (g > best) {
      best = g;
      bc = sqrt(sig) * c;
      bs = sqrt(sig) * sn;
    }
  }
  double u1 = bc, u2 = bs, G = best;
  for (int it = 0; it < 40; it++) {
    double S11 = u1 * u1, S22 = u2 * u2, S12 = u1 * u2, kk;
    double Em11 = k->a11 * S11 + k->a12 * S22, Em22 = k->a12 * S11 + k->a22 * S22;
    double Em12 = 0.5 * shear_inv(k, S12, &kk);
    // half the gradient, (E - E_m) u, and half the Hessian, E - J (J: d(E_m u)/du)
    double r1 = (E[0] - Em11) * u1 + (E[2] - Em12) * u2;
    double r2 = (E[2] - Em12) * u1 + (E[1] - Em22) * u2;
    double M11 = E[0] - (Em11 + 2 * k->a11 * S11 + 0.5 * kk * S22);
    double M12 = E[2] - (Em12 + (2 * k->a12 + 0.5 * kk) * S12);
    double M22 = E[1] - (Em22 + 2 * k->a22 * S22 + 0.5 * kk * S11);
    // not concave here: shift the Hessian (Levenberg) so that the step ascends
    double mm = 0.5 * (M11 + M22), hh = 0.5 * (M11 - M22);
    double lmax = mm + sqrt(hh * hh + M12 * M12), tr = fabs(M11) + fabs(M22);
    if (lmax > -1e-3 * tr) {
      M11 -= lmax + 1e-3 * tr;
      M22 -= lmax + 1e-3 * tr;
    }
    double det = M11 * M22 - M12 * M12;
    if (!(det > 0)) {
      break;
    }
    double d1 = -(M22 * r1 - M12 * r2) / det, d2 = -(M11 * r2 - M12 * r1) / det;
    // a step this small is converged (Newton: the next would be ~1e-12 of u); else backtrack
    // while G falls (beyond rounding)
    if (d1 * d1 + d2 * d2 <= 1e-12 * (u1 * u1 + u2 * u2)) {
      u1 += d1;
      u2 += d2;
      break;
    }
    double t = 1, Gn = G, tol = 1e-13 * fabs(G);
    for (int b = 0; b < 12; b++, t *= 0.5) {
      double v1 = u1 + t * d1, v2 = u2 + t * d2;
      Gn = v1 * v1 * E[0] + v2 * v2 * E[1] + 2 * v1 * v2 * E[2] -
           wstar(k, v1 * v1, v2 * v2, v1 * v2);
      if (Gn >= G - tol) {
        break;
      }
    }
    if (!(Gn >= G - tol)) {
      break;
    }
    u1 += t * d1;
    u2 += t * d2;
    G = Gn;
  }
  S[0] = u1 * u1;
  S[1] = u2 * u2;
  S[2] = u1 * u2;
  G = S[0] * E[0] + S[1] * E[1] + 2 * S[2] * E[2] - wstar(k, S[0], S[1], S[2]);
  *w = fmax(G, 0);
}


/* the fabric's stress resultant S (S11, S22, S12) and energy density *w at Green strain e (E11,
   E22, 2 E12): re times the taut law plus 1 - re times its relaxed energy's gradient (tension
   field: taut, wrinkled or slack, never a compressive principal stress) */
static inline void stress(const urMemSpec* s, const lawk* k, const double e[3], double S[3],
                          double* w) {
  double ws;
  S[0] = k->c11 * e[0] + k->c12 * e[1];
  S[1] = k->c12 * e[0] + k->c22 * e[1];
  S[2] = shear(k, e[2], &ws);
  double wt = 0.5 * (S[0] * e[0] + S[1] * e[1]) + ws;
  *w = wt;

  // taut when the taut stress has no compressive principal stress
  double m = 0.5 * (S[0] + S[1]), h = 0.5 * (S[0] - S[1]);
  if (m >= 0 && m * m >= h * h + S[2] * S[2]) {
    return;
  }
  double Sr[3] = {0, 0, 0}, wr = 0;
  double me = 0.5 * (e[0] + e[1]), he = 0.5 * (e[0] - e[1]);
  if (me + sqrt(he * he + 0.25 * e[2] * e[2]) > 0) {
    wrinkled(k, e, Sr, &wr); // else slack: no stress, no energy
  }
  double re = k->re;
  S[0] = re * S[0] + (1 - re) * Sr[0];
  S[1] = re * S[1] + (1 - re) * Sr[1];
  S[2] = re * S[2] + (1 - re) * Sr[2];
  *w = re * wt + (1 - re) * wr;
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
