/* gridshow.c: the last grid as text in the paper's layout: rows along offset descending,
 * columns cross offset, P in percent, each cell coloured by its band on a terminal (plain text
 * otherwise or with NO_COLOR), then the legend and a line with the conditions and Q. A
 * difference grid (design compare) says so: "ΔP = P_b - P_a" and "ΔQ" (Δ as "d" where the
 * locale is not UTF-8), on the diverging bands (blue: b safer, red: b riskier).
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ui.h"


void ura_cell_text(const urCell* cell, char buf[8]) {
  if (cell->status == urCELL_FAILED)
    snprintf(buf, 8, " fail");
  else if (cell->status == urCELL_PENDING)
    snprintf(buf, 8, "    ?");
  else
    snprintf(buf, 8, "%5.1f", cell->p * 100.0);
}

/* a number or ? when unknown */
static void num_or_q(char* buf, size_t n, double v) {
  if (isfinite(v))
    snprintf(buf, n, "%g", v);
  else
    snprintf(buf, n, "?");
}

void ura_grid_conditions(const struct uraCtx* c, char* buf, size_t n) {
  const uraGridResult* r = &c->last;
  char w[32], f[32];
  num_or_q(w, sizeof w, r->wind);
  num_or_q(f, sizeof f, r->face);
  size_t k = (size_t)snprintf(buf, n, "case %s, wind %s m/s, face %s deg",
                              r->casename[0] ? r->casename : "?", w, f);
  if (k < n && isfinite(r->speed) && r->speed > 0) {
    k += (size_t)snprintf(buf + k, n - k, ", speed %.4g m/s", r->speed);
  }
  if (k < n && isfinite(r->angle) && r->angle > 0) {
    k += (size_t)snprintf(buf + k, n - k, ", angle %.4g deg", r->angle);
  }
  if (k < n && r->tau == urTAU_TOP) snprintf(buf + k, n - k, ", tau top");
}

const char* ura_delta(void) {
  const char* v = getenv("LC_ALL");
  if (!v || !*v) v = getenv("LC_CTYPE");
  if (!v || !*v) v = getenv("LANG");
  char low[64];
  size_t k = 0;
  for (; v && v[k] && k < sizeof low - 1; k++) low[k] = (char)tolower((unsigned char)v[k]);
  low[k] = 0;
  return strstr(low, "utf-8") || strstr(low, "utf8") ? "\u0394" : "d";
}

void ura_grid_qtext(const urGrid* g, int diff, char* buf, size_t n) {
  const char* d = ura_delta();
  if (diff && g->complete) {
    snprintf(buf, n, "%sQ = Q_b - Q_a = %.4f m^2", d, g->q);
  } else if (diff) {
    snprintf(buf, n, "%sQ = %.4f m^2 over the finished cells, partial grid (%d failed, %d pending)",
             d, g->q, g->nfailed, g->npending);
  } else if (g->complete) {
    snprintf(buf, n, "Q = %.4f m^2", g->q);
  } else {
    /* not a Q: a lower bound, since the cells not counted have p >= 0 */
    snprintf(buf, n, "Q >= %.4f m^2, partial grid (%d failed, %d pending cells not counted)", g->q,
             g->nfailed, g->npending);
  }
}

/* the grid is its own mirror image in dperp (then only dperp >= 0 is printed, as the paper) */
static int symmetric(const urGrid* g) {
  if (g->ncol % 2 == 0) return 0;
  int mid = g->ncol / 2;
  if (fabs(g->perp_min + mid * g->step) > 1e-9) return 0;
  for (int i = 0; i < g->nrow; i++) {
    for (int j = 0; j < mid; j++) {
      const urCell* a = &g->cell[(size_t)i * g->ncol + j];
      const urCell* b = &g->cell[(size_t)i * g->ncol + g->ncol - 1 - j];
      if (a->status != b->status || fabs(a->p - b->p) > 1e-12) return 0;
    }
  }
  return 1;
}

/* one coloured span: the role's SGR, the text, a reset */
static void span(FILE* f, uraScheme s, uraRole r, const char* text) {
  char sgr[64];
  const uraStyle* st = ura_style(s, r);
  int plain = st->fg < 0 && st->bg < 0 && !st->attr;
  if (!plain && ura_style_sgr(s, st, sgr, sizeof sgr)) {
    fprintf(f, "%s%s\033[0m", sgr, text);
  } else {
    fputs(text, f);
  }
}

int ura_grid_show(uraCtx* c) {
  const urGrid* g = c->last.g;
  if (!g) return ura_fail(c, "grid show: no grid yet; run 'grid' or 'grid load FILE'");
  FILE* f = c->out;
  uraScheme s = ura_scheme_for_stream(f);
  int half = symmetric(g);
  int j0 = half ? g->ncol / 2 : 0;
  char buf[512];

  /* title and column header: cross offsets */
  ura_grid_conditions(c, buf, sizeof buf);
  int diff = c->last.diff;
  if (diff)
    fprintf(f, "%sP = P_b - P_a in %%: %s\n", ura_delta(), buf);
  else
    fprintf(f, "P{F|Delta} in %%: %s\n", buf);
  fprintf(f,
          "rows: dpar m (+ ahead); columns: dperp m (+ left of course); the paper's layout\n"
          "%s",
          half ? "dperp >= 0 shown (mirror-symmetric)\n" : "");
  span(f, s, uraROLE_AXIS, " dpar ");
  for (int j = j0; j < g->ncol; j++) {
    double x = g->perp_min + j * g->step;
    snprintf(buf, sizeof buf, " %5.2f", fabs(x) < 5e-13 ? 0.0 : x);
    span(f, s, uraROLE_AXIS, buf);
  }
  fputc('\n', f);

  /* rows from the front (largest dpar) to the back */
  for (int i = 0; i < g->nrow; i++) {
    double y = g->par_max - i * g->step;
    snprintf(buf, sizeof buf, "%6.2f", fabs(y) < 5e-13 ? 0.0 : y);
    span(f, s, uraROLE_AXIS, buf);
    for (int j = j0; j < g->ncol; j++) {
      const urCell* cl = &g->cell[(size_t)i * g->ncol + j];
      char t[8];
      ura_cell_text(cl, t);
      snprintf(buf, sizeof buf, " %s", t);
      span(f, s, ura_grid_role(diff, cl), buf);
    }
    fputc('\n', f);
  }

  /* legend: each band's name and thresholds on its colour */
  fprintf(f, "legend:");
  for (uraRole r = uraROLE_NONE; r <= (diff ? uraROLE_RISKIER2 : uraROLE_PENDING); r++) {
    if (r >= uraROLE_FAILED && r <= uraROLE_PENDING &&
        !(r == uraROLE_FAILED ? g->nfailed : g->npending))
      continue;
    if (diff ? r > uraROLE_NONE && r < uraROLE_SAFER2 : r > uraROLE_PENDING) continue;
    if (s == uraSCHEME_PLAIN) {
      fprintf(f, "%s %s %s", r ? ";" : "", ura_role_name(r), ura_role_label(r));
    } else {
      snprintf(buf, sizeof buf, " %s %s ", ura_role_name(r), ura_role_label(r));
      fputc(' ', f);
      span(f, s, r, buf);
    }
  }
  fputc('\n', f);

  /* conditions and Q */
  char q[256];
  ura_grid_conditions(c, buf, sizeof buf);
  ura_grid_qtext(g, diff, q, sizeof q);
  fprintf(f, "%s: %s over the %s (%d x %d cells of %g m); source %s\n", buf, q,
          c->last.extents_set ? "set extents only" : "full plane", g->nrow, g->ncol, g->step,
          c->last.source[0] ? c->last.source : "?");
  return 0;
}
