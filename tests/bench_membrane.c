/* bench_membrane.c: what the membrane airbag costs (issue 32): its mesh (nodes, triangles,
 * sub-steps per step, the inflation's relaxation steps and time), one fabric and gas force
 * evaluation on the inflated bag of case A (ur_mem_forces: microseconds per evaluation and
 * nanoseconds per triangle, best of several passes), and case A's impacts alone over the middle
 * of its zero-wind grid (the offsets of bench_impact) with the membrane bag and with the
 * analytic one: CPU per impact and per step, the membrane's share of both. The grid time of case
 * A with membrane bags on 2 threads is bench_grid's. One thread; the machine may be shared: the
 * load average is printed, the force evaluation takes the best pass.
 *   bench_membrane [-s SETTINGS]   (SETTINGS: commands run after 'case A', e.g. 'set bag_mesh 8') */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../src/app/ui/ui.h"

#define NEVAL 2000 /* force evaluations per pass */
#define NPASS 7

static double cpu(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static const char* settings = "";

typedef struct {
  double tsetup, cpu; /* set-up; the impacts' CPU */
  long steps;
  int runs;
} impacts;

/* case A's impacts alone over dpar -0.6..0.6, dperp 0..0.6 (0.1 m) where contact is possible,
   with the bag model given; the setup in *sp (its context static: the model stays alive) */
static int run_impacts(uraCtx* c, const char* bag, impacts* r, const urImpactSetup** sp) {
  char line[512];
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  snprintf(line, sizeof line, "case A; set bag_model %s; set wind 0; set face 0; %s", bag,
           settings);
  if (!c->out || ura_run_line(c, line)) {
    fprintf(stderr, "bench_membrane: '%s': %s\n", line, c->err);
    return -1;
  }
  double t0 = cpu();
  const urImpactSetup* s = ura_setup(c);
  r->tsetup = cpu() - t0;
  urImpactCond cond;
  urImpactWork w;
  if (!s || ura_impact_cond(c, &cond) || ur_impact_work_init(s, &w)) {
    fprintf(stderr, "bench_membrane: case A (%s): %s\n", bag, c->err);
    return -1;
  }
  r->cpu = 0;
  r->steps = 0;
  r->runs = 0;
  for (double dp = -0.6; dp <= 0.6 + 1e-9; dp += 0.1) {
    for (double dq = 0; dq <= 0.6 + 1e-9; dq += 0.1) {
      if (!ur_impact_may_contact(s, &cond, dp, dq)) continue;
      urImpactResult res;
      t0 = cpu();
      int rc = ur_impact_run(s, &w, &cond, &c->st.injury, dp, dq, &res);
      r->cpu += cpu() - t0;
      if (rc) {
        fprintf(stderr, "bench_membrane: (%g, %g) failed: %s\n", dp, dq, res.reason);
        ur_impact_work_free(&w);
        return -1;
      }
      r->steps += w.d->nstep;
      r->runs++;
    }
  }
  ur_impact_work_free(&w);
  *sp = s;
  return 0;
}

/* one bag's mesh and its force evaluation on the inflated state */
static int bag_report(const urModel* m, const urAirbag* b) {
  const urMembrane* mb = b->mem;
  printf(
      "  bag %s: %d nodes, %d triangles (mesh %d), %d mount nodes; stable step %.1f us: %d "
      "sub-steps of the %.0f us step (mass scaling: %.1f g added to %d triangles); inflation %d "
      "relaxation steps\n",
      b->name, mb->nn, mb->nt, mb->spec.mesh, mb->nfix, 1e6 * mb->dt_stable, b->nsub,
      1e6 * m->opt.dt, 1e3 * mb->madd, mb->nscaled, mb->inflate_steps);
  size_t n = ur_mem_state_size(mb);
  double* st = calloc(n, sizeof(double));
  double* f = malloc(3 * (size_t)mb->nn * sizeof(double));
  if (!st || !f) {
    free(st);
    free(f);
    return -1;
  }
  /* the inflated bag placed off the origin, moving and spinning (damping at work) */
  static const double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double c[3] = {0.1, -0.2, 1.9}, vc[3] = {0, 0, -7.5}, w[3] = {0.5, 1.0, 0.2};
  ur_mem_state_init(mb, st, R, c, vc, w);
  double best = 1e9, chk = 0;
  for (int p = 0; p < NPASS; p++) {
    double t0 = cpu();
    for (int k = 0; k < NEVAL; k++) {
      ur_mem_forces(mb, st, f, NULL);
      chk += f[3 * (k % mb->nn)];
    }
    double t = (cpu() - t0) / NEVAL;
    best = t < best ? t : best;
  }
  printf(
      "  bag %s: one force evaluation (fabric and gas) %.2f us, %.1f ns per triangle (best of "
      "%d x %d)%s\n",
      b->name, 1e6 * best, 1e9 * best / mb->nt, NPASS, NEVAL, chk == chk ? "" : " (NaN)");
  free(st);
  free(f);
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 2 && !strcmp(argv[1], "-s")) settings = argv[2];
  double load[3] = {0, 0, 0};
  FILE* lf = fopen("/proc/loadavg", "r");
  if (lf) {
    if (fscanf(lf, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    fclose(lf);
  }
  printf("bench_membrane: case A's membrane airbag, one thread, load average %.2f %.2f %.2f%s%s\n",
         load[0], load[1], load[2], *settings ? "; " : "", settings);
  static uraCtx cm, ca;
  impacts im, ia;
  const urImpactSetup *sm, *sa;
  if (run_impacts(&cm, "membrane", &im, &sm)) return 1;
  for (int i = 0; i < sm->m->nbag; i++) {
    const urAirbag* b = sm->m->bag + i;
    if (b->type == urBAG_MEMBRANE && b->mem && bag_report(sm->m, b)) return 1;
  }
  if (run_impacts(&ca, "analytic", &ia, &sa)) return 1;
  printf("  set-up (model, inflation, settled stance): membrane %.0f ms, analytic %.0f ms CPU\n",
         1e3 * im.tsetup, 1e3 * ia.tsetup);
  double pm = im.cpu / im.runs, pa = ia.cpu / ia.runs;
  double sm_us = 1e6 * im.cpu / im.steps, sa_us = 1e6 * ia.cpu / ia.steps;
  printf(
      "  %d impacts alone: membrane %.2f ms CPU per impact (%.0f steps of %.2f us), analytic "
      "%.2f ms (%.0f steps of %.2f us)\n",
      im.runs, 1e3 * pm, (double)im.steps / im.runs, sm_us, 1e3 * pa, (double)ia.steps / ia.runs,
      sa_us);
  printf(
      "  the membrane's cost: %.2f ms per impact, %.2f us per step over the analytic bag's "
      "(target: A's membrane grid <= 3 s on 2 threads, bench_grid)\n",
      1e3 * (pm - pa), sm_us - sa_us);
  ura_last_free(&cm);
  ura_models_free(&cm);
  ura_last_free(&ca);
  ura_models_free(&ca);
  return 0;
}
