/* test_engine_contact.c: contact in the full engine against independent answers: Hertz
 * sphere-on-plane impact (peak penetration, contact time, restitution), momentum in a two-body
 * oblique collision with friction, sliding-to-rolling transition under Coulomb friction; the
 * superellipsoid's half-width, depth bound (bit for bit the minimum it skips work on) and
 * bounding radius; a foam's backing at the person's curvature. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "../../../src/core/engine/engine_internal.h"
#include "uasimpact/modellang.h"

// scalp on a flat (Table B1 of the paper)
static const double E1 = 2.23e7, NU1 = 0.29, E2 = 5.48e10, NU2 = 0.34, R = 0.0875;

//---------------------------------- Hertz impact --------------------------------------------------

static void hertz_sphere_plane(urIntegrator integ) {
  urModel* m = ur_model_new();
  double mass = 4.5, v = 3.0, Ic = 0.4 * mass * R * R;
  double I[6] = {Ic, Ic, Ic, 0, 0, 0}, ax[3] = {R, R, R};
  int b = ur_model_add_body(m, "head", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, b, mass, NULL, I);
  int g = ur_model_add_ellipsoid(m, "skull", b, NULL, NULL, ax);
  urLaw law = {0};
  ur_law_hertz(&law, E1, NU1, R, E2, NU2, 0, 0, 0, 0);
  int p = ur_model_add_pair(m, "skull_ground", g, -1, &law);
  ur_model_add_sensor(m, "contact", urSENS_CONTACT, p, 0, NULL, NULL);
  ur_model_add_sensor(m, "vel", urSENS_BODYVEL, b, 0, NULL, NULL);
  m->opt.gravity[2] = 0;
  m->opt.sample_dt = m->opt.dt;
  m->opt.t_quiet = 0.002;
  m->opt.integrator = integ;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  assert_int_equal(ur_data_history(m, d, NULL, 5000), 0);

  // fall from 1 m: the jump must bring it just above the ground
  double pos[3] = {0, 0, 1.0}, vel[3] = {0, 0, -v};
  int st = ur_run_impact(m, d, b, pos, NULL, vel);
  assert_int_equal(st, urSTAT_SEPARATED);
  print_message("hertz: jumped %.6f s (exact %.6f s), %ld steps\n", d->t_jump,
                (1.0 - R - m->opt.jump_margin) / v, d->nstep);
  assert_true(fabs(d->t_jump - (1.0 - R - m->opt.jump_margin) / v) < 1e-12);

  // independent answer
  double es = 1 / ((1 - NU1 * NU1) / E1 + (1 - NU2 * NU2) / E2);
  double K = 4.0 / 3.0 * es * sqrt(R);
  double dmax = pow(5 * mass * v * v / (4 * K), 0.4), tc = 2.94 * dmax / v;

  // measured: peak depth, contact duration from the 1e5 Hz history, rebound speed
  int n = 0;
  for (int i = 0; i < d->nhist; i++) {
    n += d->hist[i * (1 + m->nsensordata) + 1] > 0;
  }
  double tcm = n * m->opt.dt, dm = d->peakmax[1], vr = d->qvel[2];
  print_message(
      "hertz (%s): dmax %.5f mm (exact %.5f, err %.2e), tc %.4f ms (2.94 dmax/v %.4f, "
      "err %.2e), rebound %.4f m/s\n",
      integ == urINT_RK4 ? "RK4" : "Euler", 1e3 * dm, 1e3 * dmax, fabs(dm - dmax) / dmax, 1e3 * tcm,
      1e3 * tc, fabs(tcm - tc) / tc, vr);
  assert_true(fabs(dm - dmax) / dmax < 0.01);
  assert_true(fabs(tcm - tc) / tc < 0.02);
  assert_true(fabs(vr - v) / v < 0.01);
  ur_data_free(d);
  ur_model_free(m);
}

static void test_hertz_sphere_plane(void** state) {
  hertz_sphere_plane(urINT_EULER);
  hertz_sphere_plane(urINT_RK4);
}

//---------------------------------- two-body momentum --------------------------------------------

static void test_two_body_momentum(void** state) {
  urModel* m = ur_model_new();
  double IA[6] = {0.02, 0.03, 0.04, 0.001, 0, 0}, IB[6] = {0.05, 0.04, 0.03, 0, 0.002, 0};
  double cA[3] = {0.01, 0.02, -0.01}, cB[3] = {-0.02, 0.0, 0.03};
  double qa[4] = {0.9, 0.2, 0.1, -0.3}, qb[4] = {0.7, -0.3, 0.5, 0.2};
  int a = ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, a, 2.0, cA, IA);
  int b = ur_model_add_body(m, "b", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, b, 5.0, cB, IB);
  int ga = ur_model_add_ellipsoid(m, "ea", a, (double[3]){0.01, 0, 0}, qa,
                                  (double[3]){0.06, 0.09, 0.12});
  int gb = ur_model_add_ellipsoid(m, "eb", b, NULL, qb, (double[3]){0.15, 0.1, 0.08});
  urLaw law = {0};
  ur_law_hertz(&law, E1, NU1, 0.1, E1, NU1, 0.1, 0, 0, 0);
  law.mu = 0.3;
  law.v_eps = 1e-3;
  law.damping = 200;
  ur_model_add_pair(m, "ab", ga, gb, &law);
  m->opt.gravity[2] = 0;
  m->opt.t_quiet = 0.005;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  // B at rest (spinning), A thrown at it obliquely
  double p0[3], L0[3], p1[3], L1[3];
  ur_set_free(m, d, b, (double[3]){0, 0, 0}, NULL, NULL, (double[3]){0, 3, 1});
  double vel[3] = {4, 1.5, -2};
  assert_int_equal(ur_run_start(m, d, a, (double[3]){-0.8, -0.3, 0.4}, NULL, vel), 0);
  ur_forward(m, d);
  ur_momentum(m, d, p0, L0);
  double vb0 = d->qvel[6];
  int st = ur_run(m, d);
  ur_forward(m, d);
  ur_momentum(m, d, p1, L1);
  double dp = 0, np = 0, dl = 0, nl = 0;
  for (int k = 0; k < 3; k++) {
    dp += (p1[k] - p0[k]) * (p1[k] - p0[k]);
    np += p0[k] * p0[k];
    dl += (L1[k] - L0[k]) * (L1[k] - L0[k]);
    nl += L0[k] * L0[k];
  }
  dp = sqrt(dp / np);
  dl = sqrt(dl / nl);
  print_message(
      "two bodies: status %s, contact %.3f ms, B vx %.3f -> %.3f m/s, |dp|/|p| = "
      "%.2e, |dL|/|L| = %.2e\n",
      ur_status_str(st), 1e3 * (d->t_last - d->t_first), vb0, d->qvel[6], dp, dl);
  assert_int_equal(st, urSTAT_SEPARATED);
  assert_true(fabs(d->qvel[6] - vb0) > 0.5);
  assert_true(dp < 1e-9);
  assert_true(dl < 1e-4);
  ur_data_free(d);
  ur_model_free(m);
}

//---------------------------------- friction ------------------------------------------------------

// a sliding solid sphere starts rolling at 5/7 of its initial speed; with v_eps = 1e-8 the
// regularised friction is far too stiff for the explicit step (mu fn dt / (m_t v_eps) ~ 1e3)
// unless the engine's stability floor acts
static void slide_to_roll(double v_eps) {
  urModel* m = ur_model_new();
  double mass = 1.0, r = 0.05, Ic = 0.4 * mass * r * r, v0 = 2.0, mu = 0.4;
  double I[6] = {Ic, Ic, Ic, 0, 0, 0};
  int b = ur_model_add_body(m, "ball", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, b, mass, NULL, I);
  int g = ur_model_add_ellipsoid(m, "ball", b, NULL, NULL, (double[3]){r, r, r});
  urLaw law = {0};
  ur_law_hertz(&law, 1e8, 0.3, r, 2e11, 0.3, 0, 0, 0, 0);
  law.damping = 300;
  law.mu = mu;
  law.v_eps = v_eps;
  ur_model_add_pair(m, "ball_ground", g, -1, &law);
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  // start at the static penetration, sliding without spin
  double K = 4.0 / 3.0 / ((1 - 0.09) / 1e8 + (1 - 0.09) / 2e11) * sqrt(r);
  double ds = pow(mass * 9.81 / K, 2.0 / 3.0);
  ur_set_free(m, d, b, (double[3]){0, 0, r - ds}, NULL, (double[3]){v0, 0, 0}, NULL);
  double ts = 2 * v0 / (7 * mu * 9.81);
  for (int i = 0; i < (int)(1.5 * ts / m->opt.dt); i++) {
    assert_int_equal(ur_step(m, d), urSTAT_OK);
  }
  double vx = d->qvel[0], wy = d->qvel[4];
  print_message(
      "slide-to-roll (v_eps %.0e): v %.5f m/s (exact 5/7 v0 = %.5f), omega r %.5f, "
      "z %.6f m\n",
      v_eps, vx, 5 * v0 / 7, wy * r, d->qpos[2]);
  assert_true(fabs(vx - 5 * v0 / 7) / (5 * v0 / 7) < 0.01);
  assert_true(fabs(wy * r - vx) / vx < 0.01);
  ur_data_free(d);
  ur_model_free(m);
}


static void test_slide_to_roll(void** state) {
  slide_to_roll(1e-4);
  slide_to_roll(1e-8);
}


//---------------------------------- superellipsoids -----------------------------------------------

/* a superellipsoid (degree 6) and an ellipsoid on two free bodies at random poses: the engine's
   half-width is ||diag(r) R^T u||_q (q = 6/5) from the definition, the ellipsoid's unchanged;
   the depth bound is at least the exact depth and equals the support-function gap along the
   centre line; the bounding radius is ||r||_3, the ellipsoid's its largest semi-axis */
static void test_superellipsoid_bounds(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {1, 1, 1, 0, 0, 0}, ra[3] = {0.3, 0.2, 0.06}, rb[3] = {0.08, 0.1, 0.12};
  int a = ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL);
  int b = ur_model_add_body(m, "b", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, a, 1, NULL, I);
  ur_model_set_inertia(m, b, 1, NULL, I);
  double q0[4] = {cos(0.3), sin(0.3) * 0.6, 0, sin(0.3) * 0.8};
  int ga = ur_model_add_ellipsoid(m, "frame", a, NULL, q0, ra);
  int gb = ur_model_add_ellipsoid(m, "head", b, NULL, NULL, rb);
  assert_int_equal(ur_model_set_degree(m, ga, 6), 0);
  assert_int_equal(ur_model_set_degree(m, ga, 1.5), -1);
  assert_int_equal(ur_model_set_degree(m, ga, 21), -1);
  assert_true(m->geom[ga].degree == 6 && m->geom[gb].degree == 2);
  assert_true(fabs(m->geom[ga].rbound - cbrt(0.027 + 0.008 + 0.000216)) < 1e-15);
  assert_true(m->geom[gb].rbound == 0.12);

  // a foam pair must take the ellipsoid as a, an airbag its targets of degree 2
  urLaw foam = {0};
  foam.type = urLAW_FOAM;
  assert_int_equal(ur_model_add_pair(m, "p1", ga, gb, &foam), -1);
  assert_int_equal(ur_model_add_pair(m, "p2", gb, ga, &foam), 0);
  assert_int_equal(ur_model_set_degree(m, gb, 4), -1);
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  srand(7);
  for (int t = 0; t < 200; t++) {
    for (int k = 0; k < 2; k++) {
      double *q = d->qpos + 7 * k, n = 0;
      for (int i = 0; i < 3; i++) q[i] = 0.6 * rand() / RAND_MAX - 0.3;
      for (int i = 3; i < 7; i++) {
        q[i] = 2.0 * rand() / RAND_MAX - 1;
        n += q[i] * q[i];
      }
      for (int i = 3; i < 7; i++) q[i] /= sqrt(n);
    }
    ur_kinematics(m, d);
    urEllipsoid ea, eb;
    ur_geom_ellipsoid(m, d, ga, &ea);
    ur_geom_ellipsoid(m, d, gb, &eb);
    assert_true(ea.p == 6 && eb.p == 2);

    // half-widths from the definition
    double u[3] = {2.0 * rand() / RAND_MAX - 1, 2.0 * rand() / RAND_MAX - 1,
                   2.0 * rand() / RAND_MAX - 1};
    double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), sa = 0, sb = 0;
    for (int i = 0; i < 3; i++) u[i] /= un;
    for (int k = 0; k < 3; k++) {
      double va = ea.R[k] * u[0] + ea.R[3 + k] * u[1] + ea.R[6 + k] * u[2];
      double vb = eb.R[k] * u[0] + eb.R[3 + k] * u[1] + eb.R[6 + k] * u[2];
      sa += pow(fabs(ra[k] * va), 1.2);
      sb += rb[k] * rb[k] * vb * vb;
    }
    assert_true(fabs(ur_geom_halfwidth(m, d, ga, u) - pow(sa, 1 / 1.2)) < 1e-15);
    assert_true(fabs(ur_geom_halfwidth(m, d, gb, u) - sqrt(sb)) < 1e-15);

    // the depth bound
    double z[3] = {0, 0, 0}, w[3] = {0, 0, 0};
    urGeomContact gc;
    ur_collide_ellipsoids(&ea, &eb, w, &gc);
    double fb = ur_depth_bound(m, d, ga, gb, z), fu = ur_depth_bound(m, d, ga, gb, u);
    assert_true(fb >= gc.g - 1e-15 && fu >= gc.g - 1e-15 && fu <= fb);
    double dc[3], L = 0;
    for (int i = 0; i < 3; i++) {
      dc[i] = eb.c[i] - ea.c[i];
      L += dc[i] * dc[i];
    }
    L = sqrt(L);
    for (int i = 0; i < 3; i++) dc[i] /= L;
    assert_true(fabs(fb - (-L + ur_geom_halfwidth(m, d, ga, dc) +
                           ur_geom_halfwidth(m, d, gb, dc))) < 1e-15);
  }
  ur_data_free(d);
  ur_model_free(m);
}

/* a foam whose backing is derived from a person's layer without a radius: past the lock the
   backing's Hertz force takes the radius of the person's part (a) at the contact, here an
   ellipsoid's pole on the ground, R = a b / c (the foam flat: the ground) */
static void test_foam_backing_curvature(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {1, 1, 1, 0, 0, 0}, ax[3] = {0.1, 0.2, 0.15};
  int b = ur_model_add_body(m, "torso", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, b, 30, NULL, I);
  int g = ur_model_add_ellipsoid(m, "chest", b, NULL, NULL, ax);
  urLaw foam = {0};
  foam.type = urLAW_FOAM;
  urCurve st = {2, {0, 0.9}, {0, 0.9e6}};
  foam.stress = st;
  foam.thickness = 0.02;
  foam.lock = 0.5;
  double es = 1 / ((1 - 0.45 * 0.45) / 2e5 + (1 - NU2 * NU2) / E2);
  foam.backing_estar = es;
  foam.backing_r = urHERTZ_CURVATURE;
  assert_int_equal(ur_model_add_pair(m, "cg", g, -1, &foam), 0);
  m->opt.gravity[2] = 0;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  // 4 mm past the lock depth (10 mm)
  double dep = 0.014, x = dep - 0.01, Rc = 0.1 * 0.2 / 0.15;
  d->qpos[2] = 0.15 - dep;
  d->qpos[3] = 1;
  ur_kinematics(m, d);
  ur_contacts(m, d);
  urEllipsoid e;
  ur_geom_ellipsoid(m, d, g, &e);
  double n[3] = {0, 0, -1};
  double A = ur_section_area(&e, n, dep);
  double fref = A * 0.5e6 + 4.0 / 3.0 * es * sqrt(Rc) * x * sqrt(x);
  print_message("foam on a curved backing: F %.9g N (expected %.9g), R %.9g m (a b / c %.9g)\n",
                d->pair[0].fn, fref, d->pair[0].radius, Rc);
  assert_true(fabs(d->pair[0].radius - Rc) < 1e-9);
  assert_true(fabs(d->pair[0].fn - fref) < 1e-9 * fref);

  // the commit takes the same backing: the state records the depth and the lock force
  ur_contacts_commit(m, d);
  assert_true(fabs(d->pair[0].ls.dmax - dep) < 1e-12 && d->pair[0].ls.touching == 1);
  ur_data_free(d);
  ur_model_free(m);
}

/* ur_depth_bound skips, for a superellipsoid, the direction whose cheap lower bound lies above
   the other direction's value (issue 36): the bound must stay bit for bit the minimum of f over
   the centre line and the warm start, evaluated in full here, at random poses, warm starts
   random and close to the centre line (both directions evaluated), each shape as a and as b.
   ur_depth_cull also skips the directions whose lower bound lies above 0: it must be negative
   exactly when the minimum is, and then equal to it bit for bit */
static void test_depth_bound_exact(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {1, 1, 1, 0, 0, 0}, ra[3] = {0.3, 0.2, 0.06}, rb[3] = {0.08, 0.1, 0.12};
  int a = ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL);
  int b = ur_model_add_body(m, "b", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, a, 1, NULL, I);
  ur_model_set_inertia(m, b, 1, NULL, I);
  int ga = ur_model_add_ellipsoid(m, "frame", a, NULL, NULL, ra);
  int gb = ur_model_add_ellipsoid(m, "head", b, NULL, NULL, rb);
  assert_int_equal(ur_model_set_degree(m, ga, 4.5), 0);
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);

  srand(11);
  int n = 0, ncull = 0;
  for (int t = 0; t < 2000; t++) {
    for (int k = 0; k < 2; k++) {
      double *q = d->qpos + 7 * k, s = 0;
      for (int i = 0; i < 3; i++) q[i] = 0.8 * rand() / RAND_MAX - 0.4;
      for (int i = 3; i < 7; i++) {
        q[i] = 2.0 * rand() / RAND_MAX - 1;
        s += q[i] * q[i];
      }
      for (int i = 3; i < 7; i++) q[i] /= sqrt(s);
    }
    ur_kinematics(m, d);
    for (int sw = 0; sw < 2; sw++) {
      int g1 = sw ? gb : ga, g2 = sw ? ga : gb;
      const double *c1 = d->gxpos + 3 * g1, *c2 = d->gxpos + 3 * g2;
      double dc[3] = {c1[0] - c2[0], c1[1] - c2[1], c1[2] - c2[2]};
      double L = sqrt(dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2]);
      double c[3] = {-dc[0] / L, -dc[1] / L, -dc[2] / L}, u[3], un = 0;
      double jit = t % 2 ? 1 : 1e-6; /* random, or near the centre line */
      for (int i = 0; i < 3; i++) {
        u[i] = c[i] + jit * (2.0 * rand() / RAND_MAX - 1);
        un += u[i] * u[i];
      }
      for (int i = 0; i < 3; i++) u[i] /= sqrt(un);
      double f = -L + ur_geom_halfwidth(m, d, g1, c) + ur_geom_halfwidth(m, d, g2, c);
      f = fmin(f, dc[0] * u[0] + dc[1] * u[1] + dc[2] * u[2] + ur_geom_halfwidth(m, d, g1, u) +
                      ur_geom_halfwidth(m, d, g2, u));
      double fb = ur_depth_bound(m, d, g1, g2, u);
      if (memcmp(&f, &fb, sizeof f)) {
        fail_msg("pose %d (%s): depth bound %.17g, the minimum %.17g", t, sw ? "b, a" : "a, b", fb,
                 f);
      }
      // the culling form: negative exactly when the minimum is, and then the same bits
      double fk = ur_depth_cull(m, d, g1, g2, u);
      if ((fk < 0) != (f < 0) || (f < 0 && memcmp(&f, &fk, sizeof f))) {
        fail_msg("pose %d (%s): culling bound %.17g, the minimum %.17g", t, sw ? "b, a" : "a, b",
                 fk, f);
      }
      ncull += f < 0;
      n++;
    }
  }
  print_message("depth bound: %d cases bit for bit (%d culled)\n", n, ncull);
  assert_true(ncull > n / 10 && ncull < n - n / 10); /* both kinds well represented */
  ur_data_free(d);
  ur_model_free(m);
}

/* a pair that still holds a touching history and that the narrow phase finds separated was
   listed to commit twice (once as touching, once more as if culled): the list outgrew the pairs
   and the next pass wrote past its stack array (make fuzz, issue 24). The model the fuzzer
   found: every pass lists each pair at most once (the overflow itself, in the middle of an RK4
   step, is what UBSan reports under make check-san) */
static void test_commit_list_once(void** state) {
  FILE* f = fopen("tests/fuzz/corpus_model/crash-commit-list-duplicate", "r");
  assert_non_null(f);
  char text[4096];
  size_t n = fread(text, 1, sizeof text - 1, f);
  fclose(f);
  text[n] = 0;
  char err[300];
  urModelSource src = {text, "fuzz", 1};
  urModel* m = ur_model_parse(&src, 1, NULL, 0, err, sizeof err);
  if (!m) fail_msg("%s", err);
  urData* d = ur_data_new(m);
  for (int i = 0; i < 8 && ur_step(m, d) >= 0; i++) {
    ur_kinematics(m, d);
    ur_contacts(m, d); /* a pass at the step's end, checked */
    assert_true(d->npcommit <= m->npair);
    for (int a = 0; a < d->npcommit; a++) {
      for (int b = 0; b < a; b++) assert_int_not_equal(d->plist[a], d->plist[b]);
    }
  }
  ur_data_free(d);
  ur_model_free(m);
}

/* the one enumeration of contact candidates: the pairs in order, then each airbag's targets in
   order, dense indices, and the slots of urImpactSetup.cand_src (npair + bag * urMAXBAGTGT + t) */
static void test_candidates(void** state) {
  (void)state;
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int a = ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, a, 1, NULL, I);
  int b = ur_model_add_body(m, "b", -1, urJNT_FREE, (double[3]){0, 0, 1}, NULL);
  ur_model_set_inertia(m, b, 1, NULL, I);
  int ga = ur_model_add_ellipsoid(m, "ga", a, NULL, NULL, (double[3]){0.1, 0.1, 0.1});
  int gb = ur_model_add_ellipsoid(m, "gb", b, NULL, NULL, (double[3]){0.1, 0.1, 0.1});
  int gc = ur_model_add_ellipsoid(m, "gc", b, NULL, NULL, (double[3]){0.1, 0.1, 0.1});
  urLaw law = {0};
  ur_law_hertz(&law, 1e8, 0.3, 0.1, 1e8, 0.3, 0.1, 0, 0, 0);
  ur_model_add_pair(m, "ab", ga, gb, &law);
  ur_model_add_pair(m, "ground", ga, -1, &law);
  for (int i = 0; i < 2; i++) {
    urAirbag bag = {0};
    snprintf(bag.name, sizeof bag.name, "bag%d", i);
    bag.geom = ga;
    bag.gas.v0 = 0.02;
    bag.gas.p0 = bag.gas.patm = 101325;
    bag.gas.gamma = 1.4;
    bag.kappa = 1;
    bag.thickness = 0.05;
    bag.ntarget = i + 1;
    bag.target[0] = gc;
    bag.target[1] = gb;
    ur_model_add_airbag(m, &bag);
  }
  assert_int_equal(ur_model_compile(m), 0);

  const int want[][5] = {{ga, gb, -1, 0, 0},
                         {ga, -1, -1, 1, 1},
                         {ga, gc, 0, 0, 2},
                         {ga, gc, 1, 0, 2 + urMAXBAGTGT},
                         {ga, gb, 1, 1, 3 + urMAXBAGTGT}};
  assert_int_equal(ur_cand_count(m), 5);
  urCand c;
  for (int k = 0; k < 5; k++) {
    assert_int_equal(ur_cand_at(m, k, &c), 0);
    assert_int_equal(c.g1, want[k][0]);
    assert_int_equal(c.g2, want[k][1]);
    assert_int_equal(c.bag, want[k][2]);
    assert_int_equal(c.idx, want[k][3]);
    assert_int_equal(c.src, want[k][4]);
  }
  assert_int_equal(ur_cand_at(m, 5, &c), -1);
  assert_int_equal(ur_cand_at(m, -1, &c), -1);
  assert_int_equal(ur_cand_slots(m), 2 + 2 * urMAXBAGTGT);
  assert_true(ur_geom_intree(m, gc, b) && !ur_geom_intree(m, gc, a) && !ur_geom_intree(m, -1, a));
  ur_model_free(m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_candidates),
      cmocka_unit_test(test_hertz_sphere_plane),
      cmocka_unit_test(test_two_body_momentum),
      cmocka_unit_test(test_slide_to_roll),
      cmocka_unit_test(test_superellipsoid_bounds),
      cmocka_unit_test(test_depth_bound_exact),
      cmocka_unit_test(test_commit_list_once),
      cmocka_unit_test(test_foam_backing_curvature),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
