/* init.c: the host's options of the library (init.h). */
#include <gsl/gsl_errno.h>

#include "uasimpact/init.h"

int ur_init(unsigned flags) {
  if (flags & ~urINIT_GSL_CODES) return -1;
  if (flags & urINIT_GSL_CODES) gsl_set_error_handler_off();
  return 0;
}
