/* engine_xinertia_rows.h: r += X^T I X for doubles with the rows of the 3 x 3 blocks as vectors
 * (urV4, lane 3 zero), for a run alone's ABA (engine_dynamics.c). The lanes' instance of
 * engine_spatial_inertia.h spends its vector width on four runs; a run alone spends it here on
 * the three columns of a block row, which GCC does not find in the scalar template. Every
 * element is the template's expression in the template's order (a lane's product and sum are
 * the scalar's), and each element of r gains one addition, so r's bits are uru_xinertia_t_add's
 * (test_engine_dynamics checks it). Needs urV4 (engine_internal.h). Include guard: one instance. */
#ifndef UASIMPACT_ENGINE_XINERTIA_ROWS_H
#define UASIMPACT_ENGINE_XINERTIA_ROWS_H

#include <string.h>

#if defined(__clang__)
#define urXR_SHUF(a, b, i, j, k, l) __builtin_shufflevector(a, b, i, j, k, l)
#else
#define urXR_SHUF(a, b, i, j, k, l) __builtin_shuffle(a, b, (urV4I){i, j, k, l})
#endif

typedef double urXR2 __attribute__((vector_size(2 * sizeof(double))));

// a double broadcast, a row of a 3 x 3 block (a0, a1, a2, 0), and one row of r gaining a in
// its columns 0-3 and b in 4-5 (unaligned): macros, as clang will not pass 256-bit vectors by
// value without AVX even to functions it inlines (engine_lanes.c's bc4)
#define urxr_bc(x)           ((urV4){(x), (x), (x), (x)})
#define urxr_row(a0, a1, a2) ((urV4){(a0), (a1), (a2), 0})
#define urxr_add6(r, a, b)                                                                         \
  do {                                                                                             \
    urV4 lo_;                                                                                      \
    urXR2 hi_;                                                                                     \
    memcpy(&lo_, (r), sizeof(lo_));                                                                \
    memcpy(&hi_, (r) + 4, sizeof(hi_));                                                            \
    lo_ += (a);                                                                                    \
    hi_ += (b);                                                                                    \
    memcpy((r), &lo_, sizeof(lo_));                                                                \
    memcpy((r) + 4, &hi_, sizeof(hi_));                                                            \
  } while (0)

// r += X^T I X, X = [E 0; -E px E] (engine_spatial_inertia.h; only I's upper triangle is read)
static inline __attribute__((always_inline)) void urd_xinertia_t_add(double r[36],
                                                                     const double E[9],
                                                                     const double p[3],
                                                                     const double I[36]) {
  urV4 e0 = urxr_row(E[0], E[1], E[2]), e1 = urxr_row(E[3], E[4], E[5]);
  urV4 e2 = urxr_row(E[6], E[7], E[8]);
  urV4 TA[3], TB[3], TC[3], A[3], B[3], C[3], J[3];

  // T = block E, a row at a time: T_ij = a0 E_0j + a1 E_1j + a2 E_2j
  urUNROLL for (int i = 0; i < 3; i++) {
    double a0 = I[i], a1 = i <= 1 ? I[6 * i + 1] : I[6 + i], a2 = I[6 * i + 2];
    double c0 = I[21 + i], c1 = i <= 1 ? I[6 * (3 + i) + 4] : I[27 + i], c2 = I[6 * (3 + i) + 5];
    const double* b = I + 6 * i + 3;
    TA[i] = urxr_bc(a0) * e0 + urxr_bc(a1) * e1 + urxr_bc(a2) * e2;
    TB[i] = urxr_bc(b[0]) * e0 + urxr_bc(b[1]) * e1 + urxr_bc(b[2]) * e2;
    TC[i] = urxr_bc(c0) * e0 + urxr_bc(c1) * e1 + urxr_bc(c2) * e2;
  }

  // rotated blocks, rows: X'_ij = E_0i T_0j + E_1i T_1j + E_2i T_2j (A', C': upper triangles
  // read; C' mirrored from its upper triangle)
  urUNROLL for (int i = 0; i < 3; i++) {
    urV4 x = urxr_bc(E[i]), y = urxr_bc(E[3 + i]), z = urxr_bc(E[6 + i]);
    A[i] = x * TA[0] + y * TA[1] + z * TA[2];
    B[i] = x * TB[0] + y * TB[1] + z * TB[2];
    C[i] = x * TC[0] + y * TC[1] + z * TC[2];
  }
  C[1] = urXR_SHUF(C[0], C[1], 1, 5, 6, 7);
  C[2] = urXR_SHUF(C[0], C[2], 2, 6, 6, 7);
  C[2][1] = C[1][2];

  // J12 = B' + px C', a row at a time
  urV4 p0 = urxr_bc(p[0]), p1 = urxr_bc(p[1]), p2 = urxr_bc(p[2]);
  J[0] = B[0] + p1 * C[2] - p2 * C[1];
  J[1] = B[1] + p2 * C[0] - p0 * C[2];
  J[2] = B[2] + p0 * C[1] - p1 * C[0];

  // J11 row i, lanes j >= i: A'_ij + (p x row j of B')_i - (row i of J12 x p)_j; the columns
  // of B' for the first cross product, the rotations of J12's row and of p for the second
  urV4 pv = urxr_row(p[0], p[1], p[2]), z4 = {0, 0, 0, 0};
  urV4 p_1 = urXR_SHUF(pv, pv, 1, 2, 0, 3), p_2 = urXR_SHUF(pv, pv, 2, 0, 1, 3);
  urV4 t01 = urXR_SHUF(B[0], B[1], 0, 4, 1, 5), t2 = urXR_SHUF(B[2], z4, 0, 4, 1, 5);
  urV4 t23 = urXR_SHUF(B[0], B[1], 2, 6, 3, 7);
  urV4 BT[3] = {urXR_SHUF(t01, t2, 0, 1, 4, 7), urXR_SHUF(t01, t2, 2, 3, 6, 7),
                urXR_SHUF(t23, B[2], 0, 1, 6, 7)};
  urV4 V[3];
  urUNROLL for (int i = 0; i < 3; i++) {
    urV4 pb = urxr_bc(p[(i + 1) % 3]) * BT[(i + 2) % 3] - urxr_bc(p[(i + 2) % 3]) * BT[(i + 1) % 3];
    urV4 j1 = urXR_SHUF(J[i], J[i], 1, 2, 0, 3), j2 = urXR_SHUF(J[i], J[i], 2, 0, 1, 3);
    urV4 jp = j1 * p_2 - j2 * p_1;
    V[i] = A[i] + pb - jp;
  }
  // the symmetric J11 from the upper triangles: rows (v0), (v0_1 v1_1 v1_2), (v0_2 v1_2 v2_2)
  urV4 v1 = urXR_SHUF(V[0], V[1], 1, 5, 6, 7);
  urV4 v2 = urXR_SHUF(V[0], V[2], 2, 6, 6, 7);
  v2[1] = V[1][2];

  // r's rows 0-2: J11 and J12; rows 3-5: J12^T (the columns of J12) and C'
  urV4 j01 = urXR_SHUF(J[0], J[1], 0, 4, 1, 5), j2z = urXR_SHUF(J[2], z4, 0, 4, 1, 5);
  urV4 j23 = urXR_SHUF(J[0], J[1], 2, 6, 3, 7);
  urXR2 hi;
  hi = (urXR2){J[0][1], J[0][2]};
  urxr_add6(r, urXR_SHUF(V[0], J[0], 0, 1, 2, 4), hi);
  hi = (urXR2){J[1][1], J[1][2]};
  urxr_add6(r + 6, urXR_SHUF(v1, J[1], 0, 1, 2, 4), hi);
  hi = (urXR2){J[2][1], J[2][2]};
  urxr_add6(r + 12, urXR_SHUF(v2, J[2], 0, 1, 2, 4), hi);
  hi = (urXR2){C[0][1], C[0][2]};
  urxr_add6(r + 18, urXR_SHUF(urXR_SHUF(j01, j2z, 0, 1, 4, 7), C[0], 0, 1, 2, 4), hi);
  hi = (urXR2){C[1][1], C[1][2]};
  urxr_add6(r + 24, urXR_SHUF(urXR_SHUF(j01, j2z, 2, 3, 6, 7), C[1], 0, 1, 2, 4), hi);
  hi = (urXR2){C[2][1], C[2][2]};
  urxr_add6(r + 30, urXR_SHUF(urXR_SHUF(j23, J[2], 0, 1, 6, 7), C[2], 0, 1, 2, 4), hi);
}

#undef urXR_SHUF
#undef urxr_bc
#undef urxr_row
#undef urxr_add6
#endif
