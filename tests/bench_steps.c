/* bench_steps.c: where a grid's steps go (issue 36). For the zero-wind grids of cases A, B and
 * C and B's 10 m/s grid (0.05 m, face 0, as the 'grid' command runs them), every simulated cell's
 * impact is run again alone (ur_impact_run: the lanes give the same runs bit for bit) and its
 * steps are split into phases: before the first contact, the contact phase (first to last
 * active contact), and after separation to the run's end; how runs end (contact over for
 * t_quiet or t_clear, the window after first contact, the drone passed without touching,
 * settled, tmax); and the steps after the last criterion in use took its final value (the end of
 * the HIC window, the Nij and VC peaks): what an end of run on final values could save at most.
 *   bench_steps [STEP [SETTINGS]]   grid pitch in m, default 0.05; SETTINGS: commands run after
 *                                   each grid's case, e.g. 'set t_clear 0.002'
 * Counts, not times: the figures do not depend on the machine's load. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/app/ui/ui.h"

/* the tallies of one grid */
typedef struct {
  long cells, sims, nocontact; /* lattice cells, simulated, simulated without contact */
  long pre, con, post;         /* steps before contact, in contact, after it */
  long nosteps;                /* steps of the runs without contact */
  long after_final;            /* steps after the criteria's last final value */
  long end[6];                 /* separated, window, passed, settled, tmax, other */
  long window_active;          /* runs ended by the window with contact still active */
  long proved;                 /* runs ended by the clear proof before t_quiet */
  double q;                    /* the grid's Q */
} tally;

/* the time by which every criterion of the fusion has its final value: the end of the HIC
   window, the samples of the Nij and VC maxima */
static double final_time(const urImpactWork* w, const urImpactResult* r) {
  const urData* d = w->d;
  const double* t = w->chan; /* ur_impact_finish leaves the times in the first channel */
  double tf = r->inj.hic.t2;
  if (r->inj.nij.imax >= 0 && r->inj.nij.imax < d->nhist) tf = fmax(tf, t[r->inj.nij.imax]);
  tf = fmax(tf, r->inj.vc_thorax.t);
  tf = fmax(tf, r->inj.vc_abdomen.t);
  return tf;
}

/* every simulated cell of the live case's grid, run alone and counted */
static int count(uraCtx* c, const char* setup, double step, const char* more, tally* y) {
  char line[512];
  memset(y, 0, sizeof *y);
  snprintf(line, sizeof line, "%s; set step %g; set threads 2; %s", setup, step, more);
  if (ura_run_line(c, line) || ura_grid_run(c, 1)) {
    fprintf(stderr, "bench_steps: '%s': %s\n", line, c->err);
    return -1;
  }
  const urImpactSetup* s = ura_setup(c);
  urImpactCond cond;
  urImpactWork w;
  if (!s || ura_impact_cond(c, &cond) || ur_impact_work_init(s, &w)) return -1;
  const urGrid* g = c->last.g;
  double dt = s->m->opt.dt;
  y->q = g->q;
  y->cells = (long)g->nrow * g->ncol;
  for (long k = 0; k < y->cells; k++) {
    const urCell* cell = &g->cell[k];
    if (cell->mirrored || cell->status != urCELL_DONE) continue;
    urImpactResult r;
    if (ur_impact_run(s, &w, &cond, &c->st.injury, cell->dpar, cell->dperp, &r)) {
      fprintf(stderr, "bench_steps: (%g, %g): %s\n", cell->dpar, cell->dperp, r.reason);
      ur_impact_work_free(&w);
      return -1;
    }
    const urData* d = w.d;
    y->sims++;
    int e = d->status == urSTAT_SEPARATED ? 0
            : d->status == urSTAT_OK      ? (d->t_first >= 0 ? 1 : 2)
            : d->status == urSTAT_SETTLED ? 3
            : d->status == urSTAT_TMAX    ? 4
                                          : 5;
    y->end[e]++;
    if (d->t_first < 0) {
      y->nocontact++;
      y->nosteps += d->nstep;
      continue;
    }
    long pre = lround((d->t_first - d->t_jump) / dt);
    long con = lround((d->t_last - d->t_first) / dt);
    y->pre += pre;
    y->con += con;
    y->post += d->nstep - pre - con;
    if (e == 1 && d->time - d->t_last < 1.5 * dt) y->window_active++;
    if (e == 0 && d->time - d->t_last < s->m->opt.t_quiet - 0.5 * dt) y->proved++;
    double tf = final_time(&w, &r);
    if (d->time > tf) y->after_final += lround((d->time - tf) / dt) - 1;
  }
  ur_impact_work_free(&w);
  return 0;
}

static void report(const char* name, const tally* y) {
  long contact = y->sims - y->nocontact, all = y->pre + y->con + y->post + y->nosteps;
  printf("  %-9s Q %.4f  %5ld cells, %4ld simulated (%ld without contact), %ld steps\n", name, y->q,
         y->cells, y->sims, y->nocontact, all);
  printf(
      "            per impact with contact: %5.0f before contact, %5.0f in contact, %5.0f after "
      "separation; %5.0f after the last final value\n",
      (double)y->pre / contact, (double)y->con / contact, (double)y->post / contact,
      (double)y->after_final / contact);
  printf("            runs without contact: %5.0f steps each (%4.1f %% of all steps)\n",
         y->nocontact ? (double)y->nosteps / y->nocontact : 0.0, 100.0 * y->nosteps / all);
  printf(
      "            shares of all steps: before %4.1f %%, contact %4.1f %%, after %4.1f %%; after "
      "the last final value %4.1f %%\n",
      100.0 * y->pre / all, 100.0 * y->con / all, 100.0 * y->post / all,
      100.0 * y->after_final / all);
  printf(
      "            ends: contact over %ld (%ld proved clear before t_quiet), window %ld (%ld in "
      "contact), passed %ld, settled %ld, tmax %ld, other %ld\n",
      y->end[0], y->proved, y->end[1], y->window_active, y->end[2], y->end[3], y->end[4],
      y->end[5]);
}

int main(int argc, char** argv) {
  double step = argc > 1 ? atof(argv[1]) : 0.05;
  const char* more = argc > 2 ? argv[2] : "";
  static uraCtx ctx;
  uraCtx* c = &ctx;
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  if (!c->model || !c->out || ura_run_line(c, "set recall off")) {
    fprintf(stderr, "bench_steps: no model: %s\n", c->err);
    return 1;
  }
  static const char* const names[] = {"A, 0 m/s", "B, 0 m/s", "C, 0 m/s", "B, 10 m/s"};
  static const char* const setups[] = {
      "set wind 0; set face 0; case A", "set wind 0; set face 0; case B",
      "set wind 0; set face 0; case C", "set wind 10; set face 0; case B"};
  printf("bench_steps: where the steps of grids of step %g m go (counts, not times)%s%s\n", step,
         more[0] ? "; settings: " : "", more);
  for (int i = 0; i < 4; i++) {
    tally y;
    if (count(c, setups[i], step, more, &y)) return 1;
    report(names[i], &y);
  }
  ura_last_free(c);
  ura_models_free(c);
  fclose(c->out);
  return 0;
}
