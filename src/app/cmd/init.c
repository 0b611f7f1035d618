/* init.c: the start-up file, $XDG_CONFIG_HOME/uasimpact/init (~/.config/uasimpact/init when
 * XDG_CONFIG_HOME is unset, empty or not absolute): one's own defaults, read before an
 * interactive session (main.c; -n skips it). It is data in the script language that may only
 * set things: set, case, dist, model load and drop, source (whose lines are held to the same
 * rule), undo and show. Anything that computes, plots or writes a file (save, export, report,
 * model save, grid, ...) is refused with the file and line, so that a start-up file never writes
 * a file the user did not name at the prompt; the first refused or failing line ends the file,
 * the session goes on with what the lines before it set. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd.h"


/* the commands a start-up file may run (model: only its words that do not write) */
static int init_guard(uraCtx* c, int argc, char** argv) {
  static const char* const ok[] = {"set", "case", "dist", "source", "undo", "show", NULL};
  for (int i = 0; ok[i]; i++)
    if (!strcmp(argv[0], ok[i])) return 0;
  if (!strcmp(argv[0], "model") && argc >= 2 &&
      (!strcmp(argv[1], "load") || !strcmp(argv[1], "drop") || !strcmp(argv[1], "params") ||
       !strcmp(argv[1], "parts") || !strcmp(argv[1], "notes")))
    return 0;
  char what[80];
  snprintf(what, sizeof what, "%s%s%s", argv[0], argc >= 2 && !strcmp(argv[0], "model") ? " " : "",
           argc >= 2 && !strcmp(argv[0], "model") ? argv[1] : "");
  return ura_fail(c,
                  "'%s' is not accepted in a start-up file; accepted: set, case, dist, model "
                  "load, model drop, source, undo, show (it may only set things)",
                  what);
}

int ura_init_path(char* buf, size_t n) {
  const char* xdg = getenv("XDG_CONFIG_HOME");
  const char* home = getenv("HOME");
  int k;
  if (xdg && xdg[0] == '/')
    k = snprintf(buf, n, "%s/uasimpact/init", xdg);
  else if (home && *home)
    k = snprintf(buf, n, "%s/.config/uasimpact/init", home);
  else
    return -1;
  return k > 0 && (size_t)k < n ? 0 : -1;
}

int ura_run_init(uraCtx* c) {
  char path[4096];
  if (ura_init_path(path, sizeof path)) return 0;
  FILE* f = fopen(path, "r");
  if (!f) {
    if (errno == ENOENT || errno == ENOTDIR) return 0; /* no start-up file: nothing to do */
    fprintf(c->msg, "uasimpact: start-up file '%s' not read: %s (-n skips it)\n", path,
            strerror(errno));
    return -1;
  }
  fclose(f);
  int (*keep)(uraCtx*, int, char**) = c->guard;
  c->guard = init_guard;
  int rc = ura_run_file(c, path);
  c->guard = keep;
  if (rc) {
    ura_locate(c, path, 0);
    fprintf(c->msg, "%s (the start-up file stopped there; -n skips it)\n", c->err);
    c->err_located = 0;
  }
  return rc;
}
