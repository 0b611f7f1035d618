/* plot_bag.c: 'plot bag': the membrane airbags of the last impact as meshes (gnuplot splot,
 * triangles as wire frames, equal axes) at their first contact with the person and at their
 * peak pressure in contact, each with the head ellipsoid where it then was, one panel per
 * instant and bag. The snapshots are kept by the engine in each run's membrane state
 * (membrane.h, urMEMS_TFIRST...). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ui.h"

typedef struct {
  const urModel* m;
  const urData* d;
} bagargs;

/* the triangles of positions x as closed polylines (blank line between) */
static void mesh_block(FILE* f, const char* name, const urMembrane* mb, const double* x) {
  fprintf(f, "$%s << EOD\n", name);
  for (int t = 0; t < mb->nt; t++) {
    for (int k = 0; k <= 3; k++) {
      const double* p = x + 3 * mb->tri[3 * t + k % 3];
      fprintf(f, "%.6g %.6g %.6g\n", p[0], p[1], p[2]);
    }
    fprintf(f, "\n");
  }
  fprintf(f, "EOD\n");
}


/* the head ellipsoid (axes of its body at rest taken as the world's) as meridians and parallels */
static void head_block(FILE* f, const char* name, const double* r, const double c[3]) {
  fprintf(f, "$%s << EOD\n", name);
  for (int i = 0; i < 12; i++) {
    double u = 2 * M_PI * i / 12;
    for (int j = 0; j <= 12; j++) {
      double v = -M_PI / 2 + M_PI * j / 12;
      fprintf(f, "%.6g %.6g %.6g\n", c[0] + r[0] * cos(u) * cos(v), c[1] + r[1] * sin(u) * cos(v),
              c[2] + r[2] * sin(v));
    }
    fprintf(f, "\n");
  }
  for (int j = 1; j < 6; j++) {
    double v = -M_PI / 2 + M_PI * j / 6;
    for (int i = 0; i <= 24; i++) {
      double u = 2 * M_PI * i / 24;
      fprintf(f, "%.6g %.6g %.6g\n", c[0] + r[0] * cos(u) * cos(v), c[1] + r[1] * sin(u) * cos(v),
              c[2] + r[2] * sin(v));
    }
    fprintf(f, "\n");
  }
  fprintf(f, "EOD\n");
}


/* the x and y tic steps (about three intervals: the labels of a narrow panel do not run into
   each other) of a panel: the mesh x (nn nodes) and the head at hc, radius hr */
static void panel_tics(FILE* f, const double* x, int nn, const double* hc, const double* hr) {
  double lo[2] = {hc[0] - hr[0], hc[1] - hr[1]}, hi[2] = {hc[0] + hr[0], hc[1] + hr[1]};
  for (int i = 0; i < nn; i++) {
    for (int d = 0; d < 2; d++) {
      lo[d] = fmin(lo[d], x[3 * i + d]);
      hi[d] = fmax(hi[d], x[3 * i + d]);
    }
  }
  fprintf(f, "set xtics %g\nset ytics %g\n", ura_plot_tic_step(lo[0], hi[0], 3),
          ura_plot_tic_step(lo[1], hi[1], 3));
}

static int write_bag(uraCtx* c, FILE* f, const void* arg) {
  const bagargs* a = arg;
  const urModel* m = a->m;
  int np = 0, hg = m->roles.head;
  double hr[3] = {0.0875, 0.0875, 0.0875};
  if (hg >= 0) memcpy(hr, m->geom[hg].size, sizeof(hr));

  // the datablocks: per bag and instant a mesh and a head
  for (int ib = 0; ib < m->nbag; ib++) {
    const urAirbag* b = m->bag + ib;
    if (b->type != urBAG_MEMBRANE) continue;
    const urMembrane* mb = b->mem;
    const double* st = a->d->mem + b->madr;
    const double* sc = st + 18 * mb->nn;
    for (int k = 0; k < 2; k++) {
      if (sc[k ? urMEMS_TPEAK : urMEMS_TFIRST] < 0) continue;
      char name[16];
      snprintf(name, sizeof name, "M%d_%d", ib, k);
      mesh_block(f, name, mb, st + (k ? 15 : 12) * mb->nn);
      snprintf(name, sizeof name, "H%d_%d", ib, k);
      head_block(f, name, hr, sc + (k ? urMEMS_HPEAK : urMEMS_HFIRST));
      np++;
    }
  }
  if (np == 0) {
    return ura_fail(c,
                    "plot bag: no membrane airbag touched the person in the last impact "
                    "('set bag_model membrane', then 'impact')");
  }

  /* one panel per bag and instant, two to a row (a bag's first contact beside its peak), each
     row as tall as one bag's panels; the z label along its axis, left of its tic labels, and
     the x and y tic labels moved off the corners where the axes meet */
  int cols = np > 1 ? 2 : 1, rows = (np + cols - 1) / cols;
  ura_plot_canvas(c, 1600, rows > 1 ? 700 * rows : 760);
  fprintf(f,
          "set view equal xyz\nset xlabel 'x (m)' offset 0,-1.2\nset ylabel 'y (m)' offset 3,-1\n"
          "set zlabel 'z (m)' rotate parallel offset -1,0\nset xtics offset 0,-0.4\n"
          "set ytics offset 2,-0.3\nset ztics offset -0.4,0\nset lmargin 8\nset rmargin 6\n"
          "set view 70, 30\nset key top left\nset ticslevel 0\n");
  fprintf(f, "set multiplot layout %d,%d\n", rows, cols);
  for (int ib = 0; ib < m->nbag; ib++) {
    const urAirbag* b = m->bag + ib;
    if (b->type != urBAG_MEMBRANE) continue;
    const urMembrane* mb = b->mem;
    const double* st = a->d->mem + b->madr;
    const double* sc = st + 18 * mb->nn;
    for (int k = 0; k < 2; k++) {
      double t = sc[k ? urMEMS_TPEAK : urMEMS_TFIRST];
      if (t < 0) continue;
      panel_tics(f, st + (k ? 15 : 12) * mb->nn, mb->nn, sc + (k ? urMEMS_HPEAK : urMEMS_HFIRST),
                 hr);
      char title[160];
      if (k) {
        snprintf(title, sizeof title, "%s at peak pressure %.1f kPa (gauge), t = %.2f ms", b->name,
                 1e-3 * (sc[urMEMS_PPEAK] - mb->spec.patm), 1e3 * t);
      } else {
        snprintf(title, sizeof title, "%s at first contact, t = %.2f ms", b->name, 1e3 * t);
      }
      ura_plot_text(f, "title", title);
      fprintf(f,
              "splot $M%d_%d with lines lc rgb '#1f77b4' lw 0.6 title 'bag (%d nodes, %d "
              "triangles)', $H%d_%d with lines lc rgb '#d62728' lw 0.6 title 'head'\n",
              ib, k, mb->nn, mb->nt, ib, k);
    }
  }
  fprintf(f, "unset multiplot\n");
  return 0;
}


int ura_plot_bag(uraCtx* c) {
  if (!c->have_impact) return ura_fail(c, "plot bag: no impact yet; run 'impact DPAR DPERP'");
  bagargs a = {c->setup.m, c->work.d};
  int rc = ura_plot_script(c, "plot bag", write_bag, &a);
  ura_plot_canvas(c, 0, 0);
  return rc;
}
