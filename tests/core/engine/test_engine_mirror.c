/* test_engine_mirror.c: the mirror check of a compiled model (engine_mirror.c). The built-in
 * person with the RA3 is symmetric with its analytic bag and with its membrane bags (bottom,
 * and the front one of A2); one change to one side of it, each in its own kind of part (a body's
 * centre of mass, one arm's mass, one restraint's stop, an ellipsoid's place or size, a bag's
 * mount or tilt, an injury sensor's point, a contact pair's law on one side), makes it
 * asymmetric and the reason names that part; a tilt about the plane's normal keeps it. Pairs
 * and bags pair off one to one: a duplicate on one side is asymmetric. A plate must read a
 * coordinate that keeps its sign. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/modellang.h"
#include "../../../src/app/case/builtin.h"

static const char* const PARTS[] = {"human", "ra3", "airbags", "sim"};

/* the built-in text of part k with the first occurrence of from replaced by to (NULL: none) */
static char* part_text(int k, const char* from, const char* to) {
  const char* t = ura_builtin_text(PARTS[k]);
  if (!t) fail_msg("no built-in model %s", PARTS[k]);
  const char* at = from ? strstr(t, from) : NULL;
  size_t n = strlen(t) + (to ? strlen(to) : 0) + 1;
  char* s = malloc(n);
  assert_non_null(s);
  if (!at) {
    snprintf(s, n, "%s", t);
  } else {
    snprintf(s, n, "%.*s%s%s", (int)(at - t), t, to, at + strlen(from));
  }
  return s;
}

/* the built-in model set with one edit in part k (from -> to; the edit must apply), membrane
   bags or analytic, the front bag on or off; its mirror verdict and reason in why */
static int verdict(int k, const char* from, const char* to, int membrane, int front, char* why,
                   size_t n) {
  urModelSource src[4];
  char* txt[4];
  for (int i = 0; i < 4; i++) {
    txt[i] = part_text(i, i == k ? from : NULL, i == k ? to : NULL);
    if (i == k && from) assert_non_null(strstr(ura_builtin_text(PARTS[i]), from));
    src[i] = (urModelSource){txt[i], PARTS[i], 1};
  }
  urOverride o[3] = {{"bag_membrane", membrane}, {"bag_front", front}, {"bag_mesh", 3}};
  char err[300];
  urModel* m = ur_model_parse(src, 4, o, 3, err, sizeof err);
  if (!m) fail_msg("%s", err);
  char w[urMSGLEN];
  int r = ur_model_mirror(m, w, sizeof w);
  assert_int_equal(r, m->mirror); /* the compile's verdict is the function's */
  assert_string_equal(w, m->nomirror);
  snprintf(why, n, "%s", w);
  ur_model_free(m);
  for (int i = 0; i < 4; i++) free(txt[i]);
  return r;
}

static void builtin_symmetric(void** state) {
  char why[urMSGLEN];
  for (int membrane = 0; membrane < 2; membrane++) {
    for (int front = 0; front < 2; front++) {
      assert_true(verdict(-1, NULL, NULL, membrane, front, why, sizeof why));
      assert_string_equal(why, "");
    }
  }
}

/* one edit, asymmetric: the reason names `part` */
static void asym(int k, const char* from, const char* to, int membrane, const char* part) {
  char why[urMSGLEN];
  int r = verdict(k, from, to, membrane, 1, why, sizeof why);
  if (r || !strstr(why, part)) fail_msg("%s -> %s: %d, '%s' (want '%s')", from, to, r, why, part);
}

static void bodies(void** state) {
  asym(1, "body main parent=world joint=free pos=0,0,0 mass=11.9744",
       "body main parent=world joint=free pos=0,0,0 mass=11.9744 com=0,0.08,0", 0, "body main");
  asym(1, "pos=0.1559,-0.0900,0.03 rot=0,0,1,-30 mass=0.502",
       "pos=0.1559,-0.0900,0.03 rot=0,0,1,-30 mass=0.51", 0, "body arm1");
  asym(1, "pos=0.1559,-0.0900,0.03 rot=0,0,1,-30", "pos=0.1559,-0.0910,0.03 rot=0,0,1,-30", 0,
       "body arm1");
}

static void restraints(void** state) {
  /* dof 0 of a spherical joint turns sign in the mirror: the stops must too */
  asym(0, "restraint upperarm_l dof=0 k=10 c=$joint_c lo=-0.6 hi=0.6",
       "restraint upperarm_l dof=0 k=10 c=$joint_c lo=-0.5 hi=0.6", 0, "body upperarm_l");
  /* dof 1 keeps its sign: equal stops on both sides */
  asym(0, "restraint upperarm_l dof=1 k=10 c=$joint_c lo=-1.0 hi=1.0",
       "restraint upperarm_l dof=1 k=10 c=$joint_c lo=-0.9 hi=1.0", 0, "body upperarm_l");
  asym(0, "restraint upperarm_r dof=2 k=10", "restraint upperarm_r dof=2 k=11", 0,
       "body upperarm_l");
}

static void ellipsoids_pairs_sensors(void** state) {
  asym(0, "ellipsoid thigh_l body=thigh_l pos=0.004,0.002,-0.210",
       "ellipsoid thigh_l body=thigh_l pos=0.004,0.003,-0.210", 0, "ellipsoid thigh_l");
  asym(0, "ellipsoid hand_l body=forearm_l pos=0.010,0.010,-0.353 size=0.022,0.044,0.095",
       "ellipsoid hand_l body=forearm_l pos=0.010,0.010,-0.353 size=0.022,0.045,0.095", 0,
       "ellipsoid hand_l");
  asym(0, "sensor head_acc type=accel obj=head pos=0.026,0,0.062",
       "sensor head_acc type=accel obj=head pos=0.026,0.01,0.062", 0, "head acceleration");
  /* the feet's soles on the ground: the left ones only */
  asym(0, "pairs sole a=heel_l,ball_l,heel_r,ball_r", "pairs sole a=heel_l,ball_l", 0,
       "contact pair");
}

static void membranes(void** state) {
  char why[urMSGLEN];
  asym(2, "mount=0,0,-0.22", "mount=0,0.01,-0.22", 1, "airbag bag_bottom");
  asym(2, "mount=0.30,0,-0.05 rot=0,1,0,-90", "mount=0.30,0,-0.05 rot=1,0,0,10", 1,
       "airbag bag_front");
  /* a tilt about y (the plane's normal) keeps the front bag symmetric */
  assert_true(verdict(2, "mount=0.30,0,-0.05 rot=0,1,0,-90", "mount=0.30,0,-0.05 rot=0,1,0,-80", 1,
                      1, why, sizeof why));
  /* the analytic bag moved across: its ellipsoid */
  asym(1, "ellipsoid cargo body=main pos=0,0,-0.12", "ellipsoid cargo body=main pos=0,0.02,-0.12",
       1, "ellipsoid cargo");
}

/* contact pairs and bags pair off one to one: a second one on one side only has no partner
   (before, it matched the other side's partner again and the model passed as symmetric) */
#define FRONT_SENSOR "sensor bag_front_p type=airbag obj=bag_front enable=$bag_front"
#define SIDE_BAGS                                                                                  \
  FRONT_SENSOR                                                                                     \
  "\nellipsoid wl body=arm1 pos=0.3,0,0 size=0.05,0.05,0.05"                                       \
  "\nellipsoid wr body=arm2 pos=0.3,0,0 size=0.05,0.05,0.05"                                       \
  "\nairbag bl geom=wl p0=101325 patm=101325 v0=0.001 gamma=1.4 kappa=1 "                          \
  "thickness=0.05 targets=head_cranium"                                                            \
  "\nairbag br geom=wr p0=101325 patm=101325 v0=0.001 gamma=1.4 kappa=1 "                          \
  "thickness=0.05 targets=head_cranium"

static void one_to_one(void** state) {
  char why[urMSGLEN];
  asym(0, "pairs sole a=heel_l,ball_l,heel_r,ball_r b=ground law=sole",
       "pairs sole a=heel_l,ball_l,heel_r,ball_r b=ground law=sole\n"
       "pairs sole2 a=heel_r b=ground law=sole",
       0, "contact pair sole2");
  /* a left and a right bag on the arms 1 and 2 (each other's images) keep it symmetric */
  assert_true(verdict(2, FRONT_SENSOR, SIDE_BAGS, 0, 1, why, sizeof why));
  asym(2, FRONT_SENSOR,
       SIDE_BAGS
       "\nairbag br2 geom=wr p0=101325 patm=101325 v0=0.001 gamma=1.4 kappa=1 "
       "thickness=0.05 targets=head_cranium",
       0, "airbag br2 has no mirror image");
}

/* membrane side bags on the arms 1 and 2: symmetric with equal specs; a different inflation
   method or stable-step fraction on one side is not (the numerics differ, so the cells would) */
#define MEM_BAG(NAME, GEOM, EXTRA)                                                                 \
  "\nairbag " NAME " geom=" GEOM                                                                   \
  " p0=101325 patm=101325 v0=0.001 gamma=1.4 kappa=1 "                                             \
  "thickness=0.05 targets=head_cranium membrane=1 size=0.05,0.04 depth=0.03 mount=0.3,0,0 "        \
  "mesh=2" EXTRA
#define MEM_SIDE(EXTRA_R)                                                                          \
  FRONT_SENSOR                                                                                     \
  "\nellipsoid wl body=arm1 pos=0.3,0,0 size=0.05,0.05,0.05"                                       \
  "\nellipsoid wr body=arm2 pos=0.3,0,0 size=0.05,0.05,0.05" MEM_BAG("bl", "wl", "")               \
      MEM_BAG("br", "wr", EXTRA_R)

static void membrane_specs(void** state) {
  char why[urMSGLEN];
  if (!verdict(2, FRONT_SENSOR, MEM_SIDE(""), 1, 1, why, sizeof why)) fail_msg("%s", why);
  asym(2, FRONT_SENSOR, MEM_SIDE(" inflate=1"), 1, "airbag bl");
  asym(2, FRONT_SENSOR, MEM_SIDE(" dt_factor=0.5"), 1, "airbag bl");
}

/* a plate's coordinate must keep its sign. The language takes jointpos on hinges and slides
   only, so a plate on the pelvis's free joint (dof 1: its lateral position, which turns) is set
   in the compiled model: it passed before. The neck's angular velocity (a ball's jointvel)
   about y keeps its sign in the mirror, about x turns it */
static void plates(void** state) {
  char why[urMSGLEN];
  urModelSource src[4];
  for (int i = 0; i < 4; i++) src[i] = (urModelSource){ura_builtin_text(PARTS[i]), PARTS[i], 1};
  urOverride o[1] = {{"bag_membrane", 0}};
  char err[300];
  urModel* m = ur_model_parse(src, 4, o, 1, err, sizeof err);
  if (!m) fail_msg("%s", err);
  assert_true(ur_model_mirror(m, why, sizeof why));
  urSensor* chest = m->sensor + m->roles.chest;
  chest->obj = ur_name_body(m, "pelvis");
  assert_true(chest->obj >= 0);
  chest->dof = 1;
  assert_false(ur_model_mirror(m, why, sizeof why));
  assert_non_null(strstr(why, "chest sensor"));
  chest->obj = ur_name_body(m, "neck");
  chest->type = urSENS_JOINTVEL;
  assert_true(ur_model_mirror(m, why, sizeof why));
  chest->dof = 0;
  assert_false(ur_model_mirror(m, why, sizeof why));
  ur_model_free(m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(builtin_symmetric), cmocka_unit_test(bodies),
      cmocka_unit_test(restraints),        cmocka_unit_test(ellipsoids_pairs_sensors),
      cmocka_unit_test(membranes),         cmocka_unit_test(membrane_specs),
      cmocka_unit_test(one_to_one),        cmocka_unit_test(plates),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
