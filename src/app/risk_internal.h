/* risk_internal.h: what the files of the risk figures share (cmd_risk.c, cmd_montecarlo.c,
 * risk_dist.c, plot_mc.c); after app.h */
#ifndef UASRISK_RISK_INTERNAL_H
#define UASRISK_RISK_INTERNAL_H

#include "app.h"

/* ---- shared by risk, sora and montecarlo (cmd_risk.c) ---- */

/* the deployable devices of the live model: a parachute (area_chute > 0) and the airbags it
   carries (bag_bottom, bag_front set to 1), with the reliabilities of st; dep->nbag bags, named
   by ura_risk_bag(k) */
int ura_risk_devices(uraCtx* c, const uraState* st, urDeploy* dep, int* bag);
/* the name of the k-th carried bag (bag[k] indexes "bag_bottom", "bag_front") */
const char* ura_risk_bag(int which);
/* a branch's name: "none", "chute", "chute+bag_bottom", ... */
void ura_risk_branch_name(int mask, const urDeploy* dep, const int* bag, char* buf, size_t n);
/* the state of a branch: base with the parachute (area_chute 0 and case C's Table 2 column
   without it) and each carried airbag as the mask says */
void ura_risk_branch_state(const uraState* base, int mask, const urDeploy* dep, const int* bag,
                           uraState* ns);
/* a model parameter value in a state's overrides (set by the user when user) */
void ura_risk_override(uraState* ns, const char* name, double v, int user);
/* Q of the grid of state ns (it becomes the live state; the caller restores its own) */
int ura_risk_grid(uraCtx* c, const uraState* ns, const char* who, int quiet, double* q);
/* the Annex F critical area of state ns (mass, width, its impact speed and angle), m^2 */
int ura_risk_annexf(uraCtx* c, const uraState* ns, double* ca, double* speed, double* angle);
/* a critical area (m^2) with its 95 % interval, and the reduction factor of the unmitigated
   drone's against it with its interval */
typedef struct {
  double ca, lo, hi, red, red_lo, red_hi;
} uraSoraFig;
/* the figures of the last montecarlo (cmd_montecarlo.c): [0] Q unmitigated, [1] its Annex F
   area, [2] Q of the live case (its drawn deployment), [3] its Annex F area; *mitigated: the
   drone carries a parachute; note: what they come from. 0, or -1 when there is none or the
   settings changed since */
int ura_mc_sora(uraCtx* c, uraSoraFig fig[4], int* mitigated, char* note, size_t n);
/* the last montecarlo for the plots: its samples' Q and statistics (-1: none); the shares of its
   independent inputs (names, values; their count, at most uraMAXDIST + 1 + urMAXBAGS) */
int ura_mc_data(uraCtx* c, const double** q, int* n, const urMcStats** st, const char** casename,
                double* seed);
int ura_mc_shares(uraCtx* c, const char** name, double* share);
/* the iGRC columns of a critical area: raw1, igrc, igrc_table (0, or -1 without a class) */
int ura_risk_igrc(const uraState* st, double ca, double* raw1, int* igrc, int* table);

/* ---- SORA 2.5 and eq. (1.1) (cmd_sora25.c) ---- */

/* the Table 2 look-up of the live drone: its dimension and maximum speed (set or derived), the
   highest density band, the column, row and iGRC (0 grey, -1 outside), clamped values counted */
typedef struct {
  double dim, speed, density;
  int dim_set, speed_set;
  int col, row, igrc;
  int nclamp;
} uraSora25;
void ura_sora25_inputs(uraCtx* c, double unmit_speed, uraSora25* s);
const char* ura_sora25_col_name(int col);
/* a sora row's columns igrc_sora25 and igrc_quant (the quantitative iGRC of area ca clamped) */
void ura_sora25_cells(uraTable* t, uraSora25* s, int igrc_quant, int ok, double ca);
/* sora's notes on those columns */
void ura_sora25_notes(uraTable* t, const uraSora25* s);
/* the M2 evidence table from sora's four figures (as ura_mc_sora fills them) */
int ura_sora25_m2_table(uraCtx* c, const uraSora25* s, const uraSoraFig fig[4], const char* design,
                        int from_mc);
/* eq. (1.1) per case and density band: n rows of Q with interval, and where they come from */
void ura_eq11_table(uraCtx* c, int n, const char* const* label, const double* q, const double* lo,
                    const double* hi, const char* source);

#endif
