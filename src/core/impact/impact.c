/* impact.c: one drone-on-person impact at an offset (paper 4.2, Fig. 7) and its injuries;
 * the set-up of a model is in impact_setup.c */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "uasimpact/impact.h"
#include "../engine/engine_internal.h"
#include "impact_internal.h"

#define DEG                 (M_PI / 180.0)
#define HIST_SECONDS_MARGIN 1.2 /* history rows for tmax with this margin */
#define NCHAN               9   /* channel buffers of one run: t, a(3), fz, my, fx, chest, abd */

/* the drone's course and its left normal for a face direction */
static void course(double face_deg, double c[3], double l[3]) {
  double f = face_deg * DEG;
  c[0] = -cos(f);
  c[1] = sin(f);
  c[2] = 0;
  l[0] = -c[1];
  l[1] = c[0];
  l[2] = 0;
}

int ur_impact_work_init(const urImpactSetup* s, urImpactWork* w) {
  const urModel* m = s->m;
  memset(w, 0, sizeof *w);
  w->d = ur_data_new(m);

  /* rows: the engine samples every max(1, floor(sample_dt/dt)) steps for tmax after the jump */
  double every = fmax(1.0, floor(m->opt.sample_dt / m->opt.dt + 1e-9)) * m->opt.dt;
  w->rows = (int)ceil(HIST_SECONDS_MARGIN * m->opt.tmax / every) + 16;
  if (!w->d || ur_data_history(m, w->d, NULL, w->rows)) return -1;
  w->chan = malloc(sizeof(double) * w->rows * NCHAN);
  w->work = malloc(sizeof(double) * ur_injury_work_size(w->rows));
  w->crec = malloc(sizeof(urContactRec) * (s->ncand + 1));
  w->fin = s->endrun ? ur_impact_final_new(w->rows) : NULL;
  return w->chan && w->work && w->crec && (w->fin || !s->endrun) ? 0 : -1;
}

void ur_impact_work_free(urImpactWork* w) {
  ur_data_free(w->d);
  free(w->chan);
  free(w->work);
  free(w->crec);
  ur_impact_final_free(w->fin);
  memset(w, 0, sizeof *w);
}

/* ---- placement at the moment tau ---- */

double ur_impact_tau_shift(const urImpactSetup* s, const urImpactCond* c) {
  if (c->aim || c->tau != urTAU_TOP || !(c->angle < 90.0)) return 0.0;
  double psi = c->angle * DEG;
  return s->rmax * cos(psi) / sin(psi);
}

/* aim mode: the start on the line that passes the head's centre at the eccentricity (up, side),
   R_max before the person's nearest point along it (impact.h) */
static void aim_start(const urImpactSetup* s, const urImpactCond* c, double up, double side,
                      const double cr[3], const double lf[3], double pos[3]) {
  const urModel* m = s->m;
  const urData* d = s->rest;
  double psi = c->angle * DEG, v[3], u[3], p[3];
  for (int k = 0; k < 3; k++) v[k] = cos(psi) * cr[k];
  v[2] = -sin(psi);
  uru_cross3(u, v, lf);
  const double* h = d->gxpos + 3 * s->head_geom;
  for (int k = 0; k < 3; k++) p[k] = h[k] + up * u[k] + side * lf[k];
  double near = INFINITY;
  for (int g = 0; g < m->ngeom; g++) {
    if (m->body[m->geom[g].body].tree == s->drone) continue;
    double w[3] = {d->gxpos[3 * g] - p[0], d->gxpos[3 * g + 1] - p[1], d->gxpos[3 * g + 2] - p[2]};
    near = fmin(near, uru_dot3(w, v) - m->geom[g].rbound);
  }
  double t = (isfinite(near) ? near : 0) - s->rmax;
  for (int k = 0; k < 3; k++) pos[k] = p[k] + t * v[k];
}

void ur_impact_start(const urImpactSetup* s, const urImpactCond* c, double dpar, double dperp,
                     double pos[3], double quat[4], double vel[3]) {
  double cr[3], lf[3];
  course(c->face, cr, lf);

  /* velocity along the course, descending at psi */
  double psi = c->angle * DEG;
  for (int k = 0; k < 3; k++) vel[k] = c->speed * (cos(psi) * cr[k]);
  vel[2] = -c->speed * sin(psi);

  if (c->aim) {
    aim_start(s, c, dpar, dperp, cr, lf, pos);
  } else {
    /* centre R_max above the head top, offset from the head CG along and across the course;
       with tau at head-top level the offset is reached R_max / tan(psi) further on, so the
       start is that much back along the course */
    double along = dpar - ur_impact_tau_shift(s, c);
    for (int k = 0; k < 2; k++) pos[k] = s->head_cg[k] + along * cr[k] + dperp * lf[k];
    pos[2] = s->head_top + s->rmax;
  }

  /* attitude: along axis on the course, then yaw, pitch, roll in the drone frame */
  static const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
  double qc[4], qy[4], qp[4], qr[4], t[4], u[4];
  uru_axisangle2quat(qc, ez, atan2(cr[1], cr[0]));
  uru_axisangle2quat(qy, ez, c->yaw * DEG);
  uru_axisangle2quat(qp, ey, c->pitch * DEG);
  uru_axisangle2quat(qr, ex, c->roll * DEG);
  uru_mulquat(t, qc, qy);
  uru_mulquat(u, t, qp);
  uru_mulquat(quat, u, qr);
}

/* entry and exit times of a point moving as p + v t through a sphere (centre q, radius r);
   0 if the line misses */
static int sphere_cross(const double p[3], const double v[3], const double q[3], double r,
                        double* t0, double* t1) {
  double w[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  double a = uru_dot3(v, v), b = 2 * uru_dot3(w, v), cc = uru_dot3(w, w) - r * r;
  double disc = b * b - 4 * a * cc;
  if (a <= 0 || disc < 0) return 0;
  *t0 = (-b - sqrt(disc)) / (2 * a);
  *t1 = (-b + sqrt(disc)) / (2 * a);
  return *t1 >= 0;
}

/* latest time at which a drone sphere can still touch a person's sphere (-1: never) */
static double exit_time(const urImpactSetup* s, const urData* d, const double vel[3]) {
  const urModel* m = s->m;
  double texit = -1;
  for (int k = 0; k < s->ncand; k++) {
    int ga = s->cand[k][0], gb = s->cand[k][1];
    double t0, t1;
    if (sphere_cross(d->gxpos + 3 * ga, vel, d->gxpos + 3 * gb,
                     m->geom[ga].rbound + m->geom[gb].rbound, &t0, &t1)) {
      if (t1 > texit) texit = t1;
    }
  }
  return texit;
}

int ur_impact_may_contact(const urImpactSetup* s, const urImpactCond* c, double dpar,
                          double dperp) {
  /* place a copy of the rest pose's kinematics: only the drone moves */
  const urModel* m = s->m;
  double pos[3], quat[4], vel[3];
  ur_impact_start(s, c, dpar, dperp, pos, quat, vel);
  urData* d = s->rest;
  const double* R = d->xmat + 9 * s->drone;
  double qm[9], cur[3];

  /* pose of the drone's ellipsoids at tau, from the rest pose by a rigid motion */
  uru_quat2mat(qm, quat);
  memcpy(cur, d->xcom + 3 * s->drone, sizeof cur);

  /* any candidate pair whose drone sphere's straight path crosses the person's sphere */
  for (int k = 0; k < s->ncand; k++) {
    int g = s->cand[k][0], h = s->cand[k][1];
    double rel[3], loc[3], p[3], t0, t1;
    for (int j = 0; j < 3; j++) rel[j] = d->gxpos[3 * g + j] - cur[j];
    uru_mulmat3tvec(loc, R, rel);
    uru_mulmat3vec(p, qm, loc);
    for (int j = 0; j < 3; j++) p[j] += pos[j];
    if (sphere_cross(p, vel, d->gxpos + 3 * h, m->geom[g].rbound + m->geom[h].rbound, &t0, &t1)) {
      return 1;
    }
  }
  return 0;
}

/* ---- the run ---- */

int ur_impact_channel(const urImpactSetup* s, const urImpactWork* w, int sensor, int comp,
                      double* out) {
  const urModel* m = s->m;
  const urData* d = w->d;
  if (sensor < 0 || comp < 0 || comp >= m->sensor[sensor].dim) return -1;
  int stride = 1 + m->nsensordata, col = 1 + m->sensor[sensor].adr + comp;
  for (int i = 0; i < d->nhist; i++) out[i] = d->hist[(size_t)i * stride + col];
  return d->nhist;
}

/* a run placed: from the settled stance, the drone placed at tau and jumped to its first
   possible contact; *texit: absolute time by which a drone that has not touched has passed */
void ur_impact_begin(const urImpactSetup* s, urImpactWork* w, const urImpactCond* c, double dpar,
                     double dperp, urImpactResult* r, double* texit) {
  const urModel* m = s->m;
  urData* d = w->d;
  memset(r, 0, sizeof *r);
  r->t_first = -1;
  double pos[3], quat[4], vel[3];
  ur_impact_start(s, c, dpar, dperp, pos, quat, vel);
  ur_data_copy(m, d, s->rest);
  ur_run_start(m, d, s->drone, pos, quat, vel);
  *texit = d->time + exit_time(s, d, vel);
  ur_impact_final_start(w->fin, c->speed);
}

/* after a step: 0 go on, 1 the run is over (ended, failed, drone passed, window closed or,
   with endrun 1, every criterion final), -1 the history buffer is full (r says so) */
int ur_impact_after_step(const urImpactSetup* s, const urImpactWork* w, double texit,
                         const urInjuryParams* ip, urImpactResult* r) {
  const urModel* m = s->m;
  const urData* d = w->d;
  if (d->status < 0) return 1;
  if (d->t_first < 0 && d->time > texit + 2 * m->opt.dt) return 1;
  if (d->t_first >= 0 && d->time > d->t_first + s->window) return 1;
  if (w->fin && ip && d->status == urSTAT_OK && ur_impact_final(s, w->fin, d, ip)) return 1;
  if (d->nhist >= w->rows - 1) {
    snprintf(r->reason, sizeof r->reason, "history buffer full at t = %g s", d->time);
    r->status = urSTAT_BADARG;
    return -1;
  }
  return d->status != urSTAT_OK;
}

/* the contacts through which the drone acts, after a step: the forces are those of the step's
   start, when ur_step_accept marks contact (engine_run.c); only the pairs with a force (the
   contact pass lists them) and the airbags' targets are visited. A coarse step (urOption.adapt)
   started at d->tprev (none starts with a drone contact: its forces are zero) */
static void contact_note(urContactRec* c, double f, double t) {
  if (!(f > 0)) return;
  if (c->t_first < 0) c->t_first = t;
  c->t_last = t;
  if (f > c->fmax) {
    c->fmax = f;
    c->t_fmax = t;
  }
}

static void contacts_record(const urImpactSetup* s, urImpactWork* w) {
  const urModel* m = s->m;
  const urData* d = w->d;
  double t = d->pend ? d->tprev : d->time - m->opt.dt;
  for (int k = 0; k < d->npactive; k++) {
    int i = d->plist[m->npair + k], c = s->cand_of[i];
    if (c >= 0) contact_note(w->crec + c, d->pair[i].fn, t);
  }
  for (int b = 0; b < m->nbag; b++) {
    if (!d->bag[b].active) continue;
    for (int j = 0; j < m->bag[b].ntarget; j++) {
      int c = s->cand_of[ur_cand_bag_slot(m, b, j)];
      if (c >= 0) contact_note(w->crec + c, d->bag[b].ftgt[j], t);
    }
  }
}

int ur_impact_run(const urImpactSetup* s, urImpactWork* w, const urImpactCond* c,
                  const urInjuryParams* ip, double dpar, double dperp, urImpactResult* r) {
  double texit;
  ur_impact_begin(s, w, c, dpar, dperp, r, &texit);
  for (int k = 0; k < s->ncand; k++) {
    w->crec[k] = (urContactRec){-1, -1, 0, -1};
  }

  /* step until the run ends, or the drone has passed the person without touching */
  while (w->d->status == urSTAT_OK) {
    ur_step(s->m, w->d);
    contacts_record(s, w);
    int e = ur_impact_after_step(s, w, texit, ip, r);
    if (e < 0) return -1;
    if (e) break;
  }
  return ur_impact_finish(s, w, ip, r);
}

/* the result of a finished run: status, contact, injury criteria and P from its histories */
int ur_impact_finish(const urImpactSetup* s, urImpactWork* w, const urInjuryParams* ip,
                     urImpactResult* r) {
  const urModel* m = s->m;
  urData* d = w->d;
  r->status = d->status;
  if (d->status < 0) {
    snprintf(r->reason, sizeof r->reason, "%s", d->msg[0] ? d->msg : ur_status_str(d->status));
    return -1;
  }
  r->t_first = d->t_first;
  r->contact = d->t_first >= 0;
  r->nextrap = ur_extrapolated(m, d, r->extrap, sizeof r->extrap);
  if (d->status == urSTAT_TMAX && !r->contact) {
    /* a drone that has passed the person ends the run earlier (ur_impact_after_step): this one
       could still touch it, and P = 0 would be a guess */
    snprintf(r->reason, sizeof r->reason,
             "the run reached tmax (%g s) before the drone touched or passed the person; "
             "accepted: a larger tmax, a smaller or faster drone",
             m->opt.tmax);
    return -1;
  }
  if (!r->contact || d->nhist < 2) return 0;

  /* channels: time, head acceleration, neck Fz and My (SAE signs), deflections */
  int n = d->nhist;
  double *t = w->chan, *ax = t + n, *ay = ax + n, *az = ay + n, *fz = az + n, *my = fz + n;
  double *fx = my + n, *dc = fx + n;
  int stride = 1 + m->nsensordata;
  for (int i = 0; i < n; i++) t[i] = d->hist[(size_t)i * stride];
  ur_impact_channel(s, w, s->s_head_acc, 0, ax);
  ur_impact_channel(s, w, s->s_head_acc, 1, ay);
  ur_impact_channel(s, w, s->s_head_acc, 2, az);
  ur_impact_channel(s, w, s->s_neck, 2, fz);
  ur_impact_channel(s, w, s->s_neck, 4, my);
  ur_impact_channel(s, w, s->s_neck, 0, fx);
  for (int i = 0; i < n; i++) {
    fz[i] = -fz[i]; /* tension: the neck pulls the head down */
    my[i] = -my[i]; /* flexion: the neck resists chin-down rotation */
  }

  urInjuryInput in = {n, t, {ax, ay, az}, fz, my, fx, NULL, NULL, 1}; /* HIC36 unused */
  double* de = dc + n;
  double* da = NULL;
  if (s->s_chest >= 0) {
    ur_impact_channel(s, w, s->s_chest, 0, dc);
    for (int i = 0; i < n; i++) dc[i] = -dc[i]; /* plate pushed back: compression > 0 */
    in.thorax_d = dc;
  }
  if (s->s_abd >= 0) {
    da = de;
    ur_impact_channel(s, w, s->s_abd, 0, da);
    for (int i = 0; i < n; i++) da[i] = -da[i];
    in.abdomen_d = da;
  }
  int rc = ur_injury_eval(&in, ip, w->work, &r->inj);
  if (rc) {
    snprintf(r->reason, sizeof r->reason, "injury evaluation failed (%d)", rc);
    r->status = urSTAT_BADARG;
    return -1;
  }
  r->p = r->inj.p_total;
  return 0;
}
