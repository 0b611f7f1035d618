/* cmd_impact.c: one impact at an offset (impact), its time histories (history) and its contacts
 * (contacts) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"


int ura_impact_cond(uraCtx* c, urImpactCond* cond) {
  memset(cond, 0, sizeof *cond);
  if (ura_impact_conditions(c, &cond->speed, &cond->angle)) return -1;
  cond->face = c->st.face;
  cond->pitch = c->st.pitch;
  cond->roll = c->st.roll;
  cond->yaw = c->st.yaw;
  cond->tau = c->st.tau;
  if (cond->angle < uraANGLE_DELTA) {
    return ura_fail(c,
                    "angle %g deg: an offset Delta needs a descent (at angles below %g deg "
                    "the path stays R_max above the head top); accepted: angle >= %g deg, "
                    "'set angle auto' (the descent's), or 'impact aim head UP SIDE' for a flight",
                    cond->angle, uraANGLE_DELTA, uraANGLE_DELTA);
  }
  return 0;
}

void ura_cond_notes(uraTable* t, const char* casename, double wind, int paper, int tau,
                    double shift) {
  if (paper) {
    ura_table_note(t,
                   "speed and angle: the paper's Table 2, case %s's column, at wind %g m/s "
                   "('set descent paper'), not the descent model",
                   ura_paper_descent_column(casename), wind);
  }
  if (tau == urTAU_TOP) {
    ura_table_note(t,
                   "tau top: Delta is taken when the drone centre reaches head-top level, "
                   "%.3f m further along the course than the paper's text (R_max above the "
                   "head top; 'set tau rmax')",
                   shift);
  }
}

int ura_impact_fresh(uraCtx* c, const urImpactSetup* s, const urImpactCond* cond, double dpar,
                     double dperp, urImpactResult* r) {
  urImpactWork w;
  if (ur_impact_work_init(s, &w)) {
    ur_impact_work_free(&w);
    snprintf(r->reason, sizeof r->reason, "out of memory");
    r->status = 0;
    return -1;
  }
  if (ur_impact_run(s, &w, cond, &c->st.injury, dpar, dperp, r)) {
    ur_impact_work_free(&w);
    return -1;
  }
  if (c->have_work) ur_impact_work_free(&c->work);
  c->work = w;
  c->have_work = 1;
  return 0;
}

int ura_cmd_impact(uraCtx* c, int argc, char** argv) {
  double dpar, dperp;
  if (!strcmp(argv[1], "aim")) return ura_impact_aim(c, argc, argv); /* cmd_aim.c */
  if (argc != 3) {
    return ura_fail(c,
                    "impact: %d arguments; accepted: impact DPAR DPERP, or impact aim head "
                    "UP SIDE",
                    argc - 1);
  }
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

  /* run; a failure keeps the last impact */
  urImpactResult r;
  if (ura_impact_fresh(c, s, &cond, dpar, dperp, &r)) {
    const char* kept = c->have_impact ? "; the last impact is kept" : "";
    if (r.status == urSTAT_STOPPED) {
      return ura_fail(c, "impact %g %g: interrupted (Ctrl-C)%s", dpar, dperp, kept);
    }
    return ura_fail(c, "impact %g %g: the simulation failed: %s%s", dpar, dperp, r.reason, kept);
  }
  ura_impact_keep(c, c->st.casename, c->st.descent.wind, &cond, dpar, dperp, &r);

  /* one row */
  int compact = ura_impact_compact(c);
  uraTable* t = compact ? ura_impact_compact_table() : ura_impact_table(&c->st.injury);
  ura_table_note(t,
                 "case %s, speed %.4g m/s, angle %.4g deg, face %g deg; HIC15 window "
                 "%.2f-%.2f ms",
                 c->st.casename, cond.speed, cond.angle, cond.face, 1e3 * r.inj.hic15.t1,
                 1e3 * r.inj.hic15.t2);
  if (r.nextrap) {
    ura_table_note(t, "extrapolated: %d law(s) used beyond their data; furthest: %s", r.nextrap,
                   r.extrap);
  }
  ura_cond_notes(t, c->st.casename, c->st.descent.wind, ura_paper_speed(c), cond.tau,
                 ur_impact_tau_shift(s, &cond));
  if (compact)
    ura_impact_compact_row(t, dpar, dperp, &r);
  else
    ura_impact_cells(t, &c->st.injury, dpar, dperp, &r);
  ura_table_print(c, t);
  return 0;
}

/* name of sensor channel j: SENSOR (one value), SENSOR_x/y/z (3), SENSOR_fx..mz (6), SENSOR_p/v/f/strain
   (airbag: pressure, volume, force on the targets, fabric strain) */
static void channel_name(const urModel* m, int j, char* buf, size_t n) {
  static const char* const comp3[] = {"x", "y", "z"};
  static const char* const comp6[] = {"fx", "fy", "fz", "mx", "my", "mz"};
  static const char* const comp2[] = {"p", "v"};
  static const char* const comp4[] = {"p", "v", "f", "strain"};
  snprintf(buf, n, "s%d", j);
  for (int i = 0; i < m->nsensor; i++) {
    const urSensor* sn = m->sensor + i;
    int k = j - sn->adr;
    if (k < 0 || k >= sn->dim) continue;
    const char* suffix = sn->dim == 3   ? comp3[k]
                         : sn->dim == 6 ? comp6[k]
                         : sn->dim == 2 ? comp2[k]
                         : sn->dim == 4 ? comp4[k]
                                        : NULL;
    if (suffix)
      snprintf(buf, n, "%s_%s", sn->name, suffix);
    else
      snprintf(buf, n, "%s", sn->name);
  }
}

/* the unit of sensor channel j by its sensor's kind and component (urSensorType, engine.h) */
static const char* channel_unit(const urModel* m, int j) {
  for (int i = 0; i < m->nsensor; i++) {
    const urSensor* sn = m->sensor + i;
    int k = j - sn->adr, lin;
    if (k < 0 || k >= sn->dim) continue;
    switch (sn->type) {
    case urSENS_ACCEL: return "m/s^2";
    case urSENS_JOINTLOAD: return k < 3 ? "N" : "N m";
    case urSENS_JOINTPOS:
    case urSENS_JOINTVEL:
      /* translation: a prismatic joint, or the first three dof of a free one */
      lin = m->body[sn->obj].jtype == urJNT_PRISMATIC ||
            (m->body[sn->obj].jtype == urJNT_FREE && sn->dof < 3);
      if (sn->type == urSENS_JOINTPOS) return lin ? "m" : "rad";
      return lin ? "m/s" : "rad/s";
    case urSENS_CONTACT: return k == 1 ? "m" : "N";
    case urSENS_AIRBAG: return k == 0 ? "Pa" : k == 1 ? "m^3" : k == 2 ? "N" : "1";
    case urSENS_BODYPOS: return "m";
    case urSENS_BODYVEL: return "m/s";
    case urSENS_HINGE:
      /* plastic deflection (a prismatic hinge's in m), the time it broke */
      if (k == 1) return "s";
      return m->body[sn->obj].jtype == urJNT_PRISMATIC ? "m" : "rad";
    }
  }
  return "";
}

/* every sensor channel of the last impact, one row per sample from from to to (s) */
int ura_history_samples(uraCtx* c, double from, double to) {
  if (!c->have_impact) return ura_fail(c, "history: no impact yet; run 'impact DPAR DPERP'");
  const urModel* m = c->setup.m;
  const urData* d = c->work.d;

  /* column names: time, then sensor_component */
  int ncol = 1 + m->nsensordata;
  char** names = malloc(sizeof(char*) * ncol);
  names[0] = strdup("t");
  for (int j = 0; j < m->nsensordata; j++) {
    char buf[80];
    channel_name(m, j, buf, sizeof buf);
    names[1 + j] = strdup(buf);
  }
  uraTable* t = ura_table_new(ncol, (const char* const*)names);
  ura_table_unit(t, 0, "s"); /* each channel's unit, for the sidecar of export history */
  for (int j = 0; j < m->nsensordata; j++) ura_table_unit(t, 1 + j, channel_unit(m, j));
  ura_table_note(t,
                 "impact %s (%g, %g) m; t in s from tau; SI units; engine frames "
                 "(uasimpact-model(5))",
                 c->last_aim ? "aimed at the head, up and side" : "at", c->last_dpar,
                 c->last_dperp);
  ura_history_range_note(t, d->hist, d->nhist, (size_t)ncol, from, to);
  for (int r = 0; r < d->nhist; r++) {
    double tr = d->hist[(size_t)r * ncol];
    if (tr < from || tr > to) continue;
    for (int k = 0; k < ncol; k++) ura_table_cell(t, "%.9g", d->hist[(size_t)r * ncol + k]);
  }
  ura_table_print(c, t);
  for (int k = 0; k < ncol; k++) free(names[k]);
  free(names);
  return 0;
}

/* the pairs through which the drone touched the person in the last impact, in order of first
   touch: drone part (ellipsoid, or airbag), person part, first and last touch, peak force */
/* a note for each hinge that broke in the impact: its joint released there and the arm flew on
   as a free body (uasimpact-model(5), restraint fracture) */
static void contacts_fractures(const urModel* m, const urData* d, uraTable* t) {
  for (int b = 0; b < m->nbody; b++) {
    for (int k = 0; k < 3; k++) {
      double xp, tb;
      if (ur_hinge_state(m, d, b, k, &xp, &tb) == 0 && tb != 0) {
        ura_table_note(t,
                       "joint %s (dof %d) broke at %.4f s after a plastic set of %.4g: released, "
                       "the arm flew on free",
                       m->body[b].jname, k, tb, xp);
      }
    }
  }
}

int ura_cmd_contacts(uraCtx* c, int argc, char** argv) {
  if (!c->have_impact) return ura_fail(c, "contacts: no impact yet; run 'impact DPAR DPERP'");
  const urImpactSetup* s = &c->setup;
  const urModel* m = s->m;
  const urContactRec* rec = c->work.crec;

  /* the touching pairs, ordered by first touch (then by their order in the model) */
  int* idx = malloc(sizeof(int) * (s->ncand + 1));
  if (!idx) return ura_fail(c, "contacts: out of memory");
  int n = 0;
  for (int k = 0; k < s->ncand; k++) {
    if (rec[k].t_first < 0) continue;
    int j = n++;
    while (j > 0 && rec[idx[j - 1]].t_first > rec[k].t_first) {
      idx[j] = idx[j - 1];
      j--;
    }
    idx[j] = k;
  }

  static const char* const cols[] = {"drone", "person", "first", "last", "peak_force", "peak_time"};
  uraTable* t = ura_table_new(6, cols);
  ura_table_note(t, "impact %s (%g, %g) m: %d pair%s touched; t in s from tau, force in N",
                 c->last_aim ? "aimed at the head, up and side" : "at", c->last_dpar, c->last_dperp,
                 n, n == 1 ? "" : "s");
  contacts_fractures(m, c->work.d, t);
  for (int i = 0; i < n; i++) {
    int k = idx[i], src = s->cand_src[k];
    const char* drone =
        src < m->npair ? m->geom[s->cand[k][0]].name : m->bag[(src - m->npair) / urMAXBAGTGT].name;
    ura_table_cell(t, "%s", drone);
    ura_table_cell(t, "%s", m->geom[s->cand[k][1]].name);
    ura_table_cell(t, "%.4f", rec[k].t_first);
    ura_table_cell(t, "%.4f", rec[k].t_last);
    ura_table_cell(t, "%.6g", rec[k].fmax);
    ura_table_cell(t, "%.4f", rec[k].t_fmax);
  }
  free(idx);
  ura_table_print(c, t);
  return 0;
}

/* ---- the histories of the last impact as a trace (plot history, the viewer's inspection) ---- */

/* derived signals first (what the injury criteria read), then every sensor channel */
static const char* const trace_names[] = {"head_acc", "neck_fz",    "neck_my",
                                          "neck_fx",  "chest_defl", "abd_defl"};
static const char* const trace_units[] = {"m/s^2", "N", "N m", "N", "m", "m"};
#define NDERIVED uraTRACE_NDERIVED

int ura_last_trace(uraCtx* c, uraTrace* tr) {
  if (!c->have_impact || !c->have_setup) return -1;
  const urImpactSetup* s = &c->setup;
  const urModel* m = s->m;
  const urData* d = c->work.d;
  int n = d->nhist, nsig = NDERIVED + m->nsensordata, stride = 1 + m->nsensordata;
  ura_trace_free(c);
  c->trace.t = malloc(sizeof(double) * n);
  c->trace.v = calloc((size_t)nsig * n, sizeof(double));
  c->trace.names = calloc(nsig, sizeof(char*));
  c->trace.units = calloc(nsig, sizeof(char*));
  c->trace.nsig = nsig;
  for (int k = 0; k < NDERIVED; k++) {
    c->trace.names[k] = (char*)trace_names[k];
    c->trace.units[k] = trace_units[k];
  }

  /* raw channels, then the derived ones in the injury criteria's signs */
  for (int i = 0; i < n; i++) c->trace.t[i] = d->hist[(size_t)i * stride];
  for (int j = 0; j < m->nsensordata; j++) {
    char buf[80];
    channel_name(m, j, buf, sizeof buf);
    c->trace.names[NDERIVED + j] = strdup(buf);
    c->trace.units[NDERIVED + j] = channel_unit(m, j);
    for (int i = 0; i < n; i++) {
      c->trace.v[(size_t)(NDERIVED + j) * n + i] = d->hist[(size_t)i * stride + 1 + j];
    }
  }
  int a = m->sensor[s->s_head_acc].adr, nk = m->sensor[s->s_neck].adr;
  for (int i = 0; i < n; i++) {
    const double* row = d->hist + (size_t)i * stride + 1;
    c->trace.v[0 * (size_t)n + i] =
        sqrt(row[a] * row[a] + row[a + 1] * row[a + 1] + row[a + 2] * row[a + 2]);
    c->trace.v[1 * (size_t)n + i] = -row[nk + 2];
    c->trace.v[2 * (size_t)n + i] = -row[nk + 4];
    c->trace.v[3 * (size_t)n + i] = row[nk + 0];
    if (s->s_chest >= 0) c->trace.v[4 * (size_t)n + i] = -row[m->sensor[s->s_chest].adr];
    if (s->s_abd >= 0) c->trace.v[5 * (size_t)n + i] = -row[m->sensor[s->s_abd].adr];
  }
  tr->n = n;
  tr->nsig = nsig;
  tr->t = c->trace.t;
  tr->v = c->trace.v;
  tr->names = (const char* const*)c->trace.names;
  tr->units = (const char* const*)c->trace.units;
  tr->title = c->impact_title[0] ? c->impact_title : NULL;
  return 0;
}

/* the viewer's Enter: run the cell's impact for the grid's conditions and give its trace */
int ura_inspect_cell(uraCtx* c, urCell* cell, uraTrace* tr) {
  if (c->last.diff) {
    return ura_fail(c,
                    "a difference grid has no impact of its own; 'design compare' names the "
                    "two designs: load one and run 'impact %g %g'",
                    cell->dpar, cell->dperp);
  }
  const urImpactSetup* s = ura_setup(c);
  urImpactCond cond;
  if (!s || ura_impact_cond(c, &cond)) return -1;
  if (c->last.g && !isnan(c->last.speed)) {
    cond.speed = c->last.speed;
    cond.angle = c->last.angle;
    cond.face = c->last.face;
  }
  if (c->last.g && !strcmp(c->last.source, "computed")) cond.tau = c->last.tau;
  urImpactResult r;
  if (ura_impact_fresh(c, s, &cond, cell->dpar, cell->dperp, &r)) {
    return ura_fail(c, "impact (%g, %g) failed: %s", cell->dpar, cell->dperp,
                    r.status == urSTAT_STOPPED ? "interrupted (Ctrl-C)" : r.reason);
  }
  ura_impact_keep(c, c->last.casename, c->last.wind, &cond, cell->dpar, cell->dperp, &r);
  return ura_last_trace(c, tr);
}
