/* engine_contact.c: contact pairs: broad phase by bounding spheres, narrow phase by contact.h
 * (warm-started direction kept per pair), force from the pair's law, regularised Coulomb
 * friction, equal and opposite forces at the contact point. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- helpers -------------------------------------------------------

int ur_cand_count(const urModel* m) {
  int n = m->npair;
  for (int i = 0; i < m->nbag; i++) {
    n += m->bag[i].ntarget;
  }
  return n;
}


int ur_cand_at(const urModel* m, int k, urCand* c) {
  if (k < 0) {
    return -1;
  }
  if (k < m->npair) {
    *c = (urCand){m->pair[k].geom1, m->pair[k].geom2, -1, k, k};
    return 0;
  }
  k -= m->npair;
  for (int i = 0; i < m->nbag; i++) {
    const urAirbag* b = m->bag + i;
    if (k < b->ntarget) {
      *c = (urCand){b->geom, b->target[k], i, k, ur_cand_bag_slot(m, i, k)};
      return 0;
    }
    k -= b->ntarget;
  }
  return -1;
}


// ellipsoid g in world coordinates
void ur_geom_ellipsoid(const urModel* m, urData* d, int g, urEllipsoid* e) {
  memcpy(e->c, d->gxpos + 3 * g, 3 * sizeof(double));
  memcpy(e->R, ur_geom_xmat(m, d, g), 9 * sizeof(double));
  memcpy(e->r, m->geom[g].size, 3 * sizeof(double));
  e->p = m->geom[g].degree;
}


// diag(r) R^T u of ellipsoid g into w: unit u in its frame, scaled by its semi-axes
static void scaled_dir(const urModel* m, urData* d, int g, const double u[3], double w[3]) {
  const double* R = ur_geom_xmat(m, d, g);
  const double* r = m->geom[g].size;
  uru_mulmat3tvec(w, R, u);
  w[0] *= r[0];
  w[1] *= r[1];
  w[2] *= r[2];
}


// half-width of ellipsoid g along unit u: |diag(r) R^T u| (superellipsoid: the q-norm,
// contact.h)
double ur_geom_halfwidth(const urModel* m, urData* d, int g, const double u[3]) {
  double w[3];
  scaled_dir(m, d, g, u, w);
  if (m->geom[g].degree > 2) {
    return ur_halfwidth_local(w, m->geom[g].degree);
  }
  return uru_norm3(w);
}


// |diag(r) R^T u| of ellipsoid g: its half-width along unit u when it is an ellipsoid, and a
// lower bound of it when it is a superellipsoid (the q-norm of ur_halfwidth_local, q <= 2, is at
// least the 2-norm)
static double halfwidth2(const urModel* m, urData* d, int g, const double u[3]) {
  double w[3];
  scaled_dir(m, d, g, u, w);
  return uru_norm3(w);
}


// cheap upper bound on the signed depth of ellipsoids ga, gb: the support-function gap
// f(u) = (cA - cB).u + hA(u) + hB(u) >= min f = depth, at the centre line and at the warm
// start u (if set); a negative bound proves separation without the narrow phase. With a
// superellipsoid (whose half-width costs calls of pow) f at the two directions is bounded from
// below by the 2-norms first: the direction whose bound lies clearly above the other's value
// cannot be the smaller and is not evaluated (the same minimum, bit for bit). cull: only a
// negative bound is wanted (ur_depth_cull), so neither is a direction whose 2-norm bound lies
// clearly above 0: its f is then positive, and the minimum, if negative, is the other's
static double depth_bound(const urModel* m, urData* d, int ga, int gb, const double u[3],
                          int cull) {
  const double* ca = d->gxpos + 3 * ga;
  const double* cb = d->gxpos + 3 * gb;
  double dc[3] = {ca[0] - cb[0], ca[1] - cb[1], ca[2] - cb[2]}, c[3];
  double L = uru_norm3(dc), f = INFINITY;
  int hasu = u[0] != 0 || u[1] != 0 || u[2] != 0;
  if (L > 0 && hasu && (m->geom[ga].degree > 2 || m->geom[gb].degree > 2)) {
    c[0] = -dc[0] / L;
    c[1] = -dc[1] / L;
    c[2] = -dc[2] / L;
    double du = uru_dot3(dc, u);
    double lc = -L + halfwidth2(m, d, ga, c) + halfwidth2(m, d, gb, c);
    double lu = du + halfwidth2(m, d, ga, u) + halfwidth2(m, d, gb, u);
    // far above the rounding of either side (a few ulp of these magnitudes)
    double margin = 1e-9 * (L + fabs(du) + m->geom[ga].rbound + m->geom[gb].rbound);
    if (cull && (lc - margin > 0 || lu - margin > 0)) {
      if (lc - margin > 0 && lu - margin > 0) {
        return lc - margin; /* f > 0: not culled */
      }
      if (lc - margin > 0) {
        return du + ur_geom_halfwidth(m, d, ga, u) + ur_geom_halfwidth(m, d, gb, u);
      }
      return -L + ur_geom_halfwidth(m, d, ga, c) + ur_geom_halfwidth(m, d, gb, c);
    }
    if (lu >= lc) {
      double fc = -L + ur_geom_halfwidth(m, d, ga, c) + ur_geom_halfwidth(m, d, gb, c);
      f = fc;
      if (!(lu - margin > fc)) {
        f = fmin(f, du + ur_geom_halfwidth(m, d, ga, u) + ur_geom_halfwidth(m, d, gb, u));
      }
    } else {
      double fu = du + ur_geom_halfwidth(m, d, ga, u) + ur_geom_halfwidth(m, d, gb, u);
      if (!(lc - margin > fu)) {
        f = -L + ur_geom_halfwidth(m, d, ga, c) + ur_geom_halfwidth(m, d, gb, c);
      }
      f = fmin(f, fu);
    }
    return f;
  }
  if (L > 0) {
    c[0] = -dc[0] / L;
    c[1] = -dc[1] / L;
    c[2] = -dc[2] / L;
    f = -L + ur_geom_halfwidth(m, d, ga, c) + ur_geom_halfwidth(m, d, gb, c);
  }
  if (hasu) {
    f = fmin(f, uru_dot3(dc, u) + ur_geom_halfwidth(m, d, ga, u) + ur_geom_halfwidth(m, d, gb, u));
  }
  return f;
}

double ur_depth_bound(const urModel* m, urData* d, int ga, int gb, const double u[3]) {
  return depth_bound(m, d, ga, gb, u, 0);
}

double ur_depth_cull(const urModel* m, urData* d, int ga, int gb, const double u[3]) {
  return depth_bound(m, d, ga, gb, u, 1);
}


// relative velocity of body a's point p minus body b's point p (b = -1: world)
void ur_relvel(const urModel* m, const urData* d, int a, int b, const double p[3], double v[3]) {
  double pl[3], r[3], va[3] = {0, 0, 0}, vb[3] = {0, 0, 0};
  if (a >= 0) {
    for (int k = 0; k < 3; k++) {
      r[k] = p[k] - d->xpos[3 * a + k];
    }
    uru_mulmat3tvec(pl, d->xmat + 9 * a, r);
    ur_point_vel(m, d, a, pl, va);
  }
  if (b >= 0) {
    for (int k = 0; k < 3; k++) {
      r[k] = p[k] - d->xpos[3 * b + k];
    }
    uru_mulmat3tvec(pl, d->xmat + 9 * b, r);
    ur_point_vel(m, d, b, pl, vb);
  }
  for (int k = 0; k < 3; k++) {
    v[k] = va[k] - vb[k];
  }
}


// mobility (inverse apparent mass) of an isolated body at world point p along unit t
static double mobility(const urModel* m, const urData* d, int body, const double p[3],
                       const double t[3]) {
  if (body < 0) {
    return 0;
  }
  const urBody* b = m->body + body;
  double r[3], c[3], cb[3], ic[3];
  for (int k = 0; k < 3; k++) {
    r[k] = p[k] - d->xcom[3 * body + k];
  }
  uru_cross3(c, r, t);
  uru_mulmat3tvec(cb, d->xmat + 9 * body, c);
  uru_mulmat3vec(ic, b->iinv, cb);
  return 1 / b->mass + uru_dot3(cb, ic);
}


// apply normal force fn along n (A -> B) plus friction: -(fn n) + ft on A, the opposite on B
// (v: the relative velocity of A's point p minus B's, ur_relvel);
// regularised Coulomb friction ft = -mu fn vt / max(|vt|, v_eps, v_stab) with mu and v_eps of
// the law (or given, law NULL); v_stab = mu fn dt / m_t keeps the explicit step stable, with m_t
// the apparent tangential mass of the two isolated bodies (a lower bound); returns |ft|
double ur_contact_apply(const urModel* m, urData* d, int a, int b, const double n[3],
                        const double p[3], const double v[3], double fn, double rate,
                        const urLaw* law, double mu, double v_eps) {
  double vt[3], f[3], fr[3] = {0, 0, 0};
  if (law) {
    mu = law->mu;
    v_eps = law->v_eps;
  }

  // tangential relative velocity and regularised Coulomb friction on A
  for (int k = 0; k < 3; k++) {
    vt[k] = v[k] - rate * n[k];
  }
  double s = uru_norm3(vt);
  if (mu > 0 && s > 0) {
    double t[3] = {vt[0] / s, vt[1] / s, vt[2] / s};
    double w = mobility(m, d, a, p, t) + mobility(m, d, b, p, t);
    double vs = fmax(fmax(s, v_eps), mu * fn * ur_step_h(m, d) * w);
    for (int k = 0; k < 3; k++) {
      fr[k] = -mu * fn * vt[k] / vs;
    }
  }
  for (int k = 0; k < 3; k++) {
    f[k] = -fn * n[k] + fr[k];
  }
  double ft = uru_norm3(fr);

  // equal and opposite
  if (a >= 0) {
    ur_apply_force(m, d, a, f, p);
  }
  if (b >= 0) {
    for (int k = 0; k < 3; k++) {
      f[k] = -f[k];
    }
    ur_apply_force(m, d, b, f, p);
  }
  return ft;
}

//---------------------------------- pairs ---------------------------------------------------------

// broad phase: every pair's depth set to minus the gap of its bounding spheres (of the sphere to
// the ground plane)
void ur_contacts_broad(const urModel* m, urData* d) {
  for (int i = 0; i < m->npair; i++) {
    const urPair* pr = m->pair + i;
    const double* ca = d->gxpos + 3 * pr->geom1;
    double ra = m->geom[pr->geom1].rbound;
    double gap;
    if (pr->geom2 < 0) {
      gap = ca[2] - ra;
    } else {
      const double* cb = d->gxpos + 3 * pr->geom2;
      double dx[3] = {cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]};
      gap = uru_norm3(dx) - ra - m->geom[pr->geom2].rbound;
    }
    d->pdepth[i] = -gap;
  }
}


// pair i, whose bounding spheres overlap (after ur_contacts_broad): oriented bound, narrow
// phase, law, friction
static inline __attribute__((always_inline)) void narrow1(const urModel* m, urData* d, int i) {
  static const double up[3] = {0, 0, 1};
  urPairData* pd = d->pair + i;
  pd->active = 0;
  pd->fn = pd->ft = pd->rate = pd->area = 0;
  const urPair* pr = m->pair + i;
  int ba = m->geom[pr->geom1].body;
  int bb = pr->geom2 >= 0 ? m->geom[pr->geom2].body : -1;
  urEllipsoid ea, eb;
  urGeomContact gc;

  // oriented bound: separated at the centre line or at the last normal
  if (pr->geom2 >= 0) {
    double fb = ur_depth_cull(m, d, pr->geom1, pr->geom2, pd->u);
    if (fb < 0) {
      d->pdepth[i] = fb;
      return;
    }
  }

  // narrow phase
  ur_geom_ellipsoid(m, d, pr->geom1, &ea);
  if (pr->geom2 < 0) {
    ur_collide_ellipsoid_plane(&ea, up, 0, &gc);
  } else {
    ur_geom_ellipsoid(m, d, pr->geom2, &eb);
    ur_collide_ellipsoids(&ea, &eb, pd->u, &gc);
  }
  d->pdepth[i] = gc.g;
  memcpy(pd->n, gc.n, sizeof(pd->n));
  memcpy(pd->p, gc.p, sizeof(pd->p));
  if (!(gc.g > 0)) {
    return;
  }

  // rate, area, normal force
  double v[3];
  ur_relvel(m, d, ba, bb, gc.p, v);
  pd->rate = uru_dot3(v, gc.n);
  if (pr->law.type == urLAW_FOAM) {
    pd->area = ur_section_area(&ea, gc.n, gc.g);
  }
  const urLaw* law = &pr->law;
  urLaw curv;
  if (law->type == urLAW_HERTZ && law->radius == urHERTZ_CURVATURE) {
    /* the radius from the shapes' curvature at this contact */
    curv = *law;
    curv.radius = pd->radius = ur_contact_radius(&ea, pr->geom2 >= 0 ? &eb : NULL, &gc);
    law = &curv;
  } else if (law->type == urLAW_FOAM && law->backing_r == urHERTZ_CURVATURE) {
    /* a backing derived from the person's layer: flat on the person's part (a), whose
       curvature at this contact gives its radius */
    curv = *law;
    pd->radius = ur_contact_radius(&ea, NULL, &gc);
    curv.backing_k = ur_law_backing_k(law, pd->radius);
    law = &curv;
  }
  pd->fn = ur_law_force(law, &pd->ls, gc.g, pd->rate, pd->area);
  if (!(pd->fn > 0)) {
    pd->fn = 0;
    return;
  }

  // apply with friction
  pd->active = 1;
  pd->ft = ur_contact_apply(m, d, ba, bb, gc.n, gc.p, v, pd->fn, pd->rate, &pr->law, 0, 0);
}


// every pair whose bounding spheres overlap; the lists of the pairs to commit (penetrating or
// touching) and of the active ones. A culled pair's data is not touched: only the pairs the
// last pass listed to commit can hold a force (cleared here) or a touching history (listed
// again while culled, to unload).
void ur_contacts_narrow(const urModel* m, urData* d) {
  int np = m->npair, nt = 0;
  int* commit = d->plist;
  int* act = d->plist + np;
  int touch[np > 0 ? np : 1];
  for (int k = 0; k < d->npcommit; k++) {
    urPairData* pd = d->pair + commit[k];
    pd->active = 0;
    pd->fn = pd->ft = pd->rate = pd->area = 0;
    if (pd->ls.touching && -d->pdepth[commit[k]] > 0) { // culled now: listed to unload
      touch[nt++] = commit[k];
    }
  }
  d->npcommit = d->npactive = 0;

  // the pairs whose bounding spheres overlap, listed first without a branch (in B's grid 9 of
  // its 121 pairs a step, on average, where a test and jump per pair mispredicted wherever the
  // pattern changed); narrow1 changes only its own pair's depth, so the list is the one the loop
  // would have found
  int cand[np > 0 ? np : 1], nc = 0;
  for (int i = 0; i < np; i++) {
    cand[nc] = i;
    nc += !(-d->pdepth[i] > 0);
  }
  for (int j = 0; j < nc; j++) {
    int i = cand[j];
    narrow1(m, d, i);
    const urPairData* pd = d->pair + i;
    if (d->pdepth[i] > 0 || pd->ls.touching) {
      commit[d->npcommit++] = i;
    }
    if (pd->active) {
      act[d->npactive++] = i;
    }
  }
  for (int k = 0; k < nt; k++) {
    commit[d->npcommit++] = touch[k]; // (decided before narrow1 also made depths < 0)
  }
}


// after pair data was copied in from elsewhere: every pair listed to commit, so that the next
// pass clears and revisits them all
void ur_contacts_relist(const urModel* m, urData* d) {
  for (int i = 0; i < m->npair; i++) {
    d->plist[i] = i;
  }
  d->npcommit = m->npair;
  d->npactive = 0;
}


void ur_contacts(const urModel* m, urData* d) {
  ur_contacts_broad(m, d);
  ur_contacts_narrow(m, d);
}


// commit the law histories at the evaluated depths (accepted steps only)
void ur_contacts_commit(const urModel* m, urData* d) {
  for (int k = 0; k < d->npcommit; k++) {
    int i = d->plist[k];
    urPairData* pd = d->pair + i;
    if (d->pdepth[i] > 0 || pd->ls.touching) {
      const urLaw* law = &m->pair[i].law;
      urLaw curv;
      if (law->type == urLAW_HERTZ && law->radius == urHERTZ_CURVATURE) {
        curv = *law;
        curv.radius = pd->radius > 0 ? pd->radius : urHERTZ_RMAX;
        law = &curv;
      } else if (law->type == urLAW_FOAM && law->backing_r == urHERTZ_CURVATURE) {
        curv = *law;
        curv.backing_k = ur_law_backing_k(law, pd->radius > 0 ? pd->radius : urHERTZ_RMAX);
        law = &curv;
      }
      ur_law_commit(law, &pd->ls, d->pdepth[i], pd->rate, pd->area);
    }
  }
}
