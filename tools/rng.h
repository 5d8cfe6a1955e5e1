/*
 * rng.h - the one source of random numbers of the atrbvh tool: counter-
 * based, so that a value is a function of its indices alone (the rays, and
 * every number measured with them, do not depend on threads, order or
 * timing).  splitmix64's finaliser mixes; rng_pair gives two uniforms in
 * [0, 1) for (seed, item, sample).
 */
#ifndef ATRBVH_TOOLS_RNG_H
#define ATRBVH_TOOLS_RNG_H

#include <stdint.h>

static inline uint64_t rng_mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

/* 53 random bits as a double in [0, 1). */
static inline double rng_unit(uint64_t h)
{
    return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

/* Two uniforms in [0, 1) for (seed, item, sample). */
static inline void rng_pair(uint64_t seed, uint64_t item, uint64_t sample,
                            double *u1, double *u2)
{
    uint64_t h = rng_mix64(rng_mix64(rng_mix64(seed) ^ item) ^ sample);
    uint64_t g = rng_mix64(h ^ 0x9e3779b97f4a7c15ull);
    *u1 = rng_unit(h);
    *u2 = rng_unit(g);
}

#endif
