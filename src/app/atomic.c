/* atomic.c: files written whole or not at all: a temporary file beside the target, renamed over
 * it when complete, removed on any error (the old file stays intact) */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "app.h"

int ura_atomic_open(uraCtx* c, uraAtomic* a, const char* path, const char* who) {
  snprintf(a->path, sizeof a->path, "%s", path);
  snprintf(a->tmp, sizeof a->tmp, "%.1000s.tmp.XXXXXX", path);
  int fd = mkstemp(a->tmp);

  /* mkstemp makes the file private (0600); the result gets the usual mode under the umask */
  mode_t mask = umask(0);
  umask(mask);
  if (fd >= 0) fchmod(fd, 0666 & ~mask);
  a->f = fd >= 0 ? fdopen(fd, "w") : NULL;
  if (!a->f) {
    if (fd >= 0) remove(a->tmp);
    return ura_fail(c, "%s: cannot write '%s': %s", who, path, strerror(errno));
  }
  return 0;
}

int ura_atomic_close(uraCtx* c, uraAtomic* a, int ok, const char* who) {
  int bad = !ok || fflush(a->f) || ferror(a->f);
  int e = errno;
  if (fclose(a->f)) bad = 1, e = errno;
  if (!bad && rename(a->tmp, a->path)) bad = 1, e = errno;
  if (bad) {
    remove(a->tmp);
    return ok ? ura_fail(c, "%s: cannot write '%s': %s", who, a->path, strerror(e)) : -1;
  }
  return 0;
}
