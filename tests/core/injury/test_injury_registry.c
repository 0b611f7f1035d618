/* test_injury_registry.c: the registry of injury criteria (its rows are consistent, the public
 * column names are the old ones, the fusion over it is bitwise eq. (3.1)) and the criterion
 * added through it, peak thorax deflection, against the closed form of its curve. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

/* the criterion and value rows fit together: each value belongs to the range of its criterion,
   the ranges tile [0, urNVAL) in order, names are unique, PoF columns are p_NAME */
static void test_rows_consistent(void** state) {
  (void)state;
  int next = 0;
  for (int k = 0; k < urNCRIT; k++) {
    const urCriterion* c = ur_criterion(k);
    assert_non_null(c);
    assert_int_equal(c->val0, next);
    assert_true(c->nval >= 1);
    next += c->nval;
    for (int v = c->val0; v < c->val0 + c->nval; v++) assert_int_equal(ur_value_def(v)->crit, k);
    char col[32];
    snprintf(col, sizeof col, "p_%s", c->name);
    assert_string_equal(c->pof_col, col);
    assert_int_equal(ur_criterion_find(c->name), k);
    assert_non_null(c->compute);
    assert_non_null(c->pof);
    assert_non_null(c->channels);
  }
  assert_int_equal(next, urNVAL);
  for (int v = 0; v < urNVAL; v++) {
    for (int w = v + 1; w < urNVAL; w++) {
      assert_true(strcmp(ur_value_def(v)->name, ur_value_def(w)->name) != 0);
    }
  }
  assert_null(ur_criterion(-1));
  assert_null(ur_criterion(urNCRIT));
  assert_null(ur_value_def(urNVAL));
  assert_int_equal(ur_criterion_find("bric"), -1);
}

/* the names of the values shown in `where` under p, comma-separated */
static void shown(int where, const urInjuryParams* p, char* buf, size_t n) {
  buf[0] = 0;
  for (int v = 0; v < urNVAL; v++) {
    if (!ur_value_shown(v, where, p)) continue;
    if (buf[0]) strncat(buf, ",", n - strlen(buf) - 1);
    strncat(buf, ur_value_def(v)->name, n - strlen(buf) - 1);
  }
}

/* the scripting contract: by default the impact rows and grid cells have exactly the columns
   they had before the registry; the deflection criterion adds its own only when on */
static void test_columns_stable(void** state) {
  (void)state;
  urInjuryParams p;
  ur_injury_defaults(&p);
  char buf[256];
  shown(urIN_ROW, &p, buf, sizeof buf);
  assert_string_equal(buf, "hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen");
  shown(urIN_CELL, &p, buf, sizeof buf);
  assert_string_equal(buf, "hic15,nij,vc_thorax,vc_abdomen");
  shown(urIN_LOAD, &p, buf, sizeof buf);
  assert_string_equal(buf, "hic15,hic_t1,hic_t2,nij,nij_mode,vc_thorax,vc_abdomen");
  for (int k = 0; k < urNCRIT; k++) {
    const urCriterion* c = ur_criterion(k);
    assert_int_equal(ur_criterion_used(k, &p), k != urCRIT_DEFL);
    if (!c->use) continue;
    // the offset and the named setting are the same int, and its default is the row's
    double v;
    assert_int_equal(ur_injury_param_get(&p, c->use, &v), 0);
    assert_int_equal((int)v, c->use_default);
    assert_int_equal(ur_injury_param_set(&p, c->use, 1), 0);
    assert_true(ur_criterion_used(k, &p));
    assert_int_equal(ur_injury_param_set(&p, c->use, 0), 0);
    assert_false(ur_criterion_used(k, &p));
  }

  assert_int_equal(ur_injury_param_set(&p, "use_defl", 1), 0);
  assert_true(ur_criterion_used(urCRIT_DEFL, &p));
  shown(urIN_ROW, &p, buf, sizeof buf);
  assert_string_equal(buf,
                      "hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,vc_abdomen,defl_thorax");
  shown(urIN_CELL, &p, buf, sizeof buf);
  assert_string_equal(buf, "hic15,nij,vc_thorax,vc_abdomen,defl_thorax");
  assert_int_equal(ur_injury_param_set(&p, "use_defl", 2), -2);
}

/* the fusion over the registry is bitwise (3.1) with the default criteria, and multiplies in
   1 - P_DEFL when the deflection criterion is on */
static void test_fusion(void** state) {
  (void)state;
  urInjuryParams p;
  ur_injury_defaults(&p);
  const double q[][urNCRIT] = {{0.1, 0.2, 0.3, 0.9},
                               {1e-9, 0.123456789, 0.987654321, 0.5},
                               {0, 0, 0, 1},
                               {0.3333333333333333, 0.7, 0.0001, 0.25}};
  for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
    double a = ur_pof_fuse_used(q[i], &p), b = ur_pof_fuse(q[i][0], q[i][1], q[i][2]);
    assert_memory_equal(&a, &b, sizeof a);
  }
  p.use_defl = 1;
  double a = ur_pof_fuse_used(q[0], &p);
  assert_true(fabs(a - (1 - 0.9 * 0.8 * 0.7 * 0.1)) < 1e-15);
}

/* the curve: P_DEFL(d) = defl_pof (q(D) - q(0)) / (1 - q(0)), q(D) = 1/(1 + exp(a - b D^e)),
   D in mm. At D50 = (a/b)^(1/e) = 62.33 mm, q = 1/2 exactly; at 63 mm (FMVSS 208's limit for
   the HIII-50M) q = 0.51296 (from the same formula, computed apart); 0 at and below 0 */
static void test_defl_curve(void** state) {
  (void)state;
  urInjuryParams p;
  ur_injury_defaults(&p);
  double q0 = 1 / (1 + exp(p.defl_alpha));
  double d50 = pow(p.defl_alpha / p.defl_beta, 1 / p.defl_exp) / 1e3;
  assert_true(fabs(d50 - 0.0623334) < 1e-6);
  assert_true(fabs(ur_pof_defl(d50, &p) - p.defl_pof * (0.5 - q0) / (1 - q0)) < 1e-12);
  assert_true(fabs(ur_pof_defl(0.063, &p) - 0.046165508729) < 1e-9);
  assert_true(ur_pof_defl(0, &p) == 0 && ur_pof_defl(-0.01, &p) == 0);
  assert_true(ur_pof_defl(NAN, &p) == 0);
  assert_true(fabs(ur_pof_defl(1.0, &p) - p.defl_pof) < 1e-9); /* saturates at defl_pof */

  // the `pof defl` curve: from 0, ascending, reaching 99.5 % of its limit
  double x[51], y[51];
  assert_int_equal(ur_pof_curve(urPOF_DEFL, &p, 51, x, y), 51);
  assert_true(x[0] == 0 && y[0] == 0);
  for (int i = 1; i < 51; i++) assert_true(y[i] >= y[i - 1]);
  assert_true(y[50] >= 0.995 * p.defl_pof);
}

/* through ur_injury_eval: a half-sine deflection D = A sin(w t) peaks at A, sampled exactly at
   w t = pi/2; its PoF is the curve's at A, and the values and PoF the registry recomputes from
   the stored values are the same bits */
#define NS 401
static void test_defl_eval(void** state) {
  (void)state;
  static double t[NS], d[NS], acc[NS];
  const double amp = 0.05, dt = 1e-4, w = M_PI / (2 * 100 * dt); /* peak at sample 100 */
  for (int i = 0; i < NS; i++) {
    t[i] = i * dt;
    d[i] = amp * sin(w * t[i]);
    acc[i] = 400 * urGRAVITY * exp(-pow((t[i] - 0.01) / 0.002, 2));
  }
  urInjuryParams p;
  ur_injury_defaults(&p);
  urInjuryInput in = {.n = NS, .t = t, .head_acc = {acc, NULL, NULL}, .thorax_d = d};
  urInjuryResult off, on;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &off), 0);
  assert_true(fabs(off.val[urVAL_DEFL_THORAX] - amp) < 1e-15);
  assert_true(off.pof[urCRIT_DEFL] == ur_pof_defl(off.val[urVAL_DEFL_THORAX], &p));
  assert_true(off.pof[urCRIT_DEFL] > 0.02);
  double three = ur_pof_fuse(off.pof[urCRIT_HIC], off.pof[urCRIT_NIJ], off.pof[urCRIT_VC]);
  assert_memory_equal(&off.p_total, &three, sizeof three); /* off: not in the fusion */

  p.use_defl = 1;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &on), 0);
  assert_memory_equal(on.val, off.val, sizeof on.val);
  assert_true(fabs(on.p_total - (1 - (1 - three) * (1 - on.pof[urCRIT_DEFL]))) < 1e-15);
  assert_true(on.p_total > off.p_total);

  // each criterion's PoF from the stored values equals what compute gave
  for (int k = 0; k < urNCRIT; k++) {
    double r = ur_criterion(k)->pof(on.val, &p);
    assert_memory_equal(&r, &on.pof[k], sizeof r);
  }

  // no thorax channel: no value, no PoF
  in.thorax_d = NULL;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &on), 0);
  assert_true(on.val[urVAL_DEFL_THORAX] == 0 && on.pof[urCRIT_DEFL] == 0);
}

/* display text: codes by name, numbers scaled, "-" for unknown */
static void test_value_format(void** state) {
  (void)state;
  char b[32];
  ur_value_format(urVAL_NIJ_MODE, 2, b, sizeof b);
  assert_string_equal(b, "NCF");
  ur_value_format(urVAL_NIJ_MODE, 4, b, sizeof b);
  assert_string_equal(b, "-");
  ur_value_format(urVAL_NIJ_MODE, NAN, b, sizeof b);
  assert_string_equal(b, "-");
  ur_value_format(urVAL_DEFL_THORAX, 0.0321, b, sizeof b);
  assert_string_equal(b, "32.1");
  ur_value_format(urVAL_HIC_T1, 0.00125, b, sizeof b);
  assert_string_equal(b, "1.25");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_rows_consistent), cmocka_unit_test(test_columns_stable),
      cmocka_unit_test(test_fusion),          cmocka_unit_test(test_defl_curve),
      cmocka_unit_test(test_defl_eval),       cmocka_unit_test(test_value_format),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
