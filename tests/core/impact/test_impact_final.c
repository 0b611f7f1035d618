/* test_impact_final.c: the end of a run on final values (impact_final.c, 'set endrun final'):
 * at offsets of cases A (with the analytic bag), B and C its P equals the default's (the window) within 1e-6 (measured on
 * the zero-wind 0.1 m grids of A, B, C and B at 10 m/s: no cell's printed P moved), and the runs
 * end earlier: together at least 3 % fewer steps (measured: 2-11 % on those grids; at these
 * offsets of the switched models 31 % in A, 12 % in B, 21 % in C). 'set endrun'
 * takes window or final (or the parameter's 0 and 1) and nothing else. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../test_ctx.h"

#define P_TOL 1e-6

static const double OFF[][2] = {{0, 0}, {0.2, 0.1}, {-0.1, 0.1}, {0.3, -0.2}, {0, 0.4}};
#define NOFF (int)(sizeof OFF / sizeof OFF[0])

/* each offset's P and steps in case cs with endrun (window or final) */
static void runs(const char* cs, const char* endrun, double* p, long* steps) {
  void* st;
  assert_int_equal(ctx_setup(&st), 0);
  uraCtx* c = st;
  char line[80];
  snprintf(line, sizeof line, "case %s; set wind 0; set endrun %s%s", cs, endrun,
           !strcmp(cs, "A") ? "; set bag_model analytic" : "");
  run_rc(c, line, 0);
  const urImpactSetup* s = ura_setup(c);
  assert_non_null(s);
  assert_int_equal(s->endrun, !strcmp(endrun, "final"));
  urImpactCond cond;
  assert_int_equal(ura_impact_cond(c, &cond), 0);
  urImpactWork w;
  assert_int_equal(ur_impact_work_init(s, &w), 0);
  for (int i = 0; i < NOFF; i++) {
    urImpactResult r;
    assert_int_equal(ur_impact_run(s, &w, &cond, &c->st.injury, OFF[i][0], OFF[i][1], &r), 0);
    p[i] = r.p;
    steps[i] = w.d->nstep;
  }
  ur_impact_work_free(&w);
  ctx_teardown(&st);
}

static void same_p_fewer_steps(const char* cs) {
  double pw[NOFF], pf[NOFF];
  long sw[NOFF], sf[NOFF], tw = 0, tf = 0;
  runs(cs, "window", pw, sw);
  runs(cs, "final", pf, sf);
  for (int i = 0; i < NOFF; i++) {
    print_message("%s (%g, %g): P %.9f / %.9f, steps %ld / %ld\n", cs, OFF[i][0], OFF[i][1], pw[i],
                  pf[i], sw[i], sf[i]);
    if (fabs(pf[i] - pw[i]) > P_TOL) fail_msg("P moved by %g", pf[i] - pw[i]);
    assert_true(sf[i] <= sw[i]);
    tw += sw[i];
    tf += sf[i];
  }
  assert_true(tf < 0.97 * tw);
}

static void case_b(void** state) {
  (void)state;
  same_p_fewer_steps("B");
}

static void case_a(void** state) {
  (void)state;
  same_p_fewer_steps("A");
}

static void case_c(void** state) {
  (void)state;
  same_p_fewer_steps("C");
}

/* the setting: window or final, the model parameter endrun 0 or 1 */
static void setting(void** state) {
  uraCtx* c = *state;
  /* final is the default since issue 36 (window before: src/models/replay.pins pins it) */
  assert_int_equal(ura_setup(c)->endrun, 1);
  run_rc(c, "set endrun final", 0);
  assert_int_equal(ura_setup(c)->endrun, 1);
  run_rc(c, "set endrun window", 0);
  assert_int_equal(ura_setup(c)->endrun, 0);
  run_rc(c, "set endrun sometimes", -1);
  assert_non_null(strstr(c->err, "expected window or final"));
  run_rc(c, "set endrun 2", -1);
  run_rc(c, "set endrun 1", 0);
  assert_int_equal(ura_setup(c)->endrun, 1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(case_b),
      cmocka_unit_test(case_a),
      cmocka_unit_test(case_c),
      cmocka_unit_test_setup_teardown(setting, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
