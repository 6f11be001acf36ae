/* policy.h - when to act, how much, and how to come back: a state machine.
 *
 *   STANDBY   rudder amidships; every step: assess, search the helm, and act
 *             (-> AVOID) when the policy below says so
 *   AVOID     hold the avoidance helm (raised if the search asks for more), for
 *             min_avoid_time at least and then until
 *             steadying on the present heading would keep every target out
 *             with steady_margin to spare and the course has changed by
 *             min_alteration or the target has passed, or the turn reaches the
 *             prediction's max_turn (then it steadies and decides again rather
 *             than turn round in the traffic)
 *   STEADY    hold the heading reached (the autopilot below on it) until the
 *             return to the original course keeps every target out with
 *             steady_margin to spare; act again (-> AVOID) by the STANDBY
 *             rules if a new threat calls for it.  Steadying and the return
 *             are predicted with the autopilot itself (fw_track_predict_steer),
 *             so what is checked is what is then done.
 *             A return blocked for blocked_time alters reopen_step further
 *             away, up to the prediction's max_turn in all: a ship pacing the
 *             own ship on a converging course would otherwise block it for
 *             good, and coming back part of the way only invites it again
 *             (the rule 8(b) succession of small alterations)
 *   AUTOPILOT PD on the heading error back to the original course (its first
 *             orders are the opposite helm, the paper's return), then STANDBY
 *             (which from then on keeps that course with the same PD: without
 *             disturbances its helm is near zero, the paper's "amidships").
 *             With ret = FW_RETURN_TRACK (the default) the heading steered
 *             is that of the planned track (the line through the position
 *             and heading of the first step) less a line-of-sight correction,
 *             atan(cross-track error / los_lookahead) up to los_max_angle, so
 *             the ship comes back onto its track, not only onto a parallel
 *             of it; the return ends once within track_done of the track and
 *             on the heading.  FW_RETURN_HEADING is the paper's return.
 *             If the rest of the return stops being safe and stopping it would
 *             do better, back to STEADY; if stopping would do no better, a
 *             target the return lets in is acted on by the STANDBY rules
 *             (-> AVOID): a new threat is looked at in every mode.
 *
 * Point of action for a give-way (or head-on, overtaking) own ship, the first of:
 *   - range to the threat <= act_range (the paper: act at least 1 nm before);
 *   - the minimum effective helm, if the order waited act_lookahead seconds more,
 *     would no longer keep every target out (so waiting longer would need more
 *     than the minimum helm: act now, early and substantial, rule 16);
 *   - no helm clears any more (take the best available action at once; in a
 *     traffic separation scheme the least bad manoeuvre instead, below).
 * For a stand-on own ship (rule 17: crossing target on the port side, or being
 * overtaken) keep course and speed while the give-way ship may still act; act
 * when the predicted domain entry is closer than standon_act_time, the range
 * below standon_act_range, or the largest helm ordered standon_lookahead s
 * later would no longer keep a ship it stands on for out, that ship judged
 * alone (rule 17(b): the own ship's action alone must then avoid it, and a
 * 333 m ship needs minutes; the crowd around, or no helm clearing every
 * target, is no ground for a stand-on ship to act), with at
 * least standon_min_helm (the action that best aids, not the least that
 * clears), and never to port for a target on the port side.
 *
 * The band about the route (band.h): no manoeuvre takes the heading more than
 * band_turn (90 deg) from the active leg's course, counted through every turn
 * (so no succession of alterations adds up to a round turn), nor the ship
 * more than band_xte (1 nm) across from the route, to either side.  Where
 * the route knows its waterway (a network route: route.h room_starboard,
 * room_port, its own direction's lanes less half the ship's breadth) the
 * band is that channel too, and the helm search keeps to it
 * (helm_search.h fw_helm_set_band, the active leg's): in every mode a
 * predicted track that goes out of it counts as letting a target in -
 * a candidate helm (avoid), the fallback, the steadied heading (steady),
 * the return (autopilot), the stand-on ship's least helm (rule 17) and the
 * least bad heading alike; with no candidate within it the domain cannot
 * be kept (below), and a heading held that would leave it gives way to the
 * heading parallel to its edges (the leg's course: an avoidance turn that
 * reaches the point where holding its heading would leave the channel steadies
 * on that course, as a master steadies at a channel's edge, not on the heading
 * that points out of it).  Once the domain cannot be kept in a channel, no best
 * available helm (one that does not clear) is taken from STEADY: the least bad
 * heading is held (taking it every other step and steadying back at the edge
 * between swung the rudder every 2 s in a bend-channel run), nor, once steadied
 * parallel to an edge, an alteration towards that edge (the search's track,
 * slowed by its hard turn, seems to stay in; holding any heading it turns to
 * does not).  Overtaking in a channel (rule 13: the overtaking ship keeps
 * clear) the own ship alters only away from a ship it overtakes that would
 * enter its domain, across the active leg (to starboard of one on its port
 * side), never towards it and across its bow: the least helm's side turned a 6
 * kn own ship 25 deg towards a 2 kn ship 125 m to port.  Nor is a heading held
 * in a channel because easing the rudder keeps the targets out if holding it
 * would leave the channel (the last leg's course held on through a wheel-over).
 * Why: in a narrow channel rule 9 keeps a ship to its starboard side and rule
 * 13 makes the overtaking ship keep clear; a ship overtaken close by one that
 * does not is not expected to leave the channel (nor cross into the other
 * direction's lanes): it holds its side,
 * slows where that helps, and says the domain cannot be kept.  A side
 * without room is not searched; a threat that no permitted side within the band
 * can meet means the domain cannot be kept: the decision says so
 * (fw_decision.unkept, run.log, summary.json's domain_unkept) and the ship
 * steers the least bad heading within the band (band.h fw_band_least_bad: the
 * one of the leg's course +-15, 30 .. 90 deg that keeps the targets farthest
 * out; in a channel the leg's course alone) and reduces speed to slow_factor of
 * the planned speed (not below the knowledge base's lowest fitted speed: its
 * predictions hold there) where that keeps them farther out than the planned
 * speed (each predicted; a ship coming up from astern is let in sooner by
 * slowing: in the strait study a ship slowed at the band's edge, 90 deg off its
 * route and so running along the lane, was run down from astern), until keeping
 * the course has let no target in for min_avoid_time.
 * Why: in a traffic separation scheme
 * or a channel a master who cannot open the range by altering course does not
 * circle through the lanes (rule 10 asks a crossing ship to cross at right
 * angles, and a round turn puts the ship head-on to the traffic it was
 * crossing); he keeps a predictable course and takes way off (rule 8(e):
 * "slacken her speed or take all way off"), which gives the other ship time
 * and room and keeps the own ship where the others expect it.
 * In a traffic separation scheme (def.tss: the scenario's traffic.waterway
 * tss), with a band, a threat that no helm on the permitted sides clears
 * means the domain cannot be kept as well: from STANDBY, STEADY or the
 * return the least bad manoeuvre above (heading within the band and speed)
 * is taken, not the best available helm, and an AVOID whose turn no longer
 * clears (no helm clears, and holding the heading reached lets a target in,
 * after min_avoid_time) gives way to it.  The best available helm is a turn
 * held until steadying clears, the band's edge or max_turn: among a scheme's
 * lanes it turned the own ship 160 deg across them (strait study, seed 6,
 * run 35: 305 -> 105 deg) or 90 deg on to run head-on along a lane (seed 6
 * run 49, seed 2 run 6), and the next ship of the stream ran into it.  A
 * master crossing a scheme who cannot keep his distance does not wheel round
 * in the lanes (rule 10(c): cross on a heading as nearly as practicable at
 * right angles to the flow): he keeps near his crossing heading and uses his
 * speed (rule 8(e)), taking the heading and speed that keep the ships
 * actually closing farthest off, which is what the least bad manoeuvre
 * compares, each step, over the prediction and beyond (the closest approach
 * in units of the domain).  In open water (the paper's cases, Imazu's) the
 * best available helm stays the paper's action.
 *
 * Restricted visibility (helm colregs.visibility > 0): a target farther than
 * the visibility is not in sight (encounter.h rule19) and rule 19 governs it
 * instead of rules 13-17: there is no stand-on ship (19(d): a ship that
 * detects another by radar alone takes avoiding action in ample time), so
 * such a threat makes the own ship act by the give-way rules above
 * (reasons "rule 19, not in sight: ..."), and the sides are 19(d)'s
 * (helm_search.h fw_permitted_sides): no alteration to port for a ship
 * forward of the beam other than one being overtaken, none towards a ship
 * abeam or abaft the beam.  Rule 19(e): while a target out of sight forward
 * of the beam is at risk (it enters the domain) and either its fog signal is
 * heard (within its whistle's range of audibility, COLREGs Annex III 1(c):
 * 2 nm for a ship of 200 m or more, 1.5 nm from 75 m, 1 nm from 20 m, 0.5 nm
 * below; every ship is taken to sound it, rule 35) or a close-quarters
 * situation cannot be avoided (the domain cannot be kept, above), the ship
 * reduces speed to the minimum at which she can be kept on her course:
 * taken as the knowledge base's lowest fitted speed (band.h
 * fw_rule19e_speed: 4 kn for c3-mmg's widened knowledge base, a model
 * limit, not the hull's steerage way), not above the planned speed; it
 * steers as before; the
 * speed is kept until the last target that called for it is past (its
 * closest approach behind, or out of view) and none has called for
 * min_avoid_time ("until danger of collision is over"), then the planned
 * speed is ordered again.  fw_decision.rule19e and run.log say so.  Not modelled: the sound
 * itself (its bearing is taken as the true one), taking all way off.
 */
#ifndef FW_POLICY_H
#define FW_POLICY_H

#include "avoid/helm_search.h"
#include "avoid/route.h"

typedef enum fw_policy_mode {
    FW_MODE_STANDBY,
    FW_MODE_AVOID,
    FW_MODE_STEADY,
    FW_MODE_AUTOPILOT,
} fw_policy_mode;

const char *fw_policy_mode_name(fw_policy_mode m);

typedef enum fw_return_kind { FW_RETURN_TRACK, FW_RETURN_HEADING } fw_return_kind;

/* "track", "heading"; parse: FW_EINPUT for anything else. */
const char *fw_return_name(fw_return_kind k);
fw_status fw_return_parse(const char *text, fw_return_kind *out);

typedef struct fw_policy_def {
    double act_range;          /* m, 1852 (1 nm) */
    double act_lookahead;      /* s, 10; <= 0 disables the minimum-helm trigger */
    double standon_act_range;  /* m, 926 (0.5 nm) */
    double standon_act_time;   /* s, 120: domain entry this close -> the give-way ship is late */
    double standon_lookahead;  /* s, 120: ... or the largest helm would no longer keep every
                                  target out if the order waited this long (0: off) */
    double standon_min_helm;   /* rad, 20 deg: a stand-on ship's action is at least this */
    double steady_margin;      /* 1.2: AVOID -> STEADY once steadying keeps every target
                                  this far out (normalised domain radius) ... */
    double min_alteration;     /* rad, 30 deg: ... and the heading has changed this much
                                  (rule 8(b); Woerner's "readily apparent") or the
                                  target has passed */
    double min_avoid_time;     /* s, 30: AVOID lasts at least this long */
    double return_retry;       /* s, 30: a return given up is not started again sooner: the
                                  start's prediction (from steady running) and the
                                  check's once under way (from the turning ship) can
                                  disagree, and the return would start and stop every
                                  2-5 s, the helm swinging 20 deg (measured in the
                                  default study) */
    double blocked_time;       /* s, 120: a return blocked this long in STEADY ... */
    double reopen_step;        /* rad, 30 deg: ... alters this much further away */
    /* heading autopilot: helm = -kp * error - kd * r (+ the own state's
     * delta_wind in a wind, nomoto/track.h: the rudder that holds the
     * heading there), limited to ap_max_helm.
     * kp 1 deg per deg and kd 20 s: with the C-3's 10 kn indices (K 0.013 1/s,
     * dominant lag T1 21 s, T2 and T3 nearly cancelling) the closed loop
     * 21 s^2 + (1 + K kd) s + K kp has damping 1.2 and a 4 min time constant. */
    double ap_kp;              /* rad of helm per rad of heading error */
    double ap_kd;              /* s */
    double ap_max_helm;        /* rad, 20 deg */
    double ap_deadband;        /* rad, 0.1 deg: an order within this of the order in force
                                  is not given (an autopilot's rudder dead band; a stated
                                  estimate, a tenth of a rudder angle indicator's 1 deg
                                  divisions).  Without it a track-keeping autopilot gives
                                  a new order of thousandths of a degree every second, and
                                  each restarts the MMG integrator (dynamics/stepper.h):
                                  131,000 right-hand sides an hour against 9,500 */
    double ap_done_heading;    /* rad, 1 deg: back on course within this ... */
    double ap_done_rate;       /* rad/s, ... and turning slower than 0.005 deg/s (the
                                  rudder then goes amidships: a faster residual
                                  turn would drift r (T1 + T2) off course) */
    fw_return_kind ret;        /* back to the planned track (default) or its heading */
    double los_lookahead;      /* m, 1852: the track return's line-of-sight distance */
    double los_max_angle;      /* rad, 30 deg: the largest intercept angle */
    double track_done;         /* m, 50: the return ends this close to the track */
    /* the band about the route (above; band.h); band_xte 0: no band */
    double band_turn;          /* rad, 90 deg: beyond, the ship sails back along its route */
    double band_xte;           /* m, 1852: one nautical mile, the action distance: a ship
                                  that far off its planned line is no longer where its
                                  passage plan (and the others) expect it; in the Dover
                                  scheme's 4 nm lanes it keeps the crossing within the
                                  scheme's geometry */
    double slow_factor;        /* 0.5: the speed ordered when the domain cannot be kept */
    bool tss;                  /* false; true: the ship is in a traffic separation scheme
                                  (the scenario's traffic.waterway: tss): with no helm
                                  clearing, the least bad manoeuvre, not the best
                                  available helm (above) */
    /* the planned route (route.h): its active leg is the track returned to
     * and its course the heading kept; n 0: none given, a one-leg route
     * from where the ship is and heads at its first step.  A steered route
     * (waypoints) is followed from the first step: the track autopilot
     * below on its active leg (STANDBY included), the next leg taken at the
     * wheel-over point predicted for the ship and this autopilot
     * (wheel_over.h); the leg's speed ordered (fw_decision.speed) */
    fw_route route;
} fw_policy_def;

fw_policy_def fw_default_policy_def(void);

typedef struct fw_policy {
    fw_policy_def def;
    fw_policy_mode mode;
    double psi_ref;   /* rad, the course before the manoeuvre */
    double psi_hold;  /* rad, the heading STEADY keeps */
    double psi_act;   /* rad, the heading when the present AVOID began */
    int side;         /* side of the current manoeuvre */
    double helm;      /* rad, last order */
    /* the target the manoeuvre is for: by its id (fw_target.id) when it has
     * one, so that the caller may reorder, add and drop targets between steps
     * (a target no longer in the list counts as passed); by its index in the
     * array of the step that acted when the ids are "" */
    char primary_id[FW_TARGET_ID_MAX];
    int primary;
    double t_mode;    /* s, when the present mode began */
    double t_blocked; /* s, since when the return has been blocked (< 0: it is not) */
    double t_given_up; /* s, when a return was last given up (-INFINITY: never) */
    bool course_set;  /* returned once: STANDBY keeps psi_ref by the autopilot */
    bool track_set;   /* the planned track: through (track_e, track_n) on psi_ref */
    double track_e, track_n; /* m */
    int leg;          /* the route's active leg (0 without a steered route) */
    int wo_leg;       /* the leg wo was predicted for (-1: none yet) */
    double wo;        /* m, its wheel-over distance (wheel_over.h) */
    double dev;       /* rad, the heading's turn from the active leg's course, counted
                         through every turn (not wrapped) */
    double psi_last;  /* rad, the heading at the last step */
    bool unkept;      /* the domain cannot be kept within the band */
    bool slow;        /* ... and slowing keeps the targets farther out (band.h) */
    int lb_k;         /* ... the least bad heading in force: the leg's course + lb_k 15 deg */
    bool lb_held;     /* ... chosen, and the domain not kept since (band.h) */
    bool r19e;        /* rule 19(e)'s speed held (above) ... */
    double t_19e;     /* s, ... since when no target has called for it (< 0: one does) */
    char r19e_id[FW_TARGET_ID_MAX]; /* the last target that called for it */
    bool no_room;     /* this step: no permitted side has room within the band */
    int edge_side;    /* FW_SIDE_*: the channel edge the last steady parallel to it
                         was for (the side its heading was turned to); no new
                         alteration to that side while steady (NONE: none) */
    double t_kept;    /* s, since when keeping the course lets no target in (< 0: not) */
    double speed_order; /* m/s, the last speed ordered (0: none yet) */
} fw_policy;

/* m, the own ship's distance from the planned track, + to starboard of it
 * (0 before the first step or with the heading return). */
double fw_policy_cross_track(const fw_policy *p, const fw_own_state *own);

void fw_policy_init(fw_policy *p, const fw_policy_def *def);

/* What one step decided, and why. */
typedef struct fw_decision {
    fw_policy_mode mode;    /* after this step */
    double helm;            /* rad, the order */
    double speed;           /* m/s, the speed ordered: a steered route's active leg's;
                               0: no order (the propeller is kept) */
    int leg;                /* the route's active leg */
    bool unkept;            /* the domain cannot be kept within the route's band (band.h) */
    bool rule19e;           /* rule 19(e)'s speed ordered (above) ... */
    int rule19e_target;     /* ... for this target (index this step, -1: none now) */
    const char *reason;     /* static text */
    bool acted;             /* this step started an avoidance */
    int primary;            /* most dangerous target this step: index into this
                               step's array (-1 if none); its id is tg[primary].id */
    fw_helm_result search;  /* the helm search of this step */
} fw_decision;

/* What one step decides on. */
typedef struct fw_policy_input {
    fw_helm_ctx *ctx;           /* begun here with `own` */
    const fw_helm_def *helm;
    double t;                   /* s */
    const fw_own_state *own;
    const fw_target *targets;   /* the ships seen (ids stable from step to step) */
    int n;
    fw_assessment *as;          /* room for n: filled */
    int *order;                 /* room for 2 n ints: scratch for the ranking */
    /* optional: each target's lane (traffic/lane.h; NULL entries: none
     * known), so that a ship met along a waterway the route follows is
     * judged by its lane (encounter.h fw_assess_lanes); NULL: by bearings */
    const fw_lane_info *const *lanes;
} fw_policy_input;

/* One step: assess (into in->as), search, update the mode. */
fw_status fw_policy_step(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                         fw_error *err);

#endif
