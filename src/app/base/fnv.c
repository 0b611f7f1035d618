/* fnv.c: the 64-bit FNV-1a hash (Fowler, Noll, Vo), the one hash of the application: a part
 * file's checksum and the hashes of its script and models (scale/), the model texts' hashes in a
 * report (report/). It detects accidents, not forgeries: nothing relies on it for security (a
 * part's values are checked one by one). */
#include <stddef.h>

#include "base.h"

/* h chained over the n bytes at p */
unsigned long long ura_fnv(unsigned long long h, const void* p, size_t n) {
  const unsigned char* s = p;
  for (size_t i = 0; i < n; i++) h = (h ^ s[i]) * 0x100000001b3ULL;
  return h;
}
