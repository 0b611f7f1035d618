/* interrupt.c: Ctrl-C. One SIGINT handler for the whole run sets a flag that long work polls:
 * grid workers stop taking cells, a running impact or the stance settling stops at its next step
 * (the compiled model's opt.stop points here), the model parser stops between statements, waits
 * for gnuplot and for files stop within 0.1 s, and no further command of a line or script
 * starts. At the prompt the REPL clears the line (repl.c). In a script, a second Ctrl-C before
 * the first was acted on ends the program at once, as killed by SIGINT; interactively repeated
 * Ctrl-C never end the program.
 *
 * The flag is a lock-free C11 atomic: written by the handler, read by the grid's worker threads
 * (relaxed order is enough: it only asks them to stop). Every signal whose default is to end the
 * program (SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGXCPU, SIGVTALRM,
 * SIGPROF, SIGIO, SIGPWR, the real-time signals ...), and a fatal second Ctrl-C, first kill the
 * gnuplot writing a plot file, then remove the temporary file of a write under way (atomic.c),
 * then end the program as the signal would. A signal the program was started with ignored
 * (nohup, trap '' PIPE) stays ignored; the faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) are
 * left to the system and the sanitizers.
 */
#include <signal.h>
#include <stdatomic.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
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

/* the child writing the temporary file (0: none) */
static volatile sig_atomic_t child;

void ura_child_arm(int pid) {
  child = pid;
}

void ura_child_disarm(void) {
  child = 0;
}

/* kill and reap the child, remove the temporary file (async-signal-safe), then die of sig */
static void die(int sig) {
  if (child > 0) {
    kill(child, SIGKILL);
    waitpid(child, NULL, 0);
  }
  child = 0;
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

/* the signals that end the program by default, but for SIGINT and the faults */
static const int fatal[] = {
    SIGHUP,    SIGTERM, SIGQUIT, SIGUSR1,   SIGUSR2, SIGALRM,
    SIGPIPE,   SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGIO,
#ifdef SIGPWR
    SIGPWR,
#endif
#ifdef SIGSTKFLT
    SIGSTKFLT,
#endif
};

/* on_term for sig, unless the program was started with sig ignored or another handler has it */
static void catch_fatal(int sig) {
  struct sigaction old, sa;
  if (sigaction(sig, NULL, &old)) return;
  int ours =
      !(old.sa_flags & SA_SIGINFO) && (old.sa_handler == SIG_DFL || old.sa_handler == on_term);
  if (!ours) return;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_term;
  sigfillset(&sa.sa_mask); /* one at a time: the first to come removes the file */
  sigaction(sig, &sa, NULL);
}

void ura_interrupt_install(int interactive) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0; /* no SA_RESTART: a blocked read returns and can be stopped */
  patient = interactive;
  sigaction(SIGINT, &sa, NULL);
  for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++) catch_fatal(fatal[i]);
  for (int sig = SIGRTMIN; sig <= SIGRTMAX; sig++) catch_fatal(sig);
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
