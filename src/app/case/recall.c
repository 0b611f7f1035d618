/* recall.c: complete grids kept for recall. A grid asked for again with everything a cell depends
 * on unchanged (the model: its parts and parameter overrides; the impact conditions: speed, angle,
 * face, pitch, roll, yaw, tau; the lattice: step and extents; the injury settings) is a copy of the
 * kept one instead of a computation. The worker threads are left out: the cells do not depend on
 * them. Partial or failed grids are never kept. At most uraRECALLGRIDS grids and uraRECALLBYTES
 * of cells, the least recently used freed first; 'set recall off' neither recalls nor keeps.
 */
#include <stdlib.h>
#include <string.h>

#include "case.h"


typedef struct {
  uraModelKey model;
  urImpactCond cond;
  double step;
  int set[3];                        /* along_min, along_max, cross_max set */
  double par_min, par_max, perp_max; /* when set (0 when derived) */
  urInjuryParams injury;
  int mirror; /* set mirror (a mirrored half differs from its own cells in the last bits) */
} gridKey;

typedef struct {
  gridKey key;
  urGrid* g;
  size_t bytes;
  unsigned long used;
} entry;

struct uraRecall {
  entry e[uraRECALLGRIDS];
  int n;
  size_t bytes;
};

static void key_of(uraCtx* c, const urImpactCond* cond, gridKey* k) {
  memset(k, 0, sizeof *k);
  ura_model_key(c, &c->st, &k->model);
  k->cond = *cond;
  k->step = c->st.step;
  k->mirror = c->st.mirror;
  k->set[0] = c->st.par_min_set;
  k->set[1] = c->st.par_max_set;
  k->set[2] = c->st.perp_max_set;
  if (k->set[0]) k->par_min = c->st.par_min;
  if (k->set[1]) k->par_max = c->st.par_max;
  if (k->set[2]) k->perp_max = c->st.perp_max;
  k->injury = c->st.injury;
}

/* equal to the bit */
static int same(double a, double b) {
  return !memcmp(&a, &b, sizeof a);
}

static int key_same(const gridKey* a, const gridKey* b) {
  const urImpactCond *x = &a->cond, *y = &b->cond;
  if (!same(x->speed, y->speed) || !same(x->angle, y->angle) || !same(x->face, y->face) ||
      !same(x->pitch, y->pitch) || !same(x->roll, y->roll) || !same(x->yaw, y->yaw) ||
      x->tau != y->tau || x->aim != y->aim || a->mirror != b->mirror || !same(a->step, b->step) ||
      memcmp(a->set, b->set, sizeof a->set) || !same(a->par_min, b->par_min) ||
      !same(a->par_max, b->par_max) || !same(a->perp_max, b->perp_max)) {
    return 0;
  }
  /* every injury setting, through the named table (which covers the whole struct) */
  const char* name;
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) {
    double u, v;
    ur_injury_param_get(&a->injury, name, &u);
    ur_injury_param_get(&b->injury, name, &v);
    if (!same(u, v)) return 0;
  }
  return ura_model_key_same(&a->model, &b->model);
}

static size_t grid_bytes(const urGrid* g) {
  return sizeof *g + (size_t)g->nrow * g->ncol * sizeof(urCell);
}

static urGrid* grid_copy(const urGrid* g) {
  urGrid* d = malloc(sizeof *d);
  size_t n = (size_t)g->nrow * g->ncol;
  urCell* cell = malloc(n * sizeof(urCell));
  if (!d || !cell) {
    free(d);
    free(cell);
    return NULL;
  }
  *d = *g;
  d->cell = cell;
  memcpy(cell, g->cell, n * sizeof(urCell));
  return d;
}

static void drop(uraRecall* r, int i) {
  r->bytes -= r->e[i].bytes;
  ur_grid_free(r->e[i].g);
  r->e[i] = r->e[--r->n];
}

urGrid* ura_recall_find(uraCtx* c, const urImpactCond* cond) {
  uraRecall* r = c->recall;
  if (!c->st.recall || !r) return NULL;
  gridKey k;
  key_of(c, cond, &k);
  for (int i = 0; i < r->n; i++) {
    if (!key_same(&k, &r->e[i].key)) continue;
    r->e[i].used = ++c->tick;
    return grid_copy(r->e[i].g);
  }
  return NULL;
}

void ura_recall_keep(uraCtx* c, const urImpactCond* cond, const urGrid* g) {
  if (!c->st.recall || !g->complete || grid_bytes(g) > (size_t)uraRECALLBYTES) return;
  if (!c->recall && !(c->recall = calloc(1, sizeof *c->recall))) return;
  uraRecall* r = c->recall;
  entry e = {.bytes = grid_bytes(g), .used = ++c->tick};
  key_of(c, cond, &e.key);
  for (int i = r->n - 1; i >= 0; i--) {
    if (key_same(&e.key, &r->e[i].key)) drop(r, i);
  }
  if (!(e.g = grid_copy(g))) return;

  /* room: the least recently used go */
  while (r->n == uraRECALLGRIDS || r->bytes + e.bytes > (size_t)uraRECALLBYTES) {
    int old = 0;
    for (int i = 1; i < r->n; i++) {
      if (r->e[i].used < r->e[old].used) old = i;
    }
    drop(r, old);
  }
  r->e[r->n++] = e;
  r->bytes += e.bytes;
}

void ura_recall_flush(uraCtx* c) {
  if (!c->recall) return;
  while (c->recall->n) drop(c->recall, 0);
  free(c->recall);
  c->recall = NULL;
}
