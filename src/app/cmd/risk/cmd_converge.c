/* cmd_converge.c: converge, the numerical-convergence evidence of the live grid: the grid at the
 * live step and at half of it (the change in Q, and the worst departure of a new half-step cell's
 * P from the coarse grid's interpolation, which locates the cell where P varies most), then the
 * impact at the centre and at that worst cell with the model's time step dt and with dt / 2 (the
 * change in P), and with a membrane airbag the grid again at twice its mesh (bag_mesh; the change
 * in Q, the cell that moved most). Cells that both grids share are the same simulation, so their P must agree
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
  /* a membrane bag's mesh (parameter bag_mesh) and twice it: Q, and the cell that moved most */
  double mesh, q_mesh, mworst, mworst_dpar, mworst_dperp, mworst_coarse, mworst_fine;
  int have_mesh; /* 1 refined; 0 no membrane bag in the case; -1 no parameter bag_mesh */
} conv;

/* 1 if the live model has a membrane airbag and a parameter bag_mesh (its index in *k), 0
   without a membrane bag, -1 with one but no bag_mesh */
static int membrane_mesh(const urModel* m, int* k) {
  *k = m ? ur_name_param(m, "bag_mesh") : -1;
  for (int b = 0; m && b < m->nbag; b++) {
    if (m->bag[b].type == urBAG_MEMBRANE) return *k >= 0 ? 1 : -1;
  }
  return 0;
}

/* the grid again at twice the mesh (same step, same dt): its Q, and the cell whose P departs
   most from the coarse grid's (the same lattice: the nodes themselves) */
static int run_mesh(uraCtx* c, const uraState* orig, uraState* ns, const urGrid* coarse,
                    const urCell* cells, conv* v) {
  int k;
  v->have_mesh = membrane_mesh(ura_model(c), &k);
  if (v->have_mesh < 1) return 0;
  v->mesh = c->model->param[k].value;
  *ns = *orig;
  ura_risk_override(ns, "bag_mesh", 2 * v->mesh, 1);
  if (ura_risk_grid(c, ns, "converge", 0, &v->q_mesh)) return -1;
  const urGrid* f = c->last.g;
  v->mworst = -1;
  for (int i = 0; i < f->nrow * f->ncol; i++) {
    const urCell* fc = &f->cell[i];
    double pc = coarse_p(coarse, cells, fc->dpar, fc->dperp), d = fabs(fc->p - pc);
    if (d > v->mworst) {
      v->mworst = d;
      v->mworst_dpar = fc->dpar;
      v->mworst_dperp = fc->dperp;
      v->mworst_coarse = pc;
      v->mworst_fine = fc->p;
    }
  }
  return 0;
}

static int run(uraCtx* c, const uraState* orig, uraState* ns, conv* v) {
  memset(v, 0, sizeof *v);
  *ns = *orig;
  if (ura_risk_grid(c, ns, "converge", 0, &v->q_h)) return -1;
  urGrid coarse = *c->last.g;
  size_t nc = (size_t)coarse.nrow * coarse.ncol;
  urCell* cells = malloc(nc * sizeof *cells);
  if (!cells) return ura_fail(c, "converge: out of memory");
  memcpy(cells, c->last.g->cell, nc * sizeof *cells);

  /* the mesh first, so that the last grid is the half-step one */
  int rc = run_mesh(c, orig, ns, &coarse, cells, v);
  *ns = *orig;
  ns->step = orig->step / 2;
  if (rc == 0) rc = ura_risk_grid(c, ns, "converge", 0, &v->q_h2);
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

/* one row: check, what, where (NULL: "-"), coarse, fine, their change and its relative size */
static void row(uraTable* t, const char* check, const char* what, const double* at, double a,
                double b) {
  ura_table_cell(t, "%s", check);
  ura_table_cell(t, "%s", what);
  for (int k = 0; k < 2; k++) {
    if (at)
      ura_table_cell(t, "%g", at[k]);
    else
      ura_table_cell(t, "-");
  }
  ura_table_cell(t, "%.6g", a);
  ura_table_cell(t, "%.6g", b);
  ura_table_cell(t, "%.3g", b - a);
  ura_table_cell(t, "%.3g", b > 0 ? (b - a) / b : 0);
}

/* a warning when Q moves by more than CONV_TOL of the finer result: the grid's Q is not
   converged to the accuracy a dossier quotes it with */
#define CONV_TOL 0.1
static void conv_warn(uraTable* t, const char* what, double coarse, double fine, double step) {
  double rel = fine > 0 ? (fine - coarse) / fine : 0;
  if (fabs(rel) <= CONV_TOL) return;
  ura_table_note(t,
                 "warning: %s moves Q by %.0f %% of the finer result (%.6g -> %.6g m^2), more "
                 "than %.0f %% (this note's tolerance, not a standard): the coarser Q (step %g "
                 "m) is not converged to that accuracy",
                 what, 100 * rel, coarse, fine, 100 * CONV_TOL, step);
}

/* the mesh rows: Q, and the cell whose P moved most */
static void mesh_rows(uraTable* t, const conv* v) {
  const double at[2] = {v->mworst_dpar, v->mworst_dperp};
  row(t, "mesh", "q", NULL, v->q_h, v->q_mesh);
  row(t, "mesh", "p_worst", at, v->mworst_coarse, v->mworst_fine);
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
  if (v.have_mesh == 1) {
    ura_table_note(t,
                   "mesh: the membrane bag's mesh refined: the grid at step %g m again with "
                   "bag_mesh %g (coarse) and %g (fine), the same dt; p_worst: the cell whose P "
                   "moved most",
                   step, v.mesh, 2 * v.mesh);
  } else {
    ura_table_note(t, "mesh: %s; the bag's mesh is not refined",
                   v.have_mesh ? "the model declares no parameter bag_mesh"
                               : "the case has no membrane airbag");
  }
  row(t, "step", "q", NULL, v.q_h, v.q_h2);
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
    for (int w = 0; w < 2; w++) row(t, "dt", what[w], at[w], v.p_dt[w][0], v.p_dt[w][1]);
  }
  if (v.have_mesh == 1) mesh_rows(t, &v);
  conv_warn(t, "halving the step", v.q_h, v.q_h2, step);
  if (v.have_mesh == 1) conv_warn(t, "doubling bag_mesh", v.q_h, v.q_mesh, step);
  if (v.shared_max > 0) {
    ura_table_note(t, "warning: shared cells differ by up to %.3g: the grids are not repeatable",
                   v.shared_max);
  }
  ura_table_print(c, t);
  return 0;
}
