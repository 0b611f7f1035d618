/* test_engine_run.c: runs on a drone-on-human scene: thread safety (two threads give results
 * bitwise identical to sequential runs), failure reporting (non-finite and exploding states),
 * stop requests, free-flight jump, history sampling, builder errors and name look-up; the end
 * of a run with t_clear, on two balls, and the spin bound its proof uses. */
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "uasimpact/contact.h"
#include "uasimpact/engine.h"
#include "../../../src/core/engine/engine_internal.h"
#include "test_engine_scene.h"

#define ROWS 2000

typedef struct {
  const urModel* m;
  urData* d;
  double offset; /* horizontal offset of the drone, m */
  double speed;  /* descent speed, m/s */
  int status;
} job;


static void* runjob(void* arg) {
  job* j = arg;
  double pos[3] = {j->offset, 0.3 * j->offset, 2.2}, vel[3] = {0, 0, -j->speed};
  ur_data_reset(j->m, j->d);
  j->status = ur_run_impact(j->m, j->d, ur_name_body(j->m, "drone"), pos, NULL, vel);
  return NULL;
}


// two different runs in two threads = the same runs one after the other, bit for bit
static void test_threads_bitwise(void** state) {
  urModel* m = scene_build(1);
  assert_non_null(m);
  urData* d[4];
  static double buf[4][ROWS * 64];
  assert_true(1 + m->nsensordata <= 64);
  for (int i = 0; i < 4; i++) {
    d[i] = ur_data_new(m);
    assert_int_equal(ur_data_history(m, d[i], buf[i], ROWS), 0);
  }
  job jobs[4] = {{m, d[0], 0.05, 7.5, 0},
                 {m, d[1], 0.12, 12.5, 0},
                 {m, d[2], 0.05, 7.5, 0},
                 {m, d[3], 0.12, 12.5, 0}};

  // sequential, then concurrent
  runjob(jobs + 0);
  runjob(jobs + 1);
  pthread_t th[2];
  pthread_create(th + 0, NULL, runjob, jobs + 2);
  pthread_create(th + 1, NULL, runjob, jobs + 3);
  pthread_join(th[0], NULL);
  pthread_join(th[1], NULL);

  // compare
  int ns = m->nsensordata;
  for (int i = 0; i < 2; i++) {
    print_message("run %d: %s, %d rows, %ld steps, peak head acc z %.1f m/s^2, neck Fz %.0f N\n", i,
                  ur_status_str(jobs[i].status), d[i]->nhist, d[i]->nstep, d[i]->peakmax[2],
                  d[i]->peakmin[5]);
    assert_true(jobs[i].status > 0);
    assert_int_equal(jobs[i].status, jobs[i + 2].status);
    assert_int_equal(d[i]->nhist, d[i + 2]->nhist);
    assert_true(d[i]->nhist > 10);
    assert_int_equal(memcmp(buf[i], buf[i + 2], (size_t)d[i]->nhist * (1 + ns) * sizeof(double)),
                     0);
    assert_int_equal(memcmp(d[i]->qpos, d[i + 2]->qpos, (size_t)m->nq * sizeof(double)), 0);
    assert_int_equal(memcmp(d[i]->peakmax, d[i + 2]->peakmax, (size_t)ns * sizeof(double)), 0);
  }

  // the two runs differ (so the comparison is not vacuous)
  assert_true(memcmp(d[0]->qpos, d[1]->qpos, (size_t)m->nq * sizeof(double)) != 0);
  assert_true(d[0]->peakmax[2] != d[1]->peakmax[2]);
  for (int i = 0; i < 4; i++) {
    ur_data_free(d[i]);
  }
  ur_model_free(m);
}


// a symmetric impact (offset in the symmetry plane y = 0) stays symmetric: no lateral head
// acceleration grows (stiff regularised friction at near-zero lateral slip must stay stable)
static void test_symmetric_impact(void** state) {
  urModel* m = scene_build(1);
  urData* d = ur_data_new(m);
  double pos[3] = {0.05, 0, 2.2}, vel[3] = {0, 0, -7.5};
  int st = ur_run_impact(m, d, ur_name_body(m, "drone"), pos, NULL, vel);
  double ay = fmax(fabs(d->peakmax[1]), fabs(d->peakmin[1]));
  double ax = fmax(fabs(d->peakmax[0]), fabs(d->peakmin[0]));
  double az = fmax(fabs(d->peakmax[2]), fabs(d->peakmin[2]));
  print_message("symmetric impact: %s, peak |a| x %.1f y %.2e z %.1f m/s^2\n", ur_status_str(st),
                ax, ay, az);
  assert_true(st > 0);
  assert_true(az > 100);
  assert_true(ay < 1e-6 * az);
  ur_data_free(d);
  ur_model_free(m);
}


// a NaN in the state stops the run with a failure status and a reason
static void test_nonfinite_fails(void** state) {
  urModel* m = scene_build(0);
  urData* d = ur_data_new(m);
  assert_int_equal(ur_step(m, d), urSTAT_OK);
  d->qvel[3] = NAN;
  int st = ur_step(m, d);
  print_message("non-finite: status %d (%s): %s\n", st, ur_status_str(st), d->msg);
  assert_int_equal(st, urSTAT_NONFINITE);
  assert_true(strlen(d->msg) > 0);

  // sticky: further steps and runs do nothing
  double t = d->time;
  assert_int_equal(ur_step(m, d), urSTAT_NONFINITE);
  assert_int_equal(ur_run(m, d), urSTAT_NONFINITE);
  assert_true(d->time == t);

  // a reset clears it
  ur_data_reset(m, d);
  assert_int_equal(d->status, urSTAT_OK);
  assert_int_equal(ur_step(m, d), urSTAT_OK);
  ur_data_free(d);
  ur_model_free(m);
}


// an unstable step (stiff restraint, large dt) is reported as a failed run, never a number
static void test_explosion_fails(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int b = ur_model_add_body(m, "arm", -1, urJNT_REVOLUTE, NULL, NULL);
  ur_model_set_inertia(m, b, 1, (double[3]){0.1, 0, 0}, I);
  urRestraint r = {0};
  r.k = 1e9;
  ur_model_set_restraint(m, b, 0, &r);
  m->opt.dt = 1e-3;
  m->opt.tmax = 1;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  d->qpos[0] = 0.01;
  int st = ur_run(m, d);
  print_message("explosion: status %d (%s) after %ld steps: %s\n", st, ur_status_str(st), d->nstep,
                d->msg);
  assert_true(st < 0);
  assert_true(d->nstep < 1000);
  ur_data_free(d);
  ur_model_free(m);
}


// a stop request (opt.stop, set by an interrupt) fails the run at its next step, and only then
static void test_stop_request(void** state) {
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int b = ur_model_add_body(m, "arm", -1, urJNT_REVOLUTE, NULL, NULL);
  ur_model_set_inertia(m, b, 1, (double[3]){0.1, 0, 0}, I);
  _Atomic int stop = 0;
  m->opt.stop = &stop;
  m->opt.tmax = 1;
  assert_int_equal(ur_model_compile(m), 0);
  urData* d = ur_data_new(m);
  for (int i = 0; i < 10; i++) assert_int_equal(ur_step(m, d), urSTAT_OK);
  long n = d->nstep;
  stop = 1;
  assert_int_equal(ur_step(m, d), urSTAT_STOPPED);
  assert_int_equal(d->nstep, n);
  assert_string_equal(ur_status_str(urSTAT_STOPPED), "failed: stopped on request");
  assert_int_equal(ur_run(m, d), urSTAT_STOPPED);
  ur_data_free(d);
  ur_model_free(m);
}


// the jump stops the drone between jump_margin and 2 jump_margin before its first real contact
// (conservative advancement on the exact distances, after the bounding-sphere jump)
static void test_jump(void** state) {
  urModel* m = scene_build(0);
  urData* d = ur_data_new(m);
  int dr = ur_name_body(m, "drone");
  double pos[3] = {0.01, 0, 4.0}, vel[3] = {1, 0, -10};
  assert_int_equal(ur_run_start(m, d, dr, pos, NULL, vel), urSTAT_OK);

  // smallest gaps after the jump: bounding spheres, and exact ellipsoid distances
  double gsphere = INFINITY, gexact = INFINITY;
  for (int i = 0; i < m->npair; i++) {
    int a = m->pair[i].geom1, b = m->pair[i].geom2;
    if (b < 0) {
      continue;
    }
    double dx[3];
    for (int k = 0; k < 3; k++) {
      dx[k] = d->gxpos[3 * a + k] - d->gxpos[3 * b + k];
    }
    double gap =
        sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]) - m->geom[a].rbound - m->geom[b].rbound;
    gsphere = fmin(gsphere, gap);
    urEllipsoid ea, eb;
    urGeomContact gc;
    double u[3] = {0, 0, 0};
    memcpy(ea.c, d->gxpos + 3 * a, sizeof ea.c);
    memcpy(ea.R, d->gxmat + 9 * a, sizeof ea.R);
    memcpy(ea.r, m->geom[a].size, sizeof ea.r);
    memcpy(eb.c, d->gxpos + 3 * b, sizeof eb.c);
    memcpy(eb.R, d->gxmat + 9 * b, sizeof eb.R);
    memcpy(eb.r, m->geom[b].size, sizeof eb.r);
    ur_collide_ellipsoids(&ea, &eb, u, &gc);
    gexact = fmin(gexact, -gc.g);
  }
  print_message(
      "jump: %.6f s, smallest gaps after it: spheres %.3e m, exact %.3e m (margin "
      "%.0e)\n",
      d->t_jump, gsphere, gexact, m->opt.jump_margin);
  assert_true(gexact >= m->opt.jump_margin - 1e-12);
  assert_true(gexact <= 2 * m->opt.jump_margin);
  assert_true(gsphere <= m->opt.jump_margin + 1e-9);
  assert_true(fabs(d->qpos[m->body[dr].qadr] - (0.01 + d->t_jump)) < 1e-12);
  assert_true(d->time == d->t_jump);
  ur_data_free(d);
  ur_model_free(m);
}


// histories at 10 kHz by default; caller and engine buffers; builder errors and names
static void test_history_and_names(void** state) {
  urModel* m = scene_build(1);
  urData* d = ur_data_new(m);
  assert_int_equal(ur_data_history(m, d, NULL, 100), 0);
  for (int i = 0; i < 1000; i++) {
    ur_step(m, d);
  }
  int w = 1 + m->nsensordata;
  assert_int_equal(d->nhist, 100);
  assert_true(fabs(d->hist[w] - 1e-4) < 1e-12);
  assert_true(fabs(d->hist[99 * w] - 99e-4) < 1e-12);

  // names
  assert_int_equal(ur_name_body(m, "head"), 4);
  assert_int_equal(ur_name_joint(m, "head"), 4);
  assert_true(ur_name_sensor(m, "upper_neck") >= 0);
  assert_true(ur_name_pair(m, "motor3_head") >= 0);
  assert_int_equal(ur_name_body(m, "nobody"), -1);
  ur_data_free(d);
  ur_model_free(m);

  // builder errors
  m = ur_model_new();
  int b = ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL);
  assert_int_equal(ur_model_add_body(m, "a", -1, urJNT_FREE, NULL, NULL), -1);
  assert_true(strstr(m->err, "duplicate") != NULL);
  assert_int_equal(ur_model_add_body(m, "b", 5, urJNT_FREE, NULL, NULL), -1);
  assert_int_equal(ur_model_add_ellipsoid(m, "e", b, NULL, NULL, (double[3]){1, 0, 1}), -1);
  assert_int_equal(ur_model_compile(m), -1);
  assert_true(strstr(m->err, "mass") != NULL);
  ur_model_set_inertia(m, b, 1, NULL, (double[6]){1, 1, 1, 0, 0, 0});
  assert_true(ur_model_set_param(m, "hic_window", 0.015) >= 0);
  assert_int_equal(ur_model_compile(m), 0);
  assert_true(ur_model_param(m, "hic_window", 0) == 0.015);
  assert_true(ur_model_param(m, "absent", -2) == -2);
  assert_int_equal(ur_model_add_body(m, "c", -1, urJNT_FREE, NULL, NULL), -1);
  ur_model_free(m);
}

//---------------------------------- end of a run: t_clear -----------------------------------------

// a 1 kg ball (r 0.05 m) and two fixed balls (r 0.1 m) at the origin and at (xb, 0, zb), linear
// elastic contact, no gravity; t_quiet 0.05 s; with bag, the ball carries a small membrane airbag
// whose target is the second fixed ball
static urModel* balls_bag(double xb, double zb, double t_clear, double a_clear, int bag) {
  urModel* m = ur_model_new();
  double I[6] = {1e-3, 1e-3, 1e-3, 0, 0, 0};
  int p = ur_model_add_body(m, "ball", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, p, 1, NULL, I);
  int gp = ur_model_add_ellipsoid(m, "ball", p, NULL, NULL, (double[3]){0.05, 0.05, 0.05});
  urLaw law = {0};
  law.type = urLAW_TABLE;
  law.load.n = 2;
  law.load.x[1] = 0.01;
  law.load.y[1] = 2000;
  for (int k = 0; k < 2; k++) {
    char name[8];
    snprintf(name, sizeof name, "t%d", k);
    int b = ur_model_add_body(m, name, -1, urJNT_FIXED, (double[3]){k * xb, 0, k * zb}, NULL);
    ur_model_set_inertia(m, b, 1, NULL, I);
    int g = ur_model_add_ellipsoid(m, name, b, NULL, NULL, (double[3]){0.1, 0.1, 0.1});
    ur_model_add_pair(m, name, gp, g, &law);
    if (bag && k == 1) {
      urAirbag ab = {0};
      strcpy(ab.name, "bag");
      ab.type = urBAG_MEMBRANE;
      ab.geom = ur_model_add_ellipsoid(m, "bag", p, NULL, NULL, (double[3]){0.05, 0.05, 0.05});
      ab.ntarget = 1;
      ab.target[0] = g;
      ur_mem_spec_default(&ab.mspec);
      ab.mspec.a = ab.mspec.b = 0.05;
      ab.mspec.depth = 0.04;
      ab.mspec.mesh = 2;
      ab.mspec.patm = 101325;
      ab.mspec.p0 = 1.1 * 101325;
      assert_true(ur_model_add_airbag(m, &ab) >= 0);
    }
  }
  m->opt.gravity[2] = 0;
  m->opt.dt = 1e-4;
  m->opt.t_quiet = 0.05;
  m->opt.t_clear = t_clear;
  m->opt.a_clear = a_clear;
  assert_int_equal(ur_model_compile(m), 0);
  char err[160];
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0); /* a membrane bag: before it runs */
  return m;
}


static urModel* balls(double xb, double zb, double t_clear, double a_clear) {
  return balls_bag(xb, zb, t_clear, a_clear, 0);
}


// one run of the balls (t_quiet, tmax: 0 keeps the default) from pos at vel; times of the last
// contact and of the end, after the first contact
typedef struct {
  double xb, zb, t_clear, a_clear, t_quiet, tmax, pos[3], vel[3];
} ballRun;

static void run_balls(const ballRun* b, double* tlast, double* tend) {
  urModel* m = balls(b->xb, b->zb, b->t_clear, b->a_clear);
  if (b->t_quiet > 0) m->opt.t_quiet = b->t_quiet;
  if (b->tmax > 0) m->opt.tmax = b->tmax;
  urData* d = ur_data_new(m);
  assert_int_equal(ur_run_impact(m, d, 0, b->pos, NULL, b->vel), urSTAT_SEPARATED);
  *tlast = d->t_last - d->t_first;
  *tend = d->time - d->t_first;
  ur_data_free(d);
  ur_model_free(m);
}


// a ball rebounding straight up from the first target: without t_clear the run ends at t_quiet;
// with it as soon as the separation provably cannot close by t_quiet: the ball recedes along the
// centre line (a_clear 0), so at t_clear
static void test_clear_ends_early(void** state) {
  double tlast[2], tend[2];
  for (int k = 0; k < 2; k++) {
    ballRun b = {5, 0, k ? 0.005 : INFINITY, 0, 0, 0, {0, 0, 0.3}, {0, 0, -2}};
    run_balls(&b, tlast + k, tend + k);
  }
  print_message(
      "ball rebound: run ends %.4f s after the contact (t_quiet alone), %.4f s "
      "(t_clear 0.005)\n",
      tend[0] - tlast[0], tend[1] - tlast[1]);
  assert_true(fabs(tend[0] - tlast[0] - 0.05) < 2e-4);
  assert_true(tend[1] - tlast[1] > 0.005 && tend[1] - tlast[1] < 0.0053);
}


// a ball glancing off the first target toward the second one, 0.4 m on and 0.35 m higher: the
// second contact comes about 0.2 s later, so no end is proved in between and the run is the one
// without t_clear
static void test_clear_keeps_recontact(void** state) {
  double tlast[2], tend[2];
  for (int k = 0; k < 2; k++) {
    ballRun b = {0.4, 0.35, k ? 0.005 : INFINITY, 100, 0.3, 2, {-0.4, 0, 0.14}, {2, 0, 0}};
    run_balls(&b, tlast + k, tend + k);
  }
  print_message(
      "glancing ball: last contact %.4f / %.4f s after the first, end %.4f / %.4f s "
      "(without / with t_clear)\n",
      tlast[0], tlast[1], tend[0], tend[1]);
  assert_true(tlast[0] > 0.1); /* the second target was reached */
  assert_true(tlast[1] == tlast[0]);
}


// the rebound of test_clear_ends_early with a membrane airbag on the ball, aimed at the far
// target: a membrane bag's fabric is not its declared ellipsoid, so the proof never claims its
// target clear and the run ends at t_quiet (without the bag, at t_clear)
static void test_clear_membrane_bag(void** state) {
  double tend[2];
  for (int k = 0; k < 2; k++) {
    urModel* m = balls_bag(5, 0, 0.005, 0, k);
    urData* d = ur_data_new(m);
    assert_int_equal(ur_run_impact(m, d, 0, (double[3]){0, 0, 0.3}, NULL, (double[3]){0, 0, -2}),
                     urSTAT_SEPARATED);
    tend[k] = d->time - d->t_last;
    ur_data_free(d);
    ur_model_free(m);
  }
  print_message("rebound: run ends %.4f s after the contact without the bag, %.4f s with it\n",
                tend[0], tend[1]);
  assert_true(tend[0] < 0.006);
  assert_true(fabs(tend[1] - 0.05) < 2e-4);
}


// a ball glancing off the first target and sliding on past it (the second one far away): the
// distance then grows slowly while the ball still moves fast, so the closing-speed bound |v| T
// proves nothing for a while, but along the centre line the ball recedes; with the engine's
// settings for impacts (t_quiet 0.02 s, t_clear 0.002 s, a_clear 100) the run ends soon after
// t_clear (2.6 ms after the contact: the gap must first open a little), long before t_quiet
static void test_clear_sliding_past(void** state) {
  double tlast[2], tend[2];
  for (int k = 0; k < 2; k++) {
    ballRun b = {5, 0, k ? 0.002 : INFINITY, 100, 0.02, 0, {-0.4, 0, 0.14}, {2, 0, 0}};
    run_balls(&b, tlast + k, tend + k);
  }
  print_message(
      "ball sliding past: run ends %.4f s after the contact (t_quiet alone), %.4f s "
      "(t_clear 0.002)\n",
      tend[0] - tlast[0], tend[1] - tlast[1]);
  assert_true(fabs(tend[0] - tlast[0] - 0.02) < 2e-4);
  assert_true(tend[1] - tlast[1] > 0.002 && tend[1] - tlast[1] < 0.004);
}


//---------------------------------- coarse steps (adapt) ------------------------------------------

// the glancing ball of test_clear_keeps_recontact (no gravity: between the contacts it flies
// straight at its speed) with adapt 1 and 4. With 4 the flight between the targets is taken in
// coarse steps, and none comes within reach: over each coarse step and one dt more the ball's
// straight path keeps it off both targets (exact: spheres), and no contact is active at a
// coarse step's start (ntouch 0). The contacts are stepped at dt: the second one starts at the
// same step.
// Its last contact moves by less than 0.5 % of the first-to-last time (measured: 0).
static void test_adapt_clear_only(void** state) {
  double tlast[2], tsecond[2];
  long ncoarse[2], nchecked = 0;
  for (int c = 0; c < 2; c++) {
    urModel* m = balls(0.4, 0.35, INFINITY, 100);
    m->opt.t_quiet = 0.3;
    m->opt.tmax = 2;
    m->opt.adapt = c ? 4 : 1;
    urData* d = ur_data_new(m);
    assert_int_equal(ur_run_start(m, d, 0, (double[3]){-0.4, 0, 0.14}, NULL, (double[3]){2, 0, 0}),
                     urSTAT_OK);
    tsecond[c] = -1;
    while (d->status == urSTAT_OK) {
      if (d->coarse) {
        // the centre's straight path over the step and one dt more: its closest approach to
        // each target's centre (the point on the segment nearest to it) stays beyond 0.15 m
        double T = (m->opt.adapt + 1) * m->opt.dt, v2 = 0, w[3], s0 = 0;
        for (int k = 0; k < 2; k++) {
          double tc[3] = {k * 0.4, 0, k * 0.35};
          for (int j = 0; j < 3; j++) {
            w[j] = tc[j] - d->qpos[j];
          }
          v2 = uru_dot3(d->qvel, d->qvel);
          s0 = fmin(fmax(uru_dot3(w, d->qvel) / v2, 0), T);
          double near = 0;
          for (int j = 0; j < 3; j++) {
            near += (w[j] - s0 * d->qvel[j]) * (w[j] - s0 * d->qvel[j]);
          }
          assert_true(sqrt(near) > 0.15);
        }
        nchecked++;
      }
      ur_step(m, d);
      if (tsecond[c] < 0 && d->pair[1].active) {
        tsecond[c] = d->time;
      }
    }
    assert_int_equal(d->status, urSTAT_SEPARATED);
    assert_int_equal(d->ntouch, 0);
    ncoarse[c] = d->ncoarse;
    tlast[c] = d->t_last - d->t_first;
    ur_data_free(d);
    ur_model_free(m);
  }
  print_message(
      "adapt: %ld coarse steps (all %ld proved clear), second contact at %.5f / %.5f s, "
      "last %.5f / %.5f s after the first (adapt 1 / 4)\n",
      ncoarse[1], nchecked, tsecond[0], tsecond[1], tlast[0], tlast[1]);
  assert_int_equal(ncoarse[0], 0);
  assert_true(ncoarse[1] > 300);
  assert_true(nchecked == ncoarse[1]);
  assert_true(tsecond[0] > 0.1 && tsecond[1] == tsecond[0]);
  assert_true(fabs(tlast[1] - tlast[0]) <= 0.005 * tlast[0]);
}


//---------------------------------- the spin bound ------------------------------------------------

// rotation matrix of angle t about unit axis a (Rodrigues)
static void rotm(double R[9], const double a[3], double t) {
  double c = cos(t), s = sin(t);
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) R[3 * i + j] = (1 - c) * a[i] * a[j] + (i == j ? c : 0);
  }
  R[1] -= s * a[2], R[2] += s * a[1], R[3] += s * a[2];
  R[5] -= s * a[0], R[6] -= s * a[1], R[7] += s * a[0];
}

static double urand(double lo, double hi) {
  return lo + (hi - lo) * (rand() / (RAND_MAX + 1.0));
}

static void unit(double v[3]) {
  do {
    for (int k = 0; k < 3; k++) v[k] = urand(-1, 1);
  } while (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 1 || v[0] * v[0] + v[1] * v[1] < 1e-6);
  double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; k++) v[k] /= n;
}

// half-width along world u of an ellipsoid (semi-axes a, degree p) whose frame is R
static double hwidth(const double R[9], const double a[3], double p, const double u[3]) {
  double w[3];
  for (int k = 0; k < 3; k++) w[k] = a[k] * (R[k] * u[0] + R[3 + k] * u[1] + R[6 + k] * u[2]);
  return p > 2 ? ur_halfwidth_local(w, p) : sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

// a body turning at a constant angular velocity (its own frame): the half-width of its ellipsoid
// along a fixed direction never grows by more than ur_spin_bound says (o + k t, and kr t), over
// random shapes (ellipsoids, superellipsoids up to degree 8), poses, spins and directions. The
// bound is close: some case comes within 10 % of k t. Replacing a_max - a_min by less (or
// dropping the superellipsoid's offset o) makes this fail.
static void test_spin_bound(void** state) {
  srand(36);
  double worst = 0, close = 0;
  static const double degs[] = {2, 2, 2.0002, 2.059, 3, 8};
  for (int n = 0; n < 20000; n++) {
    urGeom ge;
    memset(&ge, 0, sizeof ge);
    ge.gmat[0] = ge.gmat[4] = ge.gmat[8] = 1;
    for (int k = 0; k < 3; k++) ge.size[k] = urand(0.01, 0.4);
    if (n % 4 == 0) ge.size[1] = ge.size[0]; /* round in plan */
    ge.degree = degs[n % 6];
    ge.rbound = ur_bound_radius(ge.size, ge.degree);
    double ax[3], R0[9], u[3], w[3], wa[3];
    unit(ax);
    rotm(R0, ax, urand(0, M_PI));
    unit(u);
    unit(wa);
    double wn = urand(0.1, 60);
    for (int k = 0; k < 3; k++) w[k] = wn * wa[k];
    urSpinBound b = ur_spin_bound(&ge, w);
    double h0 = hwidth(R0, ge.size, ge.degree, u);
    for (int i = 1; i <= 20; i++) {
      double t = 0.001 * i, Rt[9], R[9];
      rotm(Rt, wa, wn * t);
      for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
          R[3 * r + c] = R0[3 * r] * Rt[c] + R0[3 * r + 1] * Rt[3 + c] + R0[3 * r + 2] * Rt[6 + c];
        }
      }
      double grow = hwidth(R, ge.size, ge.degree, u) - h0;
      double bound = fmin(b.o + b.k * t, b.kr * t);
      assert_true(grow <= bound + 1e-12);
      if (bound > 0) worst = fmax(worst, grow / bound);
      if (ge.degree == 2 && i == 1 && b.k > 0) close = fmax(close, grow / (b.k * t));
    }
  }
  print_message("spin bound: largest growth / bound %.3f; ellipsoids over 1 ms up to %.3f of k t\n",
                worst, close);
  assert_true(close > 0.9);
}


//---------------------------------- the coarse-step proof's quick test --------------------------

// coarse_clear's exact test along the centre line (gap_holds of engine_run.c, the same operations)
static int gap_exact(const double dc[3], double ce, double r1, double r2, double a, double T) {
  double L = sqrt(dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2]);
  if (!(L > 0)) return 0;
  double s = L - r1 - r2, c = ce / L;
  return s > 0 && s > c * T + 0.5 * a * T * T;
}

// ur_gap_quick never passes a case the exact test fails: random cases placed at the exact test's
// boundary (within 1e-16 .. 1 relative, closing and opening rates, a_clear 0 and 100, radii
// summing to about the distance), and it still passes the far ones (distance 2 (r + A) or more at
// rates where the exact test holds with room). NaN inputs and an overflowing right side go to the
// exact test.
// Without its 1 + 2^-20 (or with c T for 2 c T) it passes boundary cases the exact test fails.
static void test_gap_quick(void** state) {
  srand(3636);
  long quick = 0, exact = 0, far = 0, farq = 0;
  for (int n = 0; n < 400000; n++) {
    double u[3], dc[3];
    unit(u);
    double r1 = urand(0.001, 0.3), r2 = n % 7 == 0 ? 0 : urand(0.001, 0.3);
    double T = urand(1e-5, 1e-3), a = n % 3 ? 100 : 0, A = 0.5 * a * T * T;
    double S = r1 + r2 + A, L = S * (1 + pow(10, urand(-16, 0)));
    for (int k = 0; k < 3; k++) dc[k] = L * u[k];
    // the rate at which L - S = c T / L holds, nudged either side (or a receding pair)
    double c =
        (L - S) / T * pow(10, urand(-3, 3)) * (n % 5 == 0 ? -1 : 1) * (1 + urand(-1e-9, 1e-9));
    double ce = c * L;
    int q = ur_gap_quick(dc, ce, r1 + r2, A, T), e = gap_exact(dc, ce, r1, r2, a, T);
    if (q && !e) {
      fail_msg("quick passes, exact fails: L %.17g r %.17g %.17g ce %.17g T %.17g a %g", L, r1, r2,
               ce, T, a);
    }
    quick += q;
    exact += e;
    // far: twice the sum of radii away, closing at most at half of what the gap allows
    for (int k = 0; k < 3; k++) dc[k] = 2 * S * u[k] * urand(1, 10);
    double Lf = sqrt(dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2]);
    ce = 0.5 * (Lf - S) / T * Lf * urand(-1, 1);
    far += gap_exact(dc, ce, r1, r2, a, T);
    farq += ur_gap_quick(dc, ce, r1 + r2, A, T);
  }
  print_message("gap quick: %ld of %ld exact passes at the boundary; far %ld of %ld\n", quick,
                exact, farq, far);
  assert_true(quick > 0 && exact > quick);
  assert_true(far == 400000 && farq == far);
  double dc[3] = {1, 0, 0};
  assert_int_equal(ur_gap_quick(dc, NAN, 0.1, 0, 1e-4), 0);
  assert_int_equal(ur_gap_quick(dc, INFINITY, 0.1, 0, 1e-4), 0);
  assert_int_equal(ur_gap_quick(dc, 0, NAN, 0, 1e-4), 0);
  assert_int_equal(ur_gap_quick(dc, 0, 0.1, NAN, 1e-4), 0);
  assert_int_equal(ur_gap_quick(dc, 0, 0.1, 0, NAN), 0);
  assert_int_equal(ur_gap_quick(dc, 0, 1, 0, 1e-4), 0); // touching: L = r
  assert_int_equal(ur_gap_quick(dc, 0, 0.5, 0, 1e-4), 1);
  double big[3] = {1e200, 1e200, 0}; // the distance overflows: both pass
  assert_int_equal(ur_gap_quick(big, 0, 0.1, 0, 1e-4), gap_exact(big, 0, 0.1, 0, 0, 1e-4));
  assert_int_equal(ur_gap_quick(dc, 0, 1e200, 0, 1e-4), 0); // the right side overflows
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_threads_bitwise),       cmocka_unit_test(test_symmetric_impact),
      cmocka_unit_test(test_nonfinite_fails),       cmocka_unit_test(test_explosion_fails),
      cmocka_unit_test(test_stop_request),          cmocka_unit_test(test_jump),
      cmocka_unit_test(test_history_and_names),     cmocka_unit_test(test_clear_ends_early),
      cmocka_unit_test(test_clear_keeps_recontact), cmocka_unit_test(test_clear_sliding_past),
      cmocka_unit_test(test_adapt_clear_only),      cmocka_unit_test(test_spin_bound),
      cmocka_unit_test(test_clear_membrane_bag),    cmocka_unit_test(test_gap_quick),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
