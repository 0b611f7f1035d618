/* wrap.c: text wrapped between words for a terminal of a given width */
#include <stdio.h>
#include <string.h>

#include "app.h"

void ura_wrap(FILE* f, const char* lead, const char* cont, const char* text, int width) {
  size_t col = strlen(lead);
  fputs(lead, f);
  if (width <= 0) {
    fprintf(f, "%s\n", text);
    return;
  }
  const char* s = text;
  int first = 1;                   /* no word on this line yet */
  while (*s) {
    while (*s == ' ') s++;
    if (!*s) break;
    size_t k = strcspn(s, " ");
    if (!first && col + 1 + k > (size_t)width) {
      fprintf(f, "\n%s", cont);
      col = strlen(cont);
      first = 1;
    }
    if (!first) {
      fputc(' ', f);
      col++;
    }
    fwrite(s, 1, k, f);
    col += k;
    first = 0;
    s += k;
  }
  fputc('\n', f);
}
