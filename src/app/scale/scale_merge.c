/* scale_merge.c: uasimpact merge [-c COMMANDS] [--script FILE]... PART...: the parts of every
 * shard checked against each other, against the script and options given on the merge's own
 * command line (the shards' own, in their order: compared word for word with the command line
 * each part records) and against the script files and the built-in models as they are now; then
 * that command line is run with every simulated cell taken from the part of its shard (nothing is
 * simulated): the output is the unsharded run's. A part file is data: nothing it says is run (its
 * recorded command line is only compared and shown), its cells are read only when every value is
 * in its domain, and a part that holds more grids than the run has is refused at the end.
 * Whatever does not fit is refused with one line, status 2. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scale.h"

typedef struct {
  int n;
  uraPartFile* part; /* n, by shard */
  char** name;       /* their file names */
  char** argv;       /* the command line run: the merge's own words, freed with the rest */
  int ran;           /* the run started (grids are checked at its end) */
} merge;

#define USAGE "uasimpact merge [-c COMMANDS] [--script FILE]... PART..."

/* one line on standard error, its control bytes shown as \xNN (names and words from parts); 2 */
static int refuse(const char* fmt, ...) {
  char raw[2 * uraERRLEN], shown[2 * uraERRLEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(raw, sizeof raw, fmt, ap);
  va_end(ap);
  ura_printable(raw, shown, sizeof shown);
  fprintf(stderr, "uasimpact merge: %s\n", shown);
  return 2;
}

/* a word as a shell would read it back: bare when it holds only safe characters, else in single
   quotes ('\'' for a quote) */
static void put_word(FILE* f, const char* w) {
  if (*w && strspn(w, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._/,:=+-@%") ==
                strlen(w)) {
    fputs(w, f);
    return;
  }
  fputc('\'', f);
  for (; *w; w++) {
    if (*w == '\'')
      fputs("'\\''", f);
    else
      fputc(*w, f);
  }
  fputc('\'', f);
}

/* a command line (argc words) as text of at most n - 1 bytes ("..." when cut): as the shards ran
   it (FILE), or as merge takes it (--script FILE) */
static void show_argv(int argc, char** argv, int as_merge, char* buf, size_t n) {
  char* text = NULL;
  size_t len = 0;
  FILE* f = open_memstream(&text, &len);
  if (!f) {
    snprintf(buf, n, "?");
    return;
  }
  for (int i = 0; i < argc; i++) {
    if (i) fputc(' ', f);
    if (!strcmp(argv[i], "-c") && i + 1 < argc) {
      fputs("-c ", f);
      put_word(f, argv[++i]);
    } else {
      if (as_merge) fputs("--script ", f);
      put_word(f, argv[i]);
    }
  }
  fclose(f);
  if (len < n)
    snprintf(buf, n, "%s", text);
  else
    snprintf(buf, n, "%.*s...", (int)(n - 4), text);
  free(text);
}

static int m_begin(uraScale* s, long ntodo) {
  merge* m = s->impl;
  for (int i = 0; i < m->n; i++) {
    const uraPartFile* p = &m->part[i];
    if (s->grid >= p->ngrid) {
      return ura_fail(s->c,
                      "merge: part '%s' has no grid %ld: its shard ran %ld grids and ended "
                      "with status %d; accepted: parts of runs that reached every grid the merged "
                      "run reaches",
                      m->name[i], s->grid, p->ngrid, p->status);
    }
    const uraPartGrid* g = &p->grid[s->grid];
    long first = ((i - s->grid) % m->n + m->n) % m->n;
    long mine = first < ntodo ? (ntodo - first + m->n - 1) / m->n : 0;
    if (strcmp(g->key, s->key) || g->ntodo != ntodo) {
      return ura_fail(s->c,
                      "merge: grid %ld is not the one the shards ran (part '%s'): the "
                      "script, a file it reads or the model changed since; run the shards again",
                      s->grid, m->name[i]);
    }
    if (g->ncell != mine) {
      return ura_fail(s->c,
                      "merge: part '%s' is damaged: grid %ld holds %ld cells, shard %d of "
                      "%d has %ld",
                      m->name[i], s->grid, g->ncell, i, m->n, mine);
    }
    for (long k = 0; k < mine; k++) {
      if (g->pos[k] != first + k * m->n) {
        return ura_fail(s->c,
                        "merge: part '%s' is damaged: grid %ld holds cell %ld, which is "
                        "not its shard's",
                        m->name[i], s->grid, g->pos[k]);
      }
    }
  }
  return 0;
}

static long m_next(uraScale* s) {
  (void)s;
  return -1; /* every cell comes from the parts */
}

static int m_end(uraScale* s, urGrid* g, const long* todo, long ntodo) {
  merge* m = s->impl;
  for (long k = 0; k < ntodo; k++) {
    int i = (int)((k + s->grid) % m->n);
    const uraPartGrid* pg = &m->part[i].grid[s->grid];
    long first = ((i - s->grid) % m->n + m->n) % m->n;
    if (ura_cell_read(pg->cell[(k - first) / m->n], &g->cell[todo[k]])) {
      return ura_fail(s->c, "merge: part '%s' is damaged: a cell of grid %ld", m->name[i], s->grid);
    }
  }
  return 0;
}

static void m_free(uraScale* s) {
  merge* m = s->impl;
  for (int i = 0; i < m->n; i++) ura_part_free(&m->part[i]);
  free(m->part);
  free(m->name);
  free(m->argv);
  free(m);
  free(s);
}

/* the end of the run: a part that holds grids the run did not reach is not a part of it */
static int m_finish(uraScale* s, int rc) {
  merge* m = s->impl;
  for (int i = 0; !rc && m->ran && i < m->n; i++) {
    if (m->part[i].ngrid > s->grid + 1) {
      rc = refuse(
          "part '%s' holds %ld grids, the merged run ran %ld: it is not a part of this run; "
          "accepted: the parts of the shards of this script and options",
          m->name[i], m->part[i].ngrid, s->grid + 1);
    }
  }
  m_free(s);
  return rc;
}

static const uraScaleOps ops = {"merge", m_begin, m_next, m_end, m_finish};

/* the parts in shard order, each checked alone and against the first; 0 or 2 (refused) */
static int load(merge* m, int nfile, char** file) {
  uraPartFile p;
  char err[uraERRLEN];
  for (int f = 0; f < nfile; f++) {
    if (ura_part_read(file[f], &p, err, sizeof err)) {
      ura_part_free(&p);
      return refuse("%s", err);
    }
    if (!m->part) {
      m->n = p.nshard;
      m->part = calloc((size_t)m->n, sizeof *m->part);
      m->name = calloc((size_t)m->n, sizeof *m->name);
      if (!m->part || !m->name) {
        ura_part_free(&p);
        return refuse("out of memory");
      }
    }
    const uraPartFile* q = NULL;
    const char* qname = NULL;
    for (int i = 0; i < m->n && !q; i++) {
      if (m->name[i]) q = &m->part[i], qname = m->name[i];
    }
    int rc = 0;
    if (p.nshard != m->n) {
      rc = refuse(
          "'%s' and '%s' come from runs split into different numbers of shards; "
          "accepted: the parts of one run",
          qname, file[f]);
    } else if (m->name[p.shard]) {
      rc = refuse("'%s' and '%s' are the same shard; accepted: each shard once", m->name[p.shard],
                  file[f]);
    } else if (q && (strcmp(p.script, q->script) || p.argc != q->argc)) {
      rc = refuse(
          "'%s' and '%s' come from different scripts or command lines; accepted: the "
          "parts of one run",
          qname, file[f]);
    } else if (q && strcmp(p.model, q->model)) {
      rc = refuse(
          "'%s' and '%s' come from different uasimpact builds (built-in models); accepted: "
          "the parts of one run",
          qname, file[f]);
    }
    for (int a = 0; q && !rc && a < p.argc; a++) {
      if (strcmp(p.argv[a], q->argv[a])) {
        rc = refuse(
            "'%s' and '%s' come from different command lines; accepted: the parts of one "
            "run",
            qname, file[f]);
      }
    }
    if (rc) {
      ura_part_free(&p);
      return rc;
    }
    m->part[p.shard] = p;
    m->name[p.shard] = file[f];
  }
  char missing[400] = "";
  int nmiss = 0;
  for (int i = 0; i < m->n; i++) {
    if (m->name[i]) continue;
    size_t len = strlen(missing);
    if (nmiss < 20)
      snprintf(missing + len, sizeof missing - len, "%s%d", nmiss ? ", " : "", i);
    else if (nmiss == 20)
      snprintf(missing + len, sizeof missing - len, ", ...");
    nmiss++;
  }
  if (nmiss) {
    return refuse("missing shards %s of %d (numbered from 0); accepted: one part of every shard",
                  missing, m->n);
  }
  return 0;
}

/* the command line given (argc words: scripts and -c COMMANDS) against the one the parts record,
   word for word, then the script files and the built-in models as they are now; 0 or 2 */
static int check_run(merge* m, int argc, char** argv) {
  const uraPartFile* p0 = &m->part[0];
  int same = p0->argc == argc;
  for (int i = 0; same && i < argc; i++) same = !strcmp(p0->argv[i], argv[i]);
  if (!same) {
    char given[400], ran[400];
    show_argv(argc, argv, 0, given, sizeof given);
    show_argv(p0->argc, p0->argv, 0, ran, sizeof ran);
    return refuse(
        "the script and options given (%s) are not the ones the shards ran (%s, recorded in "
        "'%s'); accepted: the shards' scripts and -c commands, in their order",
        given, ran, m->name[0]);
  }
  char sh[17], mh[17];
  ura_scale_script_hash(argc, argv, sh);
  ura_scale_model_hash(mh);
  if (strcmp(sh, p0->script)) {
    return refuse(
        "a script file of the command line changed since the shards ran; accepted: the script "
        "as it was (or run the shards again)");
  }
  if (strcmp(mh, p0->model)) {
    return refuse(
        "the parts were written by a uasimpact with other built-in models; accepted: parts of "
        "this build");
  }
  return 0;
}

/* the merge named without its script (the form of old, which ran what the parts said): what to
   pass, with the command line the first readable part records, shown as merge takes it */
static int no_script(int nfile, char** file) {
  char err[uraERRLEN], rec[400] = "";
  uraPartFile p;
  for (int f = 0; f < nfile && !*rec; f++) {
    if (!ura_part_read(file[f], &p, err, sizeof err)) {
      char words[360];
      show_argv(p.argc, p.argv, 1, words, sizeof words);
      snprintf(rec, sizeof rec, " (the parts record: %s)", words);
    }
    ura_part_free(&p);
  }
  return refuse(
      "no script given: a part file is data, its command line is not run; accepted: %s with "
      "the shards' scripts and -c commands, in their order%s",
      USAGE, rec);
}

int ura_merge_new(uraCtx* c, int* argc, char*** argv) {
  int ac = *argc;
  char** av = *argv;
  char** run = calloc((size_t)ac + 1, sizeof *run); /* argv[0], the scripts and -c commands */
  char** file = calloc((size_t)ac + 1, sizeof *file);
  int nrun = 1, nfile = 0, script = 0;
  if (!run || !file) {
    free(run);
    free(file);
    return refuse("out of memory");
  }
  run[0] = av[0];
  int rc = 0;
  for (int i = 2; i < ac && !rc; i++) {
    int opt_c = !strcmp(av[i], "-c");
    if (opt_c || !strcmp(av[i], "--script")) {
      if (i + 1 >= ac) {
        rc = refuse("%s needs %s as its argument; usage: %s", av[i],
                    opt_c ? "the commands" : "the script file", USAGE);
      } else if (!opt_c && av[i + 1][0] == '-' && av[i + 1][1]) {
        rc = refuse(
            "--script '%s': a name that starts with '-' reads as an option; accepted: "
            "./%s, as the shards were given it",
            av[i + 1], av[i + 1]);
      } else {
        if (opt_c) run[nrun++] = av[i];
        run[nrun++] = av[++i];
        script = 1;
      }
    } else if (av[i][0] == '-' && av[i][1]) {
      rc = refuse(
          "unknown option '%s'; usage: %s (the shards' scripts and -c commands in their "
          "order, then the part files)",
          av[i], USAGE);
    } else {
      file[nfile++] = av[i];
    }
  }
  if (!rc && !nfile) {
    rc = refuse(
        "no part files; usage: %s (the files of 'uasimpact --shard I/N --part PART', one "
        "per shard)",
        USAGE);
  }
  if (!rc && !script) rc = no_script(nfile, file);
  merge* m = rc ? NULL : calloc(1, sizeof *m);
  uraScale* s = rc ? NULL : calloc(1, sizeof *s);
  if (!rc && (!m || !s)) rc = refuse("out of memory");
  if (rc) {
    free(m);
    free(s);
    free(run);
    free(file);
    return rc;
  }
  s->ops = &ops;
  s->c = c;
  s->grid = -1;
  s->impl = m;
  m->argv = run;
  rc = load(m, nfile, file);
  if (!rc) rc = check_run(m, nrun - 1, run + 1);
  free(file); /* the names are argv's: they live as long as the run */
  if (rc) {
    m_free(s);
    return rc;
  }
  run[nrun] = NULL;
  *argc = nrun;
  *argv = run; /* the merge's own words: lives as long as the run, freed by m_free */
  m->ran = 1;
  c->scale = s;
  return 0;
}
