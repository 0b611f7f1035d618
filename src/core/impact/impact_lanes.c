/* impact_lanes.c: many impacts on one thread, urIMPACT_LANES at a time in lock-step over the
 * engine's lanes (ur_step_lanes). A lane whose run is over hands its result on and takes the
 * next offset at once, so the lanes stay full until the offsets run out. */
#include <stdlib.h>
#include <string.h>

#include "../engine/engine_internal.h"
#include "impact_internal.h"

_Static_assert(urIMPACT_LANES == urNLANE, "impact lanes are the engine's lanes");

struct urImpactLanes {
  urLanes lanes;
  urImpactWork w[urNLANE];
};

urImpactLanes* ur_impact_lanes_new(const urImpactSetup* s) {
  urImpactLanes* L = calloc(1, sizeof *L);
  if (!L) return NULL;
  if (ur_lanes_init(s->m, &L->lanes)) {
    free(L);
    return NULL;
  }
  for (int l = 0; l < urNLANE; l++) {
    if (ur_impact_work_init(s, &L->w[l])) {
      ur_impact_lanes_free(L);
      return NULL;
    }
  }
  return L;
}

void ur_impact_lanes_free(urImpactLanes* L) {
  if (!L) return;
  for (int l = 0; l < urNLANE; l++) ur_impact_work_free(&L->w[l]);
  ur_lanes_free(&L->lanes);
  free(L);
}

/* the runs in the lanes: work, result so far, exit time, caller's tag */
typedef struct {
  urImpactWork w;
  urImpactResult r;
  double texit;
  void* tag;
} slot;

/* start the next offset in slot k; 0 if none is left. A run that is over at once (e.g. a bad
   start) is finished and handed on here. */
static int fill(const urImpactSetup* s, slot* k, const urImpactCond* c, const urInjuryParams* ip,
                urImpactNextFn next, urImpactDoneFn done, void* ctx) {
  double dpar, dperp;
  while (next(ctx, &dpar, &dperp, &k->tag)) {
    ur_impact_begin(s, &k->w, c, dpar, dperp, &k->r, &k->texit);
    if (k->w.d->status == urSTAT_OK) return 1;
    done(ctx, k->tag, ur_impact_finish(s, &k->w, ip, &k->r), &k->r, &k->w);
  }
  return 0;
}

void ur_impact_run_many(const urImpactSetup* s, urImpactLanes* L, const urImpactCond* c,
                        const urInjuryParams* ip, urImpactNextFn next, urImpactDoneFn done,
                        void* ctx) {
  slot sl[urNLANE];
  urData* d[urNLANE];
  int n = 0;
  for (int l = 0; l < urNLANE; l++) sl[l].w = L->w[l];
  while (n < urNLANE && fill(s, &sl[n], c, ip, next, done, ctx)) n++;

  while (n > 0) {
    for (int l = 0; l < n; l++) d[l] = sl[l].w.d;
    ur_step_lanes(s->m, d, n, &L->lanes);

    /* finished runs hand on their results; their lanes take the next offsets, or the last
       running lane moves into the gap */
    for (int l = 0; l < n;) {
      int e = ur_impact_after_step(s, &sl[l].w, sl[l].texit, ip, &sl[l].r);
      if (e == 0) {
        l++;
        continue;
      }
      int rc = e < 0 ? -1 : ur_impact_finish(s, &sl[l].w, ip, &sl[l].r);
      done(ctx, sl[l].tag, rc, &sl[l].r, &sl[l].w);
      if (fill(s, &sl[l], c, ip, next, done, ctx)) {
        l++;
        continue;
      }
      n--;
      slot t = sl[l];
      sl[l] = sl[n];
      sl[n] = t;
    }
  }
}
