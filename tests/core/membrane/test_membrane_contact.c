/* test_membrane_contact.c: the penalty contact of one membrane node with an ellipsoid or a
 * superellipsoid (membrane_contact.c) against closed forms: on a local axis at a fraction s of the
 * semi-axis the depth is the first-order distance (1 - s) r and the force is the penalty
 * k = alpha m / max(dt, kc_dt)^2 times it along the axis (at rest, no friction); a node on or
 * beyond a face of the shape's box, or in the box's corner but outside the rounded shape, is
 * outside: no force, depth 0; a rotated, moved shape gives the same in its own frame. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#include "../../../src/core/membrane/membrane_internal.h"

static const double z3[3] = {0, 0, 0};

/* a shape of semi-axes (0.1, 0.2, 0.3) and degree p, turned 90 deg about z (local x along world
   y, local y along world -x) and centred at (1, 2, 3) */
static urEllipsoid shape(double p) {
  urEllipsoid e = {{1, 2, 3}, {0, -1, 0, 1, 0, 0, 0, 0, 1}, {0.1, 0.2, 0.3}, p};
  return e;
}

/* the world point of local coordinates (u, v, w) in semi-axes */
static void world(const urEllipsoid* e, double u, double v, double w, double x[3]) {
  double l[3] = {u * e->r[0], v * e->r[1], w * e->r[2]};
  for (int k = 0; k < 3; k++) {
    x[k] = e->c[k] + e->R[3 * k] * l[0] + e->R[3 * k + 1] * l[1] + e->R[3 * k + 2] * l[2];
  }
}


static void test_axis_depth(void** state) {
  // at 0.99 of each semi-axis: depth 0.01 r, force k depth along the local axis, outward
  urMemSpec s;
  ur_mem_spec_default(&s);
  double m = 1e-3, dt = 1e-4, k = s.kc_alpha * m / (dt * dt);
  static const double P[3] = {2, 4, 8};
  for (int ip = 0; ip < 3; ip++) {
    urEllipsoid e = shape(P[ip]);
    for (int a = 0; a < 3; a++) {
      double loc[3] = {0, 0, 0}, x[3], f[3];
      loc[a] = 0.99;
      world(&e, loc[0], loc[1], loc[2], x);
      double d = urm_contact_node(&s, dt, &e, e.c, z3, z3, x, z3, m, f);
      assert_true(fabs(d - 0.01 * e.r[a]) < 1e-12);
      double n[3] = {e.R[a], e.R[3 + a], e.R[6 + a]}; /* local axis a in the world */
      for (int j = 0; j < 3; j++) {
        assert_true(fabs(f[j] - k * d * n[j]) < 1e-9 * k * d);
      }
    }
  }
}


static void test_outside(void** state) {
  // on a face of the box, beyond it, and in the box's corner outside the rounded shape: no
  // force, depth 0; inside the corner's rounding of a degree-8 shape: a force
  urMemSpec s;
  ur_mem_spec_default(&s);
  static const double P[3] = {2, 4, 8};
  for (int ip = 0; ip < 3; ip++) {
    urEllipsoid e = shape(P[ip]);
    static const double out[4][3] = {{1, 0, 0}, {0, -1.5, 0}, {0.2, 0.1, -1}, {0.95, 0.95, 0.95}};
    for (int q = 0; q < 4; q++) {
      double x[3], f[3] = {1, 1, 1};
      world(&e, out[q][0], out[q][1], out[q][2], x);
      double d = urm_contact_node(&s, 1e-4, &e, e.c, z3, z3, x, z3, 1e-3, f);
      assert_true(d == 0 && f[0] == 0 && f[1] == 0 && f[2] == 0);
    }
  }
  urEllipsoid e = shape(8);
  double x[3], f[3];
  world(&e, 0.8, 0.8, 0.8, x); /* 3 0.8^8 = 0.50 < 1 */
  double d = urm_contact_node(&s, 1e-4, &e, e.c, z3, z3, x, z3, 1e-3, f);
  assert_true(d > 0 && f[0] * f[0] + f[1] * f[1] + f[2] * f[2] > 0);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_axis_depth),
      cmocka_unit_test(test_outside),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
