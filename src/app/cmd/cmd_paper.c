/* cmd_paper.c: the parts of the paper that need no impact simulation: descent and parametric
 * (the paper's Table 2 itself, which 'set descent paper' takes, is case/paper.c) */
#include <stdio.h>
#include <string.h>

#include "cmd.h"

int ura_cmd_descent(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case", "wind", "speed", "angle"};
  uraTable* t = ura_table_new(4, cols);
  urDescentParams p = c->st.descent;
  char err[256];
  if (c->st.descent_src == uraDESC_PAPER) {
    ura_table_note(t,
                   "the descent model (eq. 2.2); impacts and grids take the paper's Table 2 "
                   "instead ('set descent paper')");
  }

  /* one descent per wind of the list */
  for (int i = 0; i < c->st.nwinds; i++) {
    urDescentResult r;
    p.wind = c->st.winds[i];
    if (ur_descent(&p, &r, err, sizeof err)) {
      ura_table_print(c, t);
      return ura_fail(c, "%s", err);
    }
    ura_table_cell(t, "%s", c->st.casename);
    ura_table_cell(t, "%g", p.wind);
    ura_table_cell(t, "%.3f", r.speed);
    ura_table_cell(t, "%.2f", r.angle);
  }
  ura_table_print(c, t);
  return 0;
}

int ura_cmd_parametric(uraCtx* c, int argc, char** argv) {
  static const char* const cols[] = {"case", "wind",    "speed",   "angle",  "planform",
                                     "mtow", "gliding", "pof_rcc", "pof_bc", "pof_awke"};
  uraTable* t = ura_table_new(10, cols);
  const urParametricParams* pp = &c->st.para;
  urDescentParams p = c->st.descent;
  char err[256];

  if (c->st.descent_src == uraDESC_PAPER) {
    ura_table_note(t,
                   "speed and angle from the descent model (eq. 2.2); impacts and grids take "
                   "the paper's Table 2 instead ('set descent paper')");
  }

  /* the choices the paper leaves open, stated with the numbers */
  ura_table_note(t,
                 "gliding area D.1 with W=%g m across, L=%g m along, H_P=%g m, 2R_P=%g m, "
                 "D_slide=%g m (D_slide from the paper's 2.55 m^2 at 90 deg)",
                 pp->width, pp->length, pp->person_height, pp->person_diameter, pp->slide);
  ura_table_note(t,
                 "pof_rcc: eq. D.3 head curve (a=74.8 J, b=0.2802); pof_bc: head, "
                 "D_imp=%g m (not in the paper), body mass %g kg; pof_awke: stand-in, "
                 "weighted mean of the three D.3 curves (the AWKE equation is not public)",
                 pp->bc_diameter, pp->body_mass);

  /* one row per wind of the list */
  for (int i = 0; i < c->st.nwinds; i++) {
    urDescentResult r;
    urParametricResult q;
    p.wind = c->st.winds[i];
    if (ur_descent(&p, &r, err, sizeof err)) {
      ura_table_print(c, t);
      return ura_fail(c, "%s", err);
    }
    ur_parametric(pp, p.mass, r.speed, r.angle, &q);
    ura_table_cell(t, "%s", c->st.casename);
    ura_table_cell(t, "%g", p.wind);
    ura_table_cell(t, "%.3f", r.speed);
    ura_table_cell(t, "%.2f", r.angle);
    ura_table_cell(t, "%.3f", q.planform);
    ura_table_cell(t, "%.3f", q.mtow_area);
    ura_table_cell(t, "%.3f", q.gliding);
    ura_table_cell(t, "%.4f", q.pof_rcc);
    ura_table_cell(t, "%.4f", q.pof_bc);
    ura_table_cell(t, "%.4f", q.pof_awke);
  }
  ura_table_print(c, t);
  return 0;
}
