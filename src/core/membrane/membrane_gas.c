/* membrane_gas.c: the bag's uniform-pressure gas: the enclosed volume of the triangulated
 * surface by the divergence theorem, the isentropic pressure of the remaining gas mass
 * (P V^gamma = const while closed), its energy, and the optional outflow through vent orifices
 * and the fabric (Wang-Nefske isentropic orifice flow with choking). Sources:
 * materials-membrane sheet B.1, B.2, A.4. */
#include <math.h>

#include "membrane_internal.h"

double ur_mem_volume(const urMembrane* mb, const double* x) {
  // V = 1/6 sum x1 . (x2 x x3) over outward-oriented triangles
  double V = 0;
  for (int t = 0; t < mb->nt; t++) {
    const int* v = mb->tri + 3 * t;
    double c[3];
    urm_cross(c, x + 3 * v[1], x + 3 * v[2]);
    V += urm_dot(x + 3 * v[0], c);
  }
  return V / 6;
}


double ur_mem_pressure(const urMembrane* mb, double V, double mgas) {
  // isentropic: P / rho^gamma constant from the inflated state
  double r = (mgas / mb->mref) * (mb->vref / fmax(V, 1e-9 * mb->vref));
  return mb->pref * pow(r, mb->spec.gamma);
}


double ur_mem_gas_energy(const urMembrane* mb, double p, double V) {
  // internal energy p V / (gamma - 1) plus the ambient's p_atm V: d/dV = p_atm - p
  return p * V / (mb->spec.gamma - 1) + mb->spec.patm * V;
}


double ur_mem_outflow(const urMembrane* mb, const double* st, double dt) {
  const urMemSpec* s = &mb->spec;
  const double* sc = st + 18 * mb->nn;
  double p = sc[urMEMS_P], V = sc[urMEMS_V], mg = sc[urMEMS_MGAS];
  if (!(s->vent_area > 0 || s->leak > 0) || !(p > s->patm) || !(V > 0)) {
    return 0;
  }
  // open area: vents (times C_D) and the fabric's leakage share of the current surface
  double area = 0;
  if (s->leak > 0) {
    const double* x = st;
    for (int t = 0; t < mb->nt; t++) {
      const int* v = mb->tri + 3 * t;
      double d1[3], d2[3], c[3];
      urm_sub(d1, x + 3 * v[1], x + 3 * v[0]);
      urm_sub(d2, x + 3 * v[2], x + 3 * v[0]);
      urm_cross(c, d1, d2);
      area += 0.5 * sqrt(urm_dot(c, c));
    }
    area *= s->leak;
  }
  area = s->vent_cd * (s->vent_area + area);

  // isentropic orifice flow, choked below the critical pressure ratio
  double g = s->gamma, rho = mg / V;
  double pcrit = p * pow(2 / (g + 1), g / (g - 1));
  double pe = fmax(s->patm, pcrit);
  double u = sqrt(2 * g / (g - 1) * (p / rho) * (1 - pow(pe / p, (g - 1) / g)));
  double rhoe = rho * pow(pe / p, 1 / g);
  double dm = rhoe * u * area * dt;
  return fmin(dm, 0.5 * mg);
}
