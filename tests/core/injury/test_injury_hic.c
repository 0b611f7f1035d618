/* test_injury_hic.c: HIC15/HIC36 on closed-form pulses, uniform and non-uniform samples. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

#define DT   1e-5 /* sample step, s */
#define NMAX 8001

/* rectangular pulse of amp g from t0 to t0 + T (sample-aligned), zero elsewhere */
static int rect(double* t, double* a, double amp, double t0, double T, double tend) {
  int n = (int)lround(tend / DT) + 1;
  int k0 = (int)lround(t0 / DT), k1 = (int)lround((t0 + T) / DT);
  for (int k = 0; k < n; k++) {
    t[k] = k * DT;
    a[k] = (k >= k0 && k <= k1) ? amp : 0.0;
  }
  return n;
}

/* half-sine amp sin(pi (t - t0) / T) on [t0, t0 + T] */
static double halfsine(double tt, double amp, double t0, double T) {
  double s = tt - t0;
  return (s >= 0 && s <= T) ? amp * sin(M_PI * s / T) : 0.0;
}

/* closed-form half-sine HIC: x = pi D / (2 T), optimum tan x = 5x/3 unless the window binds */
static double halfsine_hic(double amp, double T, double window, double* width) {
  // bisection for tan x = 5x/3 on (0.5, 1.5)
  double lo = 0.5, hi = 1.5;
  for (int it = 0; it < 200; it++) {
    double mid = 0.5 * (lo + hi);
    if (tan(mid) - 5.0 * mid / 3.0 < 0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  double x = 0.5 * (lo + hi);
  double d = 2.0 * T * x / M_PI;
  if (d > window) {
    d = window;
    x = M_PI * d / (2.0 * T);
  }
  *width = d;
  return pow(amp, 2.5) * (2.0 * T / M_PI) * pow(sin(x), 2.5) / pow(x, 1.5);
}

static void test_rect_10ms(void** state) {
  static double t[NMAX], a[NMAX];
  int n = rect(t, a, 100.0, 0.005, 0.010, 0.030);
  urHic h15, h36;
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h15), 0);
  assert_int_equal(ur_hic(t, a, n, 0.036, NULL, &h36), 0);
  assert_true(fabs(h15.hic - 1000.0) / 1000.0 < 1e-6);
  assert_true(fabs(h36.hic - 1000.0) / 1000.0 < 1e-6);
  assert_true(fabs(h15.t1 - 0.005) < 0.5 * DT);
  assert_true(fabs(h15.t2 - 0.015) < 0.5 * DT);
}

static void test_rect_long_window_limit(void** state) {
  // 100 g for 30 ms: HIC15 = 100^2.5 * 0.015, HIC36 = 100^2.5 * 0.030
  static double t[NMAX], a[NMAX];
  int n = rect(t, a, 100.0, 0.005, 0.030, 0.045);
  urHic h15, h36;
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h15), 0);
  assert_int_equal(ur_hic(t, a, n, 0.036, NULL, &h36), 0);
  assert_true(fabs(h15.hic - 1500.0) / 1500.0 < 1e-6);
  assert_true(fabs(h36.hic - 3000.0) / 3000.0 < 1e-6);
  assert_true(h15.t2 - h15.t1 <= 0.015 * (1 + 1e-9));
  assert_true(h15.t2 - h15.t1 > 0.015 - 0.5 * DT);
  assert_true(h15.t1 >= 0.005 - 0.5 * DT && h15.t2 <= 0.035 + 0.5 * DT);
}

static void test_halfsine_10ms(void** state) {
  static double t[NMAX], a[NMAX];
  int n = 2001;
  for (int k = 0; k < n; k++) {
    t[k] = k * DT;
    a[k] = halfsine(t[k], 100.0, 0.005, 0.010);
  }
  double w;
  double ref = halfsine_hic(100.0, 0.010, 0.015, &w);
  assert_true(fabs(ref - 414.646) < 1e-3);
  urHic h;
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h), 0);
  assert_true(fabs(h.hic - 414.646) / 414.646 < 1e-3);
  assert_true(fabs(h.hic - ref) / ref < 1e-4);

  // unconstrained optimum: centred window of 0.6702 T, a(t1) = a(t2) = 0.6 mean
  assert_true(fabs(0.5 * (h.t1 + h.t2) - 0.010) < 2 * DT);
  assert_true(fabs((h.t2 - h.t1) - w) < 0.05e-3);
  double mean = 2.0 * 100.0 * 0.010 / M_PI * sin(M_PI * w / (2 * 0.010)) / w;
  assert_true(fabs(a[h.i1] - 0.6 * mean) / mean < 0.01);
  assert_true(fabs(a[h.i2] - 0.6 * mean) / mean < 0.01);
}

static void test_halfsine_30ms(void** state) {
  static double t[NMAX], a[NMAX];
  int n = 4001;
  for (int k = 0; k < n; k++) {
    t[k] = k * DT;
    a[k] = halfsine(t[k], 100.0, 0.0, 0.030);
  }
  urHic h15, h36;
  double w15, w36;
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h15), 0);
  assert_int_equal(ur_hic(t, a, n, 0.036, NULL, &h36), 0);
  double r15 = halfsine_hic(100.0, 0.030, 0.015, &w15);
  double r36 = halfsine_hic(100.0, 0.030, 0.036, &w36);
  assert_true(fabs(r15 - 1153.663) < 1e-2 && fabs(r36 - 1243.937) < 1e-2);

  // HIC15 = 1153.66 with the window 7.5-22.5 ms
  assert_true(fabs(h15.hic - 1153.66) / 1153.66 < 1e-3);
  assert_true(fabs(h15.t1 - 0.0075) < 1.5 * DT);
  assert_true(fabs(h15.t2 - 0.0225) < 1.5 * DT);

  // HIC36 = 1243.94, window 0.6702 T = 20.1 ms centred on 15 ms
  assert_true(fabs(h36.hic - 1243.94) / 1243.94 < 1e-3);
  assert_true(fabs(w36 - 0.6702297 * 0.030) < 1e-6);
  assert_true(fabs(h36.t1 - (0.015 - 0.5 * w36)) < 0.05e-3);
  assert_true(fabs(h36.t2 - (0.015 + 0.5 * w36)) < 0.05e-3);
}

static void test_nonuniform(void** state) {
  // alternating steps of 5 and 15 us, plus a 7 us step, with the pulse edges on samples
  static double t[NMAX], a[NMAX];
  int n = 0;
  double tt = 0;
  const double steps[3] = {5e-6, 15e-6, 10e-6};
  while (tt <= 0.030 && n < NMAX) {
    t[n++] = tt;
    tt += steps[n % 3];
  }
  // rectangular pulse between two chosen samples
  int k0 = 300, k1 = k0;
  while (t[k1] - t[k0] < 0.010 - 1e-12) {
    k1++;
  }
  double T = t[k1] - t[k0];
  for (int k = 0; k < n; k++) {
    a[k] = (k >= k0 && k <= k1) ? 100.0 : 0.0;
  }
  urHic h;
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h), 0);
  assert_true(fabs(h.hic - 1e5 * T) / (1e5 * T) < 1e-6);

  // half-sine 10 ms on the same grid
  for (int k = 0; k < n; k++) {
    a[k] = halfsine(t[k], 100.0, 0.005, 0.010);
  }
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h), 0);
  assert_true(fabs(h.hic - 414.646) / 414.646 < 1e-3);
}

static void test_workspace_and_errors(void** state) {
  static double t[NMAX], a[NMAX], work[6 * NMAX];
  assert_true(ur_hic_work_size(NMAX) <= 6 * NMAX);
  int n = rect(t, a, 80.0, 0.002, 0.004, 0.010);
  urHic h1, h2;
  assert_int_equal(ur_hic(t, a, n, 0.015, work, &h1), 0);
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h2), 0);
  assert_true(h1.hic == h2.hic && h1.i1 == h2.i1 && h1.i2 == h2.i2);

  // no positive window: HIC 0
  for (int k = 0; k < n; k++) {
    a[k] = -50.0;
  }
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h1), 0);
  assert_true(h1.hic == 0.0);

  // bad input
  assert_int_equal(ur_hic(t, a, n, 0.0, NULL, &h1), -1);
  assert_int_equal(ur_hic(NULL, a, n, 0.015, NULL, &h1), -1);
  t[5] = t[4];
  assert_int_equal(ur_hic(t, a, n, 0.015, NULL, &h1), -1);
}

/* the plain O(N W) scan of every pair, the definition the pruned scan must equal */
/* every pair; squared = 0 compares HIC values, squared = 1 compares as the pruned scan does
   (HIC^2 = dv^5 / dt^3, ties to the smallest (i, j)) and reports the value from the best pair
   as it does */
static double brute(const double* t, const double* a, int n, double w, int squared, int* i1,
                    int* i2) {
  static double v[NMAX];
  double best = 0;
  v[0] = 0;
  for (int k = 1; k < n; k++) {
    v[k] = v[k - 1] + 0.5 * (a[k] + a[k - 1]) * (t[k] - t[k - 1]);
  }
  *i1 = *i2 = 0;
  for (int i = 0; i < n - 1; i++) {
    for (int j = i + 1; j < n && t[j] - t[i] <= w * (1 + 1e-9); j++) {
      double dv = v[j] - v[i], dt = t[j] - t[i];
      double h =
          squared ? dv * dv * dv * dv * dv / (dt * dt * dt) : dv * dv * sqrt(dv) / (dt * sqrt(dt));
      if (dv > 0 && h > best) {
        best = h;
        *i1 = i;
        *i2 = j;
      }
    }
  }
  if (squared && best > 0) {
    double dv = v[*i2] - v[*i1], dt = t[*i2] - t[*i1];
    best = dv * dv * sqrt(dv) / (dt * sqrt(dt));
  }
  return best;
}

/* random multi-peak traces with negative parts, uniform and jittered times, and noise-free
   plateaus where many pairs tie: the pruned scan returns exactly the maximum and pair of the
   scan of every pair under the same comparison, and the brute-force HIC (compared as HIC
   values, which can order near-ties differently: bitwise on peaked traces, to 1e-12 on
   plateaus) */
static void test_pruned_equals_brute_force(void** state) {
  static double t[2000], a[2000];
  srand(12345);
  for (int trial = 0; trial < 200; trial++) {
    int n = 200 + rand() % 1500;
    double tt = 0;
    int npk = 1 + rand() % 5;
    double c[5], w[5], h[5];
    for (int p = 0; p < npk; p++) {
      c[p] = (rand() / (double)RAND_MAX) * n * 1e-4;
      w[p] = 5e-4 + (rand() / (double)RAND_MAX) * 0.02;
      h[p] = -50 + (rand() / (double)RAND_MAX) * 400;
    }
    for (int k = 0; k < n; k++) {
      t[k] = tt;
      tt += (trial % 2) ? 1e-4 : 1e-4 * (0.5 + rand() / (double)RAND_MAX);
      a[k] = 5 * (rand() / (double)RAND_MAX - 0.5);
      for (int p = 0; p < npk; p++) {
        a[k] += h[p] * exp(-0.5 * pow((t[k] - c[p]) / w[p], 2));
      }
      if (trial % 3 == 2) {
        /* plateaus without noise (airbag-like; many pairs tie) */
        a[k] = 0;
        for (int p = 0; p < npk; p++) {
          if (fabs(t[k] - c[p]) < w[p]) a[k] = fmax(a[k], fabs(h[p]) / 4);
        }
      }
    }
    for (int win = 0; win < 2; win++) {
      double W = win ? 0.036 : 0.015;
      int i1, i2;
      double hb = brute(t, a, n, W, 0, &i1, &i2);
      urHic hp;
      assert_int_equal(ur_hic(t, a, n, W, NULL, &hp), 0);
      if (trial % 3 == 2) {
        assert_true(fabs(hp.hic - hb) <= 1e-12 * hb);
      } else {
        assert_true(hp.hic == hb);
        assert_int_equal(hp.i1, i1);
        assert_int_equal(hp.i2, i2);
      }
      double h2 = brute(t, a, n, W, 1, &i1, &i2);
      assert_true(hp.hic == h2);
      assert_int_equal(hp.i1, i1);
      assert_int_equal(hp.i2, i2);
    }
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_rect_10ms),
      cmocka_unit_test(test_rect_long_window_limit),
      cmocka_unit_test(test_halfsine_10ms),
      cmocka_unit_test(test_halfsine_30ms),
      cmocka_unit_test(test_nonuniform),
      cmocka_unit_test(test_workspace_and_errors),
      cmocka_unit_test(test_pruned_equals_brute_force),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
