/* test_gridload.c: grid load: the paper's tables give the README's full-plane Q (mirror rule),
 * our own export loads back to the same grid, and malformed files give FILE:LINE errors that
 * leave the last grid as it was */
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

/* the paper's grids, part of the repository: a missing file fails the test, it is not skipped */
#define GRIDS "sessions/paper/grids"

/* a context whose output goes to a buffer, and a scratch directory */
typedef struct {
  uraCtx c;
  char* buf;
  size_t len;
  char dir[64];
  char path[128];
} fixture;

static int setup(void** state) {
  fixture* f = calloc(1, sizeof *f);
  ura_init(&f->c);
  f->c.out = open_memstream(&f->buf, &f->len);
  strcpy(f->dir, "/tmp/test_gridload.XXXXXX");
  assert_non_null(mkdtemp(f->dir));
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fixture* f = *state;
  ura_last_free(&f->c);
  ura_models_free(&f->c);
  fclose(f->c.out);
  free(f->buf);
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", f->dir);
  assert_int_equal(system(cmd), 0);
  free(f);
  return 0;
}

/* write text to a file of the scratch directory; returns its path */
static const char* put_file(fixture* f, const char* name, const char* text, size_t n) {
  snprintf(f->path, sizeof f->path, "%s/%s", f->dir, name);
  FILE* o = fopen(f->path, "wb");
  assert_non_null(o);
  assert_int_equal(fwrite(text, 1, n, o), n);
  fclose(o);
  return f->path;
}

static const char* put_text(fixture* f, const char* name, const char* text) {
  return put_file(f, name, text, strlen(text));
}

static urCell* at(urGrid* g, int i, int j) {
  return &g->cell[(size_t)i * g->ncol + j];
}

/* the cell at an offset, found by its stored offsets (not by index arithmetic) */
static urCell* find(urGrid* g, double dpar, double dperp) {
  for (int k = 0; k < g->nrow * g->ncol; k++) {
    if (fabs(g->cell[k].dpar - dpar) < 1e-9 && fabs(g->cell[k].dperp - dperp) < 1e-9) {
      return &g->cell[k];
    }
  }
  return NULL;
}

/* ---- the paper's tables ---- */

typedef struct {
  const char* file;
  const char* casename;
  double wind;
  int nrow, ncol; /* full plane */
  double q;       /* README Q_full, m^2 */
} table;

static const table tables[] = {
    {"table04_caseA_wind0.csv", "A", 0, 29, 31, 0.0581},
    {"table05_caseB_wind0.csv", "B", 0, 29, 31, 0.2861},
    {"table06_caseC_wind0.csv", "C", 0, 29, 31, 0.8469},
    {"table08_caseA_wind10.csv", "A", 10, 48, 33, 0.6766},
    {"table09_caseB_wind10.csv", "B", 10, 48, 33, 0.8582},
    {"table10_caseC_wind10.csv", "C", 10, 29, 31, 0.8588},
    {"table15_caseA1_wind10.csv", "A1", 10, 48, 33, 0.6378},
    {"table16_caseA2_wind10.csv", "A2", 10, 48, 33, 0.4515},
};

static void paper_tables(void** state) {
  fixture* f = *state;
  for (size_t k = 0; k < sizeof tables / sizeof tables[0]; k++) {
    const table* t = &tables[k];
    char path[256];
    snprintf(path, sizeof path, "%s/%s", GRIDS, t->file);
    if (ura_grid_load(&f->c, path)) fail_msg("%s: %s", path, f->c.err);
    urGrid* g = f->c.last.g;
    assert_non_null(g);

    /* Q over the full plane: column dperp = 0 once, the others twice */
    if (fabs(g->q - t->q) > 1e-4) fail_msg("%s: Q %.5f, README %.4f", t->file, g->q, t->q);
    assert_int_equal(g->nrow, t->nrow);
    assert_int_equal(g->ncol, t->ncol);
    assert_true(g->complete);
    assert_int_equal(g->nfailed + g->npending, 0);
    assert_string_equal(f->c.last.casename, t->casename);
    assert_true(f->c.last.wind == t->wind);
    assert_true(f->c.last.face == 0);
    assert_string_equal(f->c.last.source, path);
    assert_true(fabs(g->step - 0.05) < 1e-12);

    /* mirror symmetric, the negative side marked as mirrored, dperp = 0 in the middle */
    int mid = g->ncol / 2;
    for (int i = 0; i < g->nrow; i++) {
      assert_true(at(g, i, mid)->dperp == 0);
      assert_int_equal(at(g, i, mid)->mirrored, 0);
      for (int j = 1; j <= mid; j++) {
        assert_true(at(g, i, mid + j)->p == at(g, i, mid - j)->p);
        assert_true(fabs(at(g, i, mid - j)->dperp + at(g, i, mid + j)->dperp) < 1e-12);
        assert_int_equal(at(g, i, mid - j)->mirrored, 1);
        assert_int_equal(at(g, i, mid + j)->mirrored, 0);
      }
    }
  }
}

/* single cells of Table 6 read where the paper prints them */
static void paper_cells(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, GRIDS "/table06_caseC_wind0.csv"), 0);
  urGrid* g = f->c.last.g;
  assert_true(fabs(g->par_max - 0.70) < 1e-12);
  assert_true(fabs(g->perp_min + 0.75) < 1e-12);
  urCell* a = find(g, 0.65, 0.25);
  urCell* b = find(g, 0.65, -0.25);
  urCell* z = find(g, 0.70, 0.0);
  urCell* w = find(g, -0.10, 0.40);
  assert_non_null(a);
  assert_non_null(b);
  assert_non_null(z);
  assert_non_null(w);
  assert_true(fabs(a->p - 0.127) < 1e-12);
  assert_true(fabs(b->p - 0.127) < 1e-12);
  assert_int_equal(a->status, urCELL_DONE);
  assert_int_equal(a->contact, 1);
  assert_true(fabs(w->p - 0.812) < 1e-12);
  assert_int_equal(z->status, urCELL_NOCONTACT);
  assert_int_equal(z->contact, 0);
  assert_true(z->p == 0);
  assert_true(isnan(a->val[urVAL_HIC15])); /* the paper gives no criteria */
  assert_string_equal(f->c.last.casename, "C");
  assert_true(fabs(f->c.last.speed - 40.6) < 1e-12);
  assert_true(fabs(f->c.last.angle - 90) < 1e-12);
}

/* ---- a small table of our own, independent of the paper's files ---- */

static const char* small =
    "# case B; horizontal wind 2 m/s\n"
    "along,0.00,0.05,0.10\n"
    "0.10,0,2,0\n"
    "0.05,50,100,10\n"
    "0.00,100,95,0\n"
    "-0.05,0,4,0\n";

static void small_table(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, put_text(f, "small.csv", small)), 0);
  urGrid* g = f->c.last.g;
  assert_int_equal(g->nrow, 4);
  assert_int_equal(g->ncol, 5);
  /* 0.0025 m^2 x [(0+50+100+0) + 2 (2+100+95+4+0+10+0+0)] / 100 */
  assert_true(fabs(g->q - 0.0025 * 572 / 100) < 1e-12);
  assert_string_equal(f->c.last.casename, "B");
  assert_true(f->c.last.wind == 2);
  assert_true(isnan(f->c.last.face));
  assert_true(fabs(find(g, 0.05, -0.10)->p - 0.10) < 1e-12);
  assert_true(fabs(find(g, -0.05, 0.05)->p - 0.04) < 1e-12);
}

/* no comments: case ? and unknown wind */
static void no_comments(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, put_text(f, "n.csv",
                                                 "along,0.00,0.05\n0.05,1,2\n"
                                                 "0.00,3,4\n")),
                   0);
  assert_string_equal(f->c.last.casename, "?");
  assert_true(isnan(f->c.last.wind));
  assert_true(fabs(f->c.last.g->q - 0.0025 * (1 + 3 + 2 * (2 + 4)) / 100) < 1e-12);
}

/* ---- malformed files: FILE:LINE: message, last grid unchanged ---- */

typedef struct {
  const char* name;
  const char* text;
  size_t n; /* 0: strlen */
  int line;
  const char* says;
} badfile;

#define NUL_TEXT "along,0.00,0.05\n0.05,1,\0002\n"

static const badfile bads[] = {
    {"badnum.csv", "# c\nalong,0.00,0.05\n0.05,1,abc\n0.00,1,2\n", 0, 3, "'abc' is not a number"},
    {"hexnum.csv", "along,0.00,0.05\n0.05,1,0x10\n", 0, 2, "is not a number"},
    {"nan.csv", "along,0.00,0.05\n0.05,1,nan\n", 0, 2, "is not a number"},
    {"ragged.csv", "along,0.00,0.05\n0.05,1,2\n0.00,1\n", 0, 3, "row has 1 values"},
    {"long.csv", "along,0.00,0.05\n0.05,1,2,3\n", 0, 2, "row has 3 values"},
    {"nohead.csv", "# a comment\n0.05,1,2\n0.00,1,2\n", 0, 2, "missing header"},
    {"empty.csv", "", 0, 1, "empty file"},
    {"comments.csv", "# only\n# comments\n", 0, 2, "no data"},
    {"norows.csv", "along,0.00,0.05\n", 0, 1, "no data rows"},
    {"range.csv", "along,0.00,0.05\n0.05,1,101\n", 0, 2, "outside [0, 100]"},
    {"negative.csv", "along,0.00,0.05\n0.05,-1,1\n", 0, 2, "outside [0, 100]"},
    {"order.csv", "along,0.00,0.05\n0.05,1,2\n0.10,1,2\n", 0, 3, "breaks the descending"},
    {"gap.csv", "along,0.00,0.05\n0.10,1,2\n0.00,1,2\n", 0, 3, "breaks the descending"},
    {"header0.csv", "along,0.05,0.10\n0.05,1,2\n", 0, 1, "expected 0"},
    {"header.csv", "along,0.00,0.05,0.12\n0.05,1,2,3\n", 0, 1, "off the 0.05 m step"},
    {"headnum.csv", "along,0.00,x\n0.05,1,2\n", 0, 1, "cross offset 'x'"},
    {"nul.csv", NUL_TEXT, sizeof NUL_TEXT - 1, 2, "NUL byte"},
    {"x_req.csv", "dpar,dperp,contact\n0,0,1\n", 0, 1, "dpar, dperp and p are required"},
    {"x_p.csv", "dpar,dperp,p\n0,0,1.5\n0,0.05,0\n", 0, 2, "outside [0, 1]"},
    {"x_dup.csv", "dpar,dperp,p\n0,0,0.5\n0,0.05,0\n0,0,0.1\n", 0, 4,
     "given twice (first at line 2)"},
    {"x_off.csv", "dpar,dperp,p\n0,0,0.5\n0,0.05,0\n0,-0.05,0\n0,0.07,0\n", 0, 5,
     "off the 0.05 m lattice"},
    {"x_contact.csv", "dpar,dperp,contact,p\n0,0,0,0.5\n0,0.05,0,0\n", 0, 2, "without contact"},
    {"x_ragged.csv", "dpar,dperp,p\n0,0,0.5\n0,0.05\n", 0, 3, "row has 2 fields"},
};

static void malformed(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, put_text(f, "good.csv", small)), 0);
  urGrid* keep = f->c.last.g;
  double q = keep->q;
  char src[512];
  snprintf(src, sizeof src, "%s", f->c.last.source);

  for (size_t k = 0; k < sizeof bads / sizeof bads[0]; k++) {
    const badfile* b = &bads[k];
    const char* path = put_file(f, b->name, b->text, b->n ? b->n : strlen(b->text));
    char want[256];
    snprintf(want, sizeof want, "%s:%d: ", path, b->line);
    f->c.err[0] = 0;
    if (ura_grid_load(&f->c, path) != -1) fail_msg("%s: loaded", b->name);
    if (strncmp(f->c.err, want, strlen(want)) || !strstr(f->c.err, b->says)) {
      fail_msg("%s: message '%s', expected '%s... %s'", b->name, f->c.err, want, b->says);
    }
    assert_int_equal(f->c.err_located, 0); /* a script's FILE:LINE comes first */
    assert_null(strchr(f->c.err, '\n'));
    /* the last grid is the one loaded before */
    assert_ptr_equal(f->c.last.g, keep);
    assert_true(f->c.last.g->q == q);
    assert_string_equal(f->c.last.source, src);
    assert_string_equal(f->c.last.casename, "B");
  }

  /* a file that cannot be opened: named, not located */
  assert_int_equal(ura_grid_load(&f->c, "/nonexistent/x.csv"), -1);
  assert_non_null(strstr(f->c.err, "cannot open '/nonexistent/x.csv'"));
  assert_ptr_equal(f->c.last.g, keep);
}

/* ---- our export format ---- */

static void export_format(void** state) {
  fixture* f = *state;
  const char* text =
      "# grid of case C, wind 4 m/s, face 30 deg (computed); status: complete\n"
      "dpar,dperp,contact,hic15,nij,vc_thorax,vc_abdomen,p\n"
      "0.050,-0.050,0,0,0,0,0,0\n"
      "0.050,0.000,1,1200.5,0.8,0.1,0.2,0.75\n"
      "0.050,0.050,1,10,0.1,0,0,0\n"
      "0.000,-0.050,1,nan,nan,nan,nan,0.25\n"
      "0.000,0.050,1,5,0.1,0,0,0.125\n"
      "-0.050,0.000,1,5,0.1,0,0,1\n";
  assert_int_equal(ura_grid_load(&f->c, put_text(f, "export.csv", text)), 0);
  urGrid* g = f->c.last.g;
  assert_int_equal(g->nrow, 3);
  assert_int_equal(g->ncol, 3);
  assert_true(fabs(g->par_max - 0.05) < 1e-12);
  assert_true(fabs(g->perp_min + 0.05) < 1e-12);
  assert_string_equal(f->c.last.casename, "C");
  assert_true(f->c.last.wind == 4);
  assert_true(f->c.last.face == 30);

  /* cells where the rows put them; contact 0 is no contact, contact with p 0 is done */
  urCell* a = find(g, 0.05, 0);
  assert_int_equal(a->status, urCELL_DONE);
  assert_true(a->val[urVAL_HIC15] == 1200.5 && a->val[urVAL_NIJ] == 0.8 &&
              a->val[urVAL_VC_ABDOMEN] == 0.2 && a->p == 0.75);
  assert_int_equal(find(g, 0.05, -0.05)->status, urCELL_NOCONTACT);
  assert_int_equal(find(g, 0.05, 0.05)->status, urCELL_DONE);
  assert_int_equal(find(g, 0.05, 0.05)->contact, 1);
  assert_true(isnan(find(g, 0, -0.05)->val[urVAL_HIC15]));

  /* three cells are not in the file: pending, so the grid is partial */
  assert_int_equal(g->npending, 3);
  assert_false(g->complete);
  assert_true(fabs(g->q - 0.0025 * (0.75 + 0.25 + 0.125 + 1)) < 1e-12);
}

/* the table grid cells prints (CSV) loads back to the same grid */
static void export_round_trip(void** state) {
  fixture* f = *state;
  assert_int_equal(ura_grid_load(&f->c, GRIDS "/table08_caseA_wind10.csv"), 0);
  urGrid* g0 = f->c.last.g;
  int nrow = g0->nrow, ncol = g0->ncol;
  double q = g0->q;
  double* p = malloc(sizeof(double) * nrow * ncol);
  for (int k = 0; k < nrow * ncol; k++) p[k] = g0->cell[k].p;

  /* grid cells in CSV into the buffer, then into a file */
  fflush(f->c.out);
  rewind(f->c.out);
  assert_int_equal(ura_run_line(&f->c, "set format csv; grid cells"), 0);
  fflush(f->c.out);
  const char* path = put_file(f, "cells.csv", f->buf, ftell(f->c.out));
  assert_int_equal(ura_grid_load(&f->c, path), 0);
  urGrid* g = f->c.last.g;
  assert_int_equal(g->nrow, nrow);
  assert_int_equal(g->ncol, ncol);
  assert_true(fabs(g->q - q) < 1e-9);
  assert_true(g->complete);
  for (int k = 0; k < nrow * ncol; k++) assert_true(fabs(g->cell[k].p - p[k]) < 1e-9);
  assert_string_equal(f->c.last.casename, "A");
  assert_true(f->c.last.wind == 10);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(paper_tables, setup, teardown),
      cmocka_unit_test_setup_teardown(paper_cells, setup, teardown),
      cmocka_unit_test_setup_teardown(small_table, setup, teardown),
      cmocka_unit_test_setup_teardown(no_comments, setup, teardown),
      cmocka_unit_test_setup_teardown(malformed, setup, teardown),
      cmocka_unit_test_setup_teardown(export_format, setup, teardown),
      cmocka_unit_test_setup_teardown(export_round_trip, setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
