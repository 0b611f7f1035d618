/* interrupt.c: Ctrl-C. One SIGINT handler for the whole run sets a flag that long work polls:
 * grid workers stop taking cells, a running impact or the stance settling stops at its next step
 * (the compiled model's opt.stop points here), the model parser stops between statements, waits
 * for gnuplot and for files stop within 0.1 s, and no further command of a line or script
 * starts. At the prompt the REPL clears the line (repl.c). In a script, a second Ctrl-C before
 * the first was acted on ends the program at once, as killed by SIGINT; interactively repeated
 * Ctrl-C never end the program.
 *
 * The flag is a lock-free C11 atomic: written by the handler, read by the grid's worker threads
 * (relaxed order is enough: it only asks them to stop). SIGTERM and SIGHUP, and a fatal second
 * Ctrl-C, first remove the temporary file of a write under way (atomic.c), then end the program
 * as the signal would.
 */
#include <signal.h>
#include <stdatomic.h>
#include <string.h>
#include <unistd.h>

#include "base.h"


_Static_assert(ATOMIC_INT_LOCK_FREE == 2, "the stop flag is written by a signal handler");
static _Atomic int flag;
static volatile sig_atomic_t patient; /* interactive: Ctrl-C never ends the program */

/* the temporary file of the write under way: its name is complete before armed is set */
static char temp_path[1200];
static volatile sig_atomic_t armed;

void ura_temp_arm(const char* path) {
  armed = 0;
  size_t n = strlen(path);
  if (n >= sizeof temp_path) return;
  memcpy(temp_path, path, n + 1);
  armed = 1;
}

void ura_temp_disarm(void) {
  armed = 0;
}

/* remove the temporary file (async-signal-safe), then die of sig */
static void die(int sig) {
  if (armed) unlink(temp_path);
  armed = 0;
  signal(sig, SIG_DFL);
  raise(sig); /* delivered on return from the handler */
}

static void on_sigint(int sig) {
  if (atomic_load_explicit(&flag, memory_order_relaxed) && !patient) {
    die(sig);
    return;
  }
  atomic_store_explicit(&flag, 1, memory_order_relaxed);
}

static void on_term(int sig) {
  die(sig);
}

void ura_interrupt_install(int interactive) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; /* no SA_RESTART: a blocked read returns and can be stopped */
  patient = interactive;
  sigaction(SIGINT, &sa, NULL);
  sa.sa_handler = on_term;
  sigaction(SIGTERM, &sa, NULL);
  sigaction(SIGHUP, &sa, NULL);
}

_Atomic int* ura_interrupt_flag(void) {
  return &flag;
}

int ura_interrupted(void) {
  return atomic_load_explicit(&flag, memory_order_relaxed) != 0;
}

void ura_interrupt_clear(void) {
  atomic_store_explicit(&flag, 0, memory_order_relaxed);
}
