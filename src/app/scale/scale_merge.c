/* scale_merge.c: uasimpact merge PART...: the parts of every shard checked against each other and
 * against the script and the built-in models as they are now, then the parts' command line
 * replayed with every simulated cell taken from the part of its shard (nothing is simulated):
 * the output is the unsharded run's. Whatever does not fit is refused with one line, status 2. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scale.h"

typedef struct {
  int n;
  uraPartFile* part; /* n, by shard */
  char** name;       /* their file names */
  char** argv;       /* the replayed command line, freed with the rest */
} merge;

static int refuse(const char* fmt, const char* a, const char* b) {
  fprintf(stderr, "uasimpact merge: ");
  fprintf(stderr, fmt, a, b);
  fputc('\n', stderr);
  return 2;
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

static int m_finish(uraScale* s, int rc) {
  merge* m = s->impl;
  for (int i = 0; i < m->n; i++) ura_part_free(&m->part[i]);
  free(m->part);
  free(m->name);
  free(m->argv);
  free(m);
  free(s);
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
      return refuse("%s%s", err, "");
    }
    if (!m->part) {
      m->n = p.nshard;
      m->part = calloc((size_t)m->n, sizeof *m->part);
      m->name = calloc((size_t)m->n, sizeof *m->name);
      if (!m->part || !m->name) return refuse("out of memory%s%s", "", "");
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
    char n[32];
    snprintf(n, sizeof n, "%d", m->n);
    return refuse("missing shards %s of %s (numbered from 0); accepted: one part of every shard",
                  missing, n);
  }
  const uraPartFile* p0 = &m->part[0];
  char sh[17], mh[17];
  ura_scale_script_hash(p0->argc, p0->argv, sh);
  ura_scale_model_hash(mh);
  if (strcmp(sh, p0->script)) {
    return refuse(
        "a script file of the parts' command line changed since the shards ran%s%s; "
        "accepted: the script as it was (or run the shards again)",
        "", "");
  }
  if (strcmp(mh, p0->model)) {
    return refuse(
        "the parts were written by a uasimpact with other built-in models%s%s; "
        "accepted: parts of this build",
        "", "");
  }
  return 0;
}

int ura_merge_new(uraCtx* c, int nfile, char** file, int* argc, char*** argv) {
  merge* m = calloc(1, sizeof *m);
  uraScale* s = calloc(1, sizeof *s);
  if (!m || !s) return refuse("out of memory%s%s", "", "");
  s->ops = &ops;
  s->c = c;
  s->grid = -1;
  s->impl = m;
  int rc = load(m, nfile, file);
  if (rc) {
    m_finish(s, 0);
    return rc;
  }
  const uraPartFile* p0 = &m->part[0];
  char** av = calloc((size_t)p0->argc + 2, sizeof *av);
  if (!av) {
    m_finish(s, 0);
    return refuse("out of memory%s%s", "", "");
  }
  av[0] = (*argv)[0];
  for (int i = 0; i < p0->argc; i++) av[i + 1] = p0->argv[i];
  *argc = p0->argc + 1;
  *argv = av; /* lives as long as the run: freed by m_finish */
  m->argv = av;
  c->scale = s;
  return 0;
}
