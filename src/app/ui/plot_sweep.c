/* plot_sweep.c: plot sweep: Q of the kept sweeps (cmd_sweep.c, sweep_param.c) against wind
 * speed (the paper's Figs 10, 11 and 13), face direction or any swept parameter, one curve per
 * sweep, one panel per kind: plain 'plot sweep' draws every kind kept, each in its own panel
 * (a multiplot), never dropping one. What all curves of a panel share (face or wind, grid step,
 * changed settings) goes into its title, what tells them apart into the legend. A parameter's
 * sweeps share one axis in one unit (the first sweep's: atm and kPa sweeps of one pressure are
 * drawn in atm, the kPa values converted).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ui.h"


/* do all sweeps of a kind share the fixed value, the step, the changes? */
typedef struct {
  int n;                    /* sweeps of the kind */
  int fixed, step, changes; /* 1: the same in all of them */
} shared;

static shared common(const uraCtx* c, int over_face) {
  shared s = {0, 1, 1, 1};
  const uraSweep* first = NULL;
  for (int i = 0; i < c->nsweep; i++) {
    const uraSweep* w = &c->sweep[i];
    if (w->over_face != over_face) continue;
    s.n++;
    if (!first) {
      first = w;
      continue;
    }
    if (w->fixed != first->fixed) s.fixed = 0;
    if (w->step != first->step) s.step = 0;
    if (strcmp(w->changes, first->changes)) s.changes = 0;
  }
  return s;
}

/* write the datablock and the plot command of one panel; a sweep keeps its colour and point
   type in both panels (colour-blind safe, no yellow on white) */
static void panel(uraCtx* c, FILE* f, int over_face) {
  static const char* const colours[8] = {"#9400d3", "#009e73", "#56b4e9", "#e69f00",
                                         "#0072b2", "#d55e00", "#cc79a7", "#000000"};
  shared sh = common(c, over_face);
  const uraSweep* first = NULL;
  char title[800], cases[64] = "";
  size_t k = 0;

  /* one datablock per sweep: value, Q */
  for (int i = 0; i < c->nsweep; i++) {
    const uraSweep* w = &c->sweep[i];
    if (w->over_face != over_face) continue;
    if (!first) first = w;
    if (!strstr(cases, w->casename) && strlen(cases) + strlen(w->casename) + 3 < sizeof cases) {
      if (*cases) strcat(cases, ", ");
      strcat(cases, w->casename);
    }
    fprintf(f, "$%c%d << EOD\n", over_face ? 'F' : 'W', i);
    for (int j = 0; j < w->n; j++) fprintf(f, "%.9g %.9g\n", w->x[j], w->q[j]);
    fprintf(f, "EOD\n");
  }

  /* the title: what the curves share */
  k = (size_t)snprintf(title, sizeof title, "Q against %s; case%s %s",
                       over_face ? "face direction" : "horizontal wind",
                       strchr(cases, ',') ? "s" : "", cases);
  if (sh.fixed) {
    k += (size_t)snprintf(title + k, sizeof title - k,
                          over_face ? ", wind %g m/s" : ", face %g deg", first->fixed);
  }
  if (sh.step) k += (size_t)snprintf(title + k, sizeof title - k, ", grid step %g m", first->step);
  if (sh.changes && strcmp(first->changes, "none") && k < sizeof title) {
    snprintf(title + k, sizeof title - k, "\n%s", first->changes);
  }
  fprintf(f, "set title ");
  ura_plot_quote(f, title);
  fprintf(f, " noenhanced\n");
  if (over_face) {
    fprintf(f,
            "set xlabel \"face direction phi (deg; 0 faces the incoming drone)\" noenhanced\n"
            "set xtics 45\n");
  } else {
    fprintf(f, "set xlabel \"horizontal wind speed (m/s)\" noenhanced\nset xtics autofreq\n");
  }
  fprintf(f,
          "set ylabel \"Q (m^2)\" noenhanced\nset yrange [0:*]\nset autoscale xfix\n"
          "set offsets graph 0.04, graph 0.04, graph 0.1, 0\n");

  /* one curve per sweep; the legend says what differs */
  fprintf(f, "plot ");
  int first_curve = 1;
  for (int i = 0; i < c->nsweep; i++) {
    const uraSweep* w = &c->sweep[i];
    char label[400];
    size_t m;
    if (w->over_face != over_face) continue;
    m = (size_t)snprintf(label, sizeof label, "case %s", w->casename);
    if (!sh.fixed) {
      m += (size_t)snprintf(label + m, sizeof label - m,
                            over_face ? ", wind %g m/s" : ", face %g deg", w->fixed);
    }
    if (!sh.step) m += (size_t)snprintf(label + m, sizeof label - m, ", step %g m", w->step);
    if (!sh.changes && strcmp(w->changes, "none") && m < sizeof label) {
      snprintf(label + m, sizeof label - m, ", %s", w->changes);
    }
    fprintf(f, "%s$%c%d using 1:2 with linespoints lc rgb '%s' lw 2 pt %d ps 1.2 title ",
            first_curve ? "" : ", ", over_face ? 'F' : 'W', i, colours[i % 8], 5 + 2 * (i % 4));
    ura_plot_quote(f, label);
    first_curve = 0;
  }
  fprintf(f, "\n");
}

/* a label with its quotes and backslashes escaped for gnuplot */
static void quoted(FILE* f, const char* s) {
  fputc('"', f);
  for (; *s; s++) {
    if (*s == '"' || *s == '\\') fputc('\\', f);
    fputc(*s, f);
  }
  fputc('"', f);
}

/* the factor from a sweep's unit to the axis unit (both of the language: atm, kPa, Pa, deg...);
   0 when they cannot share an axis */
static double to_axis(const char* unit, const char* axis) {
  double fu = 1, fa = 1;
  char su[64] = "", sa[64] = "";
  if (!strcmp(unit, axis)) return 1;
  if (ur_unit_parse(unit, &fu, su, sizeof su) || ur_unit_parse(axis, &fa, sa, sizeof sa)) return 0;
  return strcmp(su, sa) ? 0 : fu / fa;
}

/* the datablocks and the plot command of the panel of the sweeps over parameter name: one
   axis in one unit, the first sweep's (the others converted to it, their legend saying the
   unit they were entered in); -1 with c->err when two units cannot share an axis */
static int psweep_panel(uraCtx* c, FILE* f, const char* name) {
  static const char* const colours[8] = {"#9400d3", "#009e73", "#56b4e9", "#e69f00",
                                         "#0072b2", "#d55e00", "#cc79a7", "#000000"};
  const uraPSweep* first = NULL;
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* w = c->psweep + i;
    if (strcmp(w->param, name)) continue;
    if (!first) first = w;
    double k = to_axis(w->unit, first->unit);
    if (k == 0) {
      return ura_fail(c,
                      "plot sweep %s: the sweeps in %s and in %s cannot share an axis; 'sweep "
                      "clear' and sweep again in one unit",
                      name, first->unit, w->unit);
    }
    fprintf(f, "$P%d << EOD\n", i);
    for (int j = 0; j < w->n; j++) fprintf(f, "%.9g %.9g\n", w->x[j] * k, w->q[j]);
    fprintf(f, "EOD\n");
  }
  /* what every curve shares goes into the title, what differs into the legend */
  int same_wind = 1, same_face = 1, same_changes = 1;
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* w = c->psweep + i;
    if (strcmp(w->param, name)) continue;
    same_wind &= w->wind == first->wind;
    same_face &= w->face == first->face;
    same_changes &= !strcmp(w->changes, first->changes);
  }
  char title[600], xl[100];
  size_t t =
      (size_t)snprintf(title, sizeof title, "Q against %s; grid step %g m", name, first->step);
  if (same_wind) t += (size_t)snprintf(title + t, sizeof title - t, ", wind %g m/s", first->wind);
  if (same_face) t += (size_t)snprintf(title + t, sizeof title - t, ", face %g deg", first->face);
  if (same_changes && strcmp(first->changes, "none") && t < sizeof title) {
    snprintf(title + t, sizeof title - t, "\n%s", first->changes);
  }
  snprintf(xl, sizeof xl, "%s%s%s%s", name, *first->unit ? " (" : "", first->unit,
           *first->unit ? ")" : "");
  fprintf(f, "set title ");
  ura_plot_quote(f, title); /* a newline (the changes' line) becomes "\n" */
  fprintf(f, " noenhanced\nset xlabel ");
  quoted(f, xl);
  fprintf(f,
          " noenhanced\nset xtics autofreq\nset ylabel \"Q (m^2)\" noenhanced\nset yrange [0:*]\n"
          "set autoscale xfix\nset offsets graph 0.04, graph 0.04, graph 0.1, 0\nplot ");
  int k = 0;
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* w = c->psweep + i;
    if (strcmp(w->param, name)) continue;
    char label[400];
    size_t m = (size_t)snprintf(label, sizeof label, "case %s", w->casename);
    if (!same_wind) m += (size_t)snprintf(label + m, sizeof label - m, ", wind %g m/s", w->wind);
    if (!same_face) m += (size_t)snprintf(label + m, sizeof label - m, ", face %g deg", w->face);
    if (strcmp(w->unit, first->unit) && m < sizeof label) {
      m += (size_t)snprintf(label + m, sizeof label - m, ", swept in %s", w->unit);
    }
    if (!same_changes && strcmp(w->changes, "none") && m < sizeof label) {
      snprintf(label + m, sizeof label - m, ", %s", w->changes);
    }
    fprintf(f, "%s$P%d using 1:2 with linespoints lc rgb '%s' lw 2 pt %d ps 1.2 title ",
            k ? ", " : "", i, colours[k % 8], 5 + 2 * (k % 4));
    quoted(f, label);
    k++;
  }
  fprintf(f, "\n");
  return 0;
}

/* the distinct parameters of the kept parameter sweeps, in the order first swept; their count */
static int psweep_names(const uraCtx* c, const char** names, int max) {
  int n = 0;
  for (int i = 0; i < c->npsweep; i++) {
    int seen = 0;
    for (int j = 0; j < n; j++) seen |= !strcmp(names[j], c->psweep[i].param);
    if (!seen && n < max) names[n++] = c->psweep[i].param;
  }
  return n;
}

/* the curves of the kept sweeps a panel each: wind, face, then each parameter in names (np);
   several panels as a multiplot, the same bottom margin in all (the tallest legend's) */
static int write_sweep(uraCtx* c, FILE* f, int want_wind, int want_face, const char** names,
                       int np) {
  int panels = want_wind + want_face + np;
  fprintf(f,
          "set grid\nset key below left Left reverse noenhanced samplen 3 vertical maxcols 1\n"
          "set tics out\n");
  if (panels > 1) {
    int rows = common(c, 0).n > common(c, 1).n ? common(c, 0).n : common(c, 1).n;
    for (int i = 0; i < np; i++) {
      int k = 0;
      for (int j = 0; j < c->npsweep; j++) k += !strcmp(c->psweep[j].param, names[i]);
      if (k > rows) rows = k;
    }
    fprintf(f, "set multiplot layout %d,%d\nset bmargin %d\n", panels > 3 ? 2 : 1,
            panels > 3 ? (panels + 1) / 2 : panels, 5 + (rows < 6 ? rows : 6));
  }
  if (want_wind) panel(c, f, 0);
  if (want_face) panel(c, f, 1);
  for (int i = 0; i < np; i++) {
    if (psweep_panel(c, f, names[i])) return -1;
  }
  if (panels > 1) fprintf(f, "unset multiplot\n");
  return 0;
}

/* write the script of the panels and run it, on a canvas wide enough for them */
static int run_sweep(uraCtx* c, int want_wind, int want_face, const char** names, int np) {
  const char* who = "plot sweep";
  char* s = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&s, &n);
  if (!f) return ura_fail(c, "%s: out of memory", who);
  int rc = write_sweep(c, f, want_wind, want_face, names, np);
  fclose(f);
  int panels = want_wind + want_face + np;
  if (panels > 1) {
    int cols = panels > 3 ? (panels + 1) / 2 : panels;
    ura_plot_canvas(c, 600 * cols, panels > 3 ? 1000 : 520);
  }
  if (rc == 0) rc = ura_gnuplot_run(c, who, s, n);
  ura_plot_canvas(c, 0, 0);
  free(s);
  return rc;
}

int ura_plot_sweep(uraCtx* c, const char* kind) {
  const char* who = "plot sweep";
  const char* names[64];
  int nw = common(c, 0).n, nf = common(c, 1).n;
  if (kind && strcmp(kind, "wind") && strcmp(kind, "face")) {
    return ura_plot_psweep(c, kind); /* a sweep over another parameter (sweep_param.c) */
  }
  if (kind) {
    int wind = !strcmp(kind, "wind");
    if ((wind && !nw) || (!wind && !nf)) {
      return ura_fail(c, "%s: no %s sweep yet; run 'sweep %s LIST'", who, kind, kind);
    }
    return run_sweep(c, wind, !wind, NULL, 0);
  }
  int np = psweep_names(c, names, 64);
  if (!nw && !nf && !np) {
    return ura_fail(c,
                    "%s: no sweep yet; run 'sweep wind LIST', 'sweep face LIST' or 'sweep NAME "
                    "LIST [UNIT]'",
                    who);
  }
  return run_sweep(c, nw > 0, nf > 0, names, np); /* every kind kept, a panel each */
}

int ura_plot_psweep(uraCtx* c, const char* name) {
  const char* who = "plot sweep";
  if (!name && c->npsweep) name = c->psweep[c->npsweep - 1].param;
  int n = 0;
  for (int i = 0; i < c->npsweep; i++) n += !strcmp(c->psweep[i].param, name);
  if (!n) {
    const char* names[64];
    char list[600] = "";
    size_t m = 0;
    int np = psweep_names(c, names, 64);
    for (int i = 0; i < np && m < sizeof list; i++) {
      m += (size_t)snprintf(list + m, sizeof list - m, ", plot sweep %s", names[i]);
    }
    return ura_fail(c,
                    "%s: unknown '%s'; accepted: plot sweep, plot sweep wind, plot sweep "
                    "face%s, or plot sweep NAME after 'sweep NAME LIST' (none over '%s' yet)",
                    who, name, list, name);
  }
  return run_sweep(c, 0, 0, &name, 1);
}
