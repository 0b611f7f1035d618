/* membrane.h: the finite-element membrane airbag (paper 3.2: MADYMO FE airbag with uniform-pressure
 * gas). A bag is a closed triangulated fabric surface made of two panels of a plan shape
 * (ellipse or rounded rectangle) sewn at their edge; constant-strain triangles, total
 * Lagrangian, orthotropic woven fabric (warp along the plan's x axis) with a locking shear law,
 * tension only (wrinkling: the tension-field relaxed energy), optional material damping; a uniform-pressure adiabatic gas,
 * optional vents and fabric leakage. Sources of every law and value: uasimpact-model(5), BAGS.
 *
 * Split like the engine: urMembrane is constant once built and inflated (mesh topology,
 * reference metric, masses, the inflated state in the carrier's body frame), shared by threads;
 * the state of one run (node positions and velocities, gas mass) is a caller-owned array of
 * ur_mem_state_size() doubles. No globals, no I/O.
 *
 * Use:
 *   urMemSpec s; ur_mem_spec_default(&s);  s.a = 0.3; ...
 *   urMembrane* mb = ur_mem_build(&s, err, sizeof err);   // mesh and reference metric
 *   ur_mem_inflate(mb, err, sizeof err);                  // once: the stabilised inflated bag
 *   double* st = malloc(ur_mem_state_size(mb) * sizeof(double));
 *   ur_mem_state_init(mb, st, R, x0, v0, w0);             // placed rigidly on its carrier
 *   ur_mem_forces(mb, st, force, &info);                   // fabric + gas forces on the nodes
 */
#ifndef UASIMPACT_MEMBRANE_H
#define UASIMPACT_MEMBRANE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  urMEM_ELLIPSE = 0, /* plan (x/a)^2 + (y/b)^2 <= 1 */
  urMEM_RECT         /* rounded rectangle: the superellipse |x/a|^4 + |y/b|^4 <= 1 */
} urMemPlan;

typedef enum {
  urMEM_SHAPE = 0, /* the reference metric is the declared inflated shape (stress free there) */
  urMEM_FLAT       /* two flat panels of the plan shape (initial metric method: the mesh starts
                      in the declared shape, the fabric's rest lengths are the flat pattern's) */
} urMemPattern;

typedef enum {
  urMEM_RELAX = 0, /* kinetic damping (velocities zeroed at each peak of the kinetic energy) */
  urMEM_FIRE       /* FIRE (Bitzek et al. 2006): velocity mixing, adaptive step */
} urMemInflate;

typedef enum {
  urMEM_RELAXED = 0, /* wrinkling by the relaxed energy (tension-field theory): a potential */
  urMEM_REDUCE       /* the compressive principal stress scaled by re (OpenRadioss LAW19's rule):
                        no Newton, no potential (uasimpact-model(5), BAGS, wrinkle) */
} urMemWrinkle;

/* a declared bag (model language 'airbag ... mesh=N'): SI units */
typedef struct {
  urMemPlan plan;
  urMemPattern pattern;
  double a, b;     /* plan semi-axes, m (x: along, warp; y: across, weft) */
  double depth;    /* bottom panel's depth below the seam in the declared shape, m */
  double top;      /* top panel's height above the seam (0: flat top), m */
  double mount[3]; /* top centre of the bag in the carrier's body frame, m */
  double quat[4];  /* the bag's frame in the carrier's (w, x, y, z; identity: the plan in the
                      body's x-y plane, the bottom panel towards -z) */
  double mount_r;  /* top-panel nodes within this fraction of the plan are fixed to the
                         carrier (the rigid mount patch, a fixed joint), 0..1 */
  int mesh;        /* rings per panel: 2 + 6 mesh^2 nodes, 12 mesh^2 triangles */
  int inflate;     /* the inflation's relaxation: urMEM_RELAX (default) or urMEM_FIRE */
  int wrinkle;     /* the wrinkling law: urMEM_RELAXED (default) or urMEM_REDUCE */
  /* fabric (membrane stiffnesses: modulus times thickness) */
  double e1t, e2t; /* warp, weft tensile stiffness, N/m */
  double nu12;     /* Poisson ratio (warp strain -> weft) */
  double g0t, gtt; /* shear stiffness before and after locking, N/m */
  double lock;     /* locking shear angle, rad */
  double re;       /* share of the taut law kept beside the relaxed (wrinkling) energy, 0..1;
                      with urMEM_REDUCE the factor on the compressive principal stress */
  double rhot;     /* areal density, kg/m^2 */
  double damp;     /* material damping: fraction of critical at the element frequency */
  /* gas */
  double p0, patm;  /* inflation (absolute) and ambient pressure, Pa */
  double gamma;     /* ratio of specific heats */
  double temp;      /* gas temperature at inflation, K (density for the vents) */
  double vent_area; /* vent orifice area, m^2 (0: none) */
  double vent_cd;   /* orifice discharge coefficient */
  double leak;      /* fabric leakage: effective open area per fabric area (0: none) */
  /* contact with ellipsoids (person and the carrier's own bodies) */
  double kc_alpha;  /* penalty stiffness alpha m_node / max(dt, kc_dt)^2 (explicit for alpha <= 1;
                       beyond, up to 1000, linearly implicit along the normal) */
  double kc_dt;     /* the step that stiffness refers to when dt is smaller, s */
  double zeta_c;    /* contact damping, fraction of critical per node */
  double mu, v_eps; /* regularised Coulomb friction */
  double dt_factor; /* fraction of the stable step taken (<= 1) */
  double mscale;    /* selective mass scaling: at most this fraction of the fabric's mass added,
                       to the triangles whose step is below hstep / n, n the fewest sub-steps that
                       allows (0: none; uasimpact-model(5), BAGS) */
  double hstep;     /* the multibody step the fabric is sub-cycled in, s: set by the engine when
                       the model compiles, for mscale (0: no mass scaling) */
} urMemSpec;

/* constant once inflated */
typedef struct {
  urMemSpec spec;
  int nn, nt;        /* nodes, triangles */
  int ntop;          /* nodes of the top panel (0..ntop-1; the seam is its last ring) */
  int nfix;          /* mount nodes */
  int* tri;          /* 3 nt node indices, outward normals by the right-hand rule */
  double* dminv;     /* 4 nt: inverse of the reference edge matrix in the material axes */
  double* area0;     /* nt: reference area, m^2 */
  double* beta;      /* nt: stiffness-proportional damping time, s */
  double* mass;      /* nn: lumped node mass, kg */
  double* invm;      /* nn: 1/mass, 0 for mount nodes */
  int* fix;          /* nfix: the mount nodes */
  int ntb;           /* blocks of 4 triangles (the last one padded) */
  int* tri4;         /* 12 ntb: node indices by blocks, tri4[12 b + 4 k + l] = node k of
                        triangle 4 b + l (padding: node 0) */
  double* tk4;       /* 24 ntb: per block Dm^-1 (4 rows), area0, beta, each 4 lanes (padding 0) */
  int* adj0;         /* nn + 1: node i's triangle corners are adj[adj0[i] .. adj0[i + 1]) */
  int* adj;          /* 3 nt: the corners by node in triangle order, as offsets of their force
                        in the force pass's scratch */
  int ne;            /* edges */
  int* tedge;        /* 3 nt: the edges of triangle t (nodes 1-2, 2-3, 3-1), 0 .. ne - 1 */
  int* enode;        /* 2 ne: the nodes of each edge */
  int nfree, ntfree; /* free nodes; triangles whose three nodes are free */
  int* free;         /* nfree: the free nodes, ascending */
  int* tfree;        /* ntfree: those triangles, ascending */
  double* xshape;    /* 3 nn: the declared shape, carrier body frame */
  double* x0;        /* 3 nn: the inflated state, carrier body frame */
  double pref, vref; /* inflated gas state: absolute pressure Pa, volume m^3 */
  double mref;       /* gas mass at inflation, kg */
  double dt_stable;  /* stable explicit step of the fabric (times dt_factor), s; with mass
                        scaling hstep / n */
  double madd;       /* mass added by the scaling (mscale), kg (0: none) */
  int nscaled;       /* triangles whose mass it raised */
  double lmin;       /* shortest characteristic length (2 A / longest edge) of the triangles
                        with a free node, m */
  double cbound[3];  /* centre and radius of a sphere holding the inflated bag, body frame */
  double rbound;
  double strain0;          /* largest yarn strain (Green, warp or weft) of the inflated state */
  int inflate_steps;       /* relaxation steps the inflation took */
  double inflate_res;      /* its final residual (largest free-node force / pressure force) */
  const _Atomic int* stop; /* optional (not part of the bag): ur_mem_inflate gives up while
                              *stop != 0 (an interrupt flag); the cache's copies have NULL */
} urMembrane;

/* per-run scalars at the end of the state array */
enum {
  urMEMS_MGAS = 0, /* gas mass, kg */
  urMEMS_P,        /* absolute pressure at the last force evaluation, Pa */
  urMEMS_V,        /* gas volume, m^3 */
  urMEMS_STRAIN,   /* largest yarn strain (Green, warp or weft) at the last force evaluation */
  urMEMS_EFAB,     /* fabric strain energy at the last force evaluation, J */
  urMEMS_TFIRST,   /* time of the first-contact snapshot, s (-1: none) */
  urMEMS_TPEAK,    /* time of the peak-pressure snapshot (in contact), s (-1: none) */
  urMEMS_PPEAK,    /* that peak absolute pressure, Pa */
  urMEMS_HFIRST,   /* 3: the head ellipsoid's centre at the first snapshot (world) */
  urMEMS_HPEAK = urMEMS_HFIRST + 3, /* 3: and at the peak snapshot */
  urMEMS_ECONT = urMEMS_HPEAK + 3,  /* energy in the contact penalty springs, J */
  urMEMS_N
};

/* forces and diagnostics of one evaluation */
typedef struct {
  double pressure, volume; /* absolute Pa, m^3 */
  double strain;           /* largest yarn strain (Green, warp or weft) */
  double efabric;          /* elastic strain energy of the fabric (the potential of its law), J */
} urMemInfo;

/* the default bag: nylon-6,6 woven fabric and air (uasimpact-model(5), BAGS) */
void ur_mem_spec_default(urMemSpec* s);

/* check a spec: 0, or -1 with what is wrong in err */
int ur_mem_spec_check(const urMemSpec* s, char* err, size_t n);

/* mesh, reference metric, masses and stable step of a bag (not inflated: x0 = the declared
   shape). NULL with a message in err on bad input or no memory. */
urMembrane* ur_mem_build(const urMemSpec* s, char* err, size_t n);

/* inflate to the declared pressure and relax until stable (kinetic damping), closed gas; sets
   x0, pref, vref, mref, strain0. 0, or -1 with err when it does not converge or mb->stop asks it
   to stop ("stopped on request (interrupted)"). */
int ur_mem_inflate(urMembrane* mb, char* err, size_t n);

/* the same on up to threads threads (fewer for a small bag: one per 1000 triangles at most),
   the same bits for any number (the calling thread and threads - 1 started and joined here) */
int ur_mem_inflate_threads(urMembrane* mb, int threads, char* err, size_t n);

void ur_mem_free(urMembrane* mb);

/* a deep copy of a bag (every array its own), NULL when out of memory; freed by ur_mem_free */
urMembrane* ur_mem_clone(const urMembrane* mb);

/* the inflated-bag cache (membrane_cache.c): built and inflated bags kept by their whole spec
   (every field of urMemSpec equal, doubles bit for bit), at most 24 bags and 100 000 nodes, the
   least recently used evicted first. Owned by its caller (one per session, e.g. the compile
   options' memcache, engine.h); no globals; a mutex guards it, so threads may share one. */
typedef struct urMemCache urMemCache;

typedef struct {
  long hits, misses; /* look-ups that found a bag, and that built and inflated one */
  int entries;       /* bags kept */
  long nodes;        /* their nodes */
} urMemCacheStats;

urMemCache* ur_memcache_new(void); /* NULL when out of memory */
/* the threads its inflations may use (ur_mem_inflate_threads; default 1): no result changes */
void ur_memcache_set_threads(urMemCache* c, int threads);
void ur_memcache_free(urMemCache* c);
void ur_memcache_stats(urMemCache* c, urMemCacheStats* st); /* c NULL: all zero */

/* a built and inflated bag of spec s, owned by the caller (ur_mem_free): a copy of the one kept
   for an equal spec (the same bits as ur_mem_build then ur_mem_inflate), else built and inflated
   and a copy kept (a failure is not), inflated on the cache's threads. c NULL: ur_mem_build
   and ur_mem_inflate alone. NULL with
   a message in err on bad input, no memory or an inflation that does not settle. */
urMembrane* ur_mem_build_inflated(urMemCache* c, const urMemSpec* s, char* err, size_t n);

/* the same for a bag already built (ur_mem_build; its stop polled by the inflation): mb itself
   inflated (and a copy kept), or freed and a copy of the one kept for its spec returned; NULL
   with err on failure (mb freed). For a model compiled before it is inflated (ur_model_inflate). */
urMembrane* ur_mem_cache_inflate(urMemCache* c, urMembrane* mb, char* err, size_t n);

/* 1 when the cache keeps a bag of spec s (no use counted, nothing built) */
int ur_memcache_has(urMemCache* c, const urMemSpec* s);

/* doubles in one run's state: x (3 nn), v (3 nn), forces (3 nn), the contact part of them
   (3 nn), the positions at first contact (3 nn) and at the peak pressure in contact (3 nn),
   scalars (urMEMS_N, after 18 nn), then the force evaluation's scratch (36 ntb), then each
   triangle's warm start of the wrinkled law (8 ntb: 2 per triangle, 0 when none), then the
   engine's contact scratch (5 nt: each triangle's bounding sphere, a list of triangles; then
   7 doubles per urMEM_CBLK free nodes and per urMEM_CBLK free triangles: their boxes; then for
   the implicit stiff penalty 5 nn: each node's normal stiffness, normal and lumped stiffness, 3
   nn: its position correction along the normal (the implicit midpoint's), 6 nn: the solve's
   work, 3 ne: each edge's coupling and nodes, ne: the list of the edges coupled) */
size_t ur_mem_state_size(const urMembrane* mb);

/* where the stiff penalty's buffers start in the run's state (the 5 nn of normal stiffness, the
   last part of ur_mem_state_size's layout): one place for the engine and the size */
size_t ur_mem_stiff_offset(const urMembrane* mb);

/* free nodes (and free triangles) per box of the face contact's culling (engine_membrane.c) */
#define urMEM_CBLK 8

/* place the inflated bag rigidly: x = c + R x0, v = vc + w x (x - c) (world; R row-major body ->
   world, c the carrier origin, vc its velocity, w its angular velocity); gas at the inflated
   state */
void ur_mem_state_init(const urMembrane* mb, double* st, const double R[9], const double c[3],
                       const double vc[3], const double w[3]);

/* enclosed volume of positions x (divergence theorem), m^3 */
double ur_mem_volume(const urMembrane* mb, const double* x);

/* absolute gas pressure at volume V and gas mass mgas (isentropic from the inflated state) */
double ur_mem_pressure(const urMembrane* mb, double V, double mgas);

/* gas energy relative to the ambient: p V / (gamma - 1) + patm V, J */
double ur_mem_gas_energy(const urMembrane* mb, double p, double V);

/* fabric and gas forces on every node at the state (x, v) of st into f (3 nn, overwritten);
   info may be NULL; scalars of st updated (pressure, volume, strain, energy). st is a whole run
   state of ur_mem_state_size() doubles: the evaluation's scratch is its end, and its wrinkled
   triangles' warm starts are read and updated there, and each triangle's bounding sphere at x
   (centre, squared radius: the face contact's culling) written after them */
void ur_mem_forces(const urMembrane* mb, double* st, double* f, urMemInfo* info);

/* Green strain (E11, E22, 2 E12, warp/weft axes) and stress resultant (N/m, the tension-field
   law, no damping) of triangle t at positions x */
void ur_mem_tri_state(const urMembrane* mb, const double* x, int t, double e[3], double S[3]);

/* gas leaving through the vents and the fabric in dt at the state's pressure (kg), >= 0 */
double ur_mem_outflow(const urMembrane* mb, const double* st, double dt);

/* the stable step of the fabric from the reference metric and the material (no dt_factor), s */
double ur_mem_stable_dt(const urMembrane* mb);

/* kinetic energy of the free nodes, J */
double ur_mem_kinetic(const urMembrane* mb, const double* st);

#ifdef __cplusplus
}
#endif
#endif
