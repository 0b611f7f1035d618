/* scale_cell.c: one grid cell's results as one line of text and back, exactly (hexadecimal
 * floating point), for the part files of shards and the messages of MPI ranks. The one place
 * that knows which fields a cell's result has, and what values they may hold: a part file is
 * data someone else wrote, so a line is read only when every value is in its domain (p and every
 * PoF finite in [0, 1], the criteria finite or NaN, the Nij mode an index) and its failure reason
 * is printable text (no byte that could drive a terminal). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scale.h"

/* a probability: finite, in [0, 1] */
static int prob(double x) {
  return x >= 0 && x <= 1;
}

/* 1 if every value of t is in its domain: the criteria finite or NAN (not known), p and the PoFs
   probabilities, the Nij mode an index (a whole number of -1..3, or NAN) */
static int in_domain(const urCell* t) {
  for (int i = 0; i < urNVAL; i++) {
    if (isinf(t->val[i])) return 0;
  }
  for (int i = 0; i < urNCRIT; i++) {
    if (!prob(t->pof[i])) return 0;
  }
  double md = t->val[urVAL_NIJ_MODE];
  return prob(t->p) && (md != md || (md >= -1 && md <= 3 && md == (int)md)); /* no UB cast */
}

/* 1 if s is printable text as ura_printable keeps it (no control byte, DEL, C1 control or byte
   that is not UTF-8), else 0 */
static int printable(const char* s) {
  char shown[4 * sizeof((urCell*)0)->reason + 1];
  if (strlen(s) >= sizeof((urCell*)0)->reason) return 0;
  ura_printable(s, shown, sizeof shown);
  return !strcmp(shown, s);
}

int ura_cell_write(const urCell* c, char* buf, size_t n) {
  if (!in_domain(c)) return -2;
  char reason[sizeof c->reason];
  size_t k = 0;
  for (; k < sizeof reason - 1 && c->reason[k]; k++) {
    unsigned char ch = (unsigned char)c->reason[k];
    reason[k] = ch < 32 || ch == 127 ? ' ' : (char)ch;
  }
  reason[k] = 0;
  for (k = 0; !printable(reason) && reason[k]; k++) { /* not UTF-8, or C1 controls: ASCII */
    if ((unsigned char)reason[k] >= 128) reason[k] = '?';
  }
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

/* a whole number in [lo, hi] and its blank */
static int get_int(const char** s, int lo, int hi, int* v) {
  char* end;
  if (**s != '-' && (**s < '0' || **s > '9')) return -1;
  long x = strtol(*s, &end, 10);
  if (end == *s || *end != ' ' || x < lo || x > hi) return -1;
  *v = (int)x;
  *s = end + 1;
  return 0;
}

/* a number as %a writes it (or a decimal one): a sign, a digit or NaN first, no blank */
static int get_double(const char** s, double* v) {
  char* end;
  if (**s != '-' && **s != 'n' && (**s < '0' || **s > '9')) return -1;
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
  if (!in_domain(&t)) return -1;
  s++;
  size_t n = strcspn(s, "\n");
  if (n >= sizeof t.reason) return -1;
  memcpy(t.reason, s, n);
  t.reason[n] = 0;
  if (!printable(t.reason)) return -1; /* printed later: no escape sequence */
  t.dpar = c->dpar;
  t.dperp = c->dperp;
  *c = t;
  return 0;
}
