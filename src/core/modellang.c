/* modellang.c: parser of the model language (uasrisk-model(5)): statements into builder calls,
 * parameters, units, overrides, enable flags, name resolution, checks with FILE:LINE messages,
 * and the split of a text into parts. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasrisk/modellang.h"
#include "modellang_internal.h"

#define MAXKEY  20  /* keys of one statement kind */
#define MSGLEN  512 /* internal message buffer */
#define MAXLIST 64  /* names in one list of 'pairs' */
#define NUMLEN  400 /* longest number accepted, characters */

static const char* const keywords =
    "param, option, curve, body, restraint, ellipsoid, law, pair, pairs, airbag, sensor, part, "
    "role, preset";
static const char* const expect_num =
    "expected a decimal number such as 12, -0.5 or 2.5e-3, or $param";
static const char* const expect_name =
    "expected letters, digits, '_' or '.', starting with a letter or '_', at most 31 characters";

//---------------------------------- tables --------------------------------------------------------

/* kinds of names */
enum {
  SYM_PARAM = 0,
  SYM_CURVE,
  SYM_LAW,
  SYM_BODY,
  SYM_JOINT,
  SYM_ELLIPSOID,
  SYM_PAIR,
  SYM_AIRBAG,
  SYM_SENSOR,
  SYM_PART,
  SYM_PRESET
};
static const char* const symkind[] = {"parameter", "curve",  "law",    "body", "joint", "ellipsoid",
                                      "pair",      "airbag", "sensor", "part", "preset"};
static const char* const symkinds[] = {"parameters", "curves",     "laws",   "bodies",
                                       "joints",     "ellipsoids", "pairs",  "airbags",
                                       "sensors",    "parts",      "presets"};

/* the most elements of each kind a model may have (uasrisk-model(5), LIMITS): a model of the
   person and a drone has tens of bodies and a few hundred pairs; the limits keep the largest
   model parsing and compiling within about a second (the builder checks each new name among
   the elements of its kind) */
static const int limit[] = {4000, 4000, 4000, 1000, 0, 2000, 5000, 64, 1000, 256, 64};
_Static_assert(sizeof limit / sizeof limit[0] == sizeof symkind / sizeof symkind[0] &&
                   sizeof symkinds / sizeof symkinds[0] == sizeof symkind / sizeof symkind[0],
               "a kind of name without its limit or plural");

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

/* kinds of values */
enum {
  K_NUM = 0, /* one number */
  K_INT,     /* one whole number >= 0 */
  K_FLAG,    /* 0 or 1 */
  K_VEC,     /* n numbers (or n2) */
  K_LIST,    /* n2..n numbers */
  K_NAME,    /* one name */
  K_NAMES,   /* n2..n names */
  K_ENUM     /* one of the words in enums */
};

/* one key of a statement */
typedef struct {
  const char* key;
  int kind;
  int n, n2;         /* counts, see the kinds */
  int req;           /* 1: required */
  const char* enums; /* K_ENUM: words separated by '|' */
} KeySpec;

/* shorthands for the key tables */
#define NUM(k)                                                                                     \
  { k, K_NUM, 1, 0, 0, NULL }
#define NUMR(k)                                                                                    \
  { k, K_NUM, 1, 0, 1, NULL }
#define VEC3(k)                                                                                    \
  { k, K_VEC, 3, 0, 0, NULL }
#define VEC3R(k)                                                                                   \
  { k, K_VEC, 3, 0, 1, NULL }
#define QUAT                                                                                       \
  { "quat", K_VEC, 4, 0, 0, NULL }
#define ROT                                                                                        \
  { "rot", K_VEC, 4, 0, 0, NULL }
#define NAMER(k)                                                                                   \
  { k, K_NAME, 1, 0, 1, NULL }
#define NAME(k)                                                                                    \
  { k, K_NAME, 1, 0, 0, NULL }
#define FLAG(k)                                                                                    \
  { k, K_FLAG, 1, 0, 0, NULL }
#define ENABLE   FLAG("enable")
#define FRICTION NUM("damping"), NUM("chi"), NUM("mu"), NUM("v_eps")
#define NKEY(a)  ((int)(sizeof(a) / sizeof(a[0])))

static const KeySpec spec_option[] = {NUM("dt"),
                                      NUM("sample_dt"),
                                      NUM("tmax"),
                                      NUM("t_quiet"),
                                      NUM("t_clear"),
                                      NUM("a_clear"),
                                      NUM("ke_settle"),
                                      NUM("vmax"),
                                      NUM("jump_margin"),
                                      VEC3("gravity"),
                                      {"integrator", K_ENUM, 1, 0, 0, "euler|rk4"},
                                      {"damping", K_ENUM, 1, 0, 0, "implicit|explicit"},
                                      ENABLE};
static const KeySpec spec_curve[] = {{"x", K_LIST, urMAXCURVE, 2, 1, NULL},
                                     {"y", K_LIST, urMAXCURVE, 2, 1, NULL},
                                     NUM("xscale"),
                                     NUM("yscale"),
                                     ENABLE};
static const KeySpec spec_body[] = {
    NAMER("parent"),
    {"joint", K_ENUM, 1, 0, 1, "free|fixed|revolute|universal|spherical|prismatic"},
    VEC3R("pos"),
    QUAT,
    ROT,
    NUMR("mass"),
    VEC3("com"),
    {"inertia", K_VEC, 3, 6, 0, NULL},
    VEC3("axis"),
    VEC3("axis2"),
    NAME("jname"),
    FLAG("gravity"),
    ENABLE};
static const KeySpec spec_restraint[] = {{"dof", K_INT, 1, 0, 1, NULL},
                                         NUM("k"),
                                         NUM("sat"),
                                         NAME("load"),
                                         NAME("unload"),
                                         NUM("c"),
                                         NUM("lo"),
                                         NUM("hi"),
                                         NUM("kstop"),
                                         NUM("cstop"),
                                         NUM("x0"),
                                         ENABLE};
static const KeySpec spec_ellipsoid[] = {NAMER("body"), VEC3R("pos"),  VEC3R("size"), QUAT,
                                         ROT,           NUM("degree"), ENABLE};
#define LAWTYPE                                                                                    \
  { "type", K_ENUM, 1, 0, 1, "hertz|table|foam" }
static const KeySpec spec_hertz[] = {LAWTYPE,         NUMR("E1"),      NUMR("nu1"), NUM("R1"),
                                     NUMR("E2"),      NUMR("nu2"),     NUM("R2"),   NUM("sy"),
                                     NUM("nu_yield"), FLAG("plastic"), FRICTION,    ENABLE};
static const KeySpec spec_table[] = {LAWTYPE, NAMER("load"), NAME("unload"), FRICTION, ENABLE};
static const KeySpec spec_foam[] = {LAWTYPE,          NAMER("stress"),  NUMR("thickness"),
                                    NUMR("unload_r"), NUMR("unload_p"), NUM("lock"),
                                    NAME("backing"),  FRICTION,         ENABLE};
static const KeySpec spec_pair[] = {NAMER("a"), NAMER("b"), NAMER("law"), ENABLE};
static const KeySpec spec_pairs[] = {
    {"a", K_NAMES, MAXLIST, 1, 1, NULL}, {"b", K_NAMES, MAXLIST, 1, 1, NULL}, NAMER("law"), ENABLE};
static const KeySpec spec_airbag[] = {NAMER("geom"),
                                      NUMR("p0"),
                                      NUMR("patm"),
                                      NUMR("v0"),
                                      NUMR("gamma"),
                                      NUMR("kappa"),
                                      NUMR("thickness"),
                                      NUM("fabric_k"),
                                      NUM("fabric_c"),
                                      NUM("mu"),
                                      NUM("v_eps"),
                                      {"targets", K_NAMES, urMAXBAGTGT, 1, 1, NULL},
                                      ENABLE};
static const KeySpec spec_role[] = {NAME("drone"),    NAME("head"),  NAME("head_acc"), NAME("neck"),
                                    NAME("head_pos"), NAME("chest"), NAME("abdomen"),  NUM("mass"),
                                    NUM("size"),      ENABLE};
static const KeySpec spec_sensor[] = {
    {"type", K_ENUM, 1, 0, 1, "accel|jointload|jointpos|jointvel|contact|airbag|bodypos|bodyvel"},
    NAMER("obj"),
    {"dof", K_INT, 1, 0, 0, NULL},
    VEC3("pos"),
    QUAT,
    ROT,
    ENABLE};

//---------------------------------- parser state --------------------------------------------------

/* one defined (or disabled) name */
typedef struct {
  int kind;
  char name[urNAMELEN];
  unsigned hash; /* namehash(name): most lookups compare only this */
  int id;        /* index in the model or parser table */
  int src, line;
  int enabled;
  int next; /* the symbol before it in its hash chain, or -1 */
} Sym;

/* one parsed value */
typedef struct {
  int set;              /* key given */
  int line;             /* line of the word */
  const char* raw;      /* text after '=' */
  int n;                /* numbers or names */
  double v[urMAXCURVE]; /* numbers */
  int e;                /* K_ENUM: index of the word */
} Val;

/* one statement with its keys bound to a key table */
typedef struct {
  const char* kw;   /* keyword */
  const char* what; /* keyword for the list of keys (law: with its type) */
  const char* name; /* NAME or NULL */
  int line;
  const KeySpec* spec;
  int nspec;
  Val val[MAXKEY];
} Bound;

typedef struct {
  const urModelSource* src;
  int nsrc;
  const urOverride* ov;
  int nov;
  urlLex lx;
  int cur;    /* statement being parsed */
  int cursrc; /* its source */
  urModel* m;
  Sym* sym;
  int nsym, capsym;
  int* chain;                /* capsym chain heads: the last symbol of each hash */
  int count[SYM_PRESET + 1]; /* enabled elements of each kind (limits) */
  const _Atomic int* stop;   /* a stop request (Ctrl-C), polled between statements */
  urCurve* curve;
  int ncurve, capcurve;
  urLaw* law;
  int nlaw, caplaw;
  double* pval;
  int npval, cappval;
  char msg[MSGLEN];
} Parser;

//---------------------------------- messages ------------------------------------------------------

/* user text shortened for messages */
typedef struct {
  char s[56];
} Quote;

static Quote quote(const char* s, size_t n) {
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
static const char* srcname(const Parser* p, int src) {
  const char* f = src >= 0 && src < p->nsrc ? p->src[src].file : NULL;
  return f && f[0] ? f : "model";
}


/* print "FILE:LINE: message" into the parser; returns -1 */
static int fail(Parser* p, int line, const char* fmt, ...) {
  int k = snprintf(p->msg, sizeof(p->msg), "%s:%d: ", srcname(p, p->cursrc), line);
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
static int isident(const char* s, size_t n) {
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
static int checkname(Parser* p, const char* s, size_t n, int line, const char* what) {
  if (!isident(s, n)) {
    return fail(p, line, "%s: '%s' is not a valid name; %s", what, quote(s, n).s, expect_name);
  }
  if (n >= urNAMELEN) {
    return fail(p, line, "%s: name '%s' is too long (%d characters); %s", what, quote(s, n).s,
                (int)n, expect_name);
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
static int findsym(const Parser* p, int kind, const char* name, int enabled) {
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
  static const char* const kw[] = {"param", "curve",  "law",    "body", NULL,    "ellipsoid",
                                   "pair",  "airbag", "sensor", "part", "preset"};
  return kw[kind];
}


/* statement after the current one that defines name of kind; -1 if none */
static int findlater(const Parser* p, int kind, const char* name) {
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
static void suggest(const Parser* p, int kind, const char* name, char* out, size_t len) {
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
static int ref(Parser* p, int kind, const char* name, int line, const char* ctx) {
  int i = findsym(p, kind, name, 1);
  if (i >= 0) {
    return p->sym[i].id;
  }

  /* explain why it is missing */
  int dis = findsym(p, kind, name, 0);
  int later = findlater(p, kind, name);
  char hint[96];
  if (dis >= 0) {
    snprintf(hint, sizeof(hint), " (disabled by enable=0 at %s:%d)", srcname(p, p->sym[dis].src),
             p->sym[dis].line);
  } else if (later >= 0) {
    snprintf(hint, sizeof(hint), " (defined later, at %s:%d; define it before use)",
             srcname(p, p->lx.stmt[later].src), p->lx.stmt[later].line);
  } else {
    suggest(p, kind, name, hint, sizeof(hint));
  }
  fail(p, line, "%s%sdangling reference to %s '%s'%s", ctx ? ctx : "", ctx ? ": " : "",
       symkind[kind], name, hint);
  return -1;
}


/* declare a name; duplicates of enabled names are errors (params, parts: per source) */
static int declare(Parser* p, int kind, const char* name, int line, int id, int enabled) {
  if (enabled) {
    int i = findsym(p, kind, name, 1);
    int persrc = kind == SYM_PARAM || kind == SYM_PART;
    if (i >= 0 && (!persrc || p->sym[i].src == p->cursrc)) {
      return fail(p, line,
                  "duplicate %s name '%s' (first defined at %s:%d); names must be "
                  "unique",
                  symkind[kind], name, srcname(p, p->sym[i].src), p->sym[i].line);
    }
  }
  if (enabled && kind != SYM_JOINT && ++p->count[kind] > limit[kind]) {
    return fail(p, line,
                "more than %d %s in the model; accepted: at most %d (uasrisk-model(5), "
                "LIMITS)",
                limit[kind], symkinds[kind], limit[kind]);
  }
  if (p->nsym == p->capsym) {
    /* twice the room, and the chains rebuilt over twice the buckets (a power of two) */
    int nc = p->capsym ? 2 * p->capsym : 64;
    Sym* s = realloc(p->sym, (size_t)nc * sizeof(Sym));
    if (!s) {
      return fail(p, line, "out of memory");
    }
    p->sym = s;
    int* ch = realloc(p->chain, (size_t)nc * sizeof(int));
    if (!ch) {
      return fail(p, line, "out of memory");
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
static int push(Parser* p, void** arr, int* n, int* cap, size_t size, int line) {
  if (*n == *cap) {
    int nc = *cap ? 2 * (*cap) : 16;
    void* a = realloc(*arr, (size_t)nc * size);
    if (!a) {
      return fail(p, line, "out of memory");
    }
    *arr = a;
    *cap = nc;
  }
  memset((char*)*arr + (size_t)(*n) * size, 0, size);
  return (*n)++;
}

//---------------------------------- numbers -------------------------------------------------------

/* length of the longest prefix of s[0..n) that is a strict decimal number (0: none) */
static size_t decimal_prefix(const char* s, size_t n) {
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
  if (checkname(p, s, n, line, ctx)) {
    return -1;
  }
  char name[urNAMELEN];
  memcpy(name, s, n);
  name[n] = 0;
  int i = findsym(p, SYM_PARAM, name, 1);
  if (i >= 0) {
    *v = p->pval[p->sym[i].id];
    return 0;
  }
  int later = findlater(p, SYM_PARAM, name);
  if (later >= 0) {
    return fail(p, line,
                "%s: parameter '%s' used before its definition (at %s:%d); expected "
                "'param %s VALUE' above this line",
                ctx, name, srcname(p, p->lx.stmt[later].src), p->lx.stmt[later].line, name);
  }
  char hint[96];
  suggest(p, SYM_PARAM, name, hint, sizeof(hint));
  return fail(p, line, "%s: unknown parameter '%s'%s%s", ctx, name, hint,
              hint[0] ? "" : "; expected 'param NAME VALUE' before its use");
}


/* one number s[0..n): strict decimal, $param or -$param; ctx prefixes messages */
static int number(Parser* p, const char* s, size_t n, int line, const char* ctx, double* v) {
  if (n == 0) {
    return fail(p, line, "%s: empty number; %s", ctx, expect_num);
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
    return fail(p, line, "%s: '%s' is not a finite number; %s", ctx, quote(s, n).s, expect_num);
  }
  if (tn >= 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
    return fail(p, line, "%s: '%s' is not a decimal number (hexadecimal is not accepted); %s", ctx,
                quote(s, n).s, expect_num);
  }

  /* strict decimal syntax over the whole word */
  size_t k = decimal_prefix(s, n);
  if (k == 0) {
    if (isident(s, n)) {
      return fail(p, line, "%s: '%s' is not a number (for a parameter write $%s); %s", ctx,
                  quote(s, n).s, quote(s, n).s, expect_num);
    }
    return fail(p, line, "%s: '%s' is not a number; %s", ctx, quote(s, n).s, expect_num);
  }
  if (k < n) {
    return fail(p, line, "%s: '%s' is not a number (unexpected '%s' after '%s'); %s", ctx,
                quote(s, n).s, quote(s + k, n - k).s, quote(s, k).s, expect_num);
  }
  if (n > NUMLEN) {
    return fail(p, line, "%s: number '%s' is too long (%d characters)", ctx, quote(s, n).s, (int)n);
  }

  /* convert the validated text (correctly rounded); the range must be that of a double */
  char buf[NUMLEN + 1];
  memcpy(buf, s, n);
  buf[n] = 0;
  char* end;
  errno = 0;
  double x = strtod(buf, &end);
  if (end != buf + n) {
    return fail(p, line, "%s: cannot convert '%s' (C library locale?)", ctx, quote(s, n).s);
  }
  if (!isfinite(x) || (errno == ERANGE && fabs(x) >= 1)) {
    return fail(p, line,
                "%s: '%s' is not a finite number (beyond the range of a double, "
                "about 1.8e308); %s",
                ctx, quote(s, n).s, expect_num);
  }
  if (errno == ERANGE) {
    return fail(p, line,
                "%s: '%s' is too small to be represented (below about 2.2e-308); "
                "expected 0 or a larger magnitude",
                ctx, quote(s, n).s);
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
    if (k < max && number(p, s, n, line, ctx, v + k)) {
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
static int count(const char* s) {
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
static const Val* get(const Bound* b, const char* key) {
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
  int n = count(v->raw);

  switch (ks->kind) {
  case K_NUM:
  case K_INT:
  case K_FLAG:
    if (n != 1) {
      return fail(p, v->line, "key '%s' needs 1 number (got %d)", ks->key, n);
    }
    if (number(p, v->raw, strlen(v->raw), v->line, ctx, v->v)) {
      return -1;
    }
    v->n = 1;
    if (ks->kind == K_INT && !(v->v[0] >= 0 && v->v[0] <= 1e6 && v->v[0] == floor(v->v[0]))) {
      return fail(p, v->line, "key '%s' must be a whole number >= 0 (got %g)", ks->key, v->v[0]);
    }
    if (ks->kind == K_FLAG && v->v[0] != 0 && v->v[0] != 1) {
      return fail(p, v->line, "key '%s' must be 0 or 1 (got %g)", ks->key, v->v[0]);
    }
    return 0;

  case K_VEC:
    if (n != ks->n && n != ks->n2) {
      if (ks->n2) {
        return fail(p, v->line, "key '%s' needs %d or %d numbers (got %d)", ks->key, ks->n, ks->n2,
                    n);
      }
      return fail(p, v->line, "key '%s' needs %d numbers (got %d)", ks->key, ks->n, n);
    }
    v->n = n;
    return numbers(p, v->raw, v->line, ctx, v->v, n) < 0 ? -1 : 0;

  case K_LIST:
    if (n < ks->n2 || n > ks->n) {
      return fail(p, v->line, "key '%s' needs %d to %d numbers (got %d)", ks->key, ks->n2, ks->n,
                  n);
    }
    v->n = n;
    return numbers(p, v->raw, v->line, ctx, v->v, n) < 0 ? -1 : 0;

  case K_NAME: v->n = 1; return checkname(p, v->raw, strlen(v->raw), v->line, ctx);

  case K_NAMES: {
    if (n < ks->n2 || n > ks->n) {
      return fail(p, v->line, "key '%s' needs %d to %d names (got %d)", ks->key, ks->n2, ks->n, n);
    }
    const char* s = v->raw;
    for (int i = 0; i < n; i++) {
      const char* c = strchr(s, ',');
      size_t len = c ? (size_t)(c - s) : strlen(s);
      if (checkname(p, s, len, v->line, ctx)) {
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
    return fail(p, v->line, "key '%s': unknown value '%s'; expected one of %s", ks->key,
                quote(v->raw, len).s, list);
  }
  }
  return fail(p, v->line, "internal error: bad key kind");
}


/* bind words [first, end) as key=value to a key table: unknown, duplicate and empty keys,
   required keys, enable, values; returns 0, 1 if disabled (values not parsed), or -1 */
static int bind(Parser* p, const urlStmt* st, int first, const KeySpec* spec, int nspec, Bound* b) {
  b->spec = spec;
  b->nspec = nspec;
  memset(b->val, 0, sizeof(b->val));
  if (nspec > MAXKEY) {
    return fail(p, b->line, "internal error: too many keys for %s", b->kw);
  }

  /* keys */
  for (int w = first; w < st->nword; w++) {
    const char* s = url_word(&p->lx, st->word + w);
    int line = p->lx.word[st->word + w].line;
    const char* eq = strchr(s, '=');
    if (!eq) {
      return fail(p, line, "%s: expected key=value, got '%s' (no blanks around '=')", b->kw,
                  quote(s, strlen(s)).s);
    }
    size_t kl = (size_t)(eq - s);
    if (kl == 0) {
      return fail(p, line, "%s: missing key before '=' in '%s'", b->kw, quote(s, strlen(s)).s);
    }
    int k = 0;
    while (k < nspec && !(strlen(spec[k].key) == kl && !strncmp(spec[k].key, s, kl))) {
      k++;
    }
    if (k == nspec) {
      char list[400];
      keylist(spec, nspec, list, sizeof(list));
      return fail(p, line, "unknown key '%s' for %s; expected one of %s", quote(s, kl).s, b->what,
                  list);
    }
    if (b->val[k].set) {
      return fail(p, line,
                  "duplicate key '%s' (first given on line %d); a key may appear once "
                  "per statement",
                  spec[k].key, b->val[k].line);
    }
    if (!eq[1]) {
      return fail(p, line, "missing value for key '%s'; expected %s=VALUE", spec[k].key,
                  spec[k].key);
    }
    b->val[k].set = 1;
    b->val[k].line = line;
    b->val[k].raw = eq + 1;
  }

  /* required keys */
  for (int k = 0; k < nspec; k++) {
    if (spec[k].req && !b->val[k].set) {
      return fail(p, b->line, "%s%s%s%s: missing key '%s'; expected %s=VALUE", b->kw,
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
static int item(const char* s, int i, char* out, size_t len) {
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
static double num(const Bound* b, const char* key, double dflt) {
  const Val* v = get(b, key);
  return v->set ? v->v[0] : dflt;
}


/* check that an optional key is >= 0 (strict: > 0) */
static int nonneg(Parser* p, const Bound* b, const char* key, int strict) {
  const Val* v = get(b, key);
  if (v->set && (strict ? !(v->v[0] > 0) : !(v->v[0] >= 0))) {
    return fail(p, v->line, "%s '%s': %s must be %s 0 (got %g)", b->kw, b->name, key,
                strict ? ">" : ">=", v->v[0]);
  }
  return 0;
}


/* orientation from quat= or rot=ax,ay,az,deg (identity if neither); -1 on error */
static int orientation(Parser* p, const Bound* b, double q[4]) {
  const Val* vq = get(b, "quat");
  const Val* vr = get(b, "rot");
  q[0] = 1;
  q[1] = q[2] = q[3] = 0;
  if (vq->set && vr->set) {
    return fail(p, vr->line, "%s '%s': give quat or rot, not both", b->kw, b->name);
  }
  if (vq->set) {
    double n =
        sqrt(vq->v[0] * vq->v[0] + vq->v[1] * vq->v[1] + vq->v[2] * vq->v[2] + vq->v[3] * vq->v[3]);
    if (!(n > 0)) {
      return fail(p, vq->line, "%s '%s': quat must not be zero; expected w,x,y,z", b->kw, b->name);
    }
    for (int k = 0; k < 4; k++) {
      q[k] = vq->v[k] / n;
    }
  }
  if (vr->set) {
    double n = sqrt(vr->v[0] * vr->v[0] + vr->v[1] * vr->v[1] + vr->v[2] * vr->v[2]);
    if (!(n > 0)) {
      return fail(p, vr->line, "%s '%s': rot axis must not be zero; expected ax,ay,az,deg", b->kw,
                  b->name);
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
static const double* vec(const Bound* b, const char* key) {
  const Val* v = get(b, key);
  return v->set ? v->v : NULL;
}

//---------------------------------- statements ----------------------------------------------------

/* param NAME VALUE [UNIT] */
static int st_param(Parser* p, const urlStmt* st) {
  const char* w[4] = {NULL, NULL, NULL, NULL};
  int ln[4] = {st->line, st->line, st->line, st->line};
  for (int i = 0; i < st->nword && i < 4; i++) {
    w[i] = url_word(&p->lx, st->word + i);
    ln[i] = p->lx.word[st->word + i].line;
  }
  if (st->nword < 3 || st->nword > 4) {
    return fail(p, st->line, "param takes NAME VALUE [UNIT]; got %d word(s) after 'param'",
                st->nword - 1);
  }
  for (int i = 1; i < st->nword; i++) {
    if (strchr(w[i], '=')) {
      return fail(p, ln[i], "param takes NAME VALUE [UNIT], not key=value ('%s')",
                  quote(w[i], strlen(w[i])).s);
    }
  }
  if (checkname(p, w[1], strlen(w[1]), ln[1], "param")) {
    return -1;
  }

  /* value and unit */
  char ctx[64];
  snprintf(ctx, sizeof(ctx), "param '%s'", w[1]);
  double v;
  if (number(p, w[2], strlen(w[2]), ln[2], ctx, &v)) {
    return -1;
  }
  char si[urNAMELEN] = "";
  if (w[3]) {
    double f;
    if (ur_unit_parse(w[3], &f, si, sizeof si)) {
      char list[200];
      size_t k = 0;
      for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
        k += (size_t)snprintf(list + k, sizeof(list) - k, "%s%s", i ? ", " : "", units[i].name);
      }
      return fail(p, ln[3],
                  "param '%s': unknown unit '%s'; expected one of %s, or several "
                  "joined by * and / (N*m/rad)",
                  w[1], quote(w[3], strlen(w[3])).s, list);
    }
    v *= f;
    if (!isfinite(v)) {
      return fail(p, ln[3], "param '%s': value overflows after conversion to SI", w[1]);
    }
  }

  /* the caller's override wins (last one given) */
  for (int i = 0; i < p->nov; i++) {
    if (!strcmp(p->ov[i].name, w[1])) {
      v = p->ov[i].value;
    }
  }

  /* store */
  int id = push(p, (void**)&p->pval, &p->npval, &p->cappval, sizeof(double), st->line);
  if (id < 0 || declare(p, SYM_PARAM, w[1], st->line, id, 1)) {
    return -1;
  }
  p->pval[id] = v;
  int k = ur_model_set_param(p->m, w[1], v);
  if (k < 0) {
    return fail(p, st->line, "param '%s': %s", w[1], p->m->err);
  }
  snprintf(p->m->param[k].unit, sizeof p->m->param[k].unit, "%s", si);
  return 0;
}


/* option key=value... */
static int st_option(Parser* p, const urlStmt* st, Bound* b) {
  int rc = bind(p, st, 1, spec_option, NKEY(spec_option), b);
  if (rc) {
    return rc < 0 ? -1 : 0;
  }
  urOption* o = &p->m->opt;
  static const char* const pos[] = {"dt", "sample_dt", "tmax", "vmax"};
  static const char* const nn[] = {"t_quiet", "ke_settle", "jump_margin", "t_clear", "a_clear"};
  for (int i = 0; i < 4; i++) {
    const Val* v = get(b, pos[i]);
    if (v->set && !(v->v[0] > 0)) {
      return fail(p, v->line, "option %s must be > 0 (got %g)", pos[i], v->v[0]);
    }
  }
  for (int i = 0; i < 5; i++) {
    const Val* v = get(b, nn[i]);
    if (v->set && !(v->v[0] >= 0)) {
      return fail(p, v->line, "option %s must be >= 0 (got %g)", nn[i], v->v[0]);
    }
  }
  o->dt = num(b, "dt", o->dt);
  o->sample_dt = num(b, "sample_dt", o->sample_dt);
  o->tmax = num(b, "tmax", o->tmax);
  o->t_quiet = num(b, "t_quiet", o->t_quiet);
  o->t_clear = num(b, "t_clear", o->t_clear);
  o->a_clear = num(b, "a_clear", o->a_clear);
  o->ke_settle = num(b, "ke_settle", o->ke_settle);
  o->vmax = num(b, "vmax", o->vmax);
  o->jump_margin = num(b, "jump_margin", o->jump_margin);
  if (vec(b, "gravity")) {
    memcpy(o->gravity, vec(b, "gravity"), 3 * sizeof(double));
  }
  if (get(b, "integrator")->set) {
    o->integrator = get(b, "integrator")->e ? urINT_RK4 : urINT_EULER;
  }
  if (get(b, "damping")->set) {
    o->implicit_damping = get(b, "damping")->e == 0;
  }
  return 0;
}


/* curve NAME x=.. y=.. */
static int st_curve(Parser* p, const Bound* b) {
  const Val* x = get(b, "x");
  const Val* y = get(b, "y");
  if (x->n != y->n) {
    return fail(p, y->line, "curve '%s': x has %d points but y has %d; expected the same count",
                b->name, x->n, y->n);
  }
  for (int i = 1; i < x->n; i++) {
    if (!(x->v[i] > x->v[i - 1])) {
      return fail(p, x->line,
                  "curve '%s': x must be strictly ascending (x[%d] = %g after "
                  "x[%d] = %g)",
                  b->name, i + 1, x->v[i], i, x->v[i - 1]);
    }
  }
  static const char* const scales[] = {"xscale", "yscale"};
  for (int k = 0; k < 2; k++) {
    const Val* v = get(b, scales[k]);
    if (v->set && !(v->v[0] > 0)) {
      return fail(p, v->line, "curve '%s': %s must be > 0 (got %g)", b->name, scales[k], v->v[0]);
    }
  }
  int id = push(p, (void**)&p->curve, &p->ncurve, &p->capcurve, sizeof(urCurve), b->line);
  if (id < 0 || declare(p, SYM_CURVE, b->name, b->line, id, 1)) {
    return -1;
  }
  urCurve* c = p->curve + id;
  double sx = num(b, "xscale", 1), sy = num(b, "yscale", 1);
  c->n = x->n;
  for (int i = 0; i < x->n; i++) {
    c->x[i] = sx * x->v[i];
    c->y[i] = sy * y->v[i];
  }
  return 0;
}


/* body NAME parent= joint= pos= mass= ... */
static int st_body(Parser* p, const Bound* b) {
  urModel* m = p->m;
  if (!strcmp(b->name, "world")) {
    return fail(p, b->line, "body name 'world' is reserved (it is the fixed world frame)");
  }

  /* parent and joint */
  const Val* vp = get(b, "parent");
  int parent = -1;
  if (strcmp(vp->raw, "world")) {
    parent = ref(p, SYM_BODY, vp->raw, vp->line, NULL);
    if (parent < 0) {
      return -1;
    }
  }
  urJointType jt = (urJointType)get(b, "joint")->e;
  double q[4];
  if (orientation(p, b, q)) {
    return -1;
  }

  /* mass and inertia */
  const Val* vm = get(b, "mass");
  if (!(vm->v[0] > 0)) {
    return fail(p, vm->line, "body '%s': mass must be > 0 (got %g)", b->name, vm->v[0]);
  }
  const Val* vi = get(b, "inertia");
  double I[6] = {0, 0, 0, 0, 0, 0};
  if (vi->set) {
    memcpy(I, vi->v, (size_t)vi->n * sizeof(double));
    double d2 = I[0] * I[1] - I[3] * I[3];
    double d3 = I[0] * (I[1] * I[2] - I[5] * I[5]) - I[3] * (I[3] * I[2] - I[5] * I[4]) +
                I[4] * (I[3] * I[5] - I[1] * I[4]);
    if (!(I[0] > 0 && d2 > 0 && d3 > 0)) {
      return fail(p, vi->line,
                  "body '%s': inertia must be positive definite (got xx,yy,zz,"
                  "xy,xz,yz = %g,%g,%g,%g,%g,%g)",
                  b->name, I[0], I[1], I[2], I[3], I[4], I[5]);
    }
    /* a real mass distribution: no principal moment above the sum of the other two, that is
       J = tr(I)/2 E - I positive semidefinite (its principal minors >= 0, to rounding) */
    double h = 0.5 * (I[0] + I[1] + I[2]), e = 1e-9 * h;
    double J[6] = {h - I[0] + e, h - I[1] + e, h - I[2] + e, -I[3], -I[4], -I[5]};
    double j2 = J[0] * J[1] - J[3] * J[3];
    double j3 = J[0] * (J[1] * J[2] - J[5] * J[5]) - J[3] * (J[3] * J[2] - J[5] * J[4]) +
                J[4] * (J[3] * J[5] - J[1] * J[4]);
    if (!(J[0] > 0 && j2 > 0 && j3 > 0)) {
      return fail(p, vi->line,
                  "body '%s': inertia is not that of a real body: a principal moment "
                  "exceeds the sum of the other two (got xx,yy,zz,xy,xz,yz = %g,%g,%g,%g,%g,%g); "
                  "expected moments such as a box's or a rod's",
                  b->name, I[0], I[1], I[2], I[3], I[4], I[5]);
    }
  } else if (jt == urJNT_FREE || jt == urJNT_SPHERICAL) {
    return fail(p, b->line, "body '%s': a %s joint needs inertia=xx,yy,zz[,xy,xz,yz]", b->name,
                jt == urJNT_FREE ? "free" : "spherical");
  }

  /* joint axes */
  const Val* va = get(b, "axis");
  const Val* va2 = get(b, "axis2");
  if (va->set && jt != urJNT_REVOLUTE && jt != urJNT_PRISMATIC && jt != urJNT_UNIVERSAL) {
    return fail(p, va->line,
                "body '%s': key 'axis' applies only to revolute, prismatic and "
                "universal joints",
                b->name);
  }
  if (va2->set && jt != urJNT_UNIVERSAL) {
    return fail(p, va2->line, "body '%s': key 'axis2' applies only to universal joints", b->name);
  }
  const Val* ax[2] = {va, va2};
  for (int k = 0; k < 2; k++) {
    if (ax[k]->set && !(fabs(ax[k]->v[0]) + fabs(ax[k]->v[1]) + fabs(ax[k]->v[2]) > 0)) {
      return fail(p, ax[k]->line, "body '%s': joint axis must not be zero", b->name);
    }
  }

  /* names: body and joint (the joint is named after the body unless jname is given) */
  const Val* vj = get(b, "jname");
  const char* jname = vj->set ? vj->raw : b->name;
  if (declare(p, SYM_BODY, b->name, b->line, m->nbody, 1) ||
      declare(p, SYM_JOINT, jname, vj->set ? vj->line : b->line, m->nbody, 1)) {
    return -1;
  }

  /* build */
  int id = ur_model_add_body(m, b->name, parent, jt, get(b, "pos")->v, q);
  if (id < 0 || ur_model_set_inertia(m, id, vm->v[0], vec(b, "com"), vi->set ? I : NULL) ||
      ur_model_set_joint(m, id, vj->set ? jname : NULL, vec(b, "axis"), vec(b, "axis2"))) {
    return fail(p, b->line, "body '%s': %s", b->name, m->err);
  }
  m->body[id].gravity = num(b, "gravity", 1);

  /* universal axes must not be parallel (checked after normalisation) */
  const urBody* bd = m->body + id;
  double c = bd->axis[0][0] * bd->axis[1][0] + bd->axis[0][1] * bd->axis[1][1] +
             bd->axis[0][2] * bd->axis[1][2];
  if (jt == urJNT_UNIVERSAL && fabs(c) > 1 - 1e-9) {
    return fail(p, va2->set ? va2->line : b->line,
                "body '%s': universal joint axes are "
                "parallel; expected two different directions in axis and axis2",
                b->name);
  }
  return 0;
}


/* restraint BODY dof= ... */
static int st_restraint(Parser* p, const Bound* b) {
  urModel* m = p->m;
  int id = ref(p, SYM_BODY, b->name, b->line, "restraint");
  if (id < 0) {
    return -1;
  }
  const urBody* bd = m->body + id;
  static const int nv[] = {6, 0, 1, 2, 3, 1};
  static const char* const jn[] = {"free",      "fixed",     "revolute",
                                   "universal", "spherical", "prismatic"};
  if (bd->jtype == urJNT_FREE || bd->jtype == urJNT_FIXED) {
    return fail(p, b->line,
                "restraint '%s': body '%s' has a %s joint; restraints need a "
                "revolute, universal, spherical or prismatic joint",
                b->name, b->name, jn[bd->jtype]);
  }
  const Val* vd = get(b, "dof");
  int dof = (int)vd->v[0];
  if (dof >= nv[bd->jtype]) {
    return fail(p, vd->line, "restraint '%s': dof %d is beyond the %s joint (dof 0..%d)", b->name,
                dof, jn[bd->jtype], nv[bd->jtype] - 1);
  }
  if (bd->rst[dof].active) {
    return fail(p, b->line,
                "restraint '%s': dof %d is already restrained; expected one "
                "restraint per dof",
                b->name, dof);
  }

  /* scalars */
  static const char* const nn[] = {"k", "c", "kstop", "cstop", "sat"};
  for (int i = 0; i < 5; i++) {
    if (nonneg(p, b, nn[i], 0)) {
      return -1;
    }
  }
  const Val* lo = get(b, "lo");
  const Val* hi = get(b, "hi");
  if (lo->set != hi->set) {
    return fail(p, (lo->set ? lo : hi)->line, "restraint '%s': give both lo and hi (end stops)",
                b->name);
  }
  if (lo->set && !(lo->v[0] <= hi->v[0])) {
    return fail(p, hi->line, "restraint '%s': lo must be <= hi (got lo %g, hi %g)", b->name,
                lo->v[0], hi->v[0]);
  }
  urRestraint r;
  memset(&r, 0, sizeof(r));
  r.k = num(b, "k", 0);
  r.sat = num(b, "sat", 0);
  r.c = num(b, "c", 0);
  r.lo = num(b, "lo", 0);
  r.hi = num(b, "hi", 0);
  r.kstop = num(b, "kstop", 0);
  r.cstop = num(b, "cstop", 0);
  r.x0 = num(b, "x0", 0);

  /* curves */
  const Val* vl = get(b, "load");
  const Val* vu = get(b, "unload");
  if (vu->set && !vl->set) {
    return fail(p, vu->line, "restraint '%s': an unload curve needs a load curve", b->name);
  }
  if (vl->set) {
    int c = ref(p, SYM_CURVE, vl->raw, vl->line, "restraint");
    if (c < 0) {
      return -1;
    }
    r.load = p->curve[c];
  }
  if (vu->set) {
    int c = ref(p, SYM_CURVE, vu->raw, vu->line, "restraint");
    if (c < 0) {
      return -1;
    }
    r.unload = p->curve[c];
  }
  if (ur_model_set_restraint(m, id, dof, &r)) {
    return fail(p, b->line, "restraint '%s': %s", b->name, m->err);
  }
  return 0;
}


/* ellipsoid NAME body= pos= size= [quat|rot] [degree=] */
static int st_ellipsoid(Parser* p, const Bound* b) {
  urModel* m = p->m;
  if (!strcmp(b->name, "ground")) {
    return fail(p, b->line, "ellipsoid name 'ground' is reserved (it is the plane z = 0)");
  }
  const Val* vb = get(b, "body");
  if (!strcmp(vb->raw, "world")) {
    return fail(p, vb->line,
                "ellipsoid '%s': ellipsoids sit on bodies, not on the world; for "
                "the ground use 'pair ... b=ground'",
                b->name);
  }
  int body = ref(p, SYM_BODY, vb->raw, vb->line, NULL);
  if (body < 0) {
    return -1;
  }
  const Val* vs = get(b, "size");
  if (!(vs->v[0] > 0 && vs->v[1] > 0 && vs->v[2] > 0)) {
    return fail(p, vs->line, "ellipsoid '%s': semi-axes must be > 0 (got %g,%g,%g)", b->name,
                vs->v[0], vs->v[1], vs->v[2]);
  }
  const Val* vd = get(b, "degree");
  if (vd->set && !(vd->v[0] >= 2 && vd->v[0] <= urMAXDEGREE)) {
    return fail(p, vd->line,
                "ellipsoid '%s': degree must be in [2, %d] (got %g); 2 is the "
                "ellipsoid, larger values flatten it towards a box",
                b->name, urMAXDEGREE, vd->v[0]);
  }
  double q[4];
  if (orientation(p, b, q) || declare(p, SYM_ELLIPSOID, b->name, b->line, m->ngeom, 1)) {
    return -1;
  }
  int g = ur_model_add_ellipsoid(m, b->name, body, get(b, "pos")->v, q, vs->v);
  if (g < 0 || (vd->set && ur_model_set_degree(m, g, vd->v[0]))) {
    return fail(p, b->line, "ellipsoid '%s': %s", b->name, m->err);
  }
  return 0;
}


/* ellipsoid g, named name, must have degree 2 in its role (a foam pair's a, an airbag target) */
/* a pair under a Hertz law without radii: both ellipsoids of degree 2 (their curvature) */
static int curv2(Parser* p, int law, int g, const char* name, int line, const char* what) {
  if (g < 0 || p->law[law].type != urLAW_HERTZ || p->law[law].radius != urHERTZ_CURVATURE ||
      p->m->geom[g].degree == 2) {
    return 0;
  }
  return fail(p, line,
              "%s: ellipsoid '%s' has degree=%g; a Hertz law without R1 and R2 takes "
              "its radius from the curvature of ellipsoids of degree 2 (give R1 and R2)",
              what, name, p->m->geom[g].degree);
}


static int degree2(Parser* p, int g, const char* name, int line, const char* what,
                   const char* role) {
  if (p->m->geom[g].degree == 2) {
    return 0;
  }
  const Sym* sy = p->sym + findsym(p, SYM_ELLIPSOID, name, 1);
  return fail(p, line,
              "%s: ellipsoid '%s' (%s:%d) has degree=%g; %s must have degree 2 (its "
              "section area and cap volume are those of an ellipsoid)",
              what, name, srcname(p, sy->src), sy->line, p->m->geom[g].degree, role);
}


/* Poisson ratio in [0, 0.5) */
static int poisson(Parser* p, const Bound* b, const char* key) {
  const Val* v = get(b, key);
  if (v->set && !(v->v[0] >= 0 && v->v[0] < 0.5)) {
    return fail(p, v->line, "law '%s': %s must be in [0, 0.5) (got %g)", b->name, key, v->v[0]);
  }
  return 0;
}


/* law NAME type=hertz|table|foam ... */
static int st_law(Parser* p, const Bound* b) {
  urLaw law;
  memset(&law, 0, sizeof(law));
  int type = get(b, "type")->e;

  /* per type */
  if (type == 0) {
    if (nonneg(p, b, "E1", 1) || nonneg(p, b, "E2", 1) || nonneg(p, b, "R1", 1) ||
        nonneg(p, b, "R2", 0) || nonneg(p, b, "sy", 0) || poisson(p, b, "nu1") ||
        poisson(p, b, "nu2") || poisson(p, b, "nu_yield")) {
      return -1;
    }
    int plastic = (int)num(b, "plastic", 0);
    if (plastic && !(num(b, "sy", 0) > 0 && get(b, "nu_yield")->set)) {
      return fail(p, get(b, "plastic")->line, "law '%s': plastic=1 needs sy > 0 and nu_yield",
                  b->name);
    }
    const Val* r1 = get(b, "R1");
    const Val* r2 = get(b, "R2");
    if (r1->set != r2->set) {
      return fail(p, (r1->set ? r1 : r2)->line,
                  "law '%s': give R1 and R2, or neither (the radius "
                  "then comes from the ellipsoids' curvature at the contact)",
                  b->name);
    }
    ur_law_hertz(&law, num(b, "E1", 0), num(b, "nu1", 0), num(b, "R1", 0), num(b, "E2", 0),
                 num(b, "nu2", 0), num(b, "R2", 0), num(b, "sy", 0), num(b, "nu_yield", 0),
                 plastic);
    if (!r1->set) {
      law.radius = urHERTZ_CURVATURE;
    }
  } else if (type == 1) {
    law.type = urLAW_TABLE;
    const Val* vl = get(b, "load");
    const Val* vu = get(b, "unload");
    int c = ref(p, SYM_CURVE, vl->raw, vl->line, "law");
    if (c < 0) {
      return -1;
    }
    law.load = p->curve[c];
    if (vu->set) {
      c = ref(p, SYM_CURVE, vu->raw, vu->line, "law");
      if (c < 0) {
        return -1;
      }
      law.unload = p->curve[c];
    }
  } else {
    law.type = urLAW_FOAM;
    const Val* vs = get(b, "stress");
    const Val* vr = get(b, "unload_r");
    int c = ref(p, SYM_CURVE, vs->raw, vs->line, "law");
    if (c < 0 || nonneg(p, b, "thickness", 1) || nonneg(p, b, "unload_p", 1)) {
      return -1;
    }
    if (!(vr->v[0] >= 0 && vr->v[0] < 1)) {
      return fail(p, vr->line, "law '%s': unload_r must be in [0, 1) (got %g)", b->name, vr->v[0]);
    }
    law.stress = p->curve[c];
    law.thickness = num(b, "thickness", 0);
    law.unload_r = vr->v[0];
    law.unload_p = num(b, "unload_p", 0);

    /* the lock strain within the stress data, and the rigid backing's Hertz law */
    const Val* vk = get(b, "lock");
    const Val* vb = get(b, "backing");
    if (vk->set != vb->set) {
      return fail(p, (vk->set ? vk : vb)->line,
                  "law '%s': lock and backing go together (the "
                  "solid foam rests on the backing)",
                  b->name);
    }
    if (vk->set) {
      double last = law.stress.x[law.stress.n - 1];
      if (!(vk->v[0] > 0 && vk->v[0] < 1 && vk->v[0] <= last)) {
        return fail(p, vk->line,
                    "law '%s': lock must be in (0, 1) and within the stress curve "
                    "(last strain %g; got %g)",
                    b->name, last, vk->v[0]);
      }
      int l = ref(p, SYM_LAW, vb->raw, vb->line, "law");
      if (l < 0) {
        return -1;
      }
      if (p->law[l].type != urLAW_HERTZ) {
        return fail(p, vb->line, "law '%s': backing '%s' must be a hertz law", b->name, vb->raw);
      }
      if (p->law[l].radius == urHERTZ_CURVATURE) {
        return fail(p, vb->line,
                    "law '%s': backing '%s' must give R1 and R2 (a backing has no "
                    "contact of its own to take a curvature from)",
                    b->name, vb->raw);
      }
      double K, dy, fy;
      ur_law_hertz_params(p->law + l, &K, &dy, &fy);
      law.lock = vk->v[0];
      law.backing_k = K;
    }
  }

  /* common terms */
  static const char* const common[] = {"damping", "chi", "mu", "v_eps"};
  for (int i = 0; i < 4; i++) {
    if (nonneg(p, b, common[i], 0)) {
      return -1;
    }
  }
  law.damping = num(b, "damping", 0);
  law.chi = num(b, "chi", 0);
  law.mu = num(b, "mu", 0);
  law.v_eps = num(b, "v_eps", 0);
  int id = push(p, (void**)&p->law, &p->nlaw, &p->caplaw, sizeof(urLaw), b->line);
  if (id < 0 || declare(p, SYM_LAW, b->name, b->line, id, 1)) {
    return -1;
  }
  p->law[id] = law;
  return 0;
}


/* pair NAME a= b=|ground law= */
static int st_pair(Parser* p, const Bound* b) {
  urModel* m = p->m;
  const Val* va = get(b, "a");
  const Val* vb = get(b, "b");
  const Val* vl = get(b, "law");
  int ga = ref(p, SYM_ELLIPSOID, va->raw, va->line, NULL);
  if (ga < 0) {
    return -1;
  }
  int gb = -1;
  if (strcmp(vb->raw, "ground") && (gb = ref(p, SYM_ELLIPSOID, vb->raw, vb->line, NULL)) < 0) {
    return -1;
  }
  int law = ref(p, SYM_LAW, vl->raw, vl->line, NULL);
  if (law < 0) {
    return -1;
  }
  if (gb >= 0 && m->geom[ga].body == m->geom[gb].body) {
    return fail(p, vb->line,
                "pair '%s': a and b are both on body '%s'; expected ellipsoids of "
                "two bodies",
                b->name, m->body[m->geom[ga].body].name);
  }
  char what[urNAMELEN + 16];
  snprintf(what, sizeof(what), "pair '%s'", b->name);
  if ((p->law[law].type == urLAW_FOAM &&
       degree2(p, ga, va->raw, va->line, what, "a, under a foam law,")) ||
      curv2(p, law, ga, va->raw, va->line, what) || curv2(p, law, gb, vb->raw, vb->line, what)) {
    return -1;
  }
  if (declare(p, SYM_PAIR, b->name, b->line, m->npair, 1)) {
    return -1;
  }
  if (ur_model_add_pair(m, b->name, ga, gb, p->law + law) < 0) {
    return fail(p, b->line, "pair '%s': %s", b->name, m->err);
  }
  return 0;
}


/* name NAME_A_B of a generated pair; -1 if too long */
static int pairname(char out[urNAMELEN], const char* name, const char* a, const char* b) {
  int n = snprintf(out, urNAMELEN, "%s_%s_%s", name, a, b);
  return n < 0 || n >= urNAMELEN ? -1 : 0;
}


/* pairs NAME a=E1,E2,.. b=F1,F2,..|ground law=: one pair NAME_Ei_Fj per combination */
static int st_pairs(Parser* p, const Bound* b) {
  urModel* m = p->m;
  const Val* va = get(b, "a");
  const Val* vb = get(b, "b");
  const Val* vl = get(b, "law");
  int law = ref(p, SYM_LAW, vl->raw, vl->line, NULL);
  if (law < 0) {
    return -1;
  }
  for (int i = 0; i < va->n; i++) {
    char na[urNAMELEN], pn[urNAMELEN];
    item(va->raw, i, na, sizeof(na));
    int ga = ref(p, SYM_ELLIPSOID, na, va->line, NULL);
    if (ga < 0) {
      return -1;
    }
    char what[urNAMELEN + 16];
    snprintf(what, sizeof(what), "pairs '%s'", b->name);
    if ((p->law[law].type == urLAW_FOAM &&
         degree2(p, ga, na, va->line, what, "each a, under a foam law,")) ||
        curv2(p, law, ga, na, va->line, what)) {
      return -1;
    }
    for (int j = 0; j < vb->n; j++) {
      char nb[urNAMELEN];
      item(vb->raw, j, nb, sizeof(nb));
      int gb = -1;
      if (strcmp(nb, "ground") && (gb = ref(p, SYM_ELLIPSOID, nb, vb->line, NULL)) < 0) {
        return -1;
      }
      if (curv2(p, law, gb, nb, vb->line, what)) {
        return -1;
      }
      if (pairname(pn, b->name, na, nb)) {
        return fail(p, b->line,
                    "pairs '%s': the pair name '%s_%s_%s' is too long (%d "
                    "characters, at most %d); shorten NAME or the ellipsoid names",
                    b->name, b->name, na, nb, (int)(strlen(b->name) + strlen(na) + strlen(nb) + 2),
                    urNAMELEN - 1);
      }
      if (gb >= 0 && m->geom[ga].body == m->geom[gb].body) {
        return fail(p, vb->line,
                    "pairs '%s': '%s' and '%s' are both on body '%s'; expected "
                    "ellipsoids of two bodies",
                    b->name, na, nb, m->body[m->geom[ga].body].name);
      }
      if (declare(p, SYM_PAIR, pn, b->line, m->npair, 1)) {
        return -1;
      }
      if (ur_model_add_pair(m, pn, ga, gb, p->law + law) < 0) {
        return fail(p, b->line, "pairs '%s': %s", b->name, m->err);
      }
    }
  }
  return 0;
}


/* names of the pairs of a disabled 'pairs' statement (for messages), as far as they are valid */
static int pairs_disabled(Parser* p, const Bound* b, int line) {
  const char* ra = get(b, "a")->raw;
  const char* rb = get(b, "b")->raw;
  int na = count(ra), nb = count(rb);
  for (int i = 0; i < na && na <= MAXLIST && nb <= MAXLIST; i++) {
    for (int j = 0; j < nb; j++) {
      char x[urNAMELEN], y[urNAMELEN], pn[urNAMELEN];
      if (!item(ra, i, x, sizeof(x)) && !item(rb, j, y, sizeof(y)) && isident(x, strlen(x)) &&
          isident(y, strlen(y)) && !pairname(pn, b->name, x, y) &&
          declare(p, SYM_PAIR, pn, line, -1, 0)) {
        return -1;
      }
    }
  }
  return 0;
}


/* airbag NAME geom= p0= patm= v0= gamma= kappa= thickness= targets= ... */
static int st_airbag(Parser* p, const Bound* b) {
  urModel* m = p->m;
  urAirbag bag;
  memset(&bag, 0, sizeof(bag));
  snprintf(bag.name, sizeof(bag.name), "%s", b->name);
  bag.type = urBAG_UNIFORM;
  const Val* vg = get(b, "geom");
  bag.geom = ref(p, SYM_ELLIPSOID, vg->raw, vg->line, NULL);
  if (bag.geom < 0) {
    return -1;
  }

  /* scalars */
  static const char* const pos[] = {"p0", "patm", "v0", "gamma", "kappa", "thickness"};
  static const char* const nn[] = {"fabric_k", "fabric_c", "mu", "v_eps"};
  for (int i = 0; i < 6; i++) {
    if (nonneg(p, b, pos[i], 1)) {
      return -1;
    }
  }
  for (int i = 0; i < 4; i++) {
    if (nonneg(p, b, nn[i], 0)) {
      return -1;
    }
  }
  bag.gas.p0 = num(b, "p0", 0);
  bag.gas.patm = num(b, "patm", 0);
  bag.gas.v0 = num(b, "v0", 0);
  bag.gas.gamma = num(b, "gamma", 0);
  bag.kappa = num(b, "kappa", 0);
  bag.thickness = num(b, "thickness", 0);
  bag.fabric_k = num(b, "fabric_k", 0);
  bag.fabric_c = num(b, "fabric_c", 0);
  bag.mu = num(b, "mu", 0);
  bag.v_eps = num(b, "v_eps", 0);

  /* targets: distinct ellipsoids of other bodies */
  const Val* vt = get(b, "targets");
  for (int i = 0; i < vt->n; i++) {
    char name[urNAMELEN];
    item(vt->raw, i, name, sizeof(name));
    int g = ref(p, SYM_ELLIPSOID, name, vt->line, "targets");
    if (g < 0) {
      return -1;
    }
    if (m->geom[g].body == m->geom[bag.geom].body) {
      return fail(p, vt->line, "airbag '%s': target '%s' is on the bag's own body '%s'", b->name,
                  name, m->body[m->geom[g].body].name);
    }
    for (int k = 0; k < i; k++) {
      if (bag.target[k] == g) {
        return fail(p, vt->line, "airbag '%s': target '%s' is listed twice", b->name, name);
      }
    }
    char what[urNAMELEN + 16];
    snprintf(what, sizeof(what), "airbag '%s'", b->name);
    if (degree2(p, g, name, vt->line, what, "a target")) {
      return -1;
    }
    bag.target[i] = g;
  }
  bag.ntarget = vt->n;
  if (declare(p, SYM_AIRBAG, b->name, b->line, m->nbag, 1)) {
    return -1;
  }
  if (ur_model_add_airbag(m, &bag) < 0) {
    return fail(p, b->line, "airbag '%s': %s", b->name, m->err);
  }
  return 0;
}


/* sensor NAME type= obj= [dof=] [pos=] [quat=|rot=] */
static int st_sensor(Parser* p, const Bound* b) {
  urModel* m = p->m;
  urSensorType type = (urSensorType)get(b, "type")->e;
  const Val* vo = get(b, "obj");
  const Val* vd = get(b, "dof");
  const Val* vp = get(b, "pos");
  const Val* vq = get(b, "quat")->set ? get(b, "quat") : get(b, "rot");
  int onbody = type == urSENS_ACCEL || type == urSENS_BODYPOS || type == urSENS_BODYVEL;
  int onjoint = type == urSENS_JOINTLOAD || type == urSENS_JOINTPOS || type == urSENS_JOINTVEL;
  int hasdof = type == urSENS_JOINTPOS || type == urSENS_JOINTVEL;

  /* keys that apply */
  if (vd->set && !hasdof) {
    return fail(p, vd->line, "sensor '%s': key 'dof' applies only to jointpos and jointvel",
                b->name);
  }
  if (vp->set && !onbody) {
    return fail(p, vp->line, "sensor '%s': key 'pos' applies only to accel, bodypos and bodyvel",
                b->name);
  }
  if (vq->set && type != urSENS_JOINTLOAD) {
    return fail(p, vq->line, "sensor '%s': key '%s' applies only to jointload", b->name,
                vq == get(b, "rot") ? "rot" : "quat");
  }

  /* object by type: joint sensors take a joint name or a body name */
  int obj;
  if (onjoint && findsym(p, SYM_JOINT, vo->raw, 1) < 0 && findsym(p, SYM_BODY, vo->raw, 1) >= 0) {
    obj = ref(p, SYM_BODY, vo->raw, vo->line, NULL);
  } else {
    int kind = onbody                   ? SYM_BODY
               : onjoint                ? SYM_JOINT
               : type == urSENS_CONTACT ? SYM_PAIR
                                        : SYM_AIRBAG;
    obj = ref(p, kind, vo->raw, vo->line, NULL);
  }
  if (obj < 0) {
    return -1;
  }

  /* dof within the joint */
  int dof = (int)num(b, "dof", 0);
  if (hasdof) {
    static const int nv[] = {6, 0, 1, 2, 3, 1};
    const urBody* bd = m->body + obj;
    int ok = dof < nv[bd->jtype];
    if (type == urSENS_JOINTPOS) {
      ok = ok && bd->jtype != urJNT_FREE && bd->jtype != urJNT_SPHERICAL;
    }
    if (!ok) {
      return fail(p, vd->set ? vd->line : b->line,
                  "sensor '%s': dof %d does not exist on "
                  "joint '%s'%s",
                  b->name, dof, bd->jname,
                  type == urSENS_JOINTPOS ? " (jointpos needs a revolute, universal or "
                                            "prismatic joint)"
                                          : "");
    }
  }
  double q[4];
  if (orientation(p, b, q) || declare(p, SYM_SENSOR, b->name, b->line, m->nsensor, 1)) {
    return -1;
  }
  if (ur_model_add_sensor(m, b->name, type, obj, dof, vec(b, "pos"), q) < 0) {
    return fail(p, b->line, "sensor '%s': %s", b->name, m->err);
  }
  return 0;
}


/* role key=value...: the elements an impact needs, and the parameters that scale the drone */
static int st_role(Parser* p, const urlStmt* st, Bound* b) {
  int rc = bind(p, st, 1, spec_role, NKEY(spec_role), b);
  if (rc) {
    return rc < 0 ? -1 : 0;
  }
  urModel* m = p->m;
  urRoles* r = &m->roles;
  static const struct {
    const char* key;
    int kind;
    int type; /* sensor type, or -1 */
  } rk[] = {{"drone", SYM_BODY, -1},
            {"head", SYM_ELLIPSOID, -1},
            {"head_acc", SYM_SENSOR, urSENS_ACCEL},
            {"neck", SYM_SENSOR, urSENS_JOINTLOAD},
            {"head_pos", SYM_SENSOR, urSENS_BODYPOS},
            {"chest", SYM_SENSOR, urSENS_JOINTPOS},
            {"abdomen", SYM_SENSOR, urSENS_JOINTPOS}};
  int* slot[] = {&r->drone, &r->head, &r->head_acc, &r->neck, &r->head_pos, &r->chest, &r->abdomen};
  for (int i = 0; i < (int)(sizeof(rk) / sizeof(rk[0])); i++) {
    const Val* v = get(b, rk[i].key);
    if (!v->set) {
      continue;
    }
    int id = ref(p, rk[i].kind, v->raw, v->line, "role");
    if (id < 0) {
      return -1;
    }
    if (rk[i].kind == SYM_BODY && r->drone >= 0 && r->drone != id) {
      return fail(p, v->line,
                  "role drone: the model has a drone already (body '%s'); one model "
                  "has one drone: drop the other drone's parts first",
                  m->body[r->drone].name);
    }
    if (rk[i].kind == SYM_BODY && (m->body[id].parent >= 0 || m->body[id].jtype != urJNT_FREE)) {
      return fail(p, v->line,
                  "role drone: body '%s' must have a free joint to the world (the "
                  "drone is placed and launched by it)",
                  v->raw);
    }
    if (rk[i].type >= 0 && (int)m->sensor[id].type != rk[i].type) {
      static const char* const tname[] = {"accel",   "jointload", "jointpos", "jointvel",
                                          "contact", "airbag",    "bodypos",  "bodyvel"};
      int t = rk[i].type;
      return fail(p, v->line, "role %s: sensor '%s' must be of type=%s", rk[i].key, v->raw,
                  t >= 0 && t < 8 ? tname[t] : "?");
    }
    *slot[i] = id;
  }
  static const char* const design[] = {"mass", "size"};
  int* dslot[] = {&r->mass_param, &r->size_param};
  for (int i = 0; i < 2; i++) {
    const Val* v = get(b, design[i]);
    if (!v->set) {
      continue;
    }
    if (v->raw[0] != '$') {
      return fail(p, v->line,
                  "role %s: expected a parameter ($NAME) that the workbench can set, "
                  "got '%s'",
                  design[i], quote(v->raw, strlen(v->raw)).s);
    }
    if (!(v->v[0] > 0)) {
      return fail(p, v->line, "role %s: must be > 0 (got %g)", design[i], v->v[0]);
    }
    *dslot[i] = ur_name_param(m, v->raw + 1);
  }
  return 0;
}


/* preset NAME key=value...: a case, as model parameters (VALUE[UNIT] or $param) and workbench
   settings (plain numbers, checked by the workbench) */
static int st_preset(Parser* p, const urlStmt* st) {
  if (st->nword < 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return fail(p, st->line,
                "preset needs a NAME before its keys; expected 'preset NAME "
                "key=value ...'");
  }
  const char* name = url_word(&p->lx, st->word + 1);
  if (checkname(p, name, strlen(name), st->line, "preset")) {
    return -1;
  }
  if (strlen(name) > 7) {
    return fail(p, st->line,
                "preset '%s': a preset name has at most 7 characters (it labels "
                "the rows of tables)",
                name);
  }
  urPreset pr;
  memset(&pr, 0, sizeof(pr));
  snprintf(pr.name, sizeof(pr.name), "%s", name);
  for (int w = 2; w < st->nword; w++) {
    const char* s = url_word(&p->lx, st->word + w);
    int line = p->lx.word[st->word + w].line;
    const char* eq = strchr(s, '=');
    size_t kl = eq ? (size_t)(eq - s) : 0;
    if (!eq || kl == 0 || !eq[1]) {
      return fail(p, line, "preset '%s': expected key=value, got '%s' (no blanks around '=')", name,
                  quote(s, strlen(s)).s);
    }
    char key[urNAMELEN];
    if (checkname(p, s, kl, line, "preset key")) {
      return -1;
    }
    memcpy(key, s, kl);
    key[kl] = 0;
    for (int k = 0; k < pr.n; k++) {
      if (!strcmp(pr.key[k], key)) {
        return fail(p, line, "preset '%s': duplicate key '%s'; a key may appear once", name, key);
      }
    }
    if (pr.n == urMAXPRESET) {
      return fail(p, line, "preset '%s': more than %d keys", name, urMAXPRESET);
    }
    int isparam = findsym(p, SYM_PARAM, key, 1) >= 0;
    const char* v = eq + 1;
    size_t vn = strlen(v), k = decimal_prefix(v, vn);
    double f = 1, x;
    char ctx[80];
    snprintf(ctx, sizeof(ctx), "preset '%s' key '%s'", name, key);
    int isref = v[0] == '$' || (v[0] == '-' && v[1] == '$');
    if (!isref && k > 0 && k < vn) {
      if (ur_unit_si(v + k, &f)) {
        return fail(p, line,
                    "%s: unknown unit '%s'; expected a unit of a param line (atm, kg, "
                    "mm, ...)",
                    ctx, quote(v + k, vn - k).s);
      }
      if (!isparam) {
        return fail(p, line,
                    "%s: a unit is taken only by model parameters ('%s' is a "
                    "workbench setting, in the unit its 'show' prints)",
                    ctx, key);
      }
      vn = k;
    }
    if (number(p, v, vn, line, ctx, &x)) {
      return -1;
    }
    x *= f;
    if (!isfinite(x)) {
      return fail(p, line, "%s: value overflows after conversion to SI", ctx);
    }
    snprintf(pr.key[pr.n], urNAMELEN, "%s", key);
    pr.value[pr.n] = x;
    pr.param[pr.n] = isparam ? ur_name_param(p->m, key) : -1;
    pr.n++;
  }
  if (declare(p, SYM_PRESET, name, st->line, p->m->npreset, 1)) {
    return -1;
  }
  urPreset* np = realloc(p->m->preset, (size_t)(p->m->npreset + 1) * sizeof(urPreset));
  if (!np) {
    return fail(p, st->line, "out of memory");
  }
  p->m->preset = np;
  np[p->m->npreset++] = pr;
  return 0;
}


/* the drone tree scaled by its design parameters (role mass=, size=) */
static int apply_design(Parser* p) {
  urModel* m = p->m;
  urRoles* r = &m->roles;
  if (r->drone < 0) {
    return 0;
  }
  r->mass0 = ur_model_tree_mass(m, r->drone);
  double fm = 1, fs = 1;
  if (r->mass_param >= 0) {
    double mm = m->param[r->mass_param].value;
    if (!(mm > 0) || !(r->mass0 > 0)) {
      snprintf(p->msg, sizeof(p->msg), "role mass: parameter '%s' must be > 0 (got %g)",
               m->param[r->mass_param].name, mm);
      return -1;
    }
    fm = mm / r->mass0;
  }
  if (r->size_param >= 0) {
    fs = m->param[r->size_param].value;
    if (!(fs > 0)) {
      snprintf(p->msg, sizeof(p->msg), "role size: parameter '%s' must be > 0 (got %g)",
               m->param[r->size_param].name, fs);
      return -1;
    }
  }
  if (fabs(fm - 1) <= 1e-12) {
    fm = 1; /* the total as written, to rounding: the bodies as written */
  }
  r->mass_scale = fm;
  r->size_scale = fs;
  if (fm != 1 || fs != 1) {
    ur_model_scale_tree(m, r->drone, fm, fs);
  }
  return 0;
}


/* part NAME */
static int st_part(Parser* p, const urlStmt* st) {
  if (st->nword != 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return fail(p, st->line, "part takes exactly one NAME; expected 'part NAME'");
  }
  const char* name = url_word(&p->lx, st->word + 1);
  if (checkname(p, name, strlen(name), st->line, "part")) {
    return -1;
  }
  return declare(p, SYM_PART, name, st->line, 0, 1);
}

//---------------------------------- driver --------------------------------------------------------

/* one statement */
static int statement(Parser* p, const urlStmt* st) {
  static const struct {
    const char* kw;
    int kind;
  } elem[] = {{"curve", SYM_CURVE},         {"body", SYM_BODY},     {"restraint", -1},
              {"ellipsoid", SYM_ELLIPSOID}, {"law", SYM_LAW},       {"pair", SYM_PAIR},
              {"airbag", SYM_AIRBAG},       {"sensor", SYM_SENSOR}, {"pairs", -1}};
  const char* kw = url_word(&p->lx, st->word);
  Bound b;
  b.kw = kw;
  b.what = kw;
  b.name = NULL;
  b.line = st->line;

  /* statements without NAME key=value */
  if (!strcmp(kw, "param")) {
    return st_param(p, st);
  }
  if (!strcmp(kw, "part")) {
    return st_part(p, st);
  }
  if (!strcmp(kw, "preset")) {
    return st_preset(p, st);
  }
  if (!strcmp(kw, "role")) {
    if (st->nword > 1 && !strchr(url_word(&p->lx, st->word + 1), '=')) {
      return fail(p, st->line, "role takes key=value pairs only (no name)");
    }
    return st_role(p, st, &b);
  }
  if (!strcmp(kw, "option")) {
    if (st->nword > 1 && !strchr(url_word(&p->lx, st->word + 1), '=')) {
      return fail(p, st->line, "option takes key=value pairs only (no name)");
    }
    return st_option(p, st, &b);
  }

  /* element statements: KEYWORD NAME key=value... */
  int e = 0, ne = (int)(sizeof(elem) / sizeof(elem[0]));
  while (e < ne && strcmp(elem[e].kw, kw)) {
    e++;
  }
  if (e == ne) {
    return fail(p, st->line, "unknown keyword '%s'; expected one of %s", quote(kw, strlen(kw)).s,
                keywords);
  }
  if (st->nword < 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return fail(p, st->line, "%s needs a %s before its keys; expected '%s %s key=value ...'", kw,
                e == 2 ? "BODY" : "NAME", kw, e == 2 ? "BODY" : "NAME");
  }
  b.name = url_word(&p->lx, st->word + 1);
  if (checkname(p, b.name, strlen(b.name), st->line, kw)) {
    return -1;
  }

  /* key table (laws by type) */
  const KeySpec* spec;
  int nspec;
  switch (e) {
  case 0:
    spec = spec_curve;
    nspec = NKEY(spec_curve);
    break;
  case 1:
    spec = spec_body;
    nspec = NKEY(spec_body);
    break;
  case 2:
    spec = spec_restraint;
    nspec = NKEY(spec_restraint);
    break;
  case 3:
    spec = spec_ellipsoid;
    nspec = NKEY(spec_ellipsoid);
    break;
  case 5:
    spec = spec_pair;
    nspec = NKEY(spec_pair);
    break;
  case 6:
    spec = spec_airbag;
    nspec = NKEY(spec_airbag);
    break;
  case 7:
    spec = spec_sensor;
    nspec = NKEY(spec_sensor);
    break;
  case 8:
    spec = spec_pairs;
    nspec = NKEY(spec_pairs);
    break;
  default: {
    const char* t = NULL;
    for (int w = 2; w < st->nword; w++) {
      const char* s = url_word(&p->lx, st->word + w);
      if (!strncmp(s, "type=", 5)) {
        t = s + 5;
      }
    }
    if (!t || !*t) {
      return fail(p, st->line, "law '%s': missing %s 'type'; expected type=hertz|table|foam",
                  b.name, t ? "value for key" : "key");
    }
    if (!strcmp(t, "hertz")) {
      spec = spec_hertz;
      nspec = NKEY(spec_hertz);
      b.what = "law type=hertz";
    } else if (!strcmp(t, "table")) {
      spec = spec_table;
      nspec = NKEY(spec_table);
      b.what = "law type=table";
    } else if (!strcmp(t, "foam")) {
      spec = spec_foam;
      nspec = NKEY(spec_foam);
      b.what = "law type=foam";
    } else {
      return fail(p, st->line, "key 'type': unknown value '%s'; expected one of hertz/table/foam",
                  quote(t, strlen(t)).s);
    }
  }
  }

  /* bind; a disabled element leaves only its name behind (for messages) */
  int rc = bind(p, st, 2, spec, nspec, &b);
  if (rc < 0) {
    return -1;
  }
  if (rc) {
    if (e == 8) {
      return pairs_disabled(p, &b, st->line);
    }
    if (elem[e].kind < 0) {
      return 0;
    }
    if (elem[e].kind == SYM_BODY) {
      const Val* vj = get(&b, "jname");
      int named = vj->set && isident(vj->raw, strlen(vj->raw)) && strlen(vj->raw) < urNAMELEN;
      if (declare(p, SYM_JOINT, named ? vj->raw : b.name, st->line, -1, 0)) {
        return -1;
      }
    }
    return declare(p, elem[e].kind, b.name, st->line, -1, 0);
  }
  switch (e) {
  case 0: return st_curve(p, &b);
  case 1: return st_body(p, &b);
  case 2: return st_restraint(p, &b);
  case 3: return st_ellipsoid(p, &b);
  case 4: return st_law(p, &b);
  case 5: return st_pair(p, &b);
  case 6: return st_airbag(p, &b);
  case 7: return st_sensor(p, &b);
  default: return st_pairs(p, &b);
  }
}


/* every override must name a parameter that some source defines, with a finite value */
static int check_overrides(Parser* p) {
  for (int i = 0; i < p->nov; i++) {
    const char* name = p->ov[i].name;
    if (!name) {
      snprintf(p->msg, sizeof(p->msg), "override %d: no parameter name", i + 1);
      return -1;
    }
    if (!isfinite(p->ov[i].value)) {
      snprintf(p->msg, sizeof(p->msg), "override '%s': the value is not a finite number",
               quote(name, strlen(name)).s);
      return -1;
    }
    int found = 0;
    for (int s = 0; s < p->lx.nstmt && !found; s++) {
      const urlStmt* st = p->lx.stmt + s;
      found = st->nword >= 2 && !strcmp(url_word(&p->lx, st->word), "param") &&
              !strcmp(url_word(&p->lx, st->word + 1), name);
    }
    if (!found) {
      snprintf(p->msg, sizeof(p->msg),
               "override '%s': no model text defines a parameter of "
               "that name; expected a name from 'param NAME VALUE' lines",
               quote(name, strlen(name)).s);
      return -1;
    }
  }
  return 0;
}


/* release everything but the model */
static void release(Parser* p) {
  url_free(&p->lx);
  free(p->sym);
  free(p->chain);
  free(p->curve);
  free(p->law);
  free(p->pval);
}


urModel* ur_model_parse(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                        char* err, int errlen) {
  return ur_model_parse_stop(src, nsrc, ov, nov, NULL, err, errlen);
}


urModel* ur_model_parse_stop(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                             const _Atomic int* stop, char* err, int errlen) {
  Parser p;
  memset(&p, 0, sizeof(p));
  p.stop = stop;
  p.src = src;
  p.nsrc = nsrc;
  p.ov = ov;
  p.nov = ov ? nov : 0;
  int rc = 0;

  /* arguments */
  if (nsrc < 0 || (nsrc > 0 && !src) || nov < 0 || (nov > 0 && !ov)) {
    snprintf(p.msg, sizeof(p.msg), "ur_model_parse: bad arguments");
    rc = -1;
  }

  /* lex every source, then check the overrides against the param lines */
  for (int i = 0; !rc && i < nsrc; i++) {
    rc = url_lex(&p.lx, src[i].text, i, srcname(&p, i), src[i].line, p.msg, sizeof(p.msg));
  }
  if (!rc) {
    rc = check_overrides(&p);
  }

  /* statements in order */
  if (!rc && !(p.m = ur_model_new())) {
    snprintf(p.msg, sizeof(p.msg), "out of memory");
    rc = -1;
  }
  for (int i = 0; !rc && i < p.lx.nstmt; i++) {
    p.cur = i;
    p.cursrc = p.lx.stmt[i].src;
    if (p.stop && *p.stop) {
      snprintf(p.msg, sizeof(p.msg), "%s:%d: stopped on request (interrupted)",
               srcname(&p, p.cursrc), p.lx.stmt[i].line);
      rc = -1;
      break;
    }
    rc = statement(&p, p.lx.stmt + i);
  }

  /* the drone's design parameters, then compile (elements were checked on their lines; this
     should not fail) */
  if (!rc) {
    rc = apply_design(&p);
  }
  if (!rc && ur_model_compile(p.m)) {
    snprintf(p.msg, sizeof(p.msg), "%s: the model does not compile: %s", srcname(&p, nsrc - 1),
             p.m->err);
    rc = -1;
  }
  release(&p);
  if (rc) {
    ur_model_free(p.m);
    p.m = NULL;
    if (err && errlen > 0) {
      snprintf(err, (size_t)errlen, "%s", p.msg);
    }
  } else if (err && errlen > 0) {
    err[0] = 0;
  }
  return p.m;
}

//---------------------------------- parts ---------------------------------------------------------

int ur_model_split(const char* text, const char* file, urModelPart* parts, int maxpart, char* err,
                   int errlen) {
  urlLex lx;
  char msg[MSGLEN];
  memset(&lx, 0, sizeof(lx));
  if (!file || !file[0]) {
    file = "model";
  }
  if (err && errlen > 0) {
    err[0] = 0;
  }
  int rc = url_lex(&lx, text, 0, file, 1, msg, sizeof(msg));

  /* check the part lines: one valid name each, no duplicates, at most limit[SYM_PART] (each
     compared with the part lines before it) */
  int* seen = NULL;
  int nseen = 0;
  for (int s = 0; !rc && s < lx.nstmt; s++) {
    const urlStmt* st = lx.stmt + s;
    if (strcmp(url_word(&lx, st->word), "part")) {
      continue;
    }
    const char* name = st->nword == 2 ? url_word(&lx, st->word + 1) : "";
    if (st->nword != 2 || !isident(name, strlen(name)) || strlen(name) >= urNAMELEN) {
      snprintf(msg, sizeof(msg), "%s:%d: part takes exactly one NAME; expected 'part NAME' (%s)",
               file, st->line, expect_name);
      rc = -1;
    } else if (nseen == limit[SYM_PART]) {
      snprintf(msg, sizeof(msg),
               "%s:%d: more than %d parts; accepted: at most %d "
               "(uasrisk-model(5), LIMITS)",
               file, st->line, limit[SYM_PART], limit[SYM_PART]);
      rc = -1;
    } else if (!seen && !(seen = malloc(sizeof(int) * (size_t)limit[SYM_PART]))) {
      snprintf(msg, sizeof(msg), "%s: out of memory", file);
      rc = -1;
    }
    for (int k = 0; !rc && k < nseen; k++) {
      const urlStmt* sk = lx.stmt + seen[k];
      if (!strcmp(url_word(&lx, sk->word + 1), name)) {
        snprintf(msg, sizeof(msg),
                 "%s:%d: duplicate part name '%s' (first at line %d); names "
                 "must be unique",
                 file, st->line, name, sk->line);
        rc = -1;
      }
    }
    if (!rc) {
      seen[nseen++] = s;
    }
  }
  free(seen);
  if (rc) {
    url_free(&lx);
    if (err && errlen > 0) {
      snprintf(err, (size_t)errlen, "%s", msg);
    }
    return -1;
  }

  /* part "" from the start when the first part line is not there */
  size_t len = strlen(text);
  int np = 0;
  for (int s = -1; s < lx.nstmt; s++) {
    const urlStmt* st = s >= 0 ? lx.stmt + s : NULL;
    if (st && strcmp(url_word(&lx, st->word), "part")) {
      continue;
    }
    size_t start = st ? st->linestart : 0;
    if (!st && (len == 0 || np > 0)) {
      continue;
    }

    /* a part line closes the previous part; at offset 0 it replaces the empty part "" */
    if (np > 0 && np <= maxpart) {
      parts[np - 1].len = start - (size_t)(parts[np - 1].text - text);
    }
    if (np == 1 && start == 0) {
      np = 0;
    }
    if (np < maxpart) {
      snprintf(parts[np].name, sizeof(parts[np].name), "%s", st ? url_word(&lx, st->word + 1) : "");
      parts[np].text = text + start;
      parts[np].len = len - start;
      parts[np].line = st ? st->line : 1;
    }
    np++;
  }
  url_free(&lx);
  return np;
}
