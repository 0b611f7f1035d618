/* test_contact_curv.c: the Hertz radius from the ellipsoids' curvature at the contact
 * (contact_curv.c): two spheres give 1/(1/R1 + 1/R2), an ellipsoid's pole on the ground
 * a b / c (its principal radii a^2/c and b^2/c), whatever its turn about the normal; a law
 * without R1 and R2 takes the radius so in the engine, the same force as the explicit law of the
 * same radius; the language's refusals. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/modellang.h"

static urEllipsoid ell(double x, double y, double z, double a, double b, double c, double turn) {
  urEllipsoid e;
  memset(&e, 0, sizeof e);
  e.c[0] = x;
  e.c[1] = y;
  e.c[2] = z;
  double ct = cos(turn), st = sin(turn);
  double R[9] = {ct, -st, 0, st, ct, 0, 0, 0, 1};
  memcpy(e.R, R, sizeof R);
  e.r[0] = a;
  e.r[1] = b;
  e.r[2] = c;
  e.p = 2;
  return e;
}

static void spheres(void** state) {
  urEllipsoid a = ell(0, 0, 0, 0.1, 0.1, 0.1, 0), b = ell(0.148, 0, 0.01, 0.05, 0.05, 0.05, 0);
  double u[3] = {1, 0, 0};
  urGeomContact gc;
  assert_int_equal(ur_collide_ellipsoids(&a, &b, u, &gc), 1);
  double r = ur_contact_radius(&a, &b, &gc);
  assert_true(fabs(r - 1 / (10.0 + 20.0)) < 1e-6);
}

static void pole_on_ground(void** state) {
  static const double up[3] = {0, 0, 1};
  for (int k = 0; k < 4; k++) {
    urEllipsoid e = ell(0.3, -0.2, 0.049, 0.2, 0.1, 0.05, 0.4 * k);
    urGeomContact gc;
    assert_int_equal(ur_collide_ellipsoid_plane(&e, up, 0, &gc), 1);
    double r = ur_contact_radius(&e, NULL, &gc);
    assert_true(fabs(r - 0.2 * 0.1 / 0.05) < 1e-6);
  }
  /* a flat face on a flat: capped */
  urEllipsoid f = ell(0, 0, 0.049, 1e6, 1e6, 0.05, 0);
  urGeomContact gc;
  ur_collide_ellipsoid_plane(&f, up, 0, &gc);
  assert_true(ur_contact_radius(&f, NULL, &gc) == urHERTZ_RMAX);
}

/* a sphere pressed 1 mm into the ground: the law without radii gives the explicit law's force */
static double ground_force(const char* law) {
  char text[600], err[256];
  snprintf(text, sizeof text,
           "body ball parent=world joint=free pos=0,0,0.099 mass=1 inertia=0.01,0.01,0.01\n"
           "ellipsoid s body=ball pos=0,0,0 size=0.1,0.1,0.1\n"
           "law h type=hertz E1=2e7 nu1=0.3 E2=2e11 nu2=0.3 %s\n"
           "pair g a=s b=ground law=h\n",
           law);
  urModelSource src = {text, "t.urm", 1};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  urData* d = ur_data_new(m);
  ur_forward(m, d);
  double f = d->pair[0].fn;
  ur_data_free(d);
  ur_model_free(m);
  return f;
}

static void engine_law(void** state) {
  double a = ground_force("R1=0.1 R2=0"), b = ground_force("");
  assert_true(a > 0 && fabs(a - b) < 1e-6 * a);
  assert_true(ground_force("R1=0.2 R2=0") > 1.2 * b); /* the radius matters: the test can fail */
}

static void refusals(void** state) {
  char err[256];
  urModelSource src = {"law h type=hertz E1=2e7 nu1=0.3 E2=2e11 nu2=0.3 R1=0.1\n", "t.urm", 1};
  assert_null(ur_model_parse(&src, 1, NULL, 0, err, sizeof err));
  assert_string_equal(err,
                      "t.urm:1: law 'h': give R1 and R2, or neither (the radius then comes "
                      "from the ellipsoids' curvature at the contact)");
  src.text =
      "body b parent=world joint=free pos=0,0,1 mass=1 inertia=1,1,1\n"
      "ellipsoid s body=b pos=0,0,0 size=0.1,0.1,0.1 degree=4\n"
      "law h type=hertz E1=2e7 nu1=0.3 E2=2e11 nu2=0.3\n"
      "pair g a=s b=ground law=h\n";
  assert_null(ur_model_parse(&src, 1, NULL, 0, err, sizeof err));
  assert_string_equal(err,
                      "t.urm:4: pair 'g': ellipsoid 's' has degree=4; a Hertz law without "
                      "R1 and R2 takes its radius from the curvature of ellipsoids of degree 2 "
                      "(give R1 and R2)");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(spheres),
      cmocka_unit_test(pole_on_ground),
      cmocka_unit_test(engine_law),
      cmocka_unit_test(refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
