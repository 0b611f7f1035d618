/* report.h: the study report (report FILE.html): what the session computed is kept as it is
 * printed (report_log.c: every table of grid, sweep, design compare, risk, montecarlo, sora,
 * converge, compare, descent and parametric, with the command line, its notes, the settings it
 * ran under and a copy of each grid), then written as one self-contained HTML file (report.c,
 * libxml2's HTML tree and serializer) with figures drawn by gnuplot's svg terminal and embedded
 * as data: images (report_fig.c), and the fixed texts on sources, validity and limits
 * (report_text.c). After app.h. */
#ifndef UASIMPACT_REPORT_H
#define UASIMPACT_REPORT_H

#include "../ui/ui.h"

/* one kept table */
typedef struct {
  char* cmd;  /* the command line */
  char* name; /* its command word */
  int ncol, nrow;
  char** names; /* ncol */
  char** cells; /* nrow * ncol */
  int nnote;
  char** notes;
  int settings; /* index of the settings text it ran under */
  int grid;     /* index of the grid kept with it, or -1 */
  int failed;   /* the command failed after printing it */
  int paper;    /* it ran at the paper's conditions but for case, wind, face, step (Table 17) */
  double step;  /* the grid pitch it ran with, m (a sweep's rows carry none of their own) */
} uraRepTable;

/* one kept grid with its conditions */
typedef struct {
  urGrid g; /* cells owned */
  char title[400];
  int diff; /* a difference grid (design compare): P_b - P_a */
} uraRepGrid;

typedef struct uraReport {
  uraRepTable* t;
  int nt, capt;
  uraRepGrid* g;
  int ng, capg;
  char** settings; /* 'show' texts, each different from the one before */
  int nset;
  char** warn; /* warnings and failures, in order */
  int nwarn;
  char cmd[1024], name[32]; /* the command running */
  int want;                 /* it is one whose tables are kept */
  int busy;                 /* the report itself is printing (nothing is kept) */
  int dropped;              /* grids not kept (the limit) */
} uraReport;

#define uraREPMAXGRIDS 24         /* grids kept for figures */
#define uraREPMAXCELLS (4L << 20) /* their cells, at most */

/* around each command (cmd/script.c): what it is; whether it failed */
void ura_report_begin(uraCtx* c, int argc, char** argv);
void ura_report_end(uraCtx* c, int rc);
/* a printed table (case/output.c, before it is printed) */
void ura_report_table(uraCtx* c, const uraTable* t);
/* the three above as the context's hooks (main), so that the layers below call them without
   knowing the report */
void ura_report_install(uraCtx* c);
void ura_report_free(uraCtx* c);
/* a note that is a warning: it says warning, failed, extrapolated, clamped, truncated, thin
   tails, few samples, partial (PARTIAL), not complete, or that the extents were set */
int ura_report_alarm(const char* note);
int ura_cmd_report(uraCtx* c, int argc, char** argv);

/* figures: an SVG of gnuplot as a data: URI (malloc'd), or NULL with c->err */
char* ura_report_svg_grid(uraCtx* c, const uraRepGrid* g);
char* ura_report_svg_plot(uraCtx* c, const char* what); /* sweep, montecarlo, tornado */
/* the fixed texts: index k of a list; NULL past the end */
const char* ura_report_check(int k, const char** proves); /* test suite's physics checks */
const char* ura_report_limit(int k);                      /* the model's known limits */
const char* ura_report_source(int k);                     /* cited documents */
/* the paper's Table 17 as printed: case, wind, Q, and the ratio's basis (the full plane of the
   paper's grid, 0 for the printed value, -1 for the printed value and twice it); 0, or -1 past
   the end */
int ura_report_table17(int k, const char** casename, double* wind, double* q, double* basis);

#endif
