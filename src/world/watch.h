/* watch.h - the officer of the watch on a background ship: how soon a ship
 * that must give way notices, and whether it does at all.  The own ship may
 * have one too (world.h own_watch): its clock starts when a ship first
 * enters its view, and an unnoticed ship is hidden from its policy.
 *
 * The reactive traffic (reactions.h) has every give-way ship act as soon as
 * the risk of collision is there, every time.  A real watchkeeper takes time
 * to notice a ship and decide, and sometimes does not act at all (a lapse:
 * no lookout, a misjudged situation, the other ship not seen).  With a watch:
 *
 *   detect_s the mean time to detect the other once it is a threat: drawn
 *            per ship and encounter from an exponential law, the law of
 *            Koopman's random search (a constant chance of detection per
 *            second of looking: P(detected by t) = 1 - exp(-t / detect_s);
 *            B. O. Koopman, Search and Screening, 1946/1980)
 *   delay_s  the time to decide: a ship acts for another only once it has
 *            detected it and delay_s seconds more have passed (fixed)
 *   lapse    with this probability, drawn once per ship and encounter (the
 *            pair) when the other first becomes a threat, the ship never acts
 *            for it: it holds course and speed as if it were not there
 *   late     with this probability, drawn likewise, the ship acts for it only
 *            once it is within late_range (m) of it (a late action: the other
 *            seen or judged dangerous only close by)
 *
 * A mix of behaviours, drawn once per ship (the first time it must give way
 * to anyone) and kept for the run (issue 27's mix: a ship, not an
 * encounter, is careless or not):
 *   compliant  acts as above (the rest of the mix)
 *   late       acts for another only once it is within mix_range (m) of it
 *   passive    never acts: neither gives way nor, as a stand-on ship, acts
 *              when the other does not (rule 17(b)); SUMO drives it on
 * The mix is all compliant by default.  TUD_RL's river traffic (shared
 * reference) makes 20 % of its target ships non-cooperative, a training
 * setting of a reinforcement-learning environment, not an observation of
 * ships; the observed figure, IWRAP's causation factors (below, about 1e-4
 * per encounter), is what the lapse carries, and a passive share of the same
 * size would be the same failures counted per ship.  No source gives how
 * many ships act late, so the mix is the user's (a study axis:
 * traffic.mix.passive, traffic.mix.late).
 *
 * All are zero by default: the flawless watch fairway had before, every
 * number unchanged.  Values with sources (scenarios/README.md "The watch"
 * has the table):
 *   lapse    FW_WATCH_LAPSE_CROSSING 1.3e-4, _HEAD_ON 4.9e-5, _OVERTAKING
 *            1.1e-4: IWRAP Mk II's default causation factors (Pedersen 1995;
 *            Fujii 1974), the probability that ships on a collision course
 *            fail to make evasive actions (IALA IWRAP wiki, Porthin 2010),
 *            the two ships' failures combined; taken whole as the give-way
 *            ship's lapse, the most the source allows it.  No figure for fog
 *            (Fujii and Mizuki's factors of 2 and 8 are on an area's yearly
 *            rate by how often visibility is below 1 km, not per encounter).
 *   detect, delay, late, late_range: no source.  The shared reference
 *            (the files of ../shared/reference) has IWRAP's causation factors and
 *            nothing on a watchkeeper's times or late ranges, and searches of
 *            the pages, docs and issues corpora (OOW detection and decision
 *            times, bridge-simulator human-error studies) found abstracts
 *            without figures.  Their defaults, 0 (detected and decided at
 *            once, never late), are therefore not data but an assumption,
 *            stated as one: the flawless watch fairway had before, kept
 *            because any other value would be a guess that moves the results
 *            (and the floor asks the defaults to reproduce main), not
 *            because a real watch is that quick.  A study that wants them
 *            sets them and sweeps them as axes (traffic.watch.detect_s ...).
 *            The lapse's IWRAP factor counts the failures to act at all;
 *            slow detection is part of what it summarises, so a study that
 *            adds detect_s on top of it counts some failures twice.
 * scenarios/studies/dover-imperfect.yaml uses the crossing lapse.  Draws come from the acting
 * ship's stream (FW_PURPOSE_WATCH, key rng.h fw_rng_vessel_key of its id),
 * so splitting re-keys them and a replication draws the same lapses in every
 * setting whose encounters come in the same order; a ship's behaviour comes
 * from its own stream (FW_PURPOSE_BEHAVIOUR), one uniform draw, so a mix
 * leaves the encounters' draws as they were.  A new encounter draws, in
 * this order and each only when its setting is not zero: the lapse (uniform),
 * the time to detect (exponential), the late action (uniform).
 */
#ifndef FW_WORLD_WATCH_H
#define FW_WORLD_WATCH_H

#include <stdbool.h>

#include "core/error.h"
#include "core/rng.h"
#include "geom/target.h"

/* The lapse probabilities with a source (above). */
#define FW_WATCH_LAPSE_CROSSING 1.3e-4
#define FW_WATCH_LAPSE_HEAD_ON 4.9e-5
#define FW_WATCH_LAPSE_OVERTAKING 1.1e-4

typedef struct fw_watch_def {
    double delay;      /* s, >= 0: the time to decide, after detection */
    double lapse;      /* probability, [0, 1]: no action */
    double detect;     /* s, >= 0: the mean time to detect (exponential) */
    double late;       /* probability, [0, 1]: action only within late_range */
    double late_range; /* m, > 0 when late > 0 */
    double mix_late;    /* share of ships, [0, 1]: late ships */
    double mix_passive; /* share of ships, [0, 1]: passive ships; the two at most 1 */
    double mix_range;   /* m, > 0 when mix_late > 0: where a late ship acts */
} fw_watch_def;

typedef enum fw_conduct { FW_BEH_COMPLIANT, FW_BEH_LATE, FW_BEH_PASSIVE, FW_BEH_N } fw_conduct;

/* Flawless: no delay, no lapse. */
fw_watch_def fw_default_watch_def(void);

/* FW_EINPUT naming the field: a negative or non-finite time, a probability
 * outside [0, 1], a late action without a positive range. */
fw_status fw_watch_check(const fw_watch_def *def, fw_error *err);
/* Not flawless: something to model (and, but for a delay alone, to draw). */
bool fw_watch_def_active(const fw_watch_def *def);
/* Draws random numbers (a lapse, a time to detect or a late action). */
bool fw_watch_def_draws(const fw_watch_def *def);

typedef struct fw_watch fw_watch;

fw_status fw_watch_create(const fw_watch_def *def, fw_watch **out, fw_error *err);
void fw_watch_destroy(fw_watch *w);
/* The world's streams (needed once the watch is not flawless). */
void fw_watch_set_rng(fw_watch *w, fw_rng_getter rng, void *ctx);
/* A delay or a lapse to model. */
bool fw_watch_active(const fw_watch *w);

/* Ship a finds ship b a threat at t (it would have to give way to it): has
 * it noticed b, so that it acts?  The first call for the pair starts its
 * clock and draws its lapse.  -1 when out of memory or without streams. */
int fw_watch_noticed(fw_watch *w, const fw_target *a, const fw_target *b, double t);

/* A split's branch at t (world.h fw_world_rekey, after the streams are
 * re-keyed): every pair not yet detected draws its time to detect afresh
 * from t, from its re-keyed stream, in the order the pairs were met.  The
 * exponential law is memoryless: given no detection by t, the time left is
 * again exponential with the same mean, so the branch continues with the
 * law its parent had, and a splitting over late detections can branch after
 * the encounter began (without this a branch repeated its parent's
 * detection).  Lapses, late actions and decided-but-not-acted pairs keep
 * their draws (decided at the encounter's start).  The pairs redrawn, -1
 * without streams. */
int fw_watch_redraw(fw_watch *w, double t);

/* How near a ship not acted for (not detected, lapsed, or late and still
 * beyond the range) has come so far: the largest 1 - range / (range when
 * first met), 0 before any; in [0, 1], 1 only at a range of 0.  Splitting's
 * score for a watch (study/split_run.h): every path on which the watch
 * noticed in time is the same path, and this tells them apart. */
double fw_watch_unseen(const fw_watch *w);

/* Encounters met so far, and of them those lapsed (late ones not counted). */
void fw_watch_counts(const fw_watch *w, long *pairs, long *lapsed);
/* Ships drawn from the mix so far, by behaviour (all 0 without a mix). */
void fw_watch_mix_counts(const fw_watch *w, long counts[FW_BEH_N]);
/* Is there a mix (some ship not compliant)? */
bool fw_watch_def_mixed(const fw_watch_def *def);

#endif
