/* test_quantile.c: sample quantiles against closed forms: exact order statistics of a small
 * sample (type 7), and P5, P50, P95 of 40 000 Weibull(5, 2) draws from the Monte Carlo generator
 * against x_p = 5 (-ln(1 - p))^(1/2), within four standard errors of a sample quantile
 * (sqrt(p (1 - p) / n) / f(x_p)); the tail flag; the truncation of an interval. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "uasimpact/quantile.h"
#include "uasimpact/risk.h"

static int cmp(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* 1..5: P0 1, P25 2, P50 3, P90 4.6, P100 5 (h = 4p) */
static void order_statistics(void** state) {
  const double s[] = {1, 2, 3, 4, 5};
  assert_true(ur_quantile_sorted(s, 5, 0) == 1);
  assert_true(ur_quantile_sorted(s, 5, 0.25) == 2);
  assert_true(ur_quantile_sorted(s, 5, 0.5) == 3);
  assert_true(fabs(ur_quantile_sorted(s, 5, 0.9) - 4.6) < 1e-15);
  assert_true(ur_quantile_sorted(s, 5, 1) == 5);
  assert_true(ur_quantile_sorted(s, 1, 0.3) == 1);
  assert_true(isnan(ur_quantile_sorted(s, 0, 0.3)));
}

static void weibull(void** state) {
  enum {
    N = 40000
  };
  double* x = malloc(N * sizeof *x);
  assert_non_null(x);
  urDist d = {.kind = urDIST_WEIBULL, .a = 5, .b = 2, .lo = 0, .hi = INFINITY};
  const char* name[] = {"wind"};
  double u[1 + urMAXBAGS];
  for (int i = 0; i < N; i++) ur_mc_inputs(7, (uint64_t)i, 1, name, &d, &x[i], u);
  qsort(x, N, sizeof *x, cmp);
  const double p[] = {0.05, 0.5, 0.95};
  for (int k = 0; k < 3; k++) {
    double xp = 5 * sqrt(-log(1 - p[k]));
    double f = 2.0 / 5 * (xp / 5) * exp(-(xp / 5) * (xp / 5));
    double se = sqrt(p[k] * (1 - p[k]) / N) / f;
    double got = ur_quantile_sorted(x, N, p[k]);
    print_message("P%g: %.5f, closed form %.5f (se %.5f)\n", 100 * p[k], got, xp, se);
    assert_true(fabs(got - xp) < 4 * se);
  }
  free(x);
}

static void thin_tails(void** state) {
  assert_int_equal(ur_quantile_thin(100, 0.05), 1); /* 5 beyond */
  assert_int_equal(ur_quantile_thin(200, 0.05), 0); /* 10 beyond */
  assert_int_equal(ur_quantile_thin(200, 0.95), 0);
  assert_int_equal(ur_quantile_thin(3, 0.5), 1);
  assert_int_equal(ur_quantile_thin(20, 0.5), 0);
}

static void clip(void** state) {
  double lo = -0.2, hi = 0.5;
  assert_int_equal(ur_interval_clip(&lo, &hi, 0, INFINITY), 1);
  assert_true(lo == 0 && hi == 0.5);
  lo = 0.5, hi = 1.2;
  assert_int_equal(ur_interval_clip(&lo, &hi, 0, 1), 2);
  assert_true(hi == 1);
  lo = 0.1, hi = 0.2;
  assert_int_equal(ur_interval_clip(&lo, &hi, 0, 1), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {cmocka_unit_test(order_statistics), cmocka_unit_test(weibull),
                                     cmocka_unit_test(thin_tails), cmocka_unit_test(clip)};
  return cmocka_run_group_tests(tests, NULL, NULL);
}
