/* output.c: the session's output through the base layer's tools, under the session's settings:
 * whether a command writes to a person at a terminal (typed at the prompt, not in a script,
 * dry run or pipe), the width text wraps at, the pager around a command, tables in the chosen
 * format, and files written atomically for a command (refused in dry mode, nowhere when muted).
 * The base layer knows nothing of a session; this is where the session's settings meet it. And
 * the session's failure message (ura_fail: every failure of the layers above lands in c->err
 * through it) and the dry mode's refusal. The bottom of the case layer: it calls only the base. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "case.h"

int ura_at_terminal(const uraCtx* c) {
  return c->interactive && c->depth == 0 && !c->dry && ura_tty(c->out);
}

int ura_text_width(const uraCtx* c) {
  int rows, cols;
  if (!ura_at_terminal(c) || c->st.format != uraFMT_TABLE) return 0;
  ura_term_size(&rows, &cols);
  return cols < 80 ? cols : 80;
}

int ura_pager_begin(uraCtx* c, const char* cmd) {
  if (!c->st.pager || !ura_at_terminal(c)) return 0;
  FILE* f = ura_pager_gather(c->out, cmd);
  if (!f) return 0;
  c->out = f;
  return 1;
}

void ura_pager_end(uraCtx* c) {
  FILE* out = ura_pager_release(c->msg);
  if (out) c->out = out;
}

void ura_table_print(uraCtx* c, uraTable* t) {
  if (c->rep_table) c->rep_table(c, t); /* kept for report before it is printed and freed */
  ura_table_write(c->out, t, c->st.format == uraFMT_CSV, ura_text_width(c));
}

void ura_input_seen(uraCtx* c, FILE* f, const char* path) {
  if (c->scale && c->scale_input) c->scale_input(c, f, path);
}

/* open as ura_atomic_open says; regular: as ura_atomic_open_file */
static int open_as(uraCtx* c, uraAtomic* a, const char* path, const char* who, int regular) {
  char err[uraERRLEN];
  memset(a, 0, sizeof *a);
  a->fd = -1;
  if (ura_dry(c, who)) return -1;
  if (c->mute && !regular) path = "/dev/null"; /* a shard or an MPI rank but 0: no files */
  if (ura_atomic_begin(a, path, who, regular, err, sizeof err)) return ura_fail(c, "%s", err);
  return 0;
}

int ura_atomic_open(uraCtx* c, uraAtomic* a, const char* path, const char* who) {
  return open_as(c, a, path, who, 0);
}

int ura_atomic_open_file(uraCtx* c, uraAtomic* a, const char* path, const char* who) {
  return open_as(c, a, path, who, 1);
}

int ura_atomic_close(uraCtx* c, uraAtomic* a, int ok, const char* who) {
  char err[uraERRLEN];
  err[0] = 0;
  if (ura_atomic_end(a, ok, who, err, sizeof err)) return err[0] ? ura_fail(c, "%s", err) : -1;
  return 0;
}

int ura_fail(uraCtx* c, const char* fmt, ...) {
  char raw[uraERRLEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(raw, sizeof raw, fmt, ap);
  va_end(ap);
  ura_printable(raw, c->err, sizeof c->err); /* no echoed input drives the terminal */
  c->err_located = 0;
  return -1;
}

int ura_dry(uraCtx* c, const char* what) {
  if (!c->dry) return 0;
  return ura_fail(c, "%s: not run (dry mode: no simulations, plots, viewer or files)", what);
}
