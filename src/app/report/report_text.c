/* report_text.c: the report's fixed texts: the documents it cites, the physics checks the test
 * suite proves (each named by its test file, so a reviewer can run it), the model's known
 * limits, and the paper's Table 17 as printed (sessions/paper/values.csv). Kept apart so that a
 * change of the test suite or of the limits is one edit here. */
#include <stddef.h>

#include "report.h"

static const char* const sources[] = {
    "EASA, Annex to ED Decision 2025/018/R: AMC and GM to Regulation (EU) 2019/947, Issue 1, "
    "Amendment 3; AMC1 Article 11, SORA (source: JARUS SORA V2.5), Edition September 2025: iGRC "
    "table (main body 'Table 2', captioned Table 1, p. 24) and its rules (pp. 23-27); Table 5, "
    "mitigations (p. 29); Annex B Table B.8, critical areas (p. 91); M2 integrity criterion #1 "
    "(p. 92) and assurance (Table B.10, pp. 94-95); TLOS 1e-6 fatalities per flight hour (p. 3).",
    "JARUS, SORA Main Body JAR-DEL-SRM-SORA-MB-2.5 and Annex B JAR-DEL-SRM-SORA-B-2.5 (13 May "
    "2024), the source EASA adopted; JARUS Annex F (JAR_doc_29), the critical-area model.",
    "JARUS-QM casex (commit 2ccfd10, version 1.2.4): CriticalAreaModels.critical_area and "
    "AnnexFParms.iGRC, whose values the test suite reproduces.",
    "Jiang, Blom and Rattanagraikanakorn (2025), Effect of parachute and airbag in reducing "
    "safety risk posed by small UAS to people on the ground, Transportation Research "
    "Interdisciplinary Perspectives 32:101521: eq. (1.1), Q (eq. 4.5), Table 17.",
    NULL};

/* { test file, what it proves } */
static const char* const checks[][2] = {
    {"test_engine_dynamics.c",
     "rigid-body and articulated dynamics: torque-free tumbling conserves energy and angular "
     "momentum, pendulum period and universal-joint frequency against closed forms, joint "
     "constraint error after violent motion, energy and momentum of a chain with every joint "
     "type"},
    {"test_engine_contact.c",
     "contact: Hertz sphere-on-plane impact (peak penetration, contact time, restitution), "
     "momentum in an oblique two-body collision with friction, sliding to rolling under "
     "Coulomb friction"},
    {"test_contact_law.c",
     "contact laws: Hertz constants and a one-degree-of-freedom Hertz impact against the closed "
     "form, unloading, blends, hysteresis energy, friction"},
    {"test_contact_gas.c, test_engine_airbag.c",
     "airbags: P V^gamma invariant, work against quadrature, volume loss and force of the "
     "uniform-pressure bag against closed forms, energy of a sphere bouncing on a bag"},
    {"test_descent.c", "descent: the descent model against closed forms and the paper's Table 2"},
    {"test_injury_hic.c, test_injury_nij.c, test_injury_pof.c",
     "injury criteria: HIC15 on closed-form pulses, Nij modes and intercepts, the PoF curves and "
     "their fusion (the paper's eq. 3.1)"},
    {"test_parametric.c", "Appendix D areas and probabilities against the paper's Table 3"},
    {"test_impact.c",
     "single impacts: symmetry, no-contact offsets, time-step convergence, the paper's zero-wind "
     "centre values (Tables 11-13)"},
    {"test_grid.c, test_grid.sh",
     "grids: the Q sum, the mirror rule, the same cells for any thread count"},
    {"test_engine_mirror.c, test_grid_mirror.sh",
     "the mirror rule only for a mirror-symmetric model: the built-ins symmetric, a change to one "
     "side found and named, an asymmetric drone's grid made of its own impacts"},
    {"test_engine_lanes.c, test_impact_lanes.c",
     "invariance: runs in vector lanes are bit for bit the runs alone"},
    {"test_sora.c", "Annex F critical areas and iGRC against casex's own values"},
    {"test_sora25.c",
     "SORA 2.5: the iGRC table cell by cell against the cited text, column and band rules, "
     "clamping, M2 levels, the final-GRC floor, eq. (1.1) against a hand computation"},
    {"test_quantile.c", "tails: sample quantiles against a Weibull closed form"},
    {"test_reproduce.sh", "the reproduction report's scoring against the paper's printed values"},
    {NULL, NULL}};

static const char* const limits[] = {
    "The person is one standing adult (a multibody model with ellipsoid contact), facing one "
    "direction per grid; children, seated or lying people and crowds are not modelled.",
    "P{F|Delta} comes from head, neck and thorax criteria (HIC15, Nij, VC) fused as the paper's "
    "eq. (3.1); other injuries and any harm after the impact (falls, fire, battery, debris) are "
    "not counted: M2's 'immediate post-impact hazards' are outside the model.",
    "The calibration used the paper's zero-wind grids of cases A, B and C only (training); every "
    "other comparison is validation.",
    "Known misses against the paper: case B at 10 m/s (the paper's P = 1 cells far downstream are "
    "underside hits the geometry does not make) and A1 at 4 m/s (a uniform-pressure bag without "
    "membrane gains little stiffness at 1.1 atm); case C's descent speed is 39.7 m/s against the "
    "paper's printed 40.6 m/s.",
    "Deployment reliability (p_chute, p_bag, h_chute_min), lambda_system and P_shelter are inputs: "
    "the model computes none of them.",
    "A Monte Carlo run on a response surface carries the surface's interpolation error (its "
    "check is printed; mc_surface_tol bounds it when declared).",
    "Ground, obstacles and sheltering are not in the impact model: Q is the area-weighted "
    "fatality probability of an unsheltered person.",
    NULL};

/* Table 17 of the paper as printed (face 0), with the value a ratio is taken against: the
   full-plane sum of the paper's own grid where it prints one (sessions/paper/grids/README.md,
   Q_full; uasimpact-model(5), CALIBRATION, Scoring), else the printed value (basis 0). A at 0
   m/s: the caption's 0.031 is the half plane, the grid's full plane 0.0581; B at 0 m/s: the
   caption's 0.256 matches neither sum, the full plane is 0.2861. A1 and A2 at 0 m/s have no grid:
   their ratio is given against the printed value and twice it (basis -1). */
static const struct {
  const char* c;
  double wind, q, basis;
} t17[] = {{"C", 0, 0.849, 0.8469}, {"C", 4, 0.853, 0},  {"C", 10, 0.859, 0.8588},
           {"B", 0, 0.256, 0.2861}, {"B", 4, 0.382, 0},  {"B", 10, 0.858, 0.8582},
           {"A", 0, 0.031, 0.0581}, {"A", 4, 0.216, 0},  {"A", 10, 0.677, 0.6766},
           {"A1", 0, 0.026, -1},    {"A1", 4, 0.086, 0}, {"A1", 10, 0.638, 0.6378},
           {"A2", 0, 0.025, -1},    {"A2", 4, 0.049, 0}, {"A2", 10, 0.452, 0.4515}};

const char* ura_report_source(int k) {
  return k >= 0 && k < (int)(sizeof sources / sizeof *sources) ? sources[k] : NULL;
}

const char* ura_report_check(int k, const char** proves) {
  if (k < 0 || k >= (int)(sizeof checks / sizeof *checks)) return NULL;
  *proves = checks[k][1];
  return checks[k][0];
}

const char* ura_report_limit(int k) {
  return k >= 0 && k < (int)(sizeof limits / sizeof *limits) ? limits[k] : NULL;
}

int ura_report_table17(int k, const char** casename, double* wind, double* q, double* basis) {
  if (k < 0 || k >= (int)(sizeof t17 / sizeof *t17)) return -1;
  *casename = t17[k].c;
  *wind = t17[k].wind;
  *q = t17[k].q;
  *basis = t17[k].basis;
  return 0;
}
