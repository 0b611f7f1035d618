/* descent.c: ballistic descent model of the paper (eq. 2.1-2.2) */
#include <math.h>
#include <stdio.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "uasimpact/descent.h"

#define EPS_ABS 1e-11
#define EPS_REL 1e-11

typedef struct {
  double k; /* 0.5 rho sum(C_D A) / m, 1/m */
  double g, wind;
} descentSys;

void ur_descent_defaults(urDescentParams* p) {
  p->altitude = 120.0;
  p->mass = 15.0;
  p->area_drone = 0.12;
  p->cd_drone = 0.73;
  p->area_chute = 2.72;
  p->cd_chute = 1.54;
  p->rho = 1.23;
  p->g = 9.81;
  p->wind = 0.0;
}

static double drag_area(const urDescentParams* p) {
  return p->area_drone * p->cd_drone + p->area_chute * p->cd_chute;
}

double ur_terminal_velocity(const urDescentParams* p) {
  return sqrt(2.0 * p->mass * p->g / (p->rho * drag_area(p)));
}

/* state y = (x, z, vx, vz), z up; wind along +x */
static int rhs(double t, const double y[], double f[], void* params) {
  const descentSys* s = params;
  double rx = y[2] - s->wind, rz = y[3];
  double r = sqrt(rx * rx + rz * rz);
  f[0] = y[2];
  f[1] = y[3];
  f[2] = -s->k * r * rx;
  f[3] = -s->g - s->k * r * rz;
  return GSL_SUCCESS;
}

/* check that every parameter is finite and in its physical range */
static int check(const urDescentParams* p, char* err, int errlen) {
  const char* bad = NULL;
  if (!(isfinite(p->altitude) && p->altitude > 0))
    bad = "altitude must be > 0";
  else if (!(isfinite(p->mass) && p->mass > 0))
    bad = "mass must be > 0";
  else if (!(isfinite(p->area_drone) && p->area_drone >= 0))
    bad = "drone area must be >= 0";
  else if (!(isfinite(p->cd_drone) && p->cd_drone >= 0))
    bad = "drone C_D must be >= 0";
  else if (!(isfinite(p->area_chute) && p->area_chute >= 0))
    bad = "parachute area must be >= 0";
  else if (!(isfinite(p->cd_chute) && p->cd_chute >= 0))
    bad = "parachute C_D must be >= 0";
  else if (!(isfinite(p->rho) && p->rho > 0))
    bad = "air density must be > 0";
  else if (!(isfinite(p->g) && p->g > 0))
    bad = "g must be > 0";
  else if (!(isfinite(p->wind) && p->wind >= 0))
    bad = "wind must be >= 0";
  else if (!(drag_area(p) > 0))
    bad = "total drag area C_D*A must be > 0";
  if (bad && err) snprintf(err, errlen, "descent: %s", bad);
  return bad ? -1 : 0;
}

int ur_descent(const urDescentParams* p, urDescentResult* out, char* err, int errlen) {
  if (check(p, err, errlen)) return -1;

  descentSys s = {0.5 * p->rho * drag_area(p) / p->mass, p->g, p->wind};
  gsl_odeiv2_system sys = {rhs, NULL, 4, &s};
  const gsl_odeiv2_step_type* T = gsl_odeiv2_step_rk8pd;
  gsl_odeiv2_step* step = gsl_odeiv2_step_alloc(T, 4);
  gsl_odeiv2_control* ctl = gsl_odeiv2_control_y_new(EPS_ABS, EPS_REL);
  gsl_odeiv2_evolve* ev = gsl_odeiv2_evolve_alloc(4);
  gsl_odeiv2_driver* drv = gsl_odeiv2_driver_alloc_y_new(&sys, T, 1e-3, EPS_ABS, EPS_REL);
  int rc = -1;
  if (!step || !ctl || !ev || !drv) {
    if (err) snprintf(err, errlen, "descent: out of memory");
    goto done;
  }

  /* march until the altitude changes sign, keeping the last state above ground */
  double t = 0, h = 1e-3, tmax = 1e5;
  double y[4] = {0, p->altitude, 0, 0}, yprev[4], tprev = 0;
  int crossed = 0;
  while (t < tmax) {
    for (int i = 0; i < 4; i++) yprev[i] = y[i];
    tprev = t;
    if (gsl_odeiv2_evolve_apply(ev, ctl, step, &sys, &t, tmax, &h, y) != GSL_SUCCESS) break;
    if (y[1] <= 0) {
      crossed = 1;
      break;
    }
  }

  /* locate the crossing by Newton on z(t), re-integrating from the last state above ground */
  if (crossed) {
    double tc = tprev + yprev[1] / (-yprev[3] > 1e-9 ? -yprev[3] : 1e-9), yc[4];
    if (tc > t) tc = t;
    for (int it = 0; it < 50; it++) {
      for (int i = 0; i < 4; i++) yc[i] = yprev[i];
      double tt = tprev;
      gsl_odeiv2_driver_reset(drv);
      if (tc > tprev && gsl_odeiv2_driver_apply(drv, &tt, tc, yc) != GSL_SUCCESS) break;
      double dt = yc[1] / (-yc[3]);
      tc += dt;
      if (fabs(dt) < 1e-13 * (1 + tc)) {
        /* final state exactly at the root */
        for (int i = 0; i < 4; i++) yc[i] = yprev[i];
        tt = tprev;
        gsl_odeiv2_driver_reset(drv);
        if (tc > tprev && gsl_odeiv2_driver_apply(drv, &tt, tc, yc) != GSL_SUCCESS) break;
        out->vh = yc[2];
        out->vz = -yc[3];
        out->speed = hypot(yc[2], yc[3]);
        out->angle = atan2(-yc[3], fabs(yc[2])) * 180.0 / M_PI;
        out->time = tc;
        out->drift = yc[0];
        rc = 0;
        break;
      }
    }
  }
  if (rc && err) snprintf(err, errlen, "descent: integration failed to reach the ground");

done:
  if (drv) gsl_odeiv2_driver_free(drv);
  if (ev) gsl_odeiv2_evolve_free(ev);
  if (ctl) gsl_odeiv2_control_free(ctl);
  if (step) gsl_odeiv2_step_free(step);
  return rc;
}
