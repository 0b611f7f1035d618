/* modellang_stmt.c: the model-language parser (uasimpact-model(5)): the statements that build the model's elements: param, option,
 * curve, body, restraint, ellipsoid, law. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

static const KeySpec spec_option[] = {NUM("dt"),
                                      NUM("sample_dt"),
                                      NUM("tmax"),
                                      NUM("t_quiet"),
                                      NUM("t_clear"),
                                      NUM("a_clear"),
                                      NUM("ke_settle"),
                                      NUM("vmax"),
                                      NUM("jump_margin"),
                                      NUM("adapt"),
                                      VEC3("gravity"),
                                      {"integrator", K_ENUM, 1, 0, 0, "euler|rk4"},
                                      {"damping", K_ENUM, 1, 0, 0, "implicit|explicit"},
                                      ENABLE};
//---------------------------------- statements ----------------------------------------------------

/* a range of a parameter's values for messages: "0.15 to 0.65 m: reason" */
static void range_text(char* buf, size_t n, double lo, double hi, const char* si, const char* why) {
  snprintf(buf, n, "%g to %g%s%s%s%s", lo, hi, *si ? " " : " (no unit)", si, *why ? ": " : "", why);
}

/* the optional range=LO,HI and why=TEXT of a param line, from word i on (LO, HI in the line's
   unit, factor f); lo, hi stay infinite and why empty when absent */
static int param_range(Parser* p, const urlStmt* st, int i, const char* name, double f, double* lo,
                       double* hi, char* why, size_t nwhy) {
  const char* w = i < st->nword ? url_word(&p->lx, st->word + i) : NULL;
  int line = i < st->nword ? p->lx.word[st->word + i].line : st->line;
  char ctx[64];
  snprintf(ctx, sizeof(ctx), "param '%s': range", name);
  if (w && !strncmp(w, "range=", 6)) {
    const char* r = w + 6;
    const char* comma = strchr(r, ',');
    if (!comma || strchr(comma + 1, ',')) {
      return url_fail(p, line,
                      "%s: '%s' is not two numbers; expected range=LO,HI (in the unit of "
                      "the value)",
                      ctx, url_quote(r, strlen(r)).s);
    }
    if (url_number(p, r, (size_t)(comma - r), line, ctx, lo) ||
        url_number(p, comma + 1, strlen(comma + 1), line, ctx, hi)) {
      return -1;
    }
    *lo *= f;
    *hi *= f;
    if (!(*lo <= *hi) || !isfinite(*lo) || !isfinite(*hi)) {
      return url_fail(p, line, "%s: LO must not exceed HI (got %g, %g after conversion to SI)", ctx,
                      *lo, *hi);
    }
    w = ++i < st->nword ? url_word(&p->lx, st->word + i) : NULL;
    line = i < st->nword ? p->lx.word[st->word + i].line : line;
  }
  if (w && !strncmp(w, "why=", 4)) {
    if (isinf(*lo)) {
      return url_fail(p, line, "param '%s': why= explains a range; expected range=LO,HI before it",
                      name);
    }
    size_t k = 0;
    for (int j = i; j < st->nword && k < nwhy; j++) {
      const char* t = url_word(&p->lx, st->word + j) + (j == i ? 4 : 0);
      k += (size_t)snprintf(why + k, nwhy - k, "%s%s", k ? " " : "", t);
    }
    if (k == 0 || k >= nwhy) {
      return url_fail(p, line, "param '%s': why= needs a reason of 1 to %d characters (got %zu)",
                      name, (int)nwhy - 1, k);
    }
    for (size_t j = 0; j < k; j++) {
      if ((unsigned char)why[j] < 32 || (unsigned char)why[j] > 126) {
        return url_fail(p, line,
                        "param '%s': why= holds a character that is not printable "
                        "ASCII; expected a reason in ASCII (only comments may hold other "
                        "characters)",
                        name);
      }
    }
    return 0;
  }
  if (w) {
    return url_fail(p, line,
                    "param takes NAME VALUE [UNIT] [range=LO,HI [why=TEXT...]]; got "
                    "'%s'",
                    url_quote(w, strlen(w)).s);
  }
  return 0;
}

/* a parameter whose value is $OTHER follows OTHER (urParam.from; a host that parses the text
   again with an override of OTHER gets the value followed too); a chain of them that comes
   back to k (a redefinition in a later part) is refused */
static int param_follow(Parser* p, int k, const char* value, double f, int line) {
  if (value[0] != '$') {
    return 0;
  }
  urParam* par = p->m->param;
  int o = ur_name_param(p->m, value + 1);
  char chain[4 * urNAMELEN] = "";
  size_t n = (size_t)snprintf(chain, sizeof chain, "%s", par[k].name);
  for (int j = o, hops = 0; j >= 0 && hops <= p->m->nparam; j = par[j].from, hops++) {
    if (n < sizeof chain) {
      n += (size_t)snprintf(chain + n, sizeof chain - n, " -> %s", par[j].name);
    }
    if (j == k) {
      return url_fail(p, line,
                      "param '%s': $%s makes a cycle (%s); expected a number, or a parameter "
                      "that does not follow '%s'",
                      par[k].name, value + 1, chain, par[k].name);
    }
  }
  par[k].from = o;
  par[k].from_f = f;
  return 0;
}

/* param NAME VALUE [UNIT] [range=LO,HI [why=TEXT...]] */
int url_st_param(Parser* p, const urlStmt* st) {
  const char* w[4] = {NULL, NULL, NULL, NULL};
  int ln[4] = {st->line, st->line, st->line, st->line};
  for (int i = 0; i < st->nword && i < 4; i++) {
    w[i] = url_word(&p->lx, st->word + i);
    ln[i] = p->lx.word[st->word + i].line;
  }
  if (w[3] && strchr(w[3], '=')) {
    w[3] = NULL; /* range= or why= */
  }
  int first = w[3] ? 4 : 3; /* the first word after NAME VALUE [UNIT] */
  if (st->nword < 3) {
    return url_fail(p, st->line,
                    "param takes NAME VALUE [UNIT] [range=LO,HI [why=TEXT...]]; got %d word(s) "
                    "after 'param'",
                    st->nword - 1);
  }
  for (int i = 1; i < 3; i++) {
    if (strchr(w[i], '=')) {
      return url_fail(p, ln[i], "param takes NAME VALUE [UNIT], not key=value ('%s')",
                      url_quote(w[i], strlen(w[i])).s);
    }
  }
  if (url_checkname(p, w[1], strlen(w[1]), ln[1], "param")) {
    return -1;
  }

  /* value and unit */
  char ctx[64];
  snprintf(ctx, sizeof(ctx), "param '%s'", w[1]);
  double v, f = 1;
  if (url_number(p, w[2], strlen(w[2]), ln[2], ctx, &v)) {
    return -1;
  }
  char si[urNAMELEN] = "";
  if (w[3]) {
    if (ur_unit_parse(w[3], &f, si, sizeof si)) {
      char list[200];
      url_unit_names(list, sizeof list);
      return url_fail(p, ln[3],
                      "param '%s': unknown unit '%s'; expected one of %s, or several "
                      "joined by * and / (N*m/rad)",
                      w[1], url_quote(w[3], strlen(w[3])).s, list);
    }
    v *= f;
    if (!isfinite(v)) {
      return url_fail(p, ln[3], "param '%s': value overflows after conversion to SI", w[1]);
    }
  }

  /* the range of its values: this line's, or an earlier definition's */
  double lo = -INFINITY, hi = INFINITY;
  char why[urWHYLEN] = "";
  if (param_range(p, st, first, w[1], f, &lo, &hi, why, sizeof why)) {
    return -1;
  }
  int had = ur_name_param(p->m, w[1]);
  if (isinf(lo) && had >= 0) {
    lo = p->m->param[had].lo;
    hi = p->m->param[had].hi;
    snprintf(why, sizeof why, "%s", p->m->param[had].why);
  }
  const char* ru = *si || had < 0 ? si : p->m->param[had].unit; /* SI unit of the range */
  char rt[urWHYLEN + 80];
  range_text(rt, sizeof rt, lo, hi, ru, why);
  if (!(v >= lo && v <= hi)) {
    return url_fail(p, st->line, "param '%s': its value %g%s%s is outside its range %s", w[1], v,
                    *ru ? " " : "", ru, rt);
  }

  /* the caller's override wins (last one given), within the range: it then holds its own */
  int own = 0;
  for (int i = 0; i < p->nov; i++) {
    if (!strcmp(p->ov[i].name, w[1])) {
      v = p->ov[i].value;
      own = 1;
    }
  }
  if (!(v >= lo && v <= hi)) {
    return url_fail(p, st->line, "param '%s': the value set, %g%s%s, is outside its range %s", w[1],
                    v, *ru ? " " : "", ru, rt);
  }

  /* store */
  int id = url_push(p, (void**)&p->pval, &p->npval, &p->cappval, sizeof(double), st->line);
  if (id < 0 || url_declare(p, SYM_PARAM, w[1], st->line, id, 1)) {
    return -1;
  }
  p->pval[id] = v;
  int k = ur_model_set_param(p->m, w[1], v);
  if (k < 0) {
    return url_fail(p, st->line, "param '%s': %s", w[1], p->m->err);
  }
  snprintf(p->m->param[k].unit, sizeof p->m->param[k].unit, "%s", si);
  if (ur_model_set_param_range(p->m, w[1], lo, hi, why) < 0) {
    return url_fail(p, st->line, "param '%s': its range cannot be kept", w[1]);
  }
  return own ? 0 : param_follow(p, k, w[2], f, ln[2]);
}


/* option key=value... */
int url_st_option(Parser* p, const urlStmt* st, Bound* b) {
  int rc = url_bind(p, st, 1, spec_option, NKEY(spec_option), b);
  if (rc) {
    return rc < 0 ? -1 : 0;
  }
  urOption* o = &p->m->opt;
  static const char* const pos[] = {"dt", "sample_dt", "tmax", "vmax"};
  static const char* const nn[] = {"t_quiet", "ke_settle", "jump_margin", "t_clear", "a_clear"};
  for (int i = 0; i < 4; i++) {
    const Val* v = url_get(b, pos[i]);
    if (v->set && !(v->v[0] > 0)) {
      return url_fail(p, v->line, "option %s must be > 0 (got %g)", pos[i], v->v[0]);
    }
  }
  for (int i = 0; i < 5; i++) {
    const Val* v = url_get(b, nn[i]);
    if (v->set && !(v->v[0] >= 0)) {
      return url_fail(p, v->line, "option %s must be >= 0 (got %g)", nn[i], v->v[0]);
    }
  }
  o->dt = url_num(b, "dt", o->dt);
  o->sample_dt = url_num(b, "sample_dt", o->sample_dt);
  o->tmax = url_num(b, "tmax", o->tmax);
  o->t_quiet = url_num(b, "t_quiet", o->t_quiet);
  o->t_clear = url_num(b, "t_clear", o->t_clear);
  o->a_clear = url_num(b, "a_clear", o->a_clear);
  o->ke_settle = url_num(b, "ke_settle", o->ke_settle);
  o->vmax = url_num(b, "vmax", o->vmax);
  o->jump_margin = url_num(b, "jump_margin", o->jump_margin);
  const Val* va = url_get(b, "adapt");
  if (va->set) {
    double k = va->v[0];
    if (!(k >= 1 && k <= urMAXADAPT && k == floor(k))) {
      return url_fail(p, va->line,
                      "option adapt must be an integer from 1 (off) to %d (got %g): the coarse "
                      "step in steps dt",
                      urMAXADAPT, k);
    }
    o->adapt = (int)k;
  }
  if (url_vec(b, "gravity")) {
    memcpy(o->gravity, url_vec(b, "gravity"), 3 * sizeof(double));
  }
  if (url_get(b, "integrator")->set) {
    o->integrator = url_get(b, "integrator")->e ? urINT_RK4 : urINT_EULER;
  }
  if (url_get(b, "damping")->set) {
    o->implicit_damping = url_get(b, "damping")->e == 0;
  }
  return 0;
}


/* the y of curve b from the Avalle-Belingardi-Ibba foam law abi=A,E,m,B,n at its x (strains) */
static int curve_abi(Parser* p, const Bound* b, double* y) {
  const Val* x = url_get(b, "x");
  const Val* va = url_get(b, "abi");
  const double* a = va->v;
  if (!(a[0] > 0 && a[1] > 0 && a[2] >= 0 && a[3] >= 0 && a[4] > 0)) {
    return url_fail(p, va->line,
                    "curve '%s': abi=A,E,m,B,n needs A > 0, E > 0, m >= 0, B >= 0, n > 0 (got "
                    "%g,%g,%g,%g,%g)",
                    b->name, a[0], a[1], a[2], a[3], a[4]);
  }
  for (int i = 0; i < x->n; i++) {
    if (!(x->v[i] >= 0 && x->v[i] < 1)) {
      return url_fail(p, x->line,
                      "curve '%s': the foam law takes strains in [0, 1) (x[%d] = %g); the foam "
                      "is solid at 1",
                      b->name, i + 1, x->v[i]);
    }
    y[i] = ur_foam_abi(a, x->v[i]);
  }
  return 0;
}


/* curve NAME x=.. y=.. | abi=A,E,m,B,n */
int url_st_curve(Parser* p, const Bound* b) {
  const Val* x = url_get(b, "x");
  const Val* y = url_get(b, "y");
  const Val* va = url_get(b, "abi");
  double ys[urMAXCURVE];
  if (y->set == va->set) {
    return url_fail(p, b->line,
                    "curve '%s': give y=LIST or abi=A,E,m,B,n (the Avalle-Belingardi-Ibba foam "
                    "law at the strains x), one of them",
                    b->name);
  }
  if (va->set) {
    if (curve_abi(p, b, ys)) {
      return -1;
    }
  } else {
    memcpy(ys, y->v, (size_t)y->n * sizeof(double));
  }
  if (y->set && x->n != y->n) {
    return url_fail(p, y->line, "curve '%s': x has %d points but y has %d; expected the same count",
                    b->name, x->n, y->n);
  }
  for (int i = 1; i < x->n; i++) {
    if (!(x->v[i] > x->v[i - 1])) {
      return url_fail(p, x->line,
                      "curve '%s': x must be strictly ascending (x[%d] = %g after "
                      "x[%d] = %g)",
                      b->name, i + 1, x->v[i], i, x->v[i - 1]);
    }
  }
  static const char* const scales[] = {"xscale", "yscale"};
  for (int k = 0; k < 2; k++) {
    const Val* v = url_get(b, scales[k]);
    if (v->set && !(v->v[0] > 0)) {
      return url_fail(p, v->line, "curve '%s': %s must be > 0 (got %g)", b->name, scales[k],
                      v->v[0]);
    }
  }
  int id = url_push(p, (void**)&p->curve, &p->ncurve, &p->capcurve, sizeof(urCurve), b->line);
  if (id < 0 || url_declare(p, SYM_CURVE, b->name, b->line, id, 1)) {
    return -1;
  }
  urCurve* c = p->curve + id;
  double sx = url_num(b, "xscale", 1), sy = url_num(b, "yscale", 1);
  c->n = x->n;
  for (int i = 0; i < x->n; i++) {
    c->x[i] = sx * x->v[i];
    c->y[i] = sy * ys[i];
  }
  return 0;
}


/* body NAME parent= joint= pos= mass= ... */
int url_st_body(Parser* p, const Bound* b) {
  urModel* m = p->m;
  if (!strcmp(b->name, "world")) {
    return url_fail(p, b->line, "body name 'world' is reserved (it is the fixed world frame)");
  }

  /* parent and joint */
  const Val* vp = url_get(b, "parent");
  int parent = -1;
  if (strcmp(vp->raw, "world")) {
    parent = url_ref(p, SYM_BODY, vp->raw, vp->line, NULL);
    if (parent < 0) {
      return -1;
    }
  }
  urJointType jt = (urJointType)url_get(b, "joint")->e;
  double q[4];
  if (url_orientation(p, b, q)) {
    return -1;
  }

  /* mass and inertia */
  const Val* vm = url_get(b, "mass");
  if (!(vm->v[0] > 0)) {
    return url_fail(p, vm->line, "body '%s': mass must be > 0 (got %g)", b->name, vm->v[0]);
  }
  const Val* vi = url_get(b, "inertia");
  double I[6] = {0, 0, 0, 0, 0, 0};
  if (vi->set) {
    memcpy(I, vi->v, (size_t)vi->n * sizeof(double));
    double d2 = I[0] * I[1] - I[3] * I[3];
    double d3 = I[0] * (I[1] * I[2] - I[5] * I[5]) - I[3] * (I[3] * I[2] - I[5] * I[4]) +
                I[4] * (I[3] * I[5] - I[1] * I[4]);
    if (!(I[0] > 0 && d2 > 0 && d3 > 0)) {
      return url_fail(p, vi->line,
                      "body '%s': inertia must be positive definite (got xx,yy,zz,"
                      "xy,xz,yz = %g,%g,%g,%g,%g,%g)",
                      b->name, I[0], I[1], I[2], I[3], I[4], I[5]);
    }
    /* a real mass distribution: no principal moment above the sum of the other two, that is
       J = tr(I)/2 E - I positive semidefinite (its principal minors >= 0, to rounding) */
    double h = 0.5 * (I[0] + I[1] + I[2]), e = 1e-9 * h;
    double J[6] = {h - I[0] + e, h - I[1] + e, h - I[2] + e, -I[3], -I[4], -I[5]};
    double j2 = J[0] * J[1] - J[3] * J[3];
    double j3 = J[0] * (J[1] * J[2] - J[5] * J[5]) - J[3] * (J[3] * J[2] - J[5] * J[4]) +
                J[4] * (J[3] * J[5] - J[1] * J[4]);
    if (!(J[0] > 0 && j2 > 0 && j3 > 0)) {
      return url_fail(
          p, vi->line,
          "body '%s': inertia is not that of a real body: a principal moment "
          "exceeds the sum of the other two (got xx,yy,zz,xy,xz,yz = %g,%g,%g,%g,%g,%g); "
          "expected moments such as a box's or a rod's",
          b->name, I[0], I[1], I[2], I[3], I[4], I[5]);
    }
  } else if (jt == urJNT_FREE || jt == urJNT_SPHERICAL) {
    return url_fail(p, b->line, "body '%s': a %s joint needs inertia=xx,yy,zz[,xy,xz,yz]", b->name,
                    jt == urJNT_FREE ? "free" : "spherical");
  }

  /* joint axes */
  const Val* va = url_get(b, "axis");
  const Val* va2 = url_get(b, "axis2");
  if (va->set && jt != urJNT_REVOLUTE && jt != urJNT_PRISMATIC && jt != urJNT_UNIVERSAL) {
    return url_fail(p, va->line,
                    "body '%s': key 'axis' applies only to revolute, prismatic and "
                    "universal joints",
                    b->name);
  }
  if (va2->set && jt != urJNT_UNIVERSAL) {
    return url_fail(p, va2->line, "body '%s': key 'axis2' applies only to universal joints",
                    b->name);
  }
  const Val* ax[2] = {va, va2};
  for (int k = 0; k < 2; k++) {
    if (ax[k]->set && !(fabs(ax[k]->v[0]) + fabs(ax[k]->v[1]) + fabs(ax[k]->v[2]) > 0)) {
      return url_fail(p, ax[k]->line, "body '%s': joint axis must not be zero", b->name);
    }
  }

  /* names: body and joint (the joint is named after the body unless jname is given) */
  const Val* vj = url_get(b, "jname");
  const char* jname = vj->set ? vj->raw : b->name;
  if (url_declare(p, SYM_BODY, b->name, b->line, m->nbody, 1) ||
      url_declare(p, SYM_JOINT, jname, vj->set ? vj->line : b->line, m->nbody, 1)) {
    return -1;
  }

  /* build */
  int id = ur_model_add_body(m, b->name, parent, jt, url_get(b, "pos")->v, q);
  if (id < 0 || ur_model_set_inertia(m, id, vm->v[0], url_vec(b, "com"), vi->set ? I : NULL) ||
      ur_model_set_joint(m, id, vj->set ? jname : NULL, url_vec(b, "axis"), url_vec(b, "axis2"))) {
    return url_fail(p, b->line, "body '%s': %s", b->name, m->err);
  }
  m->body[id].gravity = url_num(b, "gravity", 1);

  /* universal axes must not be parallel (checked after normalisation) */
  const urBody* bd = m->body + id;
  double c = bd->axis[0][0] * bd->axis[1][0] + bd->axis[0][1] * bd->axis[1][1] +
             bd->axis[0][2] * bd->axis[1][2];
  if (jt == urJNT_UNIVERSAL && fabs(c) > 1 - 1e-9) {
    return url_fail(p, va2->set ? va2->line : b->line,
                    "body '%s': universal joint axes are "
                    "parallel; expected two different directions in axis and axis2",
                    b->name);
  }
  return 0;
}


/* restraint BODY dof= ... */
int url_st_restraint(Parser* p, const Bound* b) {
  urModel* m = p->m;
  int id = url_ref(p, SYM_BODY, b->name, b->line, "restraint");
  if (id < 0) {
    return -1;
  }
  const urBody* bd = m->body + id;
  static const int nv[] = {6, 0, 1, 2, 3, 1};
  static const char* const jn[] = {"free",      "fixed",     "revolute",
                                   "universal", "spherical", "prismatic"};
  if (bd->jtype == urJNT_FREE || bd->jtype == urJNT_FIXED) {
    return url_fail(p, b->line,
                    "restraint '%s': body '%s' has a %s joint; restraints need a "
                    "revolute, universal, spherical or prismatic joint",
                    b->name, b->name, jn[bd->jtype]);
  }
  const Val* vd = url_get(b, "dof");
  int dof = (int)vd->v[0];
  if (dof >= nv[bd->jtype]) {
    return url_fail(p, vd->line, "restraint '%s': dof %d is beyond the %s joint (dof 0..%d)",
                    b->name, dof, jn[bd->jtype], nv[bd->jtype] - 1);
  }
  if (bd->rst[dof].active) {
    return url_fail(p, b->line,
                    "restraint '%s': dof %d is already restrained; expected one "
                    "restraint per dof",
                    b->name, dof);
  }

  /* scalars */
  static const char* const nn[] = {"k", "c", "kstop", "cstop", "sat"};
  for (int i = 0; i < 5; i++) {
    if (url_nonneg(p, b, nn[i], 0)) {
      return -1;
    }
  }
  const Val* lo = url_get(b, "lo");
  const Val* hi = url_get(b, "hi");
  if (lo->set != hi->set) {
    return url_fail(p, (lo->set ? lo : hi)->line, "restraint '%s': give both lo and hi (end stops)",
                    b->name);
  }
  if (lo->set && !(lo->v[0] <= hi->v[0])) {
    return url_fail(p, hi->line, "restraint '%s': lo must be <= hi (got lo %g, hi %g)", b->name,
                    lo->v[0], hi->v[0]);
  }
  urRestraint r;
  memset(&r, 0, sizeof(r));
  r.k = url_num(b, "k", 0);
  r.sat = url_num(b, "sat", 0);
  r.c = url_num(b, "c", 0);
  r.lo = url_num(b, "lo", 0);
  r.hi = url_num(b, "hi", 0);
  r.kstop = url_num(b, "kstop", 0);
  r.cstop = url_num(b, "cstop", 0);
  r.x0 = url_num(b, "x0", 0);
  if (url_hinge(p, b, &r) < 0) {
    return -1;
  }

  /* curves */
  const Val* vl = url_get(b, "load");
  const Val* vu = url_get(b, "unload");
  if (vu->set && !vl->set) {
    return url_fail(p, vu->line, "restraint '%s': an unload curve needs a load curve", b->name);
  }
  if (vl->set) {
    int c = url_ref(p, SYM_CURVE, vl->raw, vl->line, "restraint");
    if (c < 0) {
      return -1;
    }
    r.load = p->curve[c];
  }
  if (vu->set) {
    int c = url_ref(p, SYM_CURVE, vu->raw, vu->line, "restraint");
    if (c < 0) {
      return -1;
    }
    r.unload = p->curve[c];
  }
  if (ur_model_set_restraint(m, id, dof, &r)) {
    return url_fail(p, b->line, "restraint '%s': %s", b->name, m->err);
  }
  return 0;
}


/* ellipsoid NAME body= pos= size= [quat|rot] [degree=] */
int url_st_ellipsoid(Parser* p, const Bound* b) {
  urModel* m = p->m;
  if (!strcmp(b->name, "ground")) {
    return url_fail(p, b->line, "ellipsoid name 'ground' is reserved (it is the plane z = 0)");
  }
  const Val* vb = url_get(b, "body");
  if (!strcmp(vb->raw, "world")) {
    return url_fail(p, vb->line,
                    "ellipsoid '%s': ellipsoids sit on bodies, not on the world; for "
                    "the ground use 'pair ... b=ground'",
                    b->name);
  }
  int body = url_ref(p, SYM_BODY, vb->raw, vb->line, NULL);
  if (body < 0) {
    return -1;
  }
  const Val* vs = url_get(b, "size");
  if (!(vs->v[0] > 0 && vs->v[1] > 0 && vs->v[2] > 0)) {
    return url_fail(p, vs->line, "ellipsoid '%s': semi-axes must be > 0 (got %g,%g,%g)", b->name,
                    vs->v[0], vs->v[1], vs->v[2]);
  }
  const Val* vd = url_get(b, "degree");
  if (vd->set && !(vd->v[0] >= 2 && vd->v[0] <= urMAXDEGREE)) {
    return url_fail(p, vd->line,
                    "ellipsoid '%s': degree must be in [2, %d] (got %g); 2 is the "
                    "ellipsoid, larger values flatten it towards a box",
                    b->name, urMAXDEGREE, vd->v[0]);
  }
  double q[4];
  if (url_orientation(p, b, q) || url_declare(p, SYM_ELLIPSOID, b->name, b->line, m->ngeom, 1)) {
    return -1;
  }
  int g = ur_model_add_ellipsoid(m, b->name, body, url_get(b, "pos")->v, q, vs->v);
  if (g < 0 || (vd->set && ur_model_set_degree(m, g, vd->v[0]))) {
    return url_fail(p, b->line, "ellipsoid '%s': %s", b->name, m->err);
  }
  return url_geom_material(p, b, g);
}


/* ellipsoid g, named name, must have degree 2 in its role (a foam pair's a, an airbag target) */
/* a pair under a Hertz law without radii: both ellipsoids of degree 2 (their curvature) */
int url_curv2(Parser* p, const urLaw* law, int g, const char* name, int line, const char* what) {
  if (g < 0 || law->type != urLAW_HERTZ || law->radius != urHERTZ_CURVATURE ||
      p->m->geom[g].degree == 2) {
    return 0;
  }
  return url_fail(p, line,
                  "%s: ellipsoid '%s' has degree=%g; a Hertz law without R1 and R2 takes "
                  "its radius from the curvature of ellipsoids of degree 2 (give R1 and R2)",
                  what, name, p->m->geom[g].degree);
}


int url_degree2(Parser* p, int g, const char* name, int line, const char* what, const char* role) {
  if (p->m->geom[g].degree == 2) {
    return 0;
  }
  const Sym* sy = p->sym + url_findsym(p, SYM_ELLIPSOID, name, 1);
  return url_fail(p, line,
                  "%s: ellipsoid '%s' (%s:%d) has degree=%g; %s must have degree 2 (its "
                  "section area and cap volume are those of an ellipsoid)",
                  what, name, url_srcname(p, sy->src), sy->line, p->m->geom[g].degree, role);
}


/* Poisson ratio in [0, 0.5) */
static int poisson(Parser* p, const Bound* b, const char* key) {
  const Val* v = url_get(b, key);
  if (v->set && !(v->v[0] >= 0 && v->v[0] < 0.5)) {
    return url_fail(p, v->line, "law '%s': %s must be in [0, 0.5) (got %g)", b->name, key, v->v[0]);
  }
  return 0;
}


/* a foam law's keys lock=, backing= and backing_material=: the rigid backing the solid foam
   rests on, a declared Hertz law (its K now), or derived per pair from the person's layer
   (backing=derived: *backmat the backing's material, url_pair_law) */
static int foam_backing(Parser* p, const Bound* b, urLaw* law, int* backmat) {
  const Val* vk = url_get(b, "lock");
  const Val* vb = url_get(b, "backing");
  const Val* vm = url_get(b, "backing_material");
  if (vk->set != vb->set) {
    return url_fail(p, (vk->set ? vk : vb)->line,
                    "law '%s': lock and backing go together (the "
                    "solid foam rests on the backing)",
                    b->name);
  }
  int derived = vb->set && !strcmp(vb->raw, "derived");
  if (vm->set != derived) {
    return url_fail(p, (vm->set ? vm : vb)->line,
                    "law '%s': backing=derived and backing_material=MATERIAL go together (the "
                    "backing's Hertz law from the person's layer on that material)",
                    b->name);
  }
  if (!vk->set) {
    return 0;
  }
  double last = law->stress.x[law->stress.n - 1];
  if (!(vk->v[0] > 0 && vk->v[0] < 1 && vk->v[0] <= last)) {
    return url_fail(p, vk->line,
                    "law '%s': lock must be in (0, 1) and within the stress curve "
                    "(last strain %g; got %g)",
                    b->name, last, vk->v[0]);
  }
  law->lock = vk->v[0];
  if (derived) {
    *backmat = url_ref(p, SYM_MATERIAL, vm->raw, vm->line, "law");
    return *backmat < 0 ? -1 : 0;
  }
  int l = url_ref(p, SYM_LAW, vb->raw, vb->line, "law");
  if (l < 0) {
    return -1;
  }
  if (p->law[l].type != urLAW_HERTZ) {
    return url_fail(p, vb->line, "law '%s': backing '%s' must be a hertz law (or derived)", b->name,
                    vb->raw);
  }
  if (p->law[l].radius == urHERTZ_CURVATURE) {
    return url_fail(p, vb->line,
                    "law '%s': backing '%s' must give R1 and R2 (a backing has no "
                    "contact of its own to take a curvature from)",
                    b->name, vb->raw);
  }
  double K, dy, fy;
  ur_law_hertz_params(p->law + l, &K, &dy, &fy);
  law->backing_k = K;
  return 0;
}


/* law NAME type=hertz|table|foam ... */
int url_st_law(Parser* p, const Bound* b) {
  urLaw law;
  memset(&law, 0, sizeof(law));
  int backmat = -1;
  int type = url_get(b, "type")->e;

  /* per type */
  if (type == 0) {
    if (url_nonneg(p, b, "E1", 1) || url_nonneg(p, b, "E2", 1) || url_nonneg(p, b, "R1", 1) ||
        url_nonneg(p, b, "R2", 0) || url_nonneg(p, b, "sy", 0) || poisson(p, b, "nu1") ||
        poisson(p, b, "nu2") || poisson(p, b, "nu_yield")) {
      return -1;
    }
    int plastic = (int)url_num(b, "plastic", 0);
    if (plastic && !(url_num(b, "sy", 0) > 0 && url_get(b, "nu_yield")->set)) {
      return url_fail(p, url_get(b, "plastic")->line,
                      "law '%s': plastic=1 needs sy > 0 and nu_yield", b->name);
    }
    const Val* r1 = url_get(b, "R1");
    const Val* r2 = url_get(b, "R2");
    if (r1->set != r2->set) {
      return url_fail(p, (r1->set ? r1 : r2)->line,
                      "law '%s': give R1 and R2, or neither (the radius "
                      "then comes from the ellipsoids' curvature at the contact)",
                      b->name);
    }
    ur_law_hertz(&law, url_num(b, "E1", 0), url_num(b, "nu1", 0), url_num(b, "R1", 0),
                 url_num(b, "E2", 0), url_num(b, "nu2", 0), url_num(b, "R2", 0),
                 url_num(b, "sy", 0), url_num(b, "nu_yield", 0), plastic);
    if (!r1->set) {
      law.radius = urHERTZ_CURVATURE;
    }
  } else if (type == 1) {
    law.type = urLAW_TABLE;
    const Val* vl = url_get(b, "load");
    const Val* vu = url_get(b, "unload");
    int c = url_ref(p, SYM_CURVE, vl->raw, vl->line, "law");
    if (c < 0) {
      return -1;
    }
    law.load = p->curve[c];
    if (vu->set) {
      c = url_ref(p, SYM_CURVE, vu->raw, vu->line, "law");
      if (c < 0) {
        return -1;
      }
      law.unload = p->curve[c];
    }
  } else {
    law.type = urLAW_FOAM;
    const Val* vs = url_get(b, "stress");
    const Val* vr = url_get(b, "unload_r");
    int c = url_ref(p, SYM_CURVE, vs->raw, vs->line, "law");
    if (c < 0 || url_nonneg(p, b, "thickness", 1) || url_nonneg(p, b, "unload_p", 1)) {
      return -1;
    }
    if (!(vr->v[0] >= 0 && vr->v[0] < 1)) {
      return url_fail(p, vr->line, "law '%s': unload_r must be in [0, 1) (got %g)", b->name,
                      vr->v[0]);
    }
    law.stress = p->curve[c];
    law.thickness = url_num(b, "thickness", 0);
    law.unload_r = vr->v[0];
    law.unload_p = url_num(b, "unload_p", 0);

    if (foam_backing(p, b, &law, &backmat)) {
      return -1;
    }
  }

  /* common terms */
  static const char* const common[] = {"damping", "chi", "mu", "v_eps"};
  for (int i = 0; i < 4; i++) {
    if (url_nonneg(p, b, common[i], 0)) {
      return -1;
    }
  }
  law.damping = url_num(b, "damping", 0);
  law.chi = url_num(b, "chi", 0);
  law.mu = url_num(b, "mu", 0);
  law.v_eps = url_num(b, "v_eps", 0);
  int id = url_push(p, (void**)&p->law, &p->nlaw, &p->caplaw, sizeof(urLaw), b->line);
  int ib =
      id < 0 ? -1
             : url_push(p, (void**)&p->lawback, &p->nlawback, &p->caplawback, sizeof(int), b->line);
  if (ib < 0 || url_declare(p, SYM_LAW, b->name, b->line, id, 1)) {
    return -1;
  }
  p->law[id] = law;
  p->lawback[ib] = backmat;
  return 0;
}
