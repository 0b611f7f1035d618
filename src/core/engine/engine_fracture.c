/* engine_fracture.c: a broken arm flies free. A hinge with fracture (urRestraint.mfrac) that
 * breaks releases its joint at the start of the next step: the run switches to its own copy of
 * the model (urData.topo) in which the broken body is a free body of the world, its coordinates
 * in the free-joint block reserved for it at compile (urBody.fqadr, fvadr), started from the
 * pose and velocity it had. Nothing acts between the arm and its parent from then on; gravity,
 * contacts and airbags act on it as before. A model without fracture has no such block, no copy
 * and never switches: its runs are those of a rigid topology, bit for bit. A run that has broken
 * steps alone (ur_step) also inside ur_step_lanes, so lanes and lone runs agree. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- compile -------------------------------------------------------

// whether body b has a hinge that can break
static int breakable(const urBody* b) {
  if (b->jtype == urJNT_FREE || b->jtype == urJNT_FIXED) {
    return 0;
  }
  for (int k = 0; k < b->nv && k < 3; k++) {
    if (b->rst[k].active && b->rst[k].mp > 0 && b->rst[k].mfrac > 0) {
      return 1;
    }
  }
  return 0;
}


// reserve a free-joint block after the model's coordinates for every body with a breakable
// hinge (ur_model_compile, after the joint addresses; qpos0 of the blocks set by
// ur_fracture_qpos0)
void ur_fracture_compile(urModel* m) {
  m->nfrac = 0;
  for (int i = 0; i < m->nbody; i++) {
    urBody* b = m->body + i;
    b->fqadr = b->fvadr = -1;
    if (breakable(b)) {
      b->fqadr = m->nq;
      b->fvadr = m->nv;
      m->nq += 7;
      m->nv += 6;
      m->nfrac++;
    }
  }
}


// the reserved blocks' reference coordinates: a unit quaternion
void ur_fracture_qpos0(const urModel* m, double* qpos0) {
  for (int i = 0; i < m->nbody; i++) {
    if (m->body[i].fqadr >= 0) {
      qpos0[m->body[i].fqadr + 3] = 1;
    }
  }
}

//---------------------------------- run -----------------------------------------------------------

const urModel* ur_data_model(const urModel* m, const urData* d) {
  return d && d->nreleased > 0 && d->topo ? d->topo : m;
}


// unit quaternion of a rotation matrix (row-major; Shepperd's method: the largest of the four
// squares first, for accuracy)
static void mat2quat(double q[4], const double R[9]) {
  double tr = R[0] + R[4] + R[8];
  if (tr >= R[0] && tr >= R[4] && tr >= R[8]) {
    double s = 2 * sqrt(1 + tr);
    q[0] = 0.25 * s;
    q[1] = (R[7] - R[5]) / s;
    q[2] = (R[2] - R[6]) / s;
    q[3] = (R[3] - R[1]) / s;
  } else if (R[0] >= R[4] && R[0] >= R[8]) {
    double s = 2 * sqrt(1 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / s;
    q[1] = 0.25 * s;
    q[2] = (R[1] + R[3]) / s;
    q[3] = (R[2] + R[6]) / s;
  } else if (R[4] >= R[8]) {
    double s = 2 * sqrt(1 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / s;
    q[1] = (R[1] + R[3]) / s;
    q[2] = 0.25 * s;
    q[3] = (R[5] + R[7]) / s;
  } else {
    double s = 2 * sqrt(1 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / s;
    q[1] = (R[2] + R[6]) / s;
    q[2] = (R[5] + R[7]) / s;
    q[3] = 0.25 * s;
  }
}


// whether body i of m has a broken hinge that the run cur has not released yet
static int broken(const urModel* m, const urModel* cur, const urData* d, int i) {
  const urBody* b = m->body + i;
  if (b->fqadr < 0 || cur->body[i].jtype == urJNT_FREE) {
    return 0;
  }
  for (int k = 0; k < b->nv && k < 3; k++) {
    if (b->rst[k].active && b->rst[k].mp > 0 && b->rst[k].mfrac > 0 &&
        d->rst[2 * (b->vadr + k) + 1] != 0) {
      return 1;
    }
  }
  return 0;
}


int ur_fracture_pending(const urModel* m, const urData* d) {
  if (!m->nfrac) {
    return 0;
  }
  if (d->nreleased > 0) {
    return 1;
  }
  for (int i = 0; i < m->nbody; i++) {
    if (broken(m, m, d, i)) {
      return 1;
    }
  }
  return 0;
}


// release the joints whose hinge broke: the body becomes a free body of the world in the run's
// own model, started from its present world pose and velocity (so momentum is continuous); its
// old joint coordinates are frozen (velocity and acceleration 0). Returns the joints released.
int ur_fracture_release(const urModel* m, urData* d) {
  if (!m->nfrac || !d->topo) {
    return 0;
  }
  const urModel* cur = ur_data_model(m, d);
  int n = 0;
  for (int i = 0; i < m->nbody; i++) {
    n += broken(m, cur, d, i);
  }
  if (!n) {
    return 0;
  }

  // the poses and velocities in the present topology
  ur_kinematics_bodies(cur, d);
  ur_velocities(cur, d);
  if (d->nreleased == 0) {
    urBody* body = (urBody*)(d->topo + 1);
    *d->topo = *m;
    memcpy(body, m->body, (size_t)m->nbody * sizeof(urBody));
    d->topo->body = body;
  }
  for (int i = 0; i < m->nbody; i++) {
    if (!broken(m, d->topo, d, i)) {
      continue;
    }
    urBody* b = d->topo->body + i;
    const double* R = d->xmat + 9 * i;
    const double* v = d->cvel + 6 * i;
    double* q = d->qpos + b->fqadr;
    double* qd = d->qvel + b->fvadr;
    double t[3];

    // the free joint's state: CoM and orientation in the world, CoM velocity in the world,
    // angular velocity in the body
    memcpy(q, d->xcom + 3 * i, 3 * sizeof(double));
    mat2quat(q + 3, R);
    uru_normalizequat(q + 3);
    uru_cross3(t, v, b->com);
    for (int k = 0; k < 3; k++) {
      t[k] += v[3 + k];
    }
    uru_mulmat3vec(qd, R, t);
    memcpy(qd + 3, v, 3 * sizeof(double));

    // the hinge's state where the run's model reads it (the free joint has no restraint), the
    // old joint frozen, its restraint gone
    memcpy(d->rst + 2 * b->fvadr, d->rst + 2 * b->vadr,
           2 * (size_t)(b->nv < 3 ? b->nv : 3) * sizeof(double));
    for (int k = 0; k < b->nv; k++) {
      d->qvel[b->vadr + k] = 0;
      d->qacc[b->vadr + k] = 0;
    }
    b->parent = -1;
    b->jtype = urJNT_FREE;
    b->qadr = b->fqadr;
    b->vadr = b->fvadr;
    b->nq = 7;
    b->nv = 6;
    for (int k = 0; k < 3; k++) {
      b->rst[k].active = 0;
    }
    d->nreleased++;
  }
  return n;
}
