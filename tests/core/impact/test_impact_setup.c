/* test_impact_setup.c: a stance taken from another model (ur_impact_prepare with donors) is
 * bitwise the stance settling gives: the whole rest state, the balanced neutral positions, the
 * set-up values and whole impacts (results and histories). Taken only when the person is the
 * same: any change of a person's body, joint, restraint, reference coordinate, ellipsoid, pair,
 * of the settling options, time or iterations, a person placed at other indices, a drone that
 * reaches down to the person's height or touches something else, or an airbag on the person
 * refuses the donor; changes of the drone alone do not. At the workbench (modelcache.c donors),
 * 'set bag_p0 1.1 atm' after case A, and case A -> B -> bag_p0, take the stance, and equal a
 * fresh process that settles; 'set neck_k_flex 170' and 'set spine_k 410' settle anew. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../test_ctx.h"
#include "../../../src/app/case/builtin.h"


/* short settlings for the core cases: what is compared does not depend on their length */
#define T_SETTLE 0.2
#define ITERS    1

/* ---- everything a set-up gives, as bytes ---- */

/* the rest state (every byte of its arrays and its run fields), every neutral position, the
   set-up values, and impacts at a few offsets: results and histories */
static void snapshot(const urImpactSetup* s, FILE* f) {
  const urModel* m = s->m;
  const urData* d = s->rest;
  fwrite(d->buffer, 1, (size_t)((const char*)(d->bag + m->nbag) - (const char*)d->buffer), f);
  double run[] = {d->time, d->t_jump, d->t_first, d->t_last, d->t_calm, d->energy};
  int runi[] = {d->status, d->proj, d->nhist, (int)d->nstep};
  fwrite(run, sizeof run, 1, f);
  fwrite(runi, sizeof runi, 1, f);
  for (int b = 0; b < m->nbody; b++) {
    for (int k = 0; k < 3; k++) fwrite(&m->body[b].rst[k].x0, sizeof(double), 1, f);
  }
  double v[] = {s->head_cg[0],   s->head_cg[1], s->head_cg[2], s->head_top,
                s->neck_preload, s->rmax,       s->window};
  fwrite(v, sizeof v, 1, f);
  fwrite(s->cand, sizeof *s->cand, s->ncand, f);

  static const double off[][2] = {{0, 0}, {0.2, 0.1}, {-0.1, -0.25}};
  urImpactCond cond = {7.48, 90, 0, 0, 0, 0};
  urInjuryParams ip;
  ur_injury_defaults(&ip);
  urImpactWork w;
  if (ur_impact_work_init(s, &w)) return;
  for (int i = 0; i < 3; i++) {
    urImpactResult r;
    ur_impact_run(s, &w, &cond, &ip, off[i][0], off[i][1], &r);
    fwrite(&r, sizeof r, 1, f);
    fwrite(w.d->hist, sizeof(double), (size_t)w.d->nhist * (1 + m->nsensordata), f);
  }
  ur_impact_work_free(&w);
}

/* the snapshot in memory; *n its size */
static char* snap(const urImpactSetup* s, size_t* n) {
  char* buf = NULL;
  FILE* f = open_memstream(&buf, n);
  assert_non_null(f);
  snapshot(s, f);
  fclose(f);
  return buf;
}

static void assert_same_setup(const urImpactSetup* a, const urImpactSetup* b) {
  size_t na, nb;
  char *x = snap(a, &na), *y = snap(b, &nb);
  assert_int_equal(na, nb);
  if (na < 20000) fail_msg("snapshot of %zu bytes only", na);
  for (size_t k = 0; k < na; k++) {
    if (x[k] != y[k]) fail_msg("set-ups differ at byte %zu of %zu", k, na);
  }
  free(x);
  free(y);
}

/* ---- core: models from the built-in parts and extra texts ---- */

static const char* builtin(const char* name) {
  const char* t = ura_builtin_text(name);
  if (!t) fail_msg("no built-in model %s", name);
  return t;
}

/* the sources in order: built-in part names, or model text (starting with '#') */
static urModel* parse(const char* const* parts, int n, const char* ovname, double ov) {
  urModelSource src[8];
  for (int i = 0; i < n; i++) {
    src[i].text = parts[i][0] == '#' ? parts[i] : builtin(parts[i]);
    src[i].file = parts[i][0] == '#' ? "test" : parts[i];
    src[i].line = 1;
  }
  /* the RA3's airbags analytic: the stance is the subject, whatever the bag, and a membrane bag
     (A's default at the switch) would inflate at every parse here, ~15 s CPU in all */
  int bags = 0;
  for (int i = 0; i < n; i++) bags |= !strcmp(parts[i], "airbags");
  urOverride o[2] = {{"bag_membrane", 0}, {ovname, ov}};
  char err[300];
  urModel* m = ur_model_parse(src, n, o + !bags, bags + (ovname != NULL), err, sizeof err);
  if (!m) fail_msg("%s", err);
  return m;
}

static const char* const BUILTIN[] = {"human", "ra3", "airbags", "sim"};

static urModel* base(void) {
  return parse(BUILTIN, 4, NULL, 0);
}

/* prepare m (owned by the set-up's caller) with at most one donor; returns s->shared */
static int prepare(urImpactSetup* s, urModel* m, const urImpactSetup* donor) {
  const urImpactSetup* donors[2] = {NULL, donor};
  int rc = ur_impact_prepare(s, m, T_SETTLE, ITERS, donors, 2);
  if (rc) fail_msg("prepare: %d %s", rc, s->err);
  return s->shared;
}

static void release(urImpactSetup* s) {
  urModel* m = (urModel*)s->m;
  ur_impact_free(s);
  ur_model_free(m);
}

/* the model of the parts with one override takes donor's stance, bitwise as settling it gives */
static void taken_as_settled(const char* const* parts, int n, const char* ov, double v,
                             const urImpactSetup* donor) {
  urImpactSetup s, fresh;
  assert_int_equal(prepare(&s, parse(parts, n, ov, v), donor), 1);
  assert_int_equal(prepare(&fresh, parse(parts, n, ov, v), NULL), 0);
  assert_same_setup(&s, &fresh);
  release(&fresh);
  release(&s);
}

/* a change of one model, made before preparing it */
typedef void (*mutation)(urModel* m);

static int person_pair(const urModel* m) {
  for (int i = 0; i < m->npair; i++) {
    if (m->pair[i].geom2 < 0) return i; /* the soles on the ground */
  }
  fail_msg("no ground pair");
  return -1;
}

static urBody* body(urModel* m, const char* name) {
  int b = ur_name_body(m, name);
  assert_true(b >= 0);
  return m->body + b;
}

static void m_mass(urModel* m) {
  body(m, "thorax")->mass *= 1 + 1e-12;
}
static void m_com(urModel* m) {
  body(m, "head")->com[0] += 1e-9;
}
static void m_stiff(urModel* m) {
  body(m, "neck")->rst[0].k += 1;
}
static void m_curve(urModel* m) {
  body(m, "oc")->rst[0].load.y[1] *= 1.01;
}
static void m_x0(urModel* m) {
  body(m, "thigh_l")->rst[0].x0 = 1e-3;
}
static void m_stop(urModel* m) {
  body(m, "forearm_r")->rst[0].kstop += 1;
}
static void m_gravity_flag(urModel* m) {
  body(m, "shank_l")->gravity = 0.5;
}
static void m_qpos0(urModel* m) {
  m->qpos0[body(m, "forearm_l")->qadr] = -0.01;
}
static void m_geom(urModel* m) {
  m->geom[ur_name_geom(m, "heel_l")].size[2] *= 1.001;
}
static void m_law(urModel* m) {
  m->pair[person_pair(m)].law.mu = 0.61;
}
static void m_gravity(urModel* m) {
  m->opt.gravity[2] = -9.80665;
}
static void m_vmax(urModel* m) {
  m->opt.vmax = 9e3;
}
static void m_integrator(urModel* m) {
  m->opt.integrator = urINT_RK4;
}
static void m_damping(urModel* m) {
  m->opt.implicit_damping = 0;
}
static void m_settle_dt(urModel* m) {
  ur_model_set_param(m, "settle_dt", 1e-4);
}
static void m_dt(urModel* m) {
  m->opt.dt = 3e-4;
} /* above settle_dt: its step */
static void m_bag_on_person(urModel* m) {
  m->bag[0].geom = ur_name_geom(m, "heel_l");
}
static void m_bag_on_drone(urModel* m) {
  m->bag[0].target[0] = ur_name_geom(m, "cargo");
}

static void m_arm_mass(urModel* m) {
  body(m, "arm1")->mass *= 1.1;
}
static void m_arm_stiff(urModel* m) {
  body(m, "arm3")->rst[1].k *= 2;
}
static void m_drone_law(urModel* m) {
  m->pair[m->npair - 1].law.mu = 0.9;
}
static void m_fine_dt(urModel* m) {
  m->opt.dt = 5e-5;
} /* below settle_dt: not its step */
static void m_tmax(urModel* m) {
  m->opt.tmax = 0.2;
}
static void m_bag_gas(urModel* m) {
  m->bag[0].gas.p0 *= 1.1;
}

static const struct {
  const char* what;
  mutation f;
  int shared;
} mutations[] = {
    {"person mass", m_mass, 0},
    {"person centre of mass", m_com, 0},
    {"person restraint stiffness", m_stiff, 0},
    {"person restraint curve", m_curve, 0},
    {"person neutral position before balancing", m_x0, 0},
    {"person end stop", m_stop, 0},
    {"person gravity flag", m_gravity_flag, 0},
    {"person reference coordinate", m_qpos0, 0},
    {"person ellipsoid", m_geom, 0},
    {"person ground pair law", m_law, 0},
    {"gravity", m_gravity, 0},
    {"vmax", m_vmax, 0},
    {"integrator", m_integrator, 0},
    {"implicit damping", m_damping, 0},
    {"settle_dt", m_settle_dt, 0},
    {"time step above settle_dt", m_dt, 0},
    {"airbag on the person", m_bag_on_person, 0},
    {"airbag target on the drone", m_bag_on_drone, 0},
    {"drone arm mass", m_arm_mass, 1},
    {"drone arm stiffness", m_arm_stiff, 1},
    {"drone-person pair law", m_drone_law, 1},
    {"time step below settle_dt", m_fine_dt, 1},
    {"maximum impact time", m_tmax, 1},
    {"airbag pressure", m_bag_gas, 1},
};

/* every change of the person refuses the donor; changes of the drone take it, and the result is
   bitwise that of settling the changed model */
static void donor_by_change(void** state) {
  urImpactSetup donor, s, fresh;
  assert_int_equal(prepare(&donor, base(), NULL), 0);
  for (size_t i = 0; i < sizeof mutations / sizeof *mutations; i++) {
    urModel* m = base();
    mutations[i].f(m);
    const urImpactSetup* donors[1] = {&donor};
    int rc = ur_impact_prepare(&s, m, T_SETTLE, ITERS, donors, 1);
    int shared = !rc && s.shared; /* settling may fail: the donor was not taken */
    if (shared != mutations[i].shared) {
      fail_msg("%s: shared %d (%d %s), expected %d", mutations[i].what, shared, rc, s.err,
               mutations[i].shared);
    }
    if (shared) {
      urModel* m2 = base();
      mutations[i].f(m2);
      assert_int_equal(prepare(&fresh, m2, NULL), 0);
      assert_same_setup(&s, &fresh);
      release(&fresh);
    }
    ur_impact_free(&s);
    ur_model_free(m);
  }
  release(&donor);
}

/* a taken stance can be given on; other settling times or iterations refuse it */
static void donor_chain(void** state) {
  urImpactSetup a, b, c;
  assert_int_equal(prepare(&a, base(), NULL), 0);
  assert_int_equal(prepare(&b, parse(BUILTIN, 4, "bag_p0", 1.1 * 101325), &a), 1);
  release(&a);
  taken_as_settled(BUILTIN, 4, "arm_t", 0.0015, &b);

  urImpactSetup* donors[1] = {&b};
  urModel* m = base();
  assert_int_equal(ur_impact_prepare(&c, m, T_SETTLE * 2, ITERS, (const urImpactSetup**)donors, 1),
                   0);
  assert_false(c.shared);
  release(&c);
  m = base();
  assert_int_equal(ur_impact_prepare(&c, m, T_SETTLE, ITERS + 1, (const urImpactSetup**)donors, 1),
                   0);
  assert_false(c.shared);
  release(&c);

  /* a set-up without a stance (ur_impact_setup) gives nothing */
  m = base();
  assert_int_equal(ur_impact_balance(m, T_SETTLE, ITERS, NULL), 0);
  assert_int_equal(ur_impact_setup(&a, m, T_SETTLE), 0);
  assert_null(a.stance);
  assert_int_equal(prepare(&c, base(), &a), 0);
  assert_same_setup(&a, &c); /* the same settling as ur_impact_prepare's */
  release(&a);
  release(&c);
  release(&b);
}

/* a small drone of its own part, placed before or after the person */
static const char DRONE[] =
    "# a drone of one body and one arm, whose root is not called main: its role says so\n"
    "body hub parent=world joint=free pos=0,0,0 mass=10 inertia=0.5,0.4,0.7\n"
    "body arm parent=hub joint=revolute pos=0.2,0,0 axis=0,1,0 mass=0.5 com=0.2,0,0 "
    "inertia=0.001,0.002,0.003\n"
    "restraint arm dof=0 k=$arm_k c=1\n"
    "role drone=hub\n"
    "ellipsoid frame body=hub pos=0,0,0 size=0.3,0.3,0.1\n"
    "ellipsoid arm_tube body=arm pos=0.2,0,0 size=0.2,0.03,0.03\n";
static const char DRONE_PARAM[] = "# the arm stiffness\nparam arm_k 840\n";
static const char DRONE_HUGE[] =
    "# a drone whose bounding sphere reaches down to the person\n"
    "ellipsoid far body=hub pos=0,0,0 size=9999,0.1,0.1\n";
static const char DRONE_SELF[] =
    "# a drone touching itself\n"
    "law self type=table load=tissue_load damping=10 mu=0 v_eps=0.01\n"
    "pairs self a=frame b=arm_tube law=self\n";

static const char DRONE_PAIR[] =
    "# the drone's frame against the person's head\n"
    "law hit type=table load=tissue_load damping=10 mu=0 v_eps=0.01\n"
    "pair hit a=head_cranium b=frame law=hit\n";
static const char HAT[] =
    "# a person ellipsoid above the head top that the drone can touch\n"
    "ellipsoid hat body=head pos=0,0,0.3 size=0.05,0.05,0.05\n"
    "pair hat_hit a=hat b=frame law=hit\n";
static const char DRONE_TALL[] =
    "# a drone that reaches the person from its parking place, through a pair\n"
    "ellipsoid pole body=hub pos=0,0,0 size=0.1,0.1,9999\n"
    "pair pole_hit a=head_cranium b=pole law=hit\n";

/* a drone that cannot touch the person is refused before anything settles; a person ellipsoid
   above the head top is reported with its height; a drone that reaches the person while parked
   is named, not blamed on the balance */
static void drone_person_checks(void** state) {
  char err[300];
  const char* const plain[] = {DRONE_PARAM, "human", DRONE, "sim"};
  urModel* m = parse(plain, 4, NULL, 0);
  assert_int_equal(ur_impact_check(m, err, sizeof err), -1);
  assert_non_null(strstr(err, "the model has no contact pair between the drone and the person"));
  ur_model_free(m);

  const char* const paired[] = {DRONE_PARAM, "human", DRONE, DRONE_PAIR, "sim"};
  urImpactSetup s;
  m = parse(paired, 5, NULL, 0);
  assert_int_equal(ur_impact_check(m, err, sizeof err), 0);
  prepare(&s, m, NULL);
  assert_true(s.overlap == 0 && s.overlap_geom == -1);
  release(&s);

  const char* const hat[] = {DRONE_PARAM, "human", DRONE, DRONE_PAIR, HAT, "sim"};
  m = parse(hat, 6, NULL, 0);
  prepare(&s, m, NULL);
  int g = ur_name_geom(m, "hat");
  assert_int_equal(s.overlap_geom, g);
  /* the hat's top, 0.35 m above the head body's origin, over the head top */
  double top = s.rest->xpos[3 * m->geom[g].body + 2] + 0.35;
  assert_true(fabs(s.overlap - (top - s.head_top)) < 0.01 && s.overlap > 0.1);
  release(&s);

  const char* const tall[] = {DRONE_PARAM, "human", DRONE, DRONE_PAIR, DRONE_TALL, "sim"};
  m = parse(tall, 6, NULL, 0);
  assert_int_equal(ur_impact_prepare(&s, m, T_SETTLE, ITERS, NULL, 0), -2);
  assert_non_null(strstr(s.err, "the drone is too large to wait clear of the person"));
  ur_impact_free(&s);
  ur_model_free(m);
}

/* the person at other indices (the drone's bodies first) refuses the donor, at the same indices
   it is taken, and equals settling */
static void layout(void** state) {
  const char* const after[] = {DRONE_PARAM, "human", DRONE, "sim"};
  const char* const before[] = {DRONE_PARAM, DRONE, "human", "sim"};
  urImpactSetup a, b, s;
  assert_int_equal(prepare(&a, parse(after, 4, NULL, 0), NULL), 0);
  assert_int_equal(prepare(&b, parse(before, 4, NULL, 0), &a), 0);
  taken_as_settled(after, 4, "arm_k", 500, &a);
  taken_as_settled(before, 4, "arm_k", 500, &b);
  assert_int_equal(prepare(&s, parse(after, 4, NULL, 0), &b), 0);
  release(&s);
  release(&a);
  release(&b);
}

/* a drone that reaches down to the person's height neither gives nor takes a stance; nor does
   one that touches itself */
static void apart(void** state) {
  const char* const plain[] = {DRONE_PARAM, "human", DRONE, "sim"};
  const char* const huge[] = {DRONE_PARAM, "human", DRONE, DRONE_HUGE, "sim"};
  const char* const self[] = {DRONE_PARAM, "human", DRONE, DRONE_SELF, "sim"};
  urImpactSetup a, h, s;
  assert_int_equal(prepare(&a, parse(plain, 4, NULL, 0), NULL), 0);
  assert_int_equal(prepare(&h, parse(huge, 5, NULL, 0), &a), 0);
  assert_int_equal(prepare(&s, parse(huge, 5, "arm_k", 500), &h), 0);
  release(&s);
  assert_int_equal(prepare(&s, parse(plain, 4, "arm_k", 500), &h), 0);
  release(&s);
  assert_int_equal(prepare(&s, parse(self, 5, NULL, 0), &a), 0);
  release(&s);
  assert_int_equal(prepare(&s, parse(plain, 4, "arm_k", 500), &a), 1);
  release(&s);
  release(&h);
  release(&a);
}

/* ---- the workbench: donors from the kept models, against a fresh process (the analytic bag,
   as in parse) ---- */

/* the snapshot of the lines' set-up, computed in a fresh process that settles */
static char* fresh_process(const char* lines, size_t* n) {
  int fd[2];
  assert_int_equal(pipe(fd), 0);
  fflush(NULL);
  pid_t pid = fork();
  assert_true(pid >= 0);
  if (pid == 0) {
    close(fd[0]);
    uraCtx* c = calloc(1, sizeof *c);
    ura_init(c);
    c->out = fopen("/dev/null", "w");
    const urImpactSetup* s = ura_run_line(c, lines) ? NULL : ura_setup(c);
    if (!s || s->shared) _exit(1);
    size_t len;
    char* buf = snap(s, &len);
    for (size_t k = 0; k < len;) {
      ssize_t w = write(fd[1], buf + k, len - k);
      if (w <= 0) _exit(1);
      k += (size_t)w;
    }
    _exit(0);
  }
  close(fd[1]);
  char* buf = NULL;
  FILE* f = open_memstream(&buf, n);
  char chunk[65536];
  ssize_t r;
  while ((r = read(fd[0], chunk, sizeof chunk)) > 0) fwrite(chunk, 1, (size_t)r, f);
  fclose(f);
  close(fd[0]);
  int status;
  assert_int_equal(waitpid(pid, &status, 0), pid);
  assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  return buf;
}

/* the live set-up of c after line: taken (shared 1) or settled (0), and bitwise the set-up a
   fresh process settles for fresh_lines */
static void live_equals_fresh(uraCtx* c, const char* line, int shared, const char* fresh_lines) {
  run_rc(c, line, 0);
  const urImpactSetup* s = ura_setup(c);
  assert_non_null(s);
  if (s->shared != shared) fail_msg("'%s': shared %d, expected %d", line, s->shared, shared);
  size_t na, nb;
  char* a = snap(s, &na);
  char* b = fresh_process(fresh_lines, &nb);
  assert_int_equal(na, nb);
  assert_memory_equal(a, b, na);
  free(a);
  free(b);
}

static void workbench_bag_p0(void** state) {
  uraCtx* c = *state;
  run_rc(c, "case A; set bag_model analytic; impact 0 0", 0);
  assert_false(c->setup.shared);
  live_equals_fresh(c, "set bag_p0 1.1 atm", 1,
                    "case A; set bag_model analytic; set bag_p0 1.1 atm");
  run_rc(c, "impact 0.2 0.1", 0);
}

static void workbench_cases(void** state) {
  uraCtx* c = *state;
  run_rc(c, "case A; set bag_model analytic; impact 0 0", 0);
  live_equals_fresh(c, "case B", 1, "case B");
  live_equals_fresh(c, "set bag_p0 1.1 atm", 1, "case B; set bag_p0 1.1 atm");
  live_equals_fresh(c, "case A2; set bag_model analytic", 1, "case A2; set bag_model analytic");
}

static void workbench_person(void** state) {
  uraCtx* c = *state;
  run_rc(c, "case A; set bag_model analytic; impact 0 0", 0);
  live_equals_fresh(c, "set neck_k_flex 170", 0,
                    "case A; set bag_model analytic; set neck_k_flex 170");
  live_equals_fresh(c, "set neck_k_flex 160; set spine_k 410", 0,
                    "case A; set bag_model analytic; set neck_k_flex 160; set spine_k 410");
  /* back to a person seen before: the kept model (modelcache.c), or its stance */
  run_rc(c, "set spine_k 400; set bag_p0 1.05 atm", 0);
  assert_true(ura_setup(c)->shared);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(donor_by_change),
      cmocka_unit_test(donor_chain),
      cmocka_unit_test(layout),
      cmocka_unit_test(apart),
      cmocka_unit_test(drone_person_checks),
      cmocka_unit_test_setup_teardown(workbench_bag_p0, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(workbench_cases, ctx_setup, ctx_teardown),
      cmocka_unit_test_setup_teardown(workbench_person, ctx_setup, ctx_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
