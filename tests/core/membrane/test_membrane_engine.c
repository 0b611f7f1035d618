/* test_membrane_engine.c: the membrane airbag inside the multibody engine: a rigid sphere thrown
 * at a bag carried by a fixed body. Without damping (fabric, contact, friction), with the
 * default wrinkling (the tension-field relaxed energy plus re of the taut law, a potential) the
 * total energy (the sphere's kinetic energy, the fabric's kinetic and strain energy, the gas
 * energy, the contact springs' energy) stays within 1 % of the sphere's initial kinetic energy;
 * with damping the total never rises above its start; the stiff penalty, implicit along the
 * normal, is stable and never gains energy either; a bag squeezed between plates (issue 32's
 * P V^gamma and plate force against gauge x contact area);
 * the sphere is stopped and thrown back; runs stepped in lock-step lanes are bit for bit the runs
 * stepped alone (membrane state included). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/core/engine/engine_internal.h"

static const double R = 0.0875, ATM = 101325;
static int wrinkle_law = urMEM_RELAXED; /* the bags' wrinkling law (test_energy_reduce: 1) */

/* a pillow bag hanging from a fixed body; a free sphere of 4.5 kg below it; the penalty
   kc_alpha (0: the default), the step dt */
static urModel* bagmodel_dt(int damped, double alpha, double dt) {
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int b = ur_model_add_body(m, "drone", -1, urJNT_FIXED, NULL, NULL);
  ur_model_set_inertia(m, b, 12, NULL, I);
  int gb = ur_model_add_ellipsoid(m, "bag", b, NULL, NULL, (double[3]){0.2, 0.2, 0.2});
  int h = ur_model_add_body(m, "head", -1, urJNT_FREE, NULL, NULL);
  ur_model_set_inertia(m, h, 4.5, NULL, I);
  int gh = ur_model_add_ellipsoid(m, "skull", h, NULL, NULL, (double[3]){R, R, R});
  urAirbag bag = {0};
  strcpy(bag.name, "bottom");
  bag.type = urBAG_MEMBRANE;
  bag.geom = gb;
  bag.ntarget = 1;
  bag.target[0] = gh;
  ur_mem_spec_default(&bag.mspec);
  urMemSpec* s = &bag.mspec;
  s->a = s->b = 0.2;
  s->depth = 0.15;
  s->mesh = 4;
  s->wrinkle = wrinkle_law;
  s->p0 = 1.1 * ATM;
  s->patm = ATM;
  if (alpha > 0) {
    s->kc_alpha = alpha;
  }
  if (!damped) {
    s->damp = 0;
    s->zeta_c = 0;
    s->mu = 0;
  }
  int ib = ur_model_add_airbag(m, &bag);
  assert_true(ib >= 0);
  ur_model_add_sensor(m, "gas", urSENS_AIRBAG, ib, 0, NULL, NULL);
  m->opt.gravity[2] = 0;
  m->opt.dt = dt;
  assert_int_equal(ur_model_compile(m), 0);
  char err[160];
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0);
  return m;
}


/* the bag at the step 1e-5 */
static urModel* bagmodel_alpha(int damped, double alpha) {
  return bagmodel_dt(damped, alpha, 1e-5);
}


/* the bag with the default penalty */
static urModel* bagmodel(int damped) {
  return bagmodel_alpha(damped, 0);
}


/* the lowest point of the inflated bag (world = body frame here) */
static double bag_bottom(const urModel* m) {
  const urMembrane* mb = m->bag[0].mem;
  double z = 0;
  for (int i = 0; i < mb->nn; i++) {
    z = fmin(z, mb->x0[3 * i + 2]);
  }
  return z;
}


/* total energy at the last forward pass */
static double energy(const urModel* m, const urData* d) {
  const urMembrane* mb = m->bag[0].mem;
  const double* st = d->mem + m->bag[0].madr;
  const double* sc = st + 18 * mb->nn;
  // the penalty springs' energy k depth^2 / 2 (nodes and centroids)
  double ep = sc[urMEMS_ECONT];
  return ur_energy_kinetic(m, d) + ur_mem_kinetic(mb, st) +
         ur_mem_gas_energy(mb, sc[urMEMS_P], sc[urMEMS_V]) + sc[urMEMS_EFAB] + ep;
}


/* throw the sphere up at the bag at speed v; returns the largest energy change / KE0 (signed
   extremes in lo, hi) and the sphere's final vertical velocity */
static double drop(urModel* m, double v, double* lo, double* hi, double* vend) {
  urData* d = ur_data_new(m);
  double z0 = bag_bottom(m) - R - 0.002;
  ur_set_free(m, d, 1, (double[3]){0.01, 0.005, z0}, NULL, (double[3]){0, 0, v}, NULL);
  ur_forward(m, d);
  double ke0 = 0.5 * 4.5 * v * v, e0 = energy(m, d);
  *lo = *hi = 0;
  double fpk = 0;
  for (int i = 0; i < 6000; i++) {
    assert_true(ur_step(m, d) >= 0);
    ur_forward(m, d);
    double de = (energy(m, d) - e0) / ke0;
    *lo = fmin(*lo, de);
    *hi = fmax(*hi, de);
    fpk = fmax(fpk, d->bag[0].force);
  }
  *vend = d->qvel[m->body[1].vadr + 2];
  print_message(
      "drop at %.1f m/s: energy change %.4f .. %.4f of KE0, end velocity %.3f m/s, "
      "peak force %.0f N, pressure %.0f Pa\n",
      v, *lo, *hi, *vend, fpk, d->bag[0].pressure);
  assert_true(fpk > 100);
  ur_data_free(d);
  return fpk;
}


static void test_energy_undamped(void** state) {
  urModel* m = bagmodel(0);
  double lo, hi, vend;
  drop(m, 4, &lo, &hi, &vend);
  assert_true(hi < 0.01 && lo > -0.01);
  // thrown back: how much of the energy the undamped bag keeps as vibration at the end varies
  // with the mesh (-1.97 m/s at this mesh 4; -3.15, -2.04, -2.03 m/s at meshes 3, 5, 6; -1.08
  // at mesh 4 before its mount patch's edge was a ring)
  assert_true(vend < -1);
  ur_model_free(m);
}


static void test_energy_damped(void** state) {
  urModel* m = bagmodel(1);
  double lo, hi, vend;
  drop(m, 4, &lo, &hi, &vend);
  assert_true(hi <= 1e-3);
  assert_true(vend > -4);
  ur_model_free(m);
}


/* wrinkle=1, LAW19's reduction, has no potential: its energy balance holds only roughly. Measured
   on this drop: undamped -0.07 .. +1.06 % of KE0 (the relaxed law: 0 .. +0.10 %), damped -2.05 ..
   +0.49 % (the relaxed law never gains: <= 0). Bounds 2 % and 1 %: a regression guard and the
   man page's numbers (uasimpact-model(5), BAGS, wrinkle) */
static void test_energy_reduce(void** state) {
  wrinkle_law = urMEM_REDUCE;
  urModel* m = bagmodel(0);
  double lo, hi, lo1, hi1, vend, vend1;
  drop(m, 4, &lo, &hi, &vend);
  ur_model_free(m);
  m = bagmodel(1);
  drop(m, 4, &lo1, &hi1, &vend1);
  ur_model_free(m);
  wrinkle_law = urMEM_RELAXED;
  assert_true(hi < 0.02 && lo > -0.02 && vend < -1);
  assert_true(hi1 < 0.01 && vend1 > -4);
}


/* the stiff penalty, implicit along the normal: stable, never gains energy. Its normal springs
   are integrated by the implicit midpoint rule (energy-neutral for a linear spring) with the
   nodes coupled through the edge midpoints' stiffness (the consistent tangent, solved by Jacobi
   sweeps); the undamped drop loses 0.48 / 0.58 / 0.64 / 1.23 / 2.5 % at kc_alpha 1.01 / 2 / 5 /
   20 / 200 (dt 1e-5), against 1.4 / 1.8 / 3.3 / 4.9 % at 2 / 5 / 20 / 200 with the backward
   Euler and lumped stiffness it replaced (and 1.05 / 1.29 / 2.57 / 4.5 % with the midpoint
   rule on the lumped stiffness): so kc_alpha 5 within issue 32's 1 % and kc_alpha 20 within
   1.5 % fail with either. The rest shrinks with the step (kc_alpha 20: 2.15 / 1.23 / 0.66 % at
   dt 2e-5 / 1e-5 / 5e-6; tests/MEASUREMENTS.md); the explicit law (kc_alpha <= 1) loses 0.02 % */
static void test_energy_stiff(void** state) {
  double lo, hi, vend;
  urModel* m = bagmodel_alpha(0, 5);
  drop(m, 4, &lo, &hi, &vend);
  assert_true(hi <= 1e-3 && lo > -0.01);
  ur_model_free(m);
  m = bagmodel_alpha(0, 20);
  drop(m, 4, &lo, &hi, &vend);
  assert_true(hi <= 1e-3 && lo > -0.015);
  ur_model_free(m);
  m = bagmodel_alpha(1, 20);
  drop(m, 4, &lo, &hi, &vend);
  assert_true(hi <= 1e-3 && vend < -1);
  ur_model_free(m);
}


/* a target's soft layer (airbag tk, from 'layer' in the model language: E_oed / h) sets the
   fabric's penalty on it, capped at what the explicit step carries (kc_alpha 1) or at the bag's
   own kc_alpha when that asks for the stiff law; targets without a layer keep kc_alpha. The
   damped drop at dt 5e-5 (the shipped step): its peak force with a layer of stiffness k equals
   that with kc_alpha = k dt^2 / rhot declared and no layer */
static double peak_layer(double alpha, double tk) {
  urModel* m = bagmodel_dt(1, alpha, 5e-5);
  m->bag[0].tk[0] = tk;
  double lo, hi, vend, f = drop(m, 4, &lo, &hi, &vend);
  assert_true(hi <= 1e-3);
  ur_model_free(m);
  return f;
}

static void test_layer_penalty(void** state) {
  double rhot = 0.231, dk = 5e-5;
  double thorax = peak_layer(0, 0.55 * rhot / (dk * dk)), declared = peak_layer(0.55, 0);
  assert_true(fabs(thorax - declared) <= 1e-9 * declared);
  // the scalp (4.87e9 N/m^3, kc_alpha 53): the explicit cap, kc_alpha 1
  double scalp = peak_layer(0, 4.87e9), one = peak_layer(1, 0), dflt = peak_layer(0, 0);
  assert_true(fabs(scalp - one) <= 1e-9 * one);
  assert_true(scalp > dflt);
  // with the stiff law asked for (kc_alpha 5) the layer takes the bag's kc_alpha as its cap
  double stiff = peak_layer(5, 4.87e9), five = peak_layer(5, 0);
  assert_true(fabs(stiff - five) <= 1e-9 * five);
  // a soft layer is softer than the bag's stiff kc_alpha: the layer's own
  assert_true(fabs(peak_layer(5, 0.55 * rhot / (dk * dk)) - declared) <= 1e-9 * declared);
}


/* the bag's grip on a sphere sliding across it: the sphere (damped bag, mu as declared) thrown up
   at 3 m/s and sideways at 2 m/s from under the bag at step dt (kc_dt 5e-5 and below: the same
   penalty); the sideways velocity it has lost after 30 ms (the contact over) */
static double grip(double dt) {
  urModel* m = bagmodel_dt(1, 0, dt);
  urData* d = ur_data_new(m);
  double z0 = bag_bottom(m) - R - 0.002;
  ur_set_free(m, d, 1, (double[3]){-0.03, 0.005, z0}, NULL, (double[3]){2, 0, 3}, NULL);
  int n = (int)lround(0.03 / dt);
  for (int i = 0; i < n; i++) {
    assert_true(ur_step(m, d) >= 0);
  }
  double dv = 2 - d->qvel[m->body[1].vadr];
  print_message("grip at dt %g: sideways velocity lost %.4f m/s\n", dt, dv);
  ur_data_free(d);
  ur_model_free(m);
  return dv;
}


/* the friction's grip does not depend on the step: halving dt (5e-5 -> 2.5e-5, case A's step
   and half of it) changes the sideways velocity the bag takes from the sphere by <= 2 % (issue
   32's time-step halving). It failed when each contact point's friction was capped at its
   penetrated area's mass over dt: the cap, hence the grip, scaled with 1/dt */
static void test_grip_dt(void** state) {
  double g1 = grip(5e-5), g2 = grip(2.5e-5);
  assert_true(g1 > 0.02);
  assert_true(fabs(g2 - g1) <= 0.02 * g1);
}


static void test_lanes_bitwise(void** state) {
  urModel* m = bagmodel(1);
  urLanes L;
  assert_int_equal(ur_lanes_init(m, &L), 0);
  urData *a[3], *b[3];
  double z0 = bag_bottom(m) - R - 0.002;
  for (int k = 0; k < 3; k++) {
    a[k] = ur_data_new(m);
    b[k] = ur_data_new(m);
    double x[3] = {0.02 * k, -0.01 * k, z0}, v[3] = {0.3 * k, 0, 3 + k};
    ur_set_free(m, a[k], 1, x, NULL, v, NULL);
    ur_set_free(m, b[k], 1, x, NULL, v, NULL);
  }
  for (int i = 0; i < 3000; i++) {
    ur_step_lanes(m, a, 3, &L);
    for (int k = 0; k < 3; k++) {
      ur_step(m, b[k]);
    }
  }
  for (int k = 0; k < 3; k++) {
    assert_memory_equal(a[k]->qpos, b[k]->qpos, m->nq * sizeof(double));
    assert_memory_equal(a[k]->qvel, b[k]->qvel, m->nv * sizeof(double));
    assert_memory_equal(a[k]->mem, b[k]->mem, m->nmemd * sizeof(double));
    assert_true(a[k]->bag[0].live);
    ur_data_free(a[k]);
    ur_data_free(b[k]);
  }
  ur_lanes_free(&L);
  ur_model_free(m);
}


/* the plates test's measures at the end of the hold */
typedef struct {
  double pv;   /* P V^gamma / its inflated value - 1 */
  double dv;   /* V / Vref */
  double fdp;  /* the plate's force / gauge, m^2 */
  double flat; /* force on the flat region's nodes / (gauge x their tributary area) - 1 */
  double zg;   /* force / (gauge x the area inside the zero-gap contour) - 1 */
  double rim0; /* (force - gauge x the flat region's tributary area) / gauge x the rim's: */
} urPlates;    /* the share of its tributary area the rim ring carries, in [0, 1] */


/* the projected (xy) area of triangle t */
static double tri_xy(const urMembrane* mb, const double* x, int t) {
  const int* v = mb->tri + 3 * t;
  const double *p0 = x + 3 * v[0], *p1 = x + 3 * v[1], *p2 = x + 3 * v[2];
  return 0.5 * fabs((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]));
}


/* the bag squeezed slowly between the carrier's flat plate (a support) and a plate below it on
   a prismatic joint (80 mm), then held; the penalty kc_alpha (0: the default) at this mesh */
static urPlates plates(int mesh, double alpha) {
  urModel* m = ur_model_new();
  double I[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  int b = ur_model_add_body(m, "drone", -1, urJNT_FIXED, NULL, NULL);
  ur_model_set_inertia(m, b, 12, NULL, I);
  int gb = ur_model_add_ellipsoid(m, "bag", b, NULL, NULL, (double[3]){0.2, 0.2, 0.2});
  int gu = ur_model_add_ellipsoid(m, "upper", b, (double[3]){0, 0, 0.05}, NULL,
                                  (double[3]){0.5, 0.5, 0.05});
  ur_model_set_degree(m, gu, 12);
  int h = ur_model_add_body(m, "plate", -1, urJNT_PRISMATIC, (double[3]){0, 0, 0}, NULL);
  ur_model_set_joint(m, h, "lift", (double[3]){0, 0, 1}, NULL);
  ur_model_set_inertia(m, h, 1000, NULL, I);
  int gp = ur_model_add_ellipsoid(m, "lower", h, NULL, NULL, (double[3]){0.5, 0.5, 0.05});
  ur_model_set_degree(m, gp, 12);
  urAirbag bag = {0};
  strcpy(bag.name, "bag");
  bag.type = urBAG_MEMBRANE;
  bag.geom = gb;
  bag.ntarget = 1;
  bag.target[0] = gp;
  bag.nsupport = 1;
  bag.support[0] = gu;
  ur_mem_spec_default(&bag.mspec);
  urMemSpec* s = &bag.mspec;
  s->a = s->b = 0.2;
  s->depth = 0.15;
  s->mesh = mesh;
  s->mu = 0;
  s->p0 = 1.1 * ATM;
  s->patm = ATM;
  if (alpha > 0) {
    s->kc_alpha = alpha;
  }
  assert_true(ur_model_add_airbag(m, &bag) >= 0);
  m->opt.gravity[2] = 0;
  m->opt.dt = 2e-5;
  assert_int_equal(ur_model_compile(m), 0);
  char err[160];
  assert_int_equal(ur_model_inflate(m, err, sizeof err), 0);
  const urMembrane* mb = m->bag[0].mem;
  int nn = mb->nn;

  // the lower plate starts just below the bag, rises 40 mm at 0.4 m/s, then holds
  urData* d = ur_data_new(m);
  double z0 = bag_bottom(m) - 0.05 - 0.001;
  d->qpos[0] = z0;
  for (int i = 0; i < 9000; i++) {
    d->qvel[0] = i < 5000 ? 0.8 : 0;
    if (i == 5000) {
      d->qpos[0] = z0 + 0.08;
    }
    assert_true(ur_step(m, d) >= 0);
  }
  ur_forward(m, d);
  const double* st = d->mem + m->bag[0].madr;
  const double *x = st, *fc = st + 9 * nn, *sc = st + 18 * nn;
  double P = sc[urMEMS_P], V = sc[urMEMS_V];
  urPlates r;
  r.pv = P * pow(V, 1.4) / (mb->pref * pow(mb->vref, 1.4)) - 1;
  r.dv = V / mb->vref;

  // the plate's force: the contact forces of the nodes below the bag's middle; the nodes in
  // contact (gap to the plate's face <= 0) and of those the flat region's: all their triangles'
  // nodes in contact (the rim: the others)
  double force = 0, zmid = 0.5 * bag_bottom(m), dp = P - mb->spec.patm, ptop = d->qpos[0] + 0.05;
  char* in = calloc(nn, 1);
  char* rim = calloc(nn, 1);
  assert_non_null(in);
  assert_non_null(rim);
  for (int i = 0; i < nn; i++) {
    if (x[3 * i + 2] < zmid) {
      force += fc[3 * i + 2];
      in[i] = x[3 * i + 2] - ptop <= 0;
    }
  }
  for (int t = 0; t < mb->nt; t++) {
    const int* v = mb->tri + 3 * t;
    if (!(in[v[0]] && in[v[1]] && in[v[2]])) {
      rim[v[0]] = rim[v[1]] = rim[v[2]] = 1;
    }
  }
  // tributary (projected) areas: a third of each adjacent triangle's; the force on the flat
  // region
  double aflat = 0, arim = 0, fflat = 0;
  for (int t = 0; t < mb->nt; t++) {
    const int* v = mb->tri + 3 * t;
    double a3 = tri_xy(mb, x, t) / 3;
    for (int k = 0; k < 3; k++) {
      if (in[v[k]]) {
        *(rim[v[k]] ? &arim : &aflat) += a3;
      }
    }
  }
  for (int i = 0; i < nn; i++) {
    if (in[i] && !rim[i]) {
      fflat += fc[3 * i + 2];
    }
  }
  free(in);
  free(rim);

  // the area inside the zero-gap contour: the gap interpolated linearly over each triangle of
  // the lower half (where the face contact's pressure acts: membrane_contact.c)
  double a0 = 0;
  for (int t = 0; t < mb->nt; t++) {
    const int* v = mb->tri + 3 * t;
    double g[3], poly[4][2];
    int np2 = 0, low = 1;
    for (int k = 0; k < 3; k++) {
      g[k] = x[3 * v[k] + 2] - ptop;
      low &= x[3 * v[k] + 2] < zmid;
    }
    for (int k = 0; k < 3 && low; k++) {
      int l = (k + 1) % 3;
      const double *pk = x + 3 * v[k], *pl = x + 3 * v[l];
      if (g[k] <= 0) {
        poly[np2][0] = pk[0], poly[np2][1] = pk[1], np2++;
      }
      if ((g[k] <= 0) != (g[l] <= 0)) {
        double u = g[k] / (g[k] - g[l]);
        poly[np2][0] = pk[0] + u * (pl[0] - pk[0]);
        poly[np2][1] = pk[1] + u * (pl[1] - pk[1]);
        np2++;
      }
    }
    double a = 0;
    for (int k = 0; k < np2; k++) {
      int l = (k + 1) % np2;
      a += poly[k][0] * poly[l][1] - poly[l][0] * poly[k][1];
    }
    a0 += 0.5 * fabs(a);
  }
  r.fdp = force / dp;
  r.flat = fflat / (dp * aflat) - 1;
  r.zg = force / (dp * a0) - 1;
  r.rim0 = (force - dp * aflat) / (dp * arim);
  print_message(
      "plates mesh %d alpha %g: P %.0f Pa, V %.5f m^3 (from %.5f), force %.1f N, force / gauge "
      "%.4f m^2; flat region: force %.1f N / (gauge x %.5f m^2) - 1 = %+.5f; rim carries %.3f "
      "of its %.5f m^2; force / (gauge x zero-gap area %.5f m^2) - 1 = %+.4f\n",
      mesh, s->kc_alpha, P, V, mb->vref, force, r.fdp, fflat, aflat, r.flat, r.rim0, arim, a0,
      r.zg);
  ur_data_free(d);
  ur_model_free(m);
  return r;
}


/* issue 32's plates test: P V^gamma constant to 1e-6, and the plate force equals the gauge
   pressure times the contact area measured from the mesh, within 3 %, at meshes 6 to 8.
   The area: the flat region, the nodes in contact (gap <= 0) whose triangles all lie on the
   plate, with their tributary areas (a third of each adjacent triangle's projected area).
   Why that one: a flat node's triangles lie in the plate's plane, so the fabric's forces on it
   are horizontal; the gas pushes each triangle with gauge x its projected area, a third to each
   node; without friction the plate's force on the flat region is gauge x its tributary area at
   rest, exactly, but for the penalty's foundation: the explicit penalty (k_a 1.85e7 N/m^3)
   lets the fabric sink gauge / k_a = 1.2 mm and slope within L = sqrt(T / k_a) = 8.4 mm of the
   rim (T 1.3 kN/m), so flat nodes near the rim carry some of the tension's normal part:
   +2.83, -1.47, +0.32 % at meshes 6, 7, 8; with the stiff penalty made linearly implicit along
   the normal (kc_alpha 20, L 0.84 mm; engine_membrane.c) +0.089 % at mesh 6 (+0.022, +0.033,
   -0.018 % at 7, 8, 10), which the last case asserts to 0.5 %.
   The rim (the other nodes in contact) carries gauge x its tributary area less the tension's
   normal component, between none and all of it (measured 0.80, 0.49, 0.56 at meshes 6-8), and
   the whole plate force against any area taken from which nodes touch cannot hold 3 % at these
   meshes. Proof on a string (tension T, gauge p, nodes at spacing h, nodes 0..J on a rigid
   plate): the free nodes' balance T (w[j+1] - 2 w[j] + w[j-1]) / h = p h holds exactly on the
   parabolas w = (p / 2T) (x - a)^2 + b through w[J] = 0, and summing the contact nodes'
   balances gives F = p a: the force is the pressure times the span to the vertex a, where the
   fabric's continuation leaves the plate tangentially (materials-membrane B.3), and the contact
   forces' signs allow any a in [x_J - h/2, x_J + h/2]. Which nodes touch fixes the edge to
   +-h/2 only, an area error up to h / r: the mean edge of the lower half is 50, 43, 38 mm at
   meshes 6-8 against r = 0.107 m (3 % needs h < 3 mm). Measured: force / gauge stays within
   2 % from mesh 6 to 12 (0.0352-0.0355 m^2 explicit, 0.0358-0.0367 stiff) while the area
   inside the zero-gap contour (the former measure; linear gap over each triangle) moves by up
   to 50 %: force / (gauge x that) - 1 = +10.2, -18.0, -2.7 % at meshes 6-8 explicit, +42, -12,
   +10 % stiff (the contour snaps onto the last ring in contact); the vertex of a quadratic fit
   of the gap against the radius near the rim gave +2.5, -6.3, +3.6 % (stiff), moving by 4 %
   with the fit's window. The stiff penalty's own gain, the foundation's deficit gone: force /
   gauge +3.4 % (0.0352 -> 0.0364 m^2 at mesh 6). */
static void test_plates(void** state) {
  for (int mesh = 6; mesh <= 8; mesh++) {
    urPlates r = plates(mesh, 0);
    assert_true(fabs(r.pv) < 1e-6);
    assert_true(r.dv < 0.95);
    assert_true(fabs(r.flat) < 0.03);
    assert_true(r.rim0 >= 0 && r.rim0 <= 1);
  }
  // the stiff penalty, linearly implicit along the normal (kc_alpha > 1): the flat region flat
  urPlates r = plates(6, 20);
  assert_true(fabs(r.pv) < 1e-6);
  assert_true(fabs(r.flat) < 0.005);
  assert_true(r.rim0 >= 0 && r.rim0 <= 1);
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_energy_undamped), cmocka_unit_test(test_energy_damped),
      cmocka_unit_test(test_energy_reduce),   cmocka_unit_test(test_energy_stiff),
      cmocka_unit_test(test_layer_penalty),   cmocka_unit_test(test_grip_dt),
      cmocka_unit_test(test_lanes_bitwise),   cmocka_unit_test(test_plates),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
