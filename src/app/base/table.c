/* table.c: tabular output, as an aligned table for people or CSV with one header line */
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

void ura_table_write(FILE* f, uraTable* t, int csv, int width) {
  int nrow = t->ncell / t->ncol;

  /* notes first, as comment lines in both formats (at a terminal wrapped between words) */
  for (int i = 0; i < t->nnote; i++) ura_wrap(f, "# ", "#   ", t->notes[i], width);

  if (csv) {
    for (int j = 0; j < t->ncol; j++) fprintf(f, "%s%s", j ? "," : "", t->names[j]);
    fputc('\n', f);
    for (int r = 0; r < nrow; r++) {
      for (int j = 0; j < t->ncol; j++) {
        fprintf(f, "%s%s", j ? "," : "", t->cells[r * t->ncol + j]);
      }
      fputc('\n', f);
    }
  } else {
    /* column widths, then right-aligned cells */
    int* w = calloc(t->ncol, sizeof(int));
    for (int j = 0; j < t->ncol; j++) w[j] = (int)strlen(t->names[j]);
    for (int k = 0; k < nrow * t->ncol; k++) {
      int len = (int)strlen(t->cells[k]);
      if (len > w[k % t->ncol]) w[k % t->ncol] = len;
    }
    for (int j = 0; j < t->ncol; j++) fprintf(f, "%s%*s", j ? "  " : "", w[j], t->names[j]);
    fputc('\n', f);
    for (int r = 0; r < nrow; r++) {
      for (int j = 0; j < t->ncol; j++) {
        fprintf(f, "%s%*s", j ? "  " : "", w[j], t->cells[r * t->ncol + j]);
      }
      fputc('\n', f);
    }
    free(w);
  }
  fflush(f);

  /* free everything */
  for (int j = 0; j < t->ncol; j++) free(t->names[j]);
  for (int k = 0; k < t->ncell; k++) free(t->cells[k]);
  for (int i = 0; i < t->nnote; i++) free(t->notes[i]);
  free(t->names);
  free(t->cells);
  free(t->notes);
  free(t);
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
