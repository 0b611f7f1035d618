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
                         const urInjuryParams* ip, urImpactResult* r);
int ur_impact_finish(const urImpactSetup* s, urImpactWork* w, const urInjuryParams* ip,
                     urImpactResult* r);

/* the end of a run on final values (impact_final.c): the state of one work space's runs for
   rows history rows (NULL: no memory), started at each run with its impact speed; after a
   step, 1 when every criterion's value is final (the new history rows taken first) */
typedef struct urImpactFinal urImpactFinal;
urImpactFinal* ur_impact_final_new(int rows);
void ur_impact_final_free(urImpactFinal* f);
void ur_impact_final_start(urImpactFinal* f, double speed);
int ur_impact_final(const urImpactSetup* s, urImpactFinal* f, const urData* d,
                    const urInjuryParams* ip);

/* the person of m alone, for the settling (impact_person.c): every body off the drone's tree in
   m's order, their ellipsoids and the pairs among them and with the ground, m's options; NULL
   when an airbag rides on the person, or out of memory */
urModel* ur_impact_person_model(const urModel* m, int drone);
/* the person's coordinates, velocities, restraint extremes and pair histories (with depths) of
   p's data dp into m's data d, whose drone is left as it is; the contact lists rebuilt */
void ur_impact_person_state(const urModel* m, urData* d, int drone, const urModel* p,
                            const urData* dp);

#endif
