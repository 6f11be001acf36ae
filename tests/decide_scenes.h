/* decide_scenes.h - the fixed-seed scenes the decision tests draw (test_decide,
 * test_decide_parts): targets in mixed or dense traffic about the own ship's
 * track, some with a turning predictor, and own ships straight or turning.
 * One generator, reseeded by each test, so that every test is deterministic
 * on its own. */
#ifndef FW_TEST_DECIDE_SCENES_H
#define FW_TEST_DECIDE_SCENES_H

#include <stdbool.h>

#include "geom/target.h"
#include "nomoto/track.h"

/* Restarts the generator (xorshift64; seed not 0). */
void decide_seed(unsigned long long seed);
/* Uniform in [0, 1). */
double decide_uniform(void);
/* n targets about own's straight track (dense: every one aimed at it; mixed:
 * one in ten, the rest anywhere within 3 nm), ids "t0", "t1", ... */
void decide_scene(const fw_own_state *own, bool dense, fw_target *tg, int n);
/* An own ship straight (symmetric: the port tracks are mirrored) or already
 * turning. */
fw_own_state decide_own(bool turning_now);

#endif
