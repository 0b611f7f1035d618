/* test_modellang_errors.c: the model language's refusals: one malformed text per error with its
 * exact FILE:LINE and message (after a valid preamble), the short error buffer, a stop request
 * and the limits on a model's size. */
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
     "x.urm:4: unknown keyword 'bdy'; expected one of param, option, curve, material, section, layer, body, restraint, "
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
    {PRE "param q\n",
     "x.urm:4: param takes NAME VALUE [UNIT] [range=LO,HI [why=TEXT...]]; got 1 word(s) after "
     "'param'"},
    {PRE "param q 3 mm range=1,2 why=held by two stops\n",
     "x.urm:4: param 'q': its value 0.003 m is outside its range 0.001 to 0.002 m: held by two "
     "stops"},
    {PRE "param q 3 range=4,2\n",
     "x.urm:4: param 'q': range: LO must not exceed HI (got 4, 2 after conversion to SI)"},
    {PRE "param q 3 range=1\n",
     "x.urm:4: param 'q': range: '1' is not two numbers; expected range=LO,HI (in the unit of "
     "the value)"},
    {PRE "param q 3 range=1,x\n", "x.urm:4: param 'q': range: 'x' is not a number*"},
    {PRE "param q 3 why=no range\n",
     "x.urm:4: param 'q': why= explains a range; expected range=LO,HI before it"},
    {PRE "param q 3 m range=1,4 why=\n",
     "x.urm:4: param 'q': why= needs a reason of 1 to 159 characters (got 0)"},
    {PRE "param q 3 m range=1,4 stiff\n",
     "x.urm:4: param takes NAME VALUE [UNIT] [range=LO,HI [why=TEXT...]]; got 'stiff'"},
    {PRE "param q 3 m range=1,4 why=caf\xc3\xa9\n",
     "x.urm:4: param 'q': why= holds a character that is not printable ASCII*"},
    {"param q 3 range=1,4 why=first\nparam q 5\n",
     "x.urm:2: param 'q': its value 5 is outside its range 1 to 4 (no unit): first"},
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
     "x.urm:4: sensor 's': key 'dof' applies only to jointpos, jointvel and hinge"},
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
     "x.urm:6: law 'l': backing 't' must be a hertz law (or derived)"},
    {PRE "curve c x=0,0.5 y=0,1\n"
         "law l type=foam stress=c thickness=0.1 unload_r=0 unload_p=1 lock=0.5 backing=hh\n",
     "x.urm:5: law: dangling reference to law 'hh'*"},
};


/* one message per malformed text, with the exact file and line; nothing returned */

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
                      "1000 (uasimpact-model(5), LIMITS)");

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
      cmocka_unit_test(test_preamble_valid),
      cmocka_unit_test(test_malformed),
      cmocka_unit_test(test_short_err),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
