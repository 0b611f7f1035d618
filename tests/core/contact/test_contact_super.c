/* test_contact_super.c: superellipsoids (degree p > 2): closed forms, brute force against the
 * independent reference of contact_fixture.h, warm starts, the bounding radius, and p = 2 bit
 * for bit the ellipsoid code.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "uasimpact/contact.h"
#include "contact_fixture.h"

/* ---- superellipsoids ---- */

/* independent half-width ||diag(r) R^T u||_q, q = p/(p-1), straight from the definition */
static double hsup(const urEllipsoid* e, const double u[3]) {
  double p = e->p > 2 ? e->p : 2, q = p / (p - 1), s = 0;
  for (int k = 0; k < 3; k++) {
    double v = e->R[k] * u[0] + e->R[3 + k] * u[1] + e->R[6 + k] * u[2];
    s += pow(fabs(e->r[k] * v), q);
  }
  return pow(s, 1 / q);
}

/* support function of A - B: (c_A - c_B).u + h_A(u) + h_B(u); its minimum is the signed depth */
static double fsup(const urEllipsoid* a, const urEllipsoid* b, const double u[3]) {
  double dc = 0;
  for (int i = 0; i < 3; i++) dc += (a->c[i] - b->c[i]) * u[i];
  return dc + hsup(a, u) + hsup(b, u);
}

/* the level sum |x_l / r_l|^p of a world point (1 on the surface) */
static double level(const urEllipsoid* e, const double x[3]) {
  double s = 0, p = e->p > 2 ? e->p : 2;
  for (int k = 0; k < 3; k++) {
    double l = 0;
    for (int i = 0; i < 3; i++) l += e->R[3 * i + k] * (x[i] - e->c[i]);
    s += pow(fabs(l / e->r[k]), p);
  }
  return s;
}

/* brute-force signed depth: the minimum of the support function (bestdir of fsup) */
static double brutesup(const urEllipsoid* a, const urEllipsoid* b, double uref[3]) {
  return bestdir(a, b, fsup, uref);
}

/* random superellipsoid pair: p in [2, 10] (B an ellipsoid in 30 % of pairs, of A's degree in
   20 %), semi-axes 0.02-0.3 m, random rotations; B placed along a random direction d so that
   the depth along d runs from 0.05 m apart to 1.5 times the smallest semi-axis deep (the
   depth, the minimum over all directions, is at most that) */
static void randsuper(gsl_rng* rng, urEllipsoid* a, urEllipsoid* b) {
  randell(rng, a, 0.02, 0.3);
  randell(rng, b, 0.02, 0.3);
  a->p = 2 + 8 * gsl_rng_uniform(rng);
  b->p = gsl_rng_uniform(rng) < 0.3 ? 2 : 2 + 8 * gsl_rng_uniform(rng);
  if (gsl_rng_uniform(rng) < 0.2) b->p = a->p;
  double d[3];
  randunit(rng, d);
  double lim = fmin(minaxis(a), minaxis(b));
  double s = hsup(a, d) + hsup(b, d) + 0.05 - (1.5 * lim + 0.05) * gsl_rng_uniform(rng);
  for (int i = 0; i < 3; i++) {
    a->c[i] = 0.3 * gsl_rng_uniform(rng) - 0.15;
    b->c[i] = a->c[i] + s * d[i];
  }
}

/* a sphere on a flat face: over the centre of the face of a box-like superellipsoid (p = 10)
   the support points are the face centre and the sphere's pole, so the depth is exactly
   c + rho - L, the normal the face normal; from cold and from warm starts up to 0.5 rad off,
   separated and penetrating up to the sphere's radius; likewise on the plane; and a sphere
   deep inside a thin plate */
static void test_super_face(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 17);
  double maxerr = 0, maxn = 0;
  int maxit = 0;
  for (int t = 0; t < 300; t++) {
    urEllipsoid a, b;
    randell(rng, &a, 0.05, 0.3);
    randell(rng, &b, 0.02, 0.1);
    a.p = t < 150 ? 10 : 2 + 18 * gsl_rng_uniform(rng);
    b.r[1] = b.r[2] = b.r[0];
    int k = t % 3, sg = t % 2 ? 1 : -1;
    double nrm[3] = {sg * a.R[k], sg * a.R[3 + k], sg * a.R[6 + k]};
    double L = a.r[k] + b.r[0] - b.r[0] * (2.2 * gsl_rng_uniform(rng) - 1.2);
    for (int i = 0; i < 3; i++) {
      a.c[i] = gsl_rng_uniform(rng) - 0.5;
      b.c[i] = a.c[i] + L * nrm[i];
    }
    double gref = a.r[k] + b.r[0] - L;
    double u[3] = {0, 0, 0};
    if (t % 4) {
      double p[3];
      randunit(rng, p);
      for (int i = 0; i < 3; i++) u[i] = nrm[i] + 0.5 * gsl_rng_uniform(rng) * p[i];
    }
    urGeomContact c;
    int hit = ur_collide_ellipsoids(&a, &b, u, &c);
    assert_int_equal(hit, gref > 0);
    maxerr = fmax(maxerr, fabs(c.g - gref));
    for (int i = 0; i < 3; i++) maxn = fmax(maxn, fabs(c.n[i] - nrm[i]));

    // the contact point: on the sphere's axis along the face normal, half the depth from its
    // deepest point (not the face's support point, which may sit anywhere on the face)
    for (int i = 0; i < 3; i++) {
      assert_near(c.p[i], b.c[i] - (b.r[0] - 0.5 * c.g) * nrm[i], 1e-9);
    }
    if (c.iters > maxit) maxit = c.iters;

    // the plane: the face lying on it, depth d - n.c + c exactly
    double d =
        nrm[0] * a.c[0] + nrm[1] * a.c[1] + nrm[2] * a.c[2] + 0.1 * gsl_rng_uniform(rng) - 0.05;
    urGeomContact cp;
    ur_collide_ellipsoid_plane(&a, nrm, d, &cp);
    // (the deepest point itself is ill-conditioned there: a direction 1e-17 off the normal
    // moves it by |w_l|^(1/(p-1)) ~ 1 % of the face for p = 10; its height is not)
    double nc = nrm[0] * a.c[0] + nrm[1] * a.c[1] + nrm[2] * a.c[2];
    assert_near(cp.g, d - nc + a.r[k], 1e-15);
    assert_near(nrm[0] * cp.pa[0] + nrm[1] * cp.pa[1] + nrm[2] * cp.pa[2], nc - a.r[k], 1e-15);
    assert_near(level(&a, cp.pa), 1, 1e-12);
  }
  // deep: a sphere inside a thin plate (p 16..20), off the centre along the plate: the centre
  // line starts Newton at a local minimum (the plate's edge side, 0.3 - x + rho), the depth is
  // through the thin side, h + rho (the face is flat to h (x/0.3)^p / p < 1e-14 m there);
  // only the deep-penetration guard finds it
  for (int t = 0; t < 50; t++) {
    urEllipsoid a, b;
    randell(rng, &a, 0.3, 0.3);
    randell(rng, &b, 0.05, 0.05);
    a.r[2] = 0.02;
    a.p = 16 + 4 * gsl_rng_uniform(rng);
    double x = 0.02 + 0.04 * gsl_rng_uniform(rng);
    for (int i = 0; i < 3; i++) b.c[i] = a.c[i] + x * a.R[3 * i];
    double u[3] = {0, 0, 0};
    urGeomContact c;
    ur_collide_ellipsoids(&a, &b, u, &c);
    maxerr = fmax(maxerr, fabs(c.g - 0.07));
    maxn = fmax(maxn, 1 - fabs(c.n[0] * a.R[2] + c.n[1] * a.R[5] + c.n[2] * a.R[8]));
  }
  printf(
      "sphere on a flat face: max |g - g_exact| = %.3g m, max |n - n_face| = %.3g, max "
      "iterations %d\n",
      maxerr, maxn, maxit);
  assert_true(maxerr < 1e-12);
  assert_true(maxn < 1e-6);
  gsl_rng_free(rng);
}

/* superellipsoid against the plane: g and the deepest point against the minimum of n.x over
   dense surface samples x_l = r_l sign(v_l) |v_l|^(2/p) (v on the unit sphere) polished by
   Nelder-Mead; the deepest point on the surface */
typedef struct {
  const urEllipsoid* e;
  const double* n;
} supplane;

static void suppoint(const urEllipsoid* e, double th, double ph, double x[3]) {
  double v[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)}, l[3];
  for (int k = 0; k < 3; k++) l[k] = e->r[k] * copysign(pow(fabs(v[k]), 2 / e->p), v[k]);
  for (int i = 0; i < 3; i++) {
    x[i] = e->c[i];
    for (int k = 0; k < 3; k++) x[i] += e->R[3 * i + k] * l[k];
  }
}

static double supplaneobj(const gsl_vector* xv, void* par) {
  const supplane* sp = par;
  double x[3];
  suppoint(sp->e, gsl_vector_get(xv, 0), gsl_vector_get(xv, 1), x);
  return sp->n[0] * x[0] + sp->n[1] * x[1] + sp->n[2] * x[2];
}

static void test_super_plane(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 23);
  double maxerr = 0, maxlev = 0;
  for (int t = 0; t < 100; t++) {
    urEllipsoid e;
    randell(rng, &e, 0.02, 0.3);
    e.p = 2 + 8 * gsl_rng_uniform(rng);
    for (int i = 0; i < 3; i++) e.c[i] = gsl_rng_uniform(rng) - 0.5;
    double n[3];
    randunit(rng, n);
    double d = n[0] * e.c[0] + n[1] * e.c[1] + n[2] * e.c[2] + 0.4 * gsl_rng_uniform(rng) - 0.3;

    // grid, then Nelder-Mead in (theta, phi)
    supplane sp = {&e, n};
    double xy[2];
    double bv = surfmin(supplaneobj, &sp, xy);

    urGeomContact c;
    int hit = ur_collide_ellipsoid_plane(&e, n, d, &c);
    assert_int_equal(hit, d - bv > 0);
    maxerr = fmax(maxerr, fabs(c.g - (d - bv)));
    maxlev = fmax(maxlev, fabs(level(&e, c.pa) - 1));
    assert_near(n[0] * c.pb[0] + n[1] * c.pb[1] + n[2] * c.pb[2], d, 1e-14);
    assert_near(n[0] * c.pa[0] + n[1] * c.pa[1] + n[2] * c.pa[2], bv, 1e-12);
  }
  printf(
      "superellipsoid-plane: max |g - g_ref| = %.3g m, deepest point max |level - 1| = "
      "%.3g (100 cases)\n",
      maxerr, maxlev);
  assert_true(maxerr < 1e-12);
  assert_true(maxlev < 1e-12);
  gsl_rng_free(rng);
}

/* 400 random pairs (superellipsoid-ellipsoid, -superellipsoid) against the brute-force
   minimum of the support function: within 1e-9 m, and never below it by more than its own
   error (1e-12); the record consistent (g = f(n), pa and pb on the surfaces, g = n.(pa - pb)) */
static void test_super_pairs_bruteforce(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 4242);
  double maxerr = 0, maxlev = 0, maxang = 0;
  int nsep = 0, nover = 0, ndeep = 0, maxit = 0;
  for (int t = 0; t < 400; t++) {
    urEllipsoid a, b;
    randsuper(rng, &a, &b);
    double uref[3] = {0, 0, 1};
    double gref = brutesup(&a, &b, uref);
    double u[3] = {0, 0, 0};
    urGeomContact c;
    int hit = ur_collide_ellipsoids(&a, &b, u, &c);
    if (c.iters > maxit) maxit = c.iters;
    assert_int_equal(hit, c.g > 0);
    nsep += c.g < 0;
    nover += c.g > 0;
    ndeep += c.g > fmin(minaxis(&a), minaxis(&b));

    // the record
    double gd = 0;
    for (int i = 0; i < 3; i++) {
      gd += c.n[i] * (c.pa[i] - c.pb[i]);
      assert_near(u[i], c.n[i], 0);
    }
    assert_near(gd, c.g, 1e-14);
    assert_near(fsup(&a, &b, c.n), c.g, 1e-14);
    maxlev = fmax(maxlev, fmax(fabs(level(&a, c.pa) - 1), fabs(level(&b, c.pb) - 1)));

    // against the reference
    double err = c.g - gref;
    if (fabs(err) > 1e-9) {
      printf("pair %d (p %.3g, %.3g): g = %.15g  ref = %.15g\n", t, a.p, b.p, c.g, gref);
    }
    assert_true(fabs(err) <= 1e-9);
    assert_true(err >= -1e-12);
    maxerr = fmax(maxerr, fabs(err));
    double dt = c.n[0] * uref[0] + c.n[1] * uref[1] + c.n[2] * uref[2];
    maxang = fmax(maxang, acos(fmin(1.0, dt)));
  }
  printf(
      "superellipsoid pairs: %d separated, %d overlapping (%d deeper than the smallest "
      "semi-axis), max |g - g_ref| = %.3g m, max normal angle %.3g rad, max |level - 1| = "
      "%.3g, max iterations %d\n",
      nsep, nover, ndeep, maxerr, maxang, maxlev, maxit);
  assert_true(nsep > 100 && nover > 100);
  assert_true(maxlev < 1e-9);
  gsl_rng_free(rng);
}

/* warm starts equal the cold start: perturbed minimisers, and trajectories of a sphere or an
   ellipsoid sliding over a superellipsoid's flat face, across its symmetry planes, over an
   edge and a corner (each step warm from the last) */
static void test_super_warm(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 99);
  double maxdg = 0;
  long nwarm = 0, itwarm = 0;
  for (int t = 0; t < 300; t++) {
    urEllipsoid a, b;
    randsuper(rng, &a, &b);
    double u[3] = {0, 0, 0}, p[3], w[3];
    urGeomContact cold, warm;
    ur_collide_ellipsoids(&a, &b, u, &cold);
    for (int k = 0; k < 3; k++) {
      double amp = k == 0 ? 1e-4 : k == 1 ? 1e-2 : 0.3;
      randunit(rng, p);
      for (int i = 0; i < 3; i++) w[i] = cold.n[i] + amp * p[i];
      ur_collide_ellipsoids(&a, &b, w, &warm);
      maxdg = fmax(maxdg, fabs(warm.g - cold.g));
    }
  }
  for (int t = 0; t < 60; t++) {
    // box-like A (p 4..12) at the origin, axis-aligned; B passes over the top face along a
    // straight line from one edge region to the other through a random point of the face
    urEllipsoid a = {
        {0, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0.3, 0.2, 0.1}, 4 + 8 * (t % 5) / 4.0};
    urEllipsoid b;
    randell(rng, &b, 0.03, 0.08);
    if (t % 2) b.r[1] = b.r[2] = b.r[0];
    double x0 = (t % 3 == 0) ? 0 : 0.3 * (2 * gsl_rng_uniform(rng) - 1);
    double y0 = (t % 3 == 1) ? 0 : 0.2 * (2 * gsl_rng_uniform(rng) - 1);
    double dir = 2 * M_PI * gsl_rng_uniform(rng), dz = 0.02 * gsl_rng_uniform(rng) - 0.01;
    double uw[3] = {0, 0, 0};
    urGeomContact warm, cold;
    for (int s = 0; s <= 400; s++) {
      double l = 0.5 * (s / 200.0 - 1);
      b.c[0] = x0 + l * cos(dir);
      b.c[1] = y0 + l * sin(dir);
      b.c[2] = 0.1 + hsup(&b, (double[3]){0, 0, 1}) - dz;
      double uc[3] = {0, 0, 0};
      ur_collide_ellipsoids(&a, &b, uw, &warm);
      ur_collide_ellipsoids(&a, &b, uc, &cold);
      if (fabs(warm.g - cold.g) > 1e-12) {
        printf("trajectory %d step %d: warm %.15g cold %.15g\n", t, s, warm.g, cold.g);
      }
      maxdg = fmax(maxdg, fabs(warm.g - cold.g));
      nwarm++;
      itwarm += warm.iters;
    }
  }
  printf(
      "superellipsoid warm vs cold: max |dg| = %.3g m; trajectories: %.2f iterations per "
      "warm call\n",
      maxdg, (double)itwarm / nwarm);
  assert_true(maxdg < 1e-12);
  gsl_rng_free(rng);
}

/* p = 2 (and 0, the zeroed struct, and below 2) is the ellipsoid code bit for bit: results
   recorded from that code before superellipsoids existed; p slightly above 2 takes the
   superellipsoid code and lands within 1e-9 m of them */
static void test_super_p2_bits(void** state) {
  static const struct {
    double g, n[3], gwarm;
    int iters;
  } rec[6] = {
      {0x1.b32128305c198p-4,
       {0x1.2b21cf9812a27p-1, 0x1.43e389d2c928p-2, -0x1.7eac1515e5508p-1},
       0x1.b32128305c19ap-4,
       5},
      {0x1.1c0ba3d2303bfp-3,
       {-0x1.d5b2a73a9ef51p-2, -0x1.c3f42a82e4403p-1, -0x1.a1d2f98a79614p-4},
       0x1.1c0ba3d2303bfp-3,
       5},
      {-0x1.02853e78f4c01p-4,
       {0x1.8b655a251a20ep-2, -0x1.7d955e32600f9p-2, -0x1.b00a1560225dbp-1},
       -0x1.02853e78f4c02p-4,
       4},
      {-0x1.8818002703397p-4,
       {0x1.960a18b542c9p-2, -0x1.ecce9efc0474p-3, -0x1.c5984a0ef5b8fp-1},
       -0x1.881800270339ap-4,
       5},
      {0x1.60710aefcd9a8p-8,
       {-0x1.3d8718bc884ddp-4, -0x1.adbacd023f1b6p-3, -0x1.f306a4dc61083p-1},
       0x1.60710aefcd99p-8,
       6},
      {0x1.ff9034bc81183p-4,
       {0x1.0742b8d939afap-5, -0x1.e8f7820eeb6b5p-1, 0x1.2de4623ec71c1p-2},
       0x1.ff9034bc81182p-4,
       6},
  };
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 808);
  for (int t = 0; t < 6; t++) {
    urEllipsoid a, b;
    randell(rng, &a, 0.02, 0.22);
    randell(rng, &b, 0.02, 0.22);
    double d[3];
    gsl_ran_dir_3d(rng, d, d + 1, d + 2);
    double s = (0.4 + 0.75 * gsl_rng_uniform(rng)) * 0.3;
    for (int i = 0; i < 3; i++) {
      a.c[i] = 0.3 * gsl_rng_uniform(rng) - 0.15;
      b.c[i] = a.c[i] + s * d[i];
    }
    static const double ps[4][2] = {{0, 0}, {2, 2}, {2, 0}, {1.5, 2}};
    for (int k = 0; k < 4; k++) {
      a.p = ps[k][0];
      b.p = ps[k][1];
      double u[3] = {0, 0, 0};
      urGeomContact c, c2;
      ur_collide_ellipsoids(&a, &b, u, &c);
      double w[3] = {u[0] + 0.01, u[1], u[2]};
      ur_collide_ellipsoids(&a, &b, w, &c2);
      assert_true(c.g == rec[t].g && c2.g == rec[t].gwarm);
      assert_true(c.n[0] == rec[t].n[0] && c.n[1] == rec[t].n[1] && c.n[2] == rec[t].n[2]);
      assert_int_equal(c.iters, rec[t].iters);
    }
    a.p = b.p = 2 + 1e-10;
    double u[3] = {0, 0, 0};
    urGeomContact c;
    ur_collide_ellipsoids(&a, &b, u, &c);
    assert_near(c.g, rec[t].g, 1e-9);
  }
  gsl_rng_free(rng);
}

/* the bounding radius: above every one of 200000 surface samples and within 1e-3 of their
   maximum (exact); the largest semi-axis at p = 2; below the two simple bounds |r| and
   rmax 3^(1/2 - 1/p); the half-width ur_halfwidth_local against the definition; section area
   and cap volume refuse superellipsoids */
static void test_super_bound(void** state) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 31);
  double worst = 0;
  for (int t = 0; t < 40; t++) {
    urEllipsoid e;
    randell(rng, &e, 0.02, 0.3);
    e.p = t < 4 ? 2 + 1e-3 * t : 2 + 18 * gsl_rng_uniform(rng);
    double rb = ur_bound_radius(e.r, e.p), far = 0;
    double ga = M_PI * (3 - sqrt(5.0));
    const int N = 200000;
    for (int k = 0; k < N; k++) {
      double z = 1 - (2 * k + 1.0) / N, r = sqrt(1 - z * z),
             v[3] = {r * cos(ga * k), r * sin(ga * k), z};
      double x = 0;
      for (int l = 0; l < 3; l++) {
        double xl = e.r[l] * pow(fabs(v[l]), 2 / e.p);
        x += xl * xl;
      }
      far = fmax(far, sqrt(x));
    }
    // the corner itself, from the closed form of the maximiser
    double kk = 2 * e.p / (e.p - 2), sum = 0, x2 = 0;
    for (int l = 0; l < 3; l++) sum += pow(e.r[l], kk);
    for (int l = 0; l < 3; l++) x2 += e.r[l] * e.r[l] * pow(pow(e.r[l], kk) / sum, 2 / e.p);
    far = fmax(far, sqrt(x2));
    double rmax = fmax(e.r[0], fmax(e.r[1], e.r[2]));
    assert_true(rb >= far);
    assert_true(rb <= far * (1 + 1e-3));
    assert_true(rb <= sqrt(e.r[0] * e.r[0] + e.r[1] * e.r[1] + e.r[2] * e.r[2]) * (1 + 1e-14));
    assert_true(rb <= rmax * pow(3, 0.5 - 1 / e.p) * (1 + 1e-14));
    worst = fmax(worst, rb / far - 1);

    double u[3], w[3];
    randunit(rng, u);
    for (int l = 0; l < 3; l++) {
      w[l] = e.r[l] * (e.R[l] * u[0] + e.R[3 + l] * u[1] + e.R[6 + l] * u[2]);
    }
    assert_near(ur_halfwidth_local(w, e.p), hsup(&e, u), 1e-15);
    assert_true(isnan(ur_section_area(&e, u, 0.01)) == (e.p > 2));
    assert_true(isnan(ur_cap_volume(&e, u, 0.01)) == (e.p > 2));
  }
  double r[3] = {0.1, 0.3, 0.2};
  assert_true(ur_bound_radius(r, 2) == 0.3 && ur_bound_radius(r, 0) == 0.3);
  printf("bounding radius: at most %.3g above the farthest sampled surface point\n", worst);
  gsl_rng_free(rng);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_super_face),
      cmocka_unit_test(test_super_plane),
      cmocka_unit_test(test_super_pairs_bruteforce),
      cmocka_unit_test(test_super_warm),
      cmocka_unit_test(test_super_p2_bits),
      cmocka_unit_test(test_super_bound),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
