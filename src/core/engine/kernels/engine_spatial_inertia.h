/* engine_spatial_inertia.h: r += X^T I X for a spatial inertia I (the congruence that carries an
 * articulated inertia to the parent), as a template like engine_spatial.h: urT the element type,
 * urK(name) the names, urSTORAGE the linkage (empty: extern, engine_util.c; static:
 * engine_lanes.c). No include guard: included once per instance; the protocol (who defines and
 * undefines the parameters, the bit-exactness rules): src/README. */

// component k of a x b (k constant in unrolled loops; a macro, so that no vector is returned by
// value)
#ifndef urCROSSK
#define urCROSSK(a, b, k)                                                                          \
  ((a)[((k) + 1) % 3] * (b)[((k) + 2) % 3] - (a)[((k) + 2) % 3] * (b)[((k) + 1) % 3])
#endif

// symmetric inertia child -> parent, accumulated: r += X^T I X with X = [E 0; -E px E].
// I = [A B; B^T C] (A, C symmetric; only the upper triangle of I is read). Rotated blocks
// A' = E^T A E, B' = E^T B E, C' = E^T C E; then J12 = B' + px C', J11 = A' + px B'^T - J12 px,
// J22 = C' (symmetric results from their upper triangles; r stays symmetric if it was).
urSTORAGE void urK(xinertia_t_add)(urT r[36], const urT E[9], const urT p[3], const urT I[36]) {
  urT TA[9], TB[9], TC[9], A[9], B[9], C[9], J[9];

  // T = block E (rows i of the blocks, columns j of E); the lower triangles of A and C mirrored
  urUNROLL for (int i = 0; i < 3; i++) {
    urT a0 = I[i];
    urT a1 = i <= 1 ? I[6 * i + 1] : I[6 + i];
    urT a2 = I[6 * i + 2];
    urT c0 = I[21 + i];
    urT c1 = i <= 1 ? I[6 * (3 + i) + 4] : I[27 + i];
    urT c2 = I[6 * (3 + i) + 5];
    const urT* b = I + 6 * i + 3;
    urUNROLL for (int j = 0; j < 3; j++) {
      TA[3 * i + j] = a0 * E[j] + a1 * E[3 + j] + a2 * E[6 + j];
      TB[3 * i + j] = b[0] * E[j] + b[1] * E[3 + j] + b[2] * E[6 + j];
      TC[3 * i + j] = c0 * E[j] + c1 * E[3 + j] + c2 * E[6 + j];
    }
  }

  // rotated blocks: X'_ij = sum_k E_ki T_kj (A', C': upper triangles)
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      B[3 * i + j] = E[i] * TB[j] + E[3 + i] * TB[3 + j] + E[6 + i] * TB[6 + j];
      if (j >= i) {
        A[3 * i + j] = E[i] * TA[j] + E[3 + i] * TA[3 + j] + E[6 + i] * TA[6 + j];
        C[3 * i + j] = E[i] * TC[j] + E[3 + i] * TC[3 + j] + E[6 + i] * TC[6 + j];
      }
    }
  }
  C[3] = C[1];
  C[6] = C[2];
  C[7] = C[5];

  // J12 = B' + px C' (column j: p x C'_j)
  urUNROLL for (int j = 0; j < 3; j++) {
    urT x = C[j], y = C[3 + j], z = C[6 + j];
    J[j] = B[j] + p[1] * z - p[2] * y;
    J[3 + j] = B[3 + j] + p[2] * x - p[0] * z;
    J[6 + j] = B[6 + j] + p[0] * y - p[1] * x;
  }

  // J11 (upper triangle) = A' + (px B'^T)_ij - (J12 px)_ij, with
  // (px M^T)_ij = (p x row j of M)_i and (M px)_ij = (row i of M x p)_j
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = i; j < 3; j++) {
      const urT* bj = B + 3 * j;
      const urT* ji = J + 3 * i;
      urT pb = urCROSSK(p, bj, i), jp = urCROSSK(ji, p, j);
      urT v = A[3 * i + j] + pb - jp;
      r[6 * i + j] += v;
      if (j != i) {
        r[6 * j + i] += v;
      }
    }
  }

  // J12, J21 = J12^T, J22 = C'
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      r[6 * i + 3 + j] += J[3 * i + j];
      r[6 * (3 + j) + i] += J[3 * i + j];
      if (j >= i) {
        r[6 * (3 + i) + 3 + j] += C[3 * i + j];
        if (j != i) {
          r[6 * (3 + j) + 3 + i] += C[3 * i + j];
        }
      }
    }
  }
}

#undef urCROSSK
