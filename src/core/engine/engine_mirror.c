/* engine_mirror.c: whether a compiled model is its own mirror image in the plane y = 0 (the
 * person's sagittal plane; the drone's, in its own frame), so that an impact at the offset
 * (dpar, -dperp) is the mirror image of the one at (dpar, dperp) and a grid at face 0 or 180
 * simulates dperp >= 0 only (grid.h, urGridSpec.mirror). The impact places the drone with its x
 * axis on the course and pitches it about its y axis, and keeps the person where the model puts
 * him, so the plane y = 0 of both is the vertical plane of the course through the head.
 *
 * The model is symmetric when its bodies pair off (a body on the plane pairs with itself): the
 * partner of a body hangs from the partner of its parent by a joint of the same type, at the
 * mirrored place with the mirrored frame, mass, centre of mass and inertia, joint axes mirrored
 * up to sign, and restraints that act the same on the mirrored coordinates; each body's
 * ellipsoids pair with its partner's, each contact pair with the pair of the partners under the
 * same law, each airbag with its partner's bag (a membrane's mesh node for node, triangle for
 * triangle, with the same masses, reference areas and damping, its material axes mirrored), all
 * one to one as the bodies (a second pair or bag on one side only has no partner); the
 * injury sensors sit on the plane and read what the mirror keeps (head acceleration's
 * magnitude, the neck's axial force and flexion moment, the plates' deflections), and gravity
 * lies in the plane. Anything else (a part off to one side, a restraint's stop on one side
 * only) makes it asymmetric, and why is said. Values agree to 1e-9 relative (1e-9 m for
 * lengths): mirrored text gives mirrored numbers up to rounding. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

#define TOL 1e-9

/* a and b equal to TOL relative (1 the least scale: absolute below it) */
static int eq(double a, double b) {
  return a == b || fabs(a - b) <= TOL * fmax(1.0, fmax(fabs(a), fabs(b)));
}

static int eqv(const double* a, const double* b, int n) {
  for (int k = 0; k < n; k++) {
    if (!eq(a[k], b[k])) {
      return 0;
    }
  }
  return 1;
}

/* M v, M = diag(1, -1, 1) */
static void mir3(double o[3], const double v[3]) {
  o[0] = v[0];
  o[1] = -v[1];
  o[2] = v[2];
}

/* M A M of a row-major 3x3: the entries (0,1), (1,0), (1,2), (2,1) change sign */
static void mir33(double o[9], const double a[9]) {
  static const double s[9] = {1, -1, 1, -1, 1, -1, 1, -1, 1};
  for (int k = 0; k < 9; k++) {
    o[k] = s[k] * a[k];
  }
}

static int fail(char* why, size_t n, const char* fmt, ...) {
  if (why && n) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
  }
  return 0;
}

//---------------------------------- restraints ----------------------------------------------------

/* curve c2 is c1 seen on the mirrored coordinate (sigma -1: c2(x) = -c1(-x); a curve with no
   negative abscissae is extended odd-symmetrically, so equal curves are), or equal (sigma 1) */
static int curve_ok(const urCurve* c1, const urCurve* c2, int sigma) {
  if (c1->n != c2->n) {
    return 0;
  }
  int n = c1->n, equal = 1, pos = 1;
  for (int i = 0; i < n; i++) {
    equal &= eq(c1->x[i], c2->x[i]) && eq(c1->y[i], c2->y[i]);
    pos &= c1->x[i] >= 0;
  }
  if (sigma > 0 || (equal && pos)) {
    return equal;
  }
  for (int i = 0; i < n; i++) {
    if (!eq(c2->x[i], -c1->x[n - 1 - i]) || !eq(c2->y[i], -c1->y[n - 1 - i])) {
      return 0;
    }
  }
  return 1;
}

/* the restraint r2 of the partner's dof acts on its coordinate (sigma times the mirrored one)
   as r1 on the original */
static int restraint_ok(const urRestraint* r1, const urRestraint* r2, int sigma) {
  if (r1->active != r2->active) {
    return 0;
  }
  if (!r1->active) {
    return 1;
  }
  double lo = sigma > 0 ? r1->lo : -r1->hi, hi = sigma > 0 ? r1->hi : -r1->lo;
  double x0 = sigma * r1->x0;
  return eq(r1->k, r2->k) && eq(r1->sat, r2->sat) && eq(r1->c, r2->c) && eq(lo, r2->lo) &&
         eq(hi, r2->hi) && eq(x0, r2->x0) && eq(r1->kstop, r2->kstop) && eq(r1->cstop, r2->cstop) &&
         eq(r1->mp, r2->mp) && eq(r1->kh, r2->kh) && eq(r1->mfrac, r2->mfrac) &&
         curve_ok(&r1->load, &r2->load, sigma) && curve_ok(&r1->unload, &r2->unload, sigma);
}

//---------------------------------- bodies --------------------------------------------------------

/* the signs that take body a's joint coordinates to its partner b's (sig, per dof), or 0 when
   b's joint is not a's mirrored: a rotation about an axis u becomes one about M u by the
   opposite angle, a translation along u one along M u by the same length */
static int joint_signs(const urBody* a, const urBody* b, int sig[3]) {
  sig[0] = sig[1] = sig[2] = 1;
  switch (a->jtype) {
  case urJNT_FREE:
  case urJNT_FIXED: return 1;
  case urJNT_SPHERICAL: /* the rotation vector r becomes -M r */ sig[0] = sig[2] = -1; return 1;
  case urJNT_REVOLUTE:
  case urJNT_UNIVERSAL:
  case urJNT_PRISMATIC: {
    int nax = a->jtype == urJNT_UNIVERSAL ? 2 : 1;
    for (int k = 0; k < nax; k++) {
      double u[3];
      mir3(u, a->axis[k]);
      double s = uru_dot3(u, b->axis[k]);
      if (!eq(fabs(s), 1)) {
        return 0;
      }
      sig[k] = (s > 0) == (a->jtype == urJNT_PRISMATIC) ? 1 : -1;
    }
    return 1;
  }
  }
  return 0;
}

/* b is a's mirror image, hanging from the partner of a's parent (pp) */
static int body_pair(const urBody* a, const urBody* b, int pp, int sig[3]) {
  double v[3], A[9];
  if (b->parent != pp || b->jtype != a->jtype || !eq(a->mass, b->mass) ||
      a->gravity != b->gravity) {
    return 0;
  }
  mir3(v, a->pos);
  if (!eqv(v, b->pos, 3)) {
    return 0;
  }
  mir3(v, a->com);
  if (!eqv(v, b->com, 3)) {
    return 0;
  }
  mir33(A, a->inertia);
  if (!eqv(A, b->inertia, 9)) {
    return 0;
  }
  mir33(A, a->bmat);
  if (!eqv(A, b->bmat, 9) || !joint_signs(a, b, sig)) {
    return 0;
  }
  for (int k = 0; k < a->nv && k < 3; k++) {
    if (a->jtype != urJNT_FREE && !restraint_ok(&a->rst[k], &b->rst[k], sig[k])) {
      return 0;
    }
  }
  return 1;
}

//---------------------------------- ellipsoids and pairs ------------------------------------------

/* geometry h (on the partner's body) is geometry g mirrored: centre, semi-axes, degree, and
   the shape (an ellipsoid's R D^2 R^T; a superellipsoid's axes each up to sign) */
static int geom_pair(const urGeom* g, const urGeom* h) {
  double v[3];
  mir3(v, g->pos);
  if (!eqv(v, h->pos, 3) || !eqv(g->size, h->size, 3) || !eq(g->degree, h->degree) ||
      !eq(g->rbound, h->rbound)) {
    return 0;
  }
  if (g->degree == 2) {
    double Q[9] = {0}, P[9] = {0}, MQ[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        for (int k = 0; k < 3; k++) {
          double s2 = g->size[k] * g->size[k];
          Q[3 * i + j] += g->gmat[3 * i + k] * s2 * g->gmat[3 * j + k];
          P[3 * i + j] += h->gmat[3 * i + k] * s2 * h->gmat[3 * j + k];
        }
      }
    }
    mir33(MQ, Q);
    return eqv(MQ, P, 9);
  }
  for (int k = 0; k < 3; k++) {
    double u[3] = {g->gmat[k], g->gmat[3 + k], g->gmat[6 + k]}, w[3];
    double c[3] = {h->gmat[k], h->gmat[3 + k], h->gmat[6 + k]};
    mir3(w, u);
    if (!eq(fabs(uru_dot3(w, c)), 1)) {
      return 0;
    }
  }
  return 1;
}

static int law_eq(const urLaw* a, const urLaw* b) {
  return a->type == b->type && eq(a->estar, b->estar) && eq(a->radius, b->radius) &&
         eq(a->sy, b->sy) && eq(a->nu, b->nu) && a->plastic == b->plastic &&
         eq(a->layer_h, b->layer_h) && eq(a->bone_k, b->bone_k) && eq(a->shell_k, b->shell_k) &&
         eq(a->crush_f, b->crush_f) && eq(a->crush_h, b->crush_h) &&
         curve_ok(&a->load, &b->load, 1) && curve_ok(&a->unload, &b->unload, 1) &&
         curve_ok(&a->stress, &b->stress, 1) && eq(a->thickness, b->thickness) &&
         eq(a->unload_r, b->unload_r) && eq(a->unload_p, b->unload_p) && eq(a->lock, b->lock) &&
         eq(a->backing_k, b->backing_k) && eq(a->backing_estar, b->backing_estar) &&
         eq(a->backing_r, b->backing_r) && curve_ok(&a->backing, &b->backing, 1) &&
         eq(a->damping, b->damping) && eq(a->chi, b->chi) && eq(a->mu, b->mu) &&
         eq(a->v_eps, b->v_eps);
}

//---------------------------------- membranes -----------------------------------------------------

/* the reference positions of triangle t's corners in the fabric's material axes (warp,
   weft), the first at the origin: the columns of the inverse of dminv */
static void tri_material(const urMembrane* mb, int t, double P[3][2]) {
  const double* D = mb->dminv + 4 * t; /* F = [d1 d2] [D0 D1; D2 D3] */
  double det = D[0] * D[3] - D[1] * D[2];
  P[0][0] = P[0][1] = 0;
  P[1][0] = D[3] / det;
  P[1][1] = -D[2] / det;
  P[2][0] = -D[1] / det;
  P[2][1] = D[0] / det;
}

/* ordering of node indices by their x (sort_ctx: the positions; qsort has no context, and a
   compile runs on one thread per model, but models may compile on several threads at once) */
static _Thread_local const double* sort_ctx;

static int by_x(const void* a, const void* b) {
  double x = sort_ctx[3 * *(const int*)a], y = sort_ctx[3 * *(const int*)b];
  return (x > y) - (x < y);
}

/* a triangle's nodes in ascending order (the key of its node set) */
static void tri_key(const int* v, int key[3]) {
  int a = v[0], b = v[1], c = v[2], t;
  if (a > b) t = a, a = b, b = t;
  if (b > c) t = b, b = c, c = t;
  if (a > b) t = a, a = b, b = t;
  key[0] = a;
  key[1] = b;
  key[2] = c;
}

static int by_key(const void* a, const void* b) {
  const int *x = a, *y = b;
  for (int k = 0; k < 3; k++) {
    if (x[k] != y[k]) {
      return (x[k] > y[k]) - (x[k] < y[k]);
    }
  }
  return 0;
}

/* membrane b2 is membrane b1 mirrored in its carrier's frame: a node map nu (xshape mirrored;
   the same mass, mount nodes to mount nodes), each triangle's partner on the mapped nodes with
   the same reference area and damping time and its corners' material positions mirrored in one
   of the fabric's axes (warp or weft: either keeps the yarn strains and turns the shear strain's
   sign, which the woven law answers with the shear stress's; a panel cut from the other side
   flips the other axis), the same fabric, gas and contact data */
static int membrane_pair(const urMembrane* b1, const urMembrane* b2, char* why, size_t n,
                         const char* name) {
  const urMemSpec *s1 = &b1->spec, *s2 = &b2->spec;
  if (b1->nn != b2->nn || b1->nt != b2->nt || s1->e1t != s2->e1t || s1->e2t != s2->e2t ||
      s1->nu12 != s2->nu12 || s1->g0t != s2->g0t || s1->gtt != s2->gtt || s1->lock != s2->lock ||
      s1->re != s2->re || s1->p0 != s2->p0 || s1->patm != s2->patm || s1->gamma != s2->gamma ||
      s1->temp != s2->temp || s1->vent_area != s2->vent_area || s1->vent_cd != s2->vent_cd ||
      s1->leak != s2->leak || s1->kc_alpha != s2->kc_alpha || s1->kc_dt != s2->kc_dt ||
      s1->zeta_c != s2->zeta_c || s1->mu != s2->mu || s1->v_eps != s2->v_eps ||
      s1->damp != s2->damp || s1->rhot != s2->rhot || s1->inflate != s2->inflate ||
      s1->dt_factor != s2->dt_factor || s1->mscale != s2->mscale) {
    return fail(why, n,
                "airbag %s's fabric, gas, contact or numerics differ from its mirror partner's",
                name);
  }
  int nn = b1->nn, nt = b1->nt, ok = 1;
  int* nu = malloc(sizeof(int) * (size_t)(2 * nn + 4 * nt + 1));
  if (!nu) {
    return fail(why, n, "out of memory");
  }
  int *byx = nu + nn, *tk = byx + nn; /* b2's nodes by x; its triangles' sorted nodes, index */

  // nodes: each one's mirror image among b2's, found by x (sorted)
  for (int j = 0; j < nn; j++) {
    byx[j] = j;
  }
  sort_ctx = b2->xshape;
  qsort(byx, (size_t)nn, sizeof(int), by_x);
  for (int i = 0; i < nn && ok; i++) {
    double v[3];
    mir3(v, b1->xshape + 3 * i);
    double lo = v[0] - 2 * TOL * fmax(1.0, fabs(v[0]));
    int a = 0, z = nn;
    while (a < z) { /* the first of b2's nodes by x at or beyond lo */
      int h = (a + z) / 2;
      if (b2->xshape[3 * byx[h]] < lo) {
        a = h + 1;
      } else {
        z = h;
      }
    }
    nu[i] = -1;
    for (int q = a; q < nn && nu[i] < 0 && b2->xshape[3 * byx[q]] <= v[0] + (v[0] - lo); q++) {
      if (eqv(v, b2->xshape + 3 * byx[q], 3)) {
        nu[i] = byx[q];
      }
    }
    ok = nu[i] >= 0 && eq(b1->mass[i], b2->mass[nu[i]]) &&
         (b1->invm[i] == 0) == (b2->invm[nu[i]] == 0);
  }
  if (!ok) {
    free(nu);
    return fail(why, n, "airbag %s's mesh nodes have no mirrored partners", name);
  }

  // triangles: each one's partner on the mapped nodes (b2's sorted by their node triples)
  for (int s = 0; s < nt; s++) {
    tri_key(b2->tri + 3 * s, tk + 4 * s);
    tk[4 * s + 3] = s;
  }
  qsort(tk, (size_t)nt, 4 * sizeof(int), by_key);
  for (int t = 0; t < nt && ok; t++) {
    const int* v = b1->tri + 3 * t;
    int m3[3] = {nu[v[0]], nu[v[1]], nu[v[2]]}, key[4], u = -1, c[3] = {-1, -1, -1};
    tri_key(m3, key);
    const int* hit = bsearch(key, tk, (size_t)nt, 4 * sizeof(int), by_key);
    if (hit) {
      u = hit[3];
      const int* w = b2->tri + 3 * u;
      for (int k = 0; k < 3; k++) {
        c[k] = m3[k] == w[0] ? 0 : m3[k] == w[1] ? 1 : 2;
      }
    }
    if (u < 0 || !eq(b1->area0[t], b2->area0[u]) || !eq(b1->beta[t], b2->beta[u])) {
      ok = 0;
      break;
    }
    double P[3][2], R[3][2];
    tri_material(b1, t, P);
    tri_material(b2, u, R);
    int good[2];
    for (int f = 0; f < 2; f++) {
      good[f] = 1;
      for (int k = 1; k < 3; k++) {
        for (int q = 0; q < 2; q++) {
          double want = (q == f ? -1 : 1) * (P[k][q] - P[0][q]);
          good[f] &= eq(R[c[k]][q] - R[c[0]][q], want);
        }
      }
    }
    ok = good[0] || good[1];
  }
  free(nu);
  if (!ok) {
    return fail(why, n, "airbag %s's triangles or fabric axes have no mirrored partners", name);
  }
  return 1;
}

/* bag k2 is bag k1 mirrored (gm: the ellipsoids' map) */
static int bag_pair(const urModel* m, int k1, int k2, const int* gm, char* why, size_t n) {
  const urAirbag *a = m->bag + k1, *b = m->bag + k2;
  if (a->type != b->type || !eq(a->gas.v0, b->gas.v0) || !eq(a->gas.p0, b->gas.p0) ||
      !eq(a->gas.patm, b->gas.patm) || !eq(a->gas.gamma, b->gas.gamma) || !eq(a->kappa, b->kappa) ||
      !eq(a->thickness, b->thickness) || !eq(a->fabric_k, b->fabric_k) ||
      !eq(a->fabric_c, b->fabric_c) || !eq(a->mu, b->mu) || !eq(a->v_eps, b->v_eps) ||
      a->ntarget != b->ntarget || a->nsupport != b->nsupport || a->liverule != b->liverule) {
    return fail(why, n, "airbag %s differs from its mirror partner %s", a->name, b->name);
  }
  for (int i = 0; i < a->ntarget; i++) {
    int j = 0;
    while (j < b->ntarget && !(b->target[j] == gm[a->target[i]] && eq(b->tk[j], a->tk[i]))) {
      j++;
    }
    if (j == b->ntarget) {
      return fail(why, n, "airbag %s's targets are not mirrored", a->name);
    }
  }
  for (int i = 0; i < a->nsupport; i++) {
    int j = 0;
    while (j < b->nsupport && b->support[j] != gm[a->support[i]]) {
      j++;
    }
    if (j == b->nsupport) {
      return fail(why, n, "airbag %s's supports are not mirrored", a->name);
    }
  }
  if (a->type == urBAG_MEMBRANE) {
    if (!a->mem || !b->mem) {
      return fail(why, n, "airbag %s has no mesh", a->name);
    }
    return membrane_pair(a->mem, b->mem, why, n, a->name);
  }
  return 1;
}

//---------------------------------- sensors -------------------------------------------------------

/* an injury sensor reads what the mirror keeps: on a body that is its own partner, at a point of
   the plane, in a frame the mirror keeps; a plate's joint moves in the plane (sigma 1) */
static int sensor_ok(const urModel* m, int id, const int* bm, int sig1) {
  if (id < 0) {
    return 1;
  }
  const urSensor* s = m->sensor + id;
  if (s->type == urSENS_JOINTPOS || s->type == urSENS_JOINTVEL) {
    return bm[s->obj] == s->obj && sig1;
  }
  if (s->type != urSENS_ACCEL && s->type != urSENS_JOINTLOAD && s->type != urSENS_BODYPOS) {
    return 0;
  }
  double R[9], MR[9];
  uru_quat2mat(R, s->quat);
  mir33(MR, R);
  return bm[s->obj] == s->obj && eq(s->pos[1], 0) && (s->type != urSENS_JOINTLOAD || eqv(MR, R, 9));
}

/* a plate's joint coordinate (sensor s, jointpos or jointvel) keeps its sign in the mirror
   (sig: the joint signs of its body); a free joint's coordinates (translations, a quaternion or
   angular velocity) and a ball's quaternion have no sign per axis here: refused */
static int plate_keeps(const urModel* m, const urSensor* s, const int* sig) {
  urJointType t = m->body[s->obj].jtype;
  if (t == urJNT_FREE || t == urJNT_FIXED || s->dof < 0 || s->dof >= 3 ||
      (t == urJNT_SPHERICAL && s->type == urSENS_JOINTPOS)) {
    return 0;
  }
  return sig[3 * s->obj + s->dof] > 0;
}

//---------------------------------- the model -----------------------------------------------------

int ur_model_mirror(const urModel* m, char* why, size_t n) {
  if (why && n) {
    why[0] = 0;
  }
  if (!m->compiled) {
    return fail(why, n, "the model is not compiled");
  }
  if (!eq(m->opt.gravity[1], 0)) {
    return fail(why, n, "gravity has a component across the plane y = 0");
  }
  int nb = m->nbody, ng = m->ngeom, nbag = m->nbag, np = m->npair;
  int* bm = malloc(sizeof(int) * (size_t)(4 * nb + ng + nbag + np + 1));
  if (!bm) {
    return fail(why, n, "out of memory");
  }
  int *sig = bm + nb, *gm = sig + 3 * nb, *km = gm + ng, *pm = km + nbag; /* sig: 3 per body */
  int ok = 1;
  for (int i = 0; i < nb; i++) {
    bm[i] = -1;
  }

  // bodies, parents first: each one's partner among the children of its parent's partner
  for (int i = 0; i < nb && ok; i++) {
    const urBody* a = m->body + i;
    if (a->parent >= i) {
      ok = fail(why, n, "body %s comes before its parent", a->name);
      break;
    }
    if (bm[i] >= 0) {
      continue; /* paired as an earlier body's partner */
    }
    int pp = a->parent < 0 ? -1 : bm[a->parent];
    for (int j = i; j < nb && bm[i] < 0; j++) {
      int s3[3];
      if ((j == i || bm[j] < 0) && body_pair(a, m->body + j, pp, s3)) {
        int s2[3];
        /* the pairing goes both ways (the signs of a joint on the plane: its own) */
        if (j != i && !body_pair(m->body + j, a, a->parent, s2)) {
          continue;
        }
        bm[i] = j;
        bm[j] = i;
        memcpy(sig + 3 * i, s3, sizeof s3);
        memcpy(sig + 3 * j, s3, sizeof s3);
      }
    }
    if (bm[i] < 0) {
      ok = fail(why, n, "body %s has no mirror image (itself on the plane y = 0, or a partner)",
                a->name);
    }
  }

  // ellipsoids: each one's partner on the partner body
  for (int g = 0; g < ng && ok; g++) {
    gm[g] = -1;
  }
  for (int g = 0; g < ng && ok; g++) {
    if (gm[g] >= 0) {
      continue;
    }
    const urGeom* a = m->geom + g;
    for (int h = g; h < ng && gm[g] < 0; h++) {
      if ((h == g || gm[h] < 0) && m->geom[h].body == bm[a->body] && geom_pair(a, m->geom + h)) {
        gm[g] = h;
        gm[h] = g;
      }
    }
    if (gm[g] < 0) {
      ok = fail(why, n, "ellipsoid %s has no mirror image", a->name);
    }
  }

  /* contact pairs and airbags pair off as the ellipsoids do, one partner each (a second pair
     or bag on one side only has none: it would double a force there) */
  for (int p = 0; p < np; p++) {
    pm[p] = -1;
  }
  for (int k = 0; k < nbag; k++) {
    km[k] = -1;
  }

  // contact pairs: the partners' pair under the same law
  for (int p = 0; p < np && ok; p++) {
    if (pm[p] >= 0) {
      continue;
    }
    const urPair* a = m->pair + p;
    int g1 = gm[a->geom1], g2 = a->geom2 < 0 ? -1 : gm[a->geom2];
    for (int q = p; q < np && pm[p] < 0; q++) {
      const urPair* b = m->pair + q;
      if ((q == p || pm[q] < 0) && b->geom1 == g1 && b->geom2 == g2 && law_eq(&a->law, &b->law)) {
        pm[p] = q;
        pm[q] = p;
      }
    }
    if (pm[p] < 0) {
      ok = fail(why, n, "contact pair %s has no mirror image", a->name);
    }
  }

  // airbags: each one's partner on the partner ellipsoid, both ways (the first one's reason)
  for (int k = 0; k < nbag && ok; k++) {
    if (km[k] >= 0) {
      continue;
    }
    int first = -1;
    for (int l = k; l < nbag && km[k] < 0; l++) {
      if ((l == k || km[l] < 0) && m->bag[l].geom == gm[m->bag[k].geom]) {
        first = first < 0 ? l : first;
        if (bag_pair(m, k, l, gm, NULL, 0) && (l == k || bag_pair(m, l, k, gm, NULL, 0))) {
          km[k] = l;
          km[l] = k;
        }
      }
    }
    if (km[k] < 0) {
      ok = first < 0 ? fail(why, n, "airbag %s has no mirror image", m->bag[k].name)
                     : bag_pair(m, k, first, gm, why, n) && bag_pair(m, first, k, gm, why, n);
    }
  }

  // the roles: the drone and the head on the plane, the injury sensors reading what it keeps
  const urRoles* r = &m->roles;
  if (ok && r->drone >= 0 && bm[r->drone] != r->drone) {
    ok = fail(why, n, "the drone's root body is not on the plane y = 0");
  }
  if (ok && r->head >= 0 && gm[r->head] != r->head) {
    ok = fail(why, n, "the head ellipsoid is not on the plane y = 0");
  }
  int plate[2] = {r->chest, r->abdomen};
  for (int k = 0; k < 2 && ok; k++) {
    int id = plate[k];
    int s1 = id < 0 || plate_keeps(m, m->sensor + id, sig);
    if (!sensor_ok(m, id, bm, s1)) {
      ok = fail(why, n, "the %s sensor does not read the same in the mirror image",
                k ? "abdomen" : "chest");
    }
  }
  int sens[3] = {r->head_acc, r->neck, r->head_pos};
  static const char* sname[3] = {"head acceleration", "neck load", "head position"};
  for (int k = 0; k < 3 && ok; k++) {
    if (!sensor_ok(m, sens[k], bm, 1)) {
      ok = fail(why, n, "the %s sensor is not on the plane y = 0", sname[k]);
    }
  }
  free(bm);
  return ok;
}
