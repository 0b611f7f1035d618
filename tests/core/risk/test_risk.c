/* test_risk.c: deployment branches and outcomes, the distributions' quantiles against closed
 * forms, the Monte Carlo statistics (a collapsed interval, Student's t, the 1/sqrt(N) narrowing
 * on a cheap surrogate), the first-order variance shares of surrogates with known indices, the
 * paired ratio, and multilinear interpolation */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "uasimpact/risk.h"
#include "uasimpact/rng.h"

#define NEAR(a, b, tol)                                                                            \
  do {                                                                                             \
    double a_ = (a), b_ = (b);                                                                     \
    if (!(fabs(a_ - b_) <= (tol)))                                                                 \
      fail_msg("%s = %.12g, want %.12g (tol %g)", #a, a_, b_, (double)(tol));                      \
  } while (0)

/* case A: p_chute (p_bag Q(A) + (1 - p_bag) Q(B)) + (1 - p_chute) Q(C) */
static void branches(void** state) {
  urDeploy d = {1, 1, 0.9, 0.8, 120, 0};
  urBranch b[urMAXBRANCH];
  int n = ur_deploy_branches(&d, b);
  assert_int_equal(n, 3);
  assert_int_equal(b[0].mask, 3);
  assert_int_equal(b[1].mask, 1);
  assert_int_equal(b[2].mask, 0);
  NEAR(b[0].weight, 0.72, 1e-15);
  NEAR(b[1].weight, 0.18, 1e-15);
  NEAR(b[2].weight, 0.1, 1e-15);

  /* two bags: both, bottom only, front only, none; then no parachute */
  d.nbag = 2;
  n = ur_deploy_branches(&d, b);
  assert_int_equal(n, 5);
  static const int masks[5] = {7, 3, 5, 1, 0};
  static const double w[5] = {0.9 * 0.64, 0.9 * 0.16, 0.9 * 0.16, 0.9 * 0.04, 0.1};
  double sum = 0;
  for (int i = 0; i < 5; i++) {
    assert_int_equal(b[i].mask, masks[i]);
    NEAR(b[i].weight, w[i], 1e-15);
    sum += b[i].weight;
  }
  NEAR(sum, 1, 1e-15);

  /* below the minimum deployment height the parachute cannot help */
  d.h_chute_min = 150;
  n = ur_deploy_branches(&d, b);
  NEAR(b[n - 1].weight, 1, 0);
  for (int i = 0; i < n - 1; i++) NEAR(b[i].weight, 0, 0);
  assert_int_equal(ur_deploy_outcome(&d, 1e-9, (double[]){1e-9, 1e-9}), 0);

  /* no parachute: one branch; p 1 and 0 */
  urDeploy c = {0, 0, 1, 1, 120, 0};
  n = ur_deploy_branches(&c, b);
  assert_int_equal(n, 1);
  NEAR(b[0].weight, 1, 0);
  urDeploy a = {1, 1, 1, 1, 120, 0};
  assert_int_equal(ur_deploy_outcome(&a, 1 - 1e-16, (double[]){1 - 1e-16}), 3);
  a.p_chute = 0;
  assert_int_equal(ur_deploy_outcome(&a, 1e-16, (double[]){1e-16}), 0);
}

/* the outcomes drawn from the generator come with the branches' weights (within 4 standard
   errors over 100000 samples) */
static void outcomes(void** state) {
  urDeploy d = {1, 2, 0.7, 0.6, 120, 0};
  urBranch b[urMAXBRANCH];
  int nb = ur_deploy_branches(&d, b), count[8] = {0}, n = 100000;
  for (int i = 0; i < n; i++) {
    double x, u[3];
    ur_mc_inputs(5, (uint64_t)i, 0, NULL, NULL, &x, u);
    count[ur_deploy_outcome(&d, u[0], u + 1)]++;
  }
  for (int k = 0; k < nb; k++) {
    double p = b[k].weight;
    NEAR((double)count[b[k].mask] / n, p, 4 * sqrt(p * (1 - p) / n));
  }
}

static void quantiles(void** state) {
  urDist d = {urDIST_NORMAL, 5, 2, -INFINITY, INFINITY};
  assert_int_equal(ur_dist_check(&d, NULL, 0), 0);
  NEAR(ur_dist_quantile(&d, 0.975), 5 + 2 * 1.959963984540054, 1e-12);
  NEAR(ur_dist_quantile(&d, 0.5), 5, 1e-12);
  /* truncated to [0, 60]: symmetric truncation keeps the median; never outside */
  urDist t = {urDIST_NORMAL, 4, 3, 0, 8};
  NEAR(ur_dist_quantile(&t, 0.5), 4, 1e-12);
  NEAR(ur_dist_quantile(&t, 1e-12), 0, 1e-9);
  NEAR(ur_dist_quantile(&t, 1 - 1e-12), 8, 1e-9);
  /* P(X <= q) of the truncated normal at u = 0.9 */
  double q = ur_dist_quantile(&t, 0.9);
  double F = (0.5 * erfc(-(q - 4) / 3 / M_SQRT2) - 0.5 * erfc(4.0 / 3 / M_SQRT2)) /
             (0.5 * erfc(-4.0 / 3 / M_SQRT2) - 0.5 * erfc(4.0 / 3 / M_SQRT2));
  NEAR(F, 0.9, 1e-12);

  urDist u = {urDIST_UNIFORM, -180, 180, -360, 360};
  assert_int_equal(ur_dist_check(&u, NULL, 0), 0);
  NEAR(ur_dist_quantile(&u, 0.25), -90, 1e-12);

  /* Weibull: x = scale (-ln(1 - u))^(1/shape) */
  urDist w = {urDIST_WEIBULL, 5, 2, 0, INFINITY};
  assert_int_equal(ur_dist_check(&w, NULL, 0), 0);
  for (double p = 0.05; p < 1; p += 0.1) NEAR(ur_dist_quantile(&w, p), 5 * sqrt(-log(1 - p)), 1e-9);

  urDist k = {urDIST_DISCRETE, 0, 0, 0, 60, 3, {0, 4, 10}, {0.5, 0.3, 0.2}};
  assert_int_equal(ur_dist_check(&k, NULL, 0), 0);
  NEAR(ur_dist_quantile(&k, 0.49), 0, 0);
  NEAR(ur_dist_quantile(&k, 0.51), 4, 0);
  NEAR(ur_dist_quantile(&k, 0.79), 4, 0);
  NEAR(ur_dist_quantile(&k, 0.81), 10, 0);

  /* refusals, each with a message */
  char err[200];
  urDist bad[] = {
      {urDIST_NORMAL, 5, 0, 0, 60},
      {urDIST_NORMAL, 100, 1, 0, 60},
      {urDIST_UNIFORM, 3, 3, 0, 60},
      {urDIST_UNIFORM, -1, 3, 0, 60},
      {urDIST_WEIBULL, 0, 2, 0, 60},
      {urDIST_WEIBULL, 5, -1, 0, 60},
      {urDIST_DISCRETE, 0, 0, 0, 60, 2, {1, 2}, {0.5, 0.6}},
      {urDIST_DISCRETE, 0, 0, 0, 60, 2, {1, 1}, {0.5, 0.5}},
      {urDIST_DISCRETE, 0, 0, 0, 60, 2, {1, 70}, {0.5, 0.5}},
  };
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    err[0] = 0;
    assert_int_equal(ur_dist_check(&bad[i], err, sizeof err), -1);
    assert_true(err[0] != 0);
  }
}

/* the inputs of a sample depend on (seed, sample, name) only: not on the other inputs declared */
static void inputs(void** state) {
  urDist d[2] = {{urDIST_UNIFORM, 0, 1, 0, 1}, {urDIST_UNIFORM, 0, 1, 0, 1}};
  const char* ab[2] = {"a", "b"};
  const char* ba[2] = {"b", "a"};
  double x[2], y[2], u[3], v[3];
  ur_mc_inputs(9, 123, 2, ab, d, x, u);
  ur_mc_inputs(9, 123, 2, ba, d, y, v);
  assert_true(x[0] == y[1] && x[1] == y[0] && x[0] != x[1]);
  for (int k = 0; k < 3; k++) assert_true(u[k] == v[k]);
  ur_mc_inputs(9, 124, 1, ab, d, y, v);
  assert_true(y[0] != x[0]);
}

static void stats(void** state) {
  double y[10], work[10];
  urMcStats s;
  /* every input fixed: the interval collapses onto the value */
  for (int i = 0; i < 10; i++) y[i] = 0.0732;
  assert_int_equal(ur_mc_stats(y, 10, work, &s), 0);
  assert_true(s.mean == 0.0732 && s.sd == 0 && s.lo95 == 0.0732 && s.hi95 == 0.0732);
  /* 1..10: mean 5.5, sd sqrt(55/6), t(0.975, 9) = 2.2621571628 (tables) */
  for (int i = 0; i < 10; i++) y[i] = i + 1;
  ur_mc_stats(y, 10, work, &s);
  NEAR(s.mean, 5.5, 1e-15);
  NEAR(s.sd, sqrt(55.0 / 6), 1e-14);
  NEAR(s.hi95 - s.mean, 2.2621571628 * sqrt(55.0 / 6) / sqrt(10), 1e-9);
  NEAR(s.mean - s.lo95, s.hi95 - s.mean, 1e-14);
  assert_true(s.min == 1 && s.max == 10);
  assert_int_equal(ur_mc_stats(y, 1, work, &s), -1);
}

/* a cheap surrogate of Q over wind and face: the interval of the mean narrows as 1/sqrt(N)
   (4N samples: half the width, within 10 %) and holds the surrogate's true mean */
static double surrogate(double wind, double face) {
  return 0.05 + 0.01 * wind + 0.02 * cos(face * M_PI / 180) * cos(face * M_PI / 180);
}

static void narrows(void** state) {
  urDist d[2] = {{urDIST_WEIBULL, 5, 2, 0, 60}, {urDIST_UNIFORM, -180, 180, -360, 360}};
  const char* names[2] = {"wind", "face"};
  int n = 16000;
  double *y = malloc(n * sizeof *y), *work = malloc(n * sizeof *work), x[2], u[3];
  double width[2];
  for (int i = 0; i < n; i++) {
    ur_mc_inputs(3, (uint64_t)i, 2, names, d, x, u);
    y[i] = surrogate(x[0], x[1]);
  }
  urMcStats s;
  for (int k = 0; k < 2; k++) {
    ur_mc_stats(y, k ? n : n / 4, work, &s);
    width[k] = s.hi95 - s.lo95;
    /* E[wind] = 5 Gamma(1.5), E[cos^2] = 1/2 */
    double truth = 0.05 + 0.01 * 5 * tgamma(1.5) + 0.01;
    assert_true(s.lo95 < truth && truth < s.hi95);
  }
  NEAR(width[1] / width[0], 0.5, 0.05);
  free(y);
  free(work);
}

/* Y = X1 + 2 X2 with independent uniforms: S1 = 1/5, S2 = 4/5; Y = 3 X3 + e with X3 in {0, 1}
   equally likely and e ~ N(0, 1): S3 = 2.25 / 3.25; a constant input: 0 */
static void first_order(void** state) {
  int n = 20000;
  double *x1 = malloc(n * sizeof(double)), *x2 = malloc(n * sizeof(double));
  double *x3 = malloc(n * sizeof(double)), *y = malloc(n * sizeof(double));
  double *y3 = malloc(n * sizeof(double)), *k = malloc(n * sizeof(double));
  urDist u = {urDIST_UNIFORM, 0, 1, 0, 1}, b = {urDIST_DISCRETE, 0, 0, 0, 1, 2, {0, 1}, {0.5, 0.5}};
  urDist e = {urDIST_NORMAL, 0, 1, -INFINITY, INFINITY};
  for (int i = 0; i < n; i++) {
    x1[i] = ur_dist_quantile(&u, ur_rng_uniform(1, (uint64_t)i, 1));
    x2[i] = ur_dist_quantile(&u, ur_rng_uniform(1, (uint64_t)i, 2));
    x3[i] = ur_dist_quantile(&b, ur_rng_uniform(1, (uint64_t)i, 3));
    y[i] = x1[i] + 2 * x2[i];
    y3[i] = 3 * x3[i] + ur_dist_quantile(&e, ur_rng_uniform(1, (uint64_t)i, 4));
    k[i] = 7;
  }
  NEAR(ur_mc_first_order(x1, y, n), 0.2, 0.02);
  NEAR(ur_mc_first_order(x2, y, n), 0.8, 0.02);
  NEAR(ur_mc_first_order(x3, y3, n), 2.25 / 3.25, 0.02);
  NEAR(ur_mc_first_order(x1, y3, n), 0, 0.02);
  NEAR(ur_mc_first_order(k, y, n), 0, 0);
  /* a rare outcome (S = 0.996 in 1000 samples: 4 failures) that alone sets y: its share is 1
     (equal-count bins pooled it with the common outcome into one bin: a share of 0) */
  for (int i = 0; i < 1000; i++) {
    x3[i] = i % 250 == 7 ? 0 : 1;
    y3[i] = x3[i] == 0 ? 10 : 1e-3 * ur_rng_uniform(1, (uint64_t)i, 5);
  }
  NEAR(ur_mc_first_order(x3, y3, 1000), 1, 0.01);
  assert_true(isnan(ur_mc_first_order(x1, k, n)));
  free(x1), free(x2), free(x3), free(y), free(y3), free(k);
}

static void ratio(void** state) {
  double num[4] = {0.2, 0.4, 0.6, 0.8}, den[4] = {0.1, 0.2, 0.3, 0.4}, r, lo, hi;
  assert_int_equal(ur_mc_ratio(num, den, 4, &r, &lo, &hi), 0);
  NEAR(r, 2, 1e-15);
  NEAR(lo, 2, 1e-12);
  NEAR(hi, 2, 1e-12);
  double n2[4] = {0.3, 0.4, 0.5, 0.8};
  ur_mc_ratio(n2, den, 4, &r, &lo, &hi);
  NEAR(r, 2.0, 1e-15);
  assert_true(lo < 2 && hi > 2);
  double z[2] = {0, 0};
  assert_int_equal(ur_mc_ratio(num, z, 2, &r, &lo, &hi), -1);
}

/* a multilinear function is reproduced exactly; outside, the nearest end; a one-node axis */
static void lattice(void** state) {
  double a0[3] = {0, 1, 3}, a1[2] = {-180, 180}, v[6];
  const double* node[2] = {a0, a1};
  int nn[2] = {3, 2};
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 2; j++) v[i * 2 + j] = 1 + 2 * a0[i] + 3 * a1[j] + 0.01 * a0[i] * a1[j];
  }
  double x[2] = {2.2, 37};
  NEAR(ur_lattice_interp(2, nn, node, v, x), 1 + 4.4 + 111 + 0.01 * 2.2 * 37, 1e-12);
  x[0] = 5;
  NEAR(ur_lattice_interp(2, nn, node, v, x), 1 + 6 + 111 + 0.01 * 3 * 37, 1e-12);
  x[0] = 1;
  x[1] = -180;
  NEAR(ur_lattice_interp(2, nn, node, v, x), v[2], 0);
  int one[2] = {1, 2};
  double w1[2] = {4, 6};
  x[1] = 0;
  NEAR(ur_lattice_interp(2, one, node, w1, x), 5, 1e-15);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(branches),    cmocka_unit_test(outcomes), cmocka_unit_test(quantiles),
      cmocka_unit_test(inputs),      cmocka_unit_test(stats),    cmocka_unit_test(narrows),
      cmocka_unit_test(first_order), cmocka_unit_test(ratio),    cmocka_unit_test(lattice),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
