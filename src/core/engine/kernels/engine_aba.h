/* engine_aba.h: Featherstone's articulated-body algorithm as a template, included once for
 * doubles (ur_aba on urData, engine_dynamics.c) and once for lanes of runs in lock-step (urv_aba
 * on urLanes, engine_lanes.c). Parameters: urT element type, urBC(x) a double broadcast to urT,
 * urK(name) the spatial kernels (engine_spatial.h), urFN(name) this file's function names, urD
 * the data (fields S IA pA U Dinv uu cbias cvel cacc Xe Xr qfrc fext qacc freact energy), and
 * urINVSYM(d, Dinv, D, nv) the inverse of a joint-space inertia with its failure handling,
 * urSETENERGY(d, ke) the store of the kinetic energy, urSTEPH(d) the step under way (urT: the
 * implicit damping's h), urABA_ATTR (optional) attributes of the entry point. The same
 * expressions in the same order make each lane's bits those of the scalar run. No include
 * guard: included once per instance; the protocol (who defines and undefines the parameters,
 * the bit-exactness rules): src/README. */

// base acceleration (-gravity) expressed in root body i
static void urFN(baseacc)(const urModel* m, const urD* d, int i, urT a[6]) {
  urT a0[6] = {urBC(0),
               urBC(0),
               urBC(0),
               urBC(-m->opt.gravity[0]),
               urBC(-m->opt.gravity[1]),
               urBC(-m->opt.gravity[2])};
  urK(xmotion)(a, d->Xe + 9 * i, d->Xr + 3 * i, a0);
}


// pass 2 of the ABA for body i with nv dofs and nonzero rows k0..k1-1 of S (inlined with
// constant sizes so that the small loops unroll)
static inline __attribute__((always_inline)) void urFN(pass2)(const urModel* m, urD* d, int i,
                                                              const int nv, const int k0,
                                                              const int k1) {
  const urBody* b = m->body + i;
  const urT* S = d->S + 36 * i;
  urT* IA = d->IA + 36 * i;
  urT* pA = d->pA + 6 * i;
  urT* U = d->U + 36 * i;
  urT* Dinv = d->Dinv + 36 * i;
  urT* u = d->uu + 6 * i;
  urT D[36], UD[36], t[6];

  // U = IA S, D = S^T U, u = tau - S^T pA (spherical: S = [1; 0], so U = IA[:, 0:3])
  if (nv == 3 && k1 == 3) {
    urUNROLL for (int r = 0; r < 6; r++) {
      urUNROLL for (int c = 0; c < 3; c++) {
        U[3 * r + c] = IA[6 * r + c];
      }
    }
    urUNROLL for (int r = 0; r < 3; r++) {
      u[r] = d->qfrc[b->vadr + r] - pA[r];
      urUNROLL for (int c = 0; c < 3; c++) {
        D[3 * r + c] = IA[6 * r + c];
      }
    }
  } else {
    urUNROLL for (int r = 0; r < 6; r++) {
      urUNROLL for (int c = 0; c < nv; c++) {
        urT s = urBC(0);
        urUNROLL for (int k = k0; k < k1; k++) {
          s += IA[6 * r + k] * S[nv * k + c];
        }
        U[nv * r + c] = s;
      }
    }
    urUNROLL for (int r = 0; r < nv; r++) {
      urT s = d->qfrc[b->vadr + r];
      urUNROLL for (int k = k0; k < k1; k++) {
        s -= S[nv * k + r] * pA[k];
      }
      u[r] = s;
      urUNROLL for (int c = 0; c < nv; c++) {
        urT e = urBC(0);
        urUNROLL for (int k = k0; k < k1; k++) {
          e += S[nv * k + r] * U[nv * k + c];
        }
        D[nv * r + c] = e;
      }
    }
  }
  // implicit joint damping: the restraint's linear damper acts at the new velocity, so the
  // joint-space inertia gains h c on its diagonal (an armature; exact for M + h C; h the step,
  // urSTEPH: dt, or adapt dt for a coarse step)
  if (m->opt.implicit_damping && m->opt.integrator == urINT_EULER) {
    for (int r = 0; r < nv && r < 3; r++) {
      if (b->rst[r].active) {
        D[nv * r + r] += urSTEPH(d) * urBC(b->rst[r].c);
      }
    }
  }
  if (nv) {
    urINVSYM(d, Dinv, D, nv);
  }
  if (b->parent < 0) {
    return;
  }

  // Ia = IA - U Dinv U^T (symmetric), pa = pA + Ia c + U Dinv u, in place (IA and pA of body i
  // are not read again)
  urT* Ia = IA;
  urT* pa = pA;
  if (nv) {
    urT Du[6];
    urUNROLL for (int r = 0; r < 6; r++) {
      urUNROLL for (int c = 0; c < nv; c++) {
        urT s = urBC(0);
        urUNROLL for (int k = 0; k < nv; k++) {
          s += U[nv * r + k] * Dinv[nv * k + c];
        }
        UD[nv * r + c] = s;
      }
    }
    urUNROLL for (int r = 0; r < 6; r++) {
      urUNROLL for (int c = r; c < 6; c++) {
        urT s = urBC(0);
        urUNROLL for (int k = 0; k < nv; k++) {
          s += UD[nv * r + k] * U[nv * c + k];
        }
        Ia[6 * r + c] -= s;
        if (c != r) {
          Ia[6 * c + r] -= s;
        }
      }
    }
    urUNROLL for (int r = 0; r < nv; r++) {
      urT s = urBC(0);
      urUNROLL for (int k = 0; k < nv; k++) {
        s += Dinv[nv * r + k] * u[k];
      }
      Du[r] = s;
    }
    urUNROLL for (int r = 0; r < 6; r++) {
      urUNROLL for (int k = 0; k < nv; k++) {
        pa[r] += U[nv * r + k] * Du[k];
      }
    }
  }
  urK(mul6)(t, Ia, d->cbias + 6 * i);
  urUNROLL for (int k = 0; k < 6; k++) {
    pa[k] += t[k];
  }

  // accumulate into the parent
  urK(xinertia_t_add)(d->IA + 36 * b->parent, d->Xe + 9 * i, d->Xr + 3 * i, Ia);
  urK(xforce_t)(t, d->Xe + 9 * i, d->Xr + 3 * i, pa);
  urUNROLL for (int k = 0; k < 6; k++) {
    d->pA[6 * b->parent + k] += t[k];
  }
}


// pass 3 of the ABA for body i with nv dofs and nonzero rows k0..k1-1 of S (inlined with
// constant sizes)
static inline __attribute__((always_inline)) void urFN(pass3)(const urModel* m, urD* d, int i,
                                                              const int nv, const int k0,
                                                              const int k1) {
  const urBody* b = m->body + i;
  const urT* S = d->S + 36 * i;
  const urT* U = d->U + 36 * i;
  const urT* Dinv = d->Dinv + 36 * i;
  const urT* u = d->uu + 6 * i;
  urT* a = d->cacc + 6 * i;
  urT* qdd = d->qacc + b->vadr;
  urT r[6];

  // parent acceleration plus bias
  if (b->parent >= 0) {
    urK(xmotion)(a, d->Xe + 9 * i, d->Xr + 3 * i, d->cacc + 6 * b->parent);
  } else {
    urFN(baseacc)(m, d, i, a);
  }
  urUNROLL for (int k = 0; k < 6; k++) {
    a[k] += d->cbias[6 * i + k];
  }

  // joint accelerations: qdd = Dinv (u - U^T a), then a += S qdd
  urUNROLL for (int c = 0; c < nv; c++) {
    urT s = u[c];
    urUNROLL for (int k = 0; k < 6; k++) {
      s -= U[nv * k + c] * a[k];
    }
    r[c] = s;
  }
  urUNROLL for (int c = 0; c < nv; c++) {
    urT s = urBC(0);
    urUNROLL for (int k = 0; k < nv; k++) {
      s += Dinv[nv * c + k] * r[k];
    }
    qdd[c] = s;
  }
  // (the zero rows of S skipped; spherical: S = [1; 0], so a gains qdd itself)
  if (nv == 3 && k1 == 3) {
    urUNROLL for (int k = 0; k < 3; k++) {
      a[k] += qdd[k];
    }
    return;
  }
  urUNROLL for (int k = k0; k < k1; k++) {
    urUNROLL for (int c = 0; c < nv; c++) {
      a[k] += S[nv * k + c] * qdd[c];
    }
  }
}


// needs ur_kinematics, ur_velocities, joint forces d->qfrc and external forces d->fext
#ifdef urABA_ATTR
urABA_ATTR
#endif
    void
    urFN(aba)(const urModel* m, urD* d) {
  int nb = m->nbody;

  // pass 1: rigid-body inertias and bias forces (velocities from ur_velocities); the bias
  // force is kept in freact for ur_reactions (of the bodies it visits), the kinetic energy in
  // d->energy
  urT ke = urBC(0);
  for (int i = 0; i < nb; i++) {
    const urT* v = d->cvel + 6 * i;
    urT Iv[6];
    for (int k = 0; k < 36; k++) {
      d->IA[36 * i + k] = urBC(m->body[i].sinert[k]);
    }
    urK(mul6)(Iv, d->IA + 36 * i, v);
    urK(crossforce)(d->pA + 6 * i, v, Iv);
    for (int k = 0; k < 6; k++) {
      d->pA[6 * i + k] -= d->fext[6 * i + k];
      ke += 0.5 * v[k] * Iv[k];
    }
    if (m->body[i].react) {
      memcpy(d->freact + 6 * i, d->pA + 6 * i, 6 * sizeof(urT));
    }
  }
  urSETENERGY(d, ke);

  // pass 2: articulated inertias and bias forces, leaves to roots
  for (int i = nb - 1; i >= 0; i--) {
    switch (m->body[i].jtype) {
    case urJNT_FREE: urFN(pass2)(m, d, i, 6, 0, 6); break;
    case urJNT_FIXED: urFN(pass2)(m, d, i, 0, 0, 0); break;
    case urJNT_REVOLUTE: urFN(pass2)(m, d, i, 1, 0, 3); break;
    case urJNT_UNIVERSAL: urFN(pass2)(m, d, i, 2, 0, 3); break;
    case urJNT_SPHERICAL: urFN(pass2)(m, d, i, 3, 0, 3); break;
    case urJNT_PRISMATIC: urFN(pass2)(m, d, i, 1, 3, 6); break;
    }
  }

  // pass 3: accelerations, roots to leaves
  for (int i = 0; i < nb; i++) {
    switch (m->body[i].jtype) {
    case urJNT_FREE: urFN(pass3)(m, d, i, 6, 0, 6); break;
    case urJNT_FIXED: urFN(pass3)(m, d, i, 0, 0, 0); break;
    case urJNT_REVOLUTE: urFN(pass3)(m, d, i, 1, 0, 3); break;
    case urJNT_UNIVERSAL: urFN(pass3)(m, d, i, 2, 0, 3); break;
    case urJNT_SPHERICAL: urFN(pass3)(m, d, i, 3, 0, 3); break;
    case urJNT_PRISMATIC: urFN(pass3)(m, d, i, 1, 3, 6); break;
    }
  }
}

#undef urABA_ATTR
