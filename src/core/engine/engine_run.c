/* engine_run.c: the forward pipeline, time stepping (semi-implicit Euler or RK4 with an exact
 * Lie-group update of quaternions), failure detection, the free-flight jump to the first
 * possible contact, and the end of a run. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- stage timer ---------------------------------------------------

// The stage timer of a step alone (engine_internal.h): only in an object built with urSTEP_PROF
// (make bench); otherwise urLAP and urLAP_START are nothing. Per thread: one stepping thread's
// counters and the tick at which its current stage began.
#ifdef urSTEP_PROF
static _Thread_local unsigned long long* step_prof;
static _Thread_local unsigned long long step_t0;

void ur_step_prof(unsigned long long* prof) {
  step_prof = prof;
}

// the time since the stage began to stage k, and the next stage begins now
static void step_lap(int k) {
  if (step_prof) {
    unsigned long long t = uru_ticks();
    step_prof[k] += t - step_t0;
    step_t0 = t;
  }
}
#define urLAP(k)      step_lap(k)
#define urLAP_START() (step_t0 = step_prof ? uru_ticks() : 0)
#else
#define urLAP(k)      ((void)0)
#define urLAP_START() ((void)0)
#endif

//---------------------------------- forward -------------------------------------------------------

// the forward pipeline up to the accelerations: positions, velocities, the restraint kinematics
// and the contacts' broad phase, the applied forces (gravity compensation, restraints, contacts,
// airbags). The lanes run the same stages: the first four over vectors, then ur_forward_loads.
// As in the lanes, the ellipsoids' orientations are computed where first used (ur_geom_xmat):
// the bounding spheres cull most of them in most steps.
void ur_forward_pre(const urModel* m, urData* d) {
  ur_kinematics_bodies(m, d);
  ur_kinematics_gpos(m, d);
  memset(d->gmat_ok, 0, (size_t)m->ngeom);
  ur_velocities(m, d);
  urLAP(urSTEP_KIN);
  ur_restraints_kin(m, d);
  urLAP(urSTEP_RKIN);
  ur_contacts_broad(m, d);
  urLAP(urSTEP_BROAD);
  ur_forward_loads(m, d, m->rstb, m->nrstb);
}


// the applied forces of the forward pipeline, from the poses, velocities, restraint kinematics
// (rkin) and pair depths of the broad phase; the restraints of the bodies rstb[0..nrstb-1] (the
// lanes compute the rest over vectors)
void ur_forward_loads(const urModel* m, urData* d, const int* rstb, int nrstb) {
  memset(d->fext, 0, 6 * (size_t)m->nbody * sizeof(double));
  memset(d->qfrc, 0, (size_t)m->nv * sizeof(double));
  for (int j = 0; j < m->ngrav; j++) {
    int i = m->grav[j];
    const urBody* b = m->body + i;
    double f[3];
    for (int k = 0; k < 3; k++) {
      f[k] = -(1 - b->gravity) * b->mass * m->opt.gravity[k];
    }
    ur_apply_force(m, d, i, f, d->xcom + 3 * i);
  }
  urLAP(urSTEP_GRAV);
  ur_restraints(m, d, rstb, nrstb);
  urLAP(urSTEP_RESTR);
  ur_contacts_narrow(m, d);
  urLAP(urSTEP_NARROW);
  ur_airbags(m, d);
  urLAP(urSTEP_BAG);
}


// the forward pipeline after the accelerations: joint loads, sensors, the finiteness check
int ur_forward_post(const urModel* m, urData* d) {
  ur_reactions(m, d);
  ur_sensors(m, d);
  for (int k = 0; k < m->nv; k++) {
    if (!isfinite(d->qacc[k])) {
      char msg[urMSGLEN];
      snprintf(msg, sizeof(msg), "non-finite acceleration in joint dof %d at t = %.6g s", k,
               d->time);
      ur_set_status(d, urSTAT_NONFINITE, msg);
      break;
    }
  }
  return d->status;
}


int ur_forward(const urModel* m, urData* d) {
  m = ur_data_model(m, d); // a run whose joint broke: its own topology
  if (d->status < 0) {
    return d->status;
  }
  ur_forward_pre(m, d);
  ur_aba(m, d);
  urLAP(urSTEP_ABA);
  int st = ur_forward_post(m, d);
  urLAP(urSTEP_POST);
  return st;
}

//---------------------------------- integration ---------------------------------------------------

// qout = q0 "+" h * dq (dq in tangent coordinates: nv values; exact exponential for quaternions)
static void addpos(const urModel* m, double* qout, const double* q0, const double* dq, double h) {
  if (qout != q0) {
    memcpy(qout, q0, (size_t)m->nq * sizeof(double));
  }
  ur_addpos_joints(m, qout, dq, h);
}


// tangent-coordinate derivative at offset th (h * previous stage) with velocity v
static void tangent(const urModel* m, double* dq, const double* th, const double* v) {
  memcpy(dq, v, (size_t)m->nv * sizeof(double));
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    int off = b->jtype == urJNT_FREE ? 3 : (b->jtype == urJNT_SPHERICAL ? 0 : -1);
    if (off >= 0 && th) {
      double J[9];
      uru_rotvec_jrinv(J, th + b->vadr + off);
      uru_mulmat3vec(dq + b->vadr + off, J, v + b->vadr + off);
    }
  }
}


// check the state after a step
static void checkstate(const urModel* m, urData* d) {
  char msg[urMSGLEN];
  for (int k = 0; k < m->nq; k++) {
    if (!isfinite(d->qpos[k])) {
      snprintf(msg, sizeof(msg), "non-finite position (qpos %d) at t = %.6g s", k, d->time);
      ur_set_status(d, urSTAT_NONFINITE, msg);
      return;
    }
  }
  for (int k = 0; k < m->nv; k++) {
    if (!isfinite(d->qvel[k])) {
      snprintf(msg, sizeof(msg), "non-finite velocity (qvel %d) at t = %.6g s", k, d->time);
      ur_set_status(d, urSTAT_NONFINITE, msg);
      return;
    }
    if (fabs(d->qvel[k]) > m->opt.vmax) {
      snprintf(msg, sizeof(msg), "velocity %.3g beyond vmax (qvel %d) at t = %.6g s", d->qvel[k], k,
               d->time);
      ur_set_status(d, urSTAT_EXPLODE, msg);
      return;
    }
  }
}


// how fast spin can widen an ellipsoid (engine_internal.h). For an ellipsoid (semi-axes a_l, in
// a frame of its own) o = 0 and k = kr: h = |A u| and dh/dt = -w.(u x A^2 u) / |A u|, whose
// parts about each axis are at most |w_l| |a_m - a_n| (l, m, n the three axes: |u_m u_n| /
// |(a_m u_m, a_n u_n)| <= 1 / (a_m + a_n)), and in all at most |w| (a_max - a_min) (the part of
// A^2 u across u is at most (a_max - a_min) |A u|: the variance of a^2 under the weights u_l^2 is
// at most (a_max - a_min)^2 times their mean, by the Bhatia-Davis bound). A superellipsoid of
// degree p lies between the ellipsoid E of its semi-axes and s E, s = 3^(1/q - 1/2) with q =
// p/(p - 1) (its half-width is a q-norm, E's the 2-norm), so it grows by at most s h_E(t) -
// h_E(0) <= (s - 1) a_max + E's growth: o = (s - 1) a_max and k = s times E's rate (more than
// enough); kr = |w| rbound (the support point's speed about the centre).
urSpinBound ur_spin_bound(const urGeom* ge, const double wb[3]) {
  double w[3], wn = uru_norm3(wb);
  uru_mulmat3tvec(w, ge->gmat, wb); // in the ellipsoid's frame
  const double* a = ge->size;
  double amax = fmax(a[0], fmax(a[1], a[2])), amin = fmin(a[0], fmin(a[1], a[2]));
  double axes = fabs(w[0]) * fabs(a[1] - a[2]) + fabs(w[1]) * fabs(a[2] - a[0]) +
                fabs(w[2]) * fabs(a[0] - a[1]);
  urSpinBound b = {0, fmin(axes, wn * (amax - amin)), 0};
  b.kr = b.k;
  if (ge->degree > 2) {
    double q = ge->degree / (ge->degree - 1), sc = pow(3, 1 / q - 0.5);
    b.o = (sc - 1) * amax;
    b.k *= sc;
    b.kr = wn * ge->rbound;
  }
  return b;
}


// centre velocity of ellipsoid g
static void geomvel(const urModel* m, const urData* d, int g, double v[3]) {
  const urGeom* ge = m->geom + g;
  ur_point_vel(m, d, ge->body, ge->pos, v);
}


// does a gap s > 0 that closes at most at rate c (plus a_clear t^2/2) stay open for T
static int gap_holds(const urModel* m, double s, double c, double T) {
  return s > 0 && s > c * T + 0.5 * m->opt.a_clear * T * T;
}


// does a gap s > 0 whose centres close at most at rate c stay open for T while spin widens the
// two ellipsoids (their bounds summed in b: either form of ur_spin_bound)
static int gap_spin_holds(const urModel* m, double s, double c, const urSpinBound* b, double T) {
  return gap_holds(m, s - b->o, c + b->k, T) || gap_holds(m, s, c + b->kr, T);
}


// ellipsoids g1, g2 cannot touch within T (sep: a lower bound on their distance now; u: the
// pair's last separating direction from g1 towards g2, or zero). The distance is the largest
// gap (c2 - c1).e - h1(e) - h2(e) over unit e (h the half-widths): it shrinks at most at the
// relative speed of the centres while spin widens the two (ur_spin_bound). Sharper, by separating
// axes: along a fixed unit e that gap bounds the distance from below and its centres close at
// most at rate (v1 - v2).e; tried along the centre line with the bounding spheres (h = rbound,
// unchanged by spin) and with the ellipsoids, and along u. Each bound comes with a_clear T^2/2
// for the relative acceleration.
static int stays_clear(const urModel* m, urData* d, int g1, int g2, double sep, const double u[3],
                       double T) {
  double v1[3], v2[3], e[3];
  const double* c1 = d->gxpos + 3 * g1;
  const double* c2 = d->gxpos + 3 * g2;
  double dc[3] = {c2[0] - c1[0], c2[1] - c1[1], c2[2] - c1[2]};
  double L = uru_norm3(dc);
  geomvel(m, d, g1, v1);
  geomvel(m, d, g2, v2);
  urSpinBound b1 = ur_spin_bound(m->geom + g1, d->cvel + 6 * m->geom[g1].body);
  urSpinBound b2 = ur_spin_bound(m->geom + g2, d->cvel + 6 * m->geom[g2].body);
  urSpinBound b = {b1.o + b2.o, b1.k + b2.k, b1.kr + b2.kr};
  double dv[3] = {v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]};
  if (gap_spin_holds(m, sep, uru_norm3(dv), &b, T)) {
    return 1;
  }
  if (L > 0) {
    e[0] = dc[0] / L;
    e[1] = dc[1] / L;
    e[2] = dc[2] / L;
    double ce = uru_dot3(dv, e);
    if (gap_holds(m, L - m->geom[g1].rbound - m->geom[g2].rbound, ce, T) ||
        gap_spin_holds(m, L - ur_geom_halfwidth(m, d, g1, e) - ur_geom_halfwidth(m, d, g2, e), ce,
                       &b, T)) {
      return 1;
    }
  }
  if (u[0] == 0 && u[1] == 0 && u[2] == 0) {
    return 0;
  }
  double s = uru_dot3(dc, u) - ur_geom_halfwidth(m, d, g1, u) - ur_geom_halfwidth(m, d, g2, u);
  return gap_spin_holds(m, s, uru_dot3(dv, u), &b, T);
}


// is contact candidate k (ur_cand_at) across the projectile tree clear for T (1 also for
// candidates within a tree or with the ground). A membrane airbag's target is never proved
// clear: its fabric is not the bag's declared ellipsoid (the inflated bag hangs below it and
// deforms), and its depth is a placeholder while the bag rides rigidly (engine_membrane.c), so
// such a run ends by t_quiet alone.
static int item_clear(const urModel* m, urData* d, int k, double T) {
  int tree = d->proj;
  urCand c;
  if (ur_cand_at(m, k, &c) || c.g2 < 0 ||
      ur_geom_intree(m, c.g1, tree) == ur_geom_intree(m, c.g2, tree)) {
    return 1;
  }
  if (c.bag < 0) {
    return stays_clear(m, d, c.g1, c.g2, -d->pdepth[c.idx], d->pair[c.idx].u, T);
  }
  if (m->bag[c.bag].mem) {
    return 0;
  }
  const urBagData* bd = d->bag + c.bag;
  return stays_clear(m, d, c.g1, c.g2, -bd->depth[c.idx], bd->u[c.idx], T);
}


// the projectile tree provably cannot touch the rest again within T: every pair and airbag
// target across it stays clear (stays_clear, a_clear bounding the relative acceleration). The
// item that failed last is tried first (d->clear_hint): in the tail of a run the same one
// usually fails step after step.
static int proj_clear(const urModel* m, urData* d, double T) {
  int n = ur_cand_count(m);
  int h = d->clear_hint < n ? d->clear_hint : 0;
  if (!item_clear(m, d, h, T)) {
    return 0;
  }
  for (int k = 0; k < n; k++) {
    if (k != h && !item_clear(m, d, k, T)) {
      d->clear_hint = k;
      return 0;
    }
  }
  return 1;
}


// end of a run (after ur_run_start): contact over (for t_quiet, or for t_clear with the
// projectile provably clear until t_quiet), motion settled, or maximum time
static void checkend(const urModel* m, urData* d) {
  double over = d->t_first >= 0 ? d->time - d->t_last : -1;
  if (d->t_first >= 0 &&
      (over >= m->opt.t_quiet ||
       (over >= m->opt.t_clear && proj_clear(m, d, m->opt.t_quiet - over + m->opt.dt)))) {
    ur_set_status(d, urSTAT_SEPARATED, "contact over");
  } else if (d->t_first >= 0 && d->t_calm >= m->opt.t_quiet) {
    ur_set_status(d, urSTAT_SETTLED, "motion settled");
  } else if (d->time - d->t_jump >= m->opt.tmax - 0.5 * m->opt.dt) {
    ur_set_status(d, urSTAT_TMAX, d->t_first >= 0 ? "maximum time" : "maximum time, no contact");
  }
}


// bookkeeping on an accepted state: histories, peaks, contact activity (a coarse step counts
// its calm time whole; ntouch counts the coarse steps that started in contact: none should)
void ur_step_accept(const urModel* m, urData* d) {
  ur_outputs(m, d);
  ur_restraints_commit(m, d);
  ur_contacts_commit(m, d);
  if (m->nmemd) {
    urm_bags_advance(m, d);
  }
  if (d->proj >= 0 && ur_tree_active(m, d, d->proj)) {
    if (d->t_first < 0) {
      d->t_first = d->time;
    }
    d->t_last = d->time;
    d->ntouch += d->coarse;
  }
  d->t_calm = d->energy < m->opt.ke_settle ? d->t_calm + ur_step_h(m, d) : 0;
}


// a sufficient test, without square root or division, for coarse_clear's exact test along the
// centre line: gap_holds(m, L - r1 - r2, ce / L, T) with L = |dc| and ce the centres' closing
// rate along dc times L (computed as coarse_clear does), r = r1 + r2, A = 0.5 a_clear T^2 as
// gap_holds computes it, T >= 0. With S = r + max(A, 0) and c = max(ce, 0), since S L <= (S^2 +
// L^2)/2: L^2 > S^2 + 2 c T gives L - S - c T / L > 0. Asking for it with a factor 1 + 2^-20
// leaves a gap of at least 2^-23 L, which dwarfs the exact test's rounding (some 14 units of
// 2^-53 L: |rhs| <= 1.5 L and a negative rate only rounds towards 0), so 1 here means 1 there;
// a NaN, or an overflow of the right side, gives 0 (the exact test decides).
int ur_gap_quick(const double dc[3], double ce, double r, double A, double T) {
  double D = dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2];
  double S = r + (A < 0 ? 0 : A), c = ce < 0 ? 0 : ce; // (not fmax: a NaN must stay one)
  return D > (S * S + 2 * c * T) * (1 + 0x1p-20);
}


// the proof of proj_clear for a coarse step, and the projectile's ellipsoids that can touch the
// ground kept above it (their bounding spheres' lowest points falling at most at their centres'
// speed plus a_clear T^2/2), for T. Most steps that it holds for, it holds for every candidate
// by the bounding spheres alone, along the centre line (a separating axis, as in
// stays_clear), with each ellipsoid's centre velocity computed once: those that fail it are
// tried by item_clear. The item that failed last is tried first (d->clear_hint).
static int coarse_clear(const urModel* m, urData* d, double T) {
  int n = ur_cand_count(m), ng = m->ngeom > 0 ? m->ngeom : 1;
  double vel[3 * ng];
  unsigned char have[ng];
  memset(have, 0, (size_t)ng);
  int h = d->clear_hint < n ? d->clear_hint : 0;
  if (!item_clear(m, d, h, T)) {
    return 0;
  }
  double A = 0.5 * m->opt.a_clear * T * T;
  urCand c;
  for (int k = 0; ur_cand_at(m, k, &c) == 0; k++) {
    int in1 = ur_geom_intree(m, c.g1, d->proj);
    if (c.g2 >= 0 && in1 == ur_geom_intree(m, c.g2, d->proj)) {
      continue;
    }
    int gs[2] = {c.g1, c.g2};
    for (int j = 0; j < 2; j++) {
      if (gs[j] >= 0 && !have[gs[j]]) {
        geomvel(m, d, gs[j], vel + 3 * gs[j]);
        have[gs[j]] = 1;
      }
    }
    const double* c1 = d->gxpos + 3 * c.g1;
    if (c.g2 < 0) {
      if (in1 && !gap_holds(m, c1[2] - m->geom[c.g1].rbound, fmax(-vel[3 * c.g1 + 2], 0), T)) {
        return 0;
      }
      continue;
    }
    const double* c2 = d->gxpos + 3 * c.g2;
    double dc[3] = {c2[0] - c1[0], c2[1] - c1[1], c2[2] - c1[2]}, ce = 0;
    for (int i = 0; i < 3; i++) {
      ce += (vel[3 * c.g1 + i] - vel[3 * c.g2 + i]) * dc[i];
    }
    double r1 = m->geom[c.g1].rbound, r2 = m->geom[c.g2].rbound;
    if (ur_gap_quick(dc, ce, r1 + r2, A, T)) {
      continue; // the exact test below would pass
    }
    double L = uru_norm3(dc);
    if (L > 0 && gap_holds(m, L - r1 - r2, ce / L, T)) {
      continue;
    }
    if (k != h && !item_clear(m, d, k, T)) {
      d->clear_hint = k;
      return 0;
    }
  }
  return 1;
}


// may the next step be coarse (opt.adapt >= 2): a semi-implicit Euler run with a projectile
// and no membrane bag (whose fabric is stepped at dt), no projectile contact active at the
// step just taken, not within a coarse step of tmax, and the projectile provably clear of the
// rest and of the ground (proj_clear, from this step's start: the kinematics d holds) for this
// step, the coarse one and one step dt more. A run broken by a fracture takes coarse steps on
// the same rule: its pieces fly free of the person then.
static int coarse_next(const urModel* m, urData* d, double h) {
  int K = m->opt.adapt;
  double dt = m->opt.dt, T = h + K * dt + dt;
  if (K < 2 || d->status != urSTAT_OK || d->proj < 0 || m->nmemd ||
      m->opt.integrator != urINT_EULER || d->time - d->t_jump + (K - 0.5) * dt >= m->opt.tmax ||
      ur_tree_active(m, d, d->proj)) {
    return 0;
  }
  return coarse_clear(m, d, T);
}


// after the update: advance time (a coarse step by adapt additions of dt, so that its time is
// that of as many fine steps), check the state and the end of the run, choose the next step
int ur_step_end(const urModel* m, urData* d) {
  double h = ur_step_h(m, d);
  int n = d->coarse ? m->opt.adapt : 1;
  for (int k = 0; k < n; k++) {
    d->time += m->opt.dt;
  }
  d->nstep += n;
  d->ncoarse += d->coarse;
  checkstate(m, d);
  if (d->status == urSTAT_OK && d->proj >= 0) {
    checkend(m, d);
  }
  d->coarse = m->opt.adapt > 1 && coarse_next(m, d, h);
  return d->status;
}


// may a step start: not failed, not asked to stop
int ur_step_begin(const urModel* m, urData* d) {
  if (d->status < 0) {
    return d->status;
  }
  if (m->opt.stop && *m->opt.stop) {
    ur_set_status(d, urSTAT_STOPPED, "stopped on request");
  } else if (m->nraw) {
    char msg[urMSGLEN];
    ur_model_raw_text(m, msg, sizeof(msg));
    ur_set_status(d, urSTAT_BADARG, msg);
  }
  return d->status;
}


// the rest of a semi-implicit Euler step after a successful forward pass: accept the state,
// velocities first, positions with the new velocities, then the state checks
int ur_step_euler(const urModel* m, urData* d) {
  double h = ur_step_h(m, d);
  ur_step_accept(m, d);
  for (int k = 0; k < m->nv; k++) {
    d->qvel[k] += h * d->qacc[k];
  }
  addpos(m, d->qpos, d->qpos, d->qvel, h);
  int st = ur_step_end(m, d);
  urLAP(urSTEP_EULER);
  return st;
}


int ur_step(const urModel* m, urData* d) {
  // a hinge that broke in the last step releases its joint: from here on the run's own model
  if (m->nfrac > 0 && d->status >= 0) {
    ur_fracture_release(m, d);
    m = ur_data_model(m, d);
  }
  double h = m->opt.dt;
  int nv = m->nv, nq = m->nq;
  if (ur_step_begin(m, d) < 0) {
    return d->status;
  }
  urLAP_START();

  // forward at the current state
  if (ur_forward(m, d) < 0) {
    return d->status;
  }
  if (m->opt.integrator != urINT_RK4) {
    return ur_step_euler(m, d);
  }
  ur_step_accept(m, d);

  {
    // RK4; scratch: q0 | v0 | dq sum | a sum | stage dq | stage offset
    double* q0 = d->scratch;
    double* v0 = q0 + nq;
    double* dqs = v0 + nv;
    double* as = dqs + nv;
    double* dqk = as + nv;
    double* th = dqk + nv;
    memcpy(q0, d->qpos, (size_t)nq * sizeof(double));
    memcpy(v0, d->qvel, (size_t)nv * sizeof(double));

    // stage 1
    memcpy(dqk, v0, (size_t)nv * sizeof(double));
    for (int k = 0; k < nv; k++) {
      dqs[k] = dqk[k];
      as[k] = d->qacc[k];
    }

    // stages 2-4
    static const double c[3] = {0.5, 0.5, 1.0}, w[3] = {2, 2, 1};
    for (int s = 0; s < 3; s++) {
      for (int k = 0; k < nv; k++) {
        th[k] = c[s] * h * dqk[k];
        d->qvel[k] = v0[k] + c[s] * h * d->qacc[k];
      }
      addpos(m, d->qpos, q0, dqk, c[s] * h);
      if (ur_forward(m, d) < 0) {
        return d->status;
      }
      tangent(m, dqk, th, d->qvel);
      for (int k = 0; k < nv; k++) {
        dqs[k] += w[s] * dqk[k];
        as[k] += w[s] * d->qacc[k];
      }
    }

    // combine
    addpos(m, d->qpos, q0, dqs, h / 6);
    for (int k = 0; k < nv; k++) {
      d->qvel[k] = v0[k] + h / 6 * as[k];
    }
  }
  return ur_step_end(m, d);
}

//---------------------------------- runs ----------------------------------------------------------

// any force between the tree and the rest of the world
int ur_tree_active(const urModel* m, const urData* d, int tree) {
  for (int k = 0; k < d->npactive; k++) {
    int i = d->plist[m->npair + k];
    const urPair* p = m->pair + i;
    if (d->pair[i].active &&
        ur_geom_intree(m, p->geom1, tree) != ur_geom_intree(m, p->geom2, tree)) {
      return 1;
    }
  }
  for (int i = 0; i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    if (!d->bag[i].active) {
      continue;
    }
    for (int t = 0; t < b->ntarget; t++) {
      if (d->bag[i].ftgt[t] > 0 &&
          ur_geom_intree(m, b->geom, tree) != ur_geom_intree(m, b->target[t], tree)) {
        return 1;
      }
    }
  }
  return 0;
}


// earliest time at which sphere (c, r) moving with v touches sphere (cs, rs); INFINITY if never
static double sweep(const double c[3], double r, const double v[3], const double cs[3], double rs) {
  double D[3] = {c[0] - cs[0], c[1] - cs[1], c[2] - cs[2]};
  double R = r + rs;
  double a = uru_dot3(v, v), b = 2 * uru_dot3(D, v), cc = uru_dot3(D, D) - R * R;
  if (cc <= 0) {
    return 0;
  }
  double disc = b * b - 4 * a * cc;
  if (a <= 0 || disc < 0) {
    return INFINITY;
  }
  double t = (-b - sqrt(disc)) / (2 * a);
  return t >= 0 ? t : INFINITY;
}


// earliest possible contact of the moving geom gm with geom gs (-1: ground) given margin
static double firsthit(const urModel* m, const urData* d, int gm, int gs, const double v[3]) {
  double r = m->geom[gm].rbound + m->opt.jump_margin;
  const double* c = d->gxpos + 3 * gm;
  if (gs < 0) {
    double gap = c[2] - r;
    if (gap <= 0) {
      return 0;
    }
    return v[2] < 0 ? gap / (-v[2]) : INFINITY;
  }
  return sweep(c, r, v, d->gxpos + 3 * gs, m->geom[gs].rbound);
}


// world ellipsoid of geom g from the current kinematics
// smallest separation between the tree's ellipsoids and those they can touch (pairs and bag
// targets, ground excluded); -INFINITY if some already overlap. Exact distances are computed in
// the order of a cheap lower bound (bounding-sphere gap, support-function bound) and only while
// that bound is below the best so far.
static double separation(const urModel* m, urData* d, int root) {
  int n = ur_cand_count(m), k = 0;
  int g1s[n > 0 ? n : 1], g2s[n > 0 ? n : 1];
  double lb[n > 0 ? n : 1];
  static const double u0[3] = {0, 0, 0};
  urCand c;
  for (int i = 0; ur_cand_at(m, i, &c) == 0; i++) {
    int g1 = c.g1, g2 = c.g2;
    if (g2 < 0 || ur_geom_intree(m, g1, root) == ur_geom_intree(m, g2, root)) {
      continue;
    }
    const double* c1 = d->gxpos + 3 * g1;
    const double* c2 = d->gxpos + 3 * g2;
    double dx[3] = {c2[0] - c1[0], c2[1] - c1[1], c2[2] - c1[2]};
    double gap = uru_norm3(dx) - m->geom[g1].rbound - m->geom[g2].rbound;
    g1s[k] = g1;
    g2s[k] = g2;
    lb[k++] = fmax(gap, -ur_depth_bound(m, d, g1, g2, u0));
  }

  // exact distances, smallest bound first, until no bound is below the best
  double smin = INFINITY;
  while (k > 0) {
    int j = 0;
    for (int i = 1; i < k; i++) {
      if (lb[i] < lb[j]) {
        j = i;
      }
    }
    if (!(lb[j] < smin)) {
      break;
    }
    urEllipsoid a, b;
    urGeomContact gc;
    double u[3] = {0, 0, 0};
    ur_geom_ellipsoid(m, d, g1s[j], &a);
    ur_geom_ellipsoid(m, d, g2s[j], &b);
    ur_collide_ellipsoids(&a, &b, u, &gc);
    smin = fmin(smin, -gc.g);
    k--;
    g1s[j] = g1s[k];
    g2s[j] = g2s[k];
    lb[j] = lb[k];
  }
  return smin;
}


int ur_run_start(const urModel* m, urData* d, int root, const double pos[3], const double quat[4],
                 const double vel[3]) {
  // check
  if (root < 0 || root >= m->nbody || m->body[root].parent >= 0 ||
      m->body[root].jtype != urJNT_FREE || !pos || !vel) {
    d->status = urSTAT_OK;
    ur_set_status(d, urSTAT_BADARG, "ur_run_start: root must be a free body of the world");
    return d->status;
  }

  // place the tree: CoM at pos, velocity vel, joints of the tree at rest
  const urBody* rb = m->body + root;
  memcpy(d->qpos + rb->qadr, pos, 3 * sizeof(double));
  if (quat) {
    memcpy(d->qpos + rb->qadr + 3, quat, 4 * sizeof(double));
    uru_normalizequat(d->qpos + rb->qadr + 3);
  }
  for (int i = 0; i < m->nbody; i++) {
    if (m->body[i].tree == root) {
      memset(d->qvel + m->body[i].vadr, 0, (size_t)m->body[i].nv * sizeof(double));
    }
  }
  memcpy(d->qvel + rb->vadr, vel, 3 * sizeof(double));

  // reset run outputs and the contact histories of the tree
  for (int k = 0; k < m->nsensordata; k++) {
    d->peakmax[k] = -INFINITY;
    d->peakmin[k] = INFINITY;
    d->tpeak[k] = 0;
  }
  for (int i = 0; i < m->npair; i++) {
    if (ur_geom_intree(m, m->pair[i].geom1, root) || ur_geom_intree(m, m->pair[i].geom2, root)) {
      memset(d->pair + i, 0, sizeof(urPairData));
      d->pdepth[i] = -INFINITY;
    }
  }
  for (int i = 0; i < m->nbag; i++) {
    memset(d->bag + i, 0, sizeof(urBagData));
  }
  d->status = urSTAT_OK;
  d->msg[0] = 0;
  d->time = 0;
  d->nstep = 0;
  d->nhist = 0;
  d->proj = root;
  d->t_first = d->t_last = -1;
  d->t_calm = 0;
  d->clear_hint = 0;
  d->coarse = d->pend = 0;
  d->ncoarse = d->ntouch = 0;
  ur_kinematics(m, d);

  // earliest possible contact of the tree's swept bounding spheres
  double tmin = INFINITY;
  urCand c;
  for (int k = 0; ur_cand_at(m, k, &c) == 0; k++) {
    int in1 = ur_geom_intree(m, c.g1, root), in2 = ur_geom_intree(m, c.g2, root);
    if (in1 && !in2) {
      tmin = fmin(tmin, firsthit(m, d, c.g1, c.g2, vel));
    } else if (in2 && !in1) {
      tmin = fmin(tmin, firsthit(m, d, c.g2, c.g1, vel));
    }
  }

  // jump along the straight line
  if (isfinite(tmin) && tmin > 0) {
    for (int k = 0; k < 3; k++) {
      d->qpos[rb->qadr + k] += vel[k] * tmin;
    }
    d->time = tmin;
    ur_kinematics(m, d);
  }
  // conservative advancement on the exact distances: the tree moves rigidly at |vel| and the rest
  // is at rest, so no separation shrinks faster than |vel|
  double speed = uru_norm3(vel), t = d->time, tend = d->time + m->opt.tmax;
  for (int it = 0; isfinite(tmin) && speed > 0 && it < 64 && t < tend; it++) {
    double sep = separation(m, d, root);
    if (!(sep > 2 * m->opt.jump_margin) || !isfinite(sep)) {
      break;
    }
    double dt = fmin((sep - m->opt.jump_margin) / speed, tend - t);
    for (int k = 0; k < 3; k++) {
      d->qpos[rb->qadr + k] += vel[k] * dt;
    }
    t += dt;
    ur_kinematics(m, d);
  }
  d->time = t;
  d->t_jump = isfinite(tmin) ? t : 0;
  return d->status;
}


int ur_run(const urModel* m, urData* d) {
  while (d->status == urSTAT_OK) {
    ur_step(m, d);
  }
  return d->status;
}


int ur_run_impact(const urModel* m, urData* d, int root, const double pos[3], const double quat[4],
                  const double vel[3]) {
  if (ur_run_start(m, d, root, pos, quat, vel) != urSTAT_OK) {
    return d->status;
  }
  return ur_run(m, d);
}


void ur_set_free(const urModel* m, urData* d, int body, const double pos[3], const double quat[4],
                 const double vel[3], const double omega[3]) {
  const urBody* b = m->body + body;
  if (b->jtype != urJNT_FREE) {
    return;
  }
  double* q = d->qpos + b->qadr;
  double* v = d->qvel + b->vadr;
  if (pos) {
    memcpy(q, pos, 3 * sizeof(double));
  }
  if (quat) {
    memcpy(q + 3, quat, 4 * sizeof(double));
    uru_normalizequat(q + 3);
  }
  if (vel) {
    memcpy(v, vel, 3 * sizeof(double));
  }
  if (omega) {
    double R[9];
    uru_quat2mat(R, q + 3);
    uru_mulmat3tvec(v + 3, R, omega);
  }
  ur_kinematics(m, d);
}
