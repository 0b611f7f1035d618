/* cmd_montecarlo.c: montecarlo N: the declared inputs (dist) and the deployment outcomes drawn
 * per sample from a counter-based generator keyed by (seed, sample), Q of each sample from a
 * response surface of real grids (or from a grid per sample), the mean with its 95 % interval,
 * the first-order variance shares, and the paired unmitigated Q and Annex F areas that sora mc
 * reads. Sample i depends only on (seed, i): its inputs come from ur_mc_inputs, its Q from grids
 * whose cells do not depend on the number of threads, and the statistics are taken in sample
 * order, so a run is the same for any thread count (and its samples can be computed apart and
 * merged in sample order). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "../cmd.h"
#include "uasimpact/quantile.h"

#define MAXIN      (uraMAXDIST + 1 + urMAXBAGS)
#define MAXGRIDS   10000 /* grids of a response surface, at most */
#define MAXSAMPLES 1000000
#define MAXREFINE  4 /* refinements of the response surface towards mc_surface_tol */

struct uraMc {
  int n, nin, ndecl; /* samples; input columns; declared inputs (the first ones) */
  int face_col;      /* the column of face = face_dir - wind_dir, or -1 */
  int chute_col;     /* the first deployment column (chute, then bags), or -1 */
  char name[MAXIN][urNAMELEN];
  double* x;           /* n x nin inputs, sample-major */
  int* mask;           /* each sample's branch */
  double *q, *q_c;     /* Q of the sample's branch, and without any device, m^2 */
  double *ca, *ca_c;   /* their Annex F critical areas, m^2 */
  double share[MAXIN]; /* first-order variance shares (NAN: a derived column) */
  urMcStats st;
  urDeploy dep;
  int bag[urMAXBAGS];
  char casename[8];
  double seed;
  char note[5][1000]; /* inputs, method, surface check, timing, surface tolerance */
  char none[8];       /* the name of the branch without devices (ura_risk_none_name) */
  double surf_err;    /* the surface check's largest relative error (NAN: not measured) */
  char* settings;     /* the session text it ran under (sora mc checks it) */
};

void ura_mc_free(uraCtx* c) {
  struct uraMc* m = c->mc;
  if (!m) return;
  free(m->x);
  free(m->mask);
  free(m->q);
  free(m->settings);
  free(m);
  c->mc = NULL;
}

/* the session text without the settings that change no sample */
static char* settings_text(uraCtx* c) {
  static const char* const skip[] = {"set format ",
                                     "set terminal ",
                                     "set output ",
                                     "set threads ",
                                     "set recall ",
                                     "set pop_density ",
                                     "set tlos ",
                                     "set igrc_compensation ",
                                     "set lambda_system ",
                                     "set p_shelter ",
                                     "set ua_dimension ",
                                     "set ua_max_speed ",
                                     "set m2_baseline ",
                                     "set mc_quantiles ",
                                     NULL};
  char* s = ura_session_text(c);
  if (!s) return NULL;
  char* w = s;
  for (char* line = s; *line;) {
    char* end = strchr(line, '\n');
    size_t len = end ? (size_t)(end - line + 1) : strlen(line);
    int drop = 0;
    for (int i = 0; skip[i]; i++) drop |= !strncmp(line, skip[i], strlen(skip[i]));
    if (!drop) memmove(w, line, len), w += len;
    line += len;
  }
  *w = 0;
  return s;
}

/* a drawn value into a state: a number parameter of the case, an injury setting or a model
   parameter (the bearings wind_dir and face_dir act through face only) */
static void apply_input(uraState* ns, const char* name, double v) {
  if (!strcmp(name, "wind_dir") || !strcmp(name, "face_dir")) return;
  const uraParam* p = ura_param_find(name);
  if (p) {
    *(double*)((char*)ns + p->off) = v;
    if (p->setoff) *(int*)((char*)ns + p->setoff) = 1;
    return;
  }
  if (ura_injury_find(name) >= 0) {
    ur_injury_param_set(&ns->injury, name, v);
    return;
  }
  ura_risk_override(ns, name, v, 1);
}

/* the state of sample i: the live one with every drawn input (and face from the bearings) */
static void sample_state(const struct uraMc* m, const uraState* base, int i, uraState* ns) {
  *ns = *base;
  const double* x = m->x + (size_t)i * m->nin;
  for (int k = 0; k < m->ndecl; k++) apply_input(ns, m->name[k], x[k]);
  if (m->face_col >= 0) ns->face = x[m->face_col];
}

/* an input's value for messages, with its unit: "thorax_k = 30000 N/m" */
static void input_text(uraCtx* c, const char* name, double v, char* buf, size_t n) {
  const uraParam* p = ura_param_find(name);
  int i = p ? -1 : ura_injury_find(name);
  const char* unit = p ? p->unit : "";
  if (i >= 0) ur_injury_param_info(i, NULL, &unit, NULL);
  if (!strcmp(name, "wind_dir") || !strcmp(name, "face_dir")) unit = "deg";
  char t[96];
  if (p || i >= 0 || *unit)
    snprintf(t, sizeof t, "%g%s%s", v, *unit ? " " : "", unit);
  else
    ura_model_value_brief(c, name, v, t, sizeof t); /* a model parameter in its SI unit */
  snprintf(buf, n, "%s = %s", name, t);
}

/* the drawn inputs of sample i (and face from the bearings), for messages */
static void drawn_text(uraCtx* c, const struct uraMc* m, int i, char* buf, size_t n) {
  const double* x = m->x + (size_t)i * m->nin;
  size_t k = 0;
  buf[0] = 0;
  for (int j = 0; j < m->nin && k < n; j++) {
    if (j >= m->ndecl && j != m->face_col) continue;
    char t[160];
    input_text(c, m->name[j], x[j], t, sizeof t);
    k += (size_t)snprintf(buf + k, n - k, "%s%s", k ? ", " : "", t);
  }
}

/* c->err with where in a montecarlo it happened in front: "montecarlo: WHERE: message" */
static int mc_fail_at(uraCtx* c, const char* where) {
  char inner[uraERRLEN];
  const char* e = c->err;
  if (!strncmp(e, "montecarlo: ", 12)) e += 12;
  snprintf(inner, sizeof inner, "%s", e);
  return ura_fail(c, "montecarlo: %s: %.700s", where, inner);
}

/* a failure of sample i's grids or draws, naming the sample and its drawn inputs */
static int mc_fail_sample(uraCtx* c, const struct uraMc* m, int i) {
  char drawn[600], where[700];
  drawn_text(c, m, i, drawn, sizeof drawn);
  snprintf(where, sizeof where, "sample %d (%s)", i, *drawn ? drawn : "no drawn input");
  return mc_fail_at(c, where);
}

/* does an input act on the grids (the reliabilities and the bearings do not: face does) */
static int grid_input(const char* name) {
  return strcmp(name, "p_chute") && strcmp(name, "p_bag") && strcmp(name, "h_chute_min") &&
         strcmp(name, "wind_dir") && strcmp(name, "face_dir");
}

static double elapsed(const struct timespec* t0) {
  struct timespec t1;
  clock_gettime(CLOCK_MONOTONIC, &t1);
  return (t1.tv_sec - t0->tv_sec) + 1e-9 * (t1.tv_nsec - t0->tv_nsec);
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* ---- the response surface ---- */

typedef struct {
  int col; /* the input column of its coordinate */
  int n;   /* nodes */
  double node[uraMAXLIST + 1];
  int discrete; /* the nodes are the drawn values themselves */
} axis;

typedef struct {
  int nax;
  axis ax[MAXIN];
  int face_ax; /* the axis of face, or -1 */
  int mirror;  /* 1: a lattice point at face -phi takes the Q of its partner at phi */
  long total;  /* lattice points */
  int nmask, masks[urMAXBRANCH]; /* branches needed (the drawn ones and none) */
  double* value;                 /* nmask x total Q values */
} surface;

/* how a distribution lies about 0: 2 when it covers the whole circle (a uniform at least 360
   wide), 1 when it is symmetric about 0, 0 otherwise */
static int dist_sym(const urDist* d) {
  if (d->kind == urDIST_UNIFORM) return d->b - d->a >= 360 ? 2 : d->a == -d->b;
  if (d->kind == urDIST_NORMAL) return d->a == 0 && d->lo == -d->hi;
  if (d->kind != urDIST_DISCRETE) return 0;
  for (int i = 0; i < d->nval; i++) {
    int j = 0;
    while (j < d->nval && !(d->val[j] == -d->val[i] && d->prob[j] == d->prob[i])) j++;
    if (j == d->nval) return 0;
  }
  return 1;
}

/* how face's draws lie about 0 (dist_sym): declared as face, or from the bearings (a bearing
   uniform over the circle makes face uniform over it; one bearing alone, symmetric, makes it
   symmetric) */
static int face_sym(const struct uraMc* m, const uraRiskSet* r, int col) {
  if (col < m->ndecl) return dist_sym(&r->dist[col].d);
  int wd = ura_dist_find(r, "wind_dir"), fd = ura_dist_find(r, "face_dir");
  int sw = wd >= 0 ? dist_sym(&r->dist[wd].d) : 0, sf = fd >= 0 ? dist_sym(&r->dist[fd].d) : 0;
  if (sw == 2 || sf == 2) return 2;
  return (wd < 0 && sf) || (fd < 0 && sw);
}

/* whether the surface may take face -phi as phi mirrored: mc_mirror on, the live scene
   symmetric and neither roll nor yaw drawn */
static int surface_mirror(const struct uraMc* m, const uraState* st) {
  if (!st->risk.mc_mirror || !ura_grid_symmetric(st)) return 0;
  for (int k = 0; k < m->ndecl; k++) {
    if (!strcmp(m->name[k], "roll") || !strcmp(m->name[k], "yaw")) return 0;
  }
  return 1;
}

/* n nodes over [-h, h], symmetric to the bit (node n-1-j is -node j; 0 in the middle) */
static void symmetric_nodes(axis* a, int n, double h) {
  for (int j = 0; j < n / 2; j++) {
    a->node[j] = j == 0 ? -h : -h + 2 * h * j / (n - 1);
    a->node[n - 1 - j] = -a->node[j];
  }
  if (n % 2) a->node[n / 2] = 0;
  a->n = n;
}

/* the axes: one per drawn input of the grids, nodes spanning what was drawn (face's symmetric
   about 0 when its draws are and the mirror applies: the whole circle when they cover it) */
static void surface_axes(const struct uraMc* m, const uraState* st, surface* s) {
  s->nax = 0;
  s->total = 1;
  s->face_ax = -1;
  s->mirror = surface_mirror(m, st);
  for (int k = 0; k < m->nin; k++) {
    int decl = k < m->ndecl;
    if ((decl && !grid_input(m->name[k])) || (!decl && k != m->face_col)) continue;
    axis* a = &s->ax[s->nax++];
    a->col = k;
    a->discrete = decl && st->risk.dist[k].d.kind == urDIST_DISCRETE;
    double lo = INFINITY, hi = -INFINITY;
    a->n = 0;
    for (int i = 0; i < m->n; i++) {
      double v = m->x[(size_t)i * m->nin + k];
      lo = fmin(lo, v);
      hi = fmax(hi, v);
      if (a->discrete) {
        int seen = 0;
        for (int j = 0; j < a->n; j++) seen |= a->node[j] == v;
        if (!seen) a->node[a->n++] = v;
      }
    }
    int sym = !strcmp(m->name[k], "face") ? face_sym(m, &st->risk, k) : 0;
    if (!strcmp(m->name[k], "face")) s->face_ax = s->nax - 1;
    if (a->discrete) {
      qsort(a->node, (size_t)a->n, sizeof(double), cmp_double);
    } else if (s->mirror && sym && lo < 0 && hi > 0 && st->risk.surface_nodes > 2) {
      symmetric_nodes(a, (int)st->risk.surface_nodes, fmax(sym == 2 ? 180 : 0, fmax(-lo, hi)));
    } else {
      int n = lo == hi ? 1 : (int)st->risk.surface_nodes;
      for (int j = 0; j < n; j++) a->node[j] = n == 1 ? lo : lo + (hi - lo) * j / (n - 1);
      a->node[n - 1] = hi;
      a->n = n;
    }
    s->total *= a->n;
  }
}

/* the lattice point idx of a surface as a state of branch mask */
static void node_state(const struct uraMc* m, const surface* s, const uraState* base, long idx,
                       int mask, uraState* tmp, uraState* ns) {
  *tmp = *base;
  for (int d = s->nax - 1; d >= 0; d--) {
    const axis* a = &s->ax[d];
    apply_input(tmp, m->name[a->col], a->node[idx % a->n]);
    idx /= a->n;
  }
  ura_risk_branch_state(tmp, mask, &m->dep, m->bag, m->none, ns);
}

static double surface_at(const struct uraMc* m, const surface* s, int mask, int i) {
  int nn[MAXIN];
  const double* node[MAXIN];
  double x[MAXIN];
  int k = 0;
  while (s->masks[k] != mask) k++;
  for (int d = 0; d < s->nax; d++) {
    nn[d] = s->ax[d].n;
    node[d] = s->ax[d].node;
    x[d] = m->x[(size_t)i * m->nin + s->ax[d].col];
  }
  return ur_lattice_interp(s->nax, nn, node, s->value + (size_t)k * s->total, x);
}

static void progress(int tty, const char* what, long k, long n) {
  char w[80];
  snprintf(w, sizeof w, "montecarlo: %s", what);
  if (tty) ura_progress_line(w, k, n, "");
}

/* a failure of the surface's grid g, naming its node (the drawn inputs' values there) */
static int node_fail(uraCtx* c, const struct uraMc* m, const surface* s, long g) {
  char where[700], t[160];
  long idx = g % s->total;
  size_t k = (size_t)snprintf(where, sizeof where, "the response surface's grid %ld of %ld at",
                              g + 1, s->total * s->nmask);
  for (int d = s->nax - 1; d >= 0 && k < sizeof where; d--) {
    const axis* a = &s->ax[d];
    input_text(c, m->name[a->col], a->node[idx % a->n], t, sizeof t);
    k += (size_t)snprintf(where + k, sizeof where - k, "%s %s", d == s->nax - 1 ? "" : ",", t);
    idx /= a->n;
  }
  if (s->nax == 0) snprintf(where, sizeof where, "the grid of the live state");
  return mc_fail_at(c, where);
}

/* insert the midpoint of the interval holding x into a continuous axis; 0 when it cannot */
static int refine_axis(axis* a, double x) {
  if (a->discrete || a->n < 2 || a->n >= uraMAXLIST + 1) return 0;
  int j = 0;
  while (j < a->n - 2 && x >= a->node[j + 1]) j++;
  double mid = 0.5 * (a->node[j] + a->node[j + 1]);
  if (!(mid > a->node[j] && mid < a->node[j + 1])) return 0;
  memmove(&a->node[j + 2], &a->node[j + 1], (size_t)(a->n - j - 1) * sizeof(double));
  a->node[j + 1] = mid;
  a->n++;
  return 1;
}

/* after refine_axis(a, x) on a face axis whose nodes were symmetric: the midpoint of the mirror
   interval too, so that the axis stays symmetric and the new nodes at -phi cost no grid (not
   when x's interval straddled 0: its midpoint was its own mirror); 1 when inserted */
static int refine_mirror(axis* a, double x) {
  for (int j = 0; j < a->n; j++) {
    if (a->node[j] == x) return 0;
  }
  int j = 0;
  while (j < a->n - 2 && -x >= a->node[j + 1]) j++;
  double mid = 0.5 * (a->node[j] + a->node[j + 1]);
  int k = 0;
  while (k < a->n && a->node[k] != -mid) k++;
  if (k == a->n || mid == 0) return 0; /* its partner is not there: it stays as it was */
  return refine_axis(a, -x);
}

/* whether an axis's nodes are symmetric about 0 to the bit */
static int axis_symmetric(const axis* a) {
  for (int j = 0; j < a->n; j++) {
    if (a->node[j] != -a->node[a->n - 1 - j]) return 0;
  }
  return 1;
}

/* the value of lattice point idx of s (branch k) in an earlier lattice old whose axes hold every
   node of it; 0 with *v, or -1 when a node is new */
static int old_value(const surface* s, const surface* old, long idx, int k, double* v) {
  if (!old || !old->value) return -1;
  long oidx = 0, ostride = 1;
  for (int d = s->nax - 1; d >= 0; d--) {
    const axis* a = &s->ax[d];
    const axis* o = &old->ax[d];
    double x = a->node[idx % a->n];
    idx /= a->n;
    int j = 0;
    while (j < o->n && o->node[j] != x) j++;
    if (j == o->n) return -1;
    oidx += j * ostride;
    ostride *= o->n;
  }
  *v = old->value[(size_t)k * old->total + oidx];
  return 0;
}

/* Q of state ns's grid, asked for at its mirror face (ura_risk_grid_mirror: face -phi as phi)
   when mc_mirror is on; *mirrored (unless NULL) 1 when it was */
static int mc_grid(uraCtx* c, const uraState* ns, double* q, int* mirrored) {
  int mir = 0;
  int rc = ns->risk.mc_mirror ? ura_risk_grid_mirror(c, ns, "montecarlo", 1, q, &mir)
                              : ura_risk_grid(c, ns, "montecarlo", 1, q);
  if (mirrored) *mirrored = mir;
  return rc;
}

/* the grid whose Q grid g of s takes by mirror symmetry (the same lattice point and branch at
   face phi for one at -phi, ura_risk_mirror_face), or -1 when it has none */
static long mirror_partner(const surface* s, const uraState* base, long g) {
  if (!s->mirror || s->face_ax < 0) return -1;
  long stride = 1;
  for (int d = s->nax - 1; d > s->face_ax; d--) stride *= s->ax[d].n;
  const axis* a = &s->ax[s->face_ax];
  int j = (int)((g % s->total) / stride % a->n);
  double x = ura_risk_mirror_face(base, a->node[j]);
  if (x == a->node[j]) return -1;
  int p = 0;
  while (p < a->n && a->node[p] != x) p++;
  return p == a->n ? -1 : g + (p - j) * stride;
}

/* how the surface's grids were had: each lattice point once, in the round it appeared */
typedef struct {
  int kept;     /* from the earlier (coarser) lattice, each round again */
  int recalled; /* an identical earlier grid (recall.c) */
  int computed; /* run */
  int mirrored; /* the Q of its partner at the mirror face */
} gridCount;

/* the surface's grids (every lattice point of every branch needed; those of an earlier lattice
   old are taken from it, those at face -phi from their partner at phi), counted into n */
static int surface_build(uraCtx* c, struct uraMc* m, surface* s, const surface* old,
                         const uraState* base, uraState* tmp, uraState* ns, int tty, gridCount* n) {
  s->total = 1;
  for (int d = 0; d < s->nax; d++) s->total *= s->ax[d].n;
  long ngrid = s->total * s->nmask;
  if (ngrid > MAXGRIDS) {
    return ura_fail(c,
                    "montecarlo: the response surface needs %ld grids; accepted: at most %d "
                    "(lower surface_nodes, or 'set mc_method exact')",
                    ngrid, MAXGRIDS);
  }
  s->value = malloc((size_t)ngrid * sizeof *s->value);
  if (!s->value) return ura_fail(c, "montecarlo: out of memory");
  int rc = 0;
  for (long g = 0; g < ngrid && rc == 0; g++) {
    progress(tty, "surface grid", g + 1, ngrid);
    if (old_value(s, old, g % s->total, (int)(g / s->total), &s->value[g]) == 0) {
      n->kept++;
      continue;
    }
    if (mirror_partner(s, base, g) >= 0) continue; /* below, once its partner is there */
    node_state(m, s, base, g % s->total, s->masks[g / s->total], tmp, ns);
    rc = mc_grid(c, ns, &s->value[g], NULL);
    n->recalled += rc == 0 && c->last.recalled;
    n->computed += rc == 0 && !c->last.recalled;
    if (rc) node_fail(c, m, s, g);
  }
  for (long g = 0; g < ngrid && rc == 0; g++) {
    long p = mirror_partner(s, base, g);
    if (p < 0 || old_value(s, old, g % s->total, (int)(g / s->total), &s->value[g]) == 0) continue;
    /* its model (the branch's devices, the drawn parameters) must be mirror-symmetric too */
    node_state(m, s, base, g % s->total, s->masks[g / s->total], tmp, ns);
    if (ura_model_state(c, ns, "montecarlo")) {
      rc = -1;
      node_fail(c, m, s, g);
      break;
    }
    if (c->model->mirror) {
      s->value[g] = s->value[p];
      n->mirrored++;
      continue;
    }
    rc = ura_risk_grid(c, ns, "montecarlo", 1, &s->value[g]);
    n->recalled += rc == 0 && c->last.recalled;
    n->computed += rc == 0 && !c->last.recalled;
    if (rc) node_fail(c, m, s, g);
  }
  return rc;
}

/* Q of every sample from the surface; a few samples again by their own grids; below
   mc_surface_tol, or refined where the error is largest, or a failure */
static int by_surface(uraCtx* c, struct uraMc* m, const uraState* base, uraState* tmp, uraState* ns,
                      int tty) {
  surface s;
  memset(&s, 0, sizeof s);
  surface_axes(m, base, &s);
  s.masks[s.nmask++] = 0;
  for (int i = 0; i < m->n; i++) {
    int seen = 0;
    for (int k = 0; k < s.nmask; k++) seen |= s.masks[k] == m->mask[i];
    if (!seen) s.masks[s.nmask++] = m->mask[i];
  }
  int exact = 1;
  for (int d = 0; d < s.nax; d++) exact &= s.ax[d].discrete || s.ax[d].n == 1;
  int nchk = exact ? 0 : (int)fmin(base->risk.surface_check, m->n);
  double tol = base->risk.surface_tol, *qchk = calloc((size_t)nchk + 1, sizeof *qchk);
  if (!qchk) return ura_fail(c, "montecarlo: out of memory");
  int rc = 0, round = 0, first_worse = 0;
  gridCount cnt = {0, 0, 0, 0};
  double first_err = 0, emax = 0, rmax = 0, esum = 0;
  long ngrid = 0;
  /* the check samples' own grids, once */
  for (int i = 0; i < nchk && rc == 0; i++) {
    progress(tty, "surface check", i + 1, nchk);
    sample_state(m, base, i, tmp);
    ura_risk_branch_state(tmp, m->mask[i], &m->dep, m->bag, m->none, ns);
    rc = mc_grid(c, ns, &qchk[i], NULL);
    if (rc) mc_fail_sample(c, m, i);
  }
  surface prev;
  memset(&prev, 0, sizeof prev);
  for (;; round++) {
    if (rc == 0) {
      rc = surface_build(c, m, &s, &prev, base, tmp, ns, tty, &cnt);
    }
    free(prev.value);
    prev.value = NULL;
    if (rc) break;
    ngrid = s.total * s.nmask;
    for (int i = 0; i < m->n; i++) {
      m->q[i] = surface_at(m, &s, m->mask[i], i);
      m->q_c[i] = surface_at(m, &s, 0, i);
    }
    int worst = -1;
    emax = rmax = esum = 0;
    for (int i = 0; i < nchk; i++) {
      double e = fabs(m->q[i] - qchk[i]);
      emax = fmax(emax, e);
      esum += e;
      double rel = qchk[i] > 0 ? e / qchk[i] : e > 0 ? INFINITY : 0;
      if (rel > rmax || worst < 0) rmax = fmax(rmax, rel), worst = i;
    }
    if (round == 0) first_err = rmax, first_worse = tol > 0 && rmax > tol;
    if (!(tol > 0) || rmax <= tol || !nchk) break;
    if (round == MAXREFINE) {
      rc = ura_fail(c,
                    "montecarlo: the response surface's error %.3g %% (sample %d) is above "
                    "mc_surface_tol %.3g %% after %d refinements; accepted: more surface_nodes, "
                    "a larger mc_surface_tol, or 'set mc_method exact'",
                    100 * rmax, worst, 100 * tol, MAXREFINE);
      break;
    }
    /* refine every continuous axis at the worst sample (the lattice so far kept) */
    prev = s;
    s.value = NULL;
    int any = 0;
    for (int d = 0; d < s.nax; d++) {
      double x = m->x[(size_t)worst * m->nin + s.ax[d].col];
      int sym = d == s.face_ax && s.mirror && axis_symmetric(&s.ax[d]);
      int r = refine_axis(&s.ax[d], x);
      if (r && sym) refine_mirror(&s.ax[d], x);
      any |= r;
    }
    if (!any) {
      rc = ura_fail(c,
                    "montecarlo: the response surface's error %.3g %% is above mc_surface_tol "
                    "%.3g %% and its axes cannot be refined further; accepted: 'set mc_method "
                    "exact' or a larger mc_surface_tol",
                    100 * rmax, 100 * tol);
      s.value = prev.value; /* nothing refined: the lattice is the one kept */
      prev.value = NULL;
      break;
    }
  }
  free(qchk);

  /* the method, in words */
  int recalled = cnt.recalled + cnt.kept;
  char mirror[500], asym[300] = "";
  const urModel* lm = s.mirror && s.face_ax >= 0 && !cnt.mirrored ? c->model : NULL;
  if (lm && !lm->mirror)
    snprintf(asym, sizeof asym, ": the model is not mirror-symmetric: %s", lm->nomirror);
  snprintf(mirror, sizeof mirror,
           "grids: %d computed, %d taken by mirror symmetry (face -phi is phi mirrored)%s, %d "
           "recalled",
           cnt.computed, cnt.mirrored,
           !base->risk.mc_mirror ? ": mc_mirror off"
           : !s.mirror           ? ": roll or yaw breaks the symmetry"
           : s.face_ax < 0       ? ": face is not drawn"
                                 : asym,
           cnt.recalled);
  char axes[400] = "";
  size_t k = 0;
  for (int d = 0; d < s.nax && k < sizeof axes; d++) {
    const axis* a = &s.ax[d];
    k += (size_t)snprintf(axes + k, sizeof axes - k, "%s%s %d %s %g..%g", d ? ", " : "",
                          m->name[a->col], a->n, a->discrete ? "values" : "nodes", a->node[0],
                          a->node[a->n - 1]);
  }
  snprintf(m->note[1], sizeof m->note[1],
           "method: response surface: Q on a lattice of real "
           "grids (step %g m), %ld point%s x %d deployment branch%s = %ld grids%s%s%s; %s; %s; %s",
           base->step, s.total, s.total == 1 ? "" : "s", s.nmask, s.nmask == 1 ? "" : "es", ngrid,
           recalled ? " (" : "", recalled ? "some recalled" : "", recalled ? ")" : "",
           s.nax ? axes : "no drawn input acts on the grids",
           exact ? "every sample is on a lattice point: exact"
                 : "multilinear interpolation between the nodes",
           mirror);
  m->surf_err = nchk ? rmax : NAN;
  if (exact) {
    snprintf(m->note[2], sizeof m->note[2], "surface check: not needed (exact)");
  } else if (nchk) {
    snprintf(m->note[2], sizeof m->note[2],
             "surface check: samples 0..%d computed by their own "
             "grids: |Q_surface - Q_grid| at most %.3g m^2 (%.2g %%), mean %.3g m^2 "
             "(surface_check)",
             nchk - 1, emax, 100 * rmax, esum / nchk);
  } else {
    snprintf(m->note[2], sizeof m->note[2],
             "surface check: none (surface_check 0): the "
             "interpolation error is not measured");
  }
  if (exact) {
    m->note[4][0] = 0;
  } else if (!(tol > 0)) {
    snprintf(m->note[4], sizeof m->note[4],
             "surface tolerance: none declared (set mc_surface_tol): the surface's error%s is "
             "not held to any bound",
             nchk ? " above" : "");
  } else if (first_worse) {
    snprintf(m->note[4], sizeof m->note[4],
             "warning: the surface's error %.3g %% was above mc_surface_tol %.3g %%; refined %d "
             "time%s where the error was largest, now %.3g %%",
             100 * first_err, 100 * tol, round, round == 1 ? "" : "s", 100 * rmax);
  } else {
    snprintf(m->note[4], sizeof m->note[4], "surface tolerance: error %.3g %% within %.3g %%%s",
             100 * rmax, 100 * tol, nchk ? "" : " (not measured: surface_check 0)");
  }
  free(s.value);
  return rc;
}

/* Q of every sample from its own grids */
static int by_grids(uraCtx* c, struct uraMc* m, const uraState* base, uraState* tmp, uraState* ns,
                    int tty) {
  int rc = 0, ngrid = 0, recalled = 0, mirrored = 0;
  for (int i = 0; i < m->n && rc == 0; i++) {
    progress(tty, "sample", i + 1, m->n);
    sample_state(m, base, i, tmp);
    for (int b = 0; b < 2 && rc == 0; b++) {
      int mask = b ? 0 : m->mask[i];
      if (b && m->mask[i] == 0) {
        m->q_c[i] = m->q[i];
        break;
      }
      ura_risk_branch_state(tmp, mask, &m->dep, m->bag, m->none, ns);
      int mir;
      rc = mc_grid(c, ns, b ? &m->q_c[i] : &m->q[i], &mir);
      if (rc) mc_fail_sample(c, m, i);
      ngrid++;
      recalled += rc == 0 && c->last.recalled;
      mirrored += rc == 0 && c->last.recalled && mir;
    }
  }
  snprintf(m->note[1], sizeof m->note[1],
           "method: exact: every sample's own grids (step %g m), "
           "%d grids (%d recalled: samples with identical conditions; %d of them by mirror "
           "symmetry, face -phi as phi%s)",
           base->step, ngrid, recalled, mirrored, base->risk.mc_mirror ? "" : ": mc_mirror off");
  snprintf(m->note[2], sizeof m->note[2], "surface check: not needed (exact)");
  return rc;
}

/* ---- the command ---- */

static int mc_shares(uraCtx* c);
static int mc_samples(uraCtx* c);
static void mc_summary(uraCtx* c);

/* the input columns and the draws of every sample */
static int draw(uraCtx* c, struct uraMc* m, const uraState* base, uraState* ns) {
  const uraRiskSet* r = &base->risk;
  const char* names[uraMAXDIST];
  urDist dist[uraMAXDIST];
  int bearings = 0;
  m->ndecl = r->ndist;
  for (int k = 0; k < r->ndist; k++) {
    double lo, hi;
    if (ura_dist_range(c, r->dist[k].name, &lo, &hi)) return -1;
    snprintf(m->name[k], urNAMELEN, "%s", r->dist[k].name);
    names[k] = m->name[k];
    dist[k] = r->dist[k].d;
    bearings |=
        !grid_input(names[k]) && strncmp(names[k], "p_", 2) && strcmp(names[k], "h_chute_min");
  }
  m->nin = m->ndecl;
  m->face_col = bearings ? m->nin++ : -1;
  if (bearings) snprintf(m->name[m->face_col], urNAMELEN, "face");
  m->chute_col = m->dep.chute ? m->nin : -1;
  if (m->dep.chute) {
    snprintf(m->name[m->nin++], urNAMELEN, "chute");
    for (int j = 0; j < m->dep.nbag; j++) {
      snprintf(m->name[m->nin++], urNAMELEN, "%s", ura_risk_bag(m->bag[j]));
    }
  }
  size_t n = (size_t)m->n;
  m->x = malloc(n * m->nin * sizeof *m->x);
  m->mask = malloc(n * sizeof *m->mask);
  m->q = malloc(4 * n * sizeof *m->q);
  if (!m->x || !m->mask || !m->q)
    return ura_fail(c, "montecarlo: out of memory for %d samples", m->n);
  m->q_c = m->q + n;
  m->ca = m->q + 2 * n;
  m->ca_c = m->q + 3 * n;

  uint64_t seed = (uint64_t)r->seed;
  for (int i = 0; i < m->n; i++) {
    double *x = m->x + (size_t)i * m->nin, u[1 + urMAXBAGS];
    ur_mc_inputs(seed, (uint64_t)i, m->ndecl, names, dist, x, u);
    if (bearings) {
      /* the course runs downwind; face is the person's bearing from the one the wind comes
         from, wrapped to [-180, 180) */
      int wd = ura_dist_find(r, "wind_dir"), fd = ura_dist_find(r, "face_dir");
      double phi = (fd >= 0 ? x[fd] : 0) - (wd >= 0 ? x[wd] : 0);
      x[m->face_col] = phi - 360 * floor((phi + 180) / 360);
    }
    /* a model parameter drawn outside its range (declared before the model changed) */
    for (int k = 0; k < m->ndecl; k++) {
      int pk = ura_param_find(names[k]) || ura_injury_find(names[k]) >= 0
                   ? -1
                   : ura_model_param_find(c, names[k]);
      if (pk >= 0 && !ur_param_accepts(&c->model->param[pk], x[k])) {
        char v[160], range[400];
        input_text(c, names[k], x[k], v, sizeof v);
        ura_param_range_text(c, &c->model->param[pk], range, sizeof range);
        ura_fail(c,
                 "%s is out of range; accepted: %s (the model changed since 'dist %s' was "
                 "declared: declare it again)",
                 v, range, names[k]);
        return mc_fail_sample(c, m, i);
      }
    }
    sample_state(m, base, i, ns);
    urDeploy d = m->dep;
    d.p_chute = ns->risk.p_chute;
    d.p_bag = ns->risk.p_bag;
    d.altitude = ns->descent.altitude;
    d.h_chute_min = ns->risk.h_chute_min;
    m->mask[i] = ur_deploy_outcome(&d, u[0], u + 1);
    /* the outcomes as drawn: each airbag's whether the parachute deployed or not (so that the
       columns are independent inputs; the branch credits no airbag without the parachute) */
    if (m->chute_col >= 0) {
      x[m->chute_col] = m->mask[i] & 1;
      for (int j = 0; j < m->dep.nbag; j++) x[m->chute_col + 1 + j] = u[1 + j] < d.p_bag;
    }
  }
  return 0;
}

int ura_cmd_montecarlo(uraCtx* c, int argc, char** argv) {
  if (!strcmp(argv[1], "shares")) return mc_shares(c);
  if (!strcmp(argv[1], "samples")) return mc_samples(c);
  double nd;
  if (ura_parse_number(argv[1], &nd) || nd != floor(nd) || nd < 2 || nd > MAXSAMPLES) {
    return ura_fail(c,
                    "montecarlo: '%s' is not accepted; accepted: a whole number of samples "
                    "in [2, %d], shares or samples",
                    argv[1], MAXSAMPLES);
  }
  if (ura_dry(c, "simulation")) return -1;
  struct timespec t0;
  clock_gettime(CLOCK_MONOTONIC, &t0);

  struct uraMc* m = calloc(1, sizeof *m);
  uraState* st = malloc(3 * sizeof *st); /* the live state, and two to work in */
  if (!m || !st) {
    free(m);
    free(st);
    return ura_fail(c, "montecarlo: out of memory");
  }
  uraState *tmp = st + 1, *ns = st + 2;
  *st = c->st;
  m->n = (int)nd;
  m->seed = st->risk.seed;
  snprintf(m->casename, sizeof m->casename, "%s", st->casename);
  int rc = ura_risk_devices(c, st, &m->dep, m->bag);
  snprintf(m->none, sizeof m->none, "%s", ura_risk_none_name(c));
  if (rc == 0) rc = draw(c, m, st, ns);

  /* Q of each sample, then the Annex F areas at each sample's impact conditions */
  int tty = isatty(STDERR_FILENO);
  ura_progress_start();
  if (rc == 0) {
    rc = st->risk.mc_method == uraMC_EXACT ? by_grids(c, m, st, tmp, ns, tty)
                                           : by_surface(c, m, st, tmp, ns, tty);
  }
  for (int i = 0; i < m->n && rc == 0; i++) {
    double sp, an;
    sample_state(m, st, i, tmp);
    ura_risk_branch_state(tmp, m->mask[i], &m->dep, m->bag, m->none, ns);
    rc = ura_risk_annexf(c, ns, &m->ca[i], &sp, &an);
    if (rc == 0 && m->mask[i] == 0)
      m->ca_c[i] = m->ca[i];
    else if (rc == 0) {
      ura_risk_branch_state(tmp, 0, &m->dep, m->bag, m->none, ns);
      rc = ura_risk_annexf(c, ns, &m->ca_c[i], &sp, &an);
    }
  }
  if (tty) fputs("\r\033[K", stderr);

  /* the live state back (the last grid stays the last one computed) */
  char err[uraERRLEN];
  snprintf(err, sizeof err, "%s", c->err);
  if (ura_model_state(c, st, "montecarlo") && rc == 0)
    rc = -1;
  else
    snprintf(c->err, sizeof c->err, "%s", err);
  if (rc && strncmp(c->err, "montecarlo", 10)) {
    snprintf(err, sizeof err, "%s", c->err);
    ura_fail(c, "montecarlo: %.900s", err);
  }

  /* statistics in sample order, the variance shares, what it ran under */
  double* work = rc == 0 ? malloc((size_t)m->n * sizeof *work) : NULL;
  if (rc == 0 && !work) rc = ura_fail(c, "montecarlo: out of memory");
  if (rc == 0) {
    ur_mc_stats(m->q, m->n, work, &m->st);
    double* col = work;
    for (int k = 0; k < m->nin; k++) {
      for (int i = 0; i < m->n; i++) col[i] = m->x[(size_t)i * m->nin + k];
      m->share[k] = k == m->face_col ? NAN : ur_mc_first_order(col, m->q, m->n);
    }
    m->settings = settings_text(c);
    if (!m->settings) rc = ura_fail(c, "montecarlo: out of memory");
  }
  free(work);
  free(st);
  if (rc) {
    free(m->settings);
    m->settings = NULL;
    struct uraMc* keep = c->mc;
    c->mc = m;
    ura_mc_free(c);
    c->mc = keep;
    return -1;
  }
  snprintf(m->note[3], sizeof m->note[3], "time: %.1f s", elapsed(&t0));
  ura_mc_free(c);
  c->mc = m;
  mc_summary(c);
  return 0;
}

/* the inputs in words */
static void inputs_note(uraCtx* c, struct uraMc* m, char* buf, size_t n) {
  char d[400];
  size_t k = (size_t)snprintf(buf, n, "inputs: ");
  for (int i = 0; i < c->st.risk.ndist && k < n; i++) {
    ura_dist_format(&c->st.risk.dist[i], d, sizeof d);
    k += (size_t)snprintf(buf + k, n - k, "%s%s ~ %s", i ? ", " : "", c->st.risk.dist[i].name, d);
  }
  if (!c->st.risk.ndist && k < n) k += (size_t)snprintf(buf + k, n - k, "none declared");
  if (m->face_col >= 0 && k < n) {
    k += (size_t)snprintf(buf + k, n - k,
                          "; face = face_dir - wind_dir (the course runs "
                          "downwind)");
  }
  if (k < n) {
    if (m->dep.chute) {
      k += (size_t)snprintf(buf + k, n - k,
                            "; deployment drawn per sample: p_chute %g, p_bag %g (%d "
                            "airbag%s), h_chute_min %g m",
                            c->st.risk.p_chute, c->st.risk.p_bag, m->dep.nbag,
                            m->dep.nbag == 1 ? "" : "s", c->st.risk.h_chute_min);
    } else {
      k += (size_t)snprintf(buf + k, n - k, "; no parachute: nothing deploys");
    }
  }
  char fixed[800];
  if (k < n && ura_risk_fixed_bags(c, &m->dep, m->bag, fixed, sizeof fixed))
    snprintf(buf + k, n - k, "; %s", fixed);
}

static double mean_of(const double* y, int n) {
  double m = 0;
  for (int i = 0; i < n; i++) m += (y[i] - m) / (i + 1);
  return m;
}

static int cmp_q(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* the summary montecarlo prints: the interval of the mean truncated at Q >= 0 (1 when it was),
   each mc_quantiles quantile of Q into qv (NAN without memory) and its column name into qname */
static int mc_tails(const struct uraMc* m, const uraRiskSet* rs, double* lo, double* hi, double* qv,
                    char (*qname)[24]) {
  *lo = m->st.lo95;
  *hi = m->st.hi95;
  int clip = ur_interval_clip(lo, hi, 0, INFINITY);
  double* sorted = malloc((size_t)m->n * sizeof *sorted);
  if (sorted) {
    memcpy(sorted, m->q, (size_t)m->n * sizeof *sorted);
    qsort(sorted, (size_t)m->n, sizeof *sorted, cmp_q);
  }
  for (int j = 0; j < rs->nquant; j++) {
    snprintf(qname[j], sizeof qname[j], "p%g", 100 * rs->quant[j]);
    qv[j] = sorted ? ur_quantile_sorted(sorted, m->n, rs->quant[j]) : NAN;
  }
  free(sorted);
  return clip;
}

static void mc_summary(uraCtx* c) {
  struct uraMc* m = c->mc;
  const uraRiskSet* rs = &c->st.risk;
  char buf[1000], qname[uraMAXBANDS][24];
  double lo, hi, qv[uraMAXBANDS];
  int clip = mc_tails(m, rs, &lo, &hi, qv, qname), thin = 0;
  const char* cols[5 + uraMAXBANDS] = {"n", "mean", "sd", "lo95", "hi95"};
  for (int j = 0; j < rs->nquant; j++) cols[5 + j] = qname[j];
  uraTable* t = ura_table_new(5 + rs->nquant, cols);
  ura_table_note(t,
                 "Q of case %s over %d samples (seed %.0f; sample i depends on (seed, i) "
                 "only): mean and sd of the samples, lo95..hi95 the 95 %% confidence interval of "
                 "the mean (Student's t)",
                 m->casename, m->n, m->seed);
  inputs_note(c, m, buf, sizeof buf);
  snprintf(m->note[0], sizeof m->note[0], "%s", buf);
  for (int i = 0; i < 3; i++) ura_table_note(t, "%s", m->note[i]);
  if (m->note[4][0]) ura_table_note(t, "%s", m->note[4]);
  ura_table_note(t,
                 "the samples' spread: 2.5 %% and 97.5 %% quantiles %.6g and %.6g m^2, min "
                 "%.6g, max %.6g",
                 m->st.p025, m->st.p975, m->st.min, m->st.max);
  size_t k = (size_t)snprintf(buf, sizeof buf,
                              "variance shares (first-order, 'montecarlo "
                              "shares'): ");
  for (int i = 0; i < m->nin && k < sizeof buf; i++) {
    if (i == m->face_col) continue;
    k += (size_t)snprintf(buf + k, sizeof buf - k, "%s%s %.3g", i ? ", " : "", m->name[i],
                          m->share[i]);
  }
  if (!m->nin && k < sizeof buf) snprintf(buf + k, sizeof buf - k, "no input drawn");
  ura_table_note(t, "%s", buf);
  if (m->dep.chute) {
    double r, rlo, rhi;
    if (ur_mc_ratio(m->q_c, m->q, m->n, &r, &rlo, &rhi) == 0) {
      ura_table_note(t,
                     "unmitigated (no parachute, no airbag) at the same samples: mean Q %.6g "
                     "m^2, reduction factor %.4g (95 %% interval %.4g..%.4g; 'sora mc')",
                     mean_of(m->q_c, m->n), r, rlo, rhi);
    }
  }
  /* the tails: quantiles of Q; the interval of the mean truncated at Q >= 0 */
  char thin_names[200] = "";
  size_t tk = 0;
  for (int j = 0; j < rs->nquant; j++) {
    if (ur_quantile_thin(m->n, rs->quant[j]) && tk < sizeof thin_names) {
      tk += (size_t)snprintf(thin_names + tk, sizeof thin_names - tk, "%s%s", thin ? ", " : "",
                             qname[j]);
      thin++;
    }
  }
  ura_table_note(t,
                 "tails: the columns after hi95 are quantiles of Q over the samples (the spread of "
                 "Q itself, not of its mean; linear between order statistics; 'set "
                 "mc_quantiles' chooses them)");
  if (clip) {
    ura_table_note(t,
                   "truncated: the interval of the mean reached below 0 (%.4g); lo95 is held at 0, "
                   "Q's physical bound",
                   m->st.lo95);
  }
  if (m->n < 30) {
    ura_table_note(t,
                   "few samples: n = %d; the interval of the mean (Student's t) assumes a nearly "
                   "normal mean, which so few samples of a skewed Q do not show",
                   m->n);
  }
  if (thin) {
    ura_table_note(t,
                   "thin tails: %s rest%s on fewer than %d samples beyond them (n min(p, 1-p) < "
                   "%d); more samples resolve them",
                   thin_names, thin == 1 ? "s" : "", urQ_TAILMIN, urQ_TAILMIN);
  }
  ura_table_note(t, "%s", m->note[3]);
  ura_table_cell(t, "%d", m->n);
  ura_table_cell(t, "%.6g", m->st.mean);
  ura_table_cell(t, "%.6g", m->st.sd);
  ura_table_cell(t, "%.6g", lo);
  ura_table_cell(t, "%.6g", hi);
  for (int j = 0; j < rs->nquant; j++) ura_table_cell(t, "%.6g", qv[j]);
  ura_table_print(c, t);
}

static int mc_shares(uraCtx* c) {
  static const char* const cols[] = {"input", "share"};
  struct uraMc* m = c->mc;
  if (!m) return ura_fail(c, "montecarlo shares: no montecarlo yet; run 'montecarlo N'");
  uraTable* t = ura_table_new(2, cols);
  ura_table_note(t,
                 "first-order variance shares of Q over the %d samples of the last "
                 "montecarlo: S = Var(E[Q | input]) / Var(Q), by the means of Q over about "
                 "sqrt(N) bins of the input (bias-corrected); nan when Q does not vary",
                 m->n);
  for (int k = 0; k < m->nin; k++) {
    if (k == m->face_col) continue;
    ura_table_cell(t, "%s", m->name[k]);
    ura_table_cell(t, "%.4f", m->share[k]);
  }
  ura_table_print(c, t);
  return 0;
}

static int mc_samples(uraCtx* c) {
  struct uraMc* m = c->mc;
  if (!m) return ura_fail(c, "montecarlo samples: no montecarlo yet; run 'montecarlo N'");
  const uraRiskSet* rs = &c->st.risk;
  const char* cols[MAXIN + 11 + uraMAXBANDS];
  char qname[uraMAXBANDS][24];
  double lo, hi, qv[uraMAXBANDS];
  mc_tails(m, rs, &lo, &hi, qv, qname);
  int nc = 0;
  cols[nc++] = "sample";
  for (int k = 0; k < m->nin; k++) cols[nc++] = m->name[k];
  cols[nc++] = "branch";
  cols[nc++] = "q";
  cols[nc++] = "q_unmitigated";
  cols[nc++] = "ca_annexf";
  cols[nc++] = "ca_annexf_unmitigated";
  cols[nc++] = "mean";
  cols[nc++] = "sd";
  cols[nc++] = "lo95";
  cols[nc++] = "hi95";
  for (int j = 0; j < rs->nquant; j++) cols[nc++] = qname[j];
  uraTable* t = ura_table_new(nc, cols);
  /* the units for the sidecar of export montecarlo: Q, the critical areas and the summary of Q
     in m^2, each drawn input in its parameter's unit, a deployment outcome 0/1 */
  for (int j = 0; j < nc; j++) {
    const char* u = ura_column_unit(cols[j]);
    if (j > 0 && j <= m->nin) {
      const uraParam* p = ura_param_find(cols[j]);
      int k = p ? -1 : ura_model_param_find(c, cols[j]);
      u = p ? p->unit : k >= 0 ? c->model->param[k].unit : "";
    } else if (j > m->nin + 1) {
      u = "m^2";
    }
    if (u) ura_table_unit(t, j, u);
  }
  ura_table_note(t,
                 "the %d samples of the last montecarlo of case %s (seed %.0f): drawn inputs, "
                 "deployment outcomes (1 deployed), the branch, Q (m^2), Q without any device, "
                 "and both Annex F critical areas (m^2); then, the same on every row, the run's "
                 "summary as montecarlo prints it: mean, sd, lo95..hi95 (the interval of the "
                 "mean, truncated at 0) and the quantiles of Q (mc_quantiles)",
                 m->n, m->casename, m->seed);
  char name[64];
  for (int i = 0; i < m->n; i++) {
    ura_table_cell(t, "%d", i);
    for (int k = 0; k < m->nin; k++) ura_table_cell(t, "%.9g", m->x[(size_t)i * m->nin + k]);
    ura_risk_branch_name(m->mask[i], &m->dep, m->bag, name, sizeof name);
    ura_table_cell(t, "%s", name);
    ura_table_cell(t, "%.9g", m->q[i]);
    ura_table_cell(t, "%.9g", m->q_c[i]);
    ura_table_cell(t, "%.9g", m->ca[i]);
    ura_table_cell(t, "%.9g", m->ca_c[i]);
    ura_table_cell(t, "%.6g", m->st.mean);
    ura_table_cell(t, "%.6g", m->st.sd);
    ura_table_cell(t, "%.6g", lo);
    ura_table_cell(t, "%.6g", hi);
    for (int j = 0; j < rs->nquant; j++) ura_table_cell(t, "%.6g", qv[j]);
  }
  ura_table_print(c, t);
  return 0;
}

/* ---- for sora mc and the plots ---- */

/* a figure from paired samples; the intervals truncated at 0 (areas and their ratio are not
   negative): 1 when one was */
static int figure(const double* ca, const double* ref, int n, uraSoraFig* f, double* work) {
  urMcStats s;
  ur_mc_stats(ca, n, work, &s);
  f->ca = s.mean;
  f->lo = s.lo95;
  f->hi = s.hi95;
  if (ur_mc_ratio(ref, ca, n, &f->red, &f->red_lo, &f->red_hi))
    f->red = f->red_lo = f->red_hi = NAN;
  int clip = ur_interval_clip(&f->lo, &f->hi, 0, INFINITY);
  if (!isnan(f->red)) clip |= ur_interval_clip(&f->red_lo, &f->red_hi, 0, INFINITY);
  return clip != 0;
}

int ura_mc_sora(uraCtx* c, uraSoraFig fig[4], int* mitigated, char* note, size_t n) {
  struct uraMc* m = c->mc;
  if (!m) return ura_fail(c, "sora mc: no montecarlo yet; run 'montecarlo N' first");
  char* now = settings_text(c);
  int same = now && !strcmp(now, m->settings);
  free(now);
  if (!same) {
    return ura_fail(c,
                    "sora mc: the settings changed since the last montecarlo (case, "
                    "parameters or distributions); accepted: run 'montecarlo N' again");
  }
  double* work = malloc((size_t)m->n * sizeof *work);
  if (!work) return ura_fail(c, "sora mc: out of memory");
  int clip = figure(m->q_c, m->q_c, m->n, &fig[0], work);
  clip |= figure(m->ca_c, m->ca_c, m->n, &fig[1], work);
  clip |= figure(m->q, m->q_c, m->n, &fig[2], work);
  clip |= figure(m->ca, m->ca_c, m->n, &fig[3], work);
  free(work);
  *mitigated = m->dep.chute;
  snprintf(
      note, n,
      "from the last montecarlo: %d samples (seed %.0f); ca is the mean, lo95..hi95 "
      "its 95 %% confidence interval; reduction the ratio of the paired means with its "
      "interval (delta method); the iGRC of the mean%s%s",
      m->n, m->seed,
      clip ? "; truncated: an interval reached below 0 and is held at 0, the physical bound" : "",
      m->n < 30 ? "; few samples: the intervals assume a nearly normal mean" : "");
  return 0;
}

/* the samples' Q and the kept statistics, for plot_mc.c */
int ura_mc_data(uraCtx* c, const double** q, int* n, const urMcStats** st, const char** casename,
                double* seed) {
  struct uraMc* m = c->mc;
  if (!m) return -1;
  *q = m->q;
  *n = m->n;
  *st = &m->st;
  *casename = m->casename;
  *seed = m->seed;
  return 0;
}

/* the variance shares of the independent inputs: their count, names and values */
int ura_mc_shares(uraCtx* c, const char** name, double* share) {
  struct uraMc* m = c->mc;
  int k = 0;
  for (int i = 0; m && i < m->nin; i++) {
    if (i == m->face_col) continue;
    name[k] = m->name[i];
    share[k++] = m->share[i];
  }
  return k;
}
