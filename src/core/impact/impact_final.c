/* impact_final.c: an end of run once every injury criterion's value is final (model parameter
 * endrun 1, the default, or 'set endrun final'; 0 ends a run by the window alone). Each history row
 * gives the signals the criteria are maxima of: the head's resultant acceleration (HIC), the
 * neck's Nij at the sample, the thorax's and abdomen's V(t) C(t) (VC) and the thorax's
 * deflection (Dmax). Final means: from FIN_SPAN after the first contact on, with the drone
 * slowed to FIN_SPEED of its impact speed, none of HIC15 (and the HIC of hic_window), Nij, VC
 * and Dmax can rise, nor its PoF by more than FIN_PTOL, as long as each signal stays below
 * FIN_RISE times its largest value of the last FIN_SPAN. Nij, VC and Dmax are maxima of their
 * signal; for HIC, a window reaching past now has its past part in the histories and its future
 * part at most that level, which bounds it (ur_impact_final). The test runs every FIN_EVERY. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../engine/engine_internal.h"
#include "impact_internal.h"

#define FIN_RISE  2.0   /* the signals may rise to this factor of their span's largest value */
#define FIN_SPEED 0.5   /* the drone has slowed to this fraction of its impact speed */
#define FIN_PTOL  1e-6  /* a criterion whose PoF cannot rise by more than this is final */
#define FIN_EVERY 1e-3  /* the test runs this often, s */
#define FIN_HIC   0.015 /* HIC15's window, s */
#define FIN_SPAN  0.005 /* the span whose largest values bound what follows, s */

/* per row: head acceleration (g), Nij, VC thorax and abdomen, thorax deflection, then the
   trapezoid integral of the acceleration from the first row */
enum {
  F_A,
  F_NIJ,
  F_VCT,
  F_VCA,
  F_D,
  F_INT,
  NF
};
#define NSIG F_INT

struct urImpactFinal {
  int cap, n;      /* rows held, rows taken */
  int j;           /* first row of the longest HIC window ending at the last row */
  double next;     /* time of the next test, s */
  double lb;       /* the largest HIC of those windows: a lower bound of HIC15 */
  double pk[NSIG]; /* each signal's largest value */
  double speed;    /* impact speed, m/s */
  double* x;       /* cap x NF */
};

urImpactFinal* ur_impact_final_new(int rows) {
  urImpactFinal* f = calloc(1, sizeof *f);
  if (!f) return NULL;
  f->cap = rows;
  f->x = malloc((size_t)(rows + 1) * NF * sizeof(double));
  if (!f->x) {
    free(f);
    return NULL;
  }
  return f;
}

void ur_impact_final_free(urImpactFinal* f) {
  if (!f) return;
  free(f->x);
  free(f);
}

void ur_impact_final_start(urImpactFinal* f, double speed) {
  if (!f) return;
  f->n = f->j = 0;
  f->next = -INFINITY;
  f->lb = 0;
  for (int k = 0; k < NSIG; k++) f->pk[k] = 0;
  f->speed = speed;
}

/* one history row's signals (SAE signs as ur_impact_finish takes them) */
static void take_row(const urImpactSetup* s, urImpactFinal* f, const urData* d,
                     const urInjuryParams* ip) {
  const urModel* m = s->m;
  int i = f->n, stride = 1 + m->nsensordata;
  const double* row = d->hist + (size_t)i * stride;
  double* x = f->x + (size_t)i * NF;
  const double* a = row + 1 + m->sensor[s->s_head_acc].adr;
  const double* nk = row + 1 + m->sensor[s->s_neck].adr;
  x[F_A] = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / urGRAVITY;
  double fz = -nk[2], my = -nk[4];
  x[F_NIJ] = ur_nij_sample(fz, my - ip->nij_condyle_d * nk[0], ip);
  const int sens[2] = {s->s_chest, s->s_abd};
  const double d0[2] = {ip->vc_d0_thorax, ip->vc_d0_abdomen};
  for (int k = 0; k < 2; k++) {
    double vc = 0, dk = 0;
    if (sens[k] >= 0) {
      int col = 1 + m->sensor[sens[k]].adr;
      dk = -row[col];
      if (i > 0) {
        double dp = -row[col - stride], h = row[0] - row[-stride];
        vc = ip->vc_sf * (dk - dp) / h * dk / d0[k];
      }
    }
    x[F_VCT + k] = fmax(vc, 0);
    if (k == 0) x[F_D] = fmax(dk, 0);
  }
  x[F_INT] = i > 0 ? x[F_INT - NF] + 0.5 * (x[F_A] + x[F_A - NF]) * (row[0] - row[-stride]) : 0;
  for (int k = 0; k < NSIG; k++) f->pk[k] = fmax(f->pk[k], x[k]);

  /* the longest window of HIC15 ending at this row: a pair ur_hic scans */
  const double* t0 = d->hist;
  while (row[0] - t0[(size_t)f->j * stride] > fmin(FIN_HIC, ip->hic_window) + 1e-12) f->j++;
  double w = row[0] - t0[(size_t)f->j * stride];
  if (w > 0) {
    double mean = (x[F_INT] - f->x[(size_t)f->j * NF + F_INT]) / w;
    f->lb = fmax(f->lb, w * pow(mean, 2.5));
  }
  f->n++;
}

/* the PoF of criterion k at value v */
static double pof(int k, double v, const urInjuryParams* ip) {
  switch (k) {
  case F_A: return ur_pof_hic(v, ip);
  case F_NIJ: return ur_pof_nij(v, ip);
  case F_VCT: return ur_pof_vc(v, urTHORAX, ip);
  case F_VCA: return ur_pof_vc(v, urABDOMEN, ip);
  default: return ur_pof_defl(v, ip);
  }
}

int ur_impact_final(const urImpactSetup* s, urImpactFinal* f, const urData* d,
                    const urInjuryParams* ip) {
  const urModel* m = s->m;
  while (f->n < d->nhist && f->n < f->cap) take_row(s, f, d, ip);
  double span = fmax(FIN_HIC, ip->hic_window), lbwin = fmin(FIN_HIC, ip->hic_window);
  if (d->time < f->next || d->t_first < 0 || d->time - d->t_first < FIN_SPAN || f->n < 2) return 0;
  f->next = d->time + FIN_EVERY;

  /* the drone slowed */
  const double* v = d->qvel + m->body[s->drone].vadr;
  if (!(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= FIN_SPEED * f->speed)) return 0;

  /* each signal's largest value over the last FIN_SPAN: the level it may rise to */
  int stride = 1 + m->nsensordata, last = f->n - 1;
  const double* t = d->hist;
  double top[NSIG] = {0}, tn = t[(size_t)last * stride];
  for (int i = last; i >= 0 && tn - t[(size_t)i * stride] <= FIN_SPAN + 1e-12; i--) {
    for (int k = 0; k < NSIG; k++) top[k] = fmax(top[k], f->x[(size_t)i * NF + k]);
  }

  /* Nij, VC, Dmax: maxima of their signals (first: the HIC bound costs more) */
  for (int k = F_NIJ; k < NSIG; k++) {
    if (k == F_D && !ip->use_defl) continue;
    if ((k == F_VCT && s->s_chest < 0) || (k == F_VCA && s->s_abd < 0)) continue;
    double b = FIN_RISE * top[k];
    if (b > f->pk[k] && pof(k, b, ip) > pof(k, f->pk[k], ip) + FIN_PTOL) return 0;
  }
  /* HIC: a window reaching past now starts at a past row i within L of now; the acceleration
     after now at most a, its value is at most (I_now - I_i + a w2)^2.5 / (w1 + w2)^1.5 (w1 the
     past part, w2 the future's), which over w2 in [0, L - w1] is largest at an end: w2 = 0 (a
     window already passed) or L - w1 */
  double a = FIN_RISE * top[F_A], hic = 0, in = f->x[(size_t)last * NF + F_INT];
  for (int i = last; i >= 0 && tn - t[(size_t)i * stride] <= span + 1e-12; i--) {
    double w1 = tn - t[(size_t)i * stride], p = in - f->x[(size_t)i * NF + F_INT];
    if (w1 > 0 && w1 <= lbwin + 1e-12) f->lb = fmax(f->lb, w1 * pow(p / w1, 2.5));
    hic = fmax(hic, span * pow((p + a * (span - w1)) / span, 2.5));
  }
  return hic <= f->lb || pof(F_A, hic, ip) <= pof(F_A, f->lb, ip) + FIN_PTOL;
}
