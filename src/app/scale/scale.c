/* scale.c: the work of a script split over processes: the command line (--shard, --part,
 * merge), the hook that ura_grid_run calls before each grid, the end of a run. The distributors
 * themselves are in scale_shard.c, scale_merge.c and scale_mpi.c (scale.h). */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "scale.h"

void ura_scale_input(uraCtx* c, FILE* f, const char* path) {
  struct stat st;
  if (!c->scale || !c->scale->ops->input || fstat(fileno(f), &st)) return;
  c->scale->ops->input(c->scale, path, &st);
}

/* I/N: whole numbers 0 <= I < N */
static int shard_arg(const char* s, int* i, int* n) {
  const char* slash = strchr(s, '/');
  double a, b;
  char left[32];
  if (!slash || (size_t)(slash - s) >= sizeof left) return -1;
  memcpy(left, s, (size_t)(slash - s));
  left[slash - s] = 0;
  if (ura_parse_number(left, &a) || ura_parse_number(slash + 1, &b)) return -1;
  if (strchr(s, '.') || strchr(s, 'e') || strchr(s, 'E') || strchr(s, '+')) return -1;
  if (b < 1 || b > 1000000 || a < 0 || a >= b) return -1;
  *i = (int)a;
  *n = (int)b;
  return 0;
}

int ura_scale_args(uraCtx* c, int* argc, char*** argv) {
  char** av = *argv;
  int ac = *argc;
  if (ac >= 2 && !strcmp(av[1], "merge")) return ura_merge_new(c, argc, argv);
  uraScale* mpi = ura_mpi_new(c, argc, argv);
  if (mpi) {
    c->scale = mpi;
    return 0;
  }

  /* --shard I/N --part OUT, anywhere; the rest is the command line */
  int shard = -1, nshard = 0, w = 1;
  const char* part = NULL;
  for (int i = 1; i < ac; i++) {
    if (!strcmp(av[i], "-c") && i + 1 < ac) {
      av[w++] = av[i++];
      av[w++] = av[i];
    } else if (!strcmp(av[i], "--shard") || !strcmp(av[i], "--part")) {
      if (i + 1 >= ac) {
        fprintf(stderr, "uasimpact: %s needs %s as its argument\n", av[i],
                av[i][2] == 's' ? "I/N (shard I of N)" : "the part file to write");
        return 2;
      }
      if (av[i][2] == 'p') {
        part = av[++i];
      } else if (shard_arg(av[++i], &shard, &nshard)) {
        fprintf(stderr,
                "uasimpact: --shard '%s' is not a shard; accepted: I/N with whole numbers "
                "0 <= I < N <= 1000000 (e.g. --shard 0/4)\n",
                av[i]);
        return 2;
      }
    } else {
      av[w++] = av[i];
    }
  }
  av[w] = NULL;
  *argc = w;
  if (!part && shard < 0) return 0;
  if (!part || shard < 0) {
    fprintf(stderr,
            "uasimpact: --shard and --part go together; usage: uasimpact --shard I/N --part "
            "OUT FILE.ses\n");
    return 2;
  }
  for (int i = 1; i < w; i++) {
    if (!strcmp(av[i], "-i")) {
      fprintf(stderr, "uasimpact: --shard runs a script, not a session; -i is not accepted\n");
      return 2;
    }
  }
  /* -n changes nothing in a script run (only a session reads the start-up file), so the part
     does not record it: its merge takes the command line without it */
  int kept = 1;
  for (int i = 1; i < w; i++) {
    if (!strcmp(av[i], "-c") && i + 1 < w) {
      av[kept++] = av[i++];
    } else if (!strcmp(av[i], "-n")) {
      continue;
    }
    av[kept++] = av[i];
  }
  av[kept] = NULL;
  *argc = w = kept;
  if (w == 1) {
    fprintf(stderr,
            "uasimpact: --shard needs the script as FILE or -c COMMANDS; standard input is "
            "not accepted (merge could not replay it)\n");
    return 2;
  }
  c->scale = ura_shard_new(c, shard, nshard, part, w - 1, av + 1);
  if (!c->scale) {
    fprintf(stderr, "uasimpact: %s\n", c->err);
    return 2;
  }
  return 0;
}

int ura_scale_end(uraCtx* c, int rc) {
  uraScale* s = c->scale;
  if (!s) return rc;
  c->scale = NULL;
  return s->ops->finish(s, rc);
}

/* ---- the hook of ura_grid_run ---- */

static int d_begin(void* ctx, long ntodo) {
  uraScale* s = ctx;
  char n[32];
  snprintf(n, sizeof n, "%ld", ntodo);
  unsigned long long h = strtoull(s->key, NULL, 16);
  snprintf(s->key, sizeof s->key, "%016llx", ura_fnv(h, n, strlen(n)));
  return s->ops->begin(s, ntodo);
}

static long d_next(void* ctx) {
  uraScale* s = ctx;
  return s->ops->next(s);
}

static int d_end(void* ctx, urGrid* g, const long* todo, long ntodo) {
  uraScale* s = ctx;
  return s->ops->end(s, g, todo, ntodo);
}

/* the settings text that decides the cells: the session without what changes none */
static unsigned long long settings_hash(uraCtx* c) {
  static const char* const skip[] = {"set format ",  "set terminal ", "set output ",
                                     "set threads ", "set recall ",   NULL};
  unsigned long long h = uraFNV0;
  char* text = ura_session_text(c);
  if (!text) return h;
  for (char* line = text; line && *line;) {
    char* end = strchr(line, '\n');
    size_t len = end ? (size_t)(end - line + 1) : strlen(line);
    int drop = 0;
    for (int i = 0; skip[i]; i++) drop |= !strncmp(line, skip[i], strlen(skip[i]));
    if (!drop) h = ura_fnv(h, line, len);
    line += len;
  }
  free(text);
  for (int i = 0; i < c->npart; i++) {
    if (c->part[i].text) h = ura_fnv(h, c->part[i].text, strlen(c->part[i].text) + 1);
  }
  return h;
}

void ura_scale_grid(uraCtx* c, urGridSpec* spec, urGridDist* d) {
  uraScale* s = c->scale;
  char ext[200];
  snprintf(ext, sizeof ext, "%a %a %a %a %d", spec->step, spec->par_min, spec->par_max,
           spec->perp_max, spec->mirror);
  s->grid++;
  snprintf(s->key, sizeof s->key, "%016llx", ura_fnv(settings_hash(c), ext, strlen(ext)));
  d->ctx = s;
  d->begin = d_begin;
  d->next = d_next;
  d->end = d_end;
  spec->dist = d;
}
