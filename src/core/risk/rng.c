/* rng.c: Philox4x32-10 (rng.h). The round function and constants are those of the SC'11 paper:
 * two 32x32->64 multiplications by M0 and M1 per round, the key bumped by the Weyl constants W0
 * and W1 between rounds. Tested against Random123's known-answer vectors (tests/core/risk/test_rng.c). */
#include "uasimpact/rng.h"

#define M0 0xD2511F53u
#define M1 0xCD9E8D57u
#define W0 0x9E3779B9u
#define W1 0xBB67AE85u

void ur_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4]) {
  uint32_t x0 = ctr[0], x1 = ctr[1], x2 = ctr[2], x3 = ctr[3], k0 = key[0], k1 = key[1];
  for (int r = 0; r < 10; r++) {
    uint64_t p0 = (uint64_t)M0 * x0, p1 = (uint64_t)M1 * x2;
    uint32_t y0 = (uint32_t)(p1 >> 32) ^ x1 ^ k0, y2 = (uint32_t)(p0 >> 32) ^ x3 ^ k1;
    x0 = y0;
    x1 = (uint32_t)p1;
    x2 = y2;
    x3 = (uint32_t)p0;
    k0 += W0;
    k1 += W1;
  }
  out[0] = x0;
  out[1] = x1;
  out[2] = x2;
  out[3] = x3;
}

uint32_t ur_rng_stream(const char* name) {
  uint32_t h = 2166136261u;
  for (const unsigned char* p = (const unsigned char*)name; *p; p++) h = (h ^ *p) * 16777619u;
  return h;
}

double ur_rng_uniform(uint64_t seed, uint64_t sample, uint32_t stream) {
  uint32_t ctr[4] = {(uint32_t)sample, (uint32_t)(sample >> 32), stream, 0};
  uint32_t key[2] = {(uint32_t)seed, (uint32_t)(seed >> 32)}, out[4];
  ur_philox4x32_10(ctr, key, out);
  /* 53 bits, centred in their cell: never 0, never 1 */
  uint64_t b = ((uint64_t)(out[0] >> 5) << 26) | (out[1] >> 6);
  return ((double)b + 0.5) / 9007199254740992.0;
}
