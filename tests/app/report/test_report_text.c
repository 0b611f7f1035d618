/* test_report_text.c: the report's copy of the paper's Table 17 (src/app/report/report_text.c,
 * ura_report_table17): each ratio basis that names a grid's full plane is that grid's sum,
 * recomputed here from the paper's grids as committed (sessions/paper/grids, the mirror rule of
 * its README: 0.0025 m^2 x [column 0 + 2 x the columns > 0] / 100), to 5e-5 m^2 (the basis is
 * typed to 4 decimals); a row whose case and wind has a grid takes it as basis; the rest say
 * 0 (the printed value) or -1 (A1, A2 at 0 m/s: no grid, both readings). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/report/report.h"

/* the full-plane Q of the paper's grid of case c at wind w, or -1 when there is none */
static double full_q(const char* c, double w) {
  static const char* const files[] = {
      "table04_caseA_wind0",   "table05_caseB_wind0",   "table06_caseC_wind0",
      "table08_caseA_wind10",  "table09_caseB_wind10",  "table10_caseC_wind10",
      "table15_caseA1_wind10", "table16_caseA2_wind10", NULL};
  char want[64];
  snprintf(want, sizeof want, "_case%s_wind%g", c, w);
  for (int i = 0; files[i]; i++) {
    const char* tail = strchr(files[i], '_');
    if (strcmp(tail, want)) continue;
    char path[200];
    snprintf(path, sizeof path, "sessions/paper/grids/%s.csv", files[i]);
    FILE* f = fopen(path, "r");
    assert_non_null(f);
    char line[4096];
    double cross[64], q = 0;
    int ncol = 0;
    while (fgets(line, sizeof line, f)) {
      if (line[0] == '#' || line[0] == '\n') continue;
      char* save = NULL;
      char* tok = strtok_r(line, ",\n", &save);
      if (!strcmp(tok, "along")) {
        while ((tok = strtok_r(NULL, ",\n", &save)) && ncol < 64) cross[ncol++] = atof(tok);
        continue;
      }
      for (int k = 0; (tok = strtok_r(NULL, ",\n", &save)) && k < ncol; k++)
        q += (cross[k] > 0 ? 2 : 1) * atof(tok) / 100 * 0.0025;
    }
    fclose(f);
    assert_true(ncol > 0);
    return q;
  }
  return -1;
}

static void test_bases(void** state) {
  (void)state;
  const char* c;
  double wind, q, basis;
  int n = 0, grids = 0;
  for (int k = 0; ura_report_table17(k, &c, &wind, &q, &basis) == 0; k++, n++) {
    double fq = full_q(c, wind);
    if (fq >= 0) {
      assert_true(basis > 0);
      assert_float_equal(basis, fq, 5e-5);
      grids++;
    } else if (wind == 0 && (!strcmp(c, "A1") || !strcmp(c, "A2"))) {
      assert_true(basis == -1);
    } else {
      assert_true(basis == 0);
    }
  }
  assert_int_equal(n, 15); /* Table 17: 5 cases x 3 winds */
  assert_int_equal(grids, 8);
}

int main(void) {
  const struct CMUnitTest tests[] = {cmocka_unit_test(test_bases)};
  return cmocka_run_group_tests(tests, NULL, NULL);
}
