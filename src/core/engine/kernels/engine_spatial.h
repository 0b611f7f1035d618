/* engine_spatial.h: the small vector, matrix and spatial-algebra kernels that run many times per
 * step, as a template: included with urT the element type (double, or a vector of lanes that run
 * in lock-step) and urK(name) the function name. Scalar and lane instances are the same
 * expressions in the same order, so each lane gives the bits of the scalar kernel. No include
 * guard: included once per instance (engine_util_inline.h, engine_lanes.c); the protocol (who
 * defines and undefines the parameters, the bit-exactness rules): src/README. */

static inline void urK(cross3)(urT r[3], const urT a[3], const urT b[3]) {
  urT t0 = a[1] * b[2] - a[2] * b[1];
  urT t1 = a[2] * b[0] - a[0] * b[2];
  urT t2 = a[0] * b[1] - a[1] * b[0];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

static inline void urK(mulmat3vec)(urT r[3], const urT M[9], const urT v[3]) {
  urT t0 = M[0] * v[0] + M[1] * v[1] + M[2] * v[2];
  urT t1 = M[3] * v[0] + M[4] * v[1] + M[5] * v[2];
  urT t2 = M[6] * v[0] + M[7] * v[1] + M[8] * v[2];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

static inline void urK(mulmat3tvec)(urT r[3], const urT M[9], const urT v[3]) {
  urT t0 = M[0] * v[0] + M[3] * v[1] + M[6] * v[2];
  urT t1 = M[1] * v[0] + M[4] * v[1] + M[7] * v[2];
  urT t2 = M[2] * v[0] + M[5] * v[1] + M[8] * v[2];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
}

// r = t element by element: a memcpy of the lanes' 288 bytes became a rep movs, which cannot
// forward the vector stores of t just made (a stall of the kinematics)
static inline void urK(copy6)(urT r[6], const urT t[6]) {
  r[0] = t[0];
  r[1] = t[1];
  r[2] = t[2];
  r[3] = t[3];
  r[4] = t[4];
  r[5] = t[5];
}

static inline void urK(copy9)(urT r[9], const urT t[9]) {
  urK(copy6)(r, t);
  r[6] = t[6];
  r[7] = t[7];
  r[8] = t[8];
}

static inline void urK(mulmat3)(urT r[9], const urT A[9], const urT B[9]) {
  urT t[9];
  urUNROLL for (int i = 0; i < 3; i++) {
    urUNROLL for (int j = 0; j < 3; j++) {
      t[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    }
  }
  urK(copy9)(r, t);
}

// quaternion product r = a b (w, x, y, z)
static inline void urK(mulquat)(urT r[4], const urT a[4], const urT b[4]) {
  urT t0 = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  urT t1 = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  urT t2 = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  urT t3 = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
  r[0] = t0;
  r[1] = t1;
  r[2] = t2;
  r[3] = t3;
}

static inline void urK(quat2mat)(urT R[9], const urT q[4]) {
  urT w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

// motion vector parent -> child: w' = E w, v' = E (v - p x w)
static inline void urK(xmotion)(urT r[6], const urT E[9], const urT p[3], const urT v[6]) {
  urT t[3];
  urK(cross3)(t, p, v);
  t[0] = v[3] - t[0];
  t[1] = v[4] - t[1];
  t[2] = v[5] - t[2];
  urK(mulmat3vec)(r, E, v);
  urK(mulmat3vec)(r + 3, E, t);
}

// force vector child -> parent (X^T f): f = E^T f', n = E^T n' + p x f
static inline void urK(xforce_t)(urT r[6], const urT E[9], const urT p[3], const urT f[6]) {
  urT n[3], l[3], t[3];
  urK(mulmat3tvec)(n, E, f);
  urK(mulmat3tvec)(l, E, f + 3);
  urK(cross3)(t, p, l);
  r[0] = n[0] + t[0];
  r[1] = n[1] + t[1];
  r[2] = n[2] + t[2];
  r[3] = l[0];
  r[4] = l[1];
  r[5] = l[2];
}

// motion cross product v x m
static inline void urK(crossmotion)(urT r[6], const urT v[6], const urT m[6]) {
  urT a[3], b[3], c[3];
  urK(cross3)(a, v, m);
  urK(cross3)(b, v, m + 3);
  urK(cross3)(c, v + 3, m);
  r[0] = a[0];
  r[1] = a[1];
  r[2] = a[2];
  r[3] = b[0] + c[0];
  r[4] = b[1] + c[1];
  r[5] = b[2] + c[2];
}

// force cross product v x* f
static inline void urK(crossforce)(urT r[6], const urT v[6], const urT f[6]) {
  urT a[3], b[3], c[3];
  urK(cross3)(a, v, f);
  urK(cross3)(b, v + 3, f + 3);
  urK(cross3)(c, v, f + 3);
  r[0] = a[0] + b[0];
  r[1] = a[1] + b[1];
  r[2] = a[2] + b[2];
  r[3] = c[0];
  r[4] = c[1];
  r[5] = c[2];
}

static inline void urK(mul6)(urT r[6], const urT I[36], const urT v[6]) {
  urT t[6];
  urUNROLL for (int i = 0; i < 6; i++) {
    const urT* row = I + 6 * i;
    t[i] = row[0] * v[0] + row[1] * v[1] + row[2] * v[2] + row[3] * v[3] + row[4] * v[4] +
           row[5] * v[5];
  }
  urK(copy6)(r, t);
}
