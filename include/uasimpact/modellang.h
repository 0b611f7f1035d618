/* modellang.h: the uasimpact model language. Human, drone and airbag models are plain text
 * (uasimpact-model(5)); this parses one or more texts into a compiled urModel and splits a text
 * into named parts so that an application can replace or add parts. Pure library code: no I/O,
 * no globals, reentrant.
 */
#ifndef UASIMPACT_MODELLANG_H
#define UASIMPACT_MODELLANG_H

#include <stddef.h>
#include "uasimpact/engine.h"

#ifdef __cplusplus
extern "C" {
#endif

/* a parameter value forced by the caller, in SI units (replaces every definition of name) */
typedef struct {
  const char* name;
  double value;
} urOverride;

/* one model text; file is the name used in messages ("FILE:LINE: ..."); line is the line of
   the file where the text starts (0 or 1: the first line), so that a part of a file is reported
   at its lines in the file */
typedef struct {
  const char* text;
  const char* file;
  int line;
} urModelSource;

/* one part of a text: bytes [text, text + len) of the text given to ur_model_split */
typedef struct {
  char name[urNAMELEN]; /* part name; "" for the text before the first part line */
  const char* text;     /* first byte (start of the line holding 'part NAME') */
  size_t len;           /* bytes, up to the start of the next part line */
  int line;             /* line number of the first byte (1-based) */
} urModelPart;

/* Parse the sources in order (parameters, curves, laws, bodies... are shared by all sources:
   a later source may refer to names of an earlier one), apply the overrides, build and compile
   the model. Returns the compiled model, or NULL with a one-line message in err (at most
   errlen bytes, "FILE:LINE: what was wrong; expected ...") and nothing allocated. An override
   naming a parameter that no source defines is an error, and so is a model beyond the limits of
   uasimpact-model(5) (e.g. more than 1000 bodies). err may be NULL. Time and memory grow linearly
   with the text up to those limits. */
urModel* ur_model_parse(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                        char* err, int errlen);

/* The same, polling *stop (when stop is not NULL) between statements: a stop request fails the
   parse with "FILE:LINE: stopped on request (interrupted)" (an interrupt flag, e.g. Ctrl-C). */
urModel* ur_model_parse_stop(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                             const _Atomic int* stop, char* err, int errlen);

/* The same, with the inflated-bag cache c (membrane.h; NULL: none) as the model's
   opt.memcache: ur_model_inflate takes a bag whose whole spec was inflated before from the
   cache, the same to the bit, so c must outlive the model's inflation (or the model); one cache
   serves any number of parses, e.g. one per session. No parse inflates: ur_model_inflate does,
   before the model runs (engine.h). */
urModel* ur_model_parse_cache(const urModelSource* src, int nsrc, const urOverride* ov, int nov,
                              const _Atomic int* stop, urMemCache* c, char* err, int errlen);

/* Split text at its 'part NAME' lines. Each part starts at the beginning of the line holding its
   'part' statement and ends where the next part starts, so the parts concatenated in order give
   back the text exactly. Text before the first part line is a part named "", present only when
   that text is not empty (an empty text has no parts). Fills at most maxpart parts (parts may be
   NULL with maxpart 0) and returns the total number of parts, or -1 with a message in err
   ("FILE:LINE: ...", FILE from file, may be NULL) for a malformed part line, more than 256 part lines, a duplicate part
   name or a continuation at the end of the text. */
int ur_model_split(const char* text, const char* file, urModelPart* parts, int maxpart, char* err,
                   int errlen);

/* one word of a model-language text as the parser reads it */
typedef struct {
  size_t at, len; /* its place in the text: [at, at + len) (blanks joined at ',' included) */
  int stmt;       /* its statement (logical line), from 0 */
} urModelWord;

/* The words of text as the parser reads them (comments removed, continued lines joined, blanks
   next to ',' not separating), for a tool that edits the text in place: *words a new array of
   *nword (the caller frees it; NULL when there are none). Returns 0, or -1 with a message in err
   ("model:LINE: ..."). */
int ur_model_words(const char* text, urModelWord** words, int* nword, char* err, int errlen);

/* factor from a unit of the language (m, mm, atm, deg, ...; several joined by '*' and '/':
   N*m/rad, kN/m) to SI; 0, or -1 if unknown. ur_unit_parse also gives the SI unit (kN/m: N/m,
   atm: Pa, none: "") into si (n bytes; NULL: not wanted). */
int ur_unit_si(const char* unit, double* factor);
int ur_unit_parse(const char* unit, double* factor, char* si, size_t n);

#ifdef __cplusplus
}
#endif
#endif
