/* quantile.h: the tails of a Monte Carlo sample: the quantile of a sorted sample (linear
 * interpolation between order statistics, Hyndman and Fan's type 7, as GSL's
 * gsl_stats_quantile_from_sorted_data and R's default), whether a sample of n resolves a tail
 * probability, and an interval truncated at the physical bounds of the quantity. Pure functions.
 */
#ifndef UASIMPACT_QUANTILE_H
#define UASIMPACT_QUANTILE_H

#ifdef __cplusplus
extern "C" {
#endif

#define urQ_TAILMIN 10 /* samples expected beyond a quantile for it to be resolved */

/* the p-quantile (0 <= p <= 1) of n >= 1 values sorted in increasing order */
double ur_quantile_sorted(const double* sorted, int n, double p);
/* 1 when n samples put fewer than urQ_TAILMIN samples beyond the p-quantile (n min(p, 1-p) <
   urQ_TAILMIN): the quantile is then little more than the extreme sample */
int ur_quantile_thin(int n, double p);
/* [*lo, *hi] truncated to [min, max] (the quantity's physical range); the bits of the return
   value: 1 the lower end was raised, 2 the upper one lowered */
int ur_interval_clip(double* lo, double* hi, double min, double max);

#ifdef __cplusplus
}
#endif
#endif
