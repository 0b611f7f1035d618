/* injury_vc.c: viscous criterion VC = SF V(t) C(t), C = D/D0 as a fraction. */
#include <math.h>

#include "uasimpact/injury.h"

/* derivative at i by the three-point formula on possibly non-uniform samples */
static double deriv3(const double* t, const double* d, int n, int i) {
  // one-sided at the ends (second order), central otherwise
  int k = i == 0 ? 1 : (i == n - 1 ? n - 2 : i);
  double h1 = t[k] - t[k - 1], h2 = t[k + 1] - t[k];
  double d0 = d[k - 1], d1 = d[k], d2 = d[k + 1];
  if (i == k) {
    return (-h2 / (h1 * (h1 + h2))) * d0 + ((h2 - h1) / (h1 * h2)) * d1 +
           (h1 / (h2 * (h1 + h2))) * d2;
  }
  if (i == 0) {
    return (-(2 * h1 + h2) / (h1 * (h1 + h2))) * d0 + ((h1 + h2) / (h1 * h2)) * d1 -
           (h1 / (h2 * (h1 + h2))) * d2;
  }
  return (h2 / (h1 * (h1 + h2))) * d0 - ((h1 + h2) / (h1 * h2)) * d1 +
         ((2 * h2 + h1) / (h2 * (h1 + h2))) * d2;
}

int ur_vc(const double* t, const double* d, int n, double d0, double sf, double* vct, urVc* out) {
  if (!t || !d || !out || n < 3 || !(d0 > 0)) {
    return -1;
  }
  for (int k = 1; k < n; k++) {
    if (!(t[k] > t[k - 1])) {
      return -1;
    }
  }

  // uniform spacing allows the five-point formula
  double h = (t[n - 1] - t[0]) / (n - 1);
  int uniform = n >= 5;
  for (int k = 1; k < n && uniform; k++) {
    if (fabs((t[k] - t[k - 1]) - h) > 1e-6 * h) {
      uniform = 0;
    }
  }

  // VC(t) and its maximum
  out->vc = 0;
  out->t = t[0];
  out->v = out->c = 0;
  out->imax = 0;
  for (int i = 0; i < n; i++) {
    double v;
    if (uniform && i >= 2 && i <= n - 3) {
      v = (8.0 * (d[i + 1] - d[i - 1]) - (d[i + 2] - d[i - 2])) / (12.0 * h);
    } else {
      v = deriv3(t, d, n, i);
    }
    double c = d[i] / d0;
    double vc = sf * v * c;
    if (vct) {
      vct[i] = vc;
    }
    if (vc > out->vc) {
      out->vc = vc;
      out->t = t[i];
      out->v = v;
      out->c = c;
      out->imax = i;
    }
  }
  return 0;
}
