/* test_engine_lanes.c: runs stepped in lock-step lanes (ur_step_lanes) are bit for bit the same
 * runs stepped alone (ur_step): on the drone-on-human scene with 2, 3 and 4 lanes, runs that end
 * at different times, a chain with every joint type, a lane whose joint-space inertia turns
 * singular (only that lane fails, with the scalar message), the RK4 integrator (each run on its
 * own), more runs than lanes in one call, and a stop request; and a run alone's joints over the
 * vectors against the scalar kernels. Compared after every step: state, poses, velocities,
 * accelerations, forces, joint loads, contact and airbag histories, sensors and peaks, the
 * recorded rows and the run's fields. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "../../../src/core/engine/engine_internal.h"
#include "test_engine_scene.h"

#define ROWS 2000

/* whether a sensor reads the joint transform, acceleration or reaction of body i: a joint load
   on it or on a body above it, or an acceleration sensor on it */
static int read_dyn(const urModel* m, int i) {
  for (int k = 0; k < m->nsensor; k++) {
    const urSensor* s = m->sensor + k;
    if (s->type == urSENS_ACCEL && s->obj == i) {
      return 1;
    }
    if (s->type == urSENS_JOINTLOAD) {
      for (int j = i; j >= 0; j = m->body[j].parent) {
        if (j == s->obj) {
          return 1;
        }
      }
    }
  }
  return 0;
}

/* byte-compare what a lane run keeps against the scalar run; fails naming the first field */
static void assert_same(const urModel* m, urData* a, urData* b, long step) {
  // the lane run computes the ellipsoids' orientations on first use: every one through the
  // accessor, then byte-compared like the rest
  for (int g = 0; g < m->ngeom; g++) {
    ur_geom_xmat(m, a, g);
    ur_geom_xmat(m, b, g);
  }
  size_t nb = (size_t)m->nbody, ng = (size_t)m->ngeom, ns = (size_t)m->nsensordata;
  struct {
    const char* name;
    const void *x, *y;
    size_t n;
  } f[] = {
      {"qpos", a->qpos, b->qpos, m->nq * sizeof(double)},
      {"qvel", a->qvel, b->qvel, m->nv * sizeof(double)},
      {"qacc", a->qacc, b->qacc, m->nv * sizeof(double)},
      {"qfrc", a->qfrc, b->qfrc, m->nv * sizeof(double)},
      {"rst", a->rst, b->rst, 2 * m->nv * sizeof(double)},
      {"xpos", a->xpos, b->xpos, 3 * nb * sizeof(double)},
      {"xmat", a->xmat, b->xmat, 9 * nb * sizeof(double)},
      {"xcom", a->xcom, b->xcom, 3 * nb * sizeof(double)},
      {"gxpos", a->gxpos, b->gxpos, 3 * ng * sizeof(double)},
      {"gxmat", a->gxmat, b->gxmat, 9 * ng * sizeof(double)},
      {"cvel", a->cvel, b->cvel, 6 * nb * sizeof(double)},
      {"fext", a->fext, b->fext, 6 * nb * sizeof(double)},
      {"pair", a->pair, b->pair, m->npair * sizeof(urPairData)},
      {"pdepth", a->pdepth, b->pdepth, m->npair * sizeof(double)},
      {"bag", a->bag, b->bag, m->nbag * sizeof(urBagData)},
      {"sensordata", a->sensordata, b->sensordata, ns * sizeof(double)},
      {"peakmax", a->peakmax, b->peakmax, ns * sizeof(double)},
      {"peakmin", a->peakmin, b->peakmin, ns * sizeof(double)},
      {"tpeak", a->tpeak, b->tpeak, ns * sizeof(double)},
      {"time", &a->time, &b->time, sizeof(double)},
      {"energy", &a->energy, &b->energy, sizeof(double)},
      {"t_first", &a->t_first, &b->t_first, sizeof(double)},
      {"t_last", &a->t_last, &b->t_last, sizeof(double)},
      {"t_calm", &a->t_calm, &b->t_calm, sizeof(double)},
      {"status", &a->status, &b->status, sizeof(int)},
      {"nstep", &a->nstep, &b->nstep, sizeof(a->nstep)},
      {"nhist", &a->nhist, &b->nhist, sizeof(int)},
      {"msg", a->msg, b->msg, sizeof(a->msg)},
  };
  for (size_t k = 0; k < sizeof(f) / sizeof(f[0]); k++) {
    if (memcmp(f[k].x, f[k].y, f[k].n)) {
      fail_msg("step %ld: %s differs between the lane run and the run alone", step, f[k].name);
    }
  }
  if (a->hist && memcmp(a->hist, b->hist, (size_t)a->nhist * (1 + ns) * sizeof(double))) {
    fail_msg("step %ld: the recorded rows differ", step);
  }

  /* the spherical restraints' kinematics: of the bodies whose restraint forces the lanes
     compute lane by lane (the vectors keep the rest: ur_restraint_vec) */
  for (int j = 0; j < m->nrstb; j++) {
    int i = m->rstb[j];
    if (!ur_restraint_vec(m, i) &&
        memcmp(a->rkin + 12 * i, b->rkin + 12 * i, 12 * sizeof(double))) {
      fail_msg("step %ld: rkin of body %d differs between the lane run and the run alone", step, i);
    }
  }

  /* joint transforms, accelerations and reactions: of the bodies a sensor reads (joint loads
     of the body or below it, accelerations) */
  for (int i = 0; i < m->nbody; i++) {
    if (!read_dyn(m, i)) {
      continue;
    }
    if (memcmp(a->Xe + 9 * i, b->Xe + 9 * i, 9 * sizeof(double)) ||
        memcmp(a->Xr + 3 * i, b->Xr + 3 * i, 3 * sizeof(double)) ||
        memcmp(a->cacc + 6 * i, b->cacc + 6 * i, 6 * sizeof(double)) ||
        memcmp(a->freact + 6 * i, b->freact + 6 * i, 6 * sizeof(double))) {
      fail_msg("step %ld: Xe, Xr, cacc or freact of body %d differ", step, i);
    }
  }
}

/* n runs from the given starts, in lanes and alone, compared after every step until all end;
   returns the number of lock-steps and fills steps[] with each run's step count */
static long lockstep(const urModel* m, int n, const double (*pos)[3], const double (*vel)[3],
                     long* steps) {
  urData *lane[urNLANE], *alone[urNLANE];
  urLanes L;
  assert_int_equal(ur_lanes_init(m, &L), 0);
  int root = ur_name_body(m, "drone");
  for (int i = 0; i < n; i++) {
    lane[i] = ur_data_new(m);
    alone[i] = ur_data_new(m);
    assert_int_equal(ur_data_history(m, lane[i], NULL, ROWS), 0);
    assert_int_equal(ur_data_history(m, alone[i], NULL, ROWS), 0);
    ur_run_start(m, lane[i], root, pos[i], NULL, vel[i]);
    ur_run_start(m, alone[i], root, pos[i], NULL, vel[i]);
  }

  // lock-step over the runs still going (as ur_impact_run_many drops finished lanes)
  long it = 0;
  for (;;) {
    urData* go[urNLANE];
    int k = 0;
    for (int i = 0; i < n; i++) {
      if (lane[i]->status == urSTAT_OK) go[k++] = lane[i];
    }
    if (k == 0) break;
    ur_step_lanes(m, go, k, &L);
    for (int i = 0; i < n; i++) {
      if (alone[i]->status == urSTAT_OK) ur_step(m, alone[i]);
      assert_same(m, lane[i], alone[i], it);
    }
    it++;
  }
  for (int i = 0; i < n; i++) {
    steps[i] = lane[i]->nstep;
    ur_data_free(lane[i]);
    ur_data_free(alone[i]);
  }
  ur_lanes_free(&L);
  return it;
}

// the drone on the human, 2 to 4 lanes, runs of different lengths
static void test_scene_lanes(void** state) {
  urModel* m = scene_build(1);
  assert_non_null(m);
  static const double pos[4][3] = {
      {0.05, 0.015, 2.2}, {0.12, 0.036, 2.2}, {-0.3, 0.2, 2.2}, {0.0, 0.0, 2.2}};
  static const double vel[4][3] = {{0, 0, -7.5}, {0, 0, -12.5}, {1.0, 0, -9.0}, {0, 0, -20}};
  for (int n = 2; n <= 4; n++) {
    long steps[4];
    long it = lockstep(m, n, pos, vel, steps);
    print_message("%d lanes: %ld lock-steps; runs of %ld, %ld, %ld, %ld steps\n", n, it, steps[0],
                  steps[1], n > 2 ? steps[2] : 0, n > 3 ? steps[3] : 0);
    assert_true(it > 100);
    assert_true(steps[0] != steps[1]); /* the lanes really ended at different times */
  }
  ur_model_free(m);
}

// the RK4 integrator: each run steps on its own, the same bits
static void test_scene_rk4(void** state) {
  urModel* m = scene_build(0);
  assert_non_null(m);
  m->opt.integrator = urINT_RK4;
  m->opt.tmax = 0.01;
  static const double pos[2][3] = {{0.05, 0.015, 2.2}, {0.12, 0.036, 2.2}};
  static const double vel[2][3] = {{0, 0, -7.5}, {0, 0, -12.5}};
  long steps[2];
  assert_true(lockstep(m, 2, pos, vel, steps) > 10);
  ur_model_free(m);
}

// 4 lanes from the given states (lane[i] set up), stepped n times, each compared after every
// step with the same state stepped alone; the datas are freed
static void lanes_vs_alone(const urModel* m, urData** lane, long n) {
  urLanes L;
  urData* alone[4];
  assert_int_equal(ur_lanes_init(m, &L), 0);
  for (int i = 0; i < 4; i++) {
    alone[i] = ur_data_new(m);
    ur_data_copy(m, alone[i], lane[i]);
  }
  for (long it = 0; it < n; it++) {
    ur_step_lanes(m, lane, 4, &L);
    for (int i = 0; i < 4; i++) {
      ur_step(m, alone[i]);
      assert_same(m, lane[i], alone[i], it);
    }
  }
  for (int i = 0; i < 4; i++) ur_data_free(alone[i]);
  ur_lanes_free(&L);
}

// a chain with every joint type, violent velocities, 4 lanes of different states
static void test_chain_lanes(void** state) {
  urModel* m = scene_chain(urINT_EULER, 1e-4, -9.81);
  assert_non_null(m);
  urData* lane[4];
  for (int i = 0; i < 4; i++) {
    lane[i] = ur_data_new(m);
    for (int k = 0; k < m->nv; k++) lane[i]->qvel[k] = 8.0 * sin(1.7 * k + 0.3 + i);
  }
  lanes_vs_alone(m, lane, 3000);
  assert_true(memcmp(lane[0]->qpos, lane[1]->qpos, m->nq * sizeof(double)) != 0);
  for (int i = 0; i < 4; i++) {
    assert_int_equal(lane[i]->status, urSTAT_OK);
    ur_data_free(lane[i]);
  }
  ur_model_free(m);
}

// scene_chain's bodies with every restraint: on the revolute joint a plastic hinge with
// hardening and stops; on the universal joint a linear spring about x0 with stops and a hinge
// without hardening; on the spherical joint a hinge, the linear spring and a free dof; on the
// prismatic joint a saturating spring with a curve with hysteresis (lane by lane); with
// sph_sat the spherical joint's free dof saturates too, so it goes lane by lane
static urModel* restraint_chain(int sph_sat) {
  urModel* m = scene_chain_bodies();
  int b1 = ur_name_body(m, "rev"), b2 = ur_name_body(m, "uni"), b3 = ur_name_body(m, "sph"),
      b4 = ur_name_body(m, "pri");
  urRestraint h = {0}; // hinge with hardening and stops
  h.k = 40;
  h.mp = 2;
  h.kh = 4;
  h.c = 0.3;
  h.lo = -0.12;
  h.hi = 0.1;
  h.kstop = 500;
  h.cstop = 2;
  ur_model_set_restraint(m, b1, 0, &h);
  urRestraint p = h; // hinge without hardening, no stops
  p.kh = 0;
  p.lo = p.hi = 0;
  urRestraint l = {0}; // linear with stops about x0
  l.k = 30;
  l.c = 0.1;
  l.lo = -0.06;
  l.hi = 0.04;
  l.kstop = 300;
  l.cstop = 1;
  l.x0 = 0.05;
  ur_model_set_restraint(m, b2, 0, &l);
  ur_model_set_restraint(m, b2, 1, &p);
  ur_model_set_restraint(m, b3, 0, &p);
  ur_model_set_restraint(m, b3, 1, &l);
  urRestraint cu = {0}; // saturating, with a curve with hysteresis
  cu.k = 300;
  cu.sat = 20;
  cu.c = 0.2;
  cu.load.n = 4;
  cu.unload.n = 3;
  memcpy(cu.load.x, (double[4]){0, 0.1, 0.3, 1.0}, 4 * sizeof(double));
  memcpy(cu.load.y, (double[4]){0, 2, 10, 60}, 4 * sizeof(double));
  memcpy(cu.unload.x, (double[3]){0, 0.5, 1.0}, 3 * sizeof(double));
  memcpy(cu.unload.y, (double[3]){0, 1, 5}, 3 * sizeof(double));
  ur_model_set_restraint(m, b4, 0, &cu);
  if (sph_sat) {
    urRestraint sat = {0};
    sat.k = 30;
    sat.sat = 1;
    ur_model_set_restraint(m, b3, 2, &sat);
  }
  m->opt.gravity[2] = -9.81;
  m->opt.dt = 1e-4;
  if (ur_model_compile(m)) {
    ur_model_free(m);
    return NULL;
  }
  return m;
}

// the restraints over the vectors and lane by lane, violent velocities, 4 lanes: the hinges
// yield, two have broken, the stops are reached: bit for bit as alone (rkin too where the
// spherical joint goes lane by lane)
static void restraint_lanes(int sph_sat) {
  urModel* m = restraint_chain(sph_sat);
  assert_non_null(m);
  const char* hinge[] = {"rev", "uni", "sph"};
  const int dof[] = {0, 1, 0};
  for (int k = 0; k < 3; k++) {
    assert_int_equal(ur_restraint_vec(m, ur_name_body(m, hinge[k])), k < 2 || !sph_sat);
  }
  assert_false(ur_restraint_vec(m, ur_name_body(m, "pri")));
  urData* lane[4];
  for (int i = 0; i < 4; i++) {
    lane[i] = ur_data_new(m);
    for (int k = 0; k < m->nv; k++) lane[i]->qvel[k] = 8.0 * sin(1.7 * k + 0.3 + i);
  }
  // a hinge that broke (without a fracture moment, so its joint stays): lane 1's on the
  // universal joint, lane 2's on the spherical one
  lane[1]->rst[2 * (m->body[ur_name_body(m, "uni")].vadr + 1) + 1] = 0.5;
  lane[2]->rst[2 * m->body[ur_name_body(m, "sph")].vadr + 1] = 0.5;
  lanes_vs_alone(m, lane, 3000);

  // every hinge yielded (a plastic deflection committed) in some lane
  int yielded[3] = {0, 0, 0};
  for (int i = 0; i < 4; i++) {
    assert_int_equal(lane[i]->status, urSTAT_OK);
    for (int k = 0; k < 3; k++) {
      double xp, tb;
      assert_int_equal(ur_hinge_state(m, lane[i], ur_name_body(m, hinge[k]), dof[k], &xp, &tb), 0);
      yielded[k] += xp != 0;
    }
    ur_data_free(lane[i]);
  }
  print_message("hinges yielded in %d, %d, %d of 4 lanes\n", yielded[0], yielded[1], yielded[2]);
  for (int k = 0; k < 3; k++) assert_true(yielded[k] > 0);
  ur_model_free(m);
}

static void test_restraint_lanes(void** state) {
  restraint_lanes(0);
  restraint_lanes(1);
}


// a point mass on a hinge about z carrying, through a hinge about x, a point mass 0.5 m up the z
// axis: the joint-space inertia of the z hinge is m L^2 sin^2(q2), singular at q2 = 0. The lane
// at q2 = 0 fails as the run alone does; the others go on, the same bits.
static void test_singular_lane(void** state) {
  urModel* m = ur_model_new();
  double I0[6] = {0, 0, 0, 0, 0, 0}, c0[3] = {0, 0, 0}, cm[3] = {0, 0, 0.5};
  int b1 = ur_model_add_body(m, "z", -1, urJNT_REVOLUTE, (double[3]){0, 0, 1}, NULL);
  ur_model_set_inertia(m, b1, 1.0, c0, I0);
  ur_model_set_joint(m, b1, NULL, (double[3]){0, 0, 1}, NULL);
  int b2 = ur_model_add_body(m, "x", b1, urJNT_REVOLUTE, (double[3]){0, 0, 0}, NULL);
  ur_model_set_inertia(m, b2, 1.0, cm, I0);
  ur_model_set_joint(m, b2, NULL, (double[3]){1, 0, 0}, NULL);
  m->opt.gravity[2] = 0;
  assert_int_equal(ur_model_compile(m), 0);

  urData* lane[4];
  for (int i = 0; i < 4; i++) {
    lane[i] = ur_data_new(m);
    lane[i]->qpos[1] = 0.2 * i;
    lane[i]->qvel[0] = 1.0;
  }
  lanes_vs_alone(m, lane, 50);
  assert_int_equal(lane[0]->status, urSTAT_NONFINITE);
  assert_non_null(strstr(lane[0]->msg, "singular"));
  for (int i = 1; i < 4; i++) assert_int_equal(lane[i]->status, urSTAT_OK);
  for (int i = 0; i < 4; i++) ur_data_free(lane[i]);
  ur_model_free(m);
}

// more runs than lanes in one call: taken urNLANE at a time, the same bits
static void test_more_than_lanes(void** state) {
  urModel* m = scene_chain(urINT_EULER, 1e-4, -9.81);
  assert_non_null(m);
  urLanes L;
  assert_int_equal(ur_lanes_init(m, &L), 0);
  urData *lane[6], *alone[6];
  for (int i = 0; i < 6; i++) {
    lane[i] = ur_data_new(m);
    for (int k = 0; k < m->nv; k++) lane[i]->qvel[k] = 5.0 * cos(0.9 * k + i);
    alone[i] = ur_data_new(m);
    ur_data_copy(m, alone[i], lane[i]);
  }
  for (long it = 0; it < 200; it++) {
    ur_step_lanes(m, lane, 6, &L);
    for (int i = 0; i < 6; i++) {
      ur_step(m, alone[i]);
      assert_same(m, lane[i], alone[i], it);
    }
  }
  for (int i = 0; i < 6; i++) {
    assert_true(lane[i]->nstep == 200);
    ur_data_free(lane[i]);
    ur_data_free(alone[i]);
  }
  ur_lanes_free(&L);
  ur_model_free(m);
}

// a stop request stops every lane, as it stops a run alone
static void test_stop_lanes(void** state) {
  urModel* m = scene_build(0);
  assert_non_null(m);
  _Atomic int stop = 0;
  m->opt.stop = &stop;
  urLanes L;
  assert_int_equal(ur_lanes_init(m, &L), 0);
  urData* d[3];
  int root = ur_name_body(m, "drone");
  for (int i = 0; i < 3; i++) {
    d[i] = ur_data_new(m);
    double pos[3] = {0.05 * i, 0, 2.2}, vel[3] = {0, 0, -8};
    ur_run_start(m, d[i], root, pos, NULL, vel);
  }
  for (int it = 0; it < 20; it++) ur_step_lanes(m, d, 3, &L);
  stop = 1;
  ur_step_lanes(m, d, 3, &L);
  for (int i = 0; i < 3; i++) {
    assert_int_equal(d[i]->status, urSTAT_STOPPED);
    assert_int_equal(d[i]->nstep, 20);
    ur_data_free(d[i]);
  }
  ur_lanes_free(&L);
  ur_model_free(m);
}

// a run alone's joints over the vectors (ur_restraints_kin_joints, ur_addpos_joints) against
// the scalar kernels, bit for bit, on random states: the scene (10 quaternions: groups of 4, 4
// and 2; 8 spherical restraints) and the restraint chain (one of each: a group of 1), the
// spherical restraints' x0 set apart, quaternions near the identity (the series of rotvec_jrinv)
// and with w < 0
static void joints_alone(urModel* m, unsigned seed) {
  int nb = m->nbody, nq = m->nq, nv = m->nv;
  for (int i = 0; i < nb; i++) {
    for (int k = 0; k < 3; k++) {
      m->body[i].rst[k].x0 = i % 2 ? 0.01 * (i % 5) - 0.02 * k : 0; /* even: the series */
    }
  }
  double q[nq], qa[nq], qb[nq], v[nv], ra[12 * nb], rb[12 * nb];
  for (int n = 0; n < 200; n++) {
    for (int k = 0; k < nq; k++) {
      seed = seed * 1103515245u + 12345u;
      q[k] = ((seed >> 8) & 0xffff) / 32768.0 - 1;
    }
    for (int i = 0; i < nb; i++) {
      const urBody* b = m->body + i;
      int o = b->jtype == urJNT_FREE ? 3 : 0;
      if (b->jtype == urJNT_FREE || b->jtype == urJNT_SPHERICAL) {
        double* e = q + b->qadr + o;
        if (n % 4 == 1) {
          e[0] = 1; /* near the identity */
          e[1] *= 1e-6;
          e[2] *= 1e-6;
          e[3] *= 1e-6;
        }
        uru_normalizequat(e);
      }
    }
    for (int k = 0; k < nv; k++) {
      v[k] = 20 * sin(1.3 * k + n);
    }
    memset(ra, 0, sizeof(ra));
    memset(rb, 0, sizeof(rb));
    uru_restraints_kin(m, q, ra);
    ur_restraints_kin_joints(m, q, rb);
    assert_memory_equal(ra, rb, sizeof(ra));
    memcpy(qa, q, sizeof(q));
    memcpy(qb, q, sizeof(q));
    uru_addpos(m, qa, v, 1e-3 * (1 + n % 3));
    ur_addpos_joints(m, qb, v, 1e-3 * (1 + n % 3));
    assert_memory_equal(qa, qb, sizeof(qa));
  }
}

static void test_joints_alone(void** state) {
  urModel* m = scene_build(1);
  assert_non_null(m);
  joints_alone(m, 5);
  ur_model_free(m);
  m = restraint_chain(0);
  assert_non_null(m);
  joints_alone(m, 9);
  ur_model_free(m);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_scene_lanes),   cmocka_unit_test(test_scene_rk4),
      cmocka_unit_test(test_chain_lanes),   cmocka_unit_test(test_restraint_lanes),
      cmocka_unit_test(test_singular_lane), cmocka_unit_test(test_more_than_lanes),
      cmocka_unit_test(test_stop_lanes),    cmocka_unit_test(test_joints_alone),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
