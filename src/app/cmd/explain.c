/* explain.c: a zero that has a reason says it. compare's p_centre is 0 when the impact aimed at
 * the head's centre misses (under wind the footprint moves downstream, off the centre); the note
 * names where the grid's P is largest (of equal ones the nearest to the centre). */
#include <stdio.h>

#include "cmd.h"


void ura_explain_centre(uraTable* t, const urImpactResult* r, const urGrid* g) {
  if (r->p > 0) return;
  const urCell* best = NULL;
  for (size_t i = 0; g && i < (size_t)g->nrow * g->ncol; i++) {
    const urCell* cl = g->cell + i;
    /* the largest P; of equal ones the nearest to the centre */
    if (cl->status != urCELL_DONE) continue;
    double d = cl->dpar * cl->dpar + cl->dperp * cl->dperp;
    if (!best || cl->p > best->p ||
        (cl->p == best->p && d < best->dpar * best->dpar + best->dperp * best->dperp)) {
      best = cl;
    }
  }
  const char* why = r->contact ? "the impact at (0, 0) touches the person but no criterion "
                                 "reaches a fatality probability"
                               : "the impact at (0, 0) does not touch the person";
  if (best && best->p > 0) {
    ura_table_note(t,
                   "p_centre 0: %s; the footprint is off the centre (peak P %.3f at (%g, %g) "
                   "m), so factor is 0",
                   why, best->p, best->dpar, best->dperp);
  } else {
    ura_table_note(t, "p_centre 0: %s", why);
  }
}
