/* test_impact_person.c: the person alone (impact_person.c) steps as the whole model does with
 * the drone parked and held: after a settling of 400 steps its coordinates, velocities,
 * restraint extremes and pair histories are the whole model's to the bit; a person model with
 * one law changed in its last digits differs (so the comparison can fail); an airbag on the
 * person gives no person model. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "uasimpact/modellang.h"
#include "../../../src/core/engine/engine_internal.h"
#include "../../../src/core/impact/impact_internal.h"
#include "../../../src/app/case/builtin.h"


#define NSTEP 400

static const double PARK[3] = {0, 0, 1e4}, QID[4] = {1, 0, 0, 0}, ZERO3[3] = {0, 0, 0};

static const char* builtin(const char* name) {
  const char* t = ura_builtin_text(name);
  if (!t) fail_msg("no built-in model %s", name);
  return t;
}

/* the RA3 on the person, its airbags analytic, with the settling's step */
static urModel* model(void) {
  static const char* const parts[] = {"human", "ra3", "airbags", "sim"};
  urModelSource src[4];
  for (int i = 0; i < 4; i++) src[i] = (urModelSource){builtin(parts[i]), parts[i], 1};
  urOverride o[1] = {{"bag_membrane", 0}};
  char err[300];
  urModel* m = ur_model_parse(src, 4, o, 1, err, sizeof err);
  if (!m) fail_msg("%s", err);
  m->opt.dt = ur_model_param(m, "settle_dt", 2e-4);
  return m;
}

/* the drone's tree back in its reference posture, at rest, parked far above */
static void hold(const urModel* m, urData* d, int drone) {
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    if (bd->tree != drone) continue;
    memcpy(d->qpos + bd->qadr, m->qpos0 + bd->qadr, bd->nq * sizeof(double));
    memset(d->qvel + bd->vadr, 0, bd->nv * sizeof(double));
    memset(d->rst + 2 * bd->vadr, 0, 2 * bd->nv * sizeof(double));
  }
  ur_set_free(m, d, drone, PARK, QID, ZERO3, ZERO3);
}

static urData* parked(const urModel* m, int drone) {
  urData* d = ur_data_new(m);
  assert_non_null(d);
  ur_data_reset(m, d);
  ur_set_free(m, d, drone, PARK, QID, ZERO3, ZERO3);
  return d;
}

/* the person's state in d and e: 0 the same to the bit, else 1 */
static int person_differs(const urModel* m, const urData* d, const urData* e, int drone) {
  int n = 0;
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    if (bd->tree == drone) continue;
    n++;
    if (memcmp(d->qpos + bd->qadr, e->qpos + bd->qadr, bd->nq * sizeof(double)) ||
        memcmp(d->qvel + bd->vadr, e->qvel + bd->vadr, bd->nv * sizeof(double)) ||
        memcmp(d->rst + 2 * bd->vadr, e->rst + 2 * bd->vadr, 2 * bd->nv * sizeof(double)))
      return 1;
  }
  assert_true(n > 10);
  for (int i = 0; i < m->npair; i++) {
    const urPair* p = m->pair + i;
    if (m->body[m->geom[p->geom1].body].tree == drone) continue;
    if (p->geom2 >= 0 && m->body[m->geom[p->geom2].body].tree == drone) continue;
    if (memcmp(d->pair + i, e->pair + i, sizeof(urPairData))) return 1;
  }
  return 0;
}

/* NSTEP steps of the whole model with the drone held against those of the person alone
   (mu_change: the person's ground pairs' friction scaled by it); 1 if they differ */
static int settle_differs(double mu_change) {
  urModel* m = model();
  int drone = m->roles.drone;
  urData* d = parked(m, drone);
  for (int k = 0; k < NSTEP; k++) {
    assert_int_equal(ur_step(m, d), 0);
    hold(m, d, drone);
  }
  urModel* p = ur_impact_person_model(m, drone);
  assert_non_null(p);
  assert_true(p->nbody < m->nbody && p->nbody > 10 && p->npair > 0);
  for (int i = 0; i < p->npair; i++) {
    if (p->pair[i].geom2 < 0) p->pair[i].law.mu *= mu_change;
  }
  urData* dp = ur_data_new(p);
  assert_non_null(dp);
  for (int k = 0; k < NSTEP; k++) assert_int_equal(ur_step(p, dp), 0);
  urData* e = parked(m, drone);
  ur_impact_person_state(m, e, drone, p, dp);
  int differs = person_differs(m, d, e, drone);
  assert_true(e->npcommit > 0); /* the soles' contacts listed again */
  ur_data_free(e);
  ur_data_free(dp);
  ur_model_free(p);
  ur_data_free(d);
  ur_model_free(m);
  return differs;
}

static void bitwise(void** state) {
  (void)state;
  assert_int_equal(settle_differs(1.0), 0);
}

static void changed_law_differs(void** state) {
  (void)state;
  assert_int_equal(settle_differs(1 + 1e-9), 1);
}

static void bag_on_person(void** state) {
  (void)state;
  urModel* m = model();
  assert_true(m->nbag > 0);
  urModel* p = ur_impact_person_model(m, m->roles.drone);
  assert_non_null(p);
  ur_model_free(p);
  m->bag[0].geom = ur_name_geom(m, "heel_l");
  assert_true(m->bag[0].geom >= 0);
  assert_null(ur_impact_person_model(m, m->roles.drone));
  ur_model_free(m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(bitwise),
      cmocka_unit_test(changed_law_differs),
      cmocka_unit_test(bag_on_person),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
