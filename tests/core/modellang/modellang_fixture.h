/* modellang_fixture.h: what the model-language tests share (test_modellang.c,
 * test_modellang_parts.c): a tolerance assertion, one text parsed as t.urm, and the small test
 * model (a pendulum, a universal neck with restraint and curve, Hertz and foam laws, a drone
 * with an airbag, sensors) whose line numbers the tests name. Include after cmocka.h. */
#ifndef UASIMPACT_MODELLANG_FIXTURE_H
#define UASIMPACT_MODELLANG_FIXTURE_H

#include <math.h>

#include "uasimpact/modellang.h"

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

#endif
