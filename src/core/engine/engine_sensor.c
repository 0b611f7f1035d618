/* engine_sensor.c: sensor values at the current state (after the accelerations and joint
 * reactions are known), running peaks and sampled time histories. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- sensor values -------------------------------------------------

void ur_sensors(const urModel* m, urData* d) {
  for (int i = 0; i < m->nsensor; i++) {
    const urSensor* s = m->sensor + i;
    double* out = d->sensordata + s->adr;
    const urBody* b = m->body + (s->obj < m->nbody ? s->obj : 0);

    switch (s->type) {
    case urSENS_ACCEL: ur_point_acc(m, d, s->obj, s->pos, out); break;
    case urSENS_BODYPOS: ur_point_pos(m, d, s->obj, s->pos, out); break;
    case urSENS_BODYVEL: ur_point_vel(m, d, s->obj, s->pos, out); break;
    case urSENS_JOINTLOAD: {
      // reaction on the child at the anchor, rotated into the sensor frame
      double R[9];
      const double* f = d->freact + 6 * s->obj;
      uru_quat2mat(R, s->quat);
      uru_mulmat3tvec(out, R, f + 3);
      uru_mulmat3tvec(out + 3, R, f);
      break;
    }
    case urSENS_JOINTPOS: out[0] = d->qpos[b->qadr + s->dof]; break;
    case urSENS_JOINTVEL: out[0] = d->qvel[b->vadr + s->dof]; break;
    case urSENS_CONTACT: {
      const urPairData* pd = d->pair + s->obj;
      out[0] = pd->fn;
      out[1] = d->pdepth[s->obj] > 0 ? d->pdepth[s->obj] : 0;
      out[2] = pd->ft;
      break;
    }
    case urSENS_HINGE: {
      const double* st = d->rst + 2 * (b->vadr + s->dof);
      out[0] = st[0];
      out[1] = st[1];
      break;
    }
    case urSENS_AIRBAG:
      out[0] = d->bag[s->obj].pressure;
      out[1] = d->bag[s->obj].volume;
      out[2] = d->bag[s->obj].force;
      out[3] = d->bag[s->obj].strain;
      break;
    }
  }
}

//---------------------------------- peaks and histories -------------------------------------------

// the interior rows of the coarse step that ends at this state (d->pend): the sampling
// instants strictly inside it, at the times fine steps would have (dt added to its start's time
// as often), each sensor value on the straight line from its start (d->sprev) to now. Semi-
// implicit Euler holds the accelerations, and so the sensors that read them and the joint
// loads, constant through a step at their start's values; the line is the step's start and end
// values joined, as the fine steps would have sampled a smooth signal (to first order).
static void rows_between(const urModel* m, urData* d, long every) {
  int ns = m->nsensordata;
  long n = d->nstep - d->nprev;
  double t = d->tprev;
  for (long j = 1; j < n && d->nhist < d->nhist_cap; j++) {
    t += m->opt.dt;
    if ((d->nprev + j) % every != 0) {
      continue;
    }
    double w = (double)j / (double)n;
    double* row = d->hist + (size_t)d->nhist * (size_t)(1 + ns);
    row[0] = t;
    for (int k = 0; k < ns; k++) {
      row[1 + k] = d->sprev[k] + w * (d->sensordata[k] - d->sprev[k]);
    }
    d->nhist++;
  }
}


// update peaks; append a history row at the sampling instants (the rows inside a coarse step
// once its end is known: rows_between)
void ur_outputs(const urModel* m, urData* d) {
  int ns = m->nsensordata;

  // peaks
  for (int k = 0; k < ns; k++) {
    double v = d->sensordata[k];
    if (v > d->peakmax[k]) {
      d->peakmax[k] = v;
    }
    if (v < d->peakmin[k]) {
      d->peakmin[k] = v;
    }
    if (fabs(v) >= fmax(fabs(d->peakmax[k]), fabs(d->peakmin[k]))) {
      d->tpeak[k] = d->time;
    }
  }

  // history row every k steps, k dt <= sample_dt (the rate is never below 1/sample_dt)
  if (!d->hist) {
    return;
  }
  long every = (long)floor(m->opt.sample_dt / m->opt.dt + 1e-9);
  if (every < 1) {
    every = 1;
  }
  if (d->pend) {
    rows_between(m, d, every);
  }
  if (d->nstep % every == 0 && d->nhist < d->nhist_cap) {
    double* row = d->hist + (size_t)d->nhist * (size_t)(1 + ns);
    row[0] = d->time;
    memcpy(row + 1, d->sensordata, (size_t)ns * sizeof(double));
    d->nhist++;
  }

  // a coarse step starts here: its interior rows wait for its end
  d->pend = d->coarse;
  if (d->coarse) {
    memcpy(d->sprev, d->sensordata, (size_t)ns * sizeof(double));
    d->tprev = d->time;
    d->nprev = d->nstep;
  }
}
