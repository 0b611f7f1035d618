/* test_scale_part.c: the part file reader (src/app/scale_part.c) on parts written as a forger
 * would, with the checksum recomputed (it is no signature): a part is data, so the reader refuses
 * a command line no shard runs (-i, none, another option), counts larger than the file can hold
 * (before allocating), NUL bytes, cells outside their domain, and reads the magic line first: a
 * directory or /dev/zero is refused at once with its reason. A valid part is the control case. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../../src/app/scale/scale.h"

/* a cell of a simulated impact, with contact */
static urCell cell(double p) {
  urCell c;
  memset(&c, 0, sizeof c);
  c.status = urCELL_DONE;
  c.contact = 1;
  c.val[urVAL_HIC15] = 250;
  c.val[urVAL_NIJ_MODE] = 1;
  c.pof[urCRIT_HIC] = p;
  c.p = p;
  return c;
}

/* a part's text: the body (everything after the argv lines up to and with the end line) after a
   header of the given command line, its checksum line appended; malloc'd, length in *n */
static char* part(int argc, char** argv, const char* body, size_t* n) {
  char* text = NULL;
  size_t len = 0;
  FILE* f = open_memstream(&text, &len);
  assert_non_null(f);
  ura_part_header(f, 0, 1, argc, argv);
  fputs(body, f);
  fflush(f);
  fprintf(f, "sum %016llx\n", ura_fnv(uraFNV0, text, len));
  fclose(f);
  *n = len;
  return text;
}

/* the body of one grid of two cells, the second with p given as text */
static void grid_body(const char* p2, char* body, size_t nb) {
  urCell a = cell(0.25), b = cell(0.5);
  char la[512], lb[512];
  assert_true(ura_cell_write(&a, la, sizeof la) > 0);
  assert_true(ura_cell_write(&b, lb, sizeof lb) > 0);
  if (p2) { /* the p field of b: before " 0 |" (extrap 0, no reason) */
    char* end = strrchr(lb, '|') - 3;
    char* pf = end;
    while (pf > lb && pf[-1] != ' ') pf--;
    char tail[64];
    snprintf(tail, sizeof tail, "%s", end);
    snprintf(pf, sizeof lb - (size_t)(pf - lb), "%s%s", p2, tail);
  }
  snprintf(body, nb, "grid 0 0123456789abcdef 2 2\nc 0 %s\nc 1 %s\nend 0 1\n", la, lb);
}

/* parse text (owned by the part from here); 0 or -1, the message in err */
static int parse(char* text, size_t n, uraPartFile* p, char* err, size_t nerr) {
  int rc = ura_part_parse(text, n, "P", p, err, nerr);
  if (rc) ura_part_free(p);
  return rc;
}

static char* c_grid[] = {"-c", "grid"};

static void valid(void** state) {
  char body[2048], err[uraERRLEN];
  size_t n;
  uraPartFile p;
  grid_body(NULL, body, sizeof body);
  char* text = part(2, c_grid, body, &n);
  assert_int_equal(parse(text, n, &p, err, sizeof err), 0);
  assert_int_equal(p.argc, 2);
  assert_string_equal(p.argv[0], "-c");
  assert_string_equal(p.argv[1], "grid");
  assert_int_equal(p.ngrid, 1);
  assert_int_equal(p.grid[0].ncell, 2);
  urCell c = cell(0);
  assert_int_equal(ura_cell_read(p.grid[0].cell[1], &c), 0);
  assert_true(c.p == 0.5);
  ura_part_free(&p);
}

/* a command line no shard runs: -i, none, another option, -c without its commands */
static void argv_refused(void** state) {
  char body[2048], err[uraERRLEN];
  size_t n;
  uraPartFile p;
  grid_body(NULL, body, sizeof body);
  char* i_opt[] = {"-i"};
  char* i_file[] = {"study.ses", "-i"};
  char* other[] = {"--shard", "0/1", "study.ses"};
  char* c_alone[] = {"study.ses", "-c"};
  struct {
    int argc;
    char** argv;
  } bad[] = {{1, i_opt}, {2, i_file}, {0, NULL}, {3, other}, {2, c_alone}};
  for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
    char* text = part(bad[k].argc, bad[k].argv, body, &n);
    assert_int_equal(parse(text, n, &p, err, sizeof err), -1);
    assert_non_null(strstr(err, "records a command line that no shard runs"));
  }
  char* dash[] = {"-", "-c", "-i"}; /* a file named '-', commands that read "-i" */
  char* text = part(3, dash, body, &n);
  assert_int_equal(parse(text, n, &p, err, sizeof err), 0);
  ura_part_free(&p);
}

/* counts beyond what the bytes left can hold: refused before anything is allocated */
static void counts_bounded(void** state) {
  char err[uraERRLEN];
  size_t n;
  uraPartFile p;
  char* text = part(2, c_grid, "end 0 0\n", &n);
  char* argc_line = strstr(text, "argc 2\n");
  assert_non_null(argc_line);
  /* argc 99999 in a file of a few hundred bytes (the reader took up to 100000 before) */
  char forged[1024];
  snprintf(forged, sizeof forged, "%.*sargc 99999\n%s", (int)(argc_line - text), text,
           argc_line + 7);
  char* last = strstr(forged, "sum ");
  snprintf(last, sizeof forged - (size_t)(last - forged), "sum %016llx\n",
           ura_fnv(uraFNV0, forged, (size_t)(last - forged)));
  free(text);
  text = strdup(forged);
  assert_int_equal(parse(text, strlen(forged), &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "bad argc line"));

  /* a grid claiming 10^9 cells (the reader allocated 16 GB for them before) */
  text = part(2, c_grid, "grid 0 0123456789abcdef 1000000000 1000000000\nend 0 1\n", &n);
  assert_int_equal(parse(text, n, &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "bad grid line"));
}

static void nul_byte(void** state) {
  char body[2048], err[uraERRLEN];
  size_t n;
  uraPartFile p;
  grid_body(NULL, body, sizeof body);
  char* text = part(2, c_grid, body, &n);
  char* g = strstr(text, "grid 0");
  g[4] = 0; /* "grid\0..." */
  char* last = strstr(g + 5, "sum ");
  snprintf(last, n + 1 - (size_t)(last - text), "sum %016llx\n",
           ura_fnv(uraFNV0, text, (size_t)(last - text)));
  assert_int_equal(parse(text, n, &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "a NUL byte"));
}

/* p = 5, 1e300, inf, nan, -1 with the checksum recomputed; the control case first */
static void cell_domain(void** state) {
  char body[2048], err[uraERRLEN];
  size_t n;
  uraPartFile p;
  static const char* const values[] = {"0x1p-1", "5", "1e300", "inf", "nan", "-1", NULL};
  for (int k = 0; values[k]; k++) {
    grid_body(values[k], body, sizeof body);
    char* text = part(2, c_grid, body, &n);
    int rc = parse(text, n, &p, err, sizeof err);
    if (k == 0) {
      assert_int_equal(rc, 0);
      ura_part_free(&p);
    } else {
      assert_int_equal(rc, -1);
      assert_non_null(strstr(err, "bad cell line"));
    }
  }
}

/* the magic line first: another file, another version */
static void magic(void** state) {
  char err[uraERRLEN];
  uraPartFile p;
  char* text = strdup("\177ELF\002\001\001");
  assert_int_equal(parse(text, strlen(text), &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "is not a part file"));
  text = strdup("uasimpact-part 9\nshard 0 1\n");
  assert_int_equal(parse(text, strlen(text), &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "format version 9; accepted: version 1"));
  text = strdup("uasimpact-part 1\nshard 0 1\n"); /* no checksum line */
  assert_int_equal(parse(text, strlen(text), &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "is truncated"));
}

/* files: a directory and a device that never ends are refused at once, by their first line */
static void files(void** state) {
  char err[uraERRLEN], dir[] = "/tmp/test_scale_part.XXXXXX", path[64];
  uraPartFile p;
  assert_non_null(mkdtemp(dir));
  assert_int_equal(ura_part_read(dir, &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "is a directory"));
  ura_part_free(&p);
  assert_int_equal(ura_part_read("/dev/zero", &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "is not a part file"));
  ura_part_free(&p);
  snprintf(path, sizeof path, "%s/none", dir);
  assert_int_equal(ura_part_read(path, &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "cannot read"));
  ura_part_free(&p);

  /* the control case: a valid part from a file */
  char body[2048];
  size_t n;
  grid_body(NULL, body, sizeof body);
  char* text = part(2, c_grid, body, &n);
  snprintf(path, sizeof path, "%s/p0", dir);
  FILE* f = fopen(path, "wb");
  assert_non_null(f);
  fwrite(text, 1, n, f);
  fclose(f);
  free(text);
  assert_int_equal(ura_part_read(path, &p, err, sizeof err), 0);
  assert_int_equal(p.grid[0].ncell, 2);
  ura_part_free(&p);
  unlink(path);
  rmdir(dir);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(valid),    cmocka_unit_test(argv_refused), cmocka_unit_test(counts_bounded),
      cmocka_unit_test(nul_byte), cmocka_unit_test(cell_domain),  cmocka_unit_test(magic),
      cmocka_unit_test(files),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
