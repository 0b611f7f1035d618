/* table.c: tabular output, as an aligned table for people (its notes as '# ' lines above it,
 * folded into blocks of columns when a row would not fit the width), as plain CSV (a header line
 * and rows only, a field with a comma or quote quoted: what pandas and R read with no options;
 * the notes go to another stream, which may be the same), or as
 * one JSON object per table on one line (JSON Lines: columns, rows as objects, notes), built
 * with libjansson so that nothing is escaped by hand. */
#include <jansson.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base.h"


struct uraTable {
  int ncol;
  char** names;
  char** cells; /* row-major, ncell used of cap */
  int ncell, cap;
  char** notes; /* '# ...' lines printed before the header */
  int nnote;
  char** units; /* ncol, NULL until a unit is given: each column's unit or NULL */
};

static char* vfmt(const char* fmt, va_list ap) {
  va_list aq;
  va_copy(aq, ap);
  int n = vsnprintf(NULL, 0, fmt, aq);
  va_end(aq);
  char* s = malloc(n + 1);
  if (s) vsnprintf(s, n + 1, fmt, ap);
  return s;
}

uraTable* ura_table_new(int ncol, const char* const* names) {
  uraTable* t = calloc(1, sizeof *t);
  t->ncol = ncol;
  t->names = calloc(ncol, sizeof(char*));
  for (int i = 0; i < ncol; i++) t->names[i] = strdup(names[i]);
  return t;
}

void ura_table_cell(uraTable* t, const char* fmt, ...) {
  if (t->ncell == t->cap) {
    t->cap = t->cap ? 2 * t->cap : 64;
    t->cells = realloc(t->cells, t->cap * sizeof(char*));
  }
  va_list ap;
  va_start(ap, fmt);
  t->cells[t->ncell++] = vfmt(fmt, ap);
  va_end(ap);
}

void ura_table_note(uraTable* t, const char* fmt, ...) {
  t->notes = realloc(t->notes, (t->nnote + 1) * sizeof(char*));
  va_list ap;
  va_start(ap, fmt);
  t->notes[t->nnote++] = vfmt(fmt, ap);
  va_end(ap);
}

/* one row of columns [j0, j1) of the aligned table, right-aligned to the widths w; the first
   column (the row's key) leads every block after the first */
static void text_row(FILE* f, char* const* cell, const int* w, int j0, int j1) {
  if (j0 > 0) fprintf(f, "%*s", w[0], cell[0]);
  for (int j = j0; j < j1; j++) fprintf(f, "%s%*s", j || j0 ? "  " : "", w[j], cell[j]);
  fputc('\n', f);
}

/* the aligned table: column widths, then blocks of columns that fit width (0: one block) */
static void write_text(FILE* f, const uraTable* t, int width) {
  int nrow = t->ncell / t->ncol;
  int* w = calloc(t->ncol, sizeof(int));
  for (int j = 0; j < t->ncol; j++) w[j] = (int)strlen(t->names[j]);
  for (int k = 0; k < nrow * t->ncol; k++) {
    int len = (int)strlen(t->cells[k]);
    if (len > w[k % t->ncol]) w[k % t->ncol] = len;
  }
  for (int j0 = 0; j0 < t->ncol;) {
    int used = j0 ? w[0] : 0, j1 = j0;
    while (j1 < t->ncol && (j1 == j0 || width <= 0 || used + 2 + w[j1] <= width)) {
      used += (j1 || j0 ? 2 : 0) + w[j1];
      j1++;
    }
    if (j0) fputc('\n', f); /* a blank line between the blocks of a folded table */
    text_row(f, t->names, w, j0, j1);
    for (int r = 0; r < nrow; r++) text_row(f, t->cells + (size_t)r * t->ncol, w, j0, j1);
    j0 = j1;
  }
  free(w);
}

/* one CSV field: as it is, or in double quotes (inner ones doubled) when it holds a comma, a
   quote or a line break (RFC 4180, as pandas and R read it) */
static void csv_field(FILE* f, const char* s) {
  if (!strpbrk(s, ",\"\r\n")) {
    fputs(s, f);
    return;
  }
  fputc('"', f);
  for (; *s; s++) {
    if (*s == '"') fputc('"', f);
    fputc(*s, f);
  }
  fputc('"', f);
}

/* a cell as JSON: a number when the whole cell is one (finite), null when empty or "-" (the
   aligned table's mark of no value), else a string */
static json_t* json_cell(const char* s) {
  char* end;
  if (!*s || !strcmp(s, "-")) return json_null();
  double v = strtod(s, &end);
  if (*end || end == s || !isfinite(v) || strchr(s, 'x') || strchr(s, 'X')) return json_string(s);
  if (!strpbrk(s, ".eE") && fabs(v) < 9e15) return json_integer((json_int_t)v);
  return json_real(v);
}

json_t* ura_table_json(const uraTable* t) {
  int nrow = t->ncell / t->ncol;
  json_t *o = json_object(), *cols = json_array(), *rows = json_array(), *notes = json_array();
  for (int j = 0; j < t->ncol; j++) json_array_append_new(cols, json_string(t->names[j]));
  for (int r = 0; r < nrow; r++) {
    json_t* row = json_object();
    for (int j = 0; j < t->ncol; j++) {
      json_object_set_new(row, t->names[j], json_cell(t->cells[(size_t)r * t->ncol + j]));
    }
    json_array_append_new(rows, row);
  }
  for (int i = 0; i < t->nnote; i++) json_array_append_new(notes, json_string(t->notes[i]));
  json_object_set_new(o, "columns", cols);
  json_object_set_new(o, "rows", rows);
  json_object_set_new(o, "notes", notes);
  return o;
}

void ura_table_write(FILE* f, FILE* nf, uraTable* t, int how, int width) {
  int nrow = t->ncell / t->ncol;

  if (how == uraTAB_TEXT) {
    /* notes first, as comment lines (at a terminal wrapped between words) */
    for (int i = 0; i < t->nnote; i++) ura_wrap(f, "# ", "#   ", t->notes[i], width);
    write_text(f, t, width);
  } else if (how == uraTAB_CSV) {
    /* plain CSV; the notes to nf as comment lines */
    for (int i = 0; nf && i < t->nnote; i++) fprintf(nf, "# %s\n", t->notes[i]);
    for (int j = 0; j < t->ncol; j++) {
      if (j) fputc(',', f);
      csv_field(f, t->names[j]);
    }
    fputc('\n', f);
    for (int r = 0; r < nrow; r++) {
      for (int j = 0; j < t->ncol; j++) {
        const char* v = t->cells[r * t->ncol + j];
        if (j) fputc(',', f);
        csv_field(f, strcmp(v, "-") ? v : ""); /* no value: an empty field (NA) */
      }
      fputc('\n', f);
    }
  } else {
    json_t* o = ura_table_json(t);
    json_dumpf(o, f, JSON_COMPACT | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(15));
    fputc('\n', f);
    json_decref(o);
  }
  if (nf) fflush(nf);
  fflush(f);

  ura_table_free(t);
}

void ura_table_unit(uraTable* t, int col, const char* unit) {
  if (col < 0 || col >= t->ncol) return;
  if (!t->units) t->units = calloc(t->ncol, sizeof(char*));
  free(t->units[col]);
  t->units[col] = unit ? strdup(unit) : NULL;
}

const char* ura_table_unit_of(const uraTable* t, int col) {
  return t->units && col >= 0 && col < t->ncol ? t->units[col] : NULL;
}

void ura_table_free(uraTable* t) {
  for (int j = 0; t->units && j < t->ncol; j++) free(t->units[j]);
  free(t->units);
  for (int j = 0; j < t->ncol; j++) free(t->names[j]);
  for (int k = 0; k < t->ncell; k++) free(t->cells[k]);
  for (int i = 0; i < t->nnote; i++) free(t->notes[i]);
  free(t->names);
  free(t->cells);
  free(t->notes);
  free(t);
}

int ura_table_rows(const uraTable* t) {
  return t->ncell / t->ncol;
}

void ura_table_parts(const uraTable* t, int* ncol, char* const** names, int* ncell,
                     char* const** cells, int* nnote, char* const** notes) {
  *ncol = t->ncol;
  *names = t->names;
  *ncell = t->ncell;
  *cells = t->cells;
  *nnote = t->nnote;
  *notes = t->notes;
}
