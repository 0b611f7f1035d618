/* test_recall.c: grid recall (src/app/case/recall.c) through the workbench context: every injury
 * setting is part of what a recalled grid must match; the recalled grid is a copy (changing or
 * freeing the last grid leaves the kept one intact); a recalled grid's cells can be inspected
 * (the impact run again gives the same numbers); at most uraRECALLGRIDS grids are kept, the least
 * recently used freed first. (tests/test_recall.sh: the commands and their output.) */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "../../test_ctx.h"

static void run(uraCtx* c, const char* line) {
  run_rc(c, line, 0);
}

/* one grid: 1 if it was recalled */
static int grid(uraCtx* c) {
  run(c, "grid");
  assert_non_null(c->last.g);
  assert_true(c->last.g->complete);
  return c->last.recalled;
}

/* each injury setting changed alone computes; put back, the grid is recalled */
static void injury_settings(void** state) {
  uraCtx* c = *state;
  run(c, "set step 1; case C");
  assert_false(grid(c));
  assert_true(grid(c));
  const char* name;
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) {
    double v, lo, hi, w;
    int open_lo, isint;
    ur_injury_param_get(&c->st.injury, name, &v);
    ur_injury_param_range(i, &lo, &hi, &open_lo, &isint);
    if (isint)
      w = v < hi ? v + 1 : v - 1;
    else
      w = v < hi ? v + 0.01 * (hi - v) : v - 0.01 * (v - lo);
    assert_int_equal(ur_injury_param_set(&c->st.injury, name, w), 0);
    if (grid(c)) fail_msg("recalled although %s changed from %g to %g", name, v, w);
    assert_int_equal(ur_injury_param_set(&c->st.injury, name, v), 0);
    assert_true(grid(c));
  }
}

/* the kept grid is not the last grid: changing or freeing that one does not reach it */
static void copies(void** state) {
  uraCtx* c = *state;
  run(c, "set step 0.5; case C");
  assert_false(grid(c));
  double q = c->last.g->q;
  int n = c->last.g->nrow * c->last.g->ncol;
  for (int k = 0; k < n; k++) c->last.g->cell[k].p = 0.5;
  ura_last_free(c);
  assert_true(grid(c));
  assert_memory_equal(&c->last.g->q, &q, sizeof q);
}

/* run the impacts of three simulated cells of the last grid again: the same numbers */
static void inspect_cells(uraCtx* c) {
  urGrid* g = c->last.g;
  int tried = 0;
  for (int k = 0; k < g->nrow * g->ncol && tried < 3; k++) {
    urCell cell = g->cell[k];
    if (cell.status != urCELL_DONE || cell.mirrored || !cell.contact || cell.p <= 0) continue;
    uraTrace tr;
    assert_int_equal(ura_inspect_cell(c, &g->cell[k], &tr), 0);
    assert_true(tr.n > 10 && tr.nsig > 6);
    assert_memory_equal(&c->last_impact.p, &cell.p, sizeof cell.p);
    assert_memory_equal(&c->last_impact.inj.hic15.hic, &cell.val[urVAL_HIC15], sizeof(double));
    tried++;
  }
  assert_int_equal(tried, 3);
  run(c, "history");
}

/* Enter in the viewer on a recalled grid: the impact is run again and gives the cell's numbers,
   with the model kept from before the switch, and with one compiled and settled anew */
static void inspect(void** state) {
  uraCtx* c = *state;
  run(c, "set step 0.2; case C");
  assert_false(grid(c));
  run(c, "case B; case C");
  assert_true(c->have_setup);
  assert_true(grid(c));
  inspect_cells(c);
  ura_model_stale(c);
  assert_true(grid(c));
  assert_false(c->have_setup);
  inspect_cells(c);
}

/* uraRECALLGRIDS + 1 grids: the first is freed; computed again, it frees the second */
static void bound(void** state) {
  uraCtx* c = *state;
  char line[64];
  run(c, "set step 1; case C");
  for (int i = 0; i <= uraRECALLGRIDS; i++) {
    snprintf(line, sizeof line, "set speed %d", 10 + i);
    run(c, line);
    assert_false(grid(c));
  }
  run(c, "set speed 10");
  assert_false(grid(c));
  run(c, "set speed 12");
  assert_true(grid(c));
  run(c, "set speed 11");
  assert_false(grid(c));
  snprintf(line, sizeof line, "set speed %d", 10 + uraRECALLGRIDS);
  run(c, line);
  assert_true(grid(c));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(injury_settings, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(copies, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(inspect, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(bound, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
