/* fuzz_run.c: libFuzzer target for the command language, executing: each input is a session
 * script run by the real reader and dispatcher (ura_run_stream) on the real code paths that the
 * dry target (fuzz_script.c) only parses: impacts, grids, sweeps and compare run their
 * simulations, files are written and read (export, save session, model save and load, grid
 * load, source), and plots go through a fake gnuplot. A guard (uraCtx.guard) keeps each input
 * short and contained, refusing a command as the application refuses a bad one:
 *   - simulations only on the parts of the fresh state (the built-in ones, with the simulation
 *     part loaded from bin/sim.urm: tmax 0.02 s), with at most 400 steps of one impact, no
 *     setting that would settle the person again (only the drone's, airbags' and these
 *     simulation parameters may be set: tmax, window, t_quiet, t_clear), at most 2 threads,
 *     grids of at most 49 cells (the fresh state sets extents of 3 x 3 cells), sweeps of at
 *     most 3 values; no reset (it forgets every settled person, and settling again takes a
 *     second: the dry target runs it; a saved session therefore replays up to its reset line);
 *   - file names without '/' and not starting with '.': everything happens in a scratch folder
 *     (the working directory, emptied before each input), where bin/gnuplot is the fake, first
 *     on PATH; no display (a window plot is refused before gnuplot starts).
 * The settled stances are kept from one input to the next (the model cache, as the application
 * keeps them); everything else is as a fresh context has it. FUZZ_RUN_VERBOSE=1 prints why an
 * input stopped (to see what the inputs reach).
 *   make fuzz            (tests/fuzz/corpus_run, dictionary tests/fuzz/run.dict)
 */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../src/app/report/report.h"

#define MAXSTEPS 400 /* steps of one impact */
#define MAXCELLS 49  /* cells of one grid (at most 7 x 7) */
#define MAXSWEEP 3   /* values of one sweep */

static uraCtx c;
static uraState st0;             /* the fresh state: short impacts, a 3 x 3 grid */
static char* text0[uraMAXPARTS]; /* the parts of the fresh state */
static char* origin0[uraMAXPARTS];
static int npart0;
static char simfile[400];            /* the simulation part with short impacts */
static char allowed[256][urNAMELEN]; /* model parameters that leave the person as settled */
static int nallowed;
static FILE* null;
static char scratch[256];

static int same_parts(void) {
  if (c.npart != npart0) return 0;
  for (int i = 0; i < npart0; i++) {
    if (strcmp(c.part[i].text, text0[i]) || strcmp(c.part[i].origin, origin0[i])) return 0;
  }
  return 1;
}

/* the parameters of the drone and airbag parts, and the simulation's that only end an impact */
static void allow_params(void) {
  static const char* const sim[] = {"tmax", "window", "t_quiet", "t_clear", NULL};
  for (int i = 0; sim[i]; i++) snprintf(allowed[nallowed++], urNAMELEN, "%s", sim[i]);
  for (int i = 0; i < c.npart; i++) {
    if (strcmp(c.part[i].name, "ra3") && strcmp(c.part[i].name, "airbags")) continue;
    for (const char* p = c.part[i].text; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : 0) {
      char name[urNAMELEN];
      if (nallowed < 256 && sscanf(p, "param %31s", name) == 1) {
        snprintf(allowed[nallowed++], urNAMELEN, "%s", name);
      }
    }
  }
}

static int allowed_param(const char* name) {
  for (int i = 0; i < nallowed; i++)
    if (!strcmp(allowed[i], name)) return 1;
  return 0;
}

/* a file name in the scratch folder (or the simulation part, which save session names) */
static int plain(const char* s) {
  return (*s && *s != '.' && !strchr(s, '/') && strlen(s) <= 64) || !strcmp(s, simfile);
}

static int guard(uraCtx* x, int argc, char** argv) {
  const char* cmd = argv[0];
  if (!strcmp(cmd, "reset")) return ura_fail(x, "fuzz: reset is not run here");
  int conv = !strcmp(cmd, "converge"); /* a grid at half the step */
  int sim = !strcmp(cmd, "impact") || !strcmp(cmd, "compare") || conv ||
            (!strcmp(cmd, "grid") && argc == 1) || (!strcmp(cmd, "sweep") && argc == 3);

  /* files: a plain name (the last word of the file commands, the value of set output) */
  int file = (!strcmp(cmd, "export") || !strcmp(cmd, "save") || !strcmp(cmd, "source") ||
              !strcmp(cmd, "report") || (!strcmp(cmd, "model") && argc == 3) ||
              (!strcmp(cmd, "grid") && argc == 3));
  if (file && !plain(argv[argc - 1])) return ura_fail(x, "fuzz: not a scratch file name");
  if (!strcmp(cmd, "set") && argc >= 3 && !strcmp(argv[1], "output") && *argv[2] &&
      strcmp(argv[2], "none") && !plain(argv[2])) {
    return ura_fail(x, "fuzz: not a scratch file name");
  }
  if (!sim) return 0;

  /* simulations: the built-in parts, the person as settled, short impacts, small grids */
  if (!same_parts()) return ura_fail(x, "fuzz: no simulation on loaded parts");
  for (int i = 0; i < x->st.nov; i++) {
    if (x->st.ov_user[i] && !allowed_param(x->st.ov_name[i])) {
      return ura_fail(x, "fuzz: no simulation after setting %s", x->st.ov_name[i]);
    }
  }
  const urModel* m = ura_model(x);
  if (!m || !(m->opt.tmax / m->opt.dt <= MAXSTEPS)) {
    return ura_fail(x, "fuzz: impacts of at most %d steps", MAXSTEPS);
  }
  const urImpactSetup* donor;
  if (!x->have_setup && !ura_mcache_setups(x, &donor, 1)) {
    return ura_fail(x, "fuzz: no settling of the person here (after reset)");
  }
  if (x->st.threads > 2) return ura_fail(x, "fuzz: at most 2 threads");
  if (!strcmp(cmd, "impact")) return 0;
  double lo = x->st.par_min, hi = x->st.par_max, cross = x->st.perp_max;
  if (!x->st.par_min_set || !x->st.par_max_set || !x->st.perp_max_set) {
    double e[3];
    if (ura_grid_extents(x, &e[0], &e[1], &e[2])) return -1; /* the stance of a donor */
    if (!x->st.par_min_set) lo = e[0];
    if (!x->st.par_max_set) hi = e[1];
    if (!x->st.perp_max_set) cross = e[2];
  }
  double step = conv ? x->st.step / 2 : x->st.step;
  double rows = floor((hi - lo) / step + 1e-9) + 2;
  double cols = 2 * floor(cross / step + 1e-9) + 3;
  if (!(rows * cols <= MAXCELLS)) return ura_fail(x, "fuzz: grids of at most %d cells", MAXCELLS);
  if (!strcmp(cmd, "sweep")) {
    int n = 1;
    for (const char* p = argv[2]; *p; p++) n += *p == ',';
    if (n > MAXSWEEP) return ura_fail(x, "fuzz: sweeps of at most %d values", MAXSWEEP);
  }
  return 0;
}

/* the scratch folder emptied, but for the fake gnuplot */
static void clean(void) {
  DIR* d = opendir(".");
  struct dirent* e;
  while (d && (e = readdir(d))) {
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, "bin")) {
      if (unlink(e->d_name)) rmdir(e->d_name);
    }
  }
  if (d) closedir(d);
}

/* the built-in parts with the short simulation part (a reset, or a model load, changed them);
   the settled models stay as stance donors */
static void parts0(void) {
  char line[500];
  snprintf(line, sizeof line, "model load %s", simfile);
  c.guard = NULL;
  if (ura_models_init(&c) || ura_run_line(&c, line)) abort();
}

static void fresh(void) {
  static int ready;
  if (!ready) {
    ura_init(&c);
    if (!c.model) abort();
    c.out = c.msg = null;

    /* the simulation part with tmax 0.02 s: what 'case' and 'reset' keep */
    FILE* f = fopen(simfile, "w");
    for (int i = 0; f && i < c.npart; i++) {
      if (strcmp(c.part[i].name, "sim")) continue;
      for (const char* p = c.part[i].text; *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : "") {
        size_t n = strcspn(p, "\n");
        if (!strncmp(p, "param tmax ", 11))
          fprintf(f, "param tmax 0.02 s\n");
        else
          fprintf(f, "%.*s\n", (int)n, p);
      }
    }
    if (!f || fclose(f)) abort();
    parts0();
    npart0 = c.npart;
    for (int i = 0; i < npart0; i++) {
      text0[i] = strdup(c.part[i].text);
      origin0[i] = strdup(c.part[i].origin);
    }
    allow_params();
    static const char* const setup =
        "set step 0.1; set along_min -0.1; set along_max 0.1; set cross_max 0.1; set threads 1";
    if (ura_run_line(&c, setup)) abort();
    st0 = c.st;
    ready = 1;
  } else if (!same_parts()) {
    c.st = st0;
    parts0();
  }

  /* a settled person to share (a reset forgot them all): settled once more */
  const urImpactSetup* donor;
  if (!c.have_setup && !ura_mcache_setups(&c, &donor, 1) &&
      ura_model_state(&c, &st0, "fuzz") == 0 && !ura_setup(&c)) {
    abort();
  }

  /* results of the last input go; the settled stances stay (model cache) */
  char* clear[] = {"sweep", "clear", NULL};
  ura_cmd_sweep(&c, 2, clear);
  ura_last_free(&c);
  if (c.have_work) ur_impact_work_free(&c.work);
  c.have_work = c.have_impact = 0;
  ura_interrupt_clear();
  if (ura_model_state(&c, &st0, "fuzz")) abort();
  c.out = c.msg = null;
  c.dry = 0;
  c.quit = 0;
  c.depth = 0;
  c.err[0] = 0;
  c.guard = guard;
  c.inspect = ura_inspect_cell;
  ura_report_install(&c); /* report keeps what the script prints, as the program does */
}

/* the scratch folder goes with the process */
static void remove_scratch(void) {
  if (!*scratch || chdir(scratch)) return;
  clean();
  unlink("bin/gnuplot");
  unlink("bin/sim.urm");
  rmdir("bin");
  if (!chdir("/")) rmdir(scratch);
}

int LLVMFuzzerInitialize(int* argc, char*** argv) {
  null = fopen("/dev/null", "w");
  snprintf(scratch, sizeof scratch, "/tmp/uasimpact-fuzz-run.XXXXXX");
  if (!null || !mkdtemp(scratch) || chdir(scratch)) return 1;
  atexit(remove_scratch);
  mkdir("bin", 0755);
  snprintf(simfile, sizeof simfile, "%s/bin/sim.urm", scratch);
  FILE* g = fopen("bin/gnuplot", "w");
  if (!g) return 1;
  /* the output as complete as the plot's check (plot_file.c) asks: the format's first bytes and
     end marker, by the terminal; a text terminal's text */
  fprintf(
      g,
      "#!/bin/sh\n# fake gnuplot of fuzz_run: reads the script, writes its output file\n"
      "s=$(cat)\nout=$(printf '%%s\\n' \"$s\" | sed -n \"s/^set output '\\(.*\\)'\\$/\\1/p\")\n"
      "t=$(printf '%%s\\n' \"$s\" | sed -n 's/^set terminal \\([a-z]*\\).*/\\1/p')\n"
      "[ -n \"$out\" ] || exit 0\n"
      "case \"$t\" in\n"
      "  png|pngcairo) printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\0IEND\\256B`\\202' ;;\n"
      "  jpeg) printf '\\377\\330\\377\\377\\331' ;;\n"
      "  gif) printf 'GIF89a;' ;;\n"
      "  pdfcairo) printf '%%%%PDF-1.5\\n%%%%%%%%EOF\\n' ;;\n"
      "  epscairo|postscript) printf '%%%%!PS-Adobe-3.0\\n%%%%%%%%Trailer\\n%%%%%%%%EOF\\n' ;;\n"
      "  svg) printf '<svg>\\n</svg>\\n' ;;\n"
      "  canvas) printf '<html>\\n</html>\\n' ;;\n"
      "  *) echo fake ;;\n"
      "esac >\"$out\"\nexit 0\n");
  fclose(g);
  chmod("bin/gnuplot", 0755);
  char path[400];
  snprintf(path, sizeof path, "%s/bin:/usr/bin:/bin", scratch);
  setenv("PATH", path, 1);
  setenv("HOME", scratch, 1);
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  clean();
  fresh();
  FILE* f = fmemopen((void*)data, size, "r");
  if (!f) return 0;
  int rc = ura_run_stream(&c, f, "fuzz");
  fclose(f);
  if (rc && getenv("FUZZ_RUN_VERBOSE")) fprintf(stderr, "fuzz_run: %s\n", c.err);
  /* a failure leaves one printable message line */
  if (strlen(c.err) >= sizeof c.err || strchr(c.err, '\n') || strchr(c.err, '\033')) abort();
  return 0;
}
