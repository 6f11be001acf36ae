/* steer.c - a background ship that alters course (steer.h): its decisions
 * (alter, close quarters, slow, come back) and its speed; what it judges it
 * would pass is steer_look.c's. */
#include "world/steer_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"

/* knots per m/s in the knowledge base's terms (its U is in knots) */
static const double kKnot = FW_KNOT;

void fw_steer_ship(double length, double breadth, const char *type, fw_ship *out)
{
    *out = (fw_ship){0};
    snprintf(out->name, sizeof out->name, "%s", type ? type : "background");
    snprintf(out->file, sizeof out->file, "%s", "(world/steer.h: a C-3 of its length)");
    out->L = out->Loa = length;
    out->B = breadth;
    out->rho = 1025.0;
    out->rudder_max = fw_deg_to_rad(35.0);
    out->rudder_rate = fw_deg_to_rad(35.0 + 30.0) / 28.0;
    fw_nomoto_kb *kb = &out->nomoto;
    kb->present = true;
    /* K = K' U / L (U in knots: U kKnot m/s), T1 = T' L / U; T2 = T3 cancel */
    kb->K = (fw_nomoto_index){.n = 1, .basis = {FW_NB_U}, .coef = {FW_STEER_K_ND * kKnot / length}};
    kb->T1 = (fw_nomoto_index){.n = 1, .basis = {FW_NB_INV_U},
                               .coef = {FW_STEER_T_ND * length / kKnot}};
    kb->T2 = kb->T3 = (fw_nomoto_index){.n = 1, .basis = {FW_NB_ONE}, .coef = {1.0}};
    /* the forms are exact in U: any speed a ship sails */
    kb->speed_min_kn = 0.5, kb->speed_max_kn = 40.0;
    kb->rudder_min_deg = 1.0, kb->rudder_max_deg = 35.0;
}

fw_alter_def fw_default_alter_def(void)
{
    return (fw_alter_def){.alteration = fw_deg_to_rad(30.0), .cpa = 0.5 * FW_NMILE,
                          .room = INFINITY, .length = 100.0, .breadth = 16.0,
                          .helm_max = fw_deg_to_rad(20.0)};
}

/* The helm for heading psi_d: proportional, the gain T / (K tau^2) with tau
 * = L / U (critically damped with the model's T = T' L / U), limited. */
static double helm_for(const steer_ctl *c, const fw_own_state *o, double psi_d)
{
    double gain = FW_STEER_T_ND / FW_STEER_K_ND;
    double h = gain * fw_wrap_pi(psi_d - o->psi);
    return fmax(-c->def.helm_max, fmin(c->def.helm_max, h));
}

/* Past the ship it gives way to, but its way back (back: the line of
 * sight to its lane) not yet clear of it: the steepest course back, from
 * back in 5 deg steps to its lane's own course there (no farther off), that
 * passes that ship at the passing distance and every other it sees at half
 * of it in the next 10 minutes; none: chi, its alteration held.  A master
 * past a ship comes back as soon as he can without closing it again.
 * (Holding the alteration, a ferry ran on 2 km off its route behind a lane
 * ship going its way back: the Dover base scenario, seed 3, on c08d456.
 * With only its lane's course as the other choice, a ship whose quarry
 * converged on its lane from its port quarter held its alteration for 20
 * minutes: test_steer, steepest_clear_way_back.) */
static double way_back(const steer_ctl *c, const fw_sense *in, double course, double back,
                       double chi)
{
    double ang = fw_wrap_pi(back - course), step = fw_deg_to_rad(5.0);
    int n = (int)floor(fabs(ang) / step);
    for (int k = 1; k <= n; k++) {
        double x = k < n ? back - copysign(k * step, ang) : course;
        bool past;
        if (fw_steer_past_and_clear(c, in, x, &past) &&
            fw_steer_conflict_pass(c, in, x) >= 0.5 * c->def.cpa)
            return x;
    }
    return chi;
}

/* Coming back (phase return) on chi across a ship it sees, within half the
 * passing distance in the next 10 minutes (a ship of its lane, another
 * coming back, a ship crossing ahead): along its lane where it is (course)
 * while that clears them; else it holds the course it makes good now (rule
 * 8(d): its alteration stands until the other is past and clear; rule 13:
 * overtaking, it does not turn across the bow of the ship it overtakes);
 * else, of the three, the one that passes farthest (xt: its cross-track
 * offset, m to starboard of its line; held within its room).  Before, with its lane's
 * course in conflict too it turned back regardless: across the bow of a
 * slowed ferry it was overtaking (strait-domain seed 1, replication 15) and
 * 45 deg to port onto a lane ship crossing ahead at 4 kn (seed 3,
 * replication 7).  And while it is the stand-on ship of a crossing with
 * risk (stands_on) it keeps its course (rule 17(a)(i)) if that clears the
 * others: the ship giving way to it counts on that course; before, a ferry
 * coming back turned 55 deg to port across the bow of the own ship, which
 * was turning to starboard to pass astern of it, and they met (dover-domain
 * seed 4, replication 18, on 8f2a074). */
static double los_course(const steer_ctl *c, double course, double xtrack, double offset);

static double return_course(const steer_ctl *c, const fw_sense *in, double chi, double course,
                            double xt)
{
    double lim = 0.5 * c->def.cpa;
    /* held, within its room as when it altered (steer_decide) */
    double hold = course + fw_wrap_pi(c->cog - course);
    if (isfinite(c->def.room))
        hold = fmin(hold, los_course(c, course, xt, c->def.room));
    double d_hold = fw_steer_conflict_pass(c, in, hold);
    if (d_hold >= lim && fw_steer_stands_on(c, in, hold))
        return hold;
    double d_chi = fw_steer_conflict_pass(c, in, chi);
    if (d_chi >= lim)
        return chi;
    double d_lane = fw_steer_conflict_pass(c, in, course);
    if (d_lane >= lim)
        return course;
    if (d_hold >= lim || (d_hold >= d_lane && d_hold >= d_chi))
        return hold;
    return d_lane >= d_chi ? course : chi;
}

/* The least speed through the water it slows to on course chi: steerage
 * way over ground, so that a head stream does not hold it stopped in its
 * lane (dover-imperfect: the ~1 m/s spring stream against a floor of 1 m/s
 * through the water left steered ships 0.2-0.3 kn over ground for minutes,
 * which the monitors count as stopped). */
static double least_way(const fw_sense *in, double chi)
{
    double along = in->own->cur_e * sin(chi) + in->own->cur_n * cos(chi);
    return kSteerageWay + fmax(0.0, -along);
}

/* Close quarters (rules 2(b), 8(e) and 17(b)): whatever the roles, a ship
 * the course it steers (chi) would pass within a quarter of the passing
 * distance in the next 5 minutes (not one going its way: same_way) makes it
 * take, of the courses from its heading to 90 deg to starboard of it (10
 * deg steps, at most 60 deg off its lane: a wider turn at close quarters
 * made more overlaps in the strait study, 4 against 2 in 80 runs) and the
 * speeds it has (the one it sails now, its own, steerage way), the action
 * that passes every ship farthest in those 5 minutes, its speed changing
 * at its rates, if that gains 50 m on going on as it is (true: turned).
 * Taking the way off is one of those actions, not what is left when no turn
 * gains: stopped in a crossing ship's way it is run onto by a ship that
 * cannot leave its lane (17 of 19 background overlaps in strait-domain,
 * seeds 1-4, on a93facc: a steered ship at steerage way for minutes in a
 * lane), and a stopped ship hardly turns (K = K' U / L).  Never to
 * port: the other ship, by the same rules, turns to starboard (17(c)), and
 * a turn to port against a constant-velocity look at a ship that is already
 * turning is the classic way to meet it. */
static bool close_quarters(steer_ctl *c, const fw_sense *in, double course, double chi)
{
    int j = -1;
    double lim = 0.25 * c->def.cpa;
    if (!(fw_steer_pass_within(c, in, chi, in->own->U, kCloseS, true, &j) < lim))
        return false;
    double now = c->want > 0.0 ? c->want : in->own->U;
    double speeds[3] = {now, c->speed > 0.0 ? c->speed : in->own->U, least_way(in, chi)};
    double best = fw_steer_pass_along(c, in, chi, now, INFINITY) + kBetterM;
    double pick = chi, v_pick = now;
    for (int s = 0; s <= 9; s++) {
        double cand = s == 0 ? chi : in->own->psi + fw_deg_to_rad(10.0 * s);
        if (s > 0 && fw_wrap_pi(cand - course) > kMaxOff + 1e-9)
            break;
        for (int k = s == 0 ? 1 : 0; k < 3; k++) {
            double d = fw_steer_pass_along(c, in, cand, speeds[k], INFINITY);
            if (d > best)
                best = d, pick = cand, v_pick = speeds[k];
        }
    }
    if (v_pick != now) {
        bool stop = v_pick < now;
        c->stop_until = stop ? in->t + kLookS : -INFINITY;
        c->go_until = stop ? -INFINITY : in->t + kLookS;
    }
    if (pick == chi)
        return false;
    /* the same turn as it is making (its heading still swinging to it, the
     * candidates measured from that heading): no new alteration to report;
     * before, one ship reported one turn every second of its swing, 40 deg
     * to starboard again and again, and summary.json counted each */
    bool same = c->phase == FW_STEER_ALTER &&
                fabs(fw_wrap_pi(pick - (course + c->alter))) < fw_deg_to_rad(5.0);
    if (!same) {
        c->news = true, c->news_from = in->own->psi, c->news_to = pick;
        c->news_sit = fw_classify(&c->colregs, in->own, &in->targets[j]);
    }
    c->alter = fw_wrap_pi(pick - course);
    c->phase = FW_STEER_ALTER;
    snprintf(c->other, sizeof c->other, "%s", in->targets[j].id);
    return true;
}

/* Where it cannot alter it slows (rule 8(e)) as the lane ships do
 * (reactions.h): to the fastest speed from the one it has down to
 * kSlowFraction of its own (5 % steps of its own) at which every ship it
 * sees passes at the passing distance on chi, or, none, to the one that
 * passes farthest; never faster than it goes (rule 15: a give-way ship
 * does not speed up to cross ahead).  A fixed 30 % had steered ferries
 * cross the strait's lanes at 6 kn where less would have cleared, minutes
 * in the lane ships' path. */
static void slow_for(steer_ctl *c, const fw_sense *in, double chi)
{
    double own = c->speed > 0.0 ? c->speed : fmax(in->own->U, kSteerageWay);
    double floor_v = fmax(kSlowFraction * own, least_way(in, chi));
    double best = -1.0, v_best = floor_v;
    for (int k = 0; k <= 14; k++) {
        double v = own * (1.0 - 0.05 * k);
        if (v > in->own->U + 1e-9)
            continue;
        if (v < floor_v - 1e-9)
            break;
        double d = fw_steer_pass_within(c, in, chi, v, kHorizonS, false, NULL);
        if (d >= c->def.cpa) {
            v_best = v;
            break;
        }
        if (d > best + 1e-6)
            best = d, v_best = v;
    }
    c->slow_v = v_best;
    c->slow_until = in->t + kLookS;
}

/* A ship it must give way to on the course it steers (chi): it alters
 * further to starboard, by the least of 20, 25, ... 60 deg that passes
 * every ship it sees at the passing distance, and at most 60 deg off its
 * lane (true: a new alteration; false: none needed, or none that clears,
 * and then it slows for the next look). */
static bool replan(steer_ctl *c, const fw_sense *in, double course, double chi, double xt)
{
    fw_situation sit = FW_SIT_GIVE_WAY;
    int j = fw_steer_must_give_way(c, in, chi, &sit);
    if (j < 0)
        return false;
    /* at the edge of its room (less than a length of it left to starboard)
     * a further alteration only steers along the edge, where it is: it
     * slows instead (a speed reduction where altering is not possible).
     * Before, such a ship reported the same alteration every look (one 15
     * times in 150 s at twice Dover's density) while its heading stayed */
    if (isfinite(c->def.room) && c->def.room - xt < c->def.length) {
        slow_for(c, in, chi);
        return false;
    }
    /* first every ship it sees at the passing distance; if none does, the
     * least that passes this one so and every other at half of it */
    for (int tier = 0; tier < 2; tier++)
        for (double alt = fw_deg_to_rad(20.0); alt <= fw_deg_to_rad(60.0) + 1e-9;
             alt += fw_deg_to_rad(5.0)) {
            double off = fw_wrap_pi(chi + alt - course);
            if (off > kMaxOff + 1e-9)
                break;
            if (tier == 0 ? fw_steer_pass_on(c, in, chi + alt) < c->def.cpa
                          : fw_steer_pass_on(c, in, chi + alt) < 0.5 * c->def.cpa ||
                                fw_steer_pass_one(in, &in->targets[j], chi + alt) < c->def.cpa)
                continue;
            c->news = true, c->news_from = chi, c->news_to = chi + alt, c->news_sit = sit;
            c->alter = off;
            c->phase = FW_STEER_ALTER;
            snprintf(c->other, sizeof c->other, "%s", in->targets[j].id);
            return true;
        }
    slow_for(c, in, chi);
    return false;
}

/* Keeping its distance (steer.h): SUMO's gap for the background types
 * (networks/ships.add.xml minGap 200 m, tau 30 s), closed or opened over
 * kRelaxS; who counts: a ship ahead within 45 deg of its course, in its path
 * (its half breadth and the other's and kSideM) now or within kPathS. */
static const double kMinGapM = 200.0, kHeadwayS = 30.0, kRelaxS = 60.0;
static const double kSideM = 100.0, kPathS = 600.0;
/* The fastest it may sail on course chi behind the ships ahead going its way. */
static double follow_speed(const steer_ctl *c, const fw_sense *in, double chi, double want)
{
    const fw_own_state *o = in->own;
    double v = want, sc = sin(chi), cc = cos(chi), oe, on;
    fw_steer_own_velocity(o, chi, &oe, &on);
    /* m: beyond this gap no ship ahead slows it (the law below at want) */
    double reach = kMinGapM + (kHeadwayS + kRelaxS) * want + 0.5 * c->def.length + 500.0;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double dx = t->east - o->east, dy = t->north - o->north;
        double ahead = dx * sc + dy * cc;
        if (!(ahead > 0.0) || ahead > reach + 0.5 * t->length)
            continue;
        double dc = fw_wrap_pi(t->course - chi);
        if (fabs(dc) > 0.25 * FW_PI)
            continue;
        double across = dx * cc - dy * sc;
        double w = 0.5 * (c->def.breadth + t->breadth) + kSideM, tc, dcpa;
        if (fabs(across) > w) {
            fw_steer_cpa_seen(c, in, i, oe, on, &tc, &dcpa);
            if (!(tc > 0.0 && tc < kPathS && dcpa < w))
                continue;
        }
        double lead = fmax(0.0, t->speed * cos(dc));
        double gap = ahead - 0.5 * (c->def.length + t->length);
        v = fmin(v, lead + (gap - kMinGapM - kHeadwayS * lead) / kRelaxS);
    }
    return v;
}

/* Its speed order this step: towards what it wants, as fast as it may
 * change, never below steerage way. */
static double speed_order(steer_ctl *c, const fw_sense *in, double chi)
{
    if (!(c->speed > 0.0))
        c->speed = fmax(in->own->U, kSteerageWay);
    if (!isfinite(c->t_order))
        c->u_order = in->own->U, c->t_order = in->t;
    double least = least_way(in, chi);
    double want = in->t < c->stop_until   ? least
                  : in->t < c->go_until   ? c->speed
                  : in->t < c->slow_until ? c->slow_v
                                          : c->speed;
    c->want = want;
    /* behind the ships ahead on the course it steers and on the course it
     * makes good now: a slow ship turns slowly (K = K' U / L), and sails on
     * the old course for a while */
    double cog = c->cog;
    want = fmin(follow_speed(c, in, chi, want), follow_speed(c, in, cog, want));
    want = fmax(least, want);
    double dt = fmax(0.0, in->t - c->t_order), u = c->u_order;
    u = want > u ? fmin(want, u + kAccel * dt) : fmax(want, u - kDecel * dt);
    c->u_order = u, c->t_order = in->t;
    return u;
}

/* The course over ground to a line `offset` m to starboard of the lane's
 * (line-of-sight), never more than the alteration (at least 20, at most 45
 * deg) off the line's course. */
static double los_course(const steer_ctl *c, double course, double xtrack, double offset)
{
    double look = fmax(4.0 * c->def.length, 400.0);
    double off = atan2(-(xtrack - offset), look);
    double lim = fmin(fmax(fabs(c->alter), fw_deg_to_rad(20.0)), fw_deg_to_rad(45.0));
    return course + fmax(-lim, fmin(lim, off));
}

static fw_status steer_decide(fw_controller *ctl, const fw_sense *in, fw_decision *d,
                              fw_error *err)
{
    steer_ctl *c = (steer_ctl *)ctl;
    const fw_own_state *o = in->own;
    if (!fw_steer_see(c, in))
        return fw_fail(err, FW_ERUN, "out of memory");
    double course, xt;
    int seg;
    fw_lane_where(&c->def.lane, o->east, o->north, &course, &xt, &seg);
    double back = los_course(c, course, xt, 0.0);
    /* altered: the alteration, or along the edge of its room once there */
    double held = isfinite(c->def.room)
                      ? fmin(course + c->alter, los_course(c, course, xt, c->def.room))
                      : course + c->alter;
    bool past = false;
    if (c->phase == FW_STEER_ALTER && fw_steer_past_and_clear(c, in, back, &past))
        c->phase = FW_STEER_RETURN;
    if (c->phase == FW_STEER_RETURN) {
        /* its bow as the source places it on giving it back: half a length
         * ahead along its course over ground (ss_give_back).  Along the
         * heading instead, a ship crabbing along its line in a cross-set
         * never came back (its bow 8-10 m off the line for a 185 m ferry
         * in Dover's spring stream: 1 of 51 altered ships given back in
         * an hour in 1 nm fog, each steered to the end of the run) */
        double bc, bxt, half = 0.5 * c->def.length;
        double dir = o->cur_e == 0.0 && o->cur_n == 0.0 ? o->psi : c->cog;
        fw_lane_where(&c->def.lane, o->east + half * sin(dir), o->north + half * cos(dir), &bc,
                      &bxt, &seg);
        if (fabs(xt) < 0.3 && fabs(bxt) < 0.3 && fabs(o->r) < fw_deg_to_rad(0.05))
            c->phase = FW_STEER_DONE;
    }
    double chi = c->phase != FW_STEER_ALTER ? back : held;
    if (c->phase == FW_STEER_ALTER && past)
        chi = way_back(c, in, course, back, chi);
    /* coming back across ships in its way, or standing on: not yet
     * (return_course); what follows judges the course it will steer */
    if (c->phase == FW_STEER_RETURN)
        chi = return_course(c, in, chi, course, xt);
    if (in->t >= c->t_look - 1e-9) {
        c->t_look = in->t + kLookS;
        if (replan(c, in, course, chi, xt)) /* a ship it must now give way to */
            chi = course + c->alter;
    }
    if (close_quarters(c, in, course, chi))
        chi = course + c->alter;
    double psi_d = fw_steer_heading_for(chi, o->U, o->cur_e, o->cur_n);
    double helm = helm_for(c, o, psi_d);
    if (c->def.pred) {
        /* the rate its helm gives (the model's steady rate), or its own if faster */
        double L = c->def.length, rate = FW_STEER_K_ND * o->U / L * fabs(helm);
        c->def.pred->rate = fmax(rate, fabs(o->r));
        c->def.pred->heading = psi_d;
        c->def.pred->turning = fabs(fw_wrap_pi(psi_d - o->psi)) > fw_deg_to_rad(1.0);
    }
    *d = (fw_decision){.mode = c->phase == FW_STEER_ALTER ? FW_MODE_AVOID : FW_MODE_AUTOPILOT,
                       .helm = helm, .speed = speed_order(c, in, chi), .primary = -1,
                       .reason = c->phase == FW_STEER_ALTER    ? "gives way: course altered"
                                 : c->phase == FW_STEER_RETURN ? "back to its lane"
                                                               : "on its lane: to be given back"};
    return FW_OK;
}

static void steer_destroy(fw_controller *ctl)
{
    steer_ctl *c = (steer_ctl *)ctl;
    if (c)
        free(c->seen), free(c->memo);
    free(c);
}

static const fw_controller_ops steer_ops = {.name = "steer", .decide = steer_decide,
                                            .assesses = false, .destroy = steer_destroy};

fw_status fw_steer_controller_create(const fw_alter_def *def, fw_controller **out, fw_error *err)
{
    *out = NULL;
    if (def->lane.np < 2 || def->lane.np > FW_LANE_POINTS ||
        !(def->alteration > 0.0 && def->alteration < 0.5 * FW_PI) || !(def->cpa > 0.0) ||
        !(def->room >= 0.0) || !(def->speed >= 0.0) || !(def->breadth >= 0.0) ||
        !(def->length > 0.0) || !(def->helm_max > 0.0))
        return fw_fail(err, FW_EINPUT, "steer: a lane of 2 or more points, an alteration "
                                       "between 0 and 90 deg, cpa, length and helm positive, room >= 0");
    steer_ctl *c = calloc(1, sizeof *c);
    if (!c)
        return fw_fail(err, FW_ERUN, "out of memory");
    c->base.ops = &steer_ops;
    c->def = *def;
    c->phase = FW_STEER_ALTER;
    c->alter = def->alteration;
    snprintf(c->other, sizeof c->other, "%s", def->other);
    c->colregs = fw_default_colregs_def();
    c->t_look = -INFINITY; /* set at the first decision */
    c->speed = def->speed;
    c->t_order = NAN;      /* the first decision gives the first order */
    c->slow_until = c->stop_until = c->go_until = -INFINITY;
    *out = &c->base;
    return FW_OK;
}

bool fw_steer_controller_is(const fw_controller *c) { return c && c->ops == &steer_ops; }

fw_steer_phase fw_steer_controller_phase(const fw_controller *c)
{
    return ((const steer_ctl *)c)->phase;
}

bool fw_steer_controller_news(fw_controller *ctl, double *from, double *to, char *other,
                              fw_situation *sit)
{
    steer_ctl *c = (steer_ctl *)ctl;
    if (!c->news)
        return false;
    c->news = false;
    *from = c->news_from, *to = c->news_to, *sit = c->news_sit;
    snprintf(other, FW_TARGET_ID_MAX, "%s", c->other);
    return true;
}
