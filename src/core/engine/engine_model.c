/* engine_model.c: model builder (add bodies, joints, ellipsoids, pairs, airbags, sensors,
 * parameters), compilation and look-up by name. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- helpers -------------------------------------------------------

// print an error into the model
static int fail(urModel* m, const char* what, const char* name) {
  snprintf(m->err, sizeof(m->err), "%s%s%s", what, name ? ": " : "", name ? name : "");
  return -1;
}


// copy a name, checking length
static int setname(urModel* m, char dst[urNAMELEN], const char* name) {
  if (!name || !name[0] || strlen(name) >= urNAMELEN) {
    return fail(m, "missing or too long name", name);
  }
  memcpy(dst, name, strlen(name) + 1);
  return 0;
}


// grow an array so that it holds n+1 elements
static int grow(void** arr, int* cap, int n, size_t size) {
  if (n < *cap) {
    return 0;
  }
  int nc = *cap ? 2 * (*cap) : 16;
  void* p = realloc(*arr, (size_t)nc * size);
  if (!p) {
    return -1;
  }
  memset((char*)p + (size_t)(*cap) * size, 0, (size_t)(nc - *cap) * size);
  *arr = p;
  *cap = nc;
  return 0;
}


// common checks before adding an element
static int editable(urModel* m) {
  if (!m) {
    return -1;
  }
  if (m->compiled) {
    return fail(m, "model already compiled", NULL);
  }
  return 0;
}


static void setquat(double dst[4], const double q[4]) {
  if (q) {
    memcpy(dst, q, 4 * sizeof(double));
    uru_normalizequat(dst);
  } else {
    dst[0] = 1;
    dst[1] = dst[2] = dst[3] = 0;
  }
}

//---------------------------------- builder -------------------------------------------------------

urModel* ur_model_new(void) {
  urModel* m = calloc(1, sizeof(urModel));
  if (!m) {
    return NULL;
  }

  // default options
  m->opt.dt = 1e-5;
  m->opt.gravity[2] = -9.81;
  m->opt.integrator = urINT_EULER;
  m->opt.implicit_damping = 1;
  m->opt.sample_dt = 1e-4;
  m->opt.tmax = 0.2;
  m->opt.t_quiet = 0.02;
  m->opt.t_clear = INFINITY;
  m->opt.a_clear = 100;
  m->opt.ke_settle = 1e-3;
  m->opt.vmax = 1e4;
  m->opt.jump_margin = 1e-3;
  m->opt.adapt = 1;
  urRoles* r = &m->roles;
  r->drone = r->head = r->head_acc = r->neck = r->head_pos = r->chest = r->abdomen = -1;
  r->mass_param = r->size_param = -1;
  r->mass_scale = r->size_scale = 1;
  return m;
}


void ur_model_free(urModel* m) {
  if (!m) {
    return;
  }
  free(m->body);
  free(m->geom);
  free(m->pair);
  urm_model_free(m);
  free(m->bag);
  free(m->sensor);
  free(m->param);
  free(m->preset);
  free(m->qpos0);
  free(m->grav);
  free(m->derived);
  free(m);
}


int ur_model_add_body(urModel* m, const char* name, int parent, urJointType type,
                      const double pos[3], const double quat[4]) {
  if (editable(m)) {
    return -1;
  }
  if (parent < -1 || parent >= m->nbody) {
    return fail(m, "parent body does not exist for", name);
  }
  if (type < urJNT_FREE || type > urJNT_PRISMATIC) {
    return fail(m, "bad joint type for", name);
  }
  if (name && ur_name_body(m, name) >= 0) {
    return fail(m, "duplicate body name", name);
  }
  if (grow((void**)&m->body, &m->cap[0], m->nbody, sizeof(urBody))) {
    return fail(m, "out of memory", NULL);
  }

  // fill the body with defaults
  urBody* b = m->body + m->nbody;
  memset(b, 0, sizeof(urBody));
  if (setname(m, b->name, name) || setname(m, b->jname, name)) {
    return -1;
  }
  b->parent = parent;
  b->jtype = type;
  b->gravity = 1;
  if (pos) {
    memcpy(b->pos, pos, 3 * sizeof(double));
  }
  setquat(b->quat, quat);
  b->axis[0][2] = 1;
  b->axis[1][1] = 1;
  if (type == urJNT_UNIVERSAL) {
    b->axis[0][0] = 1;
    b->axis[0][2] = 0;
  }
  return m->nbody++;
}


int ur_model_set_inertia(urModel* m, int body, double mass, const double com[3],
                         const double inertia[6]) {
  if (editable(m) || body < 0 || body >= m->nbody) {
    return -1;
  }
  urBody* b = m->body + body;
  b->mass = mass;
  if (com) {
    memcpy(b->com, com, 3 * sizeof(double));
  }
  if (inertia) {
    double I[9] = {inertia[0], inertia[3], inertia[4], inertia[3], inertia[1],
                   inertia[5], inertia[4], inertia[5], inertia[2]};
    memcpy(b->inertia, I, sizeof(I));
  }
  return 0;
}


int ur_model_set_joint(urModel* m, int body, const char* jname, const double a1[3],
                       const double a2[3]) {
  if (editable(m) || body < 0 || body >= m->nbody) {
    return -1;
  }
  urBody* b = m->body + body;
  if (jname && (ur_name_joint(m, jname) >= 0 && ur_name_joint(m, jname) != body)) {
    return fail(m, "duplicate joint name", jname);
  }
  if (jname && setname(m, b->jname, jname)) {
    return -1;
  }
  const double* a[2] = {a1, a2};
  for (int k = 0; k < 2; k++) {
    if (a[k]) {
      memcpy(b->axis[k], a[k], 3 * sizeof(double));
      if (uru_normalize3(b->axis[k])) {
        return fail(m, "zero joint axis", b->jname);
      }
    }
  }
  return 0;
}


int ur_model_set_restraint(urModel* m, int body, int dof, const urRestraint* r) {
  if (editable(m) || body < 0 || body >= m->nbody || dof < 0 || dof > 2 || !r) {
    return -1;
  }
  m->body[body].rst[dof] = *r;
  m->body[body].rst[dof].active = 1;
  return 0;
}


int ur_model_add_ellipsoid(urModel* m, const char* name, int body, const double pos[3],
                           const double quat[4], const double semiaxes[3]) {
  if (editable(m)) {
    return -1;
  }
  if (body < 0 || body >= m->nbody) {
    return fail(m, "ellipsoid on a missing body", name);
  }
  if (!semiaxes || !(semiaxes[0] > 0 && semiaxes[1] > 0 && semiaxes[2] > 0)) {
    return fail(m, "ellipsoid semi-axes must be positive", name);
  }
  if (name && ur_name_geom(m, name) >= 0) {
    return fail(m, "duplicate ellipsoid name", name);
  }
  if (grow((void**)&m->geom, &m->cap[1], m->ngeom, sizeof(urGeom))) {
    return fail(m, "out of memory", NULL);
  }

  // fill
  urGeom* g = m->geom + m->ngeom;
  memset(g, 0, sizeof(urGeom));
  if (setname(m, g->name, name)) {
    return -1;
  }
  g->body = body;
  if (pos) {
    memcpy(g->pos, pos, 3 * sizeof(double));
  }
  setquat(g->quat, quat);
  memcpy(g->size, semiaxes, 3 * sizeof(double));
  g->degree = 2;
  g->rbound = fmax(semiaxes[0], fmax(semiaxes[1], semiaxes[2]));
  return m->ngeom++;
}


// is ellipsoid g the section-area ellipsoid of a foam pair or an airbag target
static int needs_ellipsoid(const urModel* m, int g) {
  for (int i = 0; i < m->npair; i++) {
    if (m->pair[i].geom1 == g && m->pair[i].law.type == urLAW_FOAM) {
      return 1;
    }
  }
  for (int i = 0; i < m->nbag; i++) {
    for (int t = 0; t < m->bag[i].ntarget; t++) {
      if (m->bag[i].target[t] == g) {
        return 1;
      }
    }
  }
  return 0;
}


int ur_model_set_degree(urModel* m, int g, double p) {
  if (editable(m)) {
    return -1;
  }
  if (g < 0 || g >= m->ngeom) {
    return fail(m, "degree of a missing ellipsoid", NULL);
  }
  urGeom* ge = m->geom + g;
  if (!(p >= 2 && p <= urMAXDEGREE)) {
    char what[48];
    snprintf(what, sizeof(what), "ellipsoid degree must be in [2, %d]", urMAXDEGREE);
    return fail(m, what, ge->name);
  }
  if (p != 2 && needs_ellipsoid(m, g)) {
    return fail(m, "degree 2 needed by a foam pair (ellipsoid a) or an airbag target", ge->name);
  }
  ge->degree = p;
  ge->rbound = ur_bound_radius(ge->size, p);
  return 0;
}


int ur_model_add_pair(urModel* m, const char* name, int geom1, int geom2, const urLaw* law) {
  if (editable(m)) {
    return -1;
  }
  if (geom1 < 0 || geom1 >= m->ngeom || geom2 < -1 || geom2 >= m->ngeom || geom1 == geom2 || !law) {
    return fail(m, "bad ellipsoids or law in pair", name);
  }
  if (geom2 >= 0 && m->geom[geom1].body == m->geom[geom2].body) {
    return fail(m, "pair on one body", name);
  }
  if (law->type == urLAW_FOAM && m->geom[geom1].degree != 2) {
    return fail(m, "foam law on a superellipsoid (its ellipsoid a must have degree 2)", name);
  }
  if (name && ur_name_pair(m, name) >= 0) {
    return fail(m, "duplicate pair name", name);
  }
  if (grow((void**)&m->pair, &m->cap[2], m->npair, sizeof(urPair))) {
    return fail(m, "out of memory", NULL);
  }

  // fill
  urPair* p = m->pair + m->npair;
  memset(p, 0, sizeof(urPair));
  if (setname(m, p->name, name)) {
    return -1;
  }
  p->geom1 = geom1;
  p->geom2 = geom2;
  p->law = *law;
  return m->npair++;
}


int ur_model_add_airbag(urModel* m, const urAirbag* bag) {
  if (editable(m) || !bag) {
    return -1;
  }
  if (bag->geom < 0 || bag->geom >= m->ngeom) {
    return fail(m, "airbag ellipsoid missing", bag->name);
  }
  if (bag->ntarget < 0 || bag->ntarget > urMAXBAGTGT) {
    return fail(m, "bad airbag target count", bag->name);
  }
  for (int i = 0; i < bag->ntarget; i++) {
    int t = bag->target[i];
    if (t < 0 || t >= m->ngeom || m->geom[t].body == m->geom[bag->geom].body) {
      return fail(m, "bad airbag target", bag->name);
    }
    if (m->geom[t].degree != 2 && bag->type != urBAG_MEMBRANE) {
      return fail(m, "airbag target of degree other than 2", bag->name);
    }
  }
  if (bag->nsupport < 0 || bag->nsupport > urMAXBAGTGT) {
    return fail(m, "bad airbag support count", bag->name);
  }
  for (int i = 0; i < bag->nsupport; i++) {
    int t = bag->support[i];
    if (t < 0 || t >= m->ngeom || t == bag->geom) {
      return fail(m, "bad airbag support ellipsoid", bag->name);
    }
  }
  if (bag->type == urBAG_MEMBRANE && ur_mem_spec_check(&bag->mspec, m->err, sizeof(m->err))) {
    return -1;
  }
  if (bag->type != urBAG_MEMBRANE && !(bag->gas.v0 > 0 && bag->gas.p0 > 0 && bag->gas.gamma > 0)) {
    return fail(m, "airbag gas needs v0, p0, gamma > 0", bag->name);
  }
  if (ur_name_airbag(m, bag->name) >= 0) {
    return fail(m, "duplicate airbag name", bag->name);
  }
  if (grow((void**)&m->bag, &m->cap[3], m->nbag, sizeof(urAirbag))) {
    return fail(m, "out of memory", NULL);
  }

  // copy, with defaults
  urAirbag* b = m->bag + m->nbag;
  *b = *bag;
  b->mem = NULL;
  b->inflated = 0;
  if (setname(m, b->name, bag->name)) {
    return -1;
  }
  if (b->kappa <= 0) {
    b->kappa = 1;
  }
  if (b->thickness <= 0) {
    b->thickness = INFINITY;
  }
  if (b->v_eps <= 0) {
    b->v_eps = 1e-2;
  }
  return m->nbag++;
}


int ur_model_add_sensor(urModel* m, const char* name, urSensorType type, int obj, int dof,
                        const double pos[3], const double quat[4]) {
  if (editable(m)) {
    return -1;
  }

  // check the object by type
  int ok, dim;
  switch (type) {
  case urSENS_ACCEL:
  case urSENS_BODYPOS:
  case urSENS_BODYVEL:
    ok = obj >= 0 && obj < m->nbody;
    dim = 3;
    break;
  case urSENS_JOINTLOAD:
    ok = obj >= 0 && obj < m->nbody;
    dim = 6;
    break;
  case urSENS_JOINTPOS:
  case urSENS_JOINTVEL:
    ok = obj >= 0 && obj < m->nbody && dof >= 0;
    dim = 1;
    break;
  case urSENS_HINGE:
    ok = obj >= 0 && obj < m->nbody && dof >= 0 && dof < 3 && m->body[obj].rst[dof].mp > 0;
    dim = 2;
    break;
  case urSENS_CONTACT:
    ok = obj >= 0 && obj < m->npair;
    dim = 3;
    break;
  case urSENS_AIRBAG:
    ok = obj >= 0 && obj < m->nbag;
    dim = 4;
    break;
  default: ok = 0; dim = 0;
  }
  if (!ok) {
    return fail(m, "bad sensor object", name);
  }
  if (name && ur_name_sensor(m, name) >= 0) {
    return fail(m, "duplicate sensor name", name);
  }
  if (grow((void**)&m->sensor, &m->cap[4], m->nsensor, sizeof(urSensor))) {
    return fail(m, "out of memory", NULL);
  }

  // fill
  urSensor* s = m->sensor + m->nsensor;
  memset(s, 0, sizeof(urSensor));
  if (setname(m, s->name, name)) {
    return -1;
  }
  s->type = type;
  s->obj = obj;
  s->dof = dof;
  s->dim = dim;
  if (pos) {
    memcpy(s->pos, pos, 3 * sizeof(double));
  }
  setquat(s->quat, quat);
  return m->nsensor++;
}


int ur_model_set_param(urModel* m, const char* name, double value) {
  if (!m) {
    return -1;
  }
  int i = ur_name_param(m, name);
  if (i >= 0) {
    m->param[i].value = value;
    m->param[i].from = -1; /* it holds its own value now */
    return i;
  }
  if (editable(m)) {
    return -1;
  }
  if (grow((void**)&m->param, &m->cap[5], m->nparam, sizeof(urParam))) {
    return fail(m, "out of memory", NULL);
  }
  if (setname(m, m->param[m->nparam].name, name)) {
    return -1;
  }
  urParam* p = m->param + m->nparam;
  p->value = value;
  p->unit[0] = 0;
  p->lo = -INFINITY;
  p->hi = INFINITY;
  p->why[0] = 0;
  p->from = -1;
  p->from_f = 1;
  return m->nparam++;
}


int ur_param_accepts(const urParam* p, double v) {
  return v >= p->lo && v <= p->hi;
}


int ur_model_set_param_range(urModel* m, const char* name, double lo, double hi, const char* why) {
  int i = m && !editable(m) ? ur_name_param(m, name) : -1;
  if (i < 0) {
    return -1;
  }
  urParam* p = m->param + i;
  if (!(lo <= hi) || (why && strlen(why) >= sizeof p->why) || !(p->value >= lo && p->value <= hi)) {
    return -1;
  }
  p->lo = lo;
  p->hi = hi;
  snprintf(p->why, sizeof p->why, "%s", why ? why : "");
  return i;
}

//---------------------------------- compile -------------------------------------------------------

int ur_model_compile(urModel* m) {
  if (editable(m)) {
    return -1;
  }
  if (!(m->opt.dt > 0) || !(m->opt.sample_dt > 0) || !(m->opt.tmax > 0)) {
    return fail(m, "dt, sample_dt and tmax must be positive", NULL);
  }
  if (m->opt.adapt < 1 || m->opt.adapt > urMAXADAPT) {
    return fail(m, "adapt must be an integer from 1 (off) to 16", NULL);
  }

  // joint sizes and addresses, trees
  m->nq = m->nv = 0;
  for (int i = 0; i < m->nbody; i++) {
    urBody* b = m->body + i;
    static const int nq[] = {7, 0, 1, 2, 4, 1}, nv[] = {6, 0, 1, 2, 3, 1};
    b->qadr = m->nq;
    b->vadr = m->nv;
    b->nq = nq[b->jtype];
    b->nv = nv[b->jtype];
    m->nq += b->nq;
    m->nv += b->nv;
    b->tree = b->parent < 0 ? i : m->body[b->parent].tree;
    if (!(b->mass > 0)) {
      return fail(m, "body mass must be positive", b->name);
    }
    if (b->jtype == urJNT_UNIVERSAL && fabs(uru_dot3(b->axis[0], b->axis[1])) > 1 - 1e-9) {
      return fail(m, "universal joint axes are parallel", b->jname);
    }

    // spatial inertia and inverse rotational inertia (zero if singular)
    uru_rbi(b->sinert, b->mass, b->com, b->inertia);
    uru_quat2mat(b->bmat, b->quat);
    if (uru_invsym(b->iinv, b->inertia, 3)) {
      memset(b->iinv, 0, sizeof(b->iinv));
    }
  }

  ur_fracture_compile(m);
  for (int g = 0; g < m->ngeom; g++) {
    uru_quat2mat(m->geom[g].gmat, m->geom[g].quat);
  }

  // reference configuration
  free(m->qpos0);
  m->qpos0 = calloc((size_t)(m->nq ? m->nq : 1), sizeof(double));
  if (!m->qpos0) {
    return fail(m, "out of memory", NULL);
  }
  for (int i = 0; i < m->nbody; i++) {
    urBody* b = m->body + i;
    double* q = m->qpos0 + b->qadr;
    if (b->jtype == urJNT_FREE) {
      double R[9], c[3];
      uru_quat2mat(R, b->quat);
      uru_mulmat3vec(c, R, b->com);
      for (int k = 0; k < 3; k++) {
        q[k] = b->pos[k] + c[k];
      }
      memcpy(q + 3, b->quat, 4 * sizeof(double));
    } else if (b->jtype == urJNT_SPHERICAL) {
      q[0] = 1;
    }
  }
  ur_fracture_qpos0(m, m->qpos0);

  // sensor addresses
  m->nsensordata = 0;
  for (int i = 0; i < m->nsensor; i++) {
    urSensor* s = m->sensor + i;
    if ((s->type == urSENS_JOINTPOS && s->dof >= m->body[s->obj].nq) ||
        (s->type == urSENS_JOINTVEL && s->dof >= m->body[s->obj].nv)) {
      return fail(m, "sensor dof beyond the joint", s->name);
    }
    s->adr = m->nsensordata;
    m->nsensordata += s->dim;
  }

  // the bodies whose joint reactions are needed: sensed by a joint load, and those below them
  // (bodies are in tree order, parents first)
  for (int i = 0; i < m->nbody; i++) {
    m->body[i].react = 0;
  }
  for (int i = 0; i < m->nsensor; i++) {
    if (m->sensor[i].type == urSENS_JOINTLOAD) {
      m->body[m->sensor[i].obj].react = 1;
    }
  }
  for (int i = 0; i < m->nbody; i++) {
    urBody* b = m->body + i;
    if (b->parent >= 0 && m->body[b->parent].react) {
      b->react = 1;
    }
  }

  // the body lists of the per-step loops (one block: grav, then rstb, hyst, reactb)
  free(m->grav);
  m->grav = malloc(4 * (size_t)(m->nbody ? m->nbody : 1) * sizeof(int));
  if (!m->grav) {
    return fail(m, "out of memory", NULL);
  }
  m->rstb = m->grav + m->nbody;
  m->hyst = m->rstb + m->nbody;
  m->reactb = m->hyst + m->nbody;
  m->ngrav = m->nrstb = m->nhyst = m->nreactb = 0;
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    const urRestraint* r = b->rst;
    if (b->gravity != 1) {
      m->grav[m->ngrav++] = i;
    }
    if (b->jtype != urJNT_FREE && (r[0].active || r[1].active || r[2].active)) {
      m->rstb[m->nrstb++] = i;
    }
    if (b->jtype != urJNT_FREE && (r[0].load.n > 0 || r[1].load.n > 0 || r[2].load.n > 0 ||
                                   r[0].mp > 0 || r[1].mp > 0 || r[2].mp > 0)) {
      m->hyst[m->nhyst++] = i;
    }
    if (b->react) {
      m->reactb[m->nreactb++] = i;
    }
  }
  if (urm_model_compile(m)) {
    return -1;
  }
  m->compiled = 1;
  m->err[0] = 0;
  m->mirror = ur_model_mirror(m, m->nomirror, sizeof m->nomirror);
  return 0;
}

//---------------------------------- names ---------------------------------------------------------

/* equal names. A plain loop, not strcmp: a compile looks every new pair's name up among all
   pairs before it (hundreds), and sanitizer and fuzzer builds intercept every strcmp call. */
static int samename(const char* a, const char* b) {
  while (*a && *a == *b) {
    a++;
    b++;
  }
  return *a == *b;
}

#define FINDNAME(arr, n, field)                                                                    \
  if (!m || !name) {                                                                               \
    return -1;                                                                                     \
  }                                                                                                \
  for (int i = 0; i < (n); i++) {                                                                  \
    if (samename(m->arr[i].field, name)) {                                                         \
      return i;                                                                                    \
    }                                                                                              \
  }                                                                                                \
  return -1;

int ur_name_body(const urModel* m, const char* name) {
  FINDNAME(body, m->nbody, name)
}


int ur_name_joint(const urModel* m, const char* name) {
  FINDNAME(body, m->nbody, jname)
}


int ur_name_geom(const urModel* m, const char* name) {
  FINDNAME(geom, m->ngeom, name)
}


int ur_name_pair(const urModel* m, const char* name) {
  FINDNAME(pair, m->npair, name)
}


int ur_name_airbag(const urModel* m, const char* name) {
  FINDNAME(bag, m->nbag, name)
}


int ur_name_sensor(const urModel* m, const char* name) {
  FINDNAME(sensor, m->nsensor, name)
}


int ur_name_param(const urModel* m, const char* name) {
  FINDNAME(param, m->nparam, name)
}


double ur_model_param(const urModel* m, const char* name, double dflt) {
  int i = ur_name_param(m, name);
  return i >= 0 ? m->param[i].value : dflt;
}
