/* steer_internal.h - what steer.c (a steered ship's decisions) shares with
 * steer_look.c (what it judges it would pass on a course and speed). */
#ifndef FW_STEER_INTERNAL_H
#define FW_STEER_INTERNAL_H

#include "core/units.h"
#include "world/steer.h"

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

/* What a decision knows of each ship it sees, taken once at its start
 * (steer_see): the ship's velocity over ground, and whether it goes its way
 * (fw_steer_same_way).  Each look along a course asked them of every ship
 * again: a sine and a cosine, and a bearing, per ship per course (a
 * returning ship judges three courses a second: in the 1 nm fog run of
 * bench/imperfect_cost.py, 0.8 M such per hour, 3 % of its instructions).
 * The bearing only when first asked: most decisions never ask it of most
 * ships. */
typedef struct steer_seen {
    double ve, vn;        /* m/s, east and north */
    signed char same_way; /* -1: not yet asked (fw_steer_seen_same_way) */
} steer_seen;

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
    steer_seen *seen; /* in->targets[i]'s, for the decision under way */
    int seen_cap;
    double cog;       /* rad, its course over ground, for the decision under way */
    /* by a ship's key (fw_target.key): its course and speed over ground at
     * the last decision and their velocity (a ship's course and speed seen
     * through AIS hold between its reports) */
    struct steer_memo {
        double course, speed, ve, vn;
    } *memo;
    int memo_cap;
} steer_ctl;

/* A ship it has altered for already acts again only for one it would pass
 * closer than this part of the passing distance (rule 8(d): its action
 * checked; one that passes nearly as far is not a new danger): at the
 * passing distance itself, 290 of its 440 looks with no alteration clear
 * in 6 seeds of the Dover base scenario found the ship passing 860-925 m
 * for 926 m, and each slowed it to 0.3 of its speed for 10 s. */
static const double kReplan = 0.8;

/* m/s^2 (ships.add.xml's accel and decel), m/s (steerage way), and the
 * fraction of its speed it slows to when it cannot alter */
static const double kAccel = 0.05, kDecel = 0.1, kSteerageWay = 1.0, kSlowFraction = 0.3;
/* s: the step of the close-quarters look ahead along a speed change */
static const double kSampleS = 5.0;

/* steer_look.c, each explained there. */
double fw_steer_heading_for(double chi, double U, double ce, double cn);
void fw_steer_velocity_at(const fw_own_state *o, double chi, double v, double *oe, double *on);
void fw_steer_own_velocity(const fw_own_state *o, double chi, double *oe, double *on);
void fw_steer_cpa_on(const fw_own_state *o, const fw_target *t, double oe, double on, double *tc,
                     double *dc);
bool fw_steer_see(steer_ctl *c, const fw_sense *in);
bool fw_steer_seen_same_way(const steer_ctl *c, const fw_sense *in, int i);
void fw_steer_cpa_seen(const steer_ctl *c, const fw_sense *in, int i, double oe, double on,
                       double *tc, double *dc);
bool fw_steer_clear_on(const steer_ctl *c, const fw_own_state *o, const fw_target *t, double chi);
bool fw_steer_past_and_clear(const steer_ctl *c, const fw_sense *in, double chi, bool *past);
double fw_steer_ground_course(const fw_own_state *o);
double fw_steer_conflict_pass(const steer_ctl *c, const fw_sense *in, double chi);
bool fw_steer_same_way(const fw_own_state *o, const fw_target *t);
int fw_steer_at_risk(const steer_ctl *c, const fw_sense *in, double chi, bool give_way,
                     fw_situation *sit);
int fw_steer_must_give_way(const steer_ctl *c, const fw_sense *in, double chi, fw_situation *sit);
bool fw_steer_stands_on(const steer_ctl *c, const fw_sense *in, double chi);
double fw_steer_pass_within(const steer_ctl *c, const fw_sense *in, double chi, double v,
                            double horizon, bool cross_only, int *who);
double fw_steer_pass_one(const fw_sense *in, const fw_target *t, double chi);
double fw_steer_pass_on(const steer_ctl *c, const fw_sense *in, double chi);
double fw_steer_run_in(double u0, double v, double t);
double fw_steer_pass_along(const steer_ctl *c, const fw_sense *in, double chi, double v,
                           double cap);

#endif
