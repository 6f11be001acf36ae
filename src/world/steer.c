/* steer.c - a background ship that alters course (steer.h). */
#include "world/steer.h"

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


/* s: how far ahead a ship coming back to its lane looks for ships in its way */
static const double kConflictS = 600.0;

/* s: how often a steered ship looks round (as reactions.h's officer), and
 * how far ahead it looks for ships it must give way to */
static const double kLookS = 10.0;
static const double kHorizonS = 900.0;
static const double kCloseS = 300.0;
/* rad: the farthest off its lane's course it ever steers (the reactive
 * traffic's largest alteration, reactions.h alter_max): a ship crossing a
 * lane that turned 80 deg sailed against the lane's traffic (strait, seed
 * of run 10 at 600 m) */
static const double kMaxOff = 60.0 * FW_PI / 180.0;
/* m: a turn at close quarters must gain this much, or it would swing a
 * degree a step between courses alike */
static const double kBetterM = 50.0;

typedef struct steer_ctl {
    fw_controller base;
    fw_alter_def def;
    fw_steer_phase phase;
    double alter;                  /* rad, its alteration now (to starboard of its lane) */
    char other[FW_TARGET_ID_MAX];  /* the ship it gives way to now */
    fw_colregs_def colregs;
    double t_look;                 /* s, when it looks round next */
    /* a new alteration since the world last asked (fw_steer_controller_news) */
    bool news;
    double news_from, news_to;     /* rad, courses over ground */
    fw_situation news_sit;
    /* speed (steer.h): its own, the order now, when it was given, and until
     * when it slows because it cannot alter */
    double speed, u_order, t_order, slow_until, stop_until;
    /* the speed it wanted at the last decision, and until when it keeps its
     * own speed because that passes farther at close quarters */
    double want, go_until;
    double slow_v; /* m/s, the speed it slows to where it cannot alter (slow_for) */
} steer_ctl;

/* The heading that makes good course chi over ground at speed U in the
 * current (ce, cn) the ship knows. */
static double heading_for(double chi, double U, double ce, double cn)
{
    double across = ce * cos(chi) - cn * sin(chi); /* to starboard of chi */
    double s = U > 0.1 ? across / U : 0.0;
    return chi - asin(fmax(-0.9, fmin(0.9, s)));
}

/* The helm for heading psi_d: proportional, the gain T / (K tau^2) with tau
 * = L / U (critically damped with the model's T = T' L / U), limited. */
static double helm_for(const steer_ctl *c, const fw_own_state *o, double psi_d)
{
    double gain = FW_STEER_T_ND / FW_STEER_K_ND;
    double h = gain * fw_wrap_pi(psi_d - o->psi);
    return fmax(-c->def.helm_max, fmin(c->def.helm_max, h));
}

/* Its velocity over ground (m/s east, north) on course chi at speed v. */
static void velocity_at(const fw_own_state *o, double chi, double v, double *oe, double *on)
{
    fw_velocity(v, chi, oe, on);
    *oe += o->cur_e, *on += o->cur_n;
}

/* ... at its speed. */
static void own_velocity(const fw_own_state *o, double chi, double *oe, double *on)
{
    velocity_at(o, chi, o->U, oe, on);
}

/* Ship t's closest approach to it sailing (oe, on) over ground. */
static void cpa_on(const fw_own_state *o, const fw_target *t, double oe, double on, double *tc,
                   double *dc)
{
    double te, tn;
    fw_velocity(t->speed, t->course, &te, &tn);
    fw_cpa(t->east - o->east, t->north - o->north, te - oe, tn - on, tc, dc);
}

/* Does ship t pass it at the passing distance or more (or no closest
 * approach ahead) should it steer course chi over ground from now? */
static bool clear_on(const steer_ctl *c, const fw_own_state *o, const fw_target *t, double chi)
{
    double oe, on, tc, dc;
    own_velocity(o, chi, &oe, &on);
    cpa_on(o, t, oe, on, &tc, &dc);
    return tc <= 0.0 || dc >= c->def.cpa;
}

/* Is the ship it gives way to past and clear, should it steer chi (its way
 * back) now?  Past: the range opening; and clear: chi passes it at the
 * passing distance or more (or no closest approach ahead).  *past: the
 * range opening (or the ship out of sight).  (Tried: clear while still
 * closing where both chi and its lane's course pass it so at its own
 * speed; ferries came back early across the own ship's bow as it turned,
 * 4 own-ship collisions in the default study, seed 2.) */
static bool past_and_clear(const steer_ctl *c, const fw_sense *in, double chi, bool *past)
{
    const fw_own_state *o = in->own;
    *past = true;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        if (strcmp(t->id, c->other) != 0)
            continue;
        double oe, on, te, tn;
        /* over ground, as the target's course and speed are */
        fw_velocity(o->U, o->psi, &oe, &on);
        oe += o->cur_e, on += o->cur_n;
        fw_velocity(t->speed, t->course, &te, &tn);
        double dx = t->east - o->east, dy = t->north - o->north;
        *past = dx * (te - oe) + dy * (tn - on) >= 0.0;
        return *past && clear_on(c, o, t, chi);
    }
    return true; /* out of sight: past */
}

/* Its course over ground now (rad; no drift: a Nomoto vessel's). */
static double ground_course(const fw_own_state *o)
{
    return atan2(o->U * sin(o->psi) + o->cur_e, o->U * cos(o->psi) + o->cur_n);
}

static double pass_along(const steer_ctl *c, const fw_sense *in, double chi, double v);

/* The closest it would pass a ship it sees on course chi over ground in the
 * next 10 minutes (constant velocities; INFINITY: none closing). */
static double pass_within(const fw_sense *in, double chi, double v, double horizon,
                          bool cross_only, int *who);

/* ... and along the swing onto chi its helm gives it (pass_along), the
 * nearer of the two: judged as a straight line from where it is, a 22 kn
 * ferry's way back 60-90 deg to port looked clear of a ferry crawling
 * ahead that its swing (a radius of near a kilometre) ran onto (strait-domain
 * seed 3, replication 0: hulls overlapping). */
static double conflict_pass(const steer_ctl *c, const fw_sense *in, double chi)
{
    return fmin(pass_within(in, chi, in->own->U, kConflictS, false, NULL),
                pass_along(c, in, chi, in->own->U));
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
        if (past_and_clear(c, in, x, &past) && conflict_pass(c, in, x) >= 0.5 * c->def.cpa)
            return x;
    }
    return chi;
}



/* A ship it has altered for already acts again only for one it would pass
 * closer than this part of the passing distance (rule 8(d): its action
 * checked; one that passes nearly as far is not a new danger): at the
 * passing distance itself, 290 of its 440 looks with no alteration clear
 * in 6 seeds of the Dover base scenario found the ship passing 860-925 m
 * for 926 m, and each slowed it to 0.3 of its speed for 10 s. */
static const double kReplan = 0.8;

/* A ship going its way (rule 13): its course within 45 deg of its heading,
 * and one of the two more than 22.5 deg abaft the other's beam: one ahead
 * it keeps its distance from by speed (follow_speed), one astern is
 * overtaking and keeps clear of it (rule 13); neither makes it alter
 * course.  A ship converging from abeam on a course within 45 deg of its
 * own is crossing (rule 15), not going its way: the courses alone hid a
 * ferry converging at 33 deg from abeam at 19 kn from a steered lane ship
 * and the lane ship from the ferry until their hulls met (strait, seed 4). */
static bool same_way(const fw_own_state *o, const fw_target *t)
{
    if (!(fabs(fw_wrap_pi(t->course - o->psi)) < 0.25 * FW_PI))
        return false;
    const double abaft = fw_deg_to_rad(112.5);
    double brg = atan2(t->east - o->east, t->north - o->north);
    return fabs(fw_wrap_pi(brg - o->psi)) > abaft ||
           fabs(fw_wrap_pi(brg + FW_PI - t->heading)) > abaft;
}

/* The ship it must give way to by altering course (give_way; rules 14 and
 * 15, from its own side: crossing from starboard, head-on), or else the one
 * it stands on for (crossing from its port side), that on course chi it
 * would pass within 0.8 of the passing distance (give way: kReplan) or the
 * passing distance (stand on) in the horizon, the nearest in time; -1: none. */
static int at_risk(const steer_ctl *c, const fw_sense *in, double chi, bool give_way,
                   fw_situation *sit)
{
    int best = -1;
    /* a new danger for a ship that has acted (kReplan); standing on, the
     * passing distance itself, as the give-way ship counts on it */
    double tbest = INFINITY, oe, on, lim = give_way ? kReplan * c->def.cpa : c->def.cpa;
    own_velocity(in->own, chi, &oe, &on);
    for (int i = 0; i < in->n; i++) {
        double tc, dc;
        if (same_way(in->own, &in->targets[i]))
            continue;
        cpa_on(in->own, &in->targets[i], oe, on, &tc, &dc);
        if (!(tc > 0.0 && tc < kHorizonS && dc < lim && tc < tbest))
            continue;
        fw_situation s = fw_classify(&c->colregs, in->own, &in->targets[i]);
        if (give_way ? s == FW_SIT_GIVE_WAY || s == FW_SIT_HEAD_ON : s == FW_SIT_STAND_ON)
            best = i, tbest = tc, *sit = s;
    }
    return best;
}

static int must_give_way(const steer_ctl *c, const fw_sense *in, double chi, fw_situation *sit)
{
    return at_risk(c, in, chi, true, sit);
}

/* Is it the stand-on ship (rule 17(a)(i): the other has it on her
 * starboard side, crossing) of a ship that on course chi it would pass
 * within the passing distance in the horizon? */
static bool stands_on(const steer_ctl *c, const fw_sense *in, double chi)
{
    fw_situation s;
    return at_risk(c, in, chi, false, &s) >= 0;
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
    double hold = course + fw_wrap_pi(ground_course(in->own) - course);
    if (isfinite(c->def.room))
        hold = fmin(hold, los_course(c, course, xt, c->def.room));
    double d_hold = conflict_pass(c, in, hold);
    if (d_hold >= lim && stands_on(c, in, hold))
        return hold;
    double d_chi = conflict_pass(c, in, chi);
    if (d_chi >= lim)
        return chi;
    double d_lane = conflict_pass(c, in, course);
    if (d_lane >= lim)
        return course;
    if (d_hold >= lim || (d_hold >= d_lane && d_hold >= d_chi))
        return hold;
    return d_lane >= d_chi ? course : chi;
}

/* The closest it would pass any ship it sees on course chi at speed v,
 * ahead in the horizon (constant velocities; with cross_only, only ships
 * not going its way); *who (may be NULL): that ship's index. */
static double pass_within(const fw_sense *in, double chi, double v, double horizon,
                          bool cross_only, int *who)
{
    double best = INFINITY, oe, on;
    velocity_at(in->own, chi, v, &oe, &on);
    for (int i = 0; i < in->n; i++) {
        double tc, dc;
        if (cross_only && same_way(in->own, &in->targets[i]))
            continue;
        cpa_on(in->own, &in->targets[i], oe, on, &tc, &dc);
        if (tc > 0.0 && tc < horizon && dc < best) {
            best = dc;
            if (who)
                *who = i;
        }
    }
    return best;
}

/* The closest it would pass ship t on course chi, ahead in the horizon. */
static double pass_one(const fw_sense *in, const fw_target *t, double chi)
{
    double oe, on, tc, dc;
    own_velocity(in->own, chi, &oe, &on);
    cpa_on(in->own, t, oe, on, &tc, &dc);
    return tc > 0.0 && tc < kHorizonS ? dc : INFINITY;
}

static double pass_on(const fw_sense *in, double chi)
{
    return pass_within(in, chi, in->own->U, kHorizonS, false, NULL);
}

/* m/s^2 (ships.add.xml's accel and decel), m/s (steerage way), and the
 * fraction of its speed it slows to when it cannot alter */
static const double kAccel = 0.05, kDecel = 0.1, kSteerageWay = 1.0, kSlowFraction = 0.3;
/* s: the step of the close-quarters look ahead along a speed change */
static const double kSampleS = 5.0;

/* m: how far a ship at u0 m/s runs in t s when ordered v, speeding up or
 * slowing down at the background types' rates (speed_order). */
static double run_in(double u0, double v, double t)
{
    double a = v >= u0 ? kAccel : -kDecel, tr = (v - u0) / a;
    if (t <= tr)
        return u0 * t + 0.5 * a * t * t;
    return 0.5 * (u0 + v) * tr + v * (t - tr);
}

/* The closest it would come to any ship it sees in the next kCloseS on
 * course chi ordered speed v (its speed changing at its rates: a ship that
 * has taken the way off gets it back slowly), hull centres, every kSampleS;
 * a ship it is not closing counts not.  It turns to chi as its helmsman
 * turns it (steer_decide: at most helm_max, the model's rate K' U / L x
 * helm, so the heading changes by K' / L x helm per metre run), then sails
 * straight on: judged as a turn made at once, a 70 deg turn at close
 * quarters by a 180 m ferry at 20 kn (near two minutes and a kilometre of
 * swing) took it onto the slow ship fine on its bow that the straight line
 * missed (strait-domain seed 1, replication 12, and three more overlaps). */
enum { kSamples = 60 }; /* kCloseS / kSampleS */
static double pass_along(const steer_ctl *c, const fw_sense *in, double chi, double v)
{
    const fw_own_state *o = in->own;
    double pe[kSamples], pn[kSamples], e = 0.0, n = 0.0, run_prev = 0.0, psi = o->psi;
    double psi_to = heading_for(chi, v, o->cur_e, o->cur_n);
    double per_m = FW_STEER_K_ND / c->def.length * c->def.helm_max;
    for (int k = 0; k < kSamples; k++) {
        double s = kSampleS * (k + 1), run = run_in(o->U, v, s), dr = run - run_prev;
        double left = fw_wrap_pi(psi_to - psi), turn = fmin(fabs(left), per_m * dr);
        double mid = psi + copysign(0.5 * turn, left);
        psi += copysign(turn, left);
        e += dr * sin(mid) + o->cur_e * kSampleS, n += dr * cos(mid) + o->cur_n * kSampleS;
        pe[k] = e, pn[k] = n, run_prev = run;
    }
    double best = INFINITY;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double te, tn, dx = t->east - o->east, dy = t->north - o->north;
        fw_velocity(t->speed, t->course, &te, &tn);
        double d0 = hypot(dx, dy), dmin = d0;
        if (d0 > (fabs(t->speed) + fmax(o->U, v) + 2.0) * kCloseS)
            continue; /* cannot come near in the look ahead */
        for (int k = 0; k < kSamples; k++) {
            double s = kSampleS * (k + 1);
            dmin = fmin(dmin, hypot(dx + te * s - pe[k], dy + tn * s - pn[k]));
        }
        if (dmin < d0)
            best = fmin(best, dmin);
    }
    return best;
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
    if (!(pass_within(in, chi, in->own->U, kCloseS, true, &j) < lim))
        return false;
    double now = c->want > 0.0 ? c->want : in->own->U;
    double speeds[3] = {now, c->speed > 0.0 ? c->speed : in->own->U, kSteerageWay};
    double best = pass_along(c, in, chi, now) + kBetterM, pick = chi, v_pick = now;
    for (int s = 0; s <= 9; s++) {
        double cand = s == 0 ? chi : in->own->psi + fw_deg_to_rad(10.0 * s);
        if (s > 0 && fw_wrap_pi(cand - course) > kMaxOff + 1e-9)
            break;
        for (int k = s == 0 ? 1 : 0; k < 3; k++) {
            double d = pass_along(c, in, cand, speeds[k]);
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
    double best = -1.0, v_best = kSlowFraction * own;
    for (int k = 0; k <= 14; k++) {
        double v = own * (1.0 - 0.05 * k);
        if (v > in->own->U + 1e-9)
            continue;
        if (v < kSlowFraction * own - 1e-9)
            break;
        double d = pass_within(in, chi, v, kHorizonS, false, NULL);
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
    int j = must_give_way(c, in, chi, &sit);
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
            if (tier == 0 ? pass_on(in, chi + alt) < c->def.cpa
                          : pass_on(in, chi + alt) < 0.5 * c->def.cpa ||
                                pass_one(in, &in->targets[j], chi + alt) < c->def.cpa)
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
    own_velocity(o, chi, &oe, &on);
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
            cpa_on(o, t, oe, on, &tc, &dcpa);
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
    double want = in->t < c->stop_until   ? kSteerageWay
                  : in->t < c->go_until   ? c->speed
                  : in->t < c->slow_until ? c->slow_v
                                          : c->speed;
    c->want = want;
    /* behind the ships ahead on the course it steers and on the course it
     * makes good now: a slow ship turns slowly (K = K' U / L), and sails on
     * the old course for a while */
    double cog = ground_course(in->own);
    want = fmin(follow_speed(c, in, chi, want), follow_speed(c, in, cog, want));
    want = fmax(kSteerageWay, want);
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
    (void)err;
    steer_ctl *c = (steer_ctl *)ctl;
    const fw_own_state *o = in->own;
    double course, xt;
    int seg;
    fw_lane_where(&c->def.lane, o->east, o->north, &course, &xt, &seg);
    double back = los_course(c, course, xt, 0.0);
    /* altered: the alteration, or along the edge of its room once there */
    double held = isfinite(c->def.room)
                      ? fmin(course + c->alter, los_course(c, course, xt, c->def.room))
                      : course + c->alter;
    bool past = false;
    if (c->phase == FW_STEER_ALTER && past_and_clear(c, in, back, &past))
        c->phase = FW_STEER_RETURN;
    if (c->phase == FW_STEER_RETURN) {
        /* its bow as the source places it on giving it back: half a length
         * ahead along its course over ground (ss_give_back).  Along the
         * heading instead, a ship crabbing along its line in a cross-set
         * never came back (its bow 8-10 m off the line for a 185 m ferry
         * in Dover's spring stream: 1 of 51 altered ships given back in
         * an hour in 1 nm fog, each steered to the end of the run) */
        double bc, bxt, half = 0.5 * c->def.length;
        double dir = o->cur_e == 0.0 && o->cur_n == 0.0 ? o->psi : ground_course(o);
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
    double psi_d = heading_for(chi, o->U, o->cur_e, o->cur_n);
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

static void steer_destroy(fw_controller *c) { free(c); }

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
