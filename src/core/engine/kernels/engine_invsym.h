/* engine_invsym.h: the inverse of a small symmetric matrix (joint-space inertias), as a template
 * like engine_spatial.h: urT the element type, urK(name) the name, urSTORAGE the linkage,
 * urBC(x) a double broadcast, urALL(c) true if comparison c holds (in every lane), urSQRT(x) the
 * square root (lane by lane), urINVUNROLL (optional) a pragma unrolling the Cholesky's loops, for
 * an instance inlined with n constant (the same operations in the same order, so the same bits;
 * with n variable GCC would warn of the peeled copies' bounds). For lanes, -1 means some lane's
 * matrix is singular. No include guard: included once per instance; the protocol (who defines
 * and undefines the parameters, the bit-exactness rules): src/README. */

#ifndef urINVUNROLL
#define urINVUNROLL
#define urINVUNROLL_DEFAULT
#endif

// inverse of a small n x n symmetric matrix (closed forms up to 3, Cholesky beyond, which
// needs positive definiteness); -1 if singular
urSTORAGE int urK(invsym)(urT* Ainv, const urT* A, int n) {
  // closed forms for 1 x 1 and 2 x 2
  if (n == 1) {
    if (!urALL(A[0] != 0)) {
      return -1;
    }
    Ainv[0] = 1 / A[0];
    return 0;
  }
  if (n == 2) {
    urT det = A[0] * A[3] - A[1] * A[2];
    if (!urALL(det != 0)) {
      return -1;
    }
    Ainv[0] = A[3] / det;
    Ainv[1] = -A[1] / det;
    Ainv[2] = -A[2] / det;
    Ainv[3] = A[0] / det;
    return 0;
  }
  if (n == 3) {
    urT c0 = A[4] * A[8] - A[5] * A[7], c1 = A[5] * A[6] - A[3] * A[8],
        c2 = A[3] * A[7] - A[4] * A[6];
    urT det = A[0] * c0 + A[1] * c1 + A[2] * c2;
    if (!urALL(det != 0)) {
      return -1;
    }
    urT id = 1 / det;
    Ainv[0] = c0 * id;
    Ainv[1] = (A[2] * A[7] - A[1] * A[8]) * id;
    Ainv[2] = (A[1] * A[5] - A[2] * A[4]) * id;
    Ainv[3] = c1 * id;
    Ainv[4] = (A[0] * A[8] - A[2] * A[6]) * id;
    Ainv[5] = (A[2] * A[3] - A[0] * A[5]) * id;
    Ainv[6] = c2 * id;
    Ainv[7] = (A[1] * A[6] - A[0] * A[7]) * id;
    Ainv[8] = (A[0] * A[4] - A[1] * A[3]) * id;
    return 0;
  }
  // Cholesky A = L L^T, then A^-1 = L^-T L^-1 (A symmetric positive definite)
  urT L[36] = {0}, Li[36] = {0};
  urINVUNROLL for (int j = 0; j < n; j++) {
    urT s = A[n * j + j];
    urINVUNROLL for (int k = 0; k < j; k++) {
      s -= L[6 * j + k] * L[6 * j + k];
    }
    if (!urALL(s > 0)) {
      return -1;
    }
    L[6 * j + j] = urSQRT(s);
    urINVUNROLL for (int i = j + 1; i < n; i++) {
      urT t = A[n * i + j];
      urINVUNROLL for (int k = 0; k < j; k++) {
        t -= L[6 * i + k] * L[6 * j + k];
      }
      L[6 * i + j] = t / L[6 * j + j];
    }
  }

  // invert the triangle
  urINVUNROLL for (int j = 0; j < n; j++) {
    Li[6 * j + j] = 1 / L[6 * j + j];
    urINVUNROLL for (int i = j + 1; i < n; i++) {
      urT t = urBC(0);
      urINVUNROLL for (int k = j; k < i; k++) {
        t -= L[6 * i + k] * Li[6 * k + j];
      }
      Li[6 * i + j] = t / L[6 * i + i];
    }
  }

  // A^-1 = Li^T Li
  urINVUNROLL for (int i = 0; i < n; i++) {
    urINVUNROLL for (int j = i; j < n; j++) {
      urT t = urBC(0);
      urINVUNROLL for (int k = j; k < n; k++) {
        t += Li[6 * k + i] * Li[6 * k + j];
      }
      Ainv[n * i + j] = t;
      Ainv[n * j + i] = t;
    }
  }
  return 0;
}

#ifdef urINVUNROLL_DEFAULT
#undef urINVUNROLL
#undef urINVUNROLL_DEFAULT
#endif
