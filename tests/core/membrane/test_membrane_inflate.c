/* test_membrane_inflate.c: the inflation (membrane_inflate.c) on threads. The inflated state (x0,
 * vref, pref, mref, strain0, the steps and residual, the bounding sphere) is the same to the bit
 * with one thread, a team of 2 or 3 held throughout, a team that hands over to thread 0 alone and
 * back every step or every few steps (its parking and waking), more threads than chunks of
 * triangles, ur_mem_inflate_threads and the cache's threads; and one thread's state is the one the
 * serial code before the threads gave (FNV-1a checksums measured on d1fb824, the base of branch
 * inflspeed). Two bags: one at the ambient pressure (shaped at 1 % of it: the slow phase 1 of case
 * A's bag) and one at 1.1 atm. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/core/membrane/membrane_internal.h"

/* the serial code's checksums of bag(4, ambient) (8638 steps) and bag(4, 1.1 atm) (963 steps) */
#define GOLD_AMBIENT 0x8a49562617d21637ULL
#define GOLD_11ATM   0xd56f08f4ad7c1305ULL

/* FIRE against kinetic damping at mesh 6 (test_fire): bounds, about twice the largest measured */
#define FIRE_DMAX 6e-4
#define FIRE_DV   1e-4
#define FIRE_DP   0.02
#define FIRE_DS   0.03

/* a bag of the default fabric at mesh n and absolute pressure p0 */
static urMemSpec bag(int n, double p0) {
  urMemSpec s;
  ur_mem_spec_default(&s);
  s.a = 0.3;
  s.b = 0.22;
  s.depth = 0.2;
  s.mesh = n;
  s.patm = 101325;
  s.p0 = p0;
  return s;
}

static uint64_t fnv(uint64_t h, const void* p, size_t n) {
  const unsigned char* c = p;
  for (size_t i = 0; i < n; i++) {
    h ^= c[i];
    h *= 1099511628211ULL;
  }
  return h;
}

/* the checksum of everything the inflation sets */
static uint64_t state_sum(const urMembrane* mb) {
  uint64_t h = 1469598103934665603ULL;
  const double d[] = {mb->vref,   mb->pref,      mb->mref,      mb->strain0,  mb->inflate_res,
                      mb->rbound, mb->cbound[0], mb->cbound[1], mb->cbound[2]};
  h = fnv(h, mb->x0, 3 * (size_t)mb->nn * sizeof(double));
  h = fnv(h, d, sizeof d);
  return fnv(h, &mb->inflate_steps, sizeof mb->inflate_steps);
}

/* a bag built and inflated by nthr threads (alt as urm_mem_inflate_team's); its checksum */
static uint64_t team(const urMemSpec* s, int nthr, int alt, int* steps) {
  char err[200];
  urMembrane* mb = ur_mem_build(s, err, sizeof err);
  assert_non_null(mb);
  int rc = nthr == 0 ? ur_mem_inflate(mb, err, sizeof err)
                     : urm_mem_inflate_team(mb, nthr, alt, err, sizeof err);
  assert_int_equal(rc, 0);
  uint64_t h = state_sum(mb);
  if (steps) {
    *steps = mb->inflate_steps;
  }
  ur_mem_free(mb);
  return h;
}

/* one thread: the serial code's bits (checksums measured before the threads) */
static void test_serial_golden(void** state) {
  urMemSpec a = bag(4, 101325), b = bag(4, 1.1 * 101325);
  int na, nb;
  uint64_t ha = team(&a, 0, 0, &na), hb = team(&b, 0, 0, &nb);
  print_message("ambient: %d steps, %016llx; 1.1 atm: %d steps, %016llx\n", na,
                (unsigned long long)ha, nb, (unsigned long long)hb);
  assert_true(ha == GOLD_AMBIENT);
  assert_true(hb == GOLD_11ATM);
}

/* teams held throughout and handing over, on both bags */
static void test_team_bitwise(void** state) {
  static const int way[][2] = {{2, -1}, {3, -1}, {2, 1}, {2, 7}, {3, 5}, {2, 0}};
  for (int k = 0; k < 2; k++) {
    urMemSpec s = bag(k ? 6 : 4, k ? 1.1 * 101325 : 101325);
    uint64_t h1 = team(&s, 1, 0, NULL);
    for (size_t j = 0; j < sizeof way / sizeof way[0]; j++) {
      uint64_t h = team(&s, way[j][0], way[j][1], NULL);
      print_message("mesh %d, %d threads, alt %d: %016llx (one thread %016llx)\n", s.mesh,
                    way[j][0], way[j][1], (unsigned long long)h, (unsigned long long)h1);
      assert_true(h == h1);
    }
  }
}

/* more threads than chunks of triangles (mesh 2: one chunk), the public call and the cache */
static void test_threads_capped(void** state) {
  urMemSpec s = bag(2, 1.1 * 101325);
  uint64_t h1 = team(&s, 1, 0, NULL);
  assert_true(team(&s, 8, -1, NULL) == h1);
  char err[200];
  urMembrane* mb = ur_mem_build(&s, err, sizeof err);
  assert_non_null(mb);
  assert_int_equal(ur_mem_inflate_threads(mb, 64, err, sizeof err), 0);
  assert_true(state_sum(mb) == h1);
  ur_mem_free(mb);
  urMemCache* c = ur_memcache_new();
  assert_non_null(c);
  ur_memcache_set_threads(c, 4);
  mb = ur_mem_build_inflated(c, &s, err, sizeof err);
  assert_non_null(mb);
  assert_true(state_sum(mb) == h1);
  ur_mem_free(mb);
  ur_memcache_free(c);
}

/* FIRE (inflate=1): converged by the same test in a fraction of the steps, to nearly the same
   bag (the largest node distance and the volume, pressure and strain differences measured at
   mesh 6 and given a margin); the same bits on a team; inflate beyond 0, 1 refused */
static void test_fire(void** state) {
  for (int k = 0; k < 2; k++) {
    urMemSpec s = bag(6, k ? 1.1 * 101325 : 101325);
    char err[200];
    urMembrane* a = ur_mem_build(&s, err, sizeof err);
    assert_non_null(a);
    assert_int_equal(ur_mem_inflate(a, err, sizeof err), 0);
    s.inflate = urMEM_FIRE;
    urMembrane* b = ur_mem_build(&s, err, sizeof err);
    assert_non_null(b);
    assert_int_equal(ur_mem_inflate(b, err, sizeof err), 0);
    double dmax = 0;
    for (int i = 0; i < a->nn; i++) {
      double d[3];
      urm_sub(d, a->x0 + 3 * i, b->x0 + 3 * i);
      dmax = fmax(dmax, sqrt(urm_dot(d, d)));
    }
    double dv = fabs(b->vref / a->vref - 1), dp = fabs(b->pref - a->pref) / (a->pref - s.patm);
    double ds = fabs(b->strain0 / a->strain0 - 1);
    print_message(
        "p0 %.0f: relax %d steps, FIRE %d (residual %.3g); node distance %.3g m, "
        "volume %.3g, gauge pressure %.3g, strain %.3g\n",
        s.p0, a->inflate_steps, b->inflate_steps, b->inflate_res, dmax, dv, dp, ds);
    assert_true(b->inflate_res < 1e-3);
    assert_true(b->inflate_steps < a->inflate_steps / 3);
    assert_true(dmax < FIRE_DMAX);
    assert_true(dv < FIRE_DV);
    assert_true(dp < FIRE_DP);
    assert_true(ds < FIRE_DS);
    uint64_t h = state_sum(b);
    assert_true(team(&s, 2, 1, NULL) == h);
    assert_true(team(&s, 3, -1, NULL) == h);
    ur_mem_free(a);
    ur_mem_free(b);
  }
  urMemSpec s = bag(2, 101325);
  char err[200];
  s.inflate = 2;
  assert_int_equal(ur_mem_spec_check(&s, err, sizeof err), -1);
  assert_non_null(strstr(err, "inflate"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_serial_golden),
      cmocka_unit_test(test_team_bitwise),
      cmocka_unit_test(test_threads_capped),
      cmocka_unit_test(test_fire),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
