/* model_save.c: model save FILE, the model set as model-language text that carries the model
 * parameters the user set (set bag_p0 1.1 atm): each is written into its param line, in that
 * line's unit, and into the live case's preset line where that preset sets it, so that the file
 * loaded in a fresh session gives the drone the session has now (the saved case included).
 * Settings that are not model text (wind, grid step, threads, the descent's and the parametric
 * model's figures) stay out: save session keeps them. The rest of the text is kept byte for
 * byte, comments and continuation lines included; the words are the parser's own
 * (ur_model_words). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "case.h"


/* a replacement of text[at, at + len) */
typedef struct {
  size_t at, len;
  char with[96];
} Edit;

static int word_is(const char* text, const urModelWord* w, const char* s) {
  return w->len == strlen(s) && !strncmp(text + w->at, s, w->len);
}

/* the shortest decimal x with x * f == v exactly (the parser's reading of "x UNIT"); 0, or -1
   when none (v not reachable in this unit) */
static int in_unit(double v, double f, char* buf, size_t n) {
  if (f == 1) {
    ura_num_shortest(buf, n, v);
    return 0;
  }
  double x = v / f;
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(buf, n, "%.*g", prec, x);
    if (strtod(buf, NULL) * f == v) {
      ura_num_shortest(buf, n, strtod(buf, NULL));
      return 0;
    }
  }
  double up = x, down = x; /* the next doubles either side */
  for (int k = 0; k < 4; k++) {
    up = nextafter(up, INFINITY);
    down = nextafter(down, -INFINITY);
    snprintf(buf, n, "%.17g", up);
    if (strtod(buf, NULL) * f == v) return 0;
    snprintf(buf, n, "%.17g", down);
    if (strtod(buf, NULL) * f == v) return 0;
  }
  return -1;
}

/* the edits that write the user's value of parameter name (SI v) into part p's text: its param
   line (the last one, the one that counts) and the key of preset pre; *found set when the part
   defines it */
static int edits_for(uraCtx* c, const uraPart* p, const urModelWord* w, int nw, const char* name,
                     double v, const char* pre, Edit* ed, int* ned, int max, int* found) {
  const char* t = p->text;
  int last = -1;
  for (int i = 0; i + 2 < nw; i++) {
    if ((i == 0 || w[i - 1].stmt != w[i].stmt) && word_is(t, &w[i], "param") &&
        w[i + 1].stmt == w[i].stmt && w[i + 2].stmt == w[i].stmt && word_is(t, &w[i + 1], name))
      last = i;
  }
  if (last >= 0 && *ned < max) {
    const urModelWord* val = &w[last + 2];
    const urModelWord* u = last + 3 < nw && w[last + 3].stmt == val->stmt ? &w[last + 3] : NULL;
    double f = 1;
    char unit[64] = "";
    if (u && !memchr(t + u->at, '=', u->len) && u->len < sizeof unit) {
      snprintf(unit, sizeof unit, "%.*s", (int)u->len, t + u->at);
      if (ur_unit_si(unit, &f)) f = 1;
    }
    Edit* e = &ed[(*ned)++];
    e->at = val->at;
    e->len = val->len;
    if (in_unit(v, f, e->with, sizeof e->with)) {
      return ura_fail(c,
                      "model save: %s = %.17g cannot be written exactly in its line's unit '%s'; "
                      "accepted: a value that unit reaches (set %s in its SI unit)",
                      name, v, unit, name);
    }
    *found = 1;
  }
  /* the live case's preset: key=VALUE[UNIT] keeps its unit, $param becomes the number (SI) */
  for (int i = 0; i + 1 < nw; i++) {
    if (!((i == 0 || w[i - 1].stmt != w[i].stmt) && word_is(t, &w[i], "preset") &&
          w[i + 1].stmt == w[i].stmt && w[i + 1].len == strlen(pre) &&
          !strncasecmp(t + w[i + 1].at, pre, w[i + 1].len)))
      continue;
    size_t kl = strlen(name);
    for (int j = i + 2; j < nw && w[j].stmt == w[i].stmt && *ned < max; j++) {
      const char* s = t + w[j].at;
      if (w[j].len <= kl + 1 || strncmp(s, name, kl) || s[kl] != '=') continue;
      const char* val = s + kl + 1;
      size_t vn = w[j].len - kl - 1, k = 0;
      while (k < vn &&
             (strchr("+-.0123456789", val[k]) || ((val[k] == 'e' || val[k] == 'E') && k + 1 < vn &&
                                                  strchr("+-0123456789", val[k + 1]))))
        k += (val[k] == 'e' || val[k] == 'E') ? 2 : 1;
      double f = 1;
      char unit[64] = "";
      int ref = val[0] == '$' || (val[0] == '-' && vn > 1 && val[1] == '$');
      if (!ref && k < vn && vn - k < sizeof unit) {
        snprintf(unit, sizeof unit, "%.*s", (int)(vn - k), val + k);
        if (ur_unit_si(unit, &f)) f = 1, unit[0] = 0;
      }
      Edit* e = &ed[(*ned)++];
      e->at = w[j].at + kl + 1;
      e->len = vn;
      char num[64];
      if (in_unit(v, f, num, sizeof num)) f = 1, unit[0] = 0, ura_num_shortest(num, sizeof num, v);
      snprintf(e->with, sizeof e->with, "%s%s", num, unit);
    }
  }
  return 0;
}

static int by_place(const void* a, const void* b) {
  const Edit *x = a, *y = b;
  return x->at < y->at ? -1 : x->at > y->at;
}

/* part p's text with the user's parameters written in, to f */
static int write_part(uraCtx* c, FILE* f, int ip, int* defined) {
  const uraPart* p = &c->part[ip];
  int nw;
  urModelWord* w;
  char err[300];
  if (ur_model_words(p->text, &w, &nw, err, sizeof err)) return ura_fail(c, "model save: %s", err);
  Edit ed[2 * uraMAXOV];
  int ned = 0;
  for (int k = 0; k < c->st.nov; k++) {
    if (!c->st.ov_user[k]) continue;
    int found = 0;
    if (edits_for(c, p, w, nw, c->st.ov_name[k], c->st.ov_val[k], c->st.casename, ed, &ned,
                  2 * uraMAXOV, &found)) {
      free(w);
      return -1;
    }
    if (found) defined[k] = ip + 1; /* a later part's line is the one that counts */
  }
  free(w);
  qsort(ed, (size_t)ned, sizeof *ed, by_place);
  size_t at = 0;
  for (int i = 0; i < ned; i++) {
    if (ed[i].at < at) continue; /* one word, one edit */
    fwrite(p->text + at, 1, ed[i].at - at, f);
    fputs(ed[i].with, f);
    at = ed[i].at + ed[i].len;
  }
  fputs(p->text + at, f);
  size_t n = strlen(p->text);
  if (n && p->text[n - 1] != '\n') fputc('\n', f);
  return 0;
}

int ura_model_save(uraCtx* c, const char* path) {
  if (ura_name_fits(c, "model save", path, "model-language text", "urm txt")) return -1;
  int defined[uraMAXOV] = {0};
  char* text = NULL;
  size_t len = 0;
  FILE* m = open_memstream(&text, &len);
  if (!m) return ura_fail(c, "model save: out of memory");
  int rc = 0;
  for (int i = 0; i < c->npart && !rc; i++) rc = write_part(c, m, i, defined);
  fclose(m);
  for (int k = 0; k < c->st.nov && !rc; k++) {
    if (c->st.ov_user[k] && !defined[k]) {
      rc = ura_fail(c,
                    "model save: no param line of '%s' in the model text to write its value "
                    "into; accepted: parameters the model defines ('model params')",
                    c->st.ov_name[k]);
    }
  }
  uraAtomic a;
  if (!rc && !ura_atomic_open(c, &a, path, "model save")) {
    fwrite(text, 1, len, a.f);
    rc = ura_atomic_close(c, &a, 1, "model save");
  } else {
    rc = -1;
  }
  free(text);
  return rc;
}
