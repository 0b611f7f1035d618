/* plot_mc.c: plot montecarlo (the distribution of Q over the last montecarlo's samples: a
 * histogram with the mean, the 95 % interval of the mean and the samples' 2.5-97.5 % range) and
 * plot tornado (the first-order variance shares of its inputs, largest on top); their titles
 * on two lines, so that they fit the default 640-pixel canvas */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_histogram.h>

#include "ui.h"


/* the histogram of the samples' Q: about sqrt(n) bins (5 to 60) over their range */
static int write_hist(uraCtx* c, FILE* f) {
  const double* q;
  const urMcStats* st;
  const char* casename;
  double seed;
  int n;
  if (ura_mc_data(c, &q, &n, &st, &casename, &seed)) return -1;
  double lo = st->min, hi = st->max;
  if (hi <= lo) {
    double pad = lo > 0 ? 0.01 * lo : 1e-6;
    lo -= pad;
    hi += pad;
  }
  size_t nb = (size_t)fmin(60, fmax(5, nearbyint(sqrt((double)n))));
  gsl_histogram* h = gsl_histogram_alloc(nb);
  if (!h) return ura_fail(c, "plot montecarlo: out of memory");
  gsl_histogram_set_ranges_uniform(h, lo, nextafter(hi, INFINITY));
  for (int i = 0; i < n; i++) gsl_histogram_increment(h, q[i]);
  fprintf(f, "$H << EOD\n");
  for (size_t b = 0; b < nb; b++) {
    double a, z;
    gsl_histogram_get_range(h, b, &a, &z);
    fprintf(f, "%.9g %.9g %.9g\n", 0.5 * (a + z), gsl_histogram_get(h, b) / n, z - a);
  }
  fprintf(f, "EOD\n");
  double ymax = gsl_histogram_max_val(h) / n;
  gsl_histogram_free(h);
  fprintf(f,
          "set title \"Q over %d samples of case %s (seed %.0f)\\nmean %.4g m^2, 95 %% "
          "interval of the mean %.4g..%.4g m^2\" noenhanced\n",
          n, casename, seed, st->mean, st->lo95, st->hi95);
  fprintf(f,
          "set xlabel \"Q (m^2)\" noenhanced\nset ylabel \"fraction of the samples\" "
          "noenhanced\nset grid\nset key top right noenhanced\nset yrange [0:%.9g]\n"
          "set style fill solid 0.5 border -1\n",
          1.15 * ymax);
  fprintf(f, "set arrow 1 from %.9g, graph 0 to %.9g, graph 1 nohead lc rgb '#d55e00' lw 2\n",
          st->mean, st->mean);
  fprintf(f,
          "set object 1 rect from %.9g, graph 0 to %.9g, graph 1 behind fc rgb '#d55e00' "
          "fs transparent solid 0.2 noborder\n",
          st->lo95, st->hi95 > st->lo95 ? st->hi95 : st->lo95 + 1e-12);
  fprintf(f,
          "set arrow 2 from %.9g, graph 0 to %.9g, graph 1 nohead lc rgb '#0072b2' dt 2\n"
          "set arrow 3 from %.9g, graph 0 to %.9g, graph 1 nohead lc rgb '#0072b2' dt 2\n",
          st->p025, st->p025, st->p975, st->p975);
  fprintf(f,
          "plot $H using 1:2:3 with boxes lc rgb '#56b4e9' title \"samples\", "
          "NaN with lines lc rgb '#d55e00' lw 2 title \"mean (band: 95 %% interval of the mean)\", "
          "NaN with lines lc rgb '#0072b2' dt 2 title \"2.5 %% and 97.5 %% of the samples\"\n");
  return 0;
}

/* the tornado chart: one horizontal bar per input, largest share on top */
static int write_tornado(uraCtx* c, FILE* f) {
  const char* name[uraMAXDIST + 1 + urMAXBAGS];
  double share[uraMAXDIST + 1 + urMAXBAGS];
  int k = ura_mc_shares(c, name, share), ord[uraMAXDIST + 1 + urMAXBAGS];
  if (k == 0) {
    return ura_fail(c,
                    "plot tornado: the last montecarlo drew no input; declare one with "
                    "'dist' or set p_chute or p_bag below 1");
  }
  for (int i = 0; i < k; i++) ord[i] = i;
  for (int i = 1; i < k; i++) {
    for (int j = i; j > 0; j--) {
      double a = isnan(share[ord[j]]) ? -1 : share[ord[j]];
      double b = isnan(share[ord[j - 1]]) ? -1 : share[ord[j - 1]];
      if (a <= b) break;
      int t = ord[j];
      ord[j] = ord[j - 1];
      ord[j - 1] = t;
    }
  }
  const double* q;
  const urMcStats* st;
  const char* casename;
  double seed;
  int n;
  ura_mc_data(c, &q, &n, &st, &casename, &seed);
  fprintf(f, "$S << EOD\n");
  double sum = 0;
  for (int i = 0; i < k; i++) {
    double s = isnan(share[ord[i]]) ? 0 : share[ord[i]];
    sum += s;
    fprintf(f, "%d %.9g\n", i, s);
  }
  fprintf(f, "EOD\n");
  fprintf(f,
          "set title \"Variance shares of Q (first-order)\\ncase %s, %d samples; the shares "
          "sum to %.3g\" noenhanced\n",
          casename, n, sum);
  fprintf(f,
          "set xlabel \"share of the variance of Q\" noenhanced\nset xrange [0:1]\nset rmargin 8\n"
          "set yrange [%d.5:-0.5]\nset grid xtics\nunset key\nset ytics (",
          k - 1);
  for (int i = 0; i < k; i++) {
    fprintf(f, "%s\"", i ? ", " : "");
    for (const char* p = name[ord[i]]; *p; p++) {
      if (*p == '"' || *p == '\\') fputc('\\', f);
      fputc(*p, f);
    }
    fprintf(f, "\" %d", i);
  }
  fprintf(f,
          ") noenhanced\nset style fill solid 0.7 border -1\n"
          "plot $S using ($2/2):1:($2/2):(0.35) with boxxyerror lc rgb '#0072b2', "
          "$S using 2:1:(sprintf(\"%%.3f\", abs($2) < 5e-4 ? 0 : $2)) with labels left "
          "offset 0.5,0\n");
  return 0;
}

int ura_plot_mc(uraCtx* c, const char* what) {
  int tornado = !strcmp(what, "tornado");
  char who[32];
  snprintf(who, sizeof who, "plot %s", what);
  if (!c->mc) return ura_fail(c, "%s: no montecarlo yet; run 'montecarlo N'", who);
  char* s = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&s, &n);
  if (!f) return ura_fail(c, "%s: out of memory", who);
  int rc = tornado ? write_tornado(c, f) : write_hist(c, f);
  fclose(f);
  if (rc == 0) rc = ura_gnuplot_run(c, who, s, n);
  free(s);
  return rc;
}
