/* world.c - the world and its step (world.h). */
#include "world/world.h"

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
#include "world/steer.h"
#include "world/vessel_internal.h"

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
static double tick(const fw_world *w) { return w->def.timing ? fw_cpu_s() : 0.0; }

/* Adds the time since *t to *acc and moves *t to now. */
static void lap(const fw_world *w, double *acc, double *t)
{
    double now = tick(w);
    *acc += now - *t;
    *t = now;
}

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

static fw_status sense_one(fw_world *w, int i, const fw_target *src, int n_src, fw_error *err);
static fw_status decide(fw_world *w, fw_vessel *v, fw_error *err);
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
        st = sense_one(w, *i, src, n_src, err);
    if (!st)
        st = decide(w, v, err);
    if (st) /* not half there: gone again */
        drop(w, *i);
    return st;
}

static fw_vessel_handle handle_of(const fw_world *w, int i)
{
    assert(i >= 0 && i < w->n_slots && w->slots[i].v);
    return (fw_vessel_handle){.index1 = i + 1, .generation = w->slots[i].generation};
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
        *out = handle_of(w, i);
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
        *out = handle_of(w, i);
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

static int cmp_id(const void *a, const void *b)
{
    return strcmp(((const fw_target *)a)->id, ((const fw_target *)b)->id);
}

/* The vessels other than slot i within sight r of (e, no), sorted by id
 * into w->sight (pointers to their records: their ids differ, check_new, so
 * any sort gives qsort's order); *m counts them. */
static fw_status in_sight(fw_world *w, int i, double e, double no, double r, int *m,
                          fw_error *err)
{
    *m = 0;
    if (!fw_reserve((void **)&w->sight, sizeof *w->sight, &w->sight_cap, w->nv))
        return fw_fail(err, FW_ERUN, "out of memory for %d vessels", w->nv);
    for (int j = 0; j < w->n_slots; j++) {
        const fw_vessel *o = w->slots[j].v;
        if (j == i || !o || !fw_within_range(o->record.east - e, o->record.north - no, r))
            continue;
        int b = (*m)++;
        for (; b > 0 && strcmp(w->sight[b - 1]->id, o->record.id) > 0; b--)
            w->sight[b] = w->sight[b - 1];
        w->sight[b] = &o->record;
    }
    return FW_OK;
}

/* The view: the source's ships src[0, ns) (those within r of (e, no) if
 * filter) and the vessels in w->sight[0, m), sorted by id as qsort (glibc's
 * merge sort: stable) sorts the ships then the vessels, the source's first
 * among equal ids.  Every source that sorts (SUMO's, fw_traffic_nearby and
 * ss_around) gives its ships by id: they are merged with the vessels as
 * they are copied, each record copied once (before: the source's ships
 * copied, the vessels sorted apart and merged in, 43 M instructions of the
 * 1 nm fog run's 3.6 G); ships out of order are sorted whole, as before. */
static int make_view(const fw_world *w, fw_target *view, const fw_target *src, int ns,
                     bool filter, double e, double no, double r, int m)
{
    int n = 0, j = 0;
    const char *last = NULL;
    for (int a = 0; a < ns; a++) {
        if (filter && !fw_within_range(src[a].east - e, src[a].north - no, r))
            continue;
        if (m > 0 && last && strcmp(last, src[a].id) > 0) {
            /* out of order: the ships, then the vessels, sorted whole */
            n = 0;
            for (int b = 0; b < ns; b++)
                if (!filter || fw_within_range(src[b].east - e, src[b].north - no, r))
                    view[n++] = src[b];
            for (int b = 0; b < m; b++)
                view[n++] = *w->sight[b];
            qsort(view, (size_t)n, sizeof *view, cmp_id);
            return n;
        }
        for (; j < m && strcmp(w->sight[j]->id, src[a].id) < 0; j++)
            view[n++] = *w->sight[j];
        view[n++] = src[a];
        last = src[a].id;
    }
    for (; j < m; j++)
        view[n++] = *w->sight[j];
    return n;
}

/* The source's ships a vessel other than the own ship sees: source.h
 * within(), or nearby() filtered (*filter). */
static fw_status source_ships(fw_world *w, const fw_vessel *v, const fw_target **src, int *ns,
                              bool *filter, fw_error *err)
{
    const fw_source_ops *ops = w->source->ops;
    *filter = !ops->within;
    return ops->within ? ops->within(w->source, v->record.east, v->record.north, v->radius, src,
                                     ns, err)
                       : fw_source_nearby(w->source, src, ns, err);
}

/* The own ship's watch (def.own_watch): the ships in its view v it has not
 * noticed yet leave it. */
static fw_status own_watch(fw_world *w, fw_vessel *v, fw_error *err)
{
    int m = 0;
    for (int j = 0; j < v->n_view; j++) {
        int k = fw_watch_noticed(w->own_watch, &v->record, &v->view[j], fw_world_time(w));
        if (k < 0)
            return fw_fail(err, FW_ERUN, "out of memory for the own ship's watch");
        if (k)
            v->view[m++] = v->view[j];
    }
    v->n_view = m;
    return FW_OK;
}

/* The vessel in slot i's view: the source's ships (src, n_src: the own
 * ship's around(); the others query within()), then the other vessels within
 * its sight; sorted by id. */
static fw_status sense_one(fw_world *w, int i, const fw_target *src, int n_src, fw_error *err)
{
    fw_vessel *v = w->slots[i].v;
    int m;
    bool filter = false;
    fw_status st = in_sight(w, i, v->record.east, v->record.north, v->radius, &m, err);
    if (!st && i != w->own && w->source)
        st = source_ships(w, v, &src, &n_src, &filter, err);
    else if (i != w->own)
        n_src = 0;
    if (!st)
        st = fw_vessel_reserve(v, n_src + w->nv, err);
    if (st)
        return st;
    int n = make_view(w, v->view, src, n_src, filter, v->record.east, v->record.north,
                      v->radius, m);
    v->n_view = n;
    bool sensor = i == w->own && w->def.own_sensing.mode != FW_SENSE_PERFECT;
    bool watch = i == w->own && fw_watch_active(w->own_watch);
    /* a ship taken from the traffic (steered for it, world/steer.h) sees as
     * the reacting traffic does */
    bool traffic = i != w->own && v->taken && fw_reactions_active(w->react) &&
                   w->def.reactions.sensing.mode != FW_SENSE_PERFECT;
    if (sensor || watch || traffic) {
        /* the truth kept for the records; the view is what the sensor knows
         * and the watch has noticed */
        memcpy(v->truth, v->view, sizeof *v->view * (size_t)n);
        v->n_truth = n;
        v->sensed = true;
    }
    if (sensor)
        fw_sensor_place(w->sensor, &v->record); /* the antenna, for the radar */
    if (sensor && (st = fw_sensor_update(w->sensor, fw_world_time(w), v->truth, n, v->view,
                                         &v->n_view, err)))
        return st;
    if (traffic) {
        int m = 0;
        for (int j = 0; j < n; j++)
            m += fw_reactions_known(w->react, &v->record, &v->truth[j], fw_world_time(w),
                                    &v->view[m]);
        v->n_view = m;
    }
    return watch ? own_watch(w, v, err) : FW_OK;
}

void fw_world_watch_counts(const fw_world *w, long *pairs, long *lapsed)
{
    fw_reactions_watch_counts(w->react, pairs, lapsed);
}

double fw_world_own_unseen(const fw_world *w)
{
    return fw_watch_def_draws(&w->def.own_watch) ? fw_watch_unseen(w->own_watch) : -1.0;
}

void fw_world_mix_counts(const fw_world *w, long counts[FW_BEH_N])
{
    fw_reactions_mix_counts(w->react, counts);
}

void fw_world_own_watch_counts(const fw_world *w, long *pairs, long *lapsed)
{
    fw_watch_counts(w->own_watch, pairs, lapsed);
}

fw_sensing_counts fw_world_sensing_counts(const fw_world *w)
{
    return fw_sensor_counts(w->sensor);
}

/* The viewed targets' lanes (fw_world_lane; the cache keeps each ship's
 * where it is while it grows), *out NULL without a source. */
static fw_status view_lanes(fw_world *w, fw_vessel *v, const fw_lane_info *const **out,
                            fw_error *err)
{
    *out = NULL;
    if (!w->source)
        return FW_OK;
    fw_status st = FW_OK;
    for (int i = 0; i < v->n_view && !st; i++)
        st = fw_world_lane(w, &v->view[i], &v->lanes[i], err);
    *out = v->lanes;
    return st;
}

static fw_status decide(fw_world *w, fw_vessel *v, fw_error *err)
{
    if (!v->ctl) {
        v->d = (fw_decision){.mode = FW_MODE_STANDBY, .helm = 0.0, .reason = "no controller",
                             .primary = -1};
        return FW_OK;
    }
    fw_sense in = {.t = fw_world_time(w), .own = &v->own, .targets = v->view, .n = v->n_view,
                   .as = v->as, .order = v->order};
    fw_status st = view_lanes(w, v, &in.lanes, err);
    return st ? st : v->ctl->ops->decide(v->ctl, &in, &v->d, err);
}

/* Every vessel's record, the own ship first (the own ship alone: its own
 * record, nothing copied). */
static fw_status vessel_records(fw_world *w, const fw_target **v, int *n, fw_error *err)
{
    *n = 0;
    *v = NULL;
    if (w->nv == 1 && w->own >= 0) {
        *v = &w->slots[w->own].v->record;
        *n = 1;
        return FW_OK;
    }
    if (!fw_reserve((void **)&w->recs, sizeof *w->recs, &w->recs_cap, w->nv))
        return fw_fail(err, FW_ERUN, "out of memory for %d vessels", w->nv);
    if (w->own >= 0)
        w->recs[(*n)++] = w->slots[w->own].v->record;
    for (int i = 0; i < w->n_slots; i++)
        if (w->slots[i].v && i != w->own)
            w->recs[(*n)++] = w->slots[i].v->record;
    *v = w->recs;
    return FW_OK;
}

/* The ships the reactive traffic decided to steer (reactions.h give_way
 * course) taken from the source, each with its model and helmsman (steer.h). */
static fw_status take_orders(fw_world *w, fw_error *err)
{
    int n;
    const fw_take_order *o = fw_reactions_takes(w->react, &n);
    for (int k = 0; k < n; k++) {
        steered *sd_mem = malloc(sizeof *sd_mem);
        if (!sd_mem)
            return fw_fail(err, FW_ERUN, "out of memory for a ship to steer");
        fw_steer_ship(o[k].ship.length, o[k].ship.breadth, o[k].ship.type, &sd_mem->ship);
        fw_turn_pred_init(&sd_mem->pred);
        fw_turn_pred_init(&sd_mem->shown);
        fw_alter_def sd = fw_default_alter_def();
        sd.lane = o[k].lane;
        sd.alteration = o[k].alteration;
        sd.cpa = o[k].cpa;
        sd.length = o[k].ship.length;
        sd.breadth = o[k].ship.breadth;
        sd.speed = o[k].speed;
        /* as reactions.h decided it: a tenth of the room and its half breadth spare */
        sd.room = fmax(0.0, 0.9 * o[k].lane.room_starboard - 0.5 * o[k].ship.breadth);
        snprintf(sd.other, sizeof sd.other, "%s", o[k].other);
        sd.pred = &sd_mem->pred;
        fw_vessel_def vd = fw_default_vessel_def();
        vd.ship = &sd_mem->ship;
        vd.predictor = &sd_mem->shown.base;
        vd.dynamics = FW_DYN_NOMOTO;
        vd.radius = w->def.reactions.range;
        fw_vessel_handle h;
        fw_status st = fw_steer_controller_create(&sd, &vd.controller, err);
        if (!st)
            st = fw_world_take(w, o[k].ship.id, &vd, &h, err);
        if (st) {
            free(sd_mem);
            return st;
        }
        w->slots[h.index1 - 1].steered = sd_mem;
    }
    return FW_OK;
}

/* A steered ship's further alteration (steer.h), recorded as the reactive
 * traffic's are. */
static fw_status record_news(fw_world *w, fw_vessel *v, fw_error *err)
{
    fw_reaction x = {.t = fw_world_time(w), .kind = FW_REACT_ALTER, .enough = true,
                     .speed_from = v->record.speed, .speed_to = v->record.speed,
                     .dcpa_before = NAN, .dcpa_after = NAN};
    if (!fw_steer_controller_news(v->ctl, &x.course_from, &x.course_to, x.other, &x.situation))
        return FW_OK;
    x.course_from = fw_wrap_2pi(x.course_from), x.course_to = fw_wrap_2pi(x.course_to);
    snprintf(x.ship, sizeof x.ship, "%s", v->id);
    return fw_reactions_note(w->react, &x, err);
}

/* The steered ships' further alterations recorded, and those back on their
 * lanes given back to the source (one the source finds not yet on its
 * route's line is steered on and tried again the next step), each recorded. */
static fw_status steered_ships(fw_world *w, fw_error *err)
{
    for (int i = 0; w->n_taken > 0 && i < w->n_slots; i++) {
        fw_vessel *v = w->slots[i].v;
        if (!v || !v->taken || !fw_steer_controller_is(v->ctl))
            continue;
        fw_status st = record_news(w, v, err);
        if (st)
            return st;
        if (fw_steer_controller_phase(v->ctl) != FW_STEER_DONE)
            continue;
        fw_target rec = v->record;
        fw_error e2 = {0};
        st = fw_world_give_back(w, handle_of(w, i), &e2);
        if (st == FW_EINPUT)
            continue;
        if (st) {
            *err = e2;
            return st;
        }
        fw_reaction x = {.t = fw_world_time(w), .kind = FW_REACT_REJOIN,
                         .speed_from = rec.speed, .speed_to = rec.speed, .enough = true,
                         .course_from = rec.course, .course_to = rec.course};
        snprintf(x.ship, sizeof x.ship, "%s", rec.id);
        if ((st = fw_reactions_note(w->react, &x, err)))
            return st;
    }
    return FW_OK;
}

static fw_status sense_and_decide(fw_world *w, fw_error *err)
{
    const fw_target *src = NULL;
    int n_src = 0;
    fw_status st = FW_OK;
    fw_world_timing *tm = &w->timing;
    double t = tick(w);
    if (w->source && w->own >= 0)
        st = fw_source_around(w->source, &src, &n_src, err);
    lap(w, &tm->read, &t);
    /* the own ship first: the others' queries may reuse the source's list */
    if (!st && w->own >= 0)
        st = sense_one(w, w->own, src, n_src, err);
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v && i != w->own)
            st = sense_one(w, i, NULL, 0, err);
    /* every view is new: no copy of a gone ship's record is left */
    for (int i = 0; !st && i < w->n_grave; i++)
        free(w->grave[i]);
    if (!st)
        w->n_grave = 0;
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v)
            st = decide(w, w->slots[i].v, err);
    lap(w, &tm->decide, &t);
    /* the reactive traffic watches its own, wider circle (traffic/source.h) */
    if (!st && w->source && fw_reactions_active(w->react)) {
        const fw_target *vs;
        int nvs = 0;
        src = NULL, n_src = 0;
        st = steered_ships(w, err);
        if (!st && w->own >= 0)
            st = fw_source_nearby(w->source, &src, &n_src, err);
        if (!st)
            st = vessel_records(w, &vs, &nvs, err);
        if (!st)
            st = fw_reactions_step(w->react, fw_world_time(w), vs, nvs, src, n_src, w->source,
                                   err);
        if (!st)
            st = take_orders(w, err);
        lap(w, &tm->reactions, &t);
    }
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
        st = sense_and_decide(w, err);
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
    double t = tick(w);
    for (int i = 0; i < w->n_slots; i++) /* the turns the records will show */
        if (w->slots[i].steered)
            w->slots[i].steered->shown = w->slots[i].steered->pred;
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v)
            st = fw_vessel_advance(w->slots[i].v, w->def.step, err);
    if (w->gust) /* the gust of the next step */
        fw_wind_gust_step(&w->def.env.wind, w->def.step, w->gust);
    lap(w, &tm->dynamics, &t);
    if (!st && w->source) {
        st = tell_source(w, err);
        lap(w, &tm->place, &t);
        if (!st)
            st = fw_source_advance(w->source, err);
        lap(w, &tm->traffic, &t);
    }
    if (!st) {
        w->steps++;
        st = sense_and_decide(w, err);
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
    return w->own < 0 ? (fw_vessel_handle){0} : handle_of(w, w->own);
}

fw_vessel_handle fw_world_vessel_at(const fw_world *w, int i)
{
    for (int j = 0; i >= 0 && j < w->n_slots; j++)
        if (w->slots[j].v && i-- == 0)
            return handle_of(w, j);
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
