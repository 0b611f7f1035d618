/* modellang_names.c: the model-language parser (uasimpact-model(5)): messages with FILE:LINE and quoted user text, and the names: their
 * checks, symbol table with hash chains, references, declarations with limits, "did you mean". */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

const char* const url_keywords =
    "param, option, curve, material, section, layer, body, restraint, ellipsoid, law, pair, "
    "pairs, airbag, sensor, part, role, preset";
const char* const url_expect_num =
    "expected a decimal number such as 12, -0.5 or 2.5e-3, or $param";
const char* const url_expect_name =
    "expected letters, digits, '_' or '.', starting with a letter or '_', at most 31 characters";

const char* const url_symkind[SYM_NKIND] = {"parameter", "curve",    "law",     "body",   "joint",
                                            "ellipsoid", "pair",     "airbag",  "sensor", "part",
                                            "preset",    "material", "section", "layer"};
const char* const url_symkinds[SYM_NKIND] = {
    "parameters", "curves",  "laws",  "bodies",  "joints",    "ellipsoids", "pairs",
    "airbags",    "sensors", "parts", "presets", "materials", "sections",   "layers"};

/* the most elements of each kind a model may have (uasimpact-model(5), LIMITS): a model of the
   person and a drone has tens of bodies and a few hundred pairs; the limits keep the largest
   model parsing and compiling within about a second (the builder checks each new name among
   the elements of its kind) */
const int url_limit[SYM_NKIND] = {4000, 4000, 4000, 1000, 0,   2000, 5000,
                                  64,   1000, 256,  64,   256, 256,  64};
_Static_assert(sizeof url_limit / sizeof url_limit[0] ==
                       sizeof url_symkind / sizeof url_symkind[0] &&
                   sizeof url_symkinds / sizeof url_symkinds[0] ==
                       sizeof url_symkind / sizeof url_symkind[0],
               "a kind of name without its limit or plural");

//---------------------------------- messages ------------------------------------------------------


Quote url_quote(const char* s, size_t n) {
  Quote q;
  size_t max = sizeof(q.s) - 4;
  if (n <= max) {
    memcpy(q.s, s, n);
    q.s[n] = 0;
    return q;
  }

  /* cut on a UTF-8 character boundary */
  while (max > 0 && ((unsigned char)s[max] & 0xC0) == 0x80) {
    max--;
  }
  memcpy(q.s, s, max);
  memcpy(q.s + max, "...", 4);
  return q;
}


/* file name of a source */
const char* url_srcname(const Parser* p, int src) {
  const char* f = src >= 0 && src < p->nsrc ? p->src[src].file : NULL;
  return f && f[0] ? f : "model";
}


/* print "FILE:LINE: message" into the parser; returns -1 */
int url_fail(Parser* p, int line, const char* fmt, ...) {
  int k = snprintf(p->msg, sizeof(p->msg), "%s:%d: ", url_srcname(p, p->cursrc), line);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(p->msg + k, sizeof(p->msg) - (size_t)k, fmt, ap);
  va_end(ap);
  return -1;
}


/* edit distance of two short strings (for "did you mean") */
static int distance(const char* a, const char* b) {
  int la = (int)strlen(a), lb = (int)strlen(b);
  int row[urNAMELEN + 1];
  if (la >= urNAMELEN || lb >= urNAMELEN) {
    return 99;
  }
  for (int j = 0; j <= lb; j++) {
    row[j] = j;
  }
  for (int i = 1; i <= la; i++) {
    int diag = row[0];
    row[0] = i;
    for (int j = 1; j <= lb; j++) {
      int up = row[j];
      int best = diag + (a[i - 1] != b[j - 1]);
      best = best < up + 1 ? best : up + 1;
      best = best < row[j - 1] + 1 ? best : row[j - 1] + 1;
      row[j] = best;
      diag = up;
    }
  }
  return row[lb];
}

//---------------------------------- names ---------------------------------------------------------

/* 1 if s[0..n) is an identifier [A-Za-z_][A-Za-z0-9_.]* */
int url_isident(const char* s, size_t n) {
  if (n == 0 || !((s[0] >= 'A' && s[0] <= 'Z') || (s[0] >= 'a' && s[0] <= 'z') || s[0] == '_')) {
    return 0;
  }
  for (size_t i = 1; i < n; i++) {
    char c = s[i];
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
          c == '.')) {
      return 0;
    }
  }
  return 1;
}


/* check a name of n bytes; what says where it came from */
int url_checkname(Parser* p, const char* s, size_t n, int line, const char* what) {
  if (!url_isident(s, n)) {
    return url_fail(p, line, "%s: '%s' is not a valid name; %s", what, url_quote(s, n).s,
                    url_expect_name);
  }
  if (n >= urNAMELEN) {
    return url_fail(p, line, "%s: name '%s' is too long (%d characters); %s", what,
                    url_quote(s, n).s, (int)n, url_expect_name);
  }
  return 0;
}


/* FNV-1a hash of a name: a built-in model declares hundreds of pairs, each looked up among all
   names before it */
static unsigned namehash(const char* s) {
  unsigned h = 2166136261u;
  for (; *s; s++) {
    h = (h ^ (unsigned char)*s) * 16777619u;
  }
  return h;
}


/* last enabled symbol of a kind and name, or -1: its hash chain holds the symbols of that hash
   (and of others in the same bucket), newest first, so that a model of n names parses in time
   linear in n */
int url_findsym(const Parser* p, int kind, const char* name, int enabled) {
  if (!p->capsym) {
    return -1;
  }
  unsigned h = namehash(name);
  for (int i = p->chain[h & (unsigned)(p->capsym - 1)]; i >= 0; i = p->sym[i].next) {
    if (p->sym[i].hash == h && p->sym[i].kind == kind && p->sym[i].enabled == enabled &&
        !strcmp(p->sym[i].name, name)) {
      return i;
    }
  }
  return -1;
}


/* keyword that defines a kind of name */
static const char* kindword(int kind) {
  static const char* const kw[] = {"param",     "curve",    "law",     "body",   NULL,
                                   "ellipsoid", "pair",     "airbag",  "sensor", "part",
                                   "preset",    "material", "section", "layer"};
  _Static_assert(sizeof kw / sizeof kw[0] == SYM_NKIND, "a kind of name without its keyword");
  return kw[kind];
}


/* statement after the current one that defines name of kind; -1 if none */
int url_findlater(const Parser* p, int kind, const char* name) {
  const char* kw = kindword(kind == SYM_JOINT ? SYM_BODY : kind);
  for (int i = p->cur + 1; i < p->lx.nstmt; i++) {
    const urlStmt* st = p->lx.stmt + i;
    if (st->nword >= 2 && !strcmp(url_word(&p->lx, st->word), kw) &&
        !strcmp(url_word(&p->lx, st->word + 1), name)) {
      return i;
    }
  }
  return -1;
}


/* "did you mean" hint for an unknown name ("" if nothing is close) */
void url_suggest(const Parser* p, int kind, const char* name, char* out, size_t len) {
  int best = 3, bi = -1, nl = (int)strlen(name);
  out[0] = 0;
  for (int i = 0; i < p->nsym; i++) {
    if (p->sym[i].kind == kind && p->sym[i].enabled) {
      int dd = distance(name, p->sym[i].name);
      if (dd < best && dd < nl) {
        best = dd;
        bi = i;
      }
    }
  }
  if (bi >= 0) {
    snprintf(out, len, "; did you mean '%s'?", p->sym[bi].name);
  }
}


/* resolve a reference; returns the element id or -1 (message set) */
int url_ref(Parser* p, int kind, const char* name, int line, const char* ctx) {
  int i = url_findsym(p, kind, name, 1);
  if (i >= 0) {
    return p->sym[i].id;
  }

  /* explain why it is missing */
  int dis = url_findsym(p, kind, name, 0);
  int later = url_findlater(p, kind, name);
  char hint[96];
  if (dis >= 0) {
    snprintf(hint, sizeof(hint), " (disabled by enable=0 at %s:%d)",
             url_srcname(p, p->sym[dis].src), p->sym[dis].line);
  } else if (later >= 0) {
    snprintf(hint, sizeof(hint), " (defined later, at %s:%d; define it before use)",
             url_srcname(p, p->lx.stmt[later].src), p->lx.stmt[later].line);
  } else {
    url_suggest(p, kind, name, hint, sizeof(hint));
  }
  url_fail(p, line, "%s%sdangling reference to %s '%s'%s", ctx ? ctx : "", ctx ? ": " : "",
           url_symkind[kind], name, hint);
  return -1;
}


/* declare a name; duplicates of enabled names are errors (params, parts: per source) */
int url_declare(Parser* p, int kind, const char* name, int line, int id, int enabled) {
  if (enabled) {
    int i = url_findsym(p, kind, name, 1);
    int persrc = kind == SYM_PARAM || kind == SYM_PART;
    if (i >= 0 && (!persrc || p->sym[i].src == p->cursrc)) {
      return url_fail(p, line,
                      "duplicate %s name '%s' (first defined at %s:%d); names must be "
                      "unique",
                      url_symkind[kind], name, url_srcname(p, p->sym[i].src), p->sym[i].line);
    }
  }
  if (enabled && kind != SYM_JOINT && ++p->count[kind] > url_limit[kind]) {
    return url_fail(p, line,
                    "more than %d %s in the model; accepted: at most %d (uasimpact-model(5), "
                    "LIMITS)",
                    url_limit[kind], url_symkinds[kind], url_limit[kind]);
  }
  if (p->nsym == p->capsym) {
    /* twice the room, and the chains rebuilt over twice the buckets (a power of two) */
    int nc = p->capsym ? 2 * p->capsym : 64;
    Sym* s = realloc(p->sym, (size_t)nc * sizeof(Sym));
    if (!s) {
      return url_fail(p, line, "out of memory");
    }
    p->sym = s;
    int* ch = realloc(p->chain, (size_t)nc * sizeof(int));
    if (!ch) {
      return url_fail(p, line, "out of memory");
    }
    p->chain = ch;
    p->capsym = nc;
    for (int i = 0; i < nc; i++) {
      ch[i] = -1;
    }
    for (int i = 0; i < p->nsym; i++) {
      int* head = ch + (p->sym[i].hash & (unsigned)(nc - 1));
      p->sym[i].next = *head;
      *head = i;
    }
  }
  int at = p->nsym++;
  Sym* s = p->sym + at;
  s->kind = kind;
  snprintf(s->name, sizeof(s->name), "%s", name);
  s->hash = namehash(s->name);
  s->id = id;
  s->src = p->cursrc;
  s->line = line;
  s->enabled = enabled;
  int* head = p->chain + (s->hash & (unsigned)(p->capsym - 1));
  s->next = *head;
  *head = at;
  return 0;
}


/* append one element to a parser table; returns its index or -1 */
int url_push(Parser* p, void** arr, int* n, int* cap, size_t size, int line) {
  if (*n == *cap) {
    int nc = *cap ? 2 * (*cap) : 16;
    void* a = realloc(*arr, (size_t)nc * size);
    if (!a) {
      return url_fail(p, line, "out of memory");
    }
    *arr = a;
    *cap = nc;
  }
  memset((char*)*arr + (size_t)(*n) * size, 0, size);
  return (*n)++;
}
