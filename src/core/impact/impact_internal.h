/* impact_internal.h: the parts of one impact run (impact.c), shared with the runner of many
 * impacts in lock-step (impact_lanes.c). Not public API. */
#ifndef UASIMPACT_IMPACT_INTERNAL_H
#define UASIMPACT_IMPACT_INTERNAL_H

#include "uasimpact/impact.h"

/* ur_impact_run is: ur_impact_begin; while the status is ok: ur_step, ur_impact_after_step
   (-1: return -1; 1: stop); ur_impact_finish */
void ur_impact_begin(const urImpactSetup* s, urImpactWork* w, const urImpactCond* c, double dpar,
                     double dperp, urImpactResult* r, double* texit);
int ur_impact_after_step(const urImpactSetup* s, const urImpactWork* w, double texit,
                         urImpactResult* r);
int ur_impact_finish(const urImpactSetup* s, urImpactWork* w, const urInjuryParams* ip,
                     urImpactResult* r);

/* the person of m alone, for the settling (impact_person.c): every body off the drone's tree in
   m's order, their ellipsoids and the pairs among them and with the ground, m's options; NULL
   when an airbag rides on the person, or out of memory */
urModel* ur_impact_person_model(const urModel* m, int drone);
/* the person's coordinates, velocities, restraint extremes and pair histories (with depths) of
   p's data dp into m's data d, whose drone is left as it is; the contact lists rebuilt */
void ur_impact_person_state(const urModel* m, urData* d, int drone, const urModel* p,
                            const urData* dp);

#endif
