/* test_modellang_material.c: the statements material, section and layer, and what the model
 * language derives from them: an arm's hinge from beam theory (3EI/L, sigma_y Zp, hardening,
 * fracture moment), the law between a drone part and a person's layer (Hertz's combination of
 * both materials and radii, the layer's thickness and bone, a shell in series), a law layer (the
 * person's own law), a foam's backing derived from the person's layer, a declared law that
 * overrides a derivable one (kept, and noted), and the errors of each statement; a membrane
 * bag's target layers and its rule for going live (live=).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "modellang_fixture.h"

/* a head with a scalp layer, and a drone whose arm is a carbon tube on a universal joint */
#define HEAD                                                                                       \
  "material scalp E=2.23e7 nu=0.29 density=1100 yield=3.42e6\n"                                    \
  "body head parent=world joint=free pos=0,0,1.7 mass=4.5 inertia=0.02,0.02,0.015\n"               \
  "ellipsoid cranium body=head pos=0,0,0 size=0.1,0.077,0.1\n"                                     \
  "layer scalp_l on=cranium material=scalp thickness=0.006 bone_k=4.023e6 radius=0.0875 "          \
  "mu=0.3 v_eps=0.01\n"
#define DRONE                                                                                      \
  "material cf E=5.48e10 nu=0.34 density=1600 yield=5.93e7 ultimate=6e8\n"                         \
  "material abs E=2.3e9 nu=0.4 density=1050 yield=4e7\n"                                           \
  "section arm_t shape=tube D=0.03 t=0.002\n"                                                      \
  "section wall shape=shell t=0.002 R=0.1\n"                                                       \
  "body main parent=world joint=free pos=0,0,3 mass=10 inertia=0.5,0.4,0.8\n"                      \
  "body arm parent=main joint=universal pos=0.16,0,0 axis=0,1,0 axis2=0,0,1 mass=0.5 "             \
  "com=0.3,0,0 inertia=0.001,0.002,0.003\n"                                                        \
  "ellipsoid tube body=arm pos=0.22,0,0 size=0.22,0.015,0.015 material=cf section=arm_t\n"         \
  "ellipsoid shell body=main pos=0,0,-0.1 size=0.2,0.2,0.1 material=abs section=wall\n"            \
  "ellipsoid frame body=main pos=0,0,0 size=0.3,0.3,0.05 material=cf\n"

/* the hinge derived from beam theory */
static void test_hinge(void** state) {
  char err[256];
  urModel* m = parse1(DRONE
                      "restraint arm dof=0 material=cf section=arm_t length=0.41 c=4 "
                      "lo=-1.4 hi=1.4 kstop=5e4 cstop=20 fracture=1\n"
                      "restraint arm dof=1 material=cf section=arm_t length=0.41\n"
                      "sensor arm_h type=hinge obj=arm dof=0\n",
                      NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urRestraint* r = m->body[ur_name_body(m, "arm")].rst;
  double D = 0.03, d = 0.026, I = M_PI * (pow(D, 4) - pow(d, 4)) / 64;
  double Zp = (pow(D, 3) - pow(d, 3)) / 6;
  assert_near(r[0].k, 3 * 5.48e10 * I / 0.41, 1e-9 * r[0].k);
  assert_near(r[0].mp, 5.93e7 * Zp, 1e-9 * r[0].mp);
  assert_near(r[0].kh, r[0].k / 100, 1e-9 * r[0].k);
  assert_near(r[0].mfrac, 6e8 * Zp, 1e-9 * r[0].mfrac);
  assert_near(r[0].c, 4, 0);
  assert_near(r[0].hi, 1.4, 0);
  assert_near(r[1].mfrac, 0, 0); /* fracture is asked per restraint */
  assert_near(r[1].sat, 0, 0);
  assert_string_equal(m->note, "");

  // its sensor: plastic deflection and the time it broke, 0 and 0 at rest
  int s = ur_name_sensor(m, "arm_h");
  assert_true(s >= 0);
  assert_int_equal(m->sensor[s].dim, 2);
  urData* dd = ur_data_new(m);
  ur_forward(m, dd);
  assert_near(dd->sensordata[m->sensor[s].adr], 0, 0);
  assert_near(dd->sensordata[m->sensor[s].adr + 1], 0, 0);
  ur_data_free(dd);
  ur_model_free(m);
}

/* the drone-person law: Hertz's combination of both materials and radii, the layer's thickness
   and bone, friction from the layer; a shell section in series */
static void test_pair_law(void** state) {
  char err[256];
  urModel* m = parse1(HEAD DRONE "pairs dp a=cranium b=tube,shell,frame\n", NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  double es = 1 / ((1 - 0.29 * 0.29) / 2.23e7 + (1 - 0.34 * 0.34) / 5.48e10);
  const urLaw* l = &m->pair[ur_name_pair(m, "dp_cranium_tube")].law;
  assert_int_equal(l->type, urLAW_HERTZ);
  assert_near(l->estar, es, 1e-9 * es);
  assert_near(l->radius, 1 / (1 / 0.0875 + 1 / 0.015), 1e-15);
  assert_near(l->layer_h, 0.006, 0);
  assert_near(l->bone_k, 4.023e6, 0);
  assert_near(l->mu, 0.3, 0);
  assert_near(l->shell_k, 0, 0);
  assert_int_equal(l->plastic, 0);

  // the shell: ABS on scalp, radius in series with the shell's, Reissner's stiffness
  l = &m->pair[ur_name_pair(m, "dp_cranium_shell")].law;
  double ea = 1 / ((1 - 0.29 * 0.29) / 2.23e7 + (1 - 0.4 * 0.4) / 2.3e9);
  assert_near(l->estar, ea, 1e-9 * ea);
  assert_near(l->radius, 1 / (1 / 0.0875 + 1 / 0.1), 1e-15);
  assert_near(l->shell_k, 4 * 2.3e9 * 0.002 * 0.002 / (0.1 * sqrt(3 * (1 - 0.16))), 1e-6);

  // its crush load from the ABS's yield, 2 pi M0 = pi 40 MPa (2 mm)^2 / 2; bottoming at R
  assert_near(l->crush_f, M_PI * 4e7 * 0.002 * 0.002 / 2, 1e-9);
  assert_near(l->crush_h, 0.1, 0);

  // no section: the ellipsoids' curvature gives the radius
  l = &m->pair[ur_name_pair(m, "dp_cranium_frame")].law;
  assert_near(l->radius, urHERTZ_CURVATURE, 0);
  assert_string_equal(m->note, "");
  ur_model_free(m);
}

/* a shell's crush: its declared depth to bottoming (h=); a material without yield keeps the
   elastic shell (no crush load); h is a shell's key and a bad one is refused */
static void test_shell_crush(void** state) {
  char err[256], text[4096];
  const char* drone = HEAD DRONE "pairs dp a=cranium b=shell\n";
  char* w;
  snprintf(text, sizeof text, "%s", drone);
  w = strstr(text, "R=0.1\n");
  assert_non_null(w);
  memmove(w + 12, w + 5, strlen(w + 5) + 1);
  memcpy(w, "R=0.1 h=0.03", 12);
  urModel* m = parse1(text, NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urLaw* l = &m->pair[ur_name_pair(m, "dp_cranium_shell")].law;
  assert_near(l->crush_h, 0.03, 0);
  assert_near(l->crush_f, M_PI * 4e7 * 0.002 * 0.002 / 2, 1e-9);
  ur_model_free(m);

  // no yield: the elastic shell, as before the crush plateau
  snprintf(text, sizeof text, "%s", drone);
  w = strstr(text, "density=1050 yield=4e7");
  assert_non_null(w);
  memmove(w + 12, w + 22, strlen(w + 22) + 1);
  m = parse1(text, NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  l = &m->pair[ur_name_pair(m, "dp_cranium_shell")].law;
  assert_true(l->shell_k > 0);
  assert_near(l->crush_f, 0, 0);
  assert_near(l->crush_h, 0, 0);
  ur_model_free(m);

  // a negative depth, and h on a tube
  snprintf(text, sizeof text, "%s%s", HEAD DRONE, "section bad shape=shell t=0.002 R=0.1 h=-1\n");
  assert_null(parse1(text, NULL, 0, err));
  print_message("%s\n", err);
  snprintf(text, sizeof text, "%s%s", HEAD DRONE, "section bad shape=tube D=0.03 t=0.002 h=0.01\n");
  assert_null(parse1(text, NULL, 0, err));
  print_message("%s\n", err);
  assert_non_null(strstr(err, "not h"));
}

/* a membrane bag's targets: one with a layer takes the layer's foundation stiffness E_oed / h
   as the fabric's penalty (derived, and listed); one without keeps the bag's kc_alpha (tk 0) */
static void test_bag_layer(void** state) {
  char err[256];
  urModel* m = parse1(HEAD DRONE
                      "ellipsoid jaw body=head pos=0,0,-0.12 size=0.05,0.05,0.04\n"
                      "airbag bb geom=shell p0=101325 patm=101325 v0=0.01 gamma=1.4 kappa=1 "
                      "thickness=0.1 targets=jaw,cranium membrane=1 size=0.15,0.15 depth=0.08 "
                      "mount=0,0,-0.1 mesh=3\n",
                      NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urAirbag* b = m->bag + ur_name_airbag(m, "bb");
  double eoed = 2.23e7 * (1 - 0.29) / ((1 + 0.29) * (1 - 2 * 0.29)); /* 29.22 MPa */
  assert_near(b->tk[0], 0, 0);
  assert_near(b->tk[1], eoed / 0.006, 1e-9 * eoed / 0.006);
  assert_near(b->tk[1], 4.8705e9, 1e5); /* the value uasimpact-model(5) quotes */
  assert_non_null(strstr(m->derived,
                         "airbag 'bb' on cranium (layer scalp_l): fabric penalty k = "
                         "E_oed / h = 4.87049e+09 N/m^3"));
  assert_null(strstr(m->derived, "on jaw"));
  ur_model_free(m);
}


/* a membrane bag's live=: 0 (the first rule) unless declared, 1 nodes and jolts, else refused
   saying what is accepted */
static void test_bag_live(void** state) {
  static const char* const live[] = {"", " live=0", " live=1", " live=2"};
  for (int i = 0; i < 4; i++) {
    char err[256], text[2048];
    snprintf(text, sizeof text,
             "%sairbag bb geom=shell p0=101325 patm=101325 v0=0.01 gamma=1.4 kappa=1 "
             "thickness=0.1 targets=cranium membrane=1 size=0.15,0.15 depth=0.08 "
             "mount=0,0,-0.1 mesh=3%s\n",
             HEAD DRONE, live[i]);
    urModel* m = parse1(text, NULL, 0, err);
    if (i == 3) {
      assert_null(m);
      print_message("%s\n", err);
      assert_non_null(strstr(err, "airbag 'bb': live must be 0 (the first rule"));
      assert_non_null(strstr(err, "got 2"));
      continue;
    }
    assert_non_null(m);
    assert_int_equal(m->bag[ur_name_airbag(m, "bb")].liverule, i == 2 ? 1 : 0);
    ur_model_free(m);
  }
}


/* a declared law on a layer: kept as declared, and noted (with the material when the drone part
   has one: an old drone file's own scalp law is noted too) */
static void test_override(void** state) {
  char err[256];
  const char* law =
      "law frame_head type=hertz E1=2.23e7 nu1=0.29 R1=0.0875 E2=5.48e10 "
      "nu2=0.34 R2=0 mu=0.3 v_eps=0.01\n";
  char text[4096];
  snprintf(text, sizeof text, "%s%s%s", HEAD DRONE, law,
           "pair fh a=cranium b=frame law=frame_head\n");
  urModel* m = parse1(text, NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urLaw* l = &m->pair[ur_name_pair(m, "fh")].law;
  assert_near(l->radius, 0.0875, 0);
  assert_near(l->layer_h, 0, 0);
  print_message("note: %s\n", m->note);
  assert_non_null(strstr(m->note,
                         "pair 'fh': its declared law 'frame_head' overrides the layer of "
                         "'cranium' and the material of 'frame'"));
  ur_model_free(m);

  snprintf(text, sizeof text, "%s%s%s", HEAD,
           "body d parent=world joint=free pos=0,0,3 mass=1 inertia=0.1,0.1,0.1\n"
           "ellipsoid e body=d pos=0,0,0 size=0.1,0.1,0.1\n",
           law);
  strcat(text, "pair fh a=cranium b=e law=frame_head\n");
  m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  assert_string_equal(m->note,
                      "pair 'fh': its declared law 'frame_head' overrides the layer of "
                      "'cranium' (uasimpact-model(5), MATERIALS)");
  ur_model_free(m);

  // a drone without a layer on the other side: nothing to note
  m = parse1(DRONE
             "law t type=hertz E1=1e9 nu1=0.3 E2=1e9 nu2=0.3 R1=0.1 R2=0.1\n"
             "pair x a=tube b=ground law=t\n",
             NULL, 0, err);
  assert_non_null(m);
  assert_string_equal(m->note, "");
  ur_model_free(m);
}

/* a body region given by one of the person's own laws, and a cargo foam with its backing */
#define SOFT                                                                                       \
  "curve tload x=0,0.01,0.05 y=0,4200,14000\n"                                                     \
  "curve tunload x=0,0.01,0.05 y=0,1050,3500\n"                                                    \
  "law tissue type=table load=tload unload=tunload damping=150 mu=0.4 v_eps=0.01\n"                \
  "material skin E=2e5 nu=0.45 density=1100\n"                                                     \
  "body trunk parent=world joint=free pos=0,0,1.3 mass=30 inertia=1,1,1\n"                         \
  "ellipsoid chest body=trunk pos=0,0,0 size=0.12,0.145,0.14\n"                                    \
  "ellipsoid neck body=trunk pos=0,0,0.25 size=0.057,0.065,0.06\n"                                 \
  "layer skin_l on=chest material=skin thickness=0.015 bone_k=1e6 mu=0.4 v_eps=0.01\n"             \
  "layer soft on=neck law=tissue\n"
#define FOAM                                                                                       \
  "curve epp x=0,0.5,0.9 y=0,0.5e6,6e6\n"                                                          \
  "law foam type=foam stress=epp thickness=0.03 unload_r=0.2 unload_p=4 lock=0.89 "                \
  "backing=derived backing_material=cf mu=0.4 v_eps=0.01\n"

/* a law layer: a pair without law= takes the person's law, whatever the drone part; naming the
   same law is no override, another law is (noted) */
static void test_law_layer(void** state) {
  char err[256];
  urModel* m = parse1(HEAD DRONE SOFT
                      "law other type=table load=tload\n"
                      "pair n1 a=neck b=frame\n"
                      "pair n2 a=neck b=tube law=tissue\n"
                      "pairs n3 a=neck b=shell law=other\n",
                      NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urLaw* l = &m->pair[ur_name_pair(m, "n1")].law;
  assert_int_equal(l->type, urLAW_TABLE);
  assert_int_equal(l->load.n, 3);
  assert_near(l->load.y[2], 14000, 0);
  assert_near(l->unload.y[1], 1050, 0);
  assert_near(l->damping, 150, 0);
  assert_near(l->layer_h, 0, 0);
  assert_null(strstr(m->note, "'n1'"));
  assert_null(strstr(m->note, "'n2'"));
  assert_non_null(strstr(m->note,
                         "pairs 'n3': its declared law 'other' overrides the layer of "
                         "'neck' (uasimpact-model(5), MATERIALS)"));
  ur_model_free(m);
}

/* backing=derived: per pair from the layer of the person's part a. Scalp at its radius: the
   Hertz K of the scalp on the backing's material, flat, the bits of the declared law it
   replaces and 4/3 E* sqrt(R) of both materials; a layer without a radius: E* now, R at each
   contact; a law layer: its loading curve */
static void test_backing_derived(void** state) {
  char err[256];
  urModel* m = parse1(HEAD DRONE SOFT FOAM
                      "law fh type=hertz E1=2.23e7 nu1=0.29 R1=0.0875 E2=5.48e10 nu2=0.34 R2=0\n"
                      "law old type=foam stress=epp thickness=0.03 unload_r=0.2 unload_p=4 "
                      "lock=0.89 backing=fh\n"
                      "pairs cg a=cranium,chest,neck b=shell law=foam\n"
                      "pair cold a=cranium b=shell law=old\n",
                      NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urLaw* head = &m->pair[ur_name_pair(m, "cg_cranium_shell")].law;
  const urLaw* old = &m->pair[ur_name_pair(m, "cold")].law;
  assert_true(head->backing_k > 0);
  assert_true(memcmp(&head->backing_k, &old->backing_k, sizeof(double)) == 0);
  double es = 1 / ((1 - 0.29 * 0.29) / 2.23e7 + (1 - 0.34 * 0.34) / 5.48e10);
  assert_near(head->backing_k, 4.0 / 3.0 * es * sqrt(0.0875), 1e-9 * head->backing_k);
  assert_near(head->backing_r, 0.0875, 1e-15);
  assert_near(head->lock, 0.89, 0);
  assert_int_equal(head->backing.n, 0);

  const urLaw* chest = &m->pair[ur_name_pair(m, "cg_chest_shell")].law;
  double es2 = 1 / ((1 - 0.45 * 0.45) / 2e5 + (1 - 0.34 * 0.34) / 5.48e10);
  assert_true(chest->backing_r == urHERTZ_CURVATURE);
  assert_near(chest->backing_estar, es2, 1e-9 * es2);
  assert_near(chest->backing_k, 0, 0);

  const urLaw* neck = &m->pair[ur_name_pair(m, "cg_neck_shell")].law;
  assert_int_equal(neck->backing.n, 3);
  assert_near(neck->backing.y[1], 4200, 0);
  assert_near(ur_law_range(neck), 0.89 * 0.03 + 0.05, 1e-15);

  // the foam is the drone's: no override noted; what was derived is listed
  assert_null(strstr(m->note, "cg"));
  assert_non_null(strstr(m->derived,
                         "pairs 'cg', foam on layer scalp_l: backing K = "
                         "4/3 E* sqrt(R) = 9.59907e+06 N/m^1.5"));
  assert_non_null(strstr(m->derived,
                         "pairs 'cg', foam on layer soft: backing beyond the lock "
                         "strain = the loading curve of law tissue"));
  ur_model_free(m);
}

/* a foam curve from the Avalle-Belingardi-Ibba law at the strains given, scaled */
static void test_foam_curve(void** state) {
  char err[256];
  urModel* m = parse1(
      "curve f x=0,0.1,0.5,0.8 abi=1,30,2,0.3,1.6 yscale=4e5\n"
      "law foam type=foam stress=f thickness=0.03 unload_r=0.2 unload_p=4\n"
      "body a parent=world joint=free pos=0,0,1 mass=1 inertia=0.1,0.1,0.1\n"
      "ellipsoid e body=a pos=0,0,0 size=0.1,0.1,0.1\n"
      "pair p a=e b=ground law=foam\n",
      NULL, 0, err);
  if (!m) print_error("%s\n", err);
  assert_non_null(m);
  const urCurve* c = &m->pair[0].law.stress;
  static const double X[4] = {0, 0.1, 0.5, 0.8};
  assert_int_equal(c->n, 4);
  for (int i = 0; i < 4; i++) {
    double e = X[i];
    double s = 4e5 * ((1 - exp(-30 * e * (1 - e) * (1 - e))) + 0.3 * pow(e / (1 - e), 1.6));
    assert_near(c->y[i], s, 1e-9 * s + 1e-12);
  }
  ur_model_free(m);
}

/* one clear error per mistake */
static void test_errors(void** state) {
  static const struct {
    const char* text;
    const char* msg;
  } bad[] = {
      {DRONE "restraint arm dof=0 material=cf section=arm_t length=0.4 k=100\n",
       "k is an explicit law and material= derives one"},
      {DRONE "restraint arm dof=0 material=cf section=arm_t\n",
       "needs material=, section= and length= (m) together"},
      {DRONE "restraint arm dof=0 material=abs section=arm_t length=0.4 fracture=1\n",
       "fracture=1 needs the material's ultimate stress or fracture_strain"},
      {DRONE "restraint arm dof=0 material=cf section=wall length=0.4\n",
       "section 'wall' has no bending law"},
      {"material soft E=1e6 nu=0.45 density=1100\n" DRONE
       "restraint arm dof=0 material=soft section=arm_t length=0.4\n",
       "material 'soft' gives no yield stress"},
      {"curve c x=0,0.5 y=0,1 abi=1,30,2,0.3,1.6\n", "give y=LIST or abi=A,E,m,B,n"},
      {"curve c x=0,1 abi=1,30,2,0.3,1.6\n", "the foam law takes strains in [0, 1)"},
      {"curve c x=0,0.5 abi=0,30,2,0.3,1.6\n", "abi=A,E,m,B,n needs A > 0"},
      {DRONE "restraint arm dof=0 k=100\nsensor h type=hinge obj=arm dof=0\n",
       "joint 'arm' dof 0 has no hinge from beam theory"},
      {"section s shape=tube D=0.06 t=0.002\nrestraint x dof=0 material=cf section=s\n"
       "material cf E=1e9 nu=0.3 density=1000 yield=1e7\n",
       "dangling reference to body 'x'"},
      {"body b parent=world joint=free pos=0,0,1 mass=1 inertia=0.1,0.1,0.1\n"
       "ellipsoid e body=b pos=0,0,0 size=0.1,0.1,0.1\n"
       "layer l on=e material=late thickness=0.006 bone_k=1e6\n"
       "material late E=1e6 nu=0.4 density=1000\n",
       "dangling reference to material 'late' (defined later, at t.urm:4; define it before use)"},
      {"section s shape=tube D=0.02\n", "a tube needs D,t (m)"},
      {"section s shape=plate t=0.002 D=0.1\n", "a plate takes t (and b, its width), not D"},
      {"section s shape=tube D=0.02 t=0.01\n", "must be thinner than half its diameter"},
      {"material m E=1e9 nu=0.5 density=1000 yield=1e7\n", "nu must be in [0, 0.5)"},
      {"material m E=1e9 nu=0.3 density=1000 yield=1e7 ultimate=5e6\n", "must not be below yield"},
      {HEAD "layer again on=cranium material=scalp thickness=0.005 bone_k=1e6\n",
       "ellipsoid 'cranium' already has a layer"},
      {HEAD DRONE "pair p a=tube b=frame\n", "no law= and nothing to derive one from"},
      {HEAD "layer l2 on=cranium material=skin thickness=0.01 bone_k=1e6\n",
       "dangling reference to material 'skin'"},
      {HEAD SOFT "layer both on=cranium material=skin law=tissue\n",
       "layer 'both': give material= (with thickness= and bone_k=) or law="},
      {HEAD "layer none on=cranium thickness=0.01 bone_k=1e6\n",
       "layer 'none': give material= (with thickness= and bone_k=) or law="},
      {HEAD SOFT "layer t on=cranium law=tissue thickness=0.01\n",
       "a law layer takes no thickness (its law 'tissue' gives the force)"},
      {HEAD "layer m on=cranium material=scalp bone_k=1e6\n",
       "a material layer needs thickness= (m, where it bottoms)"},
      {HEAD "layer u on=cranium law=nolaw\n", "dangling reference to law 'nolaw'"},
      {DRONE FOAM "body o parent=world joint=free pos=0,0,1 mass=1 inertia=0.1,0.1,0.1\n"
                  "ellipsoid bare body=o pos=0,0,0 size=0.1,0.1,0.1\n"
                  "pair p a=bare b=shell law=foam\n",
       "pair 'p': the foam's backing=derived needs a layer on 'bare'"},
      {DRONE "curve epp x=0,0.9 y=0,6e6\nlaw f type=foam stress=epp thickness=0.03 "
             "unload_r=0.2 unload_p=4 lock=0.89 backing=derived\n",
       "backing=derived and backing_material=MATERIAL go together"},
      {DRONE "law h type=hertz E1=1e7 nu1=0.3 R1=0.1 E2=1e9 nu2=0.3 R2=0\ncurve epp x=0,0.9 "
             "y=0,6e6\nlaw f type=foam stress=epp thickness=0.03 unload_r=0.2 unload_p=4 "
             "lock=0.89 backing=h backing_material=cf\n",
       "backing=derived and backing_material=MATERIAL go together"},
      {DRONE "curve epp x=0,0.9 y=0,6e6\nlaw f type=foam stress=epp thickness=0.03 "
             "unload_r=0.2 unload_p=4 lock=0.89 backing=derived backing_material=nomat\n",
       "dangling reference to material 'nomat'"},
      {HEAD DRONE FOAM "law hz type=hertz E1=1e7 nu1=0.3 E2=1e9 nu2=0.3\n"
                       "body o parent=world joint=free pos=0,0,1 mass=1 inertia=0.1,0.1,0.1\n"
                       "ellipsoid arm_o body=o pos=0,0,0 size=0.1,0.1,0.1\n"
                       "layer lh on=arm_o law=hz\npair p a=arm_o b=shell law=foam\n",
       "takes a law layer's loading curve, and 'hz' (layer lh) is not a table law"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    char err[256] = "";
    urModel* m = parse1(bad[i].text, NULL, 0, err);
    if (m || !strstr(err, bad[i].msg)) {
      print_error("case %zu: got '%s', expected '%s'\n", i, err, bad[i].msg);
    }
    assert_null(m);
    assert_non_null(strstr(err, bad[i].msg));
  }
}

int main(void) {
  (void)model_text; /* the fixture's model: not used here */
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_hinge),           cmocka_unit_test(test_pair_law),
      cmocka_unit_test(test_override),        cmocka_unit_test(test_bag_layer),
      cmocka_unit_test(test_foam_curve),      cmocka_unit_test(test_errors),
      cmocka_unit_test(test_shell_crush),     cmocka_unit_test(test_law_layer),
      cmocka_unit_test(test_backing_derived), cmocka_unit_test(test_bag_live),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
