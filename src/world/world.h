/* world.h - the simulation: vessels fairway steps, a traffic source for the rest, one step.
 *
 * In Box2D's manner: a definition with a default (fw_default_world_def), a
 * world that owns everything created in it, and a caller that drives time:
 *
 *   fw_world_def wd = fw_default_world_def();
 *   wd.step = 1.0;
 *   wd.source = source;                    the world takes it over
 *   fw_world_create(&wd, &w, &err);
 *   fw_vessel_def vd = fw_default_vessel_def();  ...
 *   fw_world_add_vessel(w, &vd, &own, &err);      the first vessel is the own ship
 *   fw_world_start(w, &err);               sense and decide at t = 0
 *   while (...) {
 *       ... read the vessels, their views, decisions ...
 *       fw_world_step(w, dt, &err);
 *   }
 *   fw_world_destroy(w);
 *
 * One step, in this order (README.md, Layout, "One step of a run"):
 *   1. every vessel's dynamics advance dt under the order decided last
 *   2. the source is told where the own ship is and moves its ships one step
 *   3. every vessel senses: the ships within its sight (the source's, for
 *      the own ship, and the other vessels'), sorted by id
 *   4. every vessel's controller decides its next order from what it sensed,
 *      and the source's ships that must give way to another are told their
 *      speed (reactions.h; orders take effect in the next step)
 * so after fw_world_start and after each step, everything read from the world
 * is of one instant: the positions and the decision taken on them.
 *
 * The source's ships are seen from the own ship (the first vessel); other
 * vessels see the vessels.  The world checks nothing about collisions: that
 * is the records' job (run/records).
 */
#ifndef FW_WORLD_H
#define FW_WORLD_H

#include <stdint.h>

#include "core/error.h"
#include "env/env.h"
#include "traffic/source.h"
#include "world/reactions.h"
#include "world/vessel.h"

typedef struct fw_world_def {
    double step;        /* s, every fw_world_step is one step of this length */
    fw_source *source;  /* taken over (destroyed with the world, also on a
                           failed create); NULL: no background ships */
    /* how the source's ships treat the others (world/reactions.h): colregs,
     * or blind (they keep course and speed whatever happens) */
    fw_reactions_def reactions;
    /* the current and the wind (env/env.h; none by default): the MMG
     * vessels move through the current, their predictions know it, and a
     * wind that is not calm is refused (no ship has windage particulars) */
    fw_env env;
    /* keep fw_world_timing (CPU seconds by phase; seven clock reads a
     * step, each a system call): off by default */
    bool timing;
    /* the run's seed (a study's replication's): the key of the vessels'
     * random streams (core/rng.h fw_rng_make); 1 by default */
    uint64_t seed;
} fw_world_def;

/* step 1 s, no source, blind traffic (a world built by hand has the traffic
 * its source scripts; scenarios choose colregs by default), calm water and
 * still air. */
fw_world_def fw_default_world_def(void);

typedef struct fw_world fw_world;

fw_status fw_world_create(const fw_world_def *def, fw_world **out, fw_error *err);
/* Safe on NULL. */
void fw_world_destroy(fw_world *w);

/* Adds a vessel (its controller is taken over, also on failure).  Before
 * fw_world_start only. */
fw_status fw_world_add_vessel(fw_world *w, const fw_vessel_def *def, fw_vessel **out,
                              fw_error *err);

/* Senses and decides at the present time (t = 0). */
fw_status fw_world_start(fw_world *w, fw_error *err);

/* Advances by dt (the def's step; anything else is FW_EINPUT, since SUMO
 * steps at a fixed length).  On failure the world is not usable further. */
fw_status fw_world_step(fw_world *w, double dt, fw_error *err);

/* Where the world's steps spent their time so far: CPU seconds (core/clock.h
 * fw_cpu_s), kept when the def asks (all 0 otherwise); for `fairway run
 * --profile`, never in anything a run's results depend on. */
typedef struct fw_world_timing {
    double dynamics;  /* the vessels' own motion (MMG or Nomoto, integrated) */
    double place;     /* the own ship put into the traffic (SUMO: moveToXY) */
    double traffic;   /* the traffic's own step (SUMO's) */
    double read;      /* the ships around the own ship read and converted */
    double decide;    /* sensing and the controllers (the avoidance policy) */
    double reactions; /* the traffic's reactions (its nearby read, give-way) */
} fw_world_timing;
const fw_world_timing *fw_world_timing_of(const fw_world *w);

double fw_world_time(const fw_world *w);  /* s */
uint64_t fw_world_seed(const fw_world *w); /* the def's seed */
long fw_world_steps(const fw_world *w);

int fw_world_vessel_count(const fw_world *w);
fw_vessel *fw_world_vessel(fw_world *w, int i);

/* Every ship in the area around the own ship, the own ship included, sorted
 * by id (the source's area query: the survey's input). */
fw_status fw_world_area(fw_world *w, const fw_target **ships, int *n, fw_error *err);

fw_source *fw_world_source(fw_world *w);

/* Every order given to the source's ships so far (reactions.h). */
const fw_reaction *fw_world_reactions(const fw_world *w, int *n);

#endif
