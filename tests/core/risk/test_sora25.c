/* test_sora25.c: the SORA 2.5 tables against the cited text, cell by cell (the AMC to Regulation
 * (EU) 2019/947 as amended by ED Decision 2025/018/R: the iGRC table p. 24, column rule p. 25,
 * Table 5 p. 29, Annex B Table B.8 p. 91, M2 integrity p. 92; shared/reference/sora25-m2.md
 * sections 1-4, 7, 9), the column and band rules, clamping, M2 levels with the paper's Table 17
 * numbers, the final-GRC floor, and eq. (1.1) against a hand computation. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

#include "uasimpact/risk.h"
#include "uasimpact/sora.h"
#include "uasimpact/sora25.h"

/* the table as printed, one string per row ("-" for "Not part of SORA") */
static const char* const printed[urSORA25_NROW] = {
    "1 1 2 3 3", "2 3 4 5 6", "3 4 5 6 7", "4 5 6 7 8", "5 6 7 8 9", "6 7 8 9 10", "7 8 - - -"};

/* every cell against the printed table */
static void table_cells(void** state) {
  for (int r = 0; r < urSORA25_NROW; r++) {
    const char* s = printed[r];
    for (int j = 0; j < urSORA25_NCOL; j++) {
      while (*s == ' ') s++;
      int want = *s == '-' ? urSORA25_GREY : (int)strtol(s, NULL, 10);
      while (*s && *s != ' ') s++;
      if (ur_sora25_cell(r, j) != want)
        fail_msg("row %d col %d: %d, printed %d", r, j, ur_sora25_cell(r, j), want);
    }
  }
  assert_int_equal(ur_sora25_cell(-1, 0), -1);
  assert_int_equal(ur_sora25_cell(0, 5), -1);
  assert_int_equal(ur_sora25_cell(7, 0), -1);
}

/* the column headers and Table B.8 */
static void headers(void** state) {
  const double dim[] = {1, 3, 8, 20, 40}, v[] = {25, 35, 75, 120, 200},
               ca[] = {6.5, 65, 650, 6500, 65000};
  for (int j = 0; j < urSORA25_NCOL; j++) {
    assert_true(ur_sora25_dim[j] == dim[j]);
    assert_true(ur_sora25_speed[j] == v[j]);
    assert_true(ur_sora25_ca[j] == ca[j]);
  }
}

/* the non-controlled cells follow from Annex F's formula with Table B.8's areas at each band's
   upper density and compensation 0.5 (raw = 2.0119 + row + column, sora25-m2.md section 2) */
static void formula_cross_check(void** state) {
  const double rho[] = {5, 50, 500, 5000, 50000, 500000};
  for (int k = 0; k < 6; k++) {
    for (int j = 0; j < urSORA25_NCOL; j++) {
      double raw, raw1;
      int g, gt;
      assert_int_equal(ur_igrc(rho[k], ur_sora25_ca[j], 1e-6, 0.5, &raw, &raw1, &g, &gt), 0);
      assert_true(fabs(raw - (2.0119 + k + j)) < 1e-4);
      int cell = ur_sora25_cell(k + 1, j);
      if (cell != urSORA25_GREY) assert_int_equal(g, cell);
    }
  }
}

/* rightmost column matching both criteria (p. 25), and outside the table */
static void columns(void** state) {
  assert_int_equal(ur_sora25_column(1.0, 25), 0);
  assert_int_equal(ur_sora25_column(1.3, 30), 1);   /* dimension decides */
  assert_int_equal(ur_sora25_column(0.9, 40), 2);   /* speed decides */
  assert_int_equal(ur_sora25_column(1.3, 40.6), 2); /* the RA3 case C: 1.3 m at 40.6 m/s */
  assert_int_equal(ur_sora25_column(40, 200), 4);
  assert_int_equal(ur_sora25_column(41, 10), -1);
  assert_int_equal(ur_sora25_column(1, 201), -1);
  assert_int_equal(ur_sora25_column(0, 10), -1);
  assert_int_equal(ur_sora25_column_ca(0.849), 0);
  assert_int_equal(ur_sora25_column_ca(6.5), 0);
  assert_int_equal(ur_sora25_column_ca(6.6), 1);
  assert_int_equal(ur_sora25_column_ca(65000), 4);
  assert_int_equal(ur_sora25_column_ca(65001), -1);
}

/* "<" is strict; exactly 50 000 goes to "> 50 000" */
static void bands(void** state) {
  assert_int_equal(ur_sora25_row(0, 1), 0);
  assert_int_equal(ur_sora25_row(0, 0), 1);
  assert_int_equal(ur_sora25_row(4.999, 0), 1);
  assert_int_equal(ur_sora25_row(5, 0), 2);
  assert_int_equal(ur_sora25_row(499, 0), 3);
  assert_int_equal(ur_sora25_row(500, 0), 4);
  assert_int_equal(ur_sora25_row(5000, 0), 5);
  assert_int_equal(ur_sora25_row(49999, 0), 5);
  assert_int_equal(ur_sora25_row(50000, 0), 6);
  assert_int_equal(ur_sora25_row(1e6, 0), 6);
  assert_int_equal(ur_sora25_row(-1, 0), -1);
  assert_int_equal(ur_sora25_row(NAN, 0), -1);
}

/* a quantitative iGRC outside the column is clamped, and says which way */
static void clamping(void** state) {
  int w;
  assert_int_equal(ur_sora25_clamp(0, 0, &w), 1);
  assert_int_equal(w, -1);
  assert_int_equal(ur_sora25_clamp(-3, 4, &w), 1);
  assert_int_equal(w, -1);
  assert_int_equal(ur_sora25_clamp(5, 0, &w), 5);
  assert_int_equal(w, 0);
  assert_int_equal(ur_sora25_clamp(7, 0, &w), 7);
  assert_int_equal(w, 0);
  assert_int_equal(ur_sora25_clamp(8, 0, &w), 7); /* 1 m column: 7 at most */
  assert_int_equal(w, 1);
  assert_int_equal(ur_sora25_clamp(9, 1, &w), 8);
  assert_int_equal(ur_sora25_clamp(9, 2, &w), 8); /* 8 m: > 50 000 is grey, 8 at < 50 000 */
  assert_int_equal(ur_sora25_clamp(11, 4, &w), 10);
  assert_int_equal(w, 1);
}

/* M2 levels with the paper's Table 17 (sora25-m2.md section 7): C/A at 0 m/s 27.4 (medium), C/B
   3.3 (none), C/A1 at 4 m/s 9.9 (just none), B.8 baseline 6.5 over A2 260 (high) */
static void m2_levels(void** state) {
  urM2 m;
  assert_int_equal(ur_sora25_m2(0.849, 0.031, &m), 0);
  assert_true(fabs(m.factor - 0.849 / 0.031) < 1e-12);
  assert_true(fabs(m.factor - 27.4) < 0.05);
  assert_int_equal(m.level, urM2_MEDIUM);
  assert_int_equal(m.credit, -1);
  assert_int_equal(m.beyond, 0);
  assert_true(fabs(m.orders - log10(0.849 / 0.031)) < 1e-12);
  assert_true(fabs(m.percent - 100 * (1 - 0.031 / 0.849)) < 1e-12);
  ur_sora25_m2(0.849, 0.256, &m);
  assert_int_equal(m.level, urM2_NONE);
  assert_int_equal(m.credit, 0);
  ur_sora25_m2(0.853, 0.086, &m);
  assert_true(m.factor < 10);
  assert_int_equal(m.level, urM2_NONE);
  ur_sora25_m2(6.5, 0.025, &m);
  assert_int_equal(m.level, urM2_HIGH);
  assert_int_equal(m.credit, -2);
  ur_sora25_m2(10, 1, &m); /* exactly 90 % */
  assert_int_equal(m.level, urM2_MEDIUM);
  ur_sora25_m2(2000, 1, &m);
  assert_int_equal(m.credit, -2); /* never more than Table 5 */
  assert_int_equal(m.beyond, 1);
  assert_int_equal(ur_sora25_m2(0, 1, &m), -1);
  assert_int_equal(ur_sora25_m2(1, 0, &m), -1);
}

/* the M2 factor of the paired means and the delta-method interval of ur_mc_ratio: the factor
   equals Q_unmitigated / Q and the interval covers it (a sample with a known ratio 20) */
static void m2_interval(void** state) {
  enum {
    N = 400
  };
  double qc[N], q[N];
  uint64_t s = 12345;
  for (int i = 0; i < N; i++) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    double u = (double)(s >> 11) / 9007199254740992.0;
    qc[i] = 0.8 + 0.1 * u;
    q[i] = qc[i] / 20 * (0.9 + 0.2 * u);
  }
  double mc = 0, m = 0, r, lo, hi;
  for (int i = 0; i < N; i++) mc += qc[i] / N, m += q[i] / N;
  assert_int_equal(ur_mc_ratio(qc, q, N, &r, &lo, &hi), 0);
  urM2 f;
  ur_sora25_m2(mc, m, &f);
  assert_true(fabs(f.factor - r) <= 1e-12 * r);
  assert_true(lo <= f.factor && f.factor <= hi);
  assert_true(lo < hi);
  assert_int_equal(f.level, urM2_MEDIUM);
}

/* the final GRC never goes below the column's controlled-area value */
static void final_floor(void** state) {
  assert_int_equal(ur_sora25_final(5, 0, 0, -1), 4);
  assert_int_equal(ur_sora25_final(2, 0, -1, -2), 1);
  assert_int_equal(ur_sora25_final(4, 3, -1, -2), 3);
  assert_int_equal(ur_sora25_final(4, 2, 0, -2), 2);
  assert_int_equal(ur_sora25_final(4, 5, 0, 0), -1);
}

/* the note under the table (p. 24): at most 250 g and 25 m/s, iGRC 1 whatever the density,
   unless over assemblies of people (the "> 50 000" row); both edges inclusive */
static void small_ua(void** state) {
  assert_int_equal(ur_sora25_small_ua(0.25, 25, 5), 1);
  assert_int_equal(ur_sora25_small_ua(0.249, 19, 0), 1);
  assert_int_equal(ur_sora25_small_ua(0.25, 25, urSORA25_NROW - 1), 0);
  assert_int_equal(ur_sora25_small_ua(0.2501, 25, 5), 0);
  assert_int_equal(ur_sora25_small_ua(0.25, 25.01, 5), 0);
  assert_int_equal(ur_sora25_small_ua(0, 10, 5), 0);
  assert_int_equal(ur_sora25_small_ua(0.2, 10, -1), 0);
}

/* eq. (1.1) by hand: 1e-3 /h x 5000 ppl/km^2 x 1e-6 km^2/m^2 x (1 - 0.5) x 0.849 m^2 =
   2.1225e-6 /h; the density limits of sora25-m2.md section 7 (lambda 1e-3, no shelter: Q_C 0.849
   1 178, Q_A 0.031 32 258; with P_s 0.9 Q_A 322 581) */
static void eq_1_1(void** state) {
  assert_true(fabs(ur_fatality_rate(1e-3, 5000, 0.5, 0.849) - 2.1225e-6) < 1e-18);
  assert_true(ur_fatality_rate(1e-3, 5000, 1, 0.849) == 0);
  assert_true(fabs(ur_density_limit(1e-6, 1e-3, 0, 0.849) - 1177.856) < 1e-3);
  assert_true(fabs(ur_density_limit(1e-6, 1e-3, 0, 0.031) - 32258.06) < 1e-2);
  assert_true(fabs(ur_density_limit(1e-6, 1e-3, 0.9, 0.031) - 322580.6) < 1e-1);
  assert_true(isinf(ur_density_limit(1e-6, 1e-3, 1, 0.031)));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(table_cells),
      cmocka_unit_test(headers),
      cmocka_unit_test(formula_cross_check),
      cmocka_unit_test(columns),
      cmocka_unit_test(bands),
      cmocka_unit_test(clamping),
      cmocka_unit_test(m2_levels),
      cmocka_unit_test(m2_interval),
      cmocka_unit_test(final_floor),
      cmocka_unit_test(small_ua),
      cmocka_unit_test(eq_1_1),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
