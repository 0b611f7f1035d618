/* pager.c: output at a terminal. Long output goes through $PAGER (less -FRSX when unset), as git
 * does: the command's results are gathered, and when they are taller than the screen they are
 * handed to the pager through sh -c. Never in scripts, -c, pipes or the viewer: only a command
 * typed at the prompt whose standard output is a terminal (the case layer decides that:
 * ura_at_terminal, case/output.c; here only the gathering and the paging). */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base.h"


static FILE* gather; /* the buffer of the command under way, or NULL */
static char* gathered;
static size_t ngathered;
static FILE* real_out;

int ura_tty(FILE* f) {
  if (!f) return 0;
  if (gather && f == gather) return 1;
  int fd = fileno(f);
  return fd >= 0 && isatty(fd);
}


/* the terminal's size: the window of standard output (or input), else LINES/COLUMNS, else
   24x80 */
void ura_term_size(int* rows, int* cols) {
  struct winsize ws;
  *rows = 24;
  *cols = 80;
  if ((ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 || ioctl(STDIN_FILENO, TIOCGWINSZ, &ws) == 0) &&
      ws.ws_row > 0 && ws.ws_col > 0) {
    *rows = ws.ws_row;
    *cols = ws.ws_col;
    return;
  }
  const char* l = getenv("LINES");
  const char* k = getenv("COLUMNS");
  if (l && atoi(l) > 0) *rows = atoi(l);
  if (k && atoi(k) > 0) *cols = atoi(k);
}


/* commands whose output is never paged: they take the screen (view), run other commands
   (source), start a program (plot) or leave */
static int never_paged(const char* name) {
  static const char* const names[] = {"view", "source", "plot", "quit", "exit", NULL};
  for (int i = 0; names[i]; i++) {
    if (!strcmp(names[i], name)) return 1;
  }
  return 0;
}

FILE* ura_pager_gather(FILE* out, const char* cmd) {
  if (gather || never_paged(cmd)) return NULL;
  FILE* f = open_memstream(&gathered, &ngathered);
  if (!f) return NULL;
  real_out = out;
  gather = f;
  return f;
}

/* the program that pages: $PAGER, unless unset or empty (less -FRSX); "cat" is no pager */
static const char* pager_command(void) {
  const char* p = getenv("PAGER");
  return p && *p ? p : "less -FRSX";
}

/* hand text to the pager; 0 when it ran and exited 0, else -1 with why (the caller prints the
   text itself: nothing computed is lost when the pager is missing, fails or dies) */
static int page(const char* text, size_t n, char* why, size_t nwhy) {
  const char* cmd = pager_command();
  char name[120];
  why[0] = 0;
  if (!strcmp(cmd, "cat")) return -1;
  ura_printable(cmd, name, sizeof name);
  void (*old)(int) = signal(SIGPIPE, SIG_IGN);
  FILE* p = popen(cmd, "w");
  if (!p) {
    signal(SIGPIPE, old);
    snprintf(why, nwhy, "the pager '%s' could not be started", name);
    return -1;
  }
  fwrite(text, 1, n, p);
  int st = pclose(p);
  signal(SIGPIPE, old);
  /* sh -c: 127 the pager was not found, 126 not runnable; any other failure said too */
  if (st == -1) {
    snprintf(why, nwhy, "the pager '%s' could not be waited for", name);
  } else if (WIFSIGNALED(st)) {
    snprintf(why, nwhy, "the pager '%s' was ended by signal %d", name, WTERMSIG(st));
  } else if (WIFEXITED(st) && WEXITSTATUS(st) == 127) {
    snprintf(why, nwhy, "the pager '%s' was not found", name);
  } else if (WIFEXITED(st) && WEXITSTATUS(st) == 126) {
    snprintf(why, nwhy, "the pager '%s' could not be run", name);
  } else if (WIFEXITED(st) && WEXITSTATUS(st) != 0) {
    snprintf(why, nwhy, "the pager '%s' failed (exit status %d)", name, WEXITSTATUS(st));
  } else {
    return 0;
  }
  return -1;
}

FILE* ura_pager_release(FILE* msg) {
  if (!gather) return NULL;
  fclose(gather);
  gather = NULL;
  FILE* out = real_out;
  size_t lines = 0;
  for (size_t i = 0; i < ngathered; i++) lines += gathered[i] == '\n';
  int rows, cols;
  ura_term_size(&rows, &cols);
  fflush(out);
  char why[300];
  if (lines < (size_t)rows || page(gathered, ngathered, why, sizeof why)) {
    if (lines >= (size_t)rows && why[0]) {
      fprintf(msg,
              "pager: %s; the output follows here (PAGER=cat or 'set pager off' prints "
              "without a pager)\n",
              why);
      fflush(msg);
    }
    fwrite(gathered, 1, ngathered, out);
  }
  free(gathered);
  gathered = NULL;
  ngathered = 0;
  return out;
}
