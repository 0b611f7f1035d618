/* engine_membrane.c: the membrane airbags in the multibody engine. ur_model_compile checks each
 * membrane bag's declaration and builds its mesh (the run state's size and sub-steps follow from
 * it); ur_model_inflate inflates it once, when a run first needs it (constant model data shared by
 * threads from then on; through the inflated-bag cache of the options, opt.memcache, when there is
 * one) and turns the bag's ellipsoid into a bound of the inflated bag (the jump to first contact
 * and the end-of-run proofs use it). Each step: the loads stage places the mount patch on the
 * carrier (fixed joint), computes fabric, gas and penalty contact forces of the nodes against the
 * targets (the person) and supports (the carrier's own bodies) and applies the reactions to their
 * bodies and the mount forces to the carrier; the accepted step then moves the nodes (symplectic
 * Euler), in sub-steps when the fabric's stable step is smaller than the multibody step (fabric and
 * gas forces recomputed each sub-step, contact forces held over the step). A penalty beyond the
 * explicit bound (kc_alpha > 1) is made linearly implicit along each node's contact normal
 * (contact_implicit). Until it goes live (a target near, or its carrier jolted: goes_live), the
 * bag rides rigidly in its inflated state (no integration). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "engine_internal.h"
#include "../membrane/membrane_internal.h"
#include "engine_membrane_cull.h"

//---------------------------------- compile -------------------------------------------------------

/* the bag's ellipsoid as a bound of the inflated bag: centre and axes of its box, scaled so that
   every node lies inside */
static void bound_geom(urModel* m, urAirbag* b) {
  const urMembrane* mb = b->mem;
  urGeom* g = m->geom + b->geom;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < mb->nn; i++) {
    for (int k = 0; k < 3; k++) {
      lo[k] = fmin(lo[k], mb->x0[3 * i + k]);
      hi[k] = fmax(hi[k], mb->x0[3 * i + k]);
    }
  }
  memcpy(b->nbox, lo, sizeof(lo));
  memcpy(b->nbox + 3, hi, sizeof(hi));
  double c[3], h[3], s = 0;
  for (int k = 0; k < 3; k++) {
    c[k] = 0.5 * (lo[k] + hi[k]);
    h[k] = fmax(0.5 * (hi[k] - lo[k]), 1e-3);
  }
  for (int i = 0; i < mb->nn; i++) {
    double q = 0;
    for (int k = 0; k < 3; k++) {
      double u = (mb->x0[3 * i + k] - c[k]) / h[k];
      q += u * u;
    }
    s = fmax(s, sqrt(q));
  }
  static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, q1[4] = {1, 0, 0, 0};
  memcpy(g->pos, c, sizeof(c));
  memcpy(g->quat, q1, sizeof(q1));
  memcpy(g->gmat, I, sizeof(I));
  for (int k = 0; k < 3; k++) {
    g->size[k] = 1.02 * s * h[k];
  }
  g->degree = 2;
  g->rbound = fmax(g->size[0], fmax(g->size[1], g->size[2]));
}


int urm_model_compile(urModel* m) {
  m->nmemd = 0;
  m->nraw = 0;
  for (int i = 0; i < m->nbag; i++) {
    urAirbag* b = m->bag + i;
    if (b->type != urBAG_MEMBRANE) {
      continue;
    }
    char err[100];
    if (!b->mem) {
      // mass scaling targets this model's step (a bag built for another step is another bag)
      b->mspec.hstep = b->mspec.mscale > 0 ? m->opt.dt : 0;
      b->mem = ur_mem_build(&b->mspec, err, sizeof(err));
      b->inflated = 0;
      if (!b->mem) {
        snprintf(m->err, sizeof(m->err), "airbag '%s': %s", b->name, err);
        return -1;
      }
    }
    b->madr = m->nmemd;
    m->nmemd += (int)ur_mem_state_size(b->mem);
    b->nsub = (int)ceil(m->opt.dt / b->mem->dt_stable - 1e-9);
    if (b->nsub < 1) {
      b->nsub = 1;
    }
    if (b->inflated) {
      bound_geom(m, b);
    } else {
      m->nraw++;
    }
  }
  return 0;
}


int ur_model_inflate_bag(urModel* m, int i, char* err, size_t n) {
  if (!m || !m->compiled || i < 0 || i >= m->nbag) {
    snprintf(err, n, "ur_model_inflate: no compiled model or no airbag %d", i);
    return -1;
  }
  urAirbag* b = m->bag + i;
  if (b->type != urBAG_MEMBRANE || b->inflated) {
    return 0;
  }
  if (!b->mem && !(b->mem = ur_mem_build(&b->mspec, err, n))) {
    return -1; /* a failed try that found no memory to build it again */
  }
  char e[100];
  b->mem->stop = m->opt.stop;
  urMembrane* mb = ur_mem_cache_inflate(m->opt.memcache, b->mem, e, sizeof(e));
  b->mem = mb; /* the built bag is consumed: inflated, or replaced by the cache's copy */
  if (!mb) {
    /* built afresh, so that the model stays whole (compiled, runs refused) for another try */
    b->mem = ur_mem_build(&b->mspec, err, n); /* NULL (no memory): the next try builds it */
    snprintf(err, n, "airbag '%s': %s", b->name, b->mem ? e : "out of memory");
    return -1;
  }
  b->inflated = 1;
  m->nraw--;
  bound_geom(m, b);
  return 0;
}


void ur_model_raw_text(const urModel* m, char* msg, size_t n) {
  for (int i = 0; i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    if (b->type == urBAG_MEMBRANE && !b->inflated) {
      snprintf(msg, n,
               "airbag '%s' is not inflated: the model's owner calls ur_model_inflate before "
               "it runs",
               b->name);
      return;
    }
  }
  snprintf(msg, n, "every airbag is inflated");
}


int ur_model_inflate(urModel* m, char* err, size_t n) {
  for (int i = 0; m && i < m->nbag; i++) {
    if (ur_model_inflate_bag(m, i, err, n)) {
      return -1;
    }
  }
  if (n) {
    err[0] = 0;
  }
  return 0;
}


void urm_model_free(urModel* m) {
  for (int i = 0; i < m->nbag; i++) {
    ur_mem_free(m->bag[i].mem);
    m->bag[i].mem = NULL;
  }
}

//---------------------------------- loads ---------------------------------------------------------

/* world pose and velocity of body b: rotation, origin, origin velocity, angular velocity */
static void bodymotion(const urData* d, int b, double R[9], double c[3], double vc[3],
                       double w[3]) {
  memcpy(R, d->xmat + 9 * b, 9 * sizeof(double));
  memcpy(c, d->xpos + 3 * b, 3 * sizeof(double));
  const double* cv = d->cvel + 6 * b;
  uru_mulmat3vec(w, R, cv);
  uru_mulmat3vec(vc, R, cv + 3);
}


/* the squared distance from point p to the box bx (lo: bx[0..2], hi: bx[3..5]; 0 inside), summed
   in the order of urm_dot: no larger than r . r for r = x - p of any point x in the box (each
   rounding is monotone), so a box at q >= rg^2 holds no point that urm_dot(r, r) < rg^2 finds
   within */
static double box_gap2(const double* bx, const double p[3]) {
  double q = 0;
  for (int k = 0; k < 3; k++) {
    // the larger of the gaps below and above (at most one positive: lo <= hi), or 0: the
    // distance along k without a branch (maxsd)
    double a = bx[k] - p[k], b = p[k] - bx[3 + k], u = a > b ? a : b;
    u = u > 0 ? u : 0;
    q += u * u;
  }
  return q;
}


/* is the point at r from the shape's centre outside its box gh (urm_shape_box) */
static int out_box(const double r[3], const double gh[3]) {
  return fabs(r[0]) > gh[0] || fabs(r[1]) > gh[1] || fabs(r[2]) > gh[2];
}


/* the stiff contact's buffers after the culling boxes (ur_mem_stiff_offset): each free node's
   normal stiffness (5 a node, contact_implicit's kn), its position correction along the normal
   (3 a node, applied by urm_bags_advance), the solve's work (6 a node), the edges' couplings */
static double* node_bufs(const urMembrane* mb, double* st) {
  return st + ur_mem_stiff_offset(mb);
}


/* the contact pressure on sub-triangle corners q (of a triangle with nodes n3; corners 0-2 the
   nodes, 3-5 the midpoints of edges 01, 12, 20) of area a: the depths dq, normals nq, positions
   xq and velocities vq of the six points; forces added to f and fc (a midpoint's to its edge's
   nodes, half each), reactions on the body, the penalty energy to *ep, each point's stiffness
   (the penalty per area times its area share, a midpoint's half to each end) and its normal
   lumped onto the nodes in kn when kn is not NULL (contact_implicit); the normal force
   returned */
static double contact_sub(const urModel* m, urData* d, const urMembrane* mb, const urMemSpec* s,
                          int body, const double o[3], const double vo[3], const double w[3],
                          const int* n3, const int q[3], const double dq[6], double nq[6][3],
                          double xq[6][3], double vq[6][3], double a, double* f, double* fc,
                          double* kn, const int* e3, double* ke, int* nel, double* ep) {
  static const int edge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  double dd[3] = {dq[q[0]], dq[q[1]], dq[q[2]]}, I[3], A[3], E, fsum = 0;
  urm_contact_clip(dd, I, A, &E);
  double dk = fmax(m->opt.dt, s->kc_dt), ka = s->kc_alpha * s->rhot / (dk * dk);
  *ep += 0.5 * ka * E * a;
  for (int u = 0; u < 3; u++) {
    if (!(A[u] > 0)) {
      continue;
    }
    int p = q[u];
    double r[3], wr[3], vr[3], fi[3];
    urm_sub(r, xq[p], o);
    urm_cross(wr, w, r);
    for (int k = 0; k < 3; k++) {
      vr[k] = vq[p][k] - vo[k] - wr[k];
    }
    // the friction capped on the point's whole share a / 3 of the quarter (the stiffness's
    // shares: the caps of a node add up to its mass), penetrated or not
    double fn = urm_contact_force(s, m->opt.dt, nq[p], vr, I[u] * a, A[u] * a, a / 3, fi);
    if (!(fn > 0)) {
      continue;
    }
    fsum += fn;
    int nodes[2] = {p < 3 ? n3[p] : n3[edge[p - 3][0]], p < 3 ? -1 : n3[edge[p - 3][1]]};
    double share = p < 3 ? 1 : 0.5;
    double kp = share * ka * A[u] * a; /* the point's stiffness, lumped on the node */
    for (int j = 0; j < 2 && nodes[j] >= 0; j++) {
      for (int k = 0; k < 3; k++) {
        f[3 * nodes[j] + k] += share * fi[k];
        fc[3 * nodes[j] + k] += share * fi[k];
      }
      if (kn) {
        double* kj = kn + 5 * nodes[j];
        kj[0] += share * kp; /* the diagonal: a midpoint moves by half a node's motion */
        for (int k = 0; k < 3; k++) {
          kj[1 + k] += kp * nq[p][k];
        }
        kj[4] += kp; /* the row sum */
      }
    }
    if (kn && p >= 3) { /* the coupling of the edge's two nodes through its midpoint */
      double* ek = ke + 3 * (size_t)e3[p - 3];
      if (ek[0] == 0) {
        ke[3 * (size_t)mb->ne + (*nel)++] = e3[p - 3];
        ek[1] = nodes[0];
        ek[2] = nodes[1];
      }
      ek[0] += 0.5 * kp;
    }
    double rf[3] = {-fi[0], -fi[1], -fi[2]};
    ur_apply_force(m, d, body, rf, xq[p]);
  }
  return fsum;
}


/* the stiff penalty (kc_alpha > 1, beyond the explicit bound), linearly implicit along the
   contact normal per node: each node in contact with the body has the stiffness of its own
   normal motion Kd (kn[0]: the penalty per area times its corner points' penetrated areas and a
   quarter of its edge midpoints': a midpoint moves by half a node's motion, and half its force
   goes to the node) along the mean normal n (kn[1..3], weighted by the row sums; made a unit
   vector in place here), the damping C = Kr 2 zeta_c sqrt(rhot / k_a) on the row sum Kr (kn[4]:
   the lumped stiffness), and each
   edge in contact couples its two nodes by a quarter of its midpoint's stiffness (ke: the
   consistent tangent of the penalty's force on the nodes' normal motions). The explicit pass
   gave each node the force F0 at the current depth. Along n the contact springs are integrated
   by the implicit midpoint rule: the springs' force over the step is their value at the middle
   of the step's normal displacements D (relative to the body's surface), F0 - (Kd D_i + sum K_ij
   D_j) / 2, and each node moves by the mean of its start and end velocities, D = h (vn + vn+) / 2
   = h vn + b Fo / m + h^2 Fc / 2m (Fc = F0 + the increment, the contact's force; Fo the node's
   other forces held over the step, moved by the fabric's symplectic sub-steps: b = h^2 (N + 1) /
   2N for N of them, h^2 for one). The rule conserves a linear spring's energy and is stable for
   any stiffness; the damping stays backward Euler (C times the change of the normal velocity).
   The coupled increments are solved by Jacobi sweeps (diagonally dominant: a node's own
   stiffness is at least its couplings'), to 1e-12 of the largest or 100 sweeps, in the free
   nodes' order (the same bits in lanes). The increments go to f and fc, their reactions to the
   body; the position correction that turns the sub-steps' h vn+ + b Fc / m into h^2 Fc / 2m,
   -(b - h^2 / 2) Fc / m along n, is added to cor (3 a node) for urm_bags_advance; wk holds 6 nn
   of work. The body's side stays explicit (its reaction this step), so the stiffness over all
   nodes must stay within the step for the body's mass. A node's normal contact force stays
   >= 0. The normal sum returned. */
static double contact_implicit(const urModel* m, urData* d, const urMembrane* mb,
                               const urMemSpec* s, int body, const double o[3], const double vo[3],
                               const double w[3], double* st, double* kn, double* cor, double* wk,
                               const double* ke, int nel) {
  int nn = mb->nn;
  double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *fc = st + 9 * nn;
  double h = m->opt.dt, dk = fmax(h, s->kc_dt), ka = s->kc_alpha * s->rhot / (dk * dk);
  double cr = 2 * s->zeta_c * sqrt(s->rhot / ka), fsum = 0;
  // the step's displacement under a force F held over it in N sub-steps: h v + bh2 F / m
  int nsub = (int)ceil(h / mb->dt_stable - 1e-9);
  nsub = nsub < 1 ? 1 : nsub;
  double bh2 = h * h * (nsub + 1) / (2.0 * nsub), hh2 = 0.5 * h * h;
  // per node in wk (6 a node): the displacement without the increment D0, the increment df, the
  // coupling sum S; nodes out of contact have D0 = 0 and df = 0 (S reads their D as 0); and what
  // the sweeps read unchanged: the damping's term C h fo / m, the denominator and the force's
  // floor -max(fn, 0)
  double *D0 = wk, *df = wk + nn, *S = wk + 2 * nn;
  double *cd = wk + 3 * nn, *den = wk + 4 * nn, *flo = wk + 5 * nn;
  // the mean normal made a unit vector here, once (kn[1..3]); a node without stiffness or normal
  // gets kn[0] = 0, and the sweeps and the update below skip it
  for (int j = 0; j < mb->nfree; j++) {
    int i = mb->free[j];
    D0[i] = df[i] = 0;
    double* ki = kn + 5 * i;
    double nl = sqrt(ki[1] * ki[1] + ki[2] * ki[2] + ki[3] * ki[3]);
    if (!(ki[0] > 0) || !(nl > 0)) {
      ki[0] = 0;
      continue;
    }
    ki[1] /= nl, ki[2] /= nl, ki[3] /= nl;
    const double* n = ki + 1;
    double r[3], wr[3], vb[3];
    urm_sub(r, x + 3 * i, o);
    urm_cross(wr, w, r);
    for (int k = 0; k < 3; k++) {
      vb[k] = vo[k] + wr[k];
    }
    double mi = mb->mass[i], K = ki[0], C = ki[4] * cr;
    double vn = urm_dot(v + 3 * i, n) - urm_dot(vb, n), fo = urm_dot(f + 3 * i, n);
    double fn = urm_dot(fc + 3 * i, n);
    D0[i] = h * vn + (bh2 * (fo - fn) + hh2 * fn) / mi;
    cd[i] = C * h * fo / mi;
    den[i] = 1 + 0.5 * K * hh2 / mi + C * h / mi;
    flo[i] = -fmax(fn, 0);
  }
  // Jacobi sweeps on df_i (1 + Kd hh2 / 2m + C h / m) = -(Kd D0_i + S_i) / 2 - C h fo / m, with
  // S_i = sum over the edges K_ij D_j, D_j = D0_j + hh2 df_j / m_j; a node's force kept >= 0
  for (int it = 0; it < 100; it++) {
    for (int j = 0; j < mb->nfree; j++) {
      S[mb->free[j]] = 0;
    }
    for (int e = 0; e < nel; e++) {
      const double* ek = ke + 3 * (size_t)ke[3 * (size_t)mb->ne + e];
      int a = (int)ek[1], b = (int)ek[2];
      S[a] += ek[0] * (D0[b] + hh2 * df[b] / mb->mass[b]);
      S[b] += ek[0] * (D0[a] + hh2 * df[a] / mb->mass[a]);
    }
    double dmax = 0, fmx = 0;
    for (int j = 0; j < mb->nfree; j++) {
      int i = mb->free[j];
      double K = kn[5 * i];
      if (!(K > 0)) {
        continue;
      }
      double nd = fmax(-(0.5 * (K * D0[i] + S[i]) + cd[i]) / den[i], flo[i]);
      dmax = fmax(dmax, fabs(nd - df[i]));
      fmx = fmax(fmx, fabs(nd));
      df[i] = nd;
    }
    if (dmax <= 1e-12 * fmx) {
      break;
    }
  }
  for (int j = 0; j < mb->nfree; j++) {
    int i = mb->free[j];
    const double *ki = kn + 5 * i, *n = ki + 1;
    if (!(ki[0] > 0)) {
      continue;
    }
    double mi = mb->mass[i];
    double fn = urm_dot(fc + 3 * i, n), dc = -(bh2 - hh2) * (fn + df[i]) / mi;
    double fi[3] = {df[i] * n[0], df[i] * n[1], df[i] * n[2]};
    for (int k = 0; k < 3; k++) {
      f[3 * i + k] += fi[k];
      fc[3 * i + k] += fi[k];
      cor[3 * i + k] += dc * n[k];
    }
    double rf[3] = {-fi[0], -fi[1], -fi[2]};
    ur_apply_force(m, d, body, rf, x + 3 * i);
    fsum += df[i];
  }
  return fsum;
}


/* face contact of the bag's triangles (those of free nodes) with ellipsoid g: each triangle is
   split at its edges' midpoints into four, the depth is evaluated at the nodes and midpoints and
   interpolated linearly over each quarter, and the penalty pressure acts on the penetrated part
   of each quarter (membrane_contact.c); the midpoints keep a triangle from sinking into a curved
   body by its sagitta (materials-membrane C.4's midpoint checks) to a quarter of it. Forces
   added to f and fc, reactions on g's body; the normal force sum and deepest penetration
   returned. Only when g's bounding sphere reaches the free nodes' box (lo, hi): no point of the
   bag can touch g otherwise. Each node's and each edge midpoint's depth is evaluated once (the
   edge's two triangles share it: the same point, 0.5 (a + b) = 0.5 (b + a) bit for bit), and
   only the triangles whose bounding sphere (tb: centre and radius of each triangle, from
   urm_bag_loads, with a margin) reaches g's are tried: of the others no point is inside g's
   sphere (the same triangles tried, the same bits). Both lists are culled first by boxes of
   urMEM_CBLK free nodes and of urMEM_CBLK free triangles' spheres (nbx, tbx, from urm_bag_loads):
   a box out of g's sphere holds no node or sphere that the tests above would take. And by g's
   own box (urm_shape_box): a point outside it is outside g (its depth -INFINITY without the gap's
   evaluation), a triangle whose sphere misses it has no point inside g, so it adds no force and
   no depth that another triangle reads (left out of the list, the same bits). */
static double contact_geom(const urModel* m, urData* d, const urAirbag* b, double* st, int g,
                           double kc, const double lo[3], const double hi[3],
                           const urmCullGroups* sb, double* depth) {
  static const int sub[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  const urMembrane* mb = b->mem;
  const urMemSpec* s = &mb->spec;
  urMemSpec sl;
  if (kc != s->kc_alpha) { /* a target's layer (ur_bag_penalty) */
    sl = mb->spec;
    sl.kc_alpha = kc;
    s = &sl;
  }
  int nn = mb->nn, nt = mb->nt;
  double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *fc = st + 9 * nn, *sc = st + 18 * nn;
  const double* gc = d->gxpos + 3 * g;
  double rg = m->geom[g].rbound, q = 0;
  *depth = -1;
  for (int k = 0; k < 3; k++) {
    double u = gc[k] < lo[k] ? lo[k] - gc[k] : gc[k] > hi[k] ? gc[k] - hi[k] : 0;
    q += u * u;
  }
  if (q >= rg * rg) {
    return 0;
  }
  urEllipsoid e;
  ur_geom_ellipsoid(m, d, g, &e);
  double gh[3];
  urm_shape_box(&e, gh);
  int body = m->geom[g].body;
  double R[9], o[3], vo[3], w[3], fsum = 0, ep = 0;
  bodymotion(d, body, R, o, vo, w);
  // in the force pass's scratch (free until the next pass; 36 ntb >= 4 nn + 4 ne for the ring
  // meshes of 2 rings or more, membrane_mesh.c): each free node's depth and normal (4 doubles a
  // node: -INFINITY outside g's sphere or the shape, not evaluated), each edge midpoint's (NAN:
  // not yet); in the contact scratch after the warm starts: the triangles' spheres (4 nt) and
  // the list of those tried (nt)
  double *gn = sc + urMEMS_N, *ge = gn + 4 * (size_t)nn;
  double *tb = sc + urMEMS_N + 44 * (size_t)mb->ntb, *tl = tb + 4 * (size_t)nt;
  // the boxes of urMEM_CBLK free nodes and of urMEM_CBLK free triangles (after the triangle list)
  const double *nbx = tl + nt, *tbx = nbx + 7 * (size_t)((nn + urMEM_CBLK - 1) / urMEM_CBLK);
  // beyond the explicit bound (kc_alpha > 1): each free node's lumped normal stiffness (4 nn,
  // after the boxes), for contact_implicit
  double* kn = s->kc_alpha > 1 ? node_bufs(mb, st) : NULL;
  // after kn (5 nn) the position corrections (3 nn), the implicit solve's work (6 nn), each
  // edge's coupling (3 ne: stiffness, its two nodes) and the list of the edges coupled (ne)
  double* ke = kn ? kn + 14 * (size_t)nn : NULL;
  int nel = 0;
  for (int j = 0; kn && j < mb->nfree; j++) {
    int i = mb->free[j];
    kn[5 * i] = kn[5 * i + 1] = kn[5 * i + 2] = kn[5 * i + 3] = kn[5 * i + 4] = 0;
  }
  if (ke) {
    memset(ke, 0, 3 * (size_t)mb->ne * sizeof(double));
  }
  // each free node's depth is -INFINITY on entry (urm_bag_loads, and each call puts back those it
  // set: the free nodes jlo..jhi - 1 of the boxes within reach and the nodes of the triangles
  // tried), so only the nodes of the boxes within reach are evaluated or written
  int gw = sb->grp * urMEM_CBLK; /* free nodes or triangles per group of boxes */
  int jlo = mb->nfree, jhi = 0;
  for (int s0 = 0; s0 < sb->nn; s0++) {
    int g0 = s0 * gw, g1 = g0 + gw < mb->nfree ? g0 + gw : mb->nfree;
    if (box_gap2(sb->n + 7 * s0, gc) >= rg * rg) { /* no box of the group within */
      continue;
    }
    for (int j0 = g0; j0 < g1; j0 += urMEM_CBLK) {
      int j1 = j0 + urMEM_CBLK < g1 ? j0 + urMEM_CBLK : g1;
      if (box_gap2(nbx + 7 * (j0 / urMEM_CBLK), gc) >= rg * rg) {
        continue;
      }
      jlo = jlo < j0 ? jlo : j0;
      jhi = j1;
      for (int j = j0; j < j1; j++) {
        int i = mb->free[j];
        double r[3];
        urm_sub(r, x + 3 * i, gc);
        if (urm_dot(r, r) < rg * rg) {
          if (!out_box(r, gh)) {
            gn[4 * i] = urm_contact_gap(&e, x + 3 * i, 0, gn + 4 * i + 1);
          }
          *depth = fmax(*depth, fmax(gn[4 * i], 0)); /* 0: within reach, -1: none */
        }
      }
    }
  }
  int ntl = 0;
  for (int s0 = 0; s0 < sb->nt; s0++) {
    int g0 = s0 * gw, g1 = g0 + gw < mb->ntfree ? g0 + gw : mb->ntfree;
    // a group's lim no smaller than its boxes' (its largest radius): out of reach, all of them are
    double slim = rg + 1e-6 * (rg + sb->t[7 * s0 + 6]) + 1e-9;
    if (box_gap2(sb->t + 7 * s0, gc) >= slim * slim) {
      continue;
    }
    for (int j0 = g0; j0 < g1; j0 += urMEM_CBLK) {
      // a sphere (c, r) in the box tries at |c - gc| < (rg + r)(1 + 1e-9), so at a box distance
      // below rg + 1e-9 (rg + r): the margin far above the roundings of c -+ r and of the sums
      const double* bx = tbx + 7 * (j0 / urMEM_CBLK);
      double lim = rg + 1e-6 * (rg + bx[6]) + 1e-9;
      if (box_gap2(bx, gc) >= lim * lim) {
        continue;
      }
      int j1 = j0 + urMEM_CBLK < g1 ? j0 + urMEM_CBLK : g1;
      // each sphere against g's sphere, then g's box (a margin above the roundings, as for the
      // blocks): urm_cull_tris
      ntl = urm_cull_tris(mb, tb, gc, rg, gh, j0, j1, tl, ntl);
    }
  }
  for (int j = 0; j < ntl; j++) {
    const int* e3 = mb->tedge + 3 * (int)tl[j];
    ge[4 * e3[0]] = ge[4 * e3[1]] = ge[4 * e3[2]] = NAN;
  }
  for (int jt = 0; jt < ntl; jt++) {
    int t = (int)tl[jt];
    const int* n3 = mb->tri + 3 * t;
    const int* e3 = mb->tedge + 3 * t;
    double dq[6], nq[6][3], xq[6][3], vq[6][3];
    int any = 0;
    for (int k = 0; k < 3; k++) {
      dq[k] = gn[4 * n3[k]];
      any |= dq[k] > 0;
    }
    for (int k = 0; k < 3; k++) {
      const double *xa = x + 3 * n3[k], *xb = x + 3 * n3[(k + 1) % 3];
      double* gk = ge + 4 * e3[k];
      for (int c = 0; c < 3; c++) {
        xq[3 + k][c] = 0.5 * (xa[c] + xb[c]);
      }
      if (isnan(gk[0])) {
        double r[3];
        urm_sub(r, xq[3 + k], gc);
        gk[0] = -INFINITY;
        if (urm_dot(r, r) < rg * rg) {
          if (!out_box(r, gh)) {
            gk[0] = urm_contact_gap(&e, xq[3 + k], 0, gk + 1);
          }
          *depth = fmax(*depth, fmax(gk[0], 0));
        }
      }
      dq[3 + k] = gk[0];
      for (int c = 0; c < 3; c++) {
        nq[3 + k][c] = gk[1 + c];
      }
      any |= dq[3 + k] > 0;
    }
    if (!any) {
      continue;
    }
    for (int k = 0; k < 3; k++) {
      const double *va = v + 3 * n3[k], *vb = v + 3 * n3[(k + 1) % 3];
      for (int c = 0; c < 3; c++) {
        xq[k][c] = x[3 * n3[k] + c];
        vq[k][c] = v[3 * n3[k] + c];
        nq[k][c] = gn[4 * n3[k] + 1 + c];
        vq[3 + k][c] = 0.5 * (va[c] + vb[c]);
      }
    }
    // the points not evaluated beside a penetrating one: their gap, for the zero contour (kept
    // for the node's or edge's other triangles)
    for (int j = 0; j < 4; j++) {
      const int* qj = sub[j];
      if (!(dq[qj[0]] > 0 || dq[qj[1]] > 0 || dq[qj[2]] > 0)) {
        continue;
      }
      for (int u = 0; u < 3; u++) {
        int p = qj[u];
        if (dq[p] == -INFINITY) {
          dq[p] = urm_contact_gap(&e, xq[p], 1, nq[p]);
          if (dq[p] == -INFINITY) {
            dq[p] = -1; /* no gradient there: far outside */
            nq[p][0] = nq[p][1] = 0, nq[p][2] = 1;
          }
          double* gp = p < 3 ? gn + 4 * n3[p] : ge + 4 * e3[p - 3];
          gp[0] = dq[p];
          for (int c = 0; c < 3; c++) {
            gp[1 + c] = nq[p][c];
          }
        }
      }
    }
    double e1[3], e2[3], cr[3];
    urm_sub(e1, xq[1], xq[0]);
    urm_sub(e2, xq[2], xq[0]);
    urm_cross(cr, e1, e2);
    double a = 0.125 * sqrt(urm_dot(cr, cr)); /* a quarter of the triangle's area */
    for (int j = 0; j < 4; j++) {
      const int* qj = sub[j];
      if (dq[qj[0]] > 0 || dq[qj[1]] > 0 || dq[qj[2]] > 0) {
        fsum += contact_sub(m, d, mb, s, body, o, vo, w, n3, qj, dq, nq, xq, vq, a, f, fc, kn, e3,
                            ke, &nel, &ep);
      }
    }
  }
  for (int j = jlo; j < jhi; j++) {
    gn[4 * mb->free[j]] = -INFINITY;
  }
  for (int jt = 0; jt < ntl; jt++) {
    const int* n3 = mb->tri + 3 * (int)tl[jt];
    gn[4 * n3[0]] = gn[4 * n3[1]] = gn[4 * n3[2]] = -INFINITY;
  }
  sc[urMEMS_ECONT] += ep;
  if (kn) {
    fsum += contact_implicit(m, d, mb, s, body, o, vo, w, st, kn, kn + 5 * (size_t)nn,
                             kn + 8 * (size_t)nn, ke, nel);
  }
  return fsum;
}


/* does a bag that rides rigidly on its carrier (R, c: its pose; bc: its bound's centre) go live
   now. The first rule (liverule 0): once some target's bounding sphere comes within 0.05 m of the
   bag's bound sphere. The rigid ride is exact while the carrier's tree moves as one unspun rigid
   body under gravity alone (the nodes carry no gravity: a live bag in free fall only sags
   against its mount; uasimpact-model(5), live). So the tighter rule (liverule 1) takes the bag
   live, once the first rule holds (never before it: a jolt far from the person, as the bottom
   bag's strike is to A2's front bag, leaves a bag rigid as before), when (b) that ends: the
   tree touches anything (its contacts and its bags' this step, ur_tree_active), spins, or one
   of its joints moves (beyond LIVE_STILL: the ABA's roundings leave ~1e-19); or (a) a target
   comes within LIVE_GAP + LIVE_LEAD |v| of a node of the rigid bag, v the target's speed
   against the carrier (its spin's part |w| rbound): the bag then has LIVE_LEAD of live motion,
   and at least LIVE_GAP, before it can touch. Contact acts only where a node or an edge's
   midpoint is inside a target (contact_geom): so each of them is tested against the target's
   bounding sphere and its box (urm_shape_box, in the carrier's frame) widened by the margin,
   after two cheaper bounds (the spheres, the target's sphere against the nodes' box, which
   holds the midpoints too). */
#define LIVE_GAP   0.005 /* m */
#define LIVE_LEAD  1e-3  /* s */
#define LIVE_STILL 1e-9  /* rad/s, m/s */
static int goes_live(const urModel* m, urData* d, const urAirbag* b, const double R[9],
                     const double c[3], const double bc[3]) {
  const urMembrane* mb = b->mem;
  // the first rule, which the second refines: never live before it
  int near = 0;
  for (int t = 0; t < b->ntarget && !near; t++) {
    int g = b->target[t];
    double dc[3];
    urm_sub(dc, d->gxpos + 3 * g, bc);
    double r = mb->rbound + m->geom[g].rbound + 0.05;
    near = urm_dot(dc, dc) < r * r;
  }
  if (!near || b->liverule == 0) {
    return near;
  }
  // (b) the carrier's tree jolted, spun or bent
  int cb = m->geom[b->geom].body, tree = m->body[cb].tree;
  if (ur_tree_active(m, d, tree)) {
    return 1;
  }
  for (int i = 0; i < m->nbody; i++) {
    const urBody* bi = m->body + i;
    for (int k = i == tree ? 3 : 0; bi->tree == tree && k < bi->nv; k++) { /* root: its spin */
      if (fabs(d->qvel[bi->vadr + k]) > LIVE_STILL) {
        return 1;
      }
    }
  }
  // (a) a target near a node: the nodes' box in the world (centre nc, half-widths nh)
  const double* nb = b->nbox;
  double nc[3], nh[3], vc[3];
  for (int k = 0; k < 3; k++) {
    nc[k] = c[k];
    nh[k] = 0;
    for (int j = 0; j < 3; j++) {
      nc[k] += R[3 * k + j] * 0.5 * (nb[j] + nb[3 + j]);
      nh[k] += fabs(R[3 * k + j]) * 0.5 * (nb[3 + j] - nb[j]);
    }
  }
  ur_point_vel(m, d, cb, (const double[3]){0, 0, 0}, vc);
  for (int t = 0; t < b->ntarget; t++) {
    int g = b->target[t], gb = m->geom[g].body;
    const double* gc = d->gxpos + 3 * g;
    double vg[3], dv[3], dc[3];
    ur_point_vel(m, d, gb, m->geom[g].pos, vg);
    urm_sub(dv, vg, vc);
    const double* wg = d->cvel + 6 * gb; /* the target's spin (body frame: its norm) */
    double rg = m->geom[g].rbound;
    double margin = LIVE_GAP + LIVE_LEAD * (sqrt(urm_dot(dv, dv)) + sqrt(urm_dot(wg, wg)) * rg);
    // the spheres, then the target's sphere against the nodes' box
    double r = mb->rbound + rg + margin;
    urm_sub(dc, gc, bc);
    int far = urm_dot(dc, dc) > r * r;
    for (int k = 0; k < 3 && !far; k++) {
      far = fabs(gc[k] - nc[k]) > nh[k] + rg + margin;
    }
    if (far) {
      continue;
    }
    // each node against the target's sphere and box in the carrier's frame (centre gl)
    urEllipsoid e;
    ur_geom_ellipsoid(m, d, g, &e);
    double gl[3], Rl[9], gh[3];
    urm_sub(dc, gc, c);
    for (int k = 0; k < 3; k++) {
      gl[k] = R[k] * dc[0] + R[3 + k] * dc[1] + R[6 + k] * dc[2];
      for (int j = 0; j < 3; j++) {
        Rl[3 * k + j] = R[k] * e.R[j] + R[3 + k] * e.R[3 + j] + R[6 + k] * e.R[6 + j];
      }
    }
    memcpy(e.R, Rl, sizeof(Rl));
    urm_shape_box(&e, gh);
    for (int k = 0; k < 3; k++) {
      gh[k] += margin;
    }
    double rr = (rg + margin) * (rg + margin);
    for (int i = 0; i < mb->nn + mb->ne; i++) {
      double x[3];
      if (i < mb->nn) {
        memcpy(x, mb->x0 + 3 * i, sizeof(x));
      } else {
        const int* en = mb->enode + 2 * (i - mb->nn);
        for (int k = 0; k < 3; k++) {
          x[k] = 0.5 * (mb->x0[3 * en[0] + k] + mb->x0[3 * en[1] + k]);
        }
      }
      double u[3] = {x[0] - gl[0], x[1] - gl[1], x[2] - gl[2]};
      if (fabs(u[0]) <= gh[0] && fabs(u[1]) <= gh[1] && fabs(u[2]) <= gh[2] &&
          urm_dot(u, u) <= rr) {
        return 1;
      }
    }
  }
  return 0;
}


void urm_bag_loads(const urModel* m, urData* d, int ib) {
  const urAirbag* b = m->bag + ib;
  const urMembrane* mb = b->mem;
  urBagData* bd = d->bag + ib;
  int nn = mb->nn, cb = m->geom[b->geom].body;
  double* st = d->mem + b->madr;
  double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *fc = st + 9 * nn, *sc = st + 18 * nn;
  double R[9], c[3], vc[3], w[3];
  bodymotion(d, cb, R, c, vc, w);
  bd->active = 0;
  bd->force = 0;
  for (int t = 0; t < b->ntarget; t++) {
    bd->ftgt[t] = 0;
    bd->rate[t] = 0;
    bd->depth[t] = -1;
  }

  // the bag's bound now (world)
  double bc[3];
  const double* cb0 = mb->cbound;
  for (int k = 0; k < 3; k++) {
    bc[k] = c[k] + R[3 * k] * cb0[0] + R[3 * k + 1] * cb0[1] + R[3 * k + 2] * cb0[2];
  }

  // carried rigidly until a target comes near it (or its carrier is jolted: goes_live)
  if (!bd->placed || !bd->live) {
    int near = goes_live(m, d, b, R, c, bc);
    // placed on the carrier when the run starts and when it goes live (its nodes are not read
    // while it rides rigidly: no need to move them with the carrier every step)
    if (!bd->placed || near) {
      ur_mem_state_init(mb, st, R, c, vc, w);
    }
    bd->placed = 1;
    bd->live = near;
    if (!near) {
      bd->pressure = mb->pref;
      bd->volume = mb->vref;
      bd->dv = 0;
      bd->strain = mb->strain0;
      return;
    }
  }

  // the mount patch moves with the carrier
  for (int j = 0; j < mb->nfix; j++) {
    int i = mb->fix[j];
    const double* p = mb->x0 + 3 * i;
    double r[3], wr[3];
    for (int k = 0; k < 3; k++) {
      r[k] = R[3 * k] * p[0] + R[3 * k + 1] * p[1] + R[3 * k + 2] * p[2];
    }
    urm_cross(wr, w, r);
    for (int k = 0; k < 3; k++) {
      x[3 * i + k] = c[k] + r[k];
      v[3 * i + k] = vc[k] + wr[k];
    }
  }

  // fabric and gas, then contacts (near the free nodes' box)
  ur_mem_forces(mb, st, f, NULL);
  memset(fc, 0, 3 * (size_t)nn * sizeof(double));
  if (mb->spec.kc_alpha > 1) { /* the stiff contact's position corrections (contact_implicit) */
    memset(node_bufs(mb, st) + 5 * (size_t)nn, 0, 3 * (size_t)nn * sizeof(double));
  }
  sc[urMEMS_ECONT] = 0;
  // the culling boxes of contact_geom and the free nodes' box lo, hi (urm_cull_boxes)
  int nt = mb->nt;
  double* tb = sc + urMEMS_N + 44 * (size_t)mb->ntb;
  double *nbx = tb + 5 * (size_t)nt, *tbx = nbx + 7 * (size_t)((nn + urMEM_CBLK - 1) / urMEM_CBLK);
  double lo[3], hi[3];
  urmCullGroups sb;
  urm_cull_boxes(mb, x, tb, nbx, tbx, lo, hi, &sb);
  // each free node's depth not evaluated (contact_geom's state between its calls)
  double* gn = sc + urMEMS_N;
  for (int j = 0; j < mb->nfree; j++) {
    gn[4 * mb->free[j]] = -INFINITY;
  }
  for (int t = 0; t < b->ntarget; t++) {
    double dep;
    double fs = contact_geom(m, d, b, st, b->target[t], ur_bag_penalty(m, b, t), lo, hi, &sb, &dep);
    bd->depth[t] = dep;
    bd->ftgt[t] = fs;
    bd->force += fs;
    if (fs > 0) {
      bd->active = 1;
    }
  }
  for (int t = 0; t < b->nsupport; t++) {
    double dep;
    contact_geom(m, d, b, st, b->support[t], mb->spec.kc_alpha, lo, hi, &sb, &dep);
  }

  // the mount patch's forces on the carrier
  for (int j = 0; j < mb->nfix; j++) {
    int i = mb->fix[j];
    ur_apply_force(m, d, cb, f + 3 * i, x + 3 * i);
  }
  bd->pressure = sc[urMEMS_P];
  bd->volume = sc[urMEMS_V];
  bd->dv = mb->vref - sc[urMEMS_V];
  bd->strain = sc[urMEMS_STRAIN];
}

/* a target's layer: its foundation stiffness E_oed / h, at most what the explicit step carries
   (kc_alpha 1, or the bag's own kc_alpha when it asks for the stiff implicit law) */
double ur_bag_penalty(const urModel* m, const urAirbag* b, int t) {
  const urMemSpec* s = b->mem ? &b->mem->spec : &b->mspec;
  if (t < 0 || t >= b->ntarget || !(b->tk[t] > 0)) {
    return s->kc_alpha;
  }
  double dk = fmax(m->opt.dt, s->kc_dt);
  return fmin(b->tk[t] * dk * dk / s->rhot, fmax(1, s->kc_alpha));
}


//---------------------------------- advance -------------------------------------------------------

void urm_bags_advance(const urModel* m, urData* d) {
  for (int ib = 0; ib < m->nbag; ib++) {
    const urAirbag* b = m->bag + ib;
    if (b->type != urBAG_MEMBRANE || !d->bag[ib].live) {
      continue;
    }
    const urMembrane* mb = b->mem;
    int nn = mb->nn;
    double* st = d->mem + b->madr;
    double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *fc = st + 9 * nn, *sc = st + 18 * nn;
    // snapshots for the plot: at first contact with a target, at the peak pressure in contact
    if (d->bag[ib].active) {
      int hg = m->roles.head;
      double hc[3] = {0, 0, 0};
      if (hg >= 0) {
        memcpy(hc, d->gxpos + 3 * hg, sizeof(hc));
      }
      if (sc[urMEMS_TFIRST] < 0) {
        memcpy(st + 12 * nn, x, 3 * (size_t)nn * sizeof(double));
        sc[urMEMS_TFIRST] = d->time;
        memcpy(sc + urMEMS_HFIRST, hc, sizeof(hc));
      }
      if (sc[urMEMS_P] > sc[urMEMS_PPEAK]) {
        memcpy(st + 15 * nn, x, 3 * (size_t)nn * sizeof(double));
        sc[urMEMS_TPEAK] = d->time;
        sc[urMEMS_PPEAK] = sc[urMEMS_P];
        memcpy(sc + urMEMS_HPEAK, hc, sizeof(hc));
      }
    }
    int nsub = (int)ceil(m->opt.dt / mb->dt_stable - 1e-9);
    if (nsub < 1) {
      nsub = 1;
    }
    double h = m->opt.dt / nsub;
    for (int s = 0; s < nsub; s++) {
      if (s > 0) {
        ur_mem_forces(mb, st, f, NULL);
        for (int k = 0; k < 3 * nn; k++) {
          f[k] += fc[k];
        }
      }
      for (int i = 0; i < nn; i++) {
        double im = mb->invm[i];
        for (int k = 0; k < 3; k++) {
          v[3 * i + k] += h * im * f[3 * i + k];
          x[3 * i + k] += h * v[3 * i + k];
        }
      }
    }
    // the stiff contact's implicit midpoint along the normal (contact_implicit)
    if (mb->spec.kc_alpha > 1) {
      const double* cor = node_bufs(mb, st) + 5 * (size_t)nn;
      for (int k = 0; k < 3 * nn; k++) {
        x[k] += cor[k];
      }
    }
    sc[urMEMS_MGAS] -= ur_mem_outflow(mb, st, m->opt.dt);
  }
}
