/* test_modelcache.c: the model cache (src/app/case/modelcache.c): switching back to a case or setting
 * seen earlier makes its compiled, balanced and settled model live again (no settling), with the
 * same impact results; the last impact does not survive a switch; at most uraMODELCACHE models
 * are kept, the least recently used freed first; after new model parts none of them returns,
 * but their settled stances are given to new models with the same person (test_impact_setup.c
 * shows the set-up is then bitwise what settling gives) and not to another person; reset flushes
 * them; keys compare the overrides as a set, values to the bit */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../test_ctx.h"

/* A, B, A: the second A is the first one's model and stance, and its impact is the same */
static void switch_back(void** state) {
  uraCtx* c = *state;
  run_rc(c, "case A; impact 0 0", 0);
  const urModel* a = c->model;
  urImpactResult ra = c->last_impact;
  assert_true(c->have_setup && c->have_impact);

  run_rc(c, "case B", 0);
  assert_ptr_not_equal(c->model, a);
  assert_false(c->have_setup);  /* B compiled, not settled yet */
  assert_false(c->have_impact); /* A's impact went with A's model */
  run_rc(c, "history", -1);
  run_rc(c, "impact 0 0", 0);
  assert_true(c->last_impact.p != ra.p);

  run_rc(c, "case A", 0);
  assert_ptr_equal(c->model, a);
  assert_true(c->have_setup); /* settled already: nothing to settle */
  assert_ptr_equal(c->setup.m, a);
  assert_false(c->have_impact || c->have_work);
  assert_true(c->model->param[ura_model_param_find(c, "bag_bottom")].value == 1);
  run_rc(c, "impact 0 0", 0);
  assert_memory_equal(&c->last_impact.p, &ra.p, sizeof ra.p);
  assert_memory_equal(&c->last_impact.inj.hic15.hic, &ra.inj.hic15.hic, sizeof(double));
  assert_memory_equal(&c->last_impact.inj.nij.nij, &ra.inj.nij.nij, sizeof(double));
  run_rc(c, "history", 0);

  /* a value the model refuses changes nothing, the settled model stays live */
  run_rc(c, "set dt 0", -1);
  assert_ptr_equal(c->model, a);
  assert_true(c->have_setup);
}

/* uraMODELCACHE + 1 settled models: all kept (the live one and uraMODELCACHE others); one more
   parked frees the least recently used */
static void lru(void** state) {
  uraCtx* c = *state;
  char line[64];
  for (int i = 0; i <= uraMODELCACHE; i++) {
    snprintf(line, sizeof line, "set vmax %d", 10000 + i);
    run_rc(c, line, 0);
    assert_non_null(ura_setup(c));
  }
  run_rc(c, "set vmax 10000", 0); /* kept: 1..8 parked, 0 live */
  assert_true(c->have_setup);
  run_rc(c, "set vmax 10009", 0); /* parks 0: 1, the least recently used, is freed */
  assert_false(c->have_setup);
  run_rc(c, "set vmax 10001", 0);
  assert_false(c->have_setup);
  for (int i = 2; i <= uraMODELCACHE; i++) {
    snprintf(line, sizeof line, "set vmax %d", 10000 + i);
    run_rc(c, line, 0);
    assert_true(c->have_setup);
  }
  run_rc(c, "set vmax 10000", 0);
  assert_true(c->have_setup);
}

/* new model parts, even the same text loaded back: no model of the old parts returns, but a
   model with the same person takes a kept stance, with the same impact; a changed person does
   not; reset keeps nothing */
static void parts_flush(void** state) {
  uraCtx* c = *state;
  char path[] = "/tmp/test_modelcache_XXXXXX", human[] = "/tmp/test_modelcache_h_XXXXXX";
  int fd = mkstemp(path), fh = mkstemp(human);
  assert_true(fd >= 0 && fh >= 0);
  close(fd);
  close(fh);
  char line[192];
  snprintf(line, sizeof line, "model save %s; model load %s", path, path);

  run_rc(c, "case A; impact 0.1 0.1", 0);
  urImpactResult ra = c->last_impact;
  run_rc(c, "case B", 0);
  run_rc(c, line, 0);
  run_rc(c, "case A", 0);
  assert_false(c->have_setup); /* no model of the old parts */
  assert_non_null(ura_setup(c));
  assert_true(c->setup.shared); /* a stance of them, for the same person */
  run_rc(c, "impact 0.1 0.1", 0);
  assert_memory_equal(&c->last_impact.p, &ra.p, sizeof ra.p);
  assert_memory_equal(&c->last_impact.inj.hic15.hic, &ra.inj.hic15.hic, sizeof(double));

  /* another person (a stiffer neck in a loaded human part): settled anew */
  snprintf(line, sizeof line, "model save %s", path);
  run_rc(c, line, 0);
  FILE* f = fopen(path, "r");
  FILE* g = fopen(human, "w");
  assert_true(f && g);
  char buf[512];
  int in_human = 0;
  while (fgets(buf, sizeof buf, f)) {
    if (!strncmp(buf, "part ", 5)) in_human = !strncmp(buf, "part human", 10);
    if (!in_human) continue;
    if (!strncmp(buf, "param neck_k_flex 160 ", 22)) memcpy(buf + 18, "170", 3); /* range kept */
    fputs(buf, g);
  }
  fclose(f);
  fclose(g);
  snprintf(line, sizeof line, "model load %s", human);
  run_rc(c, line, 0);
  assert_false(c->have_setup);
  assert_non_null(ura_setup(c));
  assert_false(c->setup.shared);

  run_rc(c, "case B; reset", 0);
  assert_string_equal(c->st.casename, "A");
  assert_false(c->have_setup);
  assert_non_null(ura_setup(c));
  assert_false(c->setup.shared); /* reset kept no stance */
  unlink(path);
  unlink(human);
}

/* keys: the same parts and override set in any order, values to the bit */
static void keys(void** state) {
  uraCtx* c = *state;
  uraState s = c->st, t = c->st;
  uraModelKey a, b;
  s.nov = t.nov = 2;
  strcpy(s.ov_name[0], "bag_p0");
  strcpy(s.ov_name[1], "vmax");
  s.ov_val[0] = 1e5;
  s.ov_val[1] = 0.0;
  strcpy(t.ov_name[0], "vmax");
  strcpy(t.ov_name[1], "bag_p0");
  t.ov_val[0] = 0.0;
  t.ov_val[1] = 1e5;
  ura_model_key(c, &s, &a);
  ura_model_key(c, &t, &b);
  assert_true(ura_model_key_same(&a, &b));
  t.ov_val[0] = -0.0;
  ura_model_key(c, &t, &b);
  assert_false(ura_model_key_same(&a, &b));
  t.ov_val[0] = 0.0;
  t.nov = 1;
  ura_model_key(c, &t, &b);
  assert_false(ura_model_key_same(&a, &b));
  ura_model_key(c, &s, &b);
  b.gen++;
  assert_false(ura_model_key_same(&a, &b));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(keys, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(switch_back, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lru, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(parts_flush, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
