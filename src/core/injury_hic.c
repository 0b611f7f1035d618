/* injury_hic.c: Head Injury Criterion, exact maximum over sample pairs (O(N W)). */
#include <math.h>
#include <stdlib.h>

#include "uasrisk/injury.h"

int ur_hic(const double* t, const double* a, int n, double window, double* work, urHic* out)
{
  if (!t || !a || !out || n < 1 || !(window > 0)) {
    return -1;
  }
  out->hic = 0;
  out->t1 = out->t2 = t[0];
  out->i1 = out->i2 = 0;

  // times must ascend
  for (int k = 1; k < n; k++) {
    if (!(t[k] > t[k - 1])) {
      return -1;
    }
  }

  // caller workspace or one allocation
  double* v = work;
  if (!v) {
    v = malloc((size_t)n * sizeof(double));
    if (!v) {
      return -2;
    }
  }

  // cumulative trapezoid integral of a, g s
  v[0] = 0;
  for (int k = 1; k < n; k++) {
    v[k] = v[k - 1] + 0.5 * (a[k] + a[k - 1]) * (t[k] - t[k - 1]);
  }

  // scan every window start and every end within the window length
  double wmax = window * (1.0 + 1e-9);
  double best = 0;
  int b1 = 0, b2 = 0;
  for (int i = 0; i < n - 1; i++) {
    for (int j = i + 1; j < n && t[j] - t[i] <= wmax; j++) {
      double dv = v[j] - v[i];
      if (dv <= 0) {
        continue;
      }
      double dt = t[j] - t[i];
      double h = dv * dv * sqrt(dv) / (dt * sqrt(dt));
      if (h > best) {
        best = h;
        b1 = i;
        b2 = j;
      }
    }
  }

  // report the best pair
  out->hic = best;
  out->i1 = b1;
  out->i2 = b2;
  out->t1 = t[b1];
  out->t2 = t[b2];
  if (!work) {
    free(v);
  }
  return 0;
}
