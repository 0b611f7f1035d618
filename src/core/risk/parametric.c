/* parametric.c: Appendix D parametric models (RCC 2001, Weibel-Hansman, Ale-Piers, BC, AWKE) */
#include <math.h>
#include <gsl/gsl_cdf.h>

#include "uasimpact/parametric.h"

/* Table D1 (RCC 2000): a in J and b for head, thorax, abdomen */
static const double rcc_a[3] = {74.8, 59.8, 130.6};
static const double rcc_b[3] = {0.2802, 0.3737, 0.4335};

/* Gennarelli & Wodzin (2006) probability of death per AIS level 0..6, upper ends */
static const double gw_pof[7] = {0.0, 0.0, 0.02, 0.10, 0.50, 0.50, 1.0};

void ur_parametric_defaults(urParametricParams* p) {
  p->width = 1.3;
  p->length = 1.1;
  p->cfit = 0.2;
  p->person_height = 1.73;
  p->person_diameter = 0.2;
  p->slide = 0.40;
  p->body_mass = 77.0;
  p->bc_diameter = 0.03;
  p->awke_w[0] = p->awke_w[1] = p->awke_w[2] = 1.0 / 3.0;
}

double ur_pof_rcc(int part, double energy) {
  if (part < 0 || part > 2 || !(energy > 0)) return 0.0;
  return gsl_cdf_ugaussian_P((log(energy) - log(rcc_a[part])) / rcc_b[part]);
}

double ur_pof_ais(double ais) {
  if (!(ais > 0)) return 0.0;
  if (ais >= 6) return 1.0;
  int k = (int)floor(ais);
  double f = ais - k;
  return gw_pof[k] + f * (gw_pof[k + 1] - gw_pof[k]);
}

int ur_parametric(const urParametricParams* p, double m, double v, double psi_deg,
                  urParametricResult* out) {
  if (!(m > 0 && v >= 0 && psi_deg > 0 && psi_deg <= 90)) return -1;
  double psi = psi_deg * M_PI / 180.0;
  double e = 0.5 * m * v * v;
  out->energy = e;

  /* areas: D.2, Ale-Piers, D.1 (H/tan(psi) is exactly 0 at 90 deg) */
  out->planform = p->width * p->length;
  out->mtow_area = p->cfit * m;
  double glide = psi_deg >= 90.0 ? 0.0 : p->person_height / tan(psi);
  out->gliding =
      (p->width + p->person_diameter) * (glide + p->slide + p->length + p->person_diameter);

  /* RCC per body part; the drone falling on a standing person strikes the head */
  for (int i = 0; i < 3; i++) out->pof_rcc_part[i] = ur_pof_rcc(i, e);
  out->pof_rcc = out->pof_rcc_part[0];

  /* Blunt Criterion on the head (D.4, D.6): masses in kg, lengths in cm */
  double mb = 0.08 * p->body_mass, lb = 1.3, dimp = 100.0 * p->bc_diameter;
  out->bc = log(e / (cbrt(mb) * lb * dimp));
  out->ais_bc = 1.33 * out->bc + 0.6;
  out->pof_bc = ur_pof_ais(out->ais_bc);

  /* AWKE stand-in: weighted mean of the three part curves */
  double ws = p->awke_w[0] + p->awke_w[1] + p->awke_w[2];
  out->pof_awke = 0;
  for (int i = 0; i < 3; i++) out->pof_awke += p->awke_w[i] * out->pof_rcc_part[i];
  out->pof_awke = ws > 0 ? out->pof_awke / ws : 0.0;
  return 0;
}
