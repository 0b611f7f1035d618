/* contact_fixture.h: what the contact-geometry tests share (test_contact_geom.c,
 * test_contact_super.c): a tolerance assertion, random rotations, directions, ellipsoids and
 * pairs, support points, and the independent reference for a pair's separation (the best
 * direction of the Minkowski difference by Nelder-Mead over local charts from many starts).
 * The functions are static __attribute__((unused)) so that each test file takes only what it uses. Include after
 * cmocka.h. */
#ifndef UASIMPACT_CONTACT_FIXTURE_H
#define UASIMPACT_CONTACT_FIXTURE_H

#include <math.h>

#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "uasimpact/contact.h"

#define NPAIR   1000
#define NSAMPLE 20000

/* ---- helpers ---- */

/* |a - b| <= tol with both values printed on failure (cmocka 1.1 has float-only compares) */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)
static __attribute__((unused)) void near_(double a, double b, double tol, const char* what,
                                          const char* file, int line) {
  if (!(fabs(a - b) <= tol)) {
    print_error("%s = %.17g, expected %.17g +- %.3g\n", what, a, b, tol);
    _fail(file, line);
  }
}

/* random rotation matrix (row-major) from a uniform random unit quaternion */
static __attribute__((unused)) void randrot(gsl_rng* rng, double R[9]) {
  double q[4], s = 0;
  for (int i = 0; i < 4; i++) {
    q[i] = gsl_ran_gaussian(rng, 1.0);
    s += q[i] * q[i];
  }
  s = 1.0 / sqrt(s);
  double w = q[0] * s, x = q[1] * s, y = q[2] * s, z = q[3] * s;
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

static __attribute__((unused)) void randunit(gsl_rng* rng, double u[3]) {
  gsl_ran_dir_3d(rng, &u[0], &u[1], &u[2]);
}

static __attribute__((unused)) void randell(gsl_rng* rng, urEllipsoid* e, double rlo, double rhi) {
  e->p = 0;
  randrot(rng, e->R);
  for (int i = 0; i < 3; i++) {
    e->r[i] = rlo + (rhi - rlo) * gsl_rng_uniform(rng);
    e->c[i] = 0;
  }
}

static __attribute__((unused)) double minaxis(const urEllipsoid* e) {
  return fmin(e->r[0], fmin(e->r[1], e->r[2]));
}

/* independent support point: local frame, x_l = D^2 v / |D v| with v = R^T u */
static __attribute__((unused)) void support(const urEllipsoid* e, const double u[3], double x[3]) {
  double v[3], dv[3], n = 0;
  for (int k = 0; k < 3; k++) {
    v[k] = e->R[k] * u[0] + e->R[3 + k] * u[1] + e->R[6 + k] * u[2];
    dv[k] = e->r[k] * v[k];
    n += dv[k] * dv[k];
  }
  n = sqrt(n);
  for (int i = 0; i < 3; i++) {
    x[i] = e->c[i];
    for (int k = 0; k < 3; k++) x[i] += e->R[3 * i + k] * e->r[k] * dv[k] / n;
  }
}

/* boundary point of A - B with outward normal u: w = s_A(u) - s_B(-u) */
static __attribute__((unused)) void mdiff(const urEllipsoid* a, const urEllipsoid* b,
                                          const double u[3], double w[3]) {
  double mu[3] = {-u[0], -u[1], -u[2]}, xa[3], xb[3];
  support(a, u, xa);
  support(b, mu, xb);
  for (int i = 0; i < 3; i++) w[i] = xa[i] - xb[i];
}

/* an objective over directions u for a pair */
typedef double (*dirfn)(const urEllipsoid* a, const urEllipsoid* b, const double u[3]);

/* local chart around u0 for Nelder-Mead */
typedef struct {
  const urEllipsoid* a;
  const urEllipsoid* b;
  dirfn fn;
  double u0[3], t1[3], t2[3];
} chart;

static __attribute__((unused)) void chartdir(const chart* c, const gsl_vector* x, double u[3]) {
  double p = gsl_vector_get(x, 0), q = gsl_vector_get(x, 1), s = 0;
  for (int i = 0; i < 3; i++) {
    u[i] = c->u0[i] + p * c->t1[i] + q * c->t2[i];
    s += u[i] * u[i];
  }
  s = 1.0 / sqrt(s);
  for (int i = 0; i < 3; i++) u[i] *= s;
}

static __attribute__((unused)) void setchart(chart* c, const double u[3]) {
  double e[3] = {1, 0, 0};
  if (fabs(u[0]) > 0.6) {
    e[0] = 0;
    e[1] = 1;
  }
  double d = e[0] * u[0] + e[1] * u[1] + e[2] * u[2], s = 0;
  for (int i = 0; i < 3; i++) {
    c->u0[i] = u[i];
    c->t1[i] = e[i] - d * u[i];
    s += c->t1[i] * c->t1[i];
  }
  s = 1.0 / sqrt(s);
  for (int i = 0; i < 3; i++) c->t1[i] *= s;
  c->t2[0] = u[1] * c->t1[2] - u[2] * c->t1[1];
  c->t2[1] = u[2] * c->t1[0] - u[0] * c->t1[2];
  c->t2[2] = u[0] * c->t1[1] - u[1] * c->t1[0];
}

/* squared distance of the Minkowski-difference boundary point from the origin */
static __attribute__((unused)) double dist2(const urEllipsoid* a, const urEllipsoid* b,
                                            const double u[3]) {
  double w[3];
  mdiff(a, b, u, w);
  return w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
}

static __attribute__((unused)) double chartobj(const gsl_vector* x, void* par) {
  const chart* c = par;
  double u[3];
  chartdir(c, x, u);
  return c->fn(c->a, c->b, u);
}

/* Nelder-Mead polish of objective fn from direction u (in/out) */
static __attribute__((unused)) double nmpolish(const urEllipsoid* a, const urEllipsoid* b, dirfn fn,
                                               double u[3], double step) {
  double best = 0;
  for (int pass = 0; pass < 3; pass++) {
    chart c = {a, b, fn, {0}, {0}, {0}};
    setchart(&c, u);
    gsl_multimin_function mf = {chartobj, 2, &c};
    gsl_vector* x = gsl_vector_calloc(2);
    gsl_vector* ss = gsl_vector_alloc(2);
    gsl_vector_set_all(ss, step);
    gsl_multimin_fminimizer* m =
        gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2);
    gsl_multimin_fminimizer_set(m, &mf, x, ss);
    for (int it = 0; it < 5000; it++) {
      if (gsl_multimin_fminimizer_iterate(m)) break;
      if (gsl_multimin_fminimizer_size(m) < 1e-12) break;
    }
    chartdir(&c, m->x, u);
    best = m->fval;
    gsl_multimin_fminimizer_free(m);
    gsl_vector_free(x);
    gsl_vector_free(ss);
    step *= 1e-3;
  }
  return best;
}

/* brute-force minimum of fn: dense direction sampling, then Nelder-Mead polish of the best
   few separated candidates; uref its direction */
static __attribute__((unused)) double bestdir(const urEllipsoid* a, const urEllipsoid* b, dirfn fn,
                                              double uref[3]) {
  enum {
    NCAND = 4
  };
  double cu[NCAND][3], cv[NCAND];
  int nc = 0;
  double ga = M_PI * (3 - sqrt(5.0));

  // Fibonacci sphere sampling; keep the best NCAND mutually distant directions
  for (int k = 0; k < NSAMPLE; k++) {
    double z = 1 - (2 * k + 1.0) / NSAMPLE, r = sqrt(1 - z * z);
    double u[3] = {r * cos(ga * k), r * sin(ga * k), z};
    double v = fn(a, b, u);
    int near = -1;
    for (int j = 0; j < nc; j++) {
      if (cu[j][0] * u[0] + cu[j][1] * u[1] + cu[j][2] * u[2] > cos(0.3)) near = j;
    }
    if (near >= 0) {
      if (v < cv[near]) {
        cv[near] = v;
        memcpy(cu[near], u, sizeof(u));
      }
    } else if (nc < NCAND) {
      cv[nc] = v;
      memcpy(cu[nc], u, sizeof(u));
      nc++;
    } else {
      int worst = 0;
      for (int j = 1; j < nc; j++) {
        if (cv[j] > cv[worst]) worst = j;
      }
      if (v < cv[worst]) {
        cv[worst] = v;
        memcpy(cu[worst], u, sizeof(u));
      }
    }
  }

  // polish each candidate, keep the smallest
  double best = INFINITY;
  for (int j = 0; j < nc; j++) {
    double v = nmpolish(a, b, fn, cu[j], 0.02);
    if (v < best) {
      best = v;
      memcpy(uref, cu[j], sizeof(cu[j]));
    }
  }
  return best;
}

/* brute-force signed depth: the distance to the boundary of A - B (bestdir of dist2); sign
   from the side of the origin (w.u > 0: inside) */
static __attribute__((unused)) double bruteforce(const urEllipsoid* a, const urEllipsoid* b,
                                                 double uref[3]) {
  double best = bestdir(a, b, dist2, uref);
  double w[3];
  mdiff(a, b, uref, w);
  double s = w[0] * uref[0] + w[1] * uref[1] + w[2] * uref[2];
  return s > 0 ? sqrt(best) : -sqrt(best);
}

/* random pair: semi-axes 0.02-0.22 m, random rotations, centre distance from deep overlap
   to clear separation */
static __attribute__((unused)) void randpair(gsl_rng* rng, urEllipsoid* a, urEllipsoid* b) {
  randell(rng, a, 0.02, 0.22);
  randell(rng, b, 0.02, 0.22);
  double d[3];
  randunit(rng, d);
  double ra = fmax(a->r[0], fmax(a->r[1], a->r[2]));
  double rb = fmax(b->r[0], fmax(b->r[1], b->r[2]));
  double s = (0.4 + 0.75 * gsl_rng_uniform(rng)) * (ra + rb);
  for (int i = 0; i < 3; i++) {
    a->c[i] = 0.3 * gsl_rng_uniform(rng) - 0.15;
    b->c[i] = a->c[i] + s * d[i];
  }
}

/* minimum of obj over (theta, phi): a 201 x 400 grid, then three Nelder-Mead passes (steps
   0.02, 2e-5, 2e-8 rad; the chart shifted away from the poles by the restarts); xy its place */
static __attribute__((unused)) double surfmin(double (*obj)(const gsl_vector*, void*), void* par,
                                              double xy[2]) {
  gsl_vector* x = gsl_vector_alloc(2);
  double bv = INFINITY, bth = 0, bph = 0;
  for (int i = 0; i <= 200; i++) {
    for (int j = 0; j < 400; j++) {
      double th = M_PI * i / 200, ph = 2 * M_PI * j / 400;
      gsl_vector_set(x, 0, th);
      gsl_vector_set(x, 1, ph);
      double v = obj(x, par);
      if (v < bv) {
        bv = v;
        bth = th;
        bph = ph;
      }
    }
  }
  gsl_multimin_function fn = {obj, 2, par};
  gsl_vector* ss = gsl_vector_alloc(2);
  gsl_vector_set(x, 0, bth);
  gsl_vector_set(x, 1, bph);
  double step = 0.02;
  for (int pass = 0; pass < 3; pass++) {
    gsl_vector_set_all(ss, step);
    gsl_multimin_fminimizer* m =
        gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2);
    gsl_multimin_fminimizer_set(m, &fn, x, ss);
    for (int it = 0; it < 5000; it++) {
      if (gsl_multimin_fminimizer_iterate(m)) break;
      if (gsl_multimin_fminimizer_size(m) < 1e-14) break;
    }
    gsl_vector_memcpy(x, m->x);
    bv = m->fval;
    gsl_multimin_fminimizer_free(m);
    step *= 1e-3;
  }
  xy[0] = gsl_vector_get(x, 0);
  xy[1] = gsl_vector_get(x, 1);
  gsl_vector_free(x);
  gsl_vector_free(ss);
  return bv;
}

#endif
