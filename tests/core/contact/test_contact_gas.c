/* test_contact_gas.c: adiabatic closed-bag gas law: P V^gamma invariant, work against GSL
 * quadrature of the pressure, and the sheet's whole-bag compression energies (§4.2).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include <cmocka.h>
#include <gsl/gsl_integration.h>

#include "uasimpact/contact.h"

/* |a - b| <= tol with both values printed on failure (cmocka 1.1 has float-only compares) */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)
static void near_(double a, double b, double tol, const char* what, const char* file, int line) {
  if (!(fabs(a - b) <= tol)) {
    print_error("%s = %.17g, expected %.17g +- %.3g\n", what, a, b, tol);
    _fail(file, line);
  }
}

#define ATM 101325.0

/* P V^gamma = P0 V0^gamma over compression and expansion, several gases */
static void test_adiabat(void** state) {
  const urGas gases[3] = {
      {0.020, ATM, ATM, 1.4},
      {0.050, 1.1 * ATM, ATM, 1.25},
      {0.020, 1.1 * ATM, ATM, 1.0},
  };
  double worst = 0;
  for (int g = 0; g < 3; g++) {
    const urGas* gas = gases + g;
    double c0 = gas->p0 * pow(gas->v0, gas->gamma);
    assert_near(ur_gas_pressure(gas, 0), gas->p0, 0);
    for (int k = -50; k <= 95; k++) {
      double dv = gas->v0 * k / 100.0;
      double v = gas->v0 - dv;
      double rel = ur_gas_pressure(gas, dv) * pow(v, gas->gamma) / c0 - 1;
      worst = fmax(worst, fabs(rel));
      assert_true(fabs(rel) < 1e-12);
    }
  }
  printf("adiabat: max |P V^gamma / (P0 V0^gamma) - 1| = %.3g\n", worst);
}

typedef struct {
  const urGas* gas;
} qpar;

/* pressure as a function of the current volume V, through the library */
static double pofv(double v, void* par) {
  const qpar* q = par;
  return ur_gas_pressure(q->gas, q->gas->v0 - v);
}

/* work on the gas = int_{V0 - dv}^{V0} P dV by adaptive Gauss-Kronrod quadrature */
static void test_work_quadrature(void** state) {
  const urGas gases[3] = {
      {0.020, ATM, ATM, 1.4},
      {0.050, 1.1 * ATM, ATM, 1.25},
      {0.020, 1.1 * ATM, ATM, 1.0},
  };
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(1000);
  double worst = 0;
  for (int g = 0; g < 3; g++) {
    qpar q = {gases + g};
    gsl_function fn = {pofv, &q};
    for (int k = -40; k <= 90; k += 5) {
      double dv = gases[g].v0 * k / 100.0, ref, err;
      gsl_integration_qag(&fn, gases[g].v0 - dv, gases[g].v0, 0, 1e-13, 1000, GSL_INTEG_GAUSS61, ws,
                          &ref, &err);
      double w = ur_gas_work(gases + g, dv);
      double rel = k ? fabs(w / ref - 1) : fabs(w);
      worst = fmax(worst, rel);
      assert_true(rel < 1e-8);
    }
  }
  gsl_integration_workspace_free(ws);
  printf("work: max relative difference to quadrature = %.3g\n", worst);

  // small volume changes: W -> P0 dv without cancellation
  urGas air = {0.020, ATM, ATM, 1.4};
  assert_near(ur_gas_work(&air, 1e-12), ATM * 1e-12, 1e-9 * ATM * 1e-12);
}

/* sheet §4.2: whole-bag compression by 20% (40%) absorbs 68 J (338 J) for 20 L at 1.0 atm and
   169 J (845 J) for 50 L; the sheet counts the work against the overpressure, W - Patm dv */
static void test_sheet_energies(void** state) {
  const double v0[2] = {0.020, 0.050};
  const double ref[2][2] = {{68, 338}, {169, 845}};
  for (int i = 0; i < 2; i++) {
    urGas gas = {v0[i], ATM, ATM, 1.4};
    for (int j = 0; j < 2; j++) {
      double dv = v0[i] * (j ? 0.4 : 0.2);
      double w = ur_gas_work(&gas, dv) - gas.patm * dv;
      printf("%.0f L by %.0f%%: %.1f J (sheet %.0f J)\n", v0[i] * 1e3, j ? 40.0 : 20.0, w,
             ref[i][j]);
      assert_near(w, ref[i][j], 0.6);
    }
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_adiabat),
      cmocka_unit_test(test_work_quadrature),
      cmocka_unit_test(test_sheet_energies),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
