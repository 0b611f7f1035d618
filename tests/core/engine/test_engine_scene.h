/* test_engine_scene.h: a crude scene for engine tests and the benchmark: an 18-body standing
 * human (17 segments of human-model.md §3-5 plus a sternum plate on a prismatic joint) and a
 * 7-body RA3-like drone (main body + six arms on universal joints with Cardan restraints) with a
 * bottom airbag; about 30 contact pairs. Parameters are placeholders, not calibrated. */
#ifndef UASIMPACT_TEST_ENGINE_SCENE_H
#define UASIMPACT_TEST_ENGINE_SCENE_H

#include <math.h>
#include <string.h>
#include "uasimpact/engine.h"

typedef struct {
  const char* name;
  const char* parent;
  urJointType jt;
  double anchor[3]; /* joint anchor, world, standing reference */
  double mass;
  double com[3]; /* world */
  double I[3];
  double k, c; /* restraint per dof */
} sceneSeg;

typedef struct {
  const char* name;
  const char* body;
  double c[3]; /* world centre */
  double r[3];
} sceneEll;

static const sceneSeg scene_human[] = {
    {"pelvis",
     NULL,
     urJNT_FREE,
     {-0.03, 0, 0.967},
     8.601,
     {-0.03, 0, 0.967},
     {0.0698, 0.0560, 0.0636},
     0,
     0},
    {"abdomen",
     "pelvis",
     urJNT_SPHERICAL,
     {-0.05, 0, 1.057},
     12.574,
     {-0.02, 0, 1.167},
     {0.1371, 0.0866, 0.1292},
     300,
     8},
    {"thorax",
     "abdomen",
     urJNT_SPHERICAL,
     {-0.05, 0, 1.257},
     12.289,
     {-0.03, 0, 1.377},
     {0.1855, 0.0746, 0.1571},
     300,
     8},
    {"neck",
     "thorax",
     urJNT_SPHERICAL,
     {-0.04, 0, 1.485},
     0.844,
     {-0.033, 0, 1.537},
     {0.0015, 0.0015, 0.0015},
     160,
     1.5},
    {"head",
     "neck",
     urJNT_SPHERICAL,
     {-0.026, 0, 1.588},
     4.5,
     {0, 0, 1.65},
     {0.0214, 0.0232, 0.0154},
     160,
     1.5},
    {"sternum",
     "thorax",
     urJNT_PRISMATIC,
     {0.10, 0, 1.30},
     0.45,
     {0.10, 0, 1.30},
     {1e-4, 1e-4, 1e-4},
     26e3,
     520},
    {"uarm_l",
     "thorax",
     urJNT_SPHERICAL,
     {-0.03, 0.175, 1.395},
     2.087,
     {-0.03, 0.185, 1.224},
     {0.0136, 0.0121, 0.0042},
     10,
     2},
    {"uarm_r",
     "thorax",
     urJNT_SPHERICAL,
     {-0.03, -0.175, 1.395},
     2.087,
     {-0.03, -0.185, 1.224},
     {0.0136, 0.0121, 0.0042},
     10,
     2},
    {"farm_l",
     "uarm_l",
     urJNT_REVOLUTE,
     {-0.03, 0.19, 1.098},
     1.247,
     {-0.025, 0.195, 0.978},
     {0.0069, 0.0064, 0.0013},
     5,
     1},
    {"farm_r",
     "uarm_r",
     urJNT_REVOLUTE,
     {-0.03, -0.19, 1.098},
     1.247,
     {-0.025, -0.195, 0.978},
     {0.0069, 0.0064, 0.0013},
     5,
     1},
    {"hand_l",
     "farm_l",
     urJNT_UNIVERSAL,
     {-0.02, 0.2, 0.835},
     0.47,
     {-0.02, 0.2, 0.767},
     {0.0014, 0.0009, 0.0006},
     5,
     0.5},
    {"hand_r",
     "farm_r",
     urJNT_UNIVERSAL,
     {-0.02, -0.2, 0.835},
     0.47,
     {-0.02, -0.2, 0.767},
     {0.0014, 0.0009, 0.0006},
     5,
     0.5},
    {"thigh_l",
     "pelvis",
     urJNT_SPHERICAL,
     {-0.02, 0.085, 0.91},
     10.903,
     {-0.016, 0.087, 0.738},
     {0.2126, 0.2126, 0.0436},
     250,
     10},
    {"thigh_r",
     "pelvis",
     urJNT_SPHERICAL,
     {-0.02, -0.085, 0.91},
     10.903,
     {-0.016, -0.087, 0.738},
     {0.2126, 0.2126, 0.0436},
     250,
     10},
    {"shank_l",
     "thigh_l",
     urJNT_REVOLUTE,
     {-0.01, 0.09, 0.489},
     3.334,
     {-0.024, 0.09, 0.303},
     {0.0413, 0.0393, 0.0067},
     200,
     10},
    {"shank_r",
     "thigh_r",
     urJNT_REVOLUTE,
     {-0.01, -0.09, 0.489},
     3.334,
     {-0.024, -0.09, 0.303},
     {0.0413, 0.0393, 0.0067},
     200,
     10},
    {"foot_l",
     "shank_l",
     urJNT_UNIVERSAL,
     {-0.04, 0.09, 0.072},
     1.055,
     {0.06, 0.09, 0.035},
     {0.0011, 0.0047, 0.0043},
     400,
     10},
    {"foot_r",
     "shank_r",
     urJNT_UNIVERSAL,
     {-0.04, -0.09, 0.072},
     1.055,
     {0.06, -0.09, 0.035},
     {0.0011, 0.0047, 0.0043},
     400,
     10},
};

static const sceneEll scene_hell[] = {
    {"head", "head", {0, 0, 1.65}, {0.100, 0.077, 0.100}},
    {"neck", "neck", {-0.033, 0, 1.537}, {0.057, 0.065, 0.060}},
    {"thorax", "thorax", {-0.02, 0, 1.31}, {0.12, 0.145, 0.14}},
    {"shoulder_l", "thorax", {-0.03, 0.188, 1.40}, {0.06, 0.06, 0.055}},
    {"shoulder_r", "thorax", {-0.03, -0.188, 1.40}, {0.06, 0.06, 0.055}},
    {"sternum", "sternum", {0.10, 0, 1.30}, {0.03, 0.08, 0.08}},
    {"abdomen", "abdomen", {-0.01, 0, 1.12}, {0.11, 0.155, 0.10}},
    {"uarm_l", "uarm_l", {-0.03, 0.19, 1.247}, {0.045, 0.045, 0.16}},
    {"uarm_r", "uarm_r", {-0.03, -0.19, 1.247}, {0.045, 0.045, 0.16}},
    {"foot_l", "foot_l", {0.045, 0.09, 0.036}, {0.135, 0.05, 0.036}},
    {"foot_r", "foot_r", {0.045, -0.09, 0.036}, {0.135, 0.05, 0.036}},
};

// add the human; returns the root body
static int scene_add_human(urModel* m) {
  int n = (int)(sizeof(scene_human) / sizeof(scene_human[0]));
  for (int i = 0; i < n; i++) {
    const sceneSeg* s = scene_human + i;
    int p = s->parent ? ur_name_body(m, s->parent) : -1;
    double pos[3], com[3], I[6] = {s->I[0], s->I[1], s->I[2], 0, 0, 0};
    const double* pa = p >= 0 ? scene_human[p].anchor : NULL;
    for (int k = 0; k < 3; k++) {
      pos[k] = s->anchor[k] - (pa ? pa[k] : 0);
      com[k] = s->com[k] - s->anchor[k];
    }
    int b = ur_model_add_body(m, s->name, p, s->jt, pos, NULL);
    ur_model_set_inertia(m, b, s->mass, com, I);
    if (s->jt == urJNT_REVOLUTE) {
      ur_model_set_joint(m, b, NULL, (double[3]){0, 1, 0}, NULL);
    } else if (s->jt == urJNT_UNIVERSAL) {
      ur_model_set_joint(m, b, NULL, (double[3]){0, 1, 0}, (double[3]){1, 0, 0});
    } else if (s->jt == urJNT_PRISMATIC) {
      ur_model_set_joint(m, b, NULL, (double[3]){1, 0, 0}, NULL);
    }
    urRestraint r = {0};
    r.k = s->k;
    r.c = s->c;
    for (int k = 0; k < 3 && s->jt != urJNT_FREE; k++) {
      ur_model_set_restraint(m, b, k, &r);
    }
  }
  int ne = (int)(sizeof(scene_hell) / sizeof(scene_hell[0]));
  for (int i = 0; i < ne; i++) {
    const sceneEll* e = scene_hell + i;
    int b = ur_name_body(m, e->body);
    double c[3];
    for (int k = 0; k < 3; k++) {
      c[k] = e->c[k] - scene_human[b].anchor[k];
    }
    ur_model_add_ellipsoid(m, e->name, b, c, NULL, e->r);
  }
  return 0;
}


// add the drone (root "drone", gravity compensated), with an optional bottom airbag
static int scene_add_drone(urModel* m, int airbag) {
  double I0[6] = {0.499, 0.382, 0.771, 0, 0, 0}, Ia[6] = {0.001, 0.004, 0.004, 0, 0, 0};
  int d0 = ur_model_add_body(m, "drone", -1, urJNT_FREE, (double[3]){0, 0, 3}, NULL);
  ur_model_set_inertia(m, d0, 11.974, NULL, I0);
  m->body[d0].gravity = 0;
  ur_model_add_ellipsoid(m, "frame", d0, NULL, NULL, (double[3]){0.25, 0.25, 0.08});
  for (int i = 0; i < 6; i++) {
    char name[16];
    double a = i * M_PI / 3, c = cos(a), s = sin(a);
    snprintf(name, sizeof(name), "arm%d", i + 1);
    int b = ur_model_add_body(m, name, d0, urJNT_UNIVERSAL, (double[3]){0.2 * c, 0.2 * s, 0}, NULL);
    ur_model_set_inertia(m, b, 0.51, (double[3]){0.2 * c, 0.2 * s, 0}, Ia);
    ur_model_set_joint(m, b, NULL, (double[3]){-s, c, 0}, (double[3]){0, 0, 1});
    m->body[b].gravity = 0;
    urRestraint r = {0};
    r.k = 840;
    r.c = 2;
    r.lo = -0.6;
    r.hi = 0.6;
    r.kstop = 1e4;
    ur_model_set_restraint(m, b, 0, &r);
    ur_model_set_restraint(m, b, 1, &r);
    snprintf(name, sizeof(name), "motor%d", i + 1);
    ur_model_add_ellipsoid(m, name, b, (double[3]){0.25 * c, 0.25 * s, 0}, NULL,
                           (double[3]){0.03, 0.03, 0.03});
  }
  if (airbag) {
    int g = ur_model_add_ellipsoid(m, "bag", d0, (double[3]){0, 0, -0.12}, NULL,
                                   (double[3]){0.22, 0.22, 0.1});
    urAirbag bag = {0};
    strcpy(bag.name, "bag");
    bag.geom = g;
    bag.gas.v0 = 0.02;
    bag.gas.p0 = 1.1 * 101325;
    bag.gas.patm = 101325;
    bag.gas.gamma = 1.4;
    bag.kappa = 2;
    bag.thickness = 0.15;
    bag.ntarget = 3;
    bag.target[0] = ur_name_geom(m, "head");
    bag.target[1] = ur_name_geom(m, "shoulder_l");
    bag.target[2] = ur_name_geom(m, "shoulder_r");
    ur_model_add_airbag(m, &bag);
  }
  return d0;
}


// contact pairs: drone parts vs the upper body, feet vs ground
static void scene_add_pairs(urModel* m) {
  urLaw flat = {0}, arm = {0}, soft = {0}, floor = {0};
  ur_law_hertz(&flat, 2.23e7, 0.29, 0.0875, 5.48e10, 0.34, 0, 3.42e6, 0.29, 1);
  ur_law_hertz(&arm, 2.23e7, 0.29, 0.0875, 5.48e10, 0.34, 0.03, 3.42e6, 0.29, 1);
  flat.damping = arm.damping = 100;
  flat.mu = arm.mu = 0.3;
  flat.v_eps = arm.v_eps = 0.01;
  memset(&soft, 0, sizeof(soft));
  soft.type = urLAW_TABLE;
  double px[6] = {0, 0.001, 0.005, 0.01, 0.02, 0.05}, py[6] = {0, 120, 1200, 4200, 7500, 14000};
  soft.load.n = 6;
  memcpy(soft.load.x, px, sizeof(px));
  memcpy(soft.load.y, py, sizeof(py));
  soft.damping = 150;
  soft.mu = 0.4;
  soft.v_eps = 0.01;
  floor = soft;
  floor.load.n = 2;
  floor.load.x[1] = 0.01;
  floor.load.y[1] = 2000;
  floor.damping = 1500;
  floor.mu = 0.6;
  const char* upper[] = {"neck",    "thorax",  "shoulder_l", "shoulder_r",
                         "sternum", "abdomen", "uarm_l",     "uarm_r"};
  int fr = ur_name_geom(m, "frame");
  char name[urNAMELEN];
  ur_model_add_pair(m, "frame_head", ur_name_geom(m, "head"), fr, &flat);
  for (int i = 0; i < 8; i++) {
    snprintf(name, sizeof(name), "frame_%s", upper[i]);
    ur_model_add_pair(m, name, ur_name_geom(m, upper[i]), fr, &soft);
  }
  const char* tgt[] = {"head", "shoulder_l", "shoulder_r"};
  for (int a = 0; a < 6; a++) {
    char mot[16];
    snprintf(mot, sizeof(mot), "motor%d", a + 1);
    for (int t = 0; t < 3; t++) {
      snprintf(name, sizeof(name), "%s_%s", mot, tgt[t]);
      ur_model_add_pair(m, name, ur_name_geom(m, tgt[t]), ur_name_geom(m, mot), t ? &soft : &arm);
    }
  }
  ur_model_add_pair(m, "foot_l_ground", ur_name_geom(m, "foot_l"), -1, &floor);
  ur_model_add_pair(m, "foot_r_ground", ur_name_geom(m, "foot_r"), -1, &floor);
}


// sensors: head CG acceleration, upper-neck load cell, chest deflection and rate, bag
static void scene_add_sensors(urModel* m, int airbag) {
  int head = ur_name_body(m, "head"), st = ur_name_body(m, "sternum");
  double hc[3] = {0.026, 0, 0.062};
  ur_model_add_sensor(m, "head_acc", urSENS_ACCEL, head, 0, hc, NULL);
  ur_model_add_sensor(m, "upper_neck", urSENS_JOINTLOAD, head, 0, NULL, NULL);
  ur_model_add_sensor(m, "chest_defl", urSENS_JOINTPOS, st, 0, NULL, NULL);
  ur_model_add_sensor(m, "chest_rate", urSENS_JOINTVEL, st, 0, NULL, NULL);
  ur_model_add_sensor(m, "frame_head", urSENS_CONTACT, ur_name_pair(m, "frame_head"), 0, NULL,
                      NULL);
  if (airbag) {
    ur_model_add_sensor(m, "bag", urSENS_AIRBAG, ur_name_airbag(m, "bag"), 0, NULL, NULL);
  }
}


__attribute__((unused)) static urModel* scene_build(int airbag) {
  urModel* m = ur_model_new();
  scene_add_human(m);
  scene_add_drone(m, airbag);
  scene_add_pairs(m);
  scene_add_sensors(m, airbag);
  m->opt.tmax = 0.06;
  if (ur_model_compile(m)) {
    ur_model_free(m);
    return NULL;
  }
  return m;
}

// the bodies of scene_chain, to compile
__attribute__((unused)) static urModel* scene_chain_bodies(void) {
  urModel* m = ur_model_new();
  double I[6] = {0.02, 0.03, 0.015, 0.001, 0, -0.002};
  double c[3] = {0.05, 0.01, -0.08};
  int b0 = ur_model_add_body(m, "root", -1, urJNT_FREE, (double[3]){0, 0, 1}, NULL);
  ur_model_set_inertia(m, b0, 3.0, c, I);
  int b1 = ur_model_add_body(m, "rev", b0, urJNT_REVOLUTE, (double[3]){0.1, 0, -0.1},
                             (double[4]){0.9, 0.1, 0.3, 0});
  ur_model_set_inertia(m, b1, 1.0, c, I);
  ur_model_set_joint(m, b1, NULL, (double[3]){0, 1, 1}, NULL);
  int b2 = ur_model_add_body(m, "uni", b1, urJNT_UNIVERSAL, (double[3]){0, 0.1, -0.2}, NULL);
  ur_model_set_inertia(m, b2, 0.7, c, I);
  ur_model_set_joint(m, b2, NULL, (double[3]){1, 0, 0}, (double[3]){0, 0, 1});
  int b3 = ur_model_add_body(m, "sph", b2, urJNT_SPHERICAL, (double[3]){0.1, 0, -0.1}, NULL);
  ur_model_set_inertia(m, b3, 0.5, c, I);
  int b4 = ur_model_add_body(m, "pri", b3, urJNT_PRISMATIC, (double[3]){0, 0, -0.1}, NULL);
  ur_model_set_inertia(m, b4, 0.4, c, I);
  ur_model_set_joint(m, b4, NULL, (double[3]){1, 0, 1}, NULL);
  urRestraint r = {0};
  r.k = 300;
  ur_model_set_restraint(m, b4, 0, &r);
  int b5 = ur_model_add_body(m, "fix", b4, urJNT_FIXED, (double[3]){0.05, 0, 0}, NULL);
  ur_model_set_inertia(m, b5, 0.3, c, I);
  return m;
}


// a chain with every joint type under gravity g: free root, revolute, universal, spherical,
// prismatic (with a spring), fixed
__attribute__((unused)) static urModel* scene_chain(urIntegrator integ, double dt, double g) {
  urModel* m = scene_chain_bodies();
  m->opt.gravity[2] = g;
  m->opt.integrator = integ;
  m->opt.dt = dt;
  if (ur_model_compile(m)) {
    ur_model_free(m);
    return NULL;
  }
  return m;
}

#endif
