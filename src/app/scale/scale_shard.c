/* scale_shard.c: uasimpact --shard I/N --part OUT: position k of grid G is simulated when
 * (k + G) mod N == I; the other cells are placeholders (no contact) so that the script runs on,
 * its results, notes and files muted. The cells computed go to the part file (scale_part.c),
 * written whole at the end of the run (with the run's status; none when Ctrl-C stopped it).
 * OUT may replace only a part file or an empty file: not a file the run reads (same device and
 * inode as a script, a sourced file, a model or a grid it loaded), not a directory, not any other
 * file; checked before the run (the scripts of the command line) and again before writing. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scale.h"

typedef struct {
  int i, n;
  char path[1024];
  char* text; /* the part so far (a memory stream) */
  size_t len;
  FILE* f;
  long first, taken; /* this grid: the first own position; how many handed out */
  long ntodo;
  struct {
    dev_t dev;
    ino_t ino;
    char* path;
  } * input; /* the files the run read */
  int ninput, cap;
} shard;

/* keep a file the run reads (once) */
static void s_input(uraScale* s, const char* path, const struct stat* st) {
  shard* d = s->impl;
  for (int k = 0; k < d->ninput; k++) {
    if (d->input[k].dev == st->st_dev && d->input[k].ino == st->st_ino) return;
  }
  if (d->ninput == d->cap) {
    int cap = d->cap ? 2 * d->cap : 16;
    void* t = realloc(d->input, (size_t)cap * sizeof *d->input);
    if (!t) return; /* checked again against the command line's scripts at least */
    d->input = t;
    d->cap = cap;
  }
  char* name = strdup(path);
  if (!name) return;
  d->input[d->ninput].dev = st->st_dev;
  d->input[d->ninput].ino = st->st_ino;
  d->input[d->ninput++].path = name;
}

/* what the part may replace: nothing yet, an empty file, a part file or a device, not an input of
   the run; 0, or -1 with why in c->err */
static int target_ok(uraCtx* c, shard* d) {
  struct stat st;
  if (stat(d->path, &st)) return 0; /* none (or the write says why) */
  for (int k = 0; k < d->ninput; k++) {
    if (d->input[k].dev == st.st_dev && d->input[k].ino == st.st_ino) {
      return ura_fail(c,
                      "--part '%s' is a file the run reads ('%s'): the part would replace it; "
                      "accepted: a new file or a part file",
                      d->path, d->input[k].path);
    }
  }
  if (S_ISDIR(st.st_mode)) {
    return ura_fail(c, "--part '%s' is a directory; accepted: a new file or a part file", d->path);
  }
  if (!S_ISREG(st.st_mode) || st.st_size == 0) return 0;
  char head[sizeof uraPART_MAGIC + 1] = "";
  FILE* f = fopen(d->path, "rb");
  size_t n = f ? fread(head, 1, sizeof uraPART_MAGIC, f) : 0;
  if (f) fclose(f);
  if (n < sizeof uraPART_MAGIC || memcmp(head, uraPART_MAGIC " ", sizeof uraPART_MAGIC)) {
    return ura_fail(c,
                    "--part '%s' exists and is not a part file: it would be replaced; accepted: "
                    "a new file, an empty file or a part file",
                    d->path);
  }
  return 0;
}

static void s_free(uraScale* s) {
  shard* d = s->impl;
  for (int k = 0; k < d->ninput; k++) free(d->input[k].path);
  free(d->input);
  free(d->text);
  free(d);
  free(s);
}

static int s_begin(uraScale* s, long ntodo) {
  shard* d = s->impl;
  d->ntodo = ntodo;
  d->first = ((d->i - s->grid) % d->n + d->n) % d->n;
  d->taken = 0;
  return 0;
}

static long s_next(uraScale* s) {
  shard* d = s->impl;
  long k = __atomic_fetch_add(&d->taken, 1, __ATOMIC_RELAXED);
  long pos = d->first + k * d->n;
  return pos < d->ntodo ? pos : -1;
}

static int s_end(uraScale* s, urGrid* g, const long* todo, long ntodo) {
  shard* d = s->impl;
  long mine = d->first < ntodo ? (ntodo - d->first + d->n - 1) / d->n : 0;
  fprintf(d->f, "grid %ld %s %ld %ld\n", s->grid, s->key, ntodo, mine);
  char line[512];
  for (long k = 0; k < ntodo; k++) {
    urCell* c = &g->cell[todo[k]];
    if ((k + s->grid) % d->n == d->i) {
      int w = ura_cell_write(c, line, sizeof line);
      if (w == -2) {
        return ura_fail(s->c,
                        "grid: cell %ld holds a value outside its domain (p or a PoF not in [0, "
                        "1], or an infinite criterion): a part cannot carry it",
                        k);
      } else if (w < 0) {
        return ura_fail(s->c, "grid: a cell's result does not fit a part line");
      }
      fprintf(d->f, "c %ld %s\n", k, line);
    } else {
      double dpar = c->dpar, dperp = c->dperp;
      memset(c, 0, sizeof *c);
      c->dpar = dpar;
      c->dperp = dperp;
      c->status = urCELL_DONE; /* a placeholder: the merge brings the real result */
    }
  }
  return 0;
}

static int s_finish(uraScale* s, int rc) {
  shard* d = s->impl;
  uraCtx* c = s->c;
  int status = rc;
  if (rc != 130) {
    fprintf(d->f, "end %d %ld\n", rc, s->grid + 1);
    fflush(d->f);
    fprintf(d->f, "sum %016llx\n", ura_fnv(uraFNV0, d->text, d->len));
  }
  fclose(d->f);
  if (rc != 130 && target_ok(c, d)) {
    fprintf(stderr, "uasimpact: %s\n", c->err);
    if (!status) status = 2;
  } else if (rc != 130) {
    uraAtomic a;
    int mute = c->mute;
    c->mute = 0;
    int bad = ura_atomic_open(c, &a, d->path, "--part");
    c->mute = mute;
    if (!bad) {
      fwrite(d->text, 1, d->len, a.f);
      bad = ura_atomic_close(c, &a, 1, "--part");
    }
    if (bad) {
      fprintf(stderr, "uasimpact: %s\n", c->err);
      if (!status) status = 1;
    }
  }
  s_free(s);
  return status;
}

static const uraScaleOps ops = {"shard", s_begin, s_next, s_end, s_finish, s_input};

uraScale* ura_shard_new(uraCtx* c, int i, int n, const char* path, int argc, char** argv) {
  uraScale* s = calloc(1, sizeof *s);
  shard* d = calloc(1, sizeof *d);
  if (!s || !d || strlen(path) >= sizeof d->path || !*path) {
    free(s);
    free(d);
    ura_fail(c, "cannot write a part named '%.200s'; accepted: a file name of 1 to %d bytes", path,
             (int)sizeof d->path - 1);
    return NULL;
  }
  d->i = i;
  d->n = n;
  snprintf(d->path, sizeof d->path, "%s", path);
  d->f = open_memstream(&d->text, &d->len);
  if (!d->f) {
    free(s);
    free(d);
    ura_fail(c, "out of memory");
    return NULL;
  }
  ura_part_header(d->f, i, n, argc, argv);
  s->ops = &ops;
  s->c = c;
  s->grid = -1;
  s->impl = d;

  /* the scripts of the command line are inputs from the start: refused before the run */
  for (int k = 0; k < argc; k++) {
    struct stat st;
    if (!strcmp(argv[k], "-c"))
      k++;
    else if (!stat(argv[k], &st))
      s_input(s, argv[k], &st);
  }
  if (target_ok(c, d) ||
      (ura_scale_mute(c) && ura_fail(c, "cannot open /dev/null: %s", strerror(errno)))) {
    fclose(d->f);
    s_free(s);
    return NULL;
  }
  return s;
}
