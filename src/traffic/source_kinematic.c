/* source_kinematic.c - scripted ships on legs of constant course and speed (source.h).
 *
 * Positions are computed from each leg's start, never accumulated step by
 * step, so the first leg's position at time t is start + v t exactly: the same
 * numbers as a constant-velocity prediction made at t = 0.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "geom/geom.h"
#include "traffic/source.h"

typedef struct kin_leg {
    double t_start, course, speed;
    double east, north; /* m, where the leg begins */
} kin_leg;

typedef struct kin_ship {
    fw_target now;
    int n;              /* legs, the first at t = 0 */
    kin_leg leg[FW_KIN_MAX_LEGS + 1];
    /* told to hold a speed (set_speed): from (hold_e, hold_n) at hold_t on
     * its course then; given back, it follows its script shifted by
     * (off_e, off_n) so that it goes on from where it is */
    bool holding;
    double hold_t, hold_e, hold_n, hold_course, hold_speed;
    double off_e, off_n;
    /* taken by fairway (source.h take): placed by steer, not by its script */
    bool taken;
} kin_ship;

typedef struct kin_source {
    fw_source base;
    fw_kinematic_def def;
    char own_id[FW_TARGET_ID_MAX];
    kin_ship *ships;    /* sorted by id */
    int n;
    long steps;
    fw_target own;
    bool placed;
    fw_target *out;     /* the last query's list */
} kin_source;

fw_kinematic_def fw_default_kinematic_def(void)
{
    return (fw_kinematic_def){.step = 1.0, .radius = INFINITY, .area_radius = 0.0,
                              .own_id = "own", .room = INFINITY};
}

static double kin_time(const fw_source *s)
{
    const kin_source *k = (const kin_source *)s;
    return (double)k->steps * k->def.step;
}

static double kin_step_length(const fw_source *s) { return ((const kin_source *)s)->def.step; }

/* Where a ship's script puts it at time t. */
static void scripted(const kin_ship *s, double t, fw_target *at)
{
    int j = s->n - 1;
    while (j > 0 && s->leg[j].t_start > t)
        j--;
    const kin_leg *l = &s->leg[j];
    double ve, vn, dt = t - l->t_start;
    fw_velocity(l->speed, l->course, &ve, &vn);
    at->east = l->east + ve * dt + s->off_e;
    at->north = l->north + vn * dt + s->off_n;
    at->course = at->heading = l->course; /* a script knows no drift, no current */
    at->speed = at->stw = l->speed;
}

/* Every ship where it is at time t. */
static void move_all(kin_source *k, double t)
{
    for (int i = 0; i < k->n; i++) {
        kin_ship *s = &k->ships[i];
        if (s->taken)
            continue;
        if (!s->holding) {
            scripted(s, t, &s->now);
            continue;
        }
        double ve, vn, dt = t - s->hold_t;
        fw_velocity(s->hold_speed, s->hold_course, &ve, &vn);
        s->now.east = s->hold_e + ve * dt;
        s->now.north = s->hold_n + vn * dt;
        s->now.course = s->now.heading = s->hold_course;
        s->now.speed = s->now.stw = s->hold_speed;
    }
}

/* A ship's speed held from now (a script: the change is immediate), or its
 * script taken up again from where it is. */
static kin_ship *find(kin_source *k, const char *id)
{
    for (int i = 0; i < k->n; i++)
        if (strcmp(k->ships[i].now.id, id) == 0)
            return &k->ships[i];
    return NULL;
}

static fw_status kin_set_speed(fw_source *src, const char *id, double speed, fw_error *err)
{
    kin_source *k = (kin_source *)src;
    kin_ship *s = find(k, id);
    if (!s)
        return fw_fail(err, FW_ERUN, "kinematic source: no ship '%s'", id);
    if (s->taken) /* fairway steers it: nothing to hold */
        return FW_OK;
    double t = (double)k->steps * k->def.step;
    if (speed >= 0.0 && isfinite(speed)) {
        s->holding = true;
        s->hold_t = t, s->hold_e = s->now.east, s->hold_n = s->now.north;
        s->hold_course = s->now.course, s->hold_speed = speed;
    } else if (s->holding) {
        fw_target at;
        s->holding = false;
        s->off_e = s->off_n = 0.0;
        scripted(s, t, &at);
        s->off_e = s->now.east - at.east, s->off_n = s->now.north - at.north;
    }
    return FW_OK;
}

static fw_status kin_place(fw_source *s, const fw_target *own, fw_error *err)
{
    kin_source *k = (kin_source *)s;
    if (!isfinite(own->east) || !isfinite(own->north) || !isfinite(own->course))
        return fw_fail(err, FW_ERUN, "own ship state is not finite (%g, %g, %g)", own->east,
                       own->north, own->course);
    k->own = *own;
    snprintf(k->own.id, sizeof k->own.id, "%s", k->own_id);
    k->own.own = true;
    k->own.pred = NULL;
    k->placed = true;
    return FW_OK;
}

static fw_status kin_advance(fw_source *s, fw_error *err)
{
    (void)err;
    kin_source *k = (kin_source *)s;
    k->steps++;
    move_all(k, kin_time(s));
    return FW_OK;
}

/* Ships within r of the placed own ship (and the own ship itself if asked),
 * in id order: the ships are kept sorted, and the own ship is merged in. */
static fw_status list(kin_source *k, double r, bool with_own, const fw_target **v, int *n,
                      fw_error *err)
{
    *v = k->out;
    *n = 0;
    if (!k->placed)
        return fw_fail(err, FW_ERUN, "kinematic source: no query before the own ship is placed");
    int m = 0;
    bool own_done = !with_own;
    for (int i = 0; i < k->n; i++) {
        const fw_target *t = &k->ships[i].now;
        if (!own_done && strcmp(k->own.id, t->id) < 0) {
            k->out[m++] = k->own;
            own_done = true;
        }
        if (k->ships[i].taken && !with_own) /* a vessel now: only the area lists it */
            continue;
        if (isinf(r) || hypot(t->east - k->own.east, t->north - k->own.north) <= r)
            k->out[m++] = *t;
    }
    if (!own_done)
        k->out[m++] = k->own;
    *n = m;
    return FW_OK;
}

static fw_status kin_around(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    kin_source *k = (kin_source *)s;
    return list(k, k->def.radius, false, v, n, err);
}

static fw_status kin_area(fw_source *s, const fw_target **v, int *n, fw_error *err)
{
    kin_source *k = (kin_source *)s;
    if (!(k->def.area_radius > 0.0))
        return fw_fail(err, FW_ERUN, "kinematic source: no area query (area_radius 0)");
    return list(k, k->def.area_radius, true, v, n, err);
}

/* The untaken ships within r of (e, n), in id order; no own ship needed. */
static fw_status kin_within(fw_source *s, double e, double n, double r, const fw_target **v,
                            int *m, fw_error *err)
{
    (void)err;
    kin_source *k = (kin_source *)s;
    int c = 0;
    for (int i = 0; i < k->n; i++) {
        const fw_target *t = &k->ships[i].now;
        if (!k->ships[i].taken && hypot(t->east - e, t->north - n) <= r)
            k->out[c++] = *t;
    }
    *v = k->out;
    *m = c;
    return FW_OK;
}

static fw_status kin_take(fw_source *s, const char *id, fw_target *state, fw_error *err)
{
    kin_ship *p = find((kin_source *)s, id);
    if (!p || p->taken)
        return fw_fail(err, FW_EINPUT, "kinematic source: no ship '%s'%s", id,
                       p ? " to take (taken already)" : "");
    p->taken = true;
    *state = p->now;
    return FW_OK;
}

static fw_status kin_steer(fw_source *s, const fw_target *ship, fw_error *err)
{
    kin_ship *p = find((kin_source *)s, ship->id);
    if (!p || !p->taken)
        return fw_fail(err, FW_ERUN, "kinematic source: '%s' is not a taken ship", ship->id);
    p->now.east = ship->east, p->now.north = ship->north;
    p->now.course = ship->course, p->now.speed = ship->speed;
    p->now.heading = ship->heading, p->now.stw = ship->stw;
    return FW_OK;
}

/* Its script again, its leg of now moved along itself so that the ship is
 * where the foot of the perpendicular from where it is falls (refused if
 * that is farther than FW_SOURCE_REJOIN_MAX); course and speed the leg's. */
static fw_status kin_give_back(fw_source *s, const fw_target *ship, fw_error *err)
{
    kin_source *k = (kin_source *)s;
    kin_ship *p = find(k, ship->id);
    if (!p || !p->taken)
        return fw_fail(err, FW_EINPUT, "kinematic source: '%s' is not a taken ship", ship->id);
    double t = kin_time(s), ue, un;
    fw_target at;
    p->holding = false;
    scripted(p, t, &at);
    fw_velocity(1.0, at.course, &ue, &un);
    double de = ship->east - at.east, dn = ship->north - at.north;
    double along = de * ue + dn * un, across = de * un - dn * ue;
    if (fabs(across) > FW_SOURCE_REJOIN_MAX)
        return fw_fail(err, FW_EINPUT,
                       "kinematic source: '%s' is %.1f m off its route (at most %.1f m): steer "
                       "it back first",
                       ship->id, fabs(across), FW_SOURCE_REJOIN_MAX);
    p->off_e += along * ue, p->off_n += along * un;
    p->taken = false;
    scripted(p, t, &p->now);
    return FW_OK;
}

/* Its lane: the line of its leg now (as its script, shifted where it was
 * given back, has it), 10 km back to 50 km ahead, and the def's room. */
static fw_status kin_lane(fw_source *s, const char *id, fw_lane_info *out, fw_error *err)
{
    kin_source *k = (kin_source *)s;
    kin_ship *p = find(k, id);
    if (!p || p->taken)
        return fw_fail(err, FW_EINPUT, "kinematic source: no lane for '%s'%s", id,
                       p ? " (taken)" : "");
    fw_target at;
    double ue, un;
    scripted(p, kin_time(s), &at);
    fw_velocity(1.0, at.course, &ue, &un);
    /* its leg is its traffic lane: the def's room bounds it (source.h) */
    *out = (fw_lane_info){.np = 2, .room_starboard = k->def.room, .room_port = k->def.room,
                          .traffic_lane = true};
    out->e[0] = at.east - 1e4 * ue, out->n[0] = at.north - 1e4 * un;
    out->e[1] = at.east + 5e4 * ue, out->n[1] = at.north + 5e4 * un;
    return FW_OK;
}

static void kin_destroy(fw_source *s)
{
    kin_source *k = (kin_source *)s;
    fw_free_each(3, k->ships, k->out, k);
}

static const fw_source_ops kin_ops = {.name = "kinematic", .place = kin_place,
                                      .advance = kin_advance, .around = kin_around,
                                      .area = kin_area, .set_speed = kin_set_speed,
                                      .within = kin_within, .take = kin_take,
                                      .steer = kin_steer, .give_back = kin_give_back, .lane = kin_lane,
                                      .time = kin_time,
                                      .step_length = kin_step_length, .destroy = kin_destroy};

static int cmp_ship(const void *a, const void *b)
{
    return strcmp(((const kin_ship *)a)->now.id, ((const kin_ship *)b)->now.id);
}

static fw_status check_ship(const fw_kin_ship *s, int i, fw_error *err)
{
    const fw_target *t = &s->start;
    size_t len = strnlen(t->id, sizeof t->id);
    if (len == 0 || len == sizeof t->id)
        return fw_fail(err, FW_EINPUT, "kinematic ship %d: id must have 1..%d characters", i,
                       FW_TARGET_ID_MAX - 1);
    if (!isfinite(t->east) || !isfinite(t->north) || !isfinite(t->course) ||
        !(t->speed >= 0.0 && isfinite(t->speed)) || !(t->length >= 0.0) || !(t->breadth >= 0.0))
        return fw_fail(err, FW_EINPUT, "kinematic ship '%s': not a ship state", t->id);
    if (s->n_legs < 0 || s->n_legs > FW_KIN_MAX_LEGS)
        return fw_fail(err, FW_EINPUT, "kinematic ship '%s': %d legs (0..%d)", t->id, s->n_legs,
                       FW_KIN_MAX_LEGS);
    for (int j = 0; j < s->n_legs; j++) {
        double prev = j ? s->legs[j - 1].t_start : 0.0;
        if (!(s->legs[j].t_start > prev) || !isfinite(s->legs[j].course) ||
            !(s->legs[j].speed >= 0.0 && isfinite(s->legs[j].speed)))
            return fw_fail(err, FW_EINPUT, "kinematic ship '%s': leg %d out of order or not finite",
                           t->id, j + 1);
    }
    return FW_OK;
}

static void init_legs(kin_ship *k, const fw_kin_ship *s)
{
    k->now = s->start;
    k->now.own = false;
    k->now.pred = NULL;
    k->n = 1 + s->n_legs;
    k->leg[0] = (kin_leg){.t_start = 0.0, .course = s->start.course, .speed = s->start.speed,
                          .east = s->start.east, .north = s->start.north};
    for (int j = 1; j < k->n; j++) {
        const kin_leg *p = &k->leg[j - 1];
        double ve, vn, dt = s->legs[j - 1].t_start - p->t_start;
        fw_velocity(p->speed, p->course, &ve, &vn);
        k->leg[j] = (kin_leg){.t_start = s->legs[j - 1].t_start, .course = s->legs[j - 1].course,
                              .speed = s->legs[j - 1].speed, .east = p->east + ve * dt,
                              .north = p->north + vn * dt};
    }
}

fw_status fw_kinematic_source_create(const fw_kinematic_def *def, fw_source **out,
                                     fw_error *err)
{
    *out = NULL;
    if (!(def->step > 0.0 && isfinite(def->step)))
        return fw_fail(err, FW_EINPUT, "kinematic source: step %g s must be positive", def->step);
    if (!(def->radius > 0.0) || !(def->area_radius >= 0.0) || def->n < 0 || !(def->room >= 0.0))
        return fw_fail(err, FW_EINPUT,
                       "kinematic source: radius must be positive, area and room >= 0");
    const char *own_id = def->own_id ? def->own_id : "own";
    if (!own_id[0] || strlen(own_id) >= FW_TARGET_ID_MAX)
        return fw_fail(err, FW_EINPUT, "kinematic source: own id must have 1..%d characters",
                       FW_TARGET_ID_MAX - 1);
    fw_status st;
    for (int i = 0; i < def->n; i++)
        if ((st = check_ship(&def->ships[i], i, err)))
            return st;
    kin_source *k = calloc(1, sizeof *k);
    if (!k)
        return fw_fail(err, FW_ERUN, "out of memory");
    k->base.ops = &kin_ops;
    k->def = *def;
    k->def.ships = NULL;
    snprintf(k->own_id, sizeof k->own_id, "%s", own_id);
    k->def.own_id = k->own_id;
    k->n = def->n;
    k->ships = calloc((size_t)def->n + 1, sizeof *k->ships);
    k->out = calloc((size_t)def->n + 1, sizeof *k->out);
    if (!k->ships || !k->out) {
        kin_destroy(&k->base);
        return fw_fail(err, FW_ERUN, "out of memory for %d ships", def->n);
    }
    for (int i = 0; i < def->n; i++)
        init_legs(&k->ships[i], &def->ships[i]);
    qsort(k->ships, (size_t)k->n, sizeof *k->ships, cmp_ship);
    for (int i = 1; i < k->n; i++)
        if (strcmp(k->ships[i - 1].now.id, k->ships[i].now.id) == 0) {
            fw_fail(err, FW_EINPUT, "kinematic source: ship '%s' listed twice",
                    k->ships[i].now.id);
            kin_destroy(&k->base);
            return FW_EINPUT;
        }
    for (int i = 0; i < k->n; i++)
        if (strcmp(k->ships[i].now.id, own_id) == 0) {
            fw_fail(err, FW_EINPUT, "kinematic source: a ship has the own ship's id '%s'", own_id);
            kin_destroy(&k->base);
            return FW_EINPUT;
        }
    move_all(k, 0.0);
    *out = &k->base;
    return FW_OK;
}

void fw_source_destroy(fw_source *s)
{
    if (s)
        s->ops->destroy(s);
}
