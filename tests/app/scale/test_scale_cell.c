/* test_scale_cell.c: a grid cell's results as one line of text and back (src/app/scale/scale_cell.c):
 * exact for every double (negative zero, subnormals, infinities, NaN), the reason kept (control
 * characters as spaces), dpar and dperp left as they are; malformed lines refused. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/scale/scale.h"

static urCell sample(void) {
  urCell c;
  memset(&c, 0, sizeof c);
  c.dpar = 0.25;
  c.dperp = -0.5;
  c.status = urCELL_DONE;
  c.contact = 1;
  c.val[urVAL_HIC15] = 520.86312345678901;
  c.val[urVAL_HIC_T1] = 0.0934;
  c.val[urVAL_HIC_T2] = 0.10585;
  c.val[urVAL_NIJ] = 0.68482;
  c.val[urVAL_NIJ_MODE] = 3;
  c.val[urVAL_VC_THORAX] = 4.9e-324; /* the smallest subnormal */
  c.val[urVAL_VC_ABDOMEN] = -0.0;
  c.val[urVAL_DEFL_THORAX] = NAN;
  c.pof[urCRIT_HIC] = 1.0 / 3.0;
  c.pof[urCRIT_NIJ] = INFINITY;
  c.pof[urCRIT_VC] = NAN;
  c.pof[urCRIT_DEFL] = -INFINITY;
  c.p = 0x1.fffffffffffffp-1;
  c.extrap = 2;
  return c;
}

static void round_trip(void** state) {
  urCell a = sample(), b;
  char line[512];
  memset(&b, 0x5a, sizeof b);
  b.dpar = 7;
  b.dperp = 8;
  assert_true(ura_cell_write(&a, line, sizeof line) > 0);
  assert_null(strchr(line, '\n'));
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_true(b.dpar == 7 && b.dperp == 8); /* the offsets are the grid's */
  b.dpar = a.dpar;
  b.dperp = a.dperp;
  assert_int_equal(b.status, a.status);
  assert_int_equal(b.contact, a.contact);
  assert_int_equal(b.extrap, a.extrap);
  /* every registry value and PoF bit for bit (NaNs as NaNs) */
  for (int i = 0; i < urNVAL; i++) {
    if (isnan(a.val[i]))
      assert_true(isnan(b.val[i]));
    else
      assert_memory_equal(&b.val[i], &a.val[i], sizeof a.val[i]);
  }
  for (int i = 0; i < urNCRIT; i++) {
    if (isnan(a.pof[i]))
      assert_true(isnan(b.pof[i]));
    else
      assert_memory_equal(&b.pof[i], &a.pof[i], sizeof a.pof[i]);
  }
  assert_true(b.val[urVAL_VC_ABDOMEN] == 0 && signbit(b.val[urVAL_VC_ABDOMEN]));
  assert_true(isinf(b.pof[urCRIT_NIJ]) && isnan(b.pof[urCRIT_VC]));
  assert_true(b.p == a.p);
  assert_string_equal(b.reason, "");
}

static void reason(void** state) {
  urCell a = sample(), b = sample();
  char line[512];
  a.status = urCELL_FAILED;
  snprintf(a.reason, sizeof a.reason, "step\tsize | too small\n");
  assert_true(ura_cell_write(&a, line, sizeof line) > 0);
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_int_equal(b.status, urCELL_FAILED);
  assert_string_equal(b.reason, "step size | too small ");
  assert_int_equal(ura_cell_write(&a, line, 20), -1); /* too small a buffer */
}

static void malformed(void** state) {
  urCell a = sample(), b = sample();
  char line[512], bad[600];
  assert_true(ura_cell_write(&a, line, sizeof line) > 0);
  const char* cut = strchr(line, '|');
  snprintf(bad, sizeof bad, "%.*s", (int)(cut - line), line); /* no reason marker */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  snprintf(bad, sizeof bad, " %s", line); /* leading space */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  snprintf(bad, sizeof bad, "9%s", line + 1); /* no such status */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  snprintf(bad, sizeof bad, "%s", line);
  char* sp = strchr(strchr(bad, ' ') + 1, ' '); /* a field dropped */
  memmove(sp, strchr(sp + 1, ' '), strlen(strchr(sp + 1, ' ')) + 1);
  assert_int_equal(ura_cell_read(bad, &b), -1);
  snprintf(bad, sizeof bad, "%s", line);
  *strchr(strchr(bad, ' ') + 1, ' ') = 'x'; /* junk in a number */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  assert_int_equal(ura_cell_read("", &b), -1);
  urCell big = sample(); /* a mode out of range */
  big.val[urVAL_NIJ_MODE] = 1e300;
  assert_true(ura_cell_write(&big, bad, sizeof bad) > 0);
  assert_int_equal(ura_cell_read(bad, &b), -1);
  snprintf(bad, sizeof bad, "%s%070d", line, 0); /* reason too long */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  urCell keep = b; /* a refusal changes nothing */
  assert_int_equal(ura_cell_read("2 1 0x1p+0", &b), -1);
  assert_memory_equal(&keep, &b, sizeof b);
  assert_int_equal(ura_cell_read(line, &b), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(round_trip),
      cmocka_unit_test(reason),
      cmocka_unit_test(malformed),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
