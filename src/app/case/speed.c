/* speed.c: a speed setting typed in km/h or kt (set wind 10 kt, set winds 0,10,20 km/h, sweep
 * wind 0,10,20 kt): the value or list rewritten in m/s, exactly as set would keep it had it been
 * typed in m/s (each number to the shortest text that reads back the same double). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"


int ura_speed_convert(uraCtx* c, const char* who, const uraParam* p, const char* value,
                      const char* unit, char* out, size_t n) {
  double f;
  if (ura_speed_unit(unit, &f)) {
    return ura_fail(c, "%s: unknown unit '%s'; accepted: %s", who, unit, uraSPEED_UNITS);
  }
  int k = ura_list_count(value);
  if (p->kind != uraP_LIST && k != 1) {
    return ura_fail(c, "%s: '%s' is not a number; accepted: a number in %s", who, value,
                    uraSPEED_UNITS);
  }
  double* v = malloc((size_t)k * sizeof *v);
  if (!v) return ura_fail(c, "%s: out of memory", who);
  char why[200];
  if (ura_parse_list_why(value, v, k, why, sizeof why) != k) {
    free(v);
    return ura_fail(c, "%s: '%s' is not %s (%s); accepted: %s in %s", who, value,
                    p->kind == uraP_LIST ? "a list of numbers" : "a number", why,
                    p->kind == uraP_LIST ? "comma-separated numbers" : "a number", uraSPEED_UNITS);
  }
  size_t at = 0;
  out[0] = 0;
  for (int i = 0; i < k && at < n; i++) {
    double si = ura_speed_to_si(unit, v[i]);
    if (si < p->min || si > p->max) {
      double lo = p->min / f, hi = p->max / f;
      free(v);
      return ura_fail(
          c, "%s: %g %s (%g m/s) is out of range; accepted: %g to %g m/s (%.4g to %.4g %s)", who,
          si / f, unit, si, p->min, p->max, lo, hi, unit);
    }
    at += (size_t)snprintf(out + at, n - at, "%s", i ? "," : "");
    if (at < n) {
      ura_num_shortest(out + at, n - at, si);
      at += strlen(out + at);
    }
  }
  free(v);
  if (at >= n) return ura_fail(c, "%s: the list is too long", who);
  return 0;
}
