/* state.c: the live state's settings: the parameter table behind set, show, save session and
 * completion (one row per setting: name, kind, unit, range, help), their defaults, the injury
 * settings through set and show, and the risk settings' defaults. The live case as a whole
 * (loading a case, a fresh context) is case.c. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "case.h"


#define OFF(f) offsetof(uraState, f)

static const char* const format_names[] = {"table", "csv", "wide", "json", NULL};
static const char* const onoff_names[] = {"off", "on", NULL};
static const char* const descent_names[] = {"model", "paper", NULL};
static const char* const tau_names[] = {"rmax", "top", NULL};
static const char* const mc_method_names[] = {"surface", "exact", NULL};
static const char* const m2_baseline_names[] = {"unmitigated", "table_b8", "design:", NULL};

/* set m2_baseline: unmitigated (kept as ""), table_b8, or design:NAME with NAME a design's name
   as 'design save' accepts it (whether it is kept is sora's to check: a session file may set
   this before it saves the design it names, and 'design delete' may come after) */
static int m2_baseline_check(uraCtx* c, const char* value, char* norm, size_t n) {
  const char* name = strncmp(value, "design:", 7) ? NULL : value + 7;
  int ok = !strcmp(value, "unmitigated") || !strcmp(value, "table_b8");
  if (name && (isalpha((unsigned char)name[0]) || name[0] == '_') && strlen(name) < urNAMELEN) {
    ok = 1;
    for (const char* q = name; *q; q++) {
      ok &= isalnum((unsigned char)*q) || *q == '_' || *q == '.' || *q == '-';
    }
  }
  if (!ok) {
    return ura_fail(c,
                    "set m2_baseline: '%s' is not accepted; accepted: unmitigated or table_b8 or "
                    "design:NAME (a design that 'design save NAME' keeps)",
                    value);
  }
  snprintf(norm, n, "%s", strcmp(value, "unmitigated") ? value : "");
  return 0;
}

int ura_m2_baseline(const uraRiskSet* r, const char** design) {
  if (!strcmp(r->m2_baseline, "table_b8")) return uraM2_TABLE_B8;
  if (!strncmp(r->m2_baseline, "design:", 7)) {
    if (design) *design = r->m2_baseline + 7;
    return uraM2_DESIGN;
  }
  return uraM2_UNMITIGATED;
}

/* one row per settable quantity: name, kind, offset, derived flag, unit, range, help */
const uraParam ura_params[] = {
    {"case", uraP_CASE, OFF(casename), 0, "", 0, 0,
     "the case: a preset of the model (the RA3's: A parachute and 1.0 atm bottom airbag, B "
     "parachute, C none, A1 1.1 atm bottom, A2 1.1 atm bottom and front); change it with 'case'",
     NULL},
    {"wind", uraP_NUM, OFF(descent.wind), 0, "m/s", 0, 60, "horizontal wind speed", NULL},
    {"face", uraP_NUM, OFF(face), 0, "deg", -360, 360,
     "face direction phi of the person; 0 faces the incoming drone (into the wind)", NULL},
    {"pitch", uraP_NUM, OFF(pitch), 0, "deg", -90, 90,
     "drone pitch at impact, nose down > 0 (paper: 0, upright under the parachute)", NULL},
    {"roll", uraP_NUM, OFF(roll), 0, "deg", -90, 90, "drone roll at impact (paper: 0)", NULL},
    {"yaw", uraP_NUM, OFF(yaw), 0, "deg", -180, 180,
     "drone yaw from its course (paper: 0, along axis on the course)", NULL},
    {"step", uraP_NUM, OFF(step), 0, "m", 0.005, 1, "grid pitch", NULL},
    {"along_min", uraP_NUM, OFF(par_min), OFF(par_min_set), "m", -100, 100,
     "grid extent: smallest along offset (rounded outwards to the lattice); derived unless set "
     "('set along_min auto'): every cell where contact is possible",
     NULL},
    {"along_max", uraP_NUM, OFF(par_max), OFF(par_max_set), "m", -100, 100,
     "grid extent: largest along offset; derived unless set ('set along_max auto')", NULL},
    {"cross_max", uraP_NUM, OFF(perp_max), OFF(perp_max_set), "m", 0, 100,
     "grid extent: largest |cross offset|; derived unless set ('set cross_max auto')", NULL},
    {"threads", uraP_INT, OFF(threads), 0, "", 1, 64,
     "grid worker threads (results do not depend on it)", NULL},
    {"recall", uraP_ENUM, OFF(recall), 0, "", 0, 0,
     "on: a grid asked for again with the same model, conditions, step, extents and injury "
     "settings reuses the cells computed earlier in the session; off: always simulate",
     onoff_names},
    {"mirror", uraP_ENUM, OFF(mirror), 0, "", 0, 0,
     "on: a grid at face 0 or 180 simulates dperp >= 0 only and takes the other half as its "
     "mirror image, when the model and the scene are mirror-symmetric (show mirror says whether "
     "they are, or what breaks it); off: every cell simulated",
     onoff_names},
    {"winds", uraP_LIST, OFF(winds), 0, "m/s", 0, 60,
     "wind speeds of the rows of descent and parametric", NULL},
    {"speed", uraP_NUM, OFF(speed), OFF(speed_set), "m/s", 0.01, 200,
     "impact speed; derived from the descent model unless set ('set speed auto')", NULL},
    {"angle", uraP_NUM, OFF(angle), OFF(angle_set), "deg", 0, 90,
     "descent angle psi from the horizontal, 0 a horizontal flight (impact aim only: offsets and "
     "grids need >= 1 deg); derived unless set ('set angle auto')",
     NULL},
    {"descent", uraP_ENUM, OFF(descent_src), 0, "", 0, 0,
     "where derived speed and angle come from: model (the descent model at the live wind) or "
     "paper (the paper's Table 2 at the live wind, case C's column for C, case B's for the "
     "others; winds 0, 2, 4, 6, 8, 10 m/s only); 'case' keeps it",
     descent_names},
    {"tau", uraP_ENUM, OFF(tau), 0, "", 0, 0,
     "the moment Delta is taken: rmax (the paper's text: the drone centre R_max above the head "
     "top) or top (the centre at head-top level, R_max/tan(psi) further along the course, as the "
     "paper's 10 m/s grids behave); the same at zero wind; 'case' keeps it",
     tau_names},
    {"altitude", uraP_NUM, OFF(descent.altitude), 0, "m", 0.1, 10000,
     "height at which the descent starts (from rest)", NULL},
    {"mass", uraP_NUM, OFF(descent.mass), 0, "kg", 0.01, 1000,
     "mass of the UAS (descent, MTOW area, impact energy) and, when changed, the multibody "
     "drone's total (masses and inertias scaled, geometry kept; drone_mass alone: the multibody "
     "drone only)",
     NULL},
    {"area_drone", uraP_NUM, OFF(descent.area_drone), 0, "m^2", 0, 100,
     "reference area of the drone A_S^d", NULL},
    {"cd_drone", uraP_NUM, OFF(descent.cd_drone), 0, "", 0, 10, "drag coefficient of the drone",
     NULL},
    {"area_chute", uraP_NUM, OFF(descent.area_chute), 0, "m^2", 0, 1000,
     "reference area of the parachute A_S^p (0: no parachute)", NULL},
    {"cd_chute", uraP_NUM, OFF(descent.cd_chute), 0, "", 0, 10, "drag coefficient of the parachute",
     NULL},
    {"rho", uraP_NUM, OFF(descent.rho), 0, "kg/m^3", 0.01, 10, "air density", NULL},
    {"g", uraP_NUM, OFF(descent.g), 0, "m/s^2", 0.01, 100, "gravitational acceleration", NULL},
    {"width", uraP_NUM, OFF(para.width), 0, "m", 0.001, 100,
     "UAS width across the course (planform, gliding area)", NULL},
    {"length", uraP_NUM, OFF(para.length), 0, "m", 0.001, 100,
     "UAS length along the course (planform, gliding area)", NULL},
    {"cfit", uraP_NUM, OFF(para.cfit), 0, "m^2/kg", 0, 100, "MTOW area coefficient c_fit", NULL},
    {"person_height", uraP_NUM, OFF(para.person_height), 0, "m", 0.1, 3,
     "person height H_P of the gliding area (D.1)", NULL},
    {"person_diameter", uraP_NUM, OFF(para.person_diameter), 0, "m", 0, 2,
     "person diameter 2R_P of the gliding area (D.1)", NULL},
    {"slide", uraP_NUM, OFF(para.slide), 0, "m", 0, 1000, "slide distance D_slide (D.1)", NULL},
    {"body_mass", uraP_NUM, OFF(para.body_mass), 0, "kg", 1, 500,
     "whole-body mass of the person (Blunt Criterion)", NULL},
    {"bc_diameter", uraP_NUM, OFF(para.bc_diameter), 0, "m", 0.001, 10,
     "impactor diameter D_imp of the Blunt Criterion", NULL},
    /* deployment reliability, Monte Carlo, SORA figures (cmd_risk.c, cmd_montecarlo.c) */
    {"p_chute", uraP_NUM, OFF(risk.p_chute), 0, "", 0, 1,
     "probability that the parachute deploys in time (risk, montecarlo)", NULL},
    {"p_bag", uraP_NUM, OFF(risk.p_bag), 0, "", 0, 1,
     "probability that each airbag deploys (risk, montecarlo)", NULL},
    {"h_chute_min", uraP_NUM, OFF(risk.h_chute_min), 0, "m", 0, 10000,
     "minimum deployment height: a failure below it gets no parachute", NULL},
    {"seed", uraP_INT, OFF(risk.seed), 0, "", 0, 4294967295.0,
     "key of montecarlo's random numbers: sample i depends on (seed, i) only", NULL},
    {"mc_method", uraP_ENUM, OFF(risk.mc_method), 0, "", 0, 0,
     "montecarlo: surface (Q interpolated on a lattice of real grids) or exact (grids per sample)",
     mc_method_names},
    {"mc_mirror", uraP_ENUM, OFF(risk.mc_mirror), 0, "", 0, 0,
     "montecarlo: on takes the Q of face -phi from the grid at phi (the mirror image, when no "
     "roll or yaw breaks the symmetry) and spans a symmetric face range with symmetric nodes; "
     "off computes every face",
     onoff_names},
    {"surface_nodes", uraP_INT, OFF(risk.surface_nodes), 0, "", 2, 65,
     "nodes of the response surface per continuous input (discrete inputs: their values)", NULL},
    {"surface_check", uraP_INT, OFF(risk.surface_check), 0, "", 0, 1000,
     "samples that montecarlo also computes by grids to measure the surface's error", NULL},
    {"pop_density", uraP_LIST, OFF(risk.pop_density), 0, "ppl/km^2", 1e-6, 1e9,
     "population density, one value or a list of bands (500,5000,50000): sora's iGRC takes the "
     "highest (SORA 2.5: the highest density in the footprint); risk and sora print eq. (1.1) "
     "per band",
     NULL, NULL, OFF(risk.npop)},
    {"lambda_system", uraP_NUM, OFF(risk.lambda), 0, "1/h", 1e-12, 1,
     "ground-crash event rate per flight hour, lambda_system of eq. (1.1) (risk, sora; default "
     "1e-3, SORA 2.5's implied loss-of-control rate at SAIL III: set the drone's own)",
     NULL},
    {"p_shelter", uraP_NUM, OFF(risk.p_shelter), 0, "", 0, 1,
     "probability that a person is sheltered, P_shelter of eq. (1.1) (0: nobody sheltered)", NULL},
    {"ua_dimension", uraP_NUM, OFF(risk.ua_dim), OFF(risk.ua_dim_set), "m", 0.001, 1000,
     "maximum characteristic dimension for SORA 2.5 Table 2 (sora); derived: the larger of width "
     "and length ('set ua_dimension auto')",
     NULL},
    {"ua_max_speed", uraP_NUM, OFF(risk.ua_speed), OFF(risk.ua_speed_set), "m/s", 0.01, 1000,
     "maximum commanded airspeed for SORA 2.5 Table 2 (sora: the designer's figure); derived: the "
     "unmitigated impact speed, with a note ('set ua_max_speed auto')",
     NULL},
    {"m2_baseline", uraP_STR, OFF(risk.m2_baseline), 0, "", 0, urNAMELEN + 8,
     "baseline of sora's M2 reduction factor: unmitigated (Q of the same drone without parachute "
     "and airbag), table_b8 (Annex B Table B.8's critical area of the Table 2 column; warns of "
     "double counting with Step #2) or design:NAME (Q of a design 'design save NAME' kept, its "
     "grids under the live deployment mixture)",
     m2_baseline_names, m2_baseline_check},
    {"mc_quantiles", uraP_LIST, OFF(risk.quant), 0, "", 0.0001, 0.9999,
     "quantiles of Q that montecarlo prints as columns p5, p50, ... (probabilities in (0, 1))",
     NULL, NULL, OFF(risk.nquant)},
    {"mc_surface_tol", uraP_NUM, OFF(risk.surface_tol), 0, "", 0, 10,
     "montecarlo's tolerance on the response surface's relative error (0.05 = 5 %): above it the "
     "run warns, refines the surface where the error is largest, and fails if it cannot meet it; "
     "0: none declared",
     NULL},
    {"tlos", uraP_NUM, OFF(risk.tlos), 0, "1/h", 1e-12, 1,
     "target level of safety for the iGRC, fatalities per flight hour (sora)", NULL},
    {"igrc_compensation", uraP_NUM, OFF(risk.igrc_comp), 0, "", 0, 1,
     "subtracted from the raw iGRC (casex's tables: 0.5; its iGRC(): 0)", NULL},
    {"annexf_obstacles", uraP_ENUM, OFF(risk.annexf_obstacles), 0, "", 0, 0,
     "Annex F critical area with the obstacle factor 0.6 (for 1 < width < 40 m)", onoff_names},
    {"format", uraP_ENUM, OFF(format), 0, "", 0, 0,
     "output of tabular commands: aligned table (at a terminal rows fit 80 columns: impact "
     "prints its main columns, notes wrap, wider tables fold), CSV (a header line and rows, "
     "the notes as '# ' lines before it; export writes plain CSV), wide (an aligned table with every column, also at a "
     "terminal) or json (one object per table and line: columns, rows, notes; show as a table too)",
     format_names},
    {"pager", uraP_ENUM, OFF(pager), 0, "", 0, 0,
     "on: at a terminal, output taller than the screen goes through $PAGER (less -FRSX when "
     "unset); never in scripts, -c or pipes",
     onoff_names},
    {"terminal", uraP_STR, OFF(terminal), 0, "", 0, 64,
     "gnuplot terminal for plot (png, svg, pdfcairo, ...) and its options, the rest of the line "
     "as in gnuplot (set terminal png size 1000,700); 'default' for gnuplot's own",
     ura_term_choices, ura_terminal_check},
    {"output", uraP_STR, OFF(output), 0, "", 0, 512,
     "file that plot writes (with a file terminal); 'none' for a window", NULL, ura_output_check},
    {NULL, 0, 0, 0, NULL, 0, 0, NULL, NULL}};

void ura_state_defaults(uraState* s) {
  memset(s, 0, sizeof *s);
  strcpy(s->casename, "A");
  ur_descent_defaults(&s->descent);
  ur_parametric_defaults(&s->para);
  ur_injury_defaults(&s->injury);
  for (int i = 0; i < 6; i++) s->winds[i] = 2.0 * i;
  s->nwinds = 6;
  s->face = 0;
  s->format = uraFMT_TABLE;
  s->step = 0.05;
  s->recall = 1;
  s->mirror = 1;
  s->pager = 1;
  ura_risk_defaults(&s->risk);
  long n = sysconf(_SC_NPROCESSORS_ONLN);
  s->threads = n > 0 ? (double)n : 1;
}

const uraParam* ura_param_find(const char* name) {
  for (const uraParam* p = ura_params; p->name; p++) {
    if (!strcmp(p->name, name)) return p;
  }
  return NULL;
}

/* accepted values of a parameter, for error messages */
static void accepted(const uraParam* p, char* buf, size_t n) {
  if (p->kind == uraP_ENUM) {
    size_t k = 0;
    buf[0] = 0;
    for (int i = 0; p->choices[i]; i++) {
      k += snprintf(buf + k, k < n ? n - k : 0, "%s%s", i ? " or " : "", p->choices[i]);
    }
  } else {
    snprintf(buf, n, "%s in [%g, %g]%s%s%s",
             p->kind == uraP_LIST  ? "comma-separated numbers, each"
             : p->kind == uraP_INT ? "a whole number"
                                   : "a number",
             p->min, p->max, *p->unit ? " " : "", p->unit, p->setoff ? ", or auto" : "");
  }
}

int ura_param_set(uraCtx* c, const uraParam* p, const char* value) {
  char* base = (char*)&c->st;
  char acc[256];
  accepted(p, acc, sizeof acc);

  switch (p->kind) {
  case uraP_CASE:
    return ura_fail(c, "set case: use the command 'case NAME' (a preset of the model)");

  case uraP_STR: {
    size_t n = strlen(value);
    if (n >= (size_t)p->max) {
      return ura_fail(c, "set %s: value too long; accepted: at most %d characters", p->name,
                      (int)p->max - 1);
    }
    int none = !strcmp(value, "default") || !strcmp(value, "none") || n == 0;
    char norm[512];
    if (!none && p->check && p->check(c, value, norm, (size_t)p->max)) return -1;
    strcpy(base + p->off, none ? "" : p->check ? norm : value);
    return 0;
  }

  case uraP_ENUM:
    for (int i = 0; p->choices[i]; i++) {
      if (!strcmp(value, p->choices[i])) {
        *(int*)(base + p->off) = i;
        return 0;
      }
    }
    return ura_fail(c, "set %s: '%s' is not accepted; accepted: %s", p->name, value, acc);

  case uraP_LIST: {
    double v[uraMAXLIST];
    int k = ura_parse_list(value, v, uraMAXLIST);
    if (k < 0) {
      return ura_fail(c, "set %s: '%s' is not a list of numbers; accepted: %s (at most %d)",
                      p->name, value, acc, uraMAXLIST);
    }
    for (int i = 0; i < k; i++) {
      if (v[i] < p->min || v[i] > p->max) {
        return ura_fail(c, "set %s: %g is out of range; accepted: %s", p->name, v[i], acc);
      }
    }
    memcpy(base + p->off, v, k * sizeof(double));
    *(p->cntoff ? (int*)(base + p->cntoff) : &c->st.nwinds) = k;
    return 0;
  }

  case uraP_INT:
  case uraP_NUM: {
    double v;
    if (p->setoff && !strcmp(value, "auto")) {
      *(int*)(base + p->setoff) = 0;
      return 0;
    }
    if (ura_parse_number(value, &v)) {
      return ura_fail(c, "set %s: '%s' is not a number; accepted: %s", p->name, value, acc);
    }
    if (v < p->min || v > p->max || (p->kind == uraP_INT && v != floor(v))) {
      return ura_fail(c, "set %s: %g is out of range; accepted: %s", p->name, v, acc);
    }
    *(double*)(base + p->off) = v;
    if (p->setoff) *(int*)(base + p->setoff) = 1;
    return 0;
  }
  }
  return ura_fail(c, "set %s: internal error", p->name);
}

/* shortest of %.15g..%.17g that reads back exactly */
static int fmt_exact(char* buf, size_t n, double v) {
  for (int prec = 15; prec <= 17; prec++) {
    int k = snprintf(buf, n, "%.*g", prec, v);
    if (strtod(buf, NULL) == v || prec == 17) return k;
  }
  return 0;
}

/* numbers exact (save session) or as show prints them */
static void param_text(const uraCtx* c, const uraParam* p, char* buf, size_t n, int shown) {
  const char* base = (const char*)&c->st;
  switch (p->kind) {
  case uraP_CASE: snprintf(buf, n, "%s", c->st.casename); break;
  case uraP_STR:
    snprintf(buf, n, "%s",
             *(base + p->off)             ? base + p->off
             : p->choices                 ? p->choices[0]
             : !strcmp(p->name, "output") ? "none"
                                          : "default");
    break;
  case uraP_ENUM: snprintf(buf, n, "%s", p->choices[*(const int*)(base + p->off)]); break;
  case uraP_LIST: {
    size_t k = 0;
    buf[0] = 0;
    int cnt = p->cntoff ? *(const int*)(base + p->cntoff) : c->st.nwinds;
    const double* v = (const double*)(base + p->off);
    for (int i = 0; i < cnt && k < n; i++) {
      if (i) k += snprintf(buf + k, n - k, ",");
      if (k >= n) break;
      if (shown)
        ura_num_show(buf + k, n - k, v[i]);
      else
        fmt_exact(buf + k, n - k, v[i]);
      k += strlen(buf + k);
    }
    break;
  }
  case uraP_INT:
  case uraP_NUM:
    if (p->setoff && !*(const int*)(base + p->setoff))
      snprintf(buf, n, "auto");
    else if (shown)
      ura_num_show(buf, n, *(const double*)(base + p->off));
    else
      fmt_exact(buf, n, *(const double*)(base + p->off));
    break;
  }
}

void ura_param_format(const uraCtx* c, const uraParam* p, char* buf, size_t n) {
  param_text(c, p, buf, n, 0);
}

void ura_param_display(const uraCtx* c, const uraParam* p, char* buf, size_t n) {
  param_text(c, p, buf, n, 1);
}

int ura_injury_find(const char* name) {
  const char* nm;
  for (int i = 0; ur_injury_param_info(i, &nm, NULL, NULL) == 0; i++) {
    if (!strcmp(nm, name)) return i;
  }
  return -1;
}

int ura_injury_set(uraCtx* c, int i, const char* value) {
  const char *name, *unit;
  double lo, hi, v;
  int open_lo, isint;
  char acc[160];
  ur_injury_param_info(i, &name, &unit, NULL);
  ur_injury_param_range(i, &lo, &hi, &open_lo, &isint);
  snprintf(acc, sizeof acc, "%s in %c%g, %g]%s%s", isint ? "an integer" : "a number",
           open_lo ? '(' : '[', lo, hi, *unit ? " " : "", unit);
  if (ura_parse_number(value, &v)) {
    return ura_fail(c, "set %s: '%s' is not a number; accepted: %s", name, value, acc);
  }
  if (ur_injury_param_set(&c->st.injury, name, v)) {
    return ura_fail(c, "set %s: %g is out of range; accepted: %s", name, v, acc);
  }
  return 0;
}

void ura_injury_line(uraCtx* c, int i, char* buf, size_t n, int with_unit) {
  const char *name, *unit;
  double v;
  ur_injury_param_info(i, &name, &unit, NULL);
  ur_injury_param_get(&c->st.injury, name, &v);
  int k = fmt_exact(buf, n, v);
  if (with_unit && *unit && k < (int)n) snprintf(buf + k, n - k, " %s", unit);
}


void ura_suggest_params(uraCtx* c, uraSuggest* s) {
  const char* name;
  for (const uraParam* p = ura_params; p->name; p++) ura_suggest_add(s, p->name);
  for (int i = 0; ur_injury_param_info(i, &name, NULL, NULL) == 0; i++) ura_suggest_add(s, name);
  const urModel* m = c->model;
  for (int i = 0; m && i < m->nparam; i++) ura_suggest_add(s, m->param[i].name);
}

void ura_risk_defaults(uraRiskSet* r) {
  memset(r, 0, sizeof *r);
  r->p_chute = 1;
  r->p_bag = 1;
  r->h_chute_min = 0;
  r->seed = 1;
  r->mc_method = uraMC_SURFACE;
  r->mc_mirror = 1;
  r->surface_nodes = 7;
  r->surface_check = 4;
  r->pop_density[0] = 500;
  r->npop = 1;
  r->lambda = 1e-3;
  r->p_shelter = 0;
  r->quant[0] = 0.05;
  r->quant[1] = 0.5;
  r->quant[2] = 0.95;
  r->nquant = 3;
  r->surface_tol = 0;
  r->tlos = 1e-6;
  r->igrc_comp = 0;
  r->annexf_obstacles = 1;
}
