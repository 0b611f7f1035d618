/* plot_sweep.c: plot sweep: Q of the kept sweeps (cmd_sweep.c) against wind speed (the paper's
 * Figs 10, 11 and 13) or face direction, one curve per sweep, one panel per kind. What all
 * curves of a panel share (face or wind, grid step, changed settings) goes into its title, what
 * tells them apart into the legend.
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

static int write_sweep(uraCtx* c, FILE* f, int want_wind, int want_face) {
  int two = want_wind && want_face;
  fprintf(f,
          "set grid\nset key below left Left reverse noenhanced samplen 3 maxrows 3\n"
          "set tics out\n");
  if (two) {
    /* the same bottom margin in both panels: the taller legend decides */
    int rows = common(c, 0).n > common(c, 1).n ? common(c, 0).n : common(c, 1).n;
    fprintf(f, "set multiplot layout 1,2\nset bmargin %d\n", 5 + (rows < 3 ? rows : 3));
  }
  if (want_wind) panel(c, f, 0);
  if (want_face) panel(c, f, 1);
  if (two) fprintf(f, "unset multiplot\n");
  return 0;
}

int ura_plot_sweep(uraCtx* c, const char* kind) {
  const char* who = "plot sweep";
  int nw = common(c, 0).n, nf = common(c, 1).n;
  int want_wind = nw > 0, want_face = nf > 0;
  if (kind && strcmp(kind, "wind") && strcmp(kind, "face")) {
    return ura_plot_psweep(c, kind); /* a sweep over another parameter (sweep_param.c) */
  }
  if (!kind && !nw && !nf && c->npsweep) return ura_plot_psweep(c, NULL);
  if (kind) {
    want_wind = !strcmp(kind, "wind");
    want_face = !want_wind;
    if ((want_wind && !nw) || (want_face && !nf)) {
      return ura_fail(c, "%s: no %s sweep yet; run 'sweep %s LIST'", who, kind, kind);
    }
  }
  if (!want_wind && !want_face) {
    return ura_fail(c, "%s: no sweep yet; run 'sweep wind LIST' or 'sweep face LIST'", who);
  }

  /* the script in memory, then to gnuplot */
  char* s = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&s, &n);
  if (!f) return ura_fail(c, "%s: out of memory", who);
  write_sweep(c, f, want_wind, want_face);
  fclose(f);
  if (want_wind && want_face) ura_plot_canvas(c, 1200, 520);
  int rc = ura_gnuplot_run(c, who, s, n);
  ura_plot_canvas(c, 0, 0);
  free(s);
  return rc;
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

int ura_plot_psweep(uraCtx* c, const char* name) {
  static const char* const colours[8] = {"#9400d3", "#009e73", "#56b4e9", "#e69f00",
                                         "#0072b2", "#d55e00", "#cc79a7", "#000000"};
  const char* who = "plot sweep";
  if (!name && c->npsweep) name = c->psweep[c->npsweep - 1].param;
  int n = 0;
  const uraPSweep* first = NULL;
  for (int i = 0; i < c->npsweep; i++) {
    if (strcmp(c->psweep[i].param, name)) continue;
    if (!first) first = c->psweep + i;
    n++;
  }
  if (!n) {
    return ura_fail(c,
                    "%s: unknown '%s'; accepted: plot sweep, plot sweep wind, plot sweep "
                    "face, or plot sweep NAME after 'sweep NAME LIST' (none over '%s' yet)",
                    who, name, name);
  }
  char* s = NULL;
  size_t len = 0;
  FILE* f = open_memstream(&s, &len);
  if (!f) return ura_fail(c, "%s: out of memory", who);
  fprintf(f,
          "set grid\nset key below left Left reverse noenhanced samplen 3 maxrows 3\n"
          "set tics out\n");
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* w = c->psweep + i;
    if (strcmp(w->param, name)) continue;
    fprintf(f, "$P%d << EOD\n", i);
    for (int j = 0; j < w->n; j++) fprintf(f, "%.9g %.9g\n", w->x[j], w->q[j]);
    fprintf(f, "EOD\n");
  }
  char title[300], xl[100];
  snprintf(title, sizeof title, "Q against %s; grid step %g m", name, first->step);
  snprintf(xl, sizeof xl, "%s%s%s%s", name, *first->unit ? " (" : "", first->unit,
           *first->unit ? ")" : "");
  fprintf(f, "set title ");
  quoted(f, title);
  fprintf(f, " noenhanced\nset xlabel ");
  quoted(f, xl);
  fprintf(f,
          " noenhanced\nset ylabel \"Q (m^2)\" noenhanced\nset yrange [0:*]\n"
          "set autoscale xfix\nset offsets graph 0.04, graph 0.04, graph 0.1, 0\nplot ");
  int k = 0;
  for (int i = 0; i < c->npsweep; i++) {
    const uraPSweep* w = c->psweep + i;
    if (strcmp(w->param, name)) continue;
    char label[400];
    snprintf(label, sizeof label, "case %s, wind %g m/s, face %g deg%s%s%s%s", w->casename, w->wind,
             w->face, strcmp(w->unit, first->unit) ? ", in " : "",
             strcmp(w->unit, first->unit) ? w->unit : "", strcmp(w->changes, "none") ? ", " : "",
             strcmp(w->changes, "none") ? w->changes : "");
    fprintf(f, "%s$P%d using 1:2 with linespoints lc rgb '%s' lw 2 pt %d ps 1.2 title ",
            k ? ", " : "", i, colours[k % 8], 5 + 2 * (k % 4));
    quoted(f, label);
    k++;
  }
  fprintf(f, "\n");
  fclose(f);
  int rc = ura_gnuplot_run(c, who, s, len);
  free(s);
  return rc;
}
