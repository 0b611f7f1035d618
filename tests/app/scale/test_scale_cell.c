/* test_scale_cell.c: a grid cell's results as one line of text and back (src/app/scale/scale_cell.c):
 * exact for every double a cell may hold (negative zero, subnormals, NaN criteria), the reason
 * kept (control characters as spaces, bytes that are not UTF-8 as '?'), dpar and dperp left as
 * they are; malformed lines refused, and so are values outside their domain (p or a PoF of 5,
 * 1e300, inf, nan or -1, an infinite criterion) and reasons that hold control bytes (an escape
 * sequence would drive the terminal that prints it). */
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
  c.pof[urCRIT_NIJ] = 1.0;
  c.pof[urCRIT_VC] = 4.9e-324;
  c.pof[urCRIT_DEFL] = -0.0;
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
  assert_true(isnan(b.val[urVAL_DEFL_THORAX]) && b.pof[urCRIT_NIJ] == 1);
  assert_true(b.pof[urCRIT_DEFL] == 0 && signbit(b.pof[urCRIT_DEFL]));
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

  /* bytes that are not UTF-8, C1 controls: '?'; printable UTF-8 kept */
  snprintf(a.reason, sizeof a.reason, "bad \xff byte, \xc2\x9b csi");
  assert_true(ura_cell_write(&a, line, sizeof line) > 0);
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_string_equal(b.reason, "bad ? byte, ?? csi");
  snprintf(a.reason, sizeof a.reason, "angle 45\xc2\xb0 \xe2\x80\x94 too steep");
  assert_true(ura_cell_write(&a, line, sizeof line) > 0);
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_string_equal(b.reason, a.reason);
}

/* the line of cell a with its text after '|' replaced by reason */
static void with_reason(const urCell* a, const char* reason, char* line, size_t n) {
  assert_true(ura_cell_write(a, line, n) > 0);
  char* bar = strchr(line, '|');
  snprintf(bar + 1, n - (size_t)(bar + 1 - line), "%s", reason);
}

/* a reason someone wrote into a part: printed later, so no byte may drive a terminal */
static void reason_refused(void** state) {
  urCell a = sample(), b = sample(), keep;
  char line[600];
  a.status = urCELL_FAILED;
  static const char* const bad[] = {"\033]0;pwned\007", /* set the terminal's title */
                                    "\033[2J\033[H",    /* clear the screen */
                                    "tab\there",        /* any C0 control */
                                    "del\177",          /* DEL */
                                    "\xc2\x9b"
                                    "2J", /* CSI as a C1 control in UTF-8 */
                                    "\x9b"
                                    "2J",           /* CSI as a raw 8-bit byte */
                                    "\xc3",         /* a cut UTF-8 sequence */
                                    "\xed\xa0\x80", /* a surrogate */
                                    NULL};
  for (int i = 0; bad[i]; i++) {
    with_reason(&a, bad[i], line, sizeof line);
    keep = b;
    assert_int_equal(ura_cell_read(line, &b), -1);
    assert_memory_equal(&keep, &b, sizeof b);
  }
  with_reason(&a, "plain text, 45\xc2\xb0", line, sizeof line); /* the control case */
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_string_equal(b.reason, "plain text, 45\xc2\xb0");
}

/* the line of cell a with field k (0: status) replaced by text */
static void with_field(const urCell* a, int k, const char* text, char* line, size_t n) {
  char orig[600], *w[40], *save = NULL;
  int nw = 0;
  assert_true(ura_cell_write(a, orig, sizeof orig) > 0);
  char* bar = strchr(orig, '|');
  *bar = 0;
  for (char* t = strtok_r(orig, " ", &save); t && nw < 40; t = strtok_r(NULL, " ", &save)) {
    w[nw++] = t;
  }
  assert_true(k < nw);
  size_t len = 0;
  for (int i = 0; i < nw; i++) {
    len += (size_t)snprintf(line + len, n - len, "%s ", i == k ? text : w[i]);
  }
  snprintf(line + len, n - len, "|");
}

/* values outside their domain, as a forger would write them (the checksum is no signature) */
static void domain(void** state) {
  urCell a = sample(), b = sample(), keep;
  char line[600];
  const int f_pof = 2 + urNVAL, f_p = 2 + urNVAL + urNCRIT;
  static const char* const notprob[] = {
      "5", "1e300", "inf", "-inf", "nan", "-1", "0x1.0000000000001p+0", "-0x1p-1074", NULL};
  for (int i = 0; notprob[i]; i++) {
    for (int k = 0; k < urNCRIT + 1; k++) { /* every PoF, then p */
      with_field(&a, k < urNCRIT ? f_pof + k : f_p, notprob[i], line, sizeof line);
      keep = b;
      assert_int_equal(ura_cell_read(line, &b), -1);
      assert_memory_equal(&keep, &b, sizeof b);
    }
  }
  for (int v = 0; v < urNVAL; v++) { /* a criterion: finite or NaN, never infinite */
    with_field(&a, 2 + v, "inf", line, sizeof line);
    assert_int_equal(ura_cell_read(line, &b), -1);
    with_field(&a, 2 + v, "-inf", line, sizeof line);
    assert_int_equal(ura_cell_read(line, &b), -1);
    if (v == urVAL_NIJ_MODE) continue;
    with_field(&a, 2 + v, "nan", line, sizeof line);
    assert_int_equal(ura_cell_read(line, &b), 0);
    assert_true(isnan(b.val[v]));
  }
  /* the edges of the domain are in it: p = 0 and 1, a PoF of 1 */
  with_field(&a, f_p, "0x1p+0", line, sizeof line);
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_true(b.p == 1);
  with_field(&a, f_p, "0", line, sizeof line);
  assert_int_equal(ura_cell_read(line, &b), 0);
  assert_true(b.p == 0);
  with_field(&a, f_pof, "1", line, sizeof line);
  assert_int_equal(ura_cell_read(line, &b), 0);
  /* a blank or a tab before a number is not a number of the format */
  with_field(&a, f_p, "\t0", line, sizeof line);
  assert_int_equal(ura_cell_read(line, &b), -1);

  /* the writer refuses what the reader would: -2 */
  urCell w = sample();
  w.p = 5;
  assert_int_equal(ura_cell_write(&w, line, sizeof line), -2);
  w = sample();
  w.pof[urCRIT_VC] = NAN;
  assert_int_equal(ura_cell_write(&w, line, sizeof line), -2);
  w = sample();
  w.val[urVAL_HIC15] = INFINITY;
  assert_int_equal(ura_cell_write(&w, line, sizeof line), -2);
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
  with_field(&a, 2 + urVAL_NIJ_MODE, "1e300", bad, sizeof bad); /* a mode out of range */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  with_field(&a, 2 + urVAL_NIJ_MODE, "0x1.8p+0", bad, sizeof bad); /* not whole */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  with_field(&a, 2 + urVAL_NIJ_MODE, "0x1p+1", bad, sizeof bad); /* the control case: 2 */
  assert_int_equal(ura_cell_read(bad, &b), 0);
  assert_true(b.val[urVAL_NIJ_MODE] == 2);
  snprintf(bad, sizeof bad, "%s%070d", line, 0); /* reason too long */
  assert_int_equal(ura_cell_read(bad, &b), -1);
  urCell keep = b; /* a refusal changes nothing */
  assert_int_equal(ura_cell_read("2 1 0x1p+0", &b), -1);
  assert_memory_equal(&keep, &b, sizeof b);
  assert_int_equal(ura_cell_read(line, &b), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(round_trip),     cmocka_unit_test(reason), cmocka_unit_test(malformed),
      cmocka_unit_test(reason_refused), cmocka_unit_test(domain),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
