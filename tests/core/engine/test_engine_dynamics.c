/* test_engine_dynamics.c: rigid-body and articulated dynamics against independent answers:
 * torque-free tumbling (energy, angular momentum), pendulum period, universal joint frequency,
 * joint constraint error after violent motion, energy/momentum of a chain with every joint type. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/engine.h"
#include "test_engine_scene.h"

//---------------------------------- helpers -------------------------------------------------------

static double reldiff3(const double a[3], const double b[3]) {
  double d = 0, n = 0;
  for (int k = 0; k < 3; k++) {
    d += (a[k] - b[k]) * (a[k] - b[k]);
    n += b[k] * b[k];
  }
  return sqrt(d / n);
}


// a single free asymmetric body, no gravity
static urModel* tumbler(urIntegrator integ, double dt) {
  urModel* m = ur_model_new();
  double I[6] = {0.5, 1.0, 1.7, 0, 0, 0}, com[3] = {0.03, -0.02, 0.05};
  int b = ur_model_add_body(m, "box", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, b, 2.0, com, I);
  m->opt.gravity[2] = 0;
  m->opt.integrator = integ;
  m->opt.dt = dt;
  assert_int_equal(ur_model_compile(m), 0);
  return m;
}


// drift of energy and angular momentum of a tumbling body over 1 s
static void tumble(urIntegrator integ, double dt, double* de, double* dl, double* dp) {
  urModel* m = tumbler(integ, dt);
  urData* d = ur_data_new(m);
  double q[4] = {0.9, 0.1, -0.3, 0.2}, w[3] = {0.2, 4.0, 0.3}, v[3] = {0.5, -0.2, 0.1};
  double p0[3], L0[3], p1[3], L1[3];
  ur_set_free(m, d, 0, (double[3]){0, 0, 0}, q, v, w);
  ur_forward(m, d);

  // independent initial values: E = 1/2 w' I w (world), L = x x p + R I R' w
  double e0 = ur_energy_kinetic(m, d);
  ur_momentum(m, d, p0, L0);
  long n = lround(1.0 / dt);
  for (long i = 0; i < n; i++) {
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  ur_forward(m, d);
  ur_momentum(m, d, p1, L1);
  *de = fabs(ur_energy_kinetic(m, d) - e0) / e0;
  *dl = reldiff3(L1, L0);
  *dp = reldiff3(p1, p0);
  ur_data_free(d);
  ur_model_free(m);
}

//---------------------------------- tests ---------------------------------------------------------

// torque-free tumbling near the unstable intermediate axis: E and L conserved
static void test_free_tumbling(void** state) {
  double de, dl, dp;

  // RK4 with the exact Lie-group quaternion update, dt = 1e-4
  tumble(urINT_RK4, 1e-4, &de, &dl, &dp);
  print_message("free body RK4 dt=1e-4, 1 s: |dE|/E = %.2e, |dL|/|L| = %.2e, |dp|/|p| = %.2e\n", de,
                dl, dp);
  assert_true(de < 1e-6);
  assert_true(dl < 1e-6);
  assert_true(dp < 1e-12);

  // semi-implicit Euler at the production step, for the record (first order: looser bound)
  tumble(urINT_EULER, 1e-5, &de, &dl, &dp);
  print_message("free body Euler dt=1e-5, 1 s: |dE|/E = %.2e, |dL|/|L| = %.2e, |dp|/|p| = %.2e\n",
                de, dl, dp);
  assert_true(de < 1e-3);
  assert_true(dl < 1e-3);
  assert_true(dp < 1e-12);
}


// the body must really tumble (guards against a test that cannot fail)
static void test_free_tumbling_moves(void** state) {
  urModel* m = tumbler(urINT_RK4, 1e-4);
  urData* d = ur_data_new(m);
  double w[3] = {0.2, 4.0, 0.3};
  ur_set_free(m, d, 0, NULL, NULL, NULL, w);
  ur_forward(m, d);
  double w0 = d->qvel[4];
  for (int i = 0; i < 10000; i++) {
    ur_step(m, d);
  }
  // intermediate-axis instability: the body-frame spin about y changes a lot within 1 s
  print_message("free body: omega_y body %.3f -> %.3f rad/s\n", w0, d->qvel[4]);
  assert_true(fabs(d->qvel[4] - w0) > 0.5);
  ur_data_free(d);
  ur_model_free(m);
}


// period of zero up-crossings of x(t) by linear interpolation, over ncross crossings
static double period(const double* x, int n, double dt) {
  double t0 = -1, t1 = -1;
  int nc = 0;
  for (int i = 1; i < n; i++) {
    if (x[i - 1] < 0 && x[i] >= 0) {
      double t = (i - 1 + x[i - 1] / (x[i - 1] - x[i])) * dt;
      if (t0 < 0) {
        t0 = t;
      }
      t1 = t;
      nc++;
    }
  }
  return nc > 1 ? (t1 - t0) / (nc - 1) : -1;
}


// compound pendulum on a revolute joint: small-angle period 2 pi sqrt(Ip/(m g l))
static void test_pendulum_period(void** state) {
  urModel* m = ur_model_new();
  double l = 0.25, mass = 1.5, ic = 0.004;
  double I[6] = {ic, ic, ic, 0, 0, 0}, com[3] = {0, 0, -l}, pos[3] = {0, 0, 1};
  int b = ur_model_add_body(m, "bob", -1, urJNT_REVOLUTE, pos, NULL);
  ur_model_set_inertia(m, b, mass, com, I);
  ur_model_set_joint(m, b, "hinge", (double[3]){0, 1, 0}, NULL);
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  // small amplitude 0.01 rad; finite-amplitude correction T = T0 (1 + th^2/16 + ...)
  double th0 = 0.01, T0 = 2 * M_PI * sqrt((ic + mass * l * l) / (mass * 9.81 * l));
  double Ta = T0 * (1 + th0 * th0 / 16);
  int n = (int)(3.2 * T0 / m->opt.dt);
  static double x[400000];
  assert_true(n <= 400000);
  d->qpos[0] = th0;
  for (int i = 0; i < n; i++) {
    x[i] = d->qpos[0];
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  double T = period(x, n, m->opt.dt);
  print_message(
      "pendulum: T = %.8f s, small-angle %.8f s (err %.2e, tol 1e-4), with "
      "amplitude correction %.8f s (err %.2e, tol 2e-7)\n",
      T, T0, fabs(T - T0) / T0, Ta, fabs(T - Ta) / Ta);
  assert_true(fabs(T - T0) / T0 < 1e-4);
  assert_true(fabs(T - Ta) / Ta < 2e-7);
  ur_data_free(d);
  ur_model_free(m);
}


// universal joint with linear restraints: omega_i = sqrt(k_i / I_axis_i)
static void test_universal_frequency(void** state) {
  urModel* m = ur_model_new();
  double mass = 0.5, h = 0.2, Ic[6] = {0.002, 0.003, 0.001, 0, 0, 0}, com[3] = {0, 0, h};
  int b = ur_model_add_body(m, "arm", -1, urJNT_UNIVERSAL, NULL, NULL);
  ur_model_set_inertia(m, b, mass, com, Ic);
  ur_model_set_joint(m, b, "cardan", (double[3]){1, 0, 0}, (double[3]){0, 1, 0});
  urRestraint r = {0};
  r.k = 40;
  ur_model_set_restraint(m, b, 0, &r);
  r.k = 90;
  ur_model_set_restraint(m, b, 1, &r);
  m->opt.gravity[2] = 0;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  // independent answer: inertia about each axis through the anchor
  double w1 = sqrt(40 / (0.002 + mass * h * h)), w2 = sqrt(90 / (0.003 + mass * h * h));
  int n = 60000;
  static double x1[60000], x2[60000];
  d->qpos[0] = 1e-3;
  d->qpos[1] = -2e-3;
  for (int i = 0; i < n; i++) {
    x1[i] = d->qpos[0];
    x2[i] = d->qpos[1];
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  double T1 = period(x1, n, m->opt.dt), T2 = period(x2, n, m->opt.dt);
  double e1 = fabs(2 * M_PI / T1 - w1) / w1, e2 = fabs(2 * M_PI / T2 - w2) / w2;
  print_message("universal: w1 %.5f (exact %.5f, err %.1e), w2 %.5f (exact %.5f, err %.1e)\n",
                2 * M_PI / T1, w1, e1, 2 * M_PI / T2, w2, e2);
  assert_true(e1 < 1e-4);
  assert_true(e2 < 1e-4);
  ur_data_free(d);
  ur_model_free(m);
}


// a chain with every joint type under gravity (test_engine_scene.h)
static urModel* chain(urIntegrator integ, double dt, double g) {
  urModel* m = scene_chain(integ, dt, g);
  assert_non_null(m);
  return m;
}


// violent initial velocities on every joint
static void shake(const urModel* m, urData* d) {
  for (int k = 0; k < m->nv; k++) {
    d->qvel[k] = 8.0 * sin(1.7 * k + 0.3);
  }
}


// energy conserved in a chain with every joint type (checks the ABA and bias terms)
static void test_chain_energy(void** state) {
  urModel* m = chain(urINT_RK4, 1e-5, -9.81);
  urData* d = ur_data_new(m);
  shake(m, d);
  ur_forward(m, d);
  double e0 = ur_energy_kinetic(m, d) + ur_energy_potential(m, d);
  double k0 = ur_energy_kinetic(m, d);
  for (int i = 0; i < 30000; i++) {
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  ur_forward(m, d);
  double e1 = ur_energy_kinetic(m, d) + ur_energy_potential(m, d);
  print_message("chain RK4 dt=1e-5, 0.3 s: KE0 %.3f J, |dE|/KE0 = %.2e\n", k0, fabs(e1 - e0) / k0);
  assert_true(fabs(e1 - e0) / k0 < 1e-6);
  ur_data_free(d);
  ur_model_free(m);
}


// linear and angular momentum of a free chain without gravity
static void test_chain_momentum(void** state) {
  urModel* m = chain(urINT_RK4, 1e-5, 0);
  urData* d = ur_data_new(m);
  double p0[3], L0[3], p1[3], L1[3];
  shake(m, d);
  ur_forward(m, d);
  ur_momentum(m, d, p0, L0);
  for (int i = 0; i < 30000; i++) {
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  ur_forward(m, d);
  ur_momentum(m, d, p1, L1);
  print_message("chain momentum RK4 0.3 s: |dp|/|p| = %.2e, |dL|/|L| = %.2e\n", reldiff3(p1, p0),
                reldiff3(L1, L0));
  assert_true(reldiff3(p1, p0) < 1e-7);
  assert_true(reldiff3(L1, L0) < 1e-7);
  ur_data_free(d);
  ur_model_free(m);
}


// joint anchors coincide and joint axes stay aligned after violent motion
static void test_constraint_error(void** state) {
  urModel* m = chain(urINT_EULER, 1e-5, -9.81);
  urData* d = ur_data_new(m);
  shake(m, d);
  for (int i = 0; i < 20000; i++) {
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  ur_forward(m, d);
  double eanchor = 0, eaxis = 0;
  for (int i = 1; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    const double* Rp = d->xmat + 9 * b->parent;
    const double* Rc = d->xmat + 9 * i;
    double Rb[9], q[4], p[3], a[3], tmp[3], ap[3], ac[3];

    // anchor from the parent side vs the child's origin (prismatic: along the axis)
    memcpy(p, b->pos, sizeof(p));
    memcpy(q, b->quat, sizeof(q));
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double Rq[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                    2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                    2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    memcpy(Rb, Rq, sizeof(Rb));
    if (b->jtype == urJNT_PRISMATIC) {
      for (int k = 0; k < 3; k++) {
        a[k] = Rb[3 * k] * b->axis[0][0] + Rb[3 * k + 1] * b->axis[0][1] +
               Rb[3 * k + 2] * b->axis[0][2];
        p[k] += d->qpos[b->qadr] * a[k];
      }
    }
    for (int k = 0; k < 3; k++) {
      tmp[k] = d->xpos[3 * b->parent + k] + Rp[3 * k] * p[0] + Rp[3 * k + 1] * p[1] +
               Rp[3 * k + 2] * p[2];
      eanchor = fmax(eanchor, fabs(tmp[k] - d->xpos[3 * i + k]));
    }

    // axis fixed in both bodies (revolute, prismatic): same world direction
    if (b->jtype == urJNT_REVOLUTE || b->jtype == urJNT_PRISMATIC) {
      for (int k = 0; k < 3; k++) {
        a[k] = Rb[3 * k] * b->axis[0][0] + Rb[3 * k + 1] * b->axis[0][1] +
               Rb[3 * k + 2] * b->axis[0][2];
      }
      for (int k = 0; k < 3; k++) {
        ap[k] = Rp[3 * k] * a[0] + Rp[3 * k + 1] * a[1] + Rp[3 * k + 2] * a[2];
        ac[k] = Rc[3 * k] * b->axis[0][0] + Rc[3 * k + 1] * b->axis[0][1] +
                Rc[3 * k + 2] * b->axis[0][2];
        eaxis = fmax(eaxis, fabs(ap[k] - ac[k]));
      }
    }

    // universal: the parent's first axis stays perpendicular to the child's second axis
    if (b->jtype == urJNT_UNIVERSAL) {
      double dot = 0;
      for (int k = 0; k < 3; k++) {
        a[k] = Rb[3 * k] * b->axis[0][0] + Rb[3 * k + 1] * b->axis[0][1] +
               Rb[3 * k + 2] * b->axis[0][2];
      }
      for (int k = 0; k < 3; k++) {
        ap[k] = Rp[3 * k] * a[0] + Rp[3 * k + 1] * a[1] + Rp[3 * k + 2] * a[2];
        ac[k] = Rc[3 * k] * b->axis[1][0] + Rc[3 * k + 1] * b->axis[1][1] +
                Rc[3 * k + 2] * b->axis[1][2];
        dot += ap[k] * ac[k];
      }
      eaxis = fmax(eaxis, fabs(dot));
    }

    // fixed: relative rotation equals the model's
    if (b->jtype == urJNT_FIXED) {
      double Rrel[9];
      for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
          Rrel[3 * r + c] = Rp[r] * Rc[c] + Rp[3 + r] * Rc[3 + c] + Rp[6 + r] * Rc[6 + c];
          eaxis = fmax(eaxis, fabs(Rrel[3 * r + c] - Rb[3 * r + c]));
        }
      }
    }
  }

  // the motion was violent: the root moved and spun
  double speed = 0;
  for (int k = 0; k < m->nv; k++) {
    speed = fmax(speed, fabs(d->qvel[k]));
  }
  print_message(
      "constraint error after 0.2 s violent motion: anchors %.1e m, axes %.1e "
      "(max joint speed %.1f)\n",
      eanchor, eaxis, speed);
  assert_true(speed > 1);
  assert_true(eanchor < 1e-12);
  assert_true(eaxis < 1e-12);
  ur_data_free(d);
  ur_model_free(m);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_free_tumbling),    cmocka_unit_test(test_free_tumbling_moves),
      cmocka_unit_test(test_pendulum_period),  cmocka_unit_test(test_universal_frequency),
      cmocka_unit_test(test_chain_energy),     cmocka_unit_test(test_chain_momentum),
      cmocka_unit_test(test_constraint_error),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
