/* plot_history.c: the time histories of one impact as gnuplot panels (plot history): one panel
 * per signal against time in ms, head acceleration in g with its HIC15 window shaded,
 * deflections in mm, every sensor channel in its own unit; 'plot history all' leaves out the
 * channels at noise level and those that repeat a derived signal (one panel per quantity).
 * Legends are plain text (no gnuplot subscripts). The script goes to gnuplot through plot.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ui.h"


/* ---- time histories ---- */

typedef struct {
  const uraTrace* tr;
  int nsel;
  const int* sel;
  double t1, t2;
} traceargs;

/* head acceleration in m/s^2 is shown in g */
static int in_g(const uraTrace* tr, int k) {
  const char* u = tr->units ? tr->units[k] : NULL;
  return !strcmp(tr->names[k], "head_acc") && u && (!strcmp(u, "m/s^2") || !strcmp(u, "m/s2"));
}

/* deflections in m are shown in mm */
static int in_mm(const uraTrace* tr, int k) {
  const char* u = tr->units ? tr->units[k] : NULL;
  size_t n = strlen(tr->names[k]);
  return u && !strcmp(u, "m") && n > 5 && !strcmp(tr->names[k] + n - 5, "_defl");
}

double ura_trace_scale(const uraTrace* tr, int k, const char** unit) {
  int g = in_g(tr, k), mm = in_mm(tr, k);
  if (unit) *unit = g ? "g" : mm ? "mm" : tr->units && tr->units[k] ? tr->units[k] : "";
  return g ? 1.0 / urGRAVITY : mm ? 1000.0 : 1.0;
}

/* what a derived signal is, for the legend (sensor channels are named by the model) */
static const char* describe(const char* name) {
  static const char* const d[][2] = {{"head_acc", "head CG acceleration, resultant"},
                                     {"neck_fz", "upper neck axial force, tension +"},
                                     {"neck_my", "upper neck moment, flexion +"},
                                     {"neck_fx", "upper neck shear force"},
                                     {"chest_defl", "chest deflection"},
                                     {"abd_defl", "abdomen deflection"},
                                     {NULL, NULL}};
  for (int i = 0; d[i][0]; i++)
    if (!strcmp(d[i][0], name)) return d[i][1];
  return name;
}

/* the legend of signal k: a derived signal's description; an airbag channel (a sensor channel
   SENSOR_p, _v, _f, _strain in Pa, m^3, N, 1) its name and what it is; others their name */
static void legend(const uraTrace* tr, int k, char* buf, size_t n) {
  static const char* const d[][3] = {{"_p", "Pa", "airbag gas pressure, absolute"},
                                     {"_v", "m^3", "airbag gas volume"},
                                     {"_f", "N", "airbag normal force on the person"},
                                     {"_strain", "1", "largest fabric yarn strain (Green)"}};
  const char* name = tr->names[k];
  const char* u = tr->units ? tr->units[k] : NULL;
  size_t len = strlen(name);
  snprintf(buf, n, "%s", describe(name));
  for (int i = 0; i < 4 && u; i++) {
    size_t sl = strlen(d[i][0]);
    if (len > sl && !strcmp(name + len - sl, d[i][0]) && !strcmp(u, d[i][1])) {
      snprintf(buf, n, "%s: %s", name, d[i][2]);
    }
  }
}

static int write_trace(uraCtx* c, FILE* f, const void* arg) {
  const traceargs* a = arg;
  const uraTrace* tr = a->tr;
  int cols = a->nsel > 4 ? 2 : 1, rows = (a->nsel + cols - 1) / cols;

  /* one datablock: time in ms, then the selected signals in their display units */
  fprintf(f, "$T << EOD\n");
  for (int i = 0; i < tr->n; i++) {
    ura_plot_num(f, tr->t[i] * 1000.0);
    for (int s = 0; s < a->nsel; s++) {
      int k = a->sel[s];
      fputc(' ', f);
      ura_plot_num(f, tr->v[(size_t)k * tr->n + i] * ura_trace_scale(tr, k, NULL));
    }
    fputc('\n', f);
  }
  fprintf(f, "EOD\n");

  /* the impact's conditions as the title; one panel per signal with a legend, the time axis
     labelled under the bottom panels; the HIC window shaded on head_acc */
  /* the legend in a band left free above the curves */
  fprintf(f,
          "set grid\nset key top right box opaque noenhanced samplen 2\n"
          "set offsets 0, 0, graph %g, 0\n",
          a->nsel > 1 ? 0.45 : 0.2);
  if (a->nsel > 1) {
    fprintf(f, "set multiplot layout %d,%d", rows, cols);
    if (tr->title) {
      fprintf(f, " title ");
      ura_plot_quote(f, tr->title);
      fprintf(f, " noenhanced");
    }
    fprintf(f, "\nset lmargin 14\nset key font \",9\"\n");
    /* many rows (history all): small type, so that labels and tic marks of neighbouring panels
       do not run into each other */
    if (rows > 4) fprintf(f, "set tics font \",8\"\nset key font \",8\"\n");
  } else if (tr->title) {
    ura_plot_text(f, "title", tr->title);
  }
  for (int s = 0; s < a->nsel; s++) {
    int k = a->sel[s];
    const char* unit;
    double sc = ura_trace_scale(tr, k, &unit), lo = INFINITY, hi = -INFINITY;
    char label[128];
    snprintf(label, sizeof label, "%s%s%s%s", tr->names[k], *unit ? " (" : "", unit,
             *unit ? ")" : "");
    ura_plot_text(f, "ylabel", label);
    if (rows > 4) fprintf(f, "set ylabel font \",8\"\n");
    if (a->nsel == 1 || s >= a->nsel - cols)
      fprintf(f, "set xlabel \"t (ms from tau)\"%s\n", rows > 4 ? " font \",9\"" : "");
    else
      fprintf(f, "unset xlabel\n");

    for (int i = 0; i < tr->n; i++) {
      double v = tr->v[(size_t)k * tr->n + i] * sc;
      if (isfinite(v)) {
        lo = fmin(lo, v);
        hi = fmax(hi, v);
      }
    }
    /* in small panels about four tic intervals, in the many rows of history all two */
    double dy = a->nsel > 1 ? ura_plot_tic_step(lo, hi, rows > 4 ? 2 : 4) : 0;
    if (dy > 0)
      fprintf(f, "set ytics %.9g\n", dy);
    else
      fprintf(f, "set ytics autofreq\n");

    fprintf(f, "unset object\n");
    int hic = !strcmp(tr->names[k], "head_acc") && isfinite(a->t1) && a->t2 > a->t1;
    if (hic) {
      fprintf(f,
              "set object 1 rect from %.9g, graph 0 to %.9g, graph 1 behind "
              "fc rgb '#ffd580' fs solid 0.6 noborder\n",
              a->t1 * 1e3, a->t2 * 1e3);
    }
    char what[160];
    legend(tr, k, what, sizeof what);
    fprintf(f, "plot $T using 1:%d with lines lw 2 title ", s + 2);
    ura_plot_quote(f, what);
    fprintf(f, " noenhanced"); /* names hold '_': no subscripts */
    if (hic) {
      char key[128];
      snprintf(key, sizeof key, "HIC15 window %.2f-%.2f ms", a->t1 * 1e3, a->t2 * 1e3);
      fprintf(f, ", keyentry with boxes fc rgb '#ffd580' fs solid 0.6 noborder title ");
      ura_plot_quote(f, key);
      fprintf(f, " noenhanced");
    }
    fprintf(f, "\n");
  }
  if (a->nsel > 1) fprintf(f, "unset multiplot\n");
  return 0;
}

/* a channel that stays at rounding noise: its largest |value| below 1e-9 (SI units), or below
   1e-9 of the largest of the channels of its sensor (the names before the last '_') */
static int noise(const uraTrace* tr, int k) {
  double peak = 0, ref = 0;
  const char* us = strrchr(tr->names[k], '_');
  size_t stem = us ? (size_t)(us - tr->names[k]) : strlen(tr->names[k]);
  for (int j = 0; j < tr->nsig; j++) {
    const char* uj = strrchr(tr->names[j], '_');
    size_t sj = uj ? (size_t)(uj - tr->names[j]) : strlen(tr->names[j]);
    if (sj != stem || strncmp(tr->names[j], tr->names[k], stem)) continue;
    for (int i = 0; i < tr->n; i++) {
      double a = fabs(tr->v[(size_t)j * tr->n + i]);
      if (j == k && a > peak) peak = a;
      if (a > ref) ref = a;
    }
  }
  return peak < 1e-9 || peak < 1e-9 * ref;
}

/* a sensor channel that repeats a derived signal (the same samples, or their negatives: the
   neck loads and deflections the injury criteria read in their own signs), which 'plot history
   all' leaves out so that each quantity is drawn once */
static int duplicate(const uraTrace* tr, int k) {
  if (describe(tr->names[k]) != tr->names[k] && ura_trace_find(tr, tr->names[k]) == k) return 0;
  for (int d = 0; d < tr->nsig; d++) {
    if (d == k || describe(tr->names[d]) == tr->names[d] || ura_trace_find(tr, tr->names[d]) != d)
      continue;
    for (int sign = -1; sign <= 1; sign += 2) {
      double peak = 0, off = 0;
      for (int i = 0; i < tr->n; i++) {
        double a = tr->v[(size_t)k * tr->n + i], b = tr->v[(size_t)d * tr->n + i];
        peak = fmax(peak, fabs(b));
        off = fmax(off, fabs(a - sign * b));
      }
      if (peak > 0 && off <= 1e-9 * peak) return 1;
    }
  }
  return 0;
}

int ura_plot_trace_hic(uraCtx* c, const uraTrace* tr, int nsel, const char* const* names, double t1,
                       double t2) {
  const char* who = "plot history";
  if (!tr || tr->n < 2 || tr->nsig < 1 || !tr->t || !tr->v || !tr->names) {
    return ura_fail(c, "%s: no impact yet", who);
  }

  /* the selected signals by name; none named: the derived ones (what the injury criteria
     read), or every signal when the trace has none of them; "all": every signal */
  int every = nsel == 1 && !strcmp(names[0], "all");
  int* sel = malloc((size_t)(nsel > 0 ? nsel : 0) * sizeof *sel + (size_t)tr->nsig * sizeof *sel);
  if (!sel) return ura_fail(c, "%s: out of memory", who);
  int n = 0, head = -1;
  if (nsel == 0) {
    for (int k = 0; k < tr->nsig; k++) {
      if (describe(tr->names[k]) != tr->names[k] && ura_trace_find(tr, tr->names[k]) == k) {
        sel[n++] = k;
      }
    }
  }
  if (every || n == 0) {
    for (int k = 0; k < tr->nsig && nsel == 0; k++) sel[n++] = k;
    int left = 0, dup = 0;
    for (int k = 0; k < tr->nsig && every; k++) {
      if (noise(tr, k))
        left++;
      else if (duplicate(tr, k))
        dup++;
      else
        sel[n++] = k;
    }
    if (left && c->interactive) {
      fprintf(c->msg, "%s all: %d channel%s that stay at noise level (|value| < 1e-9) left out\n",
              who, left, left == 1 ? "" : "s");
    }
    if (dup && c->interactive) {
      fprintf(c->msg,
              "%s all: %d sensor channel%s that repeat a derived signal (the same or "
              "opposite sign) left out\n",
              who, dup, dup == 1 ? "" : "s");
    }
  }
  for (int s = 0; s < nsel && !every; s++) {
    int k;
    for (k = 0; k < tr->nsig && strcmp(tr->names[k], names[s]); k++) {
    }
    if (k == tr->nsig) {
      char list[512], dym[120];
      size_t m = 0;
      uraSuggest sg;
      ura_suggest_init(&sg, names[s]);
      list[0] = 0;
      for (int j = 0; j < tr->nsig && m < sizeof list; j++) {
        if (ura_trace_find(tr, tr->names[j]) != j) continue; /* each name once */
        ura_suggest_add(&sg, tr->names[j]);
        m += (size_t)snprintf(list + m, sizeof list - m, "%s%s", m ? ", " : "", tr->names[j]);
      }
      free(sel);
      return ura_fail(c, "%s: no signal '%s'%s; signals: %s (or all)", who, names[s],
                      ura_suggest_text(&sg, dym, sizeof dym), list);
    }
    sel[n++] = k;
  }
  for (int s = 0; s < n; s++) {
    if (!strcmp(tr->names[sel[s]], "head_acc")) head = sel[s];
  }

  /* HIC15 window from the head acceleration when not given */
  if (head >= 0 && !(isfinite(t1) && t2 > t1)) {
    double* a = malloc((size_t)tr->n * sizeof *a);
    urHic h;
    t1 = t2 = NAN;
    if (a) {
      for (int i = 0; i < tr->n; i++) {
        double v = tr->v[(size_t)head * tr->n + i];
        a[i] = in_g(tr, head) ? v / urGRAVITY : v;
      }
      if (!ur_hic(tr->t, a, tr->n, 0.015, NULL, &h) && h.hic > 0) {
        t1 = h.t1;
        t2 = h.t2;
      }
      free(a);
    }
  }
  traceargs ta = {tr, n, sel, t1, t2};
  if (n > 1) {
    int cols = n > 4 ? 2 : 1, rows = (n + cols - 1) / cols;
    ura_plot_canvas(c, cols == 1 ? 800 : 1100, 80 + 230 * rows);
  }
  int rc = ura_plot_script(c, who, write_trace, &ta);
  ura_plot_canvas(c, 0, 0);
  free(sel);
  return rc;
}

int ura_plot_trace(uraCtx* c, const uraTrace* tr, int nsel, const char* const* names) {
  return ura_plot_trace_hic(c, tr, nsel, names, NAN, NAN);
}
