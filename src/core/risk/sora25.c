/* sora25.c: the SORA 2.5 iGRC table, its columns and bands, clamping, the M2 integrity criterion
 * and the final-GRC floor, and the paper's eq. (1.1) (sora25.h). The numbers are transcribed from
 * the AMC to Regulation (EU) 2019/947 as amended by ED Decision 2025/018/R (SORA 2.5): the iGRC
 * table on p. 24, Table 5 on p. 29, Annex B Table B.8 on p. 91 and the M2 criteria on p. 92. */
#include <math.h>

#include "uasimpact/sora25.h"

const double ur_sora25_dim[urSORA25_NCOL] = {1, 3, 8, 20, 40};
const double ur_sora25_speed[urSORA25_NCOL] = {25, 35, 75, 120, 200};
const double ur_sora25_ca[urSORA25_NCOL] = {6.5, 65, 650, 6500, 65000};
const double ur_sora25_band_hi[urSORA25_NROW] = {0, 5, 50, 500, 5000, 50000, INFINITY};

/* p. 24; 0 = "Not part of SORA" */
static const int table[urSORA25_NROW][urSORA25_NCOL] = {
    {1, 1, 2, 3, 3},  /* controlled ground area */
    {2, 3, 4, 5, 6},  /* < 5 */
    {3, 4, 5, 6, 7},  /* < 50 */
    {4, 5, 6, 7, 8},  /* < 500 */
    {5, 6, 7, 8, 9},  /* < 5 000 */
    {6, 7, 8, 9, 10}, /* < 50 000 */
    {7, 8, 0, 0, 0}}; /* > 50 000 */

static const char* const labels[urSORA25_NROW] = {
    "controlled ground area",         "< 5 (remote)",       "< 50 (lightly populated)",
    "< 500 (sparsely populated)",     "< 5 000 (suburban)", "< 50 000 (high-density metropolitan)",
    "> 50 000 (assemblies of people)"};

int ur_sora25_cell(int row, int col) {
  if (row < 0 || row >= urSORA25_NROW || col < 0 || col >= urSORA25_NCOL) return -1;
  return table[row][col];
}

const char* ur_sora25_row_label(int row) {
  return row >= 0 && row < urSORA25_NROW ? labels[row] : "";
}

int ur_sora25_column(double dim, double speed) {
  if (!(dim > 0) || !(speed > 0)) return -1;
  int cd = -1, cs = -1;
  for (int j = urSORA25_NCOL - 1; j >= 0; j--) {
    if (dim <= ur_sora25_dim[j]) cd = j;
    if (speed <= ur_sora25_speed[j]) cs = j;
  }
  if (cd < 0 || cs < 0) return -1;
  return cd > cs ? cd : cs;
}

int ur_sora25_column_ca(double ca) {
  if (!(ca >= 0)) return -1;
  for (int j = 0; j < urSORA25_NCOL; j++) {
    if (ca <= ur_sora25_ca[j]) return j;
  }
  return -1;
}

int ur_sora25_row(double density, int controlled) {
  if (controlled) return 0;
  if (!(density >= 0)) return -1;
  for (int r = 1; r < urSORA25_NROW - 1; r++) {
    if (density < ur_sora25_band_hi[r]) return r;
  }
  return urSORA25_NROW - 1;
}

int ur_sora25_small_ua(double mass, double speed, int row) {
  return mass > 0 && mass <= 0.25 && speed > 0 && speed <= 25 && row >= 0 &&
         row < urSORA25_NROW - 1;
}

/* the highest value of a column (its lowest non-grey row from the bottom) */
static int column_max(int col) {
  for (int r = urSORA25_NROW - 1; r >= 0; r--) {
    if (table[r][col] != urSORA25_GREY) return table[r][col];
  }
  return 1;
}

int ur_sora25_clamp(int igrc, int col, int* where) {
  int hi = col >= 0 && col < urSORA25_NCOL ? column_max(col) : 10;
  *where = 0;
  if (igrc < 1) {
    *where = -1;
    return 1;
  }
  if (igrc > hi) {
    *where = 1;
    return hi;
  }
  return igrc;
}

int ur_sora25_m2(double q_base, double q, urM2* out) {
  if (!(q_base > 0) || !(q > 0)) return -1;
  out->factor = q_base / q;
  out->orders = log10(out->factor);
  out->percent = 100 * (1 - q / q_base);
  out->level = out->factor >= 100 ? urM2_HIGH : out->factor >= 10 ? urM2_MEDIUM : urM2_NONE;
  out->credit = -out->level;
  out->beyond = out->factor >= 1000;
  return 0;
}

int ur_sora25_final(int igrc, int col, int m1, int m2) {
  if (col < 0 || col >= urSORA25_NCOL) return -1;
  int g = igrc + m1 + m2, floor_ = table[0][col];
  return g < floor_ ? floor_ : g;
}

double ur_fatality_rate(double lambda, double rho, double p_shelter, double q) {
  return lambda * (rho * 1e-6) * (1 - p_shelter) * q;
}

double ur_density_limit(double tlos, double lambda, double p_shelter, double q) {
  double per = lambda * 1e-6 * (1 - p_shelter) * q;
  return per > 0 ? tlos / per : INFINITY;
}
