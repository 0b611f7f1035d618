/* bench_montecarlo.c: a 1000-sample Monte Carlo of case A over wind speed (Weibull, scale 5 m/s,
 * shape 2) and face direction (uniform over the circle), as 'montecarlo 1000' runs it: the
 * response surface (7 x 7 nodes, the grids of case A and of the unmitigated drone), its check
 * against 10 samples' own grids, and the wall time of the whole command.
 *   bench_montecarlo [STEP]     grid pitch in m, default 0.1 (0.05 is the paper's: about four
 *                               times as long)
 * The machine may be shared: wall times are noisy. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../src/app/ui/ui.h"

int main(int argc, char** argv) {
  double step = argc > 1 ? atof(argv[1]) : 0.1;
  uraCtx* c = calloc(1, sizeof *c);
  ura_init(c);
  if (!c->model) {
    fprintf(stderr, "bench_montecarlo: %s\n", c->err);
    return 1;
  }
  char line[400];
  snprintf(line, sizeof line,
           "set step %g; case A; set recall off; dist wind weibull 5 2; "
           "dist face uniform -180 180; set surface_check 10",
           step);
  if (ura_run_line(c, line)) {
    fprintf(stderr, "bench_montecarlo: %s\n", c->err);
    return 1;
  }
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  int rc = ura_run_line(c, "montecarlo 1000");
  clock_gettime(CLOCK_MONOTONIC, &t1);
  if (rc) {
    fprintf(stderr, "bench_montecarlo: %s\n", c->err);
    return 1;
  }
  printf(
      "bench_montecarlo: 1000 samples of case A over wind and face at step %g m: %.1f s wall "
      "(summary above)\n",
      step, (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));
  return 0;
}
