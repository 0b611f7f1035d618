/* test_engine_membrane_live.c: when a membrane bag stops riding rigidly on its carrier
 * (engine_membrane.c, goes_live; the airbag's live=, the model parameter bag_live). Case A's
 * bottom bag, stepped impact by impact. With the tight rule (bag_live 1, the default): at no step
 * of a rigid ride is a node or an edge midpoint of the rigidly placed bag inside a target, nor has
 * the drone's tree touched anything; at the centre the bag rides rigidly for a while after the
 * jump, is live at its first contact force and at least 10 steps before it (the rule's 1 ms
 * lead: 20 steps at 7.48 m/s); where the drone's frame meets the person first, the bag is live
 * from the step its tree touches; never before the first rule would take it. With the first rule (bag_live 0) the bag goes live at the first
 * step after the jump and its counts are those measured on main before the change (a5010a2,
 * whose runs ended by the window and whose bags were inflated by kinetic damping, as here: 89
 * live steps before the first contact at the centre, 2490 steps). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "../../../src/core/engine/engine_internal.h"
#include "../../../src/core/impact/impact_internal.h"
#include "../../../src/core/membrane/membrane_internal.h"
#include "../../test_ctx.h"

typedef struct {
  long steps;      /* steps of the run after the jump */
  long before;     /* live steps before the bag's first contact force */
  long first_live; /* the step the bag went live (1: the first after the jump; 0: never) */
  long contact;    /* the step of its first contact force (0: none) */
  long touch;      /* the step its tree first touched anything (0: never) */
  long rigid_in;   /* rigid steps with a node or an edge midpoint inside a target */
} urLiveCount;

/* is some node or edge midpoint of the bag, placed rigidly on its carrier now, inside a target */
static int rigid_inside(const urModel* m, urData* d, const urAirbag* b) {
  const urMembrane* mb = b->mem;
  int cb = m->geom[b->geom].body;
  const double *R = d->xmat + 9 * cb, *c = d->xpos + 3 * cb;
  for (int t = 0; t < b->ntarget; t++) {
    urEllipsoid e;
    ur_geom_ellipsoid(m, d, b->target[t], &e);
    for (int i = 0; i < mb->nn + mb->ne; i++) {
      double p[3], x[3], n[3];
      if (i < mb->nn) {
        memcpy(p, mb->x0 + 3 * i, sizeof p);
      } else {
        const int* en = mb->enode + 2 * (i - mb->nn);
        for (int k = 0; k < 3; k++) p[k] = 0.5 * (mb->x0[3 * en[0] + k] + mb->x0[3 * en[1] + k]);
      }
      for (int k = 0; k < 3; k++)
        x[k] = c[k] + R[3 * k] * p[0] + R[3 * k + 1] * p[1] + R[3 * k + 2] * p[2];
      if (urm_contact_gap(&e, x, 1, n) > 0) return 1;
    }
  }
  return 0;
}

/* case A's impact at (dpar, dperp) under bag_live rule, stepped and counted */
static urLiveCount run(const char* rule, double dpar, double dperp) {
  void* st;
  assert_int_equal(ctx_setup(&st), 0);
  uraCtx* c = st;
  char line[120];
  snprintf(line, sizeof line,
           "case A; set wind 0; set endrun window; set bag_inflate 0; set bag_live %s", rule);
  run_rc(c, line, 0);
  const urImpactSetup* s = ura_setup(c);
  assert_non_null(s);
  const urModel* m = s->m;
  int ib = ur_name_airbag(m, "bag_bottom");
  assert_true(ib >= 0);
  const urAirbag* b = m->bag + ib;
  assert_int_equal(b->liverule, atoi(rule));
  urImpactCond cond;
  assert_int_equal(ura_impact_cond(c, &cond), 0);
  urImpactWork w;
  assert_int_equal(ur_impact_work_init(s, &w), 0);
  urImpactResult r;
  double texit;
  ur_impact_begin(s, &w, &cond, dpar, dperp, &r, &texit);
  urData* d = w.d;
  urLiveCount n = {0};
  while (d->status == urSTAT_OK) {
    // the state the step's loads see: was the bag, riding rigidly, inside a target
    ur_kinematics(m, d);
    int was_live = d->bag[ib].live, inside = !was_live && rigid_inside(m, d, b);
    ur_step(m, d);
    n.steps++;
    const urBagData* bd = d->bag + ib;
    if (!bd->live) {
      n.rigid_in += inside;
      assert_true(d->t_first < 0); /* the tree touched nothing */
    } else if (!n.first_live) {
      n.first_live = n.steps;
    }
    if (bd->active && !n.contact) n.contact = n.steps;
    if (bd->live && !n.contact) n.before++;
    if (d->t_first >= 0 && !n.touch) n.touch = n.steps;
    if (ur_impact_after_step(s, &w, texit, NULL, &r)) break;
  }
  print_message(
      "bag_live %s at (%g, %g): %ld steps, live from step %ld, first contact %ld, tree "
      "touched %ld, %ld live steps before contact, %ld rigid steps inside\n",
      rule, dpar, dperp, n.steps, n.first_live, n.contact, n.touch, n.before, n.rigid_in);
  ur_impact_work_free(&w);
  ctx_teardown(&st);
  return n;
}

/* the centre: rigid for a while, live at least 10 steps before the first contact; the first
   rule live at once, with main's counts */
static void test_centre(void** state) {
  (void)state;
  urLiveCount t = run("1", 0, 0), o = run("0", 0, 0);
  assert_int_equal(t.rigid_in, 0);
  assert_true(t.contact > 0 && t.first_live > 1);
  assert_true(t.first_live <= t.contact - 10);
  assert_true(t.before >= 10 && t.before < o.before);
  assert_true(t.first_live >= o.first_live);
  assert_int_equal(o.rigid_in, 0);
  assert_int_equal(o.first_live, 1);
  assert_int_equal(o.before, 89);
  assert_int_equal(o.steps, 2490);
}

/* the drone's frame first (at (0, -0.7) the bag never touches): the bag is live from the step
   its tree touches */
static void test_jolt(void** state) {
  (void)state;
  urLiveCount t = run("1", 0, -0.7);
  assert_int_equal(t.rigid_in, 0);
  assert_true(t.touch > 0);
  assert_true(t.contact == 0 || t.touch < t.contact);
  assert_true(t.first_live > 0 && t.first_live <= t.touch);
  /* never live before the first rule (a jolt far from the person leaves the bag rigid) */
  urLiveCount o = run("0", 0, -0.7);
  assert_true(t.first_live >= o.first_live);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_centre),
      cmocka_unit_test(test_jolt),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
