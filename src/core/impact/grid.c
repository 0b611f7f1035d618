/* grid.c: offset lattice, parallel runner over cells, mirror rule and the Q sum (eq. 4.5) */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "uasimpact/grid.h"

#define SNAP 1e-9 /* tolerance when rounding extents to the lattice */

/* lattice indices of a spec: rows from kpar_hi down to kpar_lo, columns -kperp..kperp */
static int lattice(const urGridSpec* s, long* kpar_hi, long* kpar_lo, long* kperp) {
  if (!(s->step > 0) || !isfinite(s->step) || !isfinite(s->par_min) || !isfinite(s->par_max) ||
      !isfinite(s->perp_max) || s->par_max < s->par_min || s->perp_max < 0) {
    return -1;
  }
  double hi = ceil(s->par_max / s->step - SNAP), lo = floor(s->par_min / s->step + SNAP);
  double kp = ceil(s->perp_max / s->step - SNAP);
  if (hi - lo > 1e7 || kp > 1e7) return -1;
  *kpar_hi = (long)hi;
  *kpar_lo = (long)lo;
  *kperp = (long)kp;
  return 0;
}

long ur_grid_cell_count(const urGridSpec* s) {
  long hi, lo, kp;
  if (lattice(s, &hi, &lo, &kp)) return -1;
  return (hi - lo + 1) * (2 * kp + 1);
}

urGrid* ur_grid_new(const urGridSpec* s) {
  long hi, lo, kp;
  if (lattice(s, &hi, &lo, &kp)) return NULL;
  urGrid* g = calloc(1, sizeof *g);
  if (!g) return NULL;
  g->nrow = (int)(hi - lo + 1);
  g->ncol = (int)(2 * kp + 1);
  g->step = s->step;
  g->par_max = hi * s->step;
  g->perp_min = -kp * s->step;
  g->cell = calloc((size_t)g->nrow * g->ncol, sizeof(urCell));
  if (!g->cell) {
    free(g);
    return NULL;
  }

  /* offsets from integer indices, so that no rounding accumulates */
  for (int i = 0; i < g->nrow; i++) {
    for (int j = 0; j < g->ncol; j++) {
      urCell* c = &g->cell[(size_t)i * g->ncol + j];
      c->dpar = (hi - i) * s->step;
      c->dperp = (j - kp) * s->step;
      if (c->dpar == 0) c->dpar = 0; /* no negative zero */
      if (c->dperp == 0) c->dperp = 0;
    }
  }
  ur_grid_summarise(g);
  return g;
}

void ur_grid_free(urGrid* g) {
  if (!g) return;
  free(g->cell);
  free(g);
}

urCell* ur_grid_at(urGrid* g, int row, int col) {
  if (!g || row < 0 || col < 0 || row >= g->nrow || col >= g->ncol) return NULL;
  return &g->cell[(size_t)row * g->ncol + col];
}

urCell* ur_grid_find(urGrid* g, double dpar, double dperp) {
  if (!g) return NULL;
  int row = (int)lround((g->par_max - dpar) / g->step);
  int col = (int)lround((dperp - g->perp_min) / g->step);
  return ur_grid_at(g, row, col);
}

void ur_grid_summarise(urGrid* g) {
  double q = 0;
  g->ndone = g->ncontact = g->nfailed = g->npending = g->nsimulated = g->nextrap = 0;
  for (long k = 0; k < (long)g->nrow * g->ncol; k++) {
    const urCell* c = &g->cell[k];
    switch (c->status) {
    case urCELL_PENDING: g->npending++; break;
    case urCELL_FAILED: g->nfailed++; break;
    case urCELL_NOCONTACT: g->ndone++; break;
    case urCELL_DONE:
      g->ndone++;
      if (!c->mirrored) g->nsimulated++;
      if (c->contact) g->ncontact++;
      if (c->extrap && !c->mirrored) g->nextrap++;
      q += c->p;
      break;
    }
  }
  g->q = q * g->step * g->step;
  g->complete = g->npending == 0 && g->nfailed == 0;
}

/* ---- parallel runner ---- */

typedef struct {
  urGrid* g;
  const urGridSpec* s;
  long* todo; /* indices of the cells to simulate */
  long ntodo;
  long next; /* next index of todo to take (atomic) */
  long finished;
  pthread_mutex_t lock; /* serialises progress callbacks */
} runShared;

typedef struct {
  runShared* sh;
  int id;
} runWorker;

/* the next cell of the list, reset to pending with its offsets; NULL when none is left or a
   stop was asked */
static urCell* take(void* feed) {
  runWorker* w = feed;
  runShared* sh = w->sh;
  if (sh->s->stop && *sh->s->stop) return NULL;
  const urGridDist* d = sh->s->dist;
  long k = d ? d->next(d->ctx) : __atomic_fetch_add(&sh->next, 1, __ATOMIC_RELAXED);
  if (k < 0 || k >= sh->ntodo) return NULL;
  urCell* c = &sh->g->cell[sh->todo[k]];
  double dpar = c->dpar, dperp = c->dperp;
  memset(c, 0, sizeof *c);
  c->dpar = dpar;
  c->dperp = dperp;
  return c;
}

/* a finished cell: its status (a failure keeps its reason), then progress, one caller at a time */
static void put(void* feed, urCell* c, int rc) {
  runWorker* w = feed;
  runShared* sh = w->sh;
  if (rc == 0) {
    c->status = urCELL_DONE;
  } else {
    c->status = urCELL_FAILED;
    if (!c->reason[0]) strcpy(c->reason, "simulation failed");
  }
  pthread_mutex_lock(&sh->lock);
  sh->finished++;
  if (sh->s->progress) sh->s->progress(sh->s->ctx, (int)sh->finished, (int)sh->ntodo);
  pthread_mutex_unlock(&sh->lock);
}

static void* worker(void* arg) {
  runWorker* w = arg;
  const urGridSpec* s = w->sh->s;
  if (s->impact_stream) {
    s->impact_stream(s->ctx, w->id, take, put, w);
    return NULL;
  }
  urCell* c;
  while ((c = take(w))) put(w, c, s->impact(s->ctx, w->id, c));
  return NULL;
}

int ur_grid_run(urGrid* g, const urGridSpec* s) {
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  long n = (long)g->nrow * g->ncol, kp = (g->ncol - 1) / 2;

  /* decide every primary cell geometrically; collect those to simulate */
  long* todo = malloc(n * sizeof(long));
  if (!todo) return -1;
  long ntodo = 0;
  for (long k = 0; k < n; k++) {
    urCell* c = &g->cell[k];
    long j = k % g->ncol;
    c->mirrored = 0;
    if (s->mirror && j < kp) continue; /* filled from its mirror cell afterwards */
    if (s->may_contact && !s->may_contact(s->ctx, c->dpar, c->dperp)) {
      double dpar = c->dpar, dperp = c->dperp;
      memset(c, 0, sizeof *c);
      c->dpar = dpar;
      c->dperp = dperp;
      c->status = urCELL_NOCONTACT;
    } else {
      c->status = urCELL_PENDING;
      todo[ntodo++] = k;
    }
  }

  /* workers over the list (or this process's share of it) */
  const urGridDist* d = s->dist;
  if (d && d->begin(d->ctx, ntodo)) {
    free(todo);
    return -2;
  }
  runShared sh = {g, s, todo, ntodo, 0, 0};
  pthread_mutex_init(&sh.lock, NULL);
  int nt = s->threads < 1 ? 1 : s->threads;
  if (nt > 256) nt = 256;
  pthread_t th[256];
  runWorker w[256];
  int started = 0;
  for (int i = 0; i < nt; i++) {
    w[i].sh = &sh;
    w[i].id = i;
    if (i == 0) continue;
    if (pthread_create(&th[i], NULL, worker, &w[i]) == 0)
      started = i;
    else
      break;
  }
  worker(&w[0]);
  for (int i = 1; i <= started; i++) pthread_join(th[i], NULL);
  pthread_mutex_destroy(&sh.lock);
  int bad = d && d->end(d->ctx, g, todo, ntodo);
  free(todo);
  if (bad) return -2;

  /* mirror rule: column -j is column +j with the cross offset negated */
  if (s->mirror) {
    for (int i = 0; i < g->nrow; i++) {
      for (long j = 0; j < kp; j++) {
        urCell* dst = &g->cell[(size_t)i * g->ncol + j];
        const urCell* src = &g->cell[(size_t)i * g->ncol + (2 * kp - j)];
        double dperp = dst->dperp;
        *dst = *src;
        dst->dperp = dperp;
        dst->mirrored = 1;
      }
    }
  }

  ur_grid_summarise(g);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  g->seconds = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
  return 0;
}
