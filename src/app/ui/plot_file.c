/* plot_file.c: is a plot file gnuplot wrote complete? A plot to a file goes to a temporary file
 * beside it (atomic.c), renamed over the file named by 'set output' only when this check passes.
 * Gnuplot does not report a failed write: on a full disk it leaves a truncated file and exits
 * with status 0. So the file must not be empty, must start as its format does and end with the
 * format's end marker (PNG's IEND chunk, JPEG's EOI, GIF's trailer, %%EOF of PDF and EPS,
 * PostScript's %%Trailer, </svg>, </html> of the canvas terminal); a text terminal's file has
 * no marker, so a file system left without a free block after it (where the write must have
 * failed) fails it. Nothing here runs gnuplot (plot.c does).
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "ui.h"

#define PEEK 4096 /* bytes read at each end of the file */

/* a format: the terminals that write it, its first bytes (nhead of them; NULL: any), a text
   its last tail bytes hold (NULL: no end marker) */
typedef struct {
  const char* name;
  const char* terms; /* blank-separated, with a blank at each end */
  const char* head;
  size_t nhead;
  const char* end;
  size_t nend;
  size_t tail;
} format;

static const format formats[] = {
    {"PNG", " png pngcairo ", "\x89PNG\r\n\x1a\n", 8, "IEND\xae\x42\x60\x82", 8, 8},
    {"JPEG", " jpeg ", "\xff\xd8\xff", 3, "\xff\xd9", 2, 2},
    {"GIF", " gif ", "GIF8", 4, ";", 1, 1},
    {"PDF", " pdfcairo ", "%PDF-", 5, "%%EOF", 5, 64},
    {"EPS", " epscairo ", "%!PS-Adobe", 10, "%%EOF", 5, 64},
    {"PostScript", " postscript ", "%!PS-Adobe", 10, "%%Trailer", 9, PEEK},
    {"SVG", " svg ", NULL, 0, "</svg>", 6, 64},
    {"HTML", " canvas ", NULL, 0, "</html>", 7, 64},
};

/* the format of a terminal setting (its first word), or NULL (text terminals: no format) */
static const format* format_of(const char* term) {
  char word[40];
  size_t n = strcspn(term, " \t");
  if (n == 0 || n >= sizeof word - 2) return NULL;
  snprintf(word, sizeof word, " %.*s ", (int)n, term);
  for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++) {
    if (strstr(formats[i].terms, word)) return &formats[i];
  }
  return NULL;
}

int ura_plot_name_check(uraCtx* c, const char* who, const char* term, const char* out) {
  const char* ext = ura_ext_format(out);
  const format* fm = format_of(term);
  if (!ext) return 0;
  const char* writes = fm ? fm->name : "text";
  /* gnuplot's postscript terminal writes EPS too (set terminal postscript eps) */
  if (!strcmp(ext, writes) || (!strcmp(ext, "EPS") && !strcmp(writes, "PostScript"))) return 0;
  const char* t = NULL;
  for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++) {
    if (!strcmp(formats[i].name, ext)) t = formats[i].terms;
  }
  char want[40] = "";
  if (t) snprintf(want, sizeof want, "%.*s", (int)strcspn(t + 1, " "), t + 1);
  if (!strcmp(ext, "text")) snprintf(want, sizeof want, "dumb");
  size_t nt = strcspn(term, " \t");
  const char* mine = ura_format_ext(writes);
  char named[64] = "one named for its terminal's format";
  if (mine) snprintf(named, sizeof named, "a name ending in .%s", mine);
  return ura_fail(c,
                  "%s: the extension of output '%s' says %s, but terminal '%.*s' writes %s; "
                  "accepted: %s%s%s",
                  who, out, ext, (int)nt, term, writes, named, *want ? ", or set terminal " : "",
                  want);
}

/* n bytes in the last m of buf (k bytes) */
static int ends_with(const char* buf, size_t k, const char* s, size_t n, size_t m) {
  if (m > k) m = k;
  for (size_t i = k - m; i + n <= k; i++) {
    if (!memcmp(buf + i, s, n)) return 1;
  }
  return 0;
}

/* no free block left for us on the file system of path (where a write must have failed) */
static int disk_full(const char* path) {
  struct statvfs sv;
  if (statvfs(path, &sv)) return 0;
  unsigned long long avail = geteuid() == 0 ? sv.f_bfree : sv.f_bavail;
  return avail == 0;
}

int ura_plot_file_check(uraCtx* c, const char* who, const char* tmp, const char* term,
                        const char* shown) {
  const format* fm = format_of(term);
  char head[PEEK], tail[PEEK];
  struct stat sb;
  int fd = open(tmp, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0 || fstat(fd, &sb)) {
    int e = errno;
    if (fd >= 0) close(fd);
    return ura_fail(c, "%s: cannot read back the plot for '%s': %s; the file is unchanged", who,
                    shown, strerror(e));
  }
  ssize_t nh = sb.st_size > 0 ? pread(fd, head, sizeof head, 0) : 0;
  off_t at = sb.st_size > PEEK ? sb.st_size - PEEK : 0;
  ssize_t nt = sb.st_size > 0 ? pread(fd, tail, sizeof tail, at) : 0;
  int e = errno;
  close(fd);
  if (nh < 0 || nt < 0) {
    return ura_fail(c, "%s: cannot read back the plot for '%s': %s; the file is unchanged", who,
                    shown, strerror(e));
  }

  /* what is wrong, if anything; a full disk is the likely reason of an incomplete file */
  const char* why = NULL;
  char buf[160];
  if (sb.st_size == 0) {
    why = "gnuplot wrote nothing";
  } else if (fm && fm->head && ((size_t)nh < fm->nhead || memcmp(head, fm->head, fm->nhead))) {
    snprintf(buf, sizeof buf, "gnuplot wrote %lld bytes that do not start as a %s file",
             (long long)sb.st_size, fm->name);
    why = buf;
  } else if (fm && !ends_with(tail, (size_t)nt, fm->end, fm->nend, fm->tail)) {
    snprintf(buf, sizeof buf, "gnuplot wrote an incomplete %s file (%lld bytes, no end marker)",
             fm->name, (long long)sb.st_size);
    why = buf;
  } else if (!fm && disk_full(tmp)) {
    snprintf(buf, sizeof buf, "gnuplot wrote %lld bytes and filled the disk",
             (long long)sb.st_size);
    why = buf;
  }
  if (!why) return 0;
  if (sb.st_size > 0 && disk_full(tmp)) {
    return ura_fail(c, "%s: cannot write '%s': %s: %s; the file is unchanged", who, shown,
                    strerror(ENOSPC), why);
  }
  return ura_fail(c, "%s: cannot write '%s': %s; the file is unchanged", who, shown, why);
}
