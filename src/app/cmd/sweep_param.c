/* sweep_param.c: sweep NAME LIST [UNIT]: one grid per value of any numeric parameter (a workbench
 * setting, an injury setting or a model parameter, which takes a unit), Q against it; the sweeps
 * are kept for sweep show, export sweep and plot sweep NAME */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"


/* is name a numeric parameter that a sweep may set (wind and face have their own sweeps) */
static int sweepable(uraCtx* c, const char* name, const char** unit) {
  const uraParam* p = ura_param_find(name);
  *unit = "";
  if (p) {
    *unit = p->unit;
    return (p->kind == uraP_NUM || p->kind == uraP_INT) && strcmp(name, "threads");
  }
  if (ura_injury_find(name) >= 0) return 1;
  return ura_model_param_find(c, name) >= 0;
}

/* keep s (taking its arrays): it replaces the sweep of the same case, parameter, unit, fixed
   conditions and changes */
static int keep(uraCtx* c, const uraPSweep* s) {
  for (int i = 0; i < c->npsweep; i++) {
    uraPSweep* o = c->psweep + i;
    if (!strcmp(o->casename, s->casename) && !strcmp(o->param, s->param) &&
        !strcmp(o->unit, s->unit) && o->wind == s->wind && o->face == s->face &&
        !strcmp(o->changes, s->changes)) {
      free(o->x);
      *o = *s;
      return 0;
    }
  }
  if (c->nsweep + c->npsweep >= uraMAXSWEEPS) {
    return ura_fail(c, "sweep: %d sweeps are kept already; 'sweep clear' forgets them",
                    uraMAXSWEEPS);
  }
  uraPSweep* m = realloc(c->psweep, (size_t)(c->npsweep + 1) * sizeof *m);
  if (!m) return ura_fail(c, "sweep: out of memory");
  c->psweep = m;
  c->psweep[c->npsweep++] = *s;
  return 0;
}

void ura_sweep_param_clear(uraCtx* c) {
  for (int i = 0; i < c->npsweep; i++) free(c->psweep[i].x);
  free(c->psweep);
  c->psweep = NULL;
  c->npsweep = 0;
}

/* free a sweep under way (its arrays unless kept) and its list of values */
static void free_psweep(uraPSweep* s, double* v) {
  free(s->x);
  free(s);
  free(v);
}

int ura_sweep_param(uraCtx* c, int argc, char** argv) {
  const char* name = argv[1];
  const char* own;
  if (!sweepable(c, name, &own)) {
    c->err[0] = 0;
    return ura_fail(c,
                    "sweep: '%s' is not accepted; accepted: sweep wind LIST, sweep face LIST, "
                    "sweep NAME LIST [UNIT] with NAME a numeric setting, injury setting or model "
                    "parameter ('show' lists them), sweep show, sweep clear",
                    name);
  }
  /* the values: as many as the list holds, a refused one named by its place */
  int n = ura_list_count(argv[2]);
  double* v = malloc((size_t)n * sizeof *v);
  uraPSweep* s = calloc(1, sizeof *s);
  double* b = malloc(4 * (size_t)n * sizeof *b);
  if (!v || !s || !b) {
    free(v);
    free(s);
    free(b);
    return ura_fail(c, "sweep: out of memory for %d values", n);
  }
  s->x = b;
  s->speed = b + n;
  s->angle = b + 2 * (size_t)n;
  s->q = b + 3 * (size_t)n;
  char why[uraERRLEN];
  if (ura_parse_list_why(argv[2], v, n, why, sizeof why) < 0) {
    free_psweep(s, v);
    return ura_fail(c, "sweep %s: %s; accepted: comma-separated numbers", name, why);
  }
  const char* unit = argc == 4 ? argv[3] : NULL;

  /* every value is checked by 'set' before any grid runs; the live state comes back after */
  uraState saved = c->st;
  char val[64], *av[4] = {"set", (char*)name, val, (char*)unit};
  for (int i = 0; i < n; i++) {
    snprintf(val, sizeof val, "%.17g", v[i]);
    if (ura_cmd_set(c, unit ? 4 : 3, av)) {
      snprintf(why, sizeof why, "%s", c->err);
      ura_model_state(c, &saved, "sweep");
      free_psweep(s, v);
      return ura_fail(c, "sweep %s: %.900s", name, why); /* set names the value */
    }
  }
  if (ura_model_state(c, &saved, "sweep")) {
    free_psweep(s, v);
    return -1;
  }
  snprintf(s->casename, sizeof s->casename, "%s", c->st.casename);
  snprintf(s->param, sizeof s->param, "%s", name);
  snprintf(s->unit, sizeof s->unit, "%s", unit ? unit : own);
  s->wind = c->st.descent.wind;
  s->face = c->st.face;
  s->step = c->st.step;
  ura_sweep_changes(c, s->changes, sizeof s->changes);

  const char* cols[] = {"case", name, "wind", "face", "speed", "angle", "q"};
  uraTable* t = ura_table_new(7, cols);
  if (*s->unit) ura_table_note(t, "%s in %s", name, s->unit);
  int rc = 0;
  for (int i = 0; i < n && rc == 0; i++) {
    snprintf(val, sizeof val, "%.17g", v[i]);
    rc = ura_cmd_set(c, unit ? 4 : 3, av);
    ura_progress_label("sweep %s %g%s%s (%d of %d): ", name, v[i], *s->unit ? " " : "", s->unit,
                       i + 1, n);
    if (rc == 0) rc = ura_grid_run(c, 0);
    ura_progress_label(NULL);
    if (rc && ura_interrupted()) {
      snprintf(why, sizeof why, "%s", c->err);
      ura_fail(c, "sweep: interrupted (Ctrl-C) at %s %g; %d of %d grids finished (%.900s)", name,
               v[i], i, n, why);
    }
    if (rc == 0 && !c->last.g->complete) {
      rc = ura_fail(c, "sweep: %d cells failed at %s %g; Q is not complete", c->last.g->nfailed,
                    name, v[i]);
    }
    if (rc) break;
    ura_table_cell(t, "%s", c->st.casename);
    ura_table_cell(t, "%g", v[i]);
    ura_table_cell(t, "%g", c->st.descent.wind);
    ura_table_cell(t, "%g", c->st.face);
    ura_table_cell(t, "%.3f", c->last.speed);
    ura_table_cell(t, "%.2f", c->last.angle);
    ura_table_cell(t, "%.4f", c->last.g->q);
    int k = s->n++;
    s->x[k] = v[i];
    s->speed[k] = c->last.speed;
    s->angle[k] = c->last.angle;
    s->q[k] = c->last.g->q;
  }

  /* the live state as it was (its model is kept: no settling again) */
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  ura_model_state(c, &saved, "sweep");
  snprintf(c->err, sizeof c->err, "%s", err);
  if (ura_table_rows(t)) /* stopped before the first value: no empty header */
    ura_table_print(c, t);
  else
    ura_table_free(t);
  if (s->n > 0) {
    if (keep(c, s)) {
      rc = -1;
    } else {
      if (rc) snprintf(c->err, sizeof c->err, "%.900s (the %d values before are kept)", err, s->n);
      s->x = NULL; /* kept */
    }
  }
  free_psweep(s, v);
  return rc;
}

void ura_sweep_param_rows(uraCtx* c, uraTable* t) {
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* s = c->psweep + i;
    for (int k = 0; k < s->n; k++) {
      ura_table_cell(t, "%s", s->casename);
      ura_table_cell(t, "%s", s->param);
      ura_table_cell(t, "%g", s->wind);
      ura_table_cell(t, "%g", s->face);
      ura_table_cell(t, "%.3f", s->speed[k]);
      ura_table_cell(t, "%.2f", s->angle[k]);
      ura_table_cell(t, "%g", s->step);
      ura_table_cell(t, "%.4f", s->q[k]);
      ura_table_cell(t, "%s", s->changes);
      ura_table_cell(t, "%g", s->x[k]);
      ura_table_cell(t, "%s", s->unit);
    }
  }
}
