/* plot.c: gnuplot as an external process. A plot is a complete script (commands and named
 * datablocks $D << EOD ... EOD) built in memory, then written to gnuplot's standard input
 * through a pipe; we wait for gnuplot to exit, so an output file is complete on return, and
 * read its error output from a temporary file. SIGPIPE is ignored around the writes, a missing
 * gnuplot or a missing display gives one clear message, and nothing here ends the program.
 */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
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

#include "colors.h"
#include "plot.h"

#define GP_TIMEOUT 60.0 /* s: gnuplot taking longer than this is stopped */
#define NPOF       241  /* points per PoF curve */

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

/* the terminal and output preamble, or -1 with the error recorded: both checked again (they
   are checked when set), the terminal as we write it, the output as a quoted string */
static int preamble(uraCtx* c, const char* who, FILE* f, int* window) {
  char term[512], out[512];
  if (*c->st.terminal && ura_terminal_check(c, c->st.terminal, term, sizeof term)) return -1;
  if (*c->st.output && ura_output_check(c, c->st.output, out, sizeof out)) return -1;
  if (!*c->st.terminal) term[0] = 0;
  if (!*c->st.output) out[0] = 0;
  if (*out && !*term) {
    const char* t = ura_term_for_ext(out);
    if (!t) {
      return ura_fail(c,
                      "%s: no terminal for output '%s'; use 'set terminal png' (or svg, "
                      "pdfcairo, ...)",
                      who, out);
    }
    snprintf(term, sizeof term, "%s", t);
  }
  int kind = ura_term_kind(term);
  if (!*out && kind == uraTERM_FILE) {
    return ura_fail(c, "%s: terminal '%s' writes a file; use 'set output FILE'", who, term);
  }
  *window = !*out && kind == uraTERM_WINDOW;
  if (*term) put_terminal(c, f, term);
  if (*out) {
    fprintf(f, "set output ");
    quote(f, out);
    fputc('\n', f);
  }
  return 0;
}

int ura_gnuplot_run(uraCtx* c, const char* who, const char* script, size_t len) {
  if (ura_dry(c, who)) return -1;
  if (c->mute) return 0; /* a shard or an MPI rank but 0 draws nothing */
  /* the settings, then gnuplot and a display */
  char* pre = NULL;
  size_t npre = 0;
  FILE* pf = open_memstream(&pre, &npre);
  if (!pf) return ura_fail(c, "%s: out of memory", who);
  int window = 0;
  int rc = preamble(c, who, pf, &window);
  fclose(pf);
  if (rc) {
    free(pre);
    return -1;
  }
  if (!have_gnuplot()) {
    free(pre);
    return ura_fail(c, "%s: gnuplot not found; install it (Debian: gnuplot-nox) or use export",
                    who);
  }
  const char* d = getenv("DISPLAY");
  const char* w = getenv("WAYLAND_DISPLAY");
  if (window && !(d && *d) && !(w && *w)) {
    free(pre);
    return ura_fail(c, "plot: no display; use 'set terminal png' and 'set output FILE.png'");
  }

  /* gnuplot reads the pipe; its output and errors go to temporary files */
  FILE* ef = tmpfile();
  FILE* of = tmpfile();
  int fd[2] = {-1, -1};
  if (!ef || !of || pipe(fd)) {
    if (ef) fclose(ef);
    if (of) fclose(of);
    free(pre);
    return ura_fail(c, "%s: cannot start gnuplot: %s", who, strerror(errno));
  }
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
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
  close(fd[0]);
  if (pid < 0) {
    close(fd[1]);
    fclose(ef);
    fclose(of);
    free(pre);
    return ura_fail(c, "%s: cannot start gnuplot: %s", who, strerror(errno));
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
  if (!werr && strstr(pre, "set output")) {
    werr = write_all(fd[1], "unset output\n", 13, deadline);
  }
  close(fd[1]);
  sigaction(SIGPIPE, &old, NULL);

  /* wait for gnuplot, stopping it at the deadline or on Ctrl-C */
  int status = 0, waited = 0;
  struct timespec tick = {0, 5000000};
  for (;;) {
    pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid || (r < 0 && errno != EINTR)) {
      waited = r == pid;
      break;
    }
    if (now() > deadline || ura_interrupted()) break;
    nanosleep(&tick, NULL);
  }
  if (!waited) {
    kill(pid, SIGKILL);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  }

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
  /* the verdict: stopped, not found, killed, failed, or no file */
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
  } else if (*c->st.output) {
    struct stat sb;
    if (stat(c->st.output, &sb) || sb.st_size == 0) {
      rc = ura_fail(c, "%s: gnuplot wrote nothing to '%s'", who, c->st.output);
    }
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

/* ---- the grid as a heat map ---- */

/* the band colours as a stepped palette over 0..100 % */
static void band_palette(FILE* f) {
  fprintf(f,
          "set palette defined (0 '#ffffff', 0.001 '#fff3b0', %g '#fff3b0', %g '#ffe000', "
          "%g '#ffe000', %g '#ff9000', %g '#ff9000', %g '#d7191c', 100 '#d7191c')\n",
          uraBAND_MED, uraBAND_MED, uraBAND_HIGH, uraBAND_HIGH, uraBAND_SEVERE, uraBAND_SEVERE);
  fprintf(f, "set cbrange [0:100]\nset cbtics (0, %g, %g, %g, 100)\n", uraBAND_MED, uraBAND_HIGH,
          uraBAND_SEVERE);
}

static int write_grid(uraCtx* c, FILE* f, const void* arg) {
  const urGrid* g = c->last.g;
  char cond[256], q[256], title[600];

  /* the data: one scan line per along offset; unfinished cells are NaN */
  fprintf(f, "$D << EOD\n");
  for (int i = g->nrow - 1; i >= 0; i--) {
    for (int j = 0; j < g->ncol; j++) {
      const urCell* cl = &g->cell[(size_t)i * g->ncol + j];
      int fin = cl->status == urCELL_DONE || cl->status == urCELL_NOCONTACT;
      ura_plot_num(f, g->perp_min + j * g->step);
      fputc(' ', f);
      ura_plot_num(f, g->par_max - i * g->step);
      fputc(' ', f);
      ura_plot_num(f, fin ? cl->p * 100.0 : NAN);
      fputc('\n', f);
    }
    fputc('\n', f);
  }
  fprintf(f, "EOD\n");

  /* axes in metres, square cells, the band palette */
  ura_grid_conditions(c, cond, sizeof cond);
  ura_grid_qtext(g, q, sizeof q);
  snprintf(title, sizeof title, "P{F|Delta} in %%; %s", q);
  double h = g->step / 2;
  double width = (g->ncol - 1) * g->step;
  fprintf(f, "set title ");
  quote(f, cond);
  fprintf(f, ".\"\\n\".");
  quote(f, title);
  fprintf(f, " noenhanced\n");
  fprintf(f, "set xtics %g\n", width > 1.2 ? 0.4 : 0.2);
  fprintf(f,
          "set xlabel \"cross offset dperp (m), + left of the course (the paper's layout)\" "
          "noenhanced\n");
  fprintf(f, "set ylabel \"along offset dpar (m), + ahead\" noenhanced\n");
  fprintf(f, "set cblabel \"P{F|Delta} (%%)\" noenhanced\n");
  fprintf(f, "set size ratio -1\nset xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\n", g->perp_min - h,
          g->perp_min + (g->ncol - 1) * g->step + h, g->par_max - (g->nrow - 1) * g->step - h,
          g->par_max + h);
  fprintf(f, "set tics out\nset grid front lc rgb '#999999'\n");
  band_palette(f);
  fprintf(f, "plot $D using 1:2:3 with image notitle\n");
  return 0;
}

int ura_plot_grid(uraCtx* c) {
  if (!c->last.g) return ura_fail(c, "plot grid: no grid yet; run 'grid' or 'grid load FILE'");
  return ura_plot_script(c, "plot grid", write_grid, NULL);
}

/* ---- PoF curves ---- */

static int write_pof(uraCtx* c, FILE* f, const void* arg) {
  const urInjuryParams* p = arg;
  double x[NPOF], y[NPOF];
  static const char* const blocks[] = {"HIC", "NIJ", "VCT", "VCA", "VC"};
  static const urPofKind kinds[] = {urPOF_HIC, urPOF_NIJ, urPOF_VC_THORAX, urPOF_VC_ABDOMEN,
                                    urPOF_VC};
  double vcmax = 0;

  /* one datablock per curve; the Nij block also holds the AIS2+..AIS5+ curves */
  for (int k = 0; k < 5; k++) {
    if (ur_pof_curve(kinds[k], p, NPOF, x, y) != NPOF) {
      return ura_fail(c, "plot pof: the %s PoF curve cannot be computed", blocks[k]);
    }
    if (k >= 2) vcmax = fmax(vcmax, x[NPOF - 1]);
    fprintf(f, "$%s << EOD\n", blocks[k]);
    for (int i = 0; i < NPOF; i++) {
      fprintf(f, "%.9g %.9g", x[i], 100 * y[i]);
      if (kinds[k] == urPOF_NIJ) {
        double q[4];
        ur_nij_ais(x[i], p, q);
        fprintf(f, " %.9g %.9g %.9g %.9g", 100 * q[0], 100 * q[1], 100 * q[2], 100 * q[3]);
      }
      fputc('\n', f);
    }
    fprintf(f, "EOD\n");
  }

  /* four panels on a canvas sized for them (ura_plot_pof): HIC, Nij, the AIS curves of Nij,
     VC; keys outside the data, right of their panel */
  fprintf(f,
          "set grid\nset yrange [0:100]\nset ylabel \"P (%%)\"\n"
          "set key outside right top vertical Left reverse samplen 2 noenhanced\n");
  fprintf(f,
          "set multiplot layout 2,2 title \"probability of fatality curves "
          "(uasrisk-injury(7))\" noenhanced\n");
  fprintf(f,
          "set title \"HIC15 -> P_HIC\" noenhanced\nset xlabel \"HIC15\"\n"
          "set xtics 1000\nplot $HIC using 1:2 with lines lw 2 notitle\n");
  fprintf(f,
          "set title \"Nij -> P_NI (C.3)\" noenhanced\nset xlabel \"Nij\"\n"
          "set xtics autofreq\nplot $NIJ using 1:2 with lines lw 2 notitle\n");
  fprintf(f,
          "set title \"Nij -> P(AIS >= k)\" noenhanced\n"
          "plot for [k=2:5] $NIJ using 1:(column(k+1)) with lines lw 2 "
          "title sprintf(\"AIS%%d+\", k)\n");
  fprintf(f,
          "set title \"VC -> P_VC\" noenhanced\nset xlabel \"VC (m/s)\"\n"
          "set xrange [0:%.9g]\n"
          "plot $VCT using 1:2 with lines lw 2 title \"thorax\", "
          "$VCA using 1:2 with lines lw 2 title \"abdomen\", "
          "$VC using 1:2 with lines lw 2 dt 2 title \"fused\"\n",
          vcmax);
  fprintf(f, "unset multiplot\n");
  return 0;
}

int ura_plot_pof(uraCtx* c, const urInjuryParams* p) {
  urInjuryParams def;
  if (!p) {
    ur_injury_defaults(&def);
    p = &def;
  }
  ura_plot_canvas(c, 1280, 860);
  int rc = ura_plot_script(c, "plot pof", write_pof, p);
  ura_plot_canvas(c, 0, 0);
  return rc;
}

/* ---- the command ---- */

int ura_cmd_plot(uraCtx* c, int argc, char** argv) {
  const char* what = argv[1];
  if (!strcmp(what, "history")) {
    uraTrace tr;
    if (ura_last_trace(c, &tr)) return ura_fail(c, "plot history: no impact yet; run 'impact'");
    return ura_plot_trace(c, &tr, argc - 2, (const char* const*)argv + 2);
  }
  if (!strcmp(what, "sweep") && argc <= 3) return ura_plot_sweep(c, argc == 3 ? argv[2] : NULL);
  if (argc > 2) return ura_fail(c, "plot %s: takes no arguments", what);
  if (!strcmp(what, "montecarlo") || !strcmp(what, "tornado")) return ura_plot_mc(c, what);
  if (!strcmp(what, "pof")) return ura_plot_pof(c, &c->st.injury);
  if (!strcmp(what, "grid")) return ura_plot_grid(c);
  if (!strcmp(what, "bag")) return ura_plot_bag(c);
  uraSuggest sg;
  char dym[120];
  ura_suggest_init(&sg, what);
  ura_suggest_keywords(&sg, ura_cmd_find("plot")->usage + strlen("plot "));
  return ura_fail(c,
                  "plot: unknown plot '%s'%s; accepted: pof, grid, history SIGNAL..., sweep "
                  "[wind|face], montecarlo, tornado, bag",
                  what, ura_suggest_text(&sg, dym, sizeof dym));
}
