/* cmd_sweep.c: sweeps of the grid over wind or face direction, and the paper's comparison of Q
 * with P{F|Delta=(0,0)} x gliding area (Tables 11-13) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"


/* room for n values in a sweep's arrays (one block); 0, or -1 without memory */
static int sweep_alloc(uraSweep* s, int n) {
  double* b = malloc(4 * (size_t)n * sizeof *b);
  if (!b) return -1;
  s->x = b;
  s->speed = b + n;
  s->angle = b + 2 * (size_t)n;
  s->q = b + 3 * (size_t)n;
  return 0;
}

/* keep a sweep (taking its arrays): it replaces the one of the same case, kind, fixed value and
   changes */
static int sweep_keep(uraCtx* c, const uraSweep* s) {
  for (int i = 0; i < c->nsweep; i++) {
    uraSweep* o = &c->sweep[i];
    if (!strcmp(o->casename, s->casename) && o->over_face == s->over_face && o->fixed == s->fixed &&
        !strcmp(o->changes, s->changes)) {
      free(o->x);
      *o = *s;
      return 0;
    }
  }
  if (c->nsweep + c->npsweep >= uraMAXSWEEPS) { /* both kinds count */
    return ura_fail(c, "sweep: %d sweeps are kept already; 'sweep clear' forgets them",
                    uraMAXSWEEPS);
  }
  uraSweep* m = realloc(c->sweep, (size_t)(c->nsweep + 1) * sizeof *m);
  if (!m) return ura_fail(c, "sweep: out of memory");
  c->sweep = m;
  c->sweep[c->nsweep++] = *s;
  return 0;
}

/* add one value to a sweep, keeping the values in increasing order */
static void sweep_add(uraSweep* s, double x, double speed, double angle, double q) {
  int i = s->n++;
  for (; i > 0 && s->x[i - 1] > x; i--) {
    s->x[i] = s->x[i - 1];
    s->speed[i] = s->speed[i - 1];
    s->angle[i] = s->angle[i - 1];
    s->q[i] = s->q[i - 1];
  }
  s->x[i] = x;
  s->speed[i] = speed;
  s->angle[i] = angle;
  s->q[i] = q;
}

/* sweep show: every kept value; columns case,sweep,wind,face,speed,angle,step,q,changes,value,
   unit (value: the swept value in unit) */
static int sweep_show(uraCtx* c) {
  static const char* const cols[] = {"case", "sweep", "wind",    "face",  "speed", "angle",
                                     "step", "q",     "changes", "value", "unit"};
  if (!c->nsweep && !c->npsweep) {
    return ura_fail(c,
                    "sweep show: no sweep yet; run 'sweep wind LIST' or 'sweep face LIST' "
                    "(or 'sweep NAME LIST [UNIT]')");
  }
  uraTable* t = ura_table_new(11, cols);
  ura_table_note(t,
                 "%d sweep%s kept (plot sweep draws them; sweep clear forgets them); "
                 "changes: settings that differ from the case preset",
                 c->nsweep + c->npsweep, c->nsweep + c->npsweep == 1 ? "" : "s");
  for (int i = 0; i < c->nsweep; i++) {
    const uraSweep* s = &c->sweep[i];
    for (int k = 0; k < s->n; k++) {
      ura_table_cell(t, "%s", s->casename);
      ura_table_cell(t, "%s", s->over_face ? "face" : "wind");
      ura_table_cell(t, "%g", s->over_face ? s->fixed : s->x[k]);
      ura_table_cell(t, "%g", s->over_face ? s->x[k] : s->fixed);
      ura_table_cell(t, "%.3f", s->speed[k]);
      ura_table_cell(t, "%.2f", s->angle[k]);
      ura_table_cell(t, "%g", s->step);
      ura_table_cell(t, "%.4f", s->q[k]);
      ura_table_cell(t, "%s", s->changes);
      ura_table_cell(t, "%g", s->x[k]);
      ura_table_cell(t, "%s", s->over_face ? "deg" : "m/s");
    }
  }
  ura_sweep_param_rows(c, t);
  ura_table_print(c, t);
  return 0;
}

void ura_sweep_table(uraCtx* c, uraTable* t, int rows) {
  /* no grid finished (stopped, or failed, at the first value): no empty header */
  if (rows > 0 && ura_table_rows(t)) {
    ura_table_print(c, t);
  } else {
    ura_table_free(t);
  }
}

int ura_cmd_sweep(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case", "wind", "face", "speed", "angle", "q"};
  if (argc == 2 && !strcmp(argv[1], "show")) return sweep_show(c);
  if (argc == 2 && !strcmp(argv[1], "clear")) {
    for (int i = 0; i < c->nsweep; i++) free(c->sweep[i].x);
    free(c->sweep);
    c->sweep = NULL;
    c->nsweep = 0;
    ura_sweep_param_clear(c);
    return 0;
  }
  if (argc >= 3 && strcmp(argv[1], "wind") && strcmp(argv[1], "face")) {
    return ura_sweep_param(c, argc, argv); /* sweep NAME LIST [UNIT] (sweep_param.c) */
  }
  int is_wind = !strcmp(argv[1], "wind"), is_face = !strcmp(argv[1], "face");
  if ((is_wind || is_face) && argc == 2) {
    return ura_fail(c, "sweep %s: needs a list of values, e.g. 'sweep %s %s'", argv[1], argv[1],
                    is_wind ? "0,4,10" : "0,90,180");
  }
  /* sweep wind LIST km/h|kt: the list in m/s from here on (sweeps keep m/s) */
  char si[4096];
  if (is_wind && argc == 4) {
    if (ura_speed_convert(c, "sweep wind", ura_param_find("winds"), argv[2], argv[3], si,
                          sizeof si))
      return -1;
    argv[2] = si;
    argc = 3;
  }
  if ((!is_wind && !is_face) || argc != 3) {
    return ura_fail(c,
                    "sweep: '%s' is not accepted; accepted: sweep wind LIST, sweep face "
                    "LIST, sweep show, sweep clear",
                    argv[1]);
  }
  /* the values: as many as the list holds (a kept sweep has no limit of its own), each named by
     its place when refused, never by echoing the whole list */
  const uraParam* p = ura_param_find(is_wind ? "wind" : "face");
  int n = ura_list_count(argv[2]);
  double* v = malloc((size_t)n * sizeof *v);
  uraSweep* s = calloc(1, sizeof *s);
  if (!v || !s || sweep_alloc(s, n)) {
    free(v);
    free(s);
    return ura_fail(c, "sweep: out of memory for %d values", n);
  }
  char why[uraERRLEN];
  int bad = ura_parse_list_why(argv[2], v, n, why, sizeof why) < 0;
  for (int i = 0; i < n && !bad; i++) {
    if (v[i] < p->min || v[i] > p->max) {
      snprintf(why, sizeof why, "value %d of %d, %g, is out of range", i + 1, n, v[i]);
      bad = 1;
    }
  }
  if (bad) {
    free(v);
    free(s->x);
    free(s);
    return ura_fail(c, "sweep %s: %s; accepted: comma-separated numbers in [%g, %g] %s", argv[1],
                    why, p->min, p->max, p->unit);
  }
  /* with the paper's Table 2, every wind must be one it prints (refused before any grid runs) */
  if (ura_paper_speed(c)) {
    double ws = c->st.descent.wind, sp, an;
    for (int i = 0; i < (is_wind ? n : 1); i++) {
      if (ura_paper_descent(c, c->st.casename, is_wind ? v[i] : ws, &sp, &an)) {
        snprintf(why, sizeof why, "%s", c->err);
        free(v);
        free(s->x);
        free(s);
        return ura_fail(c, "sweep %s: %.900s", argv[1], why);
      }
    }
  }

  /* the sweep to keep: case, kind, the fixed condition, what differs from the preset */
  snprintf(s->casename, sizeof s->casename, "%s", c->st.casename);
  s->over_face = is_face;
  s->fixed = is_wind ? c->st.face : c->st.descent.wind;
  s->step = c->st.step;
  ura_sweep_changes(c, s->changes, sizeof s->changes);

  /* one grid per value (speed and angle derived per wind as 'set descent' says); the live wind
     or face is restored afterwards */
  double keep = is_wind ? c->st.descent.wind : c->st.face;
  uraTable* t = ura_table_new(6, cols);
  int paper = ura_paper_speed(c);
  double shift = 0; /* the tau shift at each value (it depends on the angle) */
  int shifts_differ = 0;
  int rc = 0;
  char recalled[200] = ""; /* the values whose grids were recalled (recall.c) */
  size_t nr = 0;
  for (int i = 0; i < n && rc == 0; i++) {
    if (is_wind)
      c->st.descent.wind = v[i];
    else
      c->st.face = v[i];
    ura_progress_run(i, n);
    ura_progress_label("sweep %s %g %s (%d of %d): ", argv[1], v[i], is_wind ? "m/s" : "deg", i + 1,
                       n);
    rc = ura_grid_run(c, 0);
    ura_progress_label(NULL);
    ura_progress_run(0, 0);
    if (rc && ura_interrupted()) {
      snprintf(why, sizeof why, "%s", c->err);
      ura_fail(c, "sweep: interrupted (Ctrl-C) at %s %g; %d of %d grids finished (%.900s)", argv[1],
               v[i], i, n, why);
    }
    if (rc == 0 && !c->last.g->complete) {
      rc = ura_fail(c, "sweep: %d cells failed at %s %g; Q is not complete", c->last.g->nfailed,
                    argv[1], v[i]);
    }
    if (rc == 0) {
      ura_table_cell(t, "%s", c->st.casename);
      ura_table_cell(t, "%g", c->st.descent.wind);
      ura_table_cell(t, "%g", c->st.face);
      ura_table_cell(t, "%.3f", c->last.speed);
      ura_table_cell(t, "%.2f", c->last.angle);
      ura_table_cell(t, "%.4f", c->last.g->q);
      sweep_add(s, v[i], c->last.speed, c->last.angle, c->last.g->q);
      if (i > 0 && c->last.tau_shift != shift) shifts_differ = 1;
      shift = c->last.tau_shift;
      if (c->last.recalled && nr < sizeof recalled) { /* a long list ends in ", ..." */
        char one[40];
        size_t w = (size_t)snprintf(one, sizeof one, "%s%g", nr ? ", " : "", v[i]);
        if (nr + w + 6 <= sizeof recalled) {
          memcpy(recalled + nr, one, w + 1);
          nr += w;
        } else {
          snprintf(recalled + nr, sizeof recalled - nr, ", ...");
          nr = sizeof recalled; /* full */
        }
      }
    }
  }
  if (is_wind)
    c->st.descent.wind = keep;
  else
    c->st.face = keep;
  if (paper) {
    ura_table_note(t,
                   "speed and angle: the paper's Table 2, case %s's column, at each wind "
                   "('set descent paper'), not the descent model",
                   ura_paper_descent_column(c->st.casename));
  }
  if (c->st.tau == urTAU_TOP) {
    if (shifts_differ || s->n == 0) {
      ura_table_note(t,
                     "tau top: Delta is taken when the drone centre reaches head-top level, "
                     "R_max/tan(psi) further along the course than the paper's text (R_max "
                     "above the head top; 'set tau rmax')");
    } else {
      ura_table_note(t,
                     "tau top: Delta is taken when the drone centre reaches head-top level, "
                     "%.3f m further along the course than the paper's text (R_max above the "
                     "head top; 'set tau rmax')",
                     shift);
    }
  }
  if (nr) {
    ura_table_note(t,
                   "recalled: the grids of %s %s are identical to grids computed earlier in "
                   "this session and were not simulated again ('set recall off' recomputes)",
                   argv[1], recalled);
  }
  ura_sweep_table(c, t, s->n);

  /* keep what finished (a sweep that stopped keeps the values before the failure) */
  int kept = 0;
  if (s->n > 0) {
    char err[uraERRLEN];
    snprintf(err, sizeof err, "%s", c->err);
    kept = sweep_keep(c, s) == 0;
    if (!kept)
      rc = -1;
    else if (rc)
      snprintf(c->err, sizeof c->err, "%.900s (the %d values before are kept)", err, s->n);
  }
  if (!kept) free(s->x);
  free(s);
  free(v);
  return rc;
}

int ura_cmd_compare(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case",         "wind", "p_centre", "gliding",
                                     "q_parametric", "q",    "factor"};
  urImpactCond cond;
  const urImpactSetup* s = ura_setup(c);
  if (!s || ura_impact_cond(c, &cond)) return -1;

  /* P{F|Delta=(0,0)}, the gliding area at this descent, and the grid's Q */
  urImpactResult r;
  if (ura_impact_fresh(c, s, &cond, 0, 0, &r)) {
    if (r.status == urSTAT_STOPPED) return ura_fail(c, "compare: interrupted (Ctrl-C)");
    return ura_fail(c, "compare: the impact at (0, 0) failed: %s", r.reason);
  }
  ura_impact_keep(c, c->st.casename, c->st.descent.wind, &cond, 0, 0, &r);
  urParametricResult q;
  ur_parametric(&c->st.para, c->st.descent.mass, cond.speed, cond.angle, &q);
  if (ura_grid_run(c, 0)) return -1;
  if (!c->last.g->complete) {
    return ura_fail(c, "compare: the grid has %d failed and %d pending cells; Q is not complete",
                    c->last.g->nfailed, c->last.g->npending);
  }

  uraTable* t = ura_table_new(7, cols);
  ura_table_note(t,
                 "paper Tables 11-13: P{F|Delta=(0,0)} x gliding area (eq. D.1) against the "
                 "dynamical Q, and the reduction factor between them");
  if (c->last.recalled) {
    ura_table_note(t,
                   "recalled: the grid is identical to one computed earlier in this session "
                   "and was not simulated again ('set recall off' recomputes)");
  }
  ura_cond_notes(t, c->st.casename, c->st.descent.wind, c->last.paper_speed, c->last.tau,
                 c->last.tau_shift);
  ura_explain_centre(t, &r, c->last.g);
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
