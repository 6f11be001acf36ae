/* world_sense.c - each step's sensing and deciding (world.h): every
 * vessel's view of the others (the source's ships and the vessels, through
 * its sensor and watch), its decision, and the reactive traffic's step with
 * the ships it takes to steer and gives back. */
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "core/units.h"
#include "core/within.h"
#include "world/world_internal.h"

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
fw_status fw_world_sense_one(fw_world *w, int i, const fw_target *src, int n_src, fw_error *err)
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

fw_status fw_world_decide(fw_world *w, fw_vessel *v, fw_error *err)
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
        st = fw_world_give_back(w, fw_world_handle_of(w, i), &e2);
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

fw_status fw_world_sense_and_decide(fw_world *w, fw_error *err)
{
    const fw_target *src = NULL;
    int n_src = 0;
    fw_status st = FW_OK;
    fw_world_timing *tm = &w->timing;
    double t = fw_world_tick(w);
    if (w->source && w->own >= 0)
        st = fw_source_around(w->source, &src, &n_src, err);
    fw_world_lap(w, &tm->read, &t);
    /* the own ship first: the others' queries may reuse the source's list */
    if (!st && w->own >= 0)
        st = fw_world_sense_one(w, w->own, src, n_src, err);
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v && i != w->own)
            st = fw_world_sense_one(w, i, NULL, 0, err);
    /* every view is new: no copy of a gone ship's record is left */
    for (int i = 0; !st && i < w->n_grave; i++)
        free(w->grave[i]);
    if (!st)
        w->n_grave = 0;
    for (int i = 0; !st && i < w->n_slots; i++)
        if (w->slots[i].v)
            st = fw_world_decide(w, w->slots[i].v, err);
    fw_world_lap(w, &tm->decide, &t);
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
        fw_world_lap(w, &tm->reactions, &t);
    }
    return st;
}
