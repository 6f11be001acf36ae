/* world_internal.h - the world's state (world.h), shared by world.c (the
 * vessels' lifecycle and the step) and world_sense.c (what each vessel sees,
 * its decisions, and the reactive traffic's turn within the step). */
#ifndef FW_WORLD_INTERNAL_H
#define FW_WORLD_INTERNAL_H

#include <assert.h>

#include "core/clock.h"
#include "core/streams.h"
#include "world/steer.h"
#include "world/vessel_internal.h"
#include "world/world.h"

/* One place a vessel can live: the vessel (NULL: free) and how many times
 * the slot was freed, so that a handle outlives no vessel. */
typedef struct slot {
    fw_vessel *v;
    uint16_t generation;
    struct steered *steered; /* a steered background ship's model and predictor
                                (steer.h), made by the world */
} slot;

/* What the world makes for a background ship it steers: its model, the
 * predictor its helmsman keeps up to date (pred), and the one its record
 * points to (shown: pred as it was when the step began, the turn the others
 * see it making at that step's sensing, whichever decides first; the records
 * write it, worst.h replays it).  Freed only once no view holds a copy of
 * its record any more: at the next sensing after the vessel is gone. */
typedef struct steered {
    fw_ship ship;
    fw_turn_pred pred, shown;
} steered;

struct fw_world {
    fw_world_def def;
    fw_source *source;
    slot *slots;
    int n_slots, cap, nv;
    int own;            /* the own ship's slot, -1: none */
    fw_target *recs;    /* the vessels' records for the reactive traffic */
    int recs_cap;
    int n_taken;        /* vessels taken from the source */
    long steps;
    bool started, broken;
    fw_reactions *react;
    fw_world_timing timing;
    fw_streams *streams; /* every random stream of the world's elements */
    fw_sensor *sensor;   /* the own ship's (def.own_sensing) */
    fw_watch *own_watch; /* the own ship's (def.own_watch) */
    fw_rng *gust;        /* the wind's gusts (env.h; NULL: a steady wind) */
    steered **grave;     /* of vessels gone since the last sensing */
    int n_grave, grave_cap;
    fw_lane_cache lanes; /* the source's ships' lanes (fw_world_lane) */
    const fw_target **sight; /* the vessels a view adds, by id (in_sight) */
    int sight_cap;
};

/* The CPU clock when the def keeps timings, else 0 (no system calls). */
static inline double fw_world_tick(const fw_world *w) { return w->def.timing ? fw_cpu_s() : 0.0; }

/* Adds the time since *t to *acc and moves *t to now. */
static inline void fw_world_lap(const fw_world *w, double *acc, double *t)
{
    double now = fw_world_tick(w);
    *acc += now - *t;
    *t = now;
}

static inline fw_vessel_handle fw_world_handle_of(const fw_world *w, int i)
{
    assert(i >= 0 && i < w->n_slots && w->slots[i].v);
    return (fw_vessel_handle){.index1 = i + 1, .generation = w->slots[i].generation};
}

/* world_sense.c: the view of the vessel in slot i (the own ship's from the
 * source's ships src, n_src; the others query the source); a vessel's
 * decision on its view; every vessel's view and decision, then the reactive
 * traffic's step and the ships it takes to steer. */
fw_status fw_world_sense_one(fw_world *w, int i, const fw_target *src, int n_src, fw_error *err);
fw_status fw_world_decide(fw_world *w, fw_vessel *v, fw_error *err);
fw_status fw_world_sense_and_decide(fw_world *w, fw_error *err);

#endif
