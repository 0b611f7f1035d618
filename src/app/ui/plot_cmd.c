/* plot_cmd.c: the plot command: which kind of plot its words ask for (grid, pof, history,
 * sweep, montecarlo, tornado), and the two kinds drawn here, the last grid as a heat map in the
 * band colours (a difference grid of design compare on a diverging palette centred on 0, its
 * title and colour bar saying ΔP = P_b − P_a and ΔQ) and the PoF curves. Every kind goes through the runner of plot.c. */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "ui.h"

#define NPOF 241 /* points per PoF curve */

/* ---- the grid as a heat map ---- */

/* the band colours as a stepped palette over 0..100 %, the colour bar ticked at the bands'
   edges (the report's heat maps too) */
void ura_plot_band_palette(FILE* f) {
  fprintf(f,
          "set palette defined (0 '#ffffff', 0.001 '#fff3b0', %g '#fff3b0', %g '#ffe000', "
          "%g '#ffe000', %g '#ff9000', %g '#ff9000', %g '#d7191c', 100 '#d7191c')\n",
          uraBAND_MED, uraBAND_MED, uraBAND_HIGH, uraBAND_HIGH, uraBAND_SEVERE, uraBAND_SEVERE);
  fprintf(f, "set cbrange [0:100]\nset cbtics (0, %g, %g, %g, 100)\n", uraBAND_MED, uraBAND_HIGH,
          uraBAND_SEVERE);
}

/* a difference grid's palette: diverging, white at 0, blue where b is safer (P_b < P_a), red
   where it is riskier, symmetric over +-m % */
static void diff_palette(FILE* f, double m) {
  fprintf(f,
          "set palette defined (-1 '#2166ac', -0.5 '#92c5de', 0 '#f7f7f7', 0.5 '#f4a582', "
          "1 '#b2182b')\n");
  fprintf(f, "set cbrange [%.9g:%.9g]\n", -m, m);
}

static int write_grid(uraCtx* c, FILE* f, const void* arg) {
  const urGrid* g = c->last.g;
  int diff = c->last.diff;
  char cond[256], q[256], title[600];
  double pmax = 0; /* the largest |P| of a difference grid, %: its colour range */

  /* the data: one scan line per along offset; unfinished cells are NaN */
  fprintf(f, "$D << EOD\n");
  for (int i = g->nrow - 1; i >= 0; i--) {
    for (int j = 0; j < g->ncol; j++) {
      const urCell* cl = &g->cell[(size_t)i * g->ncol + j];
      int fin = cl->status == urCELL_DONE || cl->status == urCELL_NOCONTACT;
      ura_plot_num(f, g->perp_min + j * g->step);
      fputc(' ', f);
      ura_plot_num(f, g->par_max - i * g->step);
      fputc(' ', f);
      ura_plot_num(f, fin ? cl->p * 100.0 : NAN);
      if (fin) pmax = fmax(pmax, fabs(cl->p * 100.0));
      fputc('\n', f);
    }
    fputc('\n', f);
  }
  fprintf(f, "EOD\n");

  /* axes in metres, square cells, the band palette */
  ura_grid_conditions(c, cond, sizeof cond);
  /* gnuplot's text is UTF-8 here: a difference says ΔP and ΔQ with a true minus sign */
  if (diff) {
    snprintf(q, sizeof q, "\u0394Q = Q_b \u2212 Q_a = %.4f m^2%s", g->q,
             g->complete ? "" : " (finished cells only: partial grid)");
    snprintf(title, sizeof title, "\u0394P = P_b \u2212 P_a in %%; %s", q);
  } else {
    ura_grid_qtext(g, 0, q, sizeof q);
    snprintf(title, sizeof title, "P{F|Delta} in %%; %s", q);
  }
  double h = g->step / 2;
  double width = (g->ncol - 1) * g->step;
  fprintf(f, "set title ");
  ura_plot_quote(f, cond);
  fprintf(f, ".\"\\n\".");
  ura_plot_quote(f, title);
  fprintf(f, " noenhanced\n");
  fprintf(f, "set xtics %g\n", width > 1.2 ? 0.4 : 0.2);
  fprintf(f,
          "set xlabel \"cross offset dperp (m), + left of the course (the paper's layout)\" "
          "noenhanced\n");
  fprintf(f, "set ylabel \"along offset dpar (m), + ahead\" noenhanced\n");
  if (diff) {
    fprintf(f,
            "set cblabel \"\u0394P = P_b \u2212 P_a (%%): blue b safer, red b riskier\" "
            "noenhanced\n");
  } else {
    fprintf(f, "set cblabel \"P{F|Delta} (%%)\" noenhanced\n");
  }
  fprintf(f, "set size ratio -1\nset xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", g->perp_min - h,
          g->perp_min + (g->ncol - 1) * g->step + h, g->par_max - (g->nrow - 1) * g->step - h,
          g->par_max + h);
  fprintf(f, "set tics out\nset grid front lc rgb '#999999'\n");
  if (diff)
    diff_palette(f, pmax > 0 ? ceil(pmax) : 1);
  else
    ura_plot_band_palette(f);
  fprintf(f, "plot $D using 1:2:3 %s notitle\n", URA_PLOT_CELLS);
  return 0;
}

int ura_plot_grid(uraCtx* c) {
  if (!c->last.g) return ura_fail(c, "plot grid: no grid yet; run 'grid' or 'grid load FILE'");
  return ura_plot_script(c, "plot grid", write_grid, NULL);
}

/* ---- PoF curves ---- */

static int write_pof(uraCtx* c, FILE* f, const void* arg) {
  const urInjuryParams* p = arg;
  double x[NPOF], y[NPOF];
  static const char* const blocks[] = {"HIC", "NIJ", "VCT", "VCA", "VC"};
  static const urPofKind kinds[] = {urPOF_HIC, urPOF_NIJ, urPOF_VC_THORAX, urPOF_VC_ABDOMEN,
                                    urPOF_VC};
  double vcmax = 0;

  /* one datablock per curve; the Nij block also holds the AIS2+..AIS5+ curves */
  for (int k = 0; k < 5; k++) {
    if (ur_pof_curve(kinds[k], p, NPOF, x, y) != NPOF) {
      return ura_fail(c, "plot pof: the %s PoF curve cannot be computed", blocks[k]);
    }
    if (k >= 2) vcmax = fmax(vcmax, x[NPOF - 1]);
    fprintf(f, "$%s << EOD\n", blocks[k]);
    for (int i = 0; i < NPOF; i++) {
      fprintf(f, "%.9g %.9g", x[i], 100 * y[i]);
      if (kinds[k] == urPOF_NIJ) {
        double q[4];
        ur_nij_ais(x[i], p, q);
        fprintf(f, " %.9g %.9g %.9g %.9g", 100 * q[0], 100 * q[1], 100 * q[2], 100 * q[3]);
      }
      fputc('\n', f);
    }
    fprintf(f, "EOD\n");
  }

  /* four panels on a canvas sized for them (ura_plot_pof): HIC, Nij, the AIS curves of Nij,
     VC; keys outside the data, right of their panel */
  fprintf(f,
          "set grid\nset yrange [0:100]\nset ylabel \"P (%%)\"\n"
          "set key outside right top vertical Left reverse samplen 2 noenhanced\n");
  fprintf(f,
          "set multiplot layout 2,2 title \"probability of fatality curves "
          "(uasimpact-injury(7))\" noenhanced\n");
  fprintf(f,
          "set title \"HIC15 -> P_HIC\" noenhanced\nset xlabel \"HIC15\"\n"
          "set xtics 1000\nplot $HIC using 1:2 with lines lw 2 notitle\n");
  fprintf(f,
          "set title \"Nij -> P_NI (C.3)\" noenhanced\nset xlabel \"Nij\"\n"
          "set xtics autofreq\nplot $NIJ using 1:2 with lines lw 2 notitle\n");
  fprintf(f,
          "set title \"Nij -> P(AIS >= k)\" noenhanced\n"
          "plot for [k=2:5] $NIJ using 1:(column(k+1)) with lines lw 2 "
          "title sprintf(\"AIS%%d+\", k)\n");
  fprintf(f,
          "set title \"VC -> P_VC\" noenhanced\nset xlabel \"VC (m/s)\"\n"
          "set xrange [0:%.9g]\n"
          "plot $VCT using 1:2 with lines lw 2 title \"thorax\", "
          "$VCA using 1:2 with lines lw 2 title \"abdomen\", "
          "$VC using 1:2 with lines lw 2 dt 2 title \"fused\"\n",
          vcmax);
  fprintf(f, "unset multiplot\n");
  return 0;
}

int ura_plot_pof(uraCtx* c, const urInjuryParams* p) {
  urInjuryParams def;
  if (!p) {
    ur_injury_defaults(&def);
    p = &def;
  }
  ura_plot_canvas(c, 1280, 860);
  int rc = ura_plot_script(c, "plot pof", write_pof, p);
  ura_plot_canvas(c, 0, 0);
  return rc;
}

/* ---- the command ---- */

int ura_cmd_plot(uraCtx* c, int argc, char** argv) {
  const char* what = argv[1];
  if (!strcmp(what, "history")) {
    uraTrace tr;
    if (ura_last_trace(c, &tr)) return ura_fail(c, "plot history: no impact yet; run 'impact'");
    return ura_plot_trace(c, &tr, argc - 2, (const char* const*)argv + 2);
  }
  if (!strcmp(what, "sweep") && argc <= 3) return ura_plot_sweep(c, argc == 3 ? argv[2] : NULL);
  if (argc > 2) return ura_fail(c, "plot %s: takes no arguments", what);
  if (!strcmp(what, "montecarlo") || !strcmp(what, "tornado")) return ura_plot_mc(c, what);
  if (!strcmp(what, "pof")) return ura_plot_pof(c, &c->st.injury);
  if (!strcmp(what, "grid")) return ura_plot_grid(c);
  if (!strcmp(what, "bag")) return ura_plot_bag(c);
  uraSuggest sg;
  char dym[120];
  ura_suggest_init(&sg, what);
  ura_suggest_keywords(&sg, ura_cmd_find("plot")->usage + strlen("plot "));
  return ura_fail(c,
                  "plot: unknown plot '%s'%s; accepted: pof, grid, history [SIGNAL...|all], "
                  "sweep [wind|face|NAME], montecarlo, tornado, bag",
                  what, ura_suggest_text(&sg, dym, sizeof dym));
}
