/* app_risk.h: the settings and results of the risk figures (cmd_risk.c, cmd_montecarlo.c,
 * risk_dist.c, plot_mc.c): deployment reliability, declared input distributions, Monte Carlo, and
 * the SORA figures. Included by app.h: the settings live in the live state (uraState.risk), so
 * that set, show, save session and case treat them as every other parameter. */
#ifndef UASRISK_APP_RISK_H
#define UASRISK_APP_RISK_H

#include "uasrisk/engine.h"
#include "uasrisk/risk.h"

#define uraMAXDIST  16 /* declared input distributions */
#define uraMAXBANDS 64 /* population density bands, mc quantiles (= uraMAXLIST, app.h) */

typedef enum {
  uraMC_SURFACE = 0,
  uraMC_EXACT
} uraMcMethod;

/* one declared input distribution ('dist NAME KIND ...') */
typedef struct {
  char name[urNAMELEN];
  urDist d;
} uraDistDecl;

typedef struct {
  double p_chute;                  /* the parachute deploys in time */
  double p_bag;                    /* each airbag deploys */
  double h_chute_min;              /* m: below this failure height the parachute cannot help */
  double seed;                     /* Monte Carlo key (a whole number) */
  int mc_method;                   /* uraMcMethod */
  double surface_nodes;            /* nodes per continuous axis of the response surface */
  double surface_check;            /* samples computed exactly to check the surface */
  double pop_density[uraMAXBANDS]; /* people/km^2: the bands of eq. (1.1); the iGRC's is the
                                      highest */
  int npop;
  double lambda;    /* ground-crash events per flight hour, eq. (1.1) */
  double p_shelter; /* probability that a person is sheltered, eq. (1.1) */
  double ua_dim;    /* m: characteristic dimension for SORA 2.5 Table 2, when set */
  int ua_dim_set;
  double ua_speed; /* m/s: maximum commanded airspeed for Table 2, when set */
  int ua_speed_set;
  int m2_baseline;           /* 0: Q unmitigated, 1: Table B.8's area of the column */
  double quant[uraMAXBANDS]; /* montecarlo's quantiles of Q (probabilities) */
  int nquant;
  double surface_tol;   /* montecarlo's tolerance on the surface's relative error; 0: none */
  double tlos;          /* target level of safety, fatalities per flight hour */
  double igrc_comp;     /* compensation subtracted from the raw iGRC */
  int annexf_obstacles; /* 1: the Annex F obstacle factor (1 < w < 40 m) */
  int ndist;
  uraDistDecl dist[uraMAXDIST];
} uraRiskSet;

struct uraCtx;
struct uraMc; /* the kept result of the last montecarlo (cmd_montecarlo.c) */

void ura_risk_defaults(uraRiskSet* r);
/* the highest of the population density bands (SORA 2.5 takes the highest in the footprint) */
double ura_risk_density_max(const uraRiskSet* r);
/* show and save session: the declared distributions, as '# ...' lines or as dist commands */
void ura_dist_show(struct uraCtx* c);
void ura_dist_save(struct uraCtx* c, FILE* f);
/* index of a declared input, or -1 */
int ura_dist_find(const uraRiskSet* r, const char* name);
/* the accepted range of an input that may be declared: 0, or -1 (with a message) when NAME
   cannot be drawn */
int ura_dist_range(struct uraCtx* c, const char* name, double* lo, double* hi);
/* the distribution as the arguments of a dist command ("weibull 5 2") */
void ura_dist_format(const uraDistDecl* d, char* buf, size_t n);

int ura_cmd_risk(struct uraCtx* c, int argc, char** argv);
int ura_cmd_dist(struct uraCtx* c, int argc, char** argv);
int ura_cmd_montecarlo(struct uraCtx* c, int argc, char** argv);
int ura_cmd_sora(struct uraCtx* c, int argc, char** argv);
int ura_cmd_converge(struct uraCtx* c, int argc, char** argv); /* cmd_converge.c */
void ura_mc_free(struct uraCtx* c);
/* plot montecarlo (Q's distribution) and plot tornado (the variance shares) */
int ura_plot_mc(struct uraCtx* c, const char* what);

#endif
