/* steer_look.c - what a steered ship (steer.h) judges before it acts: its
 * velocity over ground on a course, how close it would pass the ships it
 * sees (as a straight line, or along the swing and the speed change it would
 * make), which it must give way to or stands on for. */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"
#include "geom/ramp.h"
#include "world/steer_internal.h"

/* The heading that makes good course chi over ground at speed U in the
 * current (ce, cn) the ship knows. */
double fw_steer_heading_for(double chi, double U, double ce, double cn)
{
    double across = ce * cos(chi) - cn * sin(chi); /* to starboard of chi */
    double s = U > 0.1 ? across / U : 0.0;
    return chi - asin(fmax(-0.9, fmin(0.9, s)));
}

/* Its velocity over ground (m/s east, north) on course chi at speed v. */
void fw_steer_velocity_at(const fw_own_state *o, double chi, double v, double *oe, double *on)
{
    fw_velocity(v, chi, oe, on);
    *oe += o->cur_e, *on += o->cur_n;
}

/* ... at its speed. */
void fw_steer_own_velocity(const fw_own_state *o, double chi, double *oe, double *on)
{
    fw_steer_velocity_at(o, chi, o->U, oe, on);
}

/* Ship t's closest approach to it sailing (oe, on) over ground. */
void fw_steer_cpa_on(const fw_own_state *o, const fw_target *t, double oe, double on, double *tc,
                     double *dc)
{
    double te, tn;
    fw_velocity(t->speed, t->course, &te, &tn);
    fw_cpa(t->east - o->east, t->north - o->north, te - oe, tn - on, tc, dc);
}

/* Does ship t pass it at the passing distance or more (or no closest
 * approach ahead) should it steer course chi over ground from now? */
bool fw_steer_clear_on(const steer_ctl *c, const fw_own_state *o, const fw_target *t, double chi)
{
    double oe, on, tc, dc;
    fw_steer_own_velocity(o, chi, &oe, &on);
    fw_steer_cpa_on(o, t, oe, on, &tc, &dc);
    return tc <= 0.0 || dc >= c->def.cpa;
}

/* Is the ship it gives way to past and clear, should it steer chi (its way
 * back) now?  Past: the range opening; and clear: chi passes it at the
 * passing distance or more (or no closest approach ahead).  *past: the
 * range opening (or the ship out of sight).  (Tried: clear while still
 * closing where both chi and its lane's course pass it so at its own
 * speed; ferries came back early across the own ship's bow as it turned,
 * 4 own-ship collisions in the default study, seed 2.) */
bool fw_steer_past_and_clear(const steer_ctl *c, const fw_sense *in, double chi, bool *past)
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
        return *past && fw_steer_clear_on(c, o, t, chi);
    }
    return true; /* out of sight: past */
}

/* Its course over ground now (rad; no drift: a Nomoto vessel's). */
double fw_steer_ground_course(const fw_own_state *o)
{
    return atan2(o->U * sin(o->psi) + o->cur_e, o->U * cos(o->psi) + o->cur_n);
}

/* ... and along the swing onto chi its helm gives it (pass_along), the
 * nearer of the two: judged as a straight line from where it is, a 22 kn
 * ferry's way back 60-90 deg to port looked clear of a ferry crawling
 * ahead that its swing (a radius of near a kilometre) ran onto (strait-domain
 * seed 3, replication 0: hulls overlapping). */
double fw_steer_conflict_pass(const steer_ctl *c, const fw_sense *in, double chi)
{
    return fmin(fw_steer_pass_within(in, chi, in->own->U, kConflictS, false, NULL),
                fw_steer_pass_along(c, in, chi, in->own->U));
}

/* A ship going its way (rule 13): its course within 45 deg of its heading,
 * and one of the two more than 22.5 deg abaft the other's beam: one ahead
 * it keeps its distance from by speed (follow_speed), one astern is
 * overtaking and keeps clear of it (rule 13); neither makes it alter
 * course.  A ship converging from abeam on a course within 45 deg of its
 * own is crossing (rule 15), not going its way: the courses alone hid a
 * ferry converging at 33 deg from abeam at 19 kn from a steered lane ship
 * and the lane ship from the ferry until their hulls met (strait, seed 4). */
bool fw_steer_same_way(const fw_own_state *o, const fw_target *t)
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
int fw_steer_at_risk(const steer_ctl *c, const fw_sense *in, double chi, bool give_way,
                     fw_situation *sit)
{
    int best = -1;
    /* a new danger for a ship that has acted (kReplan); standing on, the
     * passing distance itself, as the give-way ship counts on it */
    double tbest = INFINITY, oe, on, lim = give_way ? kReplan * c->def.cpa : c->def.cpa;
    fw_steer_own_velocity(in->own, chi, &oe, &on);
    for (int i = 0; i < in->n; i++) {
        double tc, dc;
        if (fw_steer_same_way(in->own, &in->targets[i]))
            continue;
        fw_steer_cpa_on(in->own, &in->targets[i], oe, on, &tc, &dc);
        if (!(tc > 0.0 && tc < kHorizonS && dc < lim && tc < tbest))
            continue;
        fw_situation s = fw_classify(&c->colregs, in->own, &in->targets[i]);
        if (give_way ? s == FW_SIT_GIVE_WAY || s == FW_SIT_HEAD_ON : s == FW_SIT_STAND_ON)
            best = i, tbest = tc, *sit = s;
    }
    return best;
}

int fw_steer_must_give_way(const steer_ctl *c, const fw_sense *in, double chi, fw_situation *sit)
{
    return fw_steer_at_risk(c, in, chi, true, sit);
}

/* Is it the stand-on ship (rule 17(a)(i): the other has it on her
 * starboard side, crossing) of a ship that on course chi it would pass
 * within the passing distance in the horizon? */
bool fw_steer_stands_on(const steer_ctl *c, const fw_sense *in, double chi)
{
    fw_situation s;
    return fw_steer_at_risk(c, in, chi, false, &s) >= 0;
}

/* The closest it would pass any ship it sees on course chi at speed v,
 * ahead in the horizon (constant velocities; with cross_only, only ships
 * not going its way); *who (may be NULL): that ship's index. */
double fw_steer_pass_within(const fw_sense *in, double chi, double v, double horizon,
                            bool cross_only, int *who)
{
    double best = INFINITY, oe, on;
    fw_steer_velocity_at(in->own, chi, v, &oe, &on);
    for (int i = 0; i < in->n; i++) {
        double tc, dc;
        if (cross_only && fw_steer_same_way(in->own, &in->targets[i]))
            continue;
        fw_steer_cpa_on(in->own, &in->targets[i], oe, on, &tc, &dc);
        if (tc > 0.0 && tc < horizon && dc < best) {
            best = dc;
            if (who)
                *who = i;
        }
    }
    return best;
}

/* The closest it would pass ship t on course chi, ahead in the horizon. */
double fw_steer_pass_one(const fw_sense *in, const fw_target *t, double chi)
{
    double oe, on, tc, dc;
    fw_steer_own_velocity(in->own, chi, &oe, &on);
    fw_steer_cpa_on(in->own, t, oe, on, &tc, &dc);
    return tc > 0.0 && tc < kHorizonS ? dc : INFINITY;
}

double fw_steer_pass_on(const fw_sense *in, double chi)
{
    return fw_steer_pass_within(in, chi, in->own->U, kHorizonS, false, NULL);
}

/* m: how far a ship at u0 m/s runs in t s when ordered v, speeding up or
 * slowing down at the background types' rates (speed_order). */
double fw_steer_run_in(double u0, double v, double t)
{
    return fw_ramp_run(u0, v, kAccel, kDecel, t);
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
double fw_steer_pass_along(const steer_ctl *c, const fw_sense *in, double chi, double v)
{
    const fw_own_state *o = in->own;
    double pe[kSamples], pn[kSamples], e = 0.0, n = 0.0, run_prev = 0.0, psi = o->psi;
    double psi_to = fw_steer_heading_for(chi, v, o->cur_e, o->cur_n);
    double per_m = FW_STEER_K_ND / c->def.length * c->def.helm_max;
    double mid_prev = NAN, sm = 0.0, cm = 1.0;
    for (int k = 0; k < kSamples; k++) {
        double s = kSampleS * (k + 1), run = fw_steer_run_in(o->U, v, s), dr = run - run_prev;
        double left = fw_wrap_pi(psi_to - psi), turn = fmin(fabs(left), per_m * dr);
        double mid = psi + copysign(0.5 * turn, left);
        psi += copysign(turn, left);
        if (mid != mid_prev) /* steady on psi_to once turned: the same sines */
            sm = sin(mid), cm = cos(mid), mid_prev = mid;
        e += dr * sm + o->cur_e * kSampleS, n += dr * cm + o->cur_n * kSampleS;
        pe[k] = e, pn[k] = n, run_prev = run;
    }
    double best = INFINITY;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double te, tn, dx = t->east - o->east, dy = t->north - o->north;
        fw_velocity(t->speed, t->course, &te, &tn);
        double d0 = hypot(dx, dy), d2min = INFINITY;
        if (d0 > (fabs(t->speed) + fmax(o->U, v) + 2.0) * kCloseS)
            continue; /* cannot come near in the look ahead */
        for (int k = 0; k < kSamples; k++) { /* squared: one root at the end */
            double s = kSampleS * (k + 1), ex = dx + te * s - pe[k], ny = dy + tn * s - pn[k];
            d2min = fmin(d2min, ex * ex + ny * ny);
        }
        double dmin = sqrt(d2min);
        if (dmin < d0)
            best = fmin(best, dmin);
    }
    return best;
}
