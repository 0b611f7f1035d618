/* test_ctx.h: a fresh workbench context per cmocka test (ura_init, output to /dev/null), freed
 * with everything it holds, and lines run on it that must succeed or fail as expected; for the
 * tests of the application's caches (test_modelcache.c, test_recall.c). Include after cmocka.h. */
#ifndef UASIMPACT_TEST_CTX_H
#define UASIMPACT_TEST_CTX_H

#include <stdio.h>
#include <stdlib.h>

#include "../src/app/ui/ui.h"

static int ctx_setup(void** state) {
  uraCtx* c = calloc(1, sizeof *c);
  ura_init(c);
  c->out = fopen("/dev/null", "w");
  *state = c;
  return c->model && c->out ? 0 : -1;
}

static int ctx_teardown(void** state) {
  uraCtx* c = *state;
  ura_models_free(c);
  ura_last_free(c);
  fclose(c->out);
  free(c);
  return 0;
}

/* run a line; its status must be expect_rc (0 or -1) */
static void run_rc(uraCtx* c, const char* line, int expect_rc) {
  if (ura_run_line(c, line) != expect_rc) fail_msg("'%s': %s", line, c->err);
}

#endif
