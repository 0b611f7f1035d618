/* test_engine_membrane.c: the membrane airbags' compile and inflation in the engine
 * (engine_membrane.c: urm_model_compile, ur_model_inflate; the steps of a bag are
 * tests/core/membrane/test_membrane_engine.c's). The built-in model in case A with the membrane
 * bag: a parse builds the bags' meshes and inflates nothing (the cache's stats count no look-up);
 * every run refuses the model until it is inflated (a step, the set-up, the balancing), naming the
 * bag; ur_model_inflate inflates each bag once (one miss each, a second call changes nothing) to
 * the bits of the plain build and inflation; a stop request leaves the model whole and uninflated,
 * and the next call inflates it to the same bits. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/app/ui/ui.h"
#include "../../test_parts.h"

/* case A's built-in parts with the membrane bag, parsed through mc */
static urModel* parse(uraCtx* c, urMemCache* mc) {
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  assert_int_equal(ura_run_line(c, "case A"), 0);
  assert_int_equal(ura_run_line(c, "set bag_membrane 1"), 0);
  return parse_parts(c, mc);
}

static void done(uraCtx* c, urModel* m, urMemCache* mc) {
  ur_model_free(m);
  ur_memcache_free(mc);
  ura_last_free(c);
  ura_models_free(c);
  fclose(c->out);
}

static int membranes(const urModel* m) {
  int n = 0;
  for (int i = 0; i < m->nbag; i++) n += m->bag[i].type == urBAG_MEMBRANE;
  return n;
}

static urMemCacheStats stats(urMemCache* mc) {
  urMemCacheStats st;
  ur_memcache_stats(mc, &st);
  return st;
}

/* a compile builds and counts the bags, inflates none; every run refuses, naming the bag */
static void test_compile_refused(void** state) {
  (void)state;
  static uraCtx ctx;
  urMemCache* mc = ur_memcache_new();
  urModel* m = parse(&ctx, mc);
  int nm = membranes(m);
  assert_true(nm > 0);
  assert_int_equal(m->nraw, nm);
  urMemCacheStats st = stats(mc);
  assert_true(st.hits == 0 && st.misses == 0 && st.entries == 0);
  for (int i = 0; i < m->nbag; i++) {
    if (m->bag[i].type != urBAG_MEMBRANE) continue;
    assert_int_equal(m->bag[i].inflated, 0);
    assert_non_null(m->bag[i].mem);
    assert_int_equal(m->bag[i].mem->inflate_steps, 0); /* built only */
  }

  urData* d = ur_data_new(m);
  assert_non_null(d);
  assert_int_equal(ur_step(m, d), urSTAT_BADARG);
  print_message("step: %s\n", d->msg);
  assert_non_null(strstr(d->msg, "airbag 'bag_bottom' is not inflated"));
  ur_data_free(d);

  urImpactSetup s;
  assert_int_equal(ur_impact_setup(&s, m, 1.0), -1);
  assert_non_null(strstr(s.err, "is not inflated"));
  ur_impact_free(&s);
  assert_int_equal(ur_impact_prepare(&s, m, 1.0, 2, NULL, 0), -2);
  assert_non_null(strstr(s.err, "is not inflated"));
  ur_impact_free(&s);
  double res;
  assert_int_equal(ur_impact_balance(m, 1.0, 2, &res), -1);
  /* the load-time check (roles, pairs, options) does not need the inflated bag */
  char err[300];
  assert_int_equal(ur_impact_check(m, err, sizeof err), 0);
  done(&ctx, m, mc);
}

/* inflated once, to the plain build and inflation's bits; then it runs */
static void test_inflate_once(void** state) {
  (void)state;
  static uraCtx ctx;
  urMemCache* mc = ur_memcache_new();
  urModel* m = parse(&ctx, mc);
  int nm = membranes(m), ib = ur_name_airbag(m, "bag_bottom");
  assert_true(ib >= 0);
  double size0[3];
  memcpy(size0, m->geom[m->bag[ib].geom].size, sizeof size0);
  char err[300];
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0);
  assert_int_equal(m->nraw, 0);
  urMemCacheStats st = stats(mc);
  assert_true(st.misses == nm && st.hits == 0 && st.entries == nm);
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0); /* idempotent: nothing looked up */
  urMemCacheStats st2 = stats(mc);
  assert_true(st2.misses == nm && st2.hits == 0);

  const urMembrane* mb = m->bag[ib].mem;
  urMembrane* p = ur_mem_build(&m->bag[ib].mspec, err, sizeof err);
  assert_non_null(p);
  assert_int_equal(ur_mem_inflate(p, err, sizeof err), 0);
  assert_int_equal(mb->nn, p->nn);
  assert_memory_equal(mb->x0, p->x0, 3 * (size_t)p->nn * sizeof(double));
  assert_memory_equal(&mb->pref, &p->pref, sizeof p->pref);
  assert_memory_equal(&mb->vref, &p->vref, sizeof p->vref);
  assert_int_equal(mb->inflate_steps, p->inflate_steps);
  ur_mem_free(p);
  /* the bag's ellipsoid is now the inflated bag's bound, not the declared one */
  assert_memory_not_equal(size0, m->geom[m->bag[ib].geom].size, sizeof size0);

  urImpactSetup s;
  assert_int_equal(ur_impact_setup(&s, m, 1.0), 0);
  ur_impact_free(&s);
  done(&ctx, m, mc);
}

/* a stop request: -1 saying so, the model whole and uninflated, nothing kept; then the same bits */
static void test_inflate_stopped(void** state) {
  (void)state;
  static uraCtx ctx;
  static _Atomic int stop = 1;
  urMemCache* mc = ur_memcache_new();
  urModel* m = parse(&ctx, mc);
  int nm = membranes(m), ib = ur_name_airbag(m, "bag_bottom");
  m->opt.stop = &stop;
  char err[300];
  assert_int_equal(ur_model_inflate(m, err, sizeof err), -1);
  print_message("stopped: %s\n", err);
  assert_non_null(strstr(err, "airbag 'bag_bottom': stopped on request (interrupted)"));
  assert_int_equal(m->nraw, nm);
  assert_int_equal(m->bag[ib].inflated, 0);
  assert_non_null(m->bag[ib].mem);
  assert_int_equal(stats(mc).entries, 0);
  urData* d = ur_data_new(m);
  assert_int_equal(ur_step(m, d), urSTAT_STOPPED);
  ur_data_free(d);

  stop = 0;
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0);
  assert_int_equal(m->nraw, 0);
  urMembrane* p = ur_mem_build(&m->bag[ib].mspec, err, sizeof err);
  assert_int_equal(ur_mem_inflate(p, err, sizeof err), 0);
  assert_memory_equal(m->bag[ib].mem->x0, p->x0, 3 * (size_t)p->nn * sizeof(double));
  ur_mem_free(p);
  m->opt.stop = NULL;
  done(&ctx, m, mc);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_compile_refused),
      cmocka_unit_test(test_inflate_once),
      cmocka_unit_test(test_inflate_stopped),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
