/* test_engine_airbag.c: the uniform-pressure airbag element under a prescribed indentation:
 * P V^gamma = const, volume loss = kappa x spherical cap (closed form), force = (P - Patm) x
 * section area, reaction on the carrying body, bottoming at the bag thickness; and energy
 * conservation of a sphere bouncing on a kappa = 1 bag. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/engine.h"

static const double R = 0.0875, CZ = 0.15, ATM = 101325;

// bag on a fixed body; a sphere moving along -z on a prismatic joint (q = depth)
static urModel* bagmodel(double kappa, double thick, int free) {
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int b = ur_model_add_body(m, "drone", -1, urJNT_FIXED, NULL, NULL);
  ur_model_set_inertia(m, b, 12, NULL, I);
  int gb = ur_model_add_ellipsoid(m, "bag", b, NULL, NULL, (double[3]){0.3, 0.25, CZ});
  int h;
  if (free) {
    h = ur_model_add_body(m, "head", -1, urJNT_FREE, NULL, NULL);
  } else {
    h = ur_model_add_body(m, "head", -1, urJNT_PRISMATIC, (double[3]){0, 0, CZ + R}, NULL);
    ur_model_set_joint(m, h, "slide", (double[3]){0, 0, -1}, NULL);
  }
  ur_model_set_inertia(m, h, 4.5, NULL, I);
  int gh = ur_model_add_ellipsoid(m, "skull", h, NULL, NULL, (double[3]){R, R, R});
  urAirbag bag = {0};
  strcpy(bag.name, "bottom");
  bag.geom = gb;
  bag.gas.v0 = 0.02;
  bag.gas.p0 = 1.1 * ATM;
  bag.gas.patm = ATM;
  bag.gas.gamma = 1.4;
  bag.kappa = kappa;
  bag.thickness = thick;
  bag.ntarget = 1;
  bag.target[0] = gh;
  int ib = ur_model_add_airbag(m, &bag);
  ur_model_add_sensor(m, "gas", urSENS_AIRBAG, ib, 0, NULL, NULL);
  ur_model_add_sensor(m, "hold", urSENS_JOINTLOAD, b, 0, NULL, NULL); /* reaction on the bag body */
  m->opt.gravity[2] = 0;
  assert_int_equal(ur_model_compile(m), 0);
  return m;
}


static void test_airbag_gas_law(void** state) {
  double kappa = 1.5, thick = 0.06;
  urModel* m = bagmodel(kappa, thick, 0);
  urData* d = ur_data_new(m);
  double pv0 = 1.1 * ATM * pow(0.02, 1.4), worst = 0, worstv = 0, worstf = 0;
  int ib = ur_name_airbag(m, "bottom");
  assert_int_equal(ib, 0);

  // prescribed indentation 0..80 mm (beyond the 60 mm thickness: bottoming)
  for (int i = 0; i <= 80; i++) {
    double q = 1e-3 * i;
    d->qpos[0] = q;
    ur_forward(m, d);
    double P = d->sensordata[0], V = d->sensordata[1];

    // independent: spherical cap of the used depth, section area of the sphere
    double dd = fmin(q, thick);
    double vexp = 0.02 - kappa * M_PI * dd * dd * (3 * R - dd) / 3;
    double fexp = (P - ATM) * M_PI * (2 * R * dd - dd * dd);
    worst = fmax(worst, fabs(P * pow(V, 1.4) - pv0) / pv0);
    worstv = fmax(worstv, fabs(V - vexp) / 0.02);
    if (q > 0) {
      // reaction: the world holds the bag body with +F along z
      worstf = fmax(worstf, fabs(d->freact[5] - fexp) / fexp);
      worstf = fmax(worstf, fabs(d->bag[ib].ftgt[0] - fexp) / fexp);
    }
    if (i == 40 || i == 80) {
      print_message("airbag q=%2.0f mm: P %.1f Pa, V %.6f m^3, F %.2f N\n", 1e3 * q, P, V,
                    d->bag[ib].force);
    }
  }
  print_message(
      "airbag: max |PV^g - P0V0^g|/P0V0^g %.1e, max |V - Vcap|/V0 %.1e, "
      "max force/reaction rel err %.1e\n",
      worst, worstv, worstf);
  assert_true(worst < 1e-12);
  assert_true(worstv < 1e-9);
  assert_true(worstf < 1e-9);

  // the pressure rose (not a test that passes on a constant)
  assert_true(d->sensordata[0] > 1.05 * 1.1 * ATM);
  ur_data_free(d);
  ur_model_free(m);
}


// kappa = 1: the bag force is the gradient of the gas energy, so a frictionless bounce keeps
// kinetic + (gas work - Patm dV) constant and the rebound speed equals the impact speed
static void test_airbag_energy(void** state) {
  urModel* m = bagmodel(1.0, 1.0, 1);
  urData* d = ur_data_new(m);
  double v = 5.0, pos[3] = {0, 0, CZ + R + 0.2}, vel[3] = {0, 0, -v};
  int h = ur_name_body(m, "head");
  m->opt.t_quiet = 0.002;
  assert_int_equal(ur_run_impact(m, d, h, pos, NULL, vel), urSTAT_SEPARATED);
  double vr = d->qvel[m->body[h].vadr + 2];
  double Vmin = d->peakmin[1];
  urGas gas = {0.02, 1.1 * ATM, ATM, 1.4};
  double w = ur_gas_work(&gas, 0.02 - Vmin) - ATM * (0.02 - Vmin);
  print_message(
      "airbag bounce: rebound %.5f m/s (impact %.1f), Vmin %.6f, W(dV) %.3f J vs KE0 "
      "%.3f J\n",
      vr, v, Vmin, w, 0.5 * 4.5 * v * v);
  assert_true(fabs(vr - v) / v < 1e-3);
  assert_true(fabs(w - 0.5 * 4.5 * v * v) / (0.5 * 4.5 * v * v) < 1e-2);
  ur_data_free(d);
  ur_model_free(m);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_airbag_gas_law),
      cmocka_unit_test(test_airbag_energy),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
