/* parse.c: strict parsing of numbers and lists typed by people */
#include <ctype.h>
#include <errno.h>
#include <math.h>
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
  int k = 0;
  const char* p = s;
  if (!s || !*s) return -1;
  for (;;) {
    const char* q = strchr(p, ',');
    size_t len = q ? (size_t)(q - p) : strlen(p);
    char item[72];
    if (len >= sizeof item || k >= max) return -1;
    memcpy(item, p, len);
    item[len] = 0;
    if (ura_parse_number(item, &v[k])) return -1;
    k++;
    if (!q) break;
    p = q + 1;
  }
  return k;
}
