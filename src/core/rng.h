/* rng.h - splitmix64, the project's small fixed-seed generator: the same
 * numbers from the same seed on every machine (the demand's fill ships, the
 * report's bootstrap). */
#ifndef FW_CORE_RNG_H
#define FW_CORE_RNG_H

#include <stdint.h>

/* The next value of the stream whose state is *s. */
static inline uint64_t fw_splitmix64(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

#endif
