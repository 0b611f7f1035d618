/* session_base.c: what save session leaves out. A session replays 'reset', the model parts and
 * 'case NAME'; only what differs from the state those give is written, each number in the
 * shortest text that reads back exactly, a model parameter in the unit that makes it shortest
 * (set bag_p0 1.1 atm). */
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
