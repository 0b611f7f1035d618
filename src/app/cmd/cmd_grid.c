/* cmd_grid.c: the grid command: run the offset grid, print its cells, show or load it */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cmd.h"

#define MAXCELLS 4000000L      /* largest grid (and region scanned for its extents), cells */
#define STOPPED  "interrupted" /* reason of a cell whose impact Ctrl-C stopped */
#define RECALLED                                                                                   \
  "recalled: the cells of an identical grid computed earlier in this session "                     \
  "(same model, conditions, step, extents and injury settings); nothing was "                      \
  "simulated now ('set recall off' recomputes)"

typedef struct {
  const urImpactSetup* s;
  urImpactCond cond;
  const urInjuryParams* ip;
  urImpactLanes** lanes; /* per worker */
  int tty;
} gridRun;

static int cb_may(void* ctx, double dpar, double dperp) {
  gridRun* g = ctx;
  return ur_impact_may_contact(g->s, &g->cond, dpar, dperp);
}

/* a cell from its impact result */
static int cell_result(urCell* cell, int rc, const urImpactResult* r) {
  if (rc) {
    snprintf(cell->reason, sizeof cell->reason, "%.63s",
             r->status == urSTAT_STOPPED ? STOPPED : r->reason);
    return -1;
  }
  cell->contact = r->contact;
  memcpy(cell->val, r->inj.val, sizeof cell->val);
  memcpy(cell->pof, r->inj.pof, sizeof cell->pof);
  cell->p = r->contact ? r->p : 0.0;
  cell->extrap = r->nextrap;
  return 0;
}

/* a worker's cells through the lanes of ur_impact_run_many */
typedef struct {
  urCellTakeFn take;
  urCellPutFn put;
  void* feed;
} cellFeed;

static int feed_next(void* ctx, double* dpar, double* dperp, void** tag) {
  cellFeed* f = ctx;
  urCell* cell = f->take(f->feed);
  if (!cell) return 0;
  *dpar = cell->dpar;
  *dperp = cell->dperp;
  *tag = cell;
  return 1;
}

static void feed_done(void* ctx, void* tag, int rc, const urImpactResult* r,
                      const urImpactWork* w) {
  (void)w;
  cellFeed* f = ctx;
  urCell* cell = tag;
  f->put(f->feed, cell, cell_result(cell, rc, r));
}

static void cb_stream(void* ctx, int worker, urCellTakeFn take, urCellPutFn put, void* feed) {
  gridRun* g = ctx;
  cellFeed f = {take, put, feed};
  ur_impact_run_many(g->s, g->lanes[worker], &g->cond, g->ip, feed_next, feed_done, &f);
}

static void cb_progress(void* ctx, int done, int total) {
  gridRun* g = ctx;
  if (g->tty && (done == total || done % 8 == 0)) {
    ura_progress_line("grid:", done, total, "impacts");
    if (done == total) fputs("\r\033[K", stderr);
  }
}

/* the lattice extents: every cell whose straight path can touch the person, found by scanning
   the region the path can reach (upstream as far as the drone travels while it descends from
   R_max above the head to the ground; all of it moved downstream by the tau shift when Delta is
   taken at head-top level, cond->tau), padded by one cell. A region larger than MAXCELLS is
   refused before it is scanned (its size in *scan); Ctrl-C stops the scan. 0 or -1. */
static int auto_extents(const urImpactSetup* s, const urImpactCond* cond, double step,
                        double* par_min, double* par_max, double* perp_max, double* scan) {
  double psi = cond->angle * M_PI / 180.0, reach = 2.0, shift = ur_impact_tau_shift(s, cond);
  double up = psi < M_PI / 2 - 1e-9 ? (s->head_top + s->rmax) / tan(psi) : 0;
  double flo = floor((shift - up - reach) / step), fhi = ceil((reach + shift) / step);
  double fj = ceil(reach / step);
  *scan = (fhi - flo + 1) * (2 * fj + 1);
  if (!(*scan <= MAXCELLS)) return -1;
  long ilo = (long)flo, ihi = (long)fhi, jmax = (long)fj;
  long lo = 0, hi = 0, kp = 0;
  int found = 0; /* the rows found so far are lo..hi */
  for (long i = ilo; i <= ihi && !ura_interrupted(); i++) {
    for (long j = -jmax; j <= jmax; j++) {
      if (ur_impact_may_contact(s, cond, i * step, j * step)) {
        if (!found || i < lo) lo = i;
        if (!found || i > hi) hi = i;
        if (labs(j) > kp) kp = labs(j);
        found = 1;
      }
    }
  }
  if (ura_interrupted()) return -1;
  *par_min = (lo - 1) * step;
  *par_max = (hi + 1) * step;
  *perp_max = (kp + 1) * step;
  return 0;
}

/* the memory a grid of n cells needs may not exceed half of the memory available */
static int fits_memory(long n, double* mb, double* avail_mb) {
  long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  *mb = n * (double)sizeof(urCell) / 1e6;
  *avail_mb = pages > 0 && size > 0 ? (double)pages * size / 1e6 : INFINITY;
  return *mb <= *avail_mb / 2;
}

/* the scene is mirror-symmetric about the course up to the face: no roll or yaw (the drone, the
   person and the wind along the course are symmetric), so face -phi is face phi mirrored */
int ura_grid_symmetric(const uraState* st) {
  return st->roll == 0 && st->yaw == 0;
}

int ura_grid_mirror(uraCtx* c, char* why, size_t n) {
  double f = fmod(fabs(c->st.face), 180.0);
  const urModel* m = NULL;
  const char* no = !c->st.mirror                 ? "set mirror off"
                   : !ura_grid_symmetric(&c->st) ? "roll or yaw breaks the symmetry"
                   : f != 0                      ? "the face is neither 0 nor 180 deg"
                   : !(m = ura_model(c))         ? c->err
                   : !m->mirror                  ? m->nomirror
                                                 : NULL;
  if (why) snprintf(why, n, "%s", no ? no : "");
  /* the model's failure is said in why; an earlier error is not this function's to clear */
  if (no == c->err) c->err[0] = 0;
  return no == NULL;
}

static double seconds_since(const struct timespec* t0) {
  struct timespec t1;
  clock_gettime(CLOCK_MONOTONIC, &t1);
  return (t1.tv_sec - t0->tv_sec) + 1e-9 * (t1.tv_nsec - t0->tv_nsec);
}

/* g becomes the last grid, with the live case's conditions (s: the set-up it was computed on) */
static void keep_last(uraCtx* c, urGrid* g, const urImpactCond* cond, int recalled,
                      const urImpactSetup* s) {
  ura_last_free(c);
  c->last.g = g;
  snprintf(c->last.casename, sizeof c->last.casename, "%s", c->st.casename);
  c->last.wind = c->st.descent.wind;
  c->last.face = c->st.face;
  c->last.speed = cond->speed;
  c->last.angle = cond->angle;
  c->last.paper_speed = ura_paper_speed(c);
  c->last.tau = cond->tau;
  c->last.tau_shift = s ? ur_impact_tau_shift(s, cond) : 0;
  snprintf(c->last.source, sizeof c->last.source, "computed");
  c->last.recalled = recalled;
  c->last.extents_set = c->st.par_min_set || c->st.par_max_set || c->st.perp_max_set;
}

/* the extents of the live case's grid: those set, the others derived (auto_extents). 0; -1
   with *nscan the cells a refused scan would have needed, or 0 after another failure (the
   error set) */
static int extents(uraCtx* c, const urImpactSetup* s, const urImpactCond* cond, double* par_min,
                   double* par_max, double* perp_max, long* nscan) {
  const uraState* st = &c->st;
  *nscan = 0;
  if (!st->par_min_set || !st->par_max_set || !st->perp_max_set) {
    double scan;
    if (auto_extents(s, cond, st->step, par_min, par_max, perp_max, &scan)) {
      if (ura_interrupted()) return ura_fail(c, "grid: interrupted (Ctrl-C) while sizing the grid");
      *nscan = scan > 1e18 ? -1 : (long)scan;
      return -1;
    }
  }
  if (st->par_min_set) *par_min = st->par_min;
  if (st->par_max_set) *par_max = st->par_max;
  if (st->perp_max_set) *perp_max = st->perp_max;
  if (*par_min > *par_max) {
    return ura_fail(c,
                    "grid: along_min %g m is above along_max %g m; accepted: along_min <= "
                    "along_max (or 'auto' for either)",
                    *par_min, *par_max);
  }
  return 0;
}

int ura_grid_extents(uraCtx* c, double* par_min, double* par_max, double* perp_max) {
  urImpactCond cond;
  if (ura_dry(c, "simulation") || ura_impact_cond(c, &cond)) return -1;
  const urImpactSetup* s = ura_setup(c);
  long nscan;
  if (!s) return -1;
  if (extents(c, s, &cond, par_min, par_max, perp_max, &nscan)) {
    if (nscan == 0) return -1;
    return ura_fail(c,
                    "grid: the region to scan for the extents is too large; accepted: a "
                    "larger 'step', or set along_min, along_max and cross_max");
  }
  return 0;
}

/* run the grid of the live case into c->last (or recall an identical earlier one: recall.c) */
int ura_grid_run(uraCtx* c, int quiet) {
  struct timespec t0;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  urImpactCond cond;
  if (ura_dry(c, "simulation") || ura_impact_cond(c, &cond)) return -1;
  urGrid* old = ura_recall_find(c, &cond);
  if (old) {
    old->seconds = seconds_since(&t0);
    /* the tau shift needs R_max: the set-up of the live model (settled already, or kept) */
    keep_last(c, old, &cond, 1, cond.tau == urTAU_RMAX ? NULL : ura_setup(c));
    return 0;
  }
  const urImpactSetup* s = ura_setup(c);
  if (!s) return -1;

  /* extents, lattice, refusing what memory cannot hold */
  urGridSpec spec = {c->st.step,          0,      0,    0,           ura_grid_mirror(c, NULL, 0),
                     (int)c->st.threads,  cb_may, NULL, cb_progress, NULL,
                     ura_interrupt_flag()};
  long ncell;
  double mb = 0, avail = 0;
  const char* what = "";
  if (extents(c, s, &cond, &spec.par_min, &spec.par_max, &spec.perp_max, &ncell)) {
    if (ncell == 0) return -1;
    what = " to scan for the extents";
  } else {
    ncell = ur_grid_cell_count(&spec);
  }
  int fits = fits_memory(ncell < 0 ? 0 : ncell, &mb, &avail);
  if (ncell < 0 || ncell > MAXCELLS || !fits) {
    char size[64];
    if (ncell < 0)
      snprintf(size, sizeof size, "more than %ld", MAXCELLS);
    else
      snprintf(size, sizeof size, "%ld", ncell);
    return ura_fail(c,
                    "grid: %s cells of %g m%s (%.0f MB; %.0f MB of memory available) is too "
                    "large; accepted: at most %ld cells in half the available memory (raise "
                    "'step' or narrow along_min, along_max, cross_max)",
                    size, spec.step, what, mb, avail, MAXCELLS);
  }
  urGrid* g = ur_grid_new(&spec);
  int nw = spec.threads;
  urImpactLanes** w = calloc(nw, sizeof *w);
  if (!g || !w) {
    ur_grid_free(g);
    free(w);
    return ura_fail(c, "grid: out of memory for %ld cells", ncell);
  }
  for (int i = 0; i < nw; i++) {
    if (!(w[i] = ur_impact_lanes_new(s))) {
      for (int k = 0; k < i; k++) ur_impact_lanes_free(w[k]);
      free(w);
      ur_grid_free(g);
      return ura_fail(c, "grid: out of memory for the work spaces");
    }
  }

  /* run, each worker's cells in lock-step lanes; Ctrl-C (interrupt.c) stops the workers and the
     impacts they are running */
  gridRun run = {s, cond, &c->st.injury, w, !quiet && isatty(STDERR_FILENO)};
  spec.ctx = &run;
  spec.impact_stream = cb_stream;
  if (run.tty) ura_progress_start();
  urGridDist dist;
  /* cells split over processes (scale.h: its hook, set with c->scale) */
  if (c->scale && c->scale_grid) c->scale_grid(c, &spec, &dist);
  int rc = ur_grid_run(g, &spec);
  for (int i = 0; i < nw; i++) ur_impact_lanes_free(w[i]);
  free(w);
  if (run.tty) fputs("\r\033[K", stderr);
  if (rc) {
    ur_grid_free(g);
    if (rc == -2) return -1; /* the distributor said why */
    return ura_fail(c, "grid: out of memory for %ld cells", ncell);
  }

  /* an impact stopped halfway is not a failure: the cell was not computed */
  for (long k = 0; k < (long)g->nrow * g->ncol; k++) {
    urCell* e = &g->cell[k];
    if (e->status == urCELL_FAILED && !strcmp(e->reason, STOPPED)) {
      double dpar = e->dpar, dperp = e->dperp;
      memset(e, 0, sizeof *e);
      e->dpar = dpar;
      e->dperp = dperp;
      e->status = urCELL_PENDING;
    }
  }
  ur_grid_summarise(g);

  /* keep it as the last grid, and a complete one for recall */
  keep_last(c, g, &cond, 0, s);
  ura_recall_keep(c, &cond, g);
  if (g->npending) {
    return ura_fail(c,
                    "grid: interrupted (Ctrl-C); %d of %d cells finished, kept as a partial "
                    "grid (no Q)",
                    g->ndone + g->nfailed, g->nrow * g->ncol);
  }
  return 0;
}

/* the summary row of the last grid */
static int grid_summary(uraCtx* c) {
  /* complete last: the columns before it keep their places of the earlier versions */
  static const char* const cols[] = {"case", "wind",    "speed",   "angle",
                                     "face", "step",    "cells",   "contact_cells",
                                     "q",    "seconds", "complete"};
  urGrid* g = c->last.g;
  uraTable* t = ura_table_new(11, cols);
  if (!g->complete) {
    ura_table_note(t,
                   "PARTIAL grid (complete 0): %d cells failed, %d not computed; q sums the "
                   "finished cells only, a lower bound of Q",
                   g->nfailed, g->npending);
  }
  /* the impacts taken as mirror images (the grid's mirror rule: set mirror, show mirror) */
  int nmir = 0;
  for (long k = 0; k < (long)g->nrow * g->ncol; k++) {
    nmir += g->cell[k].mirrored && g->cell[k].status == urCELL_DONE;
  }
  char mir[160] = "";
  if (nmir) {
    snprintf(mir, sizeof mir,
             ", %d their mirror images (dperp < 0: the model and the scene are "
             "mirror-symmetric)",
             nmir);
  }
  ura_table_note(t,
                 "Q = sum of P{F|Delta} x %g m x %g m over the %s (eq. 4.5); "
                 "%d impacts simulated%s%s, %d cells decided geometrically",
                 g->step, g->step, c->last.extents_set ? "grid's cells" : "full plane",
                 g->nsimulated, c->last.recalled ? " when it was computed" : "", mir,
                 g->nrow * g->ncol - g->nsimulated - nmir - g->npending - g->nfailed);
  if (c->last.extents_set) {
    ura_table_note(t,
                   "extents set: Q covers only along %g .. %g m, |cross| <= %g m (cells where "
                   "contact is possible outside them are not counted)",
                   g->par_max - (g->nrow - 1) * g->step, g->par_max, -g->perp_min);
  }
  if (g->nextrap) {
    ura_table_note(t,
                   "%d of the impacts used a law beyond its data (extrapolated: 'grid cells' "
                   "lists them, 'impact' names the law)",
                   g->nextrap);
  }
  if (c->last.recalled) ura_table_note(t, "%s", RECALLED);
  if (!strcmp(c->last.source, "computed")) {
    ura_cond_notes(t, c->last.casename, c->last.wind, c->last.paper_speed, c->last.tau,
                   c->last.tau_shift);
  }
  ura_table_cell(t, "%s", c->last.casename);
  ura_table_cell(t, "%g", c->last.wind);
  ura_table_cell(t, "%.3f", c->last.speed);
  ura_table_cell(t, "%.2f", c->last.angle);
  ura_table_cell(t, "%g", c->last.face);
  ura_table_cell(t, "%g", g->step);
  ura_table_cell(t, "%d", g->nrow * g->ncol);
  ura_table_cell(t, "%d", g->ncontact);
  ura_table_cell(t, "%.4f", g->q); /* numeric always; complete says whether it is Q */
  ura_table_cell(t, "%.2f", g->seconds);
  ura_table_cell(t, "%d", g->complete ? 1 : 0);
  ura_table_print(c, t);
  for (int k = 0; k < g->nrow * g->ncol; k++) {
    if (g->cell[k].status == urCELL_FAILED && !g->cell[k].mirrored) {
      fprintf(c->msg, "grid: cell (%g, %g) failed: %s\n", g->cell[k].dpar, g->cell[k].dperp,
              g->cell[k].reason);
    }
  }
  return 0;
}

/* every cell of the last grid: dpar,dperp,contact, the cell values of the criteria in use
   (hic15,nij,vc_thorax,vc_abdomen by default), p */
static int grid_cells(uraCtx* c) {
  const char* cols[3 + urNVAL + 1] = {"dpar", "dperp", "contact"};
  int vals[urNVAL], nval = 0, ncol = 3;
  for (int v = 0; v < urNVAL; v++) {
    if (!ur_value_shown(v, urIN_CELL, &c->st.injury)) continue;
    vals[nval++] = v;
    cols[ncol++] = ur_value_def(v)->name;
  }
  cols[ncol++] = "p";
  urGrid* g = c->last.g;
  if (!g) return ura_fail(c, "grid cells: no grid yet; run 'grid' or 'grid load FILE'");
  uraTable* t = ura_table_new(ncol, cols);
  ura_table_note(t, "grid of case %s, wind %g m/s, face %g deg (%s); status: %s%s",
                 c->last.casename, c->last.wind, c->last.face, c->last.source,
                 g->complete ? "complete" : "PARTIAL",
                 c->last.tau == urTAU_TOP ? "; tau top (Delta at head-top level)" : "");
  if (g->nextrap) {
    char list[uraERRLEN] = "";
    size_t len = 0;
    int shown = 0;
    for (int k = 0; k < g->nrow * g->ncol && shown < 8; k++) {
      const urCell* e = &g->cell[k];
      if (!e->extrap || e->mirrored || e->status != urCELL_DONE) continue;
      int w = snprintf(list + len, sizeof list - len, " (%g, %g)", e->dpar, e->dperp);
      if (w < 0 || (size_t)w >= sizeof list - len) break;
      len += (size_t)w;
      shown++;
    }
    ura_table_note(t, "extrapolated: %d simulated cells used a law beyond its data:%s%s",
                   g->nextrap, list, g->nextrap > shown ? " ..." : "");
  }
  for (int k = 0; k < g->nrow * g->ncol; k++) {
    const urCell* e = &g->cell[k];
    if (e->status == urCELL_PENDING || e->status == urCELL_FAILED) continue;
    ura_table_cell(t, "%.3f", e->dpar);
    ura_table_cell(t, "%.3f", e->dperp);
    ura_table_cell(t, "%d", e->contact);
    for (int i = 0; i < nval; i++) ura_table_cell(t, "%.6g", e->val[vals[i]]);
    ura_table_cell(t, "%.6g", e->p);
  }
  ura_table_print(c, t);
  return 0;
}

int ura_cmd_grid(uraCtx* c, int argc, char** argv) {
  if (argc == 1) {
    int rc = ura_grid_run(c, 0);
    if (c->last.g) {
      char keep[uraERRLEN];
      snprintf(keep, sizeof keep, "%s", c->err);
      grid_summary(c);
      snprintf(c->err, sizeof c->err, "%s", keep);
    }
    if (rc == 0 && !c->last.g->complete) {
      return ura_fail(c,
                      "grid: %d cells failed (their simulations are listed above); Q is not "
                      "complete",
                      c->last.g->nfailed);
    }
    return rc;
  }
  if (!strcmp(argv[1], "cells") && argc == 2) return grid_cells(c);
  if (!strcmp(argv[1], "show") && argc == 2) return ura_grid_show(c);
  if (!strcmp(argv[1], "load") && argc == 3) return ura_grid_load(c, argv[2]);
  return ura_fail(c, "grid: usage: grid [show|cells|load FILE]");
}
