/* injury_eval.c: all injury criteria and PoFs of one impact from its time histories. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "uasrisk/injury.h"

#define NBUF 10                    /* work buffers of n doubles; the last one holds the HIC work */

int ur_injury_work_size(int n)
{
  return n > 0 ? (NBUF - 1) * n + ur_hic_work_size(n) : 0;
}

/* 1 if t is uniformly spaced (relative 1e-6), step in *dt */
static int uniform_step(const double* t, int n, double* dt)
{
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
static const double* condition(const double* x, int n, int filt, double dt, double cfc,
                               double* buf, int* err)
{
  if (!x || !filt) {
    return x;
  }
  if (ur_cfc_filter(x, n, dt, cfc, buf)) {
    *err = -3;
  }
  return buf;
}

int ur_injury_eval(const urInjuryInput* in, const urInjuryParams* p, double* work,
                   urInjuryResult* out)
{
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

  // HIC from the resultant head acceleration in g
  if (ha[0]) {
    double* ag = buf[8];
    for (int i = 0; i < n; i++) {
      double s = ha[0][i] * ha[0][i];
      s += ha[1] ? ha[1][i] * ha[1][i] : 0.0;
      s += ha[2] ? ha[2][i] * ha[2][i] : 0.0;
      ag[i] = (ha[1] || ha[2] ? sqrt(s) : ha[0][i]) / urGRAVITY;
    }
    if (ur_hic(in->t, ag, n, 0.015, buf[9], &out->hic15) ||
        (!in->skip_hic36 && ur_hic(in->t, ag, n, 0.036, buf[9], &out->hic36)) ||
        (p->hic_window == 0.015 ? (out->hic = out->hic15, 0)
                                : ur_hic(in->t, ag, n, p->hic_window, buf[9], &out->hic))) {
      err = -1;
      goto done;
    }
    out->p_hic = ur_pof_hic(out->hic.hic, p);
  }

  // Nij
  if (fz && my) {
    if (ur_nij(fz, my, fx, n, p, &out->nij)) {
      err = -1;
      goto done;
    }
    out->p_nij = ur_pof_nij(out->nij.nij, p);
  }

  // VC of thorax and abdomen
  if (dth) {
    if (ur_vc(in->t, dth, n, p->vc_d0_thorax, p->vc_sf, NULL, &out->vc_thorax)) {
      err = -1;
      goto done;
    }
    out->p_vc_thorax = ur_pof_vc(out->vc_thorax.vc, urTHORAX, p);
  }
  if (dab) {
    if (ur_vc(in->t, dab, n, p->vc_d0_abdomen, p->vc_sf, NULL, &out->vc_abdomen)) {
      err = -1;
      goto done;
    }
    out->p_vc_abdomen = ur_pof_vc(out->vc_abdomen.vc, urABDOMEN, p);
  }
  out->p_vc = ur_pof_vc_fuse(out->p_vc_thorax, out->p_vc_abdomen, p);

  // fusion (3.1)
  out->p_total = ur_pof_fuse(out->p_hic, out->p_nij, out->p_vc);

done:
  if (!work) {
    free(w);
  }
  return err;
}
