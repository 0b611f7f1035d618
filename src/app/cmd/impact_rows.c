/* impact_rows.c: the rows of impacts (impact, impact aim, compare): the full row (every value
 * and PoF column of the criteria in use) and, at a terminal, the compact row in 80 columns: the
 * criteria and their probabilities, the Nij modes and the contact in a note. Off a terminal
 * (scripts, -c, pipes) and with 'set format wide' the full row is printed instead. */
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

/* the columns of impact rows: dpar,dperp,contact, the row values of the criteria in use, their
   PoF columns, p (the paper's criteria: hic15,nij,nij_tf,nij_te,nij_cf,nij_ce,vc_thorax,
   vc_abdomen,p_hic,p_nij,p_vc) */
uraTable* ura_impact_table(const urInjuryParams* ip) {
  const char* cols[3 + urNVAL + urNCRIT + 1] = {"dpar", "dperp", "contact"};
  int n = 3;
  for (int v = 0; v < urNVAL; v++) {
    if (ur_value_shown(v, urIN_ROW, ip)) cols[n++] = ur_value_def(v)->name;
  }
  for (int k = 0; k < urNCRIT; k++) {
    if (ur_criterion_used(k, ip)) cols[n++] = ur_criterion(k)->pof_col;
  }
  cols[n++] = "p";
  return ura_table_new(n, cols);
}

void ura_impact_cells(uraTable* t, const urInjuryParams* ip, double dpar, double dperp,
                      const urImpactResult* r) {
  ura_table_cell(t, "%g", dpar);
  ura_table_cell(t, "%g", dperp);
  ura_table_cell(t, "%d", r->contact);
  for (int v = 0; v < urNVAL; v++) {
    if (ur_value_shown(v, urIN_ROW, ip)) ura_table_cell(t, "%.6g", r->inj.val[v]);
  }
  for (int k = 0; k < urNCRIT; k++) {
    if (ur_criterion_used(k, ip)) ura_table_cell(t, "%.6g", r->inj.pof[k]);
  }
  ura_table_cell(t, "%.6g", r->p);
}
