/* preset.c: the cases as the model declares them (preset statements, uasimpact-model(5)): the
 * state a case starts from, and the mass of a preset (or of 'set mass') as the multibody
 * drone's total. Finding a case by name and listing the names is case.c's. */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "case.h"


/* a workbench setting of the preset into ns (through the parameter tables, as 'set' would) */
static int preset_setting(uraCtx* c, uraState* ns, const char* preset, const char* key, double v) {
  char val[64];
  snprintf(val, sizeof val, "%.17g", v);
  const uraParam* p = ura_param_find(key);
  int inj = p ? -1 : ura_injury_find(key);
  if ((!p || p->kind == uraP_CASE || p->kind == uraP_LIST || p->kind == uraP_STR ||
       p->kind == uraP_ENUM) &&
      inj < 0) {
    return ura_fail(c,
                    "case %s: the preset sets '%s', which is neither a model parameter nor a "
                    "numeric workbench setting; accepted: the names 'show' lists",
                    preset, key);
  }
  uraState keep = c->st;
  c->st = *ns;
  int rc = p ? ura_param_set(c, p, val) : ura_injury_set(c, inj, val);
  *ns = c->st;
  c->st = keep;
  if (rc) {
    char why[uraERRLEN];
    snprintf(why, sizeof why, "%s", c->err);
    return ura_fail(c, "case %s: the preset's %.900s", preset, why);
  }
  return 0;
}

int ura_preset_state(uraCtx* c, const urPreset* pr, const urModel* m, uraState* ns) {
  return ura_preset_state_from(c, pr, m, &c->st, ns);
}

int ura_preset_state_from(uraCtx* c, const urPreset* pr, const urModel* m, const uraState* keep,
                          uraState* ns) {
  /* keep the live wind, face, lists, grid step, recall, descent source, tau and output settings;
     everything else from the defaults and the preset */
  ura_state_defaults(ns);
  ns->descent.wind = keep->descent.wind;
  ns->face = keep->face;
  memcpy(ns->winds, keep->winds, sizeof ns->winds);
  ns->threads = keep->threads;
  ns->step = keep->step;
  ns->nwinds = keep->nwinds;
  ns->format = keep->format;
  ns->recall = keep->recall;
  ns->descent_src = keep->descent_src;
  ns->tau = keep->tau;
  ns->risk = keep->risk;
  strcpy(ns->terminal, keep->terminal);
  strcpy(ns->output, keep->output);
  snprintf(ns->casename, sizeof ns->casename, "%.7s", pr->name);

  /* model parameters as overrides set by the case; workbench settings as 'set' takes them */
  for (int i = 0; i < pr->n; i++) {
    if (pr->param[i] < 0) {
      if (preset_setting(c, ns, pr->name, pr->key[i], pr->value[i])) return -1;
      if (!strcmp(pr->key[i], "mass") && m) ura_design_mass(m, ns, pr->value[i], 0);
      continue;
    }
    int at = -1;
    for (int k = 0; k < ns->nov; k++) {
      if (!strcmp(ns->ov_name[k], pr->key[i])) at = k;
    }
    if (at < 0 && ns->nov == uraMAXOV) {
      return ura_fail(c, "case %s: too many model parameters set", pr->name);
    }
    if (at < 0) at = ns->nov++;
    snprintf(ns->ov_name[at], urNAMELEN, "%s", pr->key[i]);
    ns->ov_val[at] = pr->value[i];
    ns->ov_user[at] = 0;
  }
  return 0;
}

int ura_design_mass(const urModel* m, uraState* ns, double mass, int user) {
  if (!m || m->roles.mass_param < 0) return -1;
  const char* name = m->param[m->roles.mass_param].name;
  int at = -1;
  for (int i = 0; i < ns->nov; i++) {
    if (!strcmp(ns->ov_name[i], name)) at = i;
  }
  if (at < 0) {
    if (ns->nov == uraMAXOV) return -1;
    at = ns->nov++;
    snprintf(ns->ov_name[at], urNAMELEN, "%s", name);
  }
  ns->ov_val[at] = mass;
  ns->ov_user[at] = user;
  return 0;
}
