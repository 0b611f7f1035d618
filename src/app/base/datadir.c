/* datadir.c: the installed sessions and example models. 'make install' puts them under
 * PREFIX/share/uasimpact/ (sessions/NAME.ses, sessions/quad/quad.urm, ...), beside PREFIX/bin; a
 * relative name that is not in the current folder (source tour.ses, model load quad.urm) is
 * looked for there: in that folder, in its sessions/, then in each folder of sessions/ in name
 * order. The folder is found from the program's own place (/proc/self/exe, ../share/uasimpact),
 * so an installed tree works wherever it was put (a scratch prefix, DESTDIR staging moved into
 * place); a program run from its build folder has none. */
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base.h"


int ura_data_dir(char* buf, size_t n) {
  char exe[PATH_MAX];
  ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (k <= 0) return -1;
  exe[k] = 0;
  char* slash = strrchr(exe, '/');
  if (!slash) return -1;
  *slash = 0;
  int w = snprintf(buf, n, "%s/../share/uasimpact", exe);
  struct stat sb;
  return w > 0 && (size_t)w < n && stat(buf, &sb) == 0 && S_ISDIR(sb.st_mode) ? 0 : -1;
}

/* open dir/path for reading when it is a regular file; the name into found */
static FILE* try_open(const char* dir, const char* path, char* found, size_t n) {
  int w = snprintf(found, n, "%s/%s", dir, path);
  struct stat sb;
  if (w <= 0 || (size_t)w >= n || stat(found, &sb) || !S_ISREG(sb.st_mode)) return NULL;
  return fopen(found, "r");
}

/* folders of sessions/ only (not . or ..) */
static int is_sub(const struct dirent* e) {
  return e->d_name[0] != '.';
}

FILE* ura_data_open(const char* path, char* found, size_t n) {
  snprintf(found, n, "%s", path);
  FILE* f = fopen(path, "r");
  int e = errno;
  if (f || path[0] == '/' || !*path || e != ENOENT) return f;
  char dir[PATH_MAX], sess[PATH_MAX + 16];
  if (ura_data_dir(dir, sizeof dir)) {
    errno = e;
    return NULL;
  }
  snprintf(sess, sizeof sess, "%s/sessions", dir);
  if ((f = try_open(dir, path, found, n)) || (f = try_open(sess, path, found, n))) return f;
  struct dirent** list = NULL;
  int m = scandir(sess, &list, is_sub, alphasort);
  for (int i = 0; i < m; i++) {
    char sub[2 * PATH_MAX];
    snprintf(sub, sizeof sub, "%s/%s", sess, list[i]->d_name);
    if (!f) f = try_open(sub, path, found, n);
    free(list[i]);
  }
  free(list);
  if (!f) {
    snprintf(found, n, "%s", path);
    errno = e;
  }
  return f;
}

void ura_dir_of(const char* path, char* buf, size_t n) {
  const char* slash = strrchr(path, '/');
  if (!slash)
    snprintf(buf, n, ".");
  else if (slash == path)
    snprintf(buf, n, "/");
  else
    snprintf(buf, n, "%.*s", (int)(slash - path), path);
}
