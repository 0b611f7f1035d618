/* textin.c: lines of text files read defensively: bounded length (a device such as /dev/zero or
 * a file without line breaks cannot exhaust memory), NUL bytes and read errors told apart from
 * the end of the file */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "app.h"

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
