/* test_contact_geom.c: ellipsoid-plane, ellipsoid-ellipsoid, section area and cap volume
 * against independent references (brute force, closed forms, Monte Carlo; contact_fixture.h).
 * Superellipsoids are test_contact_super.c.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "uasimpact/contact.h"
#include "contact_fixture.h"

/* ---- tests ---- */

/* ellipsoid-plane closed form against a dense (theta, phi) surface search plus polish */
typedef struct {
  const urEllipsoid* e;
  const double* n;
} planepar;

static double planeobj(const gsl_vector* x, void* par) {
  const planepar* p = par;
  double th = gsl_vector_get(x, 0), ph = gsl_vector_get(x, 1);
  double l[3] = {p->e->r[0] * sin(th) * cos(ph), p->e->r[1] * sin(th) * sin(ph),
                 p->e->r[2] * cos(th)};
  double v = 0;
  for (int i = 0; i < 3; i++) {
    double xi = p->e->c[i];
    for (int k = 0; k < 3; k++) xi += p->e->R[3 * i + k] * l[k];
    v += p->n[i] * xi;
  }
  return v;
}


static void test_plane_bruteforce(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 11);
  double maxerr = 0, maxperr = 0;
  for (int t = 0; t < 200; t++) {
    urEllipsoid e;
    randell(rng, &e, 0.02, 0.22);
    for (int i = 0; i < 3; i++) e.c[i] = gsl_rng_uniform(rng) - 0.5;
    double n[3];
    randunit(rng, n);
    double d = n[0] * e.c[0] + n[1] * e.c[1] + n[2] * e.c[2] + 0.4 * gsl_rng_uniform(rng) - 0.3;

    // grid search for min n.x over the surface, then Nelder-Mead in (theta, phi)
    planepar p = {&e, n};
    double xy[2];
    double bv = surfmin(planeobj, &p, xy);
    double gref = d - bv;
    double th = xy[0], ph = xy[1];
    double l[3] = {e.r[0] * sin(th) * cos(ph), e.r[1] * sin(th) * sin(ph), e.r[2] * cos(th)},
           pref[3];
    for (int i = 0; i < 3; i++) {
      pref[i] = e.c[i];
      for (int k = 0; k < 3; k++) pref[i] += e.R[3 * i + k] * l[k];
    }

    urGeomContact c;
    int hit = ur_collide_ellipsoid_plane(&e, n, d, &c);
    assert_int_equal(hit, gref > 0);
    maxerr = fmax(maxerr, fabs(c.g - gref));
    double pe = 0;
    for (int i = 0; i < 3; i++) {
      pe = fmax(pe, fabs(c.pa[i] - pref[i]));
      assert_near(c.n[i], -n[i], 1e-15);
      // pb lies on the plane, p is the midpoint
      assert_near(c.p[i], 0.5 * (c.pa[i] + c.pb[i]), 1e-15);
    }
    maxperr = fmax(maxperr, pe);
    assert_near(n[0] * c.pb[0] + n[1] * c.pb[1] + n[2] * c.pb[2], d, 1e-14);
  }
  printf("plane: max |g - g_ref| = %.3g m, max |pa - pa_ref| = %.3g m (200 cases)\n", maxerr,
         maxperr);
  assert_true(maxerr < 1e-12);
  assert_true(maxperr < 1e-6);
  gsl_rng_free(rng);
}

/* sphere-sphere against the closed form r_A + r_B - |c_B - c_A| */
static void test_sphere_sphere(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 5);
  for (int t = 0; t < 500; t++) {
    urEllipsoid a, b;
    randell(rng, &a, 0.02, 0.2);
    randell(rng, &b, 0.02, 0.2);
    a.r[1] = a.r[2] = a.r[0];
    b.r[1] = b.r[2] = b.r[0];
    double d[3];
    randunit(rng, d);
    double s = (0.2 + 1.0 * gsl_rng_uniform(rng)) * (a.r[0] + b.r[0]);
    for (int i = 0; i < 3; i++) {
      a.c[i] = gsl_rng_uniform(rng);
      b.c[i] = a.c[i] + s * d[i];
    }
    double u[3] = {0, 0, 0};
    urGeomContact c;
    int hit = ur_collide_ellipsoids(&a, &b, u, &c);
    double gref = a.r[0] + b.r[0] - s;
    assert_int_equal(hit, gref > 0);
    assert_near(c.g, gref, 1e-14);
    for (int i = 0; i < 3; i++) {
      assert_near(c.n[i], d[i], 1e-12);
      assert_near(c.pa[i], a.c[i] + a.r[0] * d[i], 1e-12);
      assert_near(c.pb[i], b.c[i] - b.r[0] * d[i], 1e-12);
    }
  }
  gsl_rng_free(rng);
}

/* 1000 random pairs against the brute-force distance to the boundary of A - B */
static void test_pairs_bruteforce(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 2025);
  double maxerr = 0, maxang = 0, maxdeep = 0;
  int nshallow = 0, nsep = 0, ndeep = 0, ndeepbad = 0, maxit = 0;
  for (int t = 0; t < NPAIR; t++) {
    urEllipsoid a, b;
    randpair(rng, &a, &b);
    double uref[3];
    double gref = bruteforce(&a, &b, uref);
    double u[3] = {0, 0, 0};
    urGeomContact c;
    int hit = ur_collide_ellipsoids(&a, &b, u, &c);
    if (c.iters > maxit) maxit = c.iters;

    // consistency of the record: g = n.(pa - pb), p midpoint, u returned = n
    double gd = 0;
    for (int i = 0; i < 3; i++) {
      gd += c.n[i] * (c.pa[i] - c.pb[i]);
      assert_near(c.p[i], 0.5 * (c.pa[i] + c.pb[i]), 1e-15);
      assert_near(u[i], c.n[i], 0);
    }
    assert_near(gd, c.g, 1e-14);
    assert_int_equal(hit, c.g > 0);

    // any value of f bounds the global minimum from above
    assert_true(c.g >= gref - 1e-9);
    double lim = fmin(minaxis(&a), minaxis(&b));
    double err = fabs(c.g - gref);
    if (gref < lim) {
      nshallow++;
      if (gref < 0) nsep++;
      maxerr = fmax(maxerr, err);
      double dt = c.n[0] * uref[0] + c.n[1] * uref[1] + c.n[2] * uref[2];
      maxang = fmax(maxang, acos(fmin(1.0, dt)));
      if (err > 1e-9) {
        printf("pair %d: g = %.15g  ref = %.15g\n", t, c.g, gref);
      }
      assert_true(err <= 1e-9);
    } else {
      ndeep++;
      maxdeep = fmax(maxdeep, err);
      if (err > 1e-9) ndeepbad++;
    }
  }
  printf(
      "pairs: %d within the exactness range (%d separated, %d overlapping), "
      "max |g - g_ref| = %.3g m, max normal angle = %.3g rad; max iterations %d\n",
      nshallow, nsep, nshallow - nsep, maxerr, maxang, maxit);
  printf(
      "pairs: %d deeper than the smallest semi-axis: %d differ by > 1e-9 m "
      "(max %.3g m)\n",
      ndeep, ndeepbad, maxdeep);
  assert_true(nshallow - nsep > 150);
  assert_true(nsep > 200);
  assert_true(maxang < 1e-6);
  // deeper pairs: exactness is not guaranteed there, but the multi-start guard finds the
  // global minimum for every pair of this fixed sample (7 misses without the guard)
  assert_int_equal(ndeepbad, 0);
  gsl_rng_free(rng);
}

/* warm starts (small and large perturbations, and along a trajectory) equal the cold start */
static void test_warm_equals_cold(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 77);
  double maxdg = 0, maxdu = 0;
  for (int t = 0; t < 1000; t++) {
    urEllipsoid a, b;
    randpair(rng, &a, &b);
    double u[3] = {0, 0, 0};
    urGeomContact cold, warm;
    ur_collide_ellipsoids(&a, &b, u, &cold);
    for (int k = 0; k < 3; k++) {
      // perturb the minimiser by 1e-4, 1e-2 and 0.3 rad
      double amp = k == 0 ? 1e-4 : k == 1 ? 1e-2 : 0.3, p[3], w[3];
      randunit(rng, p);
      for (int i = 0; i < 3; i++) w[i] = cold.n[i] + amp * p[i];
      ur_collide_ellipsoids(&a, &b, w, &warm);
      maxdg = fmax(maxdg, fabs(warm.g - cold.g));
      if (cold.g < fmin(minaxis(&a), minaxis(&b))) {
        for (int i = 0; i < 3; i++) maxdu = fmax(maxdu, fabs(warm.n[i] - cold.n[i]));
      }
    }

    // trajectory: move B a little each step, warm from the previous minimiser
    double v[3];
    randunit(rng, v);
    double uw[3] = {cold.n[0], cold.n[1], cold.n[2]};
    for (int s = 0; s < 20; s++) {
      for (int i = 0; i < 3; i++) b.c[i] += 1e-4 * v[i];
      double uc[3] = {0, 0, 0};
      ur_collide_ellipsoids(&a, &b, uw, &warm);
      ur_collide_ellipsoids(&a, &b, uc, &cold);
      maxdg = fmax(maxdg, fabs(warm.g - cold.g));
    }
  }
  printf("warm vs cold: max |dg| = %.3g m, max |dn| = %.3g\n", maxdg, maxdu);
  assert_true(maxdg < 1e-12);
  assert_true(maxdu < 1e-8);
  gsl_rng_free(rng);
}

/* section area and cap volume: sphere closed forms, ellipsoid Monte Carlo */
static void test_section_cap(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 3);

  // sphere: pi (2 R d - d^2) and pi d^2 (3 R - d) / 3, clamped to [0, 2R]
  urEllipsoid s;
  randell(rng, &s, 0.0875, 0.0875);
  double n[3];
  randunit(rng, n);
  for (int k = -2; k <= 24; k++) {
    double R = 0.0875, d = R * k / 10.0, dc = fmin(fmax(d, 0), 2 * R);
    assert_near(ur_section_area(&s, n, d), M_PI * (2 * R * dc - dc * dc), 1e-15);
    assert_near(ur_cap_volume(&s, n, d), M_PI * dc * dc * (3 * R - dc) / 3, 1e-16);
  }

  // ellipsoid: Monte Carlo in the local box; tolerance 5 standard errors
  for (int t = 0; t < 4; t++) {
    urEllipsoid e;
    randell(rng, &e, 0.03, 0.2);
    randunit(rng, n);
    double nl[3], sig = 0;
    for (int k = 0; k < 3; k++) {
      nl[k] = e.R[k] * n[0] + e.R[3 + k] * n[1] + e.R[6 + k] * n[2];
      sig += e.r[k] * e.r[k] * nl[k] * nl[k];
    }
    sig = sqrt(sig);
    double d = (0.2 + 1.5 * gsl_rng_uniform(rng)) * sig;
    const int N = 2000000;
    int inside = 0;
    for (int i = 0; i < N; i++) {
      double x[3], q = 0, h = 0;
      for (int k = 0; k < 3; k++) {
        x[k] = e.r[k] * (2 * gsl_rng_uniform(rng) - 1);
        q += x[k] * x[k] / (e.r[k] * e.r[k]);
        h += nl[k] * x[k];
      }
      if (q <= 1 && h >= sig - d) inside++;
    }
    double box = 8 * e.r[0] * e.r[1] * e.r[2], p = (double)inside / N;
    double vmc = box * p, se = box * sqrt(p * (1 - p) / N);
    double v = ur_cap_volume(&e, n, d);
    printf("cap volume: %.6g m^3, MC %.6g +- %.2g\n", v, vmc, se);
    assert_true(fabs(v - vmc) < 5 * se);

    // section: sample the plane h = sig - d over a square of side 2 rmax (local frame)
    double t1[3], t2[3], a[3] = {1, 0, 0};
    if (fabs(nl[0]) > 0.6) {
      a[0] = 0;
      a[1] = 1;
    }
    double dd = a[0] * nl[0] + a[1] * nl[1] + a[2] * nl[2], tn = 0;
    for (int k = 0; k < 3; k++) {
      t1[k] = a[k] - dd * nl[k];
      tn += t1[k] * t1[k];
    }
    for (int k = 0; k < 3; k++) t1[k] /= sqrt(tn);
    t2[0] = nl[1] * t1[2] - nl[2] * t1[1];
    t2[1] = nl[2] * t1[0] - nl[0] * t1[2];
    t2[2] = nl[0] * t1[1] - nl[1] * t1[0];
    double rm = fmax(e.r[0], fmax(e.r[1], e.r[2]));
    inside = 0;
    for (int i = 0; i < N; i++) {
      double p1 = rm * (2 * gsl_rng_uniform(rng) - 1), p2 = rm * (2 * gsl_rng_uniform(rng) - 1),
             q = 0;
      for (int k = 0; k < 3; k++) {
        double xk = (sig - d) * nl[k] + p1 * t1[k] + p2 * t2[k];
        q += xk * xk / (e.r[k] * e.r[k]);
      }
      if (q <= 1) inside++;
    }
    double sq = 4 * rm * rm;
    p = (double)inside / N;
    double amc = sq * p, sa = sq * sqrt(p * (1 - p) / N);
    double area = ur_section_area(&e, n, d);
    printf("section area: %.6g m^2, MC %.6g +- %.2g\n", area, amc, sa);
    assert_true(fabs(area - amc) < 5 * sa);
  }
  gsl_rng_free(rng);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_plane_bruteforce), cmocka_unit_test(test_sphere_sphere),
      cmocka_unit_test(test_pairs_bruteforce), cmocka_unit_test(test_warm_equals_cold),
      cmocka_unit_test(test_section_cap),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
