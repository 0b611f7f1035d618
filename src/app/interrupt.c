/* interrupt.c: Ctrl-C. One SIGINT handler for the whole run sets a flag that long work polls:
 * grid workers stop taking cells, a running impact or the stance settling stops at its next step
 * (the compiled model's opt.stop points here), and no further command of a line or script
 * starts. At the prompt the REPL clears the line (repl.c). In a script, a second Ctrl-C before
 * the first was acted on ends the program at once, as killed by SIGINT; interactively repeated
 * Ctrl-C never end the program.
 */
#include <signal.h>
#include <string.h>

#include "app.h"

/* int is sig_atomic_t here, and the engine reads the flag through a volatile int* */
_Static_assert(sizeof(sig_atomic_t) == sizeof(int), "the stop flag is written by a handler");
static volatile int flag;
static volatile int patient;       /* interactive: Ctrl-C never ends the program */

static void on_sigint(int sig) {
  if (flag && !patient) {
    signal(SIGINT, SIG_DFL);       /* delivered again on return, now fatal */
    raise(SIGINT);
    return;
  }
  flag = 1;
}

void ura_interrupt_install(int interactive) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;                 /* no SA_RESTART: a blocked read returns and can be stopped */
  patient = interactive;
  sigaction(SIGINT, &sa, NULL);
}

volatile int* ura_interrupt_flag(void) {
  return &flag;
}

int ura_interrupted(void) {
  return flag != 0;
}

void ura_interrupt_clear(void) {
  flag = 0;
}
