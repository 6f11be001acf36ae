/* reactions_course.c - a give-way ship that alters course (reactions.h, give_way course). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "core/mem.h"
#include "core/names.h"
#include "core/units.h"
#include "geom/geom.h"
#include "geom/turn.h"
#include "world/reactions_internal.h"
#include "world/steer.h"

/* fw_speed_why order */
static const char *const kWhyNames[] = {
    "", "overtaking (rule 13)", "in a junction", "in a lane change",
    "its lane's edge near", "no alteration clears", "rule 17(b)", "rule 19(e)"};

const char *fw_speed_why_name(fw_speed_why w) { return fw_name_of(kWhyNames, 8, (int)w); }

/* On its lane: within this of its line (m) and of its course (rad). */
static const double kOnLine = 10.0;
static const double kAlong = 0.035; /* 2 deg */

/* Ship self on course c at speed v: the closest approach to ship j and its time. */
static void cpa_on(const fw_reactions *r, int self, const fw_target *all, double c, double v,
                   int j, double *tc, double *d2)
{
    const fw_target *a = &all[self], *b = &all[j];
    double ae, an;
    fw_velocity(v, c, &ae, &an);
    double be = b->speed * r->sn[j], bn = b->speed * r->cs[j];
    fw_cpa_sq(b->east - a->east, b->north - a->north, be - ae, bn - an, tc, d2);
}

/* The closest ship self, on course c at speed v, would pass any ship near it
 * (r->nb) within the horizon and ahead; *t_pass: the latest time it passes
 * one of those it gives way to (list, m), which is how long it holds the new
 * course (until they are past). */
static double pass_on_course(const fw_reactions *r, int self, const fw_target *all, double c,
                             double v, const int *list, int m, double *t_pass)
{
    double best = INFINITY, tc, d2;
    *t_pass = 0.0;
    for (int q = 0; q < r->nnb; q++) {
        cpa_on(r, self, all, c, v, r->nb[q], &tc, &d2);
        if (tc > 0.0 && tc < r->def.horizon)
            best = fmin(best, d2);
    }
    for (int q = 0; q < m; q++) {
        cpa_on(r, self, all, c, v, list[q], &tc, &d2);
        *t_pass = fmax(*t_pass, tc);
    }
    return sqrt(best);
}

static fw_status order(fw_reactions *r, const fw_target *a, const fw_lane_info *lane,
                       double alt, double v0, const char *other, fw_error *err)
{
    if (!fw_reserve((void **)&r->takes, sizeof *r->takes, &r->takes_cap, r->ntakes + 1))
        return fw_fail(err, FW_ERUN, "out of memory for the ships to steer");
    fw_take_order *o = &r->takes[r->ntakes++];
    *o = (fw_take_order){.ship = *a, .lane = *lane, .alteration = alt, .cpa = r->def.cpa,
                            .speed = v0};
    o->ship.own = false;
    snprintf(o->other, sizeof o->other, "%s", other);
    return FW_OK;
}

/* Its lane (source.h) and the sea room to starboard it may use (the
 * lanes', or unlimited: reactions.h room_*); FW_EINPUT when it has none here
 * (a junction, a source without lanes); *changing: it is in the middle of a
 * lane change (its source says so, or it is off its lane's line, or crabbing
 * across it).
 * Such a ship slows instead: SUMO's continuous lane change outlives a take
 * and a give back, and goes on, stale, from where it was (tried: a strait
 * ship taken 9 deg into a lane change was given back on its lane's line and
 * jumped 339 m across at SUMO's next step; h-lc's commit), and the shadow it
 * casts on the lane it crosses into stays there while it is steered, a
 * stopped ship to that lane's ships (traffic.h fw_traffic_lane: one taken
 * 9 m into a lane change, within the 10 m, stopped one 400 s later). */
static fw_status lane_of(const fw_reactions *r, const fw_target *a, fw_source *src,
                         fw_lane_info *lane, bool *changing, fw_error *err)
{
    fw_status st = fw_source_lane(src, a->id, lane, err);
    if (st)
        return st;
    double lc, xt;
    int seg;
    fw_lane_where(lane, a->east, a->north, &lc, &xt, &seg);
    *changing = lane->changing || fabs(xt) > kOnLine || fabs(fw_wrap_pi(a->course - lc)) > kAlong;
    if (!r->def.room_from_lanes && !(r->def.room_traffic_lanes && lane->traffic_lane))
        lane->room_starboard = lane->room_port = INFINITY;
    return FW_OK;
}

int fw_react_alter(fw_reactions *r, double t, int self, const fw_target *all, react_state *st,
                   const int *list, int m, int nearest, fw_situation sit, double dcpa,
                   fw_source *src, fw_speed_why *why, fw_error *err)
{
    *why = FW_WHY_NO_CLEAR;
    const fw_target *a = &all[self];
    double v0 = st->v0, step = fw_deg_to_rad(5.0);
    fw_lane_info lane;
    fw_error e2 = {0};
    bool changing = false;
    fw_status s2 = lane_of(r, a, src, &lane, &changing, &e2);
    if (s2 == FW_EINPUT || (!s2 && changing)) {
        *why = s2 == FW_EINPUT ? FW_WHY_NO_LANE : FW_WHY_LANE_CHANGE;
        return 0;
    }
    if (s2) {
        *err = e2;
        return -1;
    }
    for (double alt = r->def.alter_min; alt <= r->def.alter_max + 1e-9; alt += step) {
        double t_pass, pass = pass_on_course(r, self, all, a->course + alt, v0, list, m, &t_pass);
        if (pass < r->def.cpa)
            continue;
        /* its sideways run until the last of them is past, its half
         * breadth, and a tenth of the room to spare */
        double run = v0 * t_pass * sin(alt) + 0.5 * a->breadth;
        if (!(run <= 0.9 * lane.room_starboard)) {
            *why = FW_WHY_NO_ROOM;
            continue;
        }
        fw_reaction x = {.t = t, .kind = FW_REACT_ALTER, .situation = sit, .speed_from = v0,
                         .speed_to = v0, .dcpa_before = dcpa, .dcpa_after = pass,
                         .enough = true, .course_from = a->course,
                         .course_to = fw_wrap_2pi(a->course + alt)};
        snprintf(x.ship, sizeof x.ship, "%s", a->id);
        snprintf(x.other, sizeof x.other, "%s", all[nearest].id);
        fw_react_sense_note(r, nearest, &x);
        snprintf(st->other, sizeof st->other, "%s", all[nearest].id);
        /* a speed it was held at is released: it is taken (world.h) */
        st->holding = false;
        if (fw_react_record(r, &x, err) || order(r, a, &lane, alt, v0, all[nearest].id, err))
            return -1;
        return 1;
    }
    return 0;
}

/* Is b a background ship fairway steers (world/steer.h: taken from the
 * source, listed among the vessels), not the own ship?  It was one of the
 * source's ships, so its state has been seen. */
static bool steered(const fw_reactions *r, const fw_target *b)
{
    if (!b->own)
        return false;
    int k = fw_idmap_find(&r->ids, b->id);
    return k >= 0 && k < r->cap && r->s[k].seen;
}

/* Ship a (at speed va, one of r->all) overtaking b, a ship fairway steers
 * off its lane (steer.h: it alters to starboard, and waits along its lane
 * while a ship would pass within half the passing distance of its way
 * back): does b leave a's way?  It does when, on the course it is turning
 * to (its record's turn, geom/turn.h: an officer sees it swing) at its
 * speed, it passes a at half the passing distance or more and is not
 * closing a's track sideways (the side it is on, square to a's course,
 * growing or held).  Then a keeps its lane and speed, as an overtaking ship
 * does that sees the one ahead moving off; before, every such ship slowed
 * for it (20 of the 35 speed orders of the Dover base scenario, seeds 1-3,
 * on c08d456), often for minutes, while the one ahead waited beside its
 * lane for it to pass. */
bool fw_react_leaves_way(const fw_reactions *r, const fw_target *a, double va,
                         const fw_target *b)
{
    if (!steered(r, b))
        return false;
    const fw_turn_pred *p = fw_turn_pred_of(b->pred);
    double cb = p && p->turning ? b->course + fw_wrap_pi(p->heading - b->heading) : b->course;
    ptrdiff_t i = a - r->all;
    double de = b->east - a->east, dn = b->north - a->north, ae, an, be, bn, tc, d2;
    double side = de * r->cs[i] - dn * r->sn[i]; /* to starboard of a's course */
    fw_velocity(b->speed, cb, &be, &bn);
    if (side * (be * r->cs[i] - bn * r->sn[i]) < 0.0)
        return false; /* closing a's track */
    fw_velocity(va, a->course, &ae, &an);
    fw_cpa_sq(de, dn, be - ae, bn - an, &tc, &d2);
    double pass = 0.5 * r->def.cpa;
    return (tc <= 0.0 ? de * de + dn * dn : d2) >= pass * pass;
}

bool fw_react_overtakes_clear(const fw_reactions *r, const fw_target *a, double v,
                              const fw_target *b)
{
    fw_own_state me = {.east = a->east, .north = a->north, .psi = a->heading, .U = v};
    return steered(r, b) && fw_react_classify(r, &me, a, b) == FW_SIT_OVERTAKING &&
           fw_react_leaves_way(r, a, v, b);
}

bool fw_react_passes_to_starboard(const fw_reactions *r, const fw_target *a, const fw_target *b)
{
    ptrdiff_t i = a - r->all;
    return steered(r, b) &&
           (b->east - a->east) * r->cs[i] - (b->north - a->north) * r->sn[i] < 0.0;
}
