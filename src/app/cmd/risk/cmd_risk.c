/* cmd_risk.c: risk (Q mixed over parachute and airbag deployment) and sora (the SORA 2.5
 * critical areas, iGRC and the mitigation's reduction factor); the deployment branches they
 * share with montecarlo are risk_branch.c's */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../cmd.h"
#include "uasimpact/sora.h"

/* fewer samples: 'sora mc' flags its intervals (the t interval's rule of thumb for a mean of
   skewed values) */
#define SORA_MC_MIN 30

/* ---- the branches of the live case ---- */

typedef struct {
  urDeploy dep;
  int bag[urMAXBAGS];
  urBranch br[urMAXBRANCH];
  int nbr;
  double q[urMAXBRANCH];     /* each branch's Q, m^2 */
  double mixed;              /* sum of weight q */
  double q_none;             /* Q without any device (the last branch) */
  double speed[2], angle[2]; /* impact conditions without and with the parachute */
  double ca[2];              /* their Annex F critical areas */
  double recalled;           /* branches whose grids were recalled */
} branches;

/* every branch's grid (and the Annex F areas without and with the parachute); the live state is
   restored afterwards, the last grid is the last branch's */
static int run_branches(uraCtx* c, const char* who, branches* b) {
  memset(b, 0, sizeof *b);
  if (ura_dry(c, "simulation") || ura_risk_devices(c, &c->st, &b->dep, b->bag)) return -1;
  b->nbr = ur_deploy_branches(&b->dep, b->br);
  uraState* orig = malloc(2 * sizeof *orig);
  if (!orig) return ura_fail(c, "%s: out of memory", who);
  uraState* ns = orig + 1;
  *orig = c->st;
  int rc = 0;
  const char* none = ura_risk_none_name(c);
  for (int i = 0; i < b->nbr && rc == 0; i++) {
    ura_risk_branch_state(orig, b->br[i].mask, &b->dep, b->bag, none, ns);
    rc = ura_risk_grid(c, ns, who, 0, &b->q[i]);
    if (rc == 0) {
      b->mixed += b->br[i].weight * b->q[i];
      b->recalled += c->last.recalled;
    }
    if (rc == 0 && (i == 0 || i == b->nbr - 1)) {
      int k = b->br[i].mask & 1;
      rc = ura_risk_annexf(c, ns, &b->ca[k], &b->speed[k], &b->angle[k]);
    }
  }
  b->q_none = b->q[b->nbr - 1];
  if (!b->dep.chute) {
    b->ca[1] = b->ca[0];
    b->speed[1] = b->speed[0];
    b->angle[1] = b->angle[0];
  }
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  if (ura_model_state(c, orig, who) && rc == 0)
    rc = -1;
  else
    snprintf(c->err, sizeof c->err, "%s", err);
  free(orig);
  return rc;
}

/* the notes every deployment table shares */
static void deploy_notes(uraCtx* c, uraTable* t, const branches* b) {
  const uraRiskSet* r = &c->st.risk;
  char fixed[800];
  int nfixed = ura_risk_fixed_bags(c, &b->dep, b->bag, fixed, sizeof fixed);
  if (!b->dep.chute) {
    ura_table_note(t,
                   "case %s carries no parachute (area_chute 0): one branch, nothing to "
                   "deploy",
                   c->st.casename);
    if (nfixed) ura_table_note(t, "%s", fixed);
    return;
  }
  ura_table_note(t,
                 "deployment: p_chute %g (the parachute deploys in time), p_bag %g (each of "
                 "%d airbag%s); failure at altitude %g m %s h_chute_min %g m%s",
                 r->p_chute, r->p_bag, b->dep.nbag, b->dep.nbag == 1 ? "" : "s",
                 c->st.descent.altitude, c->st.descent.altitude >= r->h_chute_min ? ">=" : "<",
                 r->h_chute_min,
                 c->st.descent.altitude < r->h_chute_min ? ": the parachute cannot help" : "");
  const char* none = ura_risk_none_name(c);
  ura_table_note(t,
                 "branch none: no parachute, and no airbag credited (the drone falls %s%s at "
                 "%.3f m/s, %.2f deg); with the parachute %.3f m/s, %.2f deg",
                 strcmp(none, "C") ? "without them" : "as case ", strcmp(none, "C") ? "" : none,
                 b->speed[0], b->angle[0], b->speed[1], b->angle[1]);
  if (nfixed) ura_table_note(t, "%s", fixed);
}

int ura_cmd_risk(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"branch", "weight", "q"};
  branches b;
  if (run_branches(c, "risk", &b)) return -1;
  uraTable* t = ura_table_new(3, cols);
  ura_table_note(t,
                 "Q of case %s at wind %g m/s, face %g deg mixed over the deployment "
                 "outcomes: mixed = sum of weight x q (one grid per branch, step %g m)",
                 c->st.casename, c->st.descent.wind, c->st.face, c->st.step);
  deploy_notes(c, t, &b);
  if (b.recalled) {
    ura_table_note(t,
                   "recalled: %g of the %d grids are identical to grids computed earlier in "
                   "this session ('set recall off' recomputes)",
                   b.recalled, b.nbr);
  }
  double wsum = 0;
  char name[64];
  for (int i = 0; i < b.nbr; i++) {
    ura_risk_branch_name(b.br[i].mask, &b.dep, b.bag, name, sizeof name);
    ura_table_cell(t, "%s", name);
    ura_table_cell(t, "%.6g", b.br[i].weight);
    ura_table_cell(t, "%.6f", b.q[i]);
    wsum += b.br[i].weight;
  }
  ura_table_cell(t, "mixed");
  ura_table_cell(t, "%.6g", wsum);
  ura_table_cell(t, "%.6f", b.mixed);
  ura_table_print(c, t);
  /* the unmitigated row named as sora names it: C for a model with case C, else none */
  const char* none = ura_risk_none_name(c);
  const char* lab[2] = {c->st.casename, none};
  double q[2] = {b.mixed, b.q_none};
  char qnote[200];
  snprintf(qnote, sizeof qnote,
           "Q: the mixed row (and %s %s, the unmitigated drone); deterministic "
           "(lo95 = hi95: 'sora mc' after montecarlo gives intervals)",
           strcmp(none, "C") ? "branch" : "case", none);
  ura_eq11_table(c, b.dep.chute ? 2 : 1, lab, q, q, q, qnote);
  return 0;
}

/* ---- sora ---- */

/* the rows a sora table changed: classes clamped to the table, interval bounds truncated */
typedef struct {
  char below[80], above[80], trunc[80]; /* "C q, A annex_f" */
} soraFlags;

/* append a row's name to a list of rows */
static void flag_row(char* list, size_t n, const char* casename, const char* model) {
  size_t k = strlen(list);
  snprintf(list + k, n - k, "%s%s %s", k ? ", " : "", casename, model);
}

static void sora_row(uraCtx* c, uraTable* t, const char* casename, const char* model,
                     const uraSoraFig* f, soraFlags* fl, uraSora25* s25) {
  double raw1;
  int g, gt;
  int ok = ura_risk_igrc(&c->st, f->ca, &raw1, &g, &gt) == 0;
  int g_formula = g; /* igrc_quant clamps it into the Table 2 column itself, and counts it */
  /* an area and a ratio of areas are >= 0: a t interval of few skewed samples may reach below */
  double lo = f->lo, red_lo = f->red_lo;
  if (lo < 0 || red_lo < 0) flag_row(fl->trunc, sizeof fl->trunc, casename, model);
  if (lo < 0) lo = 0;
  if (red_lo < 0) red_lo = 0;
  ura_table_cell(t, "%s", casename);
  ura_table_cell(t, "%s", model);
  ura_table_cell(t, "%.6g", f->ca);
  ura_table_cell(t, "%.6g", lo);
  ura_table_cell(t, "%.6g", f->hi);
  ura_table_cell(t, "%.6g", f->red);
  ura_table_cell(t, "%.6g", red_lo);
  ura_table_cell(t, "%.6g", f->red_hi);
  if (ok) {
    /* the classes as SORA 2.5's table holds them (igrc_raw keeps the formula's value) */
    int side = ur_igrc_clamp(&g);
    int side_t = ur_igrc_clamp(&gt);
    if (side < 0 || side_t < 0) flag_row(fl->below, sizeof fl->below, casename, model);
    if (side > 0 || side_t > 0) flag_row(fl->above, sizeof fl->above, casename, model);
    ura_table_cell(t, "%.1f", raw1);
    ura_table_cell(t, "%d", g);
    ura_table_cell(t, "%d", gt);
  } else {
    for (int k = 0; k < 3; k++) ura_table_cell(t, "none");
  }
  ura_sora25_cells(t, s25, g_formula, ok, f->ca);
}

/* the unmitigated drone's impact speed (Table 2's stand-in for the maximum speed) */
static int unmitigated_speed(uraCtx* c, double* speed) {
  urDeploy dep;
  int bag[urMAXBAGS];
  double ca, angle;
  uraState* ns = malloc(sizeof *ns);
  if (!ns) return ura_fail(c, "sora: out of memory");
  int rc = ura_risk_devices(c, &c->st, &dep, bag);
  if (rc == 0) {
    ura_risk_branch_state(&c->st, 0, &dep, bag, ura_risk_none_name(c), ns);
    rc = ura_risk_annexf(c, ns, &ca, speed, &angle);
  }
  free(ns);
  return rc;
}

/* notes for what sora_row changed, and for a montecarlo of too few samples */
static void sora_flag_notes(uraTable* t, const soraFlags* fl, int nsamples) {
  if (fl->below[0]) {
    ura_table_note(t,
                   "igrc, igrc_table of %s: the formula gives a class below %d, the lowest of "
                   "SORA 2.5's Table 2; shown as %d (igrc_raw is the formula's value)",
                   fl->below, urIGRC_TABLE_MIN, urIGRC_TABLE_MIN);
  }
  if (fl->above[0]) {
    ura_table_note(t,
                   "igrc, igrc_table of %s: the formula gives a class above %d, the highest of "
                   "SORA 2.5's Table 2 (beyond it an operation is outside SORA's scope: the "
                   "certified category); shown as %d (igrc_raw is the formula's value)",
                   fl->above, urIGRC_TABLE_MAX, urIGRC_TABLE_MAX);
  }
  if (fl->trunc[0]) {
    ura_table_note(t,
                   "lo95, red_lo95 of %s: truncated at 0 (an area and a ratio of areas are not "
                   "negative); the t interval is symmetric about the mean and reached below 0, "
                   "a sign that the samples are too few or too skewed for it",
                   fl->trunc);
  }
  if (nsamples > 0 && nsamples < SORA_MC_MIN) {
    ura_table_note(t,
                   "TOO FEW SAMPLES: %d; the 95 %% intervals take the mean as normally "
                   "distributed, which the skewed Q of few samples is not (a rule of thumb "
                   "asks for %d or more): run 'montecarlo N' with more",
                   nsamples, SORA_MC_MIN);
  }
}

/* the design that m2_baseline design:NAME names, or NULL with one line listing the kept ones */
static const uraState* named_design(uraCtx* c, const char* name) {
  const uraState* ds = ura_designs_state(c, name);
  if (!ds) {
    char names[uraERRLEN / 2];
    ura_designs_names(c, names, sizeof names);
    ura_fail(c,
             "sora: m2_baseline design:%s: no design '%s'; saved designs: %s ('design save NAME' "
             "keeps the live case)",
             name, name, names);
  }
  return ds;
}

/* the named design's Q mixed over the deployment branches (q[0]) and its Annex F area mixed
   over the parachute (q[1]), as run_branches computes the live design's: its model, devices and
   drone at the live wind, face, altitude, step and risk settings (p_chute, p_bag, h_chute_min);
   the live state is restored */
static int named_figures(uraCtx* c, const uraState* ds, double q[2]) {
  uraState* keep = malloc(2 * sizeof *keep);
  if (!keep) return ura_fail(c, "sora: out of memory");
  uraState* ns = keep + 1;
  *keep = c->st;
  *ns = *ds;
  ns->descent.wind = keep->descent.wind;
  ns->descent.altitude = keep->descent.altitude;
  ns->face = keep->face;
  ns->step = keep->step;
  ns->risk = keep->risk;
  ns->threads = keep->threads;
  ns->format = keep->format;
  ns->pager = keep->pager;
  branches b;
  int rc = ura_model_state(c, ns, "sora");
  if (rc == 0) rc = run_branches(c, "sora", &b);
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  if (ura_model_state(c, keep, "sora") && rc == 0)
    rc = -1;
  else
    snprintf(c->err, sizeof c->err, "%s", err);
  free(keep);
  if (rc) return -1;
  double pc = ur_deploy_chute(&b.dep);
  q[0] = b.mixed;
  q[1] = pc * b.ca[1] + (1 - pc) * b.ca[0];
  return 0;
}

/* a figure without interval */
static uraSoraFig fixed(double ca, double red) {
  uraSoraFig f = {ca, ca, ca, red, red, red};
  return f;
}

int ura_cmd_sora(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case",       "model",       "ca",        "lo95",     "hi95",
                                     "reduction",  "red_lo95",    "red_hi95",  "igrc_raw", "igrc",
                                     "igrc_table", "igrc_sora25", "igrc_quant"};
  if (argc == 2 && strcmp(argv[1], "mc")) {
    return ura_fail(c, "sora: unknown '%s'; accepted: sora, sora mc", argv[1]);
  }
  uraSoraFig fig[4];
  int mitigated;
  char note[600];
  branches b;
  double unmit_speed = 0, named[2];
  const char* dname = NULL;
  const uraState* ds = NULL;
  if (ura_m2_baseline(&c->st.risk, &dname) == uraM2_DESIGN && !(ds = named_design(c, dname)))
    return -1;
  if (argc == 2) {
    if (ura_mc_sora(c, fig, &mitigated, note, sizeof note)) return -1;
    if (unmitigated_speed(c, &unmit_speed)) return -1;
  } else {
    if (run_branches(c, "sora", &b)) return -1;
    double pc = ur_deploy_chute(&b.dep), ca_mix = pc * b.ca[1] + (1 - pc) * b.ca[0];
    fig[0] = fixed(b.q_none, 1);
    fig[1] = fixed(b.ca[0], 1);
    fig[2] = fixed(b.mixed, b.q_none / b.mixed);
    fig[3] = fixed(ca_mix, b.ca[0] / ca_mix);
    mitigated = b.dep.chute;
    unmit_speed = b.speed[0];
    snprintf(note, sizeof note,
             "deterministic: at the live wind %g m/s and face %g deg (lo95 = "
             "hi95; 'sora mc' gives the last montecarlo's intervals)",
             c->st.descent.wind, c->st.face);
  }

  const uraRiskSet* r = &c->st.risk;
  uraSora25 s25;
  ura_sora25_inputs(c, unmit_speed, &s25);
  uraTable* t = ura_table_new(13, cols);
  ura_table_note(t,
                 "SORA 2.5 at %g ppl/km^2, TLOS %g /h, compensation %g: raw = 1 - "
                 "log10(TLOS / (density 1e-6 CA)) - compensation; igrc_raw = raw to 0.1 (ties to "
                 "even), igrc = its ceiling (casex AnnexFParms.iGRC), igrc_table = igrc_raw - 0.1 "
                 "to the nearest (SORA 2.5 Table 2's convention)",
                 ura_risk_density_max(r), r->tlos, r->igrc_comp);
  ura_table_note(t,
                 "q: Q of the grids (expected fatalities per fall = density x Q); annex_f: the "
                 "Annex F critical area of a %g kg, %g m drone at the impact speed and angle (mu "
                 "0.65, CoR(angle), 290 J, obstacle factor %s; casex "
                 "CriticalAreaModels.critical_area)",
                 c->st.descent.mass, c->st.para.width, r->annexf_obstacles ? "on" : "off");
  if (r->ua_dim_set && r->ua_dim != c->st.para.width) {
    ura_table_note(t,
                   "warning: annex_f takes the width parameter, %g m, as Annex F's characteristic "
                   "dimension, not ua_dimension %g m: 'set width %g' for that row",
                   c->st.para.width, r->ua_dim, r->ua_dim);
  }
  const char* none = ura_risk_none_name(c);
  ura_table_note(t,
                 "reduction: the unmitigated drone's CA (no parachute, no airbag: %s %s) over "
                 "the row's, per model; each factor 10 lowers raw by 1",
                 strcmp(none, "C") ? "branch" : "case", none);
  if (argc == 1) deploy_notes(c, t, &b);
  ura_table_note(t, "%s", note);
  soraFlags fl = {"", "", ""};
  sora_row(c, t, none, "q", &fig[0], &fl, &s25);
  sora_row(c, t, none, "annex_f", &fig[1], &fl, &s25);
  if (mitigated) {
    sora_row(c, t, c->st.casename, "q", &fig[2], &fl, &s25);
    sora_row(c, t, c->st.casename, "annex_f", &fig[3], &fl, &s25);
  }
  int nsamples = 0;
  if (argc == 2) {
    const double* q;
    const urMcStats* st;
    const char* cn;
    double seed;
    ura_mc_data(c, &q, &nsamples, &st, &cn, &seed);
  }
  sora_flag_notes(t, &fl, nsamples);
  ura_sora25_notes(t, &s25);
  ura_table_print(c, t);
  if (ds && named_figures(c, ds, named)) return -1;
  if ((mitigated || ds) &&
      ura_sora25_m2_table(c, &s25, fig, c->st.casename, argc == 2, ds ? named : NULL))
    return -1;
  const char* lab[2] = {c->st.casename, none};
  double q[2] = {fig[2].ca, fig[0].ca}, lo[2] = {fig[2].lo, fig[0].lo},
         hi[2] = {fig[2].hi, fig[0].hi};
  if (!mitigated) q[0] = q[1], lo[0] = lo[1], hi[0] = hi[1];
  char qnote[300];
  snprintf(qnote, sizeof qnote,
           argc == 2 ? "Q: the last montecarlo's mean with its 95 %% interval of the mean (the "
                       "design's drawn deployment; %s without any device)"
                     : "Q: the deterministic grids (the design's deployment mixture; %s without "
                       "any device); lo95 = hi95",
           none);
  ura_eq11_table(c, mitigated ? 2 : 1, lab, q, lo, hi, qnote);
  return 0;
}
