/* paper.c: the paper's Table 2 (impact speed and descent angle against wind, cases B and C) for
 * 'set descent paper': the live case's impact conditions take it (state.c), so it is part of the
 * case, not of the descent command that prints it beside the descent model (cmd_paper.c). Only
 * the printed winds are given: a table read off a paper is not interpolated. */
#include <stdio.h>
#include <string.h>

#include "case.h"

/* the paper's Table 2 as printed: wind (m/s), then impact speed |v| (m/s) and descent angle psi
   (deg) of case B (parachute) and case C (no parachute) */
static const double table2[6][5] = {
    {0, 7.5, 90.0, 40.6, 90.0}, {2, 7.8, 75.1, 40.6, 89.0},  {4, 8.5, 62.0, 40.6, 88.0},
    {6, 9.6, 51.5, 40.5, 86.9}, {8, 11.0, 43.3, 40.5, 85.8}, {10, 12.5, 37.0, 40.4, 84.7},
};

const char* ura_paper_descent_column(const char* casename) {
  /* none: the deployment branch without parachute of a drone that has no case C (risk) */
  return !strcmp(casename, "C") || !strcmp(casename, "none") ? "C" : "B";
}

int ura_paper_descent(uraCtx* c, const char* casename, double wind, double* speed, double* angle) {
  int col = !strcmp(ura_paper_descent_column(casename), "C") ? 3 : 1;
  for (int i = 0; i < 6; i++) {
    if (table2[i][0] == wind) {
      *speed = table2[i][col];
      *angle = table2[i][col + 1];
      return 0;
    }
  }
  return ura_fail(c,
                  "descent paper: wind %g m/s is not printed in the paper's Table 2; accepted: "
                  "wind 0, 2, 4, 6, 8 or 10 m/s, or 'set descent model' (or set speed and "
                  "angle)",
                  wind);
}
