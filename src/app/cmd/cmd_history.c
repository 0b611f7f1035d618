/* cmd_history.c: the histories of the last impact at a glance. 'history' prints a summary (the
 * peak of each derived signal and its time, the injury criteria, P); 'history all' every sensor
 * channel's samples (as 'export history' writes them), 'history CHANNEL...' some signals'
 * samples; a range FROM:TO in ms (either side may be left open) limits the samples. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"
#include "uasimpact/injury_registry.h"

/* FROM:TO in ms into s; 1 if word is a range, 0 if not, -1 with a message if malformed */
static int parse_range(uraCtx* c, const char* word, double* from, double* to) {
  const char* colon = strchr(word, ':');
  if (!colon) return 0;
  char a[64], b[64];
  snprintf(a, sizeof a, "%.*s", (int)(colon - word), word);
  snprintf(b, sizeof b, "%s", colon + 1);
  double x = -INFINITY, y = INFINITY;
  if ((*a && ura_parse_number(a, &x)) || (*b && ura_parse_number(b, &y)) || y < x ||
      strlen(word) > 60) {
    return ura_fail(c,
                    "history: '%s' is not a time range; accepted: FROM:TO in ms from tau "
                    "(FROM <= TO; 50:80, :20, 60:)",
                    word);
  }
  *from = x * 1e-3;
  *to = y * 1e-3;
  return 1;
}

/* each airbag's channels (its sensor type=airbag): peak pressure (absolute), smallest volume,
   peak normal force on the person, peak fabric strain (membrane bags; 0 for analytic ones) */
static void bag_rows(uraCtx* c, const uraTrace* tr, uraTable* t) {
  static const char* const sfx[] = {"p", "v", "f", "strain"};
  const urModel* m = c->setup.m;
  int nbag = 0;
  for (int i = 0; m && i < m->nsensor; i++) {
    const urSensor* sn = m->sensor + i;
    if (sn->type != urSENS_AIRBAG) continue;
    for (int q = 0; q < 4; q++) {
      char name[96];
      snprintf(name, sizeof name, "%s_%s", sn->name, sfx[q]);
      int k = ura_trace_find(tr, name);
      if (k < 0) continue;
      const double* v = tr->v + (size_t)k * tr->n;
      int at = 0;
      for (int j = 1; j < tr->n; j++) {
        if (q == 1 ? v[j] < v[at] : fabs(v[j]) > fabs(v[at])) at = j;
      }
      ura_table_cell(t, "%s", name);
      ura_table_cell(t, "%.6g", v[at]);
      ura_table_cell(t, "%s", tr->units[k]);
      ura_table_cell(t, "%.2f", 1e3 * tr->t[at]);
    }
    nbag++;
  }
  if (nbag) {
    ura_table_note(t,
                   "airbag channels: _p absolute pressure, _v gas volume (its smallest), _f "
                   "normal force on the person, _strain largest fabric yarn strain (Green)");
  }
}

/* the peak of each derived signal, then the criteria; how to see the samples */
static int summary(uraCtx* c, const uraTrace* tr) {
  static const char* const cols[] = {"signal", "peak", "unit", "t_ms"};
  static const char* const derived[] = {"head_acc", "neck_fz",    "neck_my",
                                        "neck_fx",  "chest_defl", "abd_defl"};
  uraTable* t = ura_table_new(4, cols);
  ura_table_note(t, "impact %s (%g, %g) m: peaks (largest |value|) at t_ms from tau",
                 c->last_aim ? "aimed at the head, up and side" : "at", c->last_dpar,
                 c->last_dperp);
  ura_table_note(t, "the samples: history all, history CHANNEL..., history FROM:TO (ms)");
  for (size_t s = 0; s < sizeof derived / sizeof derived[0]; s++) {
    int k = ura_trace_find(tr, derived[s]);
    if (k < 0) continue;
    const double* v = tr->v + (size_t)k * tr->n;
    int at = 0;
    for (int i = 1; i < tr->n; i++) {
      if (fabs(v[i]) > fabs(v[at])) at = i;
    }
    ura_table_cell(t, "%s", derived[s]);
    ura_table_cell(t, "%.4g", v[at]);
    ura_table_cell(t, "%s", tr->units[k]);
    ura_table_cell(t, "%.2f", 1e3 * tr->t[at]);
  }
  bag_rows(c, tr, t);
  ura_table_print(c, t);

  static const char* const ccols[] = {"criterion", "value", "at", "p"};
  static const char* const modes[] = {"NTF", "NTE", "NCF", "NCE"};
  const urImpactResult* r = &c->last_impact;
  const urInjuryResult* in = &r->inj;
  t = ura_table_new(4, ccols);
  if (!r->contact) {
    ura_table_note(t, "no contact: the drone passed the person; every criterion and P are 0");
  }
  int w = in->nij.which >= 0 && in->nij.which < 4 ? in->nij.which : 0;
  ura_table_cell(t, "HIC15");
  ura_table_cell(t, "%.1f", in->hic15.hic);
  ura_table_cell(t, "%.2f-%.2f ms", 1e3 * in->hic15.t1, 1e3 * in->hic15.t2);
  ura_table_cell(t, "%.4f", in->pof[urCRIT_HIC]);
  ura_table_cell(t, "Nij");
  ura_table_cell(t, "%.3f", in->nij.nij);
  ura_table_cell(t, "%s", modes[w]);
  ura_table_cell(t, "%.4f", in->pof[urCRIT_NIJ]);
  ura_table_cell(t, "VC thorax");
  ura_table_cell(t, "%.3g m/s", in->vc_thorax.vc);
  ura_table_cell(t, "%.2f ms", 1e3 * in->vc_thorax.t);
  ura_table_cell(t, "%.4f", in->p_vc_thorax);
  ura_table_cell(t, "VC abdomen");
  ura_table_cell(t, "%.3g m/s", in->vc_abdomen.vc);
  ura_table_cell(t, "%.2f ms", 1e3 * in->vc_abdomen.t);
  ura_table_cell(t, "%.4f", in->p_vc_abdomen);
  /* the registry's criteria after HIC, Nij and VC that are in use (e.g. use_defl 1) */
  for (int k = urCRIT_VC + 1; k < urNCRIT; k++) {
    const urCriterion* cr = ur_criterion(k);
    if (!ur_criterion_used(k, &c->st.injury)) continue;
    char v[64], d[96];
    ur_value_format(cr->val0, in->val[cr->val0], v, sizeof v);
    const urValueDef* vd = ur_value_def(cr->val0);
    snprintf(d, sizeof d, "%s%s%s", v, *vd->dunit ? " " : "", vd->dunit);
    ura_table_cell(t, "%s", cr->label);
    ura_table_cell(t, "%s", d);
    ura_table_cell(t, "-");
    ura_table_cell(t, "%.4f", in->pof[k]);
  }
  ura_table_cell(t, "P");
  ura_table_cell(t, "-");
  ura_table_cell(t, "-");
  ura_table_cell(t, "%.4f", r->p);
  ura_table_print(c, t);
  return 0;
}

void ura_history_range_note(uraTable* t, const double* ts, int n, size_t stride, double from,
                            double to) {
  int kept = 0;
  for (int i = 0; i < n; i++)
    kept += ts[(size_t)i * stride] >= from && ts[(size_t)i * stride] <= to;
  if (kept || n < 1) return;
  char a[32] = "", b[32] = "";
  if (isfinite(from)) snprintf(a, sizeof a, "%g", 1e3 * from);
  if (isfinite(to)) snprintf(b, sizeof b, "%g", 1e3 * to);
  ura_table_note(t,
                 "no samples in %s:%s ms from tau: the last impact's samples run from %.4g to "
                 "%.4g ms",
                 a, b, 1e3 * ts[0], 1e3 * ts[(size_t)(n - 1) * stride]);
}

/* some signals' samples in [from, to] s */
static int samples(uraCtx* c, const uraTrace* tr, int nsel, char** names, double from, double to) {
  int* sel = malloc(sizeof(int) * (size_t)nsel);
  const char** cols = malloc(sizeof(char*) * (size_t)(nsel + 1));
  if (!sel || !cols) {
    free(sel);
    free(cols);
    return ura_fail(c, "history: out of memory");
  }
  cols[0] = "t";
  for (int s = 0; s < nsel; s++) {
    sel[s] = ura_trace_find(tr, names[s]);
    cols[s + 1] = names[s];
    if (sel[s] < 0) {
      uraSuggest sg;
      char dym[120], list[1024];
      size_t m = 0;
      ura_suggest_init(&sg, names[s]);
      list[0] = 0;
      for (int j = 0; j < tr->nsig; j++) {
        if (ura_trace_find(tr, tr->names[j]) != j) continue; /* each name once */
        ura_suggest_add(&sg, tr->names[j]);
        if (m < sizeof list) {
          m += (size_t)snprintf(list + m, sizeof list - m, "%s%s", m ? ", " : "", tr->names[j]);
        }
      }
      free(sel);
      free(cols);
      return ura_fail(c,
                      "history: no channel '%s'%s; accepted: all, a range FROM:TO in ms, or "
                      "%s",
                      names[s], ura_suggest_text(&sg, dym, sizeof dym), list);
    }
  }
  uraTable* t = ura_table_new(nsel + 1, cols);
  ura_table_unit(t, 0, "s");
  for (int s = 0; s < nsel && tr->units; s++) ura_table_unit(t, s + 1, tr->units[sel[s]]);
  ura_table_note(t, "impact %s (%g, %g) m; t in s from tau; units: %s",
                 c->last_aim ? "aimed at the head, up and side" : "at", c->last_dpar, c->last_dperp,
                 "head_acc m/s^2, neck forces N, moments N m, deflections m, airbag channels "
                 "_p Pa (absolute), _v m^3, _f N, _strain 1 (Green), other sensor channels in "
                 "the units 'history' lists");
  ura_history_range_note(t, tr->t, tr->n, 1, from, to);
  for (int i = 0; i < tr->n; i++) {
    if (tr->t[i] < from || tr->t[i] > to) continue;
    ura_table_cell(t, "%.9g", tr->t[i]);
    for (int s = 0; s < nsel; s++) ura_table_cell(t, "%.9g", tr->v[(size_t)sel[s] * tr->n + i]);
  }
  ura_table_print(c, t);
  free(sel);
  free(cols);
  return 0;
}

int ura_cmd_history(uraCtx* c, int argc, char** argv) {
  if (!c->have_impact) return ura_fail(c, "history: no impact yet; run 'impact DPAR DPERP'");
  double from = -INFINITY, to = INFINITY;
  int nsel = 0, all = 0, ranged = 0;
  char* names[64];
  for (int i = 1; i < argc; i++) {
    int rg = parse_range(c, argv[i], &from, &to);
    if (rg < 0) return -1;
    if (rg && ranged) return ura_fail(c, "history: two time ranges; accepted: one FROM:TO");
    ranged |= rg;
    if (rg) continue;
    if (!strcmp(argv[i], "all"))
      all = 1;
    else if (nsel < 64)
      names[nsel++] = argv[i];
  }
  if (all && nsel) {
    return ura_fail(c,
                    "history: 'all' and channels named; accepted: history all, or history "
                    "CHANNEL...");
  }
  if (all || (ranged && !nsel)) return ura_history_samples(c, from, to);
  uraTrace tr;
  if (ura_last_trace(c, &tr)) return ura_fail(c, "history: no impact yet; run 'impact'");
  if (nsel) return samples(c, &tr, nsel, names, from, to);
  return summary(c, &tr);
}
