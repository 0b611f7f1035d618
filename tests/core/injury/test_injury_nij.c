/* test_injury_nij.c: Nij mode selection by sign, per-mode maxima, intercepts, condyle offset. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

static void test_mode_by_sign(void** state) {
  assert_int_equal(ur_nij_mode(100, 10), urNIJ_NTF);
  assert_int_equal(ur_nij_mode(100, -10), urNIJ_NTE);
  assert_int_equal(ur_nij_mode(-100, 10), urNIJ_NCF);
  assert_int_equal(ur_nij_mode(-100, -10), urNIJ_NCE);
  assert_int_equal(ur_nij_mode(0, 0), urNIJ_NTF);

  // each quadrant at half of both intercepts gives Nij = 1 with its own intercepts
  urInjuryParams p;
  ur_injury_defaults(&p);
  assert_true(fabs(ur_nij_sample(3403, 155, &p) - 1.0) < 1e-12);
  assert_true(fabs(ur_nij_sample(3403, -67.5, &p) - 1.0) < 1e-12);
  assert_true(fabs(ur_nij_sample(-3080, 155, &p) - 1.0) < 1e-12);
  assert_true(fabs(ur_nij_sample(-3080, -67.5, &p) - 1.0) < 1e-12);
}

static void test_per_mode_maxima(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);

  // samples visiting every quadrant, with known values
  const double fz[] = {0, 1361.2, 2041.8, -1232, -3080, 680.6, 3403, -616, -1848, 0};
  const double my[] = {0, 31, 62, 93, 31, -27, -13.5, -40.5, -108, 0};
  const int n = 10;
  double want[4] = {0};
  int iwant[4] = {-1, -1, -1, -1};
  for (int i = 0; i < n; i++) {
    // expected value computed by hand-coded intercepts, independent of ur_nij_sample
    double fzc = fz[i] >= 0 ? 6806.0 : 6160.0, myc = my[i] >= 0 ? 310.0 : 135.0;
    int m = fz[i] >= 0 ? (my[i] >= 0 ? 0 : 1) : (my[i] >= 0 ? 2 : 3);
    double v = fabs(fz[i]) / fzc + fabs(my[i]) / myc;
    if (iwant[m] < 0 || v > want[m]) {
      want[m] = v;
      iwant[m] = i;
    }
  }
  // NTF max 0.3 + 0.2 = 0.5 at i=2; NTE 0.5 + 0.1 at i=6; NCF 0.5+0.1 at i=4; NCE 0.3+0.8 at i=8
  assert_true(fabs(want[urNIJ_NTF] - 0.5) < 1e-12 && iwant[urNIJ_NTF] == 2);
  assert_true(fabs(want[urNIJ_NTE] - 0.6) < 1e-12 && iwant[urNIJ_NTE] == 6);
  assert_true(fabs(want[urNIJ_NCF] - 0.6) < 1e-12 && iwant[urNIJ_NCF] == 4);
  assert_true(fabs(want[urNIJ_NCE] - 1.1) < 1e-12 && iwant[urNIJ_NCE] == 8);

  urNij r;
  assert_int_equal(ur_nij(fz, my, NULL, n, &p, &r), 0);
  for (int m = 0; m < 4; m++) {
    assert_true(fabs(r.mode[m] - want[m]) < 1e-12);
    assert_int_equal(r.imode[m], iwant[m]);
  }
  assert_true(fabs(r.nij - 1.1) < 1e-12);
  assert_int_equal(r.which, urNIJ_NCE);
  assert_int_equal(r.imax, 8);
}

static void test_absent_mode_and_intercepts(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);

  // pure tension with flexion: only NTF seen
  const double fz[] = {1000, 2000, 3000};
  const double my[] = {10, 20, 30};
  urNij r;
  assert_int_equal(ur_nij(fz, my, NULL, 3, &p, &r), 0);
  assert_int_equal(r.imode[urNIJ_NTF], 2);
  for (int m = 1; m < 4; m++) {
    assert_int_equal(r.imode[m], -1);
    assert_true(r.mode[m] == 0.0);
  }

  // intercepts are settable: 1998 proposal tension 4500 N
  assert_int_equal(ur_injury_param_set(&p, "nij_fzc_tension", 4500), 0);
  assert_int_equal(ur_nij(fz, my, NULL, 3, &p, &r), 0);
  assert_true(fabs(r.nij - (3000.0 / 4500.0 + 30.0 / 310.0)) < 1e-12);
  assert_int_equal(ur_injury_param_set(&p, "nij_fzc_tension", -1), -2);
}

static void test_condyle_offset(void** state) {
  // M_OC = My - D Fx: a shear force turns zero My into extension
  urInjuryParams p;
  ur_injury_defaults(&p);
  assert_int_equal(ur_injury_param_set(&p, "nij_condyle_d", 0.01778), 0);
  const double fz[] = {1000}, my[] = {0}, fx[] = {1000};
  urNij r;
  assert_int_equal(ur_nij(fz, my, fx, 1, &p, &r), 0);
  assert_int_equal(r.which, urNIJ_NTE);
  assert_true(fabs(r.nij - (1000.0 / 6806.0 + 17.78 / 135.0)) < 1e-12);

  // without fx the offset has no effect
  assert_int_equal(ur_nij(fz, my, NULL, 1, &p, &r), 0);
  assert_int_equal(r.which, urNIJ_NTF);
}

static void test_errors(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);
  const double fz[] = {1}, my[] = {1};
  urNij r;
  assert_int_equal(ur_nij(NULL, my, NULL, 1, &p, &r), -1);
  assert_int_equal(ur_nij(fz, my, NULL, 0, &p, &r), -1);
  p.nij_myc_extension = 0;
  assert_int_equal(ur_nij(fz, my, NULL, 1, &p, &r), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mode_by_sign),
      cmocka_unit_test(test_per_mode_maxima),
      cmocka_unit_test(test_absent_mode_and_intercepts),
      cmocka_unit_test(test_condyle_offset),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
