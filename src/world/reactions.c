/* reactions.c - background ships that give way by COLREGs (reactions.h). */
#include "world/reactions.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/idmap.h"
#include "core/mem.h"
#include "core/names.h"
#include "core/units.h"
#include "geom/geom.h"
#include "world/reactions_internal.h"

fw_reactions_def fw_default_reactions_def(void)
{
    return (fw_reactions_def){.behaviour = FW_BEHAVIOUR_COLREGS, .cpa = 0.5 * FW_NMILE,
                              .horizon = 900.0, .range = 8000.0, .min_speed = 0.3,
                              .parallel = fw_deg_to_rad(30.0), .last_cpa = 0.25 * FW_NMILE,
                              .last_time = 240.0, .interval = 10.0,
                              .colregs = fw_default_colregs_def(),
                              .watch = fw_default_watch_def(), .give_way = FW_GIVE_WAY_COURSE,
                              .alter_min = fw_deg_to_rad(20.0), .alter_max = fw_deg_to_rad(60.0),
                              .room_from_lanes = true, .sensing = fw_default_sensing_def()};
}

static const char *const kGiveWayNames[] = {"speed", "course"}; /* fw_give_way order */

const char *fw_give_way_name(fw_give_way g) { return fw_name_of(kGiveWayNames, 2, (int)g); }

fw_status fw_give_way_parse(const char *text, fw_give_way *out)
{
    int k = fw_name_find(kGiveWayNames, 2, text);
    *out = k < 0 ? *out : (fw_give_way)k;
    return k < 0 ? FW_EINPUT : FW_OK;
}

static const char *const kBehaviourNames[] = {"colregs", "blind"}; /* fw_behaviour order */

const char *fw_behaviour_name(fw_behaviour b) { return fw_name_of(kBehaviourNames, 2, (int)b); }

fw_status fw_behaviour_parse(const char *text, fw_behaviour *out)
{
    int k = fw_name_find(kBehaviourNames, 2, text);
    *out = k < 0 ? *out : (fw_behaviour)k;
    return k < 0 ? FW_EINPUT : FW_OK;
}

fw_status fw_reactions_create(const fw_reactions_def *def, fw_reactions **out, fw_error *err)
{
    *out = NULL;
    if (!(def->cpa > 0.0) || !(def->horizon > 0.0) || !(def->range > 0.0) ||
        !(def->min_speed >= 0.0 && def->min_speed < 1.0) ||
        !(def->interval >= 0.0 && def->interval <= 60.0) ||
        !(def->alter_min > 0.0 && def->alter_min <= def->alter_max &&
          def->alter_max < 0.5 * FW_PI))
        return fw_fail(err, FW_EINPUT, "reactions: cpa, horizon and range must be positive, "
                                       "min_speed in [0, 1), interval 0 to 60 s, alterations "
                                       "0 < min <= max < 90 deg");
    fw_status s0 = fw_sensing_check(&def->sensing, err);
    if (s0)
        return s0;
    fw_reactions *r = calloc(1, sizeof *r);
    if (r && !(r->lanes = calloc(1, sizeof *r->lanes))) {
        free(r);
        r = NULL;
    }
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory");
    r->def = *def;
    r->cos_parallel = cos(def->parallel);
    fw_status st = fw_watch_create(&def->watch, &r->watch, err);
    if (st) {
        free(r->lanes);
        free(r);
        return st;
    }
    *out = r;
    return FW_OK;
}

void fw_reactions_set_rng(fw_reactions *r, fw_rng_getter rng, void *ctx)
{
    r->rng = rng;
    r->rng_ctx = ctx;
    fw_watch_set_rng(r->watch, rng, ctx);
}

void fw_reactions_mix_counts(const fw_reactions *r, long counts[FW_BEH_N])
{
    fw_watch_mix_counts(r ? r->watch : NULL, counts);
}

void fw_reactions_watch_counts(const fw_reactions *r, long *pairs, long *lapsed)
{
    fw_watch_counts(r ? r->watch : NULL, pairs, lapsed);
}

int fw_reactions_redraw(fw_reactions *r, double t)
{
    return r ? fw_watch_redraw(r->watch, t) : 0;
}

void fw_reactions_destroy(fw_reactions *r)
{
    if (!r)
        return;
    fw_idmap_free(&r->ids);
    fw_watch_destroy(r->watch);
    fw_react_sense_free(r);
    fw_lane_cache_free(&r->lanes->cache);
    fw_free_each(11, r->lanes, r->s, r->list, r->nb, r->all_buf, r->idx, r->sn, r->cs, r->log,
                 r->takes, r);
}

bool fw_reactions_active(const fw_reactions *r)
{
    return r && r->def.behaviour != FW_BEHAVIOUR_BLIND;
}

const fw_reaction *fw_reactions_list(const fw_reactions *r, int *n)
{
    *n = r->nlog;
    return r->log;
}

const fw_take_order *fw_reactions_takes(const fw_reactions *r, int *n)
{
    *n = r->ntakes;
    return r->takes;
}

fw_status fw_reactions_note(fw_reactions *r, const fw_reaction *x, fw_error *err)
{
    return fw_react_record(r, x, err);
}

fw_status fw_react_record(fw_reactions *r, const fw_reaction *x, fw_error *err)
{
    if (r->nlog == r->logcap) {
        int cap = fw_grown_cap(r->logcap, 16);
        if (!fw_resize((void **)&r->log, sizeof *r->log, (size_t)cap))
            return fw_fail(err, FW_ERUN, "out of memory for the reactions' record");
        r->logcap = cap;
    }
    r->log[r->nlog++] = *x;
    return FW_OK;
}

/* a ship held slow gets its speed back once it passes every ship near it at
 * kResume x cpa (look) */
static const double kResume = 1.25;

/* m/s: the least a stand-on ship's last action slows it to (steerage way,
 * world/steer.h's; a ship stopped in a lane is one the monitors count) */
static const double kLastWay = 1.0;

/* Rule 17(b): a stand-on ship that finds itself so close to a ship that
 * should give way that this alone cannot avoid a collision (DCPA below
 * last_cpa within last_time s) takes the action that best aids: the speed
 * (from its own down to min_speed, 5 % steps) that passes farthest, and
 * where none of those passes at last_cpa, slower still down to steerage way
 * (rule 8(e): she takes the way off; lane-bound, it is all she can do, and
 * at min_speed she ran onto give-way ships crawling or stopped across her
 * lane: strait-domain, 10 of 25 background overlaps, seeds 1-4, a93facc).
 * *j_out: the closest such ship (-1: none). */
static double last_action(const fw_reactions *r, int self, const fw_target *all, double v0,
                          double vh, int *j_out, double *dcpa_now, double *dcpa_best)
{
    const fw_target *a = &all[self];
    *j_out = -1;
    double tbest = INFINITY;
    for (int q = 0; q < r->nnb; q++) {
        int j = r->nb[q]; /* the ships in range (react) */
        double tc, dc;
        double de = all[j].east - a->east, dn = all[j].north - a->north;
        if (j == self || de * de + dn * dn > r->def.range * r->def.range)
            continue;
        fw_react_cpa_at(r, a, v0, &all[j], &tc, &dc);
        if (!(tc > 0.0 && tc < r->def.last_time && dc < r->def.last_cpa))
            continue;
        fw_own_state me = {.east = a->east, .north = a->north, .psi = a->heading, .U = v0};
        fw_situation s = fw_react_classify(r, &me, a, &all[j]);
        if ((s == FW_SIT_STAND_ON || s == FW_SIT_OVERTAKEN) && tc < tbest) {
            tbest = tc;
            *j_out = j;
            *dcpa_now = dc;
        }
    }
    if (*j_out < 0)
        return v0;
    /* the speed that passes farthest from it and from every other ship near
     * (slowing for one must not close on another); a speed held already
     * changes only for one clearly better (50 m), or it would swing */
    double best = vh >= 0.0 ? vh : v0;
    double score = fw_react_min_pass(r, self, all, best, -1, 0.0) + (vh >= 0.0 ? 50.0 : 0.0);
    *dcpa_best = *dcpa_now;
    for (int k = 0; k <= 20; k++) {
        double v = v0 * (1.0 - 0.05 * k), tc, dc;
        if (v < r->def.min_speed * v0 - 1e-12 &&
            (score >= r->def.last_cpa || v < kLastWay - 1e-12))
            break;
        double s = fw_react_min_pass(r, self, all, v, -1, 0.0);
        if (s > score + 1e-6) {
            fw_react_cpa_at(r, a, v, &all[*j_out], &tc, &dc);
            best = v, score = s, *dcpa_best = tc <= 0.0 ? INFINITY : dc;
        }
    }
    return best;
}

/* The stand-on ship's part (rule 17(b)): a speed order, or its speed back. */
static fw_status stand_on(fw_reactions *r, double t, int self, const fw_target *all,
                          react_state *st, fw_source *src, fw_error *err)
{
    const fw_target *a = &all[self];
    int j;
    double now = INFINITY, best = INFINITY;
    double v = last_action(r, self, all, st->v0, st->holding ? st->hold : -1.0, &j, &now,
                           &best);
    fw_reaction x = {.t = t, .situation = FW_SIT_STAND_ON, .dcpa_before = now, .dcpa_after = best,
                     .enough = best >= r->def.last_cpa};
    if (j < 0 || v >= st->v0) {
        if (!st->holding)
            return FW_OK;
        snprintf(x.ship, sizeof x.ship, "%s", a->id);
        x.kind = FW_REACT_RESUME, x.speed_from = st->hold, x.speed_to = st->v0;
        st->holding = st->rule17 = false;
        fw_status s2 = fw_source_set_speed(src, a->id, -1.0, err);
        return s2 ? s2 : fw_react_record(r, &x, err);
    }
    if (st->holding && fabs(v - st->hold) < 0.05 * st->v0)
        return FW_OK;
    snprintf(x.ship, sizeof x.ship, "%s", a->id);
    snprintf(x.other, sizeof x.other, "%s", all[j].id);
    fw_react_sense_note(r, j, &x);
    x.kind = FW_REACT_SLOW, x.speed_from = st->holding ? st->hold : st->v0, x.speed_to = v;
    x.why = FW_WHY_RULE17;
    st->holding = st->rule17 = true;
    st->hold = v;
    fw_status s2 = fw_source_set_speed(src, a->id, v, err);
    return s2 ? s2 : fw_react_record(r, &x, err);
}

/* Background ship `self` of all[0..n-1] this step. */
/* The ships in range that ship self must give way to but has not noticed
 * (watch.h: still within its delay, or lapsed) leave its list: it acts as if
 * they were not there.  -1 when out of memory. */
static int unnoticed(fw_reactions *r, double t, int self, const fw_target *all, double v0)
{
    int m = 0;
    for (int q = 0; q < r->nnb; q++) {
        int j = r->nb[q];
        fw_situation s;
        double tc, dc;
        if (!fw_react_is_threat(r, &all[self], v0, -1.0, &all[j], r->def.cpa, NULL, &s, &tc, &dc)) {
            r->nb[m++] = j; /* no give-way to it now: nothing to notice */
            continue;
        }
        int k = fw_watch_noticed(r->watch, &all[self], &all[j], t);
        if (k < 0)
            return -1;
        if (k)
            r->nb[m++] = j;
    }
    r->nnb = m;
    return m;
}

/* Is b out of a's sight (restricted visibility) and forward of its beam? */
static bool out_of_sight_ahead(const fw_reactions *r, const fw_target *a, const fw_target *b)
{
    double de = b->east - a->east, dn = b->north - a->north;
    return fw_not_in_sight(&r->def.colregs, hypot(de, dn)) &&
           de * sin(a->heading) + dn * cos(a->heading) > 0.0;
}

/* Rule 19(e) (reactions.h): does ship self hear, forward of its beam, the
 * fog signal of a ship of list (those it must act for) out of its sight? */
static bool rule19e_heard(const fw_reactions *r, int self, const fw_target *all, const int *list,
                          int m)
{
    const fw_target *a = &all[self];
    for (int q = 0; q < m; q++) {
        const fw_target *b = &all[list[q]];
        if (out_of_sight_ahead(r, a, b) &&
            hypot(b->east - a->east, b->north - a->north) <= fw_fog_signal_range(b->length))
            return true;
    }
    return false;
}

/* Two background ships following one waterway the same way round a bend
 * (lane.h fw_lanes_along): they share the lanes like ships on parallel
 * courses, SUMO's to keep apart. */
static bool same_way(const fw_reactions *r, const fw_target *a, const fw_target *b)
{
    struct react_lanes *L = r->lanes;
    if (a->own || b->own || !L->src || L->err.status)
        return false;
    const fw_lane_info *la, *lb;
    if (fw_lane_cache_get(&L->cache, L->src, a, L->t, &la, &L->err) ||
        fw_lane_cache_get(&L->cache, L->src, b, L->t, &lb, &L->err))
        return false; /* the step fails with L->err */
    return la && lb && fw_lanes_along(a, la, b, lb);
}

/* r->nb: the ships in range of ship self that it must look at, every pair
 * loop of look() goes over them only.  Not background ships on parallel
 * courses, nor ones following its waterway its way round a bend: those
 * share the lanes and pass by overtaking, which SUMO's car following keeps
 * apart (the cosine of the course difference from the unit vectors).  Its
 * lane is read as it looks round, so that one is known when it is in a
 * junction, where none can be read (source.h fw_lane_cache_get).  Nonzero
 * when the source failed (r->lanes->err). */
static int neighbours(fw_reactions *r, double t, int self, const fw_target *all, int n)
{
    const fw_target *a = &all[self];
    const fw_lane_info *lane;
    if (r->lanes->src &&
        fw_lane_cache_get(&r->lanes->cache, r->lanes->src, a, t, &lane, &r->lanes->err))
        return -1;
    r->nnb = 0;
    for (int j = 0; j < n; j++) {
        double de = all[j].east - a->east, dn = all[j].north - a->north;
        bool parallel = !all[j].own && r->sn[self] * r->sn[j] + r->cs[self] * r->cs[j] >
                                           r->cos_parallel;
        if (j != self && !parallel && de * de + dn * dn <= r->def.range * r->def.range &&
            !(r->truth && r->how[j] == FW_KNOWN_NOT) && !same_way(r, a, &all[j]))
            r->nb[r->nnb++] = j;
    }
    return r->lanes->err.status ? -1 : 0;
}

/* Ship self's look round (react): all[self] its truth, the others as it
 * knows them. */
static fw_status look(fw_reactions *r, double t, int self, const fw_target *all, int n,
                      react_state *st, fw_source *src, fw_error *err)
{
    const fw_target *a = &all[self];
    if (neighbours(r, t, self, all, n))
        return fw_fail(err, r->lanes->err.status, "%s", r->lanes->err.msg);
    double v0 = st->v0;
    if (fw_watch_active(r->watch) && unnoticed(r, t, self, all, v0) < 0)
        return fw_fail(err, FW_ERUN, "out of memory for the watch's encounters");
    int nearest = -1;
    fw_situation sit = FW_SIT_GIVE_WAY;
    double dcpa = INFINITY;
    /* a ship giving way keeps its speed down until its old one would pass
     * with kResume x cpa to spare: given back at cpa exactly, it would have
     * to give way again a few steps later */
    const char *keep = st->holding ? st->other : NULL;
    double vh = st->holding ? st->hold : -1.0;
    /* the ships it gives way to (at cpa; held, those that would keep it from
     * its speed: at kResume cpa) */
    int m = fw_react_threat_list(r, self, all, v0, vh, keep, r->list);
    int k = st->holding ? fw_react_threats(r, self, all, v0, vh, kResume * r->def.cpa, keep,
                                           &nearest, &sit, &dcpa)
                        : m;
    if (!st->holding && m > 0)
        fw_react_nearest_of(r, self, all, r->list, m, v0, &nearest, &sit, &dcpa);
    /* x.ship is filled only where a reaction is recorded: this runs for every
     * ship every step */
    fw_reaction x = {.t = t, .situation = sit, .dcpa_before = dcpa};
    if (k == 0 && (!st->holding || st->rule17))
        return stand_on(r, t, self, all, st, src, err);
    st->rule17 = false;
    if (k == 0) {
        /* not while the ship it gave way to is this close (the passing
         * flips from ahead to past there), unless it leaves its way */
        for (int j = 0; j < n; j++)
            if (!(r->truth && r->how[j] == FW_KNOWN_NOT) && strcmp(all[j].id, st->other) == 0 &&
                hypot(all[j].east - a->east, all[j].north - a->north) < r->def.cpa &&
                !fw_react_overtakes_clear(r, a, v0, &all[j]))
                return FW_OK;
        /* clear at its own speed again: given back */
        snprintf(x.ship, sizeof x.ship, "%s", a->id);
        x.kind = FW_REACT_RESUME, x.speed_from = st->hold, x.speed_to = st->v0;
        x.enough = true, st->holding = false;
        fw_status s2 = fw_source_set_speed(src, a->id, -1.0, err);
        return s2 ? s2 : fw_react_record(r, &x, err);
    }
    double after;
    /* rule 19(e) (reactions.h): a fog signal heard forward of the beam */
    bool r19e = rule19e_heard(r, self, all, r->list, m);
    /* the speed it holds still keeps every ship it gives way to at cpa (a
     * new one may need another: slower is not always clear of a crossing) */
    if (!r19e && st->holding && fw_react_clears_at(r, self, all, st->hold, &after))
        return FW_OK;
    /* overtaking (rule 13) it keeps out of the way by its speed (a ship
     * steered into its way from its port side: by altering, reactions.h).
     * A ship already slowed whose speed no longer keeps the passing
     * distance alters course where it can, as one that has not slowed does:
     * rule 8(d), its action checked until the other is past and clear, and
     * 8(c), where there is sea room an alteration of course alone may be the
     * most effective (it slowed further and further before: 20 of the 46
     * speed orders of the base scenario, seeds 1-3, on 4c541ac) */
    if (r->def.give_way == FW_GIVE_WAY_COURSE)
        x.why = r19e ? FW_WHY_RULE19 : FW_WHY_OVERTAKING;
    bool held = st->holding;
    if (!(held && r19e) && r->def.give_way == FW_GIVE_WAY_COURSE &&
        (sit != FW_SIT_OVERTAKING || fw_react_passes_to_starboard(r, a, &all[nearest]))) {
        int a2 = fw_react_alter(r, t, self, all, st, r->list, m, nearest, sit, dcpa, src, &x.why,
                                err);
        /* ordered, failed, or head-on (not slowed already): no speed */
        if (a2 != 0 || (sit == FW_SIT_HEAD_ON && !held))
            return a2 < 0 ? err->status : FW_OK;
    }
    double v = r19e ? r->def.min_speed * v0
                    : fw_react_yielding_speed(r, self, all, r->list, m, v0, vh, &x.enough, &after);
    /* ... or close quarters it cannot avoid with a ship out of sight ahead */
    if (!r19e && !x.enough && out_of_sight_ahead(r, &all[self], &all[nearest])) {
        r19e = true;
        v = r->def.min_speed * v0;
    }
    if (r19e)
        x.enough = fw_react_clears_at(r, self, all, v, &after);
    x.rule19e = r19e;
    if (r19e)
        x.why = FW_WHY_RULE19;
    if (st->holding && fabs(v - st->hold) < 0.05 * v0)
        return FW_OK; /* the best there is, already ordered */
    snprintf(x.ship, sizeof x.ship, "%s", a->id);
    snprintf(x.other, sizeof x.other, "%s", all[nearest].id);
    fw_react_sense_note(r, nearest, &x);
    x.kind = FW_REACT_SLOW;
    x.speed_from = st->holding ? st->hold : v0;
    x.speed_to = v;
    x.dcpa_after = after;
    snprintf(st->other, sizeof st->other, "%s", all[nearest].id);
    st->holding = true;
    st->hold = v;
    fw_status s2 = fw_source_set_speed(src, a->id, v, err);
    return s2 ? s2 : fw_react_record(r, &x, err);
}

static fw_status react(fw_reactions *r, double t, int self, const fw_target *all, int n,
                       react_state *st, fw_source *src, fw_error *err)
{
    /* itself as it is (with sensing, all[self] is what the others know of it) */
    const fw_target *a = r->truth ? &r->truth[self] : &all[self];
    /* what it does of its own accord: the fastest it has gone untold (a ship
     * slowed by SUMO's car following or speeding up again after giving way
     * means to go on at that speed); risks and speeds are judged at it, so
     * that a ship given its speed back is not told again while it picks up */
    if (!st->seen || (!st->holding && a->speed > st->v0))
        st->v0 = a->speed;
    /* a watch officer looks round every interval s, not every step: the
     * ships' first looks are spread over the interval by their place in
     * the list, so the work is too */
    if (!st->seen)
        st->t_next = t + fmod((double)self, fmax(r->def.interval, 1e-9));
    st->seen = true;
    if (t < st->t_next - 1e-9)
        return FW_OK;
    st->t_next = t + r->def.interval;
    fw_status s2 = r->truth ? fw_react_sense_begin(r, t, self, n, st, err) : FW_OK;
    if (!s2)
        s2 = look(r, t, self, all, n, st, src, err);
    if (r->truth)
        fw_react_sense_end(r);
    return s2;
}

/* The index of ship a's state (its id interned, the array grown to hold
 * it), -1 with *err set when out of memory. */
static int state_of(fw_reactions *r, const fw_target *a, fw_error *err)
{
    int k;
    if (fw_idmap_intern_keyed(&r->ids, a->key, a->id, &k)) {
        fw_fail(err, FW_ERUN, "out of memory for ship ids");
        return -1;
    }
    if (k >= r->cap) {
        int cap = fw_grown_cap(r->cap, k + 1);
        if (!fw_resize((void **)&r->s, sizeof *r->s, (size_t)cap)) {
            fw_fail(err, FW_ERUN, "out of memory for ship ids");
            return -1;
        }
        memset(r->s + r->cap, 0, sizeof *r->s * (size_t)(cap - r->cap));
        r->cap = cap;
    }
    return k;
}

/* sn[i], cs[i]: the sine and cosine of ship i's course, from its state
 * while its course stays (the own ship, last, has none). */
static void course_trig(fw_reactions *r, const fw_target *all, int n, int m)
{
    for (int i = 0; i < n; i++) {
        react_state *s = &r->s[r->idx[i]];
        if (!(s->trig_ok && s->course == all[i].course)) {
            s->course = all[i].course;
            s->sin_c = sin(s->course);
            s->cos_c = cos(s->course);
            s->trig_ok = true;
        }
        r->sn[i] = s->sin_c;
        r->cs[i] = s->cos_c;
    }
    for (int i = n; i < m; i++) {
        r->sn[i] = sin(all[i].course);
        r->cs[i] = cos(all[i].course);
    }
}

fw_status fw_reactions_step(fw_reactions *r, double t, const fw_target *vessels, int nv,
                            const fw_target *ships, int n, fw_source *src, fw_error *err)
{
    r->ntakes = 0;
    if (r->def.behaviour == FW_BEHAVIOUR_BLIND || n == 0)
        return FW_OK;
    /* fairway's vessels join the list (last) as ships to give way to */
    if (n + nv > r->list_cap) {
        if (!fw_resize_each((size_t)(n + nv), 6, (void **)&r->list, sizeof *r->list,
                            (void **)&r->nb, sizeof *r->nb, (void **)&r->all_buf,
                            sizeof *r->all_buf, (void **)&r->idx, sizeof *r->idx,
                            (void **)&r->sn, sizeof *r->sn, (void **)&r->cs, sizeof *r->cs))
            return fw_fail(err, FW_ERUN, "out of memory for %d ships", n + nv);
        r->list_cap = n + nv;
    }
    fw_target *all = r->all_buf;
    memcpy(all, ships, sizeof *all * (size_t)n);
    int m = n;
    for (int i = 0; i < nv; i++) {
        all[m] = vessels[i];
        all[m++].own = true;
    }
    /* every state found first: a new one may move the array (with sensing
     * fairway's vessels too: their AIS is heard) */
    int ns = fw_react_sensing(r) ? m : n;
    for (int i = 0; i < ns; i++)
        if ((r->idx[i] = state_of(r, &all[i], err)) < 0)
            return err->status;
    if (fw_react_sensing(r)) {
        fw_status s1 = fw_react_sense_reserve(r, m, err);
        if (!s1)
            s1 = fw_react_sense_step(r, t, all, r->idx, m, err);
        if (s1)
            return s1;
    }
    course_trig(r, all, n, m);
    r->all = all;
    r->lanes->src = src, r->lanes->t = t, r->lanes->err = (fw_error){0};
    fw_status st = FW_OK;
    for (int i = 0; i < n && !st; i++)
        st = react(r, t, i, all, m, &r->s[r->idx[i]], src, err);
    if (!st && r->lanes->err.status)
        *err = r->lanes->err, st = err->status;
    r->all = NULL;
    r->lanes->src = NULL;
    return st;
}
