/* atomic.c: files written whole or not at all: a temporary file beside the target, flushed to
 * the disk and renamed over it when complete, removed on any error (the old file stays intact).
 * The new file keeps the mode of the file it replaces (a new one: 0666 less the umask). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"

int ura_atomic_open(uraCtx* c, uraAtomic* a, const char* path, const char* who) {
  a->f = NULL;
  if (ura_dry(c, who)) return -1;
  if (!*path || strlen(path) >= sizeof a->path - 16) {
    return ura_fail(c, "%s: cannot write '%.200s': %s; accepted: a file name of 1 to %d bytes",
                    who, path, *path ? "name too long" : "empty name", (int)sizeof a->path - 17);
  }
  snprintf(a->path, sizeof a->path, "%s", path);
  snprintf(a->tmp, sizeof a->tmp, "%s.tmp.XXXXXX", path);
  int fd = mkstemp(a->tmp);

  /* mkstemp makes the file private (0600); the result gets the usual mode under the umask */
  mode_t mask = umask(0);
  umask(mask);
  if (fd >= 0) fchmod(fd, 0666 & ~mask);
  a->f = fd >= 0 ? fdopen(fd, "w") : NULL;
  if (!a->f) {
    int e = errno;
    if (fd >= 0) {
      close(fd);
      remove(a->tmp);
    }
    return ura_fail(c, "%s: cannot write '%s': %s", who, path, strerror(e));
  }

  /* the mode of the file replaced, or what a plain fopen would give */
  struct stat sb;
  mode_t mode;
  if (stat(path, &sb) == 0 && S_ISREG(sb.st_mode)) {
    mode = sb.st_mode & 07777;
  } else {
    mode_t um = umask(0);
    umask(um);
    mode = 0666 & ~um;
  }
  fchmod(fd, mode);
  return 0;
}

int ura_atomic_close(uraCtx* c, uraAtomic* a, int ok, const char* who) {
  int bad = !ok || fflush(a->f) || ferror(a->f) || fsync(fileno(a->f));
  int e = errno;
  if (fclose(a->f)) bad = 1, e = errno;
  a->f = NULL;
  if (!bad && rename(a->tmp, a->path)) bad = 1, e = errno;
  if (bad) {
    remove(a->tmp);
    return ok ? ura_fail(c, "%s: cannot write '%s': %s; the file is unchanged", who, a->path,
                         strerror(e)) : -1;
  }
  return 0;
}
