/* engine_range.c: laws and restraint curves used beyond their data. A tabulated curve is
 * extrapolated linearly past its ends (contact.h), which is a guess, not data: a run says when it
 * went there, so that a result resting on it is not taken for a measured one. A soft layer
 * pressed through its thickness (bottomed: the bone took over) is noted the same way. */
#include <math.h>
#include <stdio.h>
#include "engine_internal.h"

// the data range of a restraint's load curve: [x0, xn], or [-xn, xn] when it is extended
// odd-symmetrically (no negative abscissae)
static void curve_range(const urCurve* c, double* lo, double* hi) {
  *hi = c->x[c->n - 1];
  *lo = c->x[0] >= 0 ? -*hi : c->x[0];
}


int ur_extrapolated(const urModel* m, const urData* d, char* msg, int len) {
  int n = 0;
  double worst = 0;
  if (len > 0) {
    msg[0] = 0;
  }

  // pairs: the largest depth reached against the depth the law's data covers
  for (int i = 0; i < m->npair; i++) {
    double r = ur_law_range(&m->pair[i].law), dm = d->pair[i].ls.dmax;
    if (!(dm > r)) {
      continue;
    }
    n++;
    if (dm / r > worst) {
      worst = dm / r;
      if (len > 0 && m->pair[i].law.layer_h > 0) {
        snprintf(msg, (size_t)len,
                 "pair %s at depth %.4g m bottomed its %.4g m layer: the bone's stiffness "
                 "took over",
                 m->pair[i].name, dm, m->pair[i].law.layer_h);
      } else if (len > 0) {
        snprintf(msg, (size_t)len, "pair %s at depth %.4g m, its law's data end at %.4g m",
                 m->pair[i].name, dm, r);
      }
    }
  }

  // pairs: a crushing shell that bottomed on its contents (the contact alone took over): noted
  // like a law at the end of its data, after any law run beyond it
  for (int i = 0; i < m->npair; i++) {
    const urLaw* l = &m->pair[i].law;
    if (!(l->crush_f > 0) || d->pair[i].ls.crush < l->crush_h) {
      continue;
    }
    n++;
    if (!(worst > 0)) {
      worst = 1;
      if (len > 0) {
        snprintf(msg, (size_t)len,
                 "pair %s crushed its shell %.4g m to the bottom: the contact alone took over",
                 m->pair[i].name, l->crush_h);
      }
    }
  }

  // restraints: the extreme deflections (tracked on every dof with a curve) against the curve
  for (int j = 0; j < m->nhyst; j++) {
    const urBody* b = m->body + m->hyst[j];
    for (int k = 0; k < b->nv && k < 3; k++) {
      const urRestraint* r = b->rst + k;
      if (!r->active || r->load.n < 2) {
        continue;
      }
      const double* st = d->rst + 2 * (b->vadr + k);
      double lo, hi;
      curve_range(&r->load, &lo, &hi);
      double span = hi - lo, out = fmax(st[0] - hi, lo - st[1]);
      if (!(out > 0)) {
        continue;
      }
      n++;
      if (1 + out / span > worst) {
        worst = 1 + out / span;
        if (len > 0) {
          snprintf(msg, (size_t)len,
                   "restraint %s dof %d at %.4g, its curve's data span "
                   "%.4g..%.4g",
                   b->name, k, st[0] - hi > 0 ? st[0] : st[1], lo, hi);
        }
      }
    }
  }
  return n;
}
