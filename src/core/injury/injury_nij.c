/* injury_nij.c: neck injury criterion Nij, four modes selected by the load signs. */
#include <math.h>

#include "uasimpact/injury.h"

urNijMode ur_nij_mode(double fz, double moc) {
  // tension/compression by Fz, flexion/extension by the moment at the condyle
  if (fz >= 0) {
    return moc >= 0 ? urNIJ_NTF : urNIJ_NTE;
  }
  return moc >= 0 ? urNIJ_NCF : urNIJ_NCE;
}

double ur_nij_sample(double fz, double moc, const urInjuryParams* p) {
  // intercepts chosen by the signs
  double fzc = fz >= 0 ? p->nij_fzc_tension : p->nij_fzc_compression;
  double myc = moc >= 0 ? p->nij_myc_flexion : p->nij_myc_extension;
  return fabs(fz) / fzc + fabs(moc) / myc;
}

int ur_nij(const double* fz, const double* my, const double* fx, int n, const urInjuryParams* p,
           urNij* out) {
  if (!fz || !my || !p || !out || n < 1) {
    return -1;
  }
  if (!(p->nij_fzc_tension > 0) || !(p->nij_fzc_compression > 0) || !(p->nij_myc_flexion > 0) ||
      !(p->nij_myc_extension > 0)) {
    return -1;
  }

  // clear the modes
  for (int m = 0; m < 4; m++) {
    out->mode[m] = 0;
    out->imode[m] = -1;
  }
  out->nij = 0;
  out->which = urNIJ_NTF;
  out->imax = 0;

  // per-sample mode and value; keep each mode's maximum
  for (int i = 0; i < n; i++) {
    double moc = my[i] - (fx ? p->nij_condyle_d * fx[i] : 0.0);
    int m = ur_nij_mode(fz[i], moc);
    double v = ur_nij_sample(fz[i], moc, p);
    if (out->imode[m] < 0 || v > out->mode[m]) {
      out->mode[m] = v;
      out->imode[m] = i;
    }
  }

  // overall maximum over the four modes
  int first = 1;
  for (int m = 0; m < 4; m++) {
    if (out->imode[m] >= 0 && (first || out->mode[m] > out->nij)) {
      out->nij = out->mode[m];
      out->which = m;
      out->imax = out->imode[m];
      first = 0;
    }
  }
  return 0;
}
