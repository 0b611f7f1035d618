/* test_wrap.c: text for an 80-column terminal (src/app/base/wrap.c): wrapping between words, long
 * lists broken after their commas, no wrapping at width 0, and fields split at double spaces */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/base/base.h"

static char* wrapped(const char* lead, const char* cont, const char* text, int width) {
  char* buf = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&buf, &n);
  ura_wrap(f, lead, cont, text, width);
  fclose(f);
  return buf;
}

static void words(void** state) {
  (void)state;
  char* s = wrapped("# ", "#   ", "one two three four five six", 14);
  assert_string_equal(s, "# one two\n#   three four\n#   five six\n");
  free(s);
  /* width 0: one line, the text as it is (spaces kept) */
  s = wrapped("# ", "#   ", "one  two three", 0);
  assert_string_equal(s, "# one  two three\n");
  free(s);
  /* a word longer than the line stays whole when it has nowhere to break */
  s = wrapped("", "", "abcdefghij xy", 5);
  assert_string_equal(s, "abcdefghij\nxy\n");
  free(s);
}

static void lists(void** state) {
  (void)state;
  char* s = wrapped("  ", "  ", "columns dpar,dperp,contact,hic15,nij", 20);
  /* longer than a line: it starts where it is and breaks after commas */
  assert_string_equal(s, "  columns dpar,\n  dperp,contact,\n  hic15,nij\n");
  free(s);
  s = wrapped("", "    ", "dist [A|bb|ccc|dddd]", 12);
  assert_string_equal(s, "dist [A|bb|\n    ccc|\n    dddd]\n");
  free(s);
  /* no line longer than the width when there are places to break */
  s = wrapped("  ", "     ",
              "case,wind,speed,angle,planform,mtow,gliding,pof_rcc,pof_bc,pof_awke "
              "and more words after it",
              30);
  for (char* l = s; *l; l = strchr(l, '\n') + 1) assert_true(strcspn(l, "\n") <= 30);
  free(s);
}

static void fields(void** state) {
  (void)state;
  char out[4][256];
  int n = ura_split_fields("aa bb  cc  dd ee  ff", 10, out, 4);
  assert_int_equal(n, 2);
  assert_string_equal(out[0], "aa bb  cc");
  assert_string_equal(out[1], "dd ee  ff");
  n = ura_split_fields("aa  bb  cc", 80, out, 4);
  assert_int_equal(n, 1);
  assert_string_equal(out[0], "aa  bb  cc");
  /* at most max lines: the last takes the rest */
  n = ura_split_fields("aa  bb  cc  dd", 2, out, 2);
  assert_int_equal(n, 2);
  assert_string_equal(out[0], "aa");
  assert_string_equal(out[1], "bb  cc  dd");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(words),
      cmocka_unit_test(lists),
      cmocka_unit_test(fields),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
