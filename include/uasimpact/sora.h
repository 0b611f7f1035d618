/* sora.h: the JARUS SORA 2.5 ground-risk figures: the Annex F critical area of a small aircraft
 * (glide and slide areas, the obstacle factor) and the intrinsic ground-risk class iGRC for a
 * population density. The formulas and their quirks are those of casex (JARUS-QM/casex, commit
 * 2ccfd10, version 1.2.4: critical_area_models.py CriticalAreaModels.critical_area,
 * annex_f_parms.py AnnexFParms.iGRC and CoR_from_impact_angle), whose values the tests reproduce
 * (tests/core/risk/test_sora.c). Inert areas only: no deflagration (the parcel drone carries no fuel).
 */
#ifndef UASIMPACT_SORA_H
#define UASIMPACT_SORA_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  double mass;          /* kg */
  double width;         /* characteristic dimension w, m */
  double speed;         /* impact speed along the path, m/s */
  double angle;         /* impact angle from the horizontal, deg */
  double mu;            /* friction coefficient (Annex F: 0.65) */
  double cor;           /* coefficient of restitution; NAN: ur_annexf_cor(angle) */
  double ke_lethal;     /* lethal kinetic energy, J; negative: |value| with the Annex F
                                      rule (doubled when w <= 1 m); -1: 290 J with the rule */
  int obstacles;        /* apply the obstacle factor 0.6 when 1 < w < 40 m */
  double person_radius; /* r_p, m (Annex F: 0.3) */
  double person_height; /* h_p, m (Annex F: 1.8) */
  double g;             /* m/s^2 (casex: 9.81) */
} urAnnexFIn;

typedef struct {
  double ca;               /* critical area, m^2 */
  double a_glide, a_slide; /* its glide and slide parts (obstacle factor applied) */
  double d_glide, d_slide; /* glide distance (factor applied, as casex returns it) and
                                      slide distance, m */
  double v_min, t_safe;    /* speed of lethal energy, m/s; time to slow to it, s */
} urAnnexFOut;

/* the Annex F settings for an aircraft of mass m, width w at speed v and angle theta: mu 0.65,
   CoR from the angle, 290 J with the w <= 1 m rule, obstacles on, person 0.3 m / 1.8 m, g 9.81 */
void ur_annexf_defaults(urAnnexFIn* in, double mass, double width, double speed, double angle);
/* CoR(theta) = 0.825 - 0.0025 theta: the straight line through (10 deg, 0.8) and (90 deg, 0.6) */
double ur_annexf_cor(double angle);
/* the critical area (casex's rules: the slide removed for w <= 1 m, the 35 deg floor for small
   aircraft not applied, as casex does not) */
void ur_annexf_ca(const urAnnexFIn* in, urAnnexFOut* out);

/* the intrinsic ground-risk class for a population density (people/km^2) and a critical area
   (m^2): raw = 1 - log10(tlos / (density 1e-6 ca)) - compensation; raw1 = raw rounded to 0.1
   (ties to even, as Python's round); igrc = ceil(raw1) (casex's AnnexFParms.iGRC); igrc_table =
   raw1 - 0.1 rounded to the nearest integer, ties to even (casex's integer tables, SORA 2.5
   Table 2's convention). 0; -1 when density, ca or tlos is not positive */
int ur_igrc(double density, double ca, double tlos, double compensation, double* raw, double* raw1,
            int* igrc, int* igrc_table);

/* the classes of SORA 2.5's iGRC table (Table 2, E S.4.2.3(d)): 1 (a controlled ground area in
   the two smallest columns) to 10 (< 50 000 ppl/km^2 in the three largest); nothing lies below
   1, and above 10 an operation is outside SORA's scope (the certified category) */
#define urIGRC_TABLE_MIN 1
#define urIGRC_TABLE_MAX 10
/* a class limited to the table's range: *igrc clamped to [urIGRC_TABLE_MIN, urIGRC_TABLE_MAX];
   -1 when it was below, +1 above, 0 within */
int ur_igrc_clamp(int* igrc);

#ifdef __cplusplus
}
#endif
#endif
