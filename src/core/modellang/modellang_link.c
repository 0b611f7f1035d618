/* modellang_link.c: the model-language parser (uasimpact-model(5)): the statements that link elements and describe cases: pair,
 * pairs, airbag, sensor, role, preset, part, and the design scale. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "uasimpact/modellang.h"
#include "modellang_internal.h"

static const KeySpec spec_role[] = {NAME("drone"),    NAME("head"),  NAME("head_acc"), NAME("neck"),
                                    NAME("head_pos"), NAME("chest"), NAME("abdomen"),  NUM("mass"),
                                    NUM("size"),      ENABLE};
/* pair NAME a= b=|ground [law=]: without law=, the law is derived from the materials */
int url_st_pair(Parser* p, const Bound* b) {
  urModel* m = p->m;
  const Val* va = url_get(b, "a");
  const Val* vb = url_get(b, "b");
  const Val* vl = url_get(b, "law");
  int ga = url_ref(p, SYM_ELLIPSOID, va->raw, va->line, NULL);
  if (ga < 0) {
    return -1;
  }
  int gb = -1;
  if (strcmp(vb->raw, "ground") && (gb = url_ref(p, SYM_ELLIPSOID, vb->raw, vb->line, NULL)) < 0) {
    return -1;
  }
  int law = -1;
  if (vl->set && (law = url_ref(p, SYM_LAW, vl->raw, vl->line, NULL)) < 0) {
    return -1;
  }
  if (gb >= 0 && m->geom[ga].body == m->geom[gb].body) {
    return url_fail(p, vb->line,
                    "pair '%s': a and b are both on body '%s'; expected ellipsoids of "
                    "two bodies",
                    b->name, m->body[m->geom[ga].body].name);
  }
  char what[urNAMELEN + 16];
  snprintf(what, sizeof(what), "pair '%s'", b->name);
  urLaw lw;
  if (url_pair_law(p, what, ga, gb, law, vl->set ? vl->line : b->line, &lw)) {
    return -1;
  }
  if ((lw.type == urLAW_FOAM &&
       url_degree2(p, ga, va->raw, va->line, what, "a, under a foam law,")) ||
      url_curv2(p, &lw, ga, va->raw, va->line, what) ||
      url_curv2(p, &lw, gb, vb->raw, vb->line, what)) {
    return -1;
  }
  if (url_declare(p, SYM_PAIR, b->name, b->line, m->npair, 1)) {
    return -1;
  }
  if (ur_model_add_pair(m, b->name, ga, gb, &lw) < 0) {
    return url_fail(p, b->line, "pair '%s': %s", b->name, m->err);
  }
  return 0;
}

/* name NAME_A_B of a generated pair; -1 if too long */
static int pairname(char out[urNAMELEN], const char* name, const char* a, const char* b) {
  int n = snprintf(out, urNAMELEN, "%s_%s_%s", name, a, b);
  return n < 0 || n >= urNAMELEN ? -1 : 0;
}


/* pairs NAME a=E1,E2,.. b=F1,F2,..|ground law=: one pair NAME_Ei_Fj per combination */
int url_st_pairs(Parser* p, const Bound* b) {
  urModel* m = p->m;
  const Val* va = url_get(b, "a");
  const Val* vb = url_get(b, "b");
  const Val* vl = url_get(b, "law");
  int law = -1;
  if (vl->set && (law = url_ref(p, SYM_LAW, vl->raw, vl->line, NULL)) < 0) {
    return -1;
  }
  for (int i = 0; i < va->n; i++) {
    char na[urNAMELEN], pn[urNAMELEN];
    url_item(va->raw, i, na, sizeof(na));
    int ga = url_ref(p, SYM_ELLIPSOID, na, va->line, NULL);
    if (ga < 0) {
      return -1;
    }
    char what[urNAMELEN + 16];
    snprintf(what, sizeof(what), "pairs '%s'", b->name);
    for (int j = 0; j < vb->n; j++) {
      char nb[urNAMELEN];
      url_item(vb->raw, j, nb, sizeof(nb));
      int gb = -1;
      if (strcmp(nb, "ground") && (gb = url_ref(p, SYM_ELLIPSOID, nb, vb->line, NULL)) < 0) {
        return -1;
      }
      urLaw lw;
      if (url_pair_law(p, what, ga, gb, law, vl->set ? vl->line : b->line, &lw)) {
        return -1;
      }
      if ((lw.type == urLAW_FOAM &&
           url_degree2(p, ga, na, va->line, what, "each a, under a foam law,")) ||
          url_curv2(p, &lw, ga, na, va->line, what) || url_curv2(p, &lw, gb, nb, vb->line, what)) {
        return -1;
      }
      if (pairname(pn, b->name, na, nb)) {
        return url_fail(p, b->line,
                        "pairs '%s': the pair name '%s_%s_%s' is too long (%d "
                        "characters, at most %d); shorten NAME or the ellipsoid names",
                        b->name, b->name, na, nb,
                        (int)(strlen(b->name) + strlen(na) + strlen(nb) + 2), urNAMELEN - 1);
      }
      if (gb >= 0 && m->geom[ga].body == m->geom[gb].body) {
        return url_fail(p, vb->line,
                        "pairs '%s': '%s' and '%s' are both on body '%s'; expected "
                        "ellipsoids of two bodies",
                        b->name, na, nb, m->body[m->geom[ga].body].name);
      }
      if (url_declare(p, SYM_PAIR, pn, b->line, m->npair, 1)) {
        return -1;
      }
      if (ur_model_add_pair(m, pn, ga, gb, &lw) < 0) {
        return url_fail(p, b->line, "pairs '%s': %s", b->name, m->err);
      }
    }
  }
  return 0;
}


/* names of the pairs of a disabled 'pairs' statement (for messages), as far as they are valid */
int url_pairs_disabled(Parser* p, const Bound* b, int line) {
  const char* ra = url_get(b, "a")->raw;
  const char* rb = url_get(b, "b")->raw;
  int na = url_count(ra), nb = url_count(rb);
  for (int i = 0; i < na && na <= MAXLIST && nb <= MAXLIST; i++) {
    for (int j = 0; j < nb; j++) {
      char x[urNAMELEN], y[urNAMELEN], pn[urNAMELEN];
      if (!url_item(ra, i, x, sizeof(x)) && !url_item(rb, j, y, sizeof(y)) &&
          url_isident(x, strlen(x)) && url_isident(y, strlen(y)) && !pairname(pn, b->name, x, y) &&
          url_declare(p, SYM_PAIR, pn, line, -1, 0)) {
        return -1;
      }
    }
  }
  return 0;
}


/* the membrane keys of an airbag: with membrane=1 (and a size) the bag is a finite-element
   membrane (membrane.h), else they are kept unused; every value from the defaults of
   ur_mem_spec_default unless given */
static int membrane_keys(Parser* p, const Bound* b, urAirbag* bag) {
  urModel* m = p->m;
  urMemSpec* s = &bag->mspec;
  ur_mem_spec_default(s);
  const Val* vm = url_get(b, "membrane");
  const Val* vs = url_get(b, "size");
  if (!(vm->set && vm->v[0] != 0)) {
    return 0;
  }
  if (!vs->set) {
    return url_fail(p, vm->line, "airbag '%s': a membrane bag needs size=A,B (plan semi-axes, m)",
                    b->name);
  }
  static const char* const nn[] = {"depth",  "top",       "mount_r", "e1t",  "e2t",      "nu12",
                                   "g0t",    "gtt",       "lock",    "re",   "rhot",     "damp",
                                   "temp",   "vent_area", "vent_cd", "leak", "kc_alpha", "kc_dt",
                                   "zeta_c", "dt_factor", "mscale"};
  for (size_t i = 0; i < sizeof(nn) / sizeof(nn[0]); i++) {
    if (url_nonneg(p, b, nn[i], 0)) {
      return -1;
    }
  }
  bag->type = urBAG_MEMBRANE;
  s->plan = url_get(b, "plan")->set ? (urMemPlan)url_get(b, "plan")->e : urMEM_ELLIPSE;
  s->pattern = url_get(b, "pattern")->set ? (urMemPattern)url_get(b, "pattern")->e : urMEM_SHAPE;
  s->a = vs->v[0];
  s->b = vs->v[1];
  if (url_get(b, "mount")->set) {
    const double* mt = url_vec(b, "mount");
    for (int k = 0; k < 3; k++) {
      s->mount[k] = mt[k];
    }
  } else {
    // default: the top centre of the bag ellipsoid
    const urGeom* g = m->geom + bag->geom;
    s->mount[0] = g->pos[0];
    s->mount[1] = g->pos[1];
    s->mount[2] = g->pos[2];
  }
  if (url_orientation(p, b, s->quat)) {
    return -1;
  }
  s->mesh = (int)url_num(b, "mesh", s->mesh);
  s->inflate = (int)url_num(b, "inflate", s->inflate);
  s->wrinkle = (int)url_num(b, "wrinkle", s->wrinkle);
  s->depth = url_num(b, "depth", s->depth);
  s->top = url_num(b, "top", s->top);
  s->mount_r = url_num(b, "mount_r", s->mount_r);
  s->e1t = url_num(b, "e1t", s->e1t);
  s->e2t = url_num(b, "e2t", s->e2t);
  s->nu12 = url_num(b, "nu12", s->nu12);
  s->g0t = url_num(b, "g0t", s->g0t);
  s->gtt = url_num(b, "gtt", s->gtt);
  s->lock = url_num(b, "lock", s->lock);
  s->re = url_num(b, "re", s->re);
  s->rhot = url_num(b, "rhot", s->rhot);
  s->damp = url_num(b, "damp", s->damp);
  s->temp = url_num(b, "temp", s->temp);
  s->vent_area = url_num(b, "vent_area", s->vent_area);
  s->vent_cd = url_num(b, "vent_cd", s->vent_cd);
  s->leak = url_num(b, "leak", s->leak);
  s->kc_alpha = url_num(b, "kc_alpha", s->kc_alpha);
  s->kc_dt = url_num(b, "kc_dt", s->kc_dt);
  s->zeta_c = url_num(b, "zeta_c", s->zeta_c);
  s->dt_factor = url_num(b, "dt_factor", s->dt_factor);
  s->mscale = url_num(b, "mscale", s->mscale);
  s->p0 = bag->gas.p0;
  s->patm = bag->gas.patm;
  s->gamma = bag->gas.gamma;
  s->mu = bag->mu;
  if (bag->v_eps > 0) {
    s->v_eps = bag->v_eps;
  }
  char err[120];
  if (ur_mem_spec_check(s, err, sizeof(err))) {
    return url_fail(p, vm->line, "airbag '%s': membrane: %s", b->name, err);
  }
  double live = url_num(b, "live", 0);
  if (live != 0 && live != 1) {
    return url_fail(p, url_get(b, "live")->line,
                    "airbag '%s': live must be 0 (the first rule: bounding spheres) or 1 "
                    "(nodes and jolts; uasimpact-model(5), live), got %g",
                    b->name, live);
  }
  bag->liverule = (int)live;

  // supports: ellipsoids of the carrier's own tree the fabric presses against
  const Val* vp = url_get(b, "support");
  for (int i = 0; vp->set && i < vp->n; i++) {
    char name[urNAMELEN];
    url_item(vp->raw, i, name, sizeof(name));
    int g = url_ref(p, SYM_ELLIPSOID, name, vp->line, "support");
    if (g < 0) {
      return -1;
    }
    bag->support[bag->nsupport++] = g;
  }
  return 0;
}


/* airbag NAME geom= p0= patm= v0= gamma= kappa= thickness= targets= ... */
int url_st_airbag(Parser* p, const Bound* b) {
  urModel* m = p->m;
  urAirbag bag;
  memset(&bag, 0, sizeof(bag));
  snprintf(bag.name, sizeof(bag.name), "%s", b->name);
  bag.type = urBAG_UNIFORM;
  const Val* vg = url_get(b, "geom");
  bag.geom = url_ref(p, SYM_ELLIPSOID, vg->raw, vg->line, NULL);
  if (bag.geom < 0) {
    return -1;
  }

  /* scalars */
  static const char* const pos[] = {"p0", "patm", "v0", "gamma", "kappa", "thickness"};
  static const char* const nn[] = {"fabric_k", "fabric_c", "mu", "v_eps"};
  for (int i = 0; i < 6; i++) {
    if (url_nonneg(p, b, pos[i], 1)) {
      return -1;
    }
  }
  for (int i = 0; i < 4; i++) {
    if (url_nonneg(p, b, nn[i], 0)) {
      return -1;
    }
  }
  bag.gas.p0 = url_num(b, "p0", 0);
  bag.gas.patm = url_num(b, "patm", 0);
  bag.gas.v0 = url_num(b, "v0", 0);
  bag.gas.gamma = url_num(b, "gamma", 0);
  bag.kappa = url_num(b, "kappa", 0);
  bag.thickness = url_num(b, "thickness", 0);
  bag.fabric_k = url_num(b, "fabric_k", 0);
  bag.fabric_c = url_num(b, "fabric_c", 0);
  bag.mu = url_num(b, "mu", 0);
  bag.v_eps = url_num(b, "v_eps", 0);

  /* targets: distinct ellipsoids of other bodies */
  const Val* vt = url_get(b, "targets");
  for (int i = 0; i < vt->n; i++) {
    char name[urNAMELEN];
    url_item(vt->raw, i, name, sizeof(name));
    int g = url_ref(p, SYM_ELLIPSOID, name, vt->line, "targets");
    if (g < 0) {
      return -1;
    }
    if (m->geom[g].body == m->geom[bag.geom].body) {
      return url_fail(p, vt->line, "airbag '%s': target '%s' is on the bag's own body '%s'",
                      b->name, name, m->body[m->geom[g].body].name);
    }
    for (int k = 0; k < i; k++) {
      if (bag.target[k] == g) {
        return url_fail(p, vt->line, "airbag '%s': target '%s' is listed twice", b->name, name);
      }
    }
    char what[urNAMELEN + 16];
    snprintf(what, sizeof(what), "airbag '%s'", b->name);
    if (url_degree2(p, g, name, vt->line, what, "a target")) {
      return -1;
    }
    bag.target[i] = g;
  }
  bag.ntarget = vt->n;
  if (membrane_keys(p, b, &bag)) {
    return -1;
  }
  if (bag.type == urBAG_MEMBRANE) {
    url_bag_layers(p, &bag);
  }
  if (url_declare(p, SYM_AIRBAG, b->name, b->line, m->nbag, 1)) {
    return -1;
  }
  if (ur_model_add_airbag(m, &bag) < 0) {
    return url_fail(p, b->line, "airbag '%s': %s", b->name, m->err);
  }
  return 0;
}


/* sensor NAME type= obj= [dof=] [pos=] [quat=|rot=] */
int url_st_sensor(Parser* p, const Bound* b) {
  urModel* m = p->m;
  urSensorType type = (urSensorType)url_get(b, "type")->e;
  const Val* vo = url_get(b, "obj");
  const Val* vd = url_get(b, "dof");
  const Val* vp = url_get(b, "pos");
  const Val* vq = url_get(b, "quat")->set ? url_get(b, "quat") : url_get(b, "rot");
  int onbody = type == urSENS_ACCEL || type == urSENS_BODYPOS || type == urSENS_BODYVEL;
  int onjoint = type == urSENS_JOINTLOAD || type == urSENS_JOINTPOS || type == urSENS_JOINTVEL ||
                type == urSENS_HINGE;
  int hasdof = type == urSENS_JOINTPOS || type == urSENS_JOINTVEL || type == urSENS_HINGE;

  /* keys that apply */
  if (vd->set && !hasdof) {
    return url_fail(p, vd->line,
                    "sensor '%s': key 'dof' applies only to jointpos, jointvel and hinge", b->name);
  }
  if (vp->set && !onbody) {
    return url_fail(p, vp->line,
                    "sensor '%s': key 'pos' applies only to accel, bodypos and bodyvel", b->name);
  }
  if (vq->set && type != urSENS_JOINTLOAD) {
    return url_fail(p, vq->line, "sensor '%s': key '%s' applies only to jointload", b->name,
                    vq == url_get(b, "rot") ? "rot" : "quat");
  }

  /* object by type: joint sensors take a joint name or a body name */
  int obj;
  if (onjoint && url_findsym(p, SYM_JOINT, vo->raw, 1) < 0 &&
      url_findsym(p, SYM_BODY, vo->raw, 1) >= 0) {
    obj = url_ref(p, SYM_BODY, vo->raw, vo->line, NULL);
  } else {
    int kind = onbody                   ? SYM_BODY
               : onjoint                ? SYM_JOINT
               : type == urSENS_CONTACT ? SYM_PAIR
                                        : SYM_AIRBAG;
    obj = url_ref(p, kind, vo->raw, vo->line, NULL);
  }
  if (obj < 0) {
    return -1;
  }

  /* dof within the joint */
  int dof = (int)url_num(b, "dof", 0);
  if (hasdof) {
    static const int nv[] = {6, 0, 1, 2, 3, 1};
    const urBody* bd = m->body + obj;
    int ok = dof < nv[bd->jtype];
    if (type == urSENS_JOINTPOS) {
      ok = ok && bd->jtype != urJNT_FREE && bd->jtype != urJNT_SPHERICAL;
    }
    if (!ok) {
      return url_fail(p, vd->set ? vd->line : b->line,
                      "sensor '%s': dof %d does not exist on "
                      "joint '%s'%s",
                      b->name, dof, bd->jname,
                      type == urSENS_JOINTPOS ? " (jointpos needs a revolute, universal or "
                                                "prismatic joint)"
                                              : "");
    }
  }
  if (type == urSENS_HINGE &&
      !(dof < 3 && m->body[obj].jtype != urJNT_FREE && m->body[obj].rst[dof].mp > 0)) {
    return url_fail(p, vd->set ? vd->line : b->line,
                    "sensor '%s': joint '%s' dof %d has no hinge from beam theory; expected a "
                    "'restraint ... material= section= length=' on it above",
                    b->name, m->body[obj].jname, dof);
  }
  double q[4];
  if (url_orientation(p, b, q) || url_declare(p, SYM_SENSOR, b->name, b->line, m->nsensor, 1)) {
    return -1;
  }
  if (ur_model_add_sensor(m, b->name, type, obj, dof, url_vec(b, "pos"), q) < 0) {
    return url_fail(p, b->line, "sensor '%s': %s", b->name, m->err);
  }
  return 0;
}


/* role key=value...: the elements an impact needs, and the parameters that scale the drone */
int url_st_role(Parser* p, const urlStmt* st, Bound* b) {
  int rc = url_bind(p, st, 1, spec_role, NKEY(spec_role), b);
  if (rc) {
    return rc < 0 ? -1 : 0;
  }
  urModel* m = p->m;
  urRoles* r = &m->roles;
  static const struct {
    const char* key;
    int kind;
    int type; /* sensor type, or -1 */
  } rk[] = {{"drone", SYM_BODY, -1},
            {"head", SYM_ELLIPSOID, -1},
            {"head_acc", SYM_SENSOR, urSENS_ACCEL},
            {"neck", SYM_SENSOR, urSENS_JOINTLOAD},
            {"head_pos", SYM_SENSOR, urSENS_BODYPOS},
            {"chest", SYM_SENSOR, urSENS_JOINTPOS},
            {"abdomen", SYM_SENSOR, urSENS_JOINTPOS}};
  int* slot[] = {&r->drone, &r->head, &r->head_acc, &r->neck, &r->head_pos, &r->chest, &r->abdomen};
  for (int i = 0; i < (int)(sizeof(rk) / sizeof(rk[0])); i++) {
    const Val* v = url_get(b, rk[i].key);
    if (!v->set) {
      continue;
    }
    int id = url_ref(p, rk[i].kind, v->raw, v->line, "role");
    if (id < 0) {
      return -1;
    }
    if (rk[i].kind == SYM_BODY && r->drone >= 0 && r->drone != id) {
      return url_fail(p, v->line,
                      "role drone: the model has a drone already (body '%s'); one model "
                      "has one drone: drop the other drone's parts first",
                      m->body[r->drone].name);
    }
    if (rk[i].kind == SYM_BODY && (m->body[id].parent >= 0 || m->body[id].jtype != urJNT_FREE)) {
      return url_fail(p, v->line,
                      "role drone: body '%s' must have a free joint to the world (the "
                      "drone is placed and launched by it)",
                      v->raw);
    }
    if (rk[i].type >= 0 && (int)m->sensor[id].type != rk[i].type) {
      static const char* const tname[] = {"accel",   "jointload", "jointpos", "jointvel",
                                          "contact", "airbag",    "bodypos",  "bodyvel"};
      int t = rk[i].type;
      return url_fail(p, v->line, "role %s: sensor '%s' must be of type=%s", rk[i].key, v->raw,
                      t >= 0 && t < 8 ? tname[t] : "?");
    }
    *slot[i] = id;
  }
  static const char* const design[] = {"mass", "size"};
  int* dslot[] = {&r->mass_param, &r->size_param};
  for (int i = 0; i < 2; i++) {
    const Val* v = url_get(b, design[i]);
    if (!v->set) {
      continue;
    }
    if (v->raw[0] != '$') {
      return url_fail(p, v->line,
                      "role %s: expected a parameter ($NAME) that the workbench can set, "
                      "got '%s'",
                      design[i], url_quote(v->raw, strlen(v->raw)).s);
    }
    if (!(v->v[0] > 0)) {
      return url_fail(p, v->line, "role %s: must be > 0 (got %g)", design[i], v->v[0]);
    }
    *dslot[i] = ur_name_param(m, v->raw + 1);
  }
  return 0;
}


/* preset NAME key=value...: a case, as model parameters (VALUE[UNIT] or $param) and workbench
   settings (plain numbers, checked by the workbench) */
int url_st_preset(Parser* p, const urlStmt* st) {
  if (st->nword < 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return url_fail(p, st->line,
                    "preset needs a NAME before its keys; expected 'preset NAME "
                    "key=value ...'");
  }
  const char* name = url_word(&p->lx, st->word + 1);
  if (url_checkname(p, name, strlen(name), st->line, "preset")) {
    return -1;
  }
  if (strlen(name) > 7) {
    return url_fail(p, st->line,
                    "preset '%s': a preset name has at most 7 characters (it labels "
                    "the rows of tables)",
                    name);
  }
  urPreset pr;
  memset(&pr, 0, sizeof(pr));
  snprintf(pr.name, sizeof(pr.name), "%s", name);
  for (int w = 2; w < st->nword; w++) {
    const char* s = url_word(&p->lx, st->word + w);
    int line = p->lx.word[st->word + w].line;
    const char* eq = strchr(s, '=');
    size_t kl = eq ? (size_t)(eq - s) : 0;
    if (!eq || kl == 0 || !eq[1]) {
      return url_fail(p, line, "preset '%s': expected key=value, got '%s' (no blanks around '=')",
                      name, url_quote(s, strlen(s)).s);
    }
    char key[urNAMELEN];
    if (url_checkname(p, s, kl, line, "preset key")) {
      return -1;
    }
    memcpy(key, s, kl);
    key[kl] = 0;
    for (int k = 0; k < pr.n; k++) {
      if (!strcmp(pr.key[k], key)) {
        return url_fail(p, line, "preset '%s': duplicate key '%s'; a key may appear once", name,
                        key);
      }
    }
    if (pr.n == urMAXPRESET) {
      return url_fail(p, line, "preset '%s': more than %d keys", name, urMAXPRESET);
    }
    int isparam = url_findsym(p, SYM_PARAM, key, 1) >= 0 || url_param_declared(p, key);
    const char* v = eq + 1;
    size_t vn = strlen(v), k = url_decimal_prefix(v, vn);
    double f = 1, x;
    char ctx[80];
    snprintf(ctx, sizeof(ctx), "preset '%s' key '%s'", name, key);
    int isref = v[0] == '$' || (v[0] == '-' && v[1] == '$');
    if (!isref && k > 0 && k < vn) {
      if (ur_unit_si(v + k, &f)) {
        return url_fail(p, line,
                        "%s: unknown unit '%s'; expected a unit of a param line (atm, kg, "
                        "mm, ...)",
                        ctx, url_quote(v + k, vn - k).s);
      }
      if (!isparam) {
        return url_fail(p, line,
                        "%s: a unit is taken only by model parameters ('%s' is a "
                        "workbench setting, in the unit its 'show' prints)",
                        ctx, key);
      }
      vn = k;
    }
    if (url_number(p, v, vn, line, ctx, &x)) {
      return -1;
    }
    x *= f;
    if (!isfinite(x)) {
      return url_fail(p, line, "%s: value overflows after conversion to SI", ctx);
    }
    snprintf(pr.key[pr.n], urNAMELEN, "%s", key);
    pr.value[pr.n] = x;
    pr.param[pr.n] = isparam ? ur_name_param(p->m, key) : -1;
    pr.n++;
  }
  if (url_declare(p, SYM_PRESET, name, st->line, p->m->npreset, 1)) {
    return -1;
  }
  urPreset* np = realloc(p->m->preset, (size_t)(p->m->npreset + 1) * sizeof(urPreset));
  if (!np) {
    return url_fail(p, st->line, "out of memory");
  }
  p->m->preset = np;
  np[p->m->npreset++] = pr;
  return 0;
}


/* the drone tree scaled by its design parameters (role mass=, size=) */
int url_apply_design(Parser* p) {
  urModel* m = p->m;
  urRoles* r = &m->roles;
  if (r->drone < 0) {
    return 0;
  }
  r->mass0 = ur_model_tree_mass(m, r->drone);
  double fm = 1, fs = 1;
  if (r->mass_param >= 0) {
    double mm = m->param[r->mass_param].value;
    if (!(mm > 0) || !(r->mass0 > 0)) {
      snprintf(p->msg, sizeof(p->msg), "role mass: parameter '%s' must be > 0 (got %g)",
               m->param[r->mass_param].name, mm);
      return -1;
    }
    fm = mm / r->mass0;
  }
  if (r->size_param >= 0) {
    fs = m->param[r->size_param].value;
    if (!(fs > 0)) {
      snprintf(p->msg, sizeof(p->msg), "role size: parameter '%s' must be > 0 (got %g)",
               m->param[r->size_param].name, fs);
      return -1;
    }
  }
  if (fabs(fm - 1) <= 1e-12) {
    fm = 1; /* the total as written, to rounding: the bodies as written */
  }
  r->mass_scale = fm;
  r->size_scale = fs;
  if (fm != 1 || fs != 1) {
    ur_model_scale_tree(m, r->drone, fm, fs);
  }
  return 0;
}


/* part NAME */
int url_st_part(Parser* p, const urlStmt* st) {
  if (st->nword != 2 || strchr(url_word(&p->lx, st->word + 1), '=')) {
    return url_fail(p, st->line, "part takes exactly one NAME; expected 'part NAME'");
  }
  const char* name = url_word(&p->lx, st->word + 1);
  if (url_checkname(p, name, strlen(name), st->line, "part")) {
    return -1;
  }
  return url_declare(p, SYM_PART, name, st->line, 0, 1);
}
