/* engine_trig.h: sine and cosine together, and the arctangent of a first-quadrant point, as a
 * template over the element type, so that lanes of runs in lock-step evaluate them as vectors
 * and still get the bits a run alone gets. The algorithms are fdlibm's (Sun, 1993, as in musl):
 * Cody-Waite reduction by pi/2 to 118 bits, the kernel polynomials __sin/__cos on [-pi/4, pi/4]
 * with the reduction's tail, and the four-interval arctangent of s_atan.c; all branch-free, the
 * rare arguments they do not cover handed to libm element by element. Errors against the true
 * value: sine and cosine under 1 ulp, the arctangent under 2 (the rounding of its quotient);
 * tests/core/engine/test_engine_trig.c measures them against libm. Parameters: urT the element type, urM the
 * type of its comparisons (the masks), urU the unsigned integer type of its width, urK(name) the
 * function names, urBC(x) a double broadcast to urT, urSEL(m, a, b) a where m else b, urANY(m)
 * whether any element's m holds, urNEL the element count, urEL(x, l) element l of x (an lvalue),
 * urASI(x) / urAST(i) the bits of x as urU and back. No include guard: included once per
 * instance; the protocol (who defines and undefines the parameters, the bit-exactness rules):
 * src/README. */

#ifndef UASIMPACT_ENGINE_TRIG_CONST
#define UASIMPACT_ENGINE_TRIG_CONST
// argument reduction (fdlibm __rem_pio2): pi/2 = PIO2_1 + PIO2_2 + PIO2_2T, 33 + 33 + 53 bits
#define urTRIG_TOINT      6755399441055744.0         /* 1.5 * 2^52: rounds to an integer */
#define urTRIG_INVPIO2    6.36619772367581382433e-01 /* 0x3FE45F30 6DC9C883 */
#define urTRIG_PIO2_1     1.57079632673412561417e+00 /* 0x3FF921FB 54400000 */
#define urTRIG_PIO2_2     6.07710050630396597660e-11 /* 0x3DD0B461 1A600000 */
#define urTRIG_PIO2_2T    2.02226624879595063154e-21 /* 0x3BA3198A 2E037073 */
#define urTRIG_REDUCE_MAX 1.6e6                      /* |x| below 2^20 pi/2: n pi/2 exact */
// kernel sine and cosine on [-pi/4, pi/4] (fdlibm __kernel_sin, __kernel_cos)
#define urTRIG_S1 -1.66666666666666324348e-01
#define urTRIG_S2 8.33333333332248946124e-03
#define urTRIG_S3 -1.98412698298579493134e-04
#define urTRIG_S4 2.75573137070700676789e-06
#define urTRIG_S5 -2.50507602534068634195e-08
#define urTRIG_S6 1.58969099521155010221e-10
#define urTRIG_C1 4.16666666666666019037e-02
#define urTRIG_C2 -1.38888888888741095749e-03
#define urTRIG_C3 2.48015872894767294178e-05
#define urTRIG_C4 -2.75573143513906633035e-07
#define urTRIG_C5 2.08757232129817482790e-09
#define urTRIG_C6 -1.13596475577881948265e-11
// arctangent (fdlibm s_atan.c): atan(1/2), atan(1), atan(3/2), pi/2 as hi + lo; the polynomial
#define urTRIG_ATAN05_HI 4.63647609000806093515e-01
#define urTRIG_ATAN05_LO 2.26987774529616870924e-17
#define urTRIG_ATAN1_HI  7.85398163397448278999e-01
#define urTRIG_ATAN1_LO  3.06161699786838301793e-17
#define urTRIG_ATAN15_HI 9.82793723247329054082e-01
#define urTRIG_ATAN15_LO 1.39033110312309984516e-17
#define urTRIG_PIO2_HI   1.57079632679489655800e+00
#define urTRIG_PIO2_LO   6.12323399573676603587e-17
#define urTRIG_AT0       3.33333333333329318027e-01
#define urTRIG_AT1       -1.99999999998764832476e-01
#define urTRIG_AT2       1.42857142725034663711e-01
#define urTRIG_AT3       -1.11111104054623557880e-01
#define urTRIG_AT4       9.09088713343650656196e-02
#define urTRIG_AT5       -7.69187620504482999495e-02
#define urTRIG_AT6       6.66107313738753120669e-02
#define urTRIG_AT7       -5.83357013379057348645e-02
#define urTRIG_AT8       4.97687799461593236017e-02
#define urTRIG_AT9       -3.65315727442169155270e-02
#define urTRIG_AT10      1.62858201153657823623e-02
#endif


// sin(x) and cos(x): x = n pi/2 + (y0 + y1), the kernels on y0 + y1, swapped and negated by
// n mod 4; |x| < 2^-26 exact (x, 1); beyond 1.6e6, non-finite, or within 2^-48 |x| of a
// multiple of pi/2 (where 118 bits of pi/2 would not do): libm
static inline __attribute__((always_inline)) void urK(sincos)(urT x, urT* sp, urT* cp) {
  urT k = x * urBC(urTRIG_INVPIO2) + urBC(urTRIG_TOINT);
  urU n = urASI(k); // n in the low bits of k
  urT fn = k - urBC(urTRIG_TOINT);
  urT r = x - fn * urBC(urTRIG_PIO2_1); // exact
  urT w = fn * urBC(urTRIG_PIO2_2);     // exact
  urT t = r;
  r = t - w;
  w = fn * urBC(urTRIG_PIO2_2T) - ((t - r) - w);
  urT y0 = r - w, y1 = (r - y0) - w;

  // kernels
  urT z = y0 * y0, ww = z * z, v = z * y0;
  urT rs = urBC(urTRIG_S2) + z * (urBC(urTRIG_S3) + z * urBC(urTRIG_S4)) +
           z * ww * (urBC(urTRIG_S5) + z * urBC(urTRIG_S6));
  urT s = y0 - ((z * (urBC(0.5) * y1 - v * rs) - y1) - v * urBC(urTRIG_S1));
  urT rc = z * (urBC(urTRIG_C1) + z * (urBC(urTRIG_C2) + z * urBC(urTRIG_C3))) +
           ww * ww * (urBC(urTRIG_C4) + z * (urBC(urTRIG_C5) + z * urBC(urTRIG_C6)));
  urT hz = urBC(0.5) * z, one_hz = urBC(1.0) - hz;
  urT c = one_hz + (((urBC(1.0) - one_hz) - hz) + (z * rc - y0 * y1));

  // quadrant: odd n swaps, n = 1, 2 negates the sine, n = 2, 3 the cosine (sign bits)
  urM odd = (n & 1) != 0;
  urU sneg = (n & 2) << 62, cneg = ((n + 1) & 2) << 62;
  urT sv = urAST(urASI(urSEL(odd, c, s)) ^ sneg);
  urT cv = urAST(urASI(urSEL(odd, s, c)) ^ cneg);

  // tiny arguments; the rest to libm
  urT ax = urAST(urASI(x) & 0x7fffffffffffffffULL);
  urM tiny = ax < urBC(0x1p-26);
  sv = urSEL(tiny, x, sv);
  cv = urSEL(tiny, urBC(1.0), cv);
  urT ay0 = urAST(urASI(y0) & 0x7fffffffffffffffULL);
  urM hard = (ax >= urBC(urTRIG_REDUCE_MAX)) | (ax != ax) | (ay0 < ax * urBC(0x1p-48));
  if (urANY(hard)) {
    for (int l_ = 0; l_ < urNEL; l_++) {
      if (urEL(hard, l_)) {
        urEL(sv, l_) = sin(urEL(x, l_));
        urEL(cv, l_) = cos(urEL(x, l_));
      }
    }
  }
  *sp = sv;
  *cp = cv;
}


// atan2(y, x) for y >= 0, x >= 0 (the point in the first quadrant), in [0, pi/2]: s_atan.c's
// reduction of t = y/x to a small argument about 0, 1/2, 1, 3/2 or infinity, taken from y and x
// directly (no rounded quotient first); (0, 0), non-finite or negative coordinates: libm
static inline __attribute__((always_inline)) urT urK(atan2q)(urT y, urT x) {
  urT y16 = urBC(16.0) * y;
  urM r1 = y16 >= urBC(7.0) * x, r2 = y16 >= urBC(11.0) * x, r3 = y16 >= urBC(19.0) * x,
      r4 = y16 >= urBC(39.0) * x;
  urT num = urSEL(
      r4, -x,
      urSEL(r3, urBC(2.0) * y - urBC(3.0) * x, urSEL(r2, y - x, urSEL(r1, urBC(2.0) * y - x, y))));
  urT den = urSEL(
      r4, y,
      urSEL(r3, urBC(2.0) * x + urBC(3.0) * y, urSEL(r2, y + x, urSEL(r1, urBC(2.0) * x + y, x))));
  urT hi =
      urSEL(r4, urBC(urTRIG_PIO2_HI),
            urSEL(r3, urBC(urTRIG_ATAN15_HI),
                  urSEL(r2, urBC(urTRIG_ATAN1_HI), urSEL(r1, urBC(urTRIG_ATAN05_HI), urBC(0.0)))));
  urT lo =
      urSEL(r4, urBC(urTRIG_PIO2_LO),
            urSEL(r3, urBC(urTRIG_ATAN15_LO),
                  urSEL(r2, urBC(urTRIG_ATAN1_LO), urSEL(r1, urBC(urTRIG_ATAN05_LO), urBC(0.0)))));
  urT t = num / den;
  urT z = t * t, w = z * z;
  urT s1 =
      z * (urBC(urTRIG_AT0) +
           w * (urBC(urTRIG_AT2) +
                w * (urBC(urTRIG_AT4) +
                     w * (urBC(urTRIG_AT6) + w * (urBC(urTRIG_AT8) + w * urBC(urTRIG_AT10))))));
  urT s2 = w * (urBC(urTRIG_AT1) +
                w * (urBC(urTRIG_AT3) +
                     w * (urBC(urTRIG_AT5) + w * (urBC(urTRIG_AT7) + w * urBC(urTRIG_AT9)))));
  urT r = hi - ((t * (s1 + s2) - lo) - t);

  urT b = urSEL(y > x, y, x);
  urM hard = (y < urBC(0.0)) | (x < urBC(0.0)) | (y != y) | (x != x) | (b <= urBC(0.0)) |
             (b >= urBC(INFINITY));
  if (urANY(hard)) {
    for (int l_ = 0; l_ < urNEL; l_++) {
      if (urEL(hard, l_)) {
        urEL(r, l_) = atan2(urEL(y, l_), urEL(x, l_));
      }
    }
  }
  return r;
}
