/* quantile.c: sample quantiles, the tail-resolution flag and interval truncation (quantile.h). */
#include <math.h>

#include "uasimpact/quantile.h"

double ur_quantile_sorted(const double* sorted, int n, double p) {
  if (n < 1) return NAN;
  if (p <= 0) return sorted[0];
  if (p >= 1) return sorted[n - 1];
  double h = (n - 1) * p;
  int i = (int)floor(h);
  if (i >= n - 1) return sorted[n - 1];
  return sorted[i] + (h - i) * (sorted[i + 1] - sorted[i]);
}

int ur_quantile_thin(int n, double p) {
  double tail = p < 1 - p ? p : 1 - p;
  return n * tail < urQ_TAILMIN;
}

int ur_interval_clip(double* lo, double* hi, double min, double max) {
  int f = 0;
  if (*lo < min) *lo = min, f |= 1;
  if (*hi > max) *hi = max, f |= 2;
  return f;
}
