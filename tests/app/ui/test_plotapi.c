/* test_plotapi.c: the plot helpers other commands call (ura_plot_trace, ura_plot_xy), checked
 * on the script they send: a fake gnuplot first on PATH keeps its standard input */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../../src/app/ui/ui.h"

#define N 401

typedef struct {
  uraCtx c;
  char dir[64];
  char script[128];
  char* text; /* the script gnuplot received */
  double t[N], v[2 * N];
  uraTrace tr;
} fixture;

static const char* const names[] = {"head_acc", "neck_fz"};
static const char* const units[] = {"m/s^2", "N"};

static int setup(void** state) {
  fixture* f = calloc(1, sizeof *f);
  ura_init(&f->c);
  strcpy(f->dir, "/tmp/test_plotapi.XXXXXX");
  assert_non_null(mkdtemp(f->dir));

  /* the fake: keep the script, write a PNG (its signature and end chunk) to the file the
     script names (the temporary file beside out.png, renamed when it is complete) */
  char path[128];
  snprintf(path, sizeof path, "%s/gnuplot", f->dir);
  FILE* g = fopen(path, "w");
  fprintf(
      g,
      "#!/bin/sh\ncat >%s/script\n"
      "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" %s/script)\n"
      "[ -n \"$out\" ] && printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\0IEND\\256B`\\202' >\"$out\"\n"
      "exit 0\n",
      f->dir, f->dir);
  fclose(g);
  assert_int_equal(chmod(path, 0755), 0);
  char env[256];
  snprintf(env, sizeof env, "%s:/usr/bin:/bin", f->dir);
  setenv("PATH", env, 1);
  snprintf(f->script, sizeof f->script, "%s/script", f->dir);
  strcpy(f->c.st.terminal, "png");
  snprintf(f->c.st.output, sizeof f->c.st.output, "%s/out.png", f->dir);

  /* a 1500 m/s^2 half-sine from 5 to 15 ms, and a neck force */
  for (int i = 0; i < N; i++) {
    f->t[i] = i * 1e-4;
    double x = (f->t[i] - 0.005) / 0.010;
    f->v[i] = x > 0 && x < 1 ? 1500 * sin(M_PI * x) : 0;
    f->v[N + i] = -1000.0 * i / N;
  }
  f->tr = (uraTrace){N, 2, f->t, f->v, names, units};
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fixture* f = *state;
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", f->dir);
  assert_int_equal(system(cmd), 0);
  free(f->text);
  ura_models_free(&f->c);
  free(f);
  return 0;
}

/* the script the fake received */
static const char* sent(fixture* f) {
  free(f->text);
  FILE* s = fopen(f->script, "r");
  assert_non_null(s);
  f->text = calloc(1, 1 << 20);
  size_t n = fread(f->text, 1, (1 << 20) - 1, s);
  f->text[n] = 0;
  fclose(s);
  return f->text;
}

/* data lines of the datablock $NAME */
static int block_rows(const char* s, const char* name) {
  char head[64];
  snprintf(head, sizeof head, "$%s << EOD\n", name);
  const char* p = strstr(s, head);
  if (!p) return -1;
  p += strlen(head);
  int n = 0;
  while (*p && strncmp(p, "EOD\n", 4)) {
    n++;
    p = strchr(p, '\n') + 1;
  }
  return n;
}

/* every signal: ms, head_acc in g, the HIC15 window of the pulse shaded */
static void trace_all(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_plot_trace(&f->c, &f->tr, 0, NULL), 0);
  const char* s = sent(f);
  assert_int_equal(block_rows(s, "T"), N);
  assert_non_null(strstr(s, "\n10 152.957")); /* 10 ms, 1500 m/s^2 = 152.96 g */
  assert_non_null(strstr(s, "set multiplot layout 2,1"));
  assert_non_null(strstr(s, "set ylabel 'head_acc (g)'"));
  assert_non_null(strstr(s, "set ylabel 'neck_fz (N)'"));
  /* the HIC15 window of a 10 ms half-sine lies inside the pulse */
  const char* r = strstr(s, "set object 1 rect from ");
  assert_non_null(r);
  double t1, t2;
  assert_int_equal(sscanf(r, "set object 1 rect from %lf, graph 0 to %lf", &t1, &t2), 2);
  assert_true(t1 >= 5 && t2 <= 15 && t2 > t1 && t2 - t1 <= 15);
  assert_non_null(strstr(s, "plot $T using 1:2 with lines"));
  assert_non_null(strstr(s, "plot $T using 1:3 with lines"));
  /* a legend entry per signal and for the window; a canvas for two panels */
  assert_non_null(strstr(s, "title 'head CG acceleration, resultant'"));
  assert_non_null(strstr(s, "keyentry with boxes"));
  assert_non_null(strstr(s, "set terminal png size 800,540\n"));
}

/* the impact's conditions as the title, its line break kept */
static void trace_title(void** state) {
  fixture* f = *state;
  const char* h[] = {"head_acc"};
  f->tr.title = "case B, wind 0 m/s\nimpact at dpar 0.00 m";
  assert_int_equal(ura_plot_trace(&f->c, &f->tr, 1, h), 0);
  const char* s = sent(f);
  assert_non_null(
      strstr(s, "set title 'case B, wind 0 m/s'.\"\\n\".'impact at dpar 0.00 m' noenhanced"));
  assert_non_null(strstr(s, "set terminal png\n")); /* one panel: the default canvas */
  assert_int_equal(ura_plot_trace(&f->c, &f->tr, 0, NULL), 0);
  assert_non_null(strstr(sent(f), "set multiplot layout 2,1 title 'case B, wind 0 m/s'.\"\\n\".'"));
}

/* selected signals, a given window, an unknown name */
static void trace_select(void** state) {
  fixture* f = *state;
  const char* sel[] = {"neck_fz"};
  assert_int_equal(ura_plot_trace(&f->c, &f->tr, 1, sel), 0);
  const char* s = sent(f);
  assert_null(strstr(s, "multiplot"));
  assert_null(strstr(s, "head_acc"));
  assert_non_null(strstr(s, "\n10 -249.376")); /* row 100: -1000 x 100 / 401 */

  const char* h[] = {"head_acc"};
  assert_int_equal(ura_plot_trace_hic(&f->c, &f->tr, 1, h, 0.006, 0.0135), 0);
  assert_non_null(strstr(sent(f), "set object 1 rect from 6, graph 0 to 13.5, graph 1"));

  const char* bad[] = {"head_acc", "nosuch"};
  assert_int_equal(ura_plot_trace(&f->c, &f->tr, 2, bad), -1);
  assert_string_equal(f->c.err,
                      "plot history: no signal 'nosuch'; signals: head_acc, neck_fz (or all)");
  assert_int_equal(ura_plot_trace(&f->c, NULL, 0, NULL), -1);
  assert_string_equal(f->c.err, "plot history: no impact yet");
}

/* curves: one datablock each, titles quoted for gnuplot */
static void xy(void** state) {
  fixture* f = *state;
  double x[3] = {0, 2, 4}, y1[3] = {0.1, 0.2, NAN}, y2[3] = {1, 2, 3};
  uraSeries s[2] = {{"case \"B\"", x, y1, 3}, {NULL, x, y2, 3}};
  assert_int_equal(
      ura_plot_xy(&f->c, "plot sweep", "Q against wind", "wind (m/s)", "Q (m^2)", 2, s), 0);
  const char* t = sent(f);
  assert_int_equal(block_rows(t, "S0"), 3);
  assert_int_equal(block_rows(t, "S1"), 3);
  assert_non_null(strstr(t, "\n4 NaN\n"));
  assert_non_null(strstr(t, "title 'case \"B\"'"));
  assert_non_null(strstr(t, "notitle"));
  assert_non_null(strstr(t, "set xlabel 'wind (m/s)' noenhanced"));
  assert_int_equal(ura_plot_xy(&f->c, "plot sweep", NULL, NULL, NULL, 0, s), -1);
}

/* the same scripts through the real gnuplot (dumb terminal into a text file): valid syntax */
static char real_path[4096];

static void real_gnuplot(void** state) {
  fixture* f = *state;
  setenv("PATH", real_path, 1);
  if (system("command -v gnuplot >/dev/null 2>&1")) skip();
  char out[128], cmd[512];
  snprintf(out, sizeof out, "%s/plot.txt", f->dir);
  strcpy(f->c.st.terminal, "dumb size 100,40");
  snprintf(f->c.st.output, sizeof f->c.st.output, "%s", out);
  if (ura_plot_trace(&f->c, &f->tr, 0, NULL)) fail_msg("%s", f->c.err);
  snprintf(cmd, sizeof cmd, "grep -q 'HIC15 window' %s && grep -q 't (ms from tau)' %s", out, out);
  assert_int_equal(system(cmd), 0);
  double x[3] = {0, 2, 4}, y[3] = {0.1, 0.2, 0.4};
  uraSeries s[1] = {{"case \"B\"", x, y, 3}};
  if (ura_plot_xy(&f->c, "plot sweep", "Q against wind", "wind (m/s)", "Q (m^2)", 1, s)) {
    fail_msg("%s", f->c.err);
  }
  snprintf(cmd, sizeof cmd, "grep -q 'Q against wind' %s && grep -q 'case \"B\"' %s", out, out);
  assert_int_equal(system(cmd), 0);
}

int main(void) {
  const char* p = getenv("PATH");
  snprintf(real_path, sizeof real_path, "%s", p ? p : "/usr/bin:/bin");
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(trace_all, setup, teardown),
      cmocka_unit_test_setup_teardown(trace_select, setup, teardown),
      cmocka_unit_test_setup_teardown(trace_title, setup, teardown),
      cmocka_unit_test_setup_teardown(xy, setup, teardown),
      cmocka_unit_test_setup_teardown(real_gnuplot, setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
