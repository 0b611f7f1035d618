/* test_injury_vc.c: viscous criterion on a closed-form deflection D = A sin(w t). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

#define AMP   0.05              /* deflection amplitude, m */
#define OMEGA (2 * M_PI * 25.0) /* rad/s: 40 ms period */
#define NV    201               /* samples over the first 20 ms, dt = 0.1 ms */

/* VC(t) = SF A^2 w sin cos / D0, max A^2 w / (2 D0) at w t = pi/4 */
static void test_closed_form(void** state) {
  static double t[NV], d[NV], vct[NV];
  double dt = 1e-4, d0 = 0.229;
  for (int i = 0; i < NV; i++) {
    t[i] = i * dt;
    d[i] = AMP * sin(OMEGA * t[i]);
  }
  urVc r;
  assert_int_equal(ur_vc(t, d, NV, d0, 1.0, vct, &r), 0);
  double want = AMP * AMP * OMEGA / (2.0 * d0);
  assert_true(fabs(r.vc - want) / want < 1e-6);
  assert_true(fabs(r.t - M_PI / (4 * OMEGA)) < 0.5 * dt);
  assert_true(fabs(r.c - AMP * sin(M_PI / 4) / d0) < 1e-9);

  // the whole history matches away from the ends (five-point, O(h^4))
  for (int i = 2; i < NV - 2; i++) {
    double ex = AMP * AMP * OMEGA * sin(OMEGA * t[i]) * cos(OMEGA * t[i]) / d0;
    assert_true(fabs(vct[i] - ex) < 1e-6 * want);
  }

  // scale factor multiplies, a larger depth divides
  urVc r2;
  assert_int_equal(ur_vc(t, d, NV, d0, 1.3, NULL, &r2), 0);
  assert_true(fabs(r2.vc - 1.3 * r.vc) < 1e-12);
  assert_int_equal(ur_vc(t, d, NV, 2 * d0, 1.0, NULL, &r2), 0);
  assert_true(fabs(r2.vc - 0.5 * r.vc) < 1e-12);
}

static void test_nonuniform(void** state) {
  // steps alternating 0.06 and 0.14 ms: three-point derivative, second order
  static double t[400], d[400];
  int n = 0;
  double tt = 0;
  while (tt <= 0.020 && n < 400) {
    t[n] = tt;
    d[n] = AMP * sin(OMEGA * tt);
    tt += (n % 2) ? 1.4e-4 : 0.6e-4;
    n++;
  }
  double d0 = 0.2185;
  urVc r;
  assert_int_equal(ur_vc(t, d, n, d0, 1.0, NULL, &r), 0);
  double want = AMP * AMP * OMEGA / (2.0 * d0);
  assert_true(fabs(r.vc - want) / want < 1e-3);
}

static void test_defaults_and_errors(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);
  assert_true(p.vc_d0_thorax == 0.229 && p.vc_d0_abdomen == 0.2185 && p.vc_sf == 1.0);
  assert_int_equal(ur_injury_param_set(&p, "vc_d0_thorax", 0.140), 0);
  assert_true(p.vc_d0_thorax == 0.140);
  assert_int_equal(ur_injury_param_set(&p, "vc_d0_abdomen", 0.0), -2);

  // rebound only (D falling): VC stays 0
  double t[5] = {0, 1e-3, 2e-3, 3e-3, 4e-3}, d[5] = {0.05, 0.04, 0.03, 0.02, 0.01};
  urVc r;
  assert_int_equal(ur_vc(t, d, 5, 0.229, 1.0, NULL, &r), 0);
  assert_true(r.vc == 0.0);
  assert_int_equal(ur_vc(t, d, 2, 0.229, 1.0, NULL, &r), -1);
  assert_int_equal(ur_vc(t, d, 5, 0.0, 1.0, NULL, &r), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_closed_form),
      cmocka_unit_test(test_nonuniform),
      cmocka_unit_test(test_defaults_and_errors),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
