/* cmd_grid.c: the grid command: run the offset grid, print its cells, show or load it */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

void ura_last_free(uraCtx* c) {
  ur_grid_free(c->last.g);
  memset(&c->last, 0, sizeof c->last);
}

/* every cell of the last grid: dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p */
static int grid_cells(uraCtx* c) {
  static const char* const cols[] = {"dpar", "dperp", "contact", "hic15", "nij", "vc_thorax",
                                     "vc_abdomen", "p"};
  urGrid* g = c->last.g;
  if (!g) return ura_fail(c, "grid cells: no grid yet; run 'grid' or 'grid load FILE'");
  uraTable* t = ura_table_new(8, cols);
  ura_table_note(t, "grid of case %s, wind %g m/s, face %g deg (%s); status: %s", 
                 c->last.casename, c->last.wind, c->last.face, c->last.source,
                 g->complete ? "complete" : "PARTIAL");
  for (int k = 0; k < g->nrow * g->ncol; k++) {
    const urCell* e = &g->cell[k];
    if (e->status == urCELL_PENDING || e->status == urCELL_FAILED) continue;
    ura_table_cell(t, "%.3f", e->dpar);
    ura_table_cell(t, "%.3f", e->dperp);
    ura_table_cell(t, "%d", e->contact);
    ura_table_cell(t, "%.6g", e->hic15);
    ura_table_cell(t, "%.6g", e->nij);
    ura_table_cell(t, "%.6g", e->vc_thorax);
    ura_table_cell(t, "%.6g", e->vc_abdomen);
    ura_table_cell(t, "%.6g", e->p);
  }
  ura_table_print(c, t);
  return 0;
}

int ura_cmd_grid(uraCtx* c, int argc, char** argv) {
  if (argc == 1) {
    return ura_fail(c, "grid: the impact simulation of the human and drone models is not built "
                    "yet; 'grid load FILE' views a grid CSV");
  }
  if (!strcmp(argv[1], "cells") && argc == 2) return grid_cells(c);
  if (!strcmp(argv[1], "show") && argc == 2) return ura_grid_show(c);
  if (!strcmp(argv[1], "load") && argc == 3) return ura_grid_load(c, argv[2]);
  return ura_fail(c, "grid: usage: grid [show|cells|load FILE]");
}
