/* membrane_inflate.c: the inflation of a bag, done once per compiled model (the paper's step 1,
 * MADYMO's initial metric method): from the declared shape (whose fabric rest lengths are the
 * shape's own or the flat pattern's), first at a constant shaping pressure (the declared gauge
 * pressure, at least 1 % of the ambient so that a bag filled to the ambient pressure still takes
 * its shape), then closed with the declared absolute pressure in the volume reached, relaxed by
 * kinetic damping (velocities zeroed at every peak of the kinetic energy) until the free nodes'
 * forces are below 1e-3 of the pressure forces on them (root mean squares; accepted below 1e-2). The result (positions in the
 * carrier's body frame, gas state) is where every impact starts (the paper's step 2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "membrane_internal.h"

#define MAXSTEP 60000
#define TOL     1e-3
#define VISC                                                                                       \
  0.98 /* velocity kept per step besides the kinetic damping: slack, wrinkled
                         patches would otherwise flap long after the bag has its shape */

/* one relaxation phase; fixedp > 0 holds the pressure there, else the gas is closed. Returns the
   steps taken, the final residual in *res */
static int relax(urMembrane* mb, double* st, double fixedp, double pscale, double* res) {
  int nn = mb->nn, it;
  double *x = st, *v = st + 3 * nn, *f = st + 6 * nn, *sc = st + 18 * nn;
  double dt = mb->dt_stable, ke_prev = 0;
  const urMemSpec* s = &mb->spec;
  *res = INFINITY;
  for (it = 0; it < MAXSTEP; it++) {
    if (mb->stop && *mb->stop) {
      break; /* stopped on request: ur_mem_inflate says so */
    }
    if (fixedp > 0) {
      double V = ur_mem_volume(mb, x);
      sc[urMEMS_MGAS] = mb->mref * (V / mb->vref) * pow(fixedp / mb->pref, 1 / s->gamma);
    }
    ur_mem_forces(mb, st, f, NULL);

    // residual: the free nodes' forces against the pressure forces on their areas (root mean
    // squares: wrinkled, slack patches flap long after the bag has its shape and volume)
    double r2 = 0, q2 = 0;
    for (int i = 0; i < nn; i++) {
      if (mb->invm[i] > 0) {
        double ref = pscale * mb->mass[i] / s->rhot;
        r2 += urm_dot(f + 3 * i, f + 3 * i);
        q2 += ref * ref;
      }
    }
    double r = sqrt(r2 / q2);
    *res = r;
    if (r < TOL && it > 10) {
      break;
    }

    // symplectic Euler; kinetic damping at the peaks of the kinetic energy
    double ke = 0;
    for (int i = 0; i < nn; i++) {
      double im = mb->invm[i];
      for (int k = 0; k < 3; k++) {
        v[3 * i + k] = VISC * v[3 * i + k] + dt * im * f[3 * i + k];
      }
      ke += im > 0 ? mb->mass[i] * urm_dot(v + 3 * i, v + 3 * i) : 0;
    }
    if (ke < ke_prev) {
      memset(v, 0, 3 * (size_t)nn * sizeof(double));
      ke = 0;
    }
    ke_prev = ke;
    for (int i = 0; i < 3 * nn; i++) {
      x[i] += dt * v[i];
    }
  }
  return it;
}


int ur_mem_inflate(urMembrane* mb, char* err, size_t n) {
  const urMemSpec* s = &mb->spec;
  int nn = mb->nn;
  double* st = calloc(ur_mem_state_size(mb), sizeof(double));
  if (!st) {
    snprintf(err, n, "out of memory");
    return -1;
  }
  static const double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, z3[3] = {0, 0, 0};
  memcpy(mb->x0, mb->xshape, 3 * (size_t)nn * sizeof(double));
  mb->vref = ur_mem_volume(mb, mb->x0);
  mb->pref = s->p0;
  mb->mref = s->p0 * mb->vref / (urMEM_RS * s->temp);
  mb->strain0 = 0;
  ur_mem_state_init(mb, st, R, z3, z3, z3);

  // phase 1: the shaping pressure held
  double pg = fmax(s->p0 - s->patm, 0.01 * s->patm), res1, res2;
  int n1 = relax(mb, st, s->patm + pg, pg, &res1);

  // phase 2: closed at the declared pressure in the volume reached
  double* sc = st + 18 * nn;
  mb->vref = ur_mem_volume(mb, st);
  mb->pref = s->p0;
  mb->mref = s->p0 * mb->vref / (urMEM_RS * s->temp);
  sc[urMEMS_MGAS] = mb->mref;
  memset(st + 3 * nn, 0, 3 * (size_t)nn * sizeof(double));
  int n2 = relax(mb, st, 0, pg, &res2);
  mb->inflate_steps = n1 + n2;
  mb->inflate_res = res2;

  // the inflated state
  urMemInfo info;
  ur_mem_forces(mb, st, st + 6 * nn, &info);
  memcpy(mb->x0, st, 3 * (size_t)nn * sizeof(double));
  mb->vref = info.volume;
  mb->pref = info.pressure;
  mb->strain0 = info.strain;
  double c[3] = {0, 0, 0};
  for (int i = 0; i < nn; i++) {
    for (int k = 0; k < 3; k++) {
      c[k] += mb->x0[3 * i + k] / nn;
    }
  }
  double r = 0;
  for (int i = 0; i < nn; i++) {
    double d[3];
    urm_sub(d, mb->x0 + 3 * i, c);
    r = fmax(r, sqrt(urm_dot(d, d)));
  }
  memcpy(mb->cbound, c, sizeof(c));
  mb->rbound = r;
  free(st);
  if (mb->stop && *mb->stop) {
    snprintf(err, n, "stopped on request (interrupted) while inflating");
    return -1;
  }
  if (!(res2 < 10 * TOL) || !(info.volume > 0) || !isfinite(info.pressure)) {
    snprintf(err, n,
             "the bag did not settle when inflated (residual %.3g after %d steps); a finer "
             "mesh or a rounder shape may help",
             res2, n1 + n2);
    return -1;
  }
  return 0;
}
