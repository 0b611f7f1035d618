/* designs.c: designs side by side: 'design save NAME' keeps the live case's full state (every
 * setting and model parameter), 'design compare A B' runs a grid for each and prints both Q and
 * their ratio, leaving the difference grid P_b - P_a as the last grid */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"


#define MAXDESIGNS 32

typedef struct uraDesign {
  char name[urNAMELEN];
  uraState st;
} uraDesign;

static uraDesign* find(uraCtx* c, const char* name) {
  for (int i = 0; i < c->ndesign; i++) {
    if (!strcmp(c->design[i].name, name)) return c->design + i;
  }
  return NULL;
}

/* a name: a letter or '_', then letters, digits, '_', '.' or '-'; at most urNAMELEN - 1 */
static int valid_name(const char* s) {
  if (!(isalpha((unsigned char)s[0]) || s[0] == '_') || strlen(s) >= urNAMELEN) return 0;
  for (const char* p = s; *p; p++) {
    if (!(isalnum((unsigned char)*p) || *p == '_' || *p == '.' || *p == '-')) return 0;
  }
  return 1;
}

static int design_save(uraCtx* c, const char* name) {
  if (!valid_name(name)) {
    return ura_fail(c,
                    "design save: '%s' is not a name; accepted: letters, digits, '_', '.' or "
                    "'-', starting with a letter or '_', at most %d characters",
                    name, urNAMELEN - 1);
  }
  uraDesign* d = find(c, name);
  if (!d) {
    if (c->ndesign == MAXDESIGNS) {
      return ura_fail(c,
                      "design save: %d designs are kept already; 'design delete NAME' "
                      "forgets one",
                      MAXDESIGNS);
    }
    uraDesign* m = realloc(c->design, (size_t)(c->ndesign + 1) * sizeof *m);
    if (!m) return ura_fail(c, "design save: out of memory");
    c->design = m;
    d = c->design + c->ndesign++;
    snprintf(d->name, sizeof d->name, "%s", name);
  }
  d->st = c->st;
  return 0;
}

/* the changes of a design from its preset, through the sweep's description */
static void changes(uraCtx* c, const uraState* st, char* buf, size_t n) {
  uraState keep = c->st;
  c->st = *st;
  ura_sweep_changes(c, buf, n);
  c->st = keep;
  c->err[0] = 0;
}

static int design_list(uraCtx* c) {
  static const char* const cols[] = {"design", "case", "wind", "face", "changes"};
  uraTable* t = ura_table_new(5, cols);
  ura_table_note(t, "%d design%s kept; changes: settings that differ from the case preset",
                 c->ndesign, c->ndesign == 1 ? "" : "s");
  for (int i = 0; i < c->ndesign; i++) {
    char ch[200];
    changes(c, &c->design[i].st, ch, sizeof ch);
    ura_table_cell(t, "%s", c->design[i].name);
    ura_table_cell(t, "%s", c->design[i].st.casename);
    ura_table_cell(t, "%g", c->design[i].st.descent.wind);
    ura_table_cell(t, "%g", c->design[i].st.face);
    ura_table_cell(t, "%s", ch);
  }
  ura_table_print(c, t);
  return 0;
}

/* a design's grid: its state made live, the grid run (or recalled), the grid taken */
static urGrid* design_grid(uraCtx* c, const uraDesign* d) {
  if (ura_model_state(c, &d->st, "design compare")) return NULL;
  if (ura_grid_run(c, 1)) return NULL;
  if (!c->last.g->complete) {
    ura_fail(c,
             "design compare: the grid of '%s' has %d failed and %d pending cells; Q is not "
             "complete",
             d->name, c->last.g->nfailed, c->last.g->npending);
    return NULL;
  }
  urGrid* g = c->last.g;
  c->last.g = NULL;
  return g;
}

/* the cell of g at an offset, or NULL (outside its lattice: no contact there, P = 0) */
static const urCell* at(const urGrid* g, double dpar, double dperp) {
  int r = (int)lround((g->par_max - dpar) / g->step),
      k = (int)lround((dperp - g->perp_min) / g->step);
  if (r < 0 || r >= g->nrow || k < 0 || k >= g->ncol) return NULL;
  const urCell* cell = g->cell + (size_t)r * g->ncol + k;
  return fabs(cell->dpar - dpar) < 1e-9 && fabs(cell->dperp - dperp) < 1e-9 ? cell : NULL;
}

/* the difference grid b - a over the union of both lattices (the same step) */
static urGrid* difference(const urGrid* a, const urGrid* b) {
  urGridSpec spec = {a->step, 0, 0, 0, 0, 1, NULL, NULL, NULL, NULL, NULL, NULL};
  double amin = a->par_max - (a->nrow - 1) * a->step, bmin = b->par_max - (b->nrow - 1) * b->step;
  spec.par_min = fmin(amin, bmin);
  spec.par_max = fmax(a->par_max, b->par_max);
  spec.perp_max = fmax(fmax(-a->perp_min, -b->perp_min), 0);
  urGrid* g = ur_grid_new(&spec);
  if (!g) return NULL;
  for (int i = 0; i < g->nrow * g->ncol; i++) {
    urCell* cell = g->cell + i;
    const urCell* ca = at(a, cell->dpar, cell->dperp);
    const urCell* cb = at(b, cell->dpar, cell->dperp);
    cell->status = urCELL_DONE;
    cell->contact = (ca && ca->contact) || (cb && cb->contact);
    cell->p = (cb ? cb->p : 0) - (ca ? ca->p : 0);
    for (int v = 0; v < urNVAL; v++) {
      if (v != urVAL_HIC15 && v != urVAL_NIJ) continue; /* the two the difference has kept */
      cell->val[v] = (cb ? cb->val[v] : 0) - (ca ? ca->val[v] : 0);
    }
  }
  ur_grid_summarise(g);
  return g;
}

static int design_compare(uraCtx* c, const char* na, const char* nb) {
  static const char* const cols[] = {"design_a", "case_a", "q_a",  "design_b",
                                     "case_b",   "q_b",    "ratio"};
  const uraDesign* d[2] = {find(c, na), find(c, nb)};
  for (int i = 0; i < 2; i++) {
    if (!d[i]) {
      return ura_fail(c,
                      "design compare: no design '%s'; 'design save NAME' keeps the live "
                      "case, 'design list' lists them",
                      i ? nb : na);
    }
  }
  if (d[0]->st.step != d[1]->st.step) {
    return ura_fail(c,
                    "design compare: the designs' grid steps differ (%g and %g m); accepted: "
                    "designs saved with the same step",
                    d[0]->st.step, d[1]->st.step);
  }
  if (ura_dry(c, "design compare")) return -1;

  /* both grids, then the live state as it was */
  uraState live = c->st;
  urGrid* g[2] = {NULL, NULL};
  int rc = 0;
  for (int i = 0; i < 2 && rc == 0; i++) {
    g[i] = design_grid(c, d[i]);
    if (!g[i]) rc = -1;
  }
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  ura_model_state(c, &live, "design compare");
  if (rc) {
    ur_grid_free(g[0]);
    snprintf(c->err, sizeof c->err, "%s", err);
    return -1;
  }

  uraTable* t = ura_table_new(7, cols);
  ura_table_note(t,
                 "ratio: q_b / q_a (the risk a change from %s to %s leaves); the last grid "
                 "is now the difference P_b - P_a ('view', 'grid show', 'export grid')",
                 na, nb);
  ura_table_cell(t, "%s", na);
  ura_table_cell(t, "%s", d[0]->st.casename);
  ura_table_cell(t, "%.4f", g[0]->q);
  ura_table_cell(t, "%s", nb);
  ura_table_cell(t, "%s", d[1]->st.casename);
  ura_table_cell(t, "%.4f", g[1]->q);
  ura_table_cell(t, "%.4f", g[0]->q > 0 ? g[1]->q / g[0]->q : NAN);
  ura_table_print(c, t);

  /* the difference as the last grid */
  urGrid* diff = difference(g[0], g[1]);
  ur_grid_free(g[0]);
  ur_grid_free(g[1]);
  if (!diff) return ura_fail(c, "design compare: out of memory for the difference grid");
  ura_last_free(c);
  c->last.g = diff;
  c->last.diff = 1;
  snprintf(c->last.casename, sizeof c->last.casename, "%s", d[1]->st.casename);
  c->last.wind = d[1]->st.descent.wind;
  c->last.face = d[1]->st.face;
  c->last.speed = c->last.angle = NAN;
  snprintf(c->last.source, sizeof c->last.source, "difference P_b - P_a: design %s - design %s", nb,
           na);
  return 0;
}

int ura_cmd_design(uraCtx* c, int argc, char** argv) {
  const char* w = argv[1];
  if (argc == 3 && !strcmp(w, "save")) return design_save(c, argv[2]);
  if (argc == 2 && !strcmp(w, "list")) return design_list(c);
  if (argc == 4 && !strcmp(w, "compare")) return design_compare(c, argv[2], argv[3]);
  if (argc == 3 && (!strcmp(w, "load") || !strcmp(w, "delete"))) {
    uraDesign* d = find(c, argv[2]);
    if (!d) {
      return ura_fail(c, "design %s: no design '%s'; 'design list' lists them", w, argv[2]);
    }
    if (!strcmp(w, "load")) return ura_model_state(c, &d->st, "design load");
    *d = c->design[--c->ndesign];
    return 0;
  }
  return ura_fail(c,
                  "design: usage: design save NAME, design load NAME, design delete NAME, "
                  "design list, design compare NAME_A NAME_B");
}

void ura_designs_write(uraCtx* c, FILE* f, void (*write_state)(uraCtx*, FILE*)) {
  if (!c->ndesign) return;
  uraState live = c->st;
  for (int i = 0; i < c->ndesign; i++) {
    c->st = c->design[i].st;
    write_state(c, f);
    fprintf(f, "design save %s\n", c->design[i].name);
  }
  c->st = live;
}

const uraState* ura_designs_state(uraCtx* c, const char* name) {
  const uraDesign* d = find(c, name);
  return d ? &d->st : NULL;
}

void ura_designs_names(uraCtx* c, char* buf, size_t n) {
  size_t k = (size_t)snprintf(buf, n, "%s", c->ndesign ? "" : "none");
  for (int i = 0; i < c->ndesign && k < n; i++) {
    k += (size_t)snprintf(buf + k, n - k, "%s%s", i ? ", " : "", c->design[i].name);
  }
}
