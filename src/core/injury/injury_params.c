/* injury_params.c: defaults of the injury settings and their names for `set NAME VALUE`. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "uasimpact/injury.h"

void ur_injury_defaults(urInjuryParams* p) {
  memset(p, 0, sizeof(*p));

  // filtering off: clean simulation output, the paper names no filter
  p->filter = 0;
  p->cfc_head = 1000;
  p->cfc_neck = 600;
  p->cfc_defl = 180;

  // HIC15 with the AIS4+ Prasad-Mertz curve
  p->hic_window = 0.015;
  p->hic_alpha = 4.90;
  p->hic_beta = 0.00351;

  // FMVSS 208 (2000) intercepts, 50th-percentile male; loads taken at the condyle
  p->nij_fzc_tension = 6806;
  p->nij_fzc_compression = 6160;
  p->nij_myc_flexion = 310;
  p->nij_myc_extension = 135;
  p->nij_condyle_d = 0;

  // Eppinger et al. (1999) AIS2+..AIS5+ curves
  const double a[4] = {2.054, 3.227, 2.693, 3.817};
  const double b[4] = {1.195, 1.969, 1.195, 1.195};
  for (int k = 0; k < 4; k++) {
    p->nij_alpha[k] = a[k];
    p->nij_beta[k] = b[k];
  }
  p->nij_rescale = 1;
  p->nij_order = urORDER_LOWER; // chosen by the calibration (uasimpact-model(5))

  // Gennarelli & Wodzin (2006) upper ends of the AIS 2005 ranges, chosen by the refit on
  // materials (uasimpact-model(5), CALIBRATION LOG; the old calibration chose the midpoints)
  p->pof_ais2 = 0.02;
  p->pof_ais3 = 0.10;
  p->pof_ais4 = 0.50;
  p->pof_ais6 = 1.0;

  // VC: human model, HIII-50M chest depth, Lau & Viano 25 % points
  p->vc_sf = 1.0;
  p->vc_d0_thorax = 0.229;
  p->vc_d0_abdomen = 0.2185;
  p->vc25_thorax = 1.0;
  p->vc25_abdomen = 1.2;
  p->vc_beta_thorax = 6.08;
  p->vc_beta_abdomen = 6.08;
  p->vc_pof_thorax = 0.5;
  p->vc_pof_abdomen = 1.0;
  p->vc_rescale = 1;
  p->vc_fuse = urVCFUSE_PRODUCT;

  // peak thorax deflection: off (not in the paper); NHTSA (2008) NCAP HIII-50M AIS3+ curve
  p->use_defl = 0;
  p->defl_alpha = 10.5456;
  p->defl_beta = 1.568;
  p->defl_exp = 0.4612;
  p->defl_pof = 0.09;
}

/* one named setting */
typedef struct {
  const char* name;
  size_t off;
  int isint;     /* 1: int field */
  double lo, hi; /* accepted range, inclusive */
  int open_lo;   /* 1: lo itself is excluded */
  const char* unit;
  const char* help;
} urParamDef;

#define D(f) offsetof(urInjuryParams, f), 0
#define I(f) offsetof(urInjuryParams, f), 1

static const urParamDef kParams[] = {
    {"filter", I(filter), 0, 1, 0, "", "1: CFC-filter channels (SAE J211-1)"},
    {"cfc_head", D(cfc_head), 0, 1e6, 1, "Hz", "head acceleration CFC (J211: 1000)"},
    {"cfc_neck", D(cfc_neck), 0, 1e6, 1, "Hz", "neck load CFC (J211: 600)"},
    {"cfc_defl", D(cfc_defl), 0, 1e6, 1, "Hz", "deflection CFC (ECE R94: 180)"},
    {"hic_window", D(hic_window), 0, 1, 1, "s", "HIC window for PoF (paper: 0.015)"},
    {"hic_alpha", D(hic_alpha), -1e3, 1e3, 0, "", "AIS4+ HIC logistic alpha (Prasad-Mertz)"},
    {"hic_beta", D(hic_beta), 0, 1, 1, "", "AIS4+ HIC logistic beta (Prasad-Mertz)"},
    {"nij_fzc_tension", D(nij_fzc_tension), 0, 1e6, 1, "N", "Fzc tension (FMVSS 208)"},
    {"nij_fzc_compression", D(nij_fzc_compression), 0, 1e6, 1, "N", "Fzc compression (FMVSS 208)"},
    {"nij_myc_flexion", D(nij_myc_flexion), 0, 1e6, 1, "N m", "Myc flexion (FMVSS 208)"},
    {"nij_myc_extension", D(nij_myc_extension), 0, 1e6, 1, "N m", "Myc extension (FMVSS 208)"},
    {"nij_condyle_d", D(nij_condyle_d), -1, 1, 0, "m", "M_OC = My - D Fx (HIII: 0.01778)"},
    {"nij_alpha2", D(nij_alpha[0]), -1e3, 1e3, 0, "", "AIS2+ Nij alpha (Eppinger 1999)"},
    {"nij_alpha3", D(nij_alpha[1]), -1e3, 1e3, 0, "", "AIS3+ Nij alpha (Eppinger 1999)"},
    {"nij_alpha4", D(nij_alpha[2]), -1e3, 1e3, 0, "", "AIS4+ Nij alpha (Eppinger 1999)"},
    {"nij_alpha5", D(nij_alpha[3]), -1e3, 1e3, 0, "", "AIS5+ Nij alpha (Eppinger 1999)"},
    {"nij_beta2", D(nij_beta[0]), 0, 1e3, 1, "", "AIS2+ Nij beta (Eppinger 1999)"},
    {"nij_beta3", D(nij_beta[1]), 0, 1e3, 1, "", "AIS3+ Nij beta (Eppinger 1999)"},
    {"nij_beta4", D(nij_beta[2]), 0, 1e3, 1, "", "AIS4+ Nij beta (Eppinger 1999)"},
    {"nij_beta5", D(nij_beta[3]), 0, 1e3, 1, "", "AIS5+ Nij beta (Eppinger 1999)"},
    {"nij_rescale", I(nij_rescale), 0, 1, 0, "", "1: AIS curves rescaled to 0 at Nij = 0"},
    {"nij_order", I(nij_order), 0, 2, 0, "", "ordering fix: 0 none, 1 raise, 2 lower"},
    {"pof_ais2", D(pof_ais2), 0, 1, 0, "", "P{F|AIS=2} (Gennarelli-Wodzin 2006)"},
    {"pof_ais3", D(pof_ais3), 0, 1, 0, "", "P{F|AIS=3} (Gennarelli-Wodzin 2006)"},
    {"pof_ais4", D(pof_ais4), 0, 1, 0, "", "P{F|AIS=4} (Gennarelli-Wodzin 2006)"},
    {"pof_ais6", D(pof_ais6), 0, 1, 0, "", "P{F|AIS>=5} bound, P{F|AIS=6}"},
    {"vc_sf", D(vc_sf), 0, 100, 1, "", "VC scale factor (human model 1.0)"},
    {"vc_d0_thorax", D(vc_d0_thorax), 0, 10, 1, "m", "thorax depth D0 (J1727 HIII-50M)"},
    {"vc_d0_abdomen", D(vc_d0_abdomen), 0, 10, 1, "m", "abdomen depth D0"},
    {"vc25_thorax", D(vc25_thorax), 0, 100, 1, "m/s", "VC at 25 % AIS4+ thorax (Lau-Viano)"},
    {"vc25_abdomen", D(vc25_abdomen), 0, 100, 1, "m/s", "VC at 25 % AIS5+ abdomen (Lau-Viano)"},
    {"vc_beta_thorax", D(vc_beta_thorax), 0, 1e3, 1, "s/m", "thorax VC logistic slope"},
    {"vc_beta_abdomen", D(vc_beta_abdomen), 0, 1e3, 1, "s/m", "abdomen VC logistic slope"},
    {"vc_pof_thorax", D(vc_pof_thorax), 0, 1, 0, "", "P{F|thorax AIS4+} (G-W AIS 4)"},
    {"vc_pof_abdomen", D(vc_pof_abdomen), 0, 1, 0, "", "P{F|abdomen AIS5+} (G-W AIS 6)"},
    {"vc_rescale", I(vc_rescale), 0, 1, 0, "", "1: VC curves rescaled to 0 at VC = 0"},
    {"vc_fuse", I(vc_fuse), 0, 1, 0, "", "thorax+abdomen: 0 1-(1-Pt)(1-Pa), 1 max"},
    {"use_defl", I(use_defl), 0, 1, 0, "", "1: peak thorax deflection enters the fusion"},
    {"defl_alpha", D(defl_alpha), -1e3, 1e3, 0, "", "AIS3+ deflection alpha (NHTSA 2008)"},
    {"defl_beta", D(defl_beta), 0, 1e3, 1, "", "AIS3+ deflection beta, per mm^exp (NHTSA 2008)"},
    {"defl_exp", D(defl_exp), 0, 10, 1, "", "AIS3+ deflection exponent (NHTSA 2008)"},
    {"defl_pof", D(defl_pof), 0, 1, 0, "", "P{F|thorax AIS3+} (G-W AIS 3)"},
};

#undef D
#undef I

#define NPARAM ((int)(sizeof(kParams) / sizeof(kParams[0])))

/* index of a name, -1 if unknown */
static int find(const char* name) {
  for (int i = 0; name && i < NPARAM; i++) {
    if (!strcmp(kParams[i].name, name)) {
      return i;
    }
  }
  return -1;
}

int ur_injury_param_set(urInjuryParams* p, const char* name, double value) {
  int i = find(name);
  if (i < 0) {
    return -1;
  }

  // range and integrality
  const urParamDef* d = kParams + i;
  if (!isfinite(value) || value < d->lo || value > d->hi || (d->open_lo && value <= d->lo)) {
    return -2;
  }
  if (d->isint && value != floor(value)) {
    return -2;
  }

  // store
  char* base = (char*)p + d->off;
  if (d->isint) {
    *(int*)base = (int)value;
  } else {
    *(double*)base = value;
  }
  return 0;
}

int ur_injury_param_get(const urInjuryParams* p, const char* name, double* value) {
  int i = find(name);
  if (i < 0) {
    return -1;
  }
  const char* base = (const char*)p + kParams[i].off;
  *value = kParams[i].isint ? (double)*(const int*)base : *(const double*)base;
  return 0;
}

int ur_injury_param_count(void) {
  return NPARAM;
}

int ur_injury_param_info(int i, const char** name, const char** unit, const char** help) {
  if (i < 0 || i >= NPARAM) {
    return -1;
  }
  if (name) {
    *name = kParams[i].name;
  }
  if (unit) {
    *unit = kParams[i].unit;
  }
  if (help) {
    *help = kParams[i].help;
  }
  return 0;
}

int ur_injury_param_range(int i, double* lo, double* hi, int* open_lo, int* isint) {
  if (i < 0 || i >= NPARAM) {
    return -1;
  }
  *lo = kParams[i].lo;
  *hi = kParams[i].hi;
  *open_lo = kParams[i].open_lo;
  *isint = kParams[i].isint;
  return 0;
}
