/* test_engine_range.c: ur_extrapolated, the laws and restraint curves a run used beyond their
 * data: a ball dropped on a tabulated floor whose data end before the ball stops, and a hinge
 * swung past its curve's last abscissa (odd-symmetric curve: both sides); what stays inside its
 * data is not reported. A ball with a crushing shell dropped on a scalp: the energy it takes is
 * the plateau's, F_c times the crushed depth, and a shell crushed to the bottom is noted. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/engine.h"
#include "uasimpact/modellang.h"

/* |a - b| <= tol with both values printed on failure */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)
static void near_(double a, double b, double tol, const char* what, const char* file, int line) {
  if (!(fabs(a - b) <= tol)) {
    print_error("%s = %.12g, expected %.12g +- %g\n", what, a, b, tol);
    _fail(file, line);
  }
}

static urModel* parse(const char* text) {
  char err[256];
  urModelSource src = {text, "t.urm"};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof err);
  if (!m) {
    print_error("%s\n", err);
  }
  assert_non_null(m);
  return m;
}

/* a 1 kg ball at v0 onto a floor of 1e5 N/m whose table ends at `last` m */
static int drop(double v0, const char* last, char* msg) {
  char text[512];
  snprintf(text, sizeof text,
           "option dt=1e-5 gravity=0,0,0\n"
           "curve floor x=0,%s y=0,%g\n"
           "law f type=table load=floor\n"
           "body ball parent=world joint=free pos=0,0,0.1 mass=1 inertia=1,1,1\n"
           "ellipsoid b body=ball pos=0,0,0 size=0.1,0.1,0.1\n"
           "pair bf a=b b=ground law=f\n",
           last, 1e5 * atof(last));
  urModel* m = parse(text);
  urData* d = ur_data_new(m);
  double v[3] = {0, 0, -v0};
  ur_set_free(m, d, 0, NULL, NULL, v, NULL);
  for (int i = 0; i < 20000; i++) {
    ur_step(m, d);
  }
  int n = ur_extrapolated(m, d, msg, 160);
  ur_data_free(d);
  ur_model_free(m);
  return n;
}

/* a 1 kg ball with a 2 mm ABS shell (R 0.1 m, yield 40 MPa: F_c = 2 pi 40 N) at 3 m/s onto
   a fixed head under a 6 mm scalp, crushed at most h m; returns the crushed depth, the kinetic
   energy after the rebound in *ke */
static double shell_drop(const char* h, double* ke, int* n, char* msg) {
  char text[1024];
  snprintf(text, sizeof text,
           "option dt=1e-5 gravity=0,0,0\n"
           "material scalp E=2.23e7 nu=0.29 density=1100\n"
           "material abs E=2.3e9 nu=0.4 density=1050 yield=4e7\n"
           "section wall shape=shell t=0.002 R=0.1 h=%s\n"
           "body head parent=world joint=fixed pos=0,0,0 mass=1 inertia=1,1,1\n"
           "ellipsoid hd body=head pos=0,0,0 size=0.1,0.1,0.1\n"
           "layer scalp on=hd material=scalp thickness=0.006 bone_k=4.023e6 radius=0.0875\n"
           "body ball parent=world joint=free pos=0,0,0.16 mass=1 inertia=1,1,1\n"
           "ellipsoid b body=ball pos=0,0,0 size=0.05,0.05,0.05 material=abs section=wall\n"
           "pair pb a=hd b=b\n",
           h);
  urModel* m = parse(text);
  assert_true(m->pair[0].law.crush_f > 0);
  urData* d = ur_data_new(m);
  double v[3] = {0, 0, -3};
  int ball = ur_name_body(m, "ball");
  ur_set_free(m, d, ball, NULL, NULL, v, NULL);
  for (int i = 0; i < 10000; i++) {
    ur_step(m, d);
  }
  const double* qv = d->qvel + m->body[ball].vadr;
  *ke = 0.5 * (qv[0] * qv[0] + qv[1] * qv[1] + qv[2] * qv[2]);
  assert_true(qv[2] > 0); /* rebounding, clear of the head */
  assert_true(d->pair[0].ls.touching == 0);
  double c = d->pair[0].ls.crush;
  *n = ur_extrapolated(m, d, msg, 160);
  ur_data_free(d);
  ur_model_free(m);
  return c;
}

/* 4.5 J in: the ball leaves with 4.5 J - F_c c (to 1 % of F_c c: the step's error); crushed
   to its 5 mm bottom, the run notes it; a 50 mm shell does not bottom */
static void test_shell(void** state) {
  char msg[160];
  double ke, fc = 2 * M_PI * 40;
  int n;
  double c = shell_drop("0.05", &ke, &n, msg);
  print_message("shell: crushed %.4g m, %.4g J of 4.5 back (F_c c %.4g J)\n", c, ke, fc * c);
  assert_true(c > 0.005 && c < 0.05);
  assert_true(ke < 4.5);
  assert_near(4.5 - ke, fc * c, 0.01 * fc * c);
  assert_int_equal(n, 0);
  c = shell_drop("0.005", &ke, &n, msg);
  print_message("shell: crushed %.4g m, %.4g J back; %s\n", c, ke, msg);
  assert_near(c, 0.005, 0);
  assert_near(4.5 - ke, fc * c, 0.01 * fc * c);
  assert_int_equal(n, 1);
  assert_non_null(strstr(msg, "pair pb crushed its shell 0.005 m to the bottom"));
}

/* depth 0.0095 m at 3 m/s (sqrt(m/k) v0): inside a table to 0.02 m, beyond one to 0.005 m */
static void test_pair(void** state) {
  char msg[160];
  assert_int_equal(drop(3, "0.02", msg), 0);
  assert_string_equal(msg, "");
  assert_int_equal(drop(3, "0.005", msg), 1);
  print_message("%s\n", msg);
  assert_non_null(strstr(msg, "pair bf at depth 0.0094"));
  assert_non_null(strstr(msg, "its law's data end at 0.005 m"));
}

/* a hinge with a curve to 0.3 rad, started at 0.5 rad (a curve with no negative abscissae
   covers -0.3..0.3); without the curve's data exceeded nothing is reported */
static void test_restraint(void** state) {
  urModel* m = parse(
      "option dt=1e-4 gravity=0,0,0\n"
      "curve c x=0,0.3 y=0,30\n"
      "body arm parent=world joint=revolute pos=0,0,0 mass=1 inertia=1,1,1\n"
      "restraint arm dof=0 load=c c=5\n");
  urData* d = ur_data_new(m);
  char msg[160];
  d->qpos[0] = 0.2;
  ur_step(m, d);
  assert_int_equal(ur_extrapolated(m, d, msg, sizeof msg), 0);
  d->qpos[0] = -0.45;
  ur_step(m, d);
  assert_int_equal(ur_extrapolated(m, d, msg, sizeof msg), 1);
  print_message("%s\n", msg);
  assert_non_null(strstr(msg, "restraint arm dof 0 at -0.45"));
  assert_non_null(strstr(msg, "-0.3..0.3"));
  ur_data_free(d);
  ur_model_free(m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_pair),
      cmocka_unit_test(test_shell),
      cmocka_unit_test(test_restraint),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
