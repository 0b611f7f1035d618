/* word.c: a text written as one word that the script reader (cmd/script.c) takes back exactly as
 * it was: in single quotes, or in double ones when it holds a single quote, so that neither the
 * script reader nor a shell expands it. Save session, model save and the plot settings write
 * their texts through it; a text with a control byte, or with both quote characters, cannot be
 * written so and is refused where it is set; ura_word_inert also refuses what a shell would expand
 * inside the double quotes. */
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

/* what a POSIX shell expands inside double quotes: parameters and commands ($), commands
   (backquote), escapes (backslash), and bash's history (!) */
static int shell_active(const char* s) {
  return strpbrk(s, "$`\\!") != NULL;
}

/* whether s can also be written so that a shell would not expand it */
int ura_word_inert(const char* s) {
  if (ura_word_ok(s)) return -1;
  return strchr(s, '\'') && shell_active(s) ? -1 : 0;
}

/* s as that word: in single quotes, or double ones when it holds a single quote */
void ura_put_word(FILE* f, const char* s) {
  char q = strchr(s, '\'') ? '"' : '\'';
  fprintf(f, "%c%s%c", q, s, q);
}
