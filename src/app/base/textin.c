/* textin.c: lines of text files read defensively: bounded length (a device such as /dev/zero or
 * a file without line breaks cannot exhaust memory), NUL bytes and read errors told apart from
 * the end of the file; untrusted text made printable before it is echoed in a message; and a
 * standard output stream that keeps the reason of a failed write (a full disk) for the message */
#define _GNU_SOURCE /* fopencookie */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base.h"


long ura_read_line(FILE* f, char** buf, size_t* cap, size_t max) {
  size_t n = 0;
  int ch;
  for (;;) {
    ch = getc_unlocked(f);
    if (ch == EOF) break;
    if (ch == 0) return uraLINE_NUL;
    if (ch != '\n' && n >= max) return uraLINE_LONG;
    if (n + 2 > *cap) {
      size_t nc = *cap ? 2 * *cap : 256;
      if (nc > max + 2) nc = max + 2;
      char* b = realloc(*buf, nc);
      if (!b) {
        errno = ENOMEM;
        return uraLINE_ERROR;
      }
      *buf = b;
      *cap = nc;
    }
    if (ch == '\n') break;
    (*buf)[n++] = (char)ch;
  }
  if (ch == EOF) {
    if (ferror(f)) return uraLINE_ERROR;
    if (n == 0) return uraLINE_EOF;
  }
  if (n > 0 && (*buf)[n - 1] == '\r') n--;
  (*buf)[n] = 0;
  return (long)n;
}

/* the length of a valid UTF-8 sequence at s for a printable code point (U+00A0 and above, no
   surrogates or overlong forms), or 0 */
static int utf8_printable(const unsigned char* s) {
  int n = s[0] >= 0xC2 && s[0] <= 0xDF   ? 2
          : s[0] >= 0xE0 && s[0] <= 0xEF ? 3
          : s[0] >= 0xF0 && s[0] <= 0xF4 ? 4
                                         : 0;
  unsigned cp = n == 2 ? s[0] & 0x1F : n == 3 ? s[0] & 0x0F : s[0] & 0x07;
  for (int i = 1; i < n; i++) {
    if ((s[i] & 0xC0) != 0x80) return 0;
    cp = cp << 6 | (s[i] & 0x3F);
  }
  if (!n || cp < 0xA0 || (n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10FFFF)) ||
      (cp >= 0xD800 && cp <= 0xDFFF)) {
    return 0;
  }
  return n;
}

size_t ura_printable(const char* s, char* buf, size_t n) {
  size_t k = 0;
  if (!n) return 0;
  const unsigned char* p = (const unsigned char*)s;
  while (*p) {
    int u = *p >= 0x80 ? utf8_printable(p) : 0;
    if (*p >= 32 && *p < 127) {
      if (k + 1 >= n) break;
      buf[k++] = (char)*p++;
    } else if (u) {
      if (k + (size_t)u >= n) break;
      memcpy(buf + k, p, (size_t)u);
      k += (size_t)u;
      p += u;
    } else {
      if (k + 4 >= n) break;
      k += (size_t)snprintf(buf + k, n - k, "\\x%02x", *p++);
    }
  }
  buf[k] = 0;
  return k;
}

/* ---- standard output that remembers why a write failed ---- */

static int out_fd = -1;
static int out_err; /* errno of the first failed write since ura_out_clear */

static ssize_t out_write(void* ck, const char* buf, size_t n) {
  size_t done = 0;
  while (done < n) {
    ssize_t k = write(out_fd, buf + done, n - done);
    if (k > 0) {
      done += (size_t)k;
    } else if (k < 0 && errno == EINTR && !ura_interrupted()) {
      continue;
    } else {
      if (!out_err) out_err = k < 0 ? errno : EIO;
      errno = out_err;
      return 0;
    }
  }
  return (ssize_t)n;
}

FILE* ura_out_stream(int fd) {
  cookie_io_functions_t io = {NULL, out_write, NULL, NULL};
  out_fd = fd;
  return fopencookie(NULL, "w", io);
}

int ura_out_errno(void) {
  return out_err;
}

void ura_out_clear(void) {
  out_err = 0;
}
