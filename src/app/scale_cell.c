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
  int w = snprintf(buf, n, "%d %d %a %a %a %a %d %a %a %a %a %a %a %d |%s", c->status, c->contact,
                   c->hic15, c->hic_t1, c->hic_t2, c->nij, c->nij_mode, c->vc_thorax,
                   c->vc_abdomen, c->p_hic, c->p_nij, c->p_vc, c->p, c->extrap, reason);
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
  if (get_int(&s, urCELL_PENDING, urCELL_FAILED, &t.status) || get_int(&s, 0, 1, &t.contact) ||
      get_double(&s, &t.hic15) || get_double(&s, &t.hic_t1) || get_double(&s, &t.hic_t2) ||
      get_double(&s, &t.nij) || get_int(&s, -1, 3, &t.nij_mode) ||
      get_double(&s, &t.vc_thorax) || get_double(&s, &t.vc_abdomen) ||
      get_double(&s, &t.p_hic) || get_double(&s, &t.p_nij) || get_double(&s, &t.p_vc) ||
      get_double(&s, &t.p) || get_int(&s, 0, 1 << 30, &t.extrap) || *s != '|') {
    return -1;
  }
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
