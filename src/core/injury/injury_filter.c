/* injury_filter.c: SAE J211-1 Appendix C channel frequency class (CFC) filter, run forward and
 * backward for zero phase. */
#include <math.h>

#include "uasimpact/injury.h"

/* J211 digital filter coefficients: y = a0 x + a1 x1 + a2 x2 + b1 y1 + b2 y2 */
typedef struct {
  double a0, a1, a2, b1, b2;
} urCfcCoef;

static int cfc_coef(double cfc, double dt, urCfcCoef* c) {
  // the analogue cut-off of one pass is 2.0775 CFC; prewarp with the step
  double wd = 2.0 * M_PI * cfc * 2.0775;
  double arg = wd * dt / 2.0;
  if (!(cfc > 0) || !(dt > 0) || !(arg < 0.5 * M_PI)) {
    return -1;
  }
  double wa = tan(arg);
  double den = 1.0 + M_SQRT2 * wa + wa * wa;

  // second-order Butterworth section by the bilinear transform
  c->a0 = wa * wa / den;
  c->a1 = 2.0 * c->a0;
  c->a2 = c->a0;
  c->b1 = -2.0 * (wa * wa - 1.0) / den;
  c->b2 = (-1.0 + M_SQRT2 * wa - wa * wa) / den;
  return 0;
}

int ur_cfc_filter(const double* x, int n, double dt, double cfc, double* y) {
  urCfcCoef c;
  if (!x || !y || n < 1 || cfc_coef(cfc, dt, &c)) {
    return -1;
  }

  // forward pass, started in steady state on the first sample
  double x1 = x[0], x2 = x[0], y1 = x[0], y2 = x[0];
  for (int i = 0; i < n; i++) {
    double xi = x[i];
    double yi = c.a0 * xi + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = xi;
    y2 = y1;
    y1 = yi;
    y[i] = yi;
  }

  // backward pass in place, started in steady state on the last forward output
  x1 = x2 = y1 = y2 = y[n - 1];
  for (int i = n - 1; i >= 0; i--) {
    double xi = y[i];
    double yi = c.a0 * xi + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = xi;
    y2 = y1;
    y1 = yi;
    y[i] = yi;
  }
  return 0;
}

double ur_cfc_gain(double cfc, double dt, double f) {
  urCfcCoef c;
  if (cfc_coef(cfc, dt, &c) || f < 0 || !(f * dt < 0.5)) {
    return -1;
  }

  // |H|^2 of one Butterworth pass is the amplitude gain of the double pass
  double wa = tan(M_PI * cfc * 2.0775 * dt);
  double r = tan(M_PI * f * dt) / wa;
  double r2 = r * r;
  return 1.0 / (1.0 + r2 * r2);
}
