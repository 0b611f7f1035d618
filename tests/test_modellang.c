/* test_modellang.c: the model language: a small model (pendulum, universal neck with restraint
 * and curve, Hertz and foam laws, airbag, sensors) parsed into the expected model fields, unit
 * conversions, overrides, enable flags, strict numbers, one malformed case per error with its
 * exact FILE:LINE, several sources, and the split into parts. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <cmocka.h>
#include "uasrisk/modellang.h"

//---------------------------------- helpers -------------------------------------------------------

/* |a - b| <= tol with both values printed on failure */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)
static void near_(double a, double b, double tol, const char* what, const char* file, int line) {
  if (!(fabs(a - b) <= tol)) {
    print_error("%s = %.17g, expected %.17g +- %.3g\n", what, a, b, tol);
    _fail(file, line);
  }
}


/* parse one text named t.urm */
static urModel* parse1(const char* text, const urOverride* ov, int nov, char* err) {
  urModelSource src = {text, "t.urm"};
  return ur_model_parse(&src, 1, ov, nov, err, 256);
}


/* the test model; line numbers matter for the enable test (bag lines 33-35) */
static const char* model_text =
    "# test model: a pendulum, a universal neck, a drone with an airbag\n"                 /* 1 */
    "param L 500 mm              # pendulum length\n"                                      /* 2 */
    "param m_bob 2000 g\n"                                                                 /* 3 */
    "param ang 30 deg\n"                                                                   /* 4 */
    "param p0 1.1 atm\n"                                                                   /* 5 */
    "param use_bag 1\n"                                                                    /* 6 */
    "param E_s 22.3 MPa\n"                                                                 /* 7 */
    "option dt=2e-5 tmax=0.1 gravity=0,0,-9.81 integrator=rk4 t_quiet=0.01\n"              /* 8 */
    "curve neck_m x=0,0.1,0.2,0.5 \\\n"                                                    /* 9 */
    "             y=0,5,15,60\n"                                                           /* 10 */
    "curve foam_s x=0, 0.5, 0.8 y=0,1e5,1e6\n"                                             /* 11 */
    "\n"                                                                                   /* 12 */
    "part pendulum\n"                                                                      /* 13 */
    "body pivot parent=world joint=revolute pos=0,0,2 axis=0,2,0 mass=$m_bob \\\n"         /* 14 */
    "     com=0,0,-$L inertia=0.01,0.02,0.03\n"                                            /* 15 */
    "ellipsoid bob body=pivot pos=0,0,-$L size=0.1,0.1,0.1\n"                              /* 16 */
    "body neck parent=pivot joint=universal pos=0,0,-0.6 rot=0,0,1,90 mass=1 \\\n"         /* 17 */
    "     inertia=0.01,0.02,0.03,0.001,0,0 axis=1,0,0 axis2=0,1,0 jname=neck_j\n"          /* 18 */
    "restraint neck dof=1 k=10 load=neck_m c=0.5 lo=-$ang hi=$ang kstop=1e3\n"             /* 19 */
    "ellipsoid head body=neck pos=0,0,-0.1 size=0.08,0.07,0.1 rot=1,0,0,90\n"              /* 20 */
    "law scalp type=hertz E1=$E_s nu1=0.29 R1=0.0875 E2=5.48e10 nu2=0.34 R2=0 \\\n"        /* 21 */
    "    sy=3.42e6 nu_yield=0.29 plastic=1 mu=0.3 v_eps=0.01\n"                            /* 22 */
    "law soft type=foam stress=foam_s thickness=0.05 unload_r=0.2 unload_p=3 damping=10\n" /* 23 */
    "law tab type=table load=neck_m chi=0.2\n"                                             /* 24 */
    "pair bob_ground a=bob b=ground law=soft\n"                                            /* 25 */
    "pair head_ground a=head b=ground law=scalp\n"                                         /* 26 */
    "\n"                                                                                   /* 27 */
    "part drone\n"                                                                         /* 28 */
    "body ra3 parent=world joint=free pos=1,0,3 mass=15 inertia=0.5,0.5,0.8 gravity=0\n"   /* 29 */
    "ellipsoid frame body=ra3 pos=0,0,0 size=0.4,0.4,0.1\n"                                /* 30 */
    "pair frame_head a=frame b=head law=tab\n"                                             /* 31 */
    "# the bag and what refers to it\n"                                                    /* 32 */
    "ellipsoid bag body=ra3 pos=0,0,-0.15 size=0.3,0.3,0.1 enable=$use_bag\n"              /* 33 */
    "airbag bag_b geom=bag p0=$p0 patm=101325 v0=0.02 gamma=1.4 kappa=0.5 thickness=0.1 \\\n" /* 34 */
    "       targets=head,bob fabric_k=100 enable=$use_bag\n"    /* 35 */
    "sensor bagp type=airbag obj=bag_b enable=$use_bag\n"       /* 36 */
    "sensor head_acc type=accel obj=neck pos=0,0,-0.1\n"        /* 37 */
    "sensor neck_load type=jointload obj=neck_j rot=0,0,1,90\n" /* 38 */
    "sensor neck_q type=jointpos obj=neck dof=1\n"              /* 39 */
    "sensor piv_w type=jointvel obj=pivot\n"                    /* 40 */
    "sensor hc type=contact obj=head_ground\n"                  /* 41 */
    "sensor dp type=bodypos obj=ra3\n";                         /* 42 */

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

//---------------------------------- malformed texts -----------------------------------------------

/* a valid preamble of three lines; each case adds lines from line 4 */
#define PRE                                                                                        \
  "param a 1\n"                                                                                    \
  "body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"                                \
  "ellipsoid e body=b pos=0,0,0 size=1,1,1\n"
#define BODY_C "body c parent=b joint=revolute pos=0,0,0 "

static const struct {
  const char* text;
  const char* msg; /* the whole message, or its start when it ends in '*' */
} bad[] = {
    {PRE "bdy c parent=world\n",
     "x.urm:4: unknown keyword 'bdy'; expected one of param, option, curve, body, restraint, "
     "ellipsoid, law, pair, pairs, airbag, sensor, part, role, preset"},
    {PRE BODY_C "mass=\n", "x.urm:4: missing value for key 'mass'; expected mass=VALUE"},
    {PRE BODY_C "mass=1 colour=red\n",
     "x.urm:4: unknown key 'colour' for body; expected one of "
     "parent, joint, pos, quat, rot, mass, com, inertia, axis, axis2, jname, gravity, enable"},
    {PRE BODY_C "mass=1 mass=2\n", "x.urm:4: duplicate key 'mass' (first given on line 4)*"},
    {PRE BODY_C "mass=-4.5\n", "x.urm:4: body 'c': mass must be > 0 (got -4.5)"},
    {PRE BODY_C "mass=0\n", "x.urm:4: body 'c': mass must be > 0 (got 0)"},
    {PRE "ellipsoid f body=b pos=0,0,0 size=1,0,1\n",
     "x.urm:4: ellipsoid 'f': semi-axes must be > 0 (got 1,0,1)"},
    {PRE BODY_C "mass=nan\n", "x.urm:4: key 'mass': 'nan' is not a finite number*"},
    {PRE BODY_C "mass=inf\n", "x.urm:4: key 'mass': 'inf' is not a finite number*"},
    {PRE BODY_C "mass=-Infinity\n", "x.urm:4: key 'mass': '-Infinity' is not a finite number*"},
    {PRE BODY_C "mass=1e400\n", "x.urm:4: key 'mass': '1e400' is not a finite number*"},
    {PRE BODY_C "mass=1e-400\n", "x.urm:4: key 'mass': '1e-400' is too small*"},
    {PRE BODY_C "mass=1.5x\n",
     "x.urm:4: key 'mass': '1.5x' is not a number (unexpected 'x' after '1.5')*"},
    {PRE BODY_C "mass=1e\n", "x.urm:4: key 'mass': '1e' is not a number (unexpected 'e'*"},
    {PRE BODY_C "mass=0x1p3\n",
     "x.urm:4: key 'mass': '0x1p3' is not a decimal number "
     "(hexadecimal is not accepted)*"},
    {PRE BODY_C "mass=a\n", "x.urm:4: key 'mass': 'a' is not a number (for a parameter write $a)*"},
    {PRE BODY_C "mass=1 com=0,,0\n", "x.urm:4: key 'com': empty number*"},
    {PRE BODY_C "mass=1 com=0,0\n", "x.urm:4: key 'com' needs 3 numbers (got 2)"},
    {PRE BODY_C "mass=1 inertia=1,1,1,0\n", "x.urm:4: key 'inertia' needs 3 or 6 numbers (got 4)"},
    {PRE BODY_C "mass=1 inertia=1,1,-1\n", "x.urm:4: body 'c': inertia must be positive definite*"},
    {PRE BODY_C "mass=1 inertia=1,1,1,2,0,0\n",
     "x.urm:4: body 'c': inertia must be positive definite*"},
    {PRE BODY_C "mass=1 joint=fixed\n", "x.urm:4: duplicate key 'joint'*"},
    {PRE "body c parent=b joint=hinge pos=0,0,0 mass=1\n",
     "x.urm:4: key 'joint': unknown value "
     "'hinge'; expected one of free/fixed/revolute/universal/spherical/prismatic"},
    {PRE "body c parent=b joint=revolute mass=1\n",
     "x.urm:4: body 'c': missing key 'pos'; expected pos=VALUE"},
    {PRE "body c parent=bb joint=revolute pos=0,0,0 mass=1\n",
     "x.urm:4: dangling reference to body 'bb'; did you mean 'b'?"},
    {PRE "law l type=hertz E1=1e9 nu1=0.3 R1=0.1 E2=1e9 nu2=0.3 R2=0\n"
         "pair p a=hed b=ground law=l\n",
     "x.urm:5: dangling reference to ellipsoid 'hed'*"},
    {PRE "pair p a=e b=ground law=l\nlaw l type=table load=c\n",
     "x.urm:4: dangling reference to law 'l' (defined later, at x.urm:5; define it before use)"},
    {PRE "curve c x=0,2,1 y=0,1,2\n",
     "x.urm:4: curve 'c': x must be strictly ascending "
     "(x[3] = 1 after x[2] = 2)"},
    {PRE "curve c x=0,1,2 y=0,1\n", "x.urm:4: curve 'c': x has 3 points but y has 2*"},
    {PRE "curve c x=0 y=0\n", "x.urm:4: key 'x' needs 2 to 48 numbers (got 1)"},
    {PRE "ellipsoid e body=b pos=0,0,0 size=1,1,1\n",
     "x.urm:4: duplicate ellipsoid name 'e' (first defined at x.urm:3); names must be unique"},
    {PRE "param a 2\n", "x.urm:4: duplicate parameter name 'a' (first defined at x.urm:1)*"},
    {PRE BODY_C "mass=$later\nparam later 2\n",
     "x.urm:4: key 'mass': parameter 'later' used "
     "before its definition (at x.urm:5)*"},
    {PRE BODY_C "mass=$zz\n", "x.urm:4: key 'mass': unknown parameter 'zz'*"},
    {PRE "param q 3 furlong\n",
     "x.urm:4: param 'q': unknown unit 'furlong'; expected one of m, "
     "mm, cm, kg, g, s, ms, N, kN, Pa, kPa, MPa, GPa, atm, bar, deg, rad, J, L, none, or several "
     "joined by * and / (N*m/rad)"},
    {PRE "param q\n", "x.urm:4: param takes NAME VALUE [UNIT]; got 1 word(s) after 'param'"},
    {PRE "param 9q 1\n", "x.urm:4: param: '9q' is not a valid name*"},
    {PRE "body abcdefghijabcdefghijabcdefghijkl parent=world joint=fixed pos=0,0,0 mass=1\n",
     "x.urm:4: body: name 'abcdefghijabcdefghijabcdefghijkl' is too long (32 characters)*"},
    {PRE "body parent=world joint=fixed pos=0,0,0 mass=1\n",
     "x.urm:4: body needs a NAME before its keys*"},
    {PRE "body world parent=world joint=fixed pos=0,0,0 mass=1\n",
     "x.urm:4: body name 'world' is reserved*"},
    {PRE BODY_C "mass=1 axis2=0,1,0\n",
     "x.urm:4: body 'c': key 'axis2' applies only to universal joints"},
    {PRE "body c parent=b joint=universal pos=0,0,0 mass=1 axis=1,0,0 axis2=2,0,0\n",
     "x.urm:4: body 'c': universal joint axes are parallel*"},
    {PRE "body c parent=b joint=spherical pos=0,0,0 mass=1\n",
     "x.urm:4: body 'c': a spherical joint needs inertia=xx,yy,zz[,xy,xz,yz]"},
    {PRE "restraint b dof=0 k=1\n", "x.urm:4: restraint 'b': body 'b' has a free joint*"},
    {PRE BODY_C "mass=1\nrestraint c dof=1 k=1\n",
     "x.urm:5: restraint 'c': dof 1 is beyond the revolute joint (dof 0..0)"},
    {PRE BODY_C "mass=1\nrestraint c dof=0.5\n",
     "x.urm:5: key 'dof' must be a whole number >= 0 (got 0.5)"},
    {PRE BODY_C "mass=1\nrestraint c dof=0 lo=1 hi=0\n",
     "x.urm:5: restraint 'c': lo must be <= hi (got lo 1, hi 0)"},
    {PRE BODY_C "mass=1\nrestraint c dof=0 k=1\nrestraint c dof=0 c=1\n",
     "x.urm:6: restraint 'c': dof 0 is already restrained*"},
    {PRE "law l type=hertz E1=1e9 nu1=0.6 R1=0.1 E2=1e9 nu2=0.3 R2=0\n",
     "x.urm:4: law 'l': nu1 must be in [0, 0.5) (got 0.6)"},
    {PRE "law l type=table stress=c\n", "x.urm:4: unknown key 'stress' for law type=table*"},
    {PRE "law l type=rubber\n", "x.urm:4: key 'type': unknown value 'rubber'*"},
    {PRE "law l E1=1\n", "x.urm:4: law 'l': missing key 'type'*"},
    {PRE "law l type=table load=c\n", "x.urm:4: law: dangling reference to curve 'c'"},
    {PRE "law l type=table load=e\npair p a=e b=e law=l\n", "x.urm:4: law: dangling reference*"},
    {PRE "curve c x=0,1 y=0,1\nlaw l type=foam stress=c thickness=0 unload_r=0 unload_p=1\n",
     "x.urm:5: law 'l': thickness must be > 0 (got 0)"},
    {PRE "curve c x=0,1 y=0,1\nlaw l type=table load=c\npair p a=e b=e law=l\n",
     "x.urm:6: pair 'p': a and b are both on body 'b'*"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1\n"
         "airbag g geom=e p0=1 patm=1 v0=1 gamma=1.4 kappa=1 thickness=1 targets=f,f\n",
     "x.urm:6: airbag 'g': target 'f' is listed twice"},
    {PRE "airbag g geom=e p0=1 patm=1 v0=1 gamma=1.4 kappa=1 thickness=1 targets=e\n",
     "x.urm:4: airbag 'g': target 'e' is on the bag's own body 'b'"},
    {PRE "airbag g geom=e p0=1 patm=1 v0=-1 gamma=1.4 kappa=1 thickness=1 targets=e\n",
     "x.urm:4: airbag 'g': v0 must be > 0 (got -1)"},
    {PRE "sensor s type=jointpos obj=b\n",
     "x.urm:4: sensor 's': dof 0 does not exist on joint "
     "'b' (jointpos needs a revolute, universal or prismatic joint)"},
    {PRE "sensor s type=accel obj=b dof=1\n",
     "x.urm:4: sensor 's': key 'dof' applies only to jointpos and jointvel"},
    {PRE "sensor s type=contact obj=b\n", "x.urm:4: dangling reference to pair 'b'"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1\ncurve k x=0,1 y=0,1\nlaw l type=table load=k\n"
         "pairs abcdefghijabcdefghijabcdefgh a=e b=f,ground law=l\n",
     "x.urm:8: pairs 'abcdefghijabcdefghijabcdefgh': the pair name "
     "'abcdefghijabcdefghijabcdefgh_e_f' is too long (32 characters, at most 31); shorten NAME or "
     "the ellipsoid names"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1\ncurve k x=0,1 y=0,1\nlaw l type=table load=k\n"
         "pairs q a=f,e b=f law=l\n",
     "x.urm:8: pairs 'q': 'f' and 'f' are both on body 'c'; expected ellipsoids of two bodies"},
    {PRE "curve k x=0,1 y=0,1\nlaw l type=table load=k\npairs q a=e b=x law=l\n",
     "x.urm:6: dangling reference to ellipsoid 'x'"},
    {PRE "ellipsoid f body=b pos=0,0,0 size=1,1,1 degree=1.5\n",
     "x.urm:4: ellipsoid 'f': degree must be in [2, 20] (got 1.5); 2 is the ellipsoid, larger "
     "values flatten it towards a box"},
    {PRE "ellipsoid f body=b pos=0,0,0 size=1,1,1 degree=20.5\n",
     "x.urm:4: ellipsoid 'f': degree must be in [2, 20] (got 20.5)*"},
    {PRE "ellipsoid f body=b pos=0,0,0 size=1,1,1 degree=4,4\n", "x.urm:4: key 'degree'*"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1 degree=4\n"
         "curve k x=0,1 y=0,1\nlaw l type=foam stress=k thickness=0.1 unload_r=0 unload_p=1\n"
         "pair p a=f b=e law=l\n",
     "x.urm:8: pair 'p': ellipsoid 'f' (x.urm:5) has degree=4; a, under a foam law, must have "
     "degree 2 (its section area and cap volume are those of an ellipsoid)"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1 degree=2.5\n"
         "curve k x=0,1 y=0,1\nlaw l type=foam stress=k thickness=0.1 unload_r=0 unload_p=1\n"
         "pairs q a=e,f b=ground law=l\n",
     "x.urm:8: pairs 'q': ellipsoid 'f' (x.urm:5) has degree=2.5; each a, under a foam law, must "
     "have degree 2*"},
    {PRE "body c parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
         "ellipsoid f body=c pos=0,0,0 size=1,1,1 degree=8\n"
         "airbag g geom=e p0=1 patm=1 v0=1 gamma=1.4 kappa=1 thickness=1 targets=f\n",
     "x.urm:6: airbag 'g': ellipsoid 'f' (x.urm:5) has degree=8; a target must have degree 2 (its "
     "section area and cap volume are those of an ellipsoid)"},
    {PRE "option dt=0\n", "x.urm:4: option dt must be > 0 (got 0)"},
    {PRE "option integrator=leapfrog\n",
     "x.urm:4: key 'integrator': unknown value 'leapfrog'; expected one of euler/rk4"},
    {PRE "part\n", "x.urm:4: part takes exactly one NAME; expected 'part NAME'"},
    {PRE "part h\npart h\n", "x.urm:5: duplicate part name 'h' (first defined at x.urm:4)*"},
    {PRE "body c parent=b joint=revolute \\\n  pos=0,0 \\\n  mass=1\n",
     "x.urm:5: key 'pos' needs 3 numbers (got 2)"},
    {PRE "body c parent=b joint=revolute pos=0,0,0 mass=1 \\\n",
     "x.urm:4: '\\' at the end of the text continues nothing*"},
    {PRE BODY_C "mass=1 pos =1,2,3\n",
     "x.urm:4: body: expected key=value, got 'pos' (no blanks around '=')"},
    {PRE BODY_C "mass=1 com= 1,2,3\n", "x.urm:4: missing value for key 'com'*"},
    {PRE "curve c x=0,1 y=0,1 yscale=0\n", "x.urm:4: curve 'c': yscale must be > 0 (got 0)"},
    {PRE "curve c x=0,1 y=0,1 xscale=-2\n", "x.urm:4: curve 'c': xscale must be > 0 (got -2)"},
    {PRE BODY_C "mass=1\nrestraint c dof=0 k=1 sat=-3\n",
     "x.urm:5: restraint 'c': sat must be >= 0 (got -3)"},
    {PRE "curve c x=0,0.5 y=0,1\nlaw l type=foam stress=c thickness=0.1 unload_r=0 unload_p=1 "
         "lock=0.4\n",
     "x.urm:5: law 'l': lock and backing go together*"},
    {PRE "curve c x=0,0.5 y=0,1\nlaw h type=hertz E1=1e9 nu1=0.3 R1=0.1 E2=1e9 nu2=0.3 R2=0\n"
         "law l type=foam stress=c thickness=0.1 unload_r=0 unload_p=1 lock=0.6 backing=h\n",
     "x.urm:6: law 'l': lock must be in (0, 1) and within the stress curve (last strain 0.5; got "
     "0.6)"},
    {PRE "curve c x=0,0.5 y=0,1\nlaw t type=table load=c\n"
         "law l type=foam stress=c thickness=0.1 unload_r=0 unload_p=1 lock=0.5 backing=t\n",
     "x.urm:6: law 'l': backing 't' must be a hertz law"},
    {PRE "curve c x=0,0.5 y=0,1\n"
         "law l type=foam stress=c thickness=0.1 unload_r=0 unload_p=1 lock=0.5 backing=hh\n",
     "x.urm:5: law: dangling reference to law 'hh'*"},
};


/* one message per malformed text, with the exact file and line; nothing returned */
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

static void test_malformed(void** state) {
  int failures = 0;
  for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
    char err[256] = "untouched";
    urModelSource src = {bad[i].text, "x.urm"};
    urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof(err));
    size_t n = strlen(bad[i].msg);
    int prefix = n > 0 && bad[i].msg[n - 1] == '*';
    int ok = !m && (prefix ? !strncmp(err, bad[i].msg, n - 1) : !strcmp(err, bad[i].msg));
    if (!ok) {
      print_error("case %d: %s\n  got:      %s\n  expected: %s\n", (int)i,
                  m ? "parsed" : "wrong message", err, bad[i].msg);
      failures++;
    }
    ur_model_free(m);
  }
  assert_int_equal(failures, 0);
}


/* the preamble alone is valid (so each case fails because of its own lines) */
static void test_preamble_valid(void** state) {
  char err[256];
  urModelSource src = {PRE BODY_C "mass=1\n", "x.urm"};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof(err));
  assert_non_null(m);
  ur_model_free(m);
}


/* a short or absent message buffer is safe */
static void test_short_err(void** state) {
  char err[8];
  memset(err, 'z', sizeof(err));
  urModelSource src = {"bdy x\n", "x.urm"};
  assert_null(ur_model_parse(&src, 1, NULL, 0, err, 8));
  assert_string_equal(err, "x.urm:1");
  assert_null(ur_model_parse(&src, 1, NULL, 0, NULL, 0));
}

//---------------------------------- roles and presets --------------------------------------------

/* role statements name the drone, head and sensors (any names: the model's own); presets keep
   model parameters in SI (a unit after the number) and workbench settings as written */
static void test_roles_presets(void** state) {
  char err[256];
  char* text = malloc(strlen(model_text) + 600);
  strcpy(text, model_text);
  strcat(text,
         "sensor hp type=bodypos obj=neck\n"
         "role drone=ra3 head=head head_acc=head_acc neck=neck_load\n"
         "role head_pos=hp chest=neck_q\n"
         "preset X p0=1.5atm use_bag=1 area_chute=0\n"
         "preset Y2 p0=$p0 L=20mm\n");
  urModel* m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  const urRoles* r = &m->roles;
  assert_int_equal(r->drone, ur_name_body(m, "ra3"));
  assert_int_equal(r->head, ur_name_geom(m, "head"));
  assert_int_equal(r->head_acc, ur_name_sensor(m, "head_acc"));
  assert_int_equal(r->neck, ur_name_sensor(m, "neck_load"));
  assert_int_equal(r->head_pos, ur_name_sensor(m, "hp"));
  assert_int_equal(r->chest, ur_name_sensor(m, "neck_q"));
  assert_int_equal(r->abdomen, -1);
  assert_int_equal(r->mass_param, -1);
  assert_near(r->mass0, 15, 0);
  assert_int_equal(m->npreset, 2);
  const urPreset* x = m->preset;
  assert_string_equal(x->name, "X");
  assert_int_equal(x->n, 3);
  assert_string_equal(x->key[0], "p0");
  assert_near(x->value[0], 1.5 * 101325, 1e-9);
  assert_int_equal(x->param[0], ur_name_param(m, "p0"));
  assert_int_equal(x->param[1], ur_name_param(m, "use_bag"));
  assert_string_equal(x->key[2], "area_chute");
  assert_int_equal(x->param[2], -1); /* a workbench setting */
  assert_near(x->value[2], 0, 0);
  assert_near(m->preset[1].value[0], 1.1 * 101325, 1e-9);
  assert_near(m->preset[1].value[1], 0.02, 1e-15);
  ur_model_free(m);

  /* without role statements nothing is declared */
  m = parse1(model_text, NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->roles.drone, -1);
  assert_int_equal(m->roles.head, -1);
  assert_int_equal(m->npreset, 0);
  ur_model_free(m);

  /* one error per wrong statement, on its line */
  static const struct {
    const char* add;
    const char* msg;
  } wrong[] = {
      {"role drone=pivot\n",
       "t.urm:43: role drone: body 'pivot' must have a free joint to the "
       "world (the drone is placed and launched by it)"},
      {"role head_acc=neck_load\n",
       "t.urm:43: role head_acc: sensor 'neck_load' must be of "
       "type=accel"},
      {"role drone=nosuch\n", "t.urm:43: role: dangling reference to body 'nosuch'*"},
      {"role mass=15\n",
       "t.urm:43: role mass: expected a parameter ($NAME) that the workbench can "
       "set, got '15'"},
      {"role main\n", "t.urm:43: role takes key=value pairs only (no name)"},
      {"preset LONGNAME p0=1\n",
       "t.urm:43: preset 'LONGNAME': a preset name has at most 7 "
       "characters (it labels the rows of tables)"},
      {"preset A p0=1 p0=2\n", "t.urm:43: preset 'A': duplicate key 'p0'; a key may appear once"},
      {"preset A p0=1furlong\n", "t.urm:43: preset 'A' key 'p0': unknown unit 'furlong'*"},
      {"preset A mass=15kg\n",
       "t.urm:43: preset 'A' key 'mass': a unit is taken only by model "
       "parameters*"},
      {"preset A p0\n", "t.urm:43: preset 'A': expected key=value, got 'p0'*"},
      {"preset A p0=x\n", "t.urm:43: preset 'A' key 'p0': 'x' is not a number*"},
      {"preset A p0=1\npreset A p0=2\n", "t.urm:44: duplicate preset name 'A'*"},
  };
  int failures = 0;
  for (size_t i = 0; i < sizeof(wrong) / sizeof(wrong[0]); i++) {
    strcpy(text, model_text);
    strcat(text, wrong[i].add);
    char e[256] = "";
    urModel* mm = parse1(text, NULL, 0, e);
    size_t n = strlen(wrong[i].msg);
    int prefix = wrong[i].msg[n - 1] == '*';
    if (mm || (prefix ? strncmp(e, wrong[i].msg, n - 1) : strcmp(e, wrong[i].msg))) {
      print_error("case %d: got '%s'\n  expected '%s'\n", (int)i, e, wrong[i].msg);
      failures++;
    }
    ur_model_free(mm);
  }
  free(text);
  assert_int_equal(failures, 0);
}

//---------------------------------- pairs ---------------------------------------------------------

/* 'pairs' makes one pair NAME_A_B per combination of the two lists */
static void test_pairs(void** state) {
  const char* text =
      "param on 1\n"
      "body p parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
      "ellipsoid h body=p pos=0,0,0 size=1,1,1\n"
      "ellipsoid t body=p pos=0,0,1 size=1,1,1\n"
      "body d parent=world joint=free pos=0,0,3 mass=1 inertia=1,1,1\n"
      "ellipsoid f body=d pos=0,0,0 size=1,1,1\n"
      "law l type=hertz E1=1e9 nu1=0.3 R1=0.1 E2=1e9 nu2=0.3 R2=0 mu=0.2\n"
      "pairs c a=h,t b=f,\\\n"
      "ground law=l enable=$on\n"
      "sensor s type=contact obj=c_t_ground\n";
  char err[256];
  urModel* m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->npair, 4);
  static const char* const names[] = {"c_h_f", "c_h_ground", "c_t_f", "c_t_ground"};
  static const int g1[] = {0, 0, 1, 1}, g2[] = {2, -1, 2, -1};
  for (int i = 0; i < 4; i++) {
    assert_string_equal(m->pair[i].name, names[i]);
    assert_int_equal(m->pair[i].geom1, g1[i]);
    assert_int_equal(m->pair[i].geom2, g2[i]);
    assert_near(m->pair[i].law.mu, 0.2, 0);
  }
  assert_int_equal(m->sensor[0].obj, 3);
  ur_model_free(m);

  /* disabled: the generated names are dangling for the sensor */
  urOverride off = {"on", 0};
  m = parse1(text, &off, 1, err);
  assert_null(m);
  assert_string_equal(err,
                      "t.urm:10: dangling reference to pair 'c_t_ground' (disabled by "
                      "enable=0 at t.urm:8)");

  /* too long generated names and pairs on one body: see test_malformed */
}

/* degree=: default 2 (the ellipsoid, bounding radius the largest semi-axis), a number or $param
   stored with the exact bounding radius ||r||_k, k = 2p/(p-2); superellipsoids allowed as a
   pair's b under a foam law, under other laws and as an airbag's own bag; the refusals and
   the range are in test_malformed */
static void test_degree(void** state) {
  const char* text =
      "param deg 4\n"
      "body p parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
      "ellipsoid h body=p pos=0,0,0 size=0.1,0.2,0.3\n"
      "ellipsoid t body=p pos=0,0,1 size=0.1,0.2,0.3 degree=2\n"
      "body d parent=world joint=free pos=0,0,3 mass=1 inertia=1,1,1\n"
      "ellipsoid f body=d pos=0,0,0 size=0.4,0.3,0.1 degree=$deg\n"
      "ellipsoid bag body=d pos=0,0,-0.1 size=0.3,0.3,0.1 degree=8.5\n"
      "curve k x=0,1 y=0,1e5\n"
      "law fo type=foam stress=k thickness=0.05 unload_r=0.2 unload_p=3\n"
      "law l type=hertz E1=1e9 nu1=0.3 R1=0.1 E2=1e9 nu2=0.3 R2=0\n"
      "pairs c a=h,t b=f law=fo\n"
      "pair fg a=f b=ground law=l\n"
      "airbag ab geom=bag p0=1 patm=1 v0=1 gamma=1.4 kappa=1 thickness=1 targets=h\n";
  char err[256];
  urModel* m = parse1(text, NULL, 0, err);
  assert_non_null(m);
  assert_int_equal(m->ngeom, 4);
  assert_true(m->geom[0].degree == 2 && m->geom[1].degree == 2);
  assert_true(m->geom[0].rbound == 0.3 && m->geom[1].rbound == 0.3);
  assert_true(m->geom[2].degree == 4 && m->geom[3].degree == 8.5);
  assert_near(m->geom[2].rbound, pow(pow(0.4, 4) + pow(0.3, 4) + pow(0.1, 4), 0.25), 1e-15);
  double k = 2 * 8.5 / 6.5;
  assert_near(m->geom[3].rbound, pow(2 * pow(0.3, k) + pow(0.1, k), 1 / k), 1e-15);
  ur_model_free(m);

  /* an override reaches it, and degree 2 by a parameter is the ellipsoid */
  urOverride two = {"deg", 2};
  m = parse1(text, &two, 1, err);
  assert_non_null(m);
  assert_true(m->geom[2].degree == 2 && m->geom[2].rbound == 0.4);
  ur_model_free(m);
}

//---------------------------------- several sources -----------------------------------------------

/* names and params are shared by the sources in order; messages name the right file */
static void test_sources(void** state) {
  char err[256];
  urModelSource src[3] = {
      {"param k 2\nbody b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n", "human.urm"},
      {"param k 3    # a later text may redefine a param\n"
       "body c parent=b joint=revolute pos=0,0,$k mass=$k\n",
       "ra3.urm"},
      {"\n\nbody d parent=q joint=fixed pos=0,0,0 mass=1\n", "bag.urm"}};
  urModel* m = ur_model_parse(src, 2, NULL, 0, err, sizeof(err));
  assert_non_null(m);
  assert_near(m->body[ur_name_body(m, "c")].mass, 3, 0);
  assert_near(ur_model_param(m, "k", -1), 3, 0);
  ur_model_free(m);

  /* an override replaces both definitions */
  urOverride ov = {"k", 5};
  m = ur_model_parse(src, 2, &ov, 1, err, sizeof(err));
  assert_non_null(m);
  assert_near(m->body[ur_name_body(m, "c")].pos[2], 5, 0);
  ur_model_free(m);

  /* the error is in the third source at its own line 3 */
  m = ur_model_parse(src, 3, NULL, 0, err, sizeof(err));
  assert_null(m);
  assert_string_equal(err, "bag.urm:3: dangling reference to body 'q'");
}

//---------------------------------- parts ---------------------------------------------------------

/* concatenating the parts gives back the text; names and lines */
static void test_split(void** state) {
  const char* text =
      "# preamble\n"
      "param a 1\n"
      "  part human   # the man\n"
      "body b parent=world joint=free pos=0,0,0 \\\n"
      "part=1 mass=1 inertia=1,1,1\n"
      "part ra3\n"
      "ellipsoid e body=b pos=0,0,0 size=1,1,1\n"
      "part bag_bottom\n"
      "# no newline at the end";
  urModelPart parts[8];
  char err[256];
  int n = ur_model_split(text, "t.urm", parts, 8, err, sizeof(err));
  assert_int_equal(n, 4);
  assert_string_equal(parts[0].name, "");
  assert_string_equal(parts[1].name, "human");
  assert_string_equal(parts[2].name, "ra3");
  assert_string_equal(parts[3].name, "bag_bottom");
  assert_int_equal(parts[0].line, 1);
  assert_int_equal(parts[1].line, 3);
  assert_int_equal(parts[2].line, 6);
  assert_int_equal(parts[3].line, 8);
  assert_true(!strncmp(parts[1].text, "  part human", 12));
  assert_true(!strncmp(parts[3].text, "part bag_bottom\n", 16));

  /* round trip */
  char joined[1024] = "";
  for (int i = 0; i < n; i++) {
    strncat(joined, parts[i].text, parts[i].len);
  }
  assert_string_equal(joined, text);

  /* counting only, and a short array */
  assert_int_equal(ur_model_split(text, "t.urm", NULL, 0, err, sizeof(err)), 4);
  assert_int_equal(ur_model_split(text, "t.urm", parts, 2, err, sizeof(err)), 4);
  assert_string_equal(parts[1].name, "human");
  assert_int_equal(parts[1].len, strlen("  part human   # the man\n"
                                        "body b parent=world joint=free pos=0,0,0 \\\n"
                                        "part=1 mass=1 inertia=1,1,1\n"));

  /* a text starting with its part line has no part ""; an empty text has no parts */
  n = ur_model_split("part x\nparam a 1\npart y\n", NULL, parts, 8, err, sizeof(err));
  assert_int_equal(n, 2);
  assert_string_equal(parts[0].name, "x");
  assert_int_equal(parts[0].len, 17);
  assert_int_equal(parts[1].len, 7);
  assert_int_equal(ur_model_split("", NULL, parts, 8, err, sizeof(err)), 0);
  n = ur_model_split("# only a comment\n", NULL, parts, 8, err, sizeof(err));
  assert_int_equal(n, 1);
  assert_int_equal(parts[0].len, 17);

  /* a text with parts parses (part is a no-op marker) */
  urModelSource src = {"part human\nparam a 1\npart ra3\nparam b $a\n", "t.urm"};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof(err));
  assert_non_null(m);
  ur_model_free(m);

  /* malformed part lines */
  assert_int_equal(ur_model_split("param a 1\npart a b\n", "p.urm", parts, 8, err, sizeof(err)),
                   -1);
  assert_true(!strncmp(err, "p.urm:2: part takes exactly one NAME", 36));
  assert_int_equal(
      ur_model_split("part a\npart b\n\npart a\n", "p.urm", parts, 8, err, sizeof(err)), -1);
  assert_string_equal(err,
                      "p.urm:4: duplicate part name 'a' (first at line 1); names must be "
                      "unique");
}

//---------------------------------- main ----------------------------------------------------------

/* a stop request ends the parse between statements; the limits end a model that is too large
   at the statement past them, in time linear in the text (issue 24, item 5) */
static void test_stop_and_limits(void** state) {
  char err[300];
  _Atomic int stop = 1;
  urModelSource src = {"param a 1\nparam b 2\n", "s.urm", 1};
  assert_null(ur_model_parse_stop(&src, 1, NULL, 0, &stop, err, sizeof err));
  assert_string_equal(err, "s.urm:1: stopped on request (interrupted)");
  stop = 0;
  urModel* m = ur_model_parse_stop(&src, 1, NULL, 0, &stop, err, sizeof err);
  assert_non_null(m);
  ur_model_free(m);

  /* 1001 bodies: refused at the 1001st, with the limit named */
  size_t cap = 1 << 20, n = 0;
  char* text = malloc(cap);
  n += (size_t)snprintf(text + n, cap - n,
                        "body b0 parent=world joint=free pos=0,0,0 mass=1 "
                        "inertia=1,1,1\n");
  for (int i = 1; i <= 1000; i++) {
    n += (size_t)snprintf(text + n, cap - n,
                          "body b%d parent=b%d joint=revolute pos=0,0,0.01 "
                          "mass=1\n",
                          i, i - 1);
  }
  urModelSource big = {text, "big.urm", 1};
  assert_null(ur_model_parse(&big, 1, NULL, 0, err, sizeof err));
  assert_string_equal(err,
                      "big.urm:1001: more than 1000 bodies in the model; accepted: at most "
                      "1000 (uasrisk-model(5), LIMITS)");

  /* 1000 bodies and 3999 parameters parse in well under a second (names by hash) */
  char* end = strstr(text, "body b1000 ");
  n = (size_t)(end - text);
  for (int i = 0; i < 3999; i++) n += (size_t)snprintf(text + n, cap - n, "param p%d %d\n", i, i);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  m = ur_model_parse(&big, 1, NULL, 0, err, sizeof err);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  if (!m) fail_msg("%s", err);
  ur_model_free(m);
  assert_true(t1.tv_sec - t0.tv_sec + 1e-9 * (t1.tv_nsec - t0.tv_nsec) < 1.0);

  /* 257 part lines: refused by the split */
  n = 0;
  for (int i = 0; i < 257; i++) n += (size_t)snprintf(text + n, cap - n, "part p%d\n", i);
  urModelPart parts[4];
  assert_int_equal(ur_model_split(text, "parts.urm", parts, 4, err, sizeof err), -1);
  assert_non_null(strstr(err, "parts.urm:257: more than 256 parts"));
  free(text);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_stop_and_limits),
      cmocka_unit_test(test_model_fields),
      cmocka_unit_test(test_numbers_accepted),
      cmocka_unit_test(test_units),
      cmocka_unit_test(test_compound_units),
      cmocka_unit_test(test_lexical),
      cmocka_unit_test(test_overrides),
      cmocka_unit_test(test_enable),
      cmocka_unit_test(test_preamble_valid),
      cmocka_unit_test(test_malformed),
      cmocka_unit_test(test_scales_lock_sat),
      cmocka_unit_test(test_short_err),
      cmocka_unit_test(test_roles_presets),
      cmocka_unit_test(test_pairs),
      cmocka_unit_test(test_degree),
      cmocka_unit_test(test_sources),
      cmocka_unit_test(test_split),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
