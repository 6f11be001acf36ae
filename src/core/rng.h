/* rng.h - the project's random numbers, the same from the same seed on every
 * machine.
 *
 * splitmix64: a small sequential generator (the demand's fill ships, the
 * report's bootstrap), its state one word that each draw advances.
 *
 * fw_rng: the random streams of what fairway itself makes stochastic
 * (sensing noise, AIS dropouts, watchkeeping delays, behaviour draws, gusts),
 * one per (run seed, vessel, purpose).  Counter-based: draw n of a stream is
 * a pure function of its key and n, Philox4x32-10 (Salmon, Moraes, Dror and
 * Shaw, "Parallel random numbers: as easy as 1, 2, 3", SC'11; Random123's
 * known-answer vectors hold it, tests/test_rng.c).  Chosen over a keyed hash
 * because it is a published bijection with published answers that passes
 * TestU01's BigCrush with 3 rounds to spare (7 pass, 10 are the default),
 * and over a sequential generator because a stream's state is then only its
 * key and counter: a snapshot copies the struct, and a stream restarted at
 * counter k continues exactly.  A draw costs one block, 20 32-bit multiplies.
 *
 * The key.  Philox's 64-bit key is the run seed; the 128-bit counter is
 * (draw index: 64 bits, vessel: 32, purpose: 32).  So every (vessel, purpose)
 * of one run walks its own part of one bijection: no two of them ever draw
 * the same block.  A branch (a copy of a run continued from a snapshot with
 * fresh randomness, issue 23's splitting) takes a new Philox key made from
 * its parent's key, vessel, purpose and branch number by one more block (a
 * block no draw uses: the purpose word's top bit set), and starts at counter
 * 0; branches of branches nest.  Two derived keys meet with probability 2^-64
 * per pair.
 *
 * Where streams live: a world's elements take theirs from the world's table
 * (world/world.h fw_world_rng, core/streams.h), never make their own, so that
 * a split re-keys every stream of a run at once.
 *
 * Common random numbers across a study's axes: the run seed is the
 * replication's (study.c fw_study_run_at: a mix of the study's seed and the
 * replication index, never of a domain size, shape, density or behaviour), so
 * the runs of one replication draw the same numbers for the same vessel and
 * purpose whatever the axis values.  The vessel's key must keep that: a key
 * the vessel has in every run of the replication (0 for the own ship, a hash
 * of a source ship's id), not its position in a list, which the axes can
 * change (a density adds ships).  One purpose per use, never shared, so a
 * change in how often one element draws leaves the others' numbers alone.
 */
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

/* What a stream is for: one each, named for the issues that add them.  The
 * values are part of the numbers drawn: append, never renumber. */
typedef enum {
    FW_PURPOSE_SENSING = 1,     /* noise on AIS reports (sense/sensing.h) */
    FW_PURPOSE_AIS_DROPOUT = 2, /* AIS reports that do not arrive */
    FW_PURPOSE_WATCH = 3,       /* watchkeeping delay before a vessel acts */
    FW_PURPOSE_BEHAVIOUR = 4,   /* behaviour draws (whether and how a ship gives way) */
    FW_PURPOSE_GUST = 5,        /* wind gusts */
    FW_PURPOSE_CURRENT = 6,     /* turbulence of the current */
    FW_PURPOSE_SPLIT = 7,       /* splitting's own draws: parents, particles' streams (study/ams.h) */
    FW_PURPOSE_RADAR = 8,       /* radar plots' range and bearing noise (sense/arpa.h) */
    FW_PURPOSE_RADAR_DETECT = 9, /* whether a scan detects a ship (sense/arpa.h) */
    FW_PURPOSE_AIS_TX = 10,     /* a ship's AIS reports as the reacting traffic hears them
                                   (world/reactions.h): noise and phase */
    FW_PURPOSE_AIS_TX_LOSS = 11, /* ... and those lost */
    FW_PURPOSE_TEST = 255       /* tests and benchmarks only */
} fw_purpose;

/* Philox4x32-10 on one block: out = the generator's 4 words for counter ctr
 * under key key (Random123's philox4x32(ctr, key)). */
void fw_philox4x32_10(const uint32_t ctr[4], const uint32_t key[2], uint32_t out[4]);

/* A stream: its key (Philox key, vessel, purpose) and the index of its next
 * draw.  Plain data: copy it to snapshot, assign counter to move. */
typedef struct {
    uint32_t key[2];  /* Philox key: the run seed, or a branch's derived key */
    uint32_t vessel;  /* counter word 2 */
    uint32_t purpose; /* counter word 3 (a fw_purpose; top bit never set) */
    uint64_t counter; /* counter words 0-1: the next draw's block */
} fw_rng;

/* The key of a vessel with this id: the FNV-1a hash of the id (core/hash.h)
 * folded to 32 bits (never 0, which is the own ship's).  The same in every
 * run of a replication, so the common random numbers hold (above). */
uint32_t fw_rng_vessel_key(const char *id);

/* The key of the link from a receiver (its vessel key; 0: the own ship,
 * whose links keep the target's own key) to a target: a mix of the two. */
static inline uint32_t fw_rng_link_key(uint32_t receiver, uint32_t target)
{
    if (receiver == 0)
        return target;
    uint64_t z = ((uint64_t)receiver << 32) | target;
    uint32_t k = (uint32_t)(fw_splitmix64(&z) >> 32);
    return k ? k : 1u;
}

/* Where an element of the world takes its streams: the world's table
 * (world.h fw_world_rng), handed down as a function and its context so the
 * element needs nothing of the world. */
typedef fw_rng *(*fw_rng_getter)(void *ctx, uint32_t vessel, fw_purpose purpose);

/* The stream of (run_seed, vessel, purpose) at counter 0. */
fw_rng fw_rng_make(uint64_t run_seed, uint32_t vessel, fw_purpose purpose);

/* The stream of branch number `branch` taken from s (at any counter): a new
 * key, the same vessel and purpose, counter 0.  Different for every branch
 * number, and different from s; s is unchanged. */
fw_rng fw_rng_branch(const fw_rng *s, uint32_t branch);

/* The 128 bits of block s->counter as two words (first: words 0-1, second:
 * words 2-3), and the counter advanced by one.  Every draw below takes one
 * block, so draw n is block n whatever kinds of draw came before. */
void fw_rng_block(fw_rng *s, uint64_t *a, uint64_t *b);

/* Uniform in [0, 1): the top 53 bits of the block's first word, times 2^-53. */
double fw_rng_uniform(fw_rng *s);

/* Standard normal by Box-Muller on the block's two words (u1 in (0, 1] from
 * the first, u2 in [0, 1) from the second): sqrt(-2 ln u1) cos(2 pi u2).  The
 * sine's twin is dropped so that a draw stays one block. */
double fw_rng_normal(fw_rng *s);

/* Exponential with mean 1 (scale it by the mean): -ln(u), u in (0, 1]. */
double fw_rng_exponential(fw_rng *s);

#endif
