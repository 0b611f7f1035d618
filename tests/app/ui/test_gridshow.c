/* test_gridshow.c: grid show prints the paper's layout: plain text without a terminal (no
 * escape sequences), ANSI colours by band on a terminal (a pseudo-terminal here) unless
 * NO_COLOR is set, the legend with the thresholds and the line with case, wind, face and Q (of
 * a difference grid ΔP and ΔQ);
 * and the colour roles: band thresholds, SGR sequences */
#define _XOPEN_SOURCE 700 /* posix_openpt, grantpt, unlockpt, ptsname */
#include <errno.h>
#include <fcntl.h>
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

typedef struct {
  uraCtx c;
  char* buf;
  size_t len;
  char path[64];
} fixture;

/* a grid in the paper's format, mirror-symmetric: Q = 0.0025 x 572 / 100 m^2 = 0.0143 */
static const char* small =
    "# case B; horizontal wind 2 m/s; face direction phi = 0 deg\n"
    "along,0.00,0.05,0.10\n"
    "0.10,0,2,0\n"
    "0.05,50,100,10\n"
    "0.00,100,95,0\n"
    "-0.05,0,4,0\n";

static int setup(void** state) {
  fixture* f = calloc(1, sizeof *f);
  ura_init(&f->c);
  f->c.out = open_memstream(&f->buf, &f->len);
  strcpy(f->path, "/tmp/test_gridshow.XXXXXX");
  int fd = mkstemp(f->path);
  assert_true(fd >= 0);
  assert_int_equal(write(fd, small, strlen(small)), (ssize_t)strlen(small));
  close(fd);
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fixture* f = *state;
  ura_last_free(&f->c);
  ura_models_free(&f->c);
  fclose(f->c.out);
  free(f->buf);
  unlink(f->path);
  free(f);
  return 0;
}

/* what grid show printed */
static const char* show(fixture* f) {
  fflush(f->c.out);
  rewind(f->c.out);
  assert_int_equal(ura_grid_show(&f->c), 0);
  fputc(0, f->c.out);
  fflush(f->c.out);
  return f->buf;
}

static int count_lines(const char* s) {
  int n = 0;
  for (; *s; s++) n += *s == '\n';
  return n;
}

static void no_grid(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_show(&f->c), -1);
  assert_non_null(strstr(f->c.err, "no grid yet"));
}

/* plain text: no escapes, the paper's half plane, rows descending, legend, Q line */
static void plain_layout(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, f->path), 0);
  const char* out = show(f);
  assert_null(strchr(out, '\033'));
  /* title lines (conditions, orientation, the half plane), the header, 4 rows, legend, Q */
  assert_int_equal(count_lines(out), 3 + 1 + 4 + 2);
  assert_non_null(strstr(out,
                         "rows: dpar m (+ ahead); columns: dperp m (+ left of course); the "
                         "paper's layout\n"));
  assert_non_null(strstr(out, " dpar   0.00  0.05  0.10\n"));
  assert_non_null(strstr(out,
                         "\n  0.10   0.0   2.0   0.0\n  0.05  50.0 100.0  10.0\n"
                         "  0.00 100.0  95.0   0.0\n -0.05   0.0   4.0   0.0\n"));
  assert_non_null(strstr(out, "dperp >= 0 shown (mirror-symmetric)"));
  assert_non_null(strstr(out,
                         "legend: none 0 / no contact; low 0-5 %; medium 5-30 %; "
                         "high 30-90 %; severe >=90 %\n"));
  assert_non_null(strstr(out,
                         "case B, wind 2 m/s, face 0 deg: Q = 0.0143 m^2 over the full "
                         "plane (4 x 5 cells of 0.05 m)"));
  assert_null(strstr(out, "partial"));
}

/* Table 6 of the paper: Q 0.8469 m^2, 29 rows, 16 columns */
static void paper_table6(void** state) {
  fixture* f = *state;
  /* part of the repository (sessions/paper/grids): a missing file fails, it is not skipped */
  assert_int_equal(ura_grid_load(&f->c, "sessions/paper/grids/table06_caseC_wind0.csv"), 0);
  const char* out = show(f);
  assert_null(strchr(out, '\033'));
  assert_int_equal(count_lines(out), 3 + 1 + 29 + 2);
  assert_non_null(strstr(out, "  0.65   0.0   0.0   0.0   0.0   0.0  12.7 100.0 100.0   0.0"));
  assert_non_null(strstr(out,
                         "case C, wind 0 m/s, face 0 deg, speed 40.6 m/s, angle 90 deg: "
                         "Q = 0.8469 m^2"));
}

/* an asymmetric grid prints the full plane; missing cells make it partial */
static void full_plane_partial(void** state) {
  fixture* f = *state;
  const char* text =
      "dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p\n"
      "0.05,-0.05,1,1,1,1,1,0.5\n0.05,0,1,1,1,1,1,0.9\n0.05,0.05,0,0,0,0,0,0\n"
      "0,-0.05,1,1,1,1,1,0.01\n0,0.05,1,1,1,1,1,0.3\n";
  FILE* o = fopen(f->path, "w");
  fputs(text, o);
  fclose(o);
  assert_int_equal(ura_grid_load(&f->c, f->path), 0);
  const char* out = show(f);
  assert_non_null(strstr(out, " dpar  -0.05  0.00  0.05\n"));
  assert_non_null(strstr(out, "  0.05  50.0  90.0   0.0\n"));
  assert_non_null(strstr(out, "  0.00   1.0     ?  30.0\n"));
  assert_null(strstr(out, "mirror-symmetric"));
  assert_non_null(strstr(out,
                         "Q >= 0.0043 m^2, partial grid (0 failed, 1 pending cells not "
                         "counted)"));
  assert_non_null(strstr(out, "; pending ?"));
  assert_non_null(strstr(out, "case ?, wind ? m/s, face ? deg"));
}

/* a pseudo-terminal as the output: colours unless NO_COLOR */
static const char* show_on_pty(fixture* f, char* got, size_t n) {
  int m = posix_openpt(O_RDWR | O_NOCTTY);
  assert_true(m >= 0);
  assert_int_equal(grantpt(m), 0);
  assert_int_equal(unlockpt(m), 0);
  int s = open(ptsname(m), O_RDWR | O_NOCTTY);
  assert_true(s >= 0);
  FILE* out = fdopen(s, "w");
  FILE* keep = f->c.out;
  f->c.out = out;
  assert_int_equal(ura_grid_show(&f->c), 0);
  fflush(out);
  f->c.out = keep;

  /* read what arrived (small: well inside the terminal's buffer) */
  size_t k = 0;
  fcntl(m, F_SETFL, O_NONBLOCK);
  for (int tries = 0; tries < 200 && k < n - 1; tries++) {
    ssize_t r = read(m, got + k, n - 1 - k);
    if (r > 0)
      k += (size_t)r;
    else if (r < 0 && errno == EAGAIN && k > 0 && tries > 20)
      break;
    else
      usleep(2000);
  }
  got[k] = 0;
  fclose(out);
  close(m);
  return got;
}

static void colour_on_terminal(void** state) {
  fixture* f = *state;
  static char got[65536];
  assert_int_equal(ura_grid_load(&f->c, f->path), 0);
  unsetenv("NO_COLOR");
  setenv("TERM", "xterm-256color", 1);
  show_on_pty(f, got, sizeof got);
  assert_non_null(strstr(got, "Q = 0.0143 m^2"));
  /* 100 % severe (red 160), 50 % high (orange 208), 10 % medium (226), 2 % low (230) */
  assert_non_null(strstr(got, "48;5;160m 100.0"));
  assert_non_null(strstr(got, "48;5;208m  50.0"));
  assert_non_null(strstr(got, "48;5;226m  10.0"));
  assert_non_null(strstr(got, "48;5;230m   2.0"));
  assert_non_null(strstr(got, "\033[0m"));

  /* 8 colours */
  setenv("TERM", "xterm", 1);
  unsetenv("COLORTERM");
  show_on_pty(f, got, sizeof got);
  assert_non_null(strstr(got, ";41m 100.0"));
  assert_null(strstr(got, "48;5;"));

  /* NO_COLOR: plain */
  setenv("NO_COLOR", "1", 1);
  show_on_pty(f, got, sizeof got);
  assert_non_null(strstr(got, "Q = 0.0143 m^2"));
  assert_null(strchr(got, '\033'));
  unsetenv("NO_COLOR");
}

/* band thresholds: 0 none, (0, 5) low, [5, 30) medium, [30, 90) high, [90, 100] severe */
static void bands(void** state) {
  struct {
    double p;
    uraRole r;
  } t[] = {
      {0, uraROLE_NONE},           {1e-6, uraROLE_LOW},          {0.0499, uraROLE_LOW},
      {5.0 / 100, uraROLE_MEDIUM}, {0.2999, uraROLE_MEDIUM},     {30.0 / 100, uraROLE_HIGH},
      {0.8999, uraROLE_HIGH},      {90.0 / 100, uraROLE_SEVERE}, {1, uraROLE_SEVERE},
      {NAN, uraROLE_NONE},
  };
  for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
    if (ura_band_role(t[k].p) != t[k].r) fail_msg("p %g: role %d", t[k].p, ura_band_role(t[k].p));
  }
  urCell c = {0};
  c.status = urCELL_FAILED;
  c.p = 1;
  assert_int_equal(ura_cell_role(&c), uraROLE_FAILED);
  c.status = urCELL_PENDING;
  assert_int_equal(ura_cell_role(&c), uraROLE_PENDING);
  c.status = urCELL_NOCONTACT;
  assert_int_equal(ura_cell_role(&c), uraROLE_NONE);
  c.status = urCELL_DONE;
  assert_int_equal(ura_cell_role(&c), uraROLE_SEVERE);
}

/* SGR sequences per scheme; MONO has attributes and no colours; PLAIN nothing */
static void sgr(void** state) {
  char b[64];
  assert_int_equal(
      ura_style_sgr(uraSCHEME_PLAIN, ura_style(uraSCHEME_PLAIN, uraROLE_SEVERE), b, sizeof b), 0);
  assert_string_equal(b, "");
  ura_style_sgr(uraSCHEME_XTERM, ura_style(uraSCHEME_XTERM, uraROLE_SEVERE), b, sizeof b);
  assert_string_equal(b, "\033[0;1;38;5;231;48;5;160m");
  ura_style_sgr(uraSCHEME_BASIC, ura_style(uraSCHEME_BASIC, uraROLE_MEDIUM), b, sizeof b);
  assert_string_equal(b, "\033[0;30;43m");
  ura_style_sgr(uraSCHEME_MONO, ura_style(uraSCHEME_MONO, uraROLE_SEVERE), b, sizeof b);
  assert_string_equal(b, "\033[0;1;7m");
  /* every band has a distinct monochrome glyph */
  for (int i = uraROLE_NONE; i <= uraROLE_PENDING; i++) {
    for (int j = i + 1; j <= uraROLE_PENDING; j++) {
      assert_true(ura_style(uraSCHEME_MONO, i)->glyph != ura_style(uraSCHEME_MONO, j)->glyph);
    }
  }
}

/* a difference grid (design compare) says ΔP = P_b - P_a and ΔQ = Q_b - Q_a, as "d" where the
   locale is not UTF-8; Q = 0.0025 x 572 / 100 m^2 of the small grid read as a difference */
static void difference(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, f->path), 0);
  f->c.last.diff = 1;
  setenv("LC_ALL", "C", 1);
  const char* out = show(f);
  assert_non_null(strstr(out, "dP = P_b - P_a in %: case B"));
  assert_non_null(strstr(out, ": dQ = Q_b - Q_a = 0.0143 m^2 over"));
  assert_null(strstr(out, ": Q = "));
  setenv("LC_ALL", "C.UTF-8", 1);
  out = show(f);
  assert_non_null(strstr(out, "\u0394P = P_b - P_a in %: case B"));
  assert_non_null(strstr(out, ": \u0394Q = Q_b - Q_a = 0.0143 m^2 over"));
  unsetenv("LC_ALL");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(no_grid, setup, teardown),
      cmocka_unit_test_setup_teardown(plain_layout, setup, teardown),
      cmocka_unit_test_setup_teardown(paper_table6, setup, teardown),
      cmocka_unit_test_setup_teardown(full_plane_partial, setup, teardown),
      cmocka_unit_test_setup_teardown(colour_on_terminal, setup, teardown),
      cmocka_unit_test_setup_teardown(difference, setup, teardown),
      cmocka_unit_test(bands),
      cmocka_unit_test(sgr),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
