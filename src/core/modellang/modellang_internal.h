/* modellang_internal.h: what the files of the model-language parser share (not public API):
 * the lexer (modellang_lex.c), the parser's state and key tables, and the helpers each file
 * offers the others, prefixed url_: messages and names (modellang_names.c), units, numbers and
 * key binding (modellang_value.c), the element statements (modellang_stmt.c), the links,
 * roles and presets (modellang_link.c), and the driver (modellang.c). */
#ifndef UASIMPACT_MODELLANG_INTERNAL_H
#define UASIMPACT_MODELLANG_INTERNAL_H

#include <stddef.h>

/* one word of a statement: a keyword, a name, a positional value or key=value */
typedef struct {
  size_t off;     /* text offset in urlLex.buf (0-terminated there) */
  int line;       /* physical line of its first character */
  size_t at, len; /* its place in the source text: [at, at + len), blanks joined at ',' included */
} urlWord;

/* one statement: a logical line with at least one word */
typedef struct {
  int src;          /* source index given to url_lex */
  int line;         /* physical line of the first word */
  size_t linestart; /* offset in the source text of that line's first byte */
  int word;         /* first word in urlLex.word */
  int nword;        /* words */
} urlStmt;

/* statements of any number of texts (append with url_lex, release with url_free) */
typedef struct {
  char* buf; /* word texts, each 0-terminated */
  size_t nbuf, capbuf;
  urlWord* word;
  int nword, capword;
  urlStmt* stmt;
  int nstmt, capstmt;
} urlLex;

/* Append the statements of text: '#' comments removed, a line ending in '\' joined with the next,
   whitespace separates words except next to ',' (so long lists may be wrapped). Returns 0, or -1
   with "FILE:LINE: message" in err (FILE from file, "model" if NULL). */
int url_lex(urlLex* lx, const char* text, int src, const char* file, int firstline, char* err,
            size_t errlen);

/* Release the lexer buffers (the struct itself is the caller's). */
void url_free(urlLex* lx);

/* Text of word i. */
const char* url_word(const urlLex* lx, int i);

//---------------------------------- the parser (modellang*.c) -------------------------------------

#include <stdio.h>
#include "uasimpact/material.h"
#include "uasimpact/modellang.h"

#define MAXKEY  48  /* keys of one statement kind */
#define MSGLEN  512 /* internal message buffer */
#define MAXLIST 64  /* names in one list of 'pairs' */
#define NUMLEN  400 /* longest number accepted, characters */

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
  SYM_PRESET,
  SYM_MATERIAL,
  SYM_SECTION,
  SYM_LAYER,
  SYM_NKIND /* the number of kinds */
};

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

/* a soft layer over bone on some of a person's ellipsoids (statement 'layer') */
typedef struct {
  int mat;       /* its material, or -1: a law layer */
  int law;       /* the person's own law that gives the region (layer ... law=), or -1 */
  double h;      /* thickness, m */
  double bone_k; /* stiffness of the bone behind it, N/m */
  double radius; /* Hertz radius of the part under it, m; 0: the ellipsoids' curvature */
  double mu;     /* friction coefficient against a drone part */
  double v_eps;  /* friction regularisation speed, m/s */
} urlLayer;

/* what an ellipsoid is made of: indices into the parser's tables, -1 none */
typedef struct {
  int mat, sec, layer;
} urlGeomMat;

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
  int* chain;              /* capsym chain heads: the last symbol of each hash */
  int count[SYM_NKIND];    /* enabled elements of each kind (limits) */
  const _Atomic int* stop; /* a stop request (Ctrl-C), polled between statements */
  urCurve* curve;
  int ncurve, capcurve;
  urLaw* law;
  int nlaw, caplaw;
  int* lawback; /* per law: the material of a foam's derived backing (backing=derived), or -1 */
  int nlawback, caplawback;
  double* pval;
  int npval, cappval;
  urMaterial* mat; /* materials (modellang_material.c) */
  int nmat, capmat;
  urSection* sec; /* sections */
  int nsec, capsec;
  urlLayer* layer; /* soft-tissue layers */
  int nlayer, caplayer;
  urlGeomMat* gmat; /* per ellipsoid: its material, section, layer (ngeom of them, grown) */
  int ngmat, capgmat;
  char msg[MSGLEN];
} Parser;

/* user text shortened for messages */
typedef struct {
  char s[56];
} Quote;

/* the words of messages and the limits of each kind of name (modellang_names.c) */
extern const char* const url_keywords;
extern const char* const url_expect_num;
extern const char* const url_expect_name;
extern const char* const url_symkind[SYM_NKIND];
extern const char* const url_symkinds[SYM_NKIND];
extern const int url_limit[SYM_NKIND];

/* the helpers each file of the parser offers the others */
void url_unit_names(char* list, size_t len);
Quote url_quote(const char* s, size_t n);
const Val* url_get(const Bound* b, const char* key);
const char* url_srcname(const Parser* p, int src);
const double* url_vec(const Bound* b, const char* key);
double url_num(const Bound* b, const char* key, double dflt);
int url_apply_design(Parser* p);
int url_bind(Parser* p, const urlStmt* st, int first, const KeySpec* spec, int nspec, Bound* b);
int url_checkname(Parser* p, const char* s, size_t n, int line, const char* what);
int url_count(const char* s);
int url_curv2(Parser* p, const urLaw* law, int g, const char* name, int line, const char* what);
int url_declare(Parser* p, int kind, const char* name, int line, int id, int enabled);
int url_degree2(Parser* p, int g, const char* name, int line, const char* what, const char* role);
int url_fail(Parser* p, int line, const char* fmt, ...);
int url_findlater(const Parser* p, int kind, const char* name);
int url_findsym(const Parser* p, int kind, const char* name, int enabled);
int url_isident(const char* s, size_t n);
int url_item(const char* s, int i, char* out, size_t len);
int url_nonneg(Parser* p, const Bound* b, const char* key, int strict);
int url_number(Parser* p, const char* s, size_t n, int line, const char* ctx, double* v);
int url_orientation(Parser* p, const Bound* b, double q[4]);
int url_pairs_disabled(Parser* p, const Bound* b, int line);
int url_push(Parser* p, void** arr, int* n, int* cap, size_t size, int line);
int url_ref(Parser* p, int kind, const char* name, int line, const char* ctx);
int url_st_airbag(Parser* p, const Bound* b);
int url_st_body(Parser* p, const Bound* b);
int url_st_curve(Parser* p, const Bound* b);
int url_st_ellipsoid(Parser* p, const Bound* b);
int url_st_law(Parser* p, const Bound* b);
int url_st_option(Parser* p, const urlStmt* st, Bound* b);
int url_st_pair(Parser* p, const Bound* b);
int url_st_pairs(Parser* p, const Bound* b);
int url_st_param(Parser* p, const urlStmt* st);
int url_st_part(Parser* p, const urlStmt* st);
int url_st_preset(Parser* p, const urlStmt* st);
int url_param_declared(Parser* p, const char* name);
int url_st_restraint(Parser* p, const Bound* b);
int url_st_material(Parser* p, const Bound* b);
int url_st_section(Parser* p, const Bound* b);
int url_st_layer(Parser* p, const Bound* b);
int url_hinge(Parser* p, const Bound* b, urRestraint* r);
int url_geom_material(Parser* p, const Bound* b, int g);
int url_pair_law(Parser* p, const char* pair, int ga, int gb, int law, int line, urLaw* out);
void url_bag_layers(Parser* p, urAirbag* bag);
void url_note(Parser* p, const char* fmt, ...);
/* append one line to the model's derived values (urModel.derived) */
void url_derived(Parser* p, const char* fmt, ...);
int url_st_role(Parser* p, const urlStmt* st, Bound* b);
int url_st_sensor(Parser* p, const Bound* b);
size_t url_decimal_prefix(const char* s, size_t n);
void url_suggest(const Parser* p, int kind, const char* name, char* out, size_t len);

#endif
