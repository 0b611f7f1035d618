/* test_engine_util.c: the spatial-algebra kernels of engine_util.c against the plain 6 x 6
 * matrix products they stand for, on random rotations, offsets and symmetric inertias. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "../../../src/core/engine/engine_internal.h"
#pragma GCC diagnostic ignored "-Wpsabi"
#include "../../../src/core/engine/kernels/engine_xinertia_rows.h"

static double urand(unsigned* s) {
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffffff) / (double)0x1000000 * 2 - 1;
}


// X = [E 0; -E px E] as a plain 6 x 6 matrix
static void xmatrix(double X[36], const double E[9], const double p[3]) {
  double P[9] = {0, -p[2], p[1], p[2], 0, -p[0], -p[1], p[0], 0};
  memset(X, 0, 36 * sizeof(double));
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      X[6 * i + j] = E[3 * i + j];
      X[6 * (3 + i) + 3 + j] = E[3 * i + j];
      double s = 0;
      for (int k = 0; k < 3; k++) {
        s += E[3 * i + k] * P[3 * k + j];
      }
      X[6 * (3 + i) + j] = -s;
    }
  }
}


// r += X^T I X, row by row
static void reference(double r[36], const double X[36], const double I[36]) {
  double T[36];
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += I[6 * i + k] * X[6 * k + j];
      }
      T[6 * i + j] = s;
    }
  }
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += X[6 * k + i] * T[6 * k + j];
      }
      r[6 * i + j] += s;
    }
  }
}


// a random rotation matrix
static void random_rotation(unsigned* seed, double E[9]) {
  double q[4];
  for (int k = 0; k < 4; k++) {
    q[k] = urand(seed);
  }
  uru_normalizequat(q);
  uru_quat2mat(E, q);
}


// the accumulated transform equals X^T I X added to what was there, for 1000 random cases
static void test_xinertia_t_add(void** state) {
  unsigned seed = 7;
  double worst = 0;
  for (int n = 0; n < 1000; n++) {
    double E[9], p[3], I[36], r[36], ref[36];
    random_rotation(&seed, E);
    for (int k = 0; k < 3; k++) {
      p[k] = 0.5 * urand(&seed);
    }
    for (int i = 0; i < 6; i++) {
      for (int j = i; j < 6; j++) {
        I[6 * i + j] = I[6 * j + i] = urand(&seed) + (i == j) * 3;
      }
    }
    for (int k = 0; k < 36; k++) {
      r[k] = ref[k] = (k / 6 <= k % 6) ? 0.25 * (k % 7) : 0.25 * ((k % 6 * 6 + k / 6) % 7);
    }
    double X[36];
    xmatrix(X, E, p);
    reference(ref, X, I);
    uru_xinertia_t_add(r, E, p, I);
    for (int k = 0; k < 36; k++) {
      worst = fmax(worst, fabs(r[k] - ref[k]));
      assert_true(r[k] == r[6 * (k % 6) + k / 6]); /* exactly symmetric */
    }
  }
  print_message("xinertia_t_add: largest deviation from X^T I X %.2e\n", worst);
  assert_true(worst < 1e-12);
}


// the row-vector congruence of a run alone's ABA (engine_xinertia_rows.h) gives the bits of
// uru_xinertia_t_add, for 1000 random cases: magnitudes spread over 2^-20..2^20 so that the
// roundings differ from element to element, the lower triangle of I other than its upper one
// (neither reads it), r not symmetric and holding signed zeros
static void test_xinertia_rows_bitwise(void** state) {
  unsigned seed = 11;
  for (int n = 0; n < 1000; n++) {
    double E[9], p[3], I[36], r[36], ref[36];
    random_rotation(&seed, E);
    for (int k = 0; k < 3; k++) {
      p[k] = ldexp(urand(&seed), (int)(20 * urand(&seed)));
    }
    for (int k = 0; k < 36; k++) {
      I[k] = ldexp(urand(&seed), (int)(20 * urand(&seed)));
      r[k] = ref[k] =
          k % 5 == 0 ? (k % 2 ? -0.0 : 0.0) : ldexp(urand(&seed), (int)(20 * urand(&seed)));
    }
    uru_xinertia_t_add(ref, E, p, I);
    urd_xinertia_t_add(r, E, p, I);
    for (int k = 0; k < 36; k++) {
      if (memcmp(r + k, ref + k, sizeof(double))) {
        fail_msg("case %d, r[%d]: %a against %a", n, k, r[k], ref[k]);
      }
    }
  }
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_xinertia_t_add),
      cmocka_unit_test(test_xinertia_rows_bitwise),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
