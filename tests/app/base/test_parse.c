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

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(good_numbers),
      cmocka_unit_test(bad_numbers),
      cmocka_unit_test(lists),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
