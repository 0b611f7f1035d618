/* test_engine_range.c: ur_extrapolated, the laws and restraint curves a run used beyond their
 * data: a ball dropped on a tabulated floor whose data end before the ball stops, and a hinge
 * swung past its curve's last abscissa (odd-symmetric curve: both sides); what stays inside its
 * data is not reported. */
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
      cmocka_unit_test(test_restraint),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
