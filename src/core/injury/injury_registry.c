/* injury_registry.c: the table of injury criteria and their value columns (injury_registry.h),
 * and each criterion's compute function: the glue from conditioned channels to the criterion
 * functions (ur_hic, ur_nij, ur_vc, ...) and their PoF curves. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "uasimpact/injury.h"

/* ---- compute functions: values and PoF of one criterion from conditioned channels ---- */

/* HIC15 (HIC36 unless skipped, and HIC with hic_window for P_HIC) from the resultant head
   acceleration in g; work: n doubles for it, then the HIC work space */
static int crit_hic(const urInjuryInput* in, const urInjuryParams* p, double* work,
                    urInjuryResult* out) {
  const double* const* ha = in->head_acc;
  int n = in->n;
  if (!ha[0]) return 0;
  double* ag = work;
  for (int i = 0; i < n; i++) {
    double s = ha[0][i] * ha[0][i];
    s += ha[1] ? ha[1][i] * ha[1][i] : 0.0;
    s += ha[2] ? ha[2][i] * ha[2][i] : 0.0;
    ag[i] = (ha[1] || ha[2] ? sqrt(s) : ha[0][i]) / urGRAVITY;
  }
  double* hw = work + n;
  if (ur_hic(in->t, ag, n, 0.015, hw, &out->hic15) ||
      (!in->skip_hic36 && ur_hic(in->t, ag, n, 0.036, hw, &out->hic36)) ||
      (p->hic_window == 0.015 ? (out->hic = out->hic15, 0)
                              : ur_hic(in->t, ag, n, p->hic_window, hw, &out->hic))) {
    return -1;
  }
  out->val[urVAL_HIC15] = out->hic15.hic;
  out->val[urVAL_HIC_T1] = out->hic15.t1;
  out->val[urVAL_HIC_T2] = out->hic15.t2;
  out->pof[urCRIT_HIC] = ur_pof_hic(out->hic.hic, p);
  return 0;
}

/* Nij from the upper-neck axial force and moment (shear for the condyle offset if given) */
static int crit_nij(const urInjuryInput* in, const urInjuryParams* p, double* work,
                    urInjuryResult* out) {
  (void)work;
  if (!in->neck_fz || !in->neck_my) return 0;
  if (ur_nij(in->neck_fz, in->neck_my, in->neck_fx, in->n, p, &out->nij)) return -1;
  out->val[urVAL_NIJ] = out->nij.nij;
  out->val[urVAL_NIJ_MODE] = out->nij.which;
  for (int k = 0; k < 4; k++) out->val[urVAL_NIJ_TF + k] = out->nij.mode[k];
  out->pof[urCRIT_NIJ] = ur_pof_nij(out->nij.nij, p);
  return 0;
}

/* VC of thorax and abdomen from their deflections, fused by vc_fuse */
static int crit_vc(const urInjuryInput* in, const urInjuryParams* p, double* work,
                   urInjuryResult* out) {
  (void)work;
  if (in->thorax_d) {
    if (ur_vc(in->t, in->thorax_d, in->n, p->vc_d0_thorax, p->vc_sf, NULL, &out->vc_thorax)) {
      return -1;
    }
    out->p_vc_thorax = ur_pof_vc(out->vc_thorax.vc, urTHORAX, p);
  }
  if (in->abdomen_d) {
    if (ur_vc(in->t, in->abdomen_d, in->n, p->vc_d0_abdomen, p->vc_sf, NULL, &out->vc_abdomen)) {
      return -1;
    }
    out->p_vc_abdomen = ur_pof_vc(out->vc_abdomen.vc, urABDOMEN, p);
  }
  out->val[urVAL_VC_THORAX] = out->vc_thorax.vc;
  out->val[urVAL_VC_ABDOMEN] = out->vc_abdomen.vc;
  out->pof[urCRIT_VC] = ur_pof_vc_fuse(out->p_vc_thorax, out->p_vc_abdomen, p);
  return 0;
}

/* peak thorax deflection (compression > 0; 0 if the chest never compresses) */
static int crit_defl(const urInjuryInput* in, const urInjuryParams* p, double* work,
                     urInjuryResult* out) {
  (void)work;
  if (!in->thorax_d) return 0;
  double dmax = 0;
  for (int i = 0; i < in->n; i++) dmax = fmax(dmax, in->thorax_d[i]);
  out->val[urVAL_DEFL_THORAX] = dmax;
  out->pof[urCRIT_DEFL] = ur_pof_defl(dmax, p);
  return 0;
}

/* ---- PoF of a criterion from stored values ---- */

static double pof_hic(const double* val, const urInjuryParams* p) {
  return ur_pof_hic(val[urVAL_HIC15], p);
}

static double pof_nij(const double* val, const urInjuryParams* p) {
  return ur_pof_nij(val[urVAL_NIJ], p);
}

static double pof_vc(const double* val, const urInjuryParams* p) {
  return ur_pof_vc_fuse(ur_pof_vc(val[urVAL_VC_THORAX], urTHORAX, p),
                        ur_pof_vc(val[urVAL_VC_ABDOMEN], urABDOMEN, p), p);
}

static double pof_defl(const double* val, const urInjuryParams* p) {
  return ur_pof_defl(val[urVAL_DEFL_THORAX], p);
}

/* ---- the tables ---- */

static const char* const kNijModes[] = {"NTF", "NTE", "NCF", "NCE"};

#define ALL (urIN_ROW | urIN_CELL | urIN_LOAD | urIN_PANEL | urIN_CURSOR)

static const urValueDef kValues[urNVAL] = {
    [urVAL_HIC15] = {"hic15", "", urCRIT_HIC, ALL, "", "%.1f", 1, "", NULL, 0},
    [urVAL_HIC_T1] = {"hic_t1", "s", urCRIT_HIC, urIN_LOAD | urIN_PANEL, "window", "%.2f", 1e3,
                      "ms", NULL, 0},
    [urVAL_HIC_T2] = {"hic_t2", "s", urCRIT_HIC, urIN_LOAD | urIN_PANEL, "to", "%.2f", 1e3, "ms",
                      NULL, 0},
    [urVAL_NIJ] = {"nij", "", urCRIT_NIJ, ALL, "", "%.3f", 1, "", NULL, 0},
    [urVAL_NIJ_MODE] = {"nij_mode", "", urCRIT_NIJ, urIN_LOAD | urIN_PANEL | urIN_CURSOR, "mode",
                        "%.0f", 1, "", kNijModes, 4},
    [urVAL_NIJ_TF] = {"nij_tf", "", urCRIT_NIJ, urIN_ROW, "tf", "%.3f", 1, "", NULL, 0},
    [urVAL_NIJ_TE] = {"nij_te", "", urCRIT_NIJ, urIN_ROW, "te", "%.3f", 1, "", NULL, 0},
    [urVAL_NIJ_CF] = {"nij_cf", "", urCRIT_NIJ, urIN_ROW, "cf", "%.3f", 1, "", NULL, 0},
    [urVAL_NIJ_CE] = {"nij_ce", "", urCRIT_NIJ, urIN_ROW, "ce", "%.3f", 1, "", NULL, 0},
    [urVAL_VC_THORAX] = {"vc_thorax", "m/s", urCRIT_VC, ALL, "thorax", "%.3f", 1, "m/s", NULL, 0},
    [urVAL_VC_ABDOMEN] = {"vc_abdomen", "m/s", urCRIT_VC, ALL, "abdomen", "%.3f", 1, "m/s", NULL,
                          0},
    [urVAL_DEFL_THORAX] = {"defl_thorax", "m", urCRIT_DEFL, ALL, "thorax", "%.1f", 1e3, "mm", NULL,
                           0},
};

#undef ALL

static const urCriterion kCriteria[urNCRIT] = {
    [urCRIT_HIC] = {"hic", "p_hic", "HIC15", "head_acc", urVAL_HIC15, 3, NULL, 0, 1, crit_hic,
                    pof_hic},
    [urCRIT_NIJ] = {"nij", "p_nij", "Nij", "neck_fz neck_my [neck_fx]", urVAL_NIJ, 6, NULL, 0, 1,
                    crit_nij, pof_nij},
    [urCRIT_VC] = {"vc", "p_vc", "VC", "thorax_d abdomen_d", urVAL_VC_THORAX, 2, NULL, 0, 1,
                   crit_vc, pof_vc},
    [urCRIT_DEFL] = {"defl", "p_defl", "Dmax", "thorax_d", urVAL_DEFL_THORAX, 1, "use_defl",
                     offsetof(urInjuryParams, use_defl), 0, crit_defl, pof_defl},
};

const urCriterion* ur_criterion(int k) {
  return k >= 0 && k < urNCRIT ? &kCriteria[k] : NULL;
}

const urValueDef* ur_value_def(int v) {
  return v >= 0 && v < urNVAL ? &kValues[v] : NULL;
}

int ur_criterion_find(const char* name) {
  for (int k = 0; name && k < urNCRIT; k++) {
    if (!strcmp(kCriteria[k].name, name)) return k;
  }
  return -1;
}

int ur_criterion_used(int k, const urInjuryParams* p) {
  const urCriterion* c = ur_criterion(k);
  if (!c) return 0;
  if (!c->use) return 1;
  return *(const int*)((const char*)p + c->use_off) != 0; /* per cell in the calibration */
}

int ur_value_shown(int v, int where, const urInjuryParams* p) {
  const urValueDef* d = ur_value_def(v);
  return d && (d->where & where) && ur_criterion_used(d->crit, p);
}

void ur_value_format(int v, double x, char* buf, unsigned n) {
  const urValueDef* d = ur_value_def(v);
  if (!d || !isfinite(x) || (d->names && (x != floor(x) || x < 0 || x >= d->nnames))) {
    snprintf(buf, n, "-");
  } else if (d->names) {
    snprintf(buf, n, "%s", d->names[(int)x]);
  } else {
    snprintf(buf, n, d->fmt, x * d->scale);
  }
}

double ur_pof_fuse_used(const double pof[urNCRIT], const urInjuryParams* p) {
  // (3.1), independent criteria; 1 - (1 - a)(1 - b)(1 - c) in the same order of operations
  double q = 1.0;
  for (int k = 0; k < urNCRIT; k++) {
    if (ur_criterion_used(k, p)) q *= 1.0 - pof[k];
  }
  return 1.0 - q;
}
