/* contact_law.c: force-penetration laws (Hertz with Jackson-Green loading and Brake unloading,
 * tabulated MADYMO-style load/unload, foam area x stress), tabulated curves and friction.
 * Sources: contact-airbag sheet §1.2-1.4 (Hertz; JG 2005 via Willert 2020 eq. 3.289-3.291;
 * Brake 2015 unloading as coded in tmd-lab SPHERE_PLASTIC_PRE.m), §3 (Chou 1994 foam model),
 * §2.6 (regularised Coulomb friction); a hollow part's shell in series, elastic (Reissner,
 * materials-membrane sheet E.3) up to its crush load, then crushing at that load until it
 * bottoms (uasimpact-model(5), Hollow parts).
 */
#include <math.h>

#include "uasimpact/contact.h"

#define JG_LO 1.9 /* JG law used beyond JG_LO * dy (sheet §1.4) */
#define JG_HI 2.2 /* end of the smoothstep blend Hertz -> JG */

/* ---- tabulated curves ---- */

/* index i of the segment [x_i, x_i+1] used for x (clamped to the end segments) */
static int segment(const urCurve* c, double x) {
  int lo = 0, hi = c->n - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (x < c->x[mid])
      hi = mid;
    else
      lo = mid;
  }
  return lo;
}

double ur_curve_eval(const urCurve* c, double x) {
  // empty and single-point curves
  if (c->n <= 0) return 0;
  if (c->n == 1) return c->y[0];

  // linear on the segment, extrapolated beyond the ends
  int i = segment(c, x);
  double dx = c->x[i + 1] - c->x[i];
  if (!(dx > 0)) return c->y[i + 1];
  return c->y[i] + (c->y[i + 1] - c->y[i]) * (x - c->x[i]) / dx;
}

/* smallest x where the curve rises through level y (y_i <= y < y_i+1), else linear
   extrapolation of the first or last segment; for the unloading-curve shift */
static double curve_inverse(const urCurve* c, double y) {
  int n = c->n;
  if (n <= 0) return 0;
  if (n == 1) return c->x[0];

  // first rising crossing inside the table
  for (int i = 0; i < n - 1; i++) {
    if (c->y[i] <= y && y < c->y[i + 1]) {
      return c->x[i] + (y - c->y[i]) * (c->x[i + 1] - c->x[i]) / (c->y[i + 1] - c->y[i]);
    }
  }

  // extrapolate the end segment on the side of y
  int i = y < c->y[0] ? 0 : n - 2;
  double dy = c->y[i + 1] - c->y[i];
  if (!(dy > 0)) return i == 0 ? c->x[0] : c->x[n - 1];
  return c->x[i] + (y - c->y[i]) * (c->x[i + 1] - c->x[i]) / dy;
}

/* ---- Hertz, Jackson-Green, Brake ---- */

void ur_law_hertz(urLaw* law, double E1, double nu1, double R1, double E2, double nu2, double R2,
                  double sy, double nu_yield, int plastic) {
  // effective modulus and radius, R = 0 meaning a flat (sheet §1.1)
  law->type = urLAW_HERTZ;
  law->estar = 1.0 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
  double k = (R1 > 0 ? 1 / R1 : 0) + (R2 > 0 ? 1 / R2 : 0);
  law->radius = k > 0 ? 1 / k : 0;
  law->sy = sy;
  law->nu = nu_yield;
  law->plastic = plastic;
}

double ur_law_range(const urLaw* law) {
  switch (law->type) {
  case urLAW_TABLE: return law->load.n > 0 ? law->load.x[law->load.n - 1] : HUGE_VAL;
  case urLAW_FOAM:
    // solid foam on a backing curve: the curve's data end beyond the lock thickness
    if (law->lock > 0 && law->backing.n > 0)
      return law->lock * law->thickness + law->backing.x[law->backing.n - 1];
    if (law->lock > 0 || law->stress.n <= 0) return HUGE_VAL;
    return law->thickness * law->stress.x[law->stress.n - 1];
  case urLAW_HERTZ: {
    // the total depth at which the layer itself is pressed through (a shell in series
    // takes F(h) / shell_k of it)
    if (!(law->layer_h > 0)) return HUGE_VAL;
    double h = law->layer_h, K = 4.0 / 3.0 * law->estar * sqrt(law->radius);
    double fh = K * h * sqrt(h);
    if (law->shell_k > 0 && law->crush_f > 0 && fh > law->crush_f)
      return h + law->crush_h + law->crush_f / law->shell_k; // the shell bottomed first
    return law->shell_k > 0 ? h + fh / law->shell_k : h;
  }
  default: return HUGE_VAL;
  }
}

void ur_law_hertz_params(const urLaw* law, double* K, double* dy, double* fy) {
  // K = 4/3 E* sqrt(R) (sheet §1.2); JG yield onset dy = R (pi C Sy / (2 E*))^2,
  // C = 1.295 exp(0.736 nu) (sheet §1.4 step 2; Jackson & Green 2005)
  double k = 4.0 / 3.0 * law->estar * sqrt(law->radius);
  *K = k;
  if (law->sy > 0 && law->estar > 0) {
    double C = 1.295 * exp(0.736 * law->nu);
    double t = M_PI * C * law->sy / (2 * law->estar);
    *dy = law->radius * t * t;
    *fy = k * (*dy) * sqrt(*dy);
  } else {
    *dy = HUGE_VAL;
    *fy = HUGE_VAL;
  }
}

double ur_law_backing_k(const urLaw* law, double R) {
  // the same expression as ur_law_hertz_params' K, so that a fixed radius gives the bits of
  // the Hertz law it replaces
  return 4.0 / 3.0 * law->backing_estar * sqrt(R);
}

/* Jackson-Green elastic-plastic loading force at w = d/dy (sheet §1.4; JG 2005) */
static double jackson_green(const urLaw* law, double d, double dy, double fy) {
  double R = law->radius, sy = law->sy;
  double w = d / dy;

  // contact radius a = sqrt(R d (w/1.9)^B), B = 0.14 exp(23 Sy/E*), capped at R
  double B = 0.14 * exp(23 * sy / law->estar);
  double a = sqrt(R * d * pow(w / JG_LO, B));
  if (a > R) a = R;

  // hardness H/Sy = 2.84 (1 - exp(-0.82 (a/R)^-0.7)) (JG 2005 form)
  double hs = 2.84 * (1 - exp(-0.82 * pow(a / R, -0.7)));
  double C = 1.295 * exp(0.736 * law->nu);
  return fy * (exp(-0.25 * pow(w, 5.0 / 12.0)) * w * sqrt(w) +
               4 * hs / C * (1 - exp(-pow(w, 5.0 / 9.0) / 25)) * w);
}

/* Hertz on a layer over bone: beyond the layer's thickness the bone's stiffness takes over
   (materials-membrane sheet F.2: bottoming) */
static double hertz_layer(const urLaw* law, double d, double K) {
  if (!(law->layer_h > 0) || d <= law->layer_h) return K * d * sqrt(d);
  double h = law->layer_h;
  return K * h * sqrt(h) + law->bone_k * (d - h);
}

/* the contact's force at contact depth d (elastic loading: Hertz, or the layer) */
static double contact_force(const urLaw* law, double d, double K) {
  return law->layer_h > 0 ? hertz_layer(law, d, K) : K * d * sqrt(d);
}

/* the force of the contact in series with a shell spring at total depth d: the root of
   d = dc(F) + F / ks, dc the inverse of contact_force (increasing), by bisection on the
   contact depth (60 halvings: to the last bits of d) */
static double series_shell(const urLaw* law, double d, double K) {
  double lo = 0, hi = d;
  for (int i = 0; i < 60; i++) {
    double x = 0.5 * (lo + hi);
    if (x + contact_force(law, x, K) / law->shell_k > d)
      hi = x;
    else
      lo = x;
  }
  return contact_force(law, 0.5 * (lo + hi), K);
}

/* the contact's depth at force f (the inverse of contact_force) */
static double contact_depth(const urLaw* law, double f, double K) {
  double x = pow(f / K, 2.0 / 3.0);
  if (!(law->layer_h > 0) || x <= law->layer_h) return x;
  double h = law->layer_h;
  return h + (f - K * h * sqrt(h)) / law->bone_k;
}

/* the force of the contact in series with a crushing shell at total depth d, the shell crushed
   by c so far: the elastic series on d - c up to the crush load; at it the shell crushes (the
   plateau) until its crushed depth reaches crush_h; then it has bottomed on its contents and
   the contact alone carries more. *cn: the crushed depth after d (never below c). */
static double series_crush(const urLaw* law, double c, double d, double K, double* cn) {
  *cn = c;
  double f = d > c ? series_shell(law, d - c, K) : 0;
  double fc = law->crush_f;
  if (!(fc > 0) || f <= fc) return f;

  // on the plateau: the crushed depth that leaves the contact and the spring at fc
  double e = d - contact_depth(law, fc, K) - fc / law->shell_k;
  if (e < law->crush_h) {
    *cn = e > c ? e : c;
    return fc;
  }

  // bottomed: the spring stays at fc, the contact takes the rest of the depth
  *cn = law->crush_h;
  return contact_force(law, d - law->crush_h - fc / law->shell_k, K);
}

/* Hertz loading curve, with the JG branch blended in over [1.9, 2.2] dy when plastic */
static double hertz_load(const urLaw* law, double d, double K, double dy, double fy) {
  double fh = law->shell_k > 0 ? series_shell(law, d, K) : contact_force(law, d, K);
  if (!law->plastic || d <= JG_LO * dy) return fh;

  // smoothstep blend removes the ~1% jump of the JG fit at 1.9 dy
  double fj = jackson_green(law, d, dy, fy);
  double w = d / dy;
  if (w >= JG_HI) return fj;
  double s = (w - JG_LO) / (JG_HI - JG_LO);
  s = s * s * (3 - 2 * s);
  return (1 - s) * fh + s * fj;
}

/* ---- elastic (rate-free) force of each law ---- */

/* the depth at which the unloading curve, shifted to pass through (dmax, fmax), reaches
   zero: dres = dmax - U^-1(fmax) + U^-1(0) */
static double table_shift(const urLaw* law, double fmax) {
  return curve_inverse(&law->unload, fmax);
}

static double elastic_force(const urLaw* law, const urLawState* s, double d, double area) {
  switch (law->type) {
  case urLAW_HERTZ: {
    double K, dy, fy;
    ur_law_hertz_params(law, &K, &dy, &fy);
    if (law->shell_k > 0) {
      double cn;
      return law->crush_f > 0 ? series_crush(law, s->crush, d, K, &cn) : series_shell(law, d, K);
    }
    if (!law->plastic) return contact_force(law, d, K);
    if (d >= s->dmax) return hertz_load(law, d, K, dy, fy);

    // Brake (2015) unloading: F = 4/3 E* sqrt(Ru) (d - dr)^1.5 with
    // Ru = Fm^2 / ((4/3 E*)^2 (dm - dr)^3), i.e. F = Fm ((d - dr)/(dm - dr))^1.5 (sheet §1.4)
    if (d <= s->dres) return 0;
    double x = (d - s->dres) / (s->dmax - s->dres);
    return s->fmax * x * sqrt(x);
  }

  case urLAW_TABLE: {
    // loading curve; elastic without an unloading curve
    double fl = ur_curve_eval(&law->load, d);
    if (law->unload.n < 2 || d >= s->dmax) return fl;

    // unload/reload along the unloading curve shifted along the depth axis through
    // (dmax, fmax), never above the loading curve
    double xs = table_shift(law, s->fmax);
    double fu = ur_curve_eval(&law->unload, d - s->dmax + xs);
    if (d <= s->dres) fu = 0;
    return fu < fl ? fu : fl;
  }

  case urLAW_FOAM: {
    // F = area x stress(strain), strain = d / thickness (sheet §3.1; Chou 1994), the strain
    // stopping at the lock strain, where the solid foam rests on its rigid backing
    if (!(law->thickness > 0)) return 0;
    double e = d / law->thickness, fb = 0;
    if (law->lock > 0 && e > law->lock) {
      double x = d - law->lock * law->thickness;
      fb = law->backing.n > 0 ? ur_curve_eval(&law->backing, x) : law->backing_k * x * sqrt(x);
      e = law->lock;
    }
    if (d >= s->dmax || !(law->unload_p > 0)) return area * ur_curve_eval(&law->stress, e) + fb;

    // unloading from (em, sm): s = sm ((e - er)/(em - er))^p, er = r em (sheet §3.2)
    double em = s->dmax / law->thickness;
    if (law->lock > 0 && em > law->lock) em = law->lock;
    double sm = ur_curve_eval(&law->stress, em);
    double er = law->unload_r * em;
    if (e <= er || !(em > er)) return fb;
    return area * sm * pow((e - er) / (em - er), law->unload_p) + fb;
  }
  }
  return 0;
}

double ur_law_force(const urLaw* law, const urLawState* s, double d, double rate, double area) {
  // no force without overlap, none while clear of the permanently deformed surface
  if (!(d > 0)) return 0;
  double fe = elastic_force(law, s, d, area);
  if (!(fe > 0)) return 0;

  // rate terms: Hunt-Crossley-type factor and linear damping (sheet §1.3); no adhesion
  double f = fe * (1 + law->chi * rate) + law->damping * rate;
  return f > 0 ? f : 0;
}

void ur_law_commit(const urLaw* law, urLawState* s, double d, double rate, double area) {
  // out of contact: keep the history (permanent set)
  if (!(d > 0)) {
    s->touching = 0;
    return;
  }

  // a crushing shell keeps the depth it crushed (no spring-back beyond its elastic part)
  if (law->type == urLAW_HERTZ && law->shell_k > 0 && law->crush_f > 0) {
    double K, dy, fy, cn;
    ur_law_hertz_params(law, &K, &dy, &fy);
    series_crush(law, s->crush, d, K, &cn);
    s->crush = cn;
  }

  // new maximum depth: record the loading force and the residual depth of each law
  if (d > s->dmax) {
    s->dmax = d;
    switch (law->type) {
    case urLAW_HERTZ: {
      double K, dy, fy;
      ur_law_hertz_params(law, &K, &dy, &fy);
      s->fmax = law->plastic                           ? hertz_load(law, d, K, dy, fy)
                : law->shell_k > 0 || law->layer_h > 0 ? elastic_force(law, s, d, area)
                                                       : K * d * sqrt(d);

      // Brake (2015): dr = dm (1 - Fm / (K dm^1.5)), 0 for Hertzian loading (sheet §1.4)
      double dr = d * (1 - s->fmax / (K * d * sqrt(d)));
      s->dres = law->plastic && dr > 0 ? dr : 0;
      break;
    }
    case urLAW_TABLE:
      s->fmax = ur_curve_eval(&law->load, d);
      if (law->unload.n >= 2) {
        double dr = d - table_shift(law, s->fmax) + curve_inverse(&law->unload, 0);
        s->dres = dr > 0 ? dr : 0;
      } else {
        s->dres = 0;
      }
      break;
    case urLAW_FOAM: {
      double dl = law->lock > 0 ? fmin(d, law->lock * law->thickness) : d;
      s->fmax = law->thickness > 0 ? area * ur_curve_eval(&law->stress, dl / law->thickness) : 0;
      s->dres = law->unload_p > 0 ? law->unload_r * dl : 0;
      break;
    }
    }
  }
  s->touching = elastic_force(law, s, d, area) > 0;
}

/* ---- friction ---- */

void ur_friction(const urLaw* law, double fn, const double vt[3], double out[3]) {
  // regularised Coulomb: Ft = -mu Fn vt / max(|vt|, v_eps) (sheet §2.6)
  double v = sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
  double den = v > law->v_eps ? v : law->v_eps;
  double k = den > 0 && fn > 0 ? -law->mu * fn / den : 0;
  out[0] = k * vt[0];
  out[1] = k * vt[1];
  out[2] = k * vt[2];
}
