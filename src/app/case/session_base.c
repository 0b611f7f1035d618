/* session_base.c: what save session leaves out. A session replays 'reset', the model parts and
 * 'case NAME'; only what differs from the state those give is written, each number in the
 * shortest text that reads back exactly, a model parameter in the unit that makes it shortest
 * (set bag_p0 1.1 atm). And the same question for a grid's label: the settings it depends on
 * that differ from the case preset (ura_sweep_changes: sweeps, designs). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "case.h"


/* the state 'reset' then 'case NAME' give with the live model parts (NAME: the live case); the
   compiled model as it is (nothing is compiled here: save session may run on a design's state
   while the live model stays) */
int ura_session_base(uraCtx* c, uraState* base) {
  uraState live = c->st;
  const urPreset* pr = NULL;
  for (int i = 0; c->model && i < c->model->npreset; i++) {
    if (!strcasecmp(c->model->preset[i].name, live.casename)) pr = c->model->preset + i;
  }
  ura_state_defaults(&c->st);
  int rc = pr ? ura_preset_state(c, pr, c->model, base) : -1;
  if (rc) ura_state_defaults(base);
  c->st = live;
  c->err[0] = 0;
  return rc;
}

/* the shortest of %.1g..%.17g and %.0f..%.17f that reads back as v (on a tie without exponent:
   27000, not 2.7e+04) */
void ura_num_shortest(char* buf, size_t n, double v) {
  char g[64], fx[64] = "";
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(g, sizeof g, "%.*g", prec, v);
    if (strtod(g, NULL) == v) break;
  }
  for (int d = 0; d <= 17 && v > -1e15 && v < 1e15; d++) {
    snprintf(fx, sizeof fx, "%.*f", d, v);
    if (strtod(fx, NULL) == v) break;
    fx[0] = 0;
  }
  snprintf(buf, n, "%s", *fx && strlen(fx) <= strlen(g) ? fx : g);
}

/* v as show prints it: its text of at most 10 significant digits that is v but for rounding
   noise (0.3, 111457.5 for 1.1 atm), else 6 digits (10 kt: 5.14444, not 5.144444444444445) */
void ura_num_show(char* buf, size_t n, double v) {
  for (int prec = 1; prec <= 10; prec++) {
    char g[64];
    snprintf(g, sizeof g, "%.*g", prec, v);
    double r = strtod(g, NULL);
    if (fabs(r - v) <= 1e-12 * fabs(v)) {
      ura_num_shortest(buf, n, r); /* 10, not 1e+01 */
      return;
    }
  }
  snprintf(buf, n, "%.6g", v);
}

/* the units a value in SI unit si may be written in (those of the model language that convert
   to it by a factor) */
static const char* const units[] = {"m",   "mm",  "cm",  "kg",  "g",   "s",   "ms",
                                    "N",   "kN",  "Pa",  "kPa", "MPa", "GPa", "atm",
                                    "bar", "rad", "deg", "J",   "L",   NULL};

void ura_model_value_text(uraCtx* c, const char* name, double v, char* buf, size_t n) {
  int k = c->model ? ur_name_param(c->model, name) : -1;
  const char* si = k >= 0 ? c->model->param[k].unit : "";
  ura_num_shortest(buf, n, v);
  if (!*si) return;
  char best[64];
  snprintf(best, sizeof best, "%s %s", buf, si);
  for (int i = 0; units[i]; i++) {
    double f;
    char usi[urNAMELEN], num[40], t[64];
    if (ur_unit_parse(units[i], &f, usi, sizeof usi) || strcmp(usi, si) || f == 1) continue;
    ura_num_shortest(num, sizeof num, v / f);
    if (strtod(num, NULL) * f != v) continue; /* not exact in this unit */
    snprintf(t, sizeof t, "%s %s", num, units[i]);
    if (strlen(t) < strlen(best)) snprintf(best, sizeof best, "%s", t);
  }
  snprintf(buf, n, "%s", best);
}

/* the settings a grid depends on that differ from the case preset, as "name=value ..." (the
   wind or face swept, the step and the threads excepted; descent=paper and tau=top, which 'case'
   keeps, included), or "none" */
void ura_sweep_changes(uraCtx* c, char* buf, size_t n) {
  static const char* const names[] = {"speed",    "angle", "pitch",      "roll",     "yaw",
                                      "altitude", "mass",  "area_drone", "cd_drone", "area_chute",
                                      "cd_chute", "rho",   "g",          NULL};
  uraState ref;
  urInjuryParams inj;
  char val[64];
  size_t k = 0;
  buf[0] = 0;

  /* the preset, as ura_case_load makes it */
  const urPreset* pr = ura_preset_find(c, c->st.casename);
  if (!pr || ura_preset_state(c, pr, c->model, &ref)) ura_state_defaults(&ref);
  c->err[0] = 0;
  ref.descent_src = uraDESC_MODEL; /* 'case' keeps these: the changes name them */
  ref.tau = urTAU_RMAX;
  for (int i = 0; names[i] && k < n; i++) {
    const uraParam* p = ura_param_find(names[i]);
    const char* a = (const char*)&c->st + p->off;
    const char* b = (const char*)&ref + p->off;
    int set = p->setoff ? *(const int*)((const char*)&c->st + p->setoff) : 1;
    if (!set || *(const double*)a == *(const double*)b) continue;
    ura_param_format(c, p, val, sizeof val);
    k += (size_t)snprintf(buf + k, n - k, "%s%s=%s", k ? " " : "", p->name, val);
  }

  /* where speed and angle come from, and the moment tau */
  if (c->st.descent_src != ref.descent_src && k < n) {
    k += (size_t)snprintf(buf + k, n - k, "%sdescent=paper", k ? " " : "");
  }
  if (c->st.tau != ref.tau && k < n) {
    k += (size_t)snprintf(buf + k, n - k, "%stau=top", k ? " " : "");
  }

  /* injury settings, and model parameters the user set */
  ur_injury_defaults(&inj);
  for (int i = 0; i < ur_injury_param_count() && k < n; i++) {
    const char* name;
    double v, v0;
    ur_injury_param_info(i, &name, NULL, NULL);
    ur_injury_param_get(&c->st.injury, name, &v);
    ur_injury_param_get(&inj, name, &v0);
    if (v != v0) k += (size_t)snprintf(buf + k, n - k, "%s%s=%.6g", k ? " " : "", name, v);
  }
  for (int i = 0; i < c->st.nov && k < n; i++) {
    if (!c->st.ov_user[i]) continue;
    k += (size_t)snprintf(buf + k, n - k, "%s%s=%.6g", k ? " " : "", c->st.ov_name[i],
                          c->st.ov_val[i]);
  }
  if (!buf[0]) snprintf(buf, n, "none");
}
