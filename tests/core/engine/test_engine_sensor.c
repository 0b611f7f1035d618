/* test_engine_sensor.c: sensors against closed forms: joint reaction (load cell) and point
 * acceleration of a swinging pendulum, static load cell of an offset body, joint coordinate
 * and rate sensors, peaks and their times. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/engine.h"

// pendulum about y through the world origin, bob below at distance l
static urModel* pendulum(double mass, double l, double ic) {
  urModel* m = ur_model_new();
  double I[6] = {ic, ic, ic, 0, 0, 0};
  int b = ur_model_add_body(m, "bob", -1, urJNT_REVOLUTE, NULL, NULL);
  ur_model_set_inertia(m, b, mass, (double[3]){0, 0, -l}, I);
  ur_model_set_joint(m, b, "pivot", (double[3]){0, 1, 0}, NULL);
  ur_model_add_sensor(m, "cell", urSENS_JOINTLOAD, b, 0, NULL, NULL);
  ur_model_add_sensor(m, "acc", urSENS_ACCEL, b, 0, (double[3]){0, 0, -l}, NULL);
  ur_model_add_sensor(m, "angle", urSENS_JOINTPOS, b, 0, NULL, NULL);
  ur_model_add_sensor(m, "rate", urSENS_JOINTVEL, b, 0, NULL, NULL);
  ur_model_add_sensor(m, "pos", urSENS_BODYPOS, b, 0, (double[3]){0, 0, -l}, NULL);
  ur_model_add_sensor(m, "vel", urSENS_BODYVEL, b, 0, (double[3]){0, 0, -l}, NULL);
  assert_int_equal(ur_model_compile(m), 0);
  return m;
}


// at angle th with rate w: tangential acc -g sin th * (m l^2 / Ip), radial w^2 l
static void test_pendulum_loads(void** state) {
  double mass = 2.0, l = 0.4, ic = 0.01, g = 9.81, th = 0.7, w = 3.0;
  urModel* m = pendulum(mass, l, ic);
  urData* d = ur_data_new(m);
  d->qpos[0] = th;
  d->qvel[0] = w;
  ur_forward(m, d);

  // independent: angular acceleration, CoM acceleration, force = m a - m g (world)
  double ip = ic + mass * l * l, al = -mass * g * l * sin(th) / ip;
  double r[3] = {-l * sin(th), 0, -l * cos(th)}; // CoM relative to the pivot, world
  double t[3] = {-cos(th), 0, sin(th)};          // d r / d th
  double a[3], f[3];
  for (int k = 0; k < 3; k++) {
    a[k] = al * l * t[k] - w * w * r[k];
  }
  for (int k = 0; k < 3; k++) {
    f[k] = mass * a[k] - mass * (k == 2 ? -g : 0);
  }

  // the load cell reports the force in the child frame: rotate the world force into it
  double c = cos(th), s = sin(th);
  double fl[3] = {c * f[0] - s * f[2], f[1], s * f[0] + c * f[2]};
  const double* cell = d->sensordata;
  const double* acc = d->sensordata + 6;
  double ef = 0, ea = 0;
  for (int k = 0; k < 3; k++) {
    ef = fmax(ef, fabs(cell[k] - fl[k]));
    ea = fmax(ea, fabs(acc[k] - a[k]));
  }

  // moment about the pivot axis must be zero (free hinge); qacc the exact one
  print_message(
      "pendulum loads: |F - F_exact| %.1e N (|F| %.2f), |a - a_exact| %.1e m/s^2, "
      "My %.1e, qacc err %.1e\n",
      ef, sqrt(f[0] * f[0] + f[2] * f[2]), ea, cell[4], fabs(d->qacc[0] - al));
  assert_true(ef < 1e-12 * mass * g * 10);
  assert_true(ea < 1e-12 * g * 10);
  assert_true(fabs(cell[4]) < 1e-12);
  assert_true(fabs(d->qacc[0] - al) < 1e-12);

  // coordinate, rate, position and velocity sensors
  assert_true(d->sensordata[9] == th);
  assert_true(d->sensordata[10] == w);
  assert_true(fabs(d->sensordata[11] - r[0]) < 1e-15 && fabs(d->sensordata[13] - r[2]) < 1e-15);
  assert_true(fabs(d->sensordata[14] - w * l * t[0]) < 1e-14);
  assert_true(fabs(d->sensordata[16] - w * l * t[2]) < 1e-14);
  ur_data_free(d);
  ur_model_free(m);
}


// a body held by a fixed joint with its CoM offset: F = m g up, M = c x F, in a rotated frame
static void test_static_cell(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {0.02, 0.02, 0.02, 0, 0, 0}, c[3] = {0.026, 0, 0.062}, mass = 4.5;
  double q[4] = {cos(0.15), 0, sin(0.15), 0}; // 0.3 rad about y
  int b = ur_model_add_body(m, "head", -1, urJNT_FIXED, (double[3]){0, 0, 1.588}, q);
  ur_model_set_inertia(m, b, mass, c, I);
  double qs[4] = {cos(0.1), 0, 0, sin(0.1)}; // sensor frame: 0.2 rad about z
  ur_model_add_sensor(m, "cell", urSENS_JOINTLOAD, b, 0, NULL, qs);
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  ur_forward(m, d);

  // independent: world force (0, 0, m g), moment c_world x F, then into the sensor frame
  double g = 9.81, a = 0.3, z = 0.2;
  double cw[3] = {cos(a) * c[0] + sin(a) * c[2], c[1], -sin(a) * c[0] + cos(a) * c[2]};
  double F[3] = {0, 0, mass * g};
  double M[3] = {cw[1] * F[2] - cw[2] * F[1], cw[2] * F[0] - cw[0] * F[2],
                 cw[0] * F[1] - cw[1] * F[0]};
  // world -> body: R_y(a)^T, body -> sensor: R_z(z)^T
  double Fb[3], Mb[3], Fs[3], Ms[3];
  Fb[0] = cos(a) * F[0] - sin(a) * F[2];
  Fb[1] = F[1];
  Fb[2] = sin(a) * F[0] + cos(a) * F[2];
  Mb[0] = cos(a) * M[0] - sin(a) * M[2];
  Mb[1] = M[1];
  Mb[2] = sin(a) * M[0] + cos(a) * M[2];
  Fs[0] = cos(z) * Fb[0] + sin(z) * Fb[1];
  Fs[1] = -sin(z) * Fb[0] + cos(z) * Fb[1];
  Fs[2] = Fb[2];
  Ms[0] = cos(z) * Mb[0] + sin(z) * Mb[1];
  Ms[1] = -sin(z) * Mb[0] + cos(z) * Mb[1];
  Ms[2] = Mb[2];
  double e = 0;
  for (int k = 0; k < 3; k++) {
    e = fmax(e, fabs(d->sensordata[k] - Fs[k]));
    e = fmax(e, fabs(d->sensordata[3 + k] - Ms[k]));
  }
  print_message("static cell: F (%.3f %.3f %.3f) M (%.4f %.4f %.4f), max err %.1e\n",
                d->sensordata[0], d->sensordata[1], d->sensordata[2], d->sensordata[3],
                d->sensordata[4], d->sensordata[5], e);
  assert_true(e < 1e-12);
  assert_true(fabs(d->sensordata[2]) > 30);
  ur_data_free(d);
  ur_model_free(m);
}


// peaks track the extreme values of a swinging pendulum and their times
static void test_peaks(void** state) {
  double mass = 1.0, l = 0.3, ic = 1e-4;
  urModel* m = pendulum(mass, l, ic);
  urData* d = ur_data_new(m);
  double th0 = 0.5;
  d->qpos[0] = th0;
  for (int i = 0; i < 120000; i++) {
    ur_step(m, d);
  }
  // angle range [-th0, th0]; peak angular rate from energy: Ip w^2 / 2 = m g l (1 - cos th0)
  double wmax = sqrt(2 * mass * 9.81 * l * (1 - cos(th0)) / (ic + mass * l * l));
  print_message("peaks: angle [%.5f, %.5f], rate max %.5f (exact %.5f) at t %.4f\n", d->peakmin[9],
                d->peakmax[9], d->peakmax[10], wmax, d->tpeak[10]);
  assert_true(fabs(d->peakmax[9] - th0) < 1e-6);
  assert_true(fabs(d->peakmin[9] + th0) < 1e-3);
  assert_true(fabs(d->peakmax[10] - wmax) / wmax < 1e-3);
  ur_data_free(d);
  ur_model_free(m);
}


// a ball thrown up under gravity, nothing else in the world: with adapt 4 every step after the
// first is coarse (nothing to touch), and the history keeps a row every dt at the times of the
// fine run, bit for bit; the rows inside a coarse step lie on the line between its ends, where
// the ball's velocity (linear in time: v0 + g t) is exact to rounding (closed form; a held
// value would be off by up to 3 g dt), while the ends' positions are Euler's with the long step
// (their lag behind the fine run's, closed form, within 5 %)
static void test_coarse_rows(void** state) {
  double t[2][400], v[2][400], z[2][400];
  long ncoarse[2];
  int nhist[2];
  for (int c = 0; c < 2; c++) {
    urModel* m = ur_model_new();
    double I[6] = {1e-3, 1e-3, 1e-3, 0, 0, 0};
    int b = ur_model_add_body(m, "ball", -1, urJNT_FREE, NULL, NULL);
    ur_model_set_inertia(m, b, 1, NULL, I);
    ur_model_add_sensor(m, "vel", urSENS_BODYVEL, b, 0, NULL, NULL);
    ur_model_add_sensor(m, "pos", urSENS_BODYPOS, b, 0, NULL, NULL);
    m->opt.dt = m->opt.sample_dt = 1e-4;
    m->opt.tmax = 0.0199;
    m->opt.adapt = c ? 4 : 1;
    assert_int_equal(ur_model_compile(m), 0);
    urData* d = ur_data_new(m);
    assert_int_equal(ur_data_history(m, d, NULL, 400), 0);
    ur_run_impact(m, d, b, (double[3]){0, 0, 1}, NULL, (double[3]){0, 0, 3});
    assert_int_equal(d->status, urSTAT_TMAX);
    ncoarse[c] = d->ncoarse;
    nhist[c] = d->nhist;
    for (int i = 0; i < d->nhist && i < 400; i++) {
      const double* row = d->hist + 7 * i;
      t[c][i] = row[0];
      v[c][i] = row[3];
      z[c][i] = row[6];
    }
    ur_data_free(d);
    ur_model_free(m);
  }
  print_message("coarse rows: %d rows fine, %d with adapt 4 (%ld coarse steps)\n", nhist[0],
                nhist[1], ncoarse[1]);
  assert_int_equal(ncoarse[0], 0);
  assert_true(ncoarse[1] >= 45);
  assert_true(nhist[1] >= nhist[0] - 3 && nhist[1] <= nhist[0]);
  double ev = 0, ez = 0;
  for (int i = 0; i < nhist[1]; i++) {
    assert_true(t[1][i] == t[0][i]);
    ev = fmax(ev, fabs(v[1][i] - v[0][i]));
    ez = fmax(ez, fabs(z[1][i] - z[0][i]));
    // the first step is fine (the proof needs its kinematics), the coarse ones start at 1, 5, ...
    int a = 1 + (i - 1) / 4 * 4, e = a + 4;
    if (i > 1 && (i - 1) % 4 && e < nhist[1]) {
      double w = (i - a) / 4.0;
      assert_true(fabs(z[1][i] - (z[1][a] + w * (z[1][e] - z[1][a]))) < 1e-12);
    }
  }
  print_message("coarse rows: velocity off by %.1e m/s, height by %.1e m\n", ev, ez);
  assert_true(ev < 1e-12);
  // Euler's position with step h lags the exact one by g h t / 2: the coarse run's by g (K - 1)
  // dt t / 2 more than the fine run's (K = 4, t the last row's time)
  double lag = 9.81 * 3 * 1e-4 * t[1][nhist[1] - 1] / 2;
  assert_true(fabs(ez / lag - 1) < 0.05);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pendulum_loads),
      cmocka_unit_test(test_static_cell),
      cmocka_unit_test(test_peaks),
      cmocka_unit_test(test_coarse_rows),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
