/* cmd_impact.c: one impact at an offset (impact) and its time histories (history) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"

int ura_impact_cond(uraCtx* c, urImpactCond* cond) {
  if (ura_impact_conditions(c, &cond->speed, &cond->angle)) return -1;
  cond->face = c->st.face;
  cond->pitch = c->st.pitch;
  cond->roll = c->st.roll;
  cond->yaw = c->st.yaw;
  return 0;
}

/* the columns of impact rows, shared with grid cells */
static const char* const impact_cols[] = {"dpar", "dperp", "contact", "hic15", "nij", "nij_tf",
                                          "nij_te", "nij_cf", "nij_ce", "vc_thorax",
                                          "vc_abdomen", "p_hic", "p_nij", "p_vc", "p"};

int ura_cmd_impact(uraCtx* c, int argc, char** argv) {
  double dpar, dperp;
  if (ura_parse_number(argv[1], &dpar)) {
    return ura_fail(c, "impact: DPAR '%s' is not a number; accepted: the along offset in m",
                    argv[1]);
  }
  if (ura_parse_number(argv[2], &dperp)) {
    return ura_fail(c, "impact: DPERP '%s' is not a number; accepted: the cross offset in m",
                    argv[2]);
  }
  if (fabs(dpar) > 10 || fabs(dperp) > 10) {
    return ura_fail(c, "impact: offset out of range; accepted: |DPAR|, |DPERP| <= 10 m");
  }

  /* model, stance, work space, conditions */
  urImpactCond cond;
  const urImpactSetup* s = ura_setup(c);
  if (!s || ura_impact_cond(c, &cond)) return -1;
  if (!c->have_work) {
    if (ur_impact_work_init(s, &c->work)) return ura_fail(c, "impact: out of memory");
    c->have_work = 1;
  }

  /* run */
  urImpactResult r;
  c->have_impact = 0;
  if (ur_impact_run(s, &c->work, &cond, &c->st.injury, dpar, dperp, &r)) {
    return ura_fail(c, "impact %g %g: the simulation failed: %s", dpar, dperp, r.reason);
  }
  c->have_impact = 1;
  c->last_impact = r;
  c->last_dpar = dpar;
  c->last_dperp = dperp;

  /* one row */
  uraTable* t = ura_table_new(15, impact_cols);
  ura_table_note(t, "case %s, speed %.4g m/s, angle %.4g deg, face %g deg; HIC15 window "
                 "%.2f-%.2f ms", c->st.casename, cond.speed, cond.angle, cond.face,
                 1e3 * r.inj.hic15.t1, 1e3 * r.inj.hic15.t2);
  ura_table_cell(t, "%g", dpar);
  ura_table_cell(t, "%g", dperp);
  ura_table_cell(t, "%d", r.contact);
  ura_table_cell(t, "%.6g", r.inj.hic15.hic);
  ura_table_cell(t, "%.6g", r.inj.nij.nij);
  for (int k = 0; k < 4; k++) ura_table_cell(t, "%.6g", r.inj.nij.mode[k]);
  ura_table_cell(t, "%.6g", r.inj.vc_thorax.vc);
  ura_table_cell(t, "%.6g", r.inj.vc_abdomen.vc);
  ura_table_cell(t, "%.6g", r.inj.p_hic);
  ura_table_cell(t, "%.6g", r.inj.p_nij);
  ura_table_cell(t, "%.6g", r.inj.p_vc);
  ura_table_cell(t, "%.6g", r.p);
  ura_table_print(c, t);
  return 0;
}

/* every sensor channel of the last impact, one row per sample */
int ura_cmd_history(uraCtx* c, int argc, char** argv) {
  if (!c->have_impact) return ura_fail(c, "history: no impact yet; run 'impact DPAR DPERP'");
  const urModel* m = c->setup.m;
  const urData* d = c->work.d;
  static const char* const comp3[] = {"x", "y", "z"};
  static const char* const comp6[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  static const char* const comp2[] = {"p", "v"};

  /* column names: time, then sensor_component */
  int ncol = 1 + m->nsensordata;
  char** names = malloc(sizeof(char*) * ncol);
  names[0] = strdup("t");
  for (int i = 0; i < m->nsensor; i++) {
    const urSensor* sn = m->sensor + i;
    for (int k = 0; k < sn->dim; k++) {
      char buf[80];
      const char* suffix = sn->dim == 3 ? comp3[k] : sn->dim == 6 ? comp6[k] :
                           sn->dim == 2 ? comp2[k] : NULL;
      if (suffix) snprintf(buf, sizeof buf, "%s_%s", sn->name, suffix);
      else snprintf(buf, sizeof buf, "%s", sn->name);
      names[1 + sn->adr + k] = strdup(buf);
    }
  }
  uraTable* t = ura_table_new(ncol, (const char* const*)names);
  ura_table_note(t, "impact at (%g, %g) m; t in s from tau; SI units; engine frames "
                 "(uasrisk-model(5))", c->last_dpar, c->last_dperp);
  for (int r = 0; r < d->nhist; r++) {
    for (int k = 0; k < ncol; k++) ura_table_cell(t, "%.9g", d->hist[(size_t)r * ncol + k]);
  }
  ura_table_print(c, t);
  for (int k = 0; k < ncol; k++) free(names[k]);
  free(names);
  return 0;
}
