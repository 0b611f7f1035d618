/* contact_material.c: the closed forms that turn materials and sections into laws (material.h):
 * section properties, a beam's hinge law, the Hertz effective modulus of two materials and the
 * local stiffness and crush load of a thin shell. Sources: materials-membrane sheet E.1, E.2,
 * E.3, E.5; EN 1993-1-5 Annex C.6 (hardening slope E/100 when the material gives no ultimate
 * point); Hopkins & Prager 1953 and Jones, Structural Impact ch. 2 (a plate's collapse load under
 * a point load, 2 pi M0).
 */
#include <math.h>

#include "uasimpact/material.h"

int ur_section_props(const urSection* s, urSectionProps* out) {
  // round sections: tube (d = D - 2t) and solid bar (d = 0), sheet E.1
  if (s->type == urSEC_TUBE || s->type == urSEC_SOLID) {
    double D = s->D, d = s->type == urSEC_TUBE ? s->D - 2 * s->t : 0;
    if (!(D > 0) || !(d >= 0) || (s->type == urSEC_TUBE && !(s->t > 0 && d > 0))) return -1;
    out->A = M_PI * (D * D - d * d) / 4;
    out->I = M_PI * (D * D * D * D - d * d * d * d) / 64;
    out->Ze = 2 * out->I / D;
    out->Zp = (D * D * D - d * d * d) / 6;
    return 0;
  }

  // rectangular plate bent about its width
  if (s->type == urSEC_PLATE) {
    if (!(s->t > 0 && s->b > 0)) return -1;
    out->A = s->b * s->t;
    out->I = s->b * s->t * s->t * s->t / 12;
    out->Ze = 2 * out->I / s->t;
    out->Zp = s->b * s->t * s->t / 4;
    return 0;
  }

  // rectangular tube bent about its width
  if (s->type == urSEC_BOX) {
    double bi = s->b - 2 * s->t, hi = s->h - 2 * s->t;
    if (!(s->t > 0 && bi > 0 && hi > 0)) return -1;
    out->A = s->b * s->h - bi * hi;
    out->I = (s->b * s->h * s->h * s->h - bi * hi * hi * hi) / 12;
    out->Ze = 2 * out->I / s->h;
    out->Zp = (s->b * s->h * s->h - bi * hi * hi) / 4;
    return 0;
  }
  return -1;
}

int ur_hinge_from_beam(const urMaterial* mat, const urSection* sec, double L, urHinge* out) {
  urSectionProps sp;
  if (!(L > 0) || !(mat->E > 0) || !(mat->sy > 0) || ur_section_props(sec, &sp)) return -1;

  // elastic slope of the tip-loaded cantilever as M = F L, theta = d/L (sheet E.2)
  out->k = 3 * mat->E * sp.I / L;
  out->mp = mat->sy * sp.Zp;

  // bilinear hardening through yield and ultimate, else E/100 (EN 1993-1-5 C.6)
  double ey = mat->sy / mat->E, et = mat->E / 100;
  if (mat->su > mat->sy && mat->ef > ey) et = (mat->su - mat->sy) / (mat->ef - ey);
  out->kh = out->k * et / mat->E;

  // fracture: the fully plastic section at the ultimate stress, or linear to the fracture strain
  out->mu = mat->su > 0 ? mat->su * sp.Zp : mat->ef > 0 ? mat->E * mat->ef * sp.Ze : 0;
  return 0;
}

double ur_hertz_estar(const urMaterial* a, const urMaterial* b) {
  // sheet E.5
  return 1.0 / ((1 - a->nu * a->nu) / a->E + (1 - b->nu * b->nu) / b->E);
}

double ur_foam_abi(const double p[5], double e) {
  // elastic-plateau term and densification term (Avalle, Belingardi & Ibba 2007)
  double A = p[0], E = p[1], m = p[2], B = p[3], n = p[4];
  return A * (1 - exp(-(E / A) * e * pow(1 - e, m))) + B * pow(e / (1 - e), n);
}

double ur_shell_stiffness(const urMaterial* mat, const urSection* sec) {
  // Reissner's shallow spherical shell under a point load (sheet E.3)
  if (sec->type != urSEC_SHELL || !(sec->t > 0 && sec->R > 0)) return 0;
  return 4 * mat->E * sec->t * sec->t / (sec->R * sqrt(3 * (1 - mat->nu * mat->nu)));
}

double ur_shell_crush_force(const urMaterial* mat, const urSection* sec) {
  // 2 pi M0, M0 = sy t^2 / 4: the rigid-plastic plate under a point load (Hopkins & Prager)
  if (sec->type != urSEC_SHELL || !(sec->t > 0) || !(mat->sy > 0)) return 0;
  return M_PI * mat->sy * sec->t * sec->t / 2;
}

double ur_shell_crush_depth(const urSection* sec) {
  // the declared depth to the contents, else the whole radius
  return sec->h > 0 ? sec->h : sec->R;
}


double ur_layer_foundation(const urMaterial* mat, double h) {
  double nu = mat->nu;
  if (!(h > 0) || !(nu >= 0 && nu < 0.5) || !(mat->E > 0)) {
    return 0;
  }
  return mat->E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / h;
}
