/* test_model_inflate.c: the workbench inflates a membrane bag when something first needs it
 * (src/app/case/model.c, ura_model_inflate), counted by the session's inflated-bag cache (its
 * look-ups: a miss is an inflation, a hit a copy): starting, 'show', 'set', 'case' and a model
 * load with the membrane bag inflate nothing; the first impact inflates case A's bag once, later
 * impacts nothing; a changed bag inflates at its next run; 'show bag' inflates, and the full
 * 'show' says the bag is not inflated yet. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../test_ctx.h"

static long lookups(uraCtx* c) {
  urMemCacheStats st;
  ur_memcache_stats(c->memcache, &st);
  return st.hits + st.misses;
}

static long misses(uraCtx* c) {
  urMemCacheStats st;
  ur_memcache_stats(c->memcache, &st);
  return st.misses;
}

/* what a line prints on the context's output */
static char* output(uraCtx* c, const char* line) {
  static char buf[1 << 16];
  FILE* keep = c->out;
  FILE* f = fmemopen(buf, sizeof buf - 1, "w");
  c->out = f;
  run_rc(c, line, 0);
  fclose(f);
  c->out = keep;
  return buf;
}

/* nothing that only compiles or prints inflates; the first impact does, once */
static void lazy_start(void** state) {
  uraCtx* c = *state;
  run_rc(c, "set bag_membrane 1; show; case B; case A1; case A", 0);
  run_rc(c, "set bag_membrane 1; set bag_p0 1.1 atm; set bag_p0 1 atm", 0);
  const char* show = output(c, "show");
  assert_non_null(strstr(show, "not inflated yet (when a run first needs it"));
  assert_non_null(strstr(show, "(derived at the next grid, after the airbag's inflation)"));
  assert_int_equal(lookups(c), 0);
  assert_true(c->model && c->model->nraw == 1);

  run_rc(c, "impact 0 0", 0);
  assert_int_equal(misses(c), 1);
  assert_int_equal(c->model->nraw, 0);
  long n = lookups(c);
  run_rc(c, "impact 0.1 0; history", 0);
  assert_int_equal(lookups(c), n); /* inflated once: nothing looked up again */
  assert_non_null(strstr(output(c, "show"), "inflated "));

  /* a changed bag: compiled now, inflated at its next run */
  run_rc(c, "set bag_p0 1.05 atm", 0);
  assert_int_equal(misses(c), 1);
  run_rc(c, "impact 0 0", 0);
  assert_int_equal(misses(c), 2);
}

/* a model load compiles every preset, inflating none; 'show bag' inflates */
static void lazy_load(void** state) {
  uraCtx* c = *state;
  char path[] = "/tmp/test_model_inflate_XXXXXX";
  int fd = mkstemp(path);
  assert_true(fd >= 0);
  FILE* f = fdopen(fd, "w");
  fprintf(f, "part extra\nparam extra_k 1\n");
  fclose(f);
  run_rc(c, "set bag_membrane 1", 0);
  char line[80];
  snprintf(line, sizeof line, "model load %s", path);
  run_rc(c, line, 0);
  unlink(path);
  assert_int_equal(lookups(c), 0);
  const char* bag = output(c, "show bag_");
  assert_non_null(strstr(bag, "# derived, membrane bag_bottom: "));
  assert_non_null(strstr(bag, " inflated "));
  assert_int_equal(misses(c), 1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(lazy_start, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lazy_load, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
