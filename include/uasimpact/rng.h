/* rng.h: a counter-based random number generator, Philox4x32-10 (Salmon, Moraes, Dror and Shaw,
 * "Parallel random numbers: as easy as 1, 2, 3", SC'11; the Random123 library). A draw is a pure
 * function of (seed, sample, stream): sample i of a Monte Carlo run gets the same numbers whatever
 * the number of threads or processes and however the samples are split among them.
 */
#ifndef UASIMPACT_RNG_H
#define UASIMPACT_RNG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* one Philox4x32 block of 10 rounds: 128 random bits from a 128-bit counter and a 64-bit key */
void ur_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4]);

/* a stream number for a name (32-bit FNV-1a): each input of a sample draws from its own stream,
   so that declaring another input does not change the draws of the others */
uint32_t ur_rng_stream(const char* name);

/* a uniform number in the open interval (0, 1), 53 random bits, from the block of counter
   (sample, stream) under key seed */
double ur_rng_uniform(uint64_t seed, uint64_t sample, uint32_t stream);

#ifdef __cplusplus
}
#endif
#endif
