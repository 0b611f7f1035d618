/* engine_scale.c: a tree of bodies scaled as a design changes: its masses (inertias with them)
 * and its size (positions, shapes, airbag volumes; inertias as size squared) */
#include <math.h>
#include "engine_internal.h"

/* is body b in the tree rooted at root (before compilation: by the parent chain) */
static int below(const urModel* m, int b, int root) {
  for (; b >= 0; b = m->body[b].parent) {
    if (b == root) return 1;
  }
  return 0;
}

double ur_model_tree_mass(const urModel* m, int root) {
  double s = 0;
  for (int b = 0; b < m->nbody; b++) {
    if (below(m, b, root)) s += m->body[b].mass;
  }
  return s;
}

int ur_model_scale_tree(urModel* m, int root, double fmass, double fsize) {
  if (!m || m->compiled || root < 0 || root >= m->nbody || !(fmass > 0) || !(fsize > 0)) {
    return -1;
  }
  double fi = fmass * fsize * fsize;
  for (int b = 0; b < m->nbody; b++) {
    urBody* bd = m->body + b;
    if (!below(m, b, root)) continue;
    bd->mass *= fmass;
    for (int k = 0; k < 9; k++) bd->inertia[k] *= fi;
    for (int k = 0; k < 3; k++) {
      bd->com[k] *= fsize;
      if (b != root) bd->pos[k] *= fsize;
    }
  }
  for (int g = 0; g < m->ngeom; g++) {
    urGeom* ge = m->geom + g;
    if (!below(m, ge->body, root)) continue;
    for (int k = 0; k < 3; k++) {
      ge->pos[k] *= fsize;
      ge->size[k] *= fsize;
    }
    ge->rbound *= fsize;
  }
  for (int i = 0; i < m->nsensor; i++) {
    urSensor* se = m->sensor + i;
    int body = se->type == urSENS_ACCEL || se->type == urSENS_BODYPOS || se->type == urSENS_BODYVEL
                   ? se->obj
                   : -1;
    if (body >= 0 && below(m, body, root)) {
      for (int k = 0; k < 3; k++) se->pos[k] *= fsize;
    }
  }
  for (int i = 0; i < m->nbag; i++) {
    urAirbag* bag = m->bag + i;
    if (!below(m, m->geom[bag->geom].body, root)) continue;
    bag->gas.v0 *= fsize * fsize * fsize;
    if (isfinite(bag->thickness)) bag->thickness *= fsize;
    urMemSpec* ms = &bag->mspec;
    ms->a *= fsize;
    ms->b *= fsize;
    ms->depth *= fsize;
    ms->top *= fsize;
    for (int k = 0; k < 3; k++) ms->mount[k] *= fsize;
  }
  return 0;
}
