/* injury_hic.c: Head Injury Criterion, exact maximum over sample pairs.
 *
 * HIC(i, j) = (t_j - t_i) * (mean a over [t_i, t_j])^2.5 with the cumulative trapezoid integral.
 * Every start i is bounded from above by V_i * amax_i^1.5 (and w_i * amax_i^2.5), where amax_i
 * is the largest sample in [t_i, t_i + window], V_i the largest rise of the integral over that
 * window and w_i the longest admissible window from i (a trapezoid mean never exceeds the
 * largest sample). Starts are taken in decreasing bound from a binary heap and the
 * scan stops when the bound cannot beat the best pair found: the same maximum as the O(N W)
 * scan of every pair, usually after a few starts around the peak. Ties go to the smallest
 * (i, j), as in the plain scan; the order among starts of equal bound does not matter, since a
 * start left unscanned has a bound, and so a HIC, strictly below the best. */
#include <math.h>
#include <stdlib.h>

#include "uasimpact/injury.h"

typedef struct {
  double bound, am, vm;
  int i;
} hicStart;

/* max-heap of starts by bound (ties: smaller i first) */
static int above(const hicStart* a, const hicStart* b) {
  return a->bound > b->bound || (a->bound == b->bound && a->i < b->i);
}

static void sift_down(hicStart* h, int n, int k) {
  for (;;) {
    int c = 2 * k + 1;
    if (c >= n) {
      return;
    }
    if (c + 1 < n && above(&h[c + 1], &h[c])) {
      c++;
    }
    if (!above(&h[c], &h[k])) {
      return;
    }
    hicStart t = h[k];
    h[k] = h[c];
    h[c] = t;
    k = c;
  }
}

/* the first k > i whose window is long enough to beat best2 (!(am5 dt^2 < best2)), n if none:
   dt = t_k - t_i and am5 dt dt rise with k (rounding is monotone), so the windows too short
   form a prefix, found by bisection; the scan below would skip each of them (and break at none
   before the first long one, its break test rising with k too), so it starts there instead */
static int first_long(const double* t, int n, int i, double am5, double best2) {
  int lo = i + 1, hi = n;
  while (lo < hi) {
    int mid = lo + (hi - lo) / 2;
    double dt = t[mid] - t[i];
    if (am5 * dt * dt < best2) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

int ur_hic(const double* t, const double* a, int n, double window, double* work, urHic* out) {
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

  // caller workspace or one allocation: n doubles of integral, n starts, n deque indices
  double* v = work;
  if (!v) {
    v = malloc((size_t)ur_hic_work_size(n) * sizeof(double));
    if (!v) {
      return -2;
    }
  }
  hicStart* st = (hicStart*)(v + n);
  int* dq = (int*)(st + n);
  int* qv = dq + n;

  // cumulative trapezoid integral of a, g s
  v[0] = 0;
  for (int k = 1; k < n; k++) {
    v[k] = v[k - 1] + 0.5 * (a[k] + a[k - 1]) * (t[k] - t[k - 1]);
  }

  // bound of every start i from the sliding maxima over its window (monotone deques) of a and
  // of v: with dv = v_j - v_i <= V_i = max v_j - v_i and dv/dt <= a_max, HIC = dv (dv/dt)^1.5
  // <= V_i a_max^1.5 (<= w a_max^2.5); a relative margin covers the rounding of the bound
  double wmax = window * (1.0 + 1e-9);
  int ns = 0, head = 0, tail = 0, vhead = 0, vtail = 0, j = 0;
  for (int i = 0; i < n - 1; i++) {
    while (j < n && t[j] - t[i] <= wmax) {
      while (tail > head && a[dq[tail - 1]] <= a[j]) {
        tail--;
      }
      dq[tail++] = j;
      while (vtail > vhead && v[qv[vtail - 1]] <= v[j]) {
        vtail--;
      }
      qv[vtail++] = j++;
    }
    while (dq[head] < i) {
      head++;
    }
    while (qv[vhead] < i) {
      vhead++;
    }
    double am = a[dq[head]], vm = v[qv[vhead]] - v[i];
    if (j - 1 > i && am > 0 && vm > 0) {
      double w = t[j - 1] - t[i];
      st[ns].bound = fmin(w * am * am * sqrt(am), vm * am * sqrt(am)) * (1 + 1e-9);
      st[ns].am = am;
      st[ns].vm = vm;
      st[ns].i = i;
      ns++;
    }
  }
  for (int k = ns / 2 - 1; k >= 0; k--) {
    sift_down(st, ns, k);
  }

  // exact scan of the starts whose bound can still beat the best pair, largest bound first;
  // pairs are compared by HIC^2 = dv^5 / dt^3 (same order, no roots), the value is taken from
  // the best pair. Within a start, dv <= a_max dt and dv <= V_i give HIC^2 <= a_max^5 dt^2
  // (too short a window cannot win) and <= V_i^5 / dt^3 (nor can any longer one once this is
  // below the best); pairs are skipped only below the best, so ties are still all seen.
  double best2 = 0, best = 0;
  int b1 = 0, b2 = 0;
  while (ns > 0 && st[0].bound >= best) {
    int i = st[0].i;
    double am = st[0].am, vm = st[0].vm;
    double am5 = am * am * am * am * am * (1 + 1e-9), vm5 = vm * vm * vm * vm * vm * (1 + 1e-9);
    st[0] = st[--ns];
    sift_down(st, ns, 0);
    for (int k = first_long(t, n, i, am5, best2); k < n && t[k] - t[i] <= wmax; k++) {
      double dt = t[k] - t[i];
      if (vm5 < best2 * dt * dt * dt) {
        break;
      }
      if (am5 * dt * dt < best2) {
        continue;
      }
      double dv = v[k] - v[i];
      if (dv <= 0) {
        continue;
      }
      double dv2 = dv * dv;
      double h2 = dv2 * dv2 * dv / (dt * dt * dt);
      if (h2 > best2 || (h2 == best2 && h2 > 0 && (i < b1 || (i == b1 && k < b2)))) {
        best2 = h2;
        best = sqrt(h2);
        b1 = i;
        b2 = k;
      }
    }
  }

  // report the best pair
  if (best > 0) {
    double dv = v[b2] - v[b1], dt = t[b2] - t[b1];
    best = dv * dv * sqrt(dv) / (dt * sqrt(dt));
  }
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

int ur_hic_work_size(int n) {
  // n doubles, n starts {3 doubles, int} (4 doubles each), 2 n ints (1 double each, rounded up)
  return n > 0 ? 6 * n : 0;
}
