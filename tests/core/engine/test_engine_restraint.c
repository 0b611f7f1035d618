/* test_engine_restraint.c: joint restraints against direct evaluation: tabulated curve with
 * odd extension, linear part, damping, end stops, hysteresis (unloading curve scaled through the
 * largest deflection), and energy conservation of a spherical joint with a linear restraint at
 * large rotations (exact rotation-vector torque map). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/engine.h"

// independent piecewise-linear interpolation (linear extrapolation)
static double interp(const double* x, const double* y, int n, double v) {
  int i = 0;
  while (i < n - 2 && v > x[i + 1]) {
    i++;
  }
  return y[i] + (y[i + 1] - y[i]) * (v - x[i]) / (x[i + 1] - x[i]);
}


static const double LX[4] = {0, 0.1, 0.3, 0.6}, LY[4] = {0, 20, 90, 400};
static const double UX[3] = {0, 0.2, 0.6}, UY[3] = {0, 5, 100};

// a massive hinge without gravity with restraint r
static urModel* hinge_with(const urRestraint* r) {
  urModel* m = ur_model_new();
  double I[6] = {0.1, 0.1, 0.1, 0, 0, 0};
  int b = ur_model_add_body(m, "arm", -1, urJNT_REVOLUTE, NULL, NULL);
  ur_model_set_inertia(m, b, 1, NULL, I);
  ur_model_set_restraint(m, b, 0, r);
  m->opt.gravity[2] = 0;
  assert_int_equal(ur_model_compile(m), 0);
  return m;
}


// the hinge with the restraint under test
static urModel* hinge(int unload) {
  urRestraint r = {0};
  r.k = 7;
  r.c = 0.5;
  r.lo = -0.5;
  r.hi = 0.4;
  r.kstop = 1000;
  r.cstop = 3;
  r.load.n = 4;
  memcpy(r.load.x, LX, sizeof(LX));
  memcpy(r.load.y, LY, sizeof(LY));
  if (unload) {
    r.unload.n = 3;
    memcpy(r.unload.x, UX, sizeof(UX));
    memcpy(r.unload.y, UY, sizeof(UY));
  }
  return hinge_with(&r);
}


// restraint moment at q, qd from ur_forward (qfrc is minus the restraint force)
static double moment(const urModel* m, urData* d, double q, double qd) {
  d->qpos[0] = q;
  d->qvel[0] = qd;
  ur_forward(m, d);
  return -d->qfrc[0];
}


static void test_curve_stops(void** state) {
  urModel* m = hinge(0);
  urData* d = ur_data_new(m);
  double qs[7] = {0.05, 0.2, 0.35, 0.45, -0.15, -0.55, 0.7}, qd = 0.8, e = 0;
  for (int i = 0; i < 7; i++) {
    double q = qs[i];
    double f = 7 * q + (q >= 0 ? interp(LX, LY, 4, q) : -interp(LX, LY, 4, -q)) + 0.5 * qd;
    if (q > 0.4) {
      f += 1000 * (q - 0.4) + 3 * qd;
    } else if (q < -0.5) {
      f += 1000 * (q + 0.5) + 3 * qd;
    }
    double g = moment(m, d, q, qd);
    e = fmax(e, fabs(g - f));
  }
  print_message("restraint curve + damping + stops: max error %.1e N m\n", e);
  assert_true(e < 1e-12);
  ur_data_free(d);
  ur_model_free(m);
}


// saturation: the linear part k x becomes sat tanh(k x / sat) (the arms' yielding law); the
// potential energy is its integral, sat^2/k ln cosh(k x / sat)
static void test_saturation(void** state) {
  urRestraint r = {0};
  r.k = 6000;
  r.sat = 600;
  urModel* m = hinge_with(&r);
  urData* d = ur_data_new(m);
  double qs[5] = {0.001, 0.05, 0.1, 0.5, -0.3}, e = 0;
  for (int i = 0; i < 5; i++) {
    double f = 600 * tanh(10 * qs[i]);
    e = fmax(e, fabs(moment(m, d, qs[i], 0) - f));
  }
  assert_true(e < 1e-9);
  assert_true(fabs(moment(m, d, 0.001, 0) - 6) < 1e-3); /* initial slope k */
  assert_true(fabs(moment(m, d, 2, 0) - 600) < 1e-9);   /* saturated */
  d->qpos[0] = 0.2;
  ur_kinematics(m, d);
  assert_true(fabs(ur_energy_potential(m, d) - 600.0 * 600 / 6000 * log(cosh(2))) < 1e-9);
  ur_data_free(d);
  ur_model_free(m);
}


static void test_hysteresis(void** state) {
  urModel* m = hinge(1);
  urData* d = ur_data_new(m);

  // load to 0.3 (accepted step), then unload to 0.2 and 0.1, reload beyond 0.3
  d->qpos[0] = 0.3;
  ur_step(m, d);
  double lm = interp(LX, LY, 4, 0.3), um = interp(UX, UY, 3, 0.3);
  double f1 = moment(m, d, 0.2, 0) - 7 * 0.2, f2 = moment(m, d, 0.1, 0) - 7 * 0.1;
  double e1 = lm * interp(UX, UY, 3, 0.2) / um, e2 = lm * interp(UX, UY, 3, 0.1) / um;
  double f3 = moment(m, d, 0.35, 0) - 7 * 0.35, e3 = interp(LX, LY, 4, 0.35);
  double f4 = moment(m, d, -0.2, 0) + 7 * 0.2, e4 = -interp(LX, LY, 4, 0.2);
  print_message(
      "hysteresis: unload 0.2 %.4f (exact %.4f), 0.1 %.4f (%.4f), reload 0.35 %.3f "
      "(%.3f), other side %.3f (%.3f)\n",
      f1, e1, f2, e2, f3, e3, f4, e4);
  assert_true(fabs(f1 - e1) < 1e-12 && fabs(f2 - e2) < 1e-12);
  assert_true(fabs(f3 - e3) < 1e-12 && fabs(f4 - e4) < 1e-12);
  assert_true(f1 < interp(LX, LY, 4, 0.2) - 10);
  ur_data_free(d);
  ur_model_free(m);
}


// an elastic-plastic hinge (k 1000 N m/rad, mp 50 N m, kh 10 N m/rad): the bilinear law
// M = mp + kh (x - mp/k) while loading, elastic unloading with slope k from the permanent set,
// reverse yield at beta xp - mp (kinematic hardening, beta = k kh / (k - kh)), fracture at
// mfrac, after which the hinge carries no moment
static urModel* plastic_hinge(double mfrac) {
  urRestraint r = {0};
  r.k = 1000;
  r.mp = 50;
  r.kh = 10;
  r.c = 0.5;
  r.mfrac = mfrac;
  return hinge_with(&r);
}


static void test_plastic_hinge(void** state) {
  urModel* m = plastic_hinge(0);
  urData* d = ur_data_new(m);
  assert_true(fabs(moment(m, d, 0.03, 0) - 30) < 1e-12);
  assert_true(fabs(moment(m, d, 0.1, 0) - 50.5) < 1e-12); /* not yet committed: same value */

  // load to 0.1 (accepted), unload: slope k from (0.1, 50.5); permanent set 0.1 - 50.5/k
  d->qpos[0] = 0.1;
  d->qvel[0] = 0;
  ur_step(m, d);
  double xp = 0.1 - 50.5 / 1000;
  print_message("plastic hinge: M(0.06) %.6f (exact %.6f), set %.6f\n", moment(m, d, 0.06, 0),
                1000 * (0.06 - xp), xp);
  assert_true(fabs(moment(m, d, 0.06, 0) - 1000 * (0.06 - xp)) < 1e-9);
  assert_true(fabs(moment(m, d, xp, 0)) < 1e-9);
  assert_true(fabs(moment(m, d, 0.12, 0) - (50 + 10 * (0.12 - 0.05))) < 1e-9);

  // reverse yield: at beta xp - mp, then the hardening slope
  double beta = 1000.0 * 10 / 990, mr = beta * xp - 50, xr = xp + mr / 1000;
  assert_true(fabs(moment(m, d, xr + 1e-6, 0) - 1000 * (xr + 1e-6 - xp)) < 1e-9);
  double x2 = xr - 0.05, m2 = mr - 10 * 0.05;
  print_message("plastic hinge: reverse yield at %.6f N m, M(%.4f) %.6f (exact %.6f)\n", mr, x2,
                moment(m, d, x2, 0), m2);
  assert_true(fabs(moment(m, d, x2, 0) - m2) < 1e-9);

  // the elastic energy is that of x - xp
  d->qpos[0] = 0.06;
  assert_true(fabs(ur_energy_potential(m, d) - 0.5 * 1000 * (0.06 - xp) * (0.06 - xp)) < 1e-9);
  ur_data_free(d);
  ur_model_free(m);
}


static void test_fracture(void** state) {
  urModel* m = plastic_hinge(52); /* reached at 0.05 + 2 / 10 = 0.25 */
  urData* d = ur_data_new(m);
  d->qpos[0] = 0.2;
  ur_step(m, d);
  double h0, hb;
  assert_int_equal(ur_hinge_state(m, d, 0, 0, &h0, &hb), 0);
  assert_true(hb == 0);
  assert_true(fabs(moment(m, d, 0.2, 0) - 51.5) < 1e-9);
  d->qpos[0] = 0.26;
  ur_step(m, d);
  assert_int_equal(ur_hinge_state(m, d, 0, 0, &h0, &hb), 0);
  print_message("fracture: broken at t = %g s, moment after %g\n", hb, moment(m, d, 0.3, 2));
  assert_true(hb > 0);
  assert_true(moment(m, d, 0.3, 2) == 0 && moment(m, d, -0.3, -2) == 0);
  assert_int_equal(ur_hinge_state(m, d, 0, 1, &h0, &hb), -1); /* no such dof */
  ur_data_free(d);
  ur_model_free(m);
}


// a drone's frame (free) with one tube arm on a universal joint whose hinge breaks: spun
// about the root without gravity, the arm bends, yields, fractures and flies off free (its
// joint released: test_engine_fracture.c); the linear and angular momentum of the whole stay
// what they were (the hinge's moments are internal)
static void test_fracture_momentum(void** state) {
  urModel* m = ur_model_new();
  double If[6] = {0.5, 0.4, 0.8, 0, 0, 0}, Ia[6] = {0.001, 0.002, 0.003, 0, 0, 0};
  int f = ur_model_add_body(m, "frame", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, f, 10, NULL, If);
  int a = ur_model_add_body(m, "arm", f, urJNT_UNIVERSAL, (double[3]){0.16, 0, 0}, NULL);
  ur_model_set_inertia(m, a, 0.5, (double[3]){0.3, 0, 0}, Ia);
  ur_model_set_joint(m, a, NULL, (double[3]){0, 1, 0}, (double[3]){0, 0, 1});
  urRestraint r = {0};
  r.k = 6949; /* the 30 x 2 carbon tube on 0.41 m (test_contact_material.c) */
  r.mp = 93.1;
  r.kh = 69.49;
  r.c = 0.5;
  r.mfrac = 100;
  ur_model_set_restraint(m, a, 0, &r);
  ur_model_set_restraint(m, a, 1, &r);
  int hs = ur_model_add_sensor(m, "hinge", urSENS_HINGE, a, 0, NULL, NULL);
  assert_true(hs >= 0);
  m->opt.gravity[2] = 0;
  m->opt.dt = 1e-5;
  m->opt.integrator = urINT_RK4; /* the chain's momentum drifts O(dt) under semi-implicit Euler */
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  double v[3] = {1, -0.5, 2}, w[3] = {0, 0, 0};
  ur_set_free(m, d, f, NULL, NULL, v, w);
  d->qvel[m->body[a].vadr] = 60; /* the arm whipped about its root: 0.06 kg m^2 at 60 rad/s */
  ur_forward(m, d);
  double p0[3], L0[3], p1[3], L1[3], xp, tb = 0;
  ur_momentum(m, d, p0, L0);
  for (int i = 0; i < 20000 && tb == 0; i++) {
    ur_step(m, d);
    ur_hinge_state(m, d, a, 0, &xp, &tb);
  }
  print_message("fracture: broke at %.5f s after a plastic set of %.4f rad\n", tb, xp);
  assert_true(tb > 0 && fabs(xp) > 0.001);
  ur_forward(m, d); /* the sensor reads the same */
  assert_true(d->sensordata[m->sensor[hs].adr] == xp && d->sensordata[m->sensor[hs].adr + 1] == tb);
  for (int i = 0; i < 5000; i++) {
    ur_step(m, d);
  }
  ur_forward(m, d);
  ur_momentum(m, d, p1, L1);
  double dp = 0, dl = 0, np = 0, nl = 0;
  for (int k = 0; k < 3; k++) {
    dp = fmax(dp, fabs(p1[k] - p0[k]));
    dl = fmax(dl, fabs(L1[k] - L0[k]));
    np = fmax(np, fabs(p0[k]));
    nl = fmax(nl, fabs(L0[k]));
  }
  print_message("fracture: |dp| %.2e of %.3g kg m/s, |dL| %.2e of %.3g kg m^2/s; released %d\n", dp,
                np, dl, nl, d->nreleased);
  assert_int_equal(d->nreleased, 1);
  assert_true(dp <= 1e-10 * np && dl <= 1e-10 * nl); /* RK4 at 1e-5 s: ~1e-11 */
  ur_data_free(d);
  ur_model_free(m);
}


// spherical joint with a linear restraint: KE + k |theta|^2 / 2 conserved at large angles
static void test_spherical_energy(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {0.02, 0.03, 0.04, 0, 0, 0};
  int b = ur_model_add_body(m, "head", -1, urJNT_SPHERICAL, NULL, NULL);
  ur_model_set_inertia(m, b, 4.5, (double[3]){0.02, 0.01, 0.06}, I);
  urRestraint r = {0};
  double ks[3] = {2, 3, 1.5}; // anisotropic: the torque map matters
  for (int k = 0; k < 3; k++) {
    r.k = ks[k];
    ur_model_set_restraint(m, b, k, &r);
  }
  m->opt.gravity[2] = 0;
  m->opt.integrator = urINT_RK4;
  m->opt.dt = 1e-4;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  d->qvel[0] = 6;
  d->qvel[1] = -4;
  d->qvel[2] = 8;
  ur_forward(m, d);
  double e0 = ur_energy_kinetic(m, d) + ur_energy_potential(m, d), thmax = 0;
  for (int i = 0; i < 10000; i++) {
    ur_step(m, d);
    double v = 2 * acos(fmin(1, fabs(d->qpos[0])));
    thmax = fmax(thmax, v);
  }
  ur_forward(m, d);
  double e1 = ur_energy_kinetic(m, d) + ur_energy_potential(m, d);
  print_message("spherical restraint: max angle %.2f rad, |dE|/E %.1e over 1 s\n", thmax,
                fabs(e1 - e0) / e0);
  assert_true(thmax > 1.0);
  assert_true(fabs(e1 - e0) / e0 < 1e-8);
  ur_data_free(d);
  ur_model_free(m);
}

// implicit joint damping (Euler): a pure damper on a hinge decays as w0 / (1 + h c / I)^n, also
// where explicit damping (h c / I = 5 > 2) grows as |1 - h c / I|^n
static void test_implicit_damping(void** state) {
  for (int impl = 1; impl >= 0; impl--) {
    urModel* m = ur_model_new();
    double I[6] = {0.1, 0.1, 0.1, 0, 0, 0};
    int b = ur_model_add_body(m, "arm", -1, urJNT_REVOLUTE, NULL, NULL);
    ur_model_set_inertia(m, b, 1, NULL, I);
    urRestraint r = {0};
    r.c = 50;
    ur_model_set_restraint(m, b, 0, &r);
    m->opt.gravity[2] = 0;
    m->opt.dt = 0.01;
    m->opt.implicit_damping = impl;
    assert_int_equal(ur_model_compile(m), 0);
    urData* d = ur_data_new(m);
    d->qvel[0] = 2;
    for (int n = 1; n <= (impl ? 10 : 5); n++) { // 2 4^5 < vmax
      ur_step(m, d);
      double want = impl ? 2 / pow(6, n) : 2 * pow(-4, n);
      assert_true(fabs(d->qvel[0] - want) <= 1e-12 * fabs(want));
    }
    ur_data_free(d);
    ur_model_free(m);
  }
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_curve_stops),      cmocka_unit_test(test_hysteresis),
      cmocka_unit_test(test_saturation),       cmocka_unit_test(test_spherical_energy),
      cmocka_unit_test(test_implicit_damping), cmocka_unit_test(test_plastic_hinge),
      cmocka_unit_test(test_fracture),         cmocka_unit_test(test_fracture_momentum),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
