/* engine_membrane_cull.h: the culling of the membrane's face contact (engine_membrane_cull.c),
 * shared by the loads stage (the boxes, once a step) and contact_geom (each target). */
#ifndef UASIMPACT_ENGINE_MEMBRANE_CULL_H
#define UASIMPACT_ENGINE_MEMBRANE_CULL_H

#include "uasimpact/membrane.h"

/* contact_geom's groups of culling boxes (engine_membrane_cull.c): boxes of grp consecutive boxes
   of urMEM_CBLK free nodes (n) and of free triangles' spheres (t, their largest radius at [6]),
   7 doubles each, nn and nt of them */
#define urmCULL_MAX 32
typedef struct {
  int grp, nn, nt;
  double n[7 * urmCULL_MAX], t[7 * urmCULL_MAX];
} urmCullGroups;
/* the boxes of urMEM_CBLK free nodes of positions x (nbx) and of free triangles' spheres (tb:
   centres and squared radii, the radii made here; tbx), the free nodes' box (lo, hi) and the
   groups sb, once a step */
void urm_cull_boxes(const urMembrane* mb, const double* x, double* tb, double* nbx, double* tbx,
                    double lo[3], double hi[3], urmCullGroups* sb);
/* the free triangles tfree[j0..j1) whose sphere (tb) reaches g's sphere (gc, rg) and box (gh):
   appended to tl (ntl there), the new count returned */
int urm_cull_tris(const urMembrane* mb, const double* tb, const double gc[3], double rg,
                  const double gh[3], int j0, int j1, double* tl, int ntl);

#endif
