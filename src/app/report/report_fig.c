/* report_fig.c: the report's figures: gnuplot's svg terminal draws each kept grid as a heat map
 * (the band palette of plot grid; a design difference on a diverging blue-white-red scale
 * symmetric about 0) and the kept sweeps, the last montecarlo's distribution and its variance
 * shares (the plot commands themselves); each SVG comes back as a data: URI, so the report holds
 * it and an <img> shows it without running anything in it or fetching anything. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "report.h"

#define SVG_TERM "svg size 760,560 font 'Helvetica,12' background '#ffffff'"

/* standard base64 of n bytes, after a prefix (malloc'd) */
static char* base64(const char* prefix, const unsigned char* p, size_t n) {
  static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  size_t lp = strlen(prefix), m = lp + 4 * ((n + 2) / 3) + 1;
  char* s = malloc(m);
  if (!s) return NULL;
  memcpy(s, prefix, lp);
  char* o = s + lp;
  for (size_t i = 0; i < n; i += 3) {
    unsigned v = (unsigned)p[i] << 16;
    if (i + 1 < n) v |= (unsigned)p[i + 1] << 8;
    if (i + 2 < n) v |= p[i + 2];
    *o++ = tab[(v >> 18) & 63];
    *o++ = tab[(v >> 12) & 63];
    *o++ = i + 1 < n ? tab[(v >> 6) & 63] : '=';
    *o++ = i + 2 < n ? tab[v & 63] : '=';
  }
  *o = 0;
  return s;
}

/* run a drawing with the svg terminal into a temporary file; the file as a data: URI */
typedef int (*drawfn)(uraCtx* c, const void* arg);

static char* draw_svg(uraCtx* c, drawfn fn, const void* arg) {
  char path[] = "/tmp/uasimpact-report-XXXXXX";
  int fd = mkstemp(path);
  if (fd < 0) {
    ura_fail(c, "report: cannot create a temporary file for a figure");
    return NULL;
  }
  close(fd);
  char term[sizeof c->st.terminal], out[sizeof c->st.output];
  memcpy(term, c->st.terminal, sizeof term);
  memcpy(out, c->st.output, sizeof out);
  snprintf(c->st.terminal, sizeof c->st.terminal, "%s", SVG_TERM);
  snprintf(c->st.output, sizeof c->st.output, "%s", path);
  FILE* keep = c->msg;
  c->msg = NULL; /* gnuplot's warnings are not the study's */
  int rc = fn(c, arg);
  c->msg = keep;
  memcpy(c->st.terminal, term, sizeof term);
  memcpy(c->st.output, out, sizeof out);
  char* uri = NULL;
  if (rc == 0) {
    FILE* f = fopen(path, "rb");
    char* buf = NULL;
    size_t n = 0;
    if (f && fseek(f, 0, SEEK_END) == 0) {
      long len = ftell(f);
      rewind(f);
      buf = len > 0 ? malloc((size_t)len) : NULL;
      if (buf) n = fread(buf, 1, (size_t)len, f);
    }
    if (f) fclose(f);
    if (buf && n > 0) uri = base64("data:image/svg+xml;base64,", (unsigned char*)buf, n);
    free(buf);
    if (!uri) ura_fail(c, "report: could not read the figure gnuplot wrote");
  }
  unlink(path);
  return uri;
}

/* ---- a kept grid as a heat map ---- */

static int write_grid(uraCtx* c, FILE* f, const void* arg) {
  const uraRepGrid* rg = arg;
  const urGrid* g = &rg->g;
  double big = 0;
  fprintf(f, "$D << EOD\n");
  for (int i = g->nrow - 1; i >= 0; i--) {
    for (int j = 0; j < g->ncol; j++) {
      const urCell* cl = &g->cell[(size_t)i * g->ncol + j];
      int fin = rg->diff || cl->status == urCELL_DONE || cl->status == urCELL_NOCONTACT;
      double v = fin ? cl->p * 100.0 : NAN;
      if (fin && fabs(v) > big) big = fabs(v);
      ura_plot_num(f, g->perp_min + j * g->step);
      fputc(' ', f);
      ura_plot_num(f, g->par_max - i * g->step);
      fputc(' ', f);
      ura_plot_num(f, v);
      fputc('\n', f);
    }
    fputc('\n', f);
  }
  fprintf(f, "EOD\n");
  char q[256], title[800];
  /* the report is UTF-8 whatever the locale: a difference says ΔP and ΔQ */
  if (rg->diff)
    snprintf(q, sizeof q, "\u0394Q = Q_b \u2212 Q_a = %.4f m^2%s", g->q,
             g->complete ? "" : " (finished cells only: partial grid)");
  else
    ura_grid_qtext(g, 0, q, sizeof q);
  snprintf(title, sizeof title, "%s\n%s%s", rg->title,
           rg->diff ? "difference \u0394P = P_b \u2212 P_a in %; " : "P{F|Delta} in %; ", q);
  ura_plot_text(f, "title", title);
  double h = g->step / 2;
  fprintf(f, "set xlabel \"cross offset dperp (m), + left of the course\" noenhanced\n");
  fprintf(f, "set ylabel \"along offset dpar (m), + ahead\" noenhanced\n");
  fprintf(f, "set size ratio -1\nset xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", g->perp_min - h,
          g->perp_min + (g->ncol - 1) * g->step + h, g->par_max - (g->nrow - 1) * g->step - h,
          g->par_max + h);
  fprintf(f, "set tics out\nset grid front lc rgb '#999999'\n");
  if (rg->diff) {
    if (big < 1) big = 1;
    fprintf(
        f,
        "set palette defined (-1 '#2166ac', -0.5 '#92c5de', 0 '#f7f7f7', 0.5 '#f4a582', 1 "
        "'#b2182b')\nset cbrange [%.9g:%.9g]\nset cblabel \"\u0394P = P_b \u2212 P_a (%%)\" noenhanced\n",
        -big, big);
  } else {
    ura_plot_band_palette(f);
    fprintf(f, "set cblabel \"P{F|Delta} (%%)\" noenhanced\n");
  }
  fprintf(f, "plot $D using 1:2:3 %s notitle\n", URA_PLOT_CELLS);
  return 0;
}

static int draw_grid(uraCtx* c, const void* arg) {
  return ura_plot_script(c, "report", write_grid, arg);
}

char* ura_report_svg_grid(uraCtx* c, const uraRepGrid* g) {
  return draw_svg(c, draw_grid, g);
}

/* ---- the plot commands ---- */

static int draw_plot(uraCtx* c, const void* arg) {
  const char* what = arg;
  if (!strcmp(what, "sweep")) return ura_plot_sweep(c, NULL);
  return ura_plot_mc(c, what);
}

char* ura_report_svg_plot(uraCtx* c, const char* what) {
  return draw_svg(c, draw_plot, what);
}
