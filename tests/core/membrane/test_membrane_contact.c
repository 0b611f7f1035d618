/* test_membrane_contact.c: the penalty contact of one membrane node with an ellipsoid or a
 * superellipsoid (membrane_contact.c) against closed forms: on a local axis at a fraction s of the
 * semi-axis the depth is the first-order distance (1 - s) r and the force is the penalty
 * k = alpha m / max(dt, kc_dt)^2 times it along the axis (at rest, no friction); a node on or
 * beyond a face of the shape's box, or in the box's corner but outside the rounded shape, is
 * outside: no force, depth 0; a rotated, moved shape gives the same in its own frame; the gap
 * outside on an axis is the first-order distance (s - 1) r; the clipped integrals of a linear
 * depth over a triangle (the face contact's pressure on its penetrated part) against the closed
 * forms of the whole triangle and of a corner cut at its edges' midpoints; the shape's box along
 * the world axes (urm_shape_box) holds every point of its surface and is reached by one; the
 * friction is mu times the normal force when sliding fast, and its viscous slope's cap is the
 * share's whole mass over max(dt, kc_dt) (not its penetrated part's, not over dt). */
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


static void test_gap_outside(void** state) {
  // at 1.01 of each semi-axis, evaluated in full: the gap -0.01 r, the normal along the axis;
  // not in full: -INFINITY
  static const double P[3] = {2, 4, 8};
  for (int ip = 0; ip < 3; ip++) {
    urEllipsoid e = shape(P[ip]);
    for (int a = 0; a < 3; a++) {
      double loc[3] = {0, 0, 0}, x[3], n[3];
      loc[a] = 1.01;
      world(&e, loc[0], loc[1], loc[2], x);
      assert_true(urm_contact_gap(&e, x, 0, n) == -INFINITY);
      double g = urm_contact_gap(&e, x, 1, n);
      assert_true(fabs(g + 0.01 * e.r[a]) < 1e-12);
      assert_true(fabs(n[0] - e.R[a]) + fabs(n[1] - e.R[3 + a]) + fabs(n[2] - e.R[6 + a]) < 1e-12);
    }
  }
}


static void test_clip(void** state) {
  // all corners in: int d N_u = (2 d_u + d_v + d_w) / 12, int N_u = 1/3,
  // int d^2 = (sum d^2 + sum d_u d_v) / 6 (unit area)
  double d[3] = {1, 2, 4}, I[3], A[3], E;
  urm_contact_clip(d, I, A, &E);
  for (int u = 0; u < 3; u++) {
    assert_true(fabs(I[u] - (d[u] + 7) / 12) < 1e-15);
    assert_true(fabs(A[u] - 1.0 / 3) < 1e-15);
  }
  assert_true(fabs(E - (1 + 4 + 16 + 2 + 8 + 4) / 6.0) < 1e-14);
  // one corner in, the others at minus its depth: the zero contour joins the edges' midpoints,
  // the penetrated part a quarter of the area; int d = 1/4 x the mean 1/3 of the corner values
  // (1, 0, 0); int d^2 = 1/4 x 1/6; the corner's shape function on that part: int N_0 =
  // 1/4 (1 + 1/2 + 1/2) / 3 = 1/6, the others 1/24 each
  double d1[3] = {-1, 1, -1};
  urm_contact_clip(d1, I, A, &E);
  assert_true(fabs(I[0] + I[1] + I[2] - 1.0 / 12) < 1e-15);
  assert_true(fabs(A[1] - 1.0 / 6) < 1e-15 && fabs(A[0] - 1.0 / 24) < 1e-15 &&
              fabs(A[2] - 1.0 / 24) < 1e-15);
  assert_true(fabs(E - 1.0 / 24) < 1e-15);
  // two corners in (the complement of a corner cut at the midpoints): the area 3/4
  double d2[3] = {1, 1, -1};
  urm_contact_clip(d2, I, A, &E);
  assert_true(fabs(A[0] + A[1] + A[2] - 0.75) < 1e-15);
  // none in: nothing
  double d3[3] = {-1, -2, 0};
  urm_contact_clip(d3, I, A, &E);
  assert_true(I[0] == 0 && I[1] == 0 && I[2] == 0 && A[0] + A[1] + A[2] == 0 && E == 0);
}


static void test_friction_cap(void** state) {
  // a share pressed along n = z (I = 1e-6 m^3, penetrated area A = 1e-5 m^2 of its whole
  // ac = 1e-3 m^2) sliding along x: fast (100 m/s) the Coulomb bound, friction mu fn; slowly
  // (1 mm/s) the viscous slope's cap rhot ac / max(dt, kc_dt) times the speed, the same at
  // dt = kc_dt and kc_dt / 2 and whatever the penetrated area
  urMemSpec s;
  ur_mem_spec_default(&s);
  double n[3] = {0, 0, 1}, f[3], I = 1e-6, ac = 1e-3;
  double fn = urm_contact_force(&s, s.kc_dt, n, (double[3]){100, 0, 0}, I, 1e-5, ac, f);
  assert_true(fn > 0 && fabs(-f[0] - s.mu * fn) < 1e-12 * fn && f[1] == 0);
  double cap = s.rhot * ac / s.kc_dt * 1e-3;
  static const double A[2] = {1e-5, 1e-3}, dt[2] = {1, 0.5};
  for (int i = 0; i < 2; i++) {
    for (int j = 0; j < 2; j++) {
      fn = urm_contact_force(&s, dt[j] * s.kc_dt, n, (double[3]){1e-3, 0, 0}, I, A[i], ac, f);
      assert_true(fn > 0 && fabs(-f[0] - cap) < 1e-12 * cap);
    }
  }
}


static void test_shape_box(void** state) {
  // turned about all three axes (a unit quaternion's matrix), degrees 2, 4 and 8: surface points
  // r (u / ||u||_p) over directions u on a grid stay within the box, the farthest along each
  // axis reach 0.99 of it (the grid's coarseness; a superellipsoid's box, the 1-norm bound of
  // its support function, at least 1 / sqrt 3 of it); and a point just outside it is outside
  static const double P[3] = {2, 4, 8};
  double q[4] = {0.8, 0.3, -0.4, 0.2}, qn = 0;
  for (int k = 0; k < 4; k++) {
    qn += q[k] * q[k];
  }
  for (int k = 0; k < 4; k++) {
    q[k] /= sqrt(qn);
  }
  double a = q[0], b = q[1], c = q[2], d = q[3];
  urEllipsoid e = {{1, 2, 3},
                   {a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c),
                    2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b),
                    2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d},
                   {0.1, 0.2, 0.3},
                   2};
  for (int ip = 0; ip < 3; ip++) {
    e.p = P[ip];
    double gh[3], far[3] = {0, 0, 0};
    urm_shape_box(&e, gh);
    for (int i = 0; i <= 60; i++) {
      for (int j = 0; j < 120; j++) {
        double th = M_PI * i / 60, ph = 2 * M_PI * j / 120;
        double u[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)}, s = 0, x[3];
        for (int k = 0; k < 3; k++) {
          s += pow(fabs(u[k]), e.p);
        }
        s = pow(s, 1 / e.p);
        world(&e, u[0] / s, u[1] / s, u[2] / s, x);
        for (int k = 0; k < 3; k++) {
          double r = fabs(x[k] - e.c[k]);
          assert_true(r <= gh[k]);
          far[k] = fmax(far[k], r);
        }
      }
    }
    for (int k = 0; k < 3; k++) {
      assert_true(far[k] > (e.p > 2 ? 0.57 : 0.99) * gh[k]);
      double x[3] = {e.c[0], e.c[1], e.c[2]}, n[3];
      x[k] += 1.000001 * gh[k];
      assert_true(urm_contact_gap(&e, x, 0, n) == -INFINITY);
    }
  }
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_axis_depth),   cmocka_unit_test(test_outside),
      cmocka_unit_test(test_gap_outside),  cmocka_unit_test(test_clip),
      cmocka_unit_test(test_friction_cap), cmocka_unit_test(test_shape_box),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
