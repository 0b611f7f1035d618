/* version.c: what uasimpact --version prints: the version and the commit it was built from (the
 * Makefile writes both into version.h: git's commit, -dirty with uncommitted changes, or the
 * COMMIT file of a git archive) */
#include <stdio.h>

#include "base.h"
#include "version.h"

const char* ura_version(void) {
  static char buf[128];
  snprintf(buf, sizeof buf, "uasimpact %s (commit %s)", uraVERSION,
           *uraCOMMIT ? uraCOMMIT : "unknown: not built from a git checkout or archive");
  return buf;
}
