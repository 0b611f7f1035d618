/* test_membrane_fabric.c: the membrane airbag's fabric and gas against closed forms: a spherical
 * bag inflated to a gauge pressure carries the Laplace tension p R / 2 in every direction (mean
 * over the triangles within 1 %, with R from the mesh's volume; the mean fabric strain within 1 %
 * of the orthotropic law's), the mesh is closed and outward (its volume near the sphere's), the
 * tension-field rule keeps the tensile principal stress and scales the compressive one by RE,
 * the shear law is G0 before the lock and GT after it, the isentropic pressure law, and the vent's
 * isentropic orifice flow against the reference sheet's mass fluxes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/core/membrane/membrane_internal.h"

/* a sphere of radius R: both panels domes of height R */
static urMembrane* sphere(double R, int mesh, double gauge) {
  urMemSpec s;
  char err[200];
  ur_mem_spec_default(&s);
  s.a = s.b = s.depth = s.top = R;
  s.mesh = mesh;
  s.mount_r = 0;
  s.damp = 0;
  s.p0 = s.patm + gauge;
  urMembrane* mb = ur_mem_build(&s, err, sizeof err);
  assert_non_null(mb);
  return mb;
}


static void test_mesh_closed(void** state) {
  // 2 + 6 n^2 nodes, 12 n^2 triangles; volume of the declared sphere within 3 % (chords)
  urMembrane* mb = sphere(0.2, 8, 1e4);
  assert_int_equal(mb->nn, 2 + 6 * 64);
  assert_int_equal(mb->nt, 12 * 64);
  double v = ur_mem_volume(mb, mb->xshape), vs = 4.0 / 3 * M_PI * 0.008;
  assert_true(v > 0.97 * vs && v < vs);
  // every edge is shared by exactly two triangles in opposite directions: the sum of all
  // directed edges vanishes
  double s[3] = {0, 0, 0};
  for (int t = 0; t < mb->nt; t++) {
    for (int k = 0; k < 3; k++) {
      const double* a = mb->xshape + 3 * mb->tri[3 * t + k];
      const double* b = mb->xshape + 3 * mb->tri[3 * t + (k + 1) % 3];
      double c[3];
      urm_cross(c, a, b);
      for (int j = 0; j < 3; j++) {
        s[j] += c[j];
      }
    }
  }
  assert_true(fabs(s[0]) + fabs(s[1]) + fabs(s[2]) < 1e-12);
  ur_mem_free(mb);
}


static void test_laplace_sphere(void** state) {
  // inflated at 10 kPa gauge: mean tension p R / 2, mean strain T (1 - nu) / (E t)
  double gauge = 1e4;
  urMembrane* mb = sphere(0.2, 8, gauge);
  char err[200];
  assert_int_equal(ur_mem_inflate(mb, err, sizeof err), 0);
  const urMemSpec* s = &mb->spec;
  double R = cbrt(3 * mb->vref / (4 * M_PI));
  double T = (mb->pref - s->patm) * R / 2;
  double eps = T * (1 - s->nu12) / s->e1t, green = eps + 0.5 * eps * eps;
  double ts = 0, es = 0, as = 0;
  for (int t = 0; t < mb->nt; t++) {
    double e[3], S[3], a = mb->area0[t];
    ur_mem_tri_state(mb, mb->x0, t, e, S);
    ts += 0.5 * (S[0] + S[1]) * a;
    es += 0.5 * (e[0] + e[1]) * a;
    as += a;
  }
  assert_true(fabs(ts / as / T - 1) < 0.01);
  assert_true(fabs(es / as / green - 1) < 0.01);
  // the gas kept its declared gauge pressure within 1 %
  assert_true(fabs((mb->pref - s->patm) / gauge - 1) < 0.01);
  ur_mem_free(mb);
}


static void test_tension_field(void** state) {
  urMemSpec s;
  ur_mem_spec_default(&s);
  double S[3], w;
  // uniaxial tension with a contraction that the law would turn into compression
  double e[3] = {0.01, -0.01, 0};
  urm_fabric_stress(&s, e, S, &w);
  double nu21 = s.nu12 * s.e2t / s.e1t, q = 1 / (1 - s.nu12 * nu21);
  double s1 = q * s.e1t * (e[0] + nu21 * e[1]), s2 = q * s.e2t * (e[1] + s.nu12 * e[0]);
  assert_true(fabs(S[0] - s1) < 1e-9 * fabs(s1));
  assert_true(fabs(S[1] - s.re * s2) < 1e-9 * fabs(s2));
  // biaxial compression: everything scaled by RE
  double c[3] = {-0.01, -0.02, 0.001};
  urm_fabric_stress(&s, c, S, &w);
  assert_true(S[0] < 0 && S[0] > s.re * 1.01 * q * s.e1t * (c[0] + nu21 * c[1]));
  // biaxial tension: the taut law
  double t[3] = {0.01, 0.02, 0};
  urm_fabric_stress(&s, t, S, &w);
  assert_true(fabs(S[1] - q * s.e2t * (t[1] + s.nu12 * t[0])) < 1e-6);
}


static void test_shear_lock(void** state) {
  // pure shear in a tensioned state: G0 below sin(lock), G0 sin(lock) + GT (g - sin lock) above
  urMemSpec s;
  ur_mem_spec_default(&s);
  double S[3], gl = sin(s.lock);
  double e1[3] = {0.02, 0.02, 0.5 * gl};
  urm_fabric_stress(&s, e1, S, NULL);
  assert_true(fabs(S[2] - s.g0t * 0.5 * gl) < 1e-9);
  double e2[3] = {0.02, 0.02, gl + 0.01};
  urm_fabric_stress(&s, e2, S, NULL);
  assert_true(fabs(S[2] - (s.g0t * gl + s.gtt * 0.01)) < 1e-9);
  assert_true(s.gtt > 10 * s.g0t);
}


static void test_gas_law(void** state) {
  // P V^gamma constant for the closed bag (materials-membrane B.3: 20 L at 1 atm to 0.8 V:
  // 138.5 kPa)
  urMembrane* mb = sphere(0.2, 4, 0);
  mb->pref = 101325;
  mb->vref = 0.020;
  double p = ur_mem_pressure(mb, 0.016, mb->mref);
  assert_true(fabs(p - 138.5e3) < 0.1e3);
  assert_true(fabs(p * pow(0.016, 1.4) / (101325 * pow(0.020, 1.4)) - 1) < 1e-12);
  ur_mem_free(mb);
}


static void test_vent_flow(void** state) {
  // isentropic orifice flow of air at 293 K into 1 atm: mass flux per area at a gauge pressure
  // of 1, 5, 10, 30 kPa (materials-membrane B.2: 49, 110, 155, 266 kg/(s m^2))
  urMemSpec s;
  char err[200];
  ur_mem_spec_default(&s);
  s.vent_area = 1e-3;
  s.vent_cd = 1;
  s.temp = 293.15;
  urMembrane* mb = ur_mem_build(&s, err, sizeof err);
  assert_non_null(mb);
  double* st = calloc(ur_mem_state_size(mb), sizeof(double));
  double* sc = st + 18 * mb->nn;
  static const double dp[4] = {1e3, 5e3, 10e3, 30e3}, flux[4] = {49, 110, 155, 266};
  for (int k = 0; k < 4; k++) {
    double p = s.patm + dp[k];
    sc[urMEMS_P] = p;
    sc[urMEMS_V] = 0.02;
    sc[urMEMS_MGAS] = p * 0.02 / (urMEM_RS * s.temp);
    double dt = 1e-6, q = ur_mem_outflow(mb, st, dt) / dt / s.vent_area;
    assert_true(fabs(q / flux[k] - 1) < 0.01);
  }
  // none without a gauge pressure, none without openings
  sc[urMEMS_P] = s.patm;
  assert_true(ur_mem_outflow(mb, st, 1e-3) == 0);
  free(st);
  ur_mem_free(mb);
}


/* a deterministic uniform number in [lo, hi) (64-bit LCG) */
static double uni(unsigned long long* r, double lo, double hi) {
  *r = *r * 6364136223846793005ULL + 1442695040888963407ULL;
  return lo + (hi - lo) * (double)(*r >> 11) / 9007199254740992.0;
}


static void test_stress4_bitwise(void** state) {
  // the force pass's vector law gives every lane the scalar law's bits, in each of its regimes:
  // taut, wrinkled, slack, shear before and after the lock (of both signs), no strain
  urMemSpec s;
  ur_mem_spec_default(&s);
  double nu21 = s.nu12 * s.e2t / s.e1t, q = 1 / (1 - s.nu12 * nu21), gl = sin(s.lock);
  unsigned long long r = 12345;
  int seen[3] = {0, 0, 0}, locked = 0, lin = 0;
  for (int it = 0; it < 4000; it++) {
    double e[12], S4[12], w4[4];
    for (int l = 0; l < 4; l++) {
      e[l] = uni(&r, -0.02, 0.03);
      e[4 + l] = uni(&r, -0.02, 0.03);
      e[8 + l] = uni(&r, -1, 1) * (it % 2 ? 1 : 0.1);
    }
    if (it == 0) {
      e[0] = e[4] = e[8] = 0;
    }
    urm_fabric_stress4(&s, e, S4, w4);
    for (int l = 0; l < 4; l++) {
      double el[3] = {e[l], e[4 + l], e[8 + l]}, S[3], w;
      urm_fabric_stress(&s, el, S, &w);
      for (int j = 0; j < 3; j++) {
        assert_memory_equal(&S[j], &S4[4 * j + l], sizeof(double));
      }
      assert_memory_equal(&w, &w4[l], sizeof(double));
      // the regime of the taut law's principal stresses
      double s1 = q * s.e1t * (el[0] + nu21 * el[1]), s2 = q * s.e2t * (el[1] + s.nu12 * el[0]);
      double ag = fabs(el[2]);
      double s3 = ag <= gl ? s.g0t * ag : s.g0t * gl + s.gtt * (ag - gl);
      double m = 0.5 * (s1 + s2), h = 0.5 * (s1 - s2), rr = sqrt(h * h + s3 * s3);
      seen[m + rr <= 0 ? 2 : m - rr < 0 ? 1 : 0]++;
      if (fabs(el[2]) > gl) {
        locked++;
      } else {
        lin++;
      }
    }
  }
  assert_true(seen[0] > 100 && seen[1] > 100 && seen[2] > 100 && locked > 100 && lin > 100);
}


/* the forces as the triangle loop computed them one triangle at a time (the reference the
   force pass must match bit for bit): volume, pressure, then each triangle's strain, law,
   damping and nodal forces added in triangle order */
static void forces_ref(const urMembrane* mb, const double* st, double* f, urMemInfo* info) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn;
  const double *x = st, *v = st + 3 * nn, *sc = st + 18 * nn;
  memset(f, 0, 3 * (size_t)nn * sizeof(double));
  double V = ur_mem_volume(mb, x);
  double p = ur_mem_pressure(mb, V, sc[urMEMS_MGAS]), pg6 = (p - s->patm) / 6;
  double emax = 0, wsum = 0;
  for (int t = 0; t < mb->nt; t++) {
    const int* n3 = mb->tri + 3 * t;
    const double* Di = mb->dminv + 4 * t;
    double F[6], e[3], S[3], w;
    urm_tri_strain(mb, x, t, F, e);
    urm_fabric_stress(s, e, S, &w);
    wsum += w * mb->area0[t];
    double e1 = fmax(e[0], e[1]);
    if (e1 > emax) {
      emax = e1;
    }
    if (mb->beta[t] > 0) {
      double dv1[3], dv2[3], L[6];
      urm_sub(dv1, v + 3 * n3[1], v + 3 * n3[0]);
      urm_sub(dv2, v + 3 * n3[2], v + 3 * n3[0]);
      for (int k = 0; k < 3; k++) {
        L[k] = dv1[k] * Di[0] + dv2[k] * Di[2];
        L[3 + k] = dv1[k] * Di[1] + dv2[k] * Di[3];
      }
      double b = mb->beta[t];
      S[0] += b * s->e1t * urm_dot(F, L);
      S[1] += b * s->e2t * urm_dot(F + 3, L + 3);
      S[2] += b * s->gtt * (urm_dot(F, L + 3) + urm_dot(F + 3, L));
    }
    double A0 = mb->area0[t], P0[3], P1[3], d1[3], d2[3], nrm[3];
    for (int k = 0; k < 3; k++) {
      P0[k] = A0 * (F[k] * S[0] + F[3 + k] * S[2]);
      P1[k] = A0 * (F[k] * S[2] + F[3 + k] * S[1]);
    }
    urm_sub(d1, x + 3 * n3[1], x + 3 * n3[0]);
    urm_sub(d2, x + 3 * n3[2], x + 3 * n3[0]);
    urm_cross(nrm, d1, d2);
    for (int k = 0; k < 3; k++) {
      double h0 = P0[k] * Di[0] + P1[k] * Di[1], h1 = P0[k] * Di[2] + P1[k] * Di[3];
      double fp = pg6 * nrm[k];
      f[3 * n3[1] + k] += fp - h0;
      f[3 * n3[2] + k] += fp - h1;
      f[3 * n3[0] + k] += fp + h0 + h1;
    }
  }
  *info = (urMemInfo){p, V, emax, wsum};
}


static void test_forces_bitwise(void** state) {
  // the force pass (4 triangles at a time, sums and nodal forces in triangle order) against the
  // one-triangle-at-a-time reference, bit for bit: a bag stretched, squeezed and sheared at
  // random (every regime of the law), moving at random, with damping and without
  for (int damp = 0; damp < 2; damp++) {
    urMemSpec s;
    char err[200];
    ur_mem_spec_default(&s);
    s.mesh = 3;
    s.damp = damp ? 0.05 : 0;
    urMembrane* mb = ur_mem_build(&s, err, sizeof err);
    assert_non_null(mb);
    int nn = mb->nn;
    double* st = calloc(ur_mem_state_size(mb), sizeof(double));
    double *f = malloc(3 * (size_t)nn * sizeof(double)),
           *g = malloc(3 * (size_t)nn * sizeof(double));
    assert_true(st && f && g);
    unsigned long long r = 777 + damp;
    for (int it = 0; it < 20; it++) {
      double sx = uni(&r, 0.9, 1.1), sz = uni(&r, 0.5, 1.5);
      for (int i = 0; i < nn; i++) {
        const double* p = mb->x0 + 3 * i;
        st[3 * i] = 2 + sx * p[0] + uni(&r, -3e-3, 3e-3);
        st[3 * i + 1] = -1 + p[1] / sx + uni(&r, -3e-3, 3e-3) + 0.1 * p[0];
        st[3 * i + 2] = 1.5 + sz * p[2] + uni(&r, -3e-3, 3e-3);
        for (int k = 0; k < 3; k++) {
          st[3 * nn + 3 * i + k] = uni(&r, -2, 2);
        }
      }
      st[18 * nn + urMEMS_MGAS] = mb->mref * uni(&r, 0.9, 1.1);
      urMemInfo a, b;
      ur_mem_forces(mb, st, f, &a);
      forces_ref(mb, st, g, &b);
      assert_memory_equal(f, g, 3 * (size_t)nn * sizeof(double));
      assert_memory_equal(&a, &b, sizeof a);
      assert_true(a.strain > 0 && a.efabric > 0 && a.volume > 0);
    }
    free(f);
    free(g);
    free(st);
    ur_mem_free(mb);
  }
}


int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_mesh_closed),     cmocka_unit_test(test_laplace_sphere),
      cmocka_unit_test(test_tension_field),   cmocka_unit_test(test_shear_lock),
      cmocka_unit_test(test_gas_law),         cmocka_unit_test(test_vent_flow),
      cmocka_unit_test(test_stress4_bitwise), cmocka_unit_test(test_forces_bitwise),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
