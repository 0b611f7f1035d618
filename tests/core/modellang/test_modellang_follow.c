/* test_modellang_follow.c: a parameter whose default is another parameter (param NAME $OTHER):
 * it follows OTHER (also OTHER's override) until it is itself set, then holds its own value;
 * urParam.from records the source; an unknown OTHER and a cycle are refused with one line. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "modellang_fixture.h"

static const char* text = "param frame_a 0.3 m\nparam bag_a $frame_a m range=0.1,0.65\n";

/* bag_a at its default: frame_a's value, and its source recorded */
static void test_follow(void** state) {
  char err[256];
  urModel* m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  int a = ur_name_param(m, "frame_a"), b = ur_name_param(m, "bag_a");
  assert_true(m->param[b].value == 0.3);
  assert_int_equal(m->param[b].from, a);
  assert_true(m->param[b].from_f == 1);
  assert_int_equal(m->param[a].from, -1);
  assert_string_equal(m->param[b].unit, "m");
  ur_model_free(m);

  /* frame_a set: bag_a follows it */
  urOverride ov = {"frame_a", 0.5};
  m = parse1(text, &ov, 1, err);
  assert_non_null(m);
  assert_true(ur_model_param(m, "bag_a", -1) == 0.5);
  assert_int_equal(m->param[ur_name_param(m, "bag_a")].from, ur_name_param(m, "frame_a"));
  ur_model_free(m);

  /* a unit scales it as it scales a number: d centimetres */
  m = parse1("param d 3\nparam h $d cm\n", NULL, 0, err);
  assert_non_null(m);
  assert_near(ur_model_param(m, "h", -1), 0.03, 1e-17);
  assert_true(m->param[1].from == 0 && m->param[1].from_f == 0.01);
  ur_model_free(m);

  /* -$OTHER is a number, not a parameter that follows */
  m = parse1("param c 2\nparam f -$c\n", NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->param[1].from, -1);
  ur_model_free(m);
}

/* bag_a set: its own value, whatever frame_a is */
static void test_own(void** state) {
  char err[256];
  urOverride ov[2] = {{"bag_a", 0.2}, {"frame_a", 0.5}};
  urModel* m = parse1(text, ov, 2, err);
  assert_non_null(m);
  int b = ur_name_param(m, "bag_a");
  assert_true(m->param[b].value == 0.2);
  assert_int_equal(m->param[b].from, -1);
  assert_true(ur_model_param(m, "frame_a", -1) == 0.5);
  ur_model_free(m);

  /* the host's own set holds it too */
  m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(ur_model_set_param(m, "bag_a", 0.25), b);
  assert_int_equal(m->param[b].from, -1);
  ur_model_free(m);

  /* a later definition by a number holds its own value */
  urModelSource src[2] = {{text, "t.urm"}, {"param bag_a 0.4 m\n", "u.urm"}};
  m = ur_model_parse(src, 2, NULL, 0, err, 256);
  assert_non_null(m);
  assert_true(ur_model_param(m, "bag_a", -1) == 0.4);
  assert_int_equal(m->param[b].from, -1);
  ur_model_free(m);
}

/* an unknown OTHER: one line naming both */
static void test_unknown(void** state) {
  char err[256];
  urModel* m = parse1("param bag_a $frame_a m\n", NULL, 0, err);
  assert_null(m);
  assert_string_equal(err,
                      "t.urm:1: param 'bag_a': unknown parameter 'frame_a'; expected 'param "
                      "NAME VALUE' before its use");
}

/* a chain that comes back (a later part redefines the first) is refused */
static void test_cycle(void** state) {
  char err[256];
  urModelSource src[2] = {{"param a 1\nparam b $a\n", "t.urm"}, {"\nparam a $b\n", "u.urm"}};
  urModel* m = ur_model_parse(src, 2, NULL, 0, err, 256);
  assert_null(m);
  assert_string_equal(err,
                      "u.urm:2: param 'a': $b makes a cycle (a -> b -> a); expected a number, "
                      "or a parameter that does not follow 'a'");

  /* itself */
  urModelSource self[2] = {{"param a 1\n", "t.urm"}, {"param a $a\n", "u.urm"}};
  m = ur_model_parse(self, 2, NULL, 0, err, 256);
  assert_null(m);
  assert_string_equal(err,
                      "u.urm:1: param 'a': $a makes a cycle (a -> a); expected a number, or a "
                      "parameter that does not follow 'a'");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_follow),
      cmocka_unit_test(test_own),
      cmocka_unit_test(test_unknown),
      cmocka_unit_test(test_cycle),
  };
  (void)model_text; /* the fixture's test model: not used here */
  return cmocka_run_group_tests(tests, NULL, NULL);
}
