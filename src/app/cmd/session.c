/* session.c: save session FILE (a script that recreates the live state exactly) and export */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"

/* write the state as commands: defaults, loaded model parts, case, then every setting that
   differs from what those give (session_base.c; never threads or the plot output, which belong
   to the machine and the last plot); every text is one quoted word that the reader takes back as
   it is and a shell would not expand (single quotes; double quotes only around a word that holds
   a single quote and nothing a shell expands: ura_word_inert; the terminal was checked when set,
   nothing in it is run) */
void ura_session_write(uraCtx* c, FILE* f) {
  char val[2048], was[2048];
  uraState base;
  ura_session_base(c, &base);
  uraCtx bc = *c;
  bc.st = base;
  fprintf(f, "# uasimpact session: replay with 'uasimpact FILE' or 'source FILE'\n");
  fprintf(f, "reset\n");
  ura_model_write_parts(c, f);
  /* a case the live model has no preset of (its parts replaced: model drop, model load) is not
     replayed: the settings below are then written against the defaults */
  if (ura_preset_find(c, c->st.casename))
    fprintf(f, "case %s\n", c->st.casename);
  else
    fprintf(f, "# case %s: not a case of the loaded model, so not replayed\n", c->st.casename);
  for (const uraParam* p = ura_params; p->name; p++) {
    if (p->kind == uraP_CASE || !strcmp(p->name, "threads") || !strcmp(p->name, "output")) {
      continue;
    }
    ura_param_format(c, p, val, sizeof val);
    ura_param_format(&bc, p, was, sizeof was);
    if (!strcmp(val, was)) continue;
    fprintf(f, "set %s ", p->name);
    if (p->kind == uraP_STR)
      ura_put_word(f, val);
    else
      fputs(val, f);
    fputc('\n', f);
  }
  for (int i = 0; i < ur_injury_param_count(); i++) {
    const char* name;
    ur_injury_param_info(i, &name, NULL, NULL);
    ura_injury_line(c, i, val, sizeof val, 0);
    ura_injury_line(&bc, i, was, sizeof was, 0);
    if (strcmp(val, was)) fprintf(f, "set %s %s\n", name, val);
  }
  for (int i = 0; i < c->st.nov; i++) {
    if (!c->st.ov_user[i]) continue;
    int same = 0;
    for (int k = 0; k < base.nov; k++) {
      same |= !strcmp(base.ov_name[k], c->st.ov_name[i]) && base.ov_val[k] == c->st.ov_val[i];
    }
    if (same) continue;
    ura_model_value_text(c, c->st.ov_name[i], c->st.ov_val[i], val, sizeof val);
    fprintf(f, "set %s %s\n", c->st.ov_name[i], val);
  }
  ura_dist_save(c, f);
}

char* ura_session_text(uraCtx* c) {
  char* text = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&text, &n);
  if (!f) return NULL;
  ura_session_write(c, f);
  if (fclose(f)) {
    free(text);
    return NULL;
  }
  return text;
}

int ura_cmd_save(uraCtx* c, int argc, char** argv) {
  if (strcmp(argv[1], "session")) {
    return ura_fail(c, "save: unknown '%s'; accepted: save session FILE", argv[1]);
  }
  if (ura_name_fits(c, "save session", argv[2], "a script of commands", "ses txt")) return -1;
  uraAtomic a;
  if (ura_atomic_open(c, &a, argv[2], "save session")) return -1;
  /* the model files named relative to the session's folder (or absolute): it replays from
     any current folder */
  char dir[4096];
  ura_dir_of(argv[2], dir, sizeof dir);
  c->savedir = dir;
  ura_designs_write(c, a.f, ura_session_write); /* each saved design, then the live state */
  ura_session_write(c, a.f);
  c->savedir = NULL;
  return ura_atomic_close(c, &a, 1, "save session");
}

/* export grid|history|sweep|contacts|montecarlo FILE: the same rows as 'grid cells', 'history',
   'sweep show', 'contacts' or 'montecarlo samples', always plain CSV (header and rows), written to
   a temporary file beside FILE and renamed when complete; the notes, units and provenance to
   FILE.meta.json beside it (and at the prompt to standard error) */
int ura_cmd_export(uraCtx* c, int argc, char** argv) {
  int grid = !strcmp(argv[1], "grid"), hist = !strcmp(argv[1], "history");
  int sweep = !strcmp(argv[1], "sweep"), cont = !strcmp(argv[1], "contacts");
  int mc = !strcmp(argv[1], "montecarlo");
  if (!grid && !hist && !sweep && !cont && !mc) {
    return ura_fail(c,
                    "export: unknown '%s'; accepted: export grid FILE, export history FILE, "
                    "export sweep FILE, export contacts FILE, export montecarlo FILE",
                    argv[1]);
  }
  if (mc && !c->mc) return ura_fail(c, "export montecarlo: no montecarlo yet; run 'montecarlo N'");
  if (sweep && !c->nsweep && !c->npsweep) {
    return ura_fail(c,
                    "export sweep: no sweep yet; run 'sweep wind LIST' or 'sweep face LIST' "
                    "(or 'sweep NAME LIST [UNIT]')");
  }
  if (ura_name_fits(c, "export", argv[2], "CSV", "csv txt")) return -1;
  uraAtomic a;
  int notes = ura_at_terminal(c); /* the notes at the prompt also to standard error */
  if (ura_atomic_open(c, &a, argv[2], "export")) return -1;

  /* print into the file in plain CSV, the notes and units gathered for the sidecar */
  FILE* out = c->out;
  int fmt = c->st.format;
  c->out = a.f;
  c->st.format = uraFMT_CSV;
  c->export_meta = json_array();
  c->export_notes = notes;
  char* av[2] = {argv[1], grid ? "cells" : mc ? "samples" : "show"};
  /* the commands' own writers, through the command table (grid cells, sweep show, montecarlo
     samples, contacts) */
  const uraCmd* k = hist ? NULL : ura_cmd_find(argv[1]);
  int rc = hist ? ura_history_samples(c, -INFINITY, INFINITY) : k->fn(c, cont ? 1 : 2, av);
  json_t* tables = c->export_meta;
  c->export_meta = NULL;
  c->export_notes = 0;
  c->out = out;
  c->st.format = fmt;
  char what[64];
  snprintf(what, sizeof what, "export %s", argv[1]);
  rc = ura_atomic_close(c, &a, rc == 0, "export") || rc;
  if (rc == 0) rc = ura_export_meta(c, argv[2], what, tables);
  json_decref(tables);
  return rc ? -1 : 0;
}
