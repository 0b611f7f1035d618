/* bench_grid.c: cost of whole offset grids through the workbench (uraCtx, as the 'grid' command
 * runs them): wall seconds per zero-wind grid for cases A (with the analytic bag), B and C and per
 * 10 m/s grid of case B, simulated impacts per second, and the speed-up from 1 to 2 worker threads
 * (whose grids must be identical), and case A's zero-wind grid with the membrane airbags (case
 * A's default since the switch-over, issue 33), also with the faster wrinkling law (bag_wrinkle 1).
 * The set-up of a case (model
 * compile, settled stance) is timed apart. The targets of issue #6 are 1 s per zero-wind grid and
 * 5 ms of CPU per impact; issue 32's is 3 s for A's grid with membrane bags; issue 36's 0.3 s
 * for the zero-wind grids of B and C and 1 s for A's with membrane bags.
 *   bench_grid [STEP [RUNS]]   grid pitch in m, default 0.05 (the paper's); each grid computed
 *                              RUNS times, default 5 (issue 36's median of 5): the median wall
 *                              time and the range, every run's cells the first run's bit for bit
 * The machine may be shared: wall times are noisy, and the load average is printed with them. */
#include <gsl/gsl_sort.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "../src/app/ui/ui.h"

static double now(double* cpu) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  *cpu = t.tv_sec + 1e-9 * t.tv_nsec;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef struct {
  double setup, wall, cpu, q; /* model and settled stance; the grid itself (median of the runs,
                                 and its CPU); Q */
  double wmin, wmax;          /* the runs' least and largest wall times */
  int impacts, cells;
} result;

static int runs = 5; /* each grid's runs (RUNS) */

static int same_cells(const urGrid* a, const urGrid* b);

/* one grid of the given set-up, run `runs` times (each run's cells the first's, bit for bit, or
   an error); the last grid stays in c->last */
static int grid(uraCtx* c, const char* setup, double step, int threads, result* r) {
  char line[256];
  snprintf(line, sizeof line, "%s; set step %g; set threads %d", setup, step, threads);
  if (ura_run_line(c, line)) {
    fprintf(stderr, "bench_grid: '%s': %s\n", line, c->err);
    return -1;
  }
  /* the case's model and settled stance first ('grid' builds them when stale), timed apart */
  double cpu0, cpu1;
  double t0 = now(&cpu0);
  if (!ura_setup(c)) {
    fprintf(stderr, "bench_grid: %s: %s\n", setup, c->err);
    return -1;
  }
  r->setup = now(&cpu1) - t0;
  double wall[64], cpu[64];
  urGrid* first = NULL;
  for (int k = 0; k < runs; k++) {
    t0 = now(&cpu0);
    if (ura_grid_run(c, 1) || !c->last.g->complete) {
      fprintf(stderr, "bench_grid: %s: %s\n", setup, c->err[0] ? c->err : "failed cells");
      ur_grid_free(first);
      return -1;
    }
    wall[k] = now(&cpu1) - t0;
    cpu[k] = cpu1 - cpu0;
    if (k == 0) {
      first = c->last.g; /* kept: the next run replaces c->last */
      c->last.g = NULL;
    } else if (!same_cells(first, c->last.g)) {
      fprintf(stderr, "bench_grid: %s: run %d's cells differ from run 1's\n", setup, k + 1);
      ur_grid_free(first);
      return -1;
    }
  }
  if (runs > 1) {
    ur_grid_free(first); /* c->last holds the last run's grid, the same cells */
  } else {
    c->last.g = first;
  }
  /* the median run (the mean of the two middle ones for an even count), its CPU with it */
  size_t ix[64], lo = (size_t)(runs - 1) / 2, hi = (size_t)runs / 2;
  gsl_sort_index(ix, wall, 1, (size_t)runs);
  r->wall = 0.5 * (wall[ix[lo]] + wall[ix[hi]]);
  r->cpu = 0.5 * (cpu[ix[lo]] + cpu[ix[hi]]);
  r->wmin = wall[ix[0]];
  r->wmax = wall[ix[runs - 1]];
  r->q = c->last.g->q;
  r->impacts = c->last.g->nsimulated;
  r->cells = c->last.g->nrow * c->last.g->ncol;
  return 0;
}

static void report(const char* name, const result* r) {
  printf(
      "  %-10s %6.2f s wall (%.2f-%.2f; +%5.2f s set-up)  %5d cells  %4d impacts  %6.1f "
      "impacts/s  %5.1f ms CPU/impact  Q %.4f m^2\n",
      name, r->wall, r->wmin, r->wmax, r->setup, r->cells, r->impacts, r->impacts / r->wall,
      1e3 * r->cpu / (r->impacts ? r->impacts : 1), r->q);
}

/* every cell's results, for comparing two grids exactly */
static int same_cells(const urGrid* a, const urGrid* b) {
  if (a->nrow != b->nrow || a->ncol != b->ncol) return 0;
  for (int k = 0; k < a->nrow * a->ncol; k++) {
    const urCell *x = &a->cell[k], *y = &b->cell[k];
    if (x->status != y->status || x->contact != y->contact || x->p != y->p ||
        memcmp(x->val, y->val, sizeof x->val) || memcmp(x->pof, y->pof, sizeof x->pof)) {
      return 0;
    }
  }
  return 1;
}

int main(int argc, char** argv) {
  double step = 0.05;
  char* end;
  if (argc > 1) {
    step = strtod(argv[1], &end);
    if (end == argv[1] || *end || !(step > 0)) {
      fprintf(stderr, "bench_grid: step '%s': accepted a pitch in m > 0, e.g. 0.05\n", argv[1]);
      return 2;
    }
  }
  if (argc > 2) {
    long n = strtol(argv[2], &end, 10);
    if (end == argv[2] || *end || n < 1 || n > 64) {
      fprintf(stderr, "bench_grid: runs '%s': accepted a whole number 1..64\n", argv[2]);
      return 2;
    }
    runs = (int)n;
  }
  static uraCtx ctx;
  uraCtx* c = &ctx;
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  /* every grid computed: the 1-thread grid of B repeats the conditions of the 2-thread one, which
     recall (recall.c) would otherwise reuse; a case's model seen before is still reused
     (modelcache.c), so its set-up then costs nothing, and so does that of a model whose person
     was settled before (B after A: ur_impact_prepare takes the settled person) */
  if (!c->model || !c->out || ura_run_line(c, "set recall off")) {
    fprintf(stderr, "bench_grid: no model: %s\n", c->err);
    return 1;
  }
  long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
  double load[3] = {0, 0, 0};
  FILE* f = fopen("/proc/loadavg", "r");
  if (f) {
    if (fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    fclose(f);
  }
  int nt = ncpu >= 2 ? 2 : 1;
  printf(
      "bench_grid: grids of step %g m, %d worker threads, %ld CPUs online, load average "
      "%.2f %.2f %.2f; each grid's wall time the median of %d runs (range)\n",
      step, nt, ncpu, load[0], load[1], load[2], runs);

  /* zero-wind grids of A, B, C and the 10 m/s grid of B, face 0 */
  static const char* const names[] = {"A analytic", "B, 0 m/s", "C, 0 m/s", "B, 10 m/s"};
  static const char* const setups[] = {
      "set wind 0; set face 0; case A; set bag_model analytic", "set wind 0; set face 0; case B",
      "set wind 0; set face 0; case C", "set wind 10; set face 0; case B"};
  result r[4];
  urGrid* b0 = NULL; /* B at 0 m/s with nt threads, kept for the thread check */
  double zero = 0, imp = 0, wall = 0;
  for (int i = 0; i < 4; i++) {
    if (grid(c, setups[i], step, nt, &r[i])) return 1;
    report(names[i], &r[i]);
    if (i < 3) zero += r[i].wall;
    imp += r[i].impacts;
    wall += r[i].wall;
    if (i == 1) {
      b0 = c->last.g;
      c->last.g = NULL;
    }
  }
  printf(
      "  zero-wind grids of A (analytic bag), B, C: mean %.2f s wall; %.1f impacts per second "
      "over the four grids; issue 36's targets: B %.2f s and C %.2f s <= 0.3 s\n",
      zero / 3, imp / wall, r[1].wall, r[2].wall);

  /* case A's zero-wind grid with the membrane airbags, its default (issue 32: target 3 s with 2
     threads) */
  result mr;
  if (grid(c, "set wind 0; set face 0; case A", step, nt, &mr)) return 1;
  report("A membrane", &mr);
  printf(
      "  membrane bags: A's zero-wind grid %.2f s wall (target 3 s; issue 36's 1 s), %.1f ms CPU "
      "per impact against %.1f with the analytic bag\n",
      mr.wall, 1e3 * mr.cpu / (mr.impacts ? mr.impacts : 1),
      1e3 * r[0].cpu / (r[0].impacts ? r[0].impacts : 1));
  /* and with the faster wrinkling law (bag_wrinkle 1: LAW19's reduction, no Newton) */
  result wr;
  if (grid(c, "set wind 0; set face 0; case A; set bag_wrinkle 1", step, nt, &wr)) return 1;
  report("A wrinkle=1", &wr);
  printf(
      "  bag_wrinkle 1 (LAW19's reduction): %.2f s wall, %.1f ms CPU per impact, Q %.4f against "
      "%.4f m^2 with the relaxed law\n",
      wr.wall, 1e3 * wr.cpu / (wr.impacts ? wr.impacts : 1), wr.q, mr.q);
  if (ura_run_line(c, "set bag_wrinkle 0")) return 1;

  /* 1 -> 2 threads on the zero-wind grid of B: the speed-up, and the same cells */
  int rc = 0;
  if (nt < 2) {
    printf("  1 -> 2 threads: skipped (one CPU online)\n");
  } else {
    result one;
    if (grid(c, setups[1], step, 1, &one)) return 1;
    int same = same_cells(b0, c->last.g);
    printf("  1 -> 2 threads (B, 0 m/s): %.2f s -> %.2f s wall, speed-up %.2f; cells %s\n",
           one.wall, r[1].wall, one.wall / r[1].wall, same ? "identical" : "DIFFER");
    rc = !same;
  }
  ur_grid_free(b0);
  ura_last_free(c);
  ura_models_free(c);
  fclose(c->out);
  return rc;
}
