/* modelcache.c: compiled models with their settled stance, kept for the parameter-override sets
 * seen earlier in the session. Switching back to a case (or a setting) makes the kept model live
 * again instead of compiling it and settling its stance anew (balance and settle: about 0.3 s).
 * The live model is c->model with c->setup; the cache holds up to uraMODELCACHE others, each
 * balanced and settled (ur_impact_balance shifts neutral positions in the model: the kept model
 * is the balanced one), the least recently used freed first. Models are swapped only between
 * commands, never while a grid's workers use the live one. New model parts keep the entries
 * as stance donors only (their keys name the old parts, so none is taken again).
 * The kept set-ups are also the donors of a new model's stance (ura_mcache_setups): when its
 * person is byte for byte that of a kept model (a drone or airbag setting changed, e.g.
 * 'set bag_p0 1.1 atm' or case A -> B), ur_impact_prepare takes that model's balanced neutral
 * positions and settled person instead of settling, with bitwise the same set-up (impact.h).
 */
#include <stdlib.h>
#include <string.h>

#include "case.h"


typedef struct {
  uraModelKey key;
  urModel* model;
  urImpactSetup setup;
  unsigned long used; /* c->tick when parked */
} entry;

struct uraModelCache {
  entry e[uraMODELCACHE];
  int n;
};

void ura_model_key(const uraCtx* c, const uraState* st, uraModelKey* k) {
  memset(k, 0, sizeof *k);
  k->gen = c->parts_gen;
  k->nov = st->nov;
  for (int i = 0; i < st->nov; i++) {
    memcpy(k->ov_name[i], st->ov_name[i], urNAMELEN);
    k->ov_val[i] = st->ov_val[i];
  }
}

/* the same parts and the same set of overrides (names are unique within a set), values equal to
   the bit */
int ura_model_key_same(const uraModelKey* a, const uraModelKey* b) {
  if (a->gen != b->gen || a->nov != b->nov) return 0;
  for (int i = 0; i < a->nov; i++) {
    int found = 0;
    for (int j = 0; j < b->nov && !found; j++) {
      found = !strcmp(a->ov_name[i], b->ov_name[j]) &&
              !memcmp(&a->ov_val[i], &b->ov_val[j], sizeof(double));
    }
    if (!found) return 0;
  }
  return 1;
}

static void entry_free(entry* e) {
  ur_impact_free(&e->setup);
  ur_model_free(e->model);
}

void ura_mcache_park(uraCtx* c) {
  /* an impact's histories belong to the model it ran on */
  if (c->have_work) ur_impact_work_free(&c->work);
  c->have_work = 0;
  c->have_impact = 0;
  if (c->model && c->have_setup && !c->mcache) c->mcache = calloc(1, sizeof *c->mcache);
  if (!c->model || !c->have_setup || !c->mcache) {
    ura_model_stale(c);
    return;
  }

  /* room: the least recently used goes */
  uraModelCache* mc = c->mcache;
  if (mc->n == uraMODELCACHE) {
    int old = 0;
    for (int i = 1; i < mc->n; i++) {
      if (mc->e[i].used < mc->e[old].used) old = i;
    }
    entry_free(&mc->e[old]);
    mc->e[old] = mc->e[--mc->n];
  }
  entry* e = &mc->e[mc->n++];
  ura_model_key(c, &c->st, &e->key);
  e->model = c->model;
  e->setup = c->setup;
  e->used = ++c->tick;
  c->model = NULL;
  c->have_setup = 0;
}

int ura_mcache_take(uraCtx* c, const uraState* ns) {
  uraModelCache* mc = c->mcache;
  if (!mc) return 0;
  uraModelKey k;
  ura_model_key(c, ns, &k);
  for (int i = 0; i < mc->n; i++) {
    if (!ura_model_key_same(&k, &mc->e[i].key)) continue;
    entry e = mc->e[i];
    mc->e[i] = mc->e[--mc->n];
    ura_mcache_park(c);
    c->model = e.model;
    c->setup = e.setup;
    c->have_setup = 1;
    return 1;
  }
  return 0;
}

int ura_mcache_setups(const uraCtx* c, const urImpactSetup** out, int max) {
  const uraModelCache* mc = c->mcache;
  int n = 0;
  for (int i = 0; mc && i < mc->n && n < max; i++) out[n++] = &mc->e[i].setup;
  return n;
}

void ura_mcache_flush(uraCtx* c) {
  if (!c->mcache) return;
  for (int i = 0; i < c->mcache->n; i++) entry_free(&c->mcache->e[i]);
  free(c->mcache);
  c->mcache = NULL;
}

void ura_model_stale(uraCtx* c) {
  ur_model_free(c->model);
  c->model = NULL;
  if (c->have_setup) ur_impact_free(&c->setup);
  c->have_setup = 0;
  if (c->have_work) ur_impact_work_free(&c->work);
  c->have_work = 0;
  c->have_impact = 0;
}
