/* world.c - the world and its step (world.h): vessels added, taken, given
 * back and removed, the step; sensing and deciding are world_sense.c's. */
#include "world/world_internal.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "core/mem.h"
#include "core/streams.h"
#include "core/units.h"
#include "core/within.h"
#include "world/world_internal.h"

fw_world_def fw_default_world_def(void)
{
    fw_world_def d = {.step = 1.0, .source = NULL, .reactions = fw_default_reactions_def(),
                      .env = fw_default_env(), .seed = 1,
                      .own_sensing = fw_default_sensing_def(),
                      .own_watch = fw_default_watch_def()};
    d.reactions.behaviour = FW_BEHAVIOUR_BLIND;
    return d;
}

void fw_world_destroy(fw_world *w)
{
    if (!w)
        return;
    for (int i = 0; i < w->n_slots; i++) {
        if (w->slots[i].v)
            fw_vessel_free(w->slots[i].v);
        free(w->slots[i].v);
        free(w->slots[i].steered);
    }
    for (int i = 0; i < w->n_grave; i++)
        free(w->grave[i]);
    free(w->grave);
    free(w->slots);
    free(w->recs);
    free((void *)w->sight);
    fw_source_destroy(w->source);
    fw_lane_cache_free(&w->lanes);
    fw_reactions_destroy(w->react);
    fw_sensor_destroy(w->sensor);
    fw_watch_destroy(w->own_watch);
    fw_streams_free(w->streams);
    free(w);
}

/* The sensor's and the watch's way to the world's streams (core/rng.h fw_rng_getter). */
static fw_rng *world_rng(void *ctx, uint32_t key, fw_purpose purpose)
{
    return fw_world_rng(ctx, key, purpose);
}

fw_status fw_world_create(const fw_world_def *def, fw_world **out, fw_error *err)
{
    *out = NULL;
    if (!(def->step > 0.0 && isfinite(def->step))) {
        fw_source_destroy(def->source);
        return fw_fail(err, FW_EINPUT, "world step %g s: must be positive", def->step);
    }
    if (def->source && fabs(fw_source_step_length(def->source) - def->step) > 1e-9) {
        double s = fw_source_step_length(def->source);
        fw_source_destroy(def->source);
        return fw_fail(err, FW_EINPUT, "the traffic source steps %g s, the world %g s", s,
                       def->step);
    }
    if (fw_env_check(&def->env, err)) {
        fw_source_destroy(def->source);
        return FW_EINPUT;
    }
    fw_world *w = calloc(1, sizeof *w);
    if (!w) {
        fw_source_destroy(def->source);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    w->def = *def;
    w->source = def->source;
    w->own = -1;
    w->streams = fw_streams_create(def->seed);
    if (!w->streams) {
        fw_world_destroy(w);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    fw_status st = fw_reactions_create(&def->reactions, &w->react, err);
    if (!st)
        fw_reactions_set_rng(w->react, world_rng, w);
    if (!st)
        st = fw_sensor_create(&def->own_sensing, world_rng, w, &w->sensor, err);
    if (!st && !(st = fw_watch_create(&def->own_watch, &w->own_watch, err)))
        fw_watch_set_rng(w->own_watch, world_rng, w);
    if (!st && fw_wind_gusty(&w->def.env.wind)) {
        /* the field's stream: key 0 (the own ship's), purpose gust */
        if (!(w->gust = fw_world_rng(w, 0, FW_PURPOSE_GUST)))
            st = fw_fail(err, FW_ERUN, "out of memory");
        else
            fw_wind_gust_start(&w->def.env.wind, w->gust);
    }
    if (st) {
        fw_world_destroy(w);
        return st;
    }
    *out = w;
    return FW_OK;
}

/* The slot behind h, or -1 for a null or stale handle. */
static int slot_of(const fw_world *w, fw_vessel_handle h)
{
    int i = h.index1 - 1;
    if (i < 0 || i >= w->n_slots || !w->slots[i].v || w->slots[i].generation != h.generation)
        return -1;
    return i;
}

static fw_status stale(fw_vessel_handle h, fw_error *err)
{
    return fw_fail(err, FW_EINPUT, "vessel handle (slot %d, generation %u) is stale or null",
                   (int)h.index1, (unsigned)h.generation);
}

/* A free slot (the lowest: the same calls give the same slots), grown if none. */
static int free_slot(fw_world *w, fw_error *err)
{
    for (int i = 0; i < w->n_slots; i++)
        if (!w->slots[i].v)
            return i;
    if (!fw_reserve((void **)&w->slots, sizeof *w->slots, &w->cap, w->n_slots + 1)) {
        fw_fail(err, FW_ERUN, "out of memory for %d vessels", w->n_slots + 1);
        return -1;
    }
    w->slots[w->n_slots] = (slot){0};
    return w->n_slots++;
}

static fw_status check_new(const fw_world *w, const fw_vessel_def *def, fw_error *err)
{
    if (def->role == FW_ROLE_OWN && w->own >= 0)
        return fw_fail(err, FW_EINPUT, "vessel '%s': the world has an own ship already ('%s')",
                       def->id ? def->id : "", w->slots[w->own].v->id);
    for (int i = 0; i < w->n_slots; i++)
        if (w->slots[i].v && def->id && strcmp(w->slots[i].v->id, def->id) == 0)
            return fw_fail(err, FW_EINPUT, "vessel '%s' added twice", def->id);
    return FW_OK;
}

static void drop(fw_world *w, int i);

/* A vessel into slot *i; after the start it senses and decides at once (the
 * own ship placed into the source first).  The controller is taken over. */
static fw_status add(fw_world *w, const fw_vessel_def *def, bool taken, int *i, fw_error *err)
{
    fw_vessel *v = NULL;
    fw_status st = check_new(w, def, err);
    if (!st && (*i = free_slot(w, err)) < 0)
        st = FW_ERUN;
    if (!st && !(v = calloc(1, sizeof *v)))
        st = fw_fail(err, FW_ERUN, "out of memory");
    /* a ship taken from the source is a background ship: wind acts on none
     * of them, SUMO's or fairway's (steer.h) */
    if (!st && def->ship && !taken)
        st = fw_env_check_vessel(&w->def.env, def->id ? def->id : "?", def->ship,
                                 def->dynamics == FW_DYN_MMG, err);
    if (!st)
        st = fw_vessel_init(v, def, w->def.step, &w->def.env, err);
    if (st) {
        /* taken over also on failure: v->ctl is not set yet, so v's free
         * leaves it alone */
        fw_controller_destroy(def->controller);
        if (v)
            fw_vessel_free(v);
        free(v);
        return st;
    }
    v->ctl = def->controller;
    v->taken = taken;
    w->slots[*i].v = v;
    w->nv++;
    w->n_taken += taken;
    if (def->role == FW_ROLE_OWN)
        w->own = *i;
    if (!w->started)
        return FW_OK;
    const fw_target *src = NULL;
    int n_src = 0;
    if (w->own == *i && w->source &&
        !(st = fw_source_place(w->source, &v->record, err)))
        st = fw_source_around(w->source, &src, &n_src, err);
    if (!st)
        st = fw_world_sense_one(w, *i, src, n_src, err);
    if (!st)
        st = fw_world_decide(w, v, err);
    if (st) /* not half there: gone again */
        drop(w, *i);
    return st;
}

fw_status fw_world_add_vessel(fw_world *w, const fw_vessel_def *def, fw_vessel_handle *out,
                              fw_error *err)
{
    if (out)
        *out = (fw_vessel_handle){0};
    if (w->broken) {
        fw_controller_destroy(def->controller);
        return fw_fail(err, FW_ERUN, "the world failed in an earlier step");
    }
    int i;
    fw_status st = add(w, def, false, &i, err);
    if (!st && out)
        *out = fw_world_handle_of(w, i);
    return st;
}

/* Slot i freed: its vessel gone, its generation bumped. */
static void drop(fw_world *w, int i)
{
    fw_vessel *v = w->slots[i].v;
    assert(v && w->nv > 0 && (w->own == i) == (v->role == FW_ROLE_OWN));
    w->n_taken -= v->taken;
    if (w->own == i)
        w->own = -1;
    fw_vessel_free(v);
    free(v);
    if (w->slots[i].steered) {
        /* copies of its record (with the predictor) may be in views until
         * the next sensing: freed then; if no room to wait, now (the views
         * of this step are then not read again) */
        if (fw_reserve((void **)&w->grave, sizeof *w->grave, &w->grave_cap, w->n_grave + 1))
            w->grave[w->n_grave++] = w->slots[i].steered;
        else
            free(w->slots[i].steered);
        w->slots[i].steered = NULL;
    }
    w->slots[i].v = NULL;
    w->slots[i].generation++;
    w->nv--;
}

fw_status fw_world_remove_vessel(fw_world *w, fw_vessel_handle h, fw_error *err)
{
    int i = slot_of(w, h);
    if (i < 0)
        return stale(h, err);
    if (w->slots[i].v->taken)
        return fw_fail(err, FW_EINPUT, "vessel '%s' was taken from the source: give it back",
                       w->slots[i].v->id);
    drop(w, i);
    return FW_OK;
}

fw_status fw_world_take(fw_world *w, const char *ship, const fw_vessel_def *def,
                        fw_vessel_handle *out, fw_error *err)
{
    if (out)
        *out = (fw_vessel_handle){0};
    fw_target at;
    fw_status st = w->broken ? fw_fail(err, FW_ERUN, "the world failed in an earlier step")
                   : !w->source ? fw_fail(err, FW_EINPUT, "no traffic source to take '%s' from",
                                          ship)
                                : FW_OK;
    fw_vessel_def vd = *def;
    vd.id = ship;
    vd.role = FW_ROLE_OTHER;
    if (!st)
        st = check_new(w, &vd, err);
    if (!st)
        st = fw_source_take(w->source, ship, &at, err);
    if (st) {
        fw_controller_destroy(def->controller);
        return st;
    }
    vd.east = at.east, vd.north = at.north, vd.course = at.course, vd.speed = at.speed;
    int i;
    if ((st = add(w, &vd, true, &i, err))) {
        /* not a vessel after all: the source drives it on from where it was */
        fw_error e2 = {0};
        fw_source_give_back(w->source, &at, &e2);
        return st;
    }
    if (out)
        *out = fw_world_handle_of(w, i);
    return FW_OK;
}

fw_status fw_world_give_back(fw_world *w, fw_vessel_handle h, fw_error *err)
{
    int i = slot_of(w, h);
    if (i < 0)
        return stale(h, err);
    fw_vessel *v = w->slots[i].v;
    if (!v->taken)
        return fw_fail(err, FW_EINPUT, "vessel '%s' was not taken from the source", v->id);
    fw_status st = fw_source_give_back(w->source, &v->record, err);
    if (!st)
        drop(w, i);
    return st;
}

fw_status fw_world_start(fw_world *w, fw_error *err)
{
    if (w->started)
        return fw_fail(err, FW_EINPUT, "the world has already started");
    w->started = true;
    fw_status st = FW_OK;
    if (w->source && w->own >= 0)
        st = fw_source_place(w->source, &w->slots[w->own].v->record, err);
    if (!st)
        st = fw_world_sense_and_decide(w, err);
    w->broken = st != FW_OK;
    return st;
}

/* The source told where the own ship and every taken ship are now. */
static fw_status tell_source(fw_world *w, fw_error *err)
{
    fw_status st = FW_OK;
    if (w->own >= 0)
        st = fw_source_place(w->source, &w->slots[w->own].v->record, err);
    for (int i = 0; !st && w->n_taken > 0 && i < w->n_slots; i++)
        if (w->slots[i].v && w->slots[i].v->taken)
            st = fw_source_steer(w->source, &w->slots[i].v->record, err);
    return st;
}

fw_status fw_world_step(fw_world *w, double dt, fw_error *err)
{
    if (!w->started || w->broken)
        return fw_fail(err, FW_ERUN, w->broken ? "the world failed in an earlier step"
                                              : "fw_world_start first");
    if (fabs(dt - w->def.step) > 1e-9 * w->def.step)
        return fw_fail(err, FW_EINPUT, "step %g s: this world steps %g s", dt, w->def.step);
    fw_status st = FW_OK;
    fw_world_timing *tm = &w->timing;
    double t = fw_world_tick(w);
    for (int i = 0; i < w->n_slots; i++) /* the turns the records will show */
        if (w->slots[i].steered)
            w->slots[i].steered->shown = w->slots[i].steered->pred;
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v)
            st = fw_vessel_advance(w->slots[i].v, w->def.step, err);
    if (w->gust) /* the gust of the next step */
        fw_wind_gust_step(&w->def.env.wind, w->def.step, w->gust);
    fw_world_lap(w, &tm->dynamics, &t);
    if (!st && w->source) {
        st = tell_source(w, err);
        fw_world_lap(w, &tm->place, &t);
        if (!st)
            st = fw_source_advance(w->source, err);
        fw_world_lap(w, &tm->traffic, &t);
    }
    if (!st) {
        w->steps++;
        st = fw_world_sense_and_decide(w, err);
    }
    w->broken = st != FW_OK;
    return st;
}

const fw_world_timing *fw_world_timing_of(const fw_world *w) { return &w->timing; }
double fw_world_time(const fw_world *w) { return (double)w->steps * w->def.step; }
uint64_t fw_world_seed(const fw_world *w) { return w->def.seed; }
fw_rng *fw_world_rng(fw_world *w, uint32_t vessel_key, fw_purpose purpose)
{
    return fw_streams_get(w->streams, vessel_key, purpose);
}
bool fw_world_rekey(fw_world *w, uint32_t branch)
{
    /* the watches' pending detections are drawn afresh (watch.h fw_watch_redraw) */
    return fw_streams_rekey(w->streams, branch) &&
           fw_watch_redraw(w->own_watch, fw_world_time(w)) >= 0 &&
           fw_reactions_redraw(w->react, fw_world_time(w)) >= 0;
}
int fw_world_streams(const fw_world *w) { return fw_streams_count(w->streams); }
long fw_world_steps(const fw_world *w) { return w->steps; }
int fw_world_vessel_count(const fw_world *w) { return w->nv; }
fw_source *fw_world_source(fw_world *w) { return w->source; }

fw_status fw_world_lane(fw_world *w, const fw_target *s, const fw_lane_info **out, fw_error *err)
{
    *out = NULL;
    if (!w->source || s->own)
        return FW_OK;
    return fw_lane_cache_get(&w->lanes, w->source, s, fw_world_time(w), out, err);
}
bool fw_world_vessel_valid(const fw_world *w, fw_vessel_handle h) { return slot_of(w, h) >= 0; }

fw_vessel *fw_world_vessel(fw_world *w, fw_vessel_handle h)
{
    int i = slot_of(w, h);
    return i < 0 ? NULL : w->slots[i].v;
}

fw_vessel_handle fw_world_own(const fw_world *w)
{
    return w->own < 0 ? (fw_vessel_handle){0} : fw_world_handle_of(w, w->own);
}

fw_vessel_handle fw_world_vessel_at(const fw_world *w, int i)
{
    for (int j = 0; i >= 0 && j < w->n_slots; j++)
        if (w->slots[j].v && i-- == 0)
            return fw_world_handle_of(w, j);
    return (fw_vessel_handle){0};
}

const fw_reaction *fw_world_reactions(const fw_world *w, int *n)
{
    return fw_reactions_list(w->react, n);
}

fw_status fw_world_area(fw_world *w, const fw_target **ships, int *n, fw_error *err)
{
    *ships = NULL;
    *n = 0;
    if (!w->source)
        return fw_fail(err, FW_ERUN, "no area query without a traffic source");
    return fw_source_area(w->source, ships, n, err);
}
