/* membrane_mesh.c: a bag's mesh from its declaration: two panels of the plan shape (ellipse or
 * rounded rectangle) meshed in rings (ring k of 6k nodes; a dome's rings divide its meridian's
 * arc evenly, a flat panel's its radius k / n; the strips between rings triangulated as the
 * hexagonal lattice), sewn at the last ring; the declared shape (bottom panel a
 * half-ellipsoid of the given depth, top flat or domed), the reference metric (that shape, or
 * the flat pattern), material axes (warp along the plan's x), lumped masses from the areal
 * density, the mount patch and the stable step. Also the default fabric and gas. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_internal.h"

//---------------------------------- defaults ------------------------------------------------------

/* uasimpact-model(5), BAGS: materials-membrane sheet A.2 (t 0.33 mm, E 0.40 GPa, rho 700 kg/m^3,
   nu 0.2), A.3 (G0 t from 1 MPa, lock 35 deg, GT = 20 G0), C.2 (RE 0.005), C.3 (5 % damping),
   C.4 (penalty alpha, contact damping, friction), B.1-B.2 (air, C_D 0.7) */
void ur_mem_spec_default(urMemSpec* s) {
  memset(s, 0, sizeof(*s));
  s->plan = urMEM_ELLIPSE;
  s->pattern = urMEM_SHAPE;
  s->a = s->b = 0.3;
  s->depth = 0.1;
  s->top = 0;
  s->mount_r = 0.35;
  s->quat[0] = 1;
  s->mesh = 6;
  s->e1t = s->e2t = 0.40e9 * 0.33e-3;
  s->nu12 = 0.2;
  s->g0t = 1e6 * 0.33e-3;
  s->gtt = 20 * s->g0t;
  s->lock = 35 * M_PI / 180;
  s->re = 0.005;
  s->rhot = 700 * 0.33e-3;
  s->damp = 0.05;
  s->p0 = s->patm = 101325;
  s->gamma = 1.4;
  s->temp = 293.15;
  s->vent_cd = 0.7;
  s->kc_alpha = 0.2;
  s->kc_dt = 5e-5;
  s->zeta_c = 0.3;
  s->mu = 0.4;
  s->v_eps = 0.01;
  s->dt_factor = 0.8;
}


int ur_mem_spec_check(const urMemSpec* s, char* err, size_t n) {
  const char* what = NULL;
  if (!(s->a > 0 && s->b > 0 && s->depth > 0 && s->top >= 0)) {
    what = "size and depth must be > 0, top >= 0";
  } else if (s->mesh < 2 || s->mesh > 64) {
    what = "mesh (rings per panel) must be in 2..64";
  } else if (s->inflate != urMEM_RELAX && s->inflate != urMEM_FIRE) {
    what = "inflate must be 0 (relax: kinetic damping) or 1 (fire)";
  } else if (s->wrinkle != urMEM_RELAXED && s->wrinkle != urMEM_REDUCE) {
    what = "wrinkle must be 0 (relaxed energy) or 1 (reduce: the compressive stress scaled by re)";
  } else if (!(s->mount_r >= 0 && s->mount_r < 1)) {
    what = "mount_r must be in [0, 1)";
  } else if (!(s->e1t > 0 && s->e2t > 0 && s->rhot > 0)) {
    what = "fabric stiffnesses and areal density must be > 0";
  } else if (!(s->nu12 >= 0 && s->nu12 * s->nu12 * s->e2t / s->e1t < 1)) {
    what = "fabric Poisson ratio must be >= 0 with nu12 nu21 < 1";
  } else if (!(s->g0t >= 0 && s->gtt >= 0 && s->lock > 0 && s->lock < M_PI / 2)) {
    what = "shear stiffnesses must be >= 0 and the lock angle in (0, 90) deg";
  } else if (!(s->re >= 0 && s->re <= 1 && s->damp >= 0 && s->damp < 1)) {
    what = "re must be in [0, 1] and damp in [0, 1)";
  } else if (!(s->p0 > 0 && s->patm > 0 && s->p0 >= s->patm && s->gamma >= 1 && s->temp > 0)) {
    what = "gas needs p0 >= patm > 0, gamma >= 1, temperature > 0";
  } else if (!(s->vent_area >= 0 && s->vent_cd >= 0 && s->leak >= 0 && s->leak < 1)) {
    what = "vent area, discharge coefficient and leak must be >= 0 (leak < 1)";
  } else if (!(s->kc_alpha > 0 && s->kc_alpha <= 1000 && s->kc_dt >= 0 && s->zeta_c >= 0 &&
               s->mu >= 0 && s->v_eps > 0)) {
    what = "contact needs 0 < kc_alpha <= 1000, kc_dt >= 0, zeta_c >= 0, mu >= 0, v_eps > 0";
  } else if (!(s->quat[0] * s->quat[0] + s->quat[1] * s->quat[1] + s->quat[2] * s->quat[2] +
                   s->quat[3] * s->quat[3] >
               0)) {
    what = "the bag's orientation quaternion is zero";
  } else if (!(s->dt_factor > 0 && s->dt_factor <= 1)) {
    what = "dt_factor must be in (0, 1]";
  } else if (!(s->mscale >= 0 && s->mscale <= 1 && s->hstep >= 0)) {
    what = "mscale must be in [0, 1] (a fraction of the fabric's mass)";
  }
  if (what) {
    snprintf(err, n, "%s", what);
    return -1;
  }
  return 0;
}

//---------------------------------- topology ------------------------------------------------------

/* node index of ring k, item j (mod 6k) of a panel; the bottom panel shares the top's last
   ring (the seam) */
static int node_at(int n, int ntop, int panel, int k, int j) {
  if (k == 0) {
    return panel == 0 ? 0 : ntop;
  }
  int m = 6 * k;
  j = ((j % m) + m) % m;
  int first = 1 + 3 * k * (k - 1); // nodes before ring k in a panel
  if (panel == 0 || k == n) {
    return first + j;
  }
  return ntop + first + j;
}


/* the meridian's arc length of a dome of plan radius R and height h from its pole to polar angle
   phi (the point R sin phi, h cos phi): Simpson's rule over 256 intervals (a smooth integrand) */
static double meridian_arc(double R, double h, double phi) {
  const int m = 256;
  double dp = phi / m, sum = 0;
  for (int i = 0; i <= m; i++) {
    double t = dp * i, c = cos(t), sn = sin(t);
    double w = i == 0 || i == m ? 1 : i % 2 ? 4 : 2;
    sum += w * sqrt(R * R * c * c + h * h * sn * sn);
  }
  return sum * dp / 3;
}


/* the unit-plan radii rho[0..n] of a panel's rings: a dome's (height h > 0) divide its meridian
   into equal arcs (the mean of the plan's half-axes as its radius: rings equally spaced on the
   fabric, not in polar angle, which crowded them at the rim of a shallow dome); a flat panel's
   divide its radius evenly, or, with a mount patch of radius mount, ring m (the nearest to
   mount n, when that is 1 .. n - 1: a patch of a ring or more, short of the seam) lies on the
   patch's edge and the rings divide the patch and the rest evenly: the patch is the declared
   one at every mesh, not the last ring inside it */
static void ring_radii(const urMemSpec* s, double h, double mount, double* rho) {
  int n = s->mesh, m = (int)floor(mount * n + 0.5);
  if (m < 1 || m > n - 1) {
    mount = 0; /* evenly */
  }
  double R = 0.5 * (s->a + s->b), total = h > 0 ? meridian_arc(R, h, 0.5 * M_PI) : 0;
  rho[0] = 0;
  rho[n] = 1;
  for (int k = 1; k < n; k++) {
    if (!(h > 0)) {
      rho[k] = !(mount > 0) ? (double)k / n
               : k < m      ? mount * k / m
               : k == m     ? mount
                            : mount + (1 - mount) * (k - m) / (n - m);
      continue;
    }
    double lo = 0, hi = 0.5 * M_PI, want = total * k / n;
    for (int it = 0; it < 60; it++) {
      double mid = 0.5 * (lo + hi);
      if (meridian_arc(R, h, mid) < want) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    rho[k] = sin(0.5 * (lo + hi));
  }
}


/* the plan point of ring k, item j of a panel whose ring k lies at unit-plan radius rho */
static void plan_point(const urMemSpec* s, double rho, int k, int j, double xy[2]) {
  double th = k == 0 ? 0 : 2 * M_PI * j / (6.0 * k);
  double c = cos(th), sn = sin(th), nrm = 1;
  if (s->plan == urMEM_RECT) {
    nrm = pow(pow(fabs(c), 4) + pow(fabs(sn), 4), 0.25);
  }
  xy[0] = rho * s->a * c / nrm;
  xy[1] = rho * s->b * sn / nrm;
}


/* triangles of the strip between rings k-1 and k of a panel, advancing by angle (where the next
   inner and outer nodes lie at the same angle, a sextant's corner, the inner one first: the
   hexagonal lattice's triangulation, no skinny triangle at the corners); flip reverses the
   orientation (bottom panel) */
static int strip(int n, int ntop, int panel, int k, int flip, int* tri) {
  int nt = 0, a = 0, b = 0, na = 6 * (k - 1), nb = 6 * k;
  if (k == 1) {
    for (int j = 0; j < 6; j++) {
      int v[3] = {node_at(n, ntop, panel, 0, 0), node_at(n, ntop, panel, 1, j),
                  node_at(n, ntop, panel, 1, j + 1)};
      tri[3 * nt] = v[0];
      tri[3 * nt + 1] = flip ? v[2] : v[1];
      tri[3 * nt + 2] = flip ? v[1] : v[2];
      nt++;
    }
    return nt;
  }
  while (a < na || b < nb) {
    // next angles (fractions of a turn) of the inner and outer ring, (a + 1) / na and
    // (b + 1) / nb, compared exactly
    int v[3];
    v[0] = node_at(n, ntop, panel, k - 1, a);
    v[1] = node_at(n, ntop, panel, k, b);
    if (b < nb && (a >= na || (long)(b + 1) * na < (long)(a + 1) * nb)) {
      // inner a, outer b, outer b+1: counter-clockwise seen from +z
      v[2] = node_at(n, ntop, panel, k, b + 1);
      b++;
    } else {
      // inner a, outer b, inner a+1: counter-clockwise too
      v[2] = node_at(n, ntop, panel, k - 1, a + 1);
      a++;
    }
    tri[3 * nt] = v[0];
    tri[3 * nt + 1] = flip ? v[2] : v[1];
    tri[3 * nt + 2] = flip ? v[1] : v[2];
    nt++;
  }
  return nt;
}

//---------------------------------- build ---------------------------------------------------------

void ur_mem_free(urMembrane* mb) {
  if (!mb) {
    return;
  }
  free(mb->tri);
  free(mb->dminv);
  free(mb->mass);
  free(mb->fix);
  free(mb->xshape);
  free(mb->tri4);
  free(mb->tk4);
  free(mb->adj0);
  free(mb->adj);
  free(mb->tedge);
  free(mb->enode);
  free(mb->free);
  free(mb->tfree);
  free(mb);
}


/* the stable step from the reference metric: the shortest 2A/longest edge over the dilatational
   wave speed (materials-membrane C.3) */
double ur_mem_stable_dt(const urMembrane* mb) {
  const urMemSpec* s = &mb->spec;
  double nu21 = s->nu12 * s->e2t / s->e1t;
  double c = sqrt(fmax(s->e1t, s->e2t) / ((1 - s->nu12 * nu21) * s->rhot));
  return mb->lmin / c;
}


/* selective mass scaling (explicit FE practice: mass added only to the elements whose stable step
   is below the target, as LS-DYNA's DT2MS and Radioss's /DT/NODA do; uasimpact-model(5), BAGS):
   for the fewest sub-steps n of the multibody step hstep, the triangles whose step dt_factor lc /
   c is below hstep / n take the areal density that brings it there, rhot (lneed / lc)^2, lneed =
   (hstep / n) c / dt_factor, their corners a third of the added mass each, when all that is added
   comes to at most mscale of the fabric's mass (lc: each triangle's length, INFINITY for the
   mount patch's; c the dilatational wave speed). The step then is hstep / n (returned; 0: no
   scaling, for mscale or hstep 0 or when no n below the unscaled one fits). The stiffness,
   damping time and contact penalty (per area: rhot) stay the material's. */
/* the mass triangle t takes to reach length lneed (0 when it is that long) */
static double tri_add(const urMembrane* mb, const double* lct, int t, double lneed) {
  double r = lneed / lct[t];
  return lct[t] < lneed ? mb->spec.rhot * mb->area0[t] * (r * r - 1) : 0;
}

static double mass_scale(urMembrane* mb, const double* lct, double c) {
  const urMemSpec* s = &mb->spec;
  mb->madd = 0;
  mb->nscaled = 0;
  if (!(s->mscale > 0 && s->hstep > 0 && mb->lmin < INFINITY)) {
    return 0;
  }
  double mfab = 0;
  for (int t = 0; t < mb->nt; t++) {
    mfab += s->rhot * mb->area0[t];
  }
  int nmax = (int)ceil(s->hstep / (s->dt_factor * mb->lmin / c) - 1e-9);
  for (int n = 1; n < nmax; n++) {
    double target = s->hstep / n, lneed = target * c / s->dt_factor, add = 0;
    for (int t = 0; t < mb->nt; t++) {
      add += tri_add(mb, lct, t, lneed);
    }
    if (add > s->mscale * mfab) {
      continue;
    }
    for (int t = 0; t < mb->nt; t++) {
      double dm = tri_add(mb, lct, t, lneed) / 3;
      if (dm > 0) {
        for (int k = 0; k < 3; k++) {
          mb->mass[mb->tri[3 * t + k]] += dm;
        }
        mb->nscaled++;
      }
    }
    mb->madd = add;
    return target;
  }
  return 0;
}


/* the triangles' nodes and constants by blocks of 4 for the force pass (ur_mem_forces): lanes
   of one quantity side by side, the last block padded with node 0 and zeros; and each node's
   triangle corners in triangle order (the scratch offset of the corner's force, x component:
   block b's corners 1, 2, 3 at 36 b + 24, 36 b, 36 b + 12, plus the lane: tri_forces in
   membrane_fabric.c); 0 or -1 */
static int blocks(urMembrane* mb) {
  int nb = (mb->nt + 3) / 4, nn = mb->nn;
  mb->ntb = nb;
  mb->tri4 = calloc(12 * (size_t)nb, sizeof(int));
  mb->tk4 = calloc(24 * (size_t)nb, sizeof(double));
  mb->adj0 = calloc((size_t)nn + 1, sizeof(int));
  mb->adj = malloc(3 * (size_t)mb->nt * sizeof(int));
  if (!mb->tri4 || !mb->tk4 || !mb->adj0 || !mb->adj) {
    return -1;
  }
  static const int slot[3] = {24, 0, 12};
  for (int t = 0; t < 3 * mb->nt; t++) {
    mb->adj0[mb->tri[t] + 1]++;
  }
  for (int i = 0; i < nn; i++) {
    mb->adj0[i + 1] += mb->adj0[i];
  }
  for (int t = 0; t < mb->nt; t++) {
    for (int k = 0; k < 3; k++) {
      int i = mb->tri[3 * t + k], j = mb->adj0[i]++;
      mb->adj[j] = 36 * (t / 4) + slot[k] + t % 4;
    }
  }
  for (int i = nn; i > 0; i--) {
    mb->adj0[i] = mb->adj0[i - 1];
  }
  mb->adj0[0] = 0;
  for (int t = 0; t < mb->nt; t++) {
    int b = t / 4, l = t % 4;
    for (int k = 0; k < 3; k++) {
      mb->tri4[12 * b + 4 * k + l] = mb->tri[3 * t + k];
    }
    double* k4 = mb->tk4 + 24 * b;
    for (int j = 0; j < 4; j++) {
      k4[4 * j + l] = mb->dminv[4 * t + j];
    }
    k4[16 + l] = mb->area0[t];
    k4[20 + l] = mb->beta[t];
  }
  return 0;
}


/* each triangle's edges numbered once (the face contact evaluates an edge's midpoint once for
   both of its triangles): nodes a < b of an edge found among the edges already seen at a (a
   chain per node); 0 or -1 */
static int edges(urMembrane* mb) {
  int nn = mb->nn, nt = mb->nt, ne = 0;
  int* head = malloc((size_t)nn * sizeof(int));
  int* next = malloc(3 * (size_t)nt * sizeof(int));
  int* other = malloc(3 * (size_t)nt * sizeof(int));
  mb->tedge = malloc(3 * (size_t)nt * sizeof(int));
  mb->enode = malloc(6 * (size_t)nt * sizeof(int));
  if (!head || !next || !other || !mb->tedge || !mb->enode) {
    free(head);
    free(next);
    free(other);
    return -1;
  }
  for (int i = 0; i < nn; i++) {
    head[i] = -1;
  }
  for (int t = 0; t < nt; t++) {
    for (int k = 0; k < 3; k++) {
      int a = mb->tri[3 * t + k], b = mb->tri[3 * t + (k + 1) % 3];
      if (a > b) {
        int u = a;
        a = b;
        b = u;
      }
      int e = head[a];
      while (e >= 0 && other[e] != b) {
        e = next[e];
      }
      if (e < 0) {
        e = ne++;
        other[e] = b;
        mb->enode[2 * e] = a;
        mb->enode[2 * e + 1] = b;
        next[e] = head[a];
        head[a] = e;
      }
      mb->tedge[3 * t + k] = e;
    }
  }
  mb->ne = ne;
  free(head);
  free(next);
  free(other);
  return 0;
}


urMembrane* ur_mem_build(const urMemSpec* s, char* err, size_t n) {
  if (ur_mem_spec_check(s, err, n)) {
    return NULL;
  }
  int r = s->mesh;
  int ntop = 1 + 3 * r * (r + 1);
  int nn = ntop + 1 + 3 * (r - 1) * r;
  int nt = 12 * r * r;
  urMembrane* mb = calloc(1, sizeof(urMembrane));
  if (!mb) {
    snprintf(err, n, "out of memory");
    return NULL;
  }
  mb->spec = *s;
  mb->nn = nn;
  mb->nt = nt;
  mb->ntop = ntop;
  mb->tri = malloc(3 * (size_t)nt * sizeof(int));
  mb->dminv = malloc(6 * (size_t)nt * sizeof(double)); // dminv 4 nt, area0 nt, beta nt
  mb->mass = malloc(2 * (size_t)nn * sizeof(double));
  mb->fix = malloc((size_t)nn * sizeof(int));
  mb->xshape = malloc(6 * (size_t)nn * sizeof(double)); // xshape, x0
  double* xref = malloc(3 * (size_t)nn * sizeof(double));
  if (!mb->tri || !mb->dminv || !mb->mass || !mb->fix || !mb->xshape || !xref) {
    free(xref);
    ur_mem_free(mb);
    snprintf(err, n, "out of memory");
    return NULL;
  }
  mb->area0 = mb->dminv + 4 * (size_t)nt;
  mb->beta = mb->area0 + nt;
  mb->invm = mb->mass + nn;
  mb->x0 = mb->xshape + 3 * (size_t)nn;

  // nodes: declared shape (body frame) and reference pattern; Q the bag's frame
  double Q[9], qn = sqrt(s->quat[0] * s->quat[0] + s->quat[1] * s->quat[1] +
                         s->quat[2] * s->quat[2] + s->quat[3] * s->quat[3]);
  {
    double w = s->quat[0] / qn, x = s->quat[1] / qn, y = s->quat[2] / qn, z = s->quat[3] / qn;
    double q9[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                    2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                    2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    memcpy(Q, q9, sizeof(Q));
  }
  double rings[65];
  for (int panel = 0; panel < 2; panel++) {
    int flat = s->pattern == urMEM_FLAT;
    ring_radii(s, flat ? 0 : panel == 0 ? s->top : s->depth, panel == 0 ? s->mount_r : 0, rings);
    for (int k = 0; k <= r; k++) {
      if (panel == 1 && k == r) {
        break;
      }
      for (int j = 0; j < (k ? 6 * k : 1); j++) {
        int i = node_at(r, ntop, panel, k, j);
        double rho = rings[k], xy[2];
        plan_point(s, rho, k, j, xy);
        double h = sqrt(fmax(0, 1 - rho * rho));
        double z = panel == 0 ? s->top * h : -s->depth * h;
        double* xs = mb->xshape + 3 * i;
        // a flat pattern starts from a quarter of the shape's heights, its plan shrunk by 10 %:
        // every triangle shorter than its pattern, slack until the gas unfolds it (the initial
        // metric method's smaller start)
        double sh = flat ? 0.9 : 1, sz = flat ? 0.25 : 1;
        double loc[3] = {sh * xy[0], sh * xy[1], sz * (z - s->top)};
        for (int c = 0; c < 3; c++) {
          xs[c] = s->mount[c] + Q[3 * c] * loc[0] + Q[3 * c + 1] * loc[1] + Q[3 * c + 2] * loc[2];
        }
        double* xr = xref + 3 * i;
        xr[0] = xy[0];
        xr[1] = xy[1];
        xr[2] = s->pattern == urMEM_FLAT ? 0 : z;
        if (panel == 0 && rho <= s->mount_r + 1e-12) {
          mb->fix[mb->nfix++] = i;
        }
      }
    }
  }

  // triangles: top panel counter-clockwise from +z (outward up), bottom reversed
  int t = 0;
  for (int k = 1; k <= r; k++) {
    t += strip(r, ntop, 0, k, 0, mb->tri + 3 * t);
  }
  for (int k = 1; k <= r; k++) {
    t += strip(r, ntop, 1, k, 1, mb->tri + 3 * t);
  }

  // reference metric in material axes, masses, damping times, characteristic lengths
  double nu21 = s->nu12 * s->e2t / s->e1t;
  double c = sqrt(fmax(s->e1t, s->e2t) / ((1 - s->nu12 * nu21) * s->rhot));
  memset(mb->mass, 0, (size_t)nn * sizeof(double));
  mb->lmin = INFINITY;
  double* lct = malloc((size_t)nt * sizeof(double)); /* each triangle's length, INFINITY: fixed */
  if (!lct) {
    free(xref);
    ur_mem_free(mb);
    snprintf(err, n, "out of memory");
    return NULL;
  }
  for (int i = 0; i < nn; i++) {
    mb->invm[i] = 1; /* for now: 0 marks a mount node */
  }
  for (int k = 0; k < mb->nfix; k++) {
    mb->invm[mb->fix[k]] = 0;
  }
  for (t = 0; t < nt; t++) {
    const int* v = mb->tri + 3 * t;
    const double *X1 = xref + 3 * v[0], *X2 = xref + 3 * v[1], *X3 = xref + 3 * v[2];
    double e1[3], e2[3], e3[3], nrm[3], a0[3], b0[3];
    urm_sub(e1, X2, X1);
    urm_sub(e2, X3, X1);
    urm_sub(e3, X3, X2);
    urm_cross(nrm, e1, e2);
    double A2 = sqrt(urm_dot(nrm, nrm));
    if (!(A2 > 0)) {
      free(lct);
      free(xref);
      ur_mem_free(mb);
      snprintf(err, n, "degenerate triangle in the mesh");
      return NULL;
    }
    for (int k = 0; k < 3; k++) {
      nrm[k] /= A2;
    }
    // warp: the plan's x projected on the triangle (the weft when x is nearly normal)
    double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    const double* ax = fabs(nrm[0]) < 0.9 ? ex : ey;
    double dd = urm_dot(ax, nrm);
    for (int k = 0; k < 3; k++) {
      a0[k] = ax[k] - dd * nrm[k];
    }
    double la = sqrt(urm_dot(a0, a0));
    for (int k = 0; k < 3; k++) {
      a0[k] /= la;
    }
    urm_cross(b0, nrm, a0);
    double m11 = urm_dot(e1, a0), m12 = urm_dot(e2, a0);
    double m21 = urm_dot(e1, b0), m22 = urm_dot(e2, b0);
    double det = m11 * m22 - m12 * m21;
    double* Di = mb->dminv + 4 * t;
    Di[0] = m22 / det;
    Di[1] = -m12 / det;
    Di[2] = -m21 / det;
    Di[3] = m11 / det;
    double A0 = 0.5 * A2;
    mb->area0[t] = A0;
    double lmax = sqrt(fmax(urm_dot(e1, e1), fmax(urm_dot(e2, e2), urm_dot(e3, e3))));
    double lc = 2 * A0 / lmax;
    if (mb->invm[v[0]] != 0 || mb->invm[v[1]] != 0 || mb->invm[v[2]] != 0) {
      mb->lmin = fmin(mb->lmin, lc); /* a triangle of the mount patch alone never moves */
      lct[t] = lc;
    } else {
      lct[t] = INFINITY;
    }
    mb->beta[t] = s->damp * lc / c;
    for (int k = 0; k < 3; k++) {
      mb->mass[v[k]] += s->rhot * A0 / 3;
    }
  }
  double dts = mass_scale(mb, lct, c);
  free(lct);
  for (int i = 0; i < nn; i++) {
    mb->invm[i] = 1 / mb->mass[i];
  }
  for (int k = 0; k < mb->nfix; k++) {
    mb->invm[mb->fix[k]] = 0;
  }
  free(xref);
  // the free nodes and the triangles of free nodes only (the face contact's)
  mb->free = malloc((size_t)nn * sizeof(int));
  mb->tfree = malloc((size_t)nt * sizeof(int));
  if (!mb->free || !mb->tfree) {
    ur_mem_free(mb);
    snprintf(err, n, "out of memory");
    return NULL;
  }
  for (int i = 0; i < nn; i++) {
    if (mb->invm[i] != 0) {
      mb->free[mb->nfree++] = i;
    }
  }
  for (t = 0; t < nt; t++) {
    const int* v = mb->tri + 3 * t;
    if (mb->invm[v[0]] != 0 && mb->invm[v[1]] != 0 && mb->invm[v[2]] != 0) {
      mb->tfree[mb->ntfree++] = t;
    }
  }
  if (blocks(mb) || edges(mb)) {
    ur_mem_free(mb);
    snprintf(err, n, "out of memory");
    return NULL;
  }
  mb->dt_stable = dts > 0 ? dts : s->dt_factor * ur_mem_stable_dt(mb);

  // not inflated yet: the declared shape, the gas at p0 in its volume
  memcpy(mb->x0, mb->xshape, 3 * (size_t)nn * sizeof(double));
  mb->vref = ur_mem_volume(mb, mb->x0);
  mb->pref = s->p0;
  mb->mref = s->p0 * mb->vref / (urMEM_RS * s->temp);
  return mb;
}

//---------------------------------- run state -----------------------------------------------------

size_t ur_mem_stiff_offset(const urMembrane* mb) {
  size_t nb = (size_t)(mb->nn + urMEM_CBLK - 1) / urMEM_CBLK;
  size_t tb = (size_t)(mb->nt + urMEM_CBLK - 1) / urMEM_CBLK;
  return 18 * (size_t)mb->nn + urMEMS_N + 44 * (size_t)mb->ntb + 5 * (size_t)mb->nt + 7 * (nb + tb);
}


size_t ur_mem_state_size(const urMembrane* mb) {
  return ur_mem_stiff_offset(mb) + 14 * (size_t)mb->nn + 4 * (size_t)mb->ne;
}


void ur_mem_state_init(const urMembrane* mb, double* st, const double R[9], const double c[3],
                       const double vc[3], const double w[3]) {
  int nn = mb->nn;
  double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *sc = st + 18 * nn;
  for (int i = 0; i < nn; i++) {
    const double* p = mb->x0 + 3 * i;
    double r[3];
    for (int k = 0; k < 3; k++) {
      r[k] = R[3 * k] * p[0] + R[3 * k + 1] * p[1] + R[3 * k + 2] * p[2];
      x[3 * i + k] = c[k] + r[k];
    }
    double wr[3];
    urm_cross(wr, w, r);
    for (int k = 0; k < 3; k++) {
      v[3 * i + k] = vc[k] + wr[k];
      f[3 * i + k] = 0;
      f[3 * nn + 3 * i + k] = 0;
    }
  }
  sc[urMEMS_MGAS] = mb->mref;
  sc[urMEMS_P] = mb->pref;
  sc[urMEMS_V] = mb->vref;
  sc[urMEMS_STRAIN] = mb->strain0;
  sc[urMEMS_EFAB] = 0;
  sc[urMEMS_TFIRST] = sc[urMEMS_TPEAK] = -1;
  sc[urMEMS_PPEAK] = 0;
  sc[urMEMS_ECONT] = 0;
  // no warm start for the wrinkled law yet (after the force pass's scratch)
  memset(sc + urMEMS_N + 36 * (size_t)mb->ntb, 0, 8 * (size_t)mb->ntb * sizeof(double));
}


double ur_mem_kinetic(const urMembrane* mb, const double* st) {
  const double* v = st + 3 * mb->nn;
  double e = 0;
  for (int i = 0; i < mb->nn; i++) {
    if (mb->invm[i] > 0) {
      e += 0.5 * mb->mass[i] * urm_dot(v + 3 * i, v + 3 * i);
    }
  }
  return e;
}
