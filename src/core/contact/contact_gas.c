/* contact_gas.c: uniform-pressure gas law of a closed, adiabatic airbag without vents.
 * Source: contact-airbag sheet §4.1 (Altair Radioss theory "Monitored Volume", GAS law):
 * P V^gamma = P0 V0^gamma with absolute pressures.
 */
#include <math.h>

#include "uasimpact/contact.h"

/* log(V0 / V) for a volume drop dv, V kept above 1e-9 V0 */
static double logratio(const urGas* gas, double dv) {
  double x = dv / gas->v0;
  if (x > 1 - 1e-9) x = 1 - 1e-9;
  return -log1p(-x);
}

double ur_gas_pressure(const urGas* gas, double dv) {
  // P = P0 (V0 / V)^gamma
  return gas->p0 * exp(gas->gamma * logratio(gas, dv));
}

double ur_gas_work(const urGas* gas, double dv) {
  // W = int_V^V0 P dV = P0 V0 ((V0/V)^(gamma-1) - 1) / (gamma - 1); isothermal limit at gamma = 1
  double l = logratio(gas, dv);
  double gm = gas->gamma - 1;
  if (fabs(gm) < 1e-12) return gas->p0 * gas->v0 * l;
  return gas->p0 * gas->v0 * expm1(gm * l) / gm;
}
