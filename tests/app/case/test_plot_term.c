/* test_plot_term.c: the gnuplot terminals and outputs plot accepts (plot_term.c): what each
 * terminal draws on, the normal form of an accepted setting, one clear refusal of a bad one,
 * and the terminal an output's extension implies. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../../../src/app/ui/ui.h"

static void test_kind(void** state) {
  (void)state;
  assert_int_equal(ura_term_kind(""), uraTERM_WINDOW);
  assert_int_equal(ura_term_kind("qt"), uraTERM_WINDOW);
  assert_int_equal(ura_term_kind("dumb size 80,24"), uraTERM_TEXT);
  assert_int_equal(ura_term_kind("pngcairo size 800,600"), uraTERM_FILE);
}

static void test_for_ext(void** state) {
  (void)state;
  assert_string_equal(ura_term_for_ext("a/b.png"), "pngcairo");
  assert_string_equal(ura_term_for_ext("x.PDF"), "pdfcairo");
  assert_string_equal(ura_term_for_ext("t.txt"), "dumb");
  assert_null(ura_term_for_ext("noext"));
  assert_null(ura_term_for_ext("x.doc"));
}

static void test_checks(void** state) {
  (void)state;
  uraCtx* c = calloc(1, sizeof *c);
  char norm[512];
  assert_int_equal(ura_terminal_check(c, "png   size 800,600 ", norm, sizeof norm), 0);
  assert_string_equal(norm, "png size 800,600");
  assert_int_equal(ura_terminal_check(c, "png size 800", norm, sizeof norm), -1);
  assert_non_null(strstr(c->err, "size needs W,H"));
  assert_int_equal(ura_terminal_check(c, "nosuchterm", norm, sizeof norm), -1);
  assert_null(strchr(c->err, '\n')); /* one line */
  assert_int_equal(ura_terminal_check(c, "png font 'x'; system 'ls'", norm, sizeof norm), -1);
  assert_int_equal(ura_output_check(c, "plot.png", norm, sizeof norm), 0);
  assert_string_equal(norm, "plot.png");
  assert_int_equal(ura_output_check(c, "|rm -rf x", norm, sizeof norm), -1);
  assert_non_null(strstr(c->err, "pipe"));
  free(c);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_kind),
      cmocka_unit_test(test_for_ext),
      cmocka_unit_test(test_checks),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
