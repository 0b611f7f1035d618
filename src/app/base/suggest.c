/* suggest.c: "did you mean" for a mistyped name, from the tables the names come from (the command
 * table, the parameter tables, a trace's signals, a usage text's keywords): the nearest name by
 * edit distance (with transpositions), if it is near enough for a typing slip */
#include <stdio.h>
#include <string.h>

#include "base.h"


#define MAXW 64

/* optimal string alignment distance: insertions, deletions, substitutions, adjacent swaps */
int ura_edit_distance(const char* a, const char* b) {
  int n = (int)strlen(a), m = (int)strlen(b);
  if (n >= MAXW || m >= MAXW) return MAXW;
  int d[MAXW + 1][MAXW + 1];
  for (int i = 0; i <= n; i++) d[i][0] = i;
  for (int j = 0; j <= m; j++) d[0][j] = j;
  for (int i = 1; i <= n; i++) {
    for (int j = 1; j <= m; j++) {
      int cost = a[i - 1] != b[j - 1];
      int v = d[i - 1][j] + 1;
      if (d[i][j - 1] + 1 < v) v = d[i][j - 1] + 1;
      if (d[i - 1][j - 1] + cost < v) v = d[i - 1][j - 1] + cost;
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
          d[i - 2][j - 2] + 1 < v) {
        v = d[i - 2][j - 2] + 1;
      }
      d[i][j] = v;
    }
  }
  return d[n][m];
}

void ura_suggest_init(uraSuggest* s, const char* word) {
  s->word = word;
  s->best[0] = 0;
  s->d = MAXW;
}

void ura_suggest_add(uraSuggest* s, const char* name) {
  if (!name || !*name || !strcmp(name, s->word)) return;
  int d = ura_edit_distance(s->word, name);
  /* near enough: 1 edit in a short word, 2 in a longer one, 3 in a long one */
  size_t len = strlen(s->word);
  int lim = len <= 4 ? 1 : len <= 8 ? 2 : 3;
  if (d <= lim && d < s->d) {
    s->d = d;
    snprintf(s->best, sizeof s->best, "%s", name);
  }
}

const char* ura_suggest_text(const uraSuggest* s, char* buf, size_t n) {
  if (!s->best[0])
    snprintf(buf, n, "%s", "");
  else
    snprintf(buf, n, " (did you mean '%s'?)", s->best);
  return buf;
}

/* the keywords of a usage text's alternatives ("pof|grid|history [SIGNAL...]": pof, grid,
   history): lowercase words at bracket depth 0 that begin the text or follow '|' */
void ura_suggest_keywords(uraSuggest* s, const char* usage) {
  int depth = 0;
  for (const char* p = usage; *p; p++) {
    if (*p == '[') depth++;
    if (*p == ']') depth--;
    if (depth || !(p == usage || p[-1] == '|' || p[-1] == ' ') || *p < 'a' || *p > 'z') continue;
    size_t k = strspn(p, "abcdefghijklmnopqrstuvwxyz_0123456789");
    char w[MAXW];
    snprintf(w, sizeof w, "%.*s", (int)k, p);
    ura_suggest_add(s, w);
    p += k - 1;
  }
}
