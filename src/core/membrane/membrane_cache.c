/* membrane_cache.c: the inflated-bag cache. Inflating a bag (ur_mem_inflate) takes most of the time
 * a model with a membrane airbag needs before it runs (ur_model_inflate, after the compile), and a
 * workbench recompiles its model at every 'set' of a parameter (and a calibration at every
 * evaluation), mostly with a bag whose declaration did not change. The cache keeps built and
 * inflated bags by their whole spec (urMemSpec: everything ur_mem_build and ur_mem_inflate read),
 * compared field by field, doubles by their bits; a hit is a deep copy (ur_mem_clone) of the bag
 * the spec gave before, so the compiled model is the same to the bit. At most a number of bags and
 * of nodes are kept, the least recently used evicted first; failed inflations are not kept.
 *
 * Owned by its caller (one per session), no globals; a mutex guards the table, so threads may
 * compile through one cache (each inflation runs outside the lock). */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_internal.h"

#define CAP      24     /* bags kept */
#define MAXNODES 100000 /* nodes kept over all bags */

typedef struct {
  urMembrane* mb;     /* built and inflated, owned: clones of it are handed out */
  unsigned long used; /* the tick of its last use */
} Entry;

struct urMemCache {
  pthread_mutex_t lock;
  int cap, n;
  long maxnodes, nodes;
  unsigned long tick;
  long hits, misses;
  int threads; /* the inflations' */
  Entry* e;    /* cap */
};

//---------------------------------- the key -------------------------------------------------------

/* a field added to urMemSpec must be compared in urm_mem_spec_same (LP64 size) */
_Static_assert(sizeof(void*) != 8 || sizeof(urMemSpec) == 312,
               "urMemSpec changed: update urm_mem_spec_same");

static int dsame(const double* a, const double* b, int n) {
  for (int i = 0; i < n; i++) {
    uint64_t x, y;
    memcpy(&x, a + i, sizeof x);
    memcpy(&y, b + i, sizeof y);
    if (x != y) {
      return 0;
    }
  }
  return 1;
}

#define SAME(f) dsame(&a->f, &b->f, 1)

int urm_mem_spec_same(const urMemSpec* a, const urMemSpec* b) {
  return a->plan == b->plan && a->pattern == b->pattern && a->mesh == b->mesh &&
         a->inflate == b->inflate && a->wrinkle == b->wrinkle && SAME(a) && SAME(b) &&
         SAME(depth) && SAME(top) && dsame(a->mount, b->mount, 3) && dsame(a->quat, b->quat, 4) &&
         SAME(mount_r) && SAME(e1t) && SAME(e2t) && SAME(nu12) && SAME(g0t) && SAME(gtt) &&
         SAME(lock) && SAME(re) && SAME(rhot) && SAME(damp) && SAME(p0) && SAME(patm) &&
         SAME(gamma) && SAME(temp) && SAME(vent_area) && SAME(vent_cd) && SAME(leak) &&
         SAME(kc_alpha) && SAME(kc_dt) && SAME(zeta_c) && SAME(mu) && SAME(v_eps) &&
         SAME(dt_factor) && SAME(mscale) && SAME(hstep);
}

//---------------------------------- the copy ------------------------------------------------------

/* a block of alloc elements of size sz, its first used copied from p (the rest unset, as the
   original's: ur_mem_build allocates some arrays for the most they may hold) */
static void* dup(const void* p, size_t sz, size_t alloc, size_t used) {
  void* q = malloc(sz * (alloc ? alloc : 1));
  if (q && used) {
    memcpy(q, p, sz * used);
  }
  return q;
}

urMembrane* ur_mem_clone(const urMembrane* mb) {
  urMembrane* c = malloc(sizeof *c);
  if (!c) {
    return NULL;
  }
  *c = *mb;
  size_t nn = (size_t)mb->nn, nt = (size_t)mb->nt, nb = (size_t)mb->ntb, D = sizeof(double),
         I = sizeof(int);
  c->tri = dup(mb->tri, I, 3 * nt, 3 * nt);
  c->dminv = dup(mb->dminv, D, 6 * nt, 6 * nt); /* dminv, area0, beta in one block */
  c->mass = dup(mb->mass, D, 2 * nn, 2 * nn);   /* mass, invm */
  c->fix = dup(mb->fix, I, nn, (size_t)mb->nfix);
  c->xshape = dup(mb->xshape, D, 6 * nn, 6 * nn); /* xshape, x0 */
  c->tri4 = dup(mb->tri4, I, 12 * nb, 12 * nb);
  c->tk4 = dup(mb->tk4, D, 24 * nb, 24 * nb);
  c->adj0 = dup(mb->adj0, I, nn + 1, nn + 1);
  c->adj = dup(mb->adj, I, 3 * nt, 3 * nt);
  c->tedge = dup(mb->tedge, I, 3 * nt, 3 * nt);
  c->enode = dup(mb->enode, I, 6 * nt, 2 * (size_t)mb->ne);
  c->free = dup(mb->free, I, nn, (size_t)mb->nfree);
  c->tfree = dup(mb->tfree, I, nt, (size_t)mb->ntfree);
  if (!c->tri || !c->dminv || !c->mass || !c->fix || !c->xshape || !c->tri4 || !c->tk4 ||
      !c->adj0 || !c->adj || !c->tedge || !c->enode || !c->free || !c->tfree) {
    ur_mem_free(c);
    return NULL;
  }
  c->area0 = c->dminv + 4 * nt;
  c->beta = c->area0 + nt;
  c->invm = c->mass + nn;
  c->x0 = c->xshape + 3 * nn;
  return c;
}

//---------------------------------- the cache -----------------------------------------------------

urMemCache* urm_memcache_new_sized(int cap, long maxnodes) {
  if (cap < 1 || maxnodes < 1) {
    return NULL;
  }
  urMemCache* c = calloc(1, sizeof *c);
  if (!c || !(c->e = calloc((size_t)cap, sizeof(Entry)))) {
    free(c);
    return NULL;
  }
  if (pthread_mutex_init(&c->lock, NULL)) {
    free(c->e);
    free(c);
    return NULL;
  }
  c->cap = cap;
  c->maxnodes = maxnodes;
  c->threads = 1;
  return c;
}

urMemCache* ur_memcache_new(void) {
  return urm_memcache_new_sized(CAP, MAXNODES);
}

void ur_memcache_set_threads(urMemCache* c, int threads) {
  if (c) {
    pthread_mutex_lock(&c->lock);
    c->threads = threads > 1 ? threads : 1;
    pthread_mutex_unlock(&c->lock);
  }
}

void ur_memcache_free(urMemCache* c) {
  if (!c) {
    return;
  }
  for (int i = 0; i < c->n; i++) {
    ur_mem_free(c->e[i].mb);
  }
  pthread_mutex_destroy(&c->lock);
  free(c->e);
  free(c);
}

void ur_memcache_stats(urMemCache* c, urMemCacheStats* st) {
  memset(st, 0, sizeof *st);
  if (!c) {
    return;
  }
  pthread_mutex_lock(&c->lock);
  st->hits = c->hits;
  st->misses = c->misses;
  st->entries = c->n;
  st->nodes = c->nodes;
  pthread_mutex_unlock(&c->lock);
}

/* drop entry i (the last one takes its place) */
static void evict(urMemCache* c, int i) {
  c->nodes -= c->e[i].mb->nn;
  ur_mem_free(c->e[i].mb);
  c->e[i] = c->e[--c->n];
}

/* keep mb (owned from here on): the least recently used go until it fits; a bag beyond the node
   budget alone, or one of a spec another thread kept meanwhile, is freed */
static void keep(urMemCache* c, urMembrane* mb) {
  for (int i = 0; i < c->n; i++) {
    if (urm_mem_spec_same(&c->e[i].mb->spec, &mb->spec)) {
      ur_mem_free(mb);
      return;
    }
  }
  if (mb->nn > c->maxnodes) {
    ur_mem_free(mb);
    return;
  }
  while (c->n > 0 && (c->n >= c->cap || c->nodes + mb->nn > c->maxnodes)) {
    int old = 0;
    for (int i = 1; i < c->n; i++) {
      if (c->e[i].used < c->e[old].used) {
        old = i;
      }
    }
    evict(c, old);
  }
  c->e[c->n].mb = mb;
  c->e[c->n++].used = ++c->tick;
  c->nodes += mb->nn;
}

/* a copy of the bag kept for spec s into *hit (NULL: no memory), its use counted; 0 when none is
   kept (a miss counted) */
static int lookup(urMemCache* c, const urMemSpec* s, urMembrane** hit) {
  int found = 0;
  pthread_mutex_lock(&c->lock);
  for (int i = 0; i < c->n && !found; i++) {
    if (urm_mem_spec_same(&c->e[i].mb->spec, s)) {
      found = 1;
      c->e[i].used = ++c->tick;
      *hit = ur_mem_clone(c->e[i].mb);
      if (*hit) {
        (*hit)->stop = NULL;
      }
    }
  }
  c->hits += found;
  c->misses += !found;
  pthread_mutex_unlock(&c->lock);
  return found;
}

/* inflate the built bag mb and keep a copy when there is a cache: mb, or NULL (freed) */
static urMembrane* inflate_keep(urMemCache* c, urMembrane* mb, char* err, size_t n) {
  int threads = 1;
  if (c) {
    pthread_mutex_lock(&c->lock);
    threads = c->threads;
    pthread_mutex_unlock(&c->lock);
  }
  int bad = ur_mem_inflate_threads(mb, threads, err, n);
  mb->stop = NULL;
  if (bad) {
    ur_mem_free(mb);
    return NULL;
  }
  if (c) {
    urMembrane* copy = ur_mem_clone(mb); /* no memory for it: not kept, no harm */
    if (copy) {
      pthread_mutex_lock(&c->lock);
      keep(c, copy);
      pthread_mutex_unlock(&c->lock);
    }
  }
  return mb;
}

urMembrane* ur_mem_build_inflated(urMemCache* c, const urMemSpec* s, char* err, size_t n) {
  urMembrane* hit = NULL;
  if (c && lookup(c, s, &hit)) {
    if (!hit) {
      snprintf(err, n, "out of memory");
    }
    return hit;
  }
  urMembrane* mb = ur_mem_build(s, err, n);
  return mb ? inflate_keep(c, mb, err, n) : NULL;
}

urMembrane* ur_mem_cache_inflate(urMemCache* c, urMembrane* mb, char* err, size_t n) {
  urMembrane* hit = NULL;
  if (c && lookup(c, &mb->spec, &hit)) {
    ur_mem_free(mb);
    if (!hit) {
      snprintf(err, n, "out of memory");
    }
    return hit;
  }
  return inflate_keep(c, mb, err, n);
}

int ur_memcache_has(urMemCache* c, const urMemSpec* s) {
  int found = 0;
  if (c) {
    pthread_mutex_lock(&c->lock);
    for (int i = 0; i < c->n && !found; i++) {
      found = urm_mem_spec_same(&c->e[i].mb->spec, s);
    }
    pthread_mutex_unlock(&c->lock);
  }
  return found;
}
