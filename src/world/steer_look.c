/* steer_look.c - what a steered ship (steer.h) judges before it acts: its
 * velocity over ground on a course, how close it would pass the ships it
 * sees (as a straight line, or along the swing and the speed change it would
 * make), which it must give way to or stands on for. */
#include <math.h>
#include <stdlib.h>
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

/* a and b alike to the bit (a zero's sign too: the same velocity) */
static bool same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The memo of the ship of this key (NULL: no key, or no memory for it:
 * then the velocity is worked out each time). */
static struct steer_memo *memo_of(steer_ctl *c, int key)
{
    if (key <= 0)
        return NULL;
    if (key > c->memo_cap) {
        int cap = key > 2 * c->memo_cap ? key : 2 * c->memo_cap;
        struct steer_memo *m = realloc(c->memo, (size_t)cap * sizeof *m);
        if (!m)
            return NULL;
        for (int i = c->memo_cap; i < cap; i++)
            m[i] = (struct steer_memo){.course = NAN}; /* matches no course */
        c->memo = m, c->memo_cap = cap;
    }
    return &c->memo[key - 1];
}

/* Takes what the decision under way knows of each ship it sees (steer_seen);
 * false: out of memory. */
bool fw_steer_see(steer_ctl *c, const fw_sense *in)
{
    if (in->n > c->seen_cap) {
        int cap = in->n > 2 * c->seen_cap ? in->n : 2 * c->seen_cap;
        steer_seen *seen = realloc(c->seen, (size_t)cap * sizeof *seen);
        if (!seen)
            return false;
        c->seen = seen, c->seen_cap = cap;
    }
    c->cog = fw_steer_ground_course(in->own);
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        steer_seen *s = &c->seen[i];
        s->same_way = -1;
        struct steer_memo *m = memo_of(c, t->key);
        if (m && same_bits(m->course, t->course) && same_bits(m->speed, t->speed)) {
            s->ve = m->ve, s->vn = m->vn;
            continue;
        }
        fw_velocity(t->speed, t->course, &s->ve, &s->vn);
        if (m)
            *m = (struct steer_memo){t->course, t->speed, s->ve, s->vn};
    }
    return true;
}

/* fw_steer_same_way for in->targets[i], asked once a decision (the table is
 * the decision's scratch: written through the const controller). */
bool fw_steer_seen_same_way(const steer_ctl *c, const fw_sense *in, int i)
{
    steer_seen *s = &c->seen[i];
    if (s->same_way < 0)
        s->same_way = fw_steer_same_way(in->own, &in->targets[i]);
    return s->same_way;
}

/* fw_steer_cpa_on for in->targets[i], its velocity as seen. */
void fw_steer_cpa_seen(const steer_ctl *c, const fw_sense *in, int i, double oe, double on,
                       double *tc, double *dc)
{
    const fw_target *t = &in->targets[i];
    fw_cpa(t->east - in->own->east, t->north - in->own->north, c->seen[i].ve - oe,
           c->seen[i].vn - on, tc, dc);
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
    double straight = fw_steer_pass_within(c, in, chi, in->own->U, kConflictS, false, NULL);
    return fw_steer_pass_along(c, in, chi, in->own->U, straight);
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
        if (fw_steer_seen_same_way(c, in, i))
            continue;
        fw_steer_cpa_seen(c, in, i, oe, on, &tc, &dc);
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
double fw_steer_pass_within(const steer_ctl *c, const fw_sense *in, double chi, double v,
                            double horizon, bool cross_only, int *who)
{
    double best = INFINITY, oe, on;
    fw_steer_velocity_at(in->own, chi, v, &oe, &on);
    for (int i = 0; i < in->n; i++) {
        double tc, dc;
        if (cross_only && fw_steer_seen_same_way(c, in, i))
            continue;
        fw_steer_cpa_seen(c, in, i, oe, on, &tc, &dc);
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

double fw_steer_pass_on(const steer_ctl *c, const fw_sense *in, double chi)
{
    return fw_steer_pass_within(c, in, chi, in->own->U, kHorizonS, false, NULL);
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
 * missed (strait-domain seed 1, replication 12, and three more overlaps).
 * A distance of cap or more counts as cap: the caller knows of one that
 * near (fw_steer_conflict_pass), and a ship that cannot come nearer is
 * not followed sample by sample (pass_bound). */
enum { kSamples = 60 }; /* kCloseS / kSampleS */

/* Its path (metres from where it is, every kSampleS), sampled as far as
 * asked: most looks find every ship out of reach of the straight line it
 * sails once turned and at speed, and need no more of it than the turn. */
typedef struct along {
    double pe[kSamples], pn[kSamples];
    int n; /* samples taken */
    double u0, v, psi_to, per_m, ce, cn;
    double e, north, run_prev, psi, mid_prev, sm, cm;
    bool steady; /* turned: every later sample on the same sines */
} along;

static void along_next(along *p)
{
    int k = p->n++;
    double s = kSampleS * (k + 1), run = fw_steer_run_in(p->u0, p->v, s), dr = run - p->run_prev;
    if (!p->steady) {
        double left = fw_wrap_pi(p->psi_to - p->psi), turn = fabs(left), most = p->per_m * dr;
        turn = most < turn ? most : turn; /* fmin: a libm call, as below */
        double mid = p->psi + copysign(0.5 * turn, left);
        p->psi += copysign(turn, left);
        if (mid != p->mid_prev)
            p->sm = sin(mid), p->cm = cos(mid), p->mid_prev = mid;
        p->steady = left == 0.0;
    }
    p->e += dr * p->sm + p->ce * kSampleS, p->north += dr * p->cm + p->cn * kSampleS;
    p->pe[k] = p->e, p->pn[k] = p->north, p->run_prev = run;
}

/* No closer than this can ship t come to the path (pe, pn) in its samples:
 * the straight line at the path's final velocity (qe, qn) from where it is,
 * less the farthest the path strays from that line (dev).  (Every sample's
 * distance is at least its distance to the line's point at that time less
 * the path's offset from that point, and the line's points are no nearer
 * than the segment they lie on.) */
static double pass_bound(double dx, double dy, double te, double tn, double qe, double qn,
                         double dev)
{
    double we = te - qe, wn = tn - qn, w2 = we * we + wn * wn;
    double s = w2 > 0.0 ? -(dx * we + dy * wn) / w2 : 0.0;
    s = fmax(kSampleS, fmin(kCloseS, s));
    double px = dx + we * s, py = dy + wn * s;
    return sqrt(px * px + py * py) - dev; /* dev's slack covers the rounding */
}

double fw_steer_pass_along(const steer_ctl *c, const fw_sense *in, double chi, double v,
                           double cap)
{
    const fw_own_state *o = in->own;
    along p = {.u0 = o->U, .v = v, .psi_to = fw_steer_heading_for(chi, v, o->cur_e, o->cur_n),
               .per_m = FW_STEER_K_ND / c->def.length * c->def.helm_max, .ce = o->cur_e,
               .cn = o->cur_n, .psi = o->psi, .mid_prev = NAN, .cm = 1.0};
    /* the line at its final velocity over ground, and how far the path
     * strays from it (pass_bound): sampled until turned and at speed (at
     * tr: fw_ramp_run's), after which it strays no farther, every step
     * then the line's own (to rounding, far below the 1 mm of slack) */
    double qe = v * sin(p.psi_to) + o->cur_e, qn = v * cos(p.psi_to) + o->cur_n, dev2 = 0.0;
    double tr = (v - o->U) / (v >= o->U ? kAccel : -kDecel);
    while (p.n < kSamples) {
        along_next(&p);
        double s = kSampleS * p.n, ex = p.e - qe * s, ny = p.north - qn * s;
        double d2 = ex * ex + ny * ny;
        dev2 = d2 > dev2 ? d2 : dev2;
        if (p.steady && s - kSampleS >= tr)
            break;
    }
    double dev = sqrt(dev2) + 1e-3, best = cap;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double te = c->seen[i].ve, tn = c->seen[i].vn;
        double dx = t->east - o->east, dy = t->north - o->north;
        double reach = (fabs(t->speed) + fmax(o->U, v) + 2.0) * kCloseS;
        if (dx * dx + dy * dy > reach * reach * (1.0 + 1e-9))
            continue; /* (squared first: most are, and need no root) */
        double d0 = hypot(dx, dy), d2min = INFINITY;
        if (d0 > reach)
            continue; /* cannot come near in the look ahead */
        if (pass_bound(dx, dy, te, tn, qe, qn, dev) >= fmin(d0, best))
            continue; /* cannot come nearer than it is, or than the nearest so far */
        while (p.n < kSamples)
            along_next(&p);
        /* squared: one root at the end; the comparison rather than fmin,
         * a libm call that spilled the loop's registers every sample */
        for (int k = 0; k < kSamples; k++) {
            double s = kSampleS * (k + 1), ex = dx + te * s - p.pe[k], ny = dy + tn * s - p.pn[k];
            double d2 = ex * ex + ny * ny;
            d2min = d2 < d2min ? d2 : d2min;
        }
        double dmin = sqrt(d2min);
        if (dmin < d0)
            best = fmin(best, dmin);
    }
    return best;
}
