/* risk.c: deployment reliability, input distributions, Monte Carlo statistics, variance shares
 * and lattice interpolation (risk.h). Quantiles, Student's t and the sample statistics are
 * GSL's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include "uasimpact/risk.h"
#include "uasimpact/rng.h"

/* ---- deployment reliability ---- */

double ur_deploy_chute(const urDeploy* d) {
  return d->chute && d->altitude >= d->h_chute_min ? d->p_chute : 0.0;
}

int ur_deploy_branches(const urDeploy* d, urBranch* out) {
  int n = 0, nb = d->chute ? d->nbag : 0;
  double pc = ur_deploy_chute(d);
  if (d->chute) {
    /* with the parachute: the airbag outcomes, most deployed first, then by bag order */
    for (int k = nb; k >= 0; k--) {
      for (int b = 0; b < (1 << nb); b++) {
        if (__builtin_popcount((unsigned)b) != k) continue;
        double w = pc;
        for (int j = 0; j < nb; j++) w *= (b >> j) & 1 ? d->p_bag : 1 - d->p_bag;
        out[n].mask = 1 | (b << 1);
        out[n++].weight = w;
      }
    }
  }
  out[n].mask = 0;
  out[n++].weight = 1 - pc;
  return n;
}

int ur_deploy_outcome(const urDeploy* d, double u_chute, const double* u_bag) {
  if (!(u_chute < ur_deploy_chute(d))) return 0;
  int mask = 1;
  for (int k = 0; k < d->nbag; k++) {
    if (u_bag[k] < d->p_bag) mask |= 1 << (k + 1);
  }
  return mask;
}

/* ---- distributions ---- */

/* the CDF of the untruncated distribution */
static double cdf(const urDist* d, double x) {
  if (isinf(x)) return x > 0 ? 1.0 : 0.0;
  if (d->kind == urDIST_NORMAL) return gsl_cdf_gaussian_P(x - d->a, d->b);
  return x <= 0 ? 0.0 : gsl_cdf_weibull_P(x, d->a, d->b);
}

int ur_dist_check(const urDist* d, char* err, int errlen) {
  char tmp[8];
  if (!err) {
    err = tmp;
    errlen = sizeof tmp;
  }
  switch (d->kind) {
  case urDIST_NORMAL:
  case urDIST_WEIBULL: {
    int nor = d->kind == urDIST_NORMAL;
    if (!(d->b > 0) || (!nor && !(d->a > 0)) || !isfinite(d->a) || !isfinite(d->b)) {
      snprintf(err, errlen,
               nor ? "normal MEAN SD needs SD > 0"
                   : "weibull SCALE SHAPE needs SCALE > 0 and SHAPE > 0");
      return -1;
    }
    if (!(cdf(d, d->hi) - cdf(d, d->lo) > 1e-9)) {
      snprintf(err, errlen, "%s %g %g has almost no probability in the accepted range [%g, %g]",
               nor ? "normal" : "weibull", d->a, d->b, d->lo, d->hi);
      return -1;
    }
    return 0;
  }
  case urDIST_UNIFORM:
    if (!(d->a < d->b) || d->a < d->lo || d->b > d->hi) {
      snprintf(err, errlen, "uniform LO HI needs LO < HI within the accepted range [%g, %g]", d->lo,
               d->hi);
      return -1;
    }
    return 0;
  case urDIST_DISCRETE: {
    double sum = 0;
    if (d->nval < 1 || d->nval > urDISTMAXVAL) {
      snprintf(err, errlen, "discrete needs 1 to %d values", urDISTMAXVAL);
      return -1;
    }
    for (int i = 0; i < d->nval; i++) {
      if (d->val[i] < d->lo || d->val[i] > d->hi) {
        snprintf(err, errlen, "discrete value %g is outside the accepted range [%g, %g]", d->val[i],
                 d->lo, d->hi);
        return -1;
      }
      for (int j = 0; j < i; j++) {
        if (d->val[j] == d->val[i]) {
          snprintf(err, errlen, "discrete value %g is given twice", d->val[i]);
          return -1;
        }
      }
      if (!(d->prob[i] > 0 && d->prob[i] <= 1)) {
        snprintf(err, errlen, "discrete probability %g is not in (0, 1]", d->prob[i]);
        return -1;
      }
      sum += d->prob[i];
    }
    if (fabs(sum - 1) > 1e-6) {
      snprintf(err, errlen, "discrete probabilities sum to %.9g; accepted: a sum of 1", sum);
      return -1;
    }
    return 0;
  }
  }
  snprintf(err, errlen, "unknown distribution");
  return -1;
}

double ur_dist_quantile(const urDist* d, double u) {
  switch (d->kind) {
  case urDIST_UNIFORM: return d->a + u * (d->b - d->a);
  case urDIST_DISCRETE: {
    double sum = 0, cum = 0;
    for (int i = 0; i < d->nval; i++) sum += d->prob[i];
    for (int i = 0; i < d->nval - 1; i++) {
      cum += d->prob[i];
      if (u * sum < cum) return d->val[i];
    }
    return d->val[d->nval - 1];
  }
  default: {
    /* the truncated distribution: u mapped into [F(lo), F(hi)] */
    double lo = d->kind == urDIST_WEIBULL && d->lo < 0 ? 0 : d->lo;
    double fl = cdf(d, lo), fh = cdf(d, d->hi), p = fl + u * (fh - fl), x;
    if (d->kind == urDIST_NORMAL)
      x = d->a + gsl_cdf_gaussian_Pinv(p, d->b);
    else
      x = gsl_cdf_weibull_Pinv(p, d->a, d->b);
    return x < lo ? lo : x > d->hi ? d->hi : x;
  }
  }
}

/* ---- Monte Carlo samples ---- */

void ur_mc_inputs(uint64_t seed, uint64_t i, int n, const char* const* name, const urDist* dist,
                  double* x, double u_dep[1 + urMAXBAGS]) {
  static const char* const dep[1 + urMAXBAGS] = {"deploy:chute", "deploy:bag0", "deploy:bag1"};
  for (int k = 0; k < n; k++) {
    x[k] = ur_dist_quantile(&dist[k], ur_rng_uniform(seed, i, ur_rng_stream(name[k])));
  }
  for (int k = 0; k < 1 + urMAXBAGS; k++) u_dep[k] = ur_rng_uniform(seed, i, ur_rng_stream(dep[k]));
}

int ur_mc_stats(const double* y, int n, double* work, urMcStats* s) {
  if (n < 2) return -1;
  s->n = n;
  s->mean = gsl_stats_mean(y, 1, (size_t)n);
  s->sd = gsl_stats_sd_m(y, 1, (size_t)n, s->mean);
  double h = gsl_cdf_tdist_Pinv(0.975, n - 1) * s->sd / sqrt((double)n);
  s->lo95 = s->mean - h;
  s->hi95 = s->mean + h;
  memcpy(work, y, (size_t)n * sizeof *work);
  gsl_sort(work, 1, (size_t)n);
  s->p025 = gsl_stats_quantile_from_sorted_data(work, 1, (size_t)n, 0.025);
  s->p975 = gsl_stats_quantile_from_sorted_data(work, 1, (size_t)n, 0.975);
  s->min = work[0];
  s->max = work[n - 1];
  return 0;
}

int ur_mc_ratio(const double* num, const double* den, int n, double* r, double* lo, double* hi) {
  if (n < 2) return -1;
  double mn = gsl_stats_mean(num, 1, (size_t)n), md = gsl_stats_mean(den, 1, (size_t)n);
  if (md == 0) return -1;
  double R = mn / md, sum = 0, mean_d = 0;
  /* the residuals num - R den (mean 0 up to rounding), their variance with n - 1 */
  for (int i = 0; i < n; i++) mean_d += (num[i] - R * den[i] - mean_d) / (i + 1);
  for (int i = 0; i < n; i++) {
    double e = num[i] - R * den[i] - mean_d;
    sum += e * e;
  }
  double se = sqrt(sum / (n - 1) / n) / fabs(md);
  double h = gsl_cdf_tdist_Pinv(0.975, n - 1) * se;
  *r = R;
  *lo = R - h;
  *hi = R + h;
  return 0;
}

double ur_mc_first_order(const double* x, const double* y, int n) {
  if (n < 2) return NAN;
  size_t* p = malloc((size_t)n * sizeof *p);
  if (!p) return NAN;
  gsl_sort_index(p, x, 1, (size_t)n);
  double mean = gsl_stats_mean(y, 1, (size_t)n), sst = 0, ssb = 0, ssw = 0;
  for (int i = 0; i < n; i++) sst += (y[i] - mean) * (y[i] - mean);
  if (sst == 0) {
    free(p);
    return NAN;
  }
  /* bins of about n / sqrt(n) samples in the order of x, equal x never split; an input with at
     most that many distinct values (a deployment outcome, a discrete choice) gets one bin per
     value, so a rare value is never pooled with a common one */
  double nb = fmax(2.0, nearbyint(sqrt((double)n))), per = n / nb;
  int distinct = 1;
  for (int i = 1; i < n && distinct <= nb; i++) distinct += x[p[i]] != x[p[i - 1]];
  if (distinct <= nb) per = 1;
  int m = 0;
  for (int i = 0; i < n;) {
    int j = i;
    double bm = 0;
    while (j < n && (j - i < per || x[p[j]] == x[p[j - 1]])) {
      bm += (y[p[j]] - bm) / (j - i + 1);
      j++;
    }
    ssb += (j - i) * (bm - mean) * (bm - mean);
    for (int k = i; k < j; k++) ssw += (y[p[k]] - bm) * (y[p[k]] - bm);
    m++;
    i = j;
  }
  free(p);
  if (m < 2) return 0;
  double msw = n > m ? ssw / (n - m) : 0;
  double s = (ssb - (m - 1) * msw) / sst;
  return s < 0 ? 0 : s > 1 ? 1 : s;
}

/* ---- response surfaces ---- */

double ur_lattice_interp(int ndim, const int* nnode, const double* const* node, const double* value,
                         const double* x) {
  int lo[16];
  double t[16];
  for (int d = 0; d < ndim; d++) {
    const double* v = node[d];
    int n = nnode[d], i = 0;
    if (n < 2 || x[d] <= v[0]) {
      lo[d] = 0;
      t[d] = 0;
      continue;
    }
    if (x[d] >= v[n - 1]) {
      lo[d] = n - 2;
      t[d] = 1;
      continue;
    }
    while (i < n - 2 && x[d] >= v[i + 1]) i++;
    lo[d] = i;
    t[d] = (x[d] - v[i]) / (v[i + 1] - v[i]);
  }
  /* the weighted sum over the cell's 2^ndim corners (a corner with weight 0 is skipped, so an
     axis of one node is never indexed beyond it) */
  double sum = 0;
  for (int corner = 0; corner < (1 << ndim); corner++) {
    double w = 1;
    long idx = 0;
    for (int d = 0; d < ndim; d++) {
      int up = (corner >> d) & 1;
      w *= up ? t[d] : 1 - t[d];
      idx = idx * nnode[d] + lo[d] + up;
    }
    if (w != 0) sum += w * value[idx];
  }
  return sum;
}
