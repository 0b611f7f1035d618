/* test_engine_fracture.c: a broken arm flies free (engine_fracture.c). A drone's frame (free)
 * carries a tube arm on a universal joint whose plastic hinge breaks; without gravity or contact
 * the whole system's linear and angular momentum are the same just before and just after the
 * joint releases, the released arm then moves as a free rigid body (its centre of mass at
 * constant velocity, its angular momentum about it constant), the hinge's sensor says when it
 * broke, and a hinge that never breaks runs bit for bit as one without fracture. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "../../../src/core/engine/engine_internal.h"

// the frame (10 kg) and its arm (0.5 kg, CoM 0.3 m out) on a universal joint 0.16 m from the
// frame's centre; the hinge of the 30 x 2 carbon tube on 0.41 m (test_engine_restraint.c),
// breaking at mfrac (0: never); no gravity
static urModel* frame_arm(double mfrac, urIntegrator integ, int* arm, int* sens) {
  urModel* m = ur_model_new();
  double If[6] = {0.5, 0.4, 0.8, 0, 0, 0}, Ia[6] = {0.001, 0.002, 0.003, 0, 0, 0};
  int f = ur_model_add_body(m, "frame", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, f, 10, NULL, If);
  int a = ur_model_add_body(m, "arm", f, urJNT_UNIVERSAL, (double[3]){0.16, 0, 0}, NULL);
  ur_model_set_inertia(m, a, 0.5, (double[3]){0.3, 0, 0}, Ia);
  ur_model_set_joint(m, a, NULL, (double[3]){0, 1, 0}, (double[3]){0, 0, 1});
  urRestraint r = {0};
  r.k = 6949;
  r.mp = 93.1;
  r.kh = 69.49;
  r.c = 0.5;
  r.mfrac = mfrac;
  ur_model_set_restraint(m, a, 0, &r);
  ur_model_set_restraint(m, a, 1, &r);
  *sens = ur_model_add_sensor(m, "hinge", urSENS_HINGE, a, 0, NULL, NULL);
  m->opt.gravity[2] = 0;
  m->opt.dt = 1e-5;
  m->opt.integrator = integ;
  assert_int_equal(ur_model_compile(m), 0);
  *arm = a;
  return m;
}


// the run: the frame moving, the arm whipped about its root at w rad/s
static urData* whip(const urModel* m, int arm, double w) {
  urData* d = ur_data_new(m);
  double v[3] = {1, -0.5, 2}, om[3] = {0, 0, 0.5};
  ur_set_free(m, d, 0, NULL, NULL, v, om);
  d->qvel[m->body[arm].vadr] = w;
  ur_forward(m, d);
  return d;
}


// largest component difference of two 3-vectors, and the larger norm
static double diff3(const double a[3], const double b[3]) {
  return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}


// the arm's angular momentum about its own CoM, world: R I R^T w (w world)
static void arm_spin(const urModel* m, const urData* d, int a, double L[3]) {
  const double* R = d->xmat + 9 * a;
  const double* w = d->cvel + 6 * a; /* body frame */
  double Iw[3];
  uru_mulmat3vec(Iw, m->body[a].inertia, w);
  uru_mulmat3vec(L, R, Iw);
}


static void test_release_momentum(void** state) {
  int a, hs;
  urModel* m = frame_arm(100, urINT_RK4, &a, &hs);
  assert_int_equal(m->nfrac, 1);
  assert_int_equal(m->nq, 7 + 2 + 7);
  urData* d = whip(m, a, 60);
  double p0[3], L0[3], p1[3], L1[3], pb[3], Lb[3], pa[3], La[3], xp, tb = 0;
  ur_momentum(m, d, p0, L0);

  // to the step that breaks it: still pinned, the hinge's state says when
  for (int i = 0; i < 20000 && tb == 0; i++) {
    ur_step(m, d);
    ur_hinge_state(m, d, a, 0, &xp, &tb);
  }
  assert_true(tb > 0);
  assert_true(ur_data_model(m, d) == m);
  ur_forward(m, d);
  ur_momentum(m, d, pb, Lb);

  // the release alone: the same state in the new topology
  assert_int_equal(ur_fracture_release(m, d), 1);
  const urModel* t = ur_data_model(m, d);
  assert_true(t != m && t->body[a].jtype == urJNT_FREE && t->body[a].parent < 0);
  assert_int_equal(t->body[a].qadr, m->body[a].fqadr);
  ur_forward(m, d);
  ur_momentum(m, d, pa, La);
  double np = uru_norm3(p0), nl = uru_norm3(L0);
  print_message("release at %.5f s: |dp| %.2e of %.3g kg m/s, |dL| %.2e of %.3g kg m^2/s\n", tb,
                diff3(pa, pb), np, diff3(La, Lb), nl);
  assert_true(diff3(pa, pb) <= 1e-13 * np && diff3(La, Lb) <= 1e-13 * nl);
  assert_int_equal(ur_fracture_release(m, d), 0); /* once */

  // the hinge's sensor still says when it broke
  assert_true(d->sensordata[m->sensor[hs].adr + 1] == tb);
  assert_true(d->sensordata[m->sensor[hs].adr] == xp);

  // free flight: the arm's CoM velocity and spin constant, its CoM on a line; the whole
  // system's momentum that of the start
  double v0[3], x0[3], S0[3], v1[3], x1[3], S1[3], t0 = d->time;
  memcpy(v0, d->qvel + m->body[a].fvadr, sizeof v0);
  memcpy(x0, d->xcom + 3 * a, sizeof x0);
  arm_spin(m, d, a, S0);
  for (int i = 0; i < 5000; i++) {
    ur_step(m, d);
  }
  ur_forward(m, d);
  assert_int_equal(d->status, urSTAT_OK);
  memcpy(v1, d->qvel + m->body[a].fvadr, sizeof v1);
  memcpy(x1, d->xcom + 3 * a, sizeof x1);
  arm_spin(m, d, a, S1);
  double T = d->time - t0, xe[3];
  for (int k = 0; k < 3; k++) {
    xe[k] = x0[k] + v0[k] * T;
  }
  ur_momentum(m, d, p1, L1);
  print_message(
      "free arm over %.3f s: |dv| %.2e of %.3g m/s, |dx| %.2e m, |dspin| %.2e of %.3g "
      "kg m^2/s; system |dp| %.2e, |dL| %.2e\n",
      T, diff3(v1, v0), uru_norm3(v0), diff3(x1, xe), diff3(S1, S0), uru_norm3(S0), diff3(p1, p0),
      diff3(L1, L0));
  assert_true(T > 0.049);
  assert_true(diff3(v1, v0) <= 1e-12 * uru_norm3(v0));
  assert_true(diff3(x1, xe) <= 1e-12);
  assert_true(diff3(S1, S0) <= 1e-10 * uru_norm3(S0));
  assert_true(diff3(p1, p0) <= 1e-10 * np && diff3(L1, L0) <= 1e-10 * nl);

  // the arm has left its root: the joint anchor is no longer on the frame
  double root[3];
  ur_point_pos(m, d, 0, m->body[a].pos, root);
  assert_true(diff3(root, d->xpos + 3 * a) > 1e-3);

  // a copy of the run keeps its topology; a reset restores the model's
  urData* c = ur_data_new(m);
  ur_data_copy(m, c, d);
  assert_true(ur_data_model(m, c) != m && ur_data_model(m, c)->body[a].jtype == urJNT_FREE);
  ur_data_reset(m, c);
  assert_true(ur_data_model(m, c) == m);
  ur_data_free(c);
  ur_data_free(d);
  ur_model_free(m);
}


// a hinge that does not break: bit for bit the run of the same hinge without fracture (the
// free block reserved for the release is never read)
static void test_unbroken_bitwise(void** state) {
  int a, b, hs;
  urModel* mf = frame_arm(1e9, urINT_EULER, &a, &hs);
  urModel* m0 = frame_arm(0, urINT_EULER, &b, &hs);
  assert_int_equal(m0->nfrac, 0);
  assert_int_equal(mf->nq, m0->nq + 7);
  urData* df = whip(mf, a, 60);
  urData* d0 = whip(m0, b, 60);
  for (int i = 0; i < 3000; i++) {
    ur_step(mf, df);
    ur_step(m0, d0);
  }
  assert_memory_equal(df->qpos, d0->qpos, (size_t)m0->nq * sizeof(double));
  assert_memory_equal(df->qvel, d0->qvel, (size_t)m0->nv * sizeof(double));
  assert_memory_equal(df->rst, d0->rst, 2 * (size_t)m0->nv * sizeof(double));
  assert_true(ur_data_model(mf, df) == mf);
  double xp, tb;
  ur_hinge_state(mf, df, a, 0, &xp, &tb);
  assert_true(tb == 0 && fabs(xp) > 0.001); /* it yielded, did not break */
  ur_data_free(df);
  ur_data_free(d0);
  ur_model_free(mf);
  ur_model_free(m0);
}


// runs in lanes that break at different steps are bit for bit those stepped alone
static void test_lanes_break(void** state) {
  int a, hs;
  urModel* m = frame_arm(100, urINT_EULER, &a, &hs);
  urLanes L;
  assert_int_equal(ur_lanes_init(m, &L), 0);
  urData *lane[4], *alone[4];
  for (int i = 0; i < 4; i++) {
    lane[i] = whip(m, a, 40 + 10 * i);
    alone[i] = whip(m, a, 40 + 10 * i);
  }
  int nbroke = 0;
  for (int it = 0; it < 4000; it++) {
    ur_step_lanes(m, lane, 4, &L);
    for (int i = 0; i < 4; i++) {
      ur_step(m, alone[i]);
      assert_memory_equal(lane[i]->qpos, alone[i]->qpos, (size_t)m->nq * sizeof(double));
      assert_memory_equal(lane[i]->qvel, alone[i]->qvel, (size_t)m->nv * sizeof(double));
      assert_memory_equal(lane[i]->sensordata, alone[i]->sensordata,
                          (size_t)m->nsensordata * sizeof(double));
    }
  }
  for (int i = 0; i < 4; i++) {
    nbroke += lane[i]->nreleased;
    print_message("lane %d: broke at %.5f s\n", i, lane[i]->sensordata[m->sensor[hs].adr + 1]);
    ur_data_free(lane[i]);
    ur_data_free(alone[i]);
  }
  assert_true(nbroke >= 2); /* some lanes broke, at different steps */
  ur_lanes_free(&L);
  ur_model_free(m);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_release_momentum),
      cmocka_unit_test(test_unbroken_bitwise),
      cmocka_unit_test(test_lanes_break),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
