/* test_rng.c: Philox4x32-10 against the known-answer vectors of Random123 (tests/kat_vectors of
 * the reference implementation by Salmon et al., SC'11), and the uniforms drawn from it */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "uasimpact/rng.h"

static void known_answers(void** state) {
  static const uint32_t ctr[3][4] = {{0, 0, 0, 0},
                                     {0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu},
                                     {0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u}};
  static const uint32_t key[3][2] = {
      {0, 0}, {0xffffffffu, 0xffffffffu}, {0xa4093822u, 0x299f31d0u}};
  static const uint32_t want[3][4] = {{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u},
                                      {0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu},
                                      {0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}};
  for (int i = 0; i < 3; i++) {
    uint32_t out[4];
    ur_philox4x32_10(ctr[i], key[i], out);
    for (int k = 0; k < 4; k++) assert_int_equal(out[k], want[i][k]);
  }
}

/* uniforms: in (0, 1), a pure function of (seed, sample, stream), different across each of
   them, and uniform (mean 1/2, variance 1/12 within 4 standard errors over 100000 draws) */
static void uniforms(void** state) {
  uint32_t s = ur_rng_stream("wind");
  assert_int_equal(s, ur_rng_stream("wind"));
  assert_int_not_equal(s, ur_rng_stream("face"));
  assert_true(ur_rng_uniform(1, 7, s) == ur_rng_uniform(1, 7, s));
  assert_true(ur_rng_uniform(1, 7, s) != ur_rng_uniform(2, 7, s));
  assert_true(ur_rng_uniform(1, 7, s) != ur_rng_uniform(1, 8, s));
  assert_true(ur_rng_uniform(1, 7, s) != ur_rng_uniform(1, 7, s + 1));
  assert_true(ur_rng_uniform(1, (uint64_t)1 << 40, s) != ur_rng_uniform(1, 0, s));
  double sum = 0, sum2 = 0;
  int n = 100000;
  for (int i = 0; i < n; i++) {
    double u = ur_rng_uniform(42, (uint64_t)i, s);
    assert_true(u > 0 && u < 1);
    sum += u;
    sum2 += (u - 0.5) * (u - 0.5);
  }
  assert_true(fabs(sum / n - 0.5) < 4 * sqrt(1.0 / 12 / n));
  assert_true(fabs(sum2 / n - 1.0 / 12) < 4 * sqrt(1.0 / 180 / n));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(known_answers),
      cmocka_unit_test(uniforms),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
