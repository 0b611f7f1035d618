/* test_engine_membrane_cull.c: the membrane contact's culling (engine_membrane_cull.c) against
 * the scalar code it replaced, on random meshes-to-be (free nodes and triangles scattered, some
 * numbers left out as mount nodes and mount triangles are, so blocks of consecutive and of
 * scattered numbers, and a short last block): the blocks' boxes and the free nodes' box equal the
 * scalar extremes bit for bit, every group holds its blocks' boxes, and the triangles tried
 * against a target's sphere and box are exactly the scalar test's, in order. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/core/engine/engine_membrane_cull.h"

#define NN 203 /* nodes */
#define NT 401 /* triangles */

static unsigned long long seed = 12345;
static double rnd(void) { /* uniform in [0, 1): a 64-bit LCG's top 53 bits */
  seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(seed >> 11) / 9007199254740992.0;
}

typedef struct {
  urMembrane mb;
  int free[NN], tfree[NT];
  double x[3 * NN + 4]; /* the kernels read one double past a node's z */
  double tb[4 * NT];    /* centres (SoA), squared radii */
} mesh;

/* every 7th node and every 9th triangle left out (mounted), positions in a 1 m cube */
static void mesh_init(mesh* s) {
  memset(s, 0, sizeof(*s));
  s->mb.nn = NN;
  s->mb.nt = NT;
  for (int i = 0; i < NN; i++) {
    if (i % 7 != 3) {
      s->free[s->mb.nfree++] = i;
    }
  }
  for (int t = 0; t < NT; t++) {
    if (t % 9 != 5) {
      s->tfree[s->mb.ntfree++] = t;
    }
  }
  s->mb.free = s->free;
  s->mb.tfree = s->tfree;
  for (int k = 0; k < 3 * NN + 4; k++) {
    s->x[k] = rnd() - 0.5;
  }
  for (int t = 0; t < NT; t++) {
    for (int k = 0; k < 3; k++) {
      s->tb[k * NT + t] = rnd() - 0.5;
    }
    double r = 0.05 * rnd();
    s->tb[3 * NT + t] = r * r;
  }
}

static int nblk(int n) {
  return (n + urMEM_CBLK - 1) / urMEM_CBLK;
}

static void test_boxes(void** state) {
  (void)state;
  static mesh s;
  mesh_init(&s);
  double r2[NT], nbx[7 * nblk(NN)], tbx[7 * nblk(NT)], lo[3], hi[3];
  memcpy(r2, s.tb + 3 * NT, sizeof(r2));
  urmCullGroups g;
  urm_cull_boxes(&s.mb, s.x, s.tb, nbx, tbx, lo, hi, &g);
  for (int t = 0; t < NT; t++) {
    assert_true(s.tb[3 * NT + t] == sqrt(r2[t]));
  }
  // the scalar extremes, in the free nodes' order
  double L[3] = {INFINITY, INFINITY, INFINITY}, H[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int j0 = 0; j0 < s.mb.nfree; j0 += urMEM_CBLK) {
    double bb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (int j = j0; j < j0 + urMEM_CBLK && j < s.mb.nfree; j++) {
      const double* xi = s.x + 3 * s.free[j];
      for (int k = 0; k < 3; k++) {
        bb[k] = xi[k] < bb[k] ? xi[k] : bb[k];
        bb[3 + k] = xi[k] > bb[3 + k] ? xi[k] : bb[3 + k];
      }
    }
    assert_memory_equal(nbx + 7 * (j0 / urMEM_CBLK), bb, sizeof(bb));
    for (int k = 0; k < 3; k++) {
      L[k] = bb[k] < L[k] ? bb[k] : L[k];
      H[k] = bb[3 + k] > H[k] ? bb[3 + k] : H[k];
    }
  }
  assert_memory_equal(lo, L, sizeof(L));
  assert_memory_equal(hi, H, sizeof(H));
  for (int j0 = 0; j0 < s.mb.ntfree; j0 += urMEM_CBLK) {
    double bb[7] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY, 0};
    for (int j = j0; j < j0 + urMEM_CBLK && j < s.mb.ntfree; j++) {
      int t = s.tfree[j];
      double r = s.tb[3 * NT + t];
      for (int k = 0; k < 3; k++) {
        double ct = s.tb[k * NT + t];
        bb[k] = ct - r < bb[k] ? ct - r : bb[k];
        bb[3 + k] = ct + r > bb[3 + k] ? ct + r : bb[3 + k];
      }
      bb[6] = r > bb[6] ? r : bb[6];
    }
    assert_memory_equal(tbx + 7 * (j0 / urMEM_CBLK), bb, sizeof(bb));
  }
  // the groups: every block in its group's box, its radius no larger, all blocks covered
  assert_true(g.nn <= urmCULL_MAX && g.nt <= urmCULL_MAX);
  assert_int_equal(g.nn, (nblk(s.mb.nfree) + g.grp - 1) / g.grp);
  assert_int_equal(g.nt, (nblk(s.mb.ntfree) + g.grp - 1) / g.grp);
  for (int b = 0; b < nblk(s.mb.ntfree); b++) {
    const double *bx = tbx + 7 * b, *gb = g.t + 7 * (b / g.grp);
    for (int k = 0; k < 3; k++) {
      assert_true(gb[k] <= bx[k] && gb[3 + k] >= bx[3 + k]);
    }
    assert_true(gb[6] >= bx[6]);
  }
  for (int b = 0; b < nblk(s.mb.nfree); b++) {
    const double *bx = nbx + 7 * b, *gb = g.n + 7 * (b / g.grp);
    for (int k = 0; k < 3; k++) {
      assert_true(gb[k] <= bx[k] && gb[3 + k] >= bx[3 + k]);
    }
  }
}

static void test_tris(void** state) {
  (void)state;
  static mesh s;
  mesh_init(&s);
  double nbx[7 * nblk(NN)], tbx[7 * nblk(NT)], lo[3], hi[3];
  urmCullGroups g;
  urm_cull_boxes(&s.mb, s.x, s.tb, nbx, tbx, lo, hi, &g);
  const double* tb = s.tb;
  int tried = 0;
  for (int it = 0; it < 200; it++) {
    double gc[3] = {rnd() - 0.5, rnd() - 0.5, rnd() - 0.5}, rg = 0.4 * rnd();
    double gh[3] = {rg * rnd(), rg * rnd(), rg};
    double tl[NT], ref[NT];
    int n = 0, nr = 0;
    for (int j0 = 0; j0 < s.mb.ntfree; j0 += urMEM_CBLK) {
      int j1 = j0 + urMEM_CBLK < s.mb.ntfree ? j0 + urMEM_CBLK : s.mb.ntfree;
      n = urm_cull_tris(&s.mb, tb, gc, rg, gh, j0, j1, tl, n);
      for (int j = j0; j < j1; j++) { /* the scalar test it replaced */
        int t = s.tfree[j];
        double dx = tb[t] - gc[0], dy = tb[NT + t] - gc[1], dz = tb[2 * NT + t] - gc[2];
        double rr = (rg + tb[3 * NT + t]) * (1 + 1e-9);
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          double ux = fmax(fabs(dx) - gh[0], 0), uy = fmax(fabs(dy) - gh[1], 0);
          double uz = fmax(fabs(dz) - gh[2], 0), rt = tb[3 * NT + t] * (1 + 1e-6) + 1e-9;
          if (ux * ux + uy * uy + uz * uz < rt * rt) {
            ref[nr++] = t;
          }
        }
      }
    }
    assert_int_equal(n, nr);
    assert_memory_equal(tl, ref, (size_t)n * sizeof(double));
    tried += n;
  }
  assert_true(tried > 0); /* some targets reach some triangles */
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_boxes),
      cmocka_unit_test(test_tris),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
