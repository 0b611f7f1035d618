/* test_session_base.c: minimal sessions (src/app/case/session_base.c, session.c): the shortest exact
 * numbers, model parameters in the unit that writes them shortest, only what differs from
 * 'reset; case NAME' written (never threads or the plot output), and the replay exact */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../test_ctx.h"

static void shortest(void** state) {
  (void)state;
  char b[64];
  static const double v[] = {0.05, 0.1 + 0.2, 111457.5, 1.0 / 3, 27000, 1e-5, 6, -0.35, 1e300};
  static const char* const want[] = {"0.05",     "0.30000000000000004",
                                     "111457.5", "0.3333333333333333",
                                     "27000",    "1e-05",
                                     "6",        "-0.35",
                                     "1e+300"};
  for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
    ura_num_shortest(b, sizeof b, v[i]);
    assert_string_equal(b, want[i]);
    assert_true(strtod(b, NULL) == v[i]);
  }
}

static void units(void** state) {
  uraCtx* c = *state;
  char b[64];
  ura_model_value_text(c, "bag_p0", 1.1 * 101325, b, sizeof b); /* 111457.50000000001 Pa */
  assert_string_equal(b, "1.1 atm");
  ura_model_value_text(c, "bag_p0", 120000, b, sizeof b);
  assert_string_equal(b, "120 kPa");                       /* shortest; first on a tie */
  ura_model_value_text(c, "thorax_k", 27000, b, sizeof b); /* N/m: no shorter unit */
  assert_string_equal(b, "27000 N/m");
  ura_model_value_text(c, "foam_t", 0.035, b, sizeof b);
  assert_string_equal(b, "35 mm");
  ura_model_value_text(c, "bag_kappa", 2.5, b, sizeof b); /* no unit */
  assert_string_equal(b, "2.5");
}

static char* session(uraCtx* c) {
  char* buf = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&buf, &n);
  ura_session_write(c, f);
  fclose(f);
  return buf;
}

static char* shown(uraCtx* c) {
  char* buf = NULL;
  size_t n = 0;
  FILE* keep = c->out;
  c->out = open_memstream(&buf, &n);
  run_rc(c, "show", 0);
  fclose(c->out);
  c->out = keep;
  return buf;
}

static void minimal(void** state) {
  uraCtx* c = *state;
  /* the defaults: nothing but reset and the case */
  char* s = session(c);
  assert_string_equal(s,
                      "# uasimpact session: replay with 'uasimpact FILE' or 'source FILE'\n"
                      "reset\ncase A\n");
  free(s);
  /* A1's own bag_p0 (1.1 atm) is the case's: not written; threads and output never */
  run_rc(c,
         "case A1; set wind 6; set threads 2; set output x.png; set terminal png; "
         "set thorax_k 27 kN/m; set hic_window 0.036; set step 0.1",
         0);
  s = session(c);
  assert_string_equal(s,
                      "# uasimpact session: replay with 'uasimpact FILE' or 'source FILE'\n"
                      "reset\ncase A1\nset wind 6\nset step 0.1\nset terminal 'png'\n"
                      "set hic_window 0.036\nset thorax_k 27000 N/m\n");
  free(s);
  /* a user value that differs from the case's */
  run_rc(c, "set bag_p0 1.2 atm", 0);
  s = session(c);
  assert_non_null(strstr(s, "\nset bag_p0 1.2 atm\n"));
  free(s);
}

/* the replay recreates what show prints (threads and output aside: they are not state) */
static void replays(void** state) {
  uraCtx* c = *state;
  run_rc(c,
         "case B; set wind 4; set face 30; set bag_p0 1.15 atm; set speed 9.5; "
         "set winds 0,5; set tau top; set format csv; set pager off",
         0);
  char* s = session(c);
  char* before = shown(c);
  char path[] = "/tmp/uasimpact-test-session-XXXXXX";
  int fd = mkstemp(path);
  assert_true(fd >= 0);
  FILE* f = fdopen(fd, "w");
  fputs(s, f);
  fclose(f);
  run_rc(c, "reset; case C; set wind 8", 0);
  char line[600];
  snprintf(line, sizeof line, "source %s", path);
  run_rc(c, line, 0);
  char* after = shown(c);
  assert_string_equal(before, after);
  unlink(path);
  free(s);
  free(before);
  free(after);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(shortest),
      cmocka_unit_test_setup_teardown(units, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(minimal, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(replays, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
