/* test_parse.c: strict number and list parsing */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "../../../src/app/base/base.h"

static void good_numbers(void** state) {
  double v;
  assert_int_equal(ura_parse_number("1.5", &v), 0);
  assert_true(v == 1.5);
  assert_int_equal(ura_parse_number(" -2e-3 ", &v), 0);
  assert_true(v == -2e-3);
  assert_int_equal(ura_parse_number("+7", &v), 0);
  assert_true(v == 7);
  assert_int_equal(ura_parse_number(".5", &v), 0);
  assert_true(v == 0.5);
}

static void bad_numbers(void** state) {
  static const char* const bad[] = {"",    " ",   "abc",  "1.5abc",   "1e400", "-1e400", "nan",
                                    "NaN", "inf", "-inf", "infinity", "0x",    "0x10",   "1,5",
                                    "1 2", "--1", "e5",   ".",        "1e",    "\t",     NULL};
  double v = 42;
  for (int i = 0; bad[i]; i++) {
    assert_int_equal(ura_parse_number(bad[i], &v), -1);
    assert_true(v == 42);
  }
  assert_int_equal(ura_parse_number(NULL, &v), -1);
}

static void lists(void** state) {
  double v[8];
  assert_int_equal(ura_parse_list("0,2,4", v, 8), 3);
  assert_true(v[0] == 0 && v[1] == 2 && v[2] == 4);
  assert_int_equal(ura_parse_list("3.5", v, 8), 1);
  assert_int_equal(ura_parse_list("1,,2", v, 8), -1);
  assert_int_equal(ura_parse_list("1,2,", v, 8), -1);
  assert_int_equal(ura_parse_list("1,x", v, 8), -1);
  assert_int_equal(ura_parse_list("", v, 8), -1);
  assert_int_equal(ura_parse_list("1,2,3", v, 2), -1);
}

/* issue 30: why a list is refused, the value named by its place and never the whole list */
static void list_reasons(void** state) {
  double v[8];
  char why[200];
  assert_int_equal(ura_list_count("0,2,4"), 3);
  assert_int_equal(ura_list_count("5"), 1);
  assert_int_equal(ura_parse_list_why("0,2,4", v, 8, why, sizeof why), 3);
  assert_string_equal(why, "");
  assert_int_equal(ura_parse_list_why("1,x,3", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "value 2 of 3, 'x', is not a number");
  assert_int_equal(ura_parse_list_why("1,,2", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "value 2 of 3 is empty");
  assert_int_equal(ura_parse_list_why("1,2,", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "value 3 of 3 is empty");
  assert_int_equal(ura_parse_list_why("", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "the list is empty");
  assert_int_equal(ura_parse_list_why("1,2,3", v, 2, why, sizeof why), -1);
  assert_string_equal(why, "3 values, more than 2");
  /* a long bad value is cut to 32 bytes, a control byte made visible */
  assert_int_equal(
      ura_parse_list_why("1,0123456789012345678901234567890123456789x", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "value 2 of 2, '01234567890123456789012345678901...', is not a number");
  assert_int_equal(ura_parse_list_why("1\x1b[2J", v, 8, why, sizeof why), -1);
  assert_string_equal(why, "value 1 of 1, '1\\x1b[2J', is not a number");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(good_numbers),
      cmocka_unit_test(bad_numbers),
      cmocka_unit_test(lists),
      cmocka_unit_test(list_reasons),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
