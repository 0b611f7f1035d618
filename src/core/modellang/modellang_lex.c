/* modellang_lex.c: lexer of the model language: comments, line continuation, words, statements
 * (uasimpact-model(5), section LEXICAL RULES). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "modellang_internal.h"

//---------------------------------- helpers -------------------------------------------------------

/* whitespace inside a line */
static int isblank_(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}


/* grow an array so that it holds n more elements */
static int reserve(void** arr, size_t* cap, size_t need, size_t size) {
  if (need <= *cap) {
    return 0;
  }
  size_t nc = *cap ? 2 * (*cap) : 64;
  while (nc < need) {
    nc *= 2;
  }
  void* p = realloc(*arr, nc * size);
  if (!p) {
    return -1;
  }
  *arr = p;
  *cap = nc;
  return 0;
}


/* int-capacity wrapper of reserve */
static int reserve_i(void** arr, int* cap, int need, size_t size) {
  size_t c = (size_t)*cap;
  if (reserve(arr, &c, (size_t)need, size)) {
    return -1;
  }
  *cap = (int)c;
  return 0;
}

//---------------------------------- lexer ---------------------------------------------------------

/* the logical text of a source: comments and continuations removed, one char per byte kept */
typedef struct {
  char* c;     /* characters; '\n' ends a statement */
  int* line;   /* physical line of each character */
  size_t* off; /* offset of each character in the source text */
  size_t n;
} Clean;


/* strip comments and join continued lines; -1 on error (message in err) */
static int clean(Clean* cl, const char* text, const char* file, int firstline, char* err,
                 size_t errlen) {
  size_t len = strlen(text);
  cl->n = 0;
  cl->c = malloc(len + 2);
  cl->line = malloc((len + 2) * sizeof(int));
  cl->off = malloc((len + 2) * sizeof(size_t));
  if (!cl->c || !cl->line || !cl->off) {
    snprintf(err, errlen, "%s: out of memory", file);
    return -1;
  }

  /* one physical line at a time (after a UTF-8 byte order mark) */
  size_t a = len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3) ? 3 : 0;
  int line = firstline > 0 ? firstline : 1;
  while (a < len) {
    const char* nl = memchr(text + a, '\n', len - a);
    size_t e = nl ? (size_t)(nl - text) : len;
    const char* hash = memchr(text + a, '#', e - a);
    size_t te = hash ? (size_t)(hash - text) : e;
    while (te > a && isblank_(text[te - 1])) {
      te--;
    }
    int cont = te > a && text[te - 1] == '\\';
    if (cont) {
      te--;
      if (!nl || e + 1 >= len) {
        snprintf(err, errlen,
                 "%s:%d: '\\' at the end of the text continues nothing; "
                 "expected another line after it",
                 file, line);
        return -1;
      }
    }

    /* copy the line, then a separator: a blank for a continuation, else a statement end */
    for (size_t i = a; i < te; i++) {
      cl->c[cl->n] = text[i];
      cl->line[cl->n] = line;
      cl->off[cl->n++] = i;
    }
    cl->c[cl->n] = cont ? ' ' : '\n';
    cl->line[cl->n] = line;
    cl->off[cl->n++] = te;
    a = e + 1;
    line++;
  }
  return 0;
}


/* append one word [c, c+n) to the lexer, from source text [at, at + len) */
static int addword(urlLex* lx, const char* c, size_t n, int line, size_t at, size_t len) {
  if (reserve((void**)&lx->buf, &lx->capbuf, lx->nbuf + n + 1, 1) ||
      reserve_i((void**)&lx->word, &lx->capword, lx->nword + 1, sizeof(urlWord))) {
    return -1;
  }
  memcpy(lx->buf + lx->nbuf, c, n);
  lx->buf[lx->nbuf + n] = 0;
  lx->word[lx->nword].off = lx->nbuf;
  lx->word[lx->nword].line = line;
  lx->word[lx->nword].at = at;
  lx->word[lx->nword].len = len;
  lx->nword++;
  lx->nbuf += n + 1;
  return 0;
}


int url_lex(urlLex* lx, const char* text, int src, const char* file, int firstline, char* err,
            size_t errlen) {
  if (!file) {
    file = "model";
  }
  if (!text) {
    snprintf(err, errlen, "%s: no text", file);
    return -1;
  }
  Clean cl = {0};
  int rc = clean(&cl, text, file, firstline, err, errlen);

  /* words: runs of non-blanks; blanks next to ',' do not separate */
  char* w = rc ? NULL : malloc(cl.n + 1);
  if (!rc && !w) {
    snprintf(err, errlen, "%s: out of memory", file);
    rc = -1;
  }
  size_t i = 0;
  while (!rc && i < cl.n) {
    /* one statement, up to the next '\n' */
    size_t end = i;
    while (cl.c[end] != '\n') {
      end++;
    }
    int first = lx->nword;
    size_t firstoff = 0;
    while (i < end) {
      while (i < end && isblank_(cl.c[i])) {
        i++;
      }
      if (i == end) {
        break;
      }
      size_t n = 0, start = i;
      for (;;) {
        while (i < end && !isblank_(cl.c[i])) {
          w[n++] = cl.c[i++];
        }
        size_t j = i;
        while (j < end && isblank_(cl.c[j])) {
          j++;
        }
        if (j < end && (w[n - 1] == ',' || cl.c[j] == ',')) {
          i = j;
          continue;
        }
        break;
      }
      if (lx->nword == first) {
        firstoff = cl.off[start];
      }
      if (addword(lx, w, n, cl.line[start], cl.off[start], cl.off[i - 1] + 1 - cl.off[start])) {
        snprintf(err, errlen, "%s: out of memory", file);
        rc = -1;
        break;
      }
    }

    /* record the statement with the start of its first line */
    if (!rc && lx->nword > first) {
      if (reserve_i((void**)&lx->stmt, &lx->capstmt, lx->nstmt + 1, sizeof(urlStmt))) {
        snprintf(err, errlen, "%s: out of memory", file);
        rc = -1;
        break;
      }
      while (firstoff > 0 && text[firstoff - 1] != '\n') {
        firstoff--;
      }
      urlStmt* s = lx->stmt + lx->nstmt++;
      s->src = src;
      s->word = first;
      s->nword = lx->nword - first;
      s->line = lx->word[first].line;
      s->linestart = firstoff;
    }
    i = end + 1;
  }
  free(w);
  free(cl.c);
  free(cl.line);
  free(cl.off);
  return rc;
}


void url_free(urlLex* lx) {
  if (!lx) {
    return;
  }
  free(lx->buf);
  free(lx->word);
  free(lx->stmt);
  memset(lx, 0, sizeof(urlLex));
}


const char* url_word(const urlLex* lx, int i) {
  return lx->buf + lx->word[i].off;
}
