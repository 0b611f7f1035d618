/* cmd_converge.c: converge, the numerical-convergence evidence of the live grid: the grid at the
 * live step and at half of it (the change in Q, and the worst departure of a new half-step cell's
 * P from the coarse grid's interpolation, which locates the cell where P varies most), then the
 * impact at the centre and at that worst cell with the model's time step dt and with dt / 2 (the
 * change in P). Cells that both grids share are the same simulation, so their P must agree
 * exactly: a determinism check printed beside the rest. The live state is restored; the last
 * grid is the half-step one. Columns in uasimpact(1), converge. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../cmd.h"

/* the P of one impact of state ns at an offset (its own work space: the last impact is kept) */
static int one_impact(uraCtx* c, const uraState* ns, double dpar, double dperp, double* p) {
  if (ura_model_state(c, ns, "converge")) return -1;
  urImpactCond cond;
  const urImpactSetup* s = ura_setup(c);
  if (!s || ura_impact_cond(c, &cond)) return -1;
  urImpactWork w;
  urImpactResult r;
  if (ur_impact_work_init(s, &w)) {
    ur_impact_work_free(&w);
    return ura_fail(c, "converge: out of memory");
  }
  int rc = ur_impact_run(s, &w, &cond, &c->st.injury, dpar, dperp, &r);
  ur_impact_work_free(&w);
  if (rc) {
    return ura_fail(c, "converge: the impact at (%g, %g) m failed: %s", dpar, dperp, r.reason);
  }
  *p = r.p;
  return 0;
}

/* P of the coarse grid at an offset: the nearest node's if it is one, else the mean of the
   nodes around it (outside the grid: 0, no contact) */
static double coarse_p(const urGrid* g, const urCell* cells, double dpar, double dperp) {
  double h = g->step, sum = 0, eps = 1e-9 * h;
  int n = 0;
  for (int i = 0; i < g->nrow; i++) {
    double cp = g->par_max - i * h;
    if (fabs(cp - dpar) > 0.5 * h + eps) continue;
    for (int j = 0; j < g->ncol; j++) {
      double cq = g->perp_min + j * h;
      if (fabs(cq - dperp) > 0.5 * h + eps) continue;
      sum += cells[i * g->ncol + j].p;
      n++;
    }
  }
  return n ? sum / n : 0;
}

typedef struct {
  double q_h, q_h2;                                                /* Q at step and half step */
  double worst, worst_dpar, worst_dperp, worst_fine, worst_coarse; /* new cells */
  double mean_new; /* mean |P_fine - P_interp| over the new cells */
  int nnew, nshared;
  double shared_max;     /* max |dP| over shared cells (0: deterministic) */
  double dt, p_dt[2][2]; /* [centre, worst][dt, dt / 2] */
  int have_dt;
} conv;

static int run(uraCtx* c, const uraState* orig, uraState* ns, conv* v) {
  memset(v, 0, sizeof *v);
  *ns = *orig;
  if (ura_risk_grid(c, ns, "converge", 0, &v->q_h)) return -1;
  urGrid coarse = *c->last.g;
  size_t nc = (size_t)coarse.nrow * coarse.ncol;
  urCell* cells = malloc(nc * sizeof *cells);
  if (!cells) return ura_fail(c, "converge: out of memory");
  memcpy(cells, c->last.g->cell, nc * sizeof *cells);

  ns->step = orig->step / 2;
  int rc = ura_risk_grid(c, ns, "converge", 0, &v->q_h2);
  if (rc == 0) {
    urGrid* f = c->last.g;
    double h = coarse.step, eps = 1e-9 * h, sum = 0;
    for (int i = 0; i < f->nrow; i++) {
      for (int j = 0; j < f->ncol; j++) {
        const urCell* fc = &f->cell[i * f->ncol + j];
        double a = (coarse.par_max - fc->dpar) / h, b = (fc->dperp - coarse.perp_min) / h;
        int on = fabs(a - nearbyint(a)) < eps && fabs(b - nearbyint(b)) < eps;
        double pc = coarse_p(&coarse, cells, fc->dpar, fc->dperp), d = fabs(fc->p - pc);
        if (on) {
          v->nshared++;
          if (d > v->shared_max) v->shared_max = d;
          continue;
        }
        v->nnew++;
        sum += d;
        if (d > v->worst) {
          v->worst = d;
          v->worst_dpar = fc->dpar;
          v->worst_dperp = fc->dperp;
          v->worst_fine = fc->p;
          v->worst_coarse = pc;
        }
      }
    }
    v->mean_new = v->nnew ? sum / v->nnew : 0;
  }
  free(cells);
  if (rc) return -1;

  /* the time step: the model's dt and half of it, at the centre and the worst cell */
  const urModel* m = ura_model(c);
  int k = m ? ur_name_param(m, "dt") : -1;
  if (k < 0) return 0;
  v->dt = m->param[k].value;
  v->have_dt = 1;
  ns->step = orig->step;
  const double at[2][2] = {{0, 0}, {v->worst_dpar, v->worst_dperp}};
  for (int h = 0; h < 2; h++) {
    ura_risk_override(ns, "dt", h ? v->dt / 2 : v->dt, 1);
    for (int w = 0; w < 2; w++) {
      if (one_impact(c, ns, at[w][0], at[w][1], &v->p_dt[w][h])) return -1;
    }
  }
  return 0;
}

int ura_cmd_converge(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"check",  "what", "dpar",   "dperp",
                                     "coarse", "fine", "change", "rel_change"};
  if (ura_dry(c, "simulation")) return -1;
  uraState* orig = malloc(2 * sizeof *orig);
  if (!orig) return ura_fail(c, "converge: out of memory");
  *orig = c->st;
  conv v;
  int rc = run(c, orig, orig + 1, &v);
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  if (ura_model_state(c, orig, "converge") && rc == 0)
    rc = -1;
  else
    snprintf(c->err, sizeof c->err, "%s", err);
  double step = orig->step;
  free(orig);
  if (rc) return -1;

  uraTable* t = ura_table_new(8, cols);
  ura_table_note(t,
                 "convergence of case %s at wind %g m/s, face %g deg: the grid at step %g m "
                 "(coarse) and %g m (fine); Q = sum P step^2 (the paper's eq. 4.5)",
                 c->st.casename, c->st.descent.wind, c->st.face, step, step / 2);
  ura_table_note(t,
                 "step p_new: the fine grid's new cells against the coarse grid's interpolation "
                 "(the mean of the coarse nodes around them): the largest departure and where; "
                 "p_mean its mean over %d new cells; shared: the %d cells both grids hold must "
                 "agree exactly (the same simulation)",
                 v.nnew, v.nshared);
  if (v.have_dt) {
    ura_table_note(t,
                   "dt: the impact at the centre and at that cell with the model's time step %g s "
                   "(coarse) and %g s (fine), at step %g m's conditions",
                   v.dt, v.dt / 2, step);
  } else {
    ura_table_note(t, "dt: the model declares no parameter dt; the time step is not halved");
  }
  ura_table_cell(t, "step");
  ura_table_cell(t, "q");
  ura_table_cell(t, "-");
  ura_table_cell(t, "-");
  ura_table_cell(t, "%.6g", v.q_h);
  ura_table_cell(t, "%.6g", v.q_h2);
  ura_table_cell(t, "%.3g", v.q_h2 - v.q_h);
  ura_table_cell(t, "%.3g", v.q_h2 > 0 ? (v.q_h2 - v.q_h) / v.q_h2 : 0);
  ura_table_cell(t, "step");
  ura_table_cell(t, "p_new");
  ura_table_cell(t, "%g", v.worst_dpar);
  ura_table_cell(t, "%g", v.worst_dperp);
  ura_table_cell(t, "%.6g", v.worst_coarse);
  ura_table_cell(t, "%.6g", v.worst_fine);
  ura_table_cell(t, "%.3g", v.worst_fine - v.worst_coarse);
  ura_table_cell(t, "-");
  ura_table_cell(t, "step");
  ura_table_cell(t, "p_mean");
  for (int k = 0; k < 4; k++) ura_table_cell(t, "-");
  ura_table_cell(t, "%.3g", v.mean_new);
  ura_table_cell(t, "-");
  ura_table_cell(t, "step");
  ura_table_cell(t, "shared");
  for (int k = 0; k < 4; k++) ura_table_cell(t, "-");
  ura_table_cell(t, "%.3g", v.shared_max);
  ura_table_cell(t, "-");
  if (v.have_dt) {
    const char* what[2] = {"p_centre", "p_worst"};
    const double at[2][2] = {{0, 0}, {v.worst_dpar, v.worst_dperp}};
    for (int w = 0; w < 2; w++) {
      double a = v.p_dt[w][0], b = v.p_dt[w][1];
      ura_table_cell(t, "dt");
      ura_table_cell(t, "%s", what[w]);
      ura_table_cell(t, "%g", at[w][0]);
      ura_table_cell(t, "%g", at[w][1]);
      ura_table_cell(t, "%.6g", a);
      ura_table_cell(t, "%.6g", b);
      ura_table_cell(t, "%.3g", b - a);
      ura_table_cell(t, "%.3g", b > 0 ? (b - a) / b : 0);
    }
  }
  if (v.shared_max > 0) {
    ura_table_note(t, "warning: shared cells differ by up to %.3g: the grids are not repeatable",
                   v.shared_max);
  }
  ura_table_print(c, t);
  return 0;
}
