/* modellang_value.c: the model-language parser (uasimpact-model(5)): units, numbers (with $param references) and the binding of a
 * statement's key=value words to its key table. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

/* units: name, factor to SI, and the SI unit it is in */
static const struct {
  const char* name;
  double f;
  const char* si;
} units[] = {
    {"m", 1, "m"},      {"mm", 1e-3, "m"},     {"cm", 1e-2, "m"},  {"kg", 1, "kg"},
    {"g", 1e-3, "kg"},  {"s", 1, "s"},         {"ms", 1e-3, "s"},  {"N", 1, "N"},
    {"kN", 1e3, "N"},   {"Pa", 1, "Pa"},       {"kPa", 1e3, "Pa"}, {"MPa", 1e6, "Pa"},
    {"GPa", 1e9, "Pa"}, {"atm", 101325, "Pa"}, {"bar", 1e5, "Pa"}, {"deg", M_PI / 180, "rad"},
    {"rad", 1, "rad"},  {"J", 1, "J"},         {"L", 1e-3, "m^3"}, {"none", 1, ""}};

/* the names of the units of the table, ", "-separated, into list (len bytes) */
void url_unit_names(char* list, size_t len) {
  size_t k = 0;
  list[0] = 0;
  for (size_t i = 0; i < sizeof units / sizeof units[0] && k < len; i++) {
    k += (size_t)snprintf(list + k, len - k, "%s%s", i ? ", " : "", units[i].name);
  }
}

/* a unit: units of the table joined by '*' and '/' (N*m/rad, kN/m); the factor to SI and the
   SI unit (si may be NULL) */
int ur_unit_parse(const char* unit, double* factor, char* si, size_t n) {
  double f = 1;
  size_t k = 0;
  char op = '*';
  if (!unit || !*unit) return -1;
  if (si && n) si[0] = 0;
  for (const char* s = unit;;) {
    size_t len = strcspn(s, "*/");
    size_t i = 0, nu = sizeof units / sizeof units[0];
    while (i < nu && !(strlen(units[i].name) == len && !strncmp(units[i].name, s, len))) i++;
    if (i == nu || (op != 0 && len == 0)) return -1;
    if (!strcmp(units[i].name, "none") && strlen(unit) != 4) return -1;
    f = op == '*' ? f * units[i].f : f / units[i].f;
    if (si && *units[i].si) {
      k += (size_t)snprintf(si + k, k < n ? n - k : 0, "%s%s",
                            k           ? (op == '*' ? "*" : "/")
                            : op == '/' ? "1/"
                                        : "",
                            units[i].si);
    }
    if (!s[len]) break;
    op = s[len];
    s += len + 1;
  }
  if (si && k >= n) return -1;
  *factor = f;
  return 0;
}

int ur_unit_si(const char* unit, double* factor) {
  return ur_unit_parse(unit, factor, NULL, 0);
}

//---------------------------------- numbers -------------------------------------------------------

/* length of the longest prefix of s[0..n) that is a strict decimal number (0: none) */
size_t url_decimal_prefix(const char* s, size_t n) {
  size_t i = 0, digits = 0;
  if (i < n && (s[i] == '+' || s[i] == '-')) {
    i++;
  }
  while (i < n && s[i] >= '0' && s[i] <= '9') {
    i++;
    digits++;
  }
  if (i < n && s[i] == '.') {
    size_t j = i + 1, frac = 0;
    while (j < n && s[j] >= '0' && s[j] <= '9') {
      j++;
      frac++;
    }
    if (digits + frac > 0) {
      i = j;
      digits += frac;
    }
  }
  if (!digits) {
    return 0;
  }

  /* exponent only when complete */
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    size_t j = i + 1, ed = 0;
    if (j < n && (s[j] == '+' || s[j] == '-')) {
      j++;
    }
    while (j < n && s[j] >= '0' && s[j] <= '9') {
      j++;
      ed++;
    }
    if (ed) {
      i = j;
    }
  }
  return i;
}


/* case-insensitive equality of s[0..n) and a lowercase word */
static int ieq(const char* s, size_t n, const char* w) {
  if (strlen(w) != n) {
    return 0;
  }
  for (size_t i = 0; i < n; i++) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') {
      c = (char)(c - 'A' + 'a');
    }
    if (c != w[i]) {
      return 0;
    }
  }
  return 1;
}


/* value of parameter name (already defined), or -1 with a message */
static int paramref(Parser* p, const char* s, size_t n, int line, const char* ctx, double* v) {
  if (url_checkname(p, s, n, line, ctx)) {
    return -1;
  }
  char name[urNAMELEN];
  memcpy(name, s, n);
  name[n] = 0;
  int i = url_findsym(p, SYM_PARAM, name, 1);
  if (i >= 0) {
    *v = p->pval[p->sym[i].id];
    return 0;
  }
  int later = url_findlater(p, SYM_PARAM, name);
  if (later >= 0) {
    return url_fail(p, line,
                    "%s: parameter '%s' used before its definition (at %s:%d); expected "
                    "'param %s VALUE' above this line",
                    ctx, name, url_srcname(p, p->lx.stmt[later].src), p->lx.stmt[later].line, name);
  }
  char hint[96];
  url_suggest(p, SYM_PARAM, name, hint, sizeof(hint));
  return url_fail(p, line, "%s: unknown parameter '%s'%s%s", ctx, name, hint,
                  hint[0] ? "" : "; expected 'param NAME VALUE' before its use");
}


/* one number s[0..n): strict decimal, $param or -$param; ctx prefixes messages */
int url_number(Parser* p, const char* s, size_t n, int line, const char* ctx, double* v) {
  if (n == 0) {
    return url_fail(p, line, "%s: empty number; %s", ctx, url_expect_num);
  }

  /* parameter reference */
  if (s[0] == '$' || (n > 1 && s[0] == '-' && s[1] == '$')) {
    int neg = s[0] == '-';
    if (paramref(p, s + 1 + neg, n - 1 - (size_t)neg, line, ctx, v)) {
      return -1;
    }
    if (neg) {
      *v = -*v;
    }
    return 0;
  }

  /* spelled-out non-finite values and hexadecimal */
  size_t b = (s[0] == '+' || s[0] == '-') ? 1 : 0;
  const char* t = s + b;
  size_t tn = n - b;
  if (ieq(t, tn, "nan") || ieq(t, tn, "inf") || ieq(t, tn, "infinity") ||
      (tn > 3 && ieq(t, 4, "nan("))) {
    return url_fail(p, line, "%s: '%s' is not a finite number; %s", ctx, url_quote(s, n).s,
                    url_expect_num);
  }
  if (tn >= 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
    return url_fail(p, line, "%s: '%s' is not a decimal number (hexadecimal is not accepted); %s",
                    ctx, url_quote(s, n).s, url_expect_num);
  }

  /* strict decimal syntax over the whole word */
  size_t k = url_decimal_prefix(s, n);
  if (k == 0) {
    if (url_isident(s, n)) {
      return url_fail(p, line, "%s: '%s' is not a number (for a parameter write $%s); %s", ctx,
                      url_quote(s, n).s, url_quote(s, n).s, url_expect_num);
    }
    return url_fail(p, line, "%s: '%s' is not a number; %s", ctx, url_quote(s, n).s,
                    url_expect_num);
  }
  if (k < n) {
    return url_fail(p, line, "%s: '%s' is not a number (unexpected '%s' after '%s'); %s", ctx,
                    url_quote(s, n).s, url_quote(s + k, n - k).s, url_quote(s, k).s,
                    url_expect_num);
  }
  if (n > NUMLEN) {
    return url_fail(p, line, "%s: number '%s' is too long (%d characters)", ctx, url_quote(s, n).s,
                    (int)n);
  }

  /* convert the validated text (correctly rounded); the range must be that of a double */
  char buf[NUMLEN + 1];
  memcpy(buf, s, n);
  buf[n] = 0;
  char* end;
  errno = 0;
  double x = strtod(buf, &end);
  if (end != buf + n) {
    return url_fail(p, line, "%s: cannot convert '%s' (C library locale?)", ctx, url_quote(s, n).s);
  }
  if (!isfinite(x) || (errno == ERANGE && fabs(x) >= 1)) {
    return url_fail(p, line,
                    "%s: '%s' is not a finite number (beyond the range of a double, "
                    "about 1.8e308); %s",
                    ctx, url_quote(s, n).s, url_expect_num);
  }
  if (errno == ERANGE) {
    return url_fail(p, line,
                    "%s: '%s' is too small to be represented (below about 2.2e-308); "
                    "expected 0 or a larger magnitude",
                    ctx, url_quote(s, n).s);
  }
  *v = x;
  return 0;
}


/* comma-separated numbers into v (at most max); returns the count or -1 */
static int numbers(Parser* p, const char* s, int line, const char* ctx, double* v, int max) {
  int k = 0;
  for (;;) {
    const char* c = strchr(s, ',');
    size_t n = c ? (size_t)(c - s) : strlen(s);
    if (k < max && url_number(p, s, n, line, ctx, v + k)) {
      return -1;
    }
    k++;
    if (!c) {
      return k;
    }
    s = c + 1;
  }
}


/* count of comma-separated items */
int url_count(const char* s) {
  int k = 1;
  for (; *s; s++) {
    k += *s == ',';
  }
  return k;
}

//---------------------------------- statement binding ---------------------------------------------

/* list of the keys of a table, for messages */
static void keylist(const KeySpec* spec, int nspec, char* out, size_t len) {
  size_t k = 0;
  out[0] = 0;
  for (int i = 0; i < nspec && k < len; i++) {
    k += (size_t)snprintf(out + k, len - k, "%s%s", i ? ", " : "", spec[i].key);
  }
}


/* value of key in a bound statement (never NULL: keys are from the table) */
const Val* url_get(const Bound* b, const char* key) {
  for (int i = 0; i < b->nspec; i++) {
    if (!strcmp(b->spec[i].key, key)) {
      return b->val + i;
    }
  }
  return NULL;
}


/* parse one value according to its key */
static int value(Parser* p, const KeySpec* ks, Val* v) {
  char ctx[64];
  snprintf(ctx, sizeof(ctx), "key '%s'", ks->key);
  int n = url_count(v->raw);

  switch (ks->kind) {
  case K_NUM:
  case K_INT:
  case K_FLAG:
    if (n != 1) {
      return url_fail(p, v->line, "key '%s' needs 1 number (got %d)", ks->key, n);
    }
    if (url_number(p, v->raw, strlen(v->raw), v->line, ctx, v->v)) {
      return -1;
    }
    v->n = 1;
    if (ks->kind == K_INT && !(v->v[0] >= 0 && v->v[0] <= 1e6 && v->v[0] == floor(v->v[0]))) {
      return url_fail(p, v->line, "key '%s' must be a whole number >= 0 (got %g)", ks->key,
                      v->v[0]);
    }
    if (ks->kind == K_FLAG && v->v[0] != 0 && v->v[0] != 1) {
      return url_fail(p, v->line, "key '%s' must be 0 or 1 (got %g)", ks->key, v->v[0]);
    }
    return 0;

  case K_VEC:
    if (n != ks->n && n != ks->n2) {
      if (ks->n2) {
        return url_fail(p, v->line, "key '%s' needs %d or %d numbers (got %d)", ks->key, ks->n,
                        ks->n2, n);
      }
      return url_fail(p, v->line, "key '%s' needs %d numbers (got %d)", ks->key, ks->n, n);
    }
    v->n = n;
    return numbers(p, v->raw, v->line, ctx, v->v, n) < 0 ? -1 : 0;

  case K_LIST:
    if (n < ks->n2 || n > ks->n) {
      return url_fail(p, v->line, "key '%s' needs %d to %d numbers (got %d)", ks->key, ks->n2,
                      ks->n, n);
    }
    v->n = n;
    return numbers(p, v->raw, v->line, ctx, v->v, n) < 0 ? -1 : 0;

  case K_NAME: v->n = 1; return url_checkname(p, v->raw, strlen(v->raw), v->line, ctx);

  case K_NAMES: {
    if (n < ks->n2 || n > ks->n) {
      return url_fail(p, v->line, "key '%s' needs %d to %d names (got %d)", ks->key, ks->n2, ks->n,
                      n);
    }
    const char* s = v->raw;
    for (int i = 0; i < n; i++) {
      const char* c = strchr(s, ',');
      size_t len = c ? (size_t)(c - s) : strlen(s);
      if (url_checkname(p, s, len, v->line, ctx)) {
        return -1;
      }
      s = c ? c + 1 : s + len;
    }
    v->n = n;
    return 0;
  }

  case K_ENUM: {
    const char* w = ks->enums;
    size_t len = strlen(v->raw);
    for (int i = 0; *w; i++) {
      const char* bar = strchr(w, '|');
      size_t wl = bar ? (size_t)(bar - w) : strlen(w);
      if (wl == len && !strncmp(w, v->raw, len)) {
        v->e = i;
        v->n = 1;
        return 0;
      }
      w += wl + (bar ? 1 : 0);
    }
    char list[160];
    snprintf(list, sizeof(list), "%s", ks->enums);
    for (char* c = list; *c; c++) {
      *c = *c == '|' ? '/' : *c;
    }
    return url_fail(p, v->line, "key '%s': unknown value '%s'; expected one of %s", ks->key,
                    url_quote(v->raw, len).s, list);
  }
  }
  return url_fail(p, v->line, "internal error: bad key kind");
}


/* bind words [first, end) as key=value to a key table: unknown, duplicate and empty keys,
   required keys, enable, values; returns 0, 1 if disabled (values not parsed), or -1 */
int url_bind(Parser* p, const urlStmt* st, int first, const KeySpec* spec, int nspec, Bound* b) {
  b->spec = spec;
  b->nspec = nspec;
  memset(b->val, 0, sizeof(b->val));
  if (nspec > MAXKEY) {
    return url_fail(p, b->line, "internal error: too many keys for %s", b->kw);
  }

  /* keys */
  for (int w = first; w < st->nword; w++) {
    const char* s = url_word(&p->lx, st->word + w);
    int line = p->lx.word[st->word + w].line;
    const char* eq = strchr(s, '=');
    if (!eq) {
      return url_fail(p, line, "%s: expected key=value, got '%s' (no blanks around '=')", b->kw,
                      url_quote(s, strlen(s)).s);
    }
    size_t kl = (size_t)(eq - s);
    if (kl == 0) {
      return url_fail(p, line, "%s: missing key before '=' in '%s'", b->kw,
                      url_quote(s, strlen(s)).s);
    }
    int k = 0;
    while (k < nspec && !(strlen(spec[k].key) == kl && !strncmp(spec[k].key, s, kl))) {
      k++;
    }
    if (k == nspec) {
      char list[400];
      keylist(spec, nspec, list, sizeof(list));
      return url_fail(p, line, "unknown key '%s' for %s; expected one of %s", url_quote(s, kl).s,
                      b->what, list);
    }
    if (b->val[k].set) {
      return url_fail(p, line,
                      "duplicate key '%s' (first given on line %d); a key may appear once "
                      "per statement",
                      spec[k].key, b->val[k].line);
    }
    if (!eq[1]) {
      return url_fail(p, line, "missing value for key '%s'; expected %s=VALUE", spec[k].key,
                      spec[k].key);
    }
    b->val[k].set = 1;
    b->val[k].line = line;
    b->val[k].raw = eq + 1;
  }

  /* required keys */
  for (int k = 0; k < nspec; k++) {
    if (spec[k].req && !b->val[k].set) {
      return url_fail(p, b->line, "%s%s%s%s: missing key '%s'; expected %s=VALUE", b->kw,
                      b->name ? " '" : "", b->name ? b->name : "", b->name ? "'" : "", spec[k].key,
                      spec[k].key);
    }
  }

  /* enable first: a disabled statement is not evaluated further */
  for (int k = 0; k < nspec; k++) {
    if (!strcmp(spec[k].key, "enable") && b->val[k].set) {
      if (value(p, spec + k, b->val + k)) {
        return -1;
      }
      if (b->val[k].v[0] == 0) {
        return 1;
      }
    }
  }

  /* values */
  for (int k = 0; k < nspec; k++) {
    if (b->val[k].set && strcmp(spec[k].key, "enable") && value(p, spec + k, b->val + k)) {
      return -1;
    }
  }
  return 0;
}


/* the i-th item of a comma-separated list into out (size len); -1 if it does not fit */
int url_item(const char* s, int i, char* out, size_t len) {
  for (int k = 0; k < i; k++) {
    s = strchr(s, ',') + 1;
  }
  size_t n = strcspn(s, ",");
  if (n >= len) {
    return -1;
  }
  memcpy(out, s, n);
  out[n] = 0;
  return 0;
}


/* number of a key or a default */
double url_num(const Bound* b, const char* key, double dflt) {
  const Val* v = url_get(b, key);
  return v->set ? v->v[0] : dflt;
}


/* check that an optional key is >= 0 (strict: > 0) */
int url_nonneg(Parser* p, const Bound* b, const char* key, int strict) {
  const Val* v = url_get(b, key);
  if (v->set && (strict ? !(v->v[0] > 0) : !(v->v[0] >= 0))) {
    return url_fail(p, v->line, "%s '%s': %s must be %s 0 (got %g)", b->kw, b->name, key,
                    strict ? ">" : ">=", v->v[0]);
  }
  return 0;
}


/* orientation from quat= or rot=ax,ay,az,deg (identity if neither); -1 on error */
int url_orientation(Parser* p, const Bound* b, double q[4]) {
  const Val* vq = url_get(b, "quat");
  const Val* vr = url_get(b, "rot");
  q[0] = 1;
  q[1] = q[2] = q[3] = 0;
  if (vq->set && vr->set) {
    return url_fail(p, vr->line, "%s '%s': give quat or rot, not both", b->kw, b->name);
  }
  if (vq->set) {
    double n =
        sqrt(vq->v[0] * vq->v[0] + vq->v[1] * vq->v[1] + vq->v[2] * vq->v[2] + vq->v[3] * vq->v[3]);
    if (!(n > 0)) {
      return url_fail(p, vq->line, "%s '%s': quat must not be zero; expected w,x,y,z", b->kw,
                      b->name);
    }
    for (int k = 0; k < 4; k++) {
      q[k] = vq->v[k] / n;
    }
  }
  if (vr->set) {
    double n = sqrt(vr->v[0] * vr->v[0] + vr->v[1] * vr->v[1] + vr->v[2] * vr->v[2]);
    if (!(n > 0)) {
      return url_fail(p, vr->line, "%s '%s': rot axis must not be zero; expected ax,ay,az,deg",
                      b->kw, b->name);
    }
    double h = 0.5 * vr->v[3] * M_PI / 180, s = sin(h);
    q[0] = cos(h);
    for (int k = 0; k < 3; k++) {
      q[k + 1] = s * vr->v[k] / n;
    }
  }
  return 0;
}


/* a vector key or NULL when absent */
const double* url_vec(const Bound* b, const char* key) {
  const Val* v = url_get(b, key);
  return v->set ? v->v : NULL;
}
