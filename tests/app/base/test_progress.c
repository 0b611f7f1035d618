/* test_progress.c: the progress line's text (progress.c): done of total, time, the time left of
   this piece by its rate; in a run of several pieces (a sweep's grids) also the time left of all
   of them, from the pieces done and the fraction of the one running over the run's time (closed
   forms: 3 s for 480 of 2971 leaves 15.6 s; 2.5 of 6 grids in 50 s leaves 70 s) */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "../../../src/app/base/base.h"

static void one_piece(void** state) {
  char buf[400];
  ura_progress_text(buf, sizeof buf, "grid:", 480, 2971, "impacts", 3.0, 0, 0, 0);
  assert_string_equal(buf, "grid: 480/2971 impacts, 3 s, about 16 s left");
  /* before a second has passed, and before anything is done: no estimate */
  ura_progress_text(buf, sizeof buf, "grid:", 480, 2971, "impacts", 0.4, 0, 0, 0);
  assert_string_equal(buf, "grid: 480/2971 impacts, 0 s");
  ura_progress_text(buf, sizeof buf, "grid:", 0, 2971, "impacts", 5, 0, 0, 0);
  assert_string_equal(buf, "grid: 0/2971 impacts, 5 s");
}

static void run_of_pieces(void** state) {
  char buf[400];
  ura_progress_label("sweep wind 4 m/s (3 of 6): ");
  ura_progress_text(buf, sizeof buf, "grid:", 100, 200, "impacts", 10, 2, 6, 50);
  assert_string_equal(buf,
                      "sweep wind 4 m/s (3 of 6): grid: 100/200 impacts, 10 s, about 10 s "
                      "left (all 6: about 1 min 10 s)");
  ura_progress_label(NULL);
  /* a new grid just begun: the grids done give the estimate */
  ura_progress_text(buf, sizeof buf, "grid:", 0, 200, "impacts", 0, 3, 6, 60);
  assert_string_equal(buf, "grid: 0/200 impacts, 0 s (all 6: about 1 min 00 s)");
  /* the last grid: its own estimate says it all */
  ura_progress_text(buf, sizeof buf, "grid:", 100, 200, "impacts", 10, 5, 6, 110);
  assert_string_equal(buf, "grid: 100/200 impacts, 10 s, about 10 s left");
  /* the first grid's start: nothing to go on yet */
  ura_progress_text(buf, sizeof buf, "grid:", 0, 200, "impacts", 0, 0, 6, 0);
  assert_string_equal(buf, "grid: 0/200 impacts, 0 s");
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(one_piece),
      cmocka_unit_test(run_of_pieces),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
