/* membrane_internal.h: what the files of the membrane room (src/core/membrane) share and the
 * engine's airbag dispatch calls: small vector helpers, the fabric law of one triangle, the
 * penalty contact of one node with an ellipsoid (the engine's glue, engine/engine_membrane.c,
 * includes it too). Not public API. */
#ifndef UASIMPACT_MEMBRANE_INTERNAL_H
#define UASIMPACT_MEMBRANE_INTERNAL_H

#include <math.h>
#include "uasimpact/contact.h"
#include "uasimpact/engine.h"
#include "uasimpact/membrane.h"

#define urMEM_RS 287.05 /* specific gas constant of air, J/(kg K) */

static inline double urm_dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void urm_cross(double o[3], const double a[3], const double b[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}
static inline void urm_sub(double o[3], const double a[3], const double b[3]) {
  o[0] = a[0] - b[0];
  o[1] = a[1] - b[1];
  o[2] = a[2] - b[2];
}

/* the stress resultant (N/m: S11, S22, S12 in the material axes) of Green strain e (E11, E22,
   2 E12) by the orthotropic law with the locking shear law relaxed for wrinkling (tension
   field), plus re of the taut law; the energy density (J/m^2) whose gradient it is in *w (may be
   NULL) */
void urm_fabric_stress(const urMemSpec* s, const double e[3], double S[3], double* w);

/* the same with the triangle's warm start uw (2 doubles of the run's state, ur_mem_state_size:
   read, then the wrinkled state's solution written; 0, 0 for none): the same law to the
   wrinkled Newton's tolerance, not bit for bit the cold one */
void urm_fabric_stress_warm(const urMemSpec* s, const double e[3], double S[3], double* w,
                            double* uw);

/* urm_fabric_stress's law over 4 strains at once (the force pass's vector law), lanes side by
   side: e[4 j + l] is component j of lane l, S likewise, w the 4 energy densities; each lane's
   bits are urm_fabric_stress's */
void urm_fabric_stress4(const urMemSpec* s, const double e[12], double S[12], double w[4]);

/* the same with the 4 triangles' warm starts (uw[2 l], uw[2 l + 1]: lane l's, as
   urm_fabric_stress_warm's): the force pass's path, each lane's bits and warm start those of
   urm_fabric_stress_warm */
void urm_fabric_stress4_warm(const urMemSpec* s, const double e[12], double S[12], double w[4],
                             double uw[8]);

/* the Green strain (E11, E22, 2 E12) and the deformation gradient F (3x2, column-major: F[0..2]
   the first column) of triangle t at positions x */
void urm_tri_strain(const urMembrane* mb, const double* x, int t, double F[6], double e[3]);

/* the signed first-order distance of point x into shape e ((1 - s) / |grad s|: > 0 inside, the
   depth; < 0 outside, the gap) and the outward unit normal in n; unless full, -INFINITY for a
   point outside the shape (or outside its box: the cheap test), n then unset */
double urm_contact_gap(const urEllipsoid* e, const double x[3], int full, double n[3]);

/* the half-widths of shape e along the world axes (its support function there, a
   superellipsoid's bounded by the 1-norm: every point of it within e->c -+ gh), widened by 1e-9
   of themselves and 1e-9 m: a point farther out has a
   gauge s > 1 far beyond the roundings, so urm_contact_gap (not full) returns -INFINITY for it
   (the face contact's culling, engine_membrane.c) */
void urm_shape_box(const urEllipsoid* e, double gh[3]);

/* the contact force on a share of the fabric: the penalty pressure's integral I = int depth N
   (m^3) and the penetrated area A = int N (m^2) over the share, the outward normal n and the
   velocity vr relative to the body's surface; force (normal, damping, friction) in f, the
   normal force returned (0 and f zero when the damped pressure does not push). The friction's
   viscous slope is capped at rhot ac / max(dt, kc_dt): ac is the whole area the share stands
   for (a point's share of its quarter, penetrated or not), so the cap is the share's mass over
   the penalty's own step, set neither by dt nor by how deep the share dips */
double urm_contact_force(const urMemSpec* s, double dt, const double n[3], const double vr[3],
                         double I, double A, double ac, double f[3]);

/* the penetrated part of a triangle of unit area whose depth d (its corners' values) is linear
   over it: I[u] = int max(d, 0) N_u, A[u] = int over d > 0 of N_u, E = int max(d, 0)^2 (times
   the triangle's area for its own) */
void urm_contact_clip(const double d[3], double I[3], double A[3], double* E);

/* the penalty contact of a node (position x, velocity v, mass m) with ellipsoid e moving with
   the rigid velocity (vo at point o, angular w): force on the node in f (3), returns the
   penetration (> 0 in contact, else the force is zero) */
double urm_contact_node(const urMemSpec* s, double dt, const urEllipsoid* e, const double o[3],
                        const double vo[3], const double w[3], const double x[3], const double v[3],
                        double m, double f[3]);

/* the parts of ur_mem_forces that the inflation's relaxation (membrane_inflate.c) spreads over
   threads, each the same bits as the whole, on run state st: the triangle pass over the blocks
   [b0, b1) (b0 a multiple of urm_tri_chunk(); its scratch and warm starts; each triangle's
   volume term x1 . (x2 x x3) in vt, nt; no energy, strain or bounding spheres), then those
   blocks' corner forces at pg6 = (p - patm) / 6, then the forces of the nodes [i0, i1) into f,
   their corners summed in triangle order */
int urm_tri_chunk(void);
void urm_tri_pass_part(const urMembrane* mb, double* st, int b0, int b1, double* vt);
void urm_tri_forces_part(const urMembrane* mb, double* st, double pg6, int b0, int b1);
void urm_node_forces(const urMembrane* mb, const double* st, int i0, int i1, double* f);

/* ur_mem_inflate over nthr threads (at most urMEM_MAXTHR and one per chunk of urm_tri_chunk()
   blocks), however small the bag: the same bits for any nthr. alt 0: the team runs while it is
   faster than one thread (ur_mem_inflate_threads); alt < 0: the team throughout; alt > 0: the team
   and one thread alternate every alt steps (the tests of its hand-overs) */
#define urMEM_MAXTHR 64
int urm_mem_inflate_team(urMembrane* mb, int nthr, int alt, char* err, size_t n);

/* 1 if two specs are equal field by field (doubles by their bits): the inflated-bag cache's key */
int urm_mem_spec_same(const urMemSpec* a, const urMemSpec* b);

/* a cache of at most cap bags and maxnodes nodes (ur_memcache_new's are 24 and 100 000); NULL
   for cap or maxnodes below 1 or no memory */
urMemCache* urm_memcache_new_sized(int cap, long maxnodes);

#endif
