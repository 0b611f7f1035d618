/* test_impact_lanes.c: many impacts in lock-step lanes (ur_impact_run_many) give, offset by
 * offset, the bytes of ur_impact_run: the whole result (criteria, P, reason) and the recorded
 * histories, on the built-in cases A and C at zero wind and B at 10 m/s (oblique path), over a
 * lattice that mixes contact cells, grazing cells and cells the drone passes by; with coarse
 * steps (adapt 4, the default: each lane its own step; none starts in contact) and without.
 * Every offset taken is handed back exactly once with its tag; fewer offsets than lanes, and
 * none, work. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../test_ctx.h"

#define MAXOFF 400

/* the offsets, and what ur_impact_run gave for each */
typedef struct {
  int n, next, ndone;
  double off[MAXOFF][2];
  int seen[MAXOFF];
  int rc[MAXOFF];
  urImpactResult r[MAXOFF];
  double* hist[MAXOFF];
  int nhist[MAXOFF];
  int stride;
  int contact;
  long coarse, touch; /* coarse steps of the lanes' runs; of them, started in contact */
} feed;

static int next(void* ctx, double* dpar, double* dperp, void** tag) {
  feed* f = ctx;
  if (f->next >= f->n) return 0;
  *dpar = f->off[f->next][0];
  *dperp = f->off[f->next][1];
  *tag = (void*)(f->off[f->next]);
  f->next++;
  return 1;
}

static void done(void* ctx, void* tag, int rc, const urImpactResult* r, const urImpactWork* w) {
  feed* f = ctx;
  int k = (int)(((double(*)[2])tag) - f->off);
  assert_true(k >= 0 && k < f->n);
  assert_int_equal(f->seen[k], 0);
  f->seen[k] = 1;
  f->ndone++;
  assert_int_equal(rc, f->rc[k]);
  if (memcmp(r, &f->r[k], sizeof *r)) {
    fail_msg("offset (%g, %g): the result differs from ur_impact_run's (p %.17g vs %.17g)",
             f->off[k][0], f->off[k][1], r->p, f->r[k].p);
  }
  assert_int_equal(w->d->nhist, f->nhist[k]);
  assert_int_equal(memcmp(w->d->hist, f->hist[k], (size_t)f->nhist[k] * f->stride * sizeof(double)),
                   0);
  f->contact += r->contact;
  f->coarse += w->d->ncoarse;
  f->touch += w->d->ntouch;
}

/* run the case's lattice both ways and compare */
static void compare(uraCtx* c, const char* setup, double step, double par_lo, double par_hi,
                    int nmax) {
  run_rc(c, setup, 0);
  const urImpactSetup* s = ura_setup(c);
  assert_non_null(s);
  urImpactCond cond;
  assert_int_equal(ura_impact_cond(c, &cond), 0);

  static feed f;
  memset(&f, 0, sizeof f);
  f.stride = 1 + s->m->nsensordata;
  urImpactWork w;
  assert_int_equal(ur_impact_work_init(s, &w), 0);
  for (double a = par_lo; a <= par_hi + 1e-9 && f.n < nmax; a += step) {
    for (double b = 0; b <= 0.45 + 1e-9 && f.n < nmax; b += step) {
      int k = f.n++;
      f.off[k][0] = a;
      f.off[k][1] = b;
      f.rc[k] = ur_impact_run(s, &w, &cond, &c->st.injury, a, b, &f.r[k]);
      f.nhist[k] = w.d->nhist;
      size_t bytes = (size_t)w.d->nhist * f.stride * sizeof(double);
      f.hist[k] = malloc(bytes ? bytes : 1);
      memcpy(f.hist[k], w.d->hist, bytes);
    }
  }
  ur_impact_work_free(&w);

  urImpactLanes* L = ur_impact_lanes_new(s);
  assert_non_null(L);
  ur_impact_run_many(s, L, &cond, &c->st.injury, next, done, &f);
  assert_int_equal(f.ndone, f.n);
  print_message("%s: %d offsets, %d with contact, %ld coarse steps, the same bytes in lanes\n",
                setup, f.n, f.contact, f.coarse);
  assert_int_equal(f.touch, 0);
  assert_true(strstr(setup, "adapt 1") ? f.coarse == 0 : f.n < 10 || f.coarse > 0);
  assert_true(f.contact > 0);
  assert_true(f.n < 10 || f.contact < f.n); /* lattices: both kinds of cell */

  /* none left to run: done is never called */
  f.ndone = 0;
  ur_impact_run_many(s, L, &cond, &c->st.injury, next, done, &f);
  assert_int_equal(f.ndone, 0);

  ur_impact_lanes_free(L);
  for (int k = 0; k < f.n; k++) free(f.hist[k]);
}

/* with the analytic bag (its per-run airbag code in lanes): the membrane bag's lanes are
   test_membrane_engine.c's, and over this lattice it costs ~6 s CPU (A's default at the switch) */
static void lanes_case_a(void** state) {
  compare(*state, "case A; set bag_model analytic", 0.15, -0.6, 0.6, MAXOFF);
}

static void lanes_case_c(void** state) {
  compare(*state, "case C", 0.15, -0.6, 0.6, MAXOFF);
}

static void lanes_case_b_wind(void** state) {
  compare(*state, "case B; set wind 10", 0.2, -1.8, 0.6, MAXOFF);
}

/* every step dt (adapt 1; the lattices above take coarse steps, adapt 4 being the default):
   B at zero wind and at 10 m/s */
static void lanes_fine(void** state) {
  compare(*state, "case B; set adapt 1", 0.15, -0.6, 0.6, MAXOFF);
  compare(*state, "case B; set wind 10; set adapt 1", 0.2, -1.8, 0.6, MAXOFF);
}

/* fewer offsets than lanes */
static void lanes_few(void** state) {
  compare(*state, "case B", 0.15, -0.15, 0.0, 3);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(lanes_case_a, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lanes_case_c, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lanes_case_b_wind, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lanes_few, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(lanes_fine, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
