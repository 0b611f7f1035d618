/* contact_geom.c: ellipsoid-plane and ellipsoid-ellipsoid contact geometry, section area and
 * cap volume. Sources: contact-airbag sheet §2.1-2.3, §2.5; support function as in MuJoCo
 * engine_collision_convex.c (mjc_ellipsoidSupport). Superellipsoids (degree p > 2, MADYMO's
 * "ellipsoid degree"): support function the dual norm ||diag(r) R^T u||_q, q = p/(p-1).
 */
#include <float.h>
#include <math.h>

#include "uasimpact/contact.h"

#define NEWTON_MAXITER 60    /* Newton iterations per start */
#define LS_MAXHALF     40    /* backtracking halvings */
#define STEP_CAP       0.5   /* largest tangent step, rad */
#define GRAD_TOL       1e-13 /* tangent gradient tolerance, relative to the length scale */
#define SUP_FLOOR      1e-12 /* floor on |w_l| / h in the Hessian weight |w_l / h|^(q-2) */
#define DEC_TOL                                                                                    \
  1e-14                 /* squared Newton decrement ending a search with a
                                      superellipsoid, relative to the length scale */
#define STALL_TOL 1e-15 /* a smaller decrease of f ends it too (rounding), relative */
#define CROSS_MIN 1e-6  /* shortest power-law step fraction tried */

/* per-ellipsoid data: Q = R D^2 R^T (symmetric, 6 entries: xx yy zz xy xz yz) */
typedef struct {
  double q[6];
  double c[3];
  double rho;  /* smallest radius of curvature: rmin^2 / rmax */
  double rmax; /* largest semi-axis */
} ellData;

/* state of the support-function evaluation at one direction */
typedef struct {
  double u[3];
  double qa[3], qb[3]; /* Q_A u, Q_B u */
  double ra, rb;       /* |M_A u|, |M_B u| */
  double f;            /* support function of A - B */
} evalPt;

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Q u for packed symmetric Q */
static void qmul(const double q[6], const double u[3], double out[3]) {
  out[0] = q[0] * u[0] + q[3] * u[1] + q[4] * u[2];
  out[1] = q[3] * u[0] + q[1] * u[1] + q[5] * u[2];
  out[2] = q[4] * u[0] + q[5] * u[1] + q[2] * u[2];
}

/* precompute Q = R diag(r^2) R^T and curvature bounds (sheet §2.1) */
static void elldata(const urEllipsoid* e, ellData* d) {
  const double* R = e->R;
  double s0 = e->r[0] * e->r[0], s1 = e->r[1] * e->r[1], s2 = e->r[2] * e->r[2];
  d->q[0] = R[0] * R[0] * s0 + R[1] * R[1] * s1 + R[2] * R[2] * s2;
  d->q[1] = R[3] * R[3] * s0 + R[4] * R[4] * s1 + R[5] * R[5] * s2;
  d->q[2] = R[6] * R[6] * s0 + R[7] * R[7] * s1 + R[8] * R[8] * s2;
  d->q[3] = R[0] * R[3] * s0 + R[1] * R[4] * s1 + R[2] * R[5] * s2;
  d->q[4] = R[0] * R[6] * s0 + R[1] * R[7] * s1 + R[2] * R[8] * s2;
  d->q[5] = R[3] * R[6] * s0 + R[4] * R[7] * s1 + R[5] * R[8] * s2;
  d->c[0] = e->c[0];
  d->c[1] = e->c[1];
  d->c[2] = e->c[2];

  // smallest and largest semi-axis
  double rmin = e->r[0], rmax = e->r[0];
  for (int i = 1; i < 3; i++) {
    if (e->r[i] < rmin) rmin = e->r[i];
    if (e->r[i] > rmax) rmax = e->r[i];
  }
  d->rmax = rmax;
  d->rho = rmin * rmin / rmax;
}

/* evaluate f(u) = (c_A - c_B).u + |M_A u| + |M_B u| at unit u (sheet §2.3) */
static void evalf(const ellData* A, const ellData* B, const double dc[3], const double u[3],
                  evalPt* p) {
  p->u[0] = u[0];
  p->u[1] = u[1];
  p->u[2] = u[2];
  qmul(A->q, u, p->qa);
  qmul(B->q, u, p->qb);
  p->ra = sqrt(dot3(u, p->qa));
  p->rb = sqrt(dot3(u, p->qb));
  p->f = dot3(dc, u) + p->ra + p->rb;
}

/* orthonormal tangent basis t1, t2 perpendicular to unit u */
static void tangents(const double u[3], double t1[3], double t2[3]) {
  // cross u with the axis of its smallest component
  double ax = fabs(u[0]), ay = fabs(u[1]), az = fabs(u[2]);
  if (ax <= ay && ax <= az) {
    t1[0] = 0;
    t1[1] = u[2];
    t1[2] = -u[1];
  } else if (ay <= az) {
    t1[0] = -u[2];
    t1[1] = 0;
    t1[2] = u[0];
  } else {
    t1[0] = u[1];
    t1[1] = -u[0];
    t1[2] = 0;
  }
  double s = 1.0 / sqrt(dot3(t1, t1));
  t1[0] *= s;
  t1[1] *= s;
  t1[2] *= s;

  // t2 = u x t1
  t2[0] = u[1] * t1[2] - u[2] * t1[1];
  t2[1] = u[2] * t1[0] - u[0] * t1[2];
  t2[2] = u[0] * t1[1] - u[1] * t1[0];
}

/* tangent-plane Hessian entries t_i^T (Q - q q^T / r^2) t_j / r of one ellipsoid, added to h */
static void addhess(const double q6[6], const double qu[3], double r, const double t1[3],
                    const double t2[3], double h[3]) {
  double Qt1[3], Qt2[3];
  qmul(q6, t1, Qt1);
  qmul(q6, t2, Qt2);
  double a1 = dot3(t1, qu), a2 = dot3(t2, qu);
  double ir = 1.0 / r, ir2 = ir * ir;
  h[0] += (dot3(t1, Qt1) - a1 * a1 * ir2) * ir;
  h[1] += (dot3(t1, Qt2) - a1 * a2 * ir2) * ir;
  h[2] += (dot3(t2, Qt2) - a2 * a2 * ir2) * ir;
}

/* Newton step (e1, e2) from the tangent Hessian h (entries 11, 12, 22) and gradient (g1, g2)
   if h is positive definite (returns 1), else a gradient step scaled by its largest curvature */
static int stepdir(const double h[3], double g1, double g2, double scale, double* e1, double* e2) {
  double det = h[0] * h[2] - h[1] * h[1];
  int newt = h[0] > 0 && det > 1e-14 * (h[0] * h[0] + h[2] * h[2]);
  if (newt) {
    *e1 = -(h[2] * g1 - h[1] * g2) / det;
    *e2 = -(h[0] * g2 - h[1] * g1) / det;
  } else {
    double tr = 0.5 * (h[0] + h[2]);
    double lmax = fabs(tr) + sqrt(0.25 * (h[0] - h[2]) * (h[0] - h[2]) + h[1] * h[1]);
    if (lmax < 1e-3 * scale) lmax = 1e-3 * scale;
    *e1 = -g1 / lmax;
    *e2 = -g2 / lmax;
  }
  return newt;
}

/* cap the step length at STEP_CAP; returns the length before */
static double capstep(double* e1, double* e2) {
  double en = sqrt(*e1 * *e1 + *e2 * *e2);
  if (en > STEP_CAP) {
    *e1 *= STEP_CAP / en;
    *e2 *= STEP_CAP / en;
  }
  return en;
}

/* unit direction u + e1 t1 + e2 t2 */
static void stepto(const double u[3], const double t1[3], const double t2[3], double e1, double e2,
                   double v[3]) {
  for (int i = 0; i < 3; i++) v[i] = u[i] + e1 * t1[i] + e2 * t2[i];
  double s = 1.0 / sqrt(dot3(v, v));
  v[0] *= s;
  v[1] *= s;
  v[2] *= s;
}

/* Riemannian Newton on the unit sphere from unit u0 (sheet §2.3); returns iterations used */
static int newton(const ellData* A, const ellData* B, const double dc[3], double scale,
                  const double u0[3], evalPt* cur, int* conv) {
  evalPt trial;
  int it;
  *conv = 0;
  evalf(A, B, dc, u0, cur);
  for (it = 0; it < NEWTON_MAXITER; it++) {
    // gradient w = s_A(u) - s_B(-u) and its tangent part
    double ira = 1.0 / cur->ra, irb = 1.0 / cur->rb;
    double w[3], t1[3], t2[3];
    for (int i = 0; i < 3; i++) w[i] = dc[i] + cur->qa[i] * ira + cur->qb[i] * irb;
    tangents(cur->u, t1, t2);
    double g1 = dot3(t1, w), g2 = dot3(t2, w);
    double gn = sqrt(g1 * g1 + g2 * g2);
    if (gn <= GRAD_TOL * scale) {
      *conv = 1;
      break;
    }

    // Riemannian Hessian: projected ambient Hessian minus (u.w) I, with u.w = f
    double h[3] = {-cur->f, 0, -cur->f};
    addhess(A->q, cur->qa, cur->ra, t1, t2, h);
    addhess(B->q, cur->qb, cur->rb, t1, t2, h);

    // Newton step if positive definite, else scaled gradient step; capped
    double e1, e2;
    int newt = stepdir(h, g1, g2, scale, &e1, &e2);
    double en0 = capstep(&e1, &e2), en = fmin(en0, STEP_CAP);

    // backtracking line search on f (skipped for tiny Newton steps: rounding dominates there)
    double slope = g1 * e1 + g2 * e2;
    int accepted = 0, k;
    for (k = 0; k < LS_MAXHALF; k++) {
      double v[3];
      stepto(cur->u, t1, t2, e1, e2, v);
      evalf(A, B, dc, v, &trial);
      if ((newt && en < 1e-5) || trial.f <= cur->f + 1e-4 * slope) {
        accepted = 1;
        break;
      }
      e1 *= 0.5;
      e2 *= 0.5;
      slope *= 0.5;
      en *= 0.5;
    }
    if (!accepted) {
      *conv = 1; /* no decrease possible at machine precision */
      break;
    }
    *cur = trial;

    // a full Newton step this short leaves an error ~ step^2: converged
    if (newt && k == 0 && en0 < 1e-7) {
      *conv = 1;
      it++;
      break;
    }
  }
  return it;
}

/* sigma = |M n| = |D R^T n| (half-width along n) and Q n = R D^2 R^T n (sheet §2.1) */
static double halfwidth(const urEllipsoid* e, const double n[3], double qn[3]) {
  const double* R = e->R;
  double v[3], s2 = 0;
  for (int k = 0; k < 3; k++) {
    double rk2 = e->r[k] * e->r[k];
    double vk = R[k] * n[0] + R[3 + k] * n[1] + R[6 + k] * n[2];
    s2 += rk2 * vk * vk;
    v[k] = rk2 * vk;
  }
  for (int i = 0; i < 3; i++) qn[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
  return sqrt(s2);
}

/* fill the contact record from the minimiser */
static void fillcontact(const ellData* A, const ellData* B, const evalPt* p, urGeomContact* out) {
  double ira = 1.0 / p->ra, irb = 1.0 / p->rb;
  for (int i = 0; i < 3; i++) {
    out->n[i] = p->u[i];
    out->pa[i] = A->c[i] + p->qa[i] * ira;
    out->pb[i] = B->c[i] - p->qb[i] * irb;
    out->p[i] = 0.5 * (out->pa[i] + out->pb[i]);
  }
  out->g = p->f;
}

/* first direction: warm u if given, else the centre line A -> B (dc = c_A - c_B) */
static void startdir(const double u[3], const double dc[3], double dist, double scale,
                     double u0[3]) {
  double un = sqrt(dot3(u, u));
  if (un > 1e-12) {
    u0[0] = u[0] / un;
    u0[1] = u[1] / un;
    u0[2] = u[2] / un;
  } else if (dist > 1e-12 * scale) {
    u0[0] = -dc[0] / dist;
    u0[1] = -dc[1] / dist;
    u0[2] = -dc[2] / dist;
  } else {
    u0[0] = 0;
    u0[1] = 0;
    u0[2] = 1;
  }
}

/* more starting directions for the deep-penetration guard: the centre line and the axes of
   A and B both ways; returns their number */
static int startset(const urEllipsoid* a, const urEllipsoid* b, const double dc[3], double dist,
                    double scale, double starts[14][3]) {
  int ns = 0;
  if (dist > 1e-12 * scale) {
    starts[ns][0] = -dc[0] / dist;
    starts[ns][1] = -dc[1] / dist;
    starts[ns][2] = -dc[2] / dist;
    ns++;
  }
  for (int k = 0; k < 3; k++) {
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      for (int i = 0; i < 3; i++) starts[ns][i] = sgn * a->R[3 * i + k];
      ns++;
      for (int i = 0; i < 3; i++) starts[ns][i] = sgn * b->R[3 * i + k];
      ns++;
    }
  }
  return ns;
}

/* ---- superellipsoids ---- */

/* one shape of a pair with a superellipsoid */
typedef struct {
  ellData e;       /* centre, Q (ellipsoid kind), curvature bounds */
  const double* R; /* orientation */
  const double* r; /* semi-axes */
  double q;        /* dual exponent p/(p-1) */
  int super;       /* p > 2 */
} shapeData;

/* one shape's half-width at a direction */
typedef struct {
  double h;           /* h(u) */
  double s[3];        /* gradient of h: support point minus centre */
  double qu[3];       /* ellipsoid: Q u */
  double g[3], wh[3]; /* superellipsoid: local gradient, |w_l| / h */
} shapeEval;

/* the support function of A - B at one direction */
typedef struct {
  double u[3];
  shapeEval a, b;
  double f;
} superPt;

/* ||w||_q, scaled by m = max |w_l|: a_l = (|w_l|/m)^(q-1), *k = ||w/m||_q / sum a_l |w_l|/m.
   The largest coordinate's x is 1 exactly, whose power is 1 without a call to pow (the same
   bits: pow(1, y) = 1), one of the three calls saved in most directions */
static double qnorm(const double w[3], double q, double a[3], double* k) {
  double m = fmax(fabs(w[0]), fmax(fabs(w[1]), fabs(w[2])));
  if (!(m > 0)) {
    a[0] = a[1] = a[2] = 0;
    *k = 0;
    return 0;
  }
  double sum = 0;
  for (int l = 0; l < 3; l++) {
    double x = fabs(w[l]) / m;
    a[l] = x == 1 ? 1 : x > 0 ? pow(x, q - 1) : 0; /* pow(1, y) is 1 exactly: no call */
    sum += a[l] * x;
  }
  double t = pow(sum, 1 / q);
  *k = t / sum;
  return m * t;
}

/* smallest principal radius of curvature of a superellipsoid, bounded below: the normal
   curvature of sum |y_l|^p = 1 (y_l = x_l / r_l) is at most (p-1) rmax / (rmin^2 max|y_l|),
   and max|y_l| >= 3^(-1/p) */
static double superrho(const urEllipsoid* e) {
  double rmin = fmin(e->r[0], fmin(e->r[1], e->r[2]));
  double rmax = fmax(e->r[0], fmax(e->r[1], e->r[2]));
  return rmin * rmin / ((e->p - 1) * pow(3, 1 / e->p) * rmax);
}

/* a superellipsoid's S->e.rho is left to superrho, and its largest Hessian weight to
   hess_floor, where they are needed (each a call of pow, needed by a few calls in a hundred) */
static void shapedata(const urEllipsoid* e, shapeData* S) {
  elldata(e, &S->e);
  S->R = e->R;
  S->r = e->r;
  S->super = e->p > 2;
  S->q = 2;
  if (S->super) {
    S->q = e->p / (e->p - 1);
  }
}

/* the largest Hessian weight of a superellipsoid: SUP_FLOOR^(q-2) */
static double hess_floor(const shapeData* S) {
  return pow(SUP_FLOOR, S->q - 2);
}

/* the shape's smallest radius of curvature, bounded below */
static double shaperho(const urEllipsoid* e, const shapeData* S) {
  return S->super ? superrho(e) : S->e.rho;
}

/* h, its gradient and the Hessian data of one shape at unit u */
static void shapeeval(const shapeData* S, const double u[3], shapeEval* v) {
  if (!S->super) {
    qmul(S->e.q, u, v->qu);
    v->h = sqrt(dot3(u, v->qu));
    double ih = 1.0 / v->h;
    for (int i = 0; i < 3; i++) v->s[i] = v->qu[i] * ih;
    return;
  }

  // local w = diag(r) R^T u, h = ||w||_q, g_l = sign(w_l) |w_l / h|^(q-1)
  const double* R = S->R;
  double w[3], a[3], k;
  for (int l = 0; l < 3; l++) w[l] = S->r[l] * (R[l] * u[0] + R[3 + l] * u[1] + R[6 + l] * u[2]);
  v->h = qnorm(w, S->q, a, &k);
  for (int l = 0; l < 3; l++) {
    v->g[l] = copysign(a[l] * k, w[l]);
    v->wh[l] = fabs(w[l]) / v->h;
  }

  // support offset R diag(r) g
  for (int i = 0; i < 3; i++) {
    v->s[i] = R[3 * i] * S->r[0] * v->g[0] + R[3 * i + 1] * S->r[1] * v->g[1] +
              R[3 * i + 2] * S->r[2] * v->g[2];
  }
}

/* tangent-plane Hessian of a superellipsoid's h, added to h3: with tau_k = diag(r) R^T t_k,
   (q-1)/h [sum_l d_l tau_il tau_jl - (g.tau_i)(g.tau_j)], d_l = |w_l / h|^(q-2) (floored
   argument: infinite at a zero coordinate) */
static void shapehess(const shapeData* S, const shapeEval* v, const double t1[3],
                      const double t2[3], double h3[3]) {
  if (!S->super) {
    addhess(S->e.q, v->qu, v->h, t1, t2, h3);
    return;
  }
  const double* R = S->R;
  double s11 = 0, s12 = 0, s22 = 0, g1 = 0, g2 = 0;
  for (int l = 0; l < 3; l++) {
    double a1 = S->r[l] * (R[l] * t1[0] + R[3 + l] * t1[1] + R[6 + l] * t1[2]);
    double a2 = S->r[l] * (R[l] * t2[0] + R[3 + l] * t2[1] + R[6 + l] * t2[2]);
    double d = v->wh[l] >= SUP_FLOOR ? fabs(v->g[l]) / v->wh[l] : hess_floor(S);
    s11 += d * a1 * a1;
    s12 += d * a1 * a2;
    s22 += d * a2 * a2;
    g1 += v->g[l] * a1;
    g2 += v->g[l] * a2;
  }
  double c = (S->q - 1) / v->h;
  h3[0] += c * (s11 - g1 * g1);
  h3[1] += c * (s12 - g1 * g2);
  h3[2] += c * (s22 - g2 * g2);
}

/* f(u) = (c_A - c_B).u + h_A(u) + h_B(u) at unit u */
static void evalsup(const shapeData* A, const shapeData* B, const double dc[3], const double u[3],
                    superPt* p) {
  p->u[0] = u[0];
  p->u[1] = u[1];
  p->u[2] = u[2];
  shapeeval(A, u, &p->a);
  shapeeval(B, u, &p->b);
  p->f = dot3(dc, u) + p->a.h + p->b.h;
}

/* step fraction a along u + a e from a superellipsoid's power law: where one local coordinate
   w_l = c0 + a c1 carries most of the curvature k of f along e, f ~ A |w_l|^q + linear in a,
   and the Newton step (a = 1) fixes A and the linear term; the minimum then lies at
   w_l / c0 = sign(rho) |rho|^(p-1), rho = 1 + (q-1) c1 / c0: at the sign change for
   rho = 0, beyond it for rho < 0, far out when escaping a zero (rho > 1). 0: none */
static double powerstep(const shapeData* S, const shapeEval* v, const double u[3],
                        const double e[3], double k, double amax) {
  for (int l = 0; S->super && l < 3; l++) {
    if (!(v->wh[l] >= SUP_FLOOR)) continue;
    double c0 = S->R[l] * u[0] + S->R[3 + l] * u[1] + S->R[6 + l] * u[2];
    double c1 = S->R[l] * e[0] + S->R[3 + l] * e[1] + S->R[6 + l] * e[2];
    double tau = S->r[l] * c1;
    if ((S->q - 1) / v->h * fabs(v->g[l]) / v->wh[l] * tau * tau > 0.5 * k) {
      double rho = 1 + (S->q - 1) * c1 / c0;
      double x = copysign(pow(fabs(rho), 1 / (S->q - 1)), rho);
      return fmin(fmax((x - 1) * c0 / c1, CROSS_MIN), amax);
    }
  }
  return 0;
}

/* step (e1, e2) = -sum_i (g.v_i) v_i / max(|lambda_i|, 1e-3 scale) over the eigenpairs of
   the tangent Hessian h: the Newton step where h is positive definite, and where it is not
   a descent step that still resolves the curvatures (one stiff direction at a flat face
   would shrink a gradient step scaled by the largest curvature); returns 1 if positive
   definite */
static int stepabs(const double h[3], double g1, double g2, double scale, double* e1, double* e2) {
  double tr = 0.5 * (h[0] + h[2]), dd = 0.5 * (h[0] - h[2]);
  double rad = sqrt(dd * dd + h[1] * h[1]);
  double l1 = tr + rad, l2 = tr - rad, v1, v2;
  if (rad == 0) {
    v1 = 1;
    v2 = 0;
  } else if (dd >= 0) {
    v1 = dd + rad; /* (l1 - h22, h12), stable for h11 >= h22 */
    v2 = h[1];
  } else {
    v1 = h[1]; /* (h12, l1 - h11) */
    v2 = rad - dd;
  }
  double vn = 1.0 / sqrt(v1 * v1 + v2 * v2);
  v1 *= vn;
  v2 *= vn;
  double lo = 1e-3 * scale;
  double c1 = (g1 * v1 + g2 * v2) / fmax(fabs(l1), lo);
  double c2 = (g2 * v1 - g1 * v2) / fmax(fabs(l2), lo);
  *e1 = -(c1 * v1 - c2 * v2);
  *e2 = -(c1 * v2 + c2 * v1);
  return l2 > 0;
}

/* evaluate at the unit direction u + a e */
static void trystep(const shapeData* A, const shapeData* B, const double dc[3], const double u[3],
                    const double e[3], double a, superPt* p) {
  double v[3];
  for (int i = 0; i < 3; i++) v[i] = u[i] + a * e[i];
  double s = 1.0 / sqrt(dot3(v, v));
  v[0] *= s;
  v[1] *= s;
  v[2] *= s;
  evalsup(A, B, dc, v, p);
}

/* Riemannian Newton for a pair with a superellipsoid. Where the support point lies on or near
   a symmetry plane of a superellipsoid (a local coordinate w_l near 0) h grows like |w_l|^q,
   1 < q < 2: full Newton steps overshoot the zero by up to p-1 times, or crawl away from it,
   so a second step along the same direction follows that coordinate's power law (powerstep)
   and the better of the two is taken before backtracking. The gradient need not vanish near
   such a minimum: the search ends when the squared Newton decrement (the predicted decrease)
   falls below DEC_TOL, after that last step if it does not increase f, or when f stops
   decreasing beyond rounding. Returns iterations used. */
static int snewton(const shapeData* A, const shapeData* B, const double dc[3], double scale,
                   const double u0[3], superPt* cur, int* conv) {
  superPt trial, alt;
  int it;
  *conv = 0;
  evalsup(A, B, dc, u0, cur);
  for (it = 0; it < NEWTON_MAXITER; it++) {
    // tangent gradient and Hessian as in newton
    double w[3], t1[3], t2[3];
    for (int i = 0; i < 3; i++) w[i] = dc[i] + cur->a.s[i] + cur->b.s[i];
    tangents(cur->u, t1, t2);
    double g1 = dot3(t1, w), g2 = dot3(t2, w);
    if (sqrt(g1 * g1 + g2 * g2) <= GRAD_TOL * scale) {
      *conv = 1;
      break;
    }
    double h[3] = {-cur->f, 0, -cur->f};
    shapehess(A, &cur->a, t1, t2, h);
    shapehess(B, &cur->b, t1, t2, h);
    double e1, e2;
    int newt = stepabs(h, g1, g2, scale, &e1, &e2);
    int last = newt && -(g1 * e1 + g2 * e2) <= DEC_TOL * scale;
    capstep(&e1, &e2);

    // the full step and the power-law step, the better one
    double slope = g1 * e1 + g2 * e2, e[3], a = 1;
    double kap = h[0] * e1 * e1 + 2 * h[1] * e1 * e2 + h[2] * e2 * e2;
    for (int i = 0; i < 3; i++) e[i] = e1 * t1[i] + e2 * t2[i];
    double amax = STEP_CAP / fmax(sqrt(e1 * e1 + e2 * e2), DBL_MIN);
    double ap = kap > 0 ? powerstep(A, &cur->a, cur->u, e, kap, amax) : 0;
    if (ap == 0 && kap > 0) ap = powerstep(B, &cur->b, cur->u, e, kap, amax);
    trystep(A, B, dc, cur->u, e, 1, &trial);
    if (ap > 0 && fabs(ap - 1) > 0.1) {
      trystep(A, B, dc, cur->u, e, ap, &alt);
      if (alt.f < trial.f) {
        trial = alt;
        a = ap;
      }
    }
    if (last) {
      if (trial.f <= cur->f) *cur = trial;
      *conv = 1;
      it++;
      break;
    }

    // backtracking from the full step
    int ok = trial.f <= cur->f + 1e-4 * fmin(a, 1) * slope;
    for (int k = 1; !ok && k <= LS_MAXHALF; k++) {
      a = ldexp(1, -k);
      trystep(A, B, dc, cur->u, e, a, &trial);
      ok = trial.f <= cur->f + 1e-4 * a * slope;
    }
    if (!ok || trial.f > cur->f - STALL_TOL * scale) {
      if (ok) *cur = trial;
      *conv = 1; /* no decrease possible beyond rounding */
      it++;
      break;
    }
    *cur = trial;
  }
  return it;
}

/* ur_collide_ellipsoids for a pair with a superellipsoid */
static int collide_super(const urEllipsoid* a, const urEllipsoid* b, double u[3],
                         urGeomContact* out) {
  shapeData A, B;
  shapedata(a, &A);
  shapedata(b, &B);
  double dc[3] = {a->c[0] - b->c[0], a->c[1] - b->c[1], a->c[2] - b->c[2]};
  double dist = sqrt(dot3(dc, dc));
  double scale = A.e.rmax + B.e.rmax + dist;
  double u0[3], starts[14][3];
  startdir(u, dc, dist, scale, u0);
  superPt best, cur;
  int conv;
  int iters = snewton(&A, &B, dc, scale, u0, &best, &conv);

  // deep-penetration guard as for ellipsoids, with the superellipsoids' curvature bounds (a
  // separated pair, f < 0, passes it whatever they are)
  if (!conv || (best.f >= 0 && best.f >= (shaperho(a, &A) + shaperho(b, &B)) * (1 - 1e-9))) {
    int ns = startset(a, b, dc, dist, scale, starts);
    for (int s = 0; s < ns; s++) {
      iters += snewton(&A, &B, dc, scale, starts[s], &cur, &conv);
      if (cur.f < best.f) best = cur;
    }
  }

  // report the minimiser; the contact point is taken from the rounder body's deepest point, a
  // depth's half along the normal: on a flat face the support point may sit anywhere on the
  // face (a direction 1e-17 rad off its normal moves it by 1 % of the face), which would make
  // the force's lever arm arbitrary
  double pa = a->p > 2 ? a->p : 2, pb = b->p > 2 ? b->p : 2;
  for (int i = 0; i < 3; i++) {
    out->n[i] = best.u[i];
    out->pa[i] = a->c[i] + best.a.s[i];
    out->pb[i] = b->c[i] - best.b.s[i];
    out->p[i] =
        pb <= pa ? out->pb[i] + 0.5 * best.f * best.u[i] : out->pa[i] - 0.5 * best.f * best.u[i];
    u[i] = best.u[i];
  }
  out->g = best.f;
  out->iters = iters;
  return out->g > 0;
}

double ur_halfwidth_local(const double w[3], double p) {
  if (!(p > 2)) return sqrt(dot3(w, w));
  double a[3], k;
  return qnorm(w, p / (p - 1), a, &k);
}

double ur_bound_radius(const double r[3], double p) {
  // farthest point: maximise sum r_l^2 y_l^2 over sum y_l^p = 1, i.e. sum r_l^2 z_l^(2/p)
  // over the simplex (concave): z_l ~ r_l^k, k = 2p/(p-2), and the maximum is ||r||_k
  double rmax = fmax(r[0], fmax(r[1], r[2]));
  if (!(p > 2)) return rmax;
  double k = 2 * p / (p - 2), s = 0;
  for (int l = 0; l < 3; l++) s += pow(r[l] / rmax, k);
  return rmax * pow(s, 1 / k) * (1 + 8 * DBL_EPSILON);
}

int ur_collide_ellipsoid_plane(const urEllipsoid* e, const double n[3], double d,
                               urGeomContact* out) {
  // support of the ellipsoid in -n: p = c - Q n / |M n|  (sheet §2.2); of a superellipsoid
  // p = c - grad h(n)
  double qn[3], sn[3], sig;
  if (e->p > 2) {
    shapeData S;
    shapeEval v;
    shapedata(e, &S);
    shapeeval(&S, n, &v);
    sig = v.h;
    sn[0] = v.s[0];
    sn[1] = v.s[1];
    sn[2] = v.s[2];
  } else {
    sig = halfwidth(e, n, qn);
    double is = 1.0 / sig;
    sn[0] = qn[0] * is;
    sn[1] = qn[1] * is;
    sn[2] = qn[2] * is;
  }
  double g = d - dot3(n, e->c) + sig;

  // deepest points: pa on the ellipsoid, pb its projection on the plane
  for (int i = 0; i < 3; i++) {
    out->pa[i] = e->c[i] - sn[i];
    out->pb[i] = out->pa[i] + g * n[i];
    out->p[i] = out->pa[i] + 0.5 * g * n[i];
    out->n[i] = -n[i];
  }
  out->g = g;
  out->iters = 0;
  return g > 0;
}

int ur_collide_ellipsoids(const urEllipsoid* a, const urEllipsoid* b, double u[3],
                          urGeomContact* out) {
  if (a->p > 2 || b->p > 2) return collide_super(a, b, u, out);
  ellData A, B;
  elldata(a, &A);
  elldata(b, &B);
  double dc[3] = {a->c[0] - b->c[0], a->c[1] - b->c[1], a->c[2] - b->c[2]};
  double dist = sqrt(dot3(dc, dc));
  double scale = A.rmax + B.rmax + dist;

  // start: warm u if given, else the centre line A -> B
  double u0[3];
  startdir(u, dc, dist, scale, u0);
  evalPt best, cur;
  int conv;
  int iters = newton(&A, &B, dc, scale, u0, &best, &conv);

  // deep-penetration guard: a local minimum below tau = rho_A + rho_B (a lower bound on the
  // radii of curvature of A - B) is the global one; above it, try more starting directions,
  // those whose value is not already tau above the best found (a flat airbag deep in a head
  // ran all 14 every step: twice the grid's time for the same cells, bit for bit, in case A)
  double tau = A.rho + B.rho;
  if (best.f >= tau * (1 - 1e-9) || !conv) {
    double starts[14][3];
    int ns = startset(a, b, dc, dist, scale, starts);
    for (int s = 0; s < ns; s++) {
      evalf(&A, &B, dc, starts[s], &cur);
      if (!(cur.f < best.f + tau)) continue;
      iters += newton(&A, &B, dc, scale, starts[s], &cur, &conv);
      if (cur.f < best.f) best = cur;
    }
  }

  // report the minimiser
  fillcontact(&A, &B, &best, out);
  out->iters = iters;
  u[0] = best.u[0];
  u[1] = best.u[1];
  u[2] = best.u[2];
  return out->g > 0;
}

double ur_section_area(const urEllipsoid* e, const double n[3], double d) {
  // A(d) = pi a b c (2 d sigma - d^2) / sigma^3  (sheet §2.5)
  if (e->p > 2) return NAN;
  double qn[3];
  double sig = halfwidth(e, n, qn);
  if (d <= 0) return 0;
  if (d > 2 * sig) d = 2 * sig;
  return M_PI * e->r[0] * e->r[1] * e->r[2] * d * (2 * sig - d) / (sig * sig * sig);
}

double ur_cap_volume(const urEllipsoid* e, const double n[3], double d) {
  // V(d) = pi a b c d^2 (3 sigma - d) / (3 sigma^3)  (sheet §2.5)
  if (e->p > 2) return NAN;
  double qn[3];
  double sig = halfwidth(e, n, qn);
  if (d <= 0) return 0;
  if (d > 2 * sig) d = 2 * sig;
  return M_PI * e->r[0] * e->r[1] * e->r[2] * d * d * (3 * sig - d) / (3 * sig * sig * sig);
}
