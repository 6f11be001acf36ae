/* world.h - the simulation: vessels fairway steps, a traffic source for the rest, one step.
 *
 * In Box2D's manner: a definition with a default (fw_default_world_def), a
 * world that owns everything created in it, handles for what comes and goes,
 * and a caller that drives time:
 *
 *   fw_world_def wd = fw_default_world_def();
 *   wd.step = 1.0;
 *   wd.source = source;                    the world takes it over
 *   fw_world_create(&wd, &w, &err);
 *   fw_vessel_def vd = fw_default_vessel_def();  ...  vd.role = FW_ROLE_OWN;
 *   fw_vessel_handle own;
 *   fw_world_add_vessel(w, &vd, &own, &err);
 *   fw_world_start(w, &err);               sense and decide at t = 0
 *   while (...) {
 *       ... read the vessels, their views, decisions ...
 *       fw_world_add_vessel / fw_world_remove_vessel / fw_world_take /
 *       fw_world_give_back                 at any time between steps
 *       fw_world_step(w, dt, &err);
 *   }
 *   fw_world_destroy(w);
 *
 * Vessels are held by handles (fw_vessel_handle: a slot index and the slot's
 * generation, as Box2D's b2BodyId): removing a vessel frees its slot and
 * bumps its generation, so an old handle is refused (FW_EINPUT from the calls
 * that take one, NULL from fw_world_vessel) and never reaches another vessel.
 *
 * Roles (vessel.h): at most one FW_ROLE_OWN vessel, the own ship: the source
 * is told where it is, its sight is what the source's around() lists and
 * what the records and the survey follow.  FW_ROLE_OTHER vessels are stepped
 * by fairway too (a background ship taken from the source, a second ship
 * under a policy).  A world with no own ship works: nothing is placed into
 * the source, and the reactive traffic judges the source's ships among
 * themselves.
 *
 * One step, in this order (README.md, "One step of a run"):
 *   1. every vessel's dynamics advance dt under the order decided last
 *   2. the source is told where the own ship is and where every ship taken
 *      from it is (fw_world_take), and moves its own ships one step
 *   3. every vessel senses the ships within its sight, sorted by id: the
 *      source's (the own ship: around(); another vessel: within(), source.h)
 *      and the other vessels' records
 *   4. every vessel's controller decides its next order from what it sensed,
 *      and the source's ships that must give way to another are told their
 *      speed (reactions.h; orders take effect in the next step)
 * so after fw_world_start and after each step, everything read from the world
 * is of one instant: the positions and the decision taken on them.  A vessel
 * added after the start senses and decides at once; the others see it from
 * the next step.  A removed vessel leaves the others' views at the next step.
 *
 * The world checks nothing about collisions: that is the records' job
 * (run/records).
 */
#ifndef FW_WORLD_H
#define FW_WORLD_H

#include <stdbool.h>
#include <stdint.h>

#include "core/error.h"
#include "core/rng.h"
#include "env/env.h"
#include "sense/sensing.h"
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
    /* what the own ship knows of the others (sense/sensing.h): perfect by
     * default; with AIS its controller decides on the ships' reports, and
     * fw_vessel_truth still gives what was there */
    fw_sensing_def own_sensing;
    /* the own ship's watch (world/watch.h): flawless by default (it sees
     * every ship in its view at once); else a ship leaves its view (the
     * policy's, after the sensor) from when it first enters it until it is
     * noticed, and for good when the watch lapses for it */
    fw_watch_def own_watch;
} fw_world_def;

/* step 1 s, no source, blind traffic (a world built by hand has the traffic
 * its source scripts; scenarios choose colregs by default), calm water and
 * still air. */
fw_world_def fw_default_world_def(void);

typedef struct fw_world fw_world;

fw_status fw_world_create(const fw_world_def *def, fw_world **out, fw_error *err);
/* Safe on NULL. */
void fw_world_destroy(fw_world *w);

/* A vessel, by the slot it has in its world and that slot's generation;
 * the zero handle is no vessel (index1 counts from 1).  A slot's generation
 * wraps after 65536 removals from it, as Box2D's does. */
typedef struct fw_vessel_handle {
    int32_t index1;
    uint16_t generation;
} fw_vessel_handle;

static inline bool fw_vessel_handle_null(fw_vessel_handle h) { return h.index1 == 0; }

/* Adds a vessel (its controller is taken over, also on failure) at any time
 * between steps; FW_EINPUT on a bad def, an id already in the world, or a
 * second own ship.  out may be NULL. */
fw_status fw_world_add_vessel(fw_world *w, const fw_vessel_def *def, fw_vessel_handle *out,
                              fw_error *err);
/* Removes a vessel and frees its slot (FW_EINPUT for a stale handle).  A
 * vessel taken from the source must be given back instead.  Removing the own
 * ship leaves the source's idea of it where it was last placed. */
fw_status fw_world_remove_vessel(fw_world *w, fw_vessel_handle h, fw_error *err);
bool fw_world_vessel_valid(const fw_world *w, fw_vessel_handle h);
/* The vessel behind h, NULL for a stale handle.  A borrowed pointer for
 * reads (vessel.h's accessors): vessels are allocated one by one and never
 * moved, so it stays valid until that vessel is removed (steps, adds and
 * other removals leave it alone). */
fw_vessel *fw_world_vessel(fw_world *w, fw_vessel_handle h);
/* The own ship's handle (the zero handle: none). */
fw_vessel_handle fw_world_own(const fw_world *w);
/* The live vessels: count, and the i-th in slot order (0 <= i < count; the
 * zero handle otherwise), for walking them. */
int fw_world_vessel_count(const fw_world *w);
fw_vessel_handle fw_world_vessel_at(const fw_world *w, int i);

/* A source's ship (by id) becomes an FW_ROLE_OTHER vessel at its exact state
 * (position, heading, speed; its Loa and B from def->ship): the source stops
 * driving it and lists it no more among its ships, and is told every step
 * where the vessel is (source.h take / steer).  def gives the ship model,
 * dynamics, sight, controller (taken over, also on failure) and predictor;
 * its id, role and start are the source's.  FW_EINPUT when the source has no
 * such ship or cannot hand ships over. */
fw_status fw_world_take(fw_world *w, const char *ship, const fw_vessel_def *def,
                        fw_vessel_handle *out, fw_error *err);
/* A taken vessel back to its source (source.h give_back: it rejoins its
 * route ahead of where it is, at its speed; FW_EINPUT if it is not near its
 * route), and its slot freed. */
fw_status fw_world_give_back(fw_world *w, fw_vessel_handle h, fw_error *err);

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
    double place;     /* the own ship and the taken ones put into the traffic
                         (SUMO: moveToXY) */
    double traffic;   /* the traffic's own step (SUMO's) */
    double read;      /* the ships around the own ship read and converted */
    double decide;    /* sensing and the controllers (the avoidance policy) */
    double reactions; /* the traffic's reactions (its nearby read, give-way) */
} fw_world_timing;
const fw_world_timing *fw_world_timing_of(const fw_world *w);

double fw_world_time(const fw_world *w);  /* s */
uint64_t fw_world_seed(const fw_world *w); /* the def's seed */

/* The world's random streams (core/streams.h): every element that draws
 * takes its stream here once, by the vessel's key (0 for the own ship, a
 * hash of a source ship's id: rng.h) and its purpose, and keeps the pointer
 * (valid for the world's life).  fw_world_rekey gives every stream, made or
 * still to be made, fresh randomness from now on (a split's branch b > 0;
 * false when out of memory), and the watches' ships not yet detected a
 * fresh time to detect (watch.h fw_watch_redraw).  fw_world_streams: how many were made, 0 for a
 * world with no randomness after its start. */
fw_rng *fw_world_rng(fw_world *w, uint32_t vessel_key, fw_purpose purpose);
bool fw_world_rekey(fw_world *w, uint32_t branch);
int fw_world_streams(const fw_world *w);
long fw_world_steps(const fw_world *w);

/* Every ship in the area around the own ship, the own ship included, sorted
 * by id (the source's area query: the survey's input). */
fw_status fw_world_area(fw_world *w, const fw_target **ships, int *n, fw_error *err);

fw_source *fw_world_source(fw_world *w);
/* A background ship's lane as the source last said it (source.h
 * fw_lane_cache_get at the world's time); *out NULL when none is known. */
fw_status fw_world_lane(fw_world *w, const fw_target *s, const fw_lane_info **out, fw_error *err);

/* The own ship's sensor's counts (AIS reports sent, lost, arrived; all 0
 * with perfect sensing). */
fw_sensing_counts fw_world_sensing_counts(const fw_world *w);

/* The background ships' watch (world/watch.h): encounters met, lapsed. */
void fw_world_watch_counts(const fw_world *w, long *pairs, long *lapsed);
/* The own ship's watch: ships met, lapsed. */
void fw_world_own_watch_counts(const fw_world *w, long *pairs, long *lapsed);
/* The own ship's watch, when it draws: how near a ship it has not acted for
 * has come (watch.h fw_watch_unseen); -1 without such a watch. */
double fw_world_own_unseen(const fw_world *w);
/* The background ships drawn from the mix so far, by behaviour (watch.h). */
void fw_world_mix_counts(const fw_world *w, long counts[FW_BEH_N]);

/* Every order given to the source's ships so far (reactions.h). */
const fw_reaction *fw_world_reactions(const fw_world *w, int *n);

#endif
