/* report_log.c: what the report is made of, kept as the session prints it: each table of the
 * commands whose results belong in a study (grid, grid load, sweep, design compare, risk,
 * montecarlo, montecarlo shares, sora, converge, compare, descent, parametric) with its command
 * line and notes, the settings it ran under (as 'show' lists them, kept once per change), a copy of each grid
 * for the figures, and the warnings: the notes ura_report_alarm picks, and the commands that
 * failed. Nothing here prints or computes. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"

/* the commands (and first arguments) whose tables are kept */
static int wanted(int argc, char** argv) {
  const char* a = argc > 1 ? argv[1] : "";
  const char* n = argv[0];
  if (!strcmp(n, "grid")) return argc == 1 || !strcmp(a, "load");
  if (!strcmp(n, "sweep")) return strcmp(a, "show") && strcmp(a, "clear");
  if (!strcmp(n, "design")) return !strcmp(a, "compare");
  if (!strcmp(n, "montecarlo")) return strcmp(a, "samples");
  static const char* const all[] = {"risk",    "sora",       "converge", "compare",
                                    "descent", "parametric", NULL};
  for (int i = 0; all[i]; i++) {
    if (!strcmp(n, all[i])) return 1;
  }
  return 0;
}

int ura_report_alarm(const char* note) {
  static const char* const alarm[] = {
      "warning",     "failed",  "extrapolat", "clamped:",     "truncated:",   "thin tails",
      "few samples", "partial", "PARTIAL",    "not complete", "extents set:", NULL};
  for (int a = 0; alarm[a]; a++) {
    if (strstr(note, alarm[a])) return 1;
  }
  return 0;
}

static char* dup(const char* s) {
  char* d = strdup(s ? s : "");
  return d;
}

static void push_warn(uraReport* r, const char* fmt_cmd, const char* text) {
  char** w = realloc(r->warn, (size_t)(r->nwarn + 1) * sizeof *w);
  if (!w) return;
  r->warn = w;
  size_t n = strlen(fmt_cmd) + strlen(text) + 4;
  char* s = malloc(n);
  if (!s) return;
  snprintf(s, n, "%s: %s", fmt_cmd, text);
  r->warn[r->nwarn++] = s;
}

/* the live settings in the layout of 'show', without its side effects: every parameter (a
   derivable one not set is "auto (derived)", with the derived impact speed and angle), the injury
   settings, the compiled model's parameters and the declared distributions; nothing is compiled,
   settled or simulated (NULL without memory) */
static char* show_text(uraCtx* c) {
  char* s = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&s, &n);
  if (!f) return NULL;
  char val[2048];
  double speed = NAN, angle = NAN;
  char keep[uraERRLEN];
  snprintf(keep, sizeof keep, "%s", c->err);
  int cond = ura_impact_conditions(c, &speed, &angle) == 0;
  snprintf(c->err, sizeof c->err, "%s", keep);
  for (const uraParam* p = ura_params; p->name; p++) {
    ura_param_format(c, p, val, sizeof val);
    int derived = p->setoff && !*(const int*)((const char*)&c->st + p->setoff);
    if (derived && cond && !strcmp(p->name, "speed"))
      snprintf(val, sizeof val, "%.6g (derived)", speed);
    else if (derived && cond && !strcmp(p->name, "angle"))
      snprintf(val, sizeof val, "%.6g (derived)", angle);
    else if (derived)
      snprintf(val, sizeof val, "auto (derived)");
    fprintf(f, "%-17s %s%s%s\n", p->name, val, *p->unit && !derived ? " " : "",
            derived ? "" : p->unit);
  }
  fprintf(f, "# injury criteria (uasimpact-injury(7))\n");
  const char* name;
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) {
    ura_injury_line(c, i, val, sizeof val, 1);
    fprintf(f, "%-17s %s\n", name, val);
  }
  if (c->model) {
    fprintf(f, "# model parameters, SI units (uasimpact-model(5))\n");
    for (int i = 0; i < c->model->nparam; i++) {
      const urParam* p = &c->model->param[i];
      fprintf(f, "%-17s %.10g%s%s\n", p->name, p->value, *p->unit ? " " : "", p->unit);
    }
  }
  for (int i = 0; i < c->st.risk.ndist; i++) {
    if (i == 0) fprintf(f, "# input distributions of montecarlo (dist)\n");
    ura_dist_format(&c->st.risk.dist[i], val, sizeof val);
    fprintf(f, "dist %s %s\n", c->st.risk.dist[i].name, val);
  }
  fclose(f);
  return s;
}

void ura_report_begin(uraCtx* c, int argc, char** argv) {
  if (c->mute || c->dry || (c->rep && c->rep->busy) || !wanted(argc, argv)) {
    if (c->rep) c->rep->want = 0;
    return;
  }
  if (!c->rep) {
    c->rep = calloc(1, sizeof *c->rep);
    if (!c->rep) return;
  }
  uraReport* r = c->rep;
  r->want = 1;
  size_t k = 0;
  r->cmd[0] = 0;
  for (int i = 0; i < argc && k < sizeof r->cmd; i++) {
    k += (size_t)snprintf(r->cmd + k, sizeof r->cmd - k, "%s%s", i ? " " : "", argv[i]);
  }
  snprintf(r->name, sizeof r->name, "%s", argv[0]);
}

/* keep a copy of the last grid; its index or -1 */
static int keep_grid(uraCtx* c, uraReport* r) {
  const urGrid* g = c->last.g;
  if (!g) return -1;
  long cells = 0;
  for (int i = 0; i < r->ng; i++) cells += (long)r->g[i].g.nrow * r->g[i].g.ncol;
  size_t n = (size_t)g->nrow * g->ncol;
  if (r->ng >= uraREPMAXGRIDS || cells + (long)n > uraREPMAXCELLS) {
    r->dropped++;
    return -1;
  }
  if (r->ng == r->capg) {
    int cap = r->capg ? 2 * r->capg : 8;
    uraRepGrid* p = realloc(r->g, (size_t)cap * sizeof *p);
    if (!p) return -1;
    r->g = p;
    r->capg = cap;
  }
  uraRepGrid* k = &r->g[r->ng];
  k->g = *g;
  k->g.cell = malloc(n * sizeof *k->g.cell);
  if (!k->g.cell) return -1;
  memcpy(k->g.cell, g->cell, n * sizeof *k->g.cell);
  k->diff = c->last.diff;
  char cond[300];
  ura_grid_conditions(c, cond, sizeof cond);
  snprintf(k->title, sizeof k->title, "%s", cond);
  return r->ng++;
}

/* whether the live state is the paper's but for the case, wind, face, step, descent source and
   tau: the session text after its last reset sets nothing else that changes a grid (a model
   part, a model or injury parameter, the attitude, the speed, the extents, ...); Table 17 of the
   report stands only such grids beside the paper's */
static int paper_state(uraCtx* c) {
  static const char* const ok[] = {"wind",
                                   "face",
                                   "step",
                                   "descent",
                                   "tau",
                                   "threads",
                                   "recall",
                                   "mirror",
                                   "format",
                                   "pager",
                                   "terminal",
                                   "output",
                                   "winds",
                                   "p_chute",
                                   "p_bag",
                                   "h_chute_min",
                                   "seed",
                                   "mc_method",
                                   "mc_mirror",
                                   "surface_nodes",
                                   "surface_check",
                                   "pop_density",
                                   "lambda_system",
                                   "p_shelter",
                                   "ua_dimension",
                                   "ua_max_speed",
                                   "m2_baseline",
                                   "mc_quantiles",
                                   "mc_surface_tol",
                                   "tlos",
                                   "igrc_compensation",
                                   "annexf_obstacles",
                                   NULL};
  char* text = ura_session_text(c);
  if (!text) return 0;
  int paper = 1;
  for (char* line = text; line && *line;) {
    char* end = strchr(line, '\n');
    if (end) *end = 0;
    char w0[16] = "", w1[32] = "";
    sscanf(line, "%15s %31s", w0, w1);
    if (!strcmp(w0, "reset")) {
      paper = 1;
    } else if (!strcmp(w0, "set")) {
      int k = 0;
      while (ok[k] && strcmp(ok[k], w1)) k++;
      if (!ok[k]) paper = 0;
    } else if (w0[0] && w0[0] != '#' && strcmp(w0, "case") && strcmp(w0, "dist") &&
               strcmp(w0, "design")) {
      paper = 0; /* model drop, model load */
    }
    line = end ? end + 1 : NULL;
  }
  free(text);
  return paper;
}

void ura_report_table(uraCtx* c, const uraTable* tab) {
  int ncol, ncell, nnote;
  char *const *names, *const *cells, *const *notes;
  ura_table_parts(tab, &ncol, &names, &ncell, &cells, &nnote, &notes);
  uraReport* r = c->rep;
  if (!r || !r->want || r->busy) return;
  if (r->nt == r->capt) {
    int cap = r->capt ? 2 * r->capt : 16;
    uraRepTable* p = realloc(r->t, (size_t)cap * sizeof *p);
    if (!p) return;
    r->t = p;
    r->capt = cap;
  }
  uraRepTable* t = &r->t[r->nt];
  memset(t, 0, sizeof *t);
  t->cmd = dup(r->cmd);
  t->name = dup(r->name);
  t->ncol = ncol;
  t->nrow = ncol ? ncell / ncol : 0;
  t->names = calloc((size_t)ncol + 1, sizeof *t->names);
  t->cells = calloc((size_t)ncell + 1, sizeof *t->cells);
  t->notes = calloc((size_t)nnote + 1, sizeof *t->notes);
  if (!t->cmd || !t->name || !t->names || !t->cells || !t->notes) return;
  for (int j = 0; j < ncol; j++) t->names[j] = dup(names[j]);
  for (int k = 0; k < ncell; k++) t->cells[k] = dup(cells[k]);
  t->nnote = nnote;
  for (int i = 0; i < nnote; i++) {
    t->notes[i] = dup(notes[i]);
    if (ura_report_alarm(notes[i])) push_warn(r, t->cmd, notes[i]);
  }
  /* the settings, kept once per change */
  r->busy = 1;
  char* s = show_text(c);
  r->busy = 0;
  if (s && r->nset && !strcmp(s, r->settings[r->nset - 1])) {
    free(s);
    s = NULL;
  } else if (s) {
    char** p = realloc(r->settings, (size_t)(r->nset + 1) * sizeof *p);
    if (p) {
      r->settings = p;
      r->settings[r->nset++] = s;
    } else {
      free(s);
    }
  }
  t->settings = r->nset - 1;
  t->paper = paper_state(c);
  t->step = c->st.step;
  t->grid = -1;
  r->nt++;
}

void ura_report_end(uraCtx* c, int rc) {
  uraReport* r = c->rep;
  if (!r || !r->want) return;
  if (rc) push_warn(r, r->cmd, c->err);
  uraRepTable* t = r->nt && !strcmp(r->t[r->nt - 1].cmd, r->cmd) ? &r->t[r->nt - 1] : NULL;
  if (rc && t) t->failed = 1;
  /* the grid a grid or design compare command leaves (a difference grid is set after its
     table is printed), with the command's last table */
  if (!rc && t && (!strcmp(r->name, "grid") || !strcmp(r->name, "design")) && c->last.g) {
    r->busy = 1;
    t->grid = keep_grid(c, r);
    r->busy = 0;
  }
  r->want = 0;
}

static void free_list(char** p, int n) {
  for (int i = 0; p && i < n; i++) free(p[i]);
  free(p);
}

void ura_report_free(uraCtx* c) {
  uraReport* r = c->rep;
  if (!r) return;
  for (int i = 0; i < r->nt; i++) {
    uraRepTable* t = &r->t[i];
    free(t->cmd);
    free(t->name);
    free_list(t->names, t->ncol);
    free_list(t->cells, t->ncol * t->nrow);
    free_list(t->notes, t->nnote);
  }
  free(r->t);
  for (int i = 0; i < r->ng; i++) free(r->g[i].g.cell);
  free(r->g);
  free_list(r->settings, r->nset);
  free_list(r->warn, r->nwarn);
  free(r);
  c->rep = NULL;
}

void ura_report_install(uraCtx* c) {
  c->rep_begin = ura_report_begin;
  c->rep_end = ura_report_end;
  c->rep_table = ura_report_table;
}
