/* bench_impact.c: CPU time of one RA3-on-human impact with the built-in models, per case, over
 * the cells of a zero-wind grid (steps per impact, time per step, time per impact): each impact
 * alone (ur_impact_run, as the impact command runs it), and the same impacts four at a time in
 * lock-step lanes (ur_impact_run_many, as grids run them; five passes, the best and the median
 * given); the one-time model set-up (compile, balance, settle) is timed separately.
 *   bench_impact [-s SETTINGS] [CASE...]   (default A B C; SETTINGS: commands run after 'case',
 *                                            e.g. -s 'set wind 10; set t_clear 0.01') */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include "../src/app/ui/ui.h"

#define NREP 5 /* passes in lanes */

static double cpu(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static const char* settings = "";

/* the offsets of the quadrant for ur_impact_run_many: those where contact is possible */
typedef struct {
  double dp, dq;
  int ndone, failed;
  long steps;
  const urImpactSetup* s;
  const urImpactCond* cond;
} lanesFeed;

static int lanes_next(void* ctx, double* dpar, double* dperp, void** tag) {
  lanesFeed* f = ctx;
  (void)tag;
  for (;;) {
    if (f->dq > 0.6 + 1e-9) {
      f->dq = 0;
      f->dp += 0.1;
    }
    if (f->dp > 0.6 + 1e-9) return 0;
    double a = f->dp, b = f->dq;
    f->dq += 0.1;
    if (ur_impact_may_contact(f->s, f->cond, a, b)) {
      *dpar = a;
      *dperp = b;
      return 1;
    }
  }
}

static void lanes_done(void* ctx, void* tag, int rc, const urImpactResult* r,
                       const urImpactWork* w) {
  lanesFeed* f = ctx;
  (void)tag;
  (void)r;
  f->ndone++;
  f->failed += rc != 0;
  f->steps += w->d->nstep;
}

static int bench(const char* cs) {
  static uraCtx c;
  char line[512];
  ura_init(&c);
  snprintf(line, sizeof line, "case %s; %s", cs, settings);
  if (ura_run_line(&c, line)) return 1;
  double t0 = cpu();
  const urImpactSetup* s = ura_setup(&c);
  double tsetup = cpu() - t0;
  urImpactCond cond;
  if (!s || ura_impact_cond(&c, &cond)) return 1;
  urImpactWork w;
  if (ur_impact_work_init(s, &w)) return 1;

  /* the offsets 0.1 m apart over -0.6..0.6 x 0..0.6 m (the middle of the grid, where impacts
     last longest) where contact is possible */
  double tot = 0, worst = 0;
  long steps = 0;
  int runs = 0;
  for (double dp = -0.6; dp <= 0.6 + 1e-9; dp += 0.1) {
    for (double dq = 0; dq <= 0.6 + 1e-9; dq += 0.1) {
      if (!ur_impact_may_contact(s, &cond, dp, dq)) continue;
      urImpactResult r;
      t0 = cpu();
      int rc = ur_impact_run(s, &w, &cond, &c.st.injury, dp, dq, &r);
      double dt = cpu() - t0;
      if (rc) {
        fprintf(stderr, "bench_impact: case %s (%g, %g) failed: %s\n", cs, dp, dq, r.reason);
        return 1;
      }
      tot += dt;
      worst = dt > worst ? dt : worst;
      steps += w.d->nstep;
      if (getenv("BENCH_VERBOSE")) {
        printf("    %5.2f %5.2f  steps %4ld  contact %6.4f..%6.4f end %6.4f  %s\n", dp, dq,
               w.d->nstep, w.d->t_first - w.d->t_jump, w.d->t_last - w.d->t_jump,
               w.d->time - w.d->t_jump, ur_status_str(w.d->status));
      }
      runs++;
    }
  }
  printf(
      "  case %-2s set-up %6.0f ms; %3d impacts alone: mean %5.2f ms CPU (worst %5.2f), "
      "%4.0f steps of %5.2f us (dt %.0e s)\n",
      cs, 1e3 * tsetup, runs, 1e3 * tot / runs, 1e3 * worst, (double)steps / runs,
      1e6 * tot / steps, s->m->opt.dt);
  ur_impact_work_free(&w);

  /* the same offsets in lanes, NREP times: this machine's speed varies from run to run, so the
     best and the median pass are given */
  urImpactLanes* L = ur_impact_lanes_new(s);
  if (!L) return 1;
  double tl[NREP];
  for (int k = 0; k < NREP; k++) {
    lanesFeed f = {-0.6, 0, 0, 0, 0, s, &cond};
    t0 = cpu();
    ur_impact_run_many(s, L, &cond, &c.st.injury, lanes_next, lanes_done, &f);
    tl[k] = cpu() - t0;
    if (f.failed || f.ndone != runs || f.steps != steps) {
      fprintf(stderr,
              "bench_impact: case %s: the lanes ran %d impacts (%d failed), %ld steps; "
              "alone %d, %ld\n",
              cs, f.ndone, f.failed, f.steps, runs, steps);
      ur_impact_lanes_free(L);
      return 1;
    }
  }
  ur_impact_lanes_free(L);
  gsl_sort(tl, 1, NREP);
  double best = tl[0], med = gsl_stats_median_from_sorted_data(tl, 1, NREP);
  printf(
      "  case %-2s %22s%3d impacts in lanes: %5.2f ms CPU per impact (best of %d; median "
      "%5.2f), %5.2f us per step (x%.2f)\n",
      cs, "", runs, 1e3 * best / runs, NREP, 1e3 * med / runs, 1e6 * best / steps, tot / med);
  return 0;
}

int main(int argc, char** argv) {
  static const char* const dflt[] = {"A", "B", "C"};
  if (argc > 2 && !strcmp(argv[1], "-s")) {
    settings = argv[2];
    argc -= 2;
    argv += 2;
  }
  int n = argc > 1 ? argc - 1 : 3;
  printf("bench_impact: built-in RA3 on the standing human, %s (one thread)\n",
         *settings ? settings : "zero wind, face 0");
  for (int i = 0; i < n; i++) {
    if (bench(argc > 1 ? argv[i + 1] : dflt[i])) return 1;
  }
  printf("  target: <= 5 ms CPU per impact\n");
  return 0;
}
