/* test_textin.c: bounded line reading: line ends (LF, CRLF, none at the end), empty lines, NUL
 * bytes, over-long lines (also without any line break, as /dev/zero), read errors */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/case/case.h"

/* a stream over n bytes of text */
static FILE* over(const char* text, size_t n) {
  FILE* f = fmemopen((void*)text, n, "r");
  assert_non_null(f);
  return f;
}

static void lines(void** state) {
  static const char text[] = "one\r\n\ntwo\nlast";
  FILE* f = over(text, sizeof text - 1);
  char* buf = NULL;
  size_t cap = 0;
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), 3);
  assert_string_equal(buf, "one");
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), 0);
  assert_string_equal(buf, "");
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), 3);
  assert_string_equal(buf, "two");
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), 4);
  assert_string_equal(buf, "last");
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), uraLINE_EOF);
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), uraLINE_EOF);
  fclose(f);
  free(buf);
}

static void refused(void** state) {
  char* buf = NULL;
  size_t cap = 0;

  /* a NUL byte ends the reading at once */
  static const char nul[] = "ok\nbad\0line\n";
  FILE* f = over(nul, sizeof nul - 1);
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), 2);
  assert_int_equal(ura_read_line(f, &buf, &cap, 100), uraLINE_NUL);
  fclose(f);

  /* exactly max bytes is a line, one more is not; the buffer stays within max + 2 */
  char lng[64];
  memset(lng, 'a', sizeof lng);
  f = over(lng, 10);
  assert_int_equal(ura_read_line(f, &buf, &cap, 10), 10);
  fclose(f);
  f = over(lng, 11);
  assert_int_equal(ura_read_line(f, &buf, &cap, 10), uraLINE_LONG);
  fclose(f);
  free(buf);
  buf = NULL;
  cap = 0;
  f = over(lng, sizeof lng);
  assert_int_equal(ura_read_line(f, &buf, &cap, 20), uraLINE_LONG);
  assert_true(cap <= 22);
  fclose(f);

  /* /dev/zero: a NUL at once, nothing read into memory beyond it */
  f = fopen("/dev/zero", "r");
  if (f) {
    assert_int_equal(ura_read_line(f, &buf, &cap, 1 << 20), uraLINE_NUL);
    fclose(f);
  }

  /* a directory: a read error, not the end of the file */
  f = fopen("/", "r");
  if (f) {
    assert_int_equal(ura_read_line(f, &buf, &cap, 100), uraLINE_ERROR);
    fclose(f);
  }
  free(buf);
}

/* text echoed in messages: control bytes, DEL, C1 controls and bytes that are not UTF-8 as \xNN;
   printable ASCII and UTF-8 kept; cut to the buffer, never in the middle of an escape */
static void printable(void** state) {
  char buf[64];
  ura_printable("set \033[2J\a\x7f", buf, sizeof buf);
  assert_string_equal(buf, "set \\x1b[2J\\x07\\x7f");
  ura_printable(
      "\xc2\x9b"
      "31m \xc3\xa9t\xc3\xa9 \xe2\x82\xac",
      buf, sizeof buf);
  assert_string_equal(buf, "\\xc2\\x9b31m \xc3\xa9t\xc3\xa9 \xe2\x82\xac");
  ura_printable("\xff\xc3(\xed\xa0\x80\xc0\xaf", buf,
                sizeof buf); /* invalid, surrogate, overlong */
  assert_string_equal(buf, "\\xff\\xc3(\\xed\\xa0\\x80\\xc0\\xaf");
  assert_int_equal(ura_printable("ab\ncd", buf, 7), 6);
  assert_string_equal(buf, "ab\\x0a");
  assert_int_equal(ura_printable("abcdef", buf, 4), 3);
  assert_string_equal(buf, "abc");

  /* every message goes through it */
  uraCtx c;
  memset(&c, 0, sizeof c);
  ura_fail(&c, "unknown '%s'", "\033]0;x\007");
  assert_string_equal(c.err, "unknown '\\x1b]0;x\\x07'");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(lines),
      cmocka_unit_test(refused),
      cmocka_unit_test(printable),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
