/* design.c: design parameters and the models they reach: 'set mass' as the descent's and
 * parametric model's mass and the multibody drone's total (its masses and inertias scaled, its
 * geometry kept: ura_design_mass, preset.c), and what each setting changes (set's note at the
 * prompt, show's marks) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "case.h"


#define DESCENT    "the descent model (speed and angle, when derived)"
#define PARAMETRIC "the parametric model only (Appendix D; not the multibody model)"

/* the models each workbench setting reaches; the model parameters reach the multibody model */
static const struct {
  const char* name;
  int multibody; /* 1: the multibody model uses it (impact, grid) */
  const char* reach;
} reach[] = {
    {"mass", 1,
     "the descent and parametric models and the multibody drone (its masses and "
     "inertias scaled to this total, its geometry kept)"},
    {"width", 0, "the parametric model only (the multibody drone keeps its size: set drone_size)"},
    {"length", 0,
     "the parametric model only (the multibody drone keeps its size: set "
     "drone_size)"},
    {"altitude", 0, DESCENT},
    {"area_drone", 0, DESCENT},
    {"cd_drone", 0, DESCENT},
    {"area_chute", 0, DESCENT},
    {"cd_chute", 0, DESCENT},
    {"rho", 0, DESCENT},
    {"g", 0, "the descent model (the multibody model's gravity is its option)"},
    {"cfit", 0, PARAMETRIC},
    {"person_height", 0, PARAMETRIC},
    {"person_diameter", 0, PARAMETRIC},
    {"slide", 0, PARAMETRIC},
    {"body_mass", 0, PARAMETRIC},
    {"bc_diameter", 0, PARAMETRIC},
    {"speed", 1, "the impact conditions of the multibody model (impact, grid)"},
    {"angle", 1, "the impact conditions of the multibody model (impact, grid)"},
    {"pitch", 1, "the drone's attitude at impact (impact, grid)"},
    {"roll", 1, "the drone's attitude at impact (impact, grid)"},
    {"yaw", 1, "the drone's attitude at impact (impact, grid)"},
    {"velocity", 1, "the impact speed and angle (both set; impact, grid)"},
    {NULL, 0, NULL}};

const char* ura_design_reach(uraCtx* c, const char* name) {
  static char buf[200];
  for (int i = 0; reach[i].name; i++) {
    if (!strcmp(reach[i].name, name)) return reach[i].reach;
  }
  const urModel* m = c->model;
  if (!m || ur_name_param(m, name) < 0) return NULL;
  int k = ur_name_param(m, name);
  if (k == m->roles.mass_param) {
    return "the multibody drone only: its masses and inertias scaled to this total ('set mass' "
           "also changes the descent and parametric models)";
  }
  if (k == m->roles.size_param) {
    return "the multibody drone's size: joint positions, shapes and airbag volumes; masses "
           "kept, inertias as the size squared";
  }
  snprintf(buf, sizeof buf, "the multibody model (impact, grid)");
  return buf;
}

/* show's mark for a setting: where the multibody model stands */
const char* ura_design_mark(uraCtx* c, const char* name, char* buf, size_t n) {
  buf[0] = 0;
  for (int i = 0; reach[i].name; i++) {
    if (strcmp(reach[i].name, name)) continue;
    if (!reach[i].multibody) {
      snprintf(buf, n, "  (not used by the multibody model)");
    } else if (!strcmp(name, "mass") && c->model && c->model->roles.drone >= 0) {
      const urRoles* r = &c->model->roles;
      snprintf(buf, n, "  (multibody drone: %.6g kg%s)", r->mass0 * r->mass_scale,
               r->mass_scale == 1 ? ", as modelled; set mass scales it" : "");
    }
  }
  return buf;
}

/* set velocity VH,VD: the speed vector in the course's vertical plane (horizontal along the
   course, downward; m/s) as the speed and angle it makes, both set */
static int set_velocity(uraCtx* c, const char* value, const char* unit) {
  double v[3], f = 1;
  int n = ura_parse_list(value, v, 3);
  if ((unit && ura_speed_unit(unit, &f)) || n != 2 || !(v[0] >= 0) || !(v[1] >= 0)) {
    return ura_fail(c,
                    "set velocity: '%s%s%s' is not accepted; accepted: VH,VD (the horizontal "
                    "speed along the course and the downward speed, each >= 0) in m/s, or "
                    "followed by km/h or kt",
                    value, unit ? " " : "", unit ? unit : "");
  }
  v[0] = unit ? ura_speed_to_si(unit, v[0]) : v[0]; /* km/h, kt: to m/s */
  v[1] = unit ? ura_speed_to_si(unit, v[1]) : v[1];
  char sp[64], an[64];
  snprintf(sp, sizeof sp, "%.17g", hypot(v[0], v[1]));
  snprintf(an, sizeof an, "%.17g", atan2(v[1], v[0]) * 180 / M_PI);
  uraState keep = c->st;
  if (ura_param_set(c, ura_param_find("speed"), sp) ||
      ura_param_set(c, ura_param_find("angle"), an)) {
    char why[uraERRLEN];
    snprintf(why, sizeof why, "%s", c->err);
    c->st = keep;
    return ura_fail(c, "set velocity: %.900s", why);
  }
  return 0;
}

int ura_design_set(uraCtx* c, const char* name, const char* value, const char* unit) {
  if (!strcmp(name, "velocity")) return set_velocity(c, value, unit);
  if (strcmp(name, "mass")) return 1;
  const uraParam* p = ura_param_find("mass");
  if (unit && strcmp(unit, p->unit)) {
    return ura_fail(c, "set mass: takes no unit but its own (it is in %s)", p->unit);
  }
  uraState keep = c->st;
  if (ura_param_set(c, p, value)) return -1;
  uraState ns = c->st;
  c->st = keep;
  if (ns.descent.mass == keep.descent.mass)
    return 0; /* unchanged: nothing changes (a saved
                                                            session replays its defaults so) */
  const urModel* m = ura_model(c);
  if (!m) return -1;
  if (m->roles.mass_param >= 0) ura_design_mass(m, &ns, ns.descent.mass, 1);
  return ura_model_state(c, &ns, "set mass");
}
