/* ui.h: the interface layer of the application (src/app/ui): the interactive loop on GNU
 * readline (repl.c), the ncurses viewer (view.c), the grid as text (gridshow.c) and the plots.
 * Includes the command layer (cmd.h); scale-out and main include this header.
 *
 * Plots: gnuplot as an external process: scripts with inline datablocks sent through a pipe,
 * under the terminal and output settings. Every function returns 0, or -1 with c->err set
 * ("plot ...: what went wrong"); none of them can end the program.
 *
 * Settings (c->st): terminal empty = gnuplot's default (a window, needs DISPLAY or
 * WAYLAND_DISPLAY), output empty = a window (or the text of a text terminal such as dumb).
 * With an output file the file is complete when the function returns: gnuplot writes a temporary
 * file beside it, renamed over it only when gnuplot succeeded and the file is checked complete;
 * on any failure an existing file of that name is left as it was. Gnuplot's warnings go to
 * c->msg; text terminals' drawings to c->out.
 */
#ifndef UASIMPACT_UI_H
#define UASIMPACT_UI_H

#include <stddef.h>
#include <stdio.h>

#include "../cmd/cmd.h"
#include "uasimpact/injury.h"

/* one x-y curve */
typedef struct {
  const char* title; /* legend entry (NULL: none) */
  const double* x;   /* n abscissae */
  const double* y;   /* n ordinates; non-finite values leave a gap */
  int n;
} uraSeries;

/* run a complete gnuplot script (commands and $NAME << EOD datablocks) after the terminal and
   output settings; who names the command in messages ("plot grid") */
int ura_gnuplot_run(uraCtx* c, const char* who, const char* script, size_t len);

/* the pieces plot.c offers the files of other kinds of plot (plot_history.c): a script writer
   run through gnuplot under the settings, a number as gnuplot reads it (NaN as a gap), and a
   text setting (set NAME "TEXT", quoted) */
typedef int (*uraPlotWriter)(uraCtx* c, FILE* f, const void* arg);
int ura_plot_script(uraCtx* c, const char* who, uraPlotWriter fn, const void* arg);
void ura_plot_num(FILE* f, double v);
void ura_plot_text(FILE* f, const char* name, const char* text);
/* a round tic spacing (1, 2 or 5 times a power of ten) that gives about n intervals over
   [lo, hi], or 0 for an empty span (the panels of plot history and plot bag) */
double ura_plot_tic_step(double lo, double hi, int n);

/* the canvas size (pixels) the next plot asks of a file terminal named without options (png,
   svg, pdfcairo, ...); 0, 0: the terminal's default */
void ura_plot_canvas(uraCtx* c, int w, int h);

/* curves in one panel: title, axis labels (NULL: none) */
int ura_plot_xy(uraCtx* c, const char* who, const char* title, const char* xlabel,
                const char* ylabel, int nser, const uraSeries* s);

/* heat map of P{F|Delta} of c->last in the band colours, axes in m */
int ura_plot_grid(uraCtx* c);
/* how a heat map's cells are drawn: one filled rectangle each, so that a viewer that scales
   the figure (a browser showing an SVG, a PDF reader) cannot blend neighbouring cells into
   colours of no band, as it smooths the one bitmap of 'with image' */
#define URA_PLOT_CELLS "with image pixels"
/* the band palette over 0..100 % and its colour bar ticked at the bands' edges */
void ura_plot_band_palette(FILE* f);

/* the PoF curves of HIC, Nij (with its AIS curves) and VC; p NULL: the documented defaults */
int ura_plot_pof(uraCtx* c, const urInjuryParams* p);

/* time histories of one impact against time in ms, one panel per signal with a legend, the
   trace's title over them; nsel 0: the six derived signals the injury criteria read (head_acc,
   neck_fz, neck_my, neck_fx, chest_defl, abd_defl; every signal when the trace has none of
   them), the one name "all": every signal. head_acc in m/s^2 is shown in g, with its HIC15
   window shaded (computed from the signal), deflections in mm */
int ura_plot_trace(uraCtx* c, const uraTrace* tr, int nsel, const char* const* names);

/* the same, with the HIC window t1-t2 (s) given (NAN: computed from the signal) */
int ura_plot_trace_hic(uraCtx* c, const uraTrace* tr, int nsel, const char* const* names, double t1,
                       double t2);

/* the membrane airbags of the last impact at first contact and at peak pressure, with the head
   (plot_bag.c) */
int ura_plot_bag(uraCtx* c);

/* Q of the kept sweeps (c->sweep) against wind or face, one curve per sweep; kind "wind" or
   "face" for one panel, NULL for every kind kept (plot_sweep.c) */
int ura_plot_sweep(uraCtx* c, const char* kind);

/* s as a gnuplot string constant: in single quotes (gnuplot substitutes nothing there), line
   breaks as '...'."\n".'...'; the only way a text reaches a plot script */
void ura_plot_quote(FILE* f, const char* s);

/* the membrane airbags of the last impact at first contact and at peak pressure, with the head
   (plot_bag.c) */
int ura_plot_bag(uraCtx* c);

/* the file tmp that gnuplot wrote under terminal term for the output shown is complete: not
   empty, the format's first bytes and end marker (PNG, JPEG, GIF, PDF, EPS, PostScript, SVG,
   HTML), for a text terminal a disk not left full (plot_file.c); 0, or -1 with c->err set */
/* the output's extension against the format the terminal writes (set output x.svg with set
   terminal png): 0, or -1 with one line naming both (plot_file.c) */
int ura_plot_name_check(uraCtx* c, const char* who, const char* term, const char* out);
int ura_plot_file_check(uraCtx* c, const char* who, const char* tmp, const char* term,
                        const char* shown);

/* factor that shows signal k in its display unit (head_acc in m/s^2: 1/g; deflections in m:
   1000, mm), and that unit */
double ura_trace_scale(const uraTrace* tr, int k, const char** unit);

/* interactive loop on GNU readline (repl.c) */
int ura_repl(uraCtx* c);

/* plot sweep NAME: Q of the kept sweeps over NAME (sweep_param.c's) against its value
   (plot_sweep.c) */
int ura_plot_psweep(uraCtx* c, const char* name);

/* plot montecarlo (Q's distribution) and plot tornado (the variance shares) (plot_mc.c) */
int ura_plot_mc(uraCtx* c, const char* what);

/* ---- texts shared by 'grid show' and 'view' ---- */

/* a cell's P in percent in 5 characters ("100.0", " 12.7"), "fail" or "?" right-aligned */
void ura_cell_text(const urCell* cell, char buf[8]);

/* "case C, wind 0 m/s, face 0 deg" (? for what is unknown) */
void ura_grid_conditions(const uraCtx* c, char* buf, size_t n);

/* "Q = 0.8469 m^2", with "(partial: N failed, M pending)" when the grid is not complete; of a
   difference grid (diff) "ΔQ = Q_b - Q_a = ..." */
void ura_grid_qtext(const urGrid* g, int diff, char* buf, size_t n);
/* the Greek capital delta in UTF-8 when the locale (LC_ALL, LC_CTYPE, LANG) is UTF-8, else "d" */
const char* ura_delta(void);

#endif
