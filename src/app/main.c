/* main.c: command line: uasimpact [-i] [-n] [-c COMMANDS] [FILE]... (-h, -V) */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "report/report.h"
#include "scale/scale.h"

static void usage(FILE* f) {
  fprintf(f,
          "usage: uasimpact [-i] [-n] [-c COMMANDS] [FILE]...\n"
          "       uasimpact --shard I/N --part OUT [-c COMMANDS] [FILE]...\n"
          "       uasimpact merge [-c COMMANDS] [--script FILE]... PART...\n"
          "  with no arguments: interactive on a terminal, else replay standard input\n"
          "  FILE         replay a session script\n"
          "  -c COMMANDS  run commands (separated by ';')\n"
          "  -i           stay interactive after the scripts and commands\n"
          "  -n           do not read the start-up file (~/.config/uasimpact/init)\n"
          "  -h, --help   this text; see uasimpact(1)\n"
          "  -V, --version  the version and the commit it was built from\n");
}

/* the exit status, after what is still buffered for standard output was written: a failed
   write is one message and status 1 (unless the run failed already) */
static uraCtx ctx;

static int done(int rc) {
  rc = ura_scale_end(&ctx, rc); /* a shard's part written; MPI finished */
  errno = 0;
  int bad = fflush(ctx.out) || ferror(ctx.out);
  int e = ura_out_errno() ? ura_out_errno() : errno;
  if (!bad) bad = fflush(stdout) || ferror(stdout), e = errno;
  if (bad) {
    fprintf(stderr, "uasimpact: cannot write standard output: %s\n", strerror(e ? e : EIO));
    return rc ? rc : 1;
  }
  return rc;
}

int main(int argc, char** argv) {
  uraCtx* c = &ctx;

  /* Ctrl-C stops work, not the program; a file size limit is a write error, not a kill */
  ura_interrupt_install(0);
  signal(SIGXFSZ, SIG_IGN);
  ura_init(c);
  c->inspect = ura_inspect_cell; /* the viewer's Enter runs a cell's impact (cmd layer) */
  ura_report_install(c);         /* what the session computes is kept for report */

  /* results to a file or a pipe through a stream that keeps why a write failed */
  if (!isatty(STDOUT_FILENO)) {
    FILE* out = ura_out_stream(STDOUT_FILENO);
    if (out) c->out = out;
  }
  if (!c->model) fprintf(stderr, "uasimpact: warning: built-in model: %s\n", c->err);

  /* --shard I/N --part OUT, merge [-c COMMANDS] [--script FILE]... PART..., or an MPI rank
     (scale.h) */
  int st = ura_scale_args(c, &argc, &argv);
  c->scale_grid = ura_scale_grid;   /* called by each grid when c->scale is set */
  c->scale_input = ura_scale_input; /* called for each file the run reads */
  if (st) return done(st);

  /* options first: -i anywhere, help */
  int stay = 0, work = 0, noinit = 0;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
      usage(stdout);
      return done(0);
    } else if (!strcmp(argv[i], "-V") || !strcmp(argv[i], "--version")) {
      fprintf(stdout, "%s\n", ura_version());
      return done(0);
    } else if (!strcmp(argv[i], "-i")) {
      stay = 1;
    } else if (!strcmp(argv[i], "-n")) {
      noinit = 1;
    } else if (!strcmp(argv[i], "-c")) {
      if (i + 1 >= argc) {
        fprintf(stderr, "uasimpact: -c needs the commands as its argument\n");
        return 2;
      }
      i++;
      work = 1;
    } else if (argv[i][0] == '-' && argv[i][1]) {
      fprintf(stderr, "uasimpact: unknown option '%s'\n", argv[i]);
      usage(stderr);
      return 2;
    } else {
      work = 1;
    }
  }

  /* an interactive session starts from one's start-up file (a script alone never reads it: it
     gives the same results on every machine); a failing line is reported, the session goes on */
  int interactive = stay || (!work && isatty(STDIN_FILENO));
  if (interactive && !noinit) {
    ura_run_init(c);
    ura_undo_free(c); /* undo goes back no further than the start-up state */
  }

  /* scripts and -c commands in the order given; the first failure ends the run */
  for (int i = 1; i < argc && !c->quit; i++) {
    int rc = 0;
    if (!strcmp(argv[i], "-i") || !strcmp(argv[i], "-n")) continue;
    if (!strcmp(argv[i], "-c")) {
      rc = ura_run_line(c, argv[++i]);
      if (rc) ura_locate(c, "-c", 1);
    } else {
      rc = ura_run_file(c, argv[i]);
      if (rc) ura_locate(c, argv[i], 0);
    }
    if (rc) {
      fprintf(stderr, "%s\n", c->err);
      if (!stay) return done(ura_interrupted() ? 130 : 1);
      break;
    }
  }
  if (c->quit) return done(0);

  /* interactive on a terminal; otherwise standard input is a script */
  if (stay || (!work && isatty(STDIN_FILENO))) return done(ura_repl(c));
  if (!work) {
    if (ura_run_stream(c, stdin, "<stdin>")) {
      fprintf(stderr, "%s\n", c->err);
      return done(ura_interrupted() ? 130 : 1);
    }
  }
  return done(0);
}
