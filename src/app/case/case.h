/* case.h: the case layer of the application (src/app/case): the live case and what it is
 * computed with. The state of a session (uraState: every setting; uraCtx: the state, the model
 * set and its compiled model and settled stance, the caches, the last grid, impact and trace),
 * the parameter table behind set and show, presets and design parameters, the model set and the
 * model cache, grid recall, what a saved session leaves out, the paper's Table 2, a grid file
 * read back, the risk settings and declared distributions, the checks of the plot settings, and
 * the context's output: tables, the pager and atomic files under the session's settings.
 * Prefix ura_ (application), types ura*. It builds on the base layer (base.h) and the core
 * (libuasimpact); the layers above (cmd, ui, scale, main) include it; it includes none of theirs.
 */
#ifndef UASIMPACT_CASE_H
#define UASIMPACT_CASE_H

#include <stddef.h>
#include <stdio.h>

#include "../base/base.h"
#include "uasimpact/descent.h"
#include "uasimpact/engine.h"
#include "uasimpact/grid.h"
#include "uasimpact/impact.h"
#include "uasimpact/init.h"
#include "uasimpact/injury.h"
#include "uasimpact/modellang.h"
#include "uasimpact/parametric.h"
#include "uasimpact/risk.h"

#define uraMAXLIST     64          /* values in a list parameter */
#define uraMAXOV       64          /* model parameters set by the case or the user */
#define uraMAXPARTS    32          /* model parts */
#define uraMODELCACHE  8           /* compiled, settled models kept besides the live one */
#define uraRECALLGRIDS 64          /* complete grids kept for recall */
#define uraRECALLBYTES (64L << 20) /* their cells, bytes at most */

/* ---- live case state ---- */

/* table: rows fit 80 columns at a terminal, every column elsewhere; wide: every column always;
   csv: CSV, its notes as '# ' lines before the header; json: one JSON object per table (JSON Lines) */
typedef enum {
  uraFMT_TABLE = 0,
  uraFMT_CSV,
  uraFMT_WIDE,
  uraFMT_JSON
} uraFormat;
/* where a derived impact speed and descent angle come from (set descent) */
typedef enum {
  uraDESC_MODEL = 0,
  uraDESC_PAPER
} uraDescentSrc;

#define uraMAXDIST  16 /* declared input distributions */
#define uraMAXBANDS 64 /* population density bands, mc quantiles (= uraMAXLIST) */

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
  int mc_mirror;                   /* 1: montecarlo takes face -phi as phi mirrored */
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
  /* sora's M2 baseline: "" (unmitigated), "table_b8" or "design:NAME" (ura_m2_baseline) */
  char m2_baseline[urNAMELEN + 8];
  double quant[uraMAXBANDS]; /* montecarlo's quantiles of Q (probabilities) */
  int nquant;
  double surface_tol;   /* montecarlo's tolerance on the surface's relative error; 0: none */
  double tlos;          /* target level of safety, fatalities per flight hour */
  double igrc_comp;     /* compensation subtracted from the raw iGRC */
  int annexf_obstacles; /* 1: the Annex F obstacle factor (1 < w < 40 m) */
  int ndist;
  uraDistDecl dist[uraMAXDIST];
} uraRiskSet;

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
  int recall; /* 1: a grid identical to an earlier one reuses its cells */
  int mirror; /* 1: a grid of a mirror-symmetric model and scene simulates dperp >= 0 only */
  char ov_name[uraMAXOV][urNAMELEN]; /* model parameters overridden (SI values) */
  double ov_val[uraMAXOV];
  int ov_user[uraMAXOV]; /* 1: set by the user, 0: by the case preset */
  int nov;
  char terminal[64]; /* gnuplot terminal; empty: gnuplot's default */
  char output[512];  /* gnuplot output file; empty: a window */
  uraRiskSet risk;   /* deployment reliability, distributions, SORA (above) */
} uraState;

/* one part of the model set (human, ra3, airbags, sim, or loaded from a file) */
typedef struct {
  char name[urNAMELEN];
  char* text;                          /* owned */
  char origin[256];                    /* "built-in" or the file it came from */
  int line;                            /* line of the origin where the part starts */
  char group[uraMAXPARTS * urNAMELEN]; /* every part its load brought, in the text's order,
                                          ' '-separated: save session drops those gone since */
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
/* the last trace (c->trace, ura_last_trace) starts with this many derived signals (static names),
   then one per sensor channel (names allocated) */
#define uraTRACE_NDERIVED 6

/* one sweep kept for plot sweep and export sweep (cmd_sweep.c): Q per wind or face value */
#define uraMAXSWEEPS 32
typedef struct {
  char casename[8];
  int over_face;                 /* 0: over wind (face fixed), 1: over face (wind fixed) */
  double fixed;                  /* the face (deg) of a wind sweep, the wind (m/s) of a face one */
  double step;                   /* grid pitch, m */
  char changes[200];             /* settings that differ from the case preset, or "none" */
  int n;                         /* values, in increasing order */
  double *x, *speed, *angle, *q; /* n values each, in one block at x (owned): no limit but
                                    the command's length */
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
  const char* srcdir;  /* folder of the script being run (a relative model load looks there
                          first), or NULL at the prompt */
  const char* savedir; /* folder of the session file being written (model load paths are
                          written relative to it), or NULL: the paths as loaded */
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
  char noted[240];   /* the last note on a set-up (a start pose that may overlap the person):
                                      each is printed once */
  urImpactWork work; /* the single-impact work space (histories of the last impact) */
  int have_work;
  int have_impact; /* the work holds a finished impact */
  urImpactResult last_impact;
  double last_dpar, last_dperp;
  int last_aim;          /* the last impact was aimed (impact aim): the two are the
                                      eccentricity up, side */
  uraModelCache* mcache; /* other models with their stances (NULL until one is kept) */
  uraRecall* recall;     /* complete grids for recall (NULL until one is kept) */
  urMemCache* memcache;  /* the session's inflated membrane bags (model.c compile; NULL until
                            the first compile), freed with the models */
  unsigned long tick;    /* use counter of both, for least-recently-used eviction */
  /* run (or recall) the impact of one grid cell and its histories, for the viewer; NULL: the
     viewer shows stored cell values only (main sets the command layer's ura_inspect_cell) */
  int (*inspect)(struct uraCtx* c, urCell* cell, uraTrace* trace);
  struct uraMc* mc;       /* the last montecarlo's samples (NULL: none; cmd_montecarlo.c) */
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
  /* with scale: called before each grid runs, to share out its cells (set with scale by the
     scale layer; the grid command calls it without knowing the distributors) */
  void (*scale_grid)(struct uraCtx* c, urGridSpec* spec, urGridDist* d);
  /* with scale: called with each file the run reads (a script, a sourced file, a model, a grid),
     open as f, so that a shard's part never replaces an input of the run (ura_input_seen) */
  void (*scale_input)(struct uraCtx* c, FILE* f, const char* path);
  int mute;              /* results, notes, files and plots go nowhere (scale.h) */
  struct uraReport* rep; /* the results kept for report (report.h; NULL: none yet) */
  struct uraUndo* undo;  /* the states undo goes back to (undo.c; NULL: none yet) */
  int undo_nest;         /* commands running inside a command (source): recorded as one */
  /* the report's hooks (ura_report_install; the report layer sits above the commands): around
     each command (script.c), and each printed table (output.c); NULL: nothing is kept */
  void (*rep_begin)(struct uraCtx* c, int argc, char** argv);
  void (*rep_end)(struct uraCtx* c, int rc);
  void (*rep_table)(struct uraCtx* c, const struct uraTable* t);
  /* while export writes a file: a JSON array that each printed table's columns (with units),
     notes and row count are appended to, for the FILE.meta.json beside it (NULL: none) */
  json_t* export_meta;
  int export_notes; /* with export_meta: the notes go to c->msg too (an export at the prompt) */
} uraCtx;

/* record a failure message; always returns -1 */
int ura_fail(uraCtx* c, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

void ura_init(uraCtx* c);
void ura_state_defaults(uraState* s);

/* in dry mode, refuse WHAT (a simulation, plot, file...) with a message; 0 otherwise */
int ura_dry(uraCtx* c, const char* what);

/* ---- the risk settings (their defaults: state.c) and declared distributions (risk_dist.c) ---- */

void ura_risk_defaults(uraRiskSet* r);
/* the highest of the population density bands (SORA 2.5 takes the highest in the footprint) */
double ura_risk_density_max(const uraRiskSet* r);
/* show and save session: the declared distributions, as '# ...' lines or as dist commands */
void ura_dist_show(uraCtx* c);
void ura_dist_save(uraCtx* c, FILE* f);
/* index of a declared input, or -1 */
int ura_dist_find(const uraRiskSet* r, const char* name);
/* the accepted range of an input that may be declared: 0, or -1 (with a message) when NAME
   cannot be drawn */
int ura_dist_range(uraCtx* c, const char* name, double* lo, double* hi);
/* the distribution as the arguments of a dist command ("weibull 5 2") */
void ura_dist_format(const uraDistDecl* d, char* buf, size_t n);
int ura_cmd_dist(uraCtx* c, int argc, char** argv);

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
  /* uraP_ENUM: NULL-terminated names; uraP_STR: words completion offers, the first shown for
     the empty value (NULL: none, the empty value shows as default) */
  const char* const* choices;
  /* uraP_STR: checks a value and writes what is kept into norm (n bytes); 0, or -1 with the
     failure recorded (NULL: any text of the size) */
  int (*check)(struct uraCtx* c, const char* value, char* norm, size_t n);
  size_t cntoff; /* uraP_LIST: offset of its int count in uraState (0: the winds' nwinds) */
} uraParam;

extern const uraParam ura_params[];
const uraParam* ura_param_find(const char* name);
int ura_param_set(uraCtx* c, const uraParam* p, const char* value);
/* sora's M2 baseline: uraM2_UNMITIGATED, uraM2_TABLE_B8 or uraM2_DESIGN (then *design, when
   not NULL, points at the design's name in r) */
enum {
  uraM2_UNMITIGATED = 0,
  uraM2_TABLE_B8,
  uraM2_DESIGN
};
int ura_m2_baseline(const uraRiskSet* r, const char** design);
/* the value as text (without unit) into buf, exact (round-trips through set); a derivable
   value that is not set prints as auto */
void ura_param_format(const uraCtx* c, const uraParam* p, char* buf, size_t n);
/* the same as show prints it: numbers through ura_num_show (5.14444 for 10 kt) */
void ura_param_display(const uraCtx* c, const uraParam* p, char* buf, size_t n);

/* the injury settings (core table) through set/show: index of NAME or -1; set; one show line */
int ura_injury_find(const char* name);
int ura_injury_set(uraCtx* c, int i, const char* value);
void ura_injury_line(uraCtx* c, int i, char* buf, size_t n, int with_unit);

/* current impact speed and angle: set values, or derived at the live wind from the descent
   model or (set descent paper) the paper's Table 2 */
int ura_impact_conditions(uraCtx* c, double* speed, double* angle);
/* 1 if the live speed or angle is derived from the paper's Table 2 */
int ura_paper_speed(const uraCtx* c);

/* the paper's Table 2 (paper.c): speed (m/s) and descent angle (deg) of a case at a wind:
   case C's column for C, case B's for A, A1, A2 and B; only the printed winds 0, 2, ..., 10
   m/s. 0, or -1 with a message naming the wind and the accepted ones */
int ura_paper_descent(uraCtx* c, const char* casename, double wind, double* speed, double* angle);
/* the column of Table 2 a case takes: "B" or "C" */
const char* ura_paper_descent_column(const char* casename);

/* load a case: a preset of the model (the RA3's A, B, C, A1, A2; wind and face are kept); the
   model's first preset (none: nothing) */
int ura_case_load(uraCtx* c, const char* name);
int ura_case_default(uraCtx* c);
/* presets: by name (any case), the names as "A, B or C" (case.c), the state a case starts
   from (the live wind, face, lists, step and output settings kept; preset.c) */
const urPreset* ura_preset_find(uraCtx* c, const char* name);
void ura_preset_names(uraCtx* c, char* buf, size_t n);
int ura_preset_state(uraCtx* c, const urPreset* pr, const urModel* m, uraState* ns);
/* the same, keeping those settings from keep rather than from the live state */
int ura_preset_state_from(uraCtx* c, const urPreset* pr, const urModel* m, const uraState* keep,
                          uraState* ns);
/* what a case or reset drops (dropped.c): the settings of state now that differ from base (the
   state its case starts with: what the user changed) and from next (what comes), as "name value
   unit, ..." into buf (n bytes); the length (0: nothing dropped) */
size_t ura_dropped(uraCtx* c, const uraState* now, const uraState* base, const uraState* next,
                   char* buf, size_t n);
/* the state the live case starts with: its preset on the defaults; keep_live: the settings a
   case keeps (wind, face, step, ...) as they are live, else their defaults (case.c) */
int ura_case_baseline(uraCtx* c, int keep_live, uraState* base);
/* the note of what a case or reset dropped (list from ura_dropped; empty: none) on c->msg at
   the prompt (a script stays quiet): "WHO: drops LIST (...; undo brings them back)" */
void ura_dropped_note(uraCtx* c, const char* who, const char* list);

/* undo (undo.c): the states before the last commands that changed the settings */
#define uraUNDO_LEVELS 32
typedef struct uraUndo uraUndo;
void ura_undo_push(uraCtx* c, const uraState* before, const char* what);
/* the newest state made live again (the model compiled for it) and popped; what the command
   that left it was into what; 0, or -1 with a message (nothing to undo; the model, its parts
   changed since, refuses it: that level is dropped all the same) */
int ura_undo_pop(uraCtx* c, char* what, size_t n);
int ura_undo_levels(const uraCtx* c);
void ura_undo_free(uraCtx* c);
/* design parameters: mass also as the multibody drone's total (its role mass= parameter, as an
   override of ns; user: set by the user; preset.c), the models a setting changes (design.c) */
int ura_design_mass(const urModel* m, uraState* ns, double mass, int user);
int ura_design_set(uraCtx* c, const char* name, const char* value, const char* unit);
const char* ura_design_reach(uraCtx* c, const char* name);
const char* ura_design_mark(uraCtx* c, const char* name, char* buf, size_t n);

/* the checks of the terminal and output settings (plot_term.c): a terminal is a known name with
   checked options (kept normalised: fonts in single quotes), an output a file name that gnuplot
   cannot take for a pipe; both can be written back by save session */
int ura_terminal_check(uraCtx* c, const char* value, char* norm, size_t n);
int ura_output_check(uraCtx* c, const char* value, char* norm, size_t n);
/* a speed parameter's value or list typed in UNIT (km/h, kt, m/s) as text in m/s into out (n
   bytes), for ura_param_set; 0, or -1 with a message that starts with who (speed.c) */
int ura_speed_convert(uraCtx* c, const char* who, const uraParam* p, const char* value,
                      const char* unit, char* out, size_t n);
/* the terminal names set terminal accepts, after "default" (completion; plot_term.c) */
extern const char* const ura_term_choices[];
/* what a gnuplot terminal draws on (plot_term.c) */
enum {
  uraTERM_WINDOW = 0,
  uraTERM_TEXT,
  uraTERM_FILE
};

/* the kind of a terminal setting (its first word; empty: gnuplot's default window) */
int ura_term_kind(const char* term);

/* the terminal an output file's extension implies (.png pngcairo, .svg, .pdf pdfcairo, .eps
   epscairo, .txt dumb, .jpg/.jpeg jpeg, .gif), NULL for none */
const char* ura_term_for_ext(const char* path);

/* index of a signal of a trace by name, or -1 (model.c) */
int ura_trace_find(const uraTrace* tr, const char* name);

/* keep a finished impact (its work space holds the histories) as the last impact, with the case
   and wind it ran for (case.c) */
void ura_impact_keep(uraCtx* c, const char* casename, double wind, const urImpactCond* cond,
                     double dpar, double dperp, const urImpactResult* r);
/* the last grid (c->last) freed (case.c); a grid CSV read into it (gridload.c) */
void ura_last_free(uraCtx* c);
int ura_grid_load(uraCtx* c, const char* path);

/* models (model.c) */
int ura_models_init(uraCtx* c);
void ura_models_free(uraCtx* c);
void ura_trace_free(uraCtx* c);            /* the signals of the last trace (c->trace) */
const urModel* ura_model(uraCtx* c);       /* compiled model, or NULL with c->err */
const urImpactSetup* ura_setup(uraCtx* c); /* settled stance, or NULL with c->err */
/* the live model's membrane bags inflated (compiling leaves them not inflated): what needs
   the inflated state calls it (ura_setup for every run, 'show bag'); 0, or -1 with c->err */
int ura_model_inflate(uraCtx* c);
void ura_model_stale(uraCtx* c);
int ura_model_param_find(uraCtx* c, const char* name); /* index in the model, or -1 */
/* the values a model parameter accepts, for messages: "0.15 to 0.65 m: REASON" (its range,
   param ... range= why=, uasimpact-model(5)), or "any number" */
void ura_param_range_text(uraCtx* c, const urParam* p, char* buf, size_t n);
/* a model parameter's value for messages, six digits and its SI unit: "1e+20 N*m/rad" */
void ura_model_value_brief(uraCtx* c, const char* name, double v, char* buf, size_t n);
int ura_model_param_set(uraCtx* c, const char* name, const char* value, const char* unit, int user);
/* the parameter a model parameter follows while it is not set (param NAME $OTHER,
   urParam.from): "$OTHER", or "$OTHER x F" when its line's unit scales it; 0, or -1 (it holds
   its own value; buf "") */
int ura_model_param_from(const urModel* m, const urParam* p, char* buf, size_t n);
/* the values the compiled model derives for its airbags (not parameters: set none of them),
   one '#' line per bag: which bag model, and for a membrane its mesh, fabric mass, stable step
   and sub-steps, inflated volume and pressure, strain once inflated (show, model params) */
void ura_bag_derived(uraCtx* c, FILE* f, uraTable* t);
/* one line per value the model language derived from materials and sections (hinges, contact
   laws, layers, shell springs and crush loads: formula and inputs), "# derived, ..." to f, or
   a note of t (show, model params) */
void ura_model_derived(uraCtx* c, FILE* f, uraTable* t);
/* the live state becomes ns if the model compiles with its parameter overrides (unchanged
   overrides keep the model and its stance); else nothing changes and WHO: refused ... */
int ura_model_state(uraCtx* c, const uraState* ns, const char* who);
int ura_cmd_model(uraCtx* c, int argc, char** argv);
/* the model parts as session commands: model drop for each built-in part missing, model load
   for each loaded one */
void ura_model_write_parts(uraCtx* c, FILE* f);
/* model save FILE: the model set with the parameters the user set written into their param
   lines and the live case's preset (model_save.c) */
int ura_model_save(uraCtx* c, const char* path);
/* the name of a loaded model file (origin, as loaded) for a file written in folder at: relative
   to at when the model is in it or below, else absolute; origin itself when at is NULL or a name
   cannot be resolved (built-in) (model.c) */
const char* ura_model_origin_at(const char* at, const char* origin, char* buf, size_t n);

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

/* what a session leaves out (session_base.c): the state 'reset; case NAME' gives with the live
   model parts (0, or -1: the defaults, the case is not a preset); the shortest text of v that
   reads back exactly; a model parameter's value in the unit that writes it shortest and exactly
   ("1.1 atm", "26 kN", "0.25 m") */
int ura_session_base(uraCtx* c, uraState* base);
void ura_num_shortest(char* buf, size_t n, double v);
/* v as show prints it: at most 10 significant digits when they give v but for rounding noise
   (111457.5), else 6 (5.14444 for 10 kt) */
void ura_num_show(char* buf, size_t n, double v);
void ura_model_value_text(uraCtx* c, const char* name, double v, char* buf, size_t n);
/* the settings a grid depends on that differ from the case preset, "name=value ..." or "none"
   (session_base.c) */
void ura_sweep_changes(uraCtx* c, char* buf, size_t n);

/* ---- output under the session's settings (output.c) ---- */

/* a command typed at the prompt writes to a terminal; the width text wraps at (0: no wrapping:
   not at a terminal, or format wide); gather a command's output and page it when taller than
   the screen (pager.c), the results stream c->out swapped meanwhile */
int ura_at_terminal(const uraCtx* c);
int ura_text_width(const uraCtx* c);
int ura_pager_begin(uraCtx* c, const char* cmd);
void ura_pager_end(uraCtx* c);
/* print a table (aligned, CSV or JSON per the format setting) to c->out and free it; in CSV
   the notes as '# ' lines before the header, but during an export to c->export_meta (and at
   the prompt to c->msg) */
void ura_table_print(uraCtx* c, uraTable* t);
/* the unit of a column the workbench writes, by its name ("" dimensionless or a count; NULL
   not one unit: a text or a column whose unit depends on the table) */
const char* ura_column_unit(const char* name);
/* write the sidecar PATH.meta.json of an exported file (only when PATH is a regular file): the
   program, the command, the case and tables (the JSON array export gathered in
   c->export_meta); 0, or -1 with c->err */
int ura_export_meta(uraCtx* c, const char* path, const char* what, json_t* tables);
/* a file name a writer of one format takes (who writes writes, e.g. "HTML", in the extensions
   exts, "html htm"): 0, or -1 with one line saying so when its extension names another format
   (report x.txt; output.c) */
int ura_name_fits(uraCtx* c, const char* who, const char* path, const char* writes,
                  const char* exts);
/* files written atomically (atomic.c) for a command: refused in dry mode, to /dev/null when
   muted (a shard, an MPI rank but 0); a failure recorded in c->err */
int ura_atomic_open(uraCtx* c, uraAtomic* a, const char* path, const char* who);
/* a file the run reads, open as f: handed to c->scale_input when the work is split (output.c) */
void ura_input_seen(uraCtx* c, FILE* f, const char* path);
/* the same for a file another process writes by the name a->tmp (gnuplot): only a regular file
   or a new one, and written even when muted */
int ura_atomic_open_file(uraCtx* c, uraAtomic* a, const char* path, const char* who);
int ura_atomic_close(uraCtx* c, uraAtomic* a, int ok, const char* who);
/* "did you mean" over the parameter tables (the workbench's, the injury settings, the live
   model's parameters) (state.c) */
void ura_suggest_params(uraCtx* c, uraSuggest* s);

#endif