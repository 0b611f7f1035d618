/* scale_shard.c: uasimpact --shard I/N --part OUT: position k of grid G is simulated when
 * (k + G) mod N == I; the other cells are placeholders (no contact) so that the script runs on,
 * its results, notes and files muted. The cells computed go to the part file (scale_part.c),
 * written whole at the end of the run (with the run's status; none when Ctrl-C stopped it). */
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
} shard;

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
      if (ura_cell_write(c, line, sizeof line) < 0) {
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
  if (rc != 130) {
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
  free(d->text);
  free(d);
  free(s);
  return status;
}

static const uraScaleOps ops = {"shard", s_begin, s_next, s_end, s_finish};

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
  if (!d->f || ura_scale_mute(c)) {
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
  return s;
}
