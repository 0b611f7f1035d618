/* speedunit.c: the units a speed may be typed in besides m/s: km/h and kt (the knot, 1852 m per
 * hour, as wind is given in aviation). Strict: exactly these spellings; the value is converted
 * to m/s before it is checked and kept, so everything downstream stays in SI. */
#include <string.h>

#include "base.h"


int ura_speed_unit(const char* unit, double* to_si) {
  static const struct {
    const char* name;
    double num, den; /* m/s = value * num / den */
  } u[] = {{"m/s", 1, 1}, {"km/h", 1000, 3600}, {"kt", 1852, 3600}, {NULL, 0, 0}};
  for (int i = 0; u[i].name; i++) {
    if (!strcmp(unit, u[i].name)) {
      *to_si = u[i].num / u[i].den;
      return 0;
    }
  }
  return -1;
}

double ura_speed_to_si(const char* unit, double v) {
  if (!strcmp(unit, "km/h")) return v * 1000 / 3600;
  if (!strcmp(unit, "kt")) return v * 1852 / 3600;
  return v;
}
