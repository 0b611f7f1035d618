/* cmd_injury.c: the pof command: Appendix C probability-of-fatality curves as x,p */
#include <string.h>

#include "cmd.h"


const char* const ura_pof_names[] = {"hic", "nij", "vc", "vc_thorax", "vc_abdomen", "defl", NULL};
static const urPofKind pof_kinds[] = {urPOF_HIC,       urPOF_NIJ,        urPOF_VC,
                                      urPOF_VC_THORAX, urPOF_VC_ABDOMEN, urPOF_DEFL};

#define NPOINTS 101

int ura_cmd_pof(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"x", "p"};
  int k = -1;
  for (int i = 0; ura_pof_names[i]; i++) {
    if (!strcmp(argv[1], ura_pof_names[i])) k = i;
  }
  if (k < 0) {
    return ura_fail(c,
                    "pof: unknown curve '%s'; accepted: hic, nij, vc, vc_thorax, vc_abdomen or "
                    "defl",
                    argv[1]);
  }

  /* the curve from 0 to where it has reached its limit */
  double x[NPOINTS], p[NPOINTS];
  if (ur_pof_curve(pof_kinds[k], &c->st.injury, NPOINTS, x, p) != NPOINTS) {
    return ura_fail(c, "pof %s: the curve cannot be evaluated with these settings", argv[1]);
  }
  uraTable* t = ura_table_new(2, cols);
  static const char* const what[] = {
      "x = HIC15; p = AIS4+ Prasad-Mertz logistic (life-threatening = fatal)",
      "x = max Nij; p = composite (C.3) of the Eppinger AIS curves and Gennarelli-Wodzin",
      "x = VC (m/s) in thorax and abdomen; p = both regions fused",
      "x = thorax VC (m/s); p = P{F|AIS4+} x P(AIS4+|VC)",
      "x = abdomen VC (m/s); p = P{F|AIS5+} x P(AIS5+|VC)",
      "x = peak thorax deflection (m); p = P{F|AIS3+} x P(AIS3+|D), NHTSA (2008) curve"};
  ura_table_note(t, "%s", what[k]);
  for (int i = 0; i < NPOINTS; i++) {
    ura_table_cell(t, "%.6g", x[i]);
    ura_table_cell(t, "%.6f", p[i]);
  }
  ura_table_print(c, t);
  return 0;
}
