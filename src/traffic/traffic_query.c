/* traffic_query.c - the ships SUMO has, in fairway's terms (traffic.h): the
 * range query read once per step, a lane-changing ship's heading from its
 * motion, the area and nearby lists, and the getters' reads for checks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "core/units.h"
#include "core/within.h"
#include "traffic/traffic_internal.h"

/* Raw SUMO values to fairway's frame: the one place this happens; sh, ch
 * the sine and cosine of SUMO's angle in radians. */
static void convert_sc(const fw_sumo_raw *r, const char *own_id, double sh, double ch,
                       fw_target *s)
{
    memcpy(s->id, r->id, sizeof s->id);
    memcpy(s->type, r->type, sizeof s->type);
    fw_traffic_from_sumo_sc(r->x, r->y, r->angle_deg, sh, ch, r->length, &s->east, &s->north,
                            &s->course);
    s->speed = r->speed;
    s->heading = s->course, s->stw = s->speed; /* SUMO knows no drift */
    s->length = r->length;
    s->breadth = r->width;
    s->own = strcmp(r->id, own_id) == 0;
    s->pred = NULL;
    s->key = 0;
}

static void convert_one(const fw_sumo_raw *r, const char *own_id, fw_target *s)
{
    double h = fw_deg_to_rad(r->angle_deg);
    convert_sc(r, own_id, sin(h), cos(h), s);
}

static fw_status room(fw_target **v, int *cap, int n, fw_error *err)
{
    if (n <= *cap)
        return FW_OK;
    if (!fw_resize((void **)v, sizeof **v, 2 * (size_t)n))
        return fw_fail(err, FW_ERUN, "out of memory for %d ships", n);
    *cap = 2 * n;
    return FW_OK;
}

/* A ship's hull as this step's range query placed it (on its bow's track:
 * below), or NULL when the query did not see it this step. */
static const fw_target *tracked(const fw_traffic *t, const fw_sumo_raw *r)
{
    if (t->ctx_step != t->steps)
        return NULL;
    int i = fw_idmap_find_keyed(&t->ids, r->key, r->id);
    if (i < 0 || i >= t->last_cap || t->last_step[i] != t->steps)
        return NULL;
    int k = t->last_k[i];
    return k >= 0 && k < t->ctx.n && strcmp(t->conv[k].id, r->id) == 0 ? &t->conv[k] : NULL;
}

static fw_status convert(fw_traffic *t, const fw_target **ships, int *n, fw_error *err)
{
    fw_status st = room(&t->ships, &t->ships_cap, t->raw.n, err);
    if (st)
        return st;
    /* every list gives a ship the same hull: the range query's where it has
     * one, SUMO's own geometry for the ships beyond it */
    for (int i = 0; i < t->raw.n; i++) {
        const fw_target *c = tracked(t, &t->raw.v[i]);
        if (c)
            t->ships[i] = *c;
        else
            convert_one(&t->raw.v[i], t->own_id, &t->ships[i]);
    }
    *ships = t->ships;
    *n = t->raw.n;
    return FW_OK;
}

/* A hull is placed on the track its bow has sailed (hull_track.h), not
 * turned about its bow with SUMO's angle.  Where the track behind the bow is
 * straight along SUMO's angle (kStraight: far below any bend or lane change,
 * far above rounding), the hull is SUMO's own geometry and its values are
 * kept exactly; elsewhere (a bend, a lane change) the hull is the chord's,
 * and its course and speed are those of its centre's motion over the step.
 *
 * SUMO's bumper itself jumps where a ship crosses a junction: an internal
 * lane's length is not its shape's (a bow moving 7 m a step at 4.4 m/s),
 * and the next edge starts elsewhere than the internal lane ends (14 m back
 * at a 30 deg bend of 250 m lanes).  The track's bow is SUMO's bumper plus
 * an offset: a step's motion beyond what the ship's speed along SUMO's angle
 * explains, by more than kSlack, goes into the offset, and the offset decays
 * as the ship sails one hull length (exp(-v dt / L)), so a jump of SUMO's is
 * spread over that distance instead of thrown at the hull.  A lane change
 * (0.3 m/s sideways at the default 900 s) is within kSlack and stays real
 * motion; a jump of more than a hull length, and at least kTeleport (a
 * teleport), starts the track anew, where the monitors see it.  The floor:
 * a 20 m small craft's bumper jumps 23 m entering the bend of networks/bend
 * at 3.6 m/s (measured), more than its length and far less than SUMO's
 * teleports, which move a ship by whole edges.
 *
 * While SUMO's angle turns, the step is also judged along the bumper's own
 * last clean step (at least half its run, within 60 deg of the one before:
 * not a stall nor one of the jumps), whichever explains it better.  SUMO's
 * angle is the direction from the ship's back to its front along the lanes:
 * past a bend it lags the bumper's motion for a hull length (24 deg for a
 * 290 m ship past networks/bend's 30 deg), and judged along it alone real
 * motion went into the offset, 50 m of it across the lane, whose decay then
 * moved the hull 2.01 m/s sideways (bend_traffic seed 1 with lcKeepRight 0).
 * Where the angle stands still (by kTurned: straight lanes; a lane change,
 * whose end SUMO makes in one larger step) it alone is the judge, as before. */
static const double kStraight = 1e-7; /* rad */
static const double kSlack = 1.0;     /* m a step, and 10% of the step's run */
static const double kTeleport = 100.0; /* m */
static const double kTurned = 0.1;     /* deg a step: SUMO's angle turning */

/* The index of the ship of context result r, its arrays grown to hold it. */
static fw_status ship_index(fw_traffic *t, const fw_sumo_raw *r, int *out, fw_error *err)
{
    int i;
    if (fw_idmap_intern_keyed(&t->ids, r->key, r->id, &i))
        return fw_fail(err, FW_ERUN, "out of memory for ship ids");
    if (i >= t->last_cap) {
        int cap = fw_grown_cap(t->last_cap, i + 1);
        if (!fw_resize_each((size_t)cap, 16, (void **)&t->last_e, sizeof *t->last_e,
                            (void **)&t->last_n, sizeof *t->last_n,
                            (void **)&t->last_step, sizeof *t->last_step,
                            (void **)&t->last_angle, sizeof *t->last_angle,
                            (void **)&t->last_sin, sizeof *t->last_sin,
                            (void **)&t->last_cos, sizeof *t->last_cos,
                            (void **)&t->tracks, sizeof *t->tracks,
                            (void **)&t->seed_heading, sizeof *t->seed_heading,
                            (void **)&t->last_bx, sizeof *t->last_bx,
                            (void **)&t->last_by, sizeof *t->last_by,
                            (void **)&t->off_x, sizeof *t->off_x,
                            (void **)&t->off_y, sizeof *t->off_y,
                            (void **)&t->dir_x, sizeof *t->dir_x,
                            (void **)&t->dir_y, sizeof *t->dir_y,
                            (void **)&t->turned, sizeof *t->turned,
                            (void **)&t->last_k, sizeof *t->last_k))
            return fw_fail(err, FW_ERUN, "out of memory for ship ids");
        for (int j = t->last_cap; j < cap; j++) {
            t->last_step[j] = -2;
            t->last_angle[j] = NAN;
            t->tracks[j] = (fw_hull_track){0};
            t->seed_heading[j] = NAN;
        }
        t->last_cap = cap;
    }
    *out = i;
    return FW_OK;
}

/* Context result k converted into conv[k] as ship i, SUMO's angle's sine
 * and cosine computed only when it changed. */
static void convert_ship(fw_traffic *t, int k, int i)
{
    const fw_sumo_raw *r = &t->ctx.v[k];
    /* turning, not SUMO's last digits moving in a lane change (NAN: new) */
    t->turned[i] = fabs(remainder(r->angle_deg - t->last_angle[i], 360.0)) > kTurned;
    if (!(r->angle_deg == t->last_angle[i])) {
        double h = fw_deg_to_rad(r->angle_deg);
        t->last_angle[i] = r->angle_deg;
        t->last_sin[i] = sin(h);
        t->last_cos[i] = cos(h);
    }
    convert_sc(r, t->own_id, t->last_sin[i], t->last_cos[i], &t->conv[k]);
    t->conv[k].key = i + 1; /* the ship's key for the run (geom/target.h) */
}

/* Ship i's hull from its bow's track; the track started anew for a ship
 * not seen at the last step (first seen, back after a gap or given back by
 * fairway: then along the heading it had).  false when out of memory. */
static bool follow_track(fw_traffic *t, int k, int i)
{
    fw_target *c = &t->conv[k];
    const fw_sumo_raw *r = &t->ctx.v[k];
    fw_hull_track *tr = &t->tracks[i];
    bool seen = t->last_step[i] == t->steps - 1;
    if (c->own) {
        t->last_step[i] = t->steps;
        t->last_k[i] = k;
        return true;
    }
    if (seen) {
        /* the step's motion against what the ship's speed explains, along
         * SUMO's angle or, while that turns, along the bumper's own last
         * clean step if that explains it better (below) */
        double run = r->speed * t->def.step;
        double mx = r->x - t->last_bx[i], my = r->y - t->last_by[i], m = hypot(mx, my);
        double ex = mx - run * t->last_sin[i], ey = my - run * t->last_cos[i];
        double e = hypot(ex, ey);
        double fx = mx - run * t->dir_x[i], fy = my - run * t->dir_y[i], f = hypot(fx, fy);
        if (t->turned[i] && f < e)
            ex = fx, ey = fy, e = f;
        if (m > 0.5 * run && mx * t->dir_x[i] + my * t->dir_y[i] > 0.5 * m)
            t->dir_x[i] = mx / m, t->dir_y[i] = my / m;
        if (e > fmax(r->length, kTeleport)) {
            seen = false; /* a teleport: a new track, the jump where it is */
        } else {
            if (e > kSlack + 0.1 * run)
                t->off_x[i] -= ex, t->off_y[i] -= ey;
            double f = exp(-fmax(r->speed, 0.1) * t->def.step / r->length);
            t->off_x[i] *= f, t->off_y[i] *= f;
        }
    }
    t->last_bx[i] = r->x, t->last_by[i] = r->y;
    if (!seen) {
        double h = isnan(t->seed_heading[i]) ? c->course : t->seed_heading[i];
        t->dir_x[i] = sin(h), t->dir_y[i] = cos(h);
        t->seed_heading[i] = NAN;
        t->off_x[i] = t->off_y[i] = 0.0;
        if (!fw_hull_track_start(tr, r->x, r->y, h, r->length))
            return false;
    } else if (!fw_hull_track_push(tr, r->x + t->off_x[i], r->y + t->off_y[i], r->length)) {
        return false;
    }
    double cx, cy, h;
    fw_hull_track_hull(tr, r->length, &cx, &cy, &h);
    double dh = fabs(remainder(h - c->course, 2.0 * M_PI));
    if (dh > kStraight) {
        c->east = cx, c->north = cy;
        c->heading = h;
        if (seen) {
            double dx = cx - t->last_e[i], dy = cy - t->last_n[i];
            c->speed = hypot(dx, dy) / t->def.step;
            c->course = c->speed > 0.0 ? fw_wrap_2pi(atan2(dx, dy)) : h;
        } else {
            c->course = h;
        }
        c->stw = c->speed; /* SUMO knows no current: through the water as over ground */
    }
    t->last_e[i] = c->east, t->last_n[i] = c->north, t->last_step[i] = t->steps;
    t->last_k[i] = k;
    return true;
}

/* The context results of the last step, asked of SUMO once per step. */
fw_status fw_traffic_context(fw_traffic *t, fw_error *err)
{
    if (t->ctx_step == t->steps)
        return FW_OK;
    fw_status st = t->be->context(&t->ctx, err);
    if (!st)
        st = room(&t->conv, &t->conv_cap, t->ctx.n, err);
    /* converted once per step, for both queries */
    for (int k = 0; !st && k < t->ctx.n; k++) {
        int i = -1;
        if ((st = ship_index(t, &t->ctx.v[k], &i, err)))
            break;
        convert_ship(t, k, i);
        if (!follow_track(t, k, i))
            st = fw_fail(err, FW_ERUN, "out of memory for ship tracks");
    }
    if (!st)
        t->ctx_step = t->steps;
    return st;
}

fw_status fw_traffic_around(fw_traffic *t, const fw_target **ships, int *n, fw_error *err)
{
    *n = 0;
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    fw_status st = fw_traffic_context(t, err);
    if (!st)
        st = room(&t->ships, &t->ships_cap, t->ctx.n, err);
    if (st)
        return st;
    /* a range query widened for the area holds more than SUMO's range test
     * would give: apply that test (front bumper within radius) here */
    bool filter = t->query_radius > t->def.radius;
    int m = 0;
    for (int i = 0; i < t->ctx.n; i++) {
        const fw_sumo_raw *r = &t->ctx.v[i];
        if (filter && !fw_within_range(r->x - t->own_x, r->y - t->own_y, t->def.radius))
            continue;
        t->ships[m++] = t->conv[i];
    }
    *ships = t->ships;
    *n = m;
    return FW_OK;
}

static int cmp_id(const void *a, const void *b)
{
    return strcmp(((const fw_target *)a)->id, ((const fw_target *)b)->id);
}

/* v[0..n-1] sorted by id, v[n - 1] the one perhaps out of place.  The range
 * query's ships come sorted by id (a map by id, range_read.h), so the lists
 * cut from them are too and only the own ship the area appends needs its
 * place: found by bisection, in O(n) where qsort took O(n log n) compares.
 * Any other order gets qsort; ids are unique, so every sort gives the same
 * list. */
static void sort_by_id(fw_target *v, int n)
{
    for (int i = 1; i + 1 < n; i++)
        if (strcmp(v[i - 1].id, v[i].id) > 0) {
            qsort(v, (size_t)n, sizeof *v, cmp_id);
            return;
        }
    if (n < 2 || strcmp(v[n - 2].id, v[n - 1].id) < 0)
        return;
    int lo = 0, hi = n - 1; /* the first of v[0..n-2] after v[n - 1] */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (strcmp(v[mid].id, v[n - 1].id) > 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    fw_target last = v[n - 1];
    memmove(&v[lo + 1], &v[lo], sizeof *v * (size_t)(n - 1 - lo));
    v[lo] = last;
}

/* The background ships of this step's context results whose hull centres
 * are within radius of the own ship's, into *buf (room for one more: the
 * area adds the own ship); their count, or -1 with *err set (what: the
 * query's name, for a def without its radius). */
static int within(fw_traffic *t, const char *what, double radius, fw_target **buf, int *cap,
                  fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return -1;
    if (!(radius > 0.0)) {
        fw_fail(err, FW_ERUN, "no %s query: the traffic def has no %s radius", what, what);
        return -1;
    }
    if (!t->placed) {
        fw_fail(err, FW_ERUN, "no %s query before the own ship is placed", what);
        return -1;
    }
    fw_status st = fw_traffic_context(t, err);
    if (!st)
        st = room(buf, cap, t->ctx.n + 1, err);
    if (st)
        return -1;
    int m = 0;
    for (int i = 0; i < t->ctx.n; i++) {
        const fw_target *s = &t->conv[i];
        if (!s->own && fw_within_range(s->east - t->own_x, s->north - t->own_y, radius))
            (*buf)[m++] = *s;
    }
    return m;
}

fw_status fw_traffic_area(fw_traffic *t, const fw_target **ships, int *n, fw_error *err)
{
    *n = 0;
    int m = within(t, "area", t->def.area_radius, &t->area, &t->area_cap, err);
    if (m < 0)
        return err->status;
    /* the own ship as placed: SUMO may not list a vehicle moved off its lanes */
    fw_target *o = &t->area[m++];
    memset(o, 0, sizeof *o);
    /* own_id is as long as an id may be: copied whole, NUL included */
    memcpy(o->id, t->own_id, strlen(t->own_id) + 1);
    memcpy(o->type, FW_TRAFFIC_OWN_TYPE, sizeof FW_TRAFFIC_OWN_TYPE);
    o->east = t->own_x;
    o->north = t->own_y;
    o->course = t->own_heading; /* SUMO has the own ship's heading and speed only */
    o->speed = t->own_speed;
    o->heading = o->course, o->stw = o->speed;
    o->length = t->def.own_length;
    o->breadth = t->def.own_width;
    o->own = true;
    sort_by_id(t->area, m);
    *ships = t->area;
    *n = m;
    return FW_OK;
}

fw_status fw_traffic_nearby(fw_traffic *t, const fw_target **ships, int *n, fw_error *err)
{
    *n = 0;
    /* every ship fairway steers asks it each step: the same context, the
     * same centre, the same answer (within and sort_by_id depend on nothing
     * else) */
    if (t->near_step >= 0 && t->near_step == t->ctx_step && t->ctx_step == t->steps &&
        t->near_x == t->own_x && t->near_y == t->own_y && !fw_traffic_alive(t, err)) {
        *ships = t->near;
        *n = t->near_n;
        return FW_OK;
    }
    int m = within(t, "nearby", t->def.near_radius, &t->near, &t->near_cap, err);
    if (m < 0)
        return err->status;
    sort_by_id(t->near, m);
    t->near_answer++;
    t->near_step = t->ctx_step, t->near_n = m;
    t->near_x = t->own_x, t->near_y = t->own_y;
    *ships = t->near;
    *n = m;
    return FW_OK;
}

long fw_traffic_nearby_answer(const fw_traffic *t) { return t->near_answer; }

fw_status fw_traffic_all(fw_traffic *t, const fw_target **ships, int *n, fw_error *err)
{
    *n = 0;
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    fw_status st = t->be->all(&t->raw, err);
    return st ? st : convert(t, ships, n, err);
}

fw_status fw_traffic_get(fw_traffic *t, const char *id, fw_target *ship, fw_error *err)
{
    if (fw_traffic_alive(t, err))
        return FW_ERUN;
    fw_sumo_raw r;
    fw_status st = t->be->get(id, &r, err);
    if (st)
        return st;
    convert_one(&r, t->own_id, ship);
    return FW_OK;
}
