/* abbrev.c: the command a typed name stands for. A name is the command's full name, one of the
 * short forms people type from other tools (q for quit), or a prefix that only one command
 * begins with (des: ambiguous, the candidates descent and design are listed; desc: descent).
 * Scripts take the same forms; saved sessions write full names, so that a command added later
 * never makes a saved file ambiguous. */
#include <stdio.h>
#include <string.h>

#include "cmd.h"


/* short forms that are not prefixes of one command alone (q is also quit's prefix today; it
   stays quit whatever command is added) */
static const char* const alias[][2] = {{"q", "quit"}, {NULL, NULL}};

const uraCmd* ura_cmd_resolve(const char* name, char* cands, size_t n) {
  if (cands && n) cands[0] = 0;
  const uraCmd* k = ura_cmd_find(name);
  if (k) return k;
  for (int i = 0; alias[i][0]; i++)
    if (!strcmp(name, alias[i][0])) return ura_cmd_find(alias[i][1]);
  size_t len = strlen(name);
  if (!len) return NULL;

  /* the commands that begin with name: one is the answer, several are listed */
  const uraCmd* found = NULL;
  int nfound = 0;
  size_t at = 0;
  for (const uraCmd* q = ura_cmds; q->name; q++) {
    if (strncmp(q->name, name, len)) continue;
    found = q;
    nfound++;
    if (cands && at < n)
      at += (size_t)snprintf(cands + at, n - at, "%s%s", at ? " or " : "", q->name);
  }
  if (nfound == 1) {
    if (cands && n) cands[0] = 0;
    return found;
  }
  if (nfound == 0 && cands && n) cands[0] = 0;
  return NULL;
}
