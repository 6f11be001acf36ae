/* source_sumo.c - the SUMO traffic source (source_sumo.h). */
#include "traffic/source_sumo_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "core/files.h"
#include "core/mem.h"
#include "core/units.h"
#include "geom/geo.h"
#include "geom/geom.h"
#include "traffic/demand.h"
#include "ship/ship.h"
#include "traffic/netbuild.h"

typedef struct sumo_source {
    fw_source base;
    fw_traffic *tr;
    double step;
    long steps;
    double wall;          /* s, in SUMO's steps */
    fw_target *sorted;    /* around(), sorted by id */
    int cap;
    fw_target *labels;    /* explicit targets: id -> the scenario's type label */
    int n_labels;
    int cleared;          /* fill ships taken out at the start */
    int unplaced;         /* fill ships SUMO found no room for at the start */
    double near_radius;   /* m, nearby() (0: around())   */
    /* ships taken by fairway (source.h take), as last steered: left out of
     * around() and nearby(), listed so in area() */
    fw_target *taken;
    int n_taken, taken_cap;
    fw_target *listed;    /* around() / nearby() / area() with the taken ships seen to */
    int listed_cap;
    long taken_change;    /* counts the takes and give-backs */
    /* listed[0..listed_n-1] is nearby() of the traffic's answer listed_answer
     * with the taken ships of taken_change left out (listed_near: it is) */
    bool listed_near;
    long listed_answer, listed_taken;
    int listed_n;
    /* the ships given back since the last advance(), as fairway left them:
     * one taken again before SUMO has stepped it starts from there */
    fw_target *given;
    int n_given, given_cap;
} sumo_source;

fw_sumo_source_def fw_default_sumo_source_def(void)
{
    return (fw_sumo_source_def){.mode = {.kind = FW_TRAFFIC_EMBEDDED}, .density = 1.0, .seed = 1,
                                .duration = 3600.0, .step = 1.0,
                                .own = {.id = "fw_own", .length = 100.0, .breadth = 16.0},
                                .radius = 6.0 * 1852.0, .clear_range = 2.0 * 1852.0,
                                .clear_cpa = 0.25 * 1852.0, .clear_tcpa = 600.0};
}

static double ss_time(const fw_source *s)
{
    const sumo_source *k = (const sumo_source *)s;
    return (double)k->steps * k->step;
}

static double ss_step_length(const fw_source *s) { return ((const sumo_source *)s)->step; }

static fw_status ss_place(fw_source *s, const fw_target *own, fw_error *err)
{
    return fw_traffic_place(((sumo_source *)s)->tr, own->east, own->north, own->heading,
                            own->speed, err);
}

static fw_status ss_advance(fw_source *s, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    double t0 = fw_clock_s();
    fw_status st = fw_traffic_step(k->tr, err);
    k->wall += fw_clock_s() - t0;
    if (!st)
        k->steps++;
    k->n_given = 0;
    return st;
}

static int cmp_id(const void *a, const void *b)
{
    return strcmp(((const fw_target *)a)->id, ((const fw_target *)b)->id);
}

/* The index of ship t among the taken ones (-1: not taken): by the run's
 * key where both have one (an int compare, not a string's, for every ship
 * of every list), else by id. */
static int find_taken(const sumo_source *k, const fw_target *t)
{
    for (int j = 0; j < k->n_taken; j++)
        if (t->key > 0 && k->taken[j].key > 0 ? t->key == k->taken[j].key
                                              : strcmp(t->id, k->taken[j].id) == 0)
            return j;
    return -1;
}

static fw_status ss_around(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    const fw_target *raw;
    int m;
    *v = k->sorted;
    *n = 0;
    fw_status st = fw_traffic_around(k->tr, &raw, &m, err);
    if (st)
        return st;
    if (!fw_reserve((void **)&k->sorted, sizeof *k->sorted, &k->cap, m))
        return fw_fail(err, FW_ERUN, "out of memory for %d ships", m);
    if (m > 0) /* no ship in range yet: the buffer may still be NULL */
        memcpy(k->sorted, raw, sizeof *raw * (size_t)m);
    for (int i = 0; i < m; i++) {
        fw_target *t = &k->sorted[i];
        if (strncmp(t->type, TARGET_TYPE_PREFIX, strlen(TARGET_TYPE_PREFIX)) != 0)
            continue;
        int j = fw_target_find(k->labels, k->n_labels, t->id);
        if (j >= 0)
            memcpy(t->type, k->labels[j].type, sizeof t->type);
    }
    /* sorted by id so that nothing downstream depends on SUMO's order */
    if (m > 1)
        qsort(k->sorted, (size_t)m, sizeof *k->sorted, cmp_id);
    int kept = 0;
    for (int i = 0; i < m; i++)
        if (k->n_taken == 0 || find_taken(k, &k->sorted[i]) < 0)
            k->sorted[kept++] = k->sorted[i];
    *v = k->sorted;
    *n = kept;
    return FW_OK;
}

/* list (n) with the taken ships left out (area: listed as steered), into
 * k->listed; list as it is when nothing is taken. */
static fw_status see_to_taken(sumo_source *k, bool area, const fw_target **v, int *n,
                              fw_error *err)
{
    if (k->n_taken == 0)
        return FW_OK;
    k->listed_near = false;
    if (!fw_reserve((void **)&k->listed, sizeof *k->listed, &k->listed_cap, *n))
        return fw_fail(err, FW_ERUN, "out of memory for %d ships", *n);
    int m = 0;
    for (int i = 0; i < *n; i++) {
        int j = find_taken(k, &(*v)[i]);
        if (j < 0)
            k->listed[m++] = (*v)[i];
        else if (area)
            k->listed[m++] = k->taken[j];
    }
    *v = k->listed;
    *n = m;
    return FW_OK;
}

static fw_status ss_area(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    fw_status st = fw_traffic_area(k->tr, v, n, err);
    return st ? st : see_to_taken(k, true, v, n, err);
}

static fw_status ss_nearby(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    if (!(k->near_radius > 0.0))
        return ss_around(s, v, n, err);
    fw_status st = fw_traffic_nearby(k->tr, v, n, err);
    if (st || k->n_taken == 0)
        return st;
    /* every ship fairway steers asks it each step: the same answer, the
     * same ships taken, the same list (before, each made it again: 1.07 M
     * look-ups among the taken ships in the 1 nm fog run) */
    long answer = fw_traffic_nearby_answer(k->tr);
    if (k->listed_near && k->listed_answer == answer && k->listed_taken == k->taken_change) {
        *v = k->listed;
        *n = k->listed_n;
        return FW_OK;
    }
    if ((st = see_to_taken(k, false, v, n, err)))
        return st;
    k->listed_near = true;
    k->listed_answer = answer, k->listed_taken = k->taken_change, k->listed_n = *n;
    return FW_OK;
}

static fw_status ss_set_speed(fw_source *s, const char *id, double speed, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    if (fw_target_find(k->taken, k->n_taken, id) >= 0) /* fairway steers it */
        return FW_OK;
    return fw_traffic_set_speed(k->tr, id, speed, err);
}

/* A ship as fairway sees it now: from the range query's lists (SUMO's angle
 * replaced by its motion in a lane change, traffic.h), else SUMO's getters. */
static fw_status state_of(sumo_source *k, const char *id, fw_target *out, fw_error *err)
{
    const fw_target *v;
    int n, j;
    fw_status st = ss_around(&k->base, &v, &n, err);
    if (!st && (j = fw_target_find(v, n, id)) >= 0) {
        *out = v[j];
        return FW_OK;
    }
    if (!st && k->near_radius > 0.0 && !(st = fw_traffic_nearby(k->tr, &v, &n, err)) &&
        (j = fw_target_find(v, n, id)) >= 0) {
        *out = v[j];
        return FW_OK;
    }
    if (st || (st = fw_traffic_get(k->tr, id, out, err)))
        return fw_fail(err, FW_EINPUT, "sumo source: no ship '%s' to take", id);
    return FW_OK;
}

/* Kept sorted by id.  A ship given back in this step is taken as it was
 * given back: SUMO has not stepped it, and its lists hold the hull SUMO's
 * bumper gives, which for a ship crabbing in a stream is half its length
 * times the drift angle's sine off where fairway steered it (ferry_n_fill8
 * of dover-imperfect seed 1 in fog: 9.3 m at 5.6 deg, a jump the monitors
 * saw as 7.6 m/s sideways). */
static fw_status ss_take(fw_source *s, const char *id, fw_target *state, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    if (fw_target_find(k->taken, k->n_taken, id) >= 0)
        return fw_fail(err, FW_EINPUT, "sumo source: '%s' is taken already", id);
    fw_status st = state_of(k, id, state, err);
    for (int g = 0; !st && g < k->n_given; g++)
        if (strcmp(k->given[g].id, id) == 0)
            *state = k->given[g];
    if (!st && !fw_reserve((void **)&k->taken, sizeof *k->taken, &k->taken_cap, k->n_taken + 1))
        st = fw_fail(err, FW_ERUN, "out of memory");
    if (!st)
        st = fw_traffic_take(k->tr, id, err);
    if (st)
        return st;
    int i = k->n_taken;
    while (i > 0 && strcmp(k->taken[i - 1].id, id) > 0) {
        k->taken[i] = k->taken[i - 1];
        i--;
    }
    k->taken[i] = *state;
    k->n_taken++;
    k->taken_change++;
    return FW_OK;
}

static fw_status ss_steer(fw_source *s, const fw_target *ship, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    int j = fw_target_find(k->taken, k->n_taken, ship->id);
    if (j < 0)
        return fw_fail(err, FW_ERUN, "sumo source: '%s' is not a taken ship", ship->id);
    fw_target *t = &k->taken[j];
    t->east = ship->east, t->north = ship->north, t->course = ship->course;
    t->speed = ship->speed, t->heading = ship->heading, t->stw = ship->stw;
    /* SUMO draws the hull: its angle is the heading, not the course over ground */
    return fw_traffic_move(k->tr, t->id, t->east, t->north, t->heading, t->length, err);
}

/* Onto its route where it will be after the next step at its speed, so
 * that SUMO's step puts it there (as steer would have). */
static fw_status ss_give_back(fw_source *s, const fw_target *ship, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    int j = fw_target_find(k->taken, k->n_taken, ship->id);
    if (j < 0)
        return fw_fail(err, FW_EINPUT, "sumo source: '%s' is not a taken ship", ship->id);
    if (!fw_reserve((void **)&k->given, sizeof *k->given, &k->given_cap, k->n_given + 1))
        return fw_fail(err, FW_ERUN, "out of memory");
    double ve, vn;
    fw_velocity(ship->speed, ship->course, &ve, &vn);
    fw_status st = fw_traffic_give_back(k->tr, ship->id, ship->east + ve * k->step,
                                        ship->north + vn * k->step, ship->course, ship->speed,
                                        k->taken[j].length, FW_SOURCE_REJOIN_MAX, err);
    if (st)
        return st;
    k->given[k->n_given++] = k->taken[j];
    memmove(&k->taken[j], &k->taken[j + 1], sizeof *k->taken * (size_t)(k->n_taken - j - 1));
    k->n_taken--;
    k->taken_change++;
    return FW_OK;
}

static fw_status ss_lane(fw_source *s, const char *id, fw_lane_info *out, fw_error *err)
{
    sumo_source *k = (sumo_source *)s;
    if (fw_target_find(k->taken, k->n_taken, id) >= 0)
        return fw_fail(err, FW_EINPUT, "sumo source: '%s' is taken: no lane", id);
    double xy[2 * FW_LANE_POINTS];
    *out = (fw_lane_info){0};
    fw_status st = fw_traffic_lane(k->tr, id, xy, FW_LANE_POINTS, &out->np, &out->room_starboard,
                                   &out->room_port, &out->traffic_lane, &out->changing, err);
    if (!st && out->np < 2)
        st = fw_fail(err, FW_EINPUT, "sumo source: '%s' has no lane ahead", id);
    for (int i = 0; !st && i < out->np; i++)
        out->e[i] = xy[2 * i], out->n[i] = xy[2 * i + 1];
    return st;
}

static void ss_destroy(fw_source *s)
{
    sumo_source *k = (sumo_source *)s;
    fw_traffic_close(k->tr);
    fw_free_each(6, k->sorted, k->labels, k->taken, k->listed, k->given, k);
}

static const fw_source_ops sumo_ops = {.name = "sumo", .place = ss_place, .advance = ss_advance,
                                       .around = ss_around, .area = ss_area,
                                       .nearby = ss_nearby,
                                       .set_speed = ss_set_speed, .take = ss_take, .lane = ss_lane,
                                       .steer = ss_steer, .give_back = ss_give_back,
                                       .time = ss_time,
                                       .step_length = ss_step_length, .destroy = ss_destroy};

int fw_sumo_source_cleared(const fw_source *s)
{
    return s && s->ops == &sumo_ops ? ((const sumo_source *)s)->cleared : 0;
}

int fw_sumo_source_unplaced(const fw_source *s)
{
    return s && s->ops == &sumo_ops ? ((const sumo_source *)s)->unplaced : 0;
}

double fw_sumo_source_step_wall(const fw_source *s)
{
    return s && s->ops == &sumo_ops ? ((const sumo_source *)s)->wall : 0.0;
}

/* Is the fill's ship i on a collision course with another ship j < i that
 * stays (its hulls' centres within clear_cpa in the next clear_tcpa s, at
 * constant velocity)?  Put there at the start it has no time to give way:
 * the later of the two in SUMO's order is taken out.  Only crossing courses
 * count: ships following one another in a lane (courses within 30 deg) keep
 * their distance by SUMO's car following, and ships meeting on reciprocal
 * lanes (courses within 40 deg of opposite: a 30 deg bend's legs included)
 * pass at the lanes' spacing, which the network sets and no other placement
 * would change; those only when their hulls would touch (centres within the
 * half beams' sum).  Whatever their courses, two hulls placed within their
 * half beams' sum of each other (overlapping among them: a crossing ship put
 * on a lane ship, already past its closest approach) are one too many. */
static bool fill_conflict(const fw_sumo_source_def *d, const fw_target *v, const bool *out, int i)
{
    double ie, in;
    fw_velocity(v[i].speed, v[i].course, &ie, &in);
    for (int j = 0; j < i; j++) {
        if (out[j] || v[j].own)
            continue;
        const fw_target *a = &v[i], *b = &v[j];
        if (fw_hull_distance(a->east, a->north, a->heading, a->length, a->breadth, b->east,
                             b->north, b->heading, b->length, b->breadth) <
            0.5 * (a->breadth + b->breadth))
            return true;
        double c = cos(v[i].course - v[j].course);
        if (c > cos(fw_deg_to_rad(30.0)))
            continue;
        double je, jn, tc, dc;
        fw_velocity(v[j].speed, v[j].course, &je, &jn);
        fw_cpa(v[j].east - v[i].east, v[j].north - v[i].north, je - ie, jn - in, &tc, &dc);
        double limit = c < -cos(fw_deg_to_rad(40.0)) ? 0.5 * (v[i].breadth + v[j].breadth)
                                                     : d->clear_cpa;
        if (tc > 0.0 && tc < d->clear_tcpa && dc < limit)
            return true;
    }
    return false;
}

/* Is id one of the fill's ships (demand.c names them STREAM_fillN; a
 * stream's arrivals are FLOW.N)? */
static bool fill_id(const char *id)
{
    const char *f = strstr(id, "_fill"), *next;
    while (f && (next = strstr(f + 1, "_fill")))
        f = next;
    if (!f || !f[5])
        return false;
    for (const char *c = f + 5; *c; c++)
        if (*c < '0' || *c > '9')
            return false;
    return true;
}

/* The fill's ships SUMO could not put on their lanes at the start (no free
 * place on the edge drawn for them: a fill larger than the lanes hold) are
 * taken out of its queue, not left to depart later: SUMO would insert one
 * where a lane ship fairway has taken off the lane has just been, onto its
 * hull, where no check of the start sees it (measured: a fill of 405 on
 * networks/dover, 35 waiting, one inserted 15 m behind a ferry, the hulls
 * overlapping, at t = 2 s).  A stream's arrivals wait at its entry, as ships
 * do.  *n_out counts them. */
static fw_status drop_unplaced(sumo_source *k, int *n_out, fw_error *err)
{
    char *ids = NULL;
    *n_out = 0;
    fw_status st = fw_traffic_pending(k->tr, &ids, err);
    for (char *id = ids, *nl; !st && id && (nl = strchr(id, '\n')); id = nl + 1) {
        *nl = '\0';
        if (fill_id(id) && !(st = fw_traffic_remove(k->tr, id, err)))
            ++*n_out;
    }
    free(ids);
    return st;
}

/* After SUMO's first step, the fill's ships that would be a scenario's
 * artefact rather than traffic are taken out: near the own ship or on a
 * collision course with it, or on one with another ship anywhere on the
 * network (see source_sumo.h; every ship read once through the getters);
 * *n_out counts them. */
static fw_status clear_start(sumo_source *k, const fw_sumo_source_def *d, int *n_out,
                             fw_error *err)
{
    const fw_target *v;
    int n;
    *n_out = 0;
    fw_status st = fw_traffic_all(k->tr, &v, &n, err);
    if (st)
        return st;
    /* ids first: removing changes the list */
    char (*ids)[FW_TARGET_ID_MAX] = malloc(sizeof *ids * (size_t)(n + 1));
    bool *out = calloc((size_t)n + 1, sizeof *out);
    if (!ids || !out) {
        free(ids);
        free(out);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    int m = 0;
    double oe, on;
    fw_velocity(d->own.speed, d->own.course, &oe, &on);
    for (int i = 0; i < n; i++) {
        if (v[i].own || fw_target_find(d->targets, d->n_targets, v[i].id) >= 0)
            continue;
        double ve, vn, tc, dc, de = v[i].east - d->own.east, dn = v[i].north - d->own.north;
        fw_velocity(v[i].speed, v[i].course, &ve, &vn);
        fw_cpa(de, dn, ve - oe, vn - on, &tc, &dc);
        bool close = hypot(de, dn) < d->clear_range;
        bool coming = tc > 0.0 && tc < d->clear_tcpa && dc < d->clear_cpa;
        if (close || coming || fill_conflict(d, v, out, i)) {
            out[i] = true;
            memcpy(ids[m++], v[i].id, FW_TARGET_ID_MAX);
        }
    }
    for (int i = 0; i < m && !st; i++)
        st = fw_traffic_remove(k->tr, ids[i], err);
    free(ids);
    free(out);
    *n_out = m;
    return st;
}

fw_status fw_sumo_source_create(const fw_sumo_source_def *d, fw_source **out, fw_error *err)
{
    *out = NULL;
    sumo_files f;
    memset(&f, 0, sizeof f);
    char slog[1200], fcd[1200];
    fw_status st;
    if ((st = fw_sumo_prepare(d, &f, err)) ||
        (st = fw_path(slog, sizeof slog, err, "%s/sumo.log", d->dir)) ||
        (st = fw_path(fcd, sizeof fcd, err, "%s/fcd.xml", d->dir)))
        return st;
    sumo_source *k = calloc(1, sizeof *k);
    if (!k)
        return fw_fail(err, FW_ERUN, "out of memory");
    k->base.ops = &sumo_ops;
    k->step = d->step;
    if (d->n_targets > 0 && !(k->labels = malloc(sizeof *k->labels * (size_t)d->n_targets))) {
        ss_destroy(&k->base);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    for (int i = 0; i < d->n_targets; i++)
        k->labels[i] = d->targets[i];
    k->n_labels = d->n_targets;
    fw_traffic_def td = fw_default_traffic_def();
    td.mode = d->mode;
    td.net_file = f.net;
    td.route_file = f.routes;
    td.add_file = f.has_types ? f.types : NULL;
    td.log_file = slog;
    td.fcd_file = d->fcd ? fcd : NULL;
    td.fcd_period = d->fcd_period;
    /* SUMO's clock is a step ahead of fairway's: its first step is t = 0 */
    td.end = d->duration + d->step;
    td.step = d->step;
    td.seed = d->seed;
    td.own_id = d->own.id;
    td.own_length = d->own.length;
    td.own_width = d->own.breadth;
    td.own_edge = d->n_targets > 0 || !(d->network && d->network[0]) ? "fw_own" : NULL;
    td.radius = d->radius;
    td.area_radius = d->area_radius;
    td.near_radius = d->near_radius;
    if (f.lane_change_s > 0.0)
        td.lane_change_s = f.lane_change_s;
    k->near_radius = d->near_radius;
    /* SUMO inserts the targets during its first step: after it, their
     * positions are those of fairway's t = 0 */
    int cleared = 0, unplaced = 0;
    if ((st = fw_traffic_open(&td, &k->tr, err)) || (st = ss_place(&k->base, &d->own, err)) ||
        (st = fw_traffic_step(k->tr, err)) || (st = clear_start(k, d, &cleared, err)) ||
        (st = drop_unplaced(k, &unplaced, err))) {
        ss_destroy(&k->base);
        return st;
    }
    k->cleared = cleared;
    k->unplaced = unplaced;
    *out = &k->base;
    return FW_OK;
}
