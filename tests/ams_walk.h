/* ams_walk.h - a rare event whose probability is known exactly, for testing
 * and benchmarking splitting (study/ams.h): tests/test_ams.c, bench/bench_ams.c.
 *
 * A ship holding a track whose cross-track offset from a hazard (another
 * ship's track, a bank) wanders as a Brownian motion under random
 * disturbances, x(t) = x0 + sigma W(t), touches the hazard when its offset
 * comes down to the clearance c within the horizon T.  By the reflection
 * principle the probability is exactly
 *     p = P(min x <= c) = 2 Phi(-d) = erfc(d / sqrt 2),  d = (x0 - c) / (sigma sqrt T).
 * The simulation steps dt and between steps asks whether the Brownian bridge
 * from x_a to x_b dipped to c, which it did with probability
 * exp(-2 (x_a - c)(x_b - c) / (sigma^2 dt)): so the simulated event is the
 * continuous one and the answer exact, not a discretisation's.  The score is
 * the closeness 1 - (x - c) / (x0 - c) clipped to [0, 1] (0 at the start, 1
 * at contact), or with `timed` the same in units of the spread still to
 * come (a monotone function of the exact chance of contact from (x, t), the
 * score under which splitting is ideal).  A branch replays the parent's
 * stored path to the first step whose score exceeded the level and goes on
 * from there with fresh numbers.
 */
#ifndef FW_TESTS_AMS_WALK_H
#define FW_TESTS_AMS_WALK_H

#include <stdbool.h>

#include "study/ams.h"

typedef struct walk_def {
    double x0, clear, sigma; /* m, m, m / sqrt(s) */
    double dt;               /* s */
    int steps;               /* horizon = steps dt */
    bool timed;              /* score by the remaining spread */
} walk_def;

/* The model for fw_ams_run (ctx: a walk_def). */
fw_ams_model walk_model(walk_def *w);
/* The exact probability of contact. */
double walk_exact_p(const walk_def *w);
/* A case with p = 10^-e (e in [1, 12]): 20 min, sigma 2 m/sqrt(s), dt 10 s. */
walk_def walk_case(double e);
/* One whole trajectory from stream r: did it touch? */
bool walk_touches(const walk_def *w, fw_rng *r);

#endif
