/* contact.h: contact geometry (ellipsoids, superellipsoids, planes), force-penetration laws and the
 * uniform-pressure airbag gas law. Pure functions on caller-owned data: no globals, no I/O,
 * safe to call from any number of threads.
 *
 * Conventions: SI units. A rotation matrix R is row-major, local -> world (x_world = c + R x_local),
 * so column k of R is the k-th local axis in world coordinates. Penetration depth g > 0 means
 * overlap, g < 0 separation. Rates are d(depth)/dt: positive while approaching.
 */
#ifndef UASIMPACT_CONTACT_H
#define UASIMPACT_CONTACT_H

#ifdef __cplusplus
extern "C" {
#endif

#define urMAXCURVE  48 /* points in a tabulated curve */
#define urMAXDEGREE 20 /* largest superellipsoid degree */

/* ---- geometry ---- */

typedef struct {
  double c[3]; /* centre, world */
  double R[9]; /* orientation, row-major, local -> world */
  double r[3]; /* semi-axes along the local axes */
  double p;    /* degree: |x/a|^p + |y/b|^p + |z/c|^p <= 1 in the local
                                      frame; 0 or 2: the ellipsoid (a zeroed struct is one),
                                      else in (2, urMAXDEGREE]: a superellipsoid, flat-faced
                                      with rounded edges (the box as p grows) */
} urEllipsoid;

typedef struct {
  double g;     /* signed depth: > 0 overlap, < 0 -(separation distance) */
  double n[3];  /* unit normal from A towards B (plane: the plane normal) */
  double pa[3]; /* deepest point of A (support point of A along n) */
  double pb[3]; /* deepest point of B (support point of B along -n) */
  double p[3];  /* contact point: midpoint of pa and pb */
  int iters;    /* iterations used (ellipsoid pairs) */
} urGeomContact;

/* Ellipsoid (or superellipsoid) against the half-space {x : n.x <= d} (n unit, pointing out
   of the solid). The normal reported is -n (from the ellipsoid into the solid) so that the
   force on the ellipsoid is -F*out.n = +F*n. Returns 1 if g > 0, else 0 (out is filled either
   way). */
int ur_collide_ellipsoid_plane(const urEllipsoid* e, const double n[3], double d,
                               urGeomContact* out);

/* Exact signed distance between two ellipsoids by minimising the support function of the
   Minkowski difference over the unit sphere. u: in, warm start direction (A towards B) or
   all zeros for a cold start; out, the minimiser. Returns 1 if g > 0, else 0.
   Superellipsoids (p > 2): the support function is the dual norm h(u) = ||diag(r) R^T u||_q,
   q = p/(p-1); the same minimisation, with a second trial step along each Newton direction
   that follows |w_l|^q where a local coordinate w_l of the direction is near zero (the flat
   faces: h is not twice differentiable there). Two ellipsoids take the ellipsoid code alone,
   bit for bit. */
int ur_collide_ellipsoids(const urEllipsoid* a, const urEllipsoid* b, double u[3],
                          urGeomContact* out);

/* Half-width along a unit direction u (h(u), the support function about the centre) from
   w = diag(r) R^T u: ||w||_q with q = p/(p-1); p <= 2: |w|. */
double ur_halfwidth_local(const double w[3], double p);

/* Radius of the smallest centred sphere holding the shape with semi-axes r and degree p: the
   largest semi-axis for p <= 2, else ||r||_k with k = 2p/(p-2) (exact, rounded upwards). */
double ur_bound_radius(const double r[3], double p);

/* Area of the section of an ellipsoid by the plane normal to unit n at depth d below its
   support point in direction n, and the volume of the cap cut off; d clamped to [0, 2 sigma].
   Ellipsoids only: NAN for a superellipsoid (p > 2; the model builder keeps those out). */
double ur_section_area(const urEllipsoid* e, const double n[3], double d);
double ur_cap_volume(const urEllipsoid* e, const double n[3], double d);

/* ---- force laws ---- */

typedef struct {
  int n;                /* number of points; 0 = absent */
  double x[urMAXCURVE]; /* ascending */
  double y[urMAXCURVE];
} urCurve;

/* piecewise-linear interpolation, linear extrapolation beyond the ends */
double ur_curve_eval(const urCurve* c, double x);

typedef enum {
  urLAW_HERTZ = 0, /* Hertz, optional Jackson-Green plastic loading + Brake unloading */
  urLAW_TABLE,     /* tabulated force-penetration loading/unloading with hysteresis */
  urLAW_FOAM       /* section area(penetration) x stress(strain), load/unload */
} urLawType;

typedef struct {
  urLawType type;
  /* Hertz / Brake */
  double estar;   /* effective modulus E*, Pa */
  double radius;  /* effective radius, m */
  double sy;      /* yield strength of the softer body, Pa */
  double nu;      /* Poisson ratio of the yielding body */
  int plastic;    /* 1: JG loading beyond yield and Brake elastic unloading */
  double layer_h; /* > 0: the softer body is a layer of this thickness (m) over bone: beyond
                     it the bone's stiffness takes over, F = F(layer_h) + bone_k (d - layer_h)
                     (uasimpact-model(5), layer) */
  double bone_k;  /* stiffness of the bone under the layer, N/m */
  double shell_k; /* > 0: a hollow part's local shell stiffness (N/m) in series with the
                     contact: d = d_contact(F) + F / shell_k */
  double crush_f; /* > 0: the shell's crush load (N): its spring's force is capped there and
                     the depth it yields beyond is kept (urLawState.crush); 0: elastic shell */
  double crush_h; /* the crushed depth (m) at which the shell bottoms on its contents: beyond
                     it the contact alone carries the force above crush_f */
  /* tabulated (urLAW_TABLE): force (N) against penetration (m) */
  urCurve load;
  urCurve unload; /* empty: unload along the loading curve (elastic) */
  /* foam (urLAW_FOAM) */
  urCurve stress;       /* loading stress (Pa) against strain */
  double thickness;     /* foam thickness, m: strain = depth / thickness */
  double unload_r;      /* residual strain as a fraction of the maximum strain */
  double unload_p;      /* exponent of the unloading curve */
  double lock;          /* strain at which the foam is solid (densified), (0, 1); 0:
                                      none (the stress curve alone, extrapolated beyond its end) */
  double backing_k;     /* Hertz constant K (N/m^1.5) of the rigid backing the solid
                                      foam rests on: F += K (d - lock thickness)^1.5 beyond lock */
  double backing_estar; /* the backing's E* (Pa) when derived from the person's layer */
  double backing_r;     /* its radius (m); urHERTZ_CURVATURE: the person's curvature at each
                           contact, backing_k = ur_law_backing_k(law, R) there (engine_contact.c) */
  urCurve backing;      /* n > 0: the backing is this force (N) against the depth beyond the lock
                           thickness (a person's law layer's loading curve) instead of Hertz */
  /* all laws */
  double damping; /* linear viscous term, N s/m, acts while in contact */
  double chi;     /* Hunt-Crossley-type factor, s/m: F *= 1 + chi*rate */
  double mu;      /* Coulomb friction coefficient */
  double v_eps;   /* friction regularisation speed, m/s */
} urLaw;

/* per-run, per-pair history (lives in the run data, never in the model) */
typedef struct {
  int touching; /* the law gave an elastic force at the last commit */
  double dmax;  /* largest depth reached */
  double fmax;  /* elastic (rate-free) force at dmax */
  double dres;  /* residual depth after unloading (permanent set) */
  double crush; /* a crushing shell's crushed (plastic) depth, m, at most crush_h */
} urLawState;

/* the Hertz radius of ellipsoids a and b (NULL: the ground plane) from their curvature at the
   contact gc: 1 / sqrt(det(K_A + K_B)), the curvature tensors in the tangent plane at gc's
   deepest points (degree-2 ellipsoids), at most urHERTZ_RMAX (flat on flat), m
   (contact_curv.c). A Hertz law whose radius is urHERTZ_CURVATURE takes it so at every contact
   (engine_contact.c). */
#define urHERTZ_CURVATURE (-1.0)
#define urHERTZ_RMAX      10.0
double ur_contact_radius(const urEllipsoid* a, const urEllipsoid* b, const urGeomContact* gc);

/* fill a Hertz law from the two materials (R2 = 0 means a flat) */
void ur_law_hertz(urLaw* law, double E1, double nu1, double R1, double E2, double nu2, double R2,
                  double sy, double nu_yield, int plastic);

/* normal force (>= 0) at depth d (> 0) and rate; area is the section area (foam only).
   Does not change the state. Below dmax the laws unload and reload along:
   HERTZ (plastic): Brake F = fmax ((d - dres)/(dmax - dres))^1.5;
   TABLE: the unloading curve shifted along the depth axis to pass through (dmax, fmax),
          capped by the loading curve (elastic when unload.n < 2);
   FOAM: stress sm ((e - er)/(em - er))^unload_p, er = unload_r em (elastic if unload_p <= 0);
         with a lock strain the strain stops there and the backing's force (elastic) adds: Hertz
         K x^1.5, or the backing curve at x, x the depth beyond the lock thickness.
   F = Fe (1 + chi rate) + damping rate while Fe > 0, then clamped at >= 0. */
double ur_law_force(const urLaw* law, const urLawState* s, double d, double rate, double area);

/* record depth d on an accepted step (updates dmax, fmax, dres, touching); d <= 0 only clears
   touching. touching = 1 while the rate-free force is positive. */
void ur_law_commit(const urLaw* law, urLawState* s, double d, double rate, double area);

/* the largest depth a law's data covers (m): a table law's last loading abscissa, a foam law's
   thickness times its stress curve's last strain (HUGE_VAL with a lock strain: the backing
   takes over; with a backing curve, the lock thickness plus the curve's last depth), a layered Hertz law's layer thickness (plus the shell's share, F(h)/shell_k, with
   a shell in series, or crush_h + crush_f/shell_k when the shell crushes before the layer
   bottoms; beyond it the layer has bottomed and the bone takes over: a run notes it), HUGE_VAL
   for Hertz; beyond it the law is extrapolated */
double ur_law_range(const urLaw* law);

/* Hertz constants of a law: K = 4/3 E* sqrt(R) (N/m^1.5), Jackson-Green yield onset depth dy
   and force fy (HUGE_VAL when sy <= 0) */
void ur_law_hertz_params(const urLaw* law, double* K, double* dy, double* fy);

/* the Hertz constant of a foam's derived backing at radius R (m): K = 4/3 E* sqrt(R), E* the
   law's backing_estar (of the person's layer on the backing's material), N/m^1.5 */
double ur_law_backing_k(const urLaw* law, double R);

/* regularised Coulomb friction on the body moving with tangential velocity vt:
   out = -mu fn vt / max(|vt|, v_eps) (v_eps <= 0: plain Coulomb, zero at vt = 0) */
void ur_friction(const urLaw* law, double fn, const double vt[3], double out[3]);

/* ---- uniform-pressure airbag gas law ---- */

typedef struct {
  double v0;    /* inflated volume, m^3 */
  double p0;    /* initial absolute pressure, Pa */
  double patm;  /* ambient pressure, Pa */
  double gamma; /* ratio of specific heats */
} urGas;

/* absolute pressure after the volume has dropped by dv (adiabatic, closed: P V^gamma = const) */
double ur_gas_pressure(const urGas* gas, double dv);

/* work done on the gas when the volume drops from v0 by dv (J) */
double ur_gas_work(const urGas* gas, double dv);

#ifdef __cplusplus
}
#endif
#endif
