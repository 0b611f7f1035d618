/* output.c: the session's output through the base layer's tools, under the session's settings:
 * whether a command writes to a person at a terminal (typed at the prompt, not in a script,
 * dry run or pipe), the width text wraps at, the pager around a command, tables in the chosen
 * format, and files written atomically for a command (refused in dry mode, nowhere when muted).
 * The base layer knows nothing of a session; this is where the session's settings meet it. And
 * the session's failure message (ura_fail: every failure of the layers above lands in c->err
 * through it) and the dry mode's refusal. What an exported file's sidecar FILE.meta.json says
 * (its columns' units, the notes, the program and case it came from) is written here too, with
 * libjansson. The bottom of the case layer: it calls only the base. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

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

/* the units of the columns the workbench writes, by name; then by prefix (history channels) */
static const char* const column_units[][2] = {
    {"dpar", "m"},       {"dperp", "m"},        {"contact", ""},         {"hic15", ""},
    {"nij", ""},         {"vc_thorax", "m/s"},  {"vc_abdomen", "m/s"},   {"vc_th", "m/s"},
    {"vc_ab", "m/s"},    {"defl", "m"},         {"chest_defl", "m"},     {"abd_defl", "m"},
    {"p", ""},           {"p_hic", ""},         {"p_nij", ""},           {"p_vc", ""},
    {"wind", "m/s"},     {"face", "deg"},       {"speed", "m/s"},        {"angle", "deg"},
    {"step", "m"},       {"q", "m^2"},          {"q_a", "m^2"},          {"q_b", "m^2"},
    {"complete", ""},    {"cells", ""},         {"contact_cells", ""},   {"seconds", "s"},
    {"t", "s"},          {"first", "s"},        {"last", "s"},           {"peak_time", "s"},
    {"peak_force", "N"}, {"head_acc", "m/s^2"}, {"q_parametric", "m^2"}, {"ratio", ""},
    {"p_centre", ""},    {"sample", ""},        {"defl_thorax", "m"},    {"p_defl", ""},
    {NULL, NULL}};

const char* ura_column_unit(const char* name) {
  for (int i = 0; column_units[i][0]; i++) {
    if (!strcmp(name, column_units[i][0])) return column_units[i][1];
  }
  if (!strncmp(name, "neck_f", 6)) return "N";
  if (!strncmp(name, "neck_m", 6)) return "N m";
  return NULL;
}

/* what the sidecar keeps of one table: its columns with their units, notes, and row count */
static json_t* table_meta(const uraTable* t) {
  json_t* o = ura_table_json(t);
  json_t* cols = json_array();
  size_t i;
  json_t* v;
  json_array_foreach(json_object_get(o, "columns"), i, v) {
    const char* unit = ura_table_unit_of(t, (int)i);
    if (!unit) unit = ura_column_unit(json_string_value(v));
    json_t* col = json_pack("{s:s}", "name", json_string_value(v));
    json_object_set_new(col, "unit", unit ? json_string(unit) : json_null());
    json_array_append_new(cols, col);
  }
  json_t* meta = json_pack("{s:o,s:i,s:O}", "columns", cols, "rows",
                           (int)json_array_size(json_object_get(o, "rows")), "notes",
                           json_object_get(o, "notes"));
  json_decref(o);
  return meta;
}

void ura_table_print(uraCtx* c, uraTable* t) {
  if (c->rep_table) c->rep_table(c, t); /* kept for report before it is printed and freed */
  int how = c->st.format == uraFMT_CSV    ? uraTAB_CSV
            : c->st.format == uraFMT_JSON ? uraTAB_JSON
                                          : uraTAB_TEXT;
  /* printed CSV keeps its notes as '# ' lines before the header (the scripts that read a
     session's output in order rely on it); an exported file is plain: its notes go to the
     sidecar, and at the prompt to c->msg */
  FILE* nf = c->out;
  if (c->export_meta) {
    json_array_append_new(c->export_meta, table_meta(t));
    nf = c->export_notes && !c->mute ? c->msg : NULL;
  }
  ura_table_write(c->out, nf, t, how, ura_text_width(c));
}

int ura_export_meta(uraCtx* c, const char* path, const char* what, json_t* tables) {
  char name[4096];
  struct stat st;
  /* only beside a regular file (not /dev/stdout, a FIFO or a device); none when muted */
  if (c->mute || stat(path, &st) || !S_ISREG(st.st_mode)) return 0;
  if (snprintf(name, sizeof name, "%s.meta.json", path) >= (int)sizeof name) {
    return ura_fail(c, "export: the file name '%.200s...' is too long for its .meta.json", path);
  }
  const char* slash = strrchr(path, '/');
  json_t* o = json_pack("{s:s,s:s,s:s,s:s,s:s,s:O}", "file", slash ? slash + 1 : path, "format",
                        "csv", "program", ura_version(), "command", what, "case", c->st.casename,
                        "tables", tables);
  uraAtomic a;
  if (ura_atomic_open(c, &a, name, "export")) {
    json_decref(o);
    return -1;
  }
  int ok = json_dumpf(o, a.f, JSON_INDENT(2) | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(15)) == 0;
  if (ok) fputc('\n', a.f);
  json_decref(o);
  return ura_atomic_close(c, &a, ok, "export");
}

int ura_name_fits(uraCtx* c, const char* who, const char* path, const char* writes,
                  const char* exts) {
  if (ura_ext_fits(path, exts)) return 0;
  char list[128];
  size_t k = 0;
  for (const char* e = exts; *e && k < sizeof list;) { /* "html htm": ".html or .htm" */
    size_t n = strcspn(e, " ");
    const char* sep = !k ? "" : e[n] ? ", " : " or ";
    k += (size_t)snprintf(list + k, sizeof list - k, "%s.%.*s", sep, (int)n, e);
    e += n + strspn(e + n, " ");
  }
  return ura_fail(c,
                  "%s: the extension of '%s' says %s, but %s writes %s; accepted: a name ending "
                  "in %s, or one whose extension names no other format",
                  who, path, ura_ext_format(path), who, writes, list);
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
