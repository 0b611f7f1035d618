/* contact_geom.c: ellipsoid-plane and ellipsoid-ellipsoid contact geometry, section area and
 * cap volume. Sources: contact-airbag sheet §2.1-2.3, §2.5; support function as in MuJoCo
 * engine_collision_convex.c (mjc_ellipsoidSupport).
 */
#include <math.h>

#include "uasrisk/contact.h"

#define NEWTON_MAXITER 60          /* Newton iterations per start */
#define LS_MAXHALF 40              /* backtracking halvings */
#define STEP_CAP 0.5               /* largest tangent step, rad */
#define GRAD_TOL 1e-13             /* tangent gradient tolerance, relative to the length scale */

/* per-ellipsoid data: Q = R D^2 R^T (symmetric, 6 entries: xx yy zz xy xz yz) */
typedef struct {
  double q[6];
  double c[3];
  double rho;                      /* smallest radius of curvature: rmin^2 / rmax */
  double rmax;                     /* largest semi-axis */
} ellData;

/* state of the support-function evaluation at one direction */
typedef struct {
  double u[3];
  double qa[3], qb[3];             /* Q_A u, Q_B u */
  double ra, rb;                   /* |M_A u|, |M_B u| */
  double f;                        /* support function of A - B */
} evalPt;

static double dot3(const double a[3], const double b[3])
{
  return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
}

/* Q u for packed symmetric Q */
static void qmul(const double q[6], const double u[3], double out[3])
{
  out[0] = q[0]*u[0] + q[3]*u[1] + q[4]*u[2];
  out[1] = q[3]*u[0] + q[1]*u[1] + q[5]*u[2];
  out[2] = q[4]*u[0] + q[5]*u[1] + q[2]*u[2];
}

/* precompute Q = R diag(r^2) R^T and curvature bounds (sheet §2.1) */
static void elldata(const urEllipsoid* e, ellData* d)
{
  const double* R = e->R;
  double s0 = e->r[0]*e->r[0], s1 = e->r[1]*e->r[1], s2 = e->r[2]*e->r[2];
  d->q[0] = R[0]*R[0]*s0 + R[1]*R[1]*s1 + R[2]*R[2]*s2;
  d->q[1] = R[3]*R[3]*s0 + R[4]*R[4]*s1 + R[5]*R[5]*s2;
  d->q[2] = R[6]*R[6]*s0 + R[7]*R[7]*s1 + R[8]*R[8]*s2;
  d->q[3] = R[0]*R[3]*s0 + R[1]*R[4]*s1 + R[2]*R[5]*s2;
  d->q[4] = R[0]*R[6]*s0 + R[1]*R[7]*s1 + R[2]*R[8]*s2;
  d->q[5] = R[3]*R[6]*s0 + R[4]*R[7]*s1 + R[5]*R[8]*s2;
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
  d->rho = rmin*rmin / rmax;
}

/* evaluate f(u) = (c_A - c_B).u + |M_A u| + |M_B u| at unit u (sheet §2.3) */
static void evalf(const ellData* A, const ellData* B, const double dc[3], const double u[3],
                  evalPt* p)
{
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
static void tangents(const double u[3], double t1[3], double t2[3])
{
  // cross u with the axis of its smallest component
  double ax = fabs(u[0]), ay = fabs(u[1]), az = fabs(u[2]);
  if (ax <= ay && ax <= az) {
    t1[0] = 0; t1[1] = u[2]; t1[2] = -u[1];
  } else if (ay <= az) {
    t1[0] = -u[2]; t1[1] = 0; t1[2] = u[0];
  } else {
    t1[0] = u[1]; t1[1] = -u[0]; t1[2] = 0;
  }
  double s = 1.0 / sqrt(dot3(t1, t1));
  t1[0] *= s; t1[1] *= s; t1[2] *= s;

  // t2 = u x t1
  t2[0] = u[1]*t1[2] - u[2]*t1[1];
  t2[1] = u[2]*t1[0] - u[0]*t1[2];
  t2[2] = u[0]*t1[1] - u[1]*t1[0];
}

/* tangent-plane Hessian entries t_i^T (Q - q q^T / r^2) t_j / r of one ellipsoid, added to h */
static void addhess(const double q6[6], const double qu[3], double r, const double t1[3],
                    const double t2[3], double h[3])
{
  double Qt1[3], Qt2[3];
  qmul(q6, t1, Qt1);
  qmul(q6, t2, Qt2);
  double a1 = dot3(t1, qu), a2 = dot3(t2, qu);
  double ir = 1.0 / r, ir2 = ir*ir;
  h[0] += (dot3(t1, Qt1) - a1*a1*ir2) * ir;
  h[1] += (dot3(t1, Qt2) - a1*a2*ir2) * ir;
  h[2] += (dot3(t2, Qt2) - a2*a2*ir2) * ir;
}

/* Riemannian Newton on the unit sphere from unit u0 (sheet §2.3); returns iterations used */
static int newton(const ellData* A, const ellData* B, const double dc[3], double scale,
                  const double u0[3], evalPt* cur, int* conv)
{
  evalPt trial;
  int it;
  *conv = 0;
  evalf(A, B, dc, u0, cur);
  for (it = 0; it < NEWTON_MAXITER; it++) {
    // gradient w = s_A(u) - s_B(-u) and its tangent part
    double ira = 1.0 / cur->ra, irb = 1.0 / cur->rb;
    double w[3], t1[3], t2[3];
    for (int i = 0; i < 3; i++) w[i] = dc[i] + cur->qa[i]*ira + cur->qb[i]*irb;
    tangents(cur->u, t1, t2);
    double g1 = dot3(t1, w), g2 = dot3(t2, w);
    double gn = sqrt(g1*g1 + g2*g2);
    if (gn <= GRAD_TOL * scale) {
      *conv = 1;
      break;
    }

    // Riemannian Hessian: projected ambient Hessian minus (u.w) I, with u.w = f
    double h[3] = {-cur->f, 0, -cur->f};
    addhess(A->q, cur->qa, cur->ra, t1, t2, h);
    addhess(B->q, cur->qb, cur->rb, t1, t2, h);

    // Newton step if positive definite, else scaled gradient step
    double det = h[0]*h[2] - h[1]*h[1];
    double e1, e2;
    int newt = h[0] > 0 && det > 1e-14 * (h[0]*h[0] + h[2]*h[2]);
    if (newt) {
      e1 = -(h[2]*g1 - h[1]*g2) / det;
      e2 = -(h[0]*g2 - h[1]*g1) / det;
    } else {
      double tr = 0.5*(h[0] + h[2]);
      double lmax = fabs(tr) + sqrt(0.25*(h[0] - h[2])*(h[0] - h[2]) + h[1]*h[1]);
      if (lmax < 1e-3 * scale) lmax = 1e-3 * scale;
      e1 = -g1 / lmax;
      e2 = -g2 / lmax;
    }

    // cap the step length
    double en = sqrt(e1*e1 + e2*e2), en0 = en;
    if (en > STEP_CAP) {
      e1 *= STEP_CAP / en;
      e2 *= STEP_CAP / en;
      en = STEP_CAP;
    }

    // backtracking line search on f (skipped for tiny Newton steps: rounding dominates there)
    double slope = g1*e1 + g2*e2;
    int accepted = 0, k;
    for (k = 0; k < LS_MAXHALF; k++) {
      double v[3];
      for (int i = 0; i < 3; i++) v[i] = cur->u[i] + e1*t1[i] + e2*t2[i];
      double s = 1.0 / sqrt(dot3(v, v));
      v[0] *= s; v[1] *= s; v[2] *= s;
      evalf(A, B, dc, v, &trial);
      if ((newt && en < 1e-5) || trial.f <= cur->f + 1e-4*slope) {
        accepted = 1;
        break;
      }
      e1 *= 0.5;
      e2 *= 0.5;
      slope *= 0.5;
      en *= 0.5;
    }
    if (!accepted) {
      *conv = 1;                   /* no decrease possible at machine precision */
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
static double halfwidth(const urEllipsoid* e, const double n[3], double qn[3])
{
  const double* R = e->R;
  double v[3], s2 = 0;
  for (int k = 0; k < 3; k++) {
    double rk2 = e->r[k]*e->r[k];
    double vk = R[k]*n[0] + R[3 + k]*n[1] + R[6 + k]*n[2];
    s2 += rk2*vk*vk;
    v[k] = rk2*vk;
  }
  for (int i = 0; i < 3; i++) qn[i] = R[3*i]*v[0] + R[3*i + 1]*v[1] + R[3*i + 2]*v[2];
  return sqrt(s2);
}

/* fill the contact record from the minimiser */
static void fillcontact(const ellData* A, const ellData* B, const evalPt* p, urGeomContact* out)
{
  double ira = 1.0 / p->ra, irb = 1.0 / p->rb;
  for (int i = 0; i < 3; i++) {
    out->n[i] = p->u[i];
    out->pa[i] = A->c[i] + p->qa[i]*ira;
    out->pb[i] = B->c[i] - p->qb[i]*irb;
    out->p[i] = 0.5*(out->pa[i] + out->pb[i]);
  }
  out->g = p->f;
}

int ur_collide_ellipsoid_plane(const urEllipsoid* e, const double n[3], double d,
                               urGeomContact* out)
{
  // support of the ellipsoid in -n: p = c - Q n / |M n|  (sheet §2.2)
  double qn[3];
  double sig = halfwidth(e, n, qn);
  double is = 1.0 / sig;
  double g = d - dot3(n, e->c) + sig;

  // deepest points: pa on the ellipsoid, pb its projection on the plane
  for (int i = 0; i < 3; i++) {
    out->pa[i] = e->c[i] - qn[i]*is;
    out->pb[i] = out->pa[i] + g*n[i];
    out->p[i] = out->pa[i] + 0.5*g*n[i];
    out->n[i] = -n[i];
  }
  out->g = g;
  out->iters = 0;
  return g > 0;
}

int ur_collide_ellipsoids(const urEllipsoid* a, const urEllipsoid* b, double u[3],
                          urGeomContact* out)
{
  ellData A, B;
  elldata(a, &A);
  elldata(b, &B);
  double dc[3] = {a->c[0] - b->c[0], a->c[1] - b->c[1], a->c[2] - b->c[2]};
  double dist = sqrt(dot3(dc, dc));
  double scale = A.rmax + B.rmax + dist;

  // start: warm u if given, else the centre line A -> B
  double u0[3];
  double un = sqrt(dot3(u, u));
  if (un > 1e-12) {
    u0[0] = u[0] / un; u0[1] = u[1] / un; u0[2] = u[2] / un;
  } else if (dist > 1e-12 * scale) {
    u0[0] = -dc[0] / dist; u0[1] = -dc[1] / dist; u0[2] = -dc[2] / dist;
  } else {
    u0[0] = 0; u0[1] = 0; u0[2] = 1;
  }
  evalPt best, cur;
  int conv;
  int iters = newton(&A, &B, dc, scale, u0, &best, &conv);

  // deep-penetration guard: a local minimum below tau = rho_A + rho_B (a lower bound on the
  // radii of curvature of A - B) is the global one; above it, try more starting directions
  double tau = A.rho + B.rho;
  if (best.f >= tau * (1 - 1e-9) || !conv) {
    double starts[14][3];
    int ns = 0;
    if (dist > 1e-12 * scale) {
      starts[ns][0] = -dc[0] / dist; starts[ns][1] = -dc[1] / dist;
      starts[ns][2] = -dc[2] / dist; ns++;
    }
    for (int k = 0; k < 3; k++) {
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        for (int i = 0; i < 3; i++) starts[ns][i] = sgn * a->R[3*i + k];
        ns++;
        for (int i = 0; i < 3; i++) starts[ns][i] = sgn * b->R[3*i + k];
        ns++;
      }
    }
    for (int s = 0; s < ns; s++) {
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

double ur_section_area(const urEllipsoid* e, const double n[3], double d)
{
  // A(d) = pi a b c (2 d sigma - d^2) / sigma^3  (sheet §2.5)
  double qn[3];
  double sig = halfwidth(e, n, qn);
  if (d <= 0) return 0;
  if (d > 2*sig) d = 2*sig;
  return M_PI * e->r[0]*e->r[1]*e->r[2] * d*(2*sig - d) / (sig*sig*sig);
}

double ur_cap_volume(const urEllipsoid* e, const double n[3], double d)
{
  // V(d) = pi a b c d^2 (3 sigma - d) / (3 sigma^3)  (sheet §2.5)
  double qn[3];
  double sig = halfwidth(e, n, qn);
  if (d <= 0) return 0;
  if (d > 2*sig) d = 2*sig;
  return M_PI * e->r[0]*e->r[1]*e->r[2] * d*d*(3*sig - d) / (3*sig*sig*sig);
}
