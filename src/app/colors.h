/* colors.h: semantic colour roles of the workbench (the P{F|Delta} bands of the paper's tables
 * and the parts of a screen), with one style table per colour scheme, after htop's
 * ColorElements/CRT_colors. Shared by 'grid show' (ANSI escapes) and 'view' (ncurses pairs).
 */
#ifndef UASIMPACT_COLORS_H
#define UASIMPACT_COLORS_H

#include <stddef.h>
#include <stdio.h>

#include "uasimpact/grid.h"

/* band thresholds, percent: low < MED <= medium < HIGH <= high < SEVERE <= severe */
#define uraBAND_MED    5.0
#define uraBAND_HIGH   30.0
#define uraBAND_SEVERE 90.0

typedef enum {
  uraROLE_NONE = 0, /* no contact, or P = 0: white / blank */
  uraROLE_LOW,      /* 0 < P < 5 % */
  uraROLE_MEDIUM,   /* 5 <= P < 30 % (yellow) */
  uraROLE_HIGH,     /* 30 <= P < 90 % (orange) */
  uraROLE_SEVERE,   /* P >= 90 % (red) */
  uraROLE_FAILED,   /* the cell's simulation failed */
  uraROLE_PENDING,  /* the cell is not computed */
  uraROLE_AXIS,     /* axis labels */
  uraROLE_TITLE,    /* title and status lines */
  /* a difference grid P_b - P_a (design compare), a diverging scale: */
  uraROLE_SAFER2,   /* P_b - P_a <= -30 % (deep blue) */
  uraROLE_SAFER,    /* -30 % < P_b - P_a < 0 (light blue) */
  uraROLE_RISKIER,  /* 0 < P_b - P_a < 30 % (light red) */
  uraROLE_RISKIER2, /* P_b - P_a >= 30 % (deep red) */
  uraROLE_N
} uraRole;

typedef enum {
  uraSCHEME_PLAIN = 0, /* no escapes at all (not a terminal, or NO_COLOR for text) */
  uraSCHEME_MONO,      /* attributes and glyphs only (ncurses without colour) */
  uraSCHEME_BASIC,     /* the 8 ANSI colours */
  uraSCHEME_XTERM,     /* 256 colours: white, pale yellow, yellow, orange, red */
  uraSCHEME_N
} uraScheme;

enum {
  uraATTR_BOLD = 1,
  uraATTR_REVERSE = 2,
  uraATTR_DIM = 4,
  uraATTR_UNDERLINE = 8
};

typedef struct {
  short fg, bg; /* colour numbers (0-7 ANSI, 8-255 xterm), -1 default */
  int attr;     /* uraATTR_* bits */
  char glyph;   /* marker of the band where colour is absent */
} uraStyle;

/* role of a probability 0..1 (band), and of a grid cell (band, failed or pending) */
uraRole ura_band_role(double p);
uraRole ura_cell_role(const urCell* cell);

/* role of a cell of a difference grid (diverging: 0 is none), and of a cell of a grid that is
   one (diff) or not */
uraRole ura_diff_role(const urCell* cell);
uraRole ura_grid_role(int diff, const urCell* cell);

/* style of a role in a scheme */
const uraStyle* ura_style(uraScheme s, uraRole r);

/* short name of a role ("none", "low", ...) and its legend text ("0 / no contact", "0-5 %") */
const char* ura_role_name(uraRole r);
const char* ura_role_label(uraRole r);

/* scheme for text on a stream: PLAIN unless it is a terminal and NO_COLOR is unset; XTERM when
   TERM or COLORTERM promise 256 colours, BASIC otherwise */
uraScheme ura_scheme_for_stream(FILE* f);

/* true when the NO_COLOR convention (https://no-color.org) asks for no colour */
int ura_no_color(void);

/* SGR escape sequence of a style into buf ("" for PLAIN); returns its length */
size_t ura_style_sgr(uraScheme s, const uraStyle* st, char* buf, size_t n);

/* ---- texts shared by 'grid show' and 'view' ---- */

struct uraCtx;

/* a cell's P in percent in 5 characters ("100.0", " 12.7"), "fail" or "?" right-aligned */
void ura_cell_text(const urCell* cell, char buf[8]);

/* "case C, wind 0 m/s, face 0 deg" (? for what is unknown) */
void ura_grid_conditions(const struct uraCtx* c, char* buf, size_t n);

/* "Q = 0.8469 m^2", with "(partial: N failed, M pending)" when the grid is not complete */
void ura_grid_qtext(const urGrid* g, char* buf, size_t n);

#endif
