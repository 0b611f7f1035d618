/* bag_summary.c: the airbags of the last impact as a few lines of text, for the viewer's cell
 * inspection (view.c) and whoever wants them at a glance: four lines per bag, its model
 * (membrane or analytic), the peak gauge pressure and its time, the volume lost at the smallest
 * volume, the peak fabric strain (membrane), the peak normal force on the person, and whether
 * the drone reached the person through the bag (bottoming: a part of the bag's carrier body
 * touched the person). A bag that never pressed on the person (no force) gets three: "no
 * contact with the person" in place of force and bottoming, which it cannot have. The values come from the bag's sensor (type=airbag) in the impact's
 * histories and from the impact's contact records, as 'history' and 'contacts' print them. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cmd.h"

/* the sensor that records bag ib (type=airbag), or -1 */
static int bag_sensor(const urModel* m, int ib) {
  for (int i = 0; i < m->nsensor; i++) {
    if (m->sensor[i].type == urSENS_AIRBAG && m->sensor[i].obj == ib) return i;
  }
  return -1;
}

/* the hardest contact of a part of body cb (the bag's carrier) with the person: its record
   index, or -1 when none touched */
static int through_bag(const urImpactSetup* s, const urContactRec* rec, int cb) {
  const urModel* m = s->m;
  int best = -1;
  for (int k = 0; k < s->ncand; k++) {
    if (rec[k].t_first < 0 || s->cand_src[k] >= m->npair) continue;
    if (m->geom[s->cand[k][0]].body != cb) continue;
    if (best < 0 || rec[k].fmax > rec[best].fmax) best = k;
  }
  return best;
}

/* the volume lost, L and % of v0, as a change: "-1.2 L (-3.4 %)", or "0.0 L (0.0 %)" when it
   rounds to nothing (never a negative zero) */
static void volume_text(double v0, double vmin, char* buf, size_t n) {
  double dl = 1e3 * (v0 - vmin), pct = v0 > 0 ? 100 * (v0 - vmin) / v0 : 0;
  if (dl < 0.05 && pct < 0.05)
    snprintf(buf, n, "0.0 L (0.0 %%)");
  else
    snprintf(buf, n, "-%.1f L (-%.1f %%)", fabs(dl), fabs(pct));
}

int ura_bag_summary(uraCtx* c, char (*lines)[160], int max) {
  if (!c->have_impact || !c->have_setup) return 0;
  const urImpactSetup* s = &c->setup;
  const urModel* m = s->m;
  const urData* d = c->work.d;
  int n = 0, stride = 1 + m->nsensordata;
  for (int ib = 0; ib < m->nbag && n + 4 <= max; ib++) {
    const urAirbag* b = m->bag + ib;
    int mem = b->type == urBAG_MEMBRANE && b->mem;
    int is = bag_sensor(m, ib);
    if (is < 0) {
      snprintf(lines[n++], 160, "%s (%s): no sensor type=airbag records it", b->name,
               mem ? "membrane" : "analytic");
      continue;
    }
    /* peaks over the samples: pressure, smallest volume, strain, force */
    int a = m->sensor[is].adr, ip = 0, iv = 0, is_ = 0, iff = 0; /* rows of the peaks */
    for (int r = 0; r < d->nhist; r++) {
      const double* row = d->hist + (size_t)r * stride + 1 + a;
      const double* bp = d->hist + (size_t)ip * stride + 1 + a;
      if (row[0] > bp[0]) ip = r;
      if (row[1] < d->hist[(size_t)iv * stride + 1 + a + 1]) iv = r;
      if (row[3] > d->hist[(size_t)is_ * stride + 1 + a + 3]) is_ = r;
      if (row[2] > d->hist[(size_t)iff * stride + 1 + a + 2]) iff = r;
    }
    if (d->nhist < 1) {
      snprintf(lines[n++], 160, "%s: no samples recorded", b->name);
      continue;
    }
    const double* h = d->hist;
    double patm = mem ? b->mem->spec.patm : b->gas.patm, v0 = h[1 + a + 1];
    double pk = h[(size_t)ip * stride + 1 + a], vmin = h[(size_t)iv * stride + 1 + a + 1];
    double st = h[(size_t)is_ * stride + 1 + a + 3], fk = h[(size_t)iff * stride + 1 + a + 2];
    snprintf(lines[n++], 160, "%s (%s): peak %.1f kPa gauge at %.1f ms", b->name,
             mem ? "membrane" : "analytic", 1e-3 * (pk - patm), 1e3 * h[(size_t)ip * stride]);
    char vol[64];
    volume_text(v0, vmin, vol, sizeof vol);
    if (mem) {
      snprintf(lines[n++], 160, "  volume %s, peak fabric strain %.1f %%", vol, 100 * st);
    } else {
      snprintf(lines[n++], 160, "  volume %s", vol);
    }
    /* a bag that never pressed on the person: no force, and nothing to bottom through */
    if (!(fk > 0)) {
      snprintf(lines[n++], 160, "  no contact with the person");
      continue;
    }
    snprintf(lines[n++], 160, "  peak force on the person %.3g kN at %.1f ms", 1e-3 * fk,
             1e3 * h[(size_t)iff * stride]);
    int k = through_bag(s, c->work.crec, m->geom[b->geom].body);
    if (k >= 0) {
      snprintf(lines[n++], 160, "  bottomed: %s on %s, %.3g kN at %.1f ms",
               m->geom[s->cand[k][0]].name, m->geom[s->cand[k][1]].name,
               1e-3 * c->work.crec[k].fmax, 1e3 * c->work.crec[k].t_fmax);
    } else {
      snprintf(lines[n++], 160, "  not bottomed: no part of %s touched the person",
               m->body[m->geom[b->geom].body].name);
    }
  }
  return n;
}
