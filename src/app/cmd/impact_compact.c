/* impact_compact.c: the impact row at a terminal, in 80 columns: the criteria and their
 * probabilities, the Nij modes and the contact in a note. Off a terminal (scripts, -c, pipes) and
 * with 'set format wide' the full row of ura_impact_table is printed instead. */
#include <math.h>
#include <stdio.h>

#include "cmd.h"


static const char* const compact_cols[] = {"dpar",  "dperp", "hic15", "nij",  "vc_th",
                                           "vc_ab", "p_hic", "p_nij", "p_vc", "p"};

int ura_impact_compact(const uraCtx* c) {
  return ura_text_width(c) > 0;
}

uraTable* ura_impact_compact_table(void) {
  return ura_table_new(10, compact_cols);
}

void ura_impact_compact_row(uraTable* t, double dpar, double dperp, const urImpactResult* r) {
  static const char* const modes[] = {"NTF", "NTE", "NCF", "NCE"};
  int m = 0;
  for (int k = 1; k < 4; k++) {
    if (r->inj.nij.mode[k] > r->inj.nij.mode[m]) m = k;
  }
  if (!r->contact) {
    ura_table_note(t,
                   "no contact: the drone passes the person at this offset; every criterion "
                   "and P are 0");
  } else {
    ura_table_note(t,
                   "Nij %s (NTF %.3g, NTE %.3g, NCF %.3g, NCE %.3g); vc_th, vc_ab: VC "
                   "in m/s",
                   modes[m], r->inj.nij.mode[0], r->inj.nij.mode[1], r->inj.nij.mode[2],
                   r->inj.nij.mode[3]);
  }
  ura_table_cell(t, "%g", dpar);
  ura_table_cell(t, "%g", dperp);
  ura_table_cell(t, "%.0f", r->inj.hic15.hic);
  ura_table_cell(t, "%.3f", r->inj.nij.nij);
  ura_table_cell(t, "%.3f", r->inj.vc_thorax.vc);
  ura_table_cell(t, "%.3f", r->inj.vc_abdomen.vc);
  ura_table_cell(t, "%.3f", r->inj.pof[urCRIT_HIC]);
  ura_table_cell(t, "%.3f", r->inj.pof[urCRIT_NIJ]);
  ura_table_cell(t, "%.3f", r->inj.pof[urCRIT_VC]);
  ura_table_cell(t, "%.3f", r->p);
}
