/* engine_kin.h: joint transforms and motion subspaces (jcalc), world poses of bodies and
 * ellipsoids, spatial velocities and velocity-product accelerations, as a template like
 * engine_aba.h: included for doubles (engine_kinematics.c: ur_kinematics_bodies,
 * ur_kinematics_geoms, ur_velocities on urData) and for lanes (engine_lanes.c: urv_ on urLanes).
 * Parameters: urT, urBC(x), urK(name), urFN(name), urD (fields qpos qvel S cbias Xe Xr xmat xpos
 * xcom gxmat gxpos cvel), urAXISROT(R, axis, angle, slot) a rotation matrix about a unit axis
 * (axis: urT[3], angle: urT; slot 0 or 1: the joint's first or second axis, for an instance
 * that computed the rotations beforehand), urKIN_ATTR (optional) attributes of the entry points,
 * urKIN_PRE(m, d) (optional) what kinematics_bodies does first. Model constants are
 * broadcast to urT before they meet the data, so both instances evaluate the same operations. No
 * include guard: included once per instance; the protocol (who defines and undefines the
 * parameters, the bit-exactness rules): src/README. */

#ifndef urKIN_ATTR
#define urKIN_ATTR
#endif
#ifndef urKIN_PRE
#define urKIN_PRE(m, d) ((void)0)
#endif

//---------------------------------- joints --------------------------------------------------------

static inline void urFN(bcast)(urT* r, const double* x, int n) {
  for (int k = 0; k < n; k++) {
    r[k] = urBC(x[k]);
  }
}


// joint transform (Xe, Xr), motion subspace S (6 x nv, row-major) and S-dot qdot (in cbias)
static inline __attribute__((always_inline)) void urFN(jcalc)(const urModel* m, urD* d, int i) {
  const urBody* b = m->body + i;
  const urT* q = d->qpos + b->qadr;
  const urT* qd = d->qvel + b->vadr;
  urT R[9], T[9], p[3], Rb[9];
  urT* S = d->S + 36 * i;
  urT* cj = d->cbias + 6 * i;
  int nv = b->nv;

  // relative pose and subspace by joint type (S: 6 x nv, the rest of its 36 never read)
  memset(S, 0, 6 * (size_t)nv * sizeof(urT));
  memset(cj, 0, 6 * sizeof(urT));
  urFN(bcast)(p, b->pos, 3);
  switch (b->jtype) {
  case urJNT_FREE: {
    // qpos: CoM in parent + quat; qvel: CoM velocity in parent + omega in body
    urT rc[3], vb[3], t[3], com[3];
    urFN(bcast)(com, b->com, 3);
    urK(quat2mat)(R, q + 3);
    urK(mulmat3vec)(rc, R, com);
    for (int k = 0; k < 3; k++) {
      p[k] = q[k] - rc[k];
    }
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        S[nv * (3 + r) + c] = R[3 * c + r];
      }
      S[nv * r + 3 + r] = urBC(1);
    }
    const double* c = b->com;
    S[nv * 3 + 4] = urBC(-c[2]);
    S[nv * 3 + 5] = urBC(c[1]);
    S[nv * 4 + 3] = urBC(c[2]);
    S[nv * 4 + 5] = urBC(-c[0]);
    S[nv * 5 + 3] = urBC(-c[1]);
    S[nv * 5 + 4] = urBC(c[0]);
    urK(mulmat3tvec)(vb, R, qd);
    urK(cross3)(t, qd + 3, vb);
    cj[3] = -t[0];
    cj[4] = -t[1];
    cj[5] = -t[2];
    break;
  }
  case urJNT_FIXED:
  default: urFN(bcast)(R, b->bmat, 9); break;
  case urJNT_REVOLUTE: {
    urT a0[3];
    urFN(bcast)(a0, b->axis[0], 3);
    urFN(bcast)(Rb, b->bmat, 9);
    urAXISROT(T, a0, q[0], 0);
    urK(mulmat3)(R, Rb, T);
    S[0] = a0[0];
    S[1] = a0[1];
    S[2] = a0[2];
    break;
  }
  case urJNT_UNIVERSAL: {
    // R = Rb Rot(a1, q0) Rot(a2, q1); s1 = Rot(a2, q1)^T a1, s2 = a2
    urT T2[9], s1[3], t[3], a0[3], a1[3];
    urFN(bcast)(a0, b->axis[0], 3);
    urFN(bcast)(a1, b->axis[1], 3);
    urFN(bcast)(Rb, b->bmat, 9);
    urAXISROT(T, a0, q[0], 0);
    urAXISROT(T2, a1, q[1], 1);
    urK(mulmat3)(R, Rb, T);
    urK(mulmat3)(R, R, T2);
    urK(mulmat3tvec)(s1, T2, a0);
    for (int k = 0; k < 3; k++) {
      S[nv * k] = s1[k];
      S[nv * k + 1] = a1[k];
    }
    urK(cross3)(t, s1, a1);
    for (int k = 0; k < 3; k++) {
      cj[k] = qd[0] * qd[1] * t[k];
    }
    break;
  }
  case urJNT_SPHERICAL:
    urFN(bcast)(Rb, b->bmat, 9);
    urK(quat2mat)(T, q);
    urK(mulmat3)(R, Rb, T);
    S[0] = S[nv + 1] = S[2 * nv + 2] = urBC(1);
    break;
  case urJNT_PRISMATIC: {
    urT t[3], a0[3];
    urFN(bcast)(a0, b->axis[0], 3);
    urFN(bcast)(R, b->bmat, 9);
    urK(mulmat3vec)(t, R, a0);
    for (int k = 0; k < 3; k++) {
      p[k] += q[0] * t[k];
      S[3 + k] = a0[k];
    }
    break;
  }
  }

  // store the transform parent -> child
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) {
      d->Xe[9 * i + 3 * r + c] = R[3 * c + r];
    }
  }
  memcpy(d->Xr + 3 * i, p, sizeof(p));
}

//---------------------------------- world poses ---------------------------------------------------

// world poses of the bodies (xmat, xpos, xcom) and the joint quantities of jcalc, in tree order
urKIN_ATTR void urFN(kinematics_bodies)(const urModel* m, urD* d) {
  urKIN_PRE(m, d);
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    urT* xm = d->xmat + 9 * i;
    urT* xp = d->xpos + 3 * i;
    urT R[9], com[3];
    urFN(jcalc)(m, d, i);
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) {
        R[3 * r + c] = d->Xe[9 * i + 3 * c + r];
      }
    }
    if (b->parent < 0) {
      memcpy(xm, R, sizeof(R));
      memcpy(xp, d->Xr + 3 * i, 3 * sizeof(urT));
    } else {
      const urT* pm = d->xmat + 9 * b->parent;
      const urT* pp = d->xpos + 3 * b->parent;
      urT t[3];
      urK(mulmat3)(xm, pm, R);
      urK(mulmat3vec)(t, pm, d->Xr + 3 * i);
      for (int k = 0; k < 3; k++) {
        xp[k] = pp[k] + t[k];
      }
    }
    urT c[3];
    urFN(bcast)(com, b->com, 3);
    urK(mulmat3vec)(c, xm, com);
    for (int k = 0; k < 3; k++) {
      d->xcom[3 * i + k] = xp[k] + c[k];
    }
  }
}

// world orientation of ellipsoid g (gxmat) from that of its body
static inline __attribute__((always_inline)) void urFN(geom_mat)(const urModel* m, urD* d, int g) {
  const urGeom* ge = m->geom + g;
  urT gm[9];
  urFN(bcast)(gm, ge->gmat, 9);
  urK(mulmat3)(d->gxmat + 9 * g, d->xmat + 9 * ge->body, gm);
}


// world positions of the ellipsoids (gxpos) from the poses of their bodies
urKIN_ATTR void urFN(kinematics_gpos)(const urModel* m, urD* d) {
  for (int g = 0; g < m->ngeom; g++) {
    const urGeom* ge = m->geom + g;
    urT t[3], gp[3];
    urFN(bcast)(gp, ge->pos, 3);
    urK(mulmat3vec)(t, d->xmat + 9 * ge->body, gp);
    for (int k = 0; k < 3; k++) {
      d->gxpos[3 * g + k] = d->xpos[3 * ge->body + k] + t[k];
    }
  }
}

//---------------------------------- velocities ----------------------------------------------------

// velocity of body i with nv dofs and nonzero rows k0..k1-1 of S (inlined, constant sizes)
static inline __attribute__((always_inline)) void urFN(bodyvel)(const urModel* m, urD* d, int i,
                                                                const int nv, const int k0,
                                                                const int k1) {
  const urBody* b = m->body + i;
  const urT* S = d->S + 36 * i;
  const urT* qd = d->qvel + b->vadr;
  urT vJ[6] = {urBC(0), urBC(0), urBC(0), urBC(0), urBC(0), urBC(0)}, t[6];
  urT* v = d->cvel + 6 * i;

  // joint velocity
  urUNROLL for (int r = k0; r < k1; r++) {
    urUNROLL for (int c = 0; c < nv; c++) {
      vJ[r] += S[nv * r + c] * qd[c];
    }
  }

  // add the parent's velocity
  if (b->parent >= 0) {
    urK(xmotion)(v, d->Xe + 9 * i, d->Xr + 3 * i, d->cvel + 6 * b->parent);
  } else {
    memset(v, 0, 6 * sizeof(urT));
  }
  for (int k = 0; k < 6; k++) {
    v[k] += vJ[k];
  }

  // bias acceleration
  urK(crossmotion)(t, v, vJ);
  for (int k = 0; k < 6; k++) {
    d->cbias[6 * i + k] += t[k];
  }
}


// spatial body velocities (cvel) and velocity-product accelerations (cbias += v x vJ)
urKIN_ATTR void urFN(velocities)(const urModel* m, urD* d) {
  for (int i = 0; i < m->nbody; i++) {
    switch (m->body[i].jtype) {
    case urJNT_FREE: urFN(bodyvel)(m, d, i, 6, 0, 6); break;
    case urJNT_FIXED: urFN(bodyvel)(m, d, i, 0, 0, 0); break;
    case urJNT_REVOLUTE: urFN(bodyvel)(m, d, i, 1, 0, 3); break;
    case urJNT_UNIVERSAL: urFN(bodyvel)(m, d, i, 2, 0, 3); break;
    case urJNT_SPHERICAL: urFN(bodyvel)(m, d, i, 3, 0, 3); break;
    case urJNT_PRISMATIC: urFN(bodyvel)(m, d, i, 1, 3, 6); break;
    }
  }
}

#undef urKIN_ATTR
#undef urKIN_PRE
