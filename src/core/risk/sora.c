/* sora.c: the SORA 2.5 Annex F critical area and the iGRC (sora.h). Written from the formulas
 * of casex (JARUS-QM/casex 2ccfd10) as documented in uasimpact(1), SORA FIGURES; the tests hold
 * casex's own values. */
#include <math.h>

#include "uasimpact/sora.h"

void ur_annexf_defaults(urAnnexFIn* in, double mass, double width, double speed, double angle) {
  in->mass = mass;
  in->width = width;
  in->speed = speed;
  in->angle = angle;
  in->mu = 0.65;
  in->cor = NAN;
  in->ke_lethal = -1;
  in->obstacles = 1;
  in->person_radius = 0.3;
  in->person_height = 1.8;
  in->g = 9.81;
}

double ur_annexf_cor(double angle) {
  return 0.825 - 0.0025 * angle;
}

void ur_annexf_ca(const urAnnexFIn* in, urAnnexFOut* out) {
  double w = in->width, rp = in->person_radius, deg = M_PI / 180.0;
  double cor = isnan(in->cor) ? ur_annexf_cor(in->angle) : in->cor;

  /* lethal energy: 290 J by default; a negative value takes the rule (doubled for w <= 1 m) */
  double ke = in->ke_lethal == -1 ? 290.0 : fabs(in->ke_lethal);
  if (in->ke_lethal < 0 && w <= 1) ke *= 2;

  /* glide: the person's height crossed at the impact angle (an angle beyond 90 deg mirrored) */
  double vh = fabs(cos(in->angle * deg)) * in->speed;
  double glide_angle = in->angle > 90 ? 180 - in->angle : in->angle;
  double dg = in->person_height / tan(glide_angle * deg);

  /* slide: from CoR vh down to the speed of lethal energy under friction */
  double vmin = sqrt(2 * ke / in->mass), a = in->mu * in->g;
  double ts = (cor * vh - vmin) / a;
  if (ts < 0) ts = 0;
  double ds = cor * vh * ts - 0.5 * a * ts * ts;

  double half = M_PI * (rp + w / 2) * (rp + w / 2) / 2;
  double ag = 2 * (rp + w / 2) * dg + half, as = ds * (2 * rp + w) + half;
  if (w <= 1) {
    as = 0;
    ds = 0;
  }
  double f = in->obstacles && w > 1 && w < 40 ? 0.6 : 1.0;
  out->a_glide = ag * f;
  out->a_slide = as * f;
  out->d_glide = dg * f;
  out->d_slide = ds;
  out->v_min = vmin;
  out->t_safe = ts;
  out->ca = out->a_glide + out->a_slide;
}

int ur_igrc(double density, double ca, double tlos, double compensation, double* raw, double* raw1,
            int* igrc, int* igrc_table) {
  if (!(density > 0) || !(ca > 0) || !(tlos > 0)) return -1;
  double r = 1 - log10(tlos / ((density * 1e-6) * ca)) - compensation;
  /* to one decimal, ties to even (nearbyint in the default rounding mode, as Python's round) */
  double r1 = nearbyint(r * 10) / 10;
  *raw = r;
  *raw1 = r1;
  *igrc = (int)ceil(r1);
  *igrc_table = (int)nearbyint(r1 - 0.1);
  return 0;
}

int ur_igrc_clamp(int* igrc) {
  if (*igrc < urIGRC_TABLE_MIN) {
    *igrc = urIGRC_TABLE_MIN;
    return -1;
  }
  if (*igrc > urIGRC_TABLE_MAX) {
    *igrc = urIGRC_TABLE_MAX;
    return 1;
  }
  return 0;
}
