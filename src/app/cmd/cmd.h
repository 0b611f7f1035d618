/* cmd.h: the command layer of the application (src/app/cmd): the one command table (cmd.c, like
 * gnuplot's: dispatch, help and completion all read it), the running of command lines and
 * scripts (script.c), and the handlers, one file per group: grid, impact and its histories and
 * contacts, sweeps, the paper's tables, PoF curves, risk, SORA and Monte Carlo, designs, save
 * session and export. Includes the case layer (case.h); the interfaces, scale-out and main
 * include this header. The table also names handlers that live in the ui layer (view, plot)
 * and the grid's text ('grid show'): the one circle the layers allow, between the command
 * table and its handlers (src/README).
 */
#ifndef UASIMPACT_CMD_H
#define UASIMPACT_CMD_H

#include "../case/case.h"

/* ---- commands ---- */

typedef int (*uraCmdFn)(uraCtx* c, int argc, char** argv);

typedef enum {
  uraC_NONE = 0,
  uraC_PARAM,
  uraC_CASE,
  uraC_COMMAND,
  uraC_FILE,
  uraC_POF
} uraCompl;

typedef struct {
  const char* name;
  uraCmdFn fn;
  int minargs, maxargs; /* argument count range (maxargs -1: any) */
  uraCompl compl ;      /* what the first argument completes to */
  const char* usage;
  const char* help;
} uraCmd;

extern const uraCmd ura_cmds[];
const uraCmd* ura_cmd_find(const char* name);
/* the command NAME stands for: its full name, a short form (q) or a prefix only one command
   begins with (abbrev.c); NULL otherwise, with the commands it begins (ambiguous: "descent,
   design") in cands (n bytes; empty when none begins with it; cands may be NULL) */
const uraCmd* ura_cmd_resolve(const char* name, char* cands, size_t n);

/* a model parameter that set also takes by name (named.c): set NAME WORD0|WORD1 sets param to
   0|1; numeric (1) when set NAME NUMBER also works (then param is NAME itself) */
typedef struct {
  const char* name;
  const char* param;
  const char* word[2];
  int numeric;
  const char* why; /* why the model may lack param: the error's last words */
} uraNamed;
extern const uraNamed ura_named[]; /* ends with {NULL} */
const uraNamed* ura_named_find(const char* name);
/* set n from argv (set NAME WORD [UNIT]): 0, or -1 with one error line */
int ura_named_set(uraCtx* c, const uraNamed* n, int argc, char** argv);
/* the word n's parameter stands for (NULL: a value that is neither 0 nor 1) and the value: 0,
   or -1 with one error line when the model lacks it */
int ura_named_word(uraCtx* c, const uraNamed* n, const char** word, double* v);

/* run one command line (may hold several commands separated by ';'); 0 or -1 */
int ura_run_line(uraCtx* c, const char* line);
/* prefix the failure message with NAME:LINE: (LINE 0: NAME: only), once */
void ura_locate(uraCtx* c, const char* name, int lineno);
/* run a script file; errors are reported as FILE:LINE: message; 0 or -1 */
int ura_run_file(uraCtx* c, const char* path);
/* the start-up file (init.c): its path into buf (n bytes; -1: no HOME nor XDG_CONFIG_HOME);
   run it, if it exists, with only the commands that set things (0, or -1 after printing why) */
int ura_init_path(char* buf, size_t n);
int ura_run_init(uraCtx* c);
/* run a script from an open stream, naming it name in messages */
int ura_run_stream(uraCtx* c, FILE* f, const char* name);

/* command handlers, one file per group */
int ura_cmd_help(uraCtx* c, int argc, char** argv);
int ura_cmd_set(uraCtx* c, int argc, char** argv);
int ura_cmd_show(uraCtx* c, int argc, char** argv);
int ura_cmd_undo(uraCtx* c, int argc, char** argv);
int ura_cmd_reset(uraCtx* c, int argc, char** argv);
int ura_cmd_case(uraCtx* c, int argc, char** argv);
int ura_cmd_source(uraCtx* c, int argc, char** argv);
int ura_cmd_quit(uraCtx* c, int argc, char** argv);
int ura_cmd_descent(uraCtx* c, int argc, char** argv);
int ura_cmd_parametric(uraCtx* c, int argc, char** argv);
int ura_cmd_pof(uraCtx* c, int argc, char** argv);
extern const char* const ura_pof_names[];

/* the grid (cmd_grid.c): the command, run one (quiet: no output), its extents */
int ura_cmd_grid(uraCtx* c, int argc, char** argv);
int ura_grid_run(uraCtx* c, int quiet);
/* 1 when the scene of st is mirror-symmetric about the course but for the face (no roll or
   yaw): the grid at face -phi is the one at phi mirrored (dperp -> -dperp), with the same Q */
int ura_grid_symmetric(const uraState* st);
/* 1 when the live case's next grid simulates dperp >= 0 only and mirrors the rest: set mirror
   on, face 0 or 180, no roll or yaw, and a mirror-symmetric model (urModel.mirror); 0 with why
   (n bytes; NULL: not wanted) saying what breaks it */
int ura_grid_mirror(uraCtx* c, char* why, size_t n);
int ura_grid_extents(uraCtx* c, double* par_min, double* par_max, double* perp_max);

/* handlers the table names that live in the ui layer: the viewer (view.c), plots (plot_cmd.c), and
   the last grid as text in the paper's layout for 'grid show' (gridshow.c) */
int ura_cmd_view(uraCtx* c, int argc, char** argv);
int ura_cmd_plot(uraCtx* c, int argc, char** argv);
int ura_grid_show(uraCtx* c);
/* and the one in the report layer above: the study as one HTML file (report/report.c) */
int ura_cmd_report(uraCtx* c, int argc, char** argv);

int ura_cmd_save(uraCtx* c, int argc, char** argv);
/* the commands of save session (session.c); the same as one allocated text (NULL: no memory) */
void ura_session_write(uraCtx* c, FILE* f);
char* ura_session_text(uraCtx* c);

int ura_cmd_sweep(uraCtx* c, int argc, char** argv);
int ura_cmd_design(uraCtx* c, int argc, char** argv); /* designs.c */
/* the saved designs as commands, for save session (designs.c) */
void ura_designs_write(uraCtx* c, FILE* f, void (*write_state)(uraCtx*, FILE*));
/* the state a design keeps, or NULL; the kept names as "a, b" ("none" without any) */
const uraState* ura_designs_state(uraCtx* c, const char* name);
void ura_designs_names(uraCtx* c, char* buf, size_t n);
/* sweeps over any numeric parameter (sweep_param.c): sweep NAME LIST [UNIT]; their rows for
   sweep show (t: its table, columns case,sweep,wind,face,speed,angle,step,q,changes,value,
   unit); forget them (plot sweep NAME: ui.h) */
/* one kept sweep over a parameter (c->psweep): Q per value (plot sweep NAME draws them) */
typedef struct uraPSweep {
  char casename[8];
  char param[urNAMELEN];
  char unit[16]; /* the unit of the values as given ("" : the setting's own) */
  double wind, face, step;
  char changes[200];
  int n;
  double *x, *speed, *angle, *q; /* n values each, in one block at x (owned): no limit but the
                                    command's length */
} uraPSweep;
int ura_sweep_param(uraCtx* c, int argc, char** argv);
/* a sweep's table printed when rows > 0; else let go unprinted (no header without rows) */
void ura_sweep_table(uraCtx* c, uraTable* t, int rows);
void ura_sweep_param_rows(uraCtx* c, uraTable* t);
void ura_sweep_param_clear(uraCtx* c);
int ura_cmd_export(uraCtx* c, int argc, char** argv);
int ura_cmd_compare(uraCtx* c, int argc, char** argv);
/* why compare's p_centre is 0, as a note of t (explain.c): the impact r at (0, 0) missed or no
   criterion counts; where the grid g's P is largest (nothing when r->p > 0) */
void ura_explain_centre(uraTable* t, const urImpactResult* r, const urGrid* g);
int ura_cmd_impact(uraCtx* c, int argc, char** argv);
int ura_cmd_history(uraCtx* c, int argc, char** argv); /* cmd_history.c */
/* every sensor channel's samples of the last impact from from to to (s from tau) */
int ura_history_samples(uraCtx* c, double from, double to);
/* a note when a range FROM:TO (s; infinite: open) kept none of the n sample times t[0], t[stride],
   ...: where the samples run instead */
void ura_history_range_note(uraTable* t, const double* ts, int n, size_t stride, double from,
                            double to);
int ura_cmd_contacts(uraCtx* c, int argc, char** argv);
int ura_impact_cond(uraCtx* c, urImpactCond* cond); /* refuses angles below uraANGLE_DELTA */
#define uraANGLE_DELTA 1.0 /* deg: the least descent angle of an offset Delta (grids) */
/* impact aim head UP SIDE (cmd_aim.c): one impact whose line of travel passes the head's centre
   at an eccentricity, at any angle 0-90 deg */
int ura_impact_aim(uraCtx* c, int argc, char** argv);
/* the table of impact rows (columns dpar,dperp,contact,hic15,...,p) and one row of it
   (impact_rows.c) */
uraTable* ura_impact_table(const urInjuryParams* ip);
void ura_impact_cells(uraTable* t, const urInjuryParams* ip, double dpar, double dperp,
                      const urImpactResult* r);
/* the impact row at a terminal (impact_rows.c): whether to print it, its table (columns
   dpar,dperp,hic15,nij,vc_th,vc_ab,p_hic,p_nij,p_vc,p) and its row with a note */
int ura_impact_compact(const uraCtx* c);
uraTable* ura_impact_compact_table(void);
void ura_impact_compact_row(uraTable* t, double dpar, double dperp, const urImpactResult* r);
/* notes for a table computed under cond: where speed and angle came from when it was the paper's
   Table 2 (paper), and the moment tau when it is not the paper's text (shift: the tau shift, m) */
void ura_cond_notes(uraTable* t, const char* casename, double wind, int paper, int tau,
                    double shift);
int ura_last_trace(uraCtx* c, uraTrace* tr); /* histories of the last impact; -1: none */
int ura_inspect_cell(uraCtx* c, urCell* cell, uraTrace* tr);
/* the airbags of the last impact in at most max lines of text, four per bag (bag_summary.c):
   model, peak gauge pressure, volume lost, peak fabric strain, peak force on the person,
   bottoming (a part of the bag's carrier touched the person); 0 lines without an impact or
   bag */
int ura_bag_summary(uraCtx* c, char (*lines)[160], int max);
/* run one impact in a work space of its own, which becomes c->work only when it finishes: a
   failed or interrupted impact leaves the last one (histories, contacts) as it was; 0, or -1
   with r->status and r->reason */
int ura_impact_fresh(uraCtx* c, const urImpactSetup* s, const urImpactCond* cond, double dpar,
                     double dperp, urImpactResult* r);

/* "did you mean" over the command table (cmd.c) */
void ura_suggest_commands(uraSuggest* s);

/* ---- risk, SORA and Monte Carlo (cmd_risk.c, cmd_montecarlo.c) ---- */

int ura_cmd_risk(uraCtx* c, int argc, char** argv);
int ura_cmd_montecarlo(uraCtx* c, int argc, char** argv);
int ura_cmd_sora(uraCtx* c, int argc, char** argv);
int ura_cmd_converge(uraCtx* c, int argc, char** argv); /* risk/cmd_converge.c */
void ura_mc_free(uraCtx* c);

/* the deployable devices of the live model: a parachute (area_chute > 0) and the airbags it
   carries (bag_bottom, bag_front set to 1), with the reliabilities of st; dep->nbag bags, named
   by ura_risk_bag(k) */
int ura_risk_devices(uraCtx* c, const uraState* st, urDeploy* dep, int* bag);
/* the name of the k-th carried bag (bag[k] indexes "bag_bottom", "bag_front") */
const char* ura_risk_bag(int which);
/* the airbags of the live model that no bag_bottom or bag_front parameter switches (fitted in
   every branch, p_bag not applied): their number, and a note naming them in text (empty when
   none) */
int ura_risk_fixed_bags(uraCtx* c, const urDeploy* dep, const int* bag, char* text, size_t n);
/* a branch's name: "none", "chute", "chute+bag_bottom", ... */
void ura_risk_branch_name(int mask, const urDeploy* dep, const int* bag, char* buf, size_t n);
/* the name of the branch without devices as a case: C where the live model has a preset C
   (the RA3's case without parachute and airbag), else none (another drone has no case C) */
const char* ura_risk_none_name(uraCtx* c);
/* the state of a branch: base with the parachute (area_chute 0, case name none, ura_risk_none_name,
   whose Table 2 column is case C's, without it) and each carried airbag as the mask says */
void ura_risk_branch_state(const uraState* base, int mask, const urDeploy* dep, const int* bag,
                           const char* none, uraState* ns);
/* a model parameter value in a state's overrides (set by the user when user) */
void ura_risk_override(uraState* ns, const char* name, double v, int user);
/* Q of the grid of state ns (it becomes the live state; the caller restores its own) */
int ura_risk_grid(uraCtx* c, const uraState* ns, const char* who, int quiet, double* q);
/* the face whose grid is the mirror image of the one at face (a face in [-180, 0) -> -face) when
   st's scene is mirror-symmetric (ura_grid_symmetric); face itself otherwise */
double ura_risk_mirror_face(const uraState* st, double face);
/* ura_risk_grid, asked for at the mirror face (ura_risk_mirror_face): the same Q, one grid (and
   one recall key) for both faces; *mirrored 1 when the face was mirrored */
int ura_risk_grid_mirror(uraCtx* c, const uraState* ns, const char* who, int quiet, double* q,
                         int* mirrored);
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

/* ---- SORA 2.5 and eq. (1.1) (risk/cmd_sora25.c) ---- */

/* the Table 2 look-up of the live drone: its dimension and maximum speed (set or derived), the
   highest density band, the column, row and iGRC (0 grey, -1 outside), clamped values counted */
typedef struct {
  double dim, speed, density;
  int dim_set, speed_set;
  int dim_ra3; /* dim is the RA3's (width and length at their defaults) for another drone */
  int col, row, igrc;
  double mass; /* take-off mass, kg */
  int small;   /* iGRC 1 by the 250 g note (p. 24), not by the table */
  int nclamp;
} uraSora25;
void ura_sora25_inputs(uraCtx* c, double unmit_speed, uraSora25* s);
const char* ura_sora25_col_name(int col);
/* a sora row's columns igrc_sora25 and igrc_quant (the quantitative iGRC of area ca clamped) */
void ura_sora25_cells(uraTable* t, uraSora25* s, int igrc_quant, int ok, double ca);
/* sora's notes on those columns */
void ura_sora25_notes(uraTable* t, const uraSora25* s);
/* the M2 evidence table from sora's four figures (as ura_mc_sora fills them); named: with
   m2_baseline design:NAME, that design's Q and Annex F area (the baseline), else NULL */
int ura_sora25_m2_table(uraCtx* c, const uraSora25* s, const uraSoraFig fig[4], const char* design,
                        int from_mc, const double* named);
/* eq. (1.1) per case and density band: n rows of Q with interval, and where they come from */
void ura_eq11_table(uraCtx* c, int n, const char* const* label, const double* q, const double* lo,
                    const double* hi, const char* source);

#endif