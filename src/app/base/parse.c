/* parse.c: strict parsing of numbers and lists typed by people */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base.h"


int ura_parse_number(const char* s, double* v) {
  /* only decimal notation: digits, one sign, one point, an exponent */
  if (!s) return -1;
  while (isspace((unsigned char)*s)) s++;
  size_t n = strlen(s);
  while (n > 0 && isspace((unsigned char)s[n - 1])) n--;
  if (n == 0 || n > 64) return -1;
  int digits = 0;
  for (size_t i = 0; i < n; i++) {
    char ch = s[i];
    if (isdigit((unsigned char)ch))
      digits++;
    else if (!strchr("+-.eE", ch))
      return -1;
  }
  if (!digits) return -1;

  /* convert and insist that everything was used and the value is finite */
  char buf[72];
  memcpy(buf, s, n);
  buf[n] = 0;
  char* end;
  errno = 0;
  double x = strtod(buf, &end);
  if (end != buf + n || errno == ERANGE || !isfinite(x)) return -1;
  *v = x;
  return 0;
}

int ura_parse_list(const char* s, double* v, int max) {
  return ura_parse_list_why(s, v, max, NULL, 0);
}

int ura_list_count(const char* s) {
  int n = 1;
  for (; s && *s; s++) n += *s == ',';
  return n;
}

/* why the value at p (len bytes), number k of total, is refused: empty, or its first 32
   bytes (made printable) and "is not a number" */
static void list_item_why(const char* p, size_t len, int k, int total, char* why, size_t nwhy) {
  char shown[40], safe[160];
  size_t m = len > 32 ? 32 : len;
  memcpy(shown, p, m);
  strcpy(shown + m, len > m ? "..." : "");
  ura_printable(shown, safe, sizeof safe);
  if (len == 0)
    snprintf(why, nwhy, "value %d of %d is empty", k, total);
  else
    snprintf(why, nwhy, "value %d of %d, '%s', is not a number", k, total, safe);
}

int ura_parse_list_why(const char* s, double* v, int max, char* why, size_t nwhy) {
  int k = 0, total = ura_list_count(s);
  const char* p = s;
  char item[72];
  if (why && nwhy) why[0] = 0;
  if (!s || !*s) {
    if (why) snprintf(why, nwhy, "the list is empty");
    return -1;
  }
  if (total > max) {
    if (why) snprintf(why, nwhy, "%d values, more than %d", total, max);
    return -1;
  }
  for (;;) {
    const char* q = strchr(p, ',');
    size_t len = q ? (size_t)(q - p) : strlen(p);
    int ok = len < sizeof item;
    if (ok) {
      memcpy(item, p, len);
      item[len] = 0;
      ok = ura_parse_number(item, &v[k]) == 0;
    }
    /* the value named by its place, so that a long list never hides what is wrong with it */
    if (!ok) {
      if (why) list_item_why(p, len, k + 1, total, why, nwhy);
      return -1;
    }
    k++;
    if (!q) break;
    p = q + 1;
  }
  return k;
}
