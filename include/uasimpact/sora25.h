/* sora25.h: SORA 2.5 as EASA adopted it (ED Decision 2025/018/R, AMC1 Article 11, "SOURCE:
 * JARUS SORA V2.5", Edition September 2025): the intrinsic ground-risk class table (main body
 * "Table 2", captioned Table 1, p. 24), the column a drone falls in (rightmost column matching
 * both its characteristic dimension and its maximum speed, p. 25), the population-density bands
 * (strict upper edges), Annex B Table B.8's critical areas, the clamping of a quantitative iGRC
 * into the table, the M2 mitigation's integrity criterion #1 (Annex B p. 92: about one order of
 * magnitude, 90 %, for medium; two, 99 %, for high) with Table 5's credit (p. 29: n/a, -1, -2),
 * the final GRC floor at the column's controlled-ground-area value (Annex B Table B.1 #8), and
 * the paper's eq. (1.1): expected fatalities per flight hour. Pure functions: no I/O, no state.
 * Every table cell is tested against the cited text (tests/core/risk/test_sora25.c).
 */
#ifndef UASIMPACT_SORA25_H
#define UASIMPACT_SORA25_H

#ifdef __cplusplus
extern "C" {
#endif

#define urSORA25_NCOL                                                                              \
  5 /* 1 m / 25 m/s, 3 m / 35 m/s, 8 m / 75 m/s, 20 m / 120 m/s, 40 m / 200 m/s */
#define urSORA25_NROW 7 /* controlled, < 5, < 50, < 500, < 5 000, < 50 000, > 50 000 ppl/km^2 */
#define urSORA25_GREY 0 /* a cell that is "Not part of SORA" (the certified category) */

/* the columns' maximum characteristic dimension (m), maximum speed (m/s) and Annex B Table B.8
   critical area (m^2, non-mitigated) */
extern const double ur_sora25_dim[urSORA25_NCOL];
extern const double ur_sora25_speed[urSORA25_NCOL];
extern const double ur_sora25_ca[urSORA25_NCOL];
/* the rows' upper density edge, ppl/km^2 (row 0, controlled ground area: 0; row 6: infinity) */
extern const double ur_sora25_band_hi[urSORA25_NROW];

/* the iGRC of a cell: 1..10, urSORA25_GREY for "Not part of SORA", -1 for an index outside */
int ur_sora25_cell(int row, int col);
/* the qualitative descriptor of a row ("Controlled ground area", "< 5", ...; Table 3's words) */
const char* ur_sora25_row_label(int row);
/* the column of a UA of characteristic dimension dim (m) and maximum speed (m/s): the rightmost
   of the column picked by the dimension and the one picked by the speed; -1 when dim > 40 m or
   speed > 200 m/s (Annex F appendices / not in the table) or either is not positive */
int ur_sora25_column(double dim, double speed);
/* the column whose Table B.8 critical area is the smallest one >= ca (m^2): Annex B p. 91 and
   main body p. 27, matching a computed critical area to a column; -1 when ca > 65 000 m^2 */
int ur_sora25_column_ca(double ca);
/* the row of a density (ppl/km^2): "<" is strict, so 5, 50, 500, 5 000 go one row up; exactly
   50 000 fits no row of the text and is taken in the "> 50 000" row (the conservative choice);
   controlled != 0: row 0. -1 when density is negative or not a number */
int ur_sora25_row(double density, int controlled);

/* the note under the table (p. 24): "A single UA with a take-off mass less than or equal to 250 g
   and having a maximum speed less than or equal to 25 m/s is considered to have an iGRC of 1
   regardless of population density, unless operating over assemblies of people". 1 when it
   applies to a UA of take-off mass (kg) and maximum speed (m/s) in row row, else 0 */
int ur_sora25_small_ua(double mass, double speed, int row);
/* the highest final GRC inside SORA: above it, "outside the scope of the SORA" and the certified
   category (p. 5, p. 30) */
#define urSORA25_FINAL_MAX 7

/* a quantitative iGRC (e.g. from Q by the Annex F formula) clamped into column col of the
   table: below 1 it becomes 1, above the column's highest value it becomes that value; *where
   is -1 (raised), +1 (lowered: beyond the table, the certified category) or 0 (inside) */
int ur_sora25_clamp(int igrc, int col, int* where);

/* ---- M2: effects of UA impact dynamics are reduced (Annex B section B.5) ---- */

typedef enum {
  urM2_NONE = 0, /* less than about one order of magnitude: no credit (Table 5: n/a at low) */
  urM2_MEDIUM,   /* >= 10 (90 %): integrity criterion #1 medium, credit -1 */
  urM2_HIGH      /* >= 100 (99 %): high, credit -2, and activation must be automated */
} urM2Level;

typedef struct {
  double factor;  /* risk reduction factor: baseline / design (e.g. Q_unmitigated / Q) */
  double orders;  /* log10(factor) */
  double percent; /* 100 (1 - 1/factor): the reduction in per cent */
  int level;      /* urM2Level of the integrity criterion #1 the factor reaches */
  int credit;     /* Table 5's GRC reduction for that level: 0, -1, -2 */
  int beyond;     /* factor >= 1000: more than Table 5 is only by authority discretion at high
                      robustness (Annex B Table B.1 #10); never credited here */
} urM2;

/* the M2 integrity level a risk reduction from q_base to q (both > 0) reaches; 0, or -1 when
   either is not positive */
int ur_sora25_m2(double q_base, double q, urM2* out);
/* the final GRC: igrc + m1 + m2 credits (<= 0), not below the column's controlled-ground-area
   value (Annex B Table B.1 #8). -1 for a bad column */
int ur_sora25_final(int igrc, int col, int m1, int m2);

/* ---- eq. (1.1) of the paper: expected fatalities per flight hour ---- */

/* E{n_F} = lambda rho (1 - p_shelter) Q: lambda ground-crash events per flight hour, rho people
   per km^2, p_shelter the probability that a person is sheltered, q = A P{F|impact} in m^2
   (converted with 1e-6 km^2/m^2) */
double ur_fatality_rate(double lambda, double rho, double p_shelter, double q);
/* the largest density (ppl/km^2) at which E{n_F} stays at or below tlos; INFINITY when the rate
   does not grow with the density */
double ur_density_limit(double tlos, double lambda, double p_shelter, double q);

#ifdef __cplusplus
}
#endif
#endif
