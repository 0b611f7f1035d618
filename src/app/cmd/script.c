/* script.c: command lines and session scripts: comments, ';', quoting, FILE:LINE errors */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cmd.h"


#define MAXARGS  64
#define MAXDEPTH 16
#define BOM      "\xef\xbb\xbf" /* U+FEFF in UTF-8: the byte-order mark some editors write */

#define printable ura_printable

void ura_locate(uraCtx* c, const char* name, int lineno) {
  if (c->err_located) return;
  char tmp[uraERRLEN + 300];
  if (lineno > 0)
    snprintf(tmp, sizeof tmp, "%.200s:%d: %s", name, lineno, c->err);
  else
    snprintf(tmp, sizeof tmp, "%.200s: %s", name, c->err);
  size_t n = strlen(tmp);
  if (n >= sizeof c->err) n = sizeof c->err - 1;
  memcpy(c->err, tmp, n);
  c->err[n] = 0;
  c->err_located = 1;
}

/* split one command into words in place; double or single quotes group (as gnuplot's
   set output 'file.png'); returns argc or -1 */
static int split_words(char* s, char** argv, uraCtx* c) {
  int argc = 0;
  while (*s) {
    while (isspace((unsigned char)*s)) s++;
    if (!*s) break;
    if (argc == MAXARGS) return ura_fail(c, "too many words in one command (at most %d)", MAXARGS);
    if (*s == '"' || *s == '\'') {
      char q = *s;
      char* end = strchr(++s, q);
      if (!end) return ura_fail(c, "unterminated quote");
      *end = 0;
      argv[argc++] = s;
      s = end + 1;
    } else {
      argv[argc++] = s;
      while (*s && !isspace((unsigned char)*s)) s++;
      if (*s) *s++ = 0;
    }
  }
  return argc;
}

/* run one command given as words */
static int run_words(uraCtx* c, int argc, char** argv) {
  char name[128];
  char cands[400];
  const uraCmd* cmd = ura_cmd_resolve(argv[0], cands, sizeof cands);
  if (!cmd && *cands) {
    printable(argv[0], name, sizeof name);
    return ura_fail(c, "ambiguous command '%s': %s? type more of the name", name, cands);
  }
  if (!cmd) {
    uraSuggest sg;
    char dym[120];
    printable(argv[0], name, sizeof name);
    ura_suggest_init(&sg, argv[0]);
    ura_suggest_commands(&sg);
    return ura_fail(c, "unknown command '%s'%s; type 'help' for the list of commands", name,
                    ura_suggest_text(&sg, dym, sizeof dym));
  }
  /* the handlers, the report and the guard see the full name (a prefix typed, q) */
  char full[64];
  snprintf(full, sizeof full, "%s", cmd->name);
  argv[0] = full;
  int nargs = argc - 1;
  if (nargs < cmd->minargs || (cmd->maxargs >= 0 && nargs > cmd->maxargs)) {
    return ura_fail(c, "%s: wrong number of arguments (%d); usage: %s", cmd->name, nargs,
                    cmd->usage);
  }
  if (c->guard && c->guard(c, argc, argv)) return -1;
  int paged = ura_pager_begin(c, cmd->name);
  if (c->rep_begin) c->rep_begin(c, argc, argv); /* report/ keeps what it prints */
  /* the settings before a command typed or read (a sourced file is one command), for undo */
  uraState* before = NULL;
  if (c->undo_nest == 0 && strcmp(cmd->name, "undo") && (before = malloc(sizeof *before)))
    memcpy(before, &c->st, sizeof *before);
  c->undo_nest++;
  int rc = cmd->fn(c, argc, argv);
  c->undo_nest--;
  if (before && memcmp(before, &c->st, sizeof *before)) {
    char what[64];
    size_t k = 0;
    for (int i = 0; i < argc && k < sizeof what; i++)
      k += (size_t)snprintf(what + k, sizeof what - k, "%s%s", i ? " " : "", argv[i]);
    ura_undo_push(c, before, what);
  }
  free(before);
  if (c->rep_end) c->rep_end(c, rc);
  if (paged) ura_pager_end(c);

  /* what the command printed reached its destination, or the command failed (a full disk, a
     closed pipe): the error is not lost when the buffer is written later */
  errno = 0;
  if (c->out && (fflush(c->out) || ferror(c->out))) {
    int e = ura_out_errno() ? ura_out_errno() : errno ? errno : EIO;
    ura_out_clear();
    clearerr(c->out);
    if (!rc) rc = ura_fail(c, "%s: cannot write the output: %s", cmd->name, strerror(e));
  }
  return rc;
}

/* a byte-order mark inside a command (a script's first bytes excepted, ura_run_stream): it
   would be part of a word, invisibly ("unknown command 'set'") */
static int bom_refused(uraCtx* c, long at) {
  return ura_fail(c,
                  "a byte-order mark (U+FEFF, bytes EF BB BF) at byte %ld of the line; "
                  "accepted only as the first bytes of a script or session file (an editor's "
                  "'UTF-8 with BOM'): delete it",
                  at + 1);
}

int ura_run_line(uraCtx* c, const char* line) {
  size_t n = strlen(line);
  char* buf = malloc(n + 1);
  if (!buf) return ura_fail(c, "out of memory for a line of %zu bytes", n);
  memcpy(buf, line, n + 1);

  /* cut the comment and split at ';' (both outside quotes), running each piece */
  int rc = 0;
  char inq = 0; /* the open quote character, or 0 */
  char* start = buf;
  for (char* p = buf;; p++) {
    int end = (*p == 0) || (!inq && *p == '#');
    if (!inq && (*p == '"' || *p == '\''))
      inq = *p;
    else if (inq && *p == inq)
      inq = 0;
    if (end || (!inq && *p == ';')) {
      char save = *p;
      *p = 0;
      char* argv[MAXARGS];
      char* bom = strstr(start, BOM);
      int argc = bom ? bom_refused(c, bom - buf) : split_words(start, argv, c);
      if (argc < 0) {
        rc = -1;
      } else if (argc > 0 && ura_interrupted()) {
        char name[128];
        printable(argv[0], name, sizeof name);
        rc = ura_fail(c, "interrupted (Ctrl-C): '%s' and the rest not run", name);
      } else if (argc > 0) {
        rc = run_words(c, argc, argv);
      }
      if (rc || end || save == 0 || c->quit) break;
      start = p + 1;
    }
  }
  free(buf);
  return rc;
}

int ura_run_stream(uraCtx* c, FILE* f, const char* name) {
  char* line = NULL;
  size_t cap = 0;
  long len;
  int lineno = 0, rc = 0;
  while (!c->quit) {
    len = ura_read_line(f, &line, &cap, uraMAXLINE);
    if (len == uraLINE_EOF) break;
    lineno++;

    /* binary input, a line without end, a read error: refuse before interpreting anything */
    if (len == uraLINE_NUL) {
      rc = ura_fail(c, "line contains a NUL byte; scripts are text files");
    } else if (len == uraLINE_LONG) {
      rc = ura_fail(c, "line longer than %ld bytes; scripts are text files", uraMAXLINE);
    } else if (len == uraLINE_ERROR) {
      rc = ura_interrupted() ? ura_fail(c, "interrupted (Ctrl-C) while reading")
                             : ura_fail(c, "cannot read: %s", strerror(errno));
    } else {
      /* a byte-order mark as the file's first bytes is skipped (an editor's 'UTF-8 with BOM') */
      int skip = lineno == 1 && !strncmp(line, BOM, 3) ? 3 : 0;
      rc = ura_run_line(c, line + skip);
    }
    if (rc) {
      ura_locate(c, name, lineno);
      break;
    }
  }
  free(line);
  return rc;
}

int ura_run_file(uraCtx* c, const char* path) {
  if (c->depth >= MAXDEPTH) {
    return ura_fail(c, "source: nesting deeper than %d (does a script source itself?)", MAXDEPTH);
  }
  if (ura_dry(c, "source")) return -1;
  /* the current folder first, then the installed sessions (source tour.ses) */
  char found[4096];
  FILE* f = ura_data_open(path, found, sizeof found);
  if (!f && ura_interrupted()) return ura_fail(c, "interrupted (Ctrl-C) while opening '%s'", path);
  if (!f) return ura_fail(c, "cannot open '%s': %s", path, strerror(errno));
  path = found;
  struct stat sb;
  if (fstat(fileno(f), &sb) == 0 && S_ISDIR(sb.st_mode)) {
    fclose(f);
    return ura_fail(c, "cannot run '%s': it is a directory; accepted: a script file", path);
  }
  ura_input_seen(c, f, path); /* a shard's part may not replace it */
  /* its folder, where the relative names of the models it loads are looked for first */
  char dir[4096];
  ura_dir_of(path, dir, sizeof dir);
  const char* outer = c->srcdir;
  c->srcdir = dir;
  c->depth++;
  int rc = ura_run_stream(c, f, path);
  c->depth--;
  c->srcdir = outer;
  fclose(f);
  return rc;
}

int ura_cmd_source(uraCtx* c, int argc, char** argv) {
  return ura_run_file(c, argv[1]);
}
