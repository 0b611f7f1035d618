/* risk.h: from Q to a risk figure: deployment reliability of the parachute and the airbags (a
 * mixture of the grids' Q over the deployment outcomes), input distributions drawn per Monte
 * Carlo sample from a counter-based generator (rng.h), the summary of a sample of Q (mean,
 * standard deviation, 95 % confidence interval of the mean), first-order variance shares, the
 * ratio of two paired means, and multilinear interpolation on a lattice (response surfaces).
 * Everything here is a pure function of its arguments.
 */
#ifndef UASIMPACT_RISK_H
#define UASIMPACT_RISK_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- deployment reliability ---- */

#define urMAXBAGS   2 /* airbags a drone may carry (bottom, front) */
#define urMAXBRANCH (1 << (urMAXBAGS + 1))

typedef struct {
  int chute;          /* the drone carries a parachute */
  int nbag;           /* the airbags it carries, 0..urMAXBAGS */
  double p_chute;     /* probability that the parachute deploys in time */
  double p_bag;       /* probability that each airbag deploys (independently) */
  double altitude;    /* height of the failure, m */
  double h_chute_min; /* below this height the parachute cannot help, m */
} urDeploy;

/* a branch: which devices deployed. bit 0 the parachute, bit 1+k airbag k. Without the parachute
   no airbag is credited (the drone falls as case C: the airbags are sized for, and deployed with,
   the parachute descent), so every branch without bit 0 is branch 0. */
typedef struct {
  int mask;
  double weight; /* its probability */
} urBranch;

/* the probability that the parachute deploys and helps: p_chute when the drone carries one and
   the failure is at or above h_chute_min, else 0 */
double ur_deploy_chute(const urDeploy* d);
/* the branches of d with their weights (summing to 1), the fully deployed one first, the one
   without parachute (mask 0) last; their number */
int ur_deploy_branches(const urDeploy* d, urBranch* out);
/* the branch drawn from uniforms in (0, 1): u_chute for the parachute, u_bag[k] for airbag k (a
   device deploys when its uniform is below its probability) */
int ur_deploy_outcome(const urDeploy* d, double u_chute, const double* u_bag);

/* ---- distributions ---- */

typedef enum {
  urDIST_NORMAL = 0,
  urDIST_UNIFORM,
  urDIST_WEIBULL,
  urDIST_DISCRETE
} urDistKind;
#define urDISTMAXVAL 32 /* values of a discrete distribution */

typedef struct {
  int kind;      /* urDistKind */
  double a, b;   /* normal: mean, sd; uniform: lo, hi; weibull: scale, shape */
  double lo, hi; /* truncation: the accepted range of the input (may be
                                      infinite); normal and weibull are truncated to it */
  int nval;      /* discrete: values and their probabilities */
  double val[urDISTMAXVAL], prob[urDISTMAXVAL];
} urDist;

/* 0, or -1 with a message (what is wrong, what is accepted) when the distribution's arguments
   are not valid for its kind and truncation range */
int ur_dist_check(const urDist* d, char* err, int errlen);
/* the value of the inverse (truncated) CDF at u in (0, 1) (GSL's quantile functions) */
double ur_dist_quantile(const urDist* d, double u);

/* ---- Monte Carlo samples ---- */

/* sample i's inputs: x[k] = the quantile of dist[k] at the uniform of stream name[k] for
   (seed, i); and three uniforms for the deployment outcomes (streams "deploy:chute",
   "deploy:bag0", "deploy:bag1") in u_dep. Depends on (seed, i) and the declarations only. */
void ur_mc_inputs(uint64_t seed, uint64_t i, int n, const char* const* name, const urDist* dist,
                  double* x, double u_dep[1 + urMAXBAGS]);

typedef struct {
  int n;
  double mean, sd;   /* sample mean and standard deviation (n - 1) */
  double lo95, hi95; /* 95 % confidence interval of the mean: mean -+ t sd/sqrt(n),
                                      t the 0.975 quantile of Student's t with n - 1 degrees */
  double p025, p975; /* the sample's 2.5 % and 97.5 % quantiles */
  double min, max;
} urMcStats;

/* statistics of n >= 2 values (GSL); work: n doubles. 0, -1 if n < 2 */
int ur_mc_stats(const double* y, int n, double* work, urMcStats* s);

/* the ratio of two paired means R = mean(num) / mean(den) with its 95 % confidence interval by
   the delta method: var(R) = var(num - R den) / (n mean(den)^2). 0; -1 if n < 2 or the mean of
   den is 0 */
int ur_mc_ratio(const double* num, const double* den, int n, double* r, double* lo, double* hi);

/* first-order variance share (Sobol index) of an input x for the output y from one sample, by
   conditional means over bins of x: the sample sorted by x is cut into about sqrt(n) bins of
   equal count (equal values of x never split; an input with at most sqrt(n) distinct values
   gets one bin per value, however rare),
   S = (SSB - (m - 1) MSW) / SST with m bins (ANOVA's bias-corrected between-bin share), clipped
   to [0, 1]; 0 when x is constant, NAN when y is (or without memory). */
double ur_mc_first_order(const double* x, const double* y, int n);

/* ---- response surfaces ---- */

/* multilinear interpolation on a rectangular lattice: ndim axes, axis d with nnode[d] increasing
   nodes node[d][0..], values in row-major order (the last axis fastest); x outside an axis is
   taken at its nearest end. An axis of one node is constant. */
double ur_lattice_interp(int ndim, const int* nnode, const double* const* node, const double* value,
                         const double* x);

#ifdef __cplusplus
}
#endif
#endif
