/* cmd_sweep.c: sweeps of the grid over wind or face direction, and the paper's comparison of Q
 * with P{F|Delta=(0,0)} x gliding area (Tables 11-13) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "app.h"

int ura_cmd_sweep(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case", "wind", "face", "speed", "angle", "q"};
  int is_wind = !strcmp(argv[1], "wind"), is_face = !strcmp(argv[1], "face");
  double v[uraMAXLIST];
  if (!is_wind && !is_face) {
    return ura_fail(c, "sweep: unknown '%s'; accepted: sweep wind LIST, sweep face LIST", argv[1]);
  }
  int n = ura_parse_list(argv[2], v, uraMAXLIST);
  const uraParam* p = ura_param_find(is_wind ? "wind" : "face");
  for (int i = 0; i < n; i++) {
    if (v[i] < p->min || v[i] > p->max) n = -1;
  }
  if (n < 0) {
    return ura_fail(c, "sweep %s: '%s' is not accepted; accepted: comma-separated numbers in "
                    "[%g, %g] %s", argv[1], argv[2], p->min, p->max, p->unit);
  }

  /* one grid per value; the live wind or face is restored afterwards */
  double keep = is_wind ? c->st.descent.wind : c->st.face;
  uraTable* t = ura_table_new(6, cols);
  int rc = 0;
  for (int i = 0; i < n && rc == 0; i++) {
    if (is_wind) c->st.descent.wind = v[i];
    else c->st.face = v[i];
    rc = ura_grid_run(c, 0);
    if (rc && ura_interrupted()) {
      char why[uraERRLEN];
      snprintf(why, sizeof why, "%s", c->err);
      ura_fail(c, "sweep: interrupted (Ctrl-C) at %s %g; %d of %d grids finished (%.900s)",
               argv[1], v[i], i, n, why);
    }
    if (rc == 0 && !c->last.g->complete) {
      rc = ura_fail(c, "sweep: %d cells failed at %s %g; Q is not complete",
                    c->last.g->nfailed, argv[1], v[i]);
    }
    if (rc == 0) {
      ura_table_cell(t, "%s", c->st.casename);
      ura_table_cell(t, "%g", c->st.descent.wind);
      ura_table_cell(t, "%g", c->st.face);
      ura_table_cell(t, "%.3f", c->last.speed);
      ura_table_cell(t, "%.2f", c->last.angle);
      ura_table_cell(t, "%.4f", c->last.g->q);
    }
  }
  if (is_wind) c->st.descent.wind = keep;
  else c->st.face = keep;
  ura_table_print(c, t);
  return rc;
}

int ura_cmd_compare(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case", "wind", "p_centre", "gliding", "q_parametric", "q",
                                     "factor"};
  urImpactCond cond;
  const urImpactSetup* s = ura_setup(c);
  if (!s || ura_impact_cond(c, &cond)) return -1;

  /* P{F|Delta=(0,0)}, the gliding area at this descent, and the grid's Q */
  if (!c->have_work) {
    if (ur_impact_work_init(s, &c->work)) return ura_fail(c, "compare: out of memory");
    c->have_work = 1;
  }
  urImpactResult r;
  if (ur_impact_run(s, &c->work, &cond, &c->st.injury, 0, 0, &r)) {
    if (r.status == urSTAT_STOPPED) return ura_fail(c, "compare: interrupted (Ctrl-C)");
    return ura_fail(c, "compare: the impact at (0, 0) failed: %s", r.reason);
  }
  c->have_impact = 1;
  c->last_impact = r;
  c->last_dpar = c->last_dperp = 0;
  urParametricResult q;
  ur_parametric(&c->st.para, c->st.descent.mass, cond.speed, cond.angle, &q);
  if (ura_grid_run(c, 0)) return -1;
  if (!c->last.g->complete) {
    return ura_fail(c, "compare: the grid has %d failed and %d pending cells; Q is not complete",
                    c->last.g->nfailed, c->last.g->npending);
  }

  uraTable* t = ura_table_new(7, cols);
  ura_table_note(t, "paper Tables 11-13: P{F|Delta=(0,0)} x gliding area (eq. D.1) against the "
                 "dynamical Q, and the reduction factor between them");
  ura_table_cell(t, "%s", c->st.casename);
  ura_table_cell(t, "%g", c->st.descent.wind);
  ura_table_cell(t, "%.4f", r.p);
  ura_table_cell(t, "%.3f", q.gliding);
  ura_table_cell(t, "%.4f", r.p * q.gliding);
  ura_table_cell(t, "%.4f", c->last.g->q);
  ura_table_cell(t, "%.2f", c->last.g->q > 0 ? r.p * q.gliding / c->last.g->q : NAN);
  ura_table_print(c, t);
  return 0;
}
