/* engine_quat.h: the quaternion maps of the integrators and the spherical restraints, the
 * integrators' position update and the restraints' kinematics, as a template like
 * engine_spatial.h, branch-free (a condition picks between both results), so that lanes give
 * each run the bits of its scalar call. Parameters: urT, urM, urK(name), urSTORAGE the linkage,
 * urBC(x), urSEL(m, a, b) and urSQRT(x) as in engine_trig.h and engine_invsym.h; uses the
 * instance's sincos and atan2q (engine_trig.h), mulquat and mulmat3 (engine_spatial.h). No
 * include guard: included once per instance; the protocol (who defines and undefines the
 * parameters, the bit-exactness rules): src/README. */

// q <- q * exp(omega dt / 2), omega in the local frame, then normalised (a zero or non-finite
// norm gives the identity); q unchanged if |omega| dt < 1e-300
urSTORAGE void urK(quatintegrate)(urT q[4], const urT omega[3], urT dt) {
  urT w = urSQRT(omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]);
  urT th = w * dt, s, c;
  urK(sincos)(urBC(0.5) * th, &s, &c);
  s = s / w;
  urT dq[4] = {c, s * omega[0], s * omega[1], s * omega[2]}, r[4];
  urK(mulquat)(r, q, dq);
  urT n = urSQRT(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  urM ok = (n > urBC(0)) & (n < urBC(INFINITY)), none = th < urBC(1e-300);
  for (int i = 0; i < 4; i++) {
    urT ri = urSEL(ok, r[i] / n, urBC(i == 0 ? 1 : 0));
    q[i] = urSEL(none, q[i], ri);
  }
}


// rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion
urSTORAGE void urK(quat2rotvec)(urT v[3], const urT q[4]) {
  urT sg = urSEL(q[0] < urBC(0), urBC(-1), urBC(1));
  urT w = sg * q[0], x = sg * q[1], y = sg * q[2], z = sg * q[3];
  urT s = urSQRT(x * x + y * y + z * z);
  urT ang = urBC(2) * urK(atan2q)(s, w);
  urT f = urSEL(s > urBC(1e-12), ang / s, urBC(2.0) / urSEL(w > urBC(0), w, urBC(1.0)));
  v[0] = f * x;
  v[1] = f * y;
  v[2] = f * z;
}


// inverse right Jacobian of SO(3) at rotation vector v: d(rotvec)/dt = Jrinv * omega_local;
// I + K/2 + c2 K^2, c2 = 1/th^2 - (1 + cos th)/(2 th sin th), its series below th = 1e-4
urSTORAGE void urK(rotvec_jrinv)(urT J[9], const urT v[3]) {
  urT th = urSQRT(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), s, c;
  urK(sincos)(th, &s, &c);
  urT c2 = urSEL(th < urBC(1e-4), urBC(1.0 / 12.0) + th * th / urBC(720.0),
                 urBC(1.0) / (th * th) - (urBC(1) + c) / (urBC(2) * th * s));
  urT K[9] = {urBC(0), -v[2], v[1], v[2], urBC(0), -v[0], -v[1], v[0], urBC(0)}, K2[9];
  urK(mulmat3)(K2, K, K);
  for (int i = 0; i < 9; i++) {
    J[i] = urBC(0.5) * K[i] + c2 * K2[i];
  }
  J[0] += urBC(1);
  J[4] += urBC(1);
  J[8] += urBC(1);
}


// q <- q "+" h v: each joint's coordinates advanced by h times its velocities, quaternions by
// their exact exponential (the position update of the integrators)
urSTORAGE void urK(addpos)(const urModel* m, urT* qpos, const urT* qvel, urT h) {
  for (int i = 0; i < m->nbody; i++) {
    const urBody* b = m->body + i;
    urT* q = qpos + b->qadr;
    const urT* v = qvel + b->vadr;
    switch (b->jtype) {
    case urJNT_FREE:
      for (int k = 0; k < 3; k++) {
        q[k] += h * v[k];
      }
      urK(quatintegrate)(q + 3, v + 3, h);
      break;
    case urJNT_SPHERICAL: urK(quatintegrate)(q, v, h); break;
    case urJNT_FIXED: break;
    default:
      for (int k = 0; k < b->nv; k++) {
        q[k] += h * v[k];
      }
    }
  }
}


// the spherical restraints' deflections (rotation vector minus x0) and inverse right Jacobians
// from the coordinates qpos into rkin (12 per body: urData.rkin)
urSTORAGE void urK(restraints_kin)(const urModel* m, const urT* qpos, urT* rkin) {
  for (int j = 0; j < m->nrstb; j++) {
    int i = m->rstb[j];
    const urBody* b = m->body + i;
    if (b->jtype == urJNT_SPHERICAL) {
      urT* x = rkin + 12 * i;
      urK(quat2rotvec)(x, qpos + b->qadr);
      for (int k = 0; k < 3; k++) {
        x[k] = x[k] - urBC(b->rst[k].x0);
      }
      urK(rotvec_jrinv)(x + 3, x);
    }
  }
}
