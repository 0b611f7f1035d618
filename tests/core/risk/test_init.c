/* test_init.c: the host's options (init.h). GSL's default error handler aborts the process; with
 * urINIT_GSL_CODES a GSL error comes back as a code. Each case runs in a child process, so the
 * abort of the default (which shows that the probe does fail without the option) is observed,
 * not suffered. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_vector.h>

#include "uasimpact/init.h"

/* in a child: apply flags (unless < 0), then make GSL fail (copying a vector into one of another
   length is a GSL_EBADLEN error); the child's wait status: exit 0 when the error came back as
   that code */
static int probe(int flags) {
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    signal(SIGABRT, SIG_DFL);                         /* cmocka catches it in the parent */
    if (!freopen("/dev/null", "w", stderr)) _exit(3); /* GSL's default handler prints */
    if (flags >= 0 && ur_init((unsigned)flags)) _exit(2);
    gsl_vector *a = gsl_vector_calloc(2), *b = gsl_vector_calloc(3);
    if (!a || !b) _exit(4);
    _exit(gsl_vector_memcpy(a, b) == GSL_EBADLEN ? 0 : 1);
  }
  int st = 0;
  waitpid(pid, &st, 0);
  return st;
}

static void test_default_aborts(void** state) {
  (void)state;
  int st = probe(-1);
  assert_true(WIFSIGNALED(st) && WTERMSIG(st) == SIGABRT);
  st = probe(0); /* no option: GSL's handler is left alone */
  assert_true(WIFSIGNALED(st) && WTERMSIG(st) == SIGABRT);
}

static void test_codes(void** state) {
  (void)state;
  int st = probe(urINIT_GSL_CODES);
  assert_true(WIFEXITED(st) && WEXITSTATUS(st) == 0);
}

static void test_unknown_flag(void** state) {
  (void)state;
  assert_int_equal(ur_init(2u), -1);
  assert_int_equal(ur_init(urINIT_GSL_CODES | 8u), -1);
  assert_int_equal(ur_init(0), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_default_aborts),
      cmocka_unit_test(test_codes),
      cmocka_unit_test(test_unknown_flag),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
