/* injury_eval.c: all injury criteria and PoFs of one impact from its time histories: the
 * channels conditioned once, then every criterion of the registry (injury_registry.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "uasimpact/injury.h"

#define NBUF                                                                                       \
  10 /* work buffers of n doubles: 8 conditioned channels, then the
                                      criteria's work space (n doubles and the HIC work) */

int ur_injury_work_size(int n) {
  return n > 0 ? (NBUF - 1) * n + ur_hic_work_size(n) : 0;
}

/* 1 if t is uniformly spaced (relative 1e-6), step in *dt */
static int uniform_step(const double* t, int n, double* dt) {
  *dt = n > 1 ? (t[n - 1] - t[0]) / (n - 1) : 0;
  if (!(*dt > 0)) {
    return 0;
  }
  for (int k = 1; k < n; k++) {
    if (fabs((t[k] - t[k - 1]) - *dt) > 1e-6 * *dt) {
      return 0;
    }
  }
  return 1;
}

/* copy a channel, filtered if asked; NULL stays NULL */
static const double* condition(const double* x, int n, int filt, double dt, double cfc, double* buf,
                               int* err) {
  if (!x || !filt) {
    return x;
  }
  if (ur_cfc_filter(x, n, dt, cfc, buf)) {
    *err = -3;
  }
  return buf;
}

int ur_injury_eval(const urInjuryInput* in, const urInjuryParams* p, double* work,
                   urInjuryResult* out) {
  if (!in || !p || !out || !in->t || in->n < 1) {
    return -1;
  }
  memset(out, 0, sizeof(*out));
  int n = in->n;

  // filtering needs uniform samples
  double dt = 0;
  int filt = p->filter != 0;
  if (filt && !uniform_step(in->t, n, &dt)) {
    return -3;
  }

  // caller workspace or one allocation
  double* w = work;
  if (!w) {
    w = malloc((size_t)ur_injury_work_size(n) * sizeof(double));
    if (!w) {
      return -2;
    }
  }
  double* buf[NBUF];
  for (int k = 0; k < NBUF; k++) {
    buf[k] = w + (size_t)k * n;
  }

  // condition every channel
  int err = 0;
  const double* ha[3];
  for (int k = 0; k < 3; k++) {
    ha[k] = condition(in->head_acc[k], n, filt, dt, p->cfc_head, buf[k], &err);
  }
  const double* fz = condition(in->neck_fz, n, filt, dt, p->cfc_neck, buf[3], &err);
  const double* my = condition(in->neck_my, n, filt, dt, p->cfc_neck, buf[4], &err);
  const double* fx = condition(in->neck_fx, n, filt, dt, p->cfc_neck, buf[5], &err);
  const double* dth = condition(in->thorax_d, n, filt, dt, p->cfc_defl, buf[6], &err);
  const double* dab = condition(in->abdomen_d, n, filt, dt, p->cfc_defl, buf[7], &err);
  if (err) {
    goto done;
  }

  // every criterion of the registry on the conditioned channels, then the fusion (3.1)
  urInjuryInput cond = *in;
  for (int k = 0; k < 3; k++) cond.head_acc[k] = ha[k];
  cond.neck_fz = fz;
  cond.neck_my = my;
  cond.neck_fx = fx;
  cond.thorax_d = dth;
  cond.abdomen_d = dab;
  for (int k = 0; k < urNCRIT; k++) {
    if (ur_criterion(k)->compute(&cond, p, buf[8], out)) {
      err = -1;
      goto done;
    }
  }
  out->p_total = ur_pof_fuse_used(out->pof, p);

done:
  if (!work) {
    free(w);
  }
  return err;
}
