/* modellang_internal.h: the model-language lexer shared by modellang_lex.c and modellang.c
 * (not public API). */
#ifndef UASRISK_MODELLANG_INTERNAL_H
#define UASRISK_MODELLANG_INTERNAL_H

#include <stddef.h>

/* one word of a statement: a keyword, a name, a positional value or key=value */
typedef struct {
  size_t off; /* text offset in urlLex.buf (0-terminated there) */
  int line;   /* physical line of its first character */
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

#endif
