/* test_scale_part_magic.c: reading a shard's part file (src/app/scale/scale_part.c): a part under the
 * present magic word (uasimpact-part 1) and one written before the tool was renamed
 * (uasrisk-part 1, the same format) are read alike; another first line, or a checksum that does
 * not match, is refused with the reason. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

#include "../../../src/app/scale/scale.h"

/* a part of one shard, no grid, the command line 't.ses', under first line MAGIC, with its
   checksum (0 in the last digit changed when damaged), into a new file; its path */
static const char* part_file(const char* magic, int damaged) {
  static char path[64];
  char text[400];
  int n = snprintf(text, sizeof text,
                   "%s 1\nshard 0 1\nscript 0123456789abcdef\nmodel fedcba9876543210\nargc 1\n"
                   "arg t.ses\nend 0 0\n",
                   magic);
  unsigned long long h = ura_fnv(uraFNV0, text, (size_t)n);
  snprintf(text + n, sizeof text - (size_t)n, "sum %016llx\n", damaged ? h ^ 1 : h);
  strcpy(path, "/tmp/test_scale_part.XXXXXX");
  int fd = mkstemp(path);
  assert_true(fd >= 0);
  assert_int_equal(write(fd, text, strlen(text)), (long)strlen(text));
  close(fd);
  return path;
}

/* both magic words read to the same part */
static void magic_words(void** state) {
  const char* const magic[] = {"uasimpact-part", "uasrisk-part"};
  for (int i = 0; i < 2; i++) {
    const char* path = part_file(magic[i], 0);
    uraPartFile p;
    char err[300] = "";
    int rc = ura_part_read(path, &p, err, sizeof err);
    unlink(path);
    if (rc) fail_msg("%s: %s", magic[i], err);
    assert_int_equal(p.shard, 0);
    assert_int_equal(p.nshard, 1);
    assert_string_equal(p.script, "0123456789abcdef");
    assert_string_equal(p.model, "fedcba9876543210");
    assert_int_equal(p.argc, 1);
    assert_string_equal(p.argv[0], "t.ses");
    assert_int_equal(p.ngrid, 0);
    ura_part_free(&p);
  }
}

/* another first line, or a damaged checksum, is refused with why */
static void refused(void** state) {
  uraPartFile p;
  char err[300];
  const char* path = part_file("uasfoo-part", 0);
  assert_int_equal(ura_part_read(path, &p, err, sizeof err), -1);
  unlink(path);
  assert_non_null(strstr(err, "is not a part file"));
  ura_part_free(&p);
  path = part_file("uasrisk-part", 1);
  assert_int_equal(ura_part_read(path, &p, err, sizeof err), -1);
  unlink(path);
  assert_non_null(strstr(err, "its checksum does not match"));
  ura_part_free(&p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(magic_words),
      cmocka_unit_test(refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
