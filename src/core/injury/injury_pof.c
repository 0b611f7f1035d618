/* injury_pof.c: injury criterion -> probability of fatality curves (paper Appendix C) and the
 * fusion (3.1). */
#include <math.h>

#include <gsl/gsl_cdf.h>

#include "uasimpact/injury.h"

/* logistic 1 / (1 + exp(alpha - beta x)) */
static double logistic(double alpha, double beta, double x) {
  return gsl_cdf_logistic_P(beta * x - alpha, 1.0);
}

double ur_pof_hic(double hic, const urInjuryParams* p) {
  // P(AIS4+) = 1 / (1 + exp(alpha + 200/HIC - beta HIC)), zero limit at HIC -> 0
  if (!(hic > 0)) {
    return 0;
  }
  return gsl_cdf_logistic_P(p->hic_beta * hic - p->hic_alpha - 200.0 / hic, 1.0);
}

void ur_nij_ais(double nij, const urInjuryParams* p, double q[4]) {
  // raw Eppinger curves, optionally rescaled to 0 at Nij = 0
  for (int k = 0; k < 4; k++) {
    double a = p->nij_alpha[k], b = p->nij_beta[k];
    double raw = logistic(a, b, nij);
    if (p->nij_rescale) {
      double q0 = logistic(a, b, 0.0);
      raw = nij > 0 ? (raw - q0) / (1.0 - q0) : 0.0;
    }
    q[k] = raw;
  }

  // ordering P(>= k) >= P(>= k+1), top-down for k = 4, 3, 2
  if (p->nij_order == urORDER_RAISE) {
    for (int k = 2; k >= 0; k--) {
      q[k] = fmax(q[k], q[k + 1]);
    }
  } else if (p->nij_order == urORDER_LOWER) {
    for (int k = 1; k < 4; k++) {
      q[k] = fmin(q[k], q[k - 1]);
    }
  }
}

double ur_pof_nij(double nij, const urInjuryParams* p) {
  // P{F|0} = 0 by the paper's condition (i)
  if (!(nij > 0)) {
    return 0;
  }

  // (C.3): sum of P{F|AIS=k} P{AIS=k|N} plus P{F|AIS=6} P{AIS>=5|N}
  double q[4];
  ur_nij_ais(nij, p, q);
  return p->pof_ais2 * (q[0] - q[1]) + p->pof_ais3 * (q[1] - q[2]) + p->pof_ais4 * (q[2] - q[3]) +
         p->pof_ais6 * q[3];
}

double ur_pof_vc(double vc, urRegion region, const urInjuryParams* p) {
  if (!(vc > 0)) {
    return 0;
  }

  // region logistic through its 25 % point: alpha = ln 3 + beta VC25
  double vc25 = region == urABDOMEN ? p->vc25_abdomen : p->vc25_thorax;
  double beta = region == urABDOMEN ? p->vc_beta_abdomen : p->vc_beta_thorax;
  double f = region == urABDOMEN ? p->vc_pof_abdomen : p->vc_pof_thorax;
  double alpha = log(3.0) + beta * vc25;
  double q = logistic(alpha, beta, vc);

  // rescale to 0 at VC = 0, then (C.5) with the AIS -> PoF factor
  if (p->vc_rescale) {
    double q0 = logistic(alpha, beta, 0.0);
    q = (q - q0) / (1.0 - q0);
  }
  return f * q;
}

double ur_pof_vc_fuse(double p_thorax, double p_abdomen, const urInjuryParams* p) {
  if (p->vc_fuse == urVCFUSE_MAX) {
    return fmax(p_thorax, p_abdomen);
  }
  return 1.0 - (1.0 - p_thorax) * (1.0 - p_abdomen);
}

double ur_pof_defl(double d, const urInjuryParams* p) {
  if (!(d > 0)) {
    return 0;
  }

  // AIS3+ 1 / (1 + exp(alpha - beta D^e)), D in mm, rescaled to 0 at D = 0, times P{F|AIS3+}
  double q = logistic(p->defl_alpha, p->defl_beta, pow(1e3 * d, p->defl_exp));
  double q0 = logistic(p->defl_alpha, p->defl_beta, 0.0);
  return p->defl_pof * (q - q0) / (1.0 - q0);
}

double ur_pof_fuse(double p_hic, double p_nij, double p_vc) {
  // (3.1), independent criteria
  return 1.0 - (1.0 - p_hic) * (1.0 - p_nij) * (1.0 - p_vc);
}

/* one point of a curve */
static double curve_eval(urPofKind kind, const urInjuryParams* p, double x) {
  switch (kind) {
  case urPOF_HIC: return ur_pof_hic(x, p);
  case urPOF_NIJ: return ur_pof_nij(x, p);
  case urPOF_VC: return ur_pof_vc_fuse(ur_pof_vc(x, urTHORAX, p), ur_pof_vc(x, urABDOMEN, p), p);
  case urPOF_VC_THORAX: return ur_pof_vc(x, urTHORAX, p);
  case urPOF_VC_ABDOMEN: return ur_pof_vc(x, urABDOMEN, p);
  case urPOF_DEFL: return ur_pof_defl(x, p);
  }
  return 0;
}

int ur_pof_curve(urPofKind kind, const urInjuryParams* p, int n, double* x, double* prob) {
  if (!p || !x || !prob || n < 2 || (int)kind < 0 || (int)kind > (int)urPOF_DEFL) {
    return -1;
  }

  // start value and a point far out for the curve's upper limit
  double x0 = kind == urPOF_HIC ? 500.0 : kind == urPOF_NIJ ? 1.0 : 0.5;
  if (kind == urPOF_DEFL) {
    x0 = 0.05;
  }
  double sup = curve_eval(kind, p, x0 * 1e4);

  // grow the range until the curve reaches 99.5 % of its limit
  double xmax = x0;
  for (int it = 0; it < 400 && sup > 0 && curve_eval(kind, p, xmax) < 0.995 * sup; it++) {
    xmax *= 1.1;
  }

  // round the end up to two significant digits
  double e = pow(10.0, floor(log10(xmax)) - 1.0);
  xmax = ceil(xmax / e - 1e-9) * e;

  // equally spaced points from 0
  for (int i = 0; i < n; i++) {
    x[i] = xmax * i / (n - 1);
    prob[i] = curve_eval(kind, p, x[i]);
  }
  return n;
}
