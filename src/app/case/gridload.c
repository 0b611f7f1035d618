/* gridload.c: read a grid CSV into the last grid: the paper's tables (P in percent, the printed
 * half dperp >= 0, mirrored to the full plane with the column dperp = 0 once) and uasimpact's own
 * export (dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p over the full plane, p in 0..1;
 * the difference grid of 'design compare', marked by DIFF_MARK in a comment, p = P_b - P_a in
 * -1..1). Parsing is strict: the first problem gives FILE:LINE: message and the last grid is kept.
 * The conditions (case, wind, face, the difference mark) come from the notes of the sidecar
 * FILE.meta.json that export writes beside a plain CSV, and from '#' comment lines before the
 * header, as exports before the sidecar wrote them (both still read).
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "case.h"

#define MAXCELLS    4000000L /* refuse grids larger than this */
#define LATTICE_TOL 1e-6     /* m: offsets must sit on the lattice within this */
/* what the note of an exported difference grid says (its source, designs.c; or loaded again) */
#define DIFF_MARK "difference P_b - P_a"

/* what the comments before the header say about the conditions */
typedef struct {
  char casename[8];
  double wind, face, speed, angle;
  int diff; /* a comment holds DIFF_MARK: a difference grid */
} meta;

/* the reader's state: file, line, and the fields of the current line */
typedef struct {
  uraCtx* c;
  const char* path;
  FILE* f;
  int line;
  char* buf;
  size_t cap;
  char** fld;
  int nfld, capfld;
  int diff; /* the file is a difference grid (p = P_b - P_a) */
} reader;

/* export columns we know (others are ignored): the offsets, contact, status and p, then every
   criterion value grid load reads (urIN_LOAD) and every criterion's PoF, by the registry */
enum {
  X_DPAR,
  X_DPERP,
  X_CONTACT,
  X_STATUS,
  X_P,
  X_VAL,
  X_POF = X_VAL + urNVAL,
  X_N = X_POF + urNCRIT
};

/* the name of known column k, NULL for a value grid load does not read */
static const char* xname(int k) {
  static const char* const fixed[X_VAL] = {"dpar", "dperp", "contact", "status", "p"};
  if (k < X_VAL) return fixed[k];
  if (k < X_POF) {
    const urValueDef* d = ur_value_def(k - X_VAL);
    return d->where & urIN_LOAD ? d->name : NULL;
  }
  return ur_criterion(k - X_POF)->pof_col;
}

/* record FILE:LINE: message as the failure; always -1 */
static int bad(reader* r, int line, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
static int bad(reader* r, int line, const char* fmt, ...) {
  char msg[uraERRLEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  ura_fail(r->c, "%s:%d: %s", r->path, line, msg); /* a script adds its own FILE:LINE */
  return -1;
}

/* next line without its end of line; 1 read, 0 end of file, -1 error (recorded) */
static int next_line(reader* r) {
  long n = ura_read_line(r->f, &r->buf, &r->cap, uraMAXLINE);
  if (n == uraLINE_EOF) return 0;
  if (n == uraLINE_ERROR) {
    return bad(r, r->line + 1,
               ura_interrupted() ? "interrupted (Ctrl-C) while reading" : "read error: %s",
               strerror(errno));
  }
  r->line++;
  if (n == uraLINE_NUL) return bad(r, r->line, "NUL byte: not a text file");
  if (n == uraLINE_LONG) return bad(r, r->line, "line longer than %ld bytes", uraMAXLINE);
  if (r->line == 1 && !strncmp(r->buf, "\xef\xbb\xbf", 3)) {
    memmove(r->buf, r->buf + 3, (size_t)n - 2);
    n -= 3;
  }
  while (n > 0 && (r->buf[n - 1] == '\n' || r->buf[n - 1] == '\r')) r->buf[--n] = 0;
  return 1;
}

/* a line holding only blanks */
static int blank(const char* s) {
  while (isspace((unsigned char)*s)) s++;
  return !*s;
}

/* split the current line at commas, trimming blanks around each field */
static int split(reader* r) {
  r->nfld = 0;
  char* s = r->buf;
  for (;;) {
    if (r->nfld == r->capfld) {
      int cap = r->capfld ? 2 * r->capfld : 32;
      char** f = realloc(r->fld, (size_t)cap * sizeof *f);
      if (!f) return bad(r, r->line, "out of memory");
      r->fld = f;
      r->capfld = cap;
    }
    char* comma = strchr(s, ',');
    if (comma) *comma = 0;
    while (isspace((unsigned char)*s)) s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1])) s[--n] = 0;
    r->fld[r->nfld++] = s;
    if (!comma) return 0;
    s = comma + 1;
  }
}

/* a number in a field (strict), naming what it is in the message */
static int field_number(reader* r, int i, const char* what, double* v) {
  if (ura_parse_number(r->fld[i], v)) {
    return bad(r, r->line, "%s: '%s' is not a number", what, r->fld[i]);
  }
  return 0;
}

/* the first number after a key word in a comment ("wind 0 m/s", "phi = 0", "case=C") */
static const char* after_key(const char* s, const char* key) {
  size_t k = strlen(key);
  for (const char* p = s; (p = strstr(p, key)) != NULL; p++) {
    int start = p == s || !isalnum((unsigned char)p[-1]);
    int end = !isalnum((unsigned char)p[k]) || !isalnum((unsigned char)key[k - 1]);
    if (!start || !end) continue;
    const char* q = p + k;
    while (*q == ' ' || *q == '\t') q++;
    if (*q == '=' || *q == ':') q++;
    while (*q == ' ' || *q == '\t') q++;
    return q;
  }
  return NULL;
}

/* a number at s, up to the next blank, ';' or ','; 0 found */
static int number_at(const char* s, double* v) {
  char tok[64];
  size_t n = 0;
  while (s[n] && strchr("0123456789+-.eE", s[n]) && n < sizeof tok - 1) n++;
  if (n == 0) return -1;
  memcpy(tok, s, n);
  tok[n] = 0;
  return ura_parse_number(tok, v);
}

/* the first of several keys followed by a number */
static void meta_number(const char* s, const char* const* keys, double* v) {
  if (!isnan(*v)) return;
  for (int i = 0; keys[i]; i++) {
    const char* q = after_key(s, keys[i]);
    double x;
    if (q && !number_at(q, &x)) {
      *v = x;
      return;
    }
  }
}

/* conditions named in one comment line */
static void meta_parse(meta* m, const char* s) {
  static const char* const kwind[] = {"wind", NULL};
  if (strstr(s, DIFF_MARK)) m->diff = 1;
  static const char* const kface[] = {"phi", "face", NULL};
  static const char* const kspeed[] = {"|v|", "speed", NULL};
  static const char* const kangle[] = {"psi", "angle", NULL};
  meta_number(s, kwind, &m->wind);
  meta_number(s, kface, &m->face);
  meta_number(s, kspeed, &m->speed);
  meta_number(s, kangle, &m->angle);

  /* case: a known case name after the word */
  const char* q = after_key(s, "case");
  if (!q || m->casename[0]) return;
  char tok[8];
  size_t n = 0;
  while (isalnum((unsigned char)q[n]) && n < sizeof tok - 1) n++;
  if (isalnum((unsigned char)q[n])) return;
  memcpy(tok, q, n);
  tok[n] = 0;
  /* the paper's case names (its files are named by them) */
  static const char* const paper_cases[] = {"A", "B", "C", "A1", "A2", NULL};
  for (int i = 0; paper_cases[i]; i++) {
    if (!strcasecmp(tok, paper_cases[i])) {
      strcpy(m->casename, paper_cases[i]);
      return;
    }
  }
}

/* the notes of the sidecar path.meta.json, when there is one, as comments (a sidecar that is
   not JSON is no sidecar: the grid's own comments still count) */
static void meta_sidecar(meta* m, const char* path) {
  char name[4096];
  if (snprintf(name, sizeof name, "%s.meta.json", path) >= (int)sizeof name) return;
  json_t* o = json_load_file(name, 0, NULL);
  size_t i, k;
  json_t *tab, *note;
  json_array_foreach(json_object_get(o, "tables"), i, tab) {
    json_array_foreach(json_object_get(tab, "notes"), k, note) {
      if (json_is_string(note)) meta_parse(m, json_string_value(note));
    }
  }
  json_decref(o);
}

/* an empty grid with every cell pending at its lattice offset */
static urGrid* grid_alloc(int nrow, int ncol, double step, double par_max, double perp_min) {
  urGrid* g = calloc(1, sizeof *g);
  if (!g) return NULL;
  g->cell = calloc((size_t)nrow * (size_t)ncol, sizeof *g->cell);
  if (!g->cell) {
    free(g);
    return NULL;
  }
  g->nrow = nrow;
  g->ncol = ncol;
  g->step = step;
  g->par_max = par_max;
  g->perp_min = perp_min;
  for (int i = 0; i < nrow; i++) {
    for (int j = 0; j < ncol; j++) {
      urCell* cl = &g->cell[(size_t)i * ncol + j];
      cl->dpar = par_max - i * step;
      cl->dperp = perp_min + j * step;
      if (fabs(cl->dpar) < 1e-12) cl->dpar = 0;
      if (fabs(cl->dperp) < 1e-12) cl->dperp = 0;
      cl->status = urCELL_PENDING;
    }
  }
  return g;
}

static void grid_free(urGrid* g) {
  if (!g) return;
  free(g->cell);
  free(g);
}

/* result fields the file does not give */
static void cell_unknown(urCell* cl) {
  for (int v = 0; v < urNVAL; v++) cl->val[v] = NAN;
  for (int k = 0; k < urNCRIT; k++) cl->pof[k] = NAN;
}

/* the paper's table: header along,0.00,0.05,...; rows of percent, dperp >= 0 only */
static int load_paper(reader* r, int hline, urGrid** out) {
  /* cross offsets from the header: 0, step, 2 step, ... */
  int m = r->nfld - 1;
  if (m < 1) return bad(r, hline, "header 'along' has no cross offsets");
  double* cross = malloc((size_t)m * sizeof *cross);
  double* val = NULL;
  double* along = NULL;
  int nrow = 0, caprow = 0, rc = -1;
  if (!cross) return bad(r, hline, "out of memory");
  for (int k = 0; k < m; k++) {
    if (ura_parse_number(r->fld[k + 1], &cross[k])) {
      bad(r, hline, "header: cross offset '%s' is not a number", r->fld[k + 1]);
      goto done;
    }
  }
  if (fabs(cross[0]) > LATTICE_TOL) {
    bad(r, hline,
        "header: the first cross offset is %g, expected 0 (the paper prints "
        "dperp >= 0)",
        cross[0]);
    goto done;
  }
  double step = m > 1 ? cross[1] - cross[0] : NAN;
  if (m > 1 && !(step > LATTICE_TOL)) {
    bad(r, hline, "header: cross offsets must increase (%g then %g)", cross[0], cross[1]);
    goto done;
  }
  for (int k = 2; k < m; k++) {
    if (fabs(cross[k] - k * step) > LATTICE_TOL) {
      bad(r, hline, "header: cross offset %g is off the %g m step (expected %g)", cross[k], step,
          k * step);
      goto done;
    }
  }

  /* rows: along offset, then m percentages, along descending by the same step */
  int last = hline;
  for (;;) {
    int got = next_line(r);
    if (got < 0) goto done;
    if (got == 0) break;
    if (r->buf[0] == '#' || blank(r->buf)) continue;
    last = r->line;
    if (split(r)) goto done;
    if (r->nfld != m + 1) {
      bad(r, r->line, "row has %d values, the header has %d cross offsets", r->nfld - 1, m);
      goto done;
    }
    if (nrow == caprow) {
      caprow = caprow ? 2 * caprow : 64;
      double* a = realloc(along, (size_t)caprow * sizeof *a);
      if (a) along = a;
      double* v = a ? realloc(val, (size_t)caprow * m * sizeof *v) : NULL;
      if (v) val = v;
      if (!a || !v || (long)caprow * m > MAXCELLS) {
        bad(r, r->line, a && v ? "grid too large (more than %ld cells)" : "out of memory",
            MAXCELLS);
        goto done;
      }
    }
    if (field_number(r, 0, "along offset", &along[nrow])) goto done;
    for (int k = 0; k < m; k++) {
      double* v = &val[(size_t)nrow * m + k];
      char what[64];
      snprintf(what, sizeof what, "value at cross offset %.2f", cross[k]);
      if (field_number(r, k + 1, what, v)) goto done;
      if (*v < 0 || *v > 100) {
        bad(r, r->line, "%s is %g, outside [0, 100] percent", what, *v);
        goto done;
      }
    }

    /* the step of the rows must be the lattice step */
    if (nrow == 1 && isnan(step)) step = along[0] - along[1];
    if (nrow >= 1) {
      double want = along[0] - nrow * step;
      if (!(step > LATTICE_TOL) || fabs(along[nrow] - want) > LATTICE_TOL) {
        bad(r, r->line, "along offset %g breaks the descending %g m steps (expected %g)",
            along[nrow], step, want);
        goto done;
      }
    }
    nrow++;
  }
  if (nrow == 0) {
    bad(r, last, "no data rows after the header");
    goto done;
  }
  if (isnan(step)) {
    bad(r, last, "one row and one column: the lattice step cannot be told");
    goto done;
  }

  /* the full plane: column dperp = 0 once, the others mirrored */
  int ncol = 2 * m - 1;
  urGrid* g = grid_alloc(nrow, ncol, step, along[0], -(m - 1) * step);
  if (!g) {
    bad(r, last, "out of memory");
    goto done;
  }
  for (int i = 0; i < nrow; i++) {
    for (int k = 0; k < m; k++) {
      double p = val[(size_t)i * m + k] / 100.0;
      for (int side = 0; side < (k ? 2 : 1); side++) {
        urCell* cl = &g->cell[(size_t)i * ncol + (m - 1) + (side ? -k : k)];
        cell_unknown(cl);
        cl->p = p;
        cl->contact = p > 0;
        cl->status = p > 0 ? urCELL_DONE : urCELL_NOCONTACT;
        cl->mirrored = side;
      }
    }
  }
  *out = g;
  rc = 0;
done:
  free(cross);
  free(val);
  free(along);
  return rc;
}

/* one parsed export row and the line it came from */
typedef struct {
  urCell cell;
  int line;
} xrow;

/* a criterion column: a number, or nan / empty for unknown */
static int field_optional(reader* r, int i, const char* what, double* v) {
  const char* s = r->fld[i];
  if (!*s || !strcasecmp(s, "nan") || !strcmp(s, "-")) {
    *v = NAN;
    return 0;
  }
  return field_number(r, i, what, v);
}

/* a cell status word or number */
static int field_status(reader* r, int i, int* st) {
  static const char* const words[] = {"pending", "nocontact", "done", "failed", NULL};
  for (int k = 0; words[k]; k++) {
    if (!strcasecmp(r->fld[i], words[k])) {
      *st = k;
      return 0;
    }
  }
  double v;
  if (!ura_parse_number(r->fld[i], &v) && v == floor(v) && v >= 0 && v <= 3) {
    *st = (int)v;
    return 0;
  }
  return bad(r, r->line, "status '%s' is not pending, nocontact, done or failed", r->fld[i]);
}

/* ascending order of doubles */
static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

/* the gaps between neighbouring distinct values (sorted in place) appended to gap */
static int add_gaps(double* v, int n, double* gap, int ngap) {
  qsort(v, (size_t)n, sizeof *v, cmp_double);
  for (int i = 1; i < n; i++) {
    double d = v[i] - v[i - 1];
    if (d > LATTICE_TOL) gap[ngap++] = d;
  }
  return ngap;
}

/* the lattice step: the most frequent gap (the smaller on a tie), NAN without gaps */
static double common_gap(double* gap, int n) {
  qsort(gap, (size_t)n, sizeof *gap, cmp_double);
  double best = NAN;
  int bestn = 0;
  for (int i = 0; i < n;) {
    int k = i;
    while (k < n && gap[k] - gap[i] <= LATTICE_TOL) k++;
    if (k - i > bestn) {
      bestn = k - i;
      best = gap[i];
    }
    i = k;
  }
  return best;
}

/* an integer-coded value outside its codes: "nij_mode is 5, expected 0 (NTF), 1 (NTE), 2 (NCF)
   or 3 (NCE)" */
static int bad_code(reader* r, const urValueDef* d, double v) {
  char list[uraERRLEN] = "";
  size_t len = 0;
  for (int i = 0; i < d->nnames && len < sizeof list; i++) {
    int w = snprintf(list + len, sizeof list - len, "%s%d (%s)",
                     i == 0               ? ""
                     : i == d->nnames - 1 ? " or "
                                          : ", ",
                     i, d->names[i]);
    if (w < 0) break;
    len += (size_t)w;
  }
  return bad(r, r->line, "%s is %g, expected %s", d->name, v, list);
}

/* parse the fields of one export row into a cell */
static int export_row(reader* r, const int* col, xrow* x) {
  urCell* cl = &x->cell;
  memset(x, 0, sizeof *x);
  cell_unknown(cl);
  x->line = r->line;
  if (field_number(r, col[X_DPAR], "dpar", &cl->dpar)) return -1;
  if (field_number(r, col[X_DPERP], "dperp", &cl->dperp)) return -1;
  if (field_number(r, col[X_P], "p", &cl->p)) return -1;
  if (r->diff && (cl->p < -1 || cl->p > 1)) {
    return bad(r, r->line, "p is %g, outside [-1, 1] (a difference P_b - P_a)", cl->p);
  }
  if (!r->diff && (cl->p < 0 || cl->p > 1)) {
    return bad(r, r->line, "p is %g, outside [0, 1]%s", cl->p,
               cl->p < 0 && cl->p >= -1
                   ? "; a difference grid (p = P_b - P_a in [-1, 1], "
                     "'design compare') is marked by a note '... " DIFF_MARK
                     " ...' in FILE.meta.json beside it, as 'export grid' writes it (or a "
                     "comment '# ...' before the header)"
                   : "");
  }

  /* criteria: numbers, or nan for unknown; an integer-coded value one of its codes */
  for (int k = X_VAL; k < X_N; k++) {
    if (col[k] < 0) continue;
    const urValueDef* d = k < X_POF ? ur_value_def(k - X_VAL) : NULL;
    double* dst = k < X_POF ? &cl->val[k - X_VAL] : &cl->pof[k - X_POF];
    if (d && d->names) {
      if (field_number(r, col[k], d->name, dst)) return -1;
      if (*dst != floor(*dst) || *dst < 0 || *dst >= d->nnames) return bad_code(r, d, *dst);
    } else if (field_optional(r, col[k], xname(k), dst)) {
      return -1;
    }
  }

  /* contact and status: given, or told by p */
  cl->contact = cl->p > 0;
  if (col[X_CONTACT] >= 0) {
    double v;
    if (field_number(r, col[X_CONTACT], "contact", &v)) return -1;
    if (v != 0 && v != 1) return bad(r, r->line, "contact is %g, expected 0 or 1", v);
    if (v == 0 && cl->p != 0) return bad(r, r->line, "p is %g without contact", cl->p);
    cl->contact = (int)v;
  }
  cl->status = cl->contact ? urCELL_DONE : urCELL_NOCONTACT;
  if (col[X_STATUS] >= 0 && field_status(r, col[X_STATUS], &cl->status)) return -1;
  return 0;
}

/* uasimpact's export: named columns, one row per cell of the full plane, p in 0..1 */
static int load_export(reader* r, int hline, urGrid** out) {
  /* which field holds which column */
  int col[X_N], ncol_file = r->nfld, rc = -1;
  for (int k = 0; k < X_N; k++) col[k] = -1;
  for (int i = 0; i < r->nfld; i++) {
    for (int k = 0; k < X_N; k++) {
      if (!xname(k) || strcmp(r->fld[i], xname(k))) continue;
      if (col[k] >= 0) return bad(r, hline, "header: column '%s' appears twice", xname(k));
      col[k] = i;
    }
  }
  if (col[X_DPAR] < 0 || col[X_DPERP] < 0 || col[X_P] < 0) {
    return bad(r, hline, "header: columns dpar, dperp and p are required");
  }

  /* rows */
  xrow* rows = NULL;
  double *vpar = NULL, *vperp = NULL;
  urGrid* g = NULL;
  int n = 0, cap = 0, last = hline;
  for (;;) {
    int got = next_line(r);
    if (got < 0) goto done;
    if (got == 0) break;
    if (r->buf[0] == '#' || blank(r->buf)) continue;
    last = r->line;
    if (split(r)) goto done;
    if (r->nfld != ncol_file) {
      bad(r, r->line, "row has %d fields, the header has %d", r->nfld, ncol_file);
      goto done;
    }
    if (n == cap) {
      cap = cap ? 2 * cap : 256;
      xrow* x = cap <= MAXCELLS ? realloc(rows, (size_t)cap * sizeof *x) : NULL;
      if (!x) {
        bad(r, r->line, cap > MAXCELLS ? "grid too large" : "out of memory");
        goto done;
      }
      rows = x;
    }
    if (export_row(r, col, &rows[n])) goto done;
    n++;
  }
  if (n == 0) {
    bad(r, last, "no data rows after the header");
    goto done;
  }

  /* the lattice: extents and the smallest spacing of either offset */
  vpar = malloc((size_t)n * sizeof *vpar);
  vperp = malloc((size_t)n * sizeof *vperp);
  if (!vpar || !vperp) {
    bad(r, last, "out of memory");
    goto done;
  }
  for (int i = 0; i < n; i++) {
    vpar[i] = rows[i].cell.dpar;
    vperp[i] = rows[i].cell.dperp;
  }
  double* gaps = malloc(2 * (size_t)n * sizeof *gaps);
  if (!gaps) {
    bad(r, last, "out of memory");
    goto done;
  }
  int ngap = add_gaps(vpar, n, gaps, 0);
  ngap = add_gaps(vperp, n, gaps, ngap);
  double step = common_gap(gaps, ngap);
  free(gaps);
  if (isnan(step)) {
    bad(r, last, "a single cell: the lattice step cannot be told");
    goto done;
  }
  double par_min = vpar[0], par_max = vpar[n - 1];
  double perp_min = vperp[0], perp_max = vperp[n - 1];
  double fr = (par_max - par_min) / step, fc = (perp_max - perp_min) / step;
  if ((fr + 1) * (fc + 1) > MAXCELLS) {
    bad(r, last, "grid too large (more than %ld cells)", MAXCELLS);
    goto done;
  }
  int nrow = (int)lround(fr) + 1, ncol = (int)lround(fc) + 1;
  g = grid_alloc(nrow, ncol, step, par_max, perp_min);
  if (!g) {
    bad(r, last, "out of memory");
    goto done;
  }

  /* place every row on its lattice cell, once */
  int* from = calloc((size_t)nrow * ncol, sizeof *from);
  if (!from) {
    bad(r, last, "out of memory");
    goto done;
  }
  for (int k = 0; k < n; k++) {
    urCell* x = &rows[k].cell;
    double fi = (par_max - x->dpar) / step, fj = (x->dperp - perp_min) / step;
    long i = lround(fi), j = lround(fj);
    if (fabs(fi - i) * step > LATTICE_TOL || fabs(fj - j) * step > LATTICE_TOL) {
      bad(r, rows[k].line, "offset (%g, %g) is off the %g m lattice", x->dpar, x->dperp, step);
      free(from);
      goto done;
    }
    size_t at = (size_t)i * ncol + j;
    if (from[at]) {
      bad(r, rows[k].line, "cell (%g, %g) is given twice (first at line %d)", x->dpar, x->dperp,
          from[at]);
      free(from);
      goto done;
    }
    from[at] = rows[k].line;
    double dpar = g->cell[at].dpar, dperp = g->cell[at].dperp;
    g->cell[at] = *x;
    g->cell[at].dpar = dpar;
    g->cell[at].dperp = dperp;
  }
  free(from);
  *out = g;
  g = NULL;
  rc = 0;
done:
  grid_free(g);
  free(rows);
  free(vpar);
  free(vperp);
  return rc;
}

int ura_grid_load(uraCtx* c, const char* path) {
  reader r = {.c = c, .path = path};
  meta m = {"", NAN, NAN, NAN, NAN};
  urGrid* g = NULL;
  int rc = -1;

  if (ura_dry(c, "grid load")) return -1;
  /* the current folder first, then the installed data (the paper's grids) */
  char found[4096];
  r.f = ura_data_open(path, found, sizeof found);
  if (!r.f && ura_interrupted()) {
    return ura_fail(c, "grid load: interrupted (Ctrl-C) while opening '%s'", path);
  }
  if (!r.f) return ura_fail(c, "grid load: cannot open '%s': %s", path, strerror(errno));
  path = r.path = found;
  ura_input_seen(c, r.f, path); /* a shard's part may not replace it */
  meta_sidecar(&m, path);

  /* comments (conditions), then the header that tells the format */
  int got;
  while ((got = next_line(&r)) > 0) {
    if (r.buf[0] == '#')
      meta_parse(&m, r.buf + 1);
    else if (!blank(r.buf))
      break;
  }
  if (got < 0) goto done;
  if (got == 0) {
    bad(&r, r.line ? r.line : 1,
        "%s: expected a header 'along,0.00,0.05,...' (paper table) "
        "or 'dpar,dperp,...,p' (uasimpact export)",
        r.line ? "no data" : "empty file");
    goto done;
  }
  int hline = r.line;
  r.diff = m.diff;
  if (split(&r)) goto done;
  if (!strcmp(r.fld[0], "along")) {
    if (m.diff) {
      bad(&r, hline,
          "a difference grid (" DIFF_MARK
          ") in the paper's layout; accepted: the "
          "difference as 'export grid' writes it (dpar,dperp,...,p)");
      goto done;
    }
    if (load_paper(&r, hline, &g)) goto done;
  } else if (!strcmp(r.fld[0], "dpar")) {
    if (load_export(&r, hline, &g)) goto done;
  } else {
    bad(&r, hline,
        "missing header: expected 'along,0.00,0.05,...' (paper table) or "
        "'dpar,dperp,...,p' (uasimpact export), found '%.40s'",
        r.fld[0]);
    goto done;
  }

  /* success: replace the last grid */
  ur_grid_summarise(g);
  ura_last_free(c);
  memset(&c->last, 0, sizeof c->last);
  c->last.g = g;
  snprintf(c->last.casename, sizeof c->last.casename, "%s", m.casename[0] ? m.casename : "?");
  c->last.wind = m.wind;
  c->last.face = m.face;
  c->last.speed = m.speed;
  c->last.angle = m.angle;
  c->last.diff = m.diff;
  if (m.diff) { /* the source says so, and so the note of 'export grid' again (round trip) */
    char shown[400];
    ura_printable(path, shown, sizeof shown);
    snprintf(c->last.source, sizeof c->last.source, DIFF_MARK " loaded from %s", shown);
  } else {
    ura_printable(path, c->last.source, sizeof c->last.source); /* shown by grid show, view */
  }
  g = NULL;
  rc = 0;
done:
  grid_free(g);
  free(r.buf);
  free(r.fld);
  fclose(r.f);
  return rc;
}
