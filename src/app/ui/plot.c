/* plot.c: gnuplot as an external process. A plot is a complete script (commands and named
 * datablocks $D << EOD ... EOD) built in memory, then written to gnuplot's standard input
 * through a pipe; we wait for gnuplot to exit, so an output file is complete on return, and
 * read its error output from a temporary file. An output file is written whole or not at all:
 * gnuplot writes a temporary file beside it (base/atomic.c), renamed over it only after gnuplot
 * exited cleanly and the file passed its check (plot_file.c); a failure removes it and leaves
 * an old file as it was. SIGPIPE is ignored around the writes, a missing gnuplot or a missing
 * display gives one clear message, Ctrl-C (or the viewer's keys, base/keywatch.c) stops the wait
 * within 0.05 s, and nothing here ends the program.
 * Here the runner and what every kind of plot shares (scripts, numbers, texts, x-y curves); the
 * plot command and its kinds are plot_cmd.c, plot_history.c, plot_sweep.c and plot_mc.c.
 */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "ui.h"


#define GP_TIMEOUT 60.0 /* s: gnuplot taking longer than this is stopped */

/* gnuplot on PATH */
static int have_gnuplot(void) {
  const char* path = getenv("PATH");
  if (!path) path = "/usr/local/bin:/usr/bin:/bin";
  char dir[4096];
  while (*path) {
    size_t n = strcspn(path, ":");
    if (n < sizeof dir - 16) {
      memcpy(dir, path, n);
      dir[n] = 0;
      if (!n) strcpy(dir, ".");
      strcat(dir, "/gnuplot");
      if (!access(dir, X_OK)) return 1;
    }
    path += n;
    if (*path == ':') path++;
  }
  return 0;
}

/* a string for gnuplot: in single quotes, where gnuplot substitutes nothing (no backquoted
   commands, no escapes; '' is a quote), line breaks joined as '...'."\n".'...', other control
   bytes as blanks */
#define quote ura_plot_quote
void ura_plot_quote(FILE* f, const char* s) {
  fputc('\'', f);
  for (; s && *s; s++) {
    unsigned char ch = (unsigned char)*s;
    if (ch == '\n')
      fputs("'.\"\\n\".'", f);
    else if (ch == '\'')
      fputs("''", f);
    else
      fputc(ch < 32 || ch == 127 ? ' ' : ch, f);
  }
  fputc('\'', f);
}

/* set NAME "text" noenhanced */
void ura_plot_text(FILE* f, const char* name, const char* text) {
  fprintf(f, "set %s ", name);
  quote(f, text);
  fprintf(f, " noenhanced\n");
}

/* a value for a datablock */
void ura_plot_num(FILE* f, double v) {
  if (isfinite(v))
    fprintf(f, "%.9g", v);
  else
    fputs("NaN", f);
}

double ura_plot_tic_step(double lo, double hi, int n) {
  double span = hi - lo;
  if (!(span > 0) || !isfinite(span)) return 0;
  double raw = span / n, p = pow(10, floor(log10(raw))), m = raw / p;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

/* seconds on a monotonic clock */
static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* write everything to a non-blocking pipe before the deadline; 0, errno, ETIMEDOUT, or EINTR
   on Ctrl-C */
static int write_all(int fd, const char* p, size_t n, double deadline) {
  while (n) {
    ssize_t k = write(fd, p, n);
    if (k >= 0) {
      p += k;
      n -= (size_t)k;
      continue;
    }
    if (ura_interrupted()) return EINTR;
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return errno;
    double left = deadline - now();
    if (left <= 0) return ETIMEDOUT;
    struct pollfd pf = {fd, POLLOUT, 0};
    poll(&pf, 1, left > 0.05 ? 50 : (int)(left * 1000) + 1); /* Ctrl-C seen within 0.05 s */
  }
  return 0;
}

/* the whole of a temporary file (at most max bytes) as a string (caller frees) */
static char* slurp(FILE* f, long max) {
  fflush(f);
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  if (n < 0) n = 0;
  if (n > max) n = max;
  char* s = malloc((size_t)n + 1);
  if (!s) return NULL;
  rewind(f);
  size_t k = fread(s, 1, (size_t)n, f);
  s[k] = 0;
  return s;
}

/* the telling line of gnuplot's error output ("FILE" line N: message) into buf; returns N
   (0 when no line is named) */
static int gp_error(const char* err, char* buf, size_t n) {
  int lineno = 0;
  snprintf(buf, n, "no message");
  for (const char* p = err; p && *p;) {
    const char* e = strchr(p, '\n');
    int len = e ? (int)(e - p) : (int)strlen(p);
    const char* at = strstr(p, "line ");
    int k = 0;
    if (at && at < p + len && sscanf(at, "line %d: %n", &lineno, &k) == 1 && k > 0) {
      const char* m = at + k;
      while (*m == ' ') m++;
      snprintf(buf, n, "%.*s", (int)(p + len - m), m);
      return lineno;
    }
    while (len > 0 && isspace((unsigned char)*p)) p++, len--;
    if (len > 0 && !lineno && !strcmp(buf, "no message")) snprintf(buf, n, "%.*s", len, p);
    p = e ? e + 1 : NULL;
  }
  return 0;
}

/* a file terminal named without options gets the canvas size asked for (vector terminals in
   inches at 100 pixels per inch) */
static void put_terminal(const uraCtx* c, FILE* f, const char* term) {
  static const char* const px[] = {"png", "pngcairo", "svg", "jpeg", "gif", NULL};
  static const char* const in[] = {"pdfcairo", "epscairo", NULL};
  int bare = !strpbrk(term, " \t"), kind = 0;
  for (int i = 0; px[i]; i++)
    if (!strcmp(term, px[i])) kind = 1;
  for (int i = 0; in[i]; i++)
    if (!strcmp(term, in[i])) kind = 2;
  fprintf(f, "set terminal %s", term);
  if (bare && kind == 1 && c->canvas_w > 0) fprintf(f, " size %d,%d", c->canvas_w, c->canvas_h);
  if (bare && kind == 2 && c->canvas_w > 0) {
    fprintf(f, " size %.2fin,%.2fin", c->canvas_w / 100.0, c->canvas_h / 100.0);
  }
  fputc('\n', f);
}

void ura_plot_canvas(uraCtx* c, int w, int h) {
  c->canvas_w = w;
  c->canvas_h = h;
}

/* the terminal (as we write it) and the output file of the settings, both checked again (they
   are checked when set); 0, or -1 with the error recorded */
static int settings(uraCtx* c, const char* who, char* term, size_t nt, char* out, size_t no,
                    int* window) {
  term[0] = out[0] = 0;
  if (*c->st.terminal && ura_terminal_check(c, c->st.terminal, term, nt)) return -1;
  if (*c->st.output && ura_output_check(c, c->st.output, out, no)) return -1;
  if (*out && !*term) {
    const char* t = ura_term_for_ext(out);
    if (!t) {
      return ura_fail(c,
                      "%s: no terminal for output '%s'; use 'set terminal png' (or svg, "
                      "pdfcairo, ...)",
                      who, out);
    }
    snprintf(term, nt, "%s", t);
  }
  int kind = ura_term_kind(term);
  if (*out && ura_plot_name_check(c, who, term, out)) return -1;
  if (!*out && kind == uraTERM_FILE) {
    return ura_fail(c, "%s: terminal '%s' writes a file; use 'set output FILE'", who, term);
  }
  *window = !*out && kind == uraTERM_WINDOW;
  return 0;
}

/* the preamble: the terminal, and the file gnuplot writes (the temporary file beside the
   output, as a quoted string; ./ before a relative name, so that no name is taken for a pipe);
   -1 with the error recorded when that name cannot be given to gnuplot as it is */
static int preamble(uraCtx* c, const char* who, FILE* f, const char* term, const char* tmp,
                    const char* out) {
  for (const char* p = tmp; p && *p; p++) {
    if ((unsigned char)*p < 32 || *p == 127) {
      return ura_fail(c,
                      "%s: cannot write '%s': the file it names holds a control character; "
                      "accepted: a file name without control characters",
                      who, out);
    }
  }
  if (*term) put_terminal(c, f, term);
  if (tmp) {
    char name[sizeof((uraAtomic*)0)->tmp + 2];
    snprintf(name, sizeof name, "%s%s", tmp[0] == '/' ? "" : "./", tmp);
    fprintf(f, "set output ");
    quote(f, name);
    fputc('\n', f);
  }
  return 0;
}

/* wait for gnuplot to exit, stopping it at the deadline or on Ctrl-C; it is reaped only once
   no signal handler can kill it any more (ura_child_arm); 1 when it exited by itself */
static int wait_gnuplot(pid_t pid, double deadline, int* status) {
  struct timespec tick = {0, 5000000};
  int exited = 0;
  for (;;) {
    siginfo_t si;
    memset(&si, 0, sizeof si);
    int r = waitid(P_PID, pid, &si, WEXITED | WNOHANG | WNOWAIT);
    if (r == 0 && si.si_pid == pid) {
      exited = 1;
      break;
    }
    if (r < 0 && errno != EINTR) break;
    if (now() > deadline || ura_interrupted()) break;
    nanosleep(&tick, NULL);
  }
  if (!exited) {
    siginfo_t si;
    kill(pid, SIGKILL);
    while (waitid(P_PID, pid, &si, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
    }
  }
  ura_child_disarm();
  *status = 0;
  while (waitpid(pid, status, 0) < 0 && errno == EINTR) {
  }
  return exited;
}

int ura_gnuplot_run(uraCtx* c, const char* who, const char* script, size_t len) {
  if (ura_dry(c, who)) return -1;
  if (c->mute) return 0; /* a shard or an MPI rank but 0 draws nothing */
  /* the settings, then gnuplot and a display */
  char term[512], out[512];
  int window = 0;
  if (settings(c, who, term, sizeof term, out, sizeof out, &window)) return -1;
  if (!have_gnuplot()) {
    return ura_fail(c, "%s: gnuplot not found; install it (Debian: gnuplot-nox) or use export",
                    who);
  }
  const char* d = getenv("DISPLAY");
  const char* w = getenv("WAYLAND_DISPLAY");
  if (window && !(d && *d) && !(w && *w)) {
    return ura_fail(c, "plot: no display; use 'set terminal png' and 'set output FILE.png'");
  }

  /* an output file: gnuplot writes a temporary file beside it (atomic.c) */
  uraAtomic a;
  int file = *out != 0;
  if (file && ura_atomic_open_file(c, &a, out, who)) return -1;
  char* pre = NULL;
  size_t npre = 0;
  FILE* pf = open_memstream(&pre, &npre);
  if (!pf) {
    if (file) ura_atomic_close(c, &a, 0, who);
    return ura_fail(c, "%s: out of memory", who);
  }
  int rc = preamble(c, who, pf, term, file ? a.tmp : NULL, out);
  fclose(pf);
  if (rc) {
    free(pre);
    if (file) ura_atomic_close(c, &a, 0, who);
    return -1;
  }

  /* gnuplot reads the pipe; its output and errors go to temporary files */
  FILE* ef = tmpfile();
  FILE* of = tmpfile();
  int fd[2] = {-1, -1};
  if (!ef || !of || pipe(fd)) {
    int e = errno;
    if (ef) fclose(ef);
    if (of) fclose(of);
    free(pre);
    if (file) ura_atomic_close(c, &a, 0, who);
    return ura_fail(c, "%s: cannot start gnuplot: %s", who, strerror(e));
  }
  fflush(NULL);
  /* every signal held from the fork until the child is armed: one that ended us in between left
     gnuplot running (the sanitized suite's plot_sig_HUP_cleaned, once); the child takes the old
     mask back before it runs gnuplot */
  sigset_t all, mask;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &mask);
  pid_t pid = fork();
  if (pid == 0) {
    pthread_sigmask(SIG_SETMASK, &mask, NULL);
    dup2(fd[0], STDIN_FILENO);
    dup2(fileno(of), STDOUT_FILENO);
    dup2(fileno(ef), STDERR_FILENO);
    close(fd[0]);
    close(fd[1]);
    /* a script file (not interactive input) stops at its first error */
    if (window)
      execlp("gnuplot", "gnuplot", "-persist", "/dev/stdin", (char*)NULL);
    else
      execlp("gnuplot", "gnuplot", "/dev/stdin", (char*)NULL);
    _exit(127);
  }
  /* a signal that ends us kills it before removing the temporary file */
  if (pid > 0) ura_child_arm(pid);
  pthread_sigmask(SIG_SETMASK, &mask, NULL);
  close(fd[0]);
  if (pid < 0) {
    int e = errno;
    close(fd[1]);
    fclose(ef);
    fclose(of);
    free(pre);
    if (file) ura_atomic_close(c, &a, 0, who);
    return ura_fail(c, "%s: cannot start gnuplot: %s", who, strerror(e));
  }

  /* the script, with SIGPIPE ignored (a gnuplot that died shows as EPIPE) and a deadline
     (a gnuplot that stops reading does not hold us) */
  struct sigaction ign = {0}, old;
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  sigaction(SIGPIPE, &ign, &old);
  double deadline = now() + GP_TIMEOUT;
  fcntl(fd[1], F_SETFL, fcntl(fd[1], F_GETFL) | O_NONBLOCK);
  int werr = write_all(fd[1], pre, npre, deadline);
  if (!werr) werr = write_all(fd[1], script, len, deadline);
  if (!werr && file) werr = write_all(fd[1], "unset output\n", 13, deadline);
  close(fd[1]);
  sigaction(SIGPIPE, &old, NULL);

  /* wait for gnuplot, stopping it at the deadline or on Ctrl-C */
  int status = 0;
  int waited = wait_gnuplot(pid, deadline, &status);

  /* text terminals' drawings to the output stream, then the verdict */
  char* outtext = slurp(of, 1L << 24);
  char* errtext = slurp(ef, 65536);
  fclose(of);
  fclose(ef);
  if (outtext && *outtext && c->out) fputs(outtext, c->out);
  free(outtext);

  /* name the setting when gnuplot refused the preamble */
  char msg[512], full[700];
  int at = gp_error(errtext, msg, sizeof msg);
  int npl = 0;
  for (const char* p = pre; p && *p; p++) npl += *p == '\n';
  if (at >= 1 && at <= npl) {
    const char* p = pre;
    for (int i = 1; i < at; i++) p = strchr(p, '\n') + 1;
    snprintf(full, sizeof full, "%.*s: %s", (int)strcspn(p, "\n"), p, msg);
  } else {
    snprintf(full, sizeof full, "%s", msg);
  }
  /* the verdict: stopped, not found, killed, failed, or a file not complete */
  rc = 0;
  if (ura_interrupted()) {
    rc = ura_fail(c, "%s: interrupted (Ctrl-C); gnuplot was stopped", who);
  } else if (!waited) {
    rc = ura_fail(c, "%s: gnuplot did not finish within %g s and was stopped", who, GP_TIMEOUT);
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    rc = ura_fail(c, "%s: gnuplot not found; install it (Debian: gnuplot-nox) or use export", who);
  } else if (WIFSIGNALED(status)) {
    rc = ura_fail(c, "%s: gnuplot was killed by signal %d%s%s", who, WTERMSIG(status),
                  errtext && *errtext ? ": " : "", errtext && *errtext ? full : "");
  } else if (WEXITSTATUS(status) != 0 || werr) {
    rc = ura_fail(c, "%s: gnuplot failed%s: %s", who, werr == EPIPE ? " (it stopped reading)" : "",
                  full);
  } else if (file) {
    rc = ura_plot_file_check(c, who, a.tmp, term, out);
  }
  /* the file renamed over the output when complete, else removed (the old one stays) */
  if (file) {
    int crc = ura_atomic_close(c, &a, rc == 0, who);
    if (!rc) rc = crc;
  }

  /* on success, gnuplot's warnings as notes */
  if (!rc && errtext && c->msg) {
    char* save = NULL;
    for (char* p = strtok_r(errtext, "\n", &save); p; p = strtok_r(NULL, "\n", &save)) {
      while (isspace((unsigned char)*p)) p++;
      if (*p) fprintf(c->msg, "%s: gnuplot: %s\n", who, p);
    }
  }
  free(errtext);
  free(pre);
  return rc;
}

/* build a script with a writer function, then run it */

int ura_plot_script(uraCtx* c, const char* who, uraPlotWriter fn, const void* arg) {
  char* s = NULL;
  size_t n = 0;
  FILE* f = open_memstream(&s, &n);
  if (!f) return ura_fail(c, "%s: out of memory", who);
  int rc = fn(c, f, arg);
  fclose(f);
  if (!rc) rc = ura_gnuplot_run(c, who, s, n);
  free(s);
  return rc;
}

/* ---- x-y curves ---- */

typedef struct {
  const char* title;
  const char* xlabel;
  const char* ylabel;
  int nser;
  const uraSeries* s;
} xyargs;

static int write_xy(uraCtx* c, FILE* f, const void* arg) {
  const xyargs* a = arg;
  for (int k = 0; k < a->nser; k++) {
    fprintf(f, "$S%d << EOD\n", k);
    for (int i = 0; i < a->s[k].n; i++) {
      ura_plot_num(f, a->s[k].x[i]);
      fputc(' ', f);
      ura_plot_num(f, a->s[k].y[i]);
      fputc('\n', f);
    }
    fprintf(f, "EOD\n");
  }
  fprintf(f, "set grid\nset key noenhanced\n");
  if (a->title) ura_plot_text(f, "title", a->title);
  if (a->xlabel) ura_plot_text(f, "xlabel", a->xlabel);
  if (a->ylabel) ura_plot_text(f, "ylabel", a->ylabel);
  fprintf(f, "plot ");
  for (int k = 0; k < a->nser; k++) {
    fprintf(f, "%s$S%d using 1:2 with linespoints pt 7 ps 0.5 lw 2 ", k ? ", " : "", k);
    if (a->s[k].title) {
      fprintf(f, "title ");
      quote(f, a->s[k].title);
    } else {
      fprintf(f, "notitle");
    }
  }
  fprintf(f, "\n");
  return 0;
}

int ura_plot_xy(uraCtx* c, const char* who, const char* title, const char* xlabel,
                const char* ylabel, int nser, const uraSeries* s) {
  if (nser < 1 || !s) return ura_fail(c, "%s: nothing to plot", who);
  for (int k = 0; k < nser; k++) {
    if (s[k].n < 1 || !s[k].x || !s[k].y) return ura_fail(c, "%s: empty curve", who);
  }
  xyargs a = {title, xlabel, ylabel, nser, s};
  return ura_plot_script(c, who, write_xy, &a);
}
