/* word.c: a text written as one word that the script reader (cmd/script.c) takes back exactly as
 * it was: in double quotes, or in single ones when it holds a double quote. Save session, model
 * save and the plot settings write their texts through it; a text with a control byte, or with
 * both quote characters, cannot be written so and is refused where it is set. */
#include <stdio.h>
#include <string.h>

#include "base.h"

/* whether s can be written as one word a script reads back as it is */
int ura_word_ok(const char* s) {
  for (const char* p = s; *p; p++) {
    if ((unsigned char)*p < 32 || *p == 127) return -1;
  }
  return strchr(s, '"') && strchr(s, '\'') ? -1 : 0;
}

/* s as that word: in double quotes, or single ones when it holds a double quote */
void ura_put_word(FILE* f, const char* s) {
  char q = strchr(s, '"') ? '\'' : '"';
  fprintf(f, "%c%s%c", q, s, q);
}
