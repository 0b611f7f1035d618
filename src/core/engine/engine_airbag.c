/* engine_airbag.c: airbag elements behind one interface (ur_airbags). The uniform-pressure
 * analytic bag: each target ellipsoid indenting the bag ellipsoid removes kappa times its cap
 * volume from the gas; the pressure follows the closed adiabatic gas law (contact.h); each
 * target gets (P - Patm) times its section area along the normal (plus an optional fabric
 * penalty), the carrying body the reaction. Depth is capped at the bag thickness (bottoming:
 * the ordinary contacts of the body behind take over). */
#include <math.h>
#include <string.h>
#include "engine_internal.h"

//---------------------------------- uniform pressure ----------------------------------------------

static void bag_uniform(const urModel* m, urData* d, int ib) {
  const urAirbag* bag = m->bag + ib;
  urBagData* bd = d->bag + ib;
  const urGeom* gb = m->geom + bag->geom;
  urEllipsoid eb, et[urMAXBAGTGT];
  urGeomContact gc[urMAXBAGTGT];
  double dv = 0;
  bd->active = 0;
  bd->force = 0;
  ur_geom_ellipsoid(m, d, bag->geom, &eb);

  // depths and volume loss
  for (int t = 0; t < bag->ntarget; t++) {
    int g = bag->target[t];
    const double* cb = d->gxpos + 3 * bag->geom;
    const double* ct = d->gxpos + 3 * g;
    double dx[3] = {ct[0] - cb[0], ct[1] - cb[1], ct[2] - cb[2]};
    double gap = uru_norm3(dx) - gb->rbound - m->geom[g].rbound;
    bd->ftgt[t] = 0;
    bd->rate[t] = 0;
    if (gap > 0) {
      bd->depth[t] = -gap;
      continue;
    }
    double fb = ur_depth_cull(m, d, bag->geom, g, bd->u[t]);
    if (fb < 0) {
      bd->depth[t] = fb;
      continue;
    }
    ur_geom_ellipsoid(m, d, g, et + t);
    ur_collide_ellipsoids(&eb, et + t, bd->u[t], gc + t);
    bd->depth[t] = gc[t].g;
    if (gc[t].g > 0) {
      double mn[3] = {-gc[t].n[0], -gc[t].n[1], -gc[t].n[2]};
      dv += bag->kappa * ur_cap_volume(et + t, mn, fmin(gc[t].g, bag->thickness));
    }
  }

  // gas state (the volume may not vanish)
  if (dv > 0.999 * bag->gas.v0) {
    dv = 0.999 * bag->gas.v0;
  }
  bd->dv = dv;
  bd->volume = bag->gas.v0 - dv;
  bd->pressure = ur_gas_pressure(&bag->gas, dv);

  // forces on the targets, reaction on the bag body
  for (int t = 0; t < bag->ntarget; t++) {
    if (!(bd->depth[t] > 0)) {
      continue;
    }
    int g = bag->target[t];
    double mn[3] = {-gc[t].n[0], -gc[t].n[1], -gc[t].n[2]};
    double dep = fmin(gc[t].g, bag->thickness), v[3];
    ur_relvel(m, d, gb->body, m->geom[g].body, gc[t].p, v);
    bd->rate[t] = uru_dot3(v, gc[t].n);
    double f = (bd->pressure - bag->gas.patm) * ur_section_area(et + t, mn, dep) +
               bag->fabric_k * dep + bag->fabric_c * bd->rate[t];
    if (!(f > 0)) {
      continue;
    }
    bd->ftgt[t] = f;
    bd->force += f;
    bd->active = 1;
    ur_contact_apply(m, d, gb->body, m->geom[g].body, gc[t].n, gc[t].p, v, f, bd->rate[t], NULL,
                     bag->mu, bag->v_eps);
  }
}

//---------------------------------- dispatch ------------------------------------------------------

void ur_airbags(const urModel* m, urData* d) {
  for (int i = 0; i < m->nbag; i++) {
    switch (m->bag[i].type) {
    case urBAG_MEMBRANE: urm_bag_loads(m, d, i); break;
    case urBAG_UNIFORM:
    default: bag_uniform(m, d, i); break;
    }
  }
}
