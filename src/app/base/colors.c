/* colors.c: the colour roles of base.h: band of a probability, one style table per scheme,
 * the legend texts, the choice of scheme for a stream, and ANSI SGR sequences */
#include <curses.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <term.h>
#include <unistd.h>

#include "base.h"


/* styles per scheme and role: fg, bg, attributes, glyph (htop's CRT_colors) */
static const uraStyle styles[uraSCHEME_N][uraROLE_N] =
    {
        [uraSCHEME_PLAIN] =
            {
                [uraROLE_NONE] = {-1, -1, 0, ' '},
                [uraROLE_LOW] = {-1, -1, 0, '.'},
                [uraROLE_MEDIUM] = {-1, -1, 0, ':'},
                [uraROLE_HIGH] = {-1, -1, 0, '#'},
                [uraROLE_SEVERE] = {-1, -1, 0, '@'},
                [uraROLE_FAILED] = {-1, -1, 0, '!'},
                [uraROLE_PENDING] = {-1, -1, 0, '?'},
                [uraROLE_AXIS] = {-1, -1, 0, ' '},
                [uraROLE_TITLE] = {-1, -1, 0, ' '},
                [uraROLE_SAFER2] = {-1, -1, 0, '='},
                [uraROLE_SAFER] = {-1, -1, 0, '-'},
                [uraROLE_RISKIER] = {-1, -1, 0, '+'},
                [uraROLE_RISKIER2] = {-1, -1, 0, '*'},
            },
        [uraSCHEME_MONO] =
            {
                [uraROLE_NONE] = {-1, -1, 0, ' '},
                [uraROLE_LOW] = {-1, -1, uraATTR_DIM, '.'},
                [uraROLE_MEDIUM] = {-1, -1, 0, ':'},
                [uraROLE_HIGH] = {-1, -1, uraATTR_BOLD, '#'},
                [uraROLE_SEVERE] = {-1, -1, uraATTR_REVERSE | uraATTR_BOLD, '@'},
                [uraROLE_FAILED] = {-1, -1, uraATTR_UNDERLINE, '!'},
                [uraROLE_PENDING] = {-1, -1, uraATTR_DIM, '?'},
                [uraROLE_AXIS] = {-1, -1, uraATTR_BOLD, ' '},
                [uraROLE_TITLE] = {-1, -1, uraATTR_BOLD, ' '},
                [uraROLE_SAFER2] = {-1, -1, uraATTR_REVERSE, '='},
                [uraROLE_SAFER] = {-1, -1, uraATTR_DIM, '-'},
                [uraROLE_RISKIER] = {-1, -1, uraATTR_BOLD, '+'},
                [uraROLE_RISKIER2] = {-1, -1, uraATTR_REVERSE | uraATTR_BOLD, '*'},
            },
        [uraSCHEME_BASIC] =
            {
                [uraROLE_NONE] = {-1, -1, 0, ' '},
                [uraROLE_LOW] = {3, -1, 0, '.'},
                [uraROLE_MEDIUM] = {0, 3, 0, ':'},
                [uraROLE_HIGH] = {0, 5, 0, '#'},
                [uraROLE_SEVERE] = {7, 1, uraATTR_BOLD, '@'},
                [uraROLE_FAILED] = {5, -1, uraATTR_BOLD | uraATTR_UNDERLINE, '!'},
                [uraROLE_PENDING] = {-1, -1, uraATTR_DIM, '?'},
                [uraROLE_AXIS] = {6, -1, uraATTR_BOLD, ' '},
                [uraROLE_TITLE] = {-1, -1, uraATTR_BOLD, ' '},
                [uraROLE_SAFER2] = {7, 4, uraATTR_BOLD, '='},
                [uraROLE_SAFER] = {4, -1, 0, '-'},
                [uraROLE_RISKIER] = {1, -1, 0, '+'},
                [uraROLE_RISKIER2] = {7, 1, uraATTR_BOLD, '*'},
            },
        [uraSCHEME_XTERM] =
            {
                [uraROLE_NONE] = {-1, -1, 0, ' '},
                [uraROLE_LOW] = {16, 230, 0, '.'},
                [uraROLE_MEDIUM] = {16, 226, 0, ':'},
                [uraROLE_HIGH] = {16, 208, 0, '#'},
                [uraROLE_SEVERE] = {231, 160, uraATTR_BOLD, '@'},
                [uraROLE_FAILED] = {201, -1, uraATTR_BOLD | uraATTR_UNDERLINE, '!'},
                [uraROLE_PENDING] = {244, -1, 0, '?'},
                [uraROLE_AXIS] = {39, -1, uraATTR_BOLD, ' '},
                [uraROLE_TITLE] = {-1, -1, uraATTR_BOLD, ' '},
                [uraROLE_SAFER2] = {231, 25, uraATTR_BOLD, '='},
                [uraROLE_SAFER] = {16, 153, 0, '-'},
                [uraROLE_RISKIER] = {16, 217, 0, '+'},
                [uraROLE_RISKIER2] = {231, 160, uraATTR_BOLD, '*'},
            },
};

static const char* const names[uraROLE_N] = {
    [uraROLE_NONE] = "none",        [uraROLE_LOW] = "low",       [uraROLE_MEDIUM] = "medium",
    [uraROLE_HIGH] = "high",        [uraROLE_SEVERE] = "severe", [uraROLE_FAILED] = "failed",
    [uraROLE_PENDING] = "pending",  [uraROLE_AXIS] = "axis",     [uraROLE_TITLE] = "title",
    [uraROLE_SAFER2] = "safer",     [uraROLE_SAFER] = "safer",   [uraROLE_RISKIER] = "riskier",
    [uraROLE_RISKIER2] = "riskier",
};

static const char* const labels[uraROLE_N] = {
    [uraROLE_NONE] = "0 / no contact", [uraROLE_LOW] = "0-5 %",     [uraROLE_MEDIUM] = "5-30 %",
    [uraROLE_HIGH] = "30-90 %",        [uraROLE_SEVERE] = ">=90 %", [uraROLE_FAILED] = "fail",
    [uraROLE_PENDING] = "?",           [uraROLE_AXIS] = "axis",     [uraROLE_TITLE] = "title",
    [uraROLE_SAFER2] = "<=-30 %",      [uraROLE_SAFER] = "-30-0 %", [uraROLE_RISKIER] = "0-30 %",
    [uraROLE_RISKIER2] = ">=30 %",
};

uraRole ura_band_role(double p) {
  /* compare in percent with a little slack, so 5.0 % read from a table is medium */
  double pc = p * 100.0;
  if (!(pc > 0)) return uraROLE_NONE;
  if (pc < uraBAND_MED - 1e-9) return uraROLE_LOW;
  if (pc < uraBAND_HIGH - 1e-9) return uraROLE_MEDIUM;
  if (pc < uraBAND_SEVERE - 1e-9) return uraROLE_HIGH;
  return uraROLE_SEVERE;
}

uraRole ura_cell_role(const urCell* cell) {
  if (cell->status == urCELL_FAILED) return uraROLE_FAILED;
  if (cell->status == urCELL_PENDING) return uraROLE_PENDING;
  if (cell->status == urCELL_NOCONTACT) return uraROLE_NONE;
  return ura_band_role(cell->p);
}

uraRole ura_diff_role(const urCell* cell) {
  if (cell->status == urCELL_FAILED) return uraROLE_FAILED;
  if (cell->status == urCELL_PENDING) return uraROLE_PENDING;
  double pc = cell->p * 100.0;
  if (!(pc != 0)) return uraROLE_NONE;
  if (pc <= -uraBAND_HIGH + 1e-9) return uraROLE_SAFER2;
  if (pc < 0) return uraROLE_SAFER;
  return pc < uraBAND_HIGH - 1e-9 ? uraROLE_RISKIER : uraROLE_RISKIER2;
}

uraRole ura_grid_role(int diff, const urCell* cell) {
  return diff ? ura_diff_role(cell) : ura_cell_role(cell);
}

const uraStyle* ura_style(uraScheme s, uraRole r) {
  if ((int)s < 0 || s >= uraSCHEME_N) s = uraSCHEME_PLAIN;
  if ((int)r < 0 || r >= uraROLE_N) r = uraROLE_NONE;
  return &styles[s][r];
}

const char* ura_role_name(uraRole r) {
  return ((int)r < 0 || r >= uraROLE_N) ? "?" : names[r];
}

const char* ura_role_label(uraRole r) {
  return ((int)r < 0 || r >= uraROLE_N) ? "?" : labels[r];
}

int ura_no_color(void) {
  const char* v = getenv("NO_COLOR");
  return v && *v;
}

/* the colours terminfo gives terminal type term (-1: none; 8 when terminfo does not know the
   type, which keeps the 8 ANSI colours); the terminal in use (readline's, the viewer's) stays
   current, and the answer is kept per type */
static int term_colors(const char* term) {
  static char last[128];
  static int ncol = -2; /* -2: not asked yet */
  if (ncol != -2 && !strcmp(last, term)) return ncol;
  TERMINAL* keep = cur_term;
  int err = 0;
  ncol = 8;
  if (setupterm(term, -1, &err) == OK) {
    ncol = tigetnum("colors");
    del_curterm(cur_term);
  }
  set_curterm(keep);
  snprintf(last, sizeof last, "%s", term);
  return ncol;
}

uraScheme ura_scheme_for_stream(FILE* f) {
  /* colour only for a terminal, and only when NO_COLOR is unset */
  if (!ura_tty(f) || ura_no_color()) return uraSCHEME_PLAIN;
  const char* term = getenv("TERM");
  const char* ct = getenv("COLORTERM");
  if (term && !strcmp(term, "dumb")) return uraSCHEME_PLAIN;
  if ((ct && *ct) || (term && strstr(term, "256"))) return uraSCHEME_XTERM;
  /* a terminal type terminfo knows without colours (vt100, vt220): plain, as the man page says */
  if (term && *term && strlen(term) < 128 && term_colors(term) < 8) return uraSCHEME_PLAIN;
  return uraSCHEME_BASIC;
}

/* one SGR colour parameter: 30+n / 40+n for ANSI colours, 38;5;n / 48;5;n above */
static size_t sgr_color(char* buf, size_t n, int base, short col) {
  if (col < 0) return 0;
  if (col < 8) return (size_t)snprintf(buf, n, ";%d", base + col);
  return (size_t)snprintf(buf, n, ";%d;5;%d", base + 8, col);
}

size_t ura_style_sgr(uraScheme s, const uraStyle* st, char* buf, size_t n) {
  if (n == 0) return 0;
  buf[0] = 0;
  if (s == uraSCHEME_PLAIN) return 0;

  /* reset, attributes, then colours, into a local buffer that always fits */
  char tmp[64];
  size_t k = (size_t)snprintf(tmp, sizeof tmp, "\033[0");
  if (st->attr & uraATTR_BOLD) k += (size_t)snprintf(tmp + k, sizeof tmp - k, ";1");
  if (st->attr & uraATTR_DIM) k += (size_t)snprintf(tmp + k, sizeof tmp - k, ";2");
  if (st->attr & uraATTR_UNDERLINE) k += (size_t)snprintf(tmp + k, sizeof tmp - k, ";4");
  if (st->attr & uraATTR_REVERSE) k += (size_t)snprintf(tmp + k, sizeof tmp - k, ";7");
  if (s != uraSCHEME_MONO) {
    k += sgr_color(tmp + k, sizeof tmp - k, 30, st->fg);
    k += sgr_color(tmp + k, sizeof tmp - k, 40, st->bg);
  }
  k += (size_t)snprintf(tmp + k, sizeof tmp - k, "m");
  if (k >= n) return 0;
  memcpy(buf, tmp, k + 1);
  return k;
}
