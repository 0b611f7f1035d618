/* test_injury_filter.c: SAE J211 CFC filter gain against the J211 corridor, zero phase. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

#define FS 50000.0 /* sampling rate, Hz (J211 asks >= 10 kHz for CFC 1000) */
#define NS 50001   /* 1 s of samples */

static double db(double g) {
  return 20.0 * log10(g);
}

/* measured gain and phase of the filter at f: least squares of sin/cos on the middle half */
static void measure(double f, double* gain, double* phase) {
  static double x[NS], y[NS];
  double dt = 1.0 / FS;
  for (int i = 0; i < NS; i++) {
    x[i] = sin(2 * M_PI * f * i * dt);
  }
  assert_int_equal(ur_cfc_filter(x, NS, dt, 1000.0, y), 0);

  // project on sin and cos over a whole number of periods in the middle
  int per = (int)lround(FS / f);
  int i0 = NS / 4, m = ((NS / 2) / per) * per;
  if (m == 0 || fabs(FS / f - per) > 1e-9) {
    m = NS / 2;
  }
  double ss = 0, sc = 0, s2 = 0, c2 = 0, sxc = 0;
  for (int i = i0; i < i0 + m; i++) {
    double s = sin(2 * M_PI * f * i * dt), c = cos(2 * M_PI * f * i * dt);
    ss += y[i] * s;
    sc += y[i] * c;
    s2 += s * s;
    c2 += c * c;
    sxc += s * c;
  }
  // 2x2 normal equations for y = A s + B c
  double det = s2 * c2 - sxc * sxc;
  double A = (ss * c2 - sc * sxc) / det, B = (sc * s2 - ss * sxc) / det;
  *gain = hypot(A, B);
  *phase = atan2(B, A);
}

static void test_gain_corridor(void** state) {
  // J211-1 CFC 1000: FH = 1000 Hz, FN = 1650 Hz. Corridor as read from J211 [tolerances]:
  // 0.1 Hz..FH within +0.5/-1 dB; at FN within +0.5/-4 dB; beyond FN falling at least 9 dB/oct.
  const double f[] = {10, 100, 300, 500, 800, 1000, 1650, 3300};
  for (size_t k = 0; k < sizeof(f) / sizeof(f[0]); k++) {
    double g, ph;
    measure(f[k], &g, &ph);
    double ga = ur_cfc_gain(1000.0, 1.0 / FS, f[k]);

    // the measured gain equals the analytic |H|^2 within 0.01 dB, phase within 1e-4 rad
    assert_true(fabs(db(g) - db(ga)) < 0.01);
    assert_true(fabs(ph) < 1e-4);
    if (f[k] <= 1000) {
      assert_true(db(g) <= 0.5 && db(g) >= -1.0);
    } else if (f[k] == 1650) {
      assert_true(db(g) <= 0.5 && db(g) >= -4.0);
    } else {
      assert_true(db(g) <= 0.5 - 9.0);
    }
  }
}

static void test_minus3db(void** state) {
  // -3 dB point of the double pass: 5/3 CFC analogue (1667 Hz); J211 nominal FN = 1650 Hz.
  // tolerance: 1600..1750 Hz at 50 kHz sampling
  double lo = 500, hi = 5000;
  for (int it = 0; it < 100; it++) {
    double mid = 0.5 * (lo + hi);
    if (db(ur_cfc_gain(1000.0, 1.0 / FS, mid)) > -3.0103) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  assert_true(lo > 1600 && lo < 1750);

  // the same holds for the other classes, scaled: CFC 600 -> ~1000 Hz, CFC 180 -> ~300 Hz
  assert_true(fabs(db(ur_cfc_gain(600.0, 1.0 / FS, 1000.0)) + 3.0) < 0.3);
  assert_true(fabs(db(ur_cfc_gain(180.0, 1.0 / FS, 300.0)) + 3.0) < 0.3);
}

static void test_zero_phase_pulse(void** state) {
  // symmetric triangle of 1 ms base centred on sample c stays centred and symmetric
  static double x[4001], y[4001];
  int n = 4001, c = 2000, hw = 25;
  double dt = 1.0 / FS;
  for (int i = 0; i < n; i++) {
    int d = abs(i - c);
    x[i] = d < hw ? 100.0 * (1.0 - (double)d / hw) : 0.0;
  }
  assert_int_equal(ur_cfc_filter(x, n, dt, 1000.0, y), 0);

  // peak at the centre, mirror symmetry, centroid on the centre
  int imax = 0;
  double m0 = 0, m1 = 0;
  for (int i = 0; i < n; i++) {
    if (y[i] > y[imax]) {
      imax = i;
    }
    m0 += y[i];
    m1 += y[i] * i;
  }
  assert_int_equal(imax, c);
  for (int k = 1; k < 200; k++) {
    assert_true(fabs(y[c + k] - y[c - k]) < 1e-9 * y[c]);
  }
  assert_true(fabs(m1 / m0 - c) < 1e-6);

  // the filter removes content: the 100 g peak is lowered
  assert_true(y[c] < 100.0 && y[c] > 50.0);
}

static void test_dc_inplace_errors(void** state) {
  // constant signal passes unchanged (steady-state start), in place
  double x[200];
  for (int i = 0; i < 200; i++) {
    x[i] = 7.5;
  }
  assert_int_equal(ur_cfc_filter(x, 200, 1e-4, 180.0, x), 0);
  for (int i = 0; i < 200; i++) {
    assert_true(fabs(x[i] - 7.5) < 1e-12);
  }

  // sampled too slowly for the class (2.0775 CFC dt >= 0.5), bad step, bad n
  assert_int_equal(ur_cfc_filter(x, 200, 1e-3, 1000.0, x), -1);
  assert_int_equal(ur_cfc_filter(x, 200, 0.0, 1000.0, x), -1);
  assert_int_equal(ur_cfc_filter(x, 0, 1e-4, 1000.0, x), -1);
  assert_true(ur_cfc_gain(1000.0, 1e-3, 10.0) < 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_gain_corridor),
      cmocka_unit_test(test_minus3db),
      cmocka_unit_test(test_zero_phase_pulse),
      cmocka_unit_test(test_dc_inplace_errors),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
