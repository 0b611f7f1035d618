/* engine_kinematics.c: joint transforms and motion subspaces (jcalc), world poses of bodies and
 * ellipsoids, point positions, velocities and accelerations. */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- joints --------------------------------------------------------

// jcalc, body and ellipsoid poses, velocities for doubles, from their template; the rotations
// about the joints' axes computed first, four at a time (ur_axisrot_joints), and read back
#define urT                             double
#define urBC(x)                         (x)
#define urK(name)                       uru_##name
#define urFN(name)                      ur_##name
#define urD                             urData
#define urAXISROT(R, axis, angle, slot) memcpy(R, ur_jrot_slot(d, i, slot), 9 * sizeof(double))
#define urKIN_PRE(m, d)                 ur_axisrot_joints(m, d)
#include "kernels/engine_kin.h"
#undef urT
#undef urBC
#undef urK
#undef urFN
#undef urD
#undef urAXISROT
#include "kernels/engine_template_check.h"

//---------------------------------- world poses ---------------------------------------------------

void ur_kinematics(const urModel* m, urData* d) {
  m = ur_data_model(m, d); // a run whose joint broke: its own topology
  ur_kinematics_bodies(m, d);
  ur_kinematics_geoms(m, d);
}


// world poses of every ellipsoid
void ur_kinematics_geoms(const urModel* m, urData* d) {
  ur_kinematics_gpos(m, d);
  for (int g = 0; g < m->ngeom; g++) {
    ur_geom_mat(m, d, g);
  }
  memset(d->gmat_ok, 1, (size_t)m->ngeom);
}


// the orientation of ellipsoid g, computed now if the lanes left it out: gxmat is a cache in the
// per-run data, so whoever reads an orientation holds the data writable (the same expression
// gives the same bits whenever it is computed)
const double* ur_geom_xmat(const urModel* m, urData* d, int g) {
  if (!d->gmat_ok[g]) {
    ur_geom_mat(m, d, g);
    d->gmat_ok[g] = 1;
  }
  return d->gxmat + 9 * g;
}

//---------------------------------- points --------------------------------------------------------

void ur_point_pos(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  double t[3];
  uru_mulmat3vec(t, d->xmat + 9 * body, p);
  for (int k = 0; k < 3; k++) {
    out[k] = d->xpos[3 * body + k] + t[k];
  }
}


void ur_point_vel(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  const double* v = d->cvel + 6 * body;
  double t[3];
  uru_cross3(t, v, p);
  for (int k = 0; k < 3; k++) {
    t[k] += v[3 + k];
  }
  uru_mulmat3vec(out, d->xmat + 9 * body, t);
}


// kinematic acceleration of a body point, world (cacc holds the -gravity base acceleration)
void ur_point_acc(const urModel* m, const urData* d, int body, const double p[3], double out[3]) {
  const double* v = d->cvel + 6 * body;
  const double* a = d->cacc + 6 * body;
  double t[3], u[3], w[3];
  uru_cross3(t, a, p);
  uru_cross3(u, v, p);
  for (int k = 0; k < 3; k++) {
    u[k] += v[3 + k];
  }
  uru_cross3(w, v, u);
  for (int k = 0; k < 3; k++) {
    t[k] += a[3 + k] + w[k];
  }
  uru_mulmat3vec(out, d->xmat + 9 * body, t);
  for (int k = 0; k < 3; k++) {
    out[k] += m->opt.gravity[k];
  }
}
