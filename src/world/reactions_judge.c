/* reactions_judge.c - what a background ship judges before it acts (reactions.h):
 * its encounter with each ship near it, the closest approaches at a speed it
 * might take, the ships it must give way to, and the speed that clears them. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "geom/geom.h"
#include "geom/ramp.h"
#include "world/reactions_internal.h"

fw_situation fw_react_classify(const fw_reactions *r, const fw_own_state *me,
                               const fw_target *a, const fw_target *b)
{
    fw_situation s = fw_classify(&r->def.colregs, me, b);
    struct react_lanes *L = r->lanes;
    if (s == FW_SIT_HEAD_ON || a->own || b->own || !L->src || L->err.status)
        return s;
    const fw_lane_info *la, *lb;
    if (fw_lane_cache_get(&L->cache, L->src, a, L->t, &la, &L->err) ||
        fw_lane_cache_get(&L->cache, L->src, b, L->t, &lb, &L->err))
        return s; /* the step fails with L->err */
    return fw_classify_lanes(&r->def.colregs, me, a, la, b, lb);
}

/* Velocity of ship t (one of r->all) at speed v on its course. */
static void vel(const fw_reactions *r, const fw_target *t, double v, double *ve, double *vn)
{
    ptrdiff_t i = t - r->all;
    *ve = v * r->sn[i];
    *vn = v * r->cs[i];
}

/* A ship judged at a speed faster than it goes by more than kRampMin (m/s)
 * gets there at kAccel (m/s^2; networks/ships.add.xml, the rate of all its
 * types but ferries and small craft, which are quicker; world/steer.h steers
 * at it too), and is judged along that (geom/ramp.h, its steps kRampStepS s):
 * a tanker held at 2 kn by rule 17(b) judged 13.9 kn at once to pass 180 m
 * ahead of a ferry crawling across its lane, was given its speed back, took
 * two minutes to reach it and ran onto the ferry (strait-domain seed 3,
 * replication 0).  A speed slower than it goes is judged as at once, as
 * before (not measured). */
static const double kRampMin = 0.5, kAccel = 0.05, kDecel = 0.1, kRampStepS = 5.0;

/* Closest approach of a (at speed va on its course, reached at kAccel from
 * its speed where faster) and b (as it goes): the square of the distance,
 * and with cpa_at the distance itself. */
static void cpa_sq_at(const fw_reactions *r, const fw_target *a, double va, const fw_target *b,
                      double *tcpa, double *dcpa2)
{
    double ae, an, be, bn;
    vel(r, b, b->speed, &be, &bn);
    if (va > a->speed + kRampMin) {
        ptrdiff_t i = a - r->all;
        fw_cpa_ramp_sq(b->east - a->east, b->north - a->north, be, bn, r->sn[i], r->cs[i],
                       a->speed, va, kAccel, kDecel, kRampStepS, tcpa, dcpa2);
        return;
    }
    vel(r, a, va, &ae, &an);
    fw_cpa_sq(b->east - a->east, b->north - a->north, be - ae, bn - an, tcpa, dcpa2);
}

void fw_react_cpa_at(const fw_reactions *r, const fw_target *a, double va, const fw_target *b,
                     double *tcpa, double *dcpa)
{
    double d2;
    cpa_sq_at(r, a, va, b, tcpa, &d2);
    *dcpa = sqrt(d2);
}

/* Does a, at speed va, have to give way to b (risk, and its role)? */
static bool gives_way_to(const fw_reactions *r, const fw_target *a, double va,
                         const fw_target *b, double cpa, const char *keep, fw_situation *sit,
                         double *tcpa, double *dcpa)
{
    double de = b->east - a->east, dn = b->north - a->north;
    if (de * de + dn * dn > r->def.range * r->def.range)
        return false;
    /* opening already (TCPA <= 0): no risk, and no square root spent (a
     * ship judged faster than it goes: along its speed's ramp, cpa_sq_at) */
    double ae, an, be, bn;
    vel(r, a, va, &ae, &an);
    vel(r, b, b->speed, &be, &bn);
    bool ramp = va > a->speed + kRampMin;
    if (!ramp && de * (be - ae) + dn * (bn - an) >= 0.0 && !(keep && strcmp(b->id, keep) == 0))
        return false;
    /* two background ships on nearly the same course share a lane (or run
     * beside each other in two): they pass by overtaking, which SUMO keeps
     * apart; only the own ship, off the lanes, is given way to there (the
     * cosine of the course difference from the unit vectors) */
    ptrdiff_t i = a - r->all, j = b - r->all;
    if (!b->own && r->sn[i] * r->sn[j] + r->cs[i] * r->cs[j] > r->cos_parallel)
        return false;
    /* the closest approach, squared distances first: most pairs fail here */
    double wx = be - ae, wy = bn - an, w2 = wx * wx + wy * wy;
    double tc = w2 > 1e-12 ? -(de * wx + dn * wy) / w2 : 0.0;
    double px = de + wx * tc, py = dn + wy * tc, d2 = px * px + py * py;
    if (ramp)
        cpa_sq_at(r, a, va, b, &tc, &d2);
    if (!(tc > 0.0 && tc < r->def.horizon))
        return false;
    if (!(d2 < cpa * cpa))
        return false;
    *tcpa = tc;
    *dcpa = sqrt(d2);
    fw_own_state me = {.east = a->east, .north = a->north, .psi = a->heading, .U = va};
    *sit = fw_react_classify(r, &me, a, b);
    if (*sit == FW_SIT_OVERTAKING && fw_react_leaves_way(r, a, va, b))
        return false;
    /* a give-way ship stays one until the other is past and clear (rule 8):
     * the ship it is giving way to counts while the risk lasts, whatever the
     * bearing says now (passing ahead, it moves onto the port bow) */
    if (keep && strcmp(b->id, keep) == 0)
        return true;
    /* rule 19 (colregs.visibility): out of sight there is no stand-on ship; a
     * ship forward of the beam is given way to by slowing (19(e)) */
    if (fw_not_in_sight(&r->def.colregs, sqrt(de * de + dn * dn)) &&
        de * sin(a->heading) + dn * cos(a->heading) > 0.0)
        return true;
    /* one background ship overtaking another in its lane is SUMO's to keep
     * apart (car following, lane changes); the own ship is off the lanes */
    return *sit == FW_SIT_GIVE_WAY || (*sit == FW_SIT_OVERTAKING && b->own) ||
           (*sit == FW_SIT_HEAD_ON && b->own && r->def.give_way == FW_GIVE_WAY_COURSE);
}

/* A ship a gives way to: with a risk at its own speed va, or at vh, the
 * speed it has been told to hold (vh < 0: none): a ship held slow may meet
 * at its slow speed a ship it would pass ahead of at its own. */
bool fw_react_is_threat(const fw_reactions *r, const fw_target *a, double va, double vh,
                        const fw_target *b, double cpa, const char *keep, fw_situation *sit,
                        double *tcpa, double *dcpa)
{
    if (gives_way_to(r, a, va, b, cpa, keep, sit, tcpa, dcpa))
        return true;
    return vh >= 0.0 && gives_way_to(r, a, vh, b, cpa, keep, sit, tcpa, dcpa);
}

/* The ships a gives way to at speed va: the count, and the nearest in time. */
int fw_react_threats(const fw_reactions *r, int self, const fw_target *all, double va,
                     double vh, double cpa, const char *keep, int *nearest, fw_situation *sit,
                     double *dcpa)
{
    int k = 0;
    double tbest = INFINITY;
    for (int q = 0; q < r->nnb; q++) {
        int j = r->nb[q]; /* the ships in range (react) */
        fw_situation s;
        double tc, dc;
        if (j == self ||
            !fw_react_is_threat(r, &all[self], va, vh, &all[j], cpa, keep, &s, &tc, &dc))
            continue;
        k++;
        if (tc < tbest) {
            tbest = tc;
            *nearest = j;
            *sit = s;
            *dcpa = dc;
        }
    }
    return k;
}

/* The ships a gives way to (at cpa) into list; their count. */
int fw_react_threat_list(const fw_reactions *r, int self, const fw_target *all, double v0,
                         double vh, const char *keep, int *list)
{
    int m = 0;
    for (int q = 0; q < r->nnb; q++) {
        int j = r->nb[q]; /* the ships in range (react) */
        fw_situation s0;
        double t0, d0;
        if (j != self &&
            fw_react_is_threat(r, &all[self], v0, vh, &all[j], r->def.cpa, keep, &s0, &t0, &d0))
            list[m++] = j;
    }
    return m;
}

/* Of the ships in list, the nearest in time (at a's speed v0). */
void fw_react_nearest_of(const fw_reactions *r, int self, const fw_target *all, const int *list,
                         int m, double v0, int *nearest, fw_situation *sit, double *dcpa)
{
    double tbest = INFINITY;
    for (int q = 0; q < m; q++) {
        double tc, dc;
        fw_react_cpa_at(r, &all[self], v0, &all[list[q]], &tc, &dc);
        if (tc < tbest) {
            fw_own_state me = {.east = all[self].east, .north = all[self].north,
                               .psi = all[self].heading, .U = v0};
            tbest = tc;
            *nearest = list[q];
            *sit = fw_react_classify(r, &me, &all[self], &all[list[q]]);
            *dcpa = dc;
        }
    }
}

/* The closest a, at speed v, would pass (within the horizon, ahead) any ship
 * it has to keep clear of (r->nb: in range, and not a background ship on a
 * parallel course, which SUMO keeps apart) other than skip (-1: none).  It
 * stops at the first below floor (0: never), which then is all one needs. */
double fw_react_min_pass(const fw_reactions *r, int self, const fw_target *all, double v,
                         int skip, double floor)
{
    const fw_target *a = &all[self];
    double best = INFINITY, floor2 = floor * floor; /* squared: one root at the end */
    for (int q = 0; q < r->nnb && best >= floor2; q++) {
        int j = r->nb[q];
        if (j == skip)
            continue;
        double tc, d2;
        cpa_sq_at(r, a, v, &all[j], &tc, &d2);
        if (tc > 0.0 && tc < r->def.horizon && d2 < best)
            best = d2;
    }
    return sqrt(best);
}

/* Does a at speed v pass every ship near it at cpa or more (or are they
 * past)?  Every ship, not only those it gives way to: slowing down for one
 * must not put it in another's way (a ferry slowing in one lane for a ship
 * of the next stays across the bows of the first lane's ships, which are
 * slowing to pass astern of it).  One test for all keeps the answer from
 * changing with which list a ship happens to be in from one step to the
 * next. */
bool fw_react_clears_at(const fw_reactions *r, int self, const fw_target *all, double v,
                        double *dcpa)
{
    *dcpa = fw_react_min_pass(r, self, all, v, -1, r->def.cpa);
    return *dcpa >= r->def.cpa;
}

/* The passes of ship a at speed v closer than cpa (within the horizon,
 * ahead) of the ships near it (r->nb), the kLexi closest, ascending, into d;
 * their count. */
enum { kLexi = 16 };
static int passes_within(const fw_reactions *r, int self, const fw_target *all, double v,
                         double *d)
{
    int m = 0;
    double cpa2 = r->def.cpa * r->def.cpa;
    for (int q = 0; q < r->nnb; q++) {
        double tc, d2;
        cpa_sq_at(r, &all[self], v, &all[r->nb[q]], &tc, &d2);
        if (!(tc > 0.0 && tc < r->def.horizon && d2 < cpa2))
            continue;
        double x = sqrt(d2);
        if (m == kLexi && x >= d[m - 1])
            continue;
        int i = m < kLexi ? m++ : m - 1;
        for (; i > 0 && d[i - 1] > x; i--)
            d[i] = d[i - 1];
        d[i] = x;
    }
    return m;
}

/* Passes a (na, ascending) better than b (nb) by more than tol at the
 * first place they differ by that much (a ship passing at cpa or more
 * counts as cpa)?  The closest pass decides, and where two speeds bring
 * the closest ship equally near (one it cannot get away from by its
 * speed), the next closest: compared by the closest alone, a ship holding
 * a speed for one ship that passes near whatever it does never judged a
 * ship it must give way to anew (strait study: a ferry overtaking the own
 * ship held the speed it had taken for another ship until it ran the own
 * ship down). */
static bool lexi_better(const double *a, int na, const double *b, int nb, double cpa,
                        double tol)
{
    for (int i = 0; i < na || i < nb; i++) {
        double x = i < na ? a[i] : cpa, y = i < nb ? b[i] : cpa;
        if (x > y + tol)
            return true;
        if (y > x + tol)
            return false;
    }
    return false;
}

/* The fastest speed from v0 (or the speed it holds, vh) down to min_speed v0
 * (5 % steps) at which a passes every ship near it at cpa or more (those it
 * gives way to and all the others); *enough false if none: then the speed, from v0
 * down, that passes farthest from every ship near it (the closest pass first, then the next:
 * lexi_better). */
double fw_react_yielding_speed(const fw_reactions *r, int self, const fw_target *all,
                               const int *list, int m, double v0, double vh, bool *enough,
                               double *dcpa_after)
{
    /* first never faster than it has been told (speeding up to pass ahead
     * is what a give-way ship must avoid, rule 15); only if no such speed
     * clears, any up to its own (rule 2(b): the departure that avoids the
     * immediate danger), but never towards the own ship, whose turns a
     * constant-velocity look ahead does not see coming */
    bool own = false;
    for (int q = 0; q < m; q++)
        own |= all[list[q]].own;
    /* a first slow-down is readily apparent (rule 8(b)): a fifth of its speed
     * at least (one "slowed" from 12.9 to 11.0 kn, which no one on the other
     * bridge would notice); held already, it slows further by any step */
    int k0 = vh < 0.0 ? 4 : 1;
    for (int pass = 0; pass < (own ? 1 : 2); pass++)
        for (int k = k0; k <= 20; k++) {
            double v = v0 * (1.0 - 0.05 * k);
            if (v < r->def.min_speed * v0 - 1e-12)
                break;
            bool slower = vh < 0.0 || v <= vh + 1e-9;
            if (slower != (pass == 0))
                continue;
            if (fw_react_clears_at(r, self, all, v, dcpa_after)) {
                *enough = true;
                return v;
            }
        }
    *enough = false;
    *dcpa_after = NAN;
    /* held already, it changes only for a clearly better speed (50 m):
     * between two alike it would otherwise swing from one to the other */
    double best = vh >= 0.0 ? vh : v0, db[kLexi], dv[kLexi];
    int nbest = passes_within(r, self, all, best, db);
    bool held = vh >= 0.0;
    for (int k = 0; k <= 20; k++) {
        double v = v0 * (1.0 - 0.05 * k);
        if (v < r->def.min_speed * v0 - 1e-12)
            break;
        if (own && vh >= 0.0 && v > vh + 1e-9)
            continue;
        int nv = passes_within(r, self, all, v, dv);
        if (lexi_better(dv, nv, db, nbest, r->def.cpa, held ? 50.0 : 1e-6)) {
            best = v, nbest = nv, held = false;
            memcpy(db, dv, (size_t)nv * sizeof *dv);
        }
    }
    return best;
}
