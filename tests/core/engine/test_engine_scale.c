/* test_engine_scale.c: a drone tree scaled by its design parameters (role mass=, size=): masses
 * and inertias by the mass ratio, positions, shapes, sensor points and airbag sizes by the size,
 * inertias by the size squared; the person untouched; the total as written leaves every number
 * as written, to the bit. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/modellang.h"

static const char* TEXT =
    "param M 3.5 kg\n"
    "param S 1\n"
    "body torso parent=world joint=free pos=0,0,1 mass=40 inertia=1,1,1\n"
    "ellipsoid chest body=torso pos=0,0,0.2 size=0.2,0.15,0.3\n"
    "body hub parent=world joint=free pos=0,0,3 mass=2.5 com=0,0,0.01 inertia=0.02,0.03,0.04\n"
    "body arm parent=hub joint=revolute pos=0.2,0,0 axis=0,1,0 mass=1 com=0.1,0,0 "
    "inertia=0.001,0.002,0.003\n"
    "ellipsoid shell body=hub pos=0,0,-0.05 size=0.3,0.3,0.08\n"
    "ellipsoid tube body=arm pos=0.1,0,0 size=0.1,0.02,0.02\n"
    "ellipsoid bag body=hub pos=0,0,-0.1 size=0.2,0.2,0.1\n"
    "airbag b geom=bag p0=101325 patm=101325 v0=0.01 gamma=1.4 kappa=2 thickness=0.1 "
    "targets=chest\n"
    "sensor tip type=bodypos obj=arm pos=0.2,0,0\n"
    "role drone=hub mass=$M size=$S\n";

static urModel* parse(double M, double S) {
  urOverride ov[2] = {{"M", M}, {"S", S}};
  urModelSource src = {TEXT, "t.urm", 1};
  char err[256];
  urModel* m = ur_model_parse(&src, 1, ov, 2, err, sizeof err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  return m;
}

/* the written total leaves the model as written; mass scales masses and inertias */
static void mass_scale(void** state) {
  urModel *a = parse(3.5, 1), *b = parse(7, 1);
  assert_true(a->roles.mass0 == 3.5 && a->roles.mass_scale == 1);
  assert_true(b->roles.mass0 == 3.5 && b->roles.mass_scale == 2);
  assert_true(ur_model_tree_mass(b, b->roles.drone) == 7);
  for (int i = 0; i < a->nbody; i++) {
    const urBody *x = a->body + i, *y = b->body + i;
    double f = strcmp(x->name, "torso") ? 2 : 1; /* the person is not the drone */
    assert_true(y->mass == f * x->mass);
    for (int k = 0; k < 9; k++) assert_true(y->inertia[k] == f * x->inertia[k]);
    for (int k = 0; k < 3; k++) assert_true(y->pos[k] == x->pos[k] && y->com[k] == x->com[k]);
  }
  for (int g = 0; g < a->ngeom; g++) {
    for (int k = 0; k < 3; k++) assert_true(a->geom[g].size[k] == b->geom[g].size[k]);
  }
  assert_true(a->body[1].mass == 2.5 && a->body[1].inertia[4] == 0.03); /* as written */
  ur_model_free(a);
  ur_model_free(b);
}

/* size scales the geometry (not the root's placement), airbag volumes by its cube, inertias by
   its square; masses stay */
static void size_scale(void** state) {
  urModel *a = parse(3.5, 1), *b = parse(3.5, 1.5);
  int hub = b->roles.drone, arm = ur_name_body(b, "arm"), torso = ur_name_body(b, "torso");
  assert_true(b->roles.size_scale == 1.5);
  assert_true(b->body[hub].mass == 2.5 && b->body[arm].mass == 1);
  for (int k = 0; k < 3; k++) {
    assert_true(b->body[hub].pos[k] == a->body[hub].pos[k]);
    assert_true(b->body[arm].pos[k] == 1.5 * a->body[arm].pos[k]);
    assert_true(b->body[arm].com[k] == 1.5 * a->body[arm].com[k]);
    assert_true(b->body[torso].pos[k] == a->body[torso].pos[k]);
  }
  for (int k = 0; k < 9; k++) {
    assert_true(fabs(b->body[arm].inertia[k] - 2.25 * a->body[arm].inertia[k]) <= 1e-18);
  }
  for (int g = 0; g < b->ngeom; g++) {
    double f = b->geom[g].body == torso ? 1 : 1.5;
    for (int k = 0; k < 3; k++) {
      assert_true(b->geom[g].size[k] == f * a->geom[g].size[k]);
      assert_true(b->geom[g].pos[k] == f * a->geom[g].pos[k]);
    }
    assert_true(fabs(b->geom[g].rbound - f * a->geom[g].rbound) <= 1e-15);
  }
  int tip = ur_name_sensor(b, "tip");
  assert_true(fabs(b->sensor[tip].pos[0] - 0.3) <= 1e-15);
  assert_true(fabs(b->bag[0].gas.v0 - 0.01 * 3.375) <= 1e-15);
  assert_true(fabs(b->bag[0].thickness - 0.15) <= 1e-15);
  ur_model_free(a);
  ur_model_free(b);
}

/* a mass or size that is not positive is refused with the parameter named */
static void refused(void** state) {
  urOverride ov[1] = {{"M", -1}};
  urModelSource src = {TEXT, "t.urm", 1};
  char err[256];
  assert_null(ur_model_parse(&src, 1, ov, 1, err, sizeof err));
  assert_string_equal(err, "t.urm:12: role mass: must be > 0 (got -1)");
  ov[0].name = "S";
  ov[0].value = 0;
  assert_null(ur_model_parse(&src, 1, ov, 1, err, sizeof err));
  assert_string_equal(err, "t.urm:12: role size: must be > 0 (got 0)");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(mass_scale),
      cmocka_unit_test(size_scale),
      cmocka_unit_test(refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
