/* view.c: the ncurses viewer of the last grid (htop-like): cells coloured by band through
 * semantic colour pairs (glyphs and attributes without colour or with NO_COLOR), axes in metres,
 * a legend, the conditions and Q, the values under the cursor; Enter inspects a cell (its peak
 * values, its airbags at a glance and head acceleration drawn in the terminal), p sends its
 * histories to gnuplot, b its membrane airbags (plot bag), q or Esc returns to the prompt.
 * The terminal is in raw mode, so Ctrl-C is a key here, not SIGINT: while Enter's impact or
 * p's or b's gnuplot runs, a thread watches the keys (keywatch.c), so that
 * Ctrl-C stops the work and q stops it and leaves, within 0.2 s.
 * The window size is polled (TIOCGWINSZ) as well as taken from KEY_RESIZE: ncurses only
 * catches SIGWINCH when nobody else does. The signal dispositions ncurses installs are undone
 * on the way out, so the application's SIGINT handling is as before.
 * ncurses keeps its own global screen state (stdscr, COLORS, ESCDELAY); we keep none.
 */
#include <locale.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <curses.h>
#include <termcap.h>

#include "ui.h"


#define LABEL_W 7  /* along offset labels */
#define CELL_W  6  /* one cell: a glyph or blank, then %5.1f */
#define MIN_W   60 /* smallest usable terminal */
#define MIN_H   12
/* the rows above the grid (title, axis caption, cross offset labels) and below it (legend,
   cursor values, keys): more when the title, the values or the keys need two lines to fit */
static int head_rows = 3, foot_rows = 3;
#define HEAD_ROWS       head_rows
#define FOOT_ROWS       foot_rows
#define STATUS_ONE_LINE 104 /* narrower: the cursor values take two lines */
#define KEYS                                                                                       \
  "arrows/hjkl move  PgUp/PgDn page  Home/End first/last row  0/$ first/last column"               \
  "  c centre  Enter inspect  p plot  b bag  q back"

typedef struct {
  uraCtx* c;
  urGrid* g;
  int fd;        /* the terminal, for its size */
  int in;        /* the terminal read, for its keys */
  int row, col;  /* cursor cell */
  int top, left; /* first visible row and column */
  uraScheme scheme;
  chtype role_attr[uraROLE_N]; /* colour pair and attributes of each role */
  char note[uraERRLEN + 600];  /* last message (errors of Enter and p) */
  int panel;                   /* the inspect panel is open */
  int gone;                    /* the grid went away, or q during a wait: leave */
  int have_trace;              /* trace holds the histories of cell (trow, tcol) */
  int trow, tcol;
  uraTrace trace;
} viewer;

/* ---- colours ---- */

static chtype attr_bits(int a) {
  chtype r = A_NORMAL;
  if (a & uraATTR_BOLD) r |= A_BOLD;
  if (a & uraATTR_REVERSE) r |= A_REVERSE;
  if (a & uraATTR_DIM) r |= A_DIM;
  if (a & uraATTR_UNDERLINE) r |= A_UNDERLINE;
  return r;
}

/* one colour pair per role, or attributes only (no colours, or NO_COLOR) */
static void setup_colors(viewer* v) {
  v->scheme = uraSCHEME_MONO;
  if (has_colors() && !ura_no_color() && start_color() == OK) {
    int dflt = use_default_colors() == OK;
    v->scheme = COLORS >= 256 ? uraSCHEME_XTERM : uraSCHEME_BASIC;
    for (int r = 0; r < uraROLE_N; r++) {
      const uraStyle* st = ura_style(v->scheme, (uraRole)r);
      short fg = st->fg, bg = st->bg;
      if (!dflt && fg < 0) fg = COLOR_WHITE;
      if (!dflt && bg < 0) bg = COLOR_BLACK;
      if (r + 1 < COLOR_PAIRS) init_pair((short)(r + 1), fg, bg);
      v->role_attr[r] = attr_bits(st->attr) | (r + 1 < COLOR_PAIRS ? COLOR_PAIR(r + 1) : 0);
    }
    return;
  }
  for (int r = 0; r < uraROLE_N; r++) {
    v->role_attr[r] = attr_bits(ura_style(uraSCHEME_MONO, (uraRole)r)->attr);
  }
}

/* ---- layout ---- */

static int vis_rows(void) {
  return LINES - HEAD_ROWS - FOOT_ROWS;
}
static int vis_cols(void) {
  return (COLS - LABEL_W) / CELL_W;
}

static urCell* cell_at(viewer* v, int i, int j) {
  return &v->g->cell[(size_t)i * v->g->ncol + j];
}

/* keep the cursor inside the grid and on screen */
static void clamp(viewer* v) {
  int nr = vis_rows(), nc = vis_cols();
  if (v->row < 0) v->row = 0;
  if (v->row >= v->g->nrow) v->row = v->g->nrow - 1;
  if (v->col < 0) v->col = 0;
  if (v->col >= v->g->ncol) v->col = v->g->ncol - 1;
  if (nr < 1) nr = 1;
  if (nc < 1) nc = 1;
  if (v->row < v->top) v->top = v->row;
  if (v->row >= v->top + nr) v->top = v->row - nr + 1;
  if (v->top > v->g->nrow - nr) v->top = v->g->nrow - nr;
  if (v->top < 0) v->top = 0;
  if (v->col < v->left) v->left = v->col;
  if (v->col >= v->left + nc) v->left = v->col - nc + 1;
  if (v->left > v->g->ncol - nc) v->left = v->g->ncol - nc;
  if (v->left < 0) v->left = 0;
}

/* a number, or - when unknown */
static void fmt_num(char* buf, size_t n, const char* fmt, double x) {
  if (isfinite(x))
    snprintf(buf, n, fmt, x);
  else
    snprintf(buf, n, "-");
}

/* text at (y, x) in a role, cut at the right edge */
static void put(WINDOW* w, int y, int x, chtype attr, const char* s) {
  int wy, wx;
  getmaxyx(w, wy, wx);
  if (y < 0 || y >= wy || x >= wx) return;
  wattrset(w, attr);
  mvwaddnstr(w, y, x, s, wx - x);
  wattrset(w, A_NORMAL);
}

/* ---- the screen ---- */

/* the values of criterion k that a place (urIN_PANEL, urIN_CURSOR) shows, from the registry:
   "0.812 mode NCF", "thorax 0.500 m/s abdomen 0.300 m/s"; of a difference grid (design
   compare) only the differences it keeps, HIC15 and Nij (a mode has no difference) */
static void crit_values(const urCell* cl, int k, int where, int diff, char* buf, size_t n) {
  const urCriterion* cr = ur_criterion(k);
  size_t len = 0;
  buf[0] = 0;
  for (int i = cr->val0; i < cr->val0 + cr->nval && len < n; i++) {
    const urValueDef* d = ur_value_def(i);
    if (!(d->where & where)) continue;
    if (diff && i != urVAL_HIC15 && i != urVAL_NIJ) continue;
    char num[32];
    ur_value_format(i, cl->val[i], num, sizeof num);
    int w = snprintf(buf + len, n - len, "%s%s%s%s%s%s", len ? " " : "", d->label,
                     *d->label ? " " : "", num, *d->dunit ? " " : "", d->dunit);
    if (w < 0) break;
    len += (size_t)w;
  }
}

static void draw_cursor_line(viewer* v, int y) {
  const urCell* cl = cell_at(v, v->row, v->col);
  char p[32], vals[160], buf[512], more[512] = "";
  fmt_num(p, sizeof p, "%.1f %%", cl->p * 100.0);
  const char* st = cl->status == urCELL_DONE        ? ""
                   : cl->status == urCELL_NOCONTACT ? "  no contact"
                   : cl->status == urCELL_FAILED    ? "  FAILED: "
                                                    : "  pending";
  /* the criteria in use from the registry; at a narrow screen those after the first two (HIC
     and Nij) and the status go on a second line */
  int two = COLS < STATUS_ONE_LINE, shown = 0;
  const char* d = v->c->last.diff ? "d" : ""; /* a difference grid: P_b - P_a, dHIC15, dNij */
  int len =
      snprintf(buf, sizeof buf, "dpar %.2f m  dperp %.2f m  %sP %s", cl->dpar, cl->dperp, d, p);
  for (int k = 0; k < urNCRIT && len >= 0 && (size_t)len < sizeof buf; k++) {
    if (!ur_criterion_used(k, &v->c->st.injury)) continue;
    crit_values(cl, k, urIN_CURSOR, v->c->last.diff, vals, sizeof vals);
    if (!vals[0]) continue;
    if (two && shown++ >= 2) {
      size_t m = strlen(more);
      snprintf(more + m, sizeof more - m, "%s%s%s %s", m ? "  " : "", d, ur_criterion(k)->label,
               vals);
    } else {
      len += snprintf(buf + len, sizeof buf - (size_t)len, "  %s%s %s", d, ur_criterion(k)->label,
                      vals);
    }
  }
  char* tail = two ? more : buf;
  size_t tl = strlen(tail), cap = two ? sizeof more : sizeof buf;
  if (tl < cap) {
    snprintf(tail + tl, cap - tl, "%s%s", st, cl->status == urCELL_FAILED ? cl->reason : "");
  }
  put(stdscr, y, 0, v->role_attr[uraROLE_TITLE], buf);
  if (two) put(stdscr, y + 1, 0, v->role_attr[uraROLE_TITLE], more);
}

/* the rows the head and the foot take at this width */
static void layout(viewer* v) {
  char title[1200], cond[256], q[256], lines[4][256];
  ura_grid_conditions(v->c, cond, sizeof cond);
  ura_grid_qtext(v->g, v->c->last.diff, q, sizeof q);
  snprintf(title, sizeof title, "%s  %s  [%s]", cond, q, v->c->last.source);
  head_rows = 2 + ura_split_fields(title, COLS, lines, 2);
  foot_rows = 1 + (COLS >= STATUS_ONE_LINE ? 1 : 2) +
              (v->note[0] ? 1 : ura_split_fields(KEYS, COLS, lines, 3));
}

/* a cell without colour: its band's glyph right before its number ("  #19.9"), never after the
   number of the cell to its left: at least one blank leads, so a number of five characters
   (100.0, -31.5) is shown without its decimal ("@100", "+-31") */
static void mono_cell(char* buf, size_t n, char glyph, const urCell* cl, const char* t) {
  char num[16];
  const char* s = t + strspn(t, " ");
  if (strlen(s) > CELL_W - 2 && cl->status != urCELL_FAILED && cl->status != urCELL_PENDING)
    snprintf(num, sizeof num, "%.0f", cl->p * 100.0);
  else
    snprintf(num, sizeof num, "%s", s);
  snprintf(buf, n, "%*s%c%s", (int)(CELL_W - 1 - strlen(num)), "", glyph, num);
}

static void draw_legend(viewer* v, int y) {
  int x = 0;
  int diff = v->c->last.diff;
  char what[32];
  snprintf(what, sizeof what, "%sP = P_b - P_a:", ura_delta());
  put(stdscr, y, x, A_NORMAL, diff ? what : "P{F|Delta}:");
  /* the columns the label takes (the UTF-8 delta is two bytes in one column) */
  x += diff ? (int)strlen(what) + 2 - (int)strlen(ura_delta()) : 12;
  for (int r = uraROLE_NONE; r <= (diff ? uraROLE_RISKIER2 : uraROLE_PENDING) && x < COLS; r++) {
    if (diff && r > uraROLE_NONE && r < uraROLE_SAFER2) continue;
    if (r == uraROLE_FAILED && !v->g->nfailed) continue;
    if (r == uraROLE_PENDING && !v->g->npending) continue;
    char buf[64];
    if (v->scheme == uraSCHEME_MONO) {
      snprintf(buf, sizeof buf, "%c %s", ura_style(uraSCHEME_MONO, (uraRole)r)->glyph,
               ura_role_label((uraRole)r));
    } else {
      snprintf(buf, sizeof buf, " %s ", ura_role_label((uraRole)r));
    }
    put(stdscr, y, x, v->role_attr[r], buf);
    x += (int)strlen(buf) + 1;
  }
}

static void draw_grid(viewer* v) {
  int nr = vis_rows(), nc = vis_cols();
  char buf[1200], cond[256], q[256];

  /* title: conditions, Q, source (two lines when one does not fit) */
  char lines[4][256];
  ura_grid_conditions(v->c, cond, sizeof cond);
  ura_grid_qtext(v->g, v->c->last.diff, q, sizeof q);
  snprintf(buf, sizeof buf, "%s  %s  [%s]", cond, q, v->c->last.source);
  int nt = ura_split_fields(buf, COLS, lines, 2);
  for (int k = 0; k < nt; k++) put(stdscr, k, 0, v->role_attr[uraROLE_TITLE], lines[k]);

  /* axis caption with the orientation (the paper's layout: uasimpact(1), ORIENTATION), cross
     offset labels; along offset labels at the left */
  char dwhat[80], dshort[32];
  snprintf(dwhat, sizeof dwhat, "%sP = P_b - P_a in %% (blue: b safer, red: b riskier)",
           ura_delta());
  snprintf(dshort, sizeof dshort, "%sP %%", ura_delta());
  const char* what = v->c->last.diff ? dwhat : "P{F|Delta} in %";
  snprintf(buf, sizeof buf,
           "%s; columns: dperp (m, + left of the course), rows: dpar (m, + "
           "ahead); the paper's layout",
           what);
  if ((int)strlen(buf) > COLS - LABEL_W) {
    snprintf(buf, sizeof buf, "%s; cols dperp m (+ left of course), rows dpar m (+ ahead)", what);
  }
  if ((int)strlen(buf) > COLS - LABEL_W) {
    snprintf(buf, sizeof buf, "%s; cols dperp m (+ left of course), rows dpar m (+ ahead)",
             v->c->last.diff ? dshort : "P %");
  }
  put(stdscr, HEAD_ROWS - 2, (int)strlen(buf) > COLS - LABEL_W ? 0 : LABEL_W, A_NORMAL, buf);
  put(stdscr, HEAD_ROWS - 1, 0, v->role_attr[uraROLE_AXIS], "  dpar");
  for (int j = v->left; j < v->g->ncol && j < v->left + nc; j++) {
    double x = v->g->perp_min + j * v->g->step;
    snprintf(buf, sizeof buf, "%*.2f", CELL_W, fabs(x) < 5e-13 ? 0.0 : x);
    put(stdscr, HEAD_ROWS - 1, LABEL_W + (j - v->left) * CELL_W, v->role_attr[uraROLE_AXIS], buf);
  }
  for (int i = v->top; i < v->g->nrow && i < v->top + nr; i++) {
    int y = HEAD_ROWS + i - v->top;
    double d = v->g->par_max - i * v->g->step;
    snprintf(buf, sizeof buf, "%*.2f ", LABEL_W - 1, fabs(d) < 5e-13 ? 0.0 : d);
    put(stdscr, y, 0, v->role_attr[uraROLE_AXIS], buf);

    /* cells: colour by band; without colour a glyph tells the band */
    for (int j = v->left; j < v->g->ncol && j < v->left + nc; j++) {
      const urCell* cl = cell_at(v, i, j);
      uraRole r = ura_grid_role(v->c->last.diff, cl);
      char t[8];
      ura_cell_text(cl, t);
      if (v->scheme == uraSCHEME_MONO)
        mono_cell(buf, sizeof buf, ura_style(v->scheme, r)->glyph, cl, t);
      else
        snprintf(buf, sizeof buf, " %s", t);
      chtype a = v->role_attr[r];
      if (i == v->row && j == v->col) {
        a = (a & A_REVERSE) ? (a & ~A_REVERSE) | A_UNDERLINE | A_BOLD : a | A_REVERSE | A_BOLD;
      }
      put(stdscr, y, LABEL_W + (j - v->left) * CELL_W, a, buf);
    }
  }

  /* scroll marks when part of the grid is off screen */
  if (v->top > 0) put(stdscr, HEAD_ROWS, LABEL_W - 1, A_BOLD, "^");
  if (v->top + nr < v->g->nrow) put(stdscr, HEAD_ROWS + nr - 1, LABEL_W - 1, A_BOLD, "v");
  if (v->left > 0) put(stdscr, HEAD_ROWS - 1, LABEL_W - 1, A_BOLD, "<");
  if (v->left + nc < v->g->ncol) put(stdscr, HEAD_ROWS - 1, LABEL_W + nc * CELL_W, A_BOLD, ">");

  /* legend, the cell under the cursor, keys or the last message */
  int y = LINES - FOOT_ROWS;
  draw_legend(v, y);
  draw_cursor_line(v, y + 1);
  y += COLS >= STATUS_ONE_LINE ? 2 : 3;
  if (v->note[0]) {
    put(stdscr, y, 0, A_BOLD, v->note);
  } else {
    int nk = ura_split_fields(KEYS, COLS, lines, 3);
    for (int k = 0; k < nk; k++) put(stdscr, y + k, 0, A_DIM, lines[k]);
  }
}

/* the head acceleration of the trace as a column chart, HIC window shaded */
static void draw_trace(viewer* v, WINDOW* w, int y0, int x0, int h, int wd, double t1, double t2) {
  const uraTrace* tr = &v->trace;
  int k = ura_trace_find(tr, "head_acc");
  if (k < 0 || tr->n < 2) {
    put(w, y0, x0, A_NORMAL, "(no head_acc signal in the histories)");
    return;
  }
  const char* unit;
  double sc = ura_trace_scale(tr, k, &unit);
  const double* s = tr->v + (size_t)k * tr->n;
  double ta = tr->t[0], tb = tr->t[tr->n - 1], lo = 0, hi = 0;
  for (int i = 0; i < tr->n; i++) {
    lo = fmin(lo, s[i] * sc);
    hi = fmax(hi, s[i] * sc);
  }
  if (hi <= lo) hi = lo + 1;
  int pw = wd - 9;
  if (pw < 8 || h < 3 || tb <= ta) return;

  /* y labels, then one column per time bin: its maximum as a bar from the bottom */
  char buf[64];
  snprintf(buf, sizeof buf, "%7.0f", hi);
  put(w, y0, x0, A_NORMAL, buf);
  snprintf(buf, sizeof buf, "%7.0f", lo);
  put(w, y0 + h - 1, x0, A_NORMAL, buf);
  snprintf(buf, sizeof buf, "%.7s", unit);
  put(w, y0 + h / 2, x0 + 1, A_NORMAL, buf);
  int i = 0;
  for (int cx = 0; cx < pw; cx++) {
    double tc0 = ta + (tb - ta) * cx / pw, tc1 = ta + (tb - ta) * (cx + 1) / pw;
    double m = -INFINITY;
    for (; i < tr->n && tr->t[i] < tc1; i++) m = fmax(m, s[i] * sc);
    int shaded = isfinite(t1) && t2 > t1 && tc1 > t1 && tc0 < t2;
    chtype sh = v->scheme == uraSCHEME_MONO ? A_DIM : v->role_attr[uraROLE_MEDIUM];
    int top = isfinite(m) ? (int)lround((hi - m) / (hi - lo) * (h - 1)) : h;
    for (int ry = 0; ry < h; ry++) {
      chtype ch = ry == top                               ? '*'
                  : ry > top                              ? '|'
                  : shaded && v->scheme == uraSCHEME_MONO ? ':'
                                                          : ' ';
      mvwaddch(w, y0 + ry, x0 + 8 + cx, ch | (shaded ? sh : A_NORMAL));
    }
  }
  snprintf(buf, sizeof buf, "%.1f ms", ta * 1e3);
  put(w, y0 + h, x0 + 8, A_NORMAL, buf);
  snprintf(buf, sizeof buf, "%.1f ms", tb * 1e3);
  put(w, y0 + h, x0 + 8 + pw - (int)strlen(buf), A_NORMAL, buf);
}

/* the inspect panel over the grid */
static void draw_panel(viewer* v) {
  int ph = LINES - 2 < 24 ? LINES - 2 : 24, pw = COLS - 4 < 80 ? COLS - 4 : 80;
  WINDOW* w = newwin(ph, pw, (LINES - ph) / 2, (COLS - pw) / 2);
  if (!w) return;
  const urCell* cl = cell_at(v, v->row, v->col);
  char buf[256], vals[160], e[32];
  werase(w);
  box(w, 0, 0);
  snprintf(buf, sizeof buf, " cell dpar %.2f m, dperp %.2f m ", cl->dpar, cl->dperp);
  put(w, 0, 2, A_BOLD, buf);

  /* peak values and the injury-specific PoF of each criterion in use */
  int y = 1;
  for (int k = 0; k < urNCRIT; k++) {
    if (!ur_criterion_used(k, &v->c->st.injury)) continue;
    const urCriterion* cr = ur_criterion(k);
    crit_values(cl, k, urIN_PANEL, v->c->last.diff, vals, sizeof vals);
    snprintf(buf, sizeof buf, "%-5s %s", cr->label, vals);
    put(w, y, 2, A_NORMAL, buf);
    fmt_num(e, sizeof e, "%.4f", cl->pof[k]);
    snprintf(buf, sizeof buf, "%-5s %s", cr->pof_col, e);
    put(w, y++, pw - 20, A_NORMAL, buf);
  }
  snprintf(buf, sizeof buf, "p     %.4f (%.1f %%)", cl->p, cl->p * 100);
  put(w, y, 2, v->role_attr[ura_grid_role(v->c->last.diff, cl)], buf);

  /* the airbags of the cell's impact: pressure, volume, strain, force, bottoming */
  if (v->have_trace) {
    /* four lines a bag, as many as leave the trace its three rows (and a blank line) */
    char bl[8][160];
    int room = (ph - 10 - y) / 4 * 4;
    int nb = room >= 4 ? ura_bag_summary(v->c, bl, room > 8 ? 8 : room) : 0;
    if (nb > 0) y++;
    for (int k = 0; k < nb; k++) put(w, ++y, 2, A_NORMAL, bl[k]);
  }

  /* the head acceleration, or why there is none */
  y += 2;
  if (!v->c->inspect) {
    put(w, y, 2, A_BOLD, "impact simulation not available: stored cell values only");
  } else if (v->have_trace) {
    put(w, y, 2, A_NORMAL, "head acceleration vs time, HIC15 window shaded:");
    if (ph - y - 4 >= 3) {
      draw_trace(v, w, y + 1, 2, ph - y - 4, pw - 4, cl->val[urVAL_HIC_T1], cl->val[urVAL_HIC_T2]);
    } else {
      put(w, y + 1, 2, A_DIM, "(enlarge the window to see the trace)");
    }
  }
  put(w, ph - 2, 2, A_DIM, "p plot in gnuplot   b bag plot   any other key closes");
  wnoutrefresh(stdscr);
  wnoutrefresh(w);
  doupdate();
  delwin(w);
}

static void draw(viewer* v) {
  erase();
  if (COLS < MIN_W || LINES < MIN_H) {
    /* too small: say what is needed, on two lines if one does not fit */
    char need[64], have[64];
    snprintf(need, sizeof need, "need at least %dx%d,", MIN_W, MIN_H);
    snprintf(have, sizeof have, "have %dx%d", COLS, LINES);
    if ((int)(strlen(need) + strlen(have) + 1) <= COLS) {
      mvprintw(0, 0, "%s %s", need, have);
      mvaddnstr(1, 0, "(q returns)", COLS);
    } else {
      mvaddnstr(0, 0, need, COLS);
      mvaddnstr(1, 0, have, COLS);
      mvaddnstr(2, 0, "(q returns)", COLS);
    }
    refresh();
    return;
  }
  layout(v);
  clamp(v);
  draw_grid(v);
  if (v->panel)
    draw_panel(v);
  else
    refresh();
}

/* ---- actions ---- */

/* run a callback with the result and message streams captured (they would spoil the screen);
   the first line of messages becomes the note */
typedef struct {
  FILE *out, *msg;
  char *obuf, *mbuf;
  size_t olen, mlen;
} quiet;

static void quiet_begin(uraCtx* c, quiet* q) {
  memset(q, 0, sizeof *q);
  q->out = c->out;
  q->msg = c->msg;
  FILE* o = open_memstream(&q->obuf, &q->olen);
  FILE* m = open_memstream(&q->mbuf, &q->mlen);
  if (o) c->out = o;
  if (m) c->msg = m;
}

static void quiet_end(uraCtx* c, quiet* q, char* note, size_t n) {
  if (c->out != q->out) fclose(c->out);
  if (c->msg != q->msg) fclose(c->msg);
  c->out = q->out;
  c->msg = q->msg;
  if (note && q->mbuf && q->mbuf[0])
    snprintf(note, n, "%.*s", (int)strcspn(q->mbuf, "\n"), q->mbuf);
  free(q->obuf);
  free(q->mbuf);
}

/* the bottom line during a wait: what runs, and the keys that stop it */
static void waiting(const char* what) {
  char buf[200];
  snprintf(buf, sizeof buf, "%s (Ctrl-C stops it, q stops it and leaves)", what);
  move(LINES - 1, 0);
  clrtoeol();
  put(stdscr, LINES - 1, 0, A_BOLD, buf);
  refresh();
}

/* after a wait under a key watch: a key that stopped it is said, and q leaves */
static int watched(viewer* v, uraKeyWatch* kw) {
  int key = ura_keywatch_stop(kw);
  if (key == 'q') v->gone = 1;
  return key;
}

/* Enter: run or recall the cell's impact, then open the panel (when asked) */
static void inspect(viewer* v, int open) {
  urCell* cl = cell_at(v, v->row, v->col);
  v->have_trace = 0;
  v->note[0] = 0;
  if (v->c->inspect) {
    waiting("running the impact of this cell...");
    quiet q;
    uraKeyWatch kw;
    memset(&v->trace, 0, sizeof v->trace);
    quiet_begin(v->c, &q);
    ura_keywatch_start(&kw, v->in);
    int rc = v->c->inspect(v->c, cl, &v->trace);
    watched(v, &kw);
    quiet_end(v->c, &q, v->note, sizeof v->note);
    if (!v->c->last.g || v->gone) {
      v->gone = 1; /* the callback dropped the grid (nothing left to show), or q */
      return;
    }
    if (v->c->last.g != v->g) {
      v->g = v->c->last.g; /* the callback replaced the grid */
      clamp(v);
    }
    ur_grid_summarise(v->g);
    if (rc) {
      snprintf(v->note, sizeof v->note, "inspect: %s", v->c->err);
      return;
    }
    v->have_trace = 1;
    v->trow = v->row;
    v->tcol = v->col;
  }
  v->panel = open;
}

/* p: the cell's histories to gnuplot */
static void plot(viewer* v) {
  if (!v->c->inspect) {
    snprintf(v->note, sizeof v->note, "plot: impact simulation not available for this cell");
    return;
  }
  if (!v->have_trace || v->trow != v->row || v->tcol != v->col) {
    inspect(v, 0);
    if (v->gone || !v->have_trace) return;
  }
  const urCell* cl = cell_at(v, v->row, v->col);
  quiet q;
  uraKeyWatch kw;
  waiting("plotting in gnuplot...");
  quiet_begin(v->c, &q);
  ura_keywatch_start(&kw, v->in);
  int rc =
      ura_plot_trace_hic(v->c, &v->trace, 0, NULL, cl->val[urVAL_HIC_T1], cl->val[urVAL_HIC_T2]);
  watched(v, &kw);
  quiet_end(v->c, &q, NULL, 0);
  if (rc)
    snprintf(v->note, sizeof v->note, "%s", v->c->err);
  else if (v->c->st.output[0])
    snprintf(v->note, sizeof v->note, "plot: wrote %s", v->c->st.output);
  else
    snprintf(v->note, sizeof v->note, "plot: histories sent to gnuplot");
}

/* b: the cell's membrane airbags at first contact and peak pressure to gnuplot (plot bag) */
static void plot_bag(viewer* v) {
  if (!v->c->inspect) {
    snprintf(v->note, sizeof v->note, "bag: impact simulation not available for this cell");
    return;
  }
  if (!v->have_trace || v->trow != v->row || v->tcol != v->col) {
    inspect(v, 0);
    if (v->gone || !v->have_trace) return;
  }
  quiet q;
  uraKeyWatch kw;
  waiting("plotting the airbag in gnuplot...");
  quiet_begin(v->c, &q);
  ura_keywatch_start(&kw, v->in);
  int rc = ura_plot_bag(v->c);
  watched(v, &kw);
  quiet_end(v->c, &q, NULL, 0);
  if (rc)
    snprintf(v->note, sizeof v->note, "%s", v->c->err);
  else if (v->c->st.output[0])
    snprintf(v->note, sizeof v->note, "plot bag: wrote %s", v->c->st.output);
  else
    snprintf(v->note, sizeof v->note, "plot bag: the airbag sent to gnuplot");
}

/* follow the terminal's size; 1 when it changed */
static int follow_size(viewer* v) {
  struct winsize ws;
  if (ioctl(v->fd, TIOCGWINSZ, &ws) || ws.ws_row == 0 || ws.ws_col == 0) return 0;
  if (!is_term_resized(ws.ws_row, ws.ws_col)) return 0;
  resizeterm(ws.ws_row, ws.ws_col);
  return 1;
}

/* the key loop; returns when q or Esc is pressed */
static void run(viewer* v) {
  int dirty = 1;
  timeout(200);
  while (!v->gone) {
    if (follow_size(v)) dirty = 1;
    if (dirty) draw(v);
    dirty = 0;
    int ch = getch();
    int page = vis_rows() > 1 ? vis_rows() - 1 : 1;
    if (ch == ERR) continue;
    dirty = 1;
    if (ch == KEY_RESIZE) continue;

    /* the panel takes p and b, and any other key closes it */
    if (v->panel) {
      v->panel = 0;
      if (ch == 'p') plot(v);
      if (ch == 'b') plot_bag(v);
      if (ch == 'q' || ch == 27 || ch == 'p' || ch == 'b' || ch == '\n' || ch == '\r' ||
          ch == KEY_ENTER) {
        continue;
      }
    }
    if (ch != 'p' && ch != 'b') v->note[0] = 0;
    if (COLS < MIN_W || LINES < MIN_H) {
      if (ch == 'q' || ch == 27) return;
      continue;
    }
    switch (ch) {
    case 'q':
    case 27: return;
    case KEY_UP:
    case 'k': v->row--; break;
    case KEY_DOWN:
    case 'j': v->row++; break;
    case KEY_LEFT:
    case 'h': v->col--; break;
    case KEY_RIGHT:
    case 'l': v->col++; break;
    case KEY_PPAGE: v->row -= page; break;
    case KEY_NPAGE:
    case ' ': v->row += page; break;
    case KEY_HOME:
    case 'g': v->row = 0; break;
    case KEY_END:
    case 'G': v->row = v->g->nrow - 1; break;
    case '0':
    case '^': v->col = 0; break;
    case '$': v->col = v->g->ncol - 1; break;
    case 'c':
      v->row = (int)lround(v->g->par_max / v->g->step);
      v->col = (int)lround(-v->g->perp_min / v->g->step);
      break;
    case '\n':
    case '\r':
    case KEY_ENTER: inspect(v, 1); break;
    case 'p': plot(v); break;
    case 'b': plot_bag(v); break;
    case 3:
      snprintf(v->note, sizeof v->note, "Ctrl-C does not stop the viewer; q returns to the prompt");
      break;
    default: break;
    }
  }
}

/* tputs' writer: the viewer's terminal */
static FILE* view_out;
static int put_out(int ch) {
  return putc(ch, view_out);
}

int ura_cmd_view(uraCtx* c, int argc, char** argv) {
  if (!c->last.g) return ura_fail(c, "view: no grid yet; run 'grid' or 'grid load FILE'");
  if (ura_dry(c, "view")) return -1;
  if (!c->out || !isatty(STDIN_FILENO) || !isatty(fileno(c->out))) {
    return ura_fail(c, "view: needs a terminal; use 'grid show'");
  }

  /* the signal dispositions as the application has them, to restore on the way out */
  static const int sigs[] = {SIGINT, SIGTERM, SIGWINCH, SIGTSTP};
  struct sigaction saved[4];
  for (int i = 0; i < 4; i++) sigaction(sigs[i], NULL, &saved[i]);

  /* a screen of our own on the terminal, raw (Ctrl-C is a key), keypad, no cursor */
  fflush(c->out);
  setlocale(LC_CTYPE, ""); /* the terminal's characters (a difference grid's Δ); numbers stay C */
  SCREEN* scr = newterm(NULL, c->out, stdin);
  if (!scr) {
    for (int i = 0; i < 4; i++) sigaction(sigs[i], &saved[i], NULL);
    const char* t = getenv("TERM");
    return ura_fail(c, "view: cannot use the terminal (TERM=%s); use 'grid show'", t ? t : "");
  }
  set_term(scr);

  /* a terminal that cannot place the cursor (TERM=dumb) would show nothing but stray codes */
  const char* cup = tigetstr("cup");
  if (!cup || cup == (char*)-1) {
    endwin();
    delscreen(scr);
    for (int i = 0; i < 4; i++) sigaction(sigs[i], &saved[i], NULL);
    fflush(c->out);
    const char* t = getenv("TERM");
    return ura_fail(c,
                    "view: the terminal (TERM=%s) cannot place the cursor; accepted: a "
                    "terminal such as xterm, screen or tmux; use 'grid show' here",
                    t ? t : "");
  }
  raw();
  noecho();
  nonl();
  keypad(stdscr, TRUE);
  set_escdelay(25);
  curs_set(0);

  viewer v;
  memset(&v, 0, sizeof v);
  v.c = c;
  v.g = c->last.g;
  v.fd = fileno(c->out);
  v.in = fileno(stdin);
  setup_colors(&v);

  /* start at the offset nearest 0, centred */
  v.row = (int)lround(v.g->par_max / v.g->step);
  v.col = (int)lround(-v.g->perp_min / v.g->step);
  v.top = v.row - vis_rows() / 2;
  v.left = v.col - vis_cols() / 2;
  run(&v);

  /* back to the prompt: the terminal as it was, nothing else changed; a terminal without an
     alternate screen to leave (vt100: no rmcup) is cleared, so that the viewer does not stay
     on it, the prompt at the top as on a fresh screen */
  const char* rmcup = tigetstr("rmcup");
  const char* clr = tigetstr("clear");
  int wipe = (!rmcup || rmcup == (char*)-1) && clr && clr != (char*)-1;
  curs_set(1);
  endwin();
  if (wipe) {
    fflush(c->out);
    view_out = c->out;
    tputs(clr, 1, put_out);
    fflush(c->out);
  }
  delscreen(scr);
  for (int i = 0; i < 4; i++) sigaction(sigs[i], &saved[i], NULL);
  fflush(c->out);
  return 0;
}
