/* test_speedunit.c: the units a speed may be typed in (speedunit.c): m/s, km/h and kt exactly so
   spelled, converted by their definitions (1 km/h = 1000/3600 m/s; 1 kt = 1852/3600 m/s, the
   international nautical mile per hour) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "../../../src/app/base/base.h"

static void known_units(void** state) {
  double f;
  assert_int_equal(ura_speed_unit("m/s", &f), 0);
  assert_true(f == 1);
  assert_int_equal(ura_speed_unit("km/h", &f), 0);
  assert_true(f == 1000.0 / 3600);
  assert_int_equal(ura_speed_unit("kt", &f), 0);
  assert_true(f == 1852.0 / 3600);
}

/* strict: no other spelling, no case folding, no blanks */
static void refused_units(void** state) {
  static const char* const bad[] = {"KT",  "kts", "knots", "kn", "kmh",  "km/h ",
                                    " kt", "mph", "m/h",   "",   "ft/s", NULL};
  double f = 7;
  for (int i = 0; bad[i]; i++) {
    assert_int_equal(ura_speed_unit(bad[i], &f), -1);
    assert_true(f == 7);
  }
}

/* closed forms: 36 km/h is 10 m/s exactly; 10 kt is 5.1444... m/s; 0 stays 0 */
static void conversions(void** state) {
  assert_true(ura_speed_to_si("km/h", 36) == 10);
  assert_true(ura_speed_to_si("km/h", 3.6) == 1);
  assert_true(fabs(ura_speed_to_si("kt", 10) - 5.144444444444445) <= 1e-15);
  assert_true(fabs(ura_speed_to_si("kt", 1) - 0.5144444444444445) <= 1e-16);
  assert_true(ura_speed_to_si("m/s", 4.25) == 4.25);
  assert_true(ura_speed_to_si("kt", 0) == 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(known_units),
      cmocka_unit_test(refused_units),
      cmocka_unit_test(conversions),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
