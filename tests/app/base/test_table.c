/* test_table.c: tables as src/app/base/table.c writes them: aligned, folded into blocks of
 * columns led by the first when a row is wider than the width (never past it), plain CSV with
 * the notes on their own stream, fields holding a comma or quote quoted and "-" (no value) empty,
 * and JSON with numbers as numbers, empty and "-" cells null and text escaped by the library */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/base/base.h"

/* a table of two rows: key and five wide columns, one note */
static uraTable* sample(void) {
  static const char* const cols[] = {"key", "alpha", "beta", "gamma", "delta", "epsilon"};
  uraTable* t = ura_table_new(6, cols);
  ura_table_note(t, "a note");
  for (int r = 0; r < 2; r++) {
    ura_table_cell(t, "%s", r ? "B" : "A");
    for (int j = 1; j < 6; j++) ura_table_cell(t, "%d.25", 1000 * j + r);
  }
  return t;
}

/* what ura_table_write prints to f (and to nf in *notes when notes is not NULL) */
static char* written(uraTable* t, int how, int width, char** notes) {
  char *buf = NULL, *nbuf = NULL;
  size_t n = 0, nn = 0;
  FILE* f = open_memstream(&buf, &n);
  FILE* nf = notes ? open_memstream(&nbuf, &nn) : NULL;
  ura_table_write(f, nf, t, how, width);
  fclose(f);
  if (nf) {
    fclose(nf);
    *notes = nbuf;
  }
  return buf;
}

static void folds_to_width(void** state) {
  (void)state;
  char* s = written(sample(), uraTAB_TEXT, 30, NULL);
  /* every line within 30 columns, and every column is there, each block led by key */
  char* line = s;
  int blocks = 0;
  while (*line) {
    char* end = strchr(line, '\n');
    assert_true(end - line <= 30);
    if (!strncmp(line, "key", 3)) blocks++;
    line = end + 1;
  }
  assert_true(blocks >= 2);
  for (int j = 1; j <= 5; j++) {
    char want[16];
    snprintf(want, sizeof want, "%d.25", 1000 * j + 1);
    assert_non_null(strstr(s, want));
  }
  assert_non_null(strstr(s, "epsilon"));
  assert_memory_equal(s, "# a note\nkey    alpha", 21);
  free(s);
  /* width 0: one block, one line per row */
  s = written(sample(), uraTAB_TEXT, 0, NULL);
  assert_string_equal(s,
                      "# a note\n"
                      "key    alpha     beta    gamma    delta  epsilon\n"
                      "  A  1000.25  2000.25  3000.25  4000.25  5000.25\n"
                      "  B  1001.25  2001.25  3001.25  4001.25  5001.25\n");
  free(s);
}

static void csv_plain(void** state) {
  (void)state;
  static const char* const cols[] = {"name", "value"};
  uraTable* t = ura_table_new(2, cols);
  ura_table_note(t, "units: none");
  ura_table_cell(t, "%s", "pop");
  ura_table_cell(t, "%s", "50,500");
  ura_table_cell(t, "%s", "say \"hi\"");
  ura_table_cell(t, "%s", "1");
  ura_table_cell(t, "%s", "none");
  ura_table_cell(t, "%s", "-");
  char* notes = NULL;
  char* s = written(t, uraTAB_CSV, 80, &notes);
  assert_string_equal(s, "name,value\npop,\"50,500\"\n\"say \"\"hi\"\"\",1\nnone,\n");
  assert_string_equal(notes, "# units: none\n");
  free(s);
  free(notes);
}

static void json_typed(void** state) {
  (void)state;
  static const char* const cols[] = {"case", "q", "n", "why", "hex", "na"};
  uraTable* t = ura_table_new(6, cols);
  ura_table_note(t, "quote \" and\ttab");
  ura_table_cell(t, "%s", "A");
  ura_table_cell(t, "%s", "0.0407");
  ura_table_cell(t, "%s", "12");
  ura_table_cell(t, "%s", "");
  ura_table_cell(t, "%s", "0x10");
  ura_table_cell(t, "%s", "-");
  char* s = written(t, uraTAB_JSON, 80, NULL);
  assert_string_equal(s,
                      "{\"columns\":[\"case\",\"q\",\"n\",\"why\",\"hex\",\"na\"],\"rows\":[{"
                      "\"case\":\"A\",\"q\":0.0407,\"n\":12,\"why\":null,\"hex\":\"0x10\","
                      "\"na\":null}],\"notes\":[\"quote \\\" and\\ttab\"]}\n");
  free(s);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(folds_to_width),
      cmocka_unit_test(csv_plain),
      cmocka_unit_test(json_typed),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
