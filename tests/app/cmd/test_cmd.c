/* test_cmd.c: the command layer: table, set/show, cases, output formats, errors */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../../src/app/ui/ui.h"

/* run lines on a fresh context, capturing what they print */
typedef struct {
  uraCtx c;
  char* buf;
  size_t len;
} fixture;

static int setup(void** state) {
  fixture* f = calloc(1, sizeof *f);
  ura_init(&f->c);
  f->c.out = open_memstream(&f->buf, &f->len);
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fixture* f = *state;
  ura_models_free(&f->c);
  ura_last_free(&f->c);
  fclose(f->c.out);
  free(f->buf);
  free(f);
  return 0;
}

/* output of one line, from a clean buffer */
static const char* run(fixture* f, const char* line, int expect_rc) {
  fflush(f->c.out);
  rewind(f->c.out);
  f->buf[0] = 0;
  assert_int_equal(ura_run_line(&f->c, line), expect_rc);
  fputc(0, f->c.out);
  fflush(f->c.out);
  return f->buf;
}

static int count_lines(const char* s, const char* prefix) {
  int n = 0;
  for (const char* p = s; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
    if (!strncmp(p, prefix, strlen(prefix))) n++;
  }
  return n;
}

/* at the prompt each set says which models it changes (design.c); a script stays quiet */
static void set_says_reach(void** state) {
  fixture* f = *state;
  char* msg = NULL;
  size_t n = 0;
  FILE* old = f->c.msg;
  f->c.msg = open_memstream(&msg, &n);
  run(f, "set width 2", 0); /* not interactive: no note */
  fflush(f->c.msg);
  assert_int_equal(n, 0);
  f->c.interactive = 1;
  run(f, "set width 2", 0);
  run(f, "set mass 12", 0);
  run(f, "set arm_t 1.5 mm", 0);
  run(f, "set drone_size 1.1", 0);
  run(f, "set wind 3", 0); /* no note: obvious */
  fclose(f->c.msg);
  f->c.msg = old;
  assert_non_null(strstr(msg, "set width: changes the parametric model only"));
  assert_non_null(strstr(msg,
                         "set mass: changes the descent and parametric models and the "
                         "multibody drone"));
  assert_non_null(strstr(msg, "set arm_t: changes the multibody model (impact, grid)"));
  assert_non_null(strstr(msg, "set drone_size: changes the multibody drone's size"));
  assert_null(strstr(msg, "set wind"));
  free(msg);
  /* show marks what the multibody model does not use, and the drone's total */
  assert_non_null(strstr(run(f, "show width", 0), "(not used by the multibody model)"));
  assert_non_null(strstr(run(f, "show mass", 0), "(multibody drone: 12 kg)"));
  assert_null(strstr(run(f, "show step", 0), "multibody"));
}

static void set_and_show(void** state) {
  fixture* f = *state;
  run(f, "set wind 4", 0);
  assert_true(f->c.st.descent.wind == 4);
  const char* out = run(f, "show wind", 0);
  assert_non_null(strstr(out, "wind"));
  assert_non_null(strstr(out, "4 m/s"));
  out = run(f, "show speed", 0);
  assert_non_null(strstr(out, "derived"));
  run(f, "set speed 9", 0);
  out = run(f, "show speed", 0);
  assert_non_null(strstr(out, "9 m/s"));
  assert_null(strstr(out, "derived"));
  run(f, "set speed auto", 0);
  assert_int_equal(f->c.st.speed_set, 0);
}

/* a refused value names the parameter and the accepted range and changes nothing */
static void bad_values_leave_state(void** state) {
  fixture* f = *state;
  run(f, "set wind 3", 0);
  static const char* const bad[] = {"set wind abc",
                                    "set wind -1",
                                    "set wind nan",
                                    "set wind 1e400",
                                    "set wind 0x10",
                                    "set wind 3m",
                                    "set wind \"\"",
                                    "set winds 1,,2",
                                    "set format xml",
                                    "set nosuch 1",
                                    "set wind",
                                    "set wind 1 2",
                                    NULL};
  for (int i = 0; bad[i]; i++) {
    run(f, bad[i], -1);
    assert_true(f->c.st.descent.wind == 3);
    assert_true(strlen(f->c.err) > 10);
  }
  run(f, "set wind abc", -1);
  assert_non_null(strstr(f->c.err, "wind"));
  assert_non_null(strstr(f->c.err, "[0, 60]"));
  run(f, "bogus", -1);
  assert_non_null(strstr(f->c.err, "unknown command"));
}

/* case presets keep wind and face; C drops the parachute; reset restores everything */
static void cases(void** state) {
  fixture* f = *state;
  run(f, "set wind 6; set face 45; set rho 1.1", 0);
  run(f, "case C", 0);
  assert_string_equal(f->c.st.casename, "C");
  assert_true(f->c.st.descent.wind == 6 && f->c.st.face == 45);
  assert_true(f->c.st.descent.area_chute == 0);
  assert_true(f->c.st.descent.rho == 1.23);
  run(f, "case B", 0);
  assert_true(f->c.st.descent.area_chute == 2.72);
  run(f, "case Z", -1);
  assert_string_equal(f->c.st.casename, "B");
  run(f, "reset", 0);
  assert_string_equal(f->c.st.casename, "A");
  assert_true(f->c.st.descent.wind == 0);
}

/* set descent paper: derived speed and angle are the paper's Table 2 as printed at the live wind
   (case C's column for C, case B's for A, A1, A2, B); show says so; only the printed winds are
   accepted, with one error naming the wind and the accepted ones; set values still win; descent
   and parametric stay the model (with a note); the default is the model */
static void descent_paper(void** state) {
  fixture* f = *state;
  static const double w[6] = {0, 2, 4, 6, 8, 10};
  static const double b[6][2] = {{7.5, 90.0}, {7.8, 75.1},  {8.5, 62.0},
                                 {9.6, 51.5}, {11.0, 43.3}, {12.5, 37.0}};
  static const double cc[6][2] = {{40.6, 90.0}, {40.6, 89.0}, {40.6, 88.0},
                                  {40.5, 86.9}, {40.5, 85.8}, {40.4, 84.7}};
  static const char* const cases[] = {"A", "B", "C", "A1", "A2"};
  double sp, an;
  assert_int_equal(f->c.st.descent_src, uraDESC_MODEL);
  assert_int_equal(ura_impact_conditions(&f->c, &sp, &an), 0);
  assert_true(fabs(sp - 7.48) < 0.01 && sp != 7.5);
  const char* out = run(f, "show speed", 0);
  assert_non_null(strstr(out, "(derived: descent model at the live wind)"));

  run(f, "set descent paper", 0);
  assert_int_equal(f->c.st.descent_src, uraDESC_PAPER);
  for (int k = 0; k < 5; k++) {
    char line[64];
    snprintf(line, sizeof line, "case %s", cases[k]);
    run(f, line, 0);
    assert_int_equal(f->c.st.descent_src, uraDESC_PAPER);
    for (int i = 0; i < 6; i++) {
      const double* want = !strcmp(cases[k], "C") ? cc[i] : b[i];
      f->c.st.descent.wind = w[i];
      assert_int_equal(ura_impact_conditions(&f->c, &sp, &an), 0);
      assert_true(sp == want[0] && an == want[1]);
    }
  }
  out = run(f, "case C; set wind 10; show speed", 0);
  assert_non_null(strstr(out,
                         "speed            40.4 m/s  (derived: the paper's Table 2, case C's "
                         "column, at the live wind"));
  out = run(f, "case A1; show angle", 0);
  assert_non_null(strstr(out,
                         "angle            37 deg  (derived: the paper's Table 2, case B's "
                         "column"));

  /* an unprinted wind: refused where the speed is needed, one line */
  run(f, "set wind 3", 0);
  run(f, "show speed", -1);
  assert_non_null(strstr(f->c.err,
                         "wind 3 m/s is not printed in the paper's Table 2; accepted: "
                         "wind 0, 2, 4, 6, 8 or 10 m/s"));
  assert_null(strchr(f->c.err, '\n'));
  run(f, "grid", -1);
  assert_non_null(strstr(f->c.err, "wind 3 m/s is not printed"));
  run(f, "sweep wind 0,3", -1);
  assert_non_null(strstr(f->c.err, "sweep wind: descent paper: wind 3 m/s is not printed"));
  assert_null(f->c.last.g);
  /* set speed and angle need nothing derived */
  run(f, "set speed 9; set angle 60", 0);
  assert_int_equal(ura_impact_conditions(&f->c, &sp, &an), 0);
  assert_true(sp == 9 && an == 60);
  run(f, "set speed auto; set angle auto; set wind 4", 0);

  /* descent and parametric: the model, saying so */
  out = run(f, "set format csv; case B; set winds 10; descent", 0);
  assert_non_null(strstr(out,
                         "# the descent model (eq. 2.2); impacts and grids take the paper's "
                         "Table 2 instead"));
  assert_non_null(strstr(out, "B,10,12.488,36.80\n"));
  out = run(f, "parametric", 0);
  assert_non_null(strstr(out, "B,10,12.488,36.80,"));

  run(f, "set descent nosuch", -1);
  assert_non_null(
      strstr(f->c.err, "set descent: 'nosuch' is not accepted; accepted: model or paper"));
  assert_int_equal(f->c.st.descent_src, uraDESC_PAPER);
  run(f, "reset", 0);
  assert_int_equal(f->c.st.descent_src, uraDESC_MODEL);
}

/* set tau: rmax (default) or top, carried into the impact conditions; 'case' keeps it, reset
   restores rmax; a refused value changes nothing */
static void tau_setting(void** state) {
  fixture* f = *state;
  urImpactCond cond;
  assert_int_equal(f->c.st.tau, urTAU_RMAX);
  assert_int_equal(ura_impact_cond(&f->c, &cond), 0);
  assert_int_equal(cond.tau, urTAU_RMAX);
  const char* out = run(f, "set tau top; show tau", 0);
  assert_non_null(strstr(out, "tau              top\n"));
  assert_int_equal(ura_impact_cond(&f->c, &cond), 0);
  assert_int_equal(cond.tau, urTAU_TOP);
  run(f, "case C", 0);
  assert_int_equal(f->c.st.tau, urTAU_TOP);
  run(f, "set tau later", -1);
  assert_non_null(strstr(f->c.err, "set tau: 'later' is not accepted; accepted: rmax or top"));
  assert_int_equal(f->c.st.tau, urTAU_TOP);
  run(f, "reset", 0);
  assert_int_equal(f->c.st.tau, urTAU_RMAX);
}

/* CSV: exactly one header line with the contract's column names, one row per wind */
static void csv_headers(void** state) {
  fixture* f = *state;
  const char* out = run(f, "set format csv; case B; descent", 0);
  assert_int_equal(count_lines(out, "case,wind,speed,angle\n"), 1);
  assert_int_equal(count_lines(out, "B,"), 6);
  out = run(f, "parametric", 0);
  assert_int_equal(count_lines(out,
                               "case,wind,speed,angle,planform,mtow,gliding,pof_rcc,"
                               "pof_bc,pof_awke\n"),
                   1);
  assert_int_equal(count_lines(out, "B,"), 6);
  assert_non_null(strstr(out, "B,0,7.480,90.00,1.430,3.000,2.550,"));
  out = run(f, "set winds 10; descent", 0);
  assert_int_equal(count_lines(out, "B,10,"), 1);
}

/* aligned table: header and rows of equal width */
static void table_format(void** state) {
  fixture* f = *state;
  const char* out = run(f, "case B; descent", 0);
  const char* nl = strchr(out, '\n');
  assert_non_null(nl);
  size_t w = nl - out;
  assert_true(strlen(nl + 1) >= w);
  assert_int_equal(nl[1 + w], '\n');
}

/* ';' separates, '#' comments, quotes group, the first failure stops the line */
static void line_syntax(void** state) {
  fixture* f = *state;
  run(f, "set wind 2 ; set face 10 # set wind 9", 0);
  assert_true(f->c.st.descent.wind == 2 && f->c.st.face == 10);
  run(f, "   # only a comment", 0);
  run(f, "", 0);
  run(f, "set wind 5; bogus; set wind 7", -1);
  assert_true(f->c.st.descent.wind == 5);
  run(f, "set wind \"8\"", 0);
  assert_true(f->c.st.descent.wind == 8);
  run(f, "set wind \"8", -1);
}

/* help lists every command of the table; help COMMAND explains one */
static void help_from_table(void** state) {
  fixture* f = *state;
  const char* out = run(f, "help", 0);
  for (const uraCmd* k = ura_cmds; k->name; k++) assert_non_null(strstr(out, k->usage));
  out = run(f, "help descent", 0);
  assert_non_null(strstr(out, "usage: descent"));
  run(f, "help nosuch", -1);
}

/* every parameter can be shown, and set back to the value show printed */
static void show_set_roundtrip(void** state) {
  fixture* f = *state;
  for (const uraParam* p = ura_params; p->name; p++) {
    char val[1024], line[1200];
    if (p->kind == uraP_CASE) continue;
    ura_param_format(&f->c, p, val, sizeof val);
    snprintf(line, sizeof line, "set %s %s", p->name, val);
    run(f, line, 0);
  }
}

/* the model is compiled again only when its parameter overrides change (cases B and C have the
   same airbag settings); a refused value keeps the model as it was */
static void model_reuse(void** state) {
  fixture* f = *state;
  run(f, "case C", 0);
  const urModel* m = ura_model(&f->c);
  assert_non_null(m);
  run(f, "case B; set bag_p0 1 atm", 0);
  assert_ptr_equal(ura_model(&f->c), m);
  run(f, "set dt 0", -1);
  assert_ptr_equal(ura_model(&f->c), m);
  assert_true(f->c.model->param[ura_model_param_find(&f->c, "bag_p0")].value == 101325);
  run(f, "case A", 0);
  assert_ptr_not_equal(ura_model(&f->c), NULL);
  assert_true(f->c.model->param[ura_model_param_find(&f->c, "bag_bottom")].value == 1);
  run(f, "set bag_p0 1.1 atm", 0);
  assert_true(fabs(f->c.model->param[ura_model_param_find(&f->c, "bag_p0")].value - 111457.5) <
              1e-6);
}

/* dry mode (the fuzz harness): arguments are still checked, then simulations, grids, plots,
   the viewer and files are refused, and nothing is written */
/* an impact that fails (here: stopped by Ctrl-C at its first step) keeps the last impact: its
   contacts and histories are as they were (issue 24, item 4) */
static void failed_impact_keeps_last(void** state) {
  fixture* f = *state;
  run(f, "case C; impact 0.25 0.25", 0);
  char* contacts = strdup(run(f, "contacts", 0));
  char* history = strdup(run(f, "history", 0));
  assert_non_null(strstr(contacts, "impact at (0.25, 0.25) m"));

  *ura_interrupt_flag() = 1;
  char* argv[] = {"impact", "0", "0", NULL};
  assert_int_equal(ura_cmd_impact(&f->c, 3, argv), -1);
  ura_interrupt_clear();
  assert_non_null(strstr(f->c.err, "impact 0 0: interrupted (Ctrl-C); the last impact is kept"));
  assert_string_equal(run(f, "contacts", 0), contacts);
  assert_string_equal(run(f, "history", 0), history);
  uraTrace tr;
  assert_int_equal(ura_last_trace(&f->c, &tr), 0); /* plot history has it too */
  free(contacts);
  free(history);
}

static void dry_mode(void** state) {
  fixture* f = *state;
  f->c.dry = 1;
  run(f, "impact 0.1 zz", -1);
  assert_non_null(strstr(f->c.err, "DPERP 'zz' is not a number"));
  static const char* const refused[] = {"impact 0 0",
                                        "grid",
                                        "sweep wind 0,2",
                                        "compare",
                                        "source /dev/null",
                                        "model load /dev/null",
                                        "grid load /dev/null",
                                        "save session /tmp/dry.ses",
                                        "model save /tmp/dry.urm",
                                        "plot pof",
                                        NULL};
  for (int i = 0; refused[i]; i++) {
    run(f, refused[i], -1);
    assert_non_null(strstr(f->c.err, "not run (dry mode"));
  }
  assert_int_equal(access("/tmp/dry.ses", F_OK), -1);
  run(f, "sweep wind 0,-1", -1);
  assert_non_null(strstr(f->c.err, "value 2 of 2, -1, is out of range"));
  run(f, "set wind 3; descent; pof hic; model params", 0);
  assert_false(f->c.have_setup);
}

/* set terminal takes the rest of the line as gnuplot does, checked as one value; quoted forms
   (the old way) still work; other settings still take VALUE [UNIT] only */
static void set_terminal_rest(void** state) {
  fixture* f = *state;
  run(f, "set terminal png size 1000,700", 0);
  assert_string_equal(f->c.st.terminal, "png size 1000,700");
  run(f, "set terminal pngcairo font 'Arial Bold,10' size 800,600 mono", 0);
  assert_string_equal(f->c.st.terminal, "pngcairo font 'Arial Bold,10' size 800,600 mono");
  run(f, "set terminal svg background '#ffffff'", 0);
  assert_string_equal(f->c.st.terminal, "svg background rgb '#ffffff'");
  run(f, "set terminal \"dumb size 90,30\"", 0);
  assert_string_equal(f->c.st.terminal, "dumb size 90,30");
  run(f, "set terminal png", 0);
  assert_string_equal(f->c.st.terminal, "png");

  /* still checked: an option gnuplot would take that plot does not, a size without H */
  run(f, "set terminal png size 1000", -1);
  assert_non_null(strstr(f->c.err, "set terminal: option 'size': size needs W,H"));
  run(f, "set terminal png; set terminal png size 800,600 set output x", -1);
  assert_non_null(strstr(f->c.err, "option 'set': not an option plot accepts"));
  run(f, "set terminal png size 800,600; system 'ls'", -1);
  assert_string_equal(f->c.st.terminal, "png size 800,600");
  assert_non_null(strstr(f->c.err, "unknown command 'system'"));
  run(f, "set step 0.1 0.2 0.3", -1);
  assert_non_null(strstr(f->c.err, "set step: wrong number of arguments (4)"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(dry_mode, setup, teardown),
      cmocka_unit_test_setup_teardown(failed_impact_keeps_last, setup, teardown),
      cmocka_unit_test_setup_teardown(model_reuse, setup, teardown),
      cmocka_unit_test_setup_teardown(set_and_show, setup, teardown),
      cmocka_unit_test_setup_teardown(set_says_reach, setup, teardown),
      cmocka_unit_test_setup_teardown(bad_values_leave_state, setup, teardown),
      cmocka_unit_test_setup_teardown(cases, setup, teardown),
      cmocka_unit_test_setup_teardown(descent_paper, setup, teardown),
      cmocka_unit_test_setup_teardown(tau_setting, setup, teardown),
      cmocka_unit_test_setup_teardown(csv_headers, setup, teardown),
      cmocka_unit_test_setup_teardown(table_format, setup, teardown),
      cmocka_unit_test_setup_teardown(line_syntax, setup, teardown),
      cmocka_unit_test_setup_teardown(help_from_table, setup, teardown),
      cmocka_unit_test_setup_teardown(set_terminal_rest, setup, teardown),
      cmocka_unit_test_setup_teardown(show_set_roundtrip, setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
