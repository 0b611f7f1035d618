/* app.h: the application layer of uasrisk: live case state, command table, output.
 * Prefix ura_ (application), types ura*. The numerical core (libuasrisk) knows nothing of this.
 */
#ifndef UASRISK_APP_H
#define UASRISK_APP_H

#include <stddef.h>
#include <stdio.h>

#include "uasrisk/descent.h"
#include "uasrisk/grid.h"
#include "uasrisk/impact.h"
#include "uasrisk/init.h"
#include "uasrisk/injury.h"
#include "uasrisk/modellang.h"
#include "uasrisk/parametric.h"
#include "app_risk.h"

#define uraMAXLIST     64 /* values in a list parameter */
#define uraMAXOV       64 /* model parameters set by the case or the user */
#define uraMAXPARTS    32 /* model parts */
#define uraERRLEN      1024
#define uraMODELCACHE  8           /* compiled, settled models kept besides the live one */
#define uraRECALLGRIDS 64          /* complete grids kept for recall */
#define uraRECALLBYTES (64L << 20) /* their cells, bytes at most */

/* ---- live case state ---- */

/* table: rows fit 80 columns at a terminal, every column elsewhere; wide: every column always */
typedef enum {
  uraFMT_TABLE = 0,
  uraFMT_CSV,
  uraFMT_WIDE
} uraFormat;
/* where a derived impact speed and descent angle come from (set descent) */
typedef enum {
  uraDESC_MODEL = 0,
  uraDESC_PAPER
} uraDescentSrc;

typedef struct {
  char casename[8];         /* A, B, C, A1, A2 */
  urDescentParams descent;  /* descent model parameters (wind is the live wind) */
  urParametricParams para;  /* Appendix D parameters */
  double winds[uraMAXLIST]; /* wind list for descent/parametric/sweeps, m/s */
  int nwinds;
  double speed, angle;               /* impact speed (m/s) and descent angle (deg) when set */
  int speed_set, angle_set;          /* 0: derived (descent_src says from what) */
  int descent_src;                   /* uraDescentSrc: the descent model, or the paper's Table 2 */
  int tau;                           /* urTau: the moment at which Delta is taken */
  double face;                       /* face direction phi, deg */
  int format;                        /* uraFormat */
  int pager;                         /* 1: long output at the prompt through $PAGER (pager.c) */
  urInjuryParams injury;             /* injury criteria and PoF curve settings */
  double pitch, roll, yaw;           /* drone attitude relative to upright on its course, deg */
  double step;                       /* grid pitch, m */
  double par_min, par_max, perp_max; /* grid extents along_min, along_max, cross_max when set, m */
  int par_min_set, par_max_set, perp_max_set; /* 0: sized automatically (derived) */
  double threads;                             /* grid worker threads (a whole number) */
  int recall;                        /* 1: a grid identical to an earlier one reuses its cells */
  char ov_name[uraMAXOV][urNAMELEN]; /* model parameters overridden (SI values) */
  double ov_val[uraMAXOV];
  int ov_user[uraMAXOV]; /* 1: set by the user, 0: by the case preset */
  int nov;
  char terminal[64]; /* gnuplot terminal; empty: gnuplot's default */
  char output[512];  /* gnuplot output file; empty: a window */
  uraRiskSet risk;   /* deployment reliability, distributions, SORA (app_risk.h) */
} uraState;

/* one part of the model set (human, ra3, airbags, sim, or loaded from a file) */
typedef struct {
  char name[urNAMELEN];
  char* text;       /* owned */
  char origin[256]; /* "built-in" or the file it came from */
  int line;         /* line of the origin where the part starts */
} uraPart;

/* the last grid with the conditions it was computed (or loaded) for */
typedef struct {
  urGrid* g; /* NULL: none yet */
  char casename[8];
  double wind, face, speed, angle; /* m/s, deg, m/s, deg */
  int paper_speed;                 /* speed or angle came from the paper's Table 2 */
  int tau;                         /* urTau of a computed grid (loaded: urTAU_RMAX) */
  double tau_shift;                /* ur_impact_tau_shift of a computed grid, m */
  char source[512];                /* "computed", or the file it was loaded from */
  int recalled;                    /* the cells of an identical earlier grid (recall.c) */
  int extents_set;                 /* some extent was set: Q covers only the lattice */
  int diff;                        /* a difference grid (design compare): p is P_b - P_a */
} uraGridResult;

/* what a compiled model is made of: the generation of the model parts (counted up whenever they
   change) and the parameter overrides, names and exact values in any order */
typedef struct {
  unsigned long gen;
  int nov;
  char ov_name[uraMAXOV][urNAMELEN];
  double ov_val[uraMAXOV];
} uraModelKey;

typedef struct uraModelCache uraModelCache; /* modelcache.c */
typedef struct uraRecall uraRecall;         /* recall.c */

/* time histories of one impact, for inspection and plotting */
typedef struct {
  int n, nsig;              /* samples, signals */
  double* t;                /* n times, s */
  double* v;                /* nsig*n values, signal-major */
  const char* const* names; /* nsig signal names (e.g. head_acc, neck_fz) */
  const char* const* units; /* nsig units */
  const char* title;        /* the impact's conditions and results (NULL: none) */
} uraTrace;

/* one sweep kept for plot sweep and export sweep (cmd_sweep.c): Q per wind or face value */
#define uraMAXSWEEPS 32
typedef struct {
  char casename[8];
  int over_face;     /* 0: over wind (face fixed), 1: over face (wind fixed) */
  double fixed;      /* the face (deg) of a wind sweep, the wind (m/s) of a face one */
  double step;       /* grid pitch, m */
  char changes[200]; /* settings that differ from the case preset, or "none" */
  int n;             /* values, in increasing order */
  double x[uraMAXLIST], speed[uraMAXLIST], angle[uraMAXLIST], q[uraMAXLIST];
} uraSweep;

/* ---- context ---- */

typedef struct uraCtx {
  uraState st;
  FILE* out;           /* results */
  FILE* msg;           /* errors and notes */
  char err[uraERRLEN]; /* message of the last failure */
  int err_located;     /* err already starts with FILE:LINE: */
  int interactive;     /* a person is typing: errors do not stop anything */
  int depth;           /* nesting of source */
  int quit;            /* set by quit */
  int dry;             /* fuzzing (tests/fuzz): commands parse their arguments but
                                      refuse to simulate, plot, open the viewer or touch files
                                      (ura_dry) */
  uraGridResult last;  /* the last grid */
  uraSweep* sweep;     /* the kept sweeps, oldest first (sweep clear frees them) */
  int nsweep;
  struct uraPSweep* psweep; /* the kept sweeps over other parameters (sweep_param.c) */
  int npsweep;
  struct uraDesign* design; /* the saved designs (design_cmd.c) */
  int ndesign;
  uraPart part[uraMAXPARTS]; /* the model set, in order */
  int npart;
  unsigned long parts_gen; /* generation of the model parts */
  urModel* model;          /* compiled with the overrides; NULL: stale */
  urImpactSetup setup;     /* settled stance of the model; valid if have_setup */
  int have_setup;
  urImpactWork work; /* the single-impact work space (histories of the last impact) */
  int have_work;
  int have_impact; /* the work holds a finished impact */
  urImpactResult last_impact;
  double last_dpar, last_dperp;
  int last_aim;          /* the last impact was aimed (impact aim): the two are the
                                      eccentricity up, side */
  uraModelCache* mcache; /* other models with their stances (NULL until one is kept) */
  uraRecall* recall;     /* complete grids for recall (NULL until one is kept) */
  unsigned long tick;    /* use counter of both, for least-recently-used eviction */
  /* run (or recall) the impact of one grid cell and its histories; NULL until impacts exist */
  int (*inspect)(struct uraCtx* c, urCell* cell, uraTrace* trace);
  struct uraMc* mc;       /* the last montecarlo's samples (NULL: none; app_risk.h) */
  char impact_title[400]; /* the last impact's conditions and results (plot titles) */
  struct {                /* the last trace's signals (ura_last_trace; ura_trace_free) */
    double* t;
    double* v;
    char** names;
    const char** units;
    int nsig;
  } trace;
  int canvas_w, canvas_h; /* canvas (pixels) a plot of several panels asks for; 0: the
                                      terminal's default (ura_plot_canvas) */
  /* optional: asked before each command runs (the executing fuzz target bounds the work and the
     files of its inputs); nonzero refuses the command with c->err set */
  int (*guard)(struct uraCtx* c, int argc, char** argv);
  struct uraScale* scale; /* the work split over processes (scale.h; NULL: serial) */
  int mute;               /* results, notes, files and plots go nowhere (scale.h) */
  struct uraReport* rep;  /* the results kept for report (report.h; NULL: none yet) */
} uraCtx;

/* record a failure message; always returns -1 */
int ura_fail(uraCtx* c, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

void ura_init(uraCtx* c);
void ura_state_defaults(uraState* s);

/* ---- strict parsing ---- */

/* a finite decimal number (no hex, nan, inf, empty, or trailing text) */
int ura_parse_number(const char* s, double* v);
/* a comma-separated list of numbers; returns count or -1 */
int ura_parse_list(const char* s, double* v, int max);

/* ---- parameters (one table drives set, show, save and completion) ---- */

typedef enum {
  uraP_NUM = 0,
  uraP_LIST,
  uraP_ENUM,
  uraP_CASE,
  uraP_STR,
  uraP_INT
} uraPKind;

typedef struct {
  const char* name;
  uraPKind kind;
  size_t off;    /* offset of the value in uraState */
  size_t setoff; /* offset of the int "set" flag of a derivable value, or 0 */
  const char* unit;
  double min, max; /* accepted closed range (numbers, list items); STR: size */
  const char* help;
  const char* const* choices; /* uraP_ENUM: NULL-terminated names */
  /* uraP_STR: checks a value and writes what is kept into norm (n bytes); 0, or -1 with the
     failure recorded (NULL: any text of the size) */
  int (*check)(struct uraCtx* c, const char* value, char* norm, size_t n);
  size_t cntoff; /* uraP_LIST: offset of its int count in uraState (0: the winds' nwinds) */
} uraParam;

extern const uraParam ura_params[];
const uraParam* ura_param_find(const char* name);
int ura_param_set(uraCtx* c, const uraParam* p, const char* value);
/* the value as text (without unit) into buf, exact (round-trips through set); a derivable
   value that is not set prints as auto */
void ura_param_format(const uraCtx* c, const uraParam* p, char* buf, size_t n);

/* the injury settings (core table) through set/show: index of NAME or -1; set; one show line */
int ura_injury_find(const char* name);
int ura_injury_set(uraCtx* c, int i, const char* value);
void ura_injury_line(uraCtx* c, int i, char* buf, size_t n, int with_unit);

/* current impact speed and angle: set values, or derived at the live wind from the descent
   model or (set descent paper) the paper's Table 2 */
int ura_impact_conditions(uraCtx* c, double* speed, double* angle);
/* 1 if the live speed or angle is derived from the paper's Table 2 */
int ura_paper_speed(const uraCtx* c);

/* the paper's Table 2 (cmd_paper.c): speed (m/s) and descent angle (deg) of a case at a wind:
   case C's column for C, case B's for A, A1, A2 and B; only the printed winds 0, 2, ..., 10
   m/s. 0, or -1 with a message naming the wind and the accepted ones */
int ura_paper_descent(uraCtx* c, const char* casename, double wind, double* speed, double* angle);
/* the column of Table 2 a case takes: "B" or "C" */
const char* ura_paper_descent_column(const char* casename);

/* load a case: a preset of the model (the RA3's A, B, C, A1, A2; wind and face are kept); the
   model's first preset (none: nothing) */
int ura_case_load(uraCtx* c, const char* name);
int ura_case_default(uraCtx* c);
/* presets (preset.c): by name (any case), the names as "A, B or C", the state a case starts
   from (the live wind, face, lists, step and output settings kept) */
const urPreset* ura_preset_find(uraCtx* c, const char* name);
void ura_preset_names(uraCtx* c, char* buf, size_t n);
int ura_preset_state(uraCtx* c, const urPreset* pr, const urModel* m, uraState* ns);
/* design parameters (design.c): mass also as the multibody drone's total (its role mass=
   parameter, as an override of ns; user: set by the user), the models a setting changes */
int ura_design_mass(const urModel* m, uraState* ns, double mass, int user);
int ura_design_set(uraCtx* c, const char* name, const char* value, const char* unit);
const char* ura_design_reach(uraCtx* c, const char* name);
const char* ura_design_mark(uraCtx* c, const char* name, char* buf, size_t n);

/* ---- tabular output ---- */

typedef struct uraTable uraTable;
uraTable* ura_table_new(int ncol, const char* const* names);
void ura_table_cell(uraTable* t, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void ura_table_note(uraTable* t, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
/* print (aligned table or CSV, per the format setting) and free */
void ura_table_print(uraCtx* c, uraTable* t);

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

/* run one command line (may hold several commands separated by ';'); 0 or -1 */
int ura_run_line(uraCtx* c, const char* line);
/* prefix the failure message with NAME:LINE: (LINE 0: NAME: only), once */
void ura_locate(uraCtx* c, const char* name, int lineno);
/* run a script file; errors are reported as FILE:LINE: message; 0 or -1 */
int ura_run_file(uraCtx* c, const char* path);
/* run a script from an open stream, naming it name in messages */
int ura_run_stream(uraCtx* c, FILE* f, const char* name);

/* command handlers, one file per group */
int ura_cmd_help(uraCtx* c, int argc, char** argv);
int ura_cmd_set(uraCtx* c, int argc, char** argv);
int ura_cmd_show(uraCtx* c, int argc, char** argv);
int ura_cmd_reset(uraCtx* c, int argc, char** argv);
int ura_cmd_case(uraCtx* c, int argc, char** argv);
int ura_cmd_source(uraCtx* c, int argc, char** argv);
int ura_cmd_quit(uraCtx* c, int argc, char** argv);
int ura_cmd_descent(uraCtx* c, int argc, char** argv);
int ura_cmd_parametric(uraCtx* c, int argc, char** argv);
int ura_cmd_pof(uraCtx* c, int argc, char** argv);
extern const char* const ura_pof_names[];

/* workbench (view.c, gridshow.c, gridload.c, plot.c) */
int ura_cmd_grid(uraCtx* c, int argc, char** argv);
int ura_grid_run(uraCtx* c, int quiet);
int ura_grid_extents(uraCtx* c, double* par_min, double* par_max, double* perp_max);
int ura_grid_show(uraCtx* c);
int ura_grid_load(uraCtx* c, const char* path);
int ura_cmd_view(uraCtx* c, int argc, char** argv);
int ura_cmd_plot(uraCtx* c, int argc, char** argv);
/* the checks of the terminal and output settings (plot.c): a terminal is a known name with
   checked options (kept normalised: fonts in single quotes), an output a file name that gnuplot
   cannot take for a pipe; both can be written back by save session */
int ura_terminal_check(uraCtx* c, const char* value, char* norm, size_t n);
int ura_output_check(uraCtx* c, const char* value, char* norm, size_t n);
/* a word a script reads back as s: in double quotes, or single ones when s holds a double quote
   (session.c); -1 when it cannot be written (a control byte, or both quote characters) */
int ura_word_ok(const char* s);
void ura_put_word(FILE* f, const char* s);
void ura_last_free(uraCtx* c);

/* files written atomically (atomic.c): open a temporary file beside path (symbolic links
   followed); close renames it over the file if ok and everything was written, else removes it (a
   failure message unless !ok). A FIFO, a character device or an open descriptor (/dev/stdout)
   is written in place; directories, block devices and sockets are refused. */
typedef struct {
  FILE* f;
  int fd;
  int inplace;     /* written in place (no temporary file, no rename) */
  int err;         /* errno of the first failed write */
  char path[1024]; /* as given (messages) */
  char real[4096]; /* the file replaced */
  char tmp[4200];  /* the temporary file beside it */
} uraAtomic;
int ura_atomic_open(uraCtx* c, uraAtomic* a, const char* path, const char* who);
int ura_atomic_close(uraCtx* c, uraAtomic* a, int ok, const char* who);

/* models (model.c) */
int ura_models_init(uraCtx* c);
void ura_models_free(uraCtx* c);
void ura_trace_free(uraCtx* c);            /* the signals of the last trace */
const urModel* ura_model(uraCtx* c);       /* compiled model, or NULL with c->err */
const urImpactSetup* ura_setup(uraCtx* c); /* settled stance, or NULL with c->err */
void ura_model_stale(uraCtx* c);
int ura_model_param_find(uraCtx* c, const char* name); /* index in the model, or -1 */
int ura_model_param_set(uraCtx* c, const char* name, const char* value, const char* unit, int user);
/* the live state becomes ns if the model compiles with its parameter overrides (unchanged
   overrides keep the model and its stance); else nothing changes and WHO: refused ... */
int ura_model_state(uraCtx* c, const uraState* ns, const char* who);
int ura_cmd_model(uraCtx* c, int argc, char** argv);
/* the model parts as session commands: model drop for each built-in part missing, model load
   for each loaded one */
void ura_model_write_parts(uraCtx* c, FILE* f);

/* the model cache (modelcache.c): the key of the live parts with st's overrides, and equality */
void ura_model_key(const uraCtx* c, const uraState* st, uraModelKey* k);
int ura_model_key_same(const uraModelKey* a, const uraModelKey* b);
/* the live model leaves: kept with its settled stance (an unsettled one is freed); its work space
   and last impact go with it */
void ura_mcache_park(uraCtx* c);
/* a kept model for ns's overrides becomes the live one (the live one is parked): 1, else 0 */
int ura_mcache_take(uraCtx* c, const uraState* ns);
void ura_mcache_flush(uraCtx* c); /* free every kept model */
/* the settled stances of the kept models into out (at most max): donors of the person's stance
   for a new model (ur_impact_prepare); their count */
int ura_mcache_setups(const uraCtx* c, const urImpactSetup** out, int max);

/* grid recall (recall.c): a copy of a kept complete grid for the live model and these
   conditions (NULL: none, or recall is off); keep a complete grid; free every kept grid */
urGrid* ura_recall_find(uraCtx* c, const urImpactCond* cond);
void ura_recall_keep(uraCtx* c, const urImpactCond* cond, const urGrid* g);
void ura_recall_flush(uraCtx* c);
int ura_cmd_save(uraCtx* c, int argc, char** argv);
/* the commands of save session (session.c) */
void ura_session_write(uraCtx* c, FILE* f);
/* what a session leaves out (session_base.c): the state 'reset; case NAME' gives with the live
   model parts (0, or -1: the defaults, the case is not a preset); the shortest text of v that
   reads back exactly; a model parameter's value in the unit that writes it shortest and exactly
   ("1.1 atm", "26 kN", "0.25 m") */
int ura_session_base(uraCtx* c, uraState* base);
void ura_num_shortest(char* buf, size_t n, double v);
void ura_model_value_text(uraCtx* c, const char* name, double v, char* buf, size_t n);
int ura_cmd_sweep(uraCtx* c, int argc, char** argv);
int ura_cmd_design(uraCtx* c, int argc, char** argv); /* designs.c */
/* the saved designs as commands, for save session (designs.c) */
void ura_designs_write(uraCtx* c, FILE* f, void (*write_state)(uraCtx*, FILE*));
/* the settings a grid depends on that differ from the case preset, "name=value ..." or "none"
   (cmd_sweep.c) */
void ura_sweep_changes(uraCtx* c, char* buf, size_t n);
/* sweeps over any numeric parameter (sweep_param.c): sweep NAME LIST [UNIT]; their rows for
   sweep show (t: its table, columns case,sweep,wind,face,speed,angle,step,q,changes,value,
   unit); plot sweep NAME; forget them */
int ura_sweep_param(uraCtx* c, int argc, char** argv);
void ura_sweep_param_rows(uraCtx* c, uraTable* t);
int ura_plot_psweep(uraCtx* c, const char* name);
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
int ura_cmd_contacts(uraCtx* c, int argc, char** argv);
int ura_impact_cond(uraCtx* c, urImpactCond* cond); /* refuses angles below uraANGLE_DELTA */
#define uraANGLE_DELTA 1.0 /* deg: the least descent angle of an offset Delta (grids) */
/* impact aim head UP SIDE (cmd_aim.c): one impact whose line of travel passes the head's centre
   at an eccentricity, at any angle 0-90 deg */
int ura_impact_aim(uraCtx* c, int argc, char** argv);
/* the table of impact rows (columns dpar,dperp,contact,hic15,...,p) and one row of it */
uraTable* ura_impact_table(const urInjuryParams* ip);
void ura_impact_cells(uraTable* t, const urInjuryParams* ip, double dpar, double dperp,
                      const urImpactResult* r);
/* the impact row at a terminal (impact_compact.c): whether to print it, its table (columns
   dpar,dperp,hic15,nij,vc_th,vc_ab,p_hic,p_nij,p_vc,p) and its row with a note */
int ura_impact_compact(const uraCtx* c);
uraTable* ura_impact_compact_table(void);
void ura_impact_compact_row(uraTable* t, double dpar, double dperp, const urImpactResult* r);
/* notes for a table computed under cond: where speed and angle came from when it was the paper's
   Table 2 (paper), and the moment tau when it is not the paper's text (shift: the tau shift, m) */
void ura_cond_notes(uraTable* t, const char* casename, double wind, int paper, int tau,
                    double shift);
int ura_last_trace(uraCtx* c, uraTrace* tr); /* histories of the last impact; -1: none */
/* keep a finished impact (its work space holds the histories) as the last impact, with the case
   and wind it ran for */
void ura_impact_keep(uraCtx* c, const char* casename, double wind, const urImpactCond* cond,
                     double dpar, double dperp, const urImpactResult* r);
int ura_inspect_cell(uraCtx* c, urCell* cell, uraTrace* tr);
/* run one impact in a work space of its own, which becomes c->work only when it finishes: a
   failed or interrupted impact leaves the last one (histories, contacts) as it was; 0, or -1
   with r->status and r->reason */
int ura_impact_fresh(uraCtx* c, const urImpactSetup* s, const urImpactCond* cond, double dpar,
                     double dperp, urImpactResult* r);

/* interactive loop on GNU readline */
int ura_repl(uraCtx* c);

/* in dry mode, refuse WHAT (a simulation, plot, file...) with a message; 0 otherwise */
int ura_dry(uraCtx* c, const char* what);

/* Ctrl-C (interrupt.c): the handler for the whole run (interactive: repeated Ctrl-C never end
   the program), the flag that long work polls (also the models' opt.stop), cleared at the
   prompt */
void ura_interrupt_install(int interactive);
_Atomic int* ura_interrupt_flag(void);
int ura_interrupted(void);
void ura_interrupt_clear(void);
/* the temporary file of a write under way, removed if SIGTERM, SIGHUP or a fatal Ctrl-C end the
   program (at most one at a time); disarm when it is renamed or removed */
void ura_temp_arm(const char* path);
void ura_temp_disarm(void);

/* text files (textin.c): the next line of f without its line end into *buf (realloc'ed, *cap
   its size), at most max bytes; its length, or one of these */
enum {
  uraLINE_EOF = -1,
  uraLINE_ERROR = -2 /* errno */,
  uraLINE_LONG = -3,
  uraLINE_NUL = -4
};
long ura_read_line(FILE* f, char** buf, size_t* cap, size_t max);
#define uraMAXLINE (1L << 20) /* longest line of a script or grid file, bytes */
/* s as printable text into buf (n bytes, cut to fit): control bytes, DEL, C1 controls and bytes
   that are not UTF-8 as \xNN, printable ASCII and UTF-8 kept; its length. Every message goes
   through it (ura_fail), so that no input echoed in an error can drive the terminal. */
size_t ura_printable(const char* s, char* buf, size_t n);
/* a buffered stream writing to fd (standard output when it is not a terminal) that keeps the
   errno of its first failed write: ura_out_errno, 0 if none since ura_out_clear */
FILE* ura_out_stream(int fd);
int ura_out_errno(void);
void ura_out_clear(void);

/* the terminal (pager.c): f is a terminal (or the pager's buffer of one); a command typed at the
   prompt writes to a terminal; its size; the width text wraps at (0: no wrapping: not at a
   terminal, or format wide); gather a command's output and page it when taller than the screen */
int ura_tty(FILE* f);
int ura_at_terminal(const uraCtx* c);
void ura_term_size(int* rows, int* cols);
int ura_text_width(const uraCtx* c);
int ura_pager_begin(uraCtx* c, const char* cmd);
void ura_pager_end(uraCtx* c);
/* the progress line on standard error (progress.c): a label before it (a sweep's value; NULL:
   none), the start of the work, one line "LABEL WHAT DONE/TOTAL NOUN, ELAPSED, about T left" */
void ura_progress_label(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
void ura_progress_start(void);
void ura_progress_line(const char* what, long done, long total, const char* noun);
/* "uasrisk VERSION (commit HASH[-dirty])" (version.c) */
const char* ura_version(void);
/* "did you mean" (suggest.c): the edit distance of two names; the nearest name offered for a
   word, near enough for a typing slip; its text (" (did you mean 'NAME'?)" or ""); the names of
   the command table, of the parameter tables, of a usage text's keywords */
typedef struct {
  const char* word;
  char best[64];
  int d;
} uraSuggest;
int ura_edit_distance(const char* a, const char* b);
void ura_suggest_init(uraSuggest* s, const char* word);
void ura_suggest_add(uraSuggest* s, const char* name);
const char* ura_suggest_text(const uraSuggest* s, char* buf, size_t n);
void ura_suggest_commands(uraSuggest* s);
void ura_suggest_params(uraCtx* c, uraSuggest* s);
void ura_suggest_keywords(uraSuggest* s, const char* usage);
/* text after lead, wrapped between words at width (0: one line), later lines after cont */
void ura_wrap(FILE* f, const char* lead, const char* cont, const char* text, int width);
/* s split at its double spaces into at most max lines of width (the last takes the rest); the
   number of lines */
int ura_split_fields(const char* s, int width, char (*out)[256], int max);

#endif
