/* test_suggest.c: "did you mean" (src/app/base/suggest.c): the edit distance, how near a name must be,
 * and the names offered in the messages of set, show, help, unknown commands, history and plot */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "../../test_ctx.h"

static void distance(void** state) {
  (void)state;
  assert_int_equal(ura_edit_distance("wind", "wind"), 0);
  assert_int_equal(ura_edit_distance("wnd", "wind"), 1);  /* a letter left out */
  assert_int_equal(ura_edit_distance("wimd", "wind"), 1); /* one wrong */
  assert_int_equal(ura_edit_distance("iwnd", "wind"), 1); /* two swapped */
  assert_int_equal(ura_edit_distance("", "abc"), 3);
  assert_int_equal(ura_edit_distance("kitten", "sitting"), 3);
}

static void nearest(void** state) {
  (void)state;
  uraSuggest s;
  char buf[100];
  ura_suggest_init(&s, "wnd");
  ura_suggest_add(&s, "face");
  ura_suggest_add(&s, "wind");
  ura_suggest_add(&s, "winds");
  assert_string_equal(ura_suggest_text(&s, buf, sizeof buf), " (did you mean 'wind'?)");
  /* too far for a typing slip: nothing offered */
  ura_suggest_init(&s, "xyz");
  ura_suggest_add(&s, "wind");
  assert_string_equal(ura_suggest_text(&s, buf, sizeof buf), "");
  /* a longer word allows two edits */
  ura_suggest_init(&s, "hic_windw");
  ura_suggest_add(&s, "hic_window");
  assert_string_equal(s.best, "hic_window");
  /* the word itself is never offered */
  ura_suggest_init(&s, "wind");
  ura_suggest_add(&s, "wind");
  assert_string_equal(s.best, "");
}

static void keywords(void** state) {
  (void)state;
  uraSuggest s;
  ura_suggest_init(&s, "grdi");
  ura_suggest_keywords(&s, "pof|grid|history [SIGNAL...|all]|sweep [wind|face]");
  assert_string_equal(s.best, "grid");
  ura_suggest_init(&s, "al"); /* inside brackets: not a keyword */
  ura_suggest_keywords(&s, "pof|grid|history [SIGNAL...|all]");
  assert_string_equal(s.best, "");
}

/* the messages: from the command table and the parameter tables */
static void messages(void** state) {
  uraCtx* c = *state;
  run_rc(c, "set wnd 5", -1);
  assert_string_equal(c->err,
                      "set: unknown parameter 'wnd' (did you mean 'wind'?); 'show' lists "
                      "the parameters");
  run_rc(c, "show bag_p1", -1);
  assert_non_null(strstr(c->err, "(did you mean 'bag_p0'?)")); /* a model parameter */
  run_rc(c, "set hic_windw 0.036", -1);
  assert_non_null(strstr(c->err, "(did you mean 'hic_window'?)")); /* an injury setting */
  run_rc(c, "imapct 0 0", -1);
  assert_non_null(strstr(c->err, "unknown command 'imapct' (did you mean 'impact'?)"));
  run_rc(c, "help shw", -1);
  assert_non_null(strstr(c->err, "(did you mean 'show'?)"));
  run_rc(c, "plot grdi", -1);
  assert_non_null(strstr(c->err, "(did you mean 'grid'?)"));
  run_rc(c, "set qqqq 1", -1);
  assert_null(strstr(c->err, "did you mean"));
}

static void channels(void** state) {
  uraCtx* c = *state;
  run_rc(c, "case C; impact 0 0", 0);
  run_rc(c, "history hed_acc", -1);
  assert_non_null(strstr(c->err, "no channel 'hed_acc' (did you mean 'head_acc'?)"));
  /* every name once (chest_defl is a derived signal and a sensor) */
  const char* p = strstr(c->err, "chest_defl");
  assert_non_null(p);
  assert_null(strstr(p + 1, "chest_defl"));
  run_rc(c, "plot history chst_defl", -1);
  assert_non_null(strstr(c->err, "(did you mean 'chest_defl'?)"));
  p = strstr(c->err, "signals: ");
  assert_non_null(p);
  p = strstr(p, "chest_defl");
  assert_non_null(p);
  assert_null(strstr(p + 1, "chest_defl"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(distance),
      cmocka_unit_test(nearest),
      cmocka_unit_test(keywords),
      cmocka_unit_test_setup_teardown(messages, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(channels, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
