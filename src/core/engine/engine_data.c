/* engine_data.c: per-run data: allocation in one buffer, reset, copy, history buffers, and the
 * run's status (set by every stage, so it lives with the data, below them all). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- layout --------------------------------------------------------

// number of doubles in the array part of the buffer
static size_t ndoubles(const urModel* m) {
  size_t nb = (size_t)m->nbody, ng = (size_t)m->ngeom, nq = (size_t)m->nq, nv = (size_t)m->nv;
  size_t ns = (size_t)m->nsensordata;
  return nq + 5 * nv + nb * (12 + 3 + 9 + 3 + 9 + 3 + 36 + 6 * 3 + 36 + 6 + 36 + 36 + 6 + 6 + 6) +
         ng * 12 + 5 * ns + 2 * nq + 8 * nv + (size_t)m->npair + (size_t)m->nmemd;
}


// point the arrays of d into its buffer
static void carve(const urModel* m, urData* d) {
  double* p = d->buffer;
  int nb = m->nbody, ng = m->ngeom, nq = m->nq, nv = m->nv, ns = m->nsensordata;
#define TAKE(field, n)                                                                             \
  d->field = p;                                                                                    \
  p += (n);
  TAKE(qpos, nq)
  TAKE(qvel, nv)
  TAKE(qacc, nv)
  TAKE(qfrc, nv)
  TAKE(rst, 2 * nv)
  TAKE(rkin, 12 * nb)
  TAKE(xpos, 3 * nb)
  TAKE(xmat, 9 * nb)
  TAKE(xcom, 3 * nb)
  TAKE(gxpos, 3 * ng)
  TAKE(gxmat, 9 * ng)
  TAKE(Xe, 9 * nb)
  TAKE(Xr, 3 * nb)
  TAKE(S, 36 * nb)
  TAKE(cvel, 6 * nb)
  TAKE(cbias, 6 * nb)
  TAKE(cacc, 6 * nb)
  TAKE(IA, 36 * nb)
  TAKE(pA, 6 * nb)
  TAKE(U, 36 * nb)
  TAKE(Dinv, 36 * nb)
  TAKE(uu, 6 * nb)
  TAKE(fext, 6 * nb)
  TAKE(freact, 6 * nb)
  TAKE(sensordata, ns)
  TAKE(peakmax, ns)
  TAKE(peakmin, ns)
  TAKE(tpeak, ns)
  TAKE(sprev, ns)
  TAKE(scratch, 2 * nq + 8 * nv)
  TAKE(pdepth, m->npair)
  TAKE(mem, m->nmemd)
#undef TAKE
  // pairs on cache lines (the buffer is aligned, so the offset is the same in every copy)
  uintptr_t a = (uintptr_t)p, al = _Alignof(urPairData);
  d->pair = (urPairData*)((a + al - 1) / al * al);
  d->bag = (urBagData*)(d->pair + m->npair);
  d->plist = (int*)(d->bag + m->nbag);
  d->gmat_ok = (unsigned char*)(d->plist + 2 * m->npair);
}


static size_t buffersize(const urModel* m) {
  size_t n = ndoubles(m) * sizeof(double) + _Alignof(urPairData) +
             (size_t)m->npair * sizeof(urPairData) + (size_t)m->nbag * sizeof(urBagData) +
             2 * (size_t)m->npair * sizeof(int) + (size_t)m->ngeom + sizeof(double);
  return (n + _Alignof(urPairData) - 1) / _Alignof(urPairData) * _Alignof(urPairData);
}

//---------------------------------- public --------------------------------------------------------

urData* ur_data_new(const urModel* m) {
  if (!m || !m->compiled) {
    return NULL;
  }
  urData* d = calloc(1, sizeof(urData));
  if (!d) {
    return NULL;
  }
  d->buffer = aligned_alloc(_Alignof(urPairData), buffersize(m));
  if (d->buffer) {
    memset(d->buffer, 0, buffersize(m));
  } else {
    free(d);
    return NULL;
  }
  if (m->nfrac > 0) {
    // the run's own topology once a joint breaks (engine_fracture.c)
    d->topo = malloc(sizeof(urModel) + (size_t)m->nbody * sizeof(urBody));
    if (!d->topo) {
      free(d->buffer);
      free(d);
      return NULL;
    }
  }
  carve(m, d);
  ur_data_reset(m, d);
  return d;
}


void ur_data_free(urData* d) {
  if (!d) {
    return;
  }
  if (d->hist_own) {
    free(d->hist);
  }
  free(d->topo);
  free(d->buffer);
  free(d);
}


void ur_data_reset(const urModel* m, urData* d) {
  // clear the buffer, set the reference configuration
  memset(d->buffer, 0, buffersize(m));
  if (m->nq) {
    memcpy(d->qpos, m->qpos0, (size_t)m->nq * sizeof(double));
  }

  // outputs and run control
  for (int i = 0; i < m->nsensordata; i++) {
    d->peakmax[i] = -INFINITY;
    d->peakmin[i] = INFINITY;
  }
  for (int i = 0; i < m->npair; i++) {
    d->pdepth[i] = -INFINITY;
  }
  d->npcommit = d->npactive = 0;
  d->time = 0;
  d->nhist = 0;
  d->status = urSTAT_OK;
  d->msg[0] = 0;
  d->nstep = 0;
  d->proj = -1;
  d->t_jump = 0;
  d->t_first = -1;
  d->t_last = -1;
  d->t_calm = 0;
  d->clear_hint = 0;
  d->coarse = d->pend = 0;
  d->ncoarse = d->ntouch = 0;
  d->energy = 0;
  d->nreleased = 0;
  ur_kinematics(m, d);
}


void ur_data_copy(const urModel* m, urData* dst, const urData* src) {
  // keep the buffer and history of dst
  void* buf = dst->buffer;
  double* hist = dst->hist;
  int cap = dst->nhist_cap, own = dst->hist_own;
  urModel* topo = dst->topo;
  memcpy(buf, src->buffer, buffersize(m));
  *dst = *src;
  dst->buffer = buf;
  dst->topo = topo;
  if (src->nreleased > 0 && topo && src->topo) {
    // the released joints too (the copy's body array follows its model)
    *topo = *src->topo;
    topo->body = (urBody*)(topo + 1);
    memcpy(topo->body, src->topo->body, (size_t)m->nbody * sizeof(urBody));
  } else {
    dst->nreleased = 0;
  }
  carve(m, dst);
  dst->hist = hist;
  dst->nhist_cap = cap;
  dst->hist_own = own;
  dst->nhist = 0;
}


int ur_data_history(const urModel* m, urData* d, double* buf, int rows) {
  // release an old engine buffer
  if (d->hist_own) {
    free(d->hist);
  }
  d->hist = NULL;
  d->hist_own = 0;
  d->nhist = 0;
  d->nhist_cap = 0;
  if (rows <= 0) {
    return 0;
  }

  // caller buffer or engine allocation
  if (buf) {
    d->hist = buf;
  } else {
    d->hist = malloc((size_t)rows * (size_t)(1 + m->nsensordata) * sizeof(double));
    if (!d->hist) {
      return -1;
    }
    d->hist_own = 1;
  }
  d->nhist_cap = rows;
  return 0;
}


//---------------------------------- status --------------------------------------------------------

void ur_set_status(urData* d, int status, const char* msg) {
  if (d->status < 0) {
    return;
  }
  d->status = status;
  snprintf(d->msg, sizeof(d->msg), "%s", msg ? msg : "");
}


const char* ur_status_str(int status) {
  switch (status) {
  case urSTAT_OK: return "ok";
  case urSTAT_SEPARATED: return "ended: contact over";
  case urSTAT_SETTLED: return "ended: motion settled";
  case urSTAT_TMAX: return "ended: maximum time";
  case urSTAT_NONFINITE: return "failed: non-finite state";
  case urSTAT_EXPLODE: return "failed: exploding state";
  case urSTAT_BADARG: return "failed: bad argument";
  case urSTAT_STOPPED: return "failed: stopped on request";
  default: return "unknown";
  }
}
