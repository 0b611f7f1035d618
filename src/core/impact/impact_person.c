/* impact_person.c: the person alone, for the settling of the stance. While the stance settles
 * the drone waits parked far above, held at rest (impact_setup.c): its bodies are stepped and
 * put back every step, and nothing passes between its tree and the person's. A model of the
 * person alone (every body off the drone's tree in the same order, their ellipsoids and the
 * pairs among them and with the ground, the same options) steps the person with the same
 * operations on the same numbers, so the settled person is the same to the bit, for about a
 * quarter less work a step (the drone's bodies, ellipsoids, pairs and airbags skipped). */
#include <stdlib.h>
#include <string.h>

#include "../engine/engine_internal.h"
#include "impact_internal.h"

/* a pair between two of the person's ellipsoids, or between one and the ground */
static int person_pair(const urModel* m, const urPair* p, int drone) {
  return !ur_geom_intree(m, p->geom1, drone) &&
         (p->geom2 < 0 || !ur_geom_intree(m, p->geom2, drone));
}

/* m's bodies, ellipsoids and pairs off the drone's tree added to p, each a copy of m's
   (indices mapped through bmap and gmap); 0, or -1 */
static int add_person(urModel* p, const urModel* m, int drone, int* bmap, int* gmap) {
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    bmap[b] = -1;
    if (ur_body_intree(m, b, drone)) continue;
    int parent = bd->parent < 0 ? -1 : bmap[bd->parent];
    int k = ur_model_add_body(p, bd->name, parent, bd->jtype, bd->pos, bd->quat);
    if (k < 0) return -1;
    p->body[k] = *bd; /* the compile derives the addresses, trees and inertias again */
    p->body[k].parent = parent;
    bmap[b] = k;
  }
  for (int g = 0; g < m->ngeom; g++) {
    const urGeom* ge = m->geom + g;
    gmap[g] = -1;
    if (bmap[ge->body] < 0) continue;
    int k = ur_model_add_ellipsoid(p, ge->name, bmap[ge->body], ge->pos, ge->quat, ge->size);
    if (k < 0) return -1;
    p->geom[k] = *ge;
    p->geom[k].body = bmap[ge->body];
    gmap[g] = k;
  }
  for (int i = 0; i < m->npair; i++) {
    const urPair* pr = m->pair + i;
    if (!person_pair(m, pr, drone)) continue;
    int g2 = pr->geom2 < 0 ? -1 : gmap[pr->geom2];
    int k = ur_model_add_pair(p, pr->name, gmap[pr->geom1], g2, &pr->law);
    if (k < 0) return -1;
    p->pair[k] = *pr;
    p->pair[k].geom1 = gmap[pr->geom1];
    p->pair[k].geom2 = g2;
  }
  return 0;
}

urModel* ur_impact_person_model(const urModel* m, int drone) {
  for (int i = 0; i < m->nbag; i++) {
    if (!ur_geom_intree(m, m->bag[i].geom, drone)) return NULL; /* an airbag on the person */
  }
  urModel* p = ur_model_new();
  int* bmap = malloc((size_t)(m->nbody + 1) * sizeof(int));
  int* gmap = malloc((size_t)(m->ngeom + 1) * sizeof(int));
  int rc = p && bmap && gmap ? add_person(p, m, drone, bmap, gmap) : -1;
  free(bmap);
  free(gmap);
  if (rc == 0) {
    p->opt = m->opt;
    p->opt.memcache = NULL;
    rc = ur_model_compile(p);
  }
  if (rc) {
    ur_model_free(p);
    return NULL;
  }
  return p;
}

void ur_impact_person_state(const urModel* m, urData* d, int drone, const urModel* p,
                            const urData* dp) {
  int k = 0;
  for (int b = 0; b < m->nbody; b++) {
    const urBody* bd = m->body + b;
    if (ur_body_intree(m, b, drone)) continue;
    const urBody* pb = p->body + k++;
    memcpy(d->qpos + bd->qadr, dp->qpos + pb->qadr, bd->nq * sizeof(double));
    memcpy(d->qvel + bd->vadr, dp->qvel + pb->vadr, bd->nv * sizeof(double));
    memcpy(d->rst + 2 * bd->vadr, dp->rst + 2 * pb->vadr, 2 * bd->nv * sizeof(double));
  }
  k = 0;
  for (int i = 0; i < m->npair; i++) {
    if (!person_pair(m, m->pair + i, drone)) continue;
    d->pair[i] = dp->pair[k];
    d->pdepth[i] = dp->pdepth[k];
    k++;
  }
  ur_contacts_relist(m, d);
}
