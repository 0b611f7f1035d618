/* parametric.h: the parametric impact-area and fatality models of the paper's Appendix D
 * (planform, MTOW and RCC gliding areas; RCC, Blunt Criterion and AWKE probabilities).
 */
#ifndef UASIMPACT_PARAMETRIC_H
#define UASIMPACT_PARAMETRIC_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  double width;           /* UAS dimension across the course (W in D.1), m */
  double length;          /* UAS dimension along the course (L in D.1), m */
  double cfit;            /* MTOW area coefficient, m^2/kg */
  double person_height;   /* H_P, m */
  double person_diameter; /* 2 R_P, m */
  double slide;           /* D_slide, m */
  double body_mass;       /* whole-body mass of the person, kg (BC) */
  double bc_diameter;     /* impactor diameter D_imp for the Blunt Criterion, m */
  double awke_w[3];       /* AWKE weights of head, thorax, abdomen */
} urParametricParams;

typedef struct {
  double energy;          /* impact kinetic energy, J */
  double planform;        /* eq. D.2, m^2 */
  double mtow_area;       /* c_fit m_MTOW, m^2 */
  double gliding;         /* eq. D.1, m^2 */
  double pof_rcc;         /* eq. D.3, head curve of Table D1 */
  double pof_rcc_part[3]; /* eq. D.3 for head, thorax, abdomen */
  double bc;              /* Blunt Criterion level (D.4), head */
  double ais_bc;          /* AIS level from BC (D.6) */
  double pof_bc;          /* AIS -> PoF (Gennarelli-Wodzin upper ends) */
  double pof_awke;        /* weighted mean of the part curves (see man page) */
} urParametricResult;

/* defaults: RA3 1.3 m x 1.1 m, 15 kg, person 1.73 m x 0.2 m, D_slide 0.40 m, ... */
void ur_parametric_defaults(urParametricParams* p);

/* evaluate every model for a UAS of mass m (kg, also the MTOW) hitting at speed v (m/s) and
   descent angle psi (deg) */
int ur_parametric(const urParametricParams* p, double m, double v, double psi_deg,
                  urParametricResult* out);

/* RCC (D.3) for body part i = 0 head, 1 thorax, 2 abdomen */
double ur_pof_rcc(int part, double energy);

/* AIS level (real) -> probability of fatality, Gennarelli & Wodzin upper ends, linear between
   integer levels */
double ur_pof_ais(double ais);

#ifdef __cplusplus
}
#endif
#endif
