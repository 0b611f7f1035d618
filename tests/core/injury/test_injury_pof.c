/* test_injury_pof.c: criterion -> PoF curves, Nij composite table, fusion (3.1), settings and
 * the all-criteria evaluation. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "uasimpact/injury.h"

static void test_hic_curve(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);

  // Mertz & Irwin anchor: ~16 % AIS4+ at HIC 1000; sheet table 0.1694
  assert_true(fabs(ur_pof_hic(1000, &p) - 0.169) < 0.002);
  assert_true(fabs(ur_pof_hic(500, &p) - 0.0281) < 5e-4);
  assert_true(fabs(ur_pof_hic(1500, &p) - 0.5577) < 5e-4);
  assert_true(fabs(ur_pof_hic(2000, &p) - 0.8829) < 5e-4);
  assert_true(ur_pof_hic(0, &p) == 0.0 && ur_pof_hic(-5, &p) == 0.0);
  assert_true(ur_pof_hic(1e-9, &p) == 0.0);
}

/* the reference sheet's choices, against which its tables are computed: rescale, raise, the
   upper ends of Gennarelli & Wodzin (the defaults are the calibration's: lower, midpoints) */
static void sheet_params(urInjuryParams* p) {
  ur_injury_defaults(p);
  p->nij_rescale = 1;
  p->nij_order = urORDER_RAISE;
  p->pof_ais2 = 0.02;
  p->pof_ais3 = 0.10;
  p->pof_ais4 = 0.50;
}

static void test_nij_composite_table(void** state) {
  urInjuryParams p;
  sheet_params(&p);

  // sheet section 3.5: Q2..Q5 and P{F|Nij} with rescale, raise, upper G&W values
  const double n[4] = {0.5, 1.0, 2.0, 3.0};
  const double pf[4] = {0.0349, 0.0940, 0.3080, 0.5842};
  const double qt[4][4] = {{0.0850, 0.0601, 0.0493, 0.0173},
                           {0.2075, 0.1904, 0.1274, 0.0472},
                           {0.6576, 0.6576, 0.3859, 0.1758},
                           {0.9333, 0.9333, 0.6896, 0.4300}};
  for (int i = 0; i < 4; i++) {
    double q[4];
    ur_nij_ais(n[i], &p, q);
    for (int k = 0; k < 4; k++) {
      assert_true(fabs(q[k] - qt[i][k]) < 1e-4);
    }
    assert_true(fabs(ur_pof_nij(n[i], &p) - pf[i]) < 0.002);
  }
  assert_true(ur_pof_nij(0, &p) == 0.0);
}

static void test_nij_variants(void** state) {
  // sheet sensitivity: "lower" ordering 29.5 % at 2, 57.1 % at 3
  urInjuryParams p;
  sheet_params(&p);
  assert_int_equal(ur_injury_param_set(&p, "nij_order", urORDER_LOWER), 0);
  assert_true(fabs(ur_pof_nij(1.0, &p) - 0.094) < 0.001);
  assert_true(fabs(ur_pof_nij(2.0, &p) - 0.295) < 0.001);
  assert_true(fabs(ur_pof_nij(3.0, &p) - 0.571) < 0.001);

  // no rescale: floor of a few % at small Nij (4.6 % at 0.05, 59.8 % at 3)
  sheet_params(&p);
  assert_int_equal(ur_injury_param_set(&p, "nij_rescale", 0), 0);
  assert_true(fabs(ur_pof_nij(0.05, &p) - 0.046) < 0.001);
  assert_true(fabs(ur_pof_nij(3.0, &p) - 0.598) < 0.001);

  // midpoint G&W values: 7.5 % at 1, 52.3 % at 3
  sheet_params(&p);
  assert_int_equal(ur_injury_param_set(&p, "pof_ais2", 0.015), 0);
  assert_int_equal(ur_injury_param_set(&p, "pof_ais3", 0.09), 0);
  assert_int_equal(ur_injury_param_set(&p, "pof_ais4", 0.275), 0);
  assert_true(fabs(ur_pof_nij(1.0, &p) - 0.075) < 0.001);
  assert_true(fabs(ur_pof_nij(3.0, &p) - 0.523) < 0.001);
}

static void test_vc_curve(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);

  // raw logistic passes through 25 % at the 25 % point (times the AIS -> PoF factor)
  p.vc_rescale = 0;
  assert_true(fabs(ur_pof_vc(1.0, urTHORAX, &p) - 0.25 * 0.5) < 1e-12);
  assert_true(fabs(ur_pof_vc(1.2, urABDOMEN, &p) - 0.25 * 1.0) < 1e-12);

  // rescaled: zero at 0, limits 0.5 (thorax) and 1.0 (abdomen)
  p.vc_rescale = 1;
  assert_true(ur_pof_vc(0, urTHORAX, &p) == 0.0 && ur_pof_vc(0, urABDOMEN, &p) == 0.0);
  assert_true(fabs(ur_pof_vc(10, urTHORAX, &p) - 0.5) < 1e-9);
  assert_true(fabs(ur_pof_vc(10, urABDOMEN, &p) - 1.0) < 1e-9);
}

static void test_curves_monotone(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);
  double x[64], pr[64];
  for (int kind = urPOF_HIC; kind <= urPOF_VC_ABDOMEN; kind++) {
    assert_int_equal(ur_pof_curve(kind, &p, 64, x, pr), 64);
    assert_true(x[0] == 0.0 && pr[0] == 0.0);
    for (int i = 1; i < 64; i++) {
      assert_true(x[i] > x[i - 1]);
      assert_true(pr[i] >= pr[i - 1]);
      assert_true(pr[i] >= 0.0 && pr[i] <= 1.0);
    }
    // reaches its limit: 1 except the thorax-only VC curve (0.5)
    double lim = kind == urPOF_VC_THORAX ? 0.5 : 1.0;
    assert_true(pr[63] >= 0.99 * lim);
  }
  assert_int_equal(ur_pof_curve(urPOF_HIC, &p, 1, x, pr), -1);
  assert_int_equal(ur_pof_curve((urPofKind)9, &p, 64, x, pr), -1);

  // monotone on a fine grid as well, for every curve
  for (int i = 1; i <= 4000; i++) {
    assert_true(ur_pof_hic(i, &p) >= ur_pof_hic(i - 1, &p));
    assert_true(ur_pof_nij(i * 0.002, &p) >= ur_pof_nij((i - 1) * 0.002, &p));
    assert_true(ur_pof_vc(i * 1e-3, urTHORAX, &p) >= ur_pof_vc((i - 1) * 1e-3, urTHORAX, &p));
    assert_true(ur_pof_vc(i * 1e-3, urABDOMEN, &p) >= ur_pof_vc((i - 1) * 1e-3, urABDOMEN, &p));
  }
}

static void test_fusion(void** state) {
  // (3.1) and the thorax/abdomen combination
  assert_true(fabs(ur_pof_fuse(0.1, 0.2, 0.3) - (1 - 0.9 * 0.8 * 0.7)) < 1e-15);
  assert_true(ur_pof_fuse(0, 0, 0) == 0.0 && ur_pof_fuse(1, 0, 0) == 1.0);
  urInjuryParams p;
  ur_injury_defaults(&p);
  assert_true(fabs(ur_pof_vc_fuse(0.2, 0.5, &p) - 0.6) < 1e-15);
  p.vc_fuse = urVCFUSE_MAX;
  assert_true(ur_pof_vc_fuse(0.2, 0.5, &p) == 0.5);
}

static void test_params(void** state) {
  urInjuryParams p;
  ur_injury_defaults(&p);
  int n = ur_injury_param_count();
  assert_true(n >= 30);

  // every name is lowercase with underscores and round-trips its default
  for (int i = 0; i < n; i++) {
    const char *name, *unit, *help;
    assert_int_equal(ur_injury_param_info(i, &name, &unit, &help), 0);
    for (const char* c = name; *c; c++) {
      assert_true((*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_');
    }
    double v;
    assert_int_equal(ur_injury_param_get(&p, name, &v), 0);
    assert_int_equal(ur_injury_param_set(&p, name, v), 0);
  }
  assert_int_equal(ur_injury_param_info(n, NULL, NULL, NULL), -1);

  // names the application exposes, with their defaults
  double v;
  assert_int_equal(ur_injury_param_get(&p, "nij_fzc_tension", &v), 0);
  assert_true(v == 6806);
  assert_int_equal(ur_injury_param_get(&p, "nij_myc_extension", &v), 0);
  assert_true(v == 135);
  assert_int_equal(ur_injury_param_get(&p, "vc_d0_thorax", &v), 0);
  assert_true(v == 0.229);
  assert_int_equal(ur_injury_param_get(&p, "filter", &v), 0);
  assert_true(v == 0);
  assert_int_equal(ur_injury_param_set(&p, "filter", 1), 0);
  assert_true(p.filter == 1);
  assert_int_equal(ur_injury_param_set(&p, "filter", 0.5), -2);
  assert_int_equal(ur_injury_param_set(&p, "no_such_thing", 1), -1);
  assert_int_equal(ur_injury_param_set(&p, "pof_ais4", 1.5), -2);
  assert_int_equal(ur_injury_param_set(&p, "nij_alpha3", 3.2269), 0);
  assert_true(p.nij_alpha[1] == 3.2269);
}

#define NE 4001

static void test_eval_all(void** state) {
  // 40 ms at 10 us: half-sine head pulse split over x and y, neck loads, thorax sine
  static double t[NE], ax[NE], ay[NE], fz[NE], my[NE], dth[NE];
  for (int i = 0; i < NE; i++) {
    t[i] = i * 1e-5;
    double s = t[i] - 0.005;
    double a = (s >= 0 && s <= 0.010) ? 100.0 * urGRAVITY * sin(M_PI * s / 0.010) : 0.0;
    ax[i] = 0.6 * a;
    ay[i] = 0.8 * a;
    fz[i] = -3080.0 * sin(M_PI * t[i] / 0.040);
    my[i] = 155.0 * sin(M_PI * t[i] / 0.040);
    dth[i] = t[i] <= 0.020 ? 0.05 * sin(2 * M_PI * 25.0 * t[i]) : 0.0;
  }
  urInjuryInput in;
  memset(&in, 0, sizeof(in));
  in.n = NE;
  in.t = t;
  in.head_acc[0] = ax;
  in.head_acc[1] = ay;
  in.neck_fz = fz;
  in.neck_my = my;
  in.thorax_d = dth;
  urInjuryParams p;
  ur_injury_defaults(&p);
  urInjuryResult r;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &r), 0);

  // criteria
  assert_true(fabs(r.hic15.hic - 414.646) / 414.646 < 1e-3);
  assert_true(r.hic.hic == r.hic15.hic && fabs(r.hic36.hic - r.hic15.hic) < 1e-9);
  assert_true(fabs(r.nij.nij - 1.0) < 1e-6 && r.nij.which == urNIJ_NCF);
  double vcw = 0.05 * 0.05 * 2 * M_PI * 25.0 / (2 * 0.229);
  assert_true(fabs(r.vc_thorax.vc - vcw) / vcw < 1e-4);
  assert_true(r.vc_abdomen.vc == 0.0 && r.p_vc_abdomen == 0.0);

  // PoFs and the fusion
  assert_true(fabs(r.pof[urCRIT_HIC] - ur_pof_hic(r.hic15.hic, &p)) < 1e-15);
  assert_true(fabs(r.pof[urCRIT_NIJ] - ur_pof_nij(1.0, &p)) < 1e-6);
  assert_true(fabs(r.pof[urCRIT_VC] - r.p_vc_thorax) < 1e-15);
  assert_true(fabs(r.p_total - (1 - (1 - r.pof[urCRIT_HIC]) * (1 - r.pof[urCRIT_NIJ]) *
                                        (1 - r.pof[urCRIT_VC]))) < 1e-15);

  // without HIC36 (as impacts evaluate): hic36 zero, everything else the same bits
  urInjuryResult r2;
  in.skip_hic36 = 1;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &r2), 0);
  assert_true(r.hic36.hic > 0 && r2.hic36.hic == 0);
  r2.hic36 = r.hic36;
  assert_memory_equal(&r, &r2, sizeof r);

  // filtering on: the CFC 1000 head channel lowers HIC slightly, still close for a 10 ms pulse
  static double work[15 * NE];
  assert_int_equal(ur_injury_work_size(NE), 9 * NE + ur_hic_work_size(NE));
  assert_true(ur_injury_work_size(NE) <= 15 * NE);
  p.filter = 1;
  urInjuryResult rf;
  assert_int_equal(ur_injury_eval(&in, &p, work, &rf), 0);
  assert_true(rf.hic15.hic < r.hic15.hic && rf.hic15.hic > 0.99 * r.hic15.hic);

  // filtering needs uniform samples
  t[7] += 3e-6;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &rf), -3);
  p.filter = 0;
  assert_int_equal(ur_injury_eval(&in, &p, NULL, &rf), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_hic_curve),       cmocka_unit_test(test_nij_composite_table),
      cmocka_unit_test(test_nij_variants),    cmocka_unit_test(test_vc_curve),
      cmocka_unit_test(test_curves_monotone), cmocka_unit_test(test_fusion),
      cmocka_unit_test(test_params),          cmocka_unit_test(test_eval_all),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
