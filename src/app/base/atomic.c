/* atomic.c: files written whole or not at all. A regular file (or a new one) is written to a
 * temporary file beside it, flushed to the disk and renamed over it when complete, removed on any
 * error, Ctrl-C, SIGTERM or SIGHUP (interrupt.c): the old file stays intact. Symbolic links are
 * followed to the file they name (the link stays a link), and the new file keeps the mode of the
 * file it replaces (a new one: 0666 less the umask).
 * What is not a regular file is never replaced: a FIFO or a character device (/dev/null, a
 * terminal) is written in place, and so is an open descriptor named /dev/stdout, /dev/stderr,
 * /dev/fd/N or /proc/self/fd/N (through a duplicate, at its offset); directories, block devices
 * and sockets are refused. Every write error is reported with its own reason (a full disk is
 * "No space left on device"), and Ctrl-C stops a write that waits (a FIFO without a reader, a
 * pipe that is full) within 0.1 s.
 * A file another process writes (gnuplot's plots) is opened with ura_atomic_open_file: only a
 * regular file (or a new one) is accepted, the other process writes the temporary file by its
 * name, and the caller checks it before ura_atomic_close renames it.
 */
#define _GNU_SOURCE /* fopencookie */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "base.h"


/* stdio writes through here, so that the first error keeps its errno */
static ssize_t cookie_write(void* ck, const char* buf, size_t n) {
  uraAtomic* a = ck;
  size_t done = 0;
  while (done < n && !a->err) {
    ssize_t k = write(a->fd, buf + done, n - done);
    if (k > 0) {
      done += (size_t)k;
    } else if (k < 0 && errno == EINTR && !ura_interrupted()) {
      continue;
    } else {
      a->err = k < 0 ? (ura_interrupted() ? EINTR : errno) : EIO;
    }
  }
  return a->err ? 0 : (ssize_t)n;
}

static int cookie_close(void* ck) {
  return 0;
}

/* the descriptor an open-descriptor name stands for (/dev/stdout ...), or -1 */
static int named_fd(const char* path) {
  static const char* const pre[] = {"/dev/fd/", "/proc/self/fd/", NULL};
  if (!strcmp(path, "/dev/stdout")) return STDOUT_FILENO;
  if (!strcmp(path, "/dev/stderr")) return STDERR_FILENO;
  for (int i = 0; pre[i]; i++) {
    size_t n = strlen(pre[i]);
    char* end;
    if (strncmp(path, pre[i], n) || !path[n]) continue;
    long fd = strtol(path + n, &end, 10);
    if (!*end && fd >= 0 && fd < INT_MAX && path[n] >= '0' && path[n] <= '9') return (int)fd;
  }
  return -1;
}

/* the file a chain of symbolic links ends at, existing or not, into out (n bytes); 0 or errno */
static int follow(const char* path, char* out, size_t n) {
  char cur[PATH_MAX], target[PATH_MAX];
  if (strlen(path) >= sizeof cur) return ENAMETOOLONG;
  strcpy(cur, path);
  for (int hops = 0;; hops++) {
    struct stat sb;
    if (lstat(cur, &sb) || !S_ISLNK(sb.st_mode)) break;
    if (hops == 40) return ELOOP;
    ssize_t k = readlink(cur, target, sizeof target - 1);
    if (k < 0) return errno;
    target[k] = 0;
    if (target[0] == '/') {
      strcpy(cur, target);
    } else {
      char* slash = strrchr(cur, '/');
      size_t dir = slash ? (size_t)(slash - cur) + 1 : 0;
      if (dir + (size_t)k >= sizeof cur) return ENAMETOOLONG;
      memcpy(cur + dir, target, (size_t)k + 1);
    }
  }

  /* an existing file: its real name (the links of its directories resolved too) */
  char real[PATH_MAX];
  const char* r = realpath(cur, real) ? real : cur;
  if (strlen(r) >= n) return ENAMETOOLONG;
  strcpy(out, r);
  return 0;
}

static const char* kind_of(mode_t m) {
  return S_ISDIR(m)    ? "a directory"
         : S_ISBLK(m)  ? "a block device"
         : S_ISSOCK(m) ? "a socket"
                       : "not a regular file";
}

/* open a FIFO or device for writing in place; a FIFO without a reader is waited for (Ctrl-C
   stops the wait) */
static int open_in_place(const char* path) {
  struct timespec tick = {0, 50000000};
  for (;;) {
    int fd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd >= 0) {
      fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    if (errno != ENXIO && errno != EINTR) return -1;
    if (ura_interrupted()) {
      errno = EINTR;
      return -1;
    }
    nanosleep(&tick, NULL);
  }
}

/* a failure message into err (nerr bytes); -1 */
static int afail(char* err, size_t nerr, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));
static int afail(char* err, size_t nerr, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, nerr, fmt, ap);
  va_end(ap);
  return -1;
}

static int fail_open(char* err, size_t nerr, const char* who, const char* path, int e) {
  if (e == EINTR && ura_interrupted()) {
    return afail(err, nerr, "%s: interrupted (Ctrl-C) while opening '%s'", who, path);
  }
  return afail(err, nerr, "%s: cannot write '%s': %s", who, path, strerror(e));
}

int ura_atomic_begin(uraAtomic* a, const char* path, const char* who, int regular, char* err,
                     size_t nerr) {
  memset(a, 0, sizeof *a);
  a->fd = -1;
  if (!*path || strlen(path) >= sizeof a->path - 16) {
    return afail(err, nerr, "%s: cannot write '%.200s': %s; accepted: a file name of 1 to %d bytes",
                 who, path, *path ? "name too long" : "empty name", (int)sizeof a->path - 17);
  }
  snprintf(a->path, sizeof a->path, "%s", path);

  /* what the name stands for */
  int dupfd = named_fd(path);
  struct stat sb;
  int exists = dupfd >= 0 ? fstat(dupfd, &sb) == 0 : stat(path, &sb) == 0;
  if (dupfd >= 0 && !exists) return fail_open(err, nerr, who, path, errno);
  if (!exists && errno != ENOENT) return fail_open(err, nerr, who, path, errno);
  if (regular && (dupfd >= 0 || (exists && !S_ISREG(sb.st_mode)))) {
    return afail(err, nerr,
                 "%s: cannot write '%s': it %s %s; accepted: a regular file, replaced "
                 "whole when complete (not a device, a FIFO or an open descriptor such as "
                 "/dev/stdout: a text terminal such as dumb without an output draws on "
                 "standard output); nothing was written",
                 who, path, dupfd >= 0 ? "names" : "is",
                 dupfd >= 0             ? "an open descriptor"
                 : S_ISFIFO(sb.st_mode) ? "a FIFO"
                 : S_ISCHR(sb.st_mode)  ? "a character device"
                                        : kind_of(sb.st_mode));
  }
  if (exists && !S_ISREG(sb.st_mode) && !S_ISFIFO(sb.st_mode) && !S_ISCHR(sb.st_mode)) {
    return afail(err, nerr,
                 "%s: cannot write '%s': it is %s; accepted: a regular file (replaced "
                 "whole), a FIFO or a character device such as /dev/stdout (written in place); "
                 "the file is unchanged",
                 who, path, kind_of(sb.st_mode));
  }

  if (dupfd >= 0 || (exists && !S_ISREG(sb.st_mode))) {
    /* in place: an open descriptor through a duplicate (its offset), a FIFO or a device */
    if (dupfd >= 0) fflush(NULL);
    a->fd = dupfd >= 0 ? fcntl(dupfd, F_DUPFD_CLOEXEC, 3) : open_in_place(path);
    if (a->fd < 0) return fail_open(err, nerr, who, path, errno);
    a->inplace = 1;
  } else {
    /* a regular file (or none yet): a temporary file beside the file the links name */
    int e = follow(path, a->real, sizeof a->real);
    if (!e && snprintf(a->tmp, sizeof a->tmp, "%s.tmp.XXXXXX", a->real) >= (int)sizeof a->tmp) {
      e = ENAMETOOLONG;
    }
    if (e) return fail_open(err, nerr, who, path, e);
    a->fd = mkstemp(a->tmp);
    if (a->fd < 0) return fail_open(err, nerr, who, path, errno);
    ura_temp_arm(a->tmp); /* SIGTERM, SIGHUP or a fatal Ctrl-C remove it */

    /* the mode of the file replaced, or what a plain fopen would give */
    mode_t um = umask(0);
    umask(um);
    mode_t mode = exists ? sb.st_mode & 07777 : 0666 & ~um;
    fchmod(a->fd, mode);
  }

  cookie_io_functions_t io = {NULL, cookie_write, NULL, cookie_close};
  a->f = fopencookie(a, "w", io);
  if (!a->f) {
    int e = errno;
    close(a->fd);
    if (!a->inplace) remove(a->tmp);
    ura_temp_disarm();
    return fail_open(err, nerr, who, path, e);
  }
  return 0;
}

int ura_atomic_end(uraAtomic* a, int ok, const char* who, char* err, size_t nerr) {
  int bad = !ok || fflush(a->f) || ferror(a->f) || a->err;
  int e = a->err ? a->err : errno;
  fclose(a->f);
  a->f = NULL;
  if (!bad && !a->inplace && fsync(a->fd)) bad = 1, e = errno;
  if (close(a->fd) && !bad) bad = 1, e = errno;
  a->fd = -1;
  if (!bad && !a->inplace && rename(a->tmp, a->real)) bad = 1, e = errno;
  if (bad && !a->inplace) remove(a->tmp);
  if (!a->inplace) ura_temp_disarm();
  if (!bad) return 0;
  if (!ok) return -1;
  if (e == EINTR && ura_interrupted()) {
    return afail(err, nerr, "%s: interrupted (Ctrl-C) while writing '%s'%s", who, a->path,
                 a->inplace ? "" : "; the file is unchanged");
  }
  return afail(err, nerr, "%s: cannot write '%s': %s%s", who, a->path, strerror(e),
               a->inplace ? "" : "; the file is unchanged");
}
