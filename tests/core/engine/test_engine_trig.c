/* test_engine_trig.c: the engine's own sine, cosine and first-quadrant arctangent (engine_trig.h)
 * against libm and, where long double is wider, against the true value: sine and cosine within
 * 1 ulp (0.998 at worst against the true value), atan2q within 2 ulp (1.46); special
 * arguments (signed zeros, subnormals, multiples of pi/2, huge, non-finite) as libm gives them;
 * and the lanes' vector instance bit for bit the scalar one, with ordinary and libm-handled
 * arguments mixed in one vector. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "../../../src/core/engine/engine_internal.h"

static double urand(uint64_t* s) {
  *s = *s * 6364136223846793005ull + 1442695040888963407ull;
  return (double)(*s >> 11) * 0x1p-53;
}

/* distance in ulps between two finite doubles of the same sign (or zero) */
static double ulps(double a, double b) {
  int64_t ia, ib;
  memcpy(&ia, &a, sizeof ia);
  memcpy(&ib, &b, sizeof ib);
  if (ia < 0) ia = INT64_MIN - ia;
  if (ib < 0) ib = INT64_MIN - ib;
  int64_t d = ia > ib ? ia - ib : ib - ia;
  return (double)d;
}

/* error of a against the true value t in ulps of the result */
static double true_ulps(double a, long double t) {
  double r = (double)t;
  double u = nextafter(fabs(r), INFINITY) - fabs(r);
  return (double)(fabsl((long double)a - t) / u);
}

static int same_bits(double a, double b) {
  return memcmp(&a, &b, sizeof a) == 0;
}

static void test_sincos_accuracy(void** state) {
  (void)state;
  static const double range[] = {1e-6, 1e-3, 0.7, 2, 10, 1e3, 1e6};
  uint64_t seed = 1;
  double worst_libm = 0, worst_true = 0;
  for (size_t r = 0; r < sizeof range / sizeof range[0]; r++) {
    for (int i = 0; i < 200000; i++) {
      double x = (2 * urand(&seed) - 1) * range[r], s, c;
      uru_sincos(x, &s, &c);
      worst_libm = fmax(worst_libm, fmax(ulps(s, sin(x)), ulps(c, cos(x))));
      if (LDBL_MANT_DIG > DBL_MANT_DIG) {
        worst_true = fmax(worst_true, fmax(true_ulps(s, sinl(x)), true_ulps(c, cosl(x))));
      }
    }
  }
  printf("sincos: worst %.0f ulp from libm, %.3f ulp from the true value\n", worst_libm,
         worst_true);
  assert_true(worst_libm <= 1);
  assert_true(worst_true < 1);
}

static void test_atan2q_accuracy(void** state) {
  (void)state;
  uint64_t seed = 2;
  double worst_libm = 0, worst_true = 0;
  for (int i = 0; i < 1000000; i++) {
    /* coordinates over eight decades, every reduction interval of the quotient */
    double y = urand(&seed) * pow(10, 8 * urand(&seed) - 4);
    double x = urand(&seed) * pow(10, 8 * urand(&seed) - 4);
    if (i % 3 == 0) x = y * 4 * urand(&seed);
    double a = uru_atan2q(y, x);
    worst_libm = fmax(worst_libm, ulps(a, atan2(y, x)));
    if (LDBL_MANT_DIG > DBL_MANT_DIG) {
      worst_true = fmax(worst_true, true_ulps(a, atan2l(y, x)));
    }
  }
  printf("atan2q: worst %.0f ulp from libm, %.3f ulp from the true value\n", worst_libm,
         worst_true);
  assert_true(worst_libm <= 2);
  assert_true(worst_true < 2);
}

static void test_special(void** state) {
  (void)state;
  double s, c;
  static const double same[] = {0.0,   -0.0,   0x1p-1074, -0x1p-1074, 1e-300,
                                1e300, -1e300, 1e7,       0x1p60};
  for (size_t i = 0; i < sizeof same / sizeof same[0]; i++) {
    uru_sincos(same[i], &s, &c);
    assert_true(same_bits(s, sin(same[i])));
    assert_true(same_bits(c, cos(same[i])));
  }
  /* the quadrants about multiples of pi/2: within an ulp, signs right */
  for (int k = -8; k <= 8; k++) {
    double x = k * M_PI_2;
    uru_sincos(x, &s, &c);
    assert_true(ulps(s, sin(x)) <= 1 || fabs(s - sin(x)) < 1e-30);
    assert_true(ulps(c, cos(x)) <= 1 || fabs(c - cos(x)) < 1e-30);
  }
  uru_sincos(NAN, &s, &c);
  assert_true(isnan(s) && isnan(c));
  uru_sincos(INFINITY, &s, &c);
  assert_true(isnan(s) && isnan(c));

  assert_true(same_bits(uru_atan2q(0, 0), 0.0));
  assert_true(same_bits(uru_atan2q(1, 0), atan2(1, 0)));
  assert_true(same_bits(uru_atan2q(0, 1), 0.0));
  assert_true(same_bits(uru_atan2q(1, 1), atan2(1, 1)));
  assert_true(same_bits(uru_atan2q(INFINITY, 1), atan2(INFINITY, 1)));
  assert_true(same_bits(uru_atan2q(-1, 2), atan2(-1, 2)));
  assert_true(same_bits(uru_atan2q(1, -2), atan2(1, -2)));
  assert_true(isnan(uru_atan2q(NAN, 1)));
}

/* four arguments at a time through the lanes' vector instance, against the scalar one */
static void test_lanes_bitwise(void** state) {
  (void)state;
  static const double odd[] = {0.0, -0.0, 1e300, NAN, INFINITY, 0x1p-1074, 5 * M_PI_2, 1e-9};
  static const double oddy[] = {0.0, 1.0, INFINITY, NAN, -1.0, 1e-300, 2.0, 0.5};
  static const double oddw[] = {0.0, 0.0, 1.0, 1.0, 2.0, 1e-300, -1.0, 0.5};
  uint64_t seed = 3;
  for (int i = 0; i < 20000; i++) {
    double x[urNLANE], y[urNLANE], w[urNLANE], s[urNLANE], c[urNLANE], a[urNLANE];
    for (int l = 0; l < urNLANE; l++) {
      int k = (int)(urand(&seed) * 16);
      x[l] = k < 8 ? odd[k] : (2 * urand(&seed) - 1) * pow(10, 6 * urand(&seed) - 2);
      y[l] = k < 8 ? oddy[k] : urand(&seed);
      w[l] = k < 8 ? oddw[k] : urand(&seed);
    }
    ur_lanes_trig(x, s, c, y, w, a);
    for (int l = 0; l < urNLANE; l++) {
      double s1, c1;
      uru_sincos(x[l], &s1, &c1);
      double a1 = uru_atan2q(y[l], w[l]);
      if (!same_bits(s[l], s1) || !same_bits(c[l], c1) || !same_bits(a[l], a1)) {
        fail_msg("lane %d: sincos(%a) or atan2q(%a, %a) differs from the scalar instance", l, x[l],
                 y[l], w[l]);
      }
    }
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_sincos_accuracy),
      cmocka_unit_test(test_atan2q_accuracy),
      cmocka_unit_test(test_special),
      cmocka_unit_test(test_lanes_bitwise),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
