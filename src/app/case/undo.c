/* undo.c: the states before the last commands that changed the live case, for undo. Each
 * command typed or read from a script (a sourced file as a whole) that leaves the settings
 * (uraState: the case, every parameter, the model parameter overrides, the risk settings and
 * distributions) different from before pushes the state it found; undo makes the newest one
 * live again, compiling the model for its overrides, and pops it. uraUNDO_LEVELS are kept; the
 * oldest goes first. What is not a setting (the model parts loaded, grids, sweeps, designs kept)
 * is not undone: undo says so in uasimpact(1). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"


struct uraUndo {
  uraState st[uraUNDO_LEVELS];
  char what[uraUNDO_LEVELS][64]; /* the command that changed the state */
  int n, head;                   /* levels held; the slot of the next push */
};

void ura_undo_push(uraCtx* c, const uraState* before, const char* what) {
  if (!c->undo && !(c->undo = calloc(1, sizeof *c->undo))) return; /* no undo, nothing lost */
  uraUndo* u = c->undo;
  memcpy(&u->st[u->head], before, sizeof *before);
  snprintf(u->what[u->head], sizeof u->what[0], "%s", what);
  u->head = (u->head + 1) % uraUNDO_LEVELS;
  if (u->n < uraUNDO_LEVELS) u->n++;
}

int ura_undo_levels(const uraCtx* c) {
  return c->undo ? c->undo->n : 0;
}

int ura_undo_pop(uraCtx* c, char* what, size_t n) {
  uraUndo* u = c->undo;
  if (!u || !u->n) {
    return ura_fail(c,
                    "undo: nothing to undo (the settings are as the session began, or the "
                    "last %d changes were undone)",
                    uraUNDO_LEVELS);
  }
  int at = (u->head + uraUNDO_LEVELS - 1) % uraUNDO_LEVELS;
  uraState back;
  memcpy(&back, &u->st[at], sizeof back);
  snprintf(what, n, "%s", u->what[at]);
  u->head = at;
  u->n--;
  /* a level the model no longer takes (its parts changed since) is dropped, not kept in the
     way of the levels before it */
  if (ura_model_state(c, &back, "undo")) {
    char why[uraERRLEN];
    snprintf(why, sizeof why, "%s", c->err);
    return ura_fail(c, "%.700s; the settings before '%s' are dropped (%d more level%s to undo)",
                    why, what, u->n, u->n == 1 ? "" : "s");
  }
  return 0;
}

void ura_undo_free(uraCtx* c) {
  free(c->undo);
  c->undo = NULL;
}
