/* scale_cell.c: one grid cell's results as one line of text and back, exactly (hexadecimal
 * floating point), for the part files of shards and the messages of MPI ranks. The one place
 * that knows which fields a cell's result has. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scale.h"

int ura_cell_write(const urCell* c, char* buf, size_t n) {
  char reason[sizeof c->reason];
  size_t k = 0;
  for (; k < sizeof reason - 1 && c->reason[k]; k++) {
    unsigned char ch = (unsigned char)c->reason[k];
    reason[k] = ch < 32 || ch == 127 ? ' ' : (char)ch;
  }
  reason[k] = 0;
  /* status, contact, every registry value and PoF (urNVAL, urNCRIT of this build), p, extrap */
  int w = snprintf(buf, n, "%d %d", c->status, c->contact);
  for (int i = 0; i < urNVAL && w >= 0 && (size_t)w < n; i++) {
    w += snprintf(buf + w, n - (size_t)w, " %a", c->val[i]);
  }
  for (int i = 0; i < urNCRIT && w >= 0 && (size_t)w < n; i++) {
    w += snprintf(buf + w, n - (size_t)w, " %a", c->pof[i]);
  }
  if (w >= 0 && (size_t)w < n) {
    w += snprintf(buf + w, n - (size_t)w, " %a %d |%s", c->p, c->extrap, reason);
  }
  return w < 0 || (size_t)w >= n ? -1 : w;
}

static int get_int(const char** s, int lo, int hi, int* v) {
  char* end;
  if (**s != '-' && (**s < '0' || **s > '9')) return -1;
  long x = strtol(*s, &end, 10);
  if (end == *s || *end != ' ' || x < lo || x > hi) return -1;
  *v = (int)x;
  *s = end + 1;
  return 0;
}

static int get_double(const char** s, double* v) {
  char* end;
  if (**s == ' ' || !**s) return -1;
  *v = strtod(*s, &end);
  if (end == *s || *end != ' ') return -1;
  *s = end + 1;
  return 0;
}

int ura_cell_read(const char* s, urCell* c) {
  urCell t;
  memset(&t, 0, sizeof t);
  int bad = get_int(&s, urCELL_PENDING, urCELL_FAILED, &t.status) || get_int(&s, 0, 1, &t.contact);
  for (int i = 0; i < urNVAL && !bad; i++) bad = get_double(&s, &t.val[i]);
  for (int i = 0; i < urNCRIT && !bad; i++) bad = get_double(&s, &t.pof[i]);
  if (bad || get_double(&s, &t.p) || get_int(&s, 0, 1 << 30, &t.extrap) || *s != '|') return -1;
  /* the Nij mode is an index: a whole number of -1..3 or NAN */
  double md = t.val[urVAL_NIJ_MODE];
  if (md == md && (md < -1 || md > 3 || md != (int)md)) return -1; /* range first: no UB cast */
  s++;
  size_t n = strcspn(s, "\n");
  if (n >= sizeof t.reason) return -1;
  memcpy(t.reason, s, n);
  t.reason[n] = 0;
  t.dpar = c->dpar;
  t.dperp = c->dperp;
  *c = t;
  return 0;
}
