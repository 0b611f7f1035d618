/* cmd_aim.c: impact aim head UP SIDE: one impact placed by the point it would hit on the person
 * (the eccentricity of the drone's line of travel from the head's centre) instead of by an
 * offset Delta, at any angle 0-90 deg (0: flying horizontally into the person) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cmd.h"


#define AIM_MAX 2.0 /* m: largest |UP|, |SIDE| */

int ura_impact_aim(uraCtx* c, int argc, char** argv) {
  double up, side;
  if (argc != 5 || strcmp(argv[2], "head")) {
    return ura_fail(c,
                    "impact aim: usage: impact aim head UP SIDE (the eccentricity in m of "
                    "the drone's line of travel from the head's centre, up and to the drone's "
                    "left)");
  }
  if (ura_parse_number(argv[3], &up) || ura_parse_number(argv[4], &side)) {
    return ura_fail(c, "impact aim: '%s' is not a number; accepted: UP and SIDE in m",
                    ura_parse_number(argv[3], &up) ? argv[3] : argv[4]);
  }
  if (fabs(up) > AIM_MAX || fabs(side) > AIM_MAX) {
    return ura_fail(c, "impact aim: eccentricity out of range; accepted: |UP|, |SIDE| <= %g m",
                    AIM_MAX);
  }

  /* conditions at any angle (ura_impact_cond refuses the flights an offset cannot describe) */
  urImpactCond cond;
  memset(&cond, 0, sizeof cond);
  const urImpactSetup* s = ura_setup(c);
  if (!s || ura_impact_conditions(c, &cond.speed, &cond.angle)) return -1;
  /* a flight (below the angles of a descent) at the descent's derived speed would be a fall's
     speed flown level: the cruise speed must be declared */
  if (cond.angle < uraANGLE_DELTA && !c->st.speed_set) {
    return ura_fail(c,
                    "impact aim: a flight at angle %g deg needs a declared cruise speed; the "
                    "derived %.3g m/s is the descent's fall, not a cruise; accepted: 'set speed "
                    "V' (m/s, km/h or kt) or 'set velocity VH,VD' first",
                    cond.angle, cond.speed);
  }
  cond.face = c->st.face;
  cond.pitch = c->st.pitch;
  cond.roll = c->st.roll;
  cond.yaw = c->st.yaw;
  cond.tau = c->st.tau;
  cond.aim = 1;
  if (!c->have_work) {
    if (ur_impact_work_init(s, &c->work)) return ura_fail(c, "impact aim: out of memory");
    c->have_work = 1;
  }

  urImpactResult r;
  c->have_impact = 0;
  if (ur_impact_run(s, &c->work, &cond, &c->st.injury, up, side, &r)) {
    if (r.status == urSTAT_STOPPED) return ura_fail(c, "impact aim: interrupted (Ctrl-C)");
    return ura_fail(c, "impact aim head %g %g: the simulation failed: %s", up, side, r.reason);
  }
  ura_impact_keep(c, c->st.casename, c->st.descent.wind, &cond, up, side, &r);

  /* the row of 'impact', its offset columns holding the eccentricity */
  int compact = ura_impact_compact(c);
  uraTable* t = compact ? ura_impact_compact_table() : ura_impact_table(&c->st.injury);
  ura_table_note(t,
                 "case %s, speed %.4g m/s, angle %.4g deg, face %g deg; aim head: dpar, "
                 "dperp are the eccentricity (up, side) of the line of travel from the head's "
                 "centre; HIC15 window %.2f-%.2f ms",
                 c->st.casename, cond.speed, cond.angle, cond.face, 1e3 * r.inj.hic15.t1,
                 1e3 * r.inj.hic15.t2);
  if (r.nextrap) {
    ura_table_note(t, "extrapolated: %d law(s) used beyond their data; furthest: %s", r.nextrap,
                   r.extrap);
  }
  if (compact)
    ura_impact_compact_row(t, up, side, &r);
  else
    ura_impact_cells(t, &c->st.injury, up, side, &r);
  ura_table_print(c, t);
  return 0;
}
