/* bench_step.c: the engine's step against the machine's floating-point bound (issue 36). A small
 * AVX2 FMA kernel measures what one core of this machine sustains (GFLOP/s); the floating-point
 * work of one step of case B at Delta = 0 divided by it is the bound, the least time a step can
 * take. The impact of case B at zero wind, face 0, Delta = (0, 0) is then run alone (as the
 * impact command runs it) and four at a time in lock-step lanes (as grids run them), each timed
 * over NREP passes (median), and its time per step given as a multiple of the bound (issue 36's
 * targets: 8 alone, 5 in lanes). NREP further passes of each, timed stage by stage, give the
 * split (each stage's least time over the passes, as shares of the median step).
 * The stages of a step alone are timed by the step's own stage timer: this program links
 * engine_run.c built with urSTEP_PROF (Makefile) before the library, whose step has no timer.
 * The timed runs are checked bitwise against one another (the last state and step count).
 *   bench_step [CASE]     (default B)
 * The floating-point operations of a step are not counted here (the processor's counters are not
 * readable on every machine): KFLOP_STEP is the count of issue 36 (case B, Delta = 0, 46-52 kFLOP
 * a step, counted exactly). The machine may be shared: the load average is printed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include "../src/app/ui/ui.h"
#define urSTEP_PROF /* ur_step_prof: the step's stage timer, linked in by the Makefile */
#include "../src/core/engine/engine_internal.h"
#include "../src/core/impact/impact_internal.h"

#define NREP       5    /* timed passes of each kind */
#define KFLOP_STEP 49.0 /* floating-point operations of one step, thousands (issue 36) */
#define KFLOP_ABA  26.0 /* of them the articulated-body algorithm's (issue 36) */

static double cpu(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double median(double* x, int n) {
  gsl_sort(x, 1, n);
  return gsl_stats_median_from_sorted_data(x, 1, n);
}

//---------------------------------- the bound ------------------------------------------------------

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAVE_FMA 1

/* n rounds of 12 independent chains of 4-wide fused multiply-adds, each chain in a register of
   its own (enough to fill two FMA units of 4-5 cycles' latency): 96 floating-point operations a
   round */
__attribute__((target("avx2,fma"), noinline)) static double fma_kernel(long n, double x0) {
  __m256d x = _mm256_set1_pd(x0), y = _mm256_set1_pd(1e-6);
  __m256d a0 = _mm256_set1_pd(1.00), a1 = _mm256_set1_pd(1.01), a2 = _mm256_set1_pd(1.02);
  __m256d a3 = _mm256_set1_pd(1.03), a4 = _mm256_set1_pd(1.04), a5 = _mm256_set1_pd(1.05);
  __m256d a6 = _mm256_set1_pd(1.06), a7 = _mm256_set1_pd(1.07), a8 = _mm256_set1_pd(1.08);
  __m256d a9 = _mm256_set1_pd(1.09), a10 = _mm256_set1_pd(1.10), a11 = _mm256_set1_pd(1.11);
  for (long i = 0; i < n; i++) {
    a0 = _mm256_fmadd_pd(a0, x, y);
    a1 = _mm256_fmadd_pd(a1, x, y);
    a2 = _mm256_fmadd_pd(a2, x, y);
    a3 = _mm256_fmadd_pd(a3, x, y);
    a4 = _mm256_fmadd_pd(a4, x, y);
    a5 = _mm256_fmadd_pd(a5, x, y);
    a6 = _mm256_fmadd_pd(a6, x, y);
    a7 = _mm256_fmadd_pd(a7, x, y);
    a8 = _mm256_fmadd_pd(a8, x, y);
    a9 = _mm256_fmadd_pd(a9, x, y);
    a10 = _mm256_fmadd_pd(a10, x, y);
    a11 = _mm256_fmadd_pd(a11, x, y);
  }
  __m256d s = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(a0, a1), _mm256_add_pd(a2, a3)),
                            _mm256_add_pd(_mm256_add_pd(a4, a5), _mm256_add_pd(a6, a7)));
  s = _mm256_add_pd(s, _mm256_add_pd(_mm256_add_pd(a8, a9), _mm256_add_pd(a10, a11)));
  double r[4];
  _mm256_storeu_pd(r, s);
  return r[0] + r[1] + r[2] + r[3];
}

/* the same without fusion: 6 chains of 4-wide multiplies and 6 of 4-wide adds in their own
   registers (12 in flight fill both units), 48 floating-point operations a round. The step's
   code rounds every product (no contraction: its lanes and its runs alone agree bit for bit,
   and results must not change), so this rate, not the fused one, is what it can approach */
__attribute__((target("avx2"), noinline)) static double muladd_kernel(long n, double x0) {
  __m256d x = _mm256_set1_pd(x0), y = _mm256_set1_pd(1e-6);
  __m256d m0 = _mm256_set1_pd(1.00), m1 = _mm256_set1_pd(1.01), m2 = _mm256_set1_pd(1.02);
  __m256d m3 = _mm256_set1_pd(1.03), m4 = _mm256_set1_pd(1.04), m5 = _mm256_set1_pd(1.05);
  __m256d s0 = _mm256_set1_pd(1.06), s1 = _mm256_set1_pd(1.07), s2 = _mm256_set1_pd(1.08);
  __m256d s3 = _mm256_set1_pd(1.09), s4 = _mm256_set1_pd(1.10), s5 = _mm256_set1_pd(1.11);
  for (long i = 0; i < n; i++) {
    m0 = _mm256_mul_pd(m0, x);
    s0 = _mm256_add_pd(s0, y);
    m1 = _mm256_mul_pd(m1, x);
    s1 = _mm256_add_pd(s1, y);
    m2 = _mm256_mul_pd(m2, x);
    s2 = _mm256_add_pd(s2, y);
    m3 = _mm256_mul_pd(m3, x);
    s3 = _mm256_add_pd(s3, y);
    m4 = _mm256_mul_pd(m4, x);
    s4 = _mm256_add_pd(s4, y);
    m5 = _mm256_mul_pd(m5, x);
    s5 = _mm256_add_pd(s5, y);
  }
  __m256d s = _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(m0, m1), _mm256_add_pd(m2, m3)),
                            _mm256_add_pd(_mm256_add_pd(m4, m5), _mm256_add_pd(s0, s1)));
  s = _mm256_add_pd(s, _mm256_add_pd(_mm256_add_pd(s2, s3), _mm256_add_pd(s4, s5)));
  double r[4];
  _mm256_storeu_pd(r, s);
  return r[0] + r[1] + r[2] + r[3];
}
#else
#define HAVE_FMA 0
#endif

/* the best of NREP measures of the FMA kernel (fused 1) or of the multiply-add one (fused 0),
   GFLOP/s; 0 where there is no AVX2 FMA */
static double fma_peak(int fused) {
#if HAVE_FMA
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return 0;
  long n = 20000000; /* about 0.1 s */
  double best = 0, sink = 0;
  for (int r = 0; r < NREP; r++) {
    double t0 = cpu();
    sink += fused ? fma_kernel(n, 0.999999 + 1e-9 * r) : muladd_kernel(n, 0.999999 + 1e-9 * r);
    double g = (fused ? 96.0 : 48.0) * n / (cpu() - t0) * 1e-9;
    best = g > best ? g : best;
  }
  if (sink != sink) printf("(nan)\n");
  return best;
#else
  (void)fused;
  return 0;
#endif
}

//---------------------------------- stepping -------------------------------------------------------

/* the stages of a step alone, as ur_step's stage timer (urSTEP_PROF) times them */
static const char* const aname[urSTEP_NPROF] = {"kinematics, velocities",
                                                "restraint kinematics",
                                                "broad phase",
                                                "gravity compensation",
                                                "restraint forces",
                                                "narrow phase",
                                                "airbags",
                                                "articulated body alg.",
                                                "joint loads, sensors",
                                                "bookkeeping, update, end"};
static const char* const lname[urLANE_NPROF] = {"kinematics, velocities (vec)",
                                                "broad phase (vec)",
                                                "restraint kinematics (vec)",
                                                "copy back: kinematics",
                                                "applied forces (scalar)",
                                                "restraint forces (vec)",
                                                "copy: forces, accelerations",
                                                "articulated body alg. (vec)",
                                                "joint loads, sensors, hist.",
                                                "update (vec), copy back",
                                                "time, checks, end"};

/* the impact at (0, 0) alone by ur_step, as ur_impact_run does; with prof, its stages timed into
   prof by the step's own stage timer (this program links engine_run.c built with urSTEP_PROF).
   Returns the CPU seconds. */
static double run_alone(const urImpactSetup* s, urImpactWork* w, const urImpactCond* c,
                        unsigned long long* prof) {
  urImpactResult r;
  double texit, t0 = cpu();
  ur_impact_begin(s, w, c, 0, 0, &r, &texit);
  ur_step_prof(prof);
  while (w->d->status == urSTAT_OK) {
    ur_step(s->m, w->d);
    if (ur_impact_after_step(s, w, texit, NULL, &r)) break;
  }
  ur_step_prof(NULL);
  return cpu() - t0;
}

/* the impact at (0, 0) in all four lanes at once; the CPU seconds */
static double run_lanes(const urImpactSetup* s, urImpactWork* w, urLanes* L,
                        const urImpactCond* c) {
  urImpactResult r[urNLANE];
  urData* d[urNLANE];
  double texit[urNLANE], t0 = cpu();
  int n = urNLANE;
  for (int l = 0; l < n; l++) {
    ur_impact_begin(s, &w[l], c, 0, 0, &r[l], &texit[l]);
    d[l] = w[l].d;
  }
  while (n > 0) {
    ur_step_lanes(s->m, d, n, L);
    for (int l = 0; l < n;) {
      int i = 0;
      while (w[i].d != d[l]) i++;
      if (ur_impact_after_step(s, &w[i], texit[i], NULL, &r[i])) {
        d[l] = d[--n];
      } else {
        l++;
      }
    }
  }
  return cpu() - t0;
}

/* the same last state and step count */
static int same_run(const urModel* m, const urData* a, const urData* b) {
  return a->nstep == b->nstep && a->status == b->status &&
         !memcmp(a->qpos, b->qpos, (size_t)m->nq * sizeof(double)) &&
         !memcmp(a->qvel, b->qvel, (size_t)m->nv * sizeof(double));
}

static void split(const char* const* name, const unsigned long long* prof, int n, double us) {
  unsigned long long tot = 0;
  for (int k = 0; k < n; k++) tot += prof[k];
  for (int k = 0; k < n; k++) {
    double f = tot ? (double)prof[k] / tot : 0;
    printf("      %-30s %5.1f %%  %6.3f us\n", name[k], 100 * f, f * us);
  }
}

int main(int argc, char** argv) {
  const char* cs = argc > 1 ? argv[1] : "B";
  double load = -1;
  FILE* f = fopen("/proc/loadavg", "r");
  if (f) {
    if (fscanf(f, "%lf", &load) != 1) load = -1;
    fclose(f);
  }
  double peak = fma_peak(1), peak2 = fma_peak(0);
  double bound = peak > 0 ? KFLOP_STEP * 1e3 / (peak * 1e9) : 0;
  double bound2 = peak2 > 0 ? KFLOP_STEP * 1e3 / (peak2 * 1e9) : 0;
  printf("bench_step: load average %.2f; AVX2 FMA kernel: %.1f GFLOP/s on one core\n", load, peak);
  if (peak > 0) {
    printf("  bound: %.0f kFLOP a step (issue 36's count) / %.1f GFLOP/s = %.3f us a step\n",
           KFLOP_STEP, peak, 1e6 * bound);
    printf(
        "  unfused bound (multiplies and adds apart, %.1f GFLOP/s, as the step rounds every "
        "product): %.3f us\n",
        peak2, 1e6 * bound2);
  } else {
    printf("  bound: not measured (no AVX2 FMA on this processor)\n");
  }

  static uraCtx c;
  char line[256];
  ura_init(&c);
  snprintf(line, sizeof line, "case %s; set wind 0; set face 0", cs);
  if (ura_run_line(&c, line)) {
    fprintf(stderr, "bench_step: '%s': %s\n", line, c.err);
    return 1;
  }
  const urImpactSetup* s = ura_setup(&c);
  urImpactCond cond;
  if (!s || ura_impact_cond(&c, &cond)) {
    fprintf(stderr, "bench_step: case %s: %s\n", cs, c.err);
    return 1;
  }
  urImpactWork w[urNLANE + 1];
  for (int l = 0; l <= urNLANE; l++) {
    if (ur_impact_work_init(s, &w[l])) return 1;
  }
  urLanes L;
  if (ur_lanes_init(s->m, &L)) return 1;

  /* interleaved passes: alone, then lanes */
  double ta[NREP], tl[NREP];
  for (int r = 0; r < NREP; r++) {
    ta[r] = run_alone(s, &w[urNLANE], &cond, NULL);
    tl[r] = run_lanes(s, w, &L, &cond);
  }
  long nstep = w[urNLANE].d->nstep;
  int ok = 1;
  for (int l = 0; l < urNLANE; l++) ok &= same_run(s->m, w[l].d, w[urNLANE].d);
  double ua = median(ta, NREP) / nstep, ul = median(tl, NREP) / nstep / urNLANE;

  /* the split: NREP more passes of each, timed by stage; each stage's least time over the
     passes (a pass the scheduler interrupts inflates the stage it lands in) */
  unsigned long long pa[urSTEP_NPROF], pl[urLANE_NPROF];
  for (int k = 0; k < urSTEP_NPROF; k++) pa[k] = ~0ull;
  for (int k = 0; k < urLANE_NPROF; k++) pl[k] = ~0ull;
  urData* ref = ur_data_new(s->m);
  if (!ref) return 1;
  ur_data_copy(s->m, ref, w[urNLANE].d);
  for (int r = 0; r < NREP; r++) {
    unsigned long long qa[urSTEP_NPROF] = {0}, ql[urLANE_NPROF] = {0};
    run_alone(s, &w[urNLANE], &cond, qa);
    ok &= same_run(s->m, ref, w[urNLANE].d);
    L.prof = ql;
    run_lanes(s, w, &L, &cond);
    L.prof = NULL;
    ok &= same_run(s->m, ref, w[0].d);
    for (int k = 0; k < urSTEP_NPROF; k++) pa[k] = qa[k] < pa[k] ? qa[k] : pa[k];
    for (int k = 0; k < urLANE_NPROF; k++) pl[k] = ql[k] < pl[k] ? ql[k] : pl[k];
  }

  printf("  case %s at Delta = (0, 0), %ld steps of %.0e s; median of %d passes:\n", cs, nstep,
         s->m->opt.dt, NREP);
  printf("    alone:    %6.3f us a step", 1e6 * ua);
  if (bound > 0) printf(" = %4.1f x the bound (target 8)", ua / bound);
  printf("\n    in lanes: %6.3f us a step", 1e6 * ul);
  if (bound > 0) printf(" = %4.1f x the bound (target 5)", ul / bound);
  if (bound2 > 0) {
    printf("\n    against the unfused bound: alone %4.1f x, in lanes %4.1f x", ua / bound2,
           ul / bound2);
  }
  printf("\n    alone, by stage:\n");
  split(aname, pa, urSTEP_NPROF, 1e6 * ua);
  printf("    in lanes, by stage (per impact):\n");
  split(lname, pl, urLANE_NPROF, 1e6 * ul);
  {
    /* the vector ABA's rate: issue 36's count of the ABA's work (26 kFLOP a step) over its
       share of a step in lanes */
    unsigned long long tot = 0;
    for (int k = 0; k < urLANE_NPROF; k++) tot += pl[k];
    double us = tot ? 1e6 * ul * pl[urLANE_ABA] / tot : 0;
    if (us > 0 && peak2 > 0) {
      printf(
          "    vector ABA: %.0f kFLOP a run in %.3f us = %.1f GFLOP/s (%.0f %% of the unfused "
          "peak)\n",
          KFLOP_ABA, us, KFLOP_ABA / us, 100 * KFLOP_ABA / us / peak2);
    }
  }
  printf("  runs alone, in lanes and stage-timed: %s\n", ok ? "bitwise the same" : "DIFFER");

  ur_data_free(ref);
  ur_lanes_free(&L);
  for (int l = 0; l <= urNLANE; l++) ur_impact_work_free(&w[l]);
  return !ok;
}
