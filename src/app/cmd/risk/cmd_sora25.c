/* cmd_sora25.c: what sora and risk print for a submission under SORA 2.5 (include/uasimpact/
 * sora25.h): the iGRC from Table 2 by characteristic dimension and maximum speed beside the
 * quantitative iGRC from a critical area (clamped into the table with a note), the M2 evidence
 * (the reduction factor of Q and of the Annex F area against the unmitigated drone, a design
 * kept by 'design save' (m2_baseline design:NAME) or Table B.8, its interval, the integrity
 * level it reaches and what a simulation cannot show), and the paper's eq. (1.1): expected
 * fatalities per flight hour per population density band against the target. cmd_risk.c calls these; the tables' columns are documented in uasimpact(1), SORA FIGURES.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../cmd.h"
#include "uasimpact/sora25.h"

static const char* const col_names[urSORA25_NCOL] = {"1 m / 25 m/s", "3 m / 35 m/s", "8 m / 75 m/s",
                                                     "20 m / 120 m/s", "40 m / 200 m/s"};

const char* ura_sora25_col_name(int col) {
  return col >= 0 && col < urSORA25_NCOL ? col_names[col] : "outside Table 2";
}

/* the characteristic dimension is the RA3's for another drone: width and length at the
   workbench's defaults (the RA3's; no preset or set changed them) while the built-in RA3 part is
   not loaded */
static int dim_of_ra3(const uraCtx* c) {
  for (int i = 0; i < c->npart; i++) {
    if (!strcmp(c->part[i].name, "ra3") && !strcmp(c->part[i].origin, "built-in")) return 0;
  }
  uraState* d = malloc(sizeof *d);
  if (!d) return 0;
  ura_state_defaults(d);
  int same = c->st.para.width == d->para.width && c->st.para.length == d->para.length;
  free(d);
  return same;
}

void ura_sora25_inputs(uraCtx* c, double unmit_speed, uraSora25* s) {
  const uraRiskSet* r = &c->st.risk;
  s->dim_set = r->ua_dim_set;
  s->dim_ra3 = !r->ua_dim_set && dim_of_ra3(c);
  s->dim = r->ua_dim_set ? r->ua_dim : fmax(c->st.para.width, c->st.para.length);
  s->speed_set = r->ua_speed_set;
  s->speed = r->ua_speed_set ? r->ua_speed : unmit_speed;
  s->density = ura_risk_density_max(r);
  s->col = ur_sora25_column(s->dim, s->speed);
  s->row = ur_sora25_row(s->density, 0);
  s->igrc = s->col >= 0 ? ur_sora25_cell(s->row, s->col) : -1;
  s->mass = c->st.descent.mass;
  s->small = ur_sora25_small_ua(s->mass, s->speed, s->row);
  if (s->small) s->igrc = 1;
  s->nclamp = 0;
}

void ura_sora25_cells(uraTable* t, uraSora25* s, int igrc_quant, int ok, double ca) {
  if (s->igrc > 0)
    ura_table_cell(t, "%d", s->igrc);
  else
    ura_table_cell(t, "%s", s->igrc == 0 ? "grey" : "none");
  if (!ok) {
    ura_table_cell(t, "none");
    return;
  }
  int where, col = ur_sora25_column_ca(ca);
  int g = ur_sora25_clamp(igrc_quant, col, &where);
  ura_table_cell(t, "%d", g);
  if (where) s->nclamp++;
}

void ura_sora25_notes(uraTable* t, const uraSora25* s) {
  ura_table_note(t,
                 "igrc_sora25: the iGRC a submission uses, SORA 2.5 Table 2 (EASA AMC1 Art. 11, ED "
                 "Decision 2025/018/R, p. 24; JARUS SORA 2.5 Table 2): column %s, the rightmost "
                 "matching both the characteristic dimension %g m (%s) and the maximum speed %g "
                 "m/s (%s), row %s for the highest density %g ppl/km^2%s",
                 ura_sora25_col_name(s->col), s->dim, s->dim_set ? "ua_dimension" : "width, length",
                 s->speed, s->speed_set ? "ua_max_speed" : "derived", ur_sora25_row_label(s->row),
                 s->density,
                 s->igrc == 0  ? ": grey cell, not part of SORA (certified category)"
                 : s->igrc < 0 ? ": outside the table (Annex F appendices A and B)"
                               : "");
  if (s->small) {
    ura_table_note(t,
                   "igrc_sora25 1: a take-off mass of %g kg (<= 250 g) and a maximum speed of %g "
                   "m/s (<= 25 m/s) give an iGRC of 1 whatever the density, unless over "
                   "assemblies of people (the note under Table 2, p. 24); the table's cell is %d",
                   s->mass, s->speed, ur_sora25_cell(s->row, s->col));
  }
  if (s->dim_ra3) {
    ura_table_note(t,
                   "warning: the characteristic dimension is not the drone's: width and length "
                   "are the workbench's defaults, the RA3's (%g m), and the loaded drone's "
                   "presets do not set them: 'set ua_dimension D' (or width and length) with the "
                   "drone's",
                   s->dim);
  }
  if (!s->speed_set) {
    ura_table_note(t,
                   "maximum speed: the unmitigated impact speed stands in for the designer's "
                   "maximum commanded airspeed, which Table 2 asks for (S.4.2.4(b)): 'set "
                   "ua_max_speed V'");
  }
  ura_table_note(
      t,
      "igrc_quant: the quantitative iGRC from the row's critical area (igrc above, Annex "
      "F's formula), clamped into Table 2's column matching that area (Annex B Table "
      "B.8: 6.5, 65, 650, 6 500, 65 000 m^2) between 1 and the column's highest value%s",
      s->nclamp ? "" : "; no value needed clamping");
  if (s->nclamp) {
    ura_table_note(t,
                   "clamped: %d value%s of igrc lay outside the table (below 1, or beyond the "
                   "column: the certified category); igrc_quant holds the clamped value",
                   s->nclamp, s->nclamp == 1 ? "" : "s");
  }
}

static const char* const level_names[] = {"none", "medium", "high"};

int ura_sora25_m2_table(uraCtx* c, const uraSora25* s, const uraSoraFig fig[4], const char* design,
                        int from_mc, const double* named) {
  static const char* const cols[] = {"quantity",     "baseline", "design",     "factor",
                                     "lo95",         "hi95",     "orders",     "reduction_pct",
                                     "m2_integrity", "m2_lo95",  "grc_credit", "final_grc"};
  const uraRiskSet* r = &c->st.risk;
  const char* dname = "";
  int kind = ura_m2_baseline(r, &dname), b8 = kind == uraM2_TABLE_B8, nd = named != NULL;
  char base_text[200];
  if (b8)
    snprintf(base_text, sizeof base_text,
             "Annex B Table B.8's critical area of the Table 2 column");
  else if (nd)
    snprintf(base_text, sizeof base_text,
             "design %s (its grids under the live deployment mixture, wind, face, altitude and "
             "step)",
             dname);
  else
    snprintf(base_text, sizeof base_text, "the unmitigated drone (no parachute, no airbag: %s%s)",
             strcmp(ura_risk_none_name(c), "C") ? "branch " : "case ", ura_risk_none_name(c));
  if (b8 && s->col < 0) {
    return ura_fail(c,
                    "sora: m2_baseline table_b8 needs a Table 2 column; the drone (%g m, %g m/s) "
                    "is outside it; accepted: set m2_baseline unmitigated",
                    s->dim, s->speed);
  }
  uraTable* t = ura_table_new(12, cols);
  ura_table_note(t,
                 "M2 evidence (SORA 2.5 Annex B B.5, integrity criterion #1, p. 92): the risk to "
                 "the population is reduced by about 1 order of magnitude (90 %%, medium, credit "
                 "-1) or 2 (99 %%, high, credit -2, and the activation must be automated); Table 5 "
                 "p. 29: M2 low n/a");
  ura_table_note(t,
                 "factor = baseline / design: %s over case %s%s; lo95..hi95 %s; m2_lo95 the level "
                 "its lower bound reaches; final_grc = igrc_sora25 + grc_credit, not below the "
                 "column's controlled-area value (Annex B Table B.1 #8), M1 not applied",
                 base_text, design,
                 b8 ? "" : " with its deployment mixture (p_chute, p_bag, h_chute_min)",
                 from_mc ? "its 95 % interval from the last montecarlo (delta method)"
                         : "equal to it (deterministic: 'sora mc' gives the interval)");
  if (nd && from_mc) {
    ura_table_note(t,
                   "baseline design %s: deterministic, its grids at the live wind %g m/s and face "
                   "%g deg, not drawn with the montecarlo's inputs; lo95..hi95 carry the live "
                   "design's interval only ('sora' without mc compares both at the same "
                   "conditions)",
                   dname, c->st.descent.wind, c->st.face);
  }
  if (b8) {
    ura_table_note(t,
                   "warning: with the Table B.8 baseline a critical area already matched to a "
                   "column in Step #2 is credited twice (column change and M2); Annex B p. 91 "
                   "asks for B.8 only when Step #2 used it");
  }
  int any_beyond = 0, any_final_out = 0;
  for (int k = 0; k < 2; k++) {
    const uraSoraFig* u = &fig[k]; /* unmitigated */
    const uraSoraFig* d = &fig[2 + k];
    double base = b8 ? ur_sora25_ca[s->col] : nd ? named[k] : u->ca;
    urM2 m, mlo;
    int ok = ur_sora25_m2(base, d->ca, &m) == 0;
    /* a fixed baseline over the design's interval; the unmitigated one is paired (delta method) */
    double lo = b8 || nd ? base / d->hi : d->red_lo, hi = b8 || nd ? base / d->lo : d->red_hi;
    if (!from_mc) lo = hi = ok ? m.factor : NAN;
    int oklo = ok && lo > 0 && ur_sora25_m2(lo, 1, &mlo) == 0;
    ura_table_cell(t, "%s", k ? "annex_f" : "q");
    ura_table_cell(t, "%.6g", base);
    ura_table_cell(t, "%.6g", d->ca);
    if (!ok) {
      for (int j = 0; j < 9; j++) ura_table_cell(t, "none");
      continue;
    }
    ura_table_cell(t, "%.6g", m.factor);
    ura_table_cell(t, "%.6g", lo);
    ura_table_cell(t, "%.6g", hi);
    ura_table_cell(t, "%.3f", m.orders);
    ura_table_cell(t, "%.2f", m.percent);
    ura_table_cell(t, "%s", level_names[m.level]);
    ura_table_cell(t, "%s", oklo ? level_names[mlo.level] : "none");
    ura_table_cell(t, "%d", m.credit);
    if (s->igrc > 0) {
      int fin = ur_sora25_final(s->igrc, s->col, 0, m.credit);
      ura_table_cell(t, "%d", fin);
      any_final_out |= fin > urSORA25_FINAL_MAX;
    } else
      ura_table_cell(t, "none");
    any_beyond |= m.beyond;
  }
  if (any_final_out) {
    ura_table_note(t,
                   "final_grc above %d: outside the scope of the SORA (p. 5, p. 30): the "
                   "operation belongs to the certified category",
                   urSORA25_FINAL_MAX);
  }
  if (any_beyond) {
    ura_table_note(t,
                   "a factor of 1000 or more: more than Table 5's -2 only at the authority's "
                   "discretion and at high robustness (Annex B Table B.1 #10); not credited here");
  }
  ura_table_note(t,
                 "what a simulation cannot show: that the devices deploy (activation tests, the "
                 "reliability p_chute/p_bag is an input, not evidence), automatic activation "
                 "(high), that a failure of the mitigation does not degrade safety, immediate "
                 "post-impact hazards (fire, debris), procedures and training (criteria #2, #3), "
                 "and the assurance level: medium accepts simulation whose validity is justified "
                 "(Table B.10: the report's model validity section), high needs an EASA DVR");
  ura_table_print(c, t);
  return 0;
}

void ura_eq11_table(uraCtx* c, int n, const char* const* label, const double* q, const double* lo,
                    const double* hi, const char* source) {
  static const char* const cols[] = {"case", "density", "q",     "fatalities_per_fh", "lo95",
                                     "hi95", "tlos",    "meets", "density_limit"};
  const uraRiskSet* r = &c->st.risk;
  uraTable* t = ura_table_new(9, cols);
  ura_table_note(t,
                 "risk per flight hour, eq. (1.1) of the paper (Jiang, Blom, Rattanagraikanakorn "
                 "2025): E{n_F} = lambda_system x density x (1 - P_shelter) x Q, with "
                 "lambda_system %g /h, P_shelter %g, Q in m^2 (x 1e-6 km^2/m^2), per density band; "
                 "meets: at or below the target tlos %g /h (SORA 2.5 TLOS: 1e-6 fatalities per "
                 "flight hour); density_limit: the highest density that meets it",
                 r->lambda, r->p_shelter, r->tlos);
  ura_table_note(t, "%s", source);
  int bad = 0;
  for (int i = 0; i < n; i++) {
    for (int b = 0; b < r->npop; b++) {
      double rho = r->pop_density[b];
      double e = ur_fatality_rate(r->lambda, rho, r->p_shelter, q[i]);
      double el = ur_fatality_rate(r->lambda, rho, r->p_shelter, lo[i]);
      double eh = ur_fatality_rate(r->lambda, rho, r->p_shelter, hi[i]);
      ura_table_cell(t, "%s", label[i]);
      ura_table_cell(t, "%g", rho);
      ura_table_cell(t, "%.6g", q[i]);
      ura_table_cell(t, "%.4g", e);
      ura_table_cell(t, "%.4g", el);
      ura_table_cell(t, "%.4g", eh);
      ura_table_cell(t, "%g", r->tlos);
      ura_table_cell(t, "%s", eh <= r->tlos ? "yes" : e <= r->tlos ? "marginal" : "no");
      ura_table_cell(t, "%.4g", ur_density_limit(r->tlos, r->lambda, r->p_shelter, q[i]));
      bad |= lo[i] < 0;
    }
  }
  if (bad) ura_table_note(t, "a lower bound below 0 was kept as printed");
  ura_table_note(t,
                 "meets: yes (the whole interval at or below tlos), marginal (the value, not its "
                 "upper bound), no; lambda_system and P_shelter are inputs the study does not "
                 "compute");
  ura_table_print(c, t);
}
