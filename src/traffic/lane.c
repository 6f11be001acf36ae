/* lane.c - a ship's lane line and where ships are on it (lane.h). */
#include "traffic/lane.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "core/units.h"
#include "traffic/source.h"

void fw_lane_foot(const fw_lane_info *lane, double e, double n, double *course, double *xtrack,
                  int *seg, double *along)
{
    double best = INFINITY, s0 = 0.0;
    *course = 0.0, *xtrack = 0.0, *seg = 0, *along = 0.0;
    for (int i = 0; i + 1 < lane->np; i++) {
        double ax = lane->e[i], ay = lane->n[i];
        double dx = lane->e[i + 1] - ax, dy = lane->n[i + 1] - ay, l2 = dx * dx + dy * dy;
        if (!(l2 > 0.0))
            continue;
        double l = sqrt(l2);
        double s = ((e - ax) * dx + (n - ay) * dy) / l2;
        /* the last segment goes on beyond its end, the first before its start */
        double sc = s < 0.0 && i > 0 ? 0.0 : s > 1.0 && i + 2 < lane->np ? 1.0 : s;
        double px = ax + sc * dx - e, py = ay + sc * dy - n, d2 = px * px + py * py;
        if (d2 < best) {
            best = d2;
            *course = atan2(dx, dy);
            /* to starboard of the line: the cross product's sign */
            *xtrack = ((e - ax) * dy - (n - ay) * dx) / l;
            *seg = i;
            *along = s0 + sc * l;
        }
        s0 += l;
    }
}

void fw_lane_where(const fw_lane_info *lane, double e, double n, double *course, double *xtrack,
                   int *seg)
{
    double along;
    fw_lane_foot(lane, e, n, course, xtrack, seg, &along);
}

/* a's and b's feet on a's lane line (how far along, and b's cross-track
 * distance and the line's course there); false for a line of no finite
 * width (open water) */
static bool feet(const fw_lane_info *la, double width, const fw_target *a, const fw_target *b,
                 double *sa, double *sb, double *xb, double *cb)
{
    if (!isfinite(width) || la->np < 2)
        return false;
    double ca, xa;
    int k;
    fw_lane_foot(la, a->east, a->north, &ca, &xa, &k, sa);
    fw_lane_foot(la, b->east, b->north, cb, xb, &k, sb);
    return true;
}

/* Is b coming the other way down a's lane ahead (lane.h)? */
static bool oncoming(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                     const fw_lane_info *lb)
{
    double width = la->room_port + la->room_starboard + lb->room_port + lb->room_starboard;
    double sa, sb, xb, cb;
    /* ahead, or abeam within the waterway's width: a line begins at its
     * edge's start, and a ship just round a bend lies on its straight
     * continuation backwards, not on the lane it came by */
    if (!feet(la, width, a, b, &sa, &sb, &xb, &cb) ||
        !(sb > sa - width && -xb > 0.0 && -xb <= width))
        return false;
    return fabs(fw_wrap_pi(b->heading - cb - FW_PI)) <= fw_deg_to_rad(FW_LANE_MEET_TOL_DEG);
}

bool fw_lanes_meet(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                   const fw_lane_info *lb)
{
    return oncoming(a, la, b, lb) && oncoming(b, lb, a, la);
}

/* Is b on a's lane's waterway ahead of a, going a's way (lane.h)? */
static bool ahead_along(const fw_target *a, const fw_lane_info *la, const fw_target *b)
{
    double width = la->room_port + la->room_starboard;
    double sa, sb, xb, cb;
    return feet(la, width, a, b, &sa, &sb, &xb, &cb) && sb >= sa && fabs(xb) <= width &&
           fabs(fw_wrap_pi(b->heading - cb)) <= fw_deg_to_rad(FW_LANE_MEET_TOL_DEG);
}

bool fw_lanes_along(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                    const fw_lane_info *lb)
{
    /* the line of the one astern reaches the one ahead */
    return ahead_along(a, la, b) || ahead_along(b, lb, a);
}

/* ---- the lane cache (source.h) ---- */
struct fw_lane_entry {
    double t_read; /* s, when last asked; -INFINITY: never */
    double t_ok;   /* s, when the lane kept was said */
    bool ok;
    fw_lane_info lane;
};

fw_status fw_lane_cache_get(fw_lane_cache *c, fw_source *src, const fw_target *s, double t,
                            const fw_lane_info **out, fw_error *err)
{
    *out = NULL;
    if (s->key <= 0 || !src->ops->lane)
        return FW_OK;
    if (s->key > c->cap) {
        int cap = fw_grown_cap(c->cap, s->key);
        if (!fw_resize((void **)&c->v, sizeof *c->v, (size_t)cap))
            return fw_fail(err, FW_ERUN, "out of memory for ships' lanes");
        memset(c->v + c->cap, 0, sizeof *c->v * (size_t)(cap - c->cap));
        c->cap = cap;
    }
    /* each entry apart: a lane handed out stays where it is while the
     * table grows for the next ship's */
    fw_lane_entry *x = c->v[s->key - 1];
    if (!x) {
        if (!(x = malloc(sizeof *x)))
            return fw_fail(err, FW_ERUN, "out of memory for ships' lanes");
        *x = (fw_lane_entry){.t_read = -INFINITY, .t_ok = -INFINITY};
        c->v[s->key - 1] = x;
    }
    if (!(t - x->t_read < FW_LANE_REFRESH_S)) {
        fw_lane_info lane;
        fw_error e2 = {0};
        fw_status st = fw_source_lane(src, s->id, &lane, &e2);
        if (st && st != FW_EINPUT) {
            *err = e2;
            return st;
        }
        x->t_read = t;
        if (!st)
            x->lane = lane, x->ok = true, x->t_ok = t;
    }
    if (x->ok && t - x->t_ok <= FW_LANE_KEEP_S)
        *out = &x->lane;
    return FW_OK;
}

void fw_lane_cache_free(fw_lane_cache *c)
{
    for (int i = 0; i < c->cap; i++)
        free(c->v[i]);
    free(c->v);
    memset(c, 0, sizeof *c);
}
