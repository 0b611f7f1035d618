/* case.c: the live case as a whole: a fresh context (the defaults, the built-in model set, the
 * model's first case), the case loaded by name from the model's presets, the impact speed and
 * angle the live settings give (set, or derived from the descent model or the paper's Table 2),
 * the last impact kept (with the title its plots take), and the last grid let go. The top of the case layer: it calls the model set, the presets and
 * the parameter table, and nothing in the layer calls back into it but through the context. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "case.h"

void ura_init(uraCtx* c) {
  ur_init(urINIT_GSL_CODES); /* the core's GSL failures as return codes */
  memset(c, 0, sizeof *c);
  ura_state_defaults(&c->st);
  c->out = stdout;
  c->msg = stderr;
  if (ura_models_init(c) == 0) ura_case_default(c);
}

int ura_paper_speed(const uraCtx* c) {
  return (!c->st.speed_set || !c->st.angle_set) && c->st.descent_src == uraDESC_PAPER;
}

int ura_impact_conditions(uraCtx* c, double* speed, double* angle) {
  urDescentResult r;
  char err[256];
  int derive = !c->st.speed_set || !c->st.angle_set;
  if (derive && c->st.descent_src == uraDESC_PAPER) {
    if (ura_paper_descent(c, c->st.casename, c->st.descent.wind, &r.speed, &r.angle)) return -1;
  } else if (derive) {
    if (ur_descent(&c->st.descent, &r, err, sizeof err)) return ura_fail(c, "%s", err);
  }
  *speed = c->st.speed_set ? c->st.speed : r.speed;
  *angle = c->st.angle_set ? c->st.angle : r.angle;
  return 0;
}

int ura_case_load(uraCtx* c, const char* name) {
  /* the cases are the model's presets (preset.c); the model is compiled once, and not at all
     when the overrides are as they were */
  if (!ura_model(c)) return -1;
  const urPreset* pr = ura_preset_find(c, name);
  if (!pr) {
    char names[400];
    ura_preset_names(c, names, sizeof names);
    return ura_fail(c, "case: unknown case '%s'; accepted: %s", name, names);
  }
  uraState ns, base;
  if (ura_preset_state(c, pr, c->model, &ns)) return -1;
  /* what the user set that the case does not keep, told once the case is live */
  char list[1500] = "";
  if (ura_case_baseline(c, 1, &base) == 0) ura_dropped(c, &c->st, &base, &ns, list, sizeof list);
  char who[48]; /* (pr lives in the model, which the new state may free) */
  snprintf(who, sizeof who, "case %s", pr->name);
  if (ura_model_state(c, &ns, "case")) return -1;
  ura_dropped_note(c, who, list);
  return 0;
}

int ura_case_default(uraCtx* c) {
  const urModel* m = ura_model(c);
  if (!m) return -1;
  if (m->npreset == 0) return 0;
  return ura_case_load(c, m->preset[0].name);
}

void ura_last_free(uraCtx* c) {
  ur_grid_free(c->last.g);
  memset(&c->last, 0, sizeof c->last);
}

const urPreset* ura_preset_find(uraCtx* c, const char* name) {
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->npreset; i++) {
    if (!strcasecmp(m->preset[i].name, name)) return m->preset + i;
  }
  return NULL;
}

void ura_preset_names(uraCtx* c, char* buf, size_t n) {
  const urModel* m = c->model ? c->model : ura_model(c);
  size_t k = 0;
  buf[0] = 0;
  for (int i = 0; m && i < m->npreset && k < n; i++) {
    k += (size_t)snprintf(buf + k, n - k, "%s%s",
                          i == 0                ? ""
                          : i + 1 == m->npreset ? " or "
                                                : ", ",
                          m->preset[i].name);
  }
  if (!buf[0]) snprintf(buf, n, "none (the model declares no preset)");
}

void ura_impact_keep(uraCtx* c, const char* casename, double wind, const urImpactCond* cond,
                     double dpar, double dperp, const urImpactResult* r) {
  c->have_impact = 1;
  c->last_impact = *r;
  c->last_dpar = dpar;
  c->last_dperp = dperp;
  c->last_aim = cond->aim;
  char w[32];
  if (isfinite(wind))
    snprintf(w, sizeof w, "%g m/s", wind);
  else
    snprintf(w, sizeof w, "?");
  snprintf(c->impact_title, sizeof c->impact_title,
           "case %s, wind %s, face %g deg, %.3g m/s at "
           "%.3g deg\nimpact %s %.2f m, %s %.2f m: HIC15 %.0f, Nij %.2f, p = %.3f",
           casename && *casename ? casename : "?", w, cond->face, cond->speed, cond->angle,
           cond->aim ? "aimed at the head, up" : "at dpar", dpar, cond->aim ? "side" : "dperp",
           dperp, r->inj.hic15.hic, r->inj.nij.nij, r->contact ? r->p : 0.0);
}

int ura_case_baseline(uraCtx* c, int keep_live, uraState* base) {
  const urPreset* pr = ura_preset_find(c, c->st.casename);
  uraState keep;
  if (keep_live)
    keep = c->st;
  else
    ura_state_defaults(&keep);
  if (!pr) {
    /* no preset by that name (a model without presets): the defaults with the kept settings */
    *base = keep;
    return c->model && c->model->npreset ? -1 : 0;
  }
  char err[uraERRLEN];
  memcpy(err, c->err, sizeof err);
  int rc = ura_preset_state_from(c, pr, c->model, &keep, base);
  memcpy(c->err, err, sizeof err); /* a note that cannot be made is no failure */
  return rc;
}

void ura_dropped_note(uraCtx* c, const char* who, const char* list) {
  if (c->mute || !c->interactive || !*list) return; /* at the prompt; a script stays quiet */
  fprintf(c->msg, "%s: drops %s (settings of yours it does not keep; undo brings them back)\n", who,
          list);
}
