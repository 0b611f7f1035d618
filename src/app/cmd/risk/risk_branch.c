/* risk_branch.c: what risk, sora and montecarlo share about deployment: the devices a drone
 * carries (a parachute, the airbags it is fitted with), a deployment branch's name and state
 * (the live state with each device deployed or not), a branch's grid and Q (or its mirror
 * image's: face -phi is face phi mirrored when nothing else breaks the symmetry), the Annex F
 * critical area of a state and the iGRC of an area. Below the three commands, so that none of
 * them calls another. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../cmd.h"
#include "uasimpact/sora.h"

static const char* const bag_names[urMAXBAGS] = {"bag_bottom", "bag_front"};

const char* ura_risk_bag(int which) {
  return bag_names[which];
}

int ura_risk_devices(uraCtx* c, const uraState* st, urDeploy* dep, int* bag) {
  const urModel* m = ura_model(c);
  if (!m) return -1;
  memset(dep, 0, sizeof *dep);
  dep->chute = st->descent.area_chute > 0;
  for (int k = 0; k < urMAXBAGS; k++) {
    int i = ur_name_param(m, bag_names[k]);
    if (i >= 0 && m->param[i].value != 0) bag[dep->nbag++] = k;
  }
  dep->p_chute = st->risk.p_chute;
  dep->p_bag = st->risk.p_bag;
  dep->altitude = st->descent.altitude;
  dep->h_chute_min = st->risk.h_chute_min;
  return 0;
}

int ura_risk_fixed_bags(uraCtx* c, const urDeploy* dep, const int* bag, char* text, size_t n) {
  const urModel* m = ura_model(c);
  text[0] = 0;
  int nfixed = m ? m->nbag - dep->nbag : 0;
  if (nfixed <= 0) return 0;
  /* their names: the airbags not named as the parameters that switch the carried ones */
  char names[400] = "";
  size_t k = 0;
  for (int i = 0; i < m->nbag && k < sizeof names; i++) {
    int on = 0;
    for (int j = 0; j < dep->nbag; j++) on |= !strcmp(m->bag[i].name, bag_names[bag[j]]);
    if (!on)
      k += (size_t)snprintf(names + k, sizeof names - k, "%s%s", k ? ", " : "", m->bag[i].name);
  }
  snprintf(
      text, n,
      "fitted in every branch, not a device: airbag%s %s (no parameter bag_bottom or "
      "bag_front switches %s: p_bag does not apply and branch none keeps %s; enable=$bag_bottom "
      "or $bag_front makes an airbag a device, uasimpact(1), RISK FIGURES)",
      nfixed == 1 ? "" : "s", names, nfixed == 1 ? "it" : "them", nfixed == 1 ? "it" : "them");
  return nfixed;
}

void ura_risk_branch_name(int mask, const urDeploy* dep, const int* bag, char* buf, size_t n) {
  size_t k = (size_t)snprintf(buf, n, "%s", mask & 1 ? "chute" : "none");
  for (int j = 0; j < dep->nbag && k < n; j++) {
    if ((mask >> (j + 1)) & 1) k += (size_t)snprintf(buf + k, n - k, "+%s", bag_names[bag[j]]);
  }
}

void ura_risk_override(uraState* ns, const char* name, double v, int user) {
  for (int i = 0; i < ns->nov; i++) {
    if (!strcmp(ns->ov_name[i], name)) {
      ns->ov_val[i] = v;
      if (user) ns->ov_user[i] = 1;
      return;
    }
  }
  if (ns->nov == uraMAXOV) return;
  snprintf(ns->ov_name[ns->nov], urNAMELEN, "%s", name);
  ns->ov_val[ns->nov] = v;
  ns->ov_user[ns->nov++] = user;
}

const char* ura_risk_none_name(uraCtx* c) {
  const urModel* m = ura_model(c);
  for (int i = 0; m && i < m->npreset; i++) {
    if (!strcmp(m->preset[i].name, "C")) return "C";
  }
  return "none";
}

void ura_risk_branch_state(const uraState* base, int mask, const urDeploy* dep, const int* bag,
                           const char* none, uraState* ns) {
  *ns = *base;
  if (!(mask & 1)) {
    /* no parachute: the drone falls as case C (and takes C's column of the paper's Table 2);
       a speed and angle set are the descent under the parachute, so they are derived again */
    if (dep->chute) ns->speed_set = ns->angle_set = 0;
    ns->descent.area_chute = 0;
    snprintf(ns->casename, sizeof ns->casename, "%s", none);
  }
  for (int j = 0; j < dep->nbag; j++) {
    ura_risk_override(ns, bag_names[bag[j]], (mask >> (j + 1)) & 1, 0);
  }
}

int ura_risk_grid(uraCtx* c, const uraState* ns, const char* who, int quiet, double* q) {
  if (ura_model_state(c, ns, who) || ura_grid_run(c, quiet)) return -1;
  if (!c->last.g->complete) {
    return ura_fail(c,
                    "%s: %d cells failed in the grid of case %s at wind %g m/s, face %g deg; "
                    "Q is not complete ('grid cells' lists the grid)",
                    who, c->last.g->nfailed, ns->casename, ns->descent.wind, ns->face);
  }
  *q = c->last.g->q;
  return 0;
}

double ura_risk_mirror_face(const uraState* st, double face) {
  return ura_grid_symmetric(st) && face < 0 && face >= -180 ? -face : face;
}

int ura_risk_grid_mirror(uraCtx* c, const uraState* ns, const char* who, int quiet, double* q,
                         int* mirrored) {
  double face = ura_risk_mirror_face(ns, ns->face);
  *mirrored = face != ns->face;
  /* the model of ns (its overrides: a device left undeployed may break the symmetry) */
  if (*mirrored && ura_model_state(c, ns, who)) return -1;
  if (*mirrored && !c->model->mirror) *mirrored = 0;
  if (!*mirrored) return ura_risk_grid(c, ns, who, quiet, q);
  uraState* m = malloc(sizeof *m);
  if (!m) return ura_fail(c, "%s: out of memory", who);
  *m = *ns;
  m->face = face;
  int rc = ura_risk_grid(c, m, who, quiet, q);
  free(m);
  if (rc) {
    size_t k = strlen(c->err);
    snprintf(c->err + k, sizeof c->err - k, " (face %g asked for as its mirror image, face %g)",
             ns->face, face);
  }
  return rc;
}

int ura_risk_annexf(uraCtx* c, const uraState* ns, double* ca, double* speed, double* angle) {
  uraState* keep = malloc(sizeof *keep);
  if (!keep) return ura_fail(c, "out of memory");
  *keep = c->st;
  c->st = *ns;
  int rc = ura_impact_conditions(c, speed, angle);
  c->st = *keep;
  free(keep);
  if (rc) return -1;
  urAnnexFIn in;
  urAnnexFOut out;
  ur_annexf_defaults(&in, ns->descent.mass, ns->para.width, *speed, *angle);
  in.obstacles = ns->risk.annexf_obstacles;
  ur_annexf_ca(&in, &out);
  *ca = out.ca;
  return 0;
}

int ura_risk_igrc(const uraState* st, double ca, double* raw1, int* igrc, int* table) {
  double raw;
  return ur_igrc(ura_risk_density_max(&st->risk), ca, st->risk.tlos, st->risk.igrc_comp, &raw, raw1,
                 igrc, table);
}
