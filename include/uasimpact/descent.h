/* descent.h: ballistic descent with optional parachute under a constant horizontal wind
 * (paper eq. 2.1-2.2, Table 1). Integrated with GSL from rest at the start altitude; the
 * ground crossing is located exactly, not taken at the last step.
 */
#ifndef UASIMPACT_DESCENT_H
#define UASIMPACT_DESCENT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  double altitude;   /* start height above ground, m */
  double mass;       /* system mass, kg */
  double area_drone; /* drone reference area A_S^d, m^2 */
  double cd_drone;   /* drone drag coefficient C_D^d */
  double area_chute; /* parachute reference area A_S^p, m^2 (0: no parachute) */
  double cd_chute;   /* parachute drag coefficient C_D^p */
  double rho;        /* air density, kg/m^3 */
  double g;          /* gravitational acceleration, m/s^2 */
  double wind;       /* horizontal wind speed, m/s (constant) */
} urDescentParams;

typedef struct {
  double speed; /* impact speed |v|, m/s */
  double angle; /* descent angle psi from the horizontal, deg */
  double vh;    /* horizontal ground speed at impact, m/s */
  double vz;    /* vertical speed at impact (positive down), m/s */
  double time;  /* time of fall, s */
  double drift; /* horizontal distance travelled, m */
} urDescentResult;

/* Table 1 values of the paper with the parachute deployed (case B) */
void ur_descent_defaults(urDescentParams* p);

/* terminal velocity in still air: sqrt(2 m g / (rho sum(C_D A))) */
double ur_terminal_velocity(const urDescentParams* p);

/* integrate from rest to the ground; 0 on success, -1 on invalid parameters or failure,
   with a message in err (if not NULL) */
int ur_descent(const urDescentParams* p, urDescentResult* out, char* err, int errlen);

#ifdef __cplusplus
}
#endif
#endif
