/* test_modellang_parts.c: the model language beyond one text's fields: roles and presets
 * (the model's own names, SI values and workbench settings), contact pairs and their degrees,
 * several sources with their own line numbers, and the split of a text into parts. */
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

/* a preset may set a parameter of a later source (airbags.urm's presets set sim.urm's tmax),
   with a unit; a key no source declares stays a workbench setting */
static void test_preset_later_param(void** state) {
  char err[256];
  urModelSource src[2] = {{"body b parent=world joint=free pos=0,0,0 mass=1 inertia=1,1,1\n"
                           "preset A tmax=400ms window=0.12 area_chute=0\n",
                           "bags.urm"},
                          {"param tmax 0.15 s\nparam window 0.06 s\n", "sim.urm"}};
  urModel* m = ur_model_parse(src, 2, NULL, 0, err, sizeof(err));
  assert_non_null(m);
  const urPreset* a = m->preset;
  assert_int_equal(a->param[0], ur_name_param(m, "tmax"));
  assert_true(a->param[0] >= 0);
  assert_near(a->value[0], 0.4, 1e-15);
  assert_int_equal(a->param[1], ur_name_param(m, "window"));
  assert_true(a->param[1] >= 0);
  assert_int_equal(a->param[2], -1);
  ur_model_free(m);
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

/* ur_model_words: the parser's words with their places in the text (what model save edits):
   comments dropped, a continued line one statement, blanks next to ',' inside one word */
static void test_words(void** state) {
  (void)state;
  const char* text =
      "# a comment\nparam a 1.5 atm  # why\n\npreset A a=2atm \\\n  b=3\n"
      "ellipsoid e pos=0, 0.1 ,0\n";
  urModelWord* w;
  int n;
  char err[200];
  assert_int_equal(ur_model_words(text, &w, &n, err, sizeof err), 0);
  const char* want[] = {"param",  "a",   "1.5",       "atm", "preset",       "A",
                        "a=2atm", "b=3", "ellipsoid", "e",   "pos=0, 0.1 ,0"};
  const int stmt[] = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2};
  assert_int_equal(n, 11);
  for (int i = 0; i < n; i++) {
    assert_int_equal(w[i].len, strlen(want[i]));
    assert_memory_equal(text + w[i].at, want[i], w[i].len);
    assert_int_equal(w[i].stmt, stmt[i]);
  }
  free(w);
  assert_int_equal(ur_model_words("# nothing\n\n", &w, &n, err, sizeof err), 0);
  assert_int_equal(n, 0);
  assert_null(w);
  assert_int_equal(ur_model_words("param a 1 \\", &w, &n, err, sizeof err), -1);
  assert_true(!strncmp(err, "model:1: '\\' at the end of the text continues nothing", 50));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_words),   cmocka_unit_test(test_roles_presets),
      cmocka_unit_test(test_pairs),   cmocka_unit_test(test_degree),
      cmocka_unit_test(test_sources), cmocka_unit_test(test_preset_later_param),
      cmocka_unit_test(test_split),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
