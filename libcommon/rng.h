/* rng.h -- a seeded pseudo-random generator (xoshiro256**, seeded by
 * splitmix64): the same seed gives the same sequence on every machine. */
#ifndef CM_RNG_H
#define CM_RNG_H
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

struct rng { uint64_t s[4]; };

void rng_seed(struct rng *r, uint64_t seed);
uint64_t rng_u64(struct rng *r);
/* uniform in [0, 1) */
double rng_uniform(struct rng *r);
/* uniform integer in [0, n) (unbiased), n >= 1 */
int rng_int(struct rng *r, int n);
/* standard normal (Box-Muller) */
double rng_normal(struct rng *r);

#ifdef __cplusplus
}
#endif
#endif
