/* test_grid.c: lattice, Q sum, mirror rule, thread independence, interruption, failures, work
 * split over processes (urGridDist) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "uasimpact/grid.h"

/* a synthetic impact: p = 1 inside a disc of radius 0.3 m, a smooth field outside */
typedef struct {
  double r;
  int fail_row;            /* cells with this dpar (x100) fail */
  _Atomic int* stop_after; /* set *stop after this many cells */
  _Atomic int stop;
  long calls;
} synth;

static int may(void* ctx, double dpar, double dperp) {
  return hypot(dpar, dperp) <= 0.5 + 1e-12;
}

static int impact(void* ctx, int worker, urCell* c) {
  synth* s = ctx;
  long n = __atomic_add_fetch(&s->calls, 1, __ATOMIC_RELAXED);
  if (s->stop_after && n >= 5) s->stop = 1;
  if (s->fail_row && lround(c->dpar * 100) == s->fail_row) {
    strcpy(c->reason, "diverged");
    return -1;
  }
  double d = hypot(c->dpar, c->dperp);
  c->contact = 1;
  c->p = d <= s->r ? 1.0 : exp(-50 * (d - s->r)) * (0.5 + 0.1 * sin(40 * c->dperp * c->dperp));
  c->val[urVAL_HIC15] = 1000 * c->p;
  return 0;
}

static urGridSpec spec(synth* s, int mirror, int threads) {
  urGridSpec sp = {0.05, -0.7, 0.7, 0.75, mirror, threads, may, impact, NULL, s, NULL};
  return sp;
}

/* the paper's zero-wind lattice: 29 rows, 31 columns (16 printed + 15 mirrored) */
static void lattice(void** state) {
  synth s = {0.3};
  urGridSpec sp = spec(&s, 0, 1);
  assert_int_equal(ur_grid_cell_count(&sp), 29 * 31);
  urGrid* g = ur_grid_new(&sp);
  assert_int_equal(g->nrow, 29);
  assert_int_equal(g->ncol, 31);
  assert_true(fabs(ur_grid_at(g, 0, 0)->dpar - 0.7) < 1e-15);
  assert_true(fabs(ur_grid_at(g, 28, 30)->dperp - 0.75) < 1e-15);
  assert_true(ur_grid_at(g, 14, 15)->dpar == 0 && ur_grid_at(g, 14, 15)->dperp == 0);
  assert_ptr_equal(ur_grid_find(g, -0.1, 0.2), ur_grid_at(g, 16, 19));
  assert_null(ur_grid_find(g, 2.0, 0));
  ur_grid_free(g);

  /* extents are rounded outwards; bad specs are refused */
  sp.par_min = -1.58;
  sp.par_max = 0.73;
  g = ur_grid_new(&sp);
  assert_int_equal(g->nrow, 48);
  ur_grid_free(g);
  sp.step = 0;
  assert_null(ur_grid_new(&sp));
  assert_int_equal(ur_grid_cell_count(&sp), -1);
  sp.step = NAN;
  assert_null(ur_grid_new(&sp));
}

/* Q = sum p step^2: p = 1 on a disc gives the lattice count of the disc times step^2 */
static void q_sum(void** state) {
  synth s = {0.3};
  urGridSpec sp = spec(&s, 0, 1);
  urGrid* g = ur_grid_new(&sp);
  ur_grid_run(g, &sp);
  double q = 0;
  int inside = 0, white = 0;
  for (int k = 0; k < g->nrow * g->ncol; k++) {
    q += g->cell[k].p;
    if (hypot(g->cell[k].dpar, g->cell[k].dperp) <= 0.3) inside++;
    if (g->cell[k].status == urCELL_NOCONTACT) white++;
  }
  assert_true(fabs(g->q - q * 0.0025) < 1e-15);
  assert_true(g->q > inside * 0.0025);
  assert_true(fabs(inside * 0.0025 - M_PI * 0.09) < 0.02);
  assert_true(g->complete);
  assert_int_equal(g->ndone, g->nrow * g->ncol);
  assert_int_equal(g->nsimulated + white, g->nrow * g->ncol);
  ur_grid_free(g);
}

/* mirror rule gives the same cells and Q as simulating the whole plane, with fewer impacts */
static void mirror(void** state) {
  synth a = {0.3}, b = {0.3};
  urGridSpec sa = spec(&a, 0, 1), sb = spec(&b, 1, 1);
  urGrid *ga = ur_grid_new(&sa), *gb = ur_grid_new(&sb);
  ur_grid_run(ga, &sa);
  ur_grid_run(gb, &sb);
  assert_true(b.calls < a.calls * 0.6);
  for (int k = 0; k < ga->nrow * ga->ncol; k++) {
    assert_true(ga->cell[k].p == gb->cell[k].p);
    assert_true(ga->cell[k].dperp == gb->cell[k].dperp);
  }
  assert_true(ga->q == gb->q);
  ur_grid_free(ga);
  ur_grid_free(gb);
}

/* one thread and two threads give bitwise identical cells */
static void threads(void** state) {
  synth a = {0.3}, b = {0.3};
  urGridSpec sa = spec(&a, 1, 1), sb = spec(&b, 1, 2);
  urGrid *ga = ur_grid_new(&sa), *gb = ur_grid_new(&sb);
  ur_grid_run(ga, &sa);
  ur_grid_run(gb, &sb);
  assert_memory_equal(ga->cell, gb->cell, sizeof(urCell) * ga->nrow * ga->ncol);
  assert_true(ga->q == gb->q);
  ur_grid_free(ga);
  ur_grid_free(gb);
}

/* a stop request keeps finished cells, leaves the rest pending, and the grid is not complete */
static void interrupted(void** state) {
  synth s = {0.3};
  s.stop_after = &s.stop;
  urGridSpec sp = spec(&s, 0, 2);
  sp.stop = &s.stop;
  urGrid* g = ur_grid_new(&sp);
  ur_grid_run(g, &sp);
  assert_false(g->complete);
  assert_true(g->npending > 0);
  assert_true(g->nsimulated >= 5 && g->nsimulated <= 7);
  ur_grid_free(g);
}

/* failed cells are counted with their reason and the grid is not complete */
static void failures(void** state) {
  synth s = {0.3};
  s.fail_row = 10;
  urGridSpec sp = spec(&s, 1, 2);
  urGrid* g = ur_grid_new(&sp);
  ur_grid_run(g, &sp);
  assert_false(g->complete);
  assert_true(g->nfailed > 0);
  urCell* c = ur_grid_find(g, 0.1, 0.0);
  assert_int_equal(c->status, urCELL_FAILED);
  assert_string_equal(c->reason, "diverged");
  ur_grid_free(g);
}

/* a distributor of one of two "processes": this one simulates the positions of its parity and
   takes the other ones from the cells the other process kept (by position) */
typedef struct {
  int parity;
  long ntodo, next;
  urCell* kept;        /* by position: the cells of this process (kept for the other) */
  const urCell* other; /* the other process's kept cells (NULL: placeholders) */
  int fail_begin, fail_end;
  long handed;
} half;

static int h_begin(void* ctx, long ntodo) {
  half* h = ctx;
  h->ntodo = ntodo;
  h->next = h->parity;
  return h->fail_begin ? -1 : 0;
}

static long h_next(void* ctx) {
  half* h = ctx;
  long k = __atomic_fetch_add(&h->next, 2, __ATOMIC_RELAXED);
  if (k >= h->ntodo) return -1;
  __atomic_add_fetch(&h->handed, 1, __ATOMIC_RELAXED);
  return k;
}

static int h_end(void* ctx, urGrid* g, const long* todo, long ntodo) {
  half* h = ctx;
  for (long k = 0; k < ntodo; k++) {
    urCell* c = &g->cell[todo[k]];
    if (k % 2 == h->parity) {
      h->kept[k] = *c;
    } else if (h->other) {
      double dpar = c->dpar, dperp = c->dperp;
      *c = h->other[k];
      c->dpar = dpar;
      c->dperp = dperp;
    } else {
      c->status = urCELL_DONE; /* a placeholder, as a shard leaves it */
    }
  }
  return h->fail_end ? -1 : 0;
}

/* two halves, the second filled from the first, give the cells of one process bitwise; each
   simulates only its half; a failing distributor makes the run return -2 */
static void distributed(void** state) {
  synth a = {0.3}, b = {0.3}, c = {0.3};
  urGridSpec sa = spec(&a, 1, 2), sb = spec(&b, 1, 1), sc = spec(&c, 1, 2);
  urGrid *ga = ur_grid_new(&sa), *gb = ur_grid_new(&sb), *gc = ur_grid_new(&sc);
  long n = (long)ga->nrow * ga->ncol;
  urCell* kept_b = calloc(n, sizeof *kept_b);
  urCell* kept_c = calloc(n, sizeof *kept_c);
  half hb = {1, 0, 0, kept_b, NULL}, hc = {0, 0, 0, kept_c, kept_b};
  urGridDist db = {&hb, h_begin, h_next, h_end}, dc = {&hc, h_begin, h_next, h_end};
  sb.dist = &db;
  sc.dist = &dc;
  assert_int_equal(ur_grid_run(ga, &sa), 0);
  assert_int_equal(ur_grid_run(gb, &sb), 0);
  assert_int_equal(ur_grid_run(gc, &sc), 0);
  assert_int_equal(hb.ntodo, hc.ntodo);
  assert_int_equal(hb.handed, hb.ntodo / 2);
  assert_int_equal(hc.handed, (hc.ntodo + 1) / 2);
  assert_int_equal(b.calls + c.calls, a.calls);
  assert_memory_equal(ga->cell, gc->cell, sizeof(urCell) * n);
  assert_true(ga->q == gc->q);
  assert_true(gb->complete && gb->q < ga->q); /* placeholders: no contact, no Q */

  hb.fail_begin = 1;
  assert_int_equal(ur_grid_run(gb, &sb), -2);
  hb.fail_begin = 0;
  hb.fail_end = 1;
  assert_int_equal(ur_grid_run(gb, &sb), -2);
  free(kept_b);
  free(kept_c);
  ur_grid_free(ga);
  ur_grid_free(gb);
  ur_grid_free(gc);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(lattice),     cmocka_unit_test(q_sum),       cmocka_unit_test(mirror),
      cmocka_unit_test(threads),     cmocka_unit_test(interrupted), cmocka_unit_test(failures),
      cmocka_unit_test(distributed),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
