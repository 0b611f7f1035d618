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
 * wrinkle=1 replaces the relaxed energy by OpenRadioss LAW19's rule (reduce(): the compressive
 * principal stress scaled by re; faster, no potential).
 * Sources: materials-membrane sheet C.1, C.2, A.3, C.3. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_internal.h"

//---------------------------------- law -----------------------------------------------------------

// 4 doubles of a vector (GCC vector extensions: the law over 4 triangles below)
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double urm4 __attribute__((vector_size(32)));

/* the law's constants, computed once per force evaluation: the taut law's stiffnesses, its
   compliance (for the wrinkled state), the shear law (stiffnesses kept above 1e-6 of the tensile
   one so that its inverse exists) */
typedef struct {
  double c11, c12, c22; /* S11 = c11 E11 + c12 E22, S22 = c12 E11 + c22 E22 */
  double a11, a12, a22; /* and back: E11 = a11 S11 + a12 S22, E22 = a12 S11 + a22 S22 */
  double g0, gt, gl;    /* shear stiffness before and after the lock, sine of the lock angle */
  double re;            /* share of the taut law kept (its compression) */
  int reduce;           /* wrinkle=1: LAW19's rule in place of the relaxed energy (reduce()) */
  struct {              /* the vector law's constants, each broadcast to 4 lanes */
    urm4 a11, a12, a22, g0, gt, gl, tl, ig0, igt, a12x2, wk0;
  } v;
} lawk;

static lawk law_constants(const urMemSpec* s) {
  double nu21 = s->nu12 * s->e2t / s->e1t, q = 1 / (1 - s->nu12 * nu21);
  double gmin = 1e-6 * fmax(s->e1t, s->e2t);
  lawk k = {q * s->e1t, q * s->e1t * nu21,  q * s->e2t,         1 / s->e1t,   -s->nu12 / s->e1t,
            1 / s->e2t, fmax(s->g0t, gmin), fmax(s->gtt, gmin), sin(s->lock), s->re};
  k.reduce = s->wrinkle == urMEM_REDUCE;
  double tl = k.g0 * k.gl;
#define urmBC(x) ((urm4){x, x, x, x})
  k.v.a11 = urmBC(k.a11);
  k.v.a12 = urmBC(k.a12);
  k.v.a22 = urmBC(k.a22);
  k.v.g0 = urmBC(k.g0);
  k.v.gt = urmBC(k.gt);
  k.v.gl = urmBC(k.gl);
  k.v.tl = urmBC(tl);
  k.v.ig0 = urmBC(1 / k.g0);
  k.v.igt = urmBC(1 / k.gt);
  k.v.a12x2 = urmBC(2 * k.a12);
  k.v.wk0 = urmBC(0.5 * tl * k.gl);
#undef urmBC
  return k;
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


/* the five candidates of wrinkled(): the major principal strain's direction (half-angle
   formulas: no trigonometry), the yarns', the bias directions, each with its best sigma; u and
   its G replaced where one beats *G */
static void candidates(const lawk* k, const double E[3], double* u1, double* u2, double* G) {
  double sig;
  double hd = 0.5 * (E[0] - E[1]), rr = sqrt(hd * hd + E[2] * E[2]), c2 = rr > 0 ? hd / rr : 1;
  double s2 = 0.5 * (1 - c2); /* fmax(0, s2) without the libm call */
  double cp = sqrt(0.5 * (1 + c2)), sp = copysign(sqrt(s2 > 0 ? s2 : 0), E[2]);
  const double h2 = 0.70710678118654752;
  const double cand[5][2] = {{cp, sp}, {1, 0}, {0, 1}, {h2, h2}, {h2, -h2}};
  for (int j = 0; j < 5; j++) {
    double c = cand[j][0], sn = cand[j][1];
    double g = uniaxial(k, E, c, sn, &sig);
    if (g > *G) {
      *G = g;
      *u1 = sqrt(sig) * c;
      *u2 = sqrt(sig) * sn;
    }
  }
}


/* the wrinkled state of Green strain e (one positive principal strain, the taut stress not
   positive): the relaxed energy W_r(E) = min over D >= 0 of W(E + D) (Pipkin 1986), by duality
   the maximum over stresses S >= 0 of G(S) = S:E - W*(S) (W* the taut law's complementary
   energy). The maximum lies on the uniaxial stresses S = u u^T: the best of five directions
   (candidates()), then Newton on u (2 unknowns, kept ascending) until G is stationary, i.e.
   (E - E_m) u = 0 with E_m the gradient of W* at S, the fabric's own strain (E_m - E = a n n^T,
   n normal to u: the wrinkles' slack). S is the gradient of W_r (envelope theorem), W_r = G(S).
   Warm start: uw (may be NULL) holds the triangle's u of its last wrinkled evaluation (0, 0 if
   none). Newton starts there; when its first step is within 1 % of |u| (the strain moved
   little, as between sub-steps: the same maximum, moved a little) the candidates are skipped,
   else they are tried against it (from a strain far away the warm start alone can climb to a
   lower local maximum: test_warm_start). The converged u is written back. Every start ends at
   the same tolerance, a Newton step below 1e-6 of |u| (then taken: ~1e-12 of u left), 40 steps
   at most. */
static void wrinkled(const lawk* k, const double e[3], double S[3], double* w, double* uw) {
  double E[3] = {e[0], e[1], 0.5 * e[2]}, u1 = 1, u2 = 0, G = -1;
  int tried = 0; /* the candidates tried (or not needed) */
  if (uw && (uw[0] != 0 || uw[1] != 0)) {
    u1 = uw[0];
    u2 = uw[1];
    G = u1 * u1 * E[0] + u2 * u2 * E[1] + 2 * u1 * u2 * E[2] - wstar(k, u1 * u1, u2 * u2, u1 * u2);
  } else {
    candidates(k, E, &u1, &u2, &G);
    tried = 1;
  }
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
    double d1 = -(M22 * r1 - M12 * r2) / det, d2 = -(M11 * r2 - M12 * r1) / det;
    if (!tried) {
      // the warm start: kept alone when Newton stays near it
      tried = 1;
      if (!(det > 0 && d1 * d1 + d2 * d2 <= 1e-4 * (u1 * u1 + u2 * u2))) {
        double G0 = G;
        candidates(k, E, &u1, &u2, &G);
        if (G > G0) {
          continue;
        }
      }
    }
    if (!(det > 0)) {
      break;
    }
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
  if (uw) {
    uw[0] = u1;
    uw[1] = u2;
  }
  S[0] = u1 * u1;
  S[1] = u2 * u2;
  S[2] = u1 * u2;
  G = S[0] * E[0] + S[1] * E[1] + 2 * S[2] * E[2] - wstar(k, S[0], S[1], S[2]);
  *w = G > 0 ? G : 0; /* fmax(G, 0) without the libm call (the same bits) */
}


/* wrinkle=1 (urMEM_REDUCE), OpenRadioss LAW19's rule on a taut stress S that has a compressive
   principal stress (m, h: the half sum and half difference of S11, S22): both principal stresses
   compressive, S becomes re S; else the compressive one alone is scaled by re, the principal axes
   and the tensile one kept: S <- beta (S - p2 I) + p2 I, beta = ((1 - re) m / r + 1 + re) / 2,
   r = sqrt(h^2 + S12^2), p2 = m + r. No Newton and no warm start; no potential either: the energy
   density given is the secant 1/2 S:E of the result (at least 0), so an undamped bag's energy
   balance holds only roughly (uasimpact-model(5), BAGS, wrinkle) */
static inline void reduce(const lawk* k, const double e[3], double m, double h, double S[3],
                          double* w) {
  double re = k->re, r = sqrt(h * h + S[2] * S[2]), p2 = m + r;
  if (p2 > 0) {
    double beta = 0.5 * ((1 - re) * m / r + 1 + re);
    S[0] = beta * (S[0] - p2) + p2;
    S[1] = beta * (S[1] - p2) + p2;
    S[2] = beta * S[2];
  } else {
    S[0] = re * S[0];
    S[1] = re * S[1];
    S[2] = re * S[2];
  }
  double wr = 0.5 * (S[0] * e[0] + S[1] * e[1] + S[2] * e[2]);
  *w = wr > 0 ? wr : 0;
}


/* the fabric's stress resultant S (S11, S22, S12) and energy density *w at Green strain e (E11,
   E22, 2 E12): re times the taut law plus 1 - re times its relaxed energy's gradient (tension
   field: taut, wrinkled or slack, never a compressive principal stress), or with wrinkle=1 the
   taut law reduced (reduce()); uw: the triangle's warm start (wrinkled(), may be NULL) */
static inline void stress(const urMemSpec* s, const lawk* k, const double e[3], double S[3],
                          double* w, double* uw) {
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
  if (k->reduce) {
    reduce(k, e, m, h, S, w);
    return;
  }
  double Sr[3] = {0, 0, 0}, wr = 0;
  double me = 0.5 * (e[0] + e[1]), he = 0.5 * (e[0] - e[1]);
  if (me + sqrt(he * he + 0.25 * e[2] * e[2]) > 0) {
    wrinkled(k, e, Sr, &wr, uw); // else slack: no stress, no energy
  }
  double re = k->re;
  S[0] = re * S[0] + (1 - re) * Sr[0];
  S[1] = re * S[1] + (1 - re) * Sr[1];
  S[2] = re * S[2] + (1 - re) * Sr[2];
  *w = re * wt + (1 - re) * wr;
}


void urm_fabric_stress(const urMemSpec* s, const double e[3], double S[3], double* w) {
  urm_fabric_stress_warm(s, e, S, w, NULL);
}


void urm_fabric_stress_warm(const urMemSpec* s, const double e[3], double S[3], double* w,
                            double* uw) {
  lawk k = law_constants(s);
  double ww;
  stress(s, &k, e, S, &ww, uw);
  if (w) {
    *w = ww;
  }
}


//---------------------------------- law over 4 triangles ------------------------------------------

// the same law as stress() over 4 triangles at once (GCC vector extensions): the taut law
// branch-free, both sides of the shear's branch computed and the lane's side selected, every
// operation the scalar one's in the same order; the wrinkled lanes through wrinkled4(), the
// warm-started Newton of wrinkled() masked lane by lane; a lane off its path (and every lane
// without warm starts) goes through the scalar stress() itself. So each lane's bits are
// stress()'s (test_membrane_fabric checks it; a change of the law goes into both). ISO C mode:
// no contraction into FMA in either.
typedef long long urm4i __attribute__((vector_size(32)));
typedef double urm4u __attribute__((vector_size(32), aligned(8))); /* unaligned load, store */

#define AI static inline __attribute__((always_inline))

/* blocks per chunk of the triangle pass: its deformation gradients, strains and stresses (13 x 4
   doubles a block, 6.7 kB) stay in the first-level cache between the chunk's three loops; its
   wrinkled lanes are packed 4 at a time, so the more blocks the fewer half-empty last groups */
#define urmCHUNK 16

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
AI urm4 shear4(const lawk* k, urm4 g, urm4* w) {
  double gl = k->gl;
  urm4 ag = fabs4(g);
  urm4i lin = ag <= bc4(gl);
  urm4 wl = bc4(0.5) * bc4(k->g0) * g * g, sl = bc4(k->g0) * g;
  urm4 d = ag - bc4(gl);
  urm4 wk = bc4(0.5 * k->g0 * gl * gl) + bc4(k->g0 * gl) * d + bc4(0.5) * bc4(k->gt) * d * d;
  urm4 sk = copysign4(bc4(k->g0 * gl) + bc4(k->gt) * d, g);
  *w = sel4(lin, wl, wk);
  return sel4(lin, sl, sk);
}

/* reduce() over the lanes of mask act (the others kept), each lane reduce()'s operations */
AI void reduce4(const lawk* k, const urm4 e[3], urm4i act, urm4 m, urm4 h, urm4 S[3], urm4* w) {
  urm4 re = bc4(k->re), r = sqrt4(h * h + S[2] * S[2]), p2 = m + r;
  urm4i one = p2 > bc4(0); /* one principal stress compressive: r > 0 there */
  urm4 beta = bc4(0.5) * ((bc4(1) - re) * m / r + bc4(1) + re);
  urm4 S0 = sel4(one, beta * (S[0] - p2) + p2, re * S[0]);
  urm4 S1 = sel4(one, beta * (S[1] - p2) + p2, re * S[1]);
  urm4 S2 = sel4(one, beta * S[2], re * S[2]);
  urm4 wr = bc4(0.5) * (S0 * e[0] + S1 * e[1] + S2 * e[2]);
  wr = sel4(wr > bc4(0), wr, bc4(0));
  S[0] = sel4(act, S0, S[0]);
  S[1] = sel4(act, S1, S[1]);
  S[2] = sel4(act, S2, S[2]);
  *w = sel4(act, wr, *w);
}

/* 1 where any lane of the mask is set; 1 where every lane is. A mask's lanes are all ones or
   zeros: on x86-64 the two halves joined, then the sign bits of both lanes at once (SSE2's
   movmskpd; 4 instructions instead of 8 extractions and ors, most of them on the Newton's
   every iteration) */
#if defined(__x86_64__) && defined(__GNUC__)
typedef long long urm2i __attribute__((vector_size(16)));
typedef double urm2 __attribute__((vector_size(16)));
typedef union {
  urm4i v;
  urm2i h[2];
} urmHalves;
AI int any4(urm4i m) {
  urmHalves u = {m};
  return __builtin_ia32_movmskpd((urm2)(u.h[0] | u.h[1])) != 0;
}
AI int all4(urm4i m) {
  urmHalves u = {m};
  return __builtin_ia32_movmskpd((urm2)(u.h[0] & u.h[1])) == 3;
}
#else
AI int any4(urm4i m) {
  return (m[0] | m[1] | m[2] | m[3]) != 0;
}
AI int all4(urm4i m) {
  return (m[0] & m[1] & m[2] & m[3]) != 0;
}
#endif

/* shear_inv() over 4 lanes */
AI urm4 shear_inv4(const lawk* k, urm4 tau, urm4* c) {
  urm4 at = fabs4(tau), tl = k->v.tl;
  urm4i lin = at <= tl;
  if (all4(lin)) { /* one side only: its division alone (the same bits) */
    *c = k->v.ig0;
    return tau / k->v.g0;
  }
  *c = sel4(lin, k->v.ig0, k->v.igt);
  urm4 rl = tau / k->v.g0;
  urm4 rk = copysign4(k->v.gl + (at - tl) / k->v.gt, tau);
  return sel4(lin, rl, rk);
}

/* wstar() over 4 lanes */
AI urm4 wstar4(const lawk* k, urm4 S11, urm4 S22, urm4 S12) {
  urm4 w = bc4(0.5) * (k->v.a11 * S11 * S11 + k->v.a12x2 * S11 * S22 + k->v.a22 * S22 * S22);
  urm4 at = fabs4(S12), tl = k->v.tl;
  urm4i lin = at <= tl;
  if (all4(lin)) { /* one side only: its division alone (the same bits) */
    return w + bc4(0.5) * S12 * S12 / k->v.g0;
  }
  urm4 wl = w + bc4(0.5) * S12 * S12 / k->v.g0;
  urm4 wk = w + k->v.wk0 + k->v.gl * (at - tl) + bc4(0.5) * (at - tl) * (at - tl) / k->v.gt;
  return sel4(lin, wl, wk);
}

/* G(u) = u^T E u - W*(u u^T) over 4 lanes, as wrinkled() writes it */
AI urm4 gdual4(const lawk* k, const urm4 E[3], urm4 u1, urm4 u2) {
  return u1 * u1 * E[0] + u2 * u2 * E[1] + bc4(2) * u1 * u2 * E[2] -
         wstar4(k, u1 * u1, u2 * u2, u1 * u2);
}

/* uniaxial() over 4 lanes along (c, sn): G in the return, sigma in *sig (both 0 where the strain
   along the direction is not positive), each lane the scalar code's operations in its order */
AI urm4 uniaxial4(const lawk* k, const urm4 E[3], urm4 c, urm4 sn, urm4* sig) {
  urm4 lam = c * c * E[0] + sn * sn * E[1] + bc4(2) * c * sn * E[2];
  urm4i pos = lam > bc4(0);
  urm4 cs = fabs4(c * sn), c2 = c * c, s2 = sn * sn;
  urm4 q = c2 * c2 * k->v.a11 + bc4(2) * c2 * s2 * k->v.a12 + s2 * s2 * k->v.a22;
  urm4 sg = lam / (q + cs * cs / k->v.g0);
  urm4 sk = (lam - cs * k->v.gl + cs * k->v.g0 * k->v.gl / k->v.gt) / (q + cs * cs / k->v.gt);
  sg = sel4(sg * cs > k->v.tl, sk, sg);
  urm4 g = sg * lam - wstar4(k, sg * c2, sg * s2, sg * c * sn);
  *sig = sel4(pos, sg, bc4(0));
  return sel4(pos, g, bc4(0));
}

/* candidates() over the 4 lanes of mask act: the same five directions in the same order, u and
   G replaced lane by lane where one beats G */
AI void candidates4(const lawk* k, const urm4 E[3], urm4i act, urm4* u1, urm4* u2, urm4* G) {
  urm4 hd = bc4(0.5) * (E[0] - E[1]), rr = sqrt4(hd * hd + E[2] * E[2]);
  urm4 c2 = sel4(rr > bc4(0), hd / rr, bc4(1));
  urm4 s2 = bc4(0.5) * (bc4(1) - c2);
  urm4 cp = sqrt4(bc4(0.5) * (bc4(1) + c2));
  urm4 sp = copysign4(sqrt4(sel4(s2 > bc4(0), s2, bc4(0))), E[2]);
  const double h2 = 0.70710678118654752;
  urm4 cc[5] = {cp, bc4(1), bc4(0), bc4(h2), bc4(h2)};
  urm4 ss[5] = {sp, bc4(0), bc4(1), bc4(h2), bc4(-h2)};
  for (int j = 0; j < 5; j++) {
    urm4 sig, g = uniaxial4(k, E, cc[j], ss[j], &sig);
    urm4i up = act & (g > *G);
    urm4 rs = sqrt4(sig);
    *G = sel4(up, g, *G);
    *u1 = sel4(up, rs * cc[j], *u1);
    *u2 = sel4(up, rs * ss[j], *u2);
  }
}

/* the state of wrinkled4()'s Newton over a group of 4 lanes between iterations (newton_start,
   newton_step, newton_end): two groups' iterations interleaved (stress4_chunk), so that one's
   chain of divisions overlaps the other's; each group's operations are those of the group alone */
typedef struct {
  urm4 E[3], u1, u2, G;
  urm4 Em12n, kkn; /* the shear's inverse at u, carried from the step (fresh) */
  urm4i act, live, fb;
  int it, fresh;
} urmNewton;

/* the group's start: its warm starts from uw (lane l's u at uw[2 l]); 1 while it iterates */
AI int newton_start(const lawk* k, urmNewton* ns, const urm4 e[3], urm4i act, const double* uw) {
  ns->E[0] = e[0];
  ns->E[1] = e[1];
  ns->E[2] = bc4(0.5) * e[2];
  urm4 u1 = {uw[0], uw[2], uw[4], uw[6]}, u2 = {uw[1], uw[3], uw[5], uw[7]};
  urm4i warm = (u1 != bc4(0)) | (u2 != bc4(0));
  ns->u1 = u1;
  ns->u2 = u2;
  ns->act = act;
  ns->fb = act & ~warm;
  ns->live = act & warm;
  ns->G = gdual4(k, ns->E, u1, u2);
  // the shear's inverse at u (Em12, kk): computed at the next step's u while G is, off the
  // iteration's chain of divisions, where every lane's u came from that step (fresh)
  ns->Em12n = bc4(0);
  ns->kkn = bc4(0);
  ns->fresh = 0;
  ns->it = 0;
  return any4(ns->live);
}

/* one Newton iteration of the group (40 at most); 1 while it iterates */
AI int newton_step(const lawk* k, urmNewton* ns) {
  const urm4* E = ns->E;
  urm4 u1 = ns->u1, u2 = ns->u2, G = ns->G, Em12n = ns->Em12n, kkn = ns->kkn;
  urm4i live = ns->live, fb = ns->fb;
  int it = ns->it, fresh = ns->fresh;
  urm4 S11 = u1 * u1, S22 = u2 * u2, S12 = u1 * u2, kk = kkn, Em12 = Em12n;
  if (!fresh) {
    Em12 = bc4(0.5) * shear_inv4(k, S12, &kk);
  }
  urm4 Em11 = k->v.a11 * S11 + k->v.a12 * S22, Em22 = k->v.a12 * S11 + k->v.a22 * S22;
  urm4 r1 = (E[0] - Em11) * u1 + (E[2] - Em12) * u2;
  urm4 r2 = (E[2] - Em12) * u1 + (E[1] - Em22) * u2;
  urm4 M11 = E[0] - (Em11 + bc4(2) * k->v.a11 * S11 + bc4(0.5) * kk * S22);
  urm4 M12 = E[2] - (Em12 + (bc4(2) * k->v.a12 + bc4(0.5) * kk) * S12);
  urm4 M22 = E[1] - (Em22 + bc4(2) * k->v.a22 * S22 + bc4(0.5) * kk * S11);
  urm4 mm = bc4(0.5) * (M11 + M22), hh = bc4(0.5) * (M11 - M22);
  urm4 X = hh * hh + M12 * M12, tr = fabs4(M11) + fabs4(M22), T = bc4(-1e-3) * tr;
  // the shift needs lmax = mm + sqrt(X) only where lmax > T may hold: sqrt(X) below T - mm
  // by 1e-12 relative (far above the roundings of D, D^2, X (1 + 1e-12) and the root) gives
  // lmax <= T, the rounding of mm + sqrt(X) being monotone and T a double (no shift there)
  urm4 D = T - mm;
  urm4i sure = (D > bc4(0)) & (X * bc4(1 + 1e-12) < D * D);
  if (!all4(sure)) {
    urm4 lmax = mm + sqrt4(X);
    urm4i shift = lmax > T;
    urm4 sh = lmax + bc4(1e-3) * tr;
    M11 = sel4(shift, M11 - sh, M11);
    M22 = sel4(shift, M22 - sh, M22);
  }
  urm4 det = M11 * M22 - M12 * M12;
  urm4 d1 = -(M22 * r1 - M12 * r2) / det, d2 = -(M11 * r2 - M12 * r1) / det;
  urm4 dd = d1 * d1 + d2 * d2, uu = u1 * u1 + u2 * u2;
  urm4i pd = det > bc4(0), step = live; /* the lanes that take this iteration's step */
  int redo = 0;
  if (it == 0) {
    // the warm start kept alone only when Newton stays near it; else the candidates tried
    // against it, Newton restarted (the next iteration) where one beats it
    urm4i far = live & ~(pd & (dd <= bc4(1e-4) * uu));
    if (any4(far)) {
      urm4 G0 = G;
      candidates4(k, E, far, &u1, &u2, &G);
      urm4i won = far & (G > G0);
      step &= ~won;
      redo = any4(won); /* a lane restarts from a candidate's u: its shear not carried */
    }
  }
  urm4i stop = step & ~pd; /* not concave even shifted: the scalar code stops there */
  live &= ~stop;
  step &= pd;
  urm4i conv = step & (dd <= bc4(1e-12) * uu);
  u1 = sel4(conv, u1 + d1, u1);
  u2 = sel4(conv, u2 + d2, u2);
  live &= ~conv;
  step &= ~conv;
  // the full step (t = 1) taken when G does not fall beyond rounding; else the scalar code.
  // No lane left to step (the group's last iteration, as a rule): nothing here would change a
  // lane, and the carried inverse is read only by a lane that stepped (the restarted ones
  // recompute theirs)
  if (any4(step)) {
    urm4 v1 = u1 + d1, v2 = u2 + d2, kv;
    urm4 Ev = bc4(0.5) * shear_inv4(k, v1 * v2, &kv);
    urm4 Gn = gdual4(k, E, v1, v2), tol = bc4(1e-13) * fabs4(G);
    urm4i up = Gn >= G - tol;
    fb |= step & ~up;
    live &= ~(step & ~up);
    step &= up;
    u1 = sel4(step, v1, u1);
    u2 = sel4(step, v2, u2);
    G = sel4(step, Gn, G);
    Em12n = Ev; /* every lane still live stepped to v, unless one restarts (redo) */
    kkn = kv;
  }
  fresh = !redo && any4(step);
  ns->u1 = u1;
  ns->u2 = u2;
  ns->G = G;
  ns->Em12n = Em12n;
  ns->kkn = kkn;
  ns->live = live;
  ns->fb = fb;
  ns->fresh = fresh;
  ns->it = ++it;
  return it < 40 && any4(live);
}

/* the group's end: the stress in Sr and energy in *wr (0 for the lanes not done here), uw
   updated for the lanes done; the lanes left to the scalar wrinkled() returned */
AI urm4i newton_end(const lawk* k, const urmNewton* ns, urm4 Sr[3], urm4* wr, double* uw) {
  const urm4* E = ns->E;
  urm4 u1 = ns->u1, u2 = ns->u2;
  urm4i fb = ns->fb, done = ns->act & ~fb;
  for (int l = 0; l < 4; l++) {
    if (done[l]) {
      uw[2 * l] = u1[l];
      uw[2 * l + 1] = u2[l];
    }
  }
  Sr[0] = sel4(done, u1 * u1, bc4(0));
  Sr[1] = sel4(done, u2 * u2, bc4(0));
  Sr[2] = sel4(done, u1 * u2, bc4(0));
  urm4 Gf = Sr[0] * E[0] + Sr[1] * E[1] + bc4(2) * Sr[2] * E[2] - wstar4(k, Sr[0], Sr[1], Sr[2]);
  *wr = sel4(done & (Gf > bc4(0)), Gf, bc4(0));
  return fb;
}

/* wrinkled() over the 4 lanes of mask act, for the paths it takes on nearly every call between
   sub-steps: a warm start (uw: lane l's u at uw[2 l]); where its first Newton step is not within
   1 % of |u| the five candidates (candidates4) tried against it, Newton restarted from the best
   one where it beats the warm start; then full Newton steps that raise G, until a step below
   1e-6 of |u| (or 40 steps, or a Hessian that is not negative definite). Every lane runs the
   scalar code's operations in its order (masked as it finishes), so its bits are wrinkled()'s;
   two of them off the iteration's chain: the shift's square root only where it may shift, the
   shear's inverse at the step's u beside its G.
   A lane off that path (no warm start, a step to backtrack) is left to the scalar wrinkled():
   its bit in the mask returned, its uw untouched. The stress in Sr and energy in *wr (0 for the
   lanes not done here); uw updated for the lanes done. */
AI urm4i wrinkled4(const lawk* k, const urm4 e[3], urm4i act, urm4 Sr[3], urm4* wr, double* uw) {
  urmNewton ns;
  if (newton_start(k, &ns, e, act, uw)) {
    while (newton_step(k, &ns)) {
    }
  }
  return newton_end(k, &ns, Sr, wr, uw);
}

/* stress() over 4 lanes: the taut law on all 4, the wrinkled lanes by wrinkled4() when uw is
   given, each lane left over (no warm start, off wrinkled4's path) by the scalar stress(),
   which recomputes the same taut law bits */
AI void stress4(const urMemSpec* s, const lawk* k, const urm4 e[3], urm4 S[3], urm4* w,
                double* uw) {
  urm4 ws;
  S[0] = bc4(k->c11) * e[0] + bc4(k->c12) * e[1];
  S[1] = bc4(k->c12) * e[0] + bc4(k->c22) * e[1];
  S[2] = shear4(k, e[2], &ws);
  *w = bc4(0.5) * (S[0] * e[0] + S[1] * e[1]) + ws;

  urm4 m = bc4(0.5) * (S[0] + S[1]), h = bc4(0.5) * (S[0] - S[1]);
  urm4i taut = (m >= bc4(0)) & (m * m >= h * h + S[2] * S[2]);
  if (!any4(~taut)) {
    return;
  }
  if (k->reduce) {
    reduce4(k, e, ~taut, m, h, S, w);
    return;
  }
  urm4i slow = ~taut;
  if (uw) {
    urm4 me = bc4(0.5) * (e[0] + e[1]), he = bc4(0.5) * (e[0] - e[1]);
    urm4i pos = me + sqrt4(he * he + bc4(0.25) * e[2] * e[2]) > bc4(0);
    urm4 Sr[3], wr, re = bc4(k->re), re1 = bc4(1 - k->re);
    slow = wrinkled4(k, e, ~taut & pos, Sr, &wr, uw);
    for (int j = 0; j < 3; j++) {
      S[j] = sel4(taut, S[j], re * S[j] + re1 * Sr[j]);
    }
    *w = sel4(taut, *w, re * *w + re1 * wr);
  }
  for (int l = 0; l < 4; l++) {
    if (slow[l]) {
      double el[3] = {e[0][l], e[1][l], e[2][l]}, Sl[3], wl;
      stress(s, k, el, Sl, &wl, uw ? uw + 2 * l : NULL);
      S[0][l] = Sl[0];
      S[1][l] = Sl[1];
      S[2][l] = Sl[2];
      (*w)[l] = wl;
    }
  }
}


/* a group of 4 wrinkled lanes of a chunk (stress4_chunk): the lanes lst[g..g+3] (4 q + c: block
   q, lane c; past n the first again, inactive), their strains, taut stresses and energies, warm
   starts and Newton state */
typedef struct {
  int id[4];
  urm4 St[3], wt;
  double ug[8];
  urmNewton ns;
} urmGroup;

/* gather group g's lanes and start its Newton; 1 while it iterates */
AI int group_start(const lawk* k, urmGroup* gr, const short* lst, int g, int n, const urm4 (*e)[3],
                   const urm4 (*S)[3], const urm4* w, const double* uw) {
  int* id = gr->id;
  for (int l = 0; l < 4; l++) {
    id[l] = lst[g + l < n ? g + l : g];
  }
  urm4i act = {-1, g + 1 < n ? -1 : 0, g + 2 < n ? -1 : 0, g + 3 < n ? -1 : 0};
  int q0 = id[0] >> 2, q1 = id[1] >> 2, q2 = id[2] >> 2, q3 = id[3] >> 2;
  int c0 = id[0] & 3, c1 = id[1] & 3, c2 = id[2] & 3, c3 = id[3] & 3;
#define urmGAT(j) ((urm4){e[q0][j][c0], e[q1][j][c1], e[q2][j][c2], e[q3][j][c3]})
  const urm4 eg[3] = {urmGAT(0), urmGAT(1), urmGAT(2)};
#undef urmGAT
  for (int j = 0; j < 3; j++) {
    gr->St[j] = (urm4){S[q0][j][c0], S[q1][j][c1], S[q2][j][c2], S[q3][j][c3]};
  }
  gr->wt = (urm4){w[q0][c0], w[q1][c1], w[q2][c2], w[q3][c3]};
  for (int l = 0; l < 4; l++) {
    gr->ug[2 * l] = uw[2 * id[l]];
    gr->ug[2 * l + 1] = uw[2 * id[l] + 1];
  }
  return newton_start(k, &gr->ns, eg, act, gr->ug);
}

/* end group g's Newton, its stresses, energies and warm starts scattered back; the lanes off
   wrinkled4's path by the scalar stress(), whole */
AI void group_end(const urMemSpec* s, const lawk* k, urmGroup* gr, int g, int n, const urm4 (*e)[3],
                  urm4 (*S)[3], urm4* w, double* uw) {
  urm4 Sr[3], wr, *St = gr->St, re = bc4(k->re), re1 = bc4(1 - k->re);
  urm4i slow = newton_end(k, &gr->ns, Sr, &wr, gr->ug);
  for (int j = 0; j < 3; j++) {
    St[j] = re * St[j] + re1 * Sr[j];
  }
  urm4 wt = re * gr->wt + re1 * wr;
  for (int l = 0; l < 4 && g + l < n; l++) {
    int q = gr->id[l] >> 2, c = gr->id[l] & 3;
    double* ul = uw + 2 * gr->id[l];
    if (slow[l]) {
      double el[3] = {e[q][0][c], e[q][1][c], e[q][2][c]}, Sl[3], wl;
      stress(s, k, el, Sl, &wl, ul);
      S[q][0][c] = Sl[0];
      S[q][1][c] = Sl[1];
      S[q][2][c] = Sl[2];
      w[q][c] = wl;
      continue;
    }
    ul[0] = gr->ug[2 * l];
    ul[1] = gr->ug[2 * l + 1];
    for (int j = 0; j < 3; j++) {
      S[q][j][c] = St[j][l];
    }
    w[q][c] = wt[l];
  }
}


/* stress4() over the nb blocks of 4 lanes of a chunk (at most urmCHUNK, uw the chunk's first
   block's warm starts), the wrinkled lanes packed: the taut law on every block, then the lanes
   that need the wrinkled Newton gathered 4 at a time, across blocks, for wrinkled4()'s Newton (a
   block's taut lanes no longer ride along in its Newton), two such groups' iterations
   interleaved, the stresses scattered back; the lanes left over by the scalar stress(). Each
   lane's operations are stress4()'s, so its bits too. e: the strains, in S the stresses and in w
   the energy densities. */
// GCC 12's AVX2 clone of tri_pass warns that the gathered strains may be uninitialized (they
// are read only from the chunk's nb blocks, all written): a false positive
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
AI void stress4_chunk(const urMemSpec* s, const lawk* k, int nb, const urm4 (*e)[3], urm4 (*S)[3],
                      urm4* w, double* uw) {
  short lst[4 * urmCHUNK];
  int n = 0;
  urm4 re = bc4(k->re), re1 = bc4(1 - k->re);
  for (int q = 0; q < nb; q++) {
    urm4 ws;
    const urm4* eq = e[q];
    urm4* Sq = S[q];
    Sq[0] = bc4(k->c11) * eq[0] + bc4(k->c12) * eq[1];
    Sq[1] = bc4(k->c12) * eq[0] + bc4(k->c22) * eq[1];
    Sq[2] = shear4(k, eq[2], &ws);
    w[q] = bc4(0.5) * (Sq[0] * eq[0] + Sq[1] * eq[1]) + ws;
    urm4 m = bc4(0.5) * (Sq[0] + Sq[1]), h = bc4(0.5) * (Sq[0] - Sq[1]);
    urm4i taut = (m >= bc4(0)) & (m * m >= h * h + Sq[2] * Sq[2]);
    if (!any4(~taut)) {
      continue;
    }
    if (k->reduce) {
      reduce4(k, eq, ~taut, m, h, Sq, &w[q]);
      continue;
    }
    urm4 me = bc4(0.5) * (eq[0] + eq[1]), he = bc4(0.5) * (eq[0] - eq[1]);
    urm4i pos = me + sqrt4(he * he + bc4(0.25) * eq[2] * eq[2]) > bc4(0);
    // slack lanes: no wrinkled stress, no energy (Sr = 0, wr = 0 as stress4's)
    urm4i slack = ~taut & ~pos, wr = ~taut & pos;
    for (int j = 0; j < 3; j++) {
      Sq[j] = sel4(slack, re * Sq[j] + re1 * bc4(0), Sq[j]);
    }
    w[q] = sel4(slack, re * w[q] + re1 * bc4(0), w[q]);
    for (int l = 0; l < 4; l++) { /* without a branch: which lanes wrinkle is the data's */
      lst[n] = (short)(4 * q + l);
      n += wr[l] != 0;
    }
  }
  // the groups two at a time, their Newton iterations interleaved
  for (int g = 0; g < n; g += 8) {
    urmGroup ga, gb;
    int two = g + 4 < n;
    int ra = group_start(k, &ga, lst, g, n, e, S, w, uw);
    int rb = two && group_start(k, &gb, lst, g + 4, n, e, S, w, uw);
    while (ra | rb) {
      if (ra) {
        ra = newton_step(k, &ga.ns);
      }
      if (rb) {
        rb = newton_step(k, &gb.ns);
      }
    }
    group_end(s, k, &ga, g, n, e, S, w, uw);
    if (two) {
      group_end(s, k, &gb, g + 4, n, e, S, w, uw);
    }
  }
}
#pragma GCC diagnostic pop


void urm_fabric_stress4(const urMemSpec* s, const double e[12], double S[12], double w[4]) {
  lawk k = law_constants(s);
  urm4 ev[3], Sv[3], wv;
  for (int j = 0; j < 3; j++) {
    ev[j] = *(const urm4u*)(e + 4 * j);
  }
  stress4(s, &k, ev, Sv, &wv, NULL);
  for (int j = 0; j < 3; j++) {
    *(urm4u*)(S + 4 * j) = Sv[j];
  }
  *(urm4u*)w = wv;
}


void urm_fabric_stress4_warm(const urMemSpec* s, const double e[12], double S[12], double w[4],
                             double uw[8]) {
  lawk k = law_constants(s);
  urm4 ev[3], Sv[3], wv;
  for (int j = 0; j < 3; j++) {
    ev[j] = *(const urm4u*)(e + 4 * j);
  }
  stress4(s, &k, ev, Sv, &wv, uw);
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
   triangle at a time would add them), the largest yarn strain in *emax, each triangle's
   bounding sphere in tb (SoA: centroids' x, y, z, then the farthest node's squared distance, nt
   each: the face contact's culling, engine_membrane.c). By chunks of blocks,
   three loops each (geometry, law, forces): short enough for the next blocks' work to overlap
   the law's square root and division. */
/* tri_pass_t is that pass over the blocks [bb, be) (bb a multiple of urmCHUNK, so each chunk is the
   whole pass's); with vt (the inflation's relaxation, urm_tri_pass_part) each triangle's volume
   term goes there instead of the sums, and no energy, strain or bounding spheres */
AI void tri_pass_t(const urMembrane* mb, const double* x, const double* v, double* sc, double* uw,
                   double* tb, int bb, int be, double* vt, double* vol, double* wsum,
                   double* emax) {
  const urMemSpec* s = &mb->spec;
  int nt = mb->nt;
  lawk lk = law_constants(s);
  double V = 0, W = 0;
  urm4 em = bc4(0);
  for (int b0 = bb; b0 < be; b0 += urmCHUNK) {
    int nb = be - b0 < urmCHUNK ? be - b0 : urmCHUNK;
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
      urm4 vv = X[0][0] * c0 + X[0][1] * c1 + X[0][2] * c2;
      // the bounding sphere: centroid, squared distance of the farthest node
      urm4 cg[3], r2 = bc4(0);
      for (int c = 0; c < 3; c++) {
        cg[c] = (X[0][c] + X[1][c] + X[2][c]) * bc4(1.0 / 3);
      }
      for (int j = 0; j < 3; j++) {
        urm4 r0 = X[j][0] - cg[0], r1 = X[j][1] - cg[1], rz = X[j][2] - cg[2];
        urm4 rr = r0 * r0 + r1 * r1 + rz * rz;
        r2 = sel4(rr > r2, rr, r2);
      }
      int nl = mb->nt - 4 * b < 4 ? mb->nt - 4 * b : 4; /* the padding's lanes left out */
      if (vt) {
        for (int l = 0; l < nl; l++) {
          vt[4 * b + l] = vv[l];
        }
        continue;
      }
      for (int l = 0; l < nl; l++) {
        V += vv[l];
      }
      if (nl == 4) { /* the spheres of 4 consecutive triangles: a vector store each */
        *(urm4u*)(tb + 4 * b) = cg[0];
        *(urm4u*)(tb + nt + 4 * b) = cg[1];
        *(urm4u*)(tb + 2 * nt + 4 * b) = cg[2];
        *(urm4u*)(tb + 3 * nt + 4 * b) = r2;
        continue;
      }
      for (int l = 0; l < nl; l++) {
        int t = 4 * b + l;
        tb[t] = cg[0][l];
        tb[nt + t] = cg[1][l];
        tb[2 * nt + t] = cg[2][l];
        tb[3 * nt + t] = r2[l];
      }
    }

    // the law: the stress in place of the strain, the energy, the largest yarn strain
    urm4 Sc[urmCHUNK][3], wc[urmCHUNK];
    stress4_chunk(s, &lk, nb, (const urm4(*)[3])Ec, Sc, wc, uw + 8 * b0);
    for (int q = 0; q < nb; q++) {
      int b = b0 + q;
      if (vt) {
        for (int c = 0; c < 3; c++) {
          Ec[q][c] = Sc[q][c];
        }
        continue;
      }
      em = sel4(Ec[q][0] > em, Ec[q][0], em);
      em = sel4(Ec[q][1] > em, Ec[q][1], em);
      for (int c = 0; c < 3; c++) {
        Ec[q][c] = Sc[q][c];
      }
      urm4 wa = wc[q] * *(const urm4u*)(mb->tk4 + 24 * b + 16);
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

static urmCLONES void tri_pass(const urMembrane* mb, const double* x, const double* v, double* sc,
                               double* uw, double* tb, double* vol, double* wsum, double* emax) {
  tri_pass_t(mb, x, v, sc, uw, tb, 0, mb->ntb, NULL, vol, wsum, emax);
}

static urmCLONES void tri_pass_part(const urMembrane* mb, const double* x, const double* v,
                                    double* sc, double* uw, int bb, int be, double* vt) {
  double d;
  tri_pass_t(mb, x, v, sc, uw, NULL, bb, be, vt, &d, &d, &d);
}


/* each triangle's nodal forces at the gas pressure's pg6 = (p - patm) / 6 (blocks [b0, b1)), in
   place of its scratch: node 1's force fp + h0 + h1 (fp = pg6 d1 x d2) where the normal was,
   node 2's fp - h0 where h0 was, node 3's fp - h1 where h1 was (the offsets membrane_mesh.c's
   adj names) */
static urmCLONES void tri_forces(const urMembrane* mb, double pg6, double* sc, int b0, int b1) {
  urm4 pg = bc4(pg6);
  for (int b = b0; b < b1; b++) {
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


/* the forces of nodes [i0, i1) into f: each one's triangle corners (tri_forces's) summed in
   triangle order */
static inline void node_forces(const urMembrane* mb, const double* scr, int i0, int i1, double* f) {
  for (int i = i0; i < i1; i++) {
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
}


void ur_mem_forces(const urMembrane* mb, double* st, double* f, urMemInfo* info) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn;
  const double *x = st, *v = st + 3 * nn;
  double *sc = st + 18 * nn, *scr = sc + urMEMS_N;

  // the fabric of every triangle, the enclosed volume (divergence theorem, ur_mem_volume's sum)
  double V, wsum, emax;
  tri_pass(mb, x, v, scr, scr + 36 * (size_t)mb->ntb, scr + 44 * (size_t)mb->ntb, &V, &wsum, &emax);
  V /= 6;

  // gas: the pressure of the remaining mass; each triangle's nodal forces, summed on every node
  // in triangle order
  double p = ur_mem_pressure(mb, V, sc[urMEMS_MGAS]);
  tri_forces(mb, (p - s->patm) / 6, scr, 0, mb->ntb);
  node_forces(mb, scr, 0, nn, f);
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

//---------------------------------- the relaxation's parts ----------------------------------------

int urm_tri_chunk(void) {
  return urmCHUNK;
}


void urm_tri_pass_part(const urMembrane* mb, double* st, int b0, int b1, double* vt) {
  int nn = mb->nn;
  double* scr = st + 18 * nn + urMEMS_N;
  tri_pass_part(mb, st, st + 3 * nn, scr, scr + 36 * (size_t)mb->ntb, b0, b1, vt);
}


void urm_tri_forces_part(const urMembrane* mb, double* st, double pg6, int b0, int b1) {
  tri_forces(mb, pg6, st + 18 * mb->nn + urMEMS_N, b0, b1);
}


void urm_node_forces(const urMembrane* mb, const double* st, int i0, int i1, double* f) {
  node_forces(mb, st + 18 * mb->nn + urMEMS_N, i0, i1, f);
}
