/* test_contact_layer.c: the Hertz law on a soft layer over bone (the layer bottoms at its
 * thickness and the bone's stiffness takes over; the law's range is the thickness, so a run
 * notes it) and a hollow part's shell spring in series with the contact (the root of
 * d = (F/K)^(2/3) + F/k_s, and the sheet's numbers for a head on a 230 kN/m ABS shell), capped
 * at its crush load: the plateau, the crushed depth kept, the bottoming, the energy it takes.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "uasimpact/contact.h"

/* |a - b| <= tol with both values printed on failure */
#define assert_near(a, b, tol) near_((a), (b), (tol), #a, __FILE__, __LINE__)
static void near_(double a, double b, double tol, const char* what, const char* file, int line) {
  if (!(fabs(a - b) <= tol)) {
    print_error("%s = %.17g, expected %.17g +- %.3g\n", what, a, b, tol);
    _fail(file, line);
  }
}

/* scalp (Table B1) on carbon, head radius 87.5 mm on a flat, 6 mm over a 4023 N/mm skull */
static urLaw scalp_law(double h, double kb) {
  urLaw l;
  memset(&l, 0, sizeof l);
  ur_law_hertz(&l, 2.23e7, 0.29, 0.0875, 5.48e10, 0.34, 0, 3.42e6, 0.29, 0);
  l.layer_h = h;
  l.bone_k = kb;
  return l;
}

/* below the thickness: Hertz; beyond: F(h) + k_bone (d - h); the slope switches at h */
static void test_bottoming(void** state) {
  urLaw l = scalp_law(0.006, 4.023e6);
  urLawState s = {0};
  double K = 4.0 / 3.0 * l.estar * sqrt(l.radius), h = 0.006;
  for (int i = 1; i <= 12; i++) {
    double d = 0.001 * i;
    double f = d <= h ? K * d * sqrt(d) : K * h * sqrt(h) + 4.023e6 * (d - h);
    assert_near(ur_law_force(&l, &s, d, 0, 0), f, 1e-9 * f);
  }
  double e = 1e-7;
  double below = (ur_law_force(&l, &s, h, 0, 0) - ur_law_force(&l, &s, h - e, 0, 0)) / e;
  double above = (ur_law_force(&l, &s, h + e, 0, 0) - ur_law_force(&l, &s, h, 0, 0)) / e;
  print_message("layer: slope %.4g N/m below %g m, %.4g N/m above (bone %.4g)\n", below, h, above,
                4.023e6);
  assert_near(below, 1.5 * K * sqrt(h), 1e-3 * below);
  assert_near(above, 4.023e6, 1e-3 * 4.023e6);

  // the range the run checks is the thickness; a plain Hertz law has none
  assert_near(ur_law_range(&l), h, 0);
  urLaw plain = scalp_law(0, 0);
  assert_true(isinf(ur_law_range(&plain)));

  // committed at a depth beyond the thickness: fmax is the layered force (elastic unloading)
  ur_law_commit(&l, &s, 0.008, 0, 0);
  assert_near(s.fmax, K * h * sqrt(h) + 4.023e6 * 0.002, 1e-6);
  assert_near(ur_law_force(&l, &s, 0.004, 0, 0), K * 0.004 * sqrt(0.004), 1e-9);
}

/* the series shell: d = (F/K)^(2/3) + F/ks at the force found; the sheet's example (E.3): head
   R 87.5 mm, E* 24.3 MPa on a 230 kN/m ABS shell gives 255, 735, 1603 N at 2, 5, 10 mm against
   Hertz alone 859, 3394, 9600 N (the sheet's rounding: 1 %) */
static void test_series_shell(void** state) {
  urLaw l;
  memset(&l, 0, sizeof l);
  l.type = urLAW_HERTZ;
  l.estar = 24.3e6;
  l.radius = 0.0875;
  l.shell_k = 230e3;
  urLawState s = {0};
  double K = 4.0 / 3.0 * l.estar * sqrt(l.radius);
  static const double D[3] = {0.002, 0.005, 0.010}, F[3] = {255, 735, 1603},
                      H[3] = {859, 3394, 9600};
  for (int i = 0; i < 3; i++) {
    double f = ur_law_force(&l, &s, D[i], 0, 0);
    double back = pow(f / K, 2.0 / 3.0) + f / l.shell_k;
    print_message("shell in series: %g m: %.1f N (sheet %g; Hertz alone %.0f, sheet %g)\n", D[i], f,
                  F[i], K * D[i] * sqrt(D[i]), H[i]);
    assert_near(back, D[i], 1e-12);
    assert_near(f, F[i], 0.01 * F[i]);
    assert_near(K * D[i] * sqrt(D[i]), H[i], 0.01 * H[i]);
  }

  // on a layer: bottomed where the contact's own depth reaches the thickness
  l.layer_h = 0.006;
  l.bone_k = 4.023e6;
  double dh = 0.006 + K * 0.006 * sqrt(0.006) / l.shell_k;
  assert_near(ur_law_range(&l), dh, 1e-15);
  assert_near(ur_law_force(&l, &s, dh, 0, 0), K * 0.006 * sqrt(0.006), 1e-6);
  l.layer_h = 0;

  // a stiff shell tends to Hertz alone; the shell alone bounds the force
  l.shell_k = 1e12;
  assert_near(ur_law_force(&l, &s, 0.005, 0, 0), K * 0.005 * sqrt(0.005), 1e-5 * 3388);
  l.shell_k = 1e3;
  assert_true(ur_law_force(&l, &s, 0.005, 0, 0) < 1e3 * 0.005);
}

/* a head on the sheet's 230 kN/m ABS shell (2 mm, yield 40 MPa: crush load 2 pi M0 = 251.3 N),
   bottoming after 10 mm of crush */
static urLaw crush_law(void) {
  urLaw l;
  memset(&l, 0, sizeof l);
  l.type = urLAW_HERTZ;
  l.estar = 24.3e6;
  l.radius = 0.0875;
  l.shell_k = 230e3;
  l.crush_f = 2 * M_PI * 40e6 * 0.002 * 0.002 / 4;
  l.crush_h = 0.010;
  return l;
}

/* loading: the elastic series (bitwise today's law) up to the crush load, then the plateau at
   exactly that load with the crushed depth d - (Fc/K)^(2/3) - Fc/k_s, then bottomed: the
   contact alone, K (d - h - Fc/k_s)^1.5 */
static void test_crush_loading(void** state) {
  urLaw l = crush_law(), e = l;
  e.crush_f = 0;
  double K = 4.0 / 3.0 * l.estar * sqrt(l.radius), fc = l.crush_f;
  double d0 = pow(fc / K, 2.0 / 3.0) + fc / l.shell_k; /* where the plateau starts */
  urLawState s = {0}, se = {0};
  int plateau = 0, bottomed = 0;
  for (int i = 1; i <= 400; i++) {
    double d = i * 1e-4, f = ur_law_force(&l, &s, d, 0, 0);
    if (d < d0) {
      assert_true(f == ur_law_force(&e, &se, d, 0, 0));
      assert_true(f < fc);
    } else if (d < d0 + l.crush_h) {
      assert_true(f == fc);
      plateau++;
    } else {
      assert_near(f, K * pow(d - l.crush_h - fc / l.shell_k, 1.5), 1e-9 * f);
      assert_true(f >= fc);
      bottomed++;
    }
    ur_law_commit(&l, &s, d, 0, 0);
    double c = d - d0;
    assert_near(s.crush, c < 0 ? 0 : c > l.crush_h ? l.crush_h : c, 1e-12);
  }
  print_message("crush: plateau %.1f N from %.3f mm, %d steps on it, %d bottomed\n", fc, d0 * 1e3,
                plateau, bottomed);
  assert_true(plateau > 90 && bottomed > 200);

  // a crush load above what the depth reaches: today's law throughout, whatever the state says
  l.crush_f = 1e9;
  s.crush = 0;
  for (int i = 1; i <= 100; i++) {
    double d = i * 1e-4;
    assert_true(ur_law_force(&l, &s, d, 0, 0) == ur_law_force(&e, &se, d, 0, 0));
  }
  se.crush = 0.005;
  assert_true(ur_law_force(&e, &se, 0.004, 0, 0) == ur_law_force(&e, &s, 0.004, 0, 0));
}

/* loading onto the plateau and unloading: the shell springs back by its elastic part only
   (the series law shifted by the crushed depth c), clear of the head below c; reloading
   follows the same curve back to the plateau with no new crush; the work taken over the cycle
   is the plateau's, Fc c (trapezoids, 1 um steps), and unloading never returns more */
static void test_crush_cycle(void** state) {
  urLaw l = crush_law(), e = l;
  e.crush_f = 0;
  double fc = l.crush_f, dm = 0.006, h = 1e-6;
  urLawState s = {0}, se = {0};
  double wl = 0, wu = 0, fp = 0;
  int n = (int)(dm / h + 0.5);
  for (int i = 1; i <= n; i++) {
    double f = ur_law_force(&l, &s, i * h, 0, 0);
    wl += 0.5 * (f + fp) * h;
    fp = f;
    ur_law_commit(&l, &s, i * h, 0, 0);
  }
  double c = s.crush;
  assert_true(c > 0.004 && c < l.crush_h);
  for (int i = n - 1; i >= 0; i--) {
    double d = i * h, f = ur_law_force(&l, &s, d, 0, 0);
    assert_true(f <= fc);
    assert_true(f == (d > c ? ur_law_force(&e, &se, d - c, 0, 0) : 0));
    wu += 0.5 * (f + fp) * h;
    fp = f;
    ur_law_commit(&l, &s, d, 0, 0);
    assert_true(s.crush == c);
  }
  print_message("crush cycle: %.4f J in, %.4f J back, Fc c = %.4f J\n", wl, wu, fc * c);
  assert_true(wu <= wl);
  assert_near(wl - wu, fc * c, 1e-3 * fc * c);

  // reloading: no new crush below dm, at the plateau again at dm
  for (int i = 1; i <= n; i++) {
    ur_law_commit(&l, &s, i * h, 0, 0);
    assert_true(s.crush == c);
  }
  assert_near(ur_law_force(&l, &s, dm, 0, 0), fc, 1e-9 * fc);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bottoming),
      cmocka_unit_test(test_series_shell),
      cmocka_unit_test(test_crush_loading),
      cmocka_unit_test(test_crush_cycle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
