/* test_membrane_cache.c: the inflated-bag cache (membrane_cache.c). A hit is the plain build and
 * inflation to the bit in every field and array of urMembrane; any one field of the spec changed
 * (by one ulp, or a sign of zero) misses; the copies handed out are independent of each other and
 * of the cache's own; the least recently used bag goes first when the count or the node budget is
 * full, and a bag beyond the budget alone is not kept; a failed inflation is not kept; the
 * built-in model in case A with the membrane bag, compiled and inflated through the cache (a
 * hit), runs an impact to the same bits as the model compiled without it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/ui/ui.h"
#include "../../../src/core/membrane/membrane_internal.h"
#include "../../test_parts.h"

/* a small bag (mesh 2: 26 nodes, quick to inflate); p0 sets it apart from its siblings */
static urMemSpec small(double p0) {
  urMemSpec s;
  ur_mem_spec_default(&s);
  s.a = s.b = 0.15;
  s.depth = 0.1;
  s.mesh = 2;
  s.patm = 101325;
  s.p0 = p0;
  return s;
}

static urMembrane* plain(const urMemSpec* s) {
  char err[200];
  urMembrane* mb = ur_mem_build(s, err, sizeof err);
  assert_non_null(mb);
  assert_int_equal(ur_mem_inflate(mb, err, sizeof err), 0);
  return mb;
}

static int bits(const void* a, const void* b, size_t n) {
  return memcmp(a, b, n) == 0;
}

/* every field of two bags the same, arrays element by element (doubles by their bits) */
static void same_bag(const urMembrane* a, const urMembrane* b) {
  size_t nn = (size_t)a->nn, nt = (size_t)a->nt, nb = (size_t)a->ntb, D = sizeof(double),
         I = sizeof(int);
  assert_true(urm_mem_spec_same(&a->spec, &b->spec));
  assert_int_equal(a->nn, b->nn);
  assert_int_equal(a->nt, b->nt);
  assert_int_equal(a->ntop, b->ntop);
  assert_int_equal(a->nfix, b->nfix);
  assert_int_equal(a->ntb, b->ntb);
  assert_int_equal(a->ne, b->ne);
  assert_int_equal(a->nfree, b->nfree);
  assert_int_equal(a->ntfree, b->ntfree);
  assert_int_equal(a->inflate_steps, b->inflate_steps);
  const double sa[] = {a->pref,   a->vref,      a->mref,       a->dt_stable,
                       a->lmin,   a->cbound[0], a->cbound[1],  a->cbound[2],
                       a->rbound, a->strain0,   a->inflate_res};
  const double sb[] = {b->pref,   b->vref,      b->mref,       b->dt_stable,
                       b->lmin,   b->cbound[0], b->cbound[1],  b->cbound[2],
                       b->rbound, b->strain0,   b->inflate_res};
  assert_true(bits(sa, sb, sizeof sa));
  assert_true(bits(a->tri, b->tri, 3 * nt * I));
  assert_true(bits(a->dminv, b->dminv, 4 * nt * D));
  assert_true(bits(a->area0, b->area0, nt * D));
  assert_true(bits(a->beta, b->beta, nt * D));
  assert_true(bits(a->mass, b->mass, nn * D));
  assert_true(bits(a->invm, b->invm, nn * D));
  assert_true(bits(a->fix, b->fix, (size_t)a->nfix * I));
  assert_true(bits(a->tri4, b->tri4, 12 * nb * I));
  assert_true(bits(a->tk4, b->tk4, 24 * nb * D));
  assert_true(bits(a->adj0, b->adj0, (nn + 1) * I));
  assert_true(bits(a->adj, b->adj, 3 * nt * I));
  assert_true(bits(a->tedge, b->tedge, 3 * nt * I));
  assert_true(bits(a->enode, b->enode, 2 * (size_t)a->ne * I));
  assert_true(bits(a->free, b->free, (size_t)a->nfree * I));
  assert_true(bits(a->tfree, b->tfree, (size_t)a->ntfree * I));
  assert_true(bits(a->xshape, b->xshape, 3 * nn * D));
  assert_true(bits(a->x0, b->x0, 3 * nn * D));
  /* the inner pointers into one block follow the copy */
  assert_true(b->area0 == b->dminv + 4 * nt && b->beta == b->area0 + nt);
  assert_true(b->invm == b->mass + nn && b->x0 == b->xshape + 3 * nn);
}

static urMembrane* get(urMemCache* c, const urMemSpec* s) {
  char err[200];
  urMembrane* mb = ur_mem_build_inflated(c, s, err, sizeof err);
  assert_non_null(mb);
  return mb;
}

static urMemCacheStats stats(urMemCache* c) {
  urMemCacheStats st;
  ur_memcache_stats(c, &st);
  return st;
}

/* a miss builds and inflates (the plain bag's bits), a hit copies them */
static void test_hit_bitwise(void** state) {
  urMemSpec s = small(1.05 * 101325);
  urMembrane* ref = plain(&s);
  assert_true(ref->inflate_steps > 0); /* the inflation ran: x0 is not the declared shape */
  assert_false(bits(ref->x0, ref->xshape, 3 * (size_t)ref->nn * sizeof(double)));
  urMemCache* c = ur_memcache_new();
  urMembrane* miss = get(c, &s);
  urMemCacheStats st = stats(c);
  assert_true(st.hits == 0 && st.misses == 1 && st.entries == 1 && st.nodes == ref->nn);
  urMembrane* hit = get(c, &s);
  st = stats(c);
  assert_true(st.hits == 1 && st.misses == 1 && st.entries == 1 && st.nodes == ref->nn);
  same_bag(ref, miss);
  same_bag(ref, hit);
  /* no cache: build and inflate alone */
  urMembrane* none = get(NULL, &s);
  same_bag(ref, none);
  ur_mem_free(none);
  ur_mem_free(hit);
  ur_mem_free(miss);
  ur_mem_free(ref);
  ur_memcache_free(c);
}

/* the doubles of urMemSpec, every one (the LP64 size below fails when a field is added) */
#define F(f) offsetof(urMemSpec, f)
static const size_t dfield[] = {
    F(a),        F(b),         F(depth),   F(top),       F(mount[0]), F(mount[1]),
    F(mount[2]), F(quat[0]),   F(quat[1]), F(quat[2]),   F(quat[3]),  F(mount_r),
    F(e1t),      F(e2t),       F(nu12),    F(g0t),       F(gtt),      F(lock),
    F(re),       F(rhot),      F(damp),    F(p0),        F(patm),     F(gamma),
    F(temp),     F(vent_area), F(vent_cd), F(leak),      F(kc_alpha), F(kc_dt),
    F(zeta_c),   F(mu),        F(v_eps),   F(dt_factor), F(mscale),   F(hstep)};
#define NDF (sizeof dfield / sizeof dfield[0])

/* any one field changed misses (by one ulp for a double; 0 and -0 differ); the spec itself hits */
static void test_field_miss(void** state) {
  assert_true(sizeof(void*) != 8 ||
              NDF * sizeof(double) + 5 * sizeof(int) + 4 /* padding after wrinkle */ ==
                  sizeof(urMemSpec));
  urMemSpec s = small(1.05 * 101325);
  urMemCache* c = urm_memcache_new_sized(64, 10000000); /* room for every variant */
  ur_mem_free(get(c, &s));
  long miss = 1;
  for (size_t k = 0; k < NDF + 6; k++) {
    urMemSpec t = s;
    if (k < NDF) {
      double* v = (double*)((char*)&t + dfield[k]);
      *v = nextafter(*v, INFINITY);
    } else if (k == NDF) {
      t.mesh++;
    } else if (k == NDF + 1) {
      t.plan = urMEM_RECT;
    } else if (k == NDF + 2) {
      t.pattern = urMEM_FLAT;
    } else if (k == NDF + 3) {
      t.inflate = !t.inflate;
    } else if (k == NDF + 4) {
      t.wrinkle = !t.wrinkle;
    } else {
      assert_true(s.top == 0 && !signbit(s.top)); /* the default: a flat top */
      t.top = -0.0;
    }
    assert_false(urm_mem_spec_same(&s, &t));
    char err[200];
    urMembrane* mb = ur_mem_build_inflated(c, &t, err, sizeof err); /* may be refused */
    ur_mem_free(mb);
    urMemCacheStats st = stats(c);
    assert_int_equal(st.hits, 0);
    assert_int_equal(st.misses, ++miss);
  }
  /* the spec itself, and a copy of it, still hit */
  urMemSpec u = s;
  assert_true(urm_mem_spec_same(&s, &u));
  ur_mem_free(get(c, &u));
  assert_int_equal(stats(c).hits, 1);
  ur_memcache_free(c);
}

/* the copies share nothing: writing one leaves the others and the cache's own as inflated */
static void test_copies_independent(void** state) {
  urMemSpec s = small(1.1 * 101325);
  urMembrane* ref = plain(&s);
  urMemCache* c = ur_memcache_new();
  urMembrane* a = get(c, &s);
  urMembrane* b = get(c, &s);
  size_t nn = (size_t)a->nn, nt = (size_t)a->nt;
  for (size_t i = 0; i < 3 * nn; i++) {
    a->x0[i] += 1;
    a->xshape[i] = -1;
  }
  for (size_t i = 0; i < nn; i++) {
    a->mass[i] *= 2;
    a->invm[i] = 7;
    a->adj0[i] = -1;
  }
  for (size_t i = 0; i < 3 * nt; i++) {
    a->tri[i] = 0;
    a->tedge[i] = 0;
    a->adj[i] = 0;
  }
  for (size_t i = 0; i < 4 * nt; i++) a->dminv[i] = 0;
  for (size_t i = 0; i < nt; i++) a->area0[i] = a->beta[i] = 0;
  for (size_t i = 0; i < 24 * (size_t)a->ntb; i++) a->tk4[i] = 0;
  for (size_t i = 0; i < 12 * (size_t)a->ntb; i++) a->tri4[i] = -1;
  for (int i = 0; i < a->nfix; i++) a->fix[i] = -1;
  for (int i = 0; i < a->nfree; i++) a->free[i] = -1;
  for (int i = 0; i < a->ntfree; i++) a->tfree[i] = -1;
  for (int i = 0; i < 2 * a->ne; i++) a->enode[i] = -1;
  same_bag(ref, b);
  ur_mem_free(a);
  urMembrane* d = get(c, &s);
  same_bag(ref, d);
  assert_int_equal(stats(c).hits, 2);
  ur_mem_free(b);
  ur_mem_free(d);
  ur_mem_free(ref);
  ur_memcache_free(c);
}

/* two bags at most: the least recently used goes */
static void test_evict_count(void** state) {
  urMemSpec s1 = small(1.02 * 101325), s2 = small(1.04 * 101325), s3 = small(1.06 * 101325);
  assert_null(urm_memcache_new_sized(0, 1000));
  urMemCache* c = urm_memcache_new_sized(2, 1000000);
  ur_mem_free(get(c, &s1));
  ur_mem_free(get(c, &s2));
  ur_mem_free(get(c, &s1)); /* s1 used last: s2 is the oldest */
  ur_mem_free(get(c, &s3));
  urMemCacheStats st = stats(c);
  assert_true(st.entries == 2 && st.hits == 1 && st.misses == 3);
  ur_mem_free(get(c, &s1)); /* kept */
  assert_int_equal(stats(c).hits, 2);
  ur_mem_free(get(c, &s3)); /* kept */
  assert_int_equal(stats(c).hits, 3);
  ur_mem_free(get(c, &s2)); /* evicted: a miss, and s1 (the oldest now) goes for it */
  st = stats(c);
  assert_true(st.entries == 2 && st.hits == 3 && st.misses == 4);
  ur_mem_free(get(c, &s1));
  assert_int_equal(stats(c).misses, 5);
  ur_memcache_free(c);
}

/* the node budget: two bags fit, a third evicts the oldest; a bag beyond the budget alone is
   built and handed out but not kept */
static void test_evict_nodes(void** state) {
  urMemSpec s1 = small(1.02 * 101325), s2 = small(1.04 * 101325), s3 = small(1.06 * 101325);
  urMembrane* one = get(NULL, &s1);
  long nn = one->nn;
  ur_mem_free(one);
  urMemCache* c = urm_memcache_new_sized(24, 2 * nn + nn / 2);
  ur_mem_free(get(c, &s1));
  ur_mem_free(get(c, &s2));
  urMemCacheStats st = stats(c);
  assert_true(st.entries == 2 && st.nodes == 2 * nn);
  ur_mem_free(get(c, &s3));
  st = stats(c);
  assert_true(st.entries == 2 && st.nodes == 2 * nn && st.misses == 3);
  ur_mem_free(get(c, &s1)); /* the oldest went */
  assert_int_equal(stats(c).misses, 4);
  ur_mem_free(get(c, &s3)); /* the newest stayed */
  assert_int_equal(stats(c).hits, 1);
  ur_memcache_free(c);

  c = urm_memcache_new_sized(24, nn - 1);
  urMembrane* mb = get(c, &s1);
  assert_int_equal(mb->nn, nn);
  ur_mem_free(mb);
  st = stats(c);
  assert_true(st.entries == 0 && st.nodes == 0);
  ur_memcache_free(c);
}

/* a bag that does not inflate (or is refused) is not kept: asked again, it misses again */
static void test_failure_not_kept(void** state) {
  urMemSpec s = small(1.05 * 101325);
  s.a = -1; /* refused by ur_mem_spec_check */
  urMemCache* c = ur_memcache_new();
  char err[200] = "";
  assert_null(ur_mem_build_inflated(c, &s, err, sizeof err));
  assert_true(err[0] != 0);
  assert_null(ur_mem_build_inflated(c, &s, err, sizeof err));
  urMemCacheStats st = stats(c);
  assert_true(st.entries == 0 && st.misses == 2 && st.hits == 0);
  ur_memcache_free(c);
}

/* case A with the membrane bag: the built-in parts with the live overrides compiled without the
   cache and through it (the second parse a hit), an impact at the centre and one off it run on
   each; results and the bags' final run states the same to the bit */
static urModel* parse(const uraCtx* c, urMemCache* mc) {
  urModel* m = parse_parts(c, mc);
  char err[300];
  assert_ptr_equal(m->opt.memcache, mc); /* kept: the inflation takes the bags through it */
  assert_true(m->nraw > 0);              /* a parse does not inflate */
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0);
  assert_int_equal(m->nraw, 0);
  return m;
}

static void test_model_bitwise(void** state) {
  static uraCtx ctx;
  uraCtx* c = &ctx;
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  assert_int_equal(ura_run_line(c, "case A"), 0);
  assert_int_equal(ura_run_line(c, "set bag_membrane 1"), 0);
  urImpactCond cond;
  assert_int_equal(ura_impact_cond(c, &cond), 0);

  urMemCache* mc = ur_memcache_new();
  urModel* m[2];
  m[0] = parse(c, NULL);
  ur_model_free(parse(c, mc)); /* a miss: kept */
  m[1] = parse(c, mc);         /* a hit */
  int nmem = 0;
  for (int b = 0; b < m[0]->nbag; b++) {
    if (m[0]->bag[b].type == urBAG_MEMBRANE) {
      nmem++;
      same_bag(m[0]->bag[b].mem, m[1]->bag[b].mem);
      assert_true(m[0]->bag[b].mem != m[1]->bag[b].mem);
    }
  }
  assert_true(nmem > 0);
  urMemCacheStats st = stats(mc);
  assert_true(st.hits == nmem && st.misses == nmem && st.entries == nmem);

  static const double off[2][2] = {{0, 0}, {0.1, -0.05}};
  urImpactResult r[2][2];
  double* mem[2][2];
  for (int k = 0; k < 2; k++) {
    urImpactSetup s = {0};
    urImpactWork w = {0};
    assert_int_equal(ur_impact_prepare(&s, m[k], 1.0, 2, NULL, 0), 0);
    assert_int_equal(ur_impact_work_init(&s, &w), 0);
    for (int j = 0; j < 2; j++) {
      assert_int_equal(ur_impact_run(&s, &w, &cond, &c->st.injury, off[j][0], off[j][1], &r[k][j]),
                       0);
      mem[k][j] = malloc((size_t)m[k]->nmemd * sizeof(double));
      memcpy(mem[k][j], w.d->mem, (size_t)m[k]->nmemd * sizeof(double));
    }
    ur_impact_work_free(&w);
    ur_impact_free(&s);
  }
  assert_true(r[0][0].contact);
  for (int j = 0; j < 2; j++) {
    const urImpactResult *a = &r[0][j], *b = &r[1][j];
    print_message("offset %g %g: P %.17g, HIC15 %.17g\n", off[j][0], off[j][1], a->p,
                  a->inj.hic15.hic);
    assert_int_equal(a->status, b->status);
    assert_int_equal(a->contact, b->contact);
    assert_true(bits(&a->p, &b->p, sizeof a->p));
    assert_true(bits(&a->t_first, &b->t_first, sizeof a->t_first));
    assert_true(bits(a->inj.val, b->inj.val, sizeof a->inj.val));
    assert_true(bits(a->inj.pof, b->inj.pof, sizeof a->inj.pof));
    assert_true(bits(mem[0][j], mem[1][j], (size_t)m[0]->nmemd * sizeof(double)));
    free(mem[0][j]);
    free(mem[1][j]);
  }
  ur_model_free(m[0]);
  ur_model_free(m[1]);
  ur_memcache_free(mc);
  ura_last_free(c);
  ura_models_free(c);
  fclose(c->out);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_hit_bitwise),        cmocka_unit_test(test_field_miss),
      cmocka_unit_test(test_copies_independent), cmocka_unit_test(test_evict_count),
      cmocka_unit_test(test_evict_nodes),        cmocka_unit_test(test_failure_not_kept),
      cmocka_unit_test(test_model_bitwise),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
