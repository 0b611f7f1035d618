/* risk_dist.c: the settings of the risk figures and the declared input distributions: dist
 * (declare, list, forget), their lines in show and save session, and what may be drawn */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"


double ura_risk_density_max(const uraRiskSet* r) {
  double m = r->pop_density[0];
  for (int i = 1; i < r->npop; i++) m = r->pop_density[i] > m ? r->pop_density[i] : m;
  return m;
}

int ura_dist_find(const uraRiskSet* r, const char* name) {
  for (int i = 0; i < r->ndist; i++) {
    if (!strcmp(r->dist[i].name, name)) return i;
  }
  return -1;
}

/* settings that describe the study itself, not what a grid or a deployment depends on */
static const char* const not_drawn[] = {
    "step",        "along_min",    "along_max",         "cross_max",
    "pop_density", "tlos",         "igrc_compensation", "lambda_system",
    "p_shelter",   "ua_dimension", "ua_max_speed",      "mc_surface_tol",
    NULL};

int ura_dist_range(uraCtx* c, const char* name, double* lo, double* hi) {
  if (!strcmp(name, "wind_dir") || !strcmp(name, "face_dir")) {
    *lo = -360;
    *hi = 360;
    return 0;
  }
  const uraParam* p = ura_param_find(name);
  if (p) {
    for (int i = 0; not_drawn[i]; i++) {
      if (!strcmp(name, not_drawn[i])) p = NULL;
    }
    if (!p || p->kind != uraP_NUM) {
      return ura_fail(c,
                      "dist: '%s' cannot be drawn; accepted: wind, wind_dir, face_dir, face, "
                      "a number parameter of the case (speed, angle, altitude, mass, ..., "
                      "p_chute, p_bag, h_chute_min), an injury setting or a model parameter",
                      name);
    }
    *lo = p->min;
    *hi = p->max;
    return 0;
  }
  int i = ura_injury_find(name);
  if (i >= 0) {
    int open_lo, isint;
    ur_injury_param_range(i, lo, hi, &open_lo, &isint);
    if (isint) {
      return ura_fail(c,
                      "dist: '%s' is a whole number and cannot be drawn; accepted: a "
                      "continuous parameter",
                      name);
    }
    if (open_lo) *lo = nextafter(*lo, INFINITY);
    return 0;
  }
  if (!strcmp(name, "bag_bottom") || !strcmp(name, "bag_front")) {
    return ura_fail(c,
                    "dist: '%s' is a deployment outcome, drawn from p_bag; accepted: dist "
                    "p_bag ... for an uncertain reliability",
                    name);
  }
  int k = ura_model_param_find(c, name);
  if (k >= 0) { /* its range (param ... range=): normal and weibull draws are truncated to it */
    *lo = c->model->param[k].lo;
    *hi = c->model->param[k].hi;
    return 0;
  }
  c->err[0] = 0;
  return ura_fail(c,
                  "dist: unknown parameter '%s'; accepted: wind, wind_dir, face_dir, face or "
                  "a parameter 'show' lists",
                  name);
}

/* the shortest of %.15g..%.17g that reads back exactly */
static int fmt_exact(char* buf, size_t n, double v) {
  for (int prec = 15; prec <= 17; prec++) {
    int k = snprintf(buf, n, "%.*g", prec, v);
    if (strtod(buf, NULL) == v || prec == 17) return k;
  }
  return 0;
}

void ura_dist_format(const uraDistDecl* d, char* buf, size_t n) {
  static const char* const kinds[] = {"normal", "uniform", "weibull", "discrete"};
  char a[32], b[32];
  size_t k = (size_t)snprintf(buf, n, "%s", kinds[d->d.kind]);
  if (d->d.kind != urDIST_DISCRETE) {
    fmt_exact(a, sizeof a, d->d.a);
    fmt_exact(b, sizeof b, d->d.b);
    snprintf(buf + k, n - k, " %s %s", a, b);
    return;
  }
  for (int list = 0; list < 2 && k < n; list++) {
    for (int i = 0; i < d->d.nval && k < n; i++) {
      fmt_exact(a, sizeof a, list ? d->d.prob[i] : d->d.val[i]);
      k += (size_t)snprintf(buf + k, n - k, "%s%s", i ? "," : " ", a);
    }
  }
}

void ura_dist_show(uraCtx* c) {
  const uraRiskSet* r = &c->st.risk;
  char buf[1200];
  fprintf(c->out, "# input distributions of montecarlo (dist)%s\n", r->ndist ? "" : ": none");
  for (int i = 0; i < r->ndist; i++) {
    ura_dist_format(&r->dist[i], buf, sizeof buf);
    fprintf(c->out, "%-16s ~ %s\n", r->dist[i].name, buf);
  }
}

void ura_dist_save(uraCtx* c, FILE* f) {
  const uraRiskSet* r = &c->st.risk;
  char buf[1200];
  for (int i = 0; i < r->ndist; i++) {
    ura_dist_format(&r->dist[i], buf, sizeof buf);
    fprintf(f, "dist %s %s\n", r->dist[i].name, buf);
  }
}

#define USAGE                                                                                      \
  "accepted: dist NAME normal MEAN SD, dist NAME uniform LO HI, dist NAME weibull "                \
  "SCALE SHAPE, dist NAME discrete V1,V2,... P1,P2,..., dist NAME off, dist clear"

int ura_cmd_dist(uraCtx* c, int argc, char** argv) {
  uraRiskSet* r = &c->st.risk;
  if (argc == 1) {
    char buf[1200];
    if (c->st.format == uraFMT_JSON) { /* one table: input, distribution */
      static const char* const cols[] = {"input", "distribution"};
      uraTable* t = ura_table_new(2, cols);
      if (!r->ndist) ura_table_note(t, "no input distribution declared");
      for (int i = 0; i < r->ndist; i++) {
        ura_dist_format(&r->dist[i], buf, sizeof buf);
        ura_table_cell(t, "%s", r->dist[i].name);
        ura_table_cell(t, "%s", buf);
      }
      ura_table_print(c, t);
      return 0;
    }
    if (!r->ndist)
      fprintf(c->out,
              "# no input distribution declared (montecarlo draws only the "
              "deployment outcomes)\n");
    for (int i = 0; i < r->ndist; i++) {
      ura_dist_format(&r->dist[i], buf, sizeof buf);
      fprintf(c->out, "dist %s %s\n", r->dist[i].name, buf);
    }
    return 0;
  }
  if (argc == 2 && !strcmp(argv[1], "clear")) {
    r->ndist = 0;
    return 0;
  }
  const char* name = argv[1];
  if (argc == 3 && !strcmp(argv[2], "off")) {
    int i = ura_dist_find(r, name);
    if (i < 0)
      return ura_fail(c, "dist %s off: '%s' has no distribution; 'dist' lists them", name, name);
    memmove(&r->dist[i], &r->dist[i + 1], (size_t)(r->ndist - i - 1) * sizeof r->dist[0]);
    r->ndist--;
    return 0;
  }
  if (argc != 5) return ura_fail(c, "dist: wrong number of arguments; " USAGE);

  uraDistDecl d;
  memset(&d, 0, sizeof d);
  if (strlen(name) >= sizeof d.name) return ura_fail(c, "dist: '%s' is too long", name);
  snprintf(d.name, sizeof d.name, "%s", name);
  if (ura_dist_range(c, name, &d.d.lo, &d.d.hi)) return -1;

  /* face is face_dir - wind_dir when a bearing is drawn: not both ways */
  int bearing = !strcmp(name, "wind_dir") || !strcmp(name, "face_dir");
  if ((bearing && ura_dist_find(r, "face") >= 0) ||
      (!strcmp(name, "face") &&
       (ura_dist_find(r, "wind_dir") >= 0 || ura_dist_find(r, "face_dir") >= 0))) {
    return ura_fail(c,
                    "dist %s: face is drawn as face_dir - wind_dir once a bearing is "
                    "declared; accepted: either face or the bearings wind_dir and face_dir "
                    "('dist face off' or 'dist wind_dir off')",
                    name);
  }

  const char* kind = argv[2];
  if (!strcmp(kind, "discrete")) {
    d.d.kind = urDIST_DISCRETE;
    int nv = ura_parse_list(argv[3], d.d.val, urDISTMAXVAL);
    int np = ura_parse_list(argv[4], d.d.prob, urDISTMAXVAL);
    if (nv < 0 || np < 0 || nv != np) {
      return ura_fail(c,
                      "dist %s discrete: '%s' '%s' are not two lists of equal length; "
                      "accepted: V1,V2,... P1,P2,... (at most %d values)",
                      name, argv[3], argv[4], urDISTMAXVAL);
    }
    d.d.nval = nv;
  } else {
    if (!strcmp(kind, "normal"))
      d.d.kind = urDIST_NORMAL;
    else if (!strcmp(kind, "uniform"))
      d.d.kind = urDIST_UNIFORM;
    else if (!strcmp(kind, "weibull"))
      d.d.kind = urDIST_WEIBULL;
    else
      return ura_fail(c, "dist %s: unknown distribution '%s'; " USAGE, name, kind);
    for (int k = 0; k < 2; k++) {
      if (ura_parse_number(argv[3 + k], k ? &d.d.b : &d.d.a)) {
        return ura_fail(c, "dist %s %s: '%s' is not a number; " USAGE, name, kind, argv[3 + k]);
      }
    }
  }
  char why[300];
  if (ur_dist_check(&d.d, why, sizeof why)) {
    int k = ura_param_find(name) || ura_injury_find(name) >= 0 ? -1 : ura_model_param_find(c, name);
    char range[400] = "";
    if (k >= 0) ura_param_range_text(c, &c->model->param[k], range, sizeof range);
    return ura_fail(c, "dist %s: %s%s%s%s", name, why, *range ? " (" : "", range,
                    *range ? ")" : "");
  }

  /* a new declaration replaces the old one of the input */
  int i = ura_dist_find(r, name);
  if (i < 0) {
    if (r->ndist == uraMAXDIST) {
      return ura_fail(c,
                      "dist: %d inputs are declared already; accepted: at most %d "
                      "('dist NAME off' forgets one)",
                      uraMAXDIST, uraMAXDIST);
    }
    i = r->ndist++;
  }
  r->dist[i] = d;
  return 0;
}
