/* test_modellang.c: the model language: a small model (pendulum, universal neck with restraint
 * and curve, Hertz and foam laws, airbag, sensors; modellang_fixture.h) parsed into the expected
 * model fields, unit conversions, strict numbers, lexical rules, overrides, enable flags and the
 * scales, locks and saturations. The malformed texts are test_modellang_errors.c; roles,
 * presets, pairs, several sources and parts test_modellang_parts.c. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <cmocka.h>
#include "uasimpact/modellang.h"
#include "modellang_fixture.h"

//---------------------------------- the small model -----------------------------------------------

/* every element of the text ends up in the model with the values written there */
static void test_model_fields(void** state) {
  char err[256];
  urModel* m = parse1(model_text, NULL, 0, err);
  if (!m) {
    print_error("%s\n", err);
  }
  assert_non_null(m);
  assert_string_equal(err, "");
  assert_int_equal(m->compiled, 1);
  assert_int_equal(m->nbody, 3);
  assert_int_equal(m->ngeom, 4);
  assert_int_equal(m->npair, 3);
  assert_int_equal(m->nbag, 1);
  assert_int_equal(m->nsensor, 7);
  assert_int_equal(m->nparam, 6);

  /* parameters in SI units */
  assert_near(ur_model_param(m, "L", -1), 0.5, 1e-15);
  assert_near(ur_model_param(m, "m_bob", -1), 2.0, 1e-15);
  assert_near(ur_model_param(m, "ang", -1), M_PI / 6, 1e-15);
  assert_near(ur_model_param(m, "p0", -1), 111457.5, 1e-9);
  assert_near(ur_model_param(m, "E_s", -1), 22.3e6, 1e-6);

  /* options (unset ones keep their defaults) */
  assert_near(m->opt.dt, 2e-5, 1e-20);
  assert_near(m->opt.tmax, 0.1, 1e-17);
  assert_near(m->opt.t_quiet, 0.01, 1e-17);
  assert_near(m->opt.sample_dt, 1e-4, 1e-19);
  assert_near(m->opt.gravity[2], -9.81, 1e-15);
  assert_int_equal(m->opt.integrator, urINT_RK4);

  /* pendulum: revolute about y (normalised), mass in kg, com from -$L */
  int piv = ur_name_body(m, "pivot");
  assert_int_equal(piv, 0);
  const urBody* b = m->body + piv;
  assert_int_equal(b->parent, -1);
  assert_int_equal(b->jtype, urJNT_REVOLUTE);
  assert_near(b->pos[2], 2, 0);
  assert_near(b->axis[0][1], 1, 1e-15);
  assert_near(b->axis[0][2], 0, 0);
  assert_near(b->mass, 2, 1e-15);
  assert_near(b->com[2], -0.5, 1e-15);
  assert_near(b->inertia[4], 0.02, 1e-17);
  assert_near(b->gravity, 1, 0);
  int bob = ur_name_geom(m, "bob");
  assert_int_equal(m->geom[bob].body, piv);
  assert_near(m->geom[bob].pos[2], -0.5, 1e-15);

  /* universal neck: rot=0,0,1,90 -> quaternion, axes, joint name, full inertia, restraint */
  int neck = ur_name_body(m, "neck");
  b = m->body + neck;
  assert_int_equal(b->parent, piv);
  assert_int_equal(b->jtype, urJNT_UNIVERSAL);
  assert_near(b->quat[0], sqrt(0.5), 1e-15);
  assert_near(b->quat[1], 0, 1e-15);
  assert_near(b->quat[3], sqrt(0.5), 1e-15);
  assert_string_equal(b->jname, "neck_j");
  assert_int_equal(ur_name_joint(m, "neck_j"), neck);
  assert_near(b->axis[0][0], 1, 0);
  assert_near(b->axis[1][1], 1, 0);
  assert_near(b->inertia[1], 0.001, 1e-18);
  assert_near(b->inertia[3], 0.001, 1e-18);
  assert_int_equal(b->rst[0].active, 0);
  assert_int_equal(b->rst[1].active, 1);
  assert_near(b->rst[1].k, 10, 0);
  assert_near(b->rst[1].c, 0.5, 0);
  assert_near(b->rst[1].lo, -M_PI / 6, 1e-15);
  assert_near(b->rst[1].hi, M_PI / 6, 1e-15);
  assert_near(b->rst[1].kstop, 1e3, 0);
  assert_int_equal(b->rst[1].load.n, 4);
  assert_near(b->rst[1].load.x[3], 0.5, 0);
  assert_near(b->rst[1].load.y[2], 15, 0);
  assert_int_equal(b->rst[1].unload.n, 0);

  /* head: rot=1,0,0,90 */
  int head = ur_name_geom(m, "head");
  assert_int_equal(m->geom[head].body, neck);
  assert_near(m->geom[head].quat[0], sqrt(0.5), 1e-15);
  assert_near(m->geom[head].quat[1], sqrt(0.5), 1e-15);
  assert_near(m->geom[head].size[1], 0.07, 0);

  /* laws in the pairs: Hertz from the materials, foam, table */
  const urPair* pr = m->pair + ur_name_pair(m, "head_ground");
  assert_int_equal(pr->geom1, head);
  assert_int_equal(pr->geom2, -1);
  assert_int_equal(pr->law.type, urLAW_HERTZ);
  double estar = 1 / ((1 - 0.29 * 0.29) / 22.3e6 + (1 - 0.34 * 0.34) / 5.48e10);
  assert_near(pr->law.estar, estar, 1e-6);
  assert_near(pr->law.radius, 0.0875, 1e-16);
  assert_near(pr->law.sy, 3.42e6, 0);
  assert_int_equal(pr->law.plastic, 1);
  assert_near(pr->law.mu, 0.3, 0);
  assert_near(pr->law.v_eps, 0.01, 0);
  pr = m->pair + ur_name_pair(m, "bob_ground");
  assert_int_equal(pr->law.type, urLAW_FOAM);
  assert_int_equal(pr->law.stress.n, 3);
  assert_near(pr->law.stress.x[1], 0.5, 0);
  assert_near(pr->law.stress.y[2], 1e6, 0);
  assert_near(pr->law.thickness, 0.05, 0);
  assert_near(pr->law.unload_r, 0.2, 0);
  assert_near(pr->law.unload_p, 3, 0);
  assert_near(pr->law.damping, 10, 0);
  pr = m->pair + ur_name_pair(m, "frame_head");
  assert_int_equal(pr->law.type, urLAW_TABLE);
  assert_int_equal(pr->geom1, ur_name_geom(m, "frame"));
  assert_int_equal(pr->geom2, head);
  assert_int_equal(pr->law.load.n, 4);
  assert_near(pr->law.chi, 0.2, 0);

  /* drone and airbag */
  int ra3 = ur_name_body(m, "ra3");
  assert_int_equal(m->body[ra3].jtype, urJNT_FREE);
  assert_near(m->body[ra3].gravity, 0, 0);
  const urAirbag* bag = m->bag;
  assert_string_equal(bag->name, "bag_b");
  assert_int_equal(bag->geom, ur_name_geom(m, "bag"));
  assert_near(bag->gas.p0, 111457.5, 1e-9);
  assert_near(bag->gas.patm, 101325, 0);
  assert_near(bag->gas.v0, 0.02, 0);
  assert_near(bag->gas.gamma, 1.4, 0);
  assert_near(bag->kappa, 0.5, 0);
  assert_near(bag->thickness, 0.1, 0);
  assert_near(bag->fabric_k, 100, 0);
  assert_int_equal(bag->ntarget, 2);
  assert_int_equal(bag->target[0], head);
  assert_int_equal(bag->target[1], bob);

  /* sensors: objects by type, dims, joint-load frame */
  const urSensor* s = m->sensor + ur_name_sensor(m, "neck_load");
  assert_int_equal(s->type, urSENS_JOINTLOAD);
  assert_int_equal(s->obj, neck);
  assert_int_equal(s->dim, 6);
  assert_near(s->quat[3], sqrt(0.5), 1e-15);
  s = m->sensor + ur_name_sensor(m, "neck_q");
  assert_int_equal(s->type, urSENS_JOINTPOS);
  assert_int_equal(s->obj, neck);
  assert_int_equal(s->dof, 1);
  s = m->sensor + ur_name_sensor(m, "head_acc");
  assert_int_equal(s->type, urSENS_ACCEL);
  assert_near(s->pos[2], -0.1, 0);
  s = m->sensor + ur_name_sensor(m, "hc");
  assert_int_equal(s->obj, ur_name_pair(m, "head_ground"));
  s = m->sensor + ur_name_sensor(m, "bagp");
  assert_int_equal(s->type, urSENS_AIRBAG);
  assert_int_equal(s->obj, 0);
  assert_int_equal(m->nsensordata, 4 + 3 + 6 + 1 + 1 + 3 + 3);

  /* the compiled model runs */
  urData* d = ur_data_new(m);
  assert_non_null(d);
  assert_true(ur_forward(m, d) >= 0);
  ur_data_free(d);
  ur_model_free(m);
}


/* strict numbers that are accepted, with their values */
static void test_numbers_accepted(void** state) {
  char err[256];
  urModel* m = parse1(
      "param a .5\nparam b 5.\nparam c -2.5E-3\nparam d +3\nparam e 0\n"
      "param f -$c\nparam g 1e-300\nparam h $d cm\nparam i 007\n",
      NULL, 0, err);
  assert_non_null(m);
  assert_near(ur_model_param(m, "a", -1), 0.5, 0);
  assert_near(ur_model_param(m, "b", -1), 5, 0);
  assert_near(ur_model_param(m, "c", -1), -2.5e-3, 0);
  assert_near(ur_model_param(m, "d", -1), 3, 0);
  assert_near(ur_model_param(m, "e", -1), 0, 0);
  assert_near(ur_model_param(m, "f", -1), 2.5e-3, 0);
  assert_near(ur_model_param(m, "g", -1), 1e-300, 1e-310);
  assert_near(ur_model_param(m, "h", -1), 0.03, 1e-17);
  assert_near(ur_model_param(m, "i", -1), 7, 0);
  ur_model_free(m);
}


/* every unit of the table */
static void test_units(void** state) {
  static const struct {
    const char* unit;
    double f;
  } u[] = {{"m", 1},     {"mm", 1e-3},    {"cm", 1e-2}, {"kg", 1},
           {"g", 1e-3},  {"s", 1},        {"ms", 1e-3}, {"N", 1},
           {"kN", 1e3},  {"Pa", 1},       {"kPa", 1e3}, {"MPa", 1e6},
           {"GPa", 1e9}, {"atm", 101325}, {"bar", 1e5}, {"deg", M_PI / 180},
           {"rad", 1},   {"J", 1},        {"L", 1e-3},  {"none", 1}};
  for (size_t i = 0; i < sizeof(u) / sizeof(u[0]); i++) {
    char text[64], err[256];
    snprintf(text, sizeof(text), "param x 2.5 %s\n", u[i].unit);
    urModel* m = parse1(text, NULL, 0, err);
    assert_non_null(m);
    assert_near(ur_model_param(m, "x", -1), 2.5 * u[i].f, 1e-12 * 2.5 * u[i].f);
    ur_model_free(m);
  }
}

/* compound units (N*m/rad, kN/m): the factor, the SI unit a parameter keeps for show and save,
   and what is refused */
static void test_compound_units(void** state) {
  static const struct {
    const char* unit;
    double f;
    const char* si;
  } u[] = {{"kN/m", 1e3, "N/m"},  {"N*m/rad", 1, "N*m/rad"}, {"N*m*s/rad", 1, "N*m*s/rad"},
           {"N*s/m", 1, "N*s/m"}, {"atm", 101325, "Pa"},     {"deg", M_PI / 180, "rad"},
           {"mm", 1e-3, "m"},     {"kg/L", 1e3, "kg/m^3"},   {"none", 1, ""}};
  for (size_t i = 0; i < sizeof u / sizeof u[0]; i++) {
    double f;
    char si[32], text[64], err[256];
    assert_int_equal(ur_unit_parse(u[i].unit, &f, si, sizeof si), 0);
    assert_near(f, u[i].f, 1e-12 * u[i].f);
    assert_string_equal(si, u[i].si);
    snprintf(text, sizeof text, "param x 2 %s\n", u[i].unit);
    urModel* m = parse1(text, NULL, 0, err);
    assert_non_null(m);
    int k = ur_name_param(m, "x");
    assert_true(k >= 0);
    assert_string_equal(m->param[k].unit, u[i].si);
    ur_model_free(m);
  }
  static const char* const bad[] = {"kN/", "*m", "N**m", "N/furlong", "none*m", "", "N m"};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    double f;
    assert_int_equal(ur_unit_parse(bad[i], &f, NULL, 0), -1);
  }
  char err[256];
  assert_null(parse1("param x 2 N/furlong\n", NULL, 0, err));
  assert_non_null(strstr(err, "unknown unit 'N/furlong'"));
  /* no unit: none kept */
  urModel* m = parse1("param x 2\n", NULL, 0, err);
  assert_non_null(m);
  assert_string_equal(m->param[ur_name_param(m, "x")].unit, "");
  ur_model_free(m);
}

/* lexical rules: BOM, CRLF, tabs, comment after '\\', lists wrapped after ',', '#' in a word */
static void test_lexical(void** state) {
  char err[256];
  urModel* m = parse1(
      "\xEF\xBB\xBFparam\ta 2\r\n"
      "curve c x=0, 1,\t2 \\  # comment after the backslash\r\n"
      "   ,3 y=0,1,4,9#comment glued to a word\r\n"
      "body b parent=world joint=free pos=0,0,$a#x\r\n"
      "   mass=1 inertia=1,1,1\n",
      NULL, 0, err);
  assert_null(m);
  assert_string_equal(err, "t.urm:4: body 'b': missing key 'mass'; expected mass=VALUE");
  m = parse1(
      "\xEF\xBB\xBFparam\ta 2\r\n"
      "curve c x=0, 1,\t2 \\  # comment after the backslash\r\n"
      "   ,3 y=0,1,4,9#comment glued to a word\r\n"
      "body b parent=world joint=free pos=0,0,$a # a comment ends in \\\r\n"
      "   mass=1 inertia=1,1,1\n",
      NULL, 0, err);
  assert_null(m);
  assert_string_equal(err, "t.urm:4: body 'b': missing key 'mass'; expected mass=VALUE");
  m = parse1(
      "\xEF\xBB\xBFparam\ta 2\r\n"
      "curve c x=0, 1,\t2 \\  # comment after the backslash\r\n"
      "   ,3 y=0,1,4,9#comment glued to a word\r\n"
      "law l type=table load=c\n"
      "body b parent=world joint=free pos=0,0,$a \\\r\n"
      "   mass=1 inertia=1,1,1\n"
      "ellipsoid e body=b pos=0,0,0 size=1,1,1\n"
      "pair p a=e b=ground law=l\n",
      NULL, 0, err);
  if (!m) {
    print_error("%s\n", err);
  }
  assert_non_null(m);
  assert_near(ur_model_param(m, "a", -1), 2, 0);
  assert_int_equal(m->pair[0].law.load.n, 4);
  assert_near(m->pair[0].law.load.x[3], 3, 0);
  assert_near(m->pair[0].law.load.y[3], 9, 0);
  assert_near(m->body[0].pos[2], 2, 0);
  ur_model_free(m);
}

//---------------------------------- overrides and enable ------------------------------------------

/* overrides replace the value wherever the param is used; unknown overrides are errors */
static void test_overrides(void** state) {
  char err[256];
  urOverride ov[] = {{"L", 0.8}, {"p0", 2e5}, {"ang", 0.1}};
  urModel* m = parse1(model_text, ov, 3, err);
  assert_non_null(m);
  assert_near(ur_model_param(m, "L", -1), 0.8, 0);
  assert_near(m->body[ur_name_body(m, "pivot")].com[2], -0.8, 0);
  assert_near(m->geom[ur_name_geom(m, "bob")].pos[2], -0.8, 0);
  assert_near(m->bag[0].gas.p0, 2e5, 0);
  assert_near(m->body[ur_name_body(m, "neck")].rst[1].hi, 0.1, 0);
  assert_near(m->body[ur_name_body(m, "neck")].rst[1].lo, -0.1, 0);
  ur_model_free(m);

  /* an override of a name no text defines */
  urOverride bad[] = {{"L", 0.8}, {"nope", 1}};
  m = parse1(model_text, bad, 2, err);
  assert_null(m);
  assert_non_null(strstr(err, "override 'nope'"));

  /* a non-finite override */
  urOverride inf[] = {{"L", INFINITY}};
  m = parse1(model_text, inf, 1, err);
  assert_null(m);
  assert_non_null(strstr(err, "override 'L'"));
  assert_non_null(strstr(err, "not a finite number"));
}


/* enable=0 removes the elements; a reference to a disabled element is dangling */
static void test_enable(void** state) {
  char err[256];
  urOverride off = {"use_bag", 0};
  urModel* m = parse1(model_text, &off, 1, err);
  assert_non_null(m);
  assert_int_equal(m->nbag, 0);
  assert_int_equal(m->ngeom, 3);
  assert_int_equal(m->nsensor, 6);
  assert_int_equal(ur_name_geom(m, "bag"), -1);
  assert_int_equal(ur_name_sensor(m, "bagp"), -1);
  ur_model_free(m);

  /* the airbag without its enable flag refers to the disabled ellipsoid */
  char* text = strdup(model_text);
  char* e = strstr(text, "fabric_k=100 enable=$use_bag");
  assert_non_null(e);
  memcpy(strstr(e, "enable=$use_bag"), "fabric_c=0.0000", 15);
  m = parse1(text, &off, 1, err);
  assert_null(m);
  assert_string_equal(err,
                      "t.urm:34: dangling reference to ellipsoid 'bag' (disabled by "
                      "enable=0 at t.urm:33)");

  /* enabled explicitly it works */
  m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->nbag, 1);
  ur_model_free(m);
  free(text);

  /* alternatives: a disabled and an enabled element of one name; joint sensors see the disabled */
  m = parse1(
      "param small 0\nparam large 1\n"
      "body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1 enable=$small\n"
      "body b parent=world joint=free pos=0,0,0 mass=9 inertia=1,1,1 enable=$large\n"
      "body n parent=b joint=revolute pos=0,0,0 mass=1 jname=nj enable=$small\n"
      "sensor s type=jointload obj=nj\n",
      NULL, 0, err);
  assert_null(m);
  assert_string_equal(err,
                      "t.urm:6: dangling reference to joint 'nj' (disabled by enable=0 at "
                      "t.urm:5)");
  m = parse1(
      "param small 0\nparam large 1\n"
      "body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1 enable=$small\n"
      "body b parent=world joint=free pos=0,0,0 mass=9 inertia=1,1,1 enable=$large\n",
      NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->nbody, 1);
  assert_near(m->body[0].mass, 9, 0);
  ur_model_free(m);

  /* enable must be 0 or 1; a disabled statement still has its keys checked */
  m = parse1(
      "param x 2\nbody b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1 "
      "enable=$x\n",
      NULL, 0, err);
  assert_null(m);
  assert_string_equal(err, "t.urm:2: key 'enable' must be 0 or 1 (got 2)");
  m = parse1("body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1 enable=0 maas=2\n",
             NULL, 0, err);
  assert_null(m);
  assert_non_null(strstr(err, "t.urm:1: unknown key 'maas' for body"));
}

/* curve scales, a restraint's saturation, a foam law's lock strain and backing reach the model */
static void test_scales_lock_sat(void** state) {
  char err[256];
  urModel* m = parse1(
      "param s 2 MPa\n"
      "body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
      "body c parent=b joint=revolute pos=0,0,0 mass=1\n"
      "restraint c dof=0 k=5000 sat=400\n"
      "ellipsoid e body=b pos=0,0,0 size=0.1,0.1,0.1\n"
      "curve c x=0,0.5,0.9 y=0,1,4 xscale=1 yscale=$s\n"
      "curve d x=0,1 y=0,3 xscale=0.25\n"
      "law h type=hertz E1=2.23e7 nu1=0.29 R1=0.0875 E2=5.48e10 nu2=0.34 R2=0\n"
      "law f type=foam stress=c thickness=0.04 unload_r=0.2 unload_p=4 lock=0.9 "
      "backing=h\n"
      "law t type=table load=d\n"
      "pair p a=e b=ground law=f\n"
      "pair q a=e b=ground law=t\n",
      NULL, 0, err);
  assert_non_null(m);
  const urLaw* f = &m->pair[0].law;
  assert_near(f->stress.y[2], 8e6, 0);
  assert_near(f->stress.x[1], 0.5, 0);
  assert_near(f->lock, 0.9, 0);
  double K, dy, fy;
  ur_law_hertz_params(&m->pair[0].law, &K, &dy, &fy);
  urLaw h;
  memset(&h, 0, sizeof h);
  ur_law_hertz(&h, 2.23e7, 0.29, 0.0875, 5.48e10, 0.34, 0, 0, 0, 0);
  ur_law_hertz_params(&h, &K, &dy, &fy);
  assert_near(f->backing_k, K, 1e-9 * K);
  assert_near(m->pair[1].law.load.x[1], 0.25, 0);
  assert_near(m->pair[1].law.load.y[1], 3, 0);
  assert_near(m->body[1].rst[0].sat, 400, 0);
  assert_near(m->body[1].rst[0].k, 5000, 0);
  ur_model_free(m);
}

/* a parameter's range and reason reach the model, in SI; an override is held to it; a later
   definition without a range keeps the earlier one */
static void test_param_range(void** state) {
  char err[256];
  const char* text =
      "param k 26 kN/m range=2.6,260 why=a chest; stiffer is rigid\n"
      "param free 1\n";
  urModel* m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  int k = ur_name_param(m, "k"), f = ur_name_param(m, "free");
  assert_near(m->param[k].lo, 2600, 0);
  assert_near(m->param[k].hi, 260000, 0);
  assert_string_equal(m->param[k].why, "a chest; stiffer is rigid");
  assert_true(ur_param_accepts(&m->param[k], 2600) && ur_param_accepts(&m->param[k], 260000));
  assert_false(ur_param_accepts(&m->param[k], 2599.9) || ur_param_accepts(&m->param[k], NAN));
  assert_true(isinf(m->param[f].lo) && isinf(m->param[f].hi) && !m->param[f].why[0]);
  assert_true(ur_param_accepts(&m->param[f], -1e300));
  ur_model_free(m);

  urOverride ov = {"k", 1e300};
  assert_null(parse1(text, &ov, 1, err));
  assert_string_equal(err,
                      "t.urm:1: param 'k': the value set, 1e+300 N/m, is outside its range 2600 "
                      "to 260000 N/m: a chest; stiffer is rigid");
  ov.value = 260000;
  m = parse1(text, &ov, 1, err);
  assert_non_null(m);
  ur_model_free(m);

  urModelSource src[2] = {{text, "a.urm", 1}, {"param k 30 kN/m\n", "b.urm", 1}};
  m = ur_model_parse(src, 2, NULL, 0, err, sizeof err);
  assert_non_null(m);
  k = ur_name_param(m, "k");
  assert_near(m->param[k].value, 30000, 0);
  assert_near(m->param[k].hi, 260000, 0);
  ur_model_free(m);
  src[1].text = "param k 300 kN/m\n";
  assert_null(ur_model_parse(src, 2, NULL, 0, err, sizeof err));
  assert_string_equal(err,
                      "b.urm:1: param 'k': its value 300000 N/m is outside its range 2600 "
                      "to 260000 N/m: a chest; stiffer is rigid");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_model_fields), cmocka_unit_test(test_numbers_accepted),
      cmocka_unit_test(test_units),        cmocka_unit_test(test_compound_units),
      cmocka_unit_test(test_lexical),      cmocka_unit_test(test_overrides),
      cmocka_unit_test(test_enable),       cmocka_unit_test(test_scales_lock_sat),
      cmocka_unit_test(test_param_range),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
