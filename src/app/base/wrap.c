/* wrap.c: text wrapped between words for a terminal of a given width */
#include <stdio.h>
#include <string.h>

#include "base.h"


void ura_wrap(FILE* f, const char* lead, const char* cont, const char* text, int width) {
  size_t col = strlen(lead);
  fputs(lead, f);
  if (width <= 0) {
    fprintf(f, "%s\n", text);
    return;
  }
  const char* s = text;
  int first = 1; /* no word on this line yet */
  while (*s) {
    while (*s == ' ') s++;
    if (!*s) break;
    size_t k = strcspn(s, " ");
    /* a word that fits a line of its own goes to the next line whole; a longer one starts here
       when its first piece fits */
    size_t p0 = strcspn(s, ",|") + 1;
    if (p0 > k) p0 = k;
    size_t need = strlen(cont) + k <= (size_t)width ? k : p0;
    if (!first && col + 1 + need > (size_t)width) {
      fprintf(f, "\n%s", cont);
      col = strlen(cont);
      first = 1;
    }
    if (!first) {
      fputc(' ', f);
      col++;
    }
    /* a word longer than a line (a list of column names) breaks after its commas and bars */
    const char* e = s + k;
    while (s < e) {
      size_t piece = strcspn(s, ",|");
      piece = s + piece < e ? piece + 1 : (size_t)(e - s);
      if (!first && col + piece > (size_t)width) {
        fprintf(f, "\n%s", cont);
        col = strlen(cont);
      }
      fwrite(s, 1, piece, f);
      col += piece;
      first = 0;
      s += piece;
    }
  }
  fputc('\n', f);
}

int ura_split_fields(const char* s, int width, char (*out)[256], int max) {
  int n = 0;
  size_t len = 0;
  if (max < 1) return 0;
  out[0][0] = 0;
  while (*s) {
    const char* sep = strstr(s, "  ");
    size_t k = sep ? (size_t)(sep - s) : strlen(s);
    if (len && len + 2 + k > (size_t)width && n + 1 < max) {
      out[++n][0] = 0;
      len = 0;
    }
    len += (size_t)snprintf(out[n] + len, len < 256 ? 256 - len : 0, "%s%.*s", len ? "  " : "",
                            (int)k, s);
    if (len > 255) len = 255;
    s += k;
    while (*s == ' ') s++;
  }
  return n + 1;
}
