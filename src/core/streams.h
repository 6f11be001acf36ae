/* streams.h - the random streams of one run, kept in one table so that a
 * split can give every one of them fresh randomness at once.
 *
 * Every element of a world that draws (sensing noise, AIS dropouts,
 * watchkeeping, behaviour draws, gusts: core/rng.h's purposes) takes its
 * stream here, once, by (vessel key, purpose), and keeps the pointer: it stays
 * valid until the table is freed.  Asking twice for the same key and purpose
 * gives the same stream (one purpose per use: rng.h).
 *
 * Re-keying.  Adaptive multilevel splitting (study/ams.h) continues a copy of
 * a run from some instant with randomness of its own.  fw_streams_rekey(t, b)
 * replaces each stream s by fw_rng_branch(s, b) (a new key, counter 0), and
 * remembers b, so that a stream first asked for later is made as if it had
 * existed at the re-keying: its numbers do not depend on when an element
 * happened to ask.  Re-keyings nest (a branch of a branch).
 *
 * Whether a run has randomness at all after its start is what
 * fw_streams_count tells afterwards: a table nobody asked anything of means
 * every copy of the run would be the run itself.
 */
#ifndef FW_CORE_STREAMS_H
#define FW_CORE_STREAMS_H

#include <stdbool.h>
#include <stdint.h>

#include "core/rng.h"

typedef struct fw_streams fw_streams;

/* NULL when out of memory. */
fw_streams *fw_streams_create(uint64_t run_seed);
void fw_streams_free(fw_streams *t); /* safe on NULL */

/* The stream of (vessel, purpose), made at its first request; NULL only when
 * out of memory. */
fw_rng *fw_streams_get(fw_streams *t, uint32_t vessel, fw_purpose purpose);

/* Fresh randomness from now on for every stream, branch number b (b > 0);
 * false (nothing changed) when out of memory. */
bool fw_streams_rekey(fw_streams *t, uint32_t branch);

int fw_streams_count(const fw_streams *t);   /* streams made so far */
int fw_streams_rekeyed(const fw_streams *t); /* re-keyings so far */

#endif
