/* policy.c - the own ship's avoidance policy (policy.h): its modes, the
 * return to the route and the step. */
#include "avoid/policy_internal.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "avoid/band.h"
#include "avoid/wheel_over.h"
#include "core/names.h"
#include "core/units.h"

fw_policy_def fw_default_policy_def(void)
{
    return (fw_policy_def){.act_range = FW_NMILE,
                           .act_lookahead = 10.0,
                           .standon_act_range = 0.5 * FW_NMILE,
                           .standon_act_time = 120.0,
                           .standon_lookahead = 120.0,
                           .standon_min_helm = fw_deg_to_rad(20.0),
                           .steady_margin = 1.2,
                           .min_alteration = fw_deg_to_rad(30.0),
                           .blocked_time = 120.0,
                           .return_retry = 30.0,
                           .min_avoid_time = 30.0,
                           .reopen_step = fw_deg_to_rad(30.0),
                           .ap_kp = 1.0,
                           .ap_kd = 20.0,
                           .ap_max_helm = fw_deg_to_rad(20.0),
                           .ap_deadband = fw_deg_to_rad(0.1),
                           .ap_done_heading = fw_deg_to_rad(1.0),
                           .ap_done_rate = fw_deg_to_rad(0.005),
                           .ret = FW_RETURN_TRACK,
                           .los_lookahead = FW_NMILE,
                           .los_max_angle = fw_deg_to_rad(30.0),
                           .track_done = 50.0,
                           .band_turn = fw_deg_to_rad(90.0),
                           .band_xte = FW_NMILE,
                           .slow_factor = 0.5,
                           .tss = false};
}

static const char *const kReturnNames[] = {"track", "heading"}; /* fw_return_kind order */

const char *fw_return_name(fw_return_kind k) { return fw_name_of(kReturnNames, 2, (int)k); }

fw_status fw_return_parse(const char *text, fw_return_kind *out)
{
    int k = fw_name_find(kReturnNames, 2, text);
    *out = k < 0 ? *out : (fw_return_kind)k;
    return k < 0 ? FW_EINPUT : FW_OK;
}

double fw_policy_cross_track(const fw_policy *p, const fw_own_state *own)
{
    if (!p->track_set || p->def.ret != FW_RETURN_TRACK)
        return 0.0;
    double de = own->east - p->track_e, dn = own->north - p->track_n;
    return de * cos(p->psi_ref) - dn * sin(p->psi_ref);
}

/* The heading that makes good course chi through a current the ship knows:
 * chi less the crab angle asin(c_across / U) (its speed through the water
 * U; a current across faster than the ship: the most it can, 90 deg). */
static double crabbed(const fw_own_state *own, double chi)
{
    if ((own->cur_e == 0.0 && own->cur_n == 0.0) || !(own->U > 0.1))
        return chi;
    double across = own->cur_e * cos(chi) - own->cur_n * sin(chi); /* to starboard of chi */
    return chi - asin(fmax(-1.0, fmin(1.0, across / own->U)));
}

/* The heading to steer home: the original course, less the line-of-sight
 * correction back onto the track (track return), less the crab angle the
 * current asks for (without it a line-of-sight return settles where the
 * correction equals the crab angle: 496 m off the track for 1.3 m/s across
 * at 10 kn, tests/test_env.c). */
static double home(const fw_policy *p, const fw_own_state *own)
{
    double xte = fw_policy_cross_track(p, own);
    double cut = atan(xte / p->def.los_lookahead);
    cut = fmax(-p->def.los_max_angle, fmin(p->def.los_max_angle, cut));
    return fw_wrap_2pi(crabbed(own, p->psi_ref - cut));
}

const char *fw_policy_mode_name(fw_policy_mode m)
{
    switch (m) {
    case FW_MODE_STANDBY: return "standby";
    case FW_MODE_AVOID: return "avoid";
    case FW_MODE_STEADY: return "steady";
    case FW_MODE_AUTOPILOT: return "autopilot";
    }
    return "?";
}

void fw_policy_init(fw_policy *p, const fw_policy_def *def)
{
    p->def = *def;
    p->mode = FW_MODE_STANDBY;
    p->psi_ref = 0.0;
    p->psi_hold = 0.0;
    p->psi_act = 0.0;
    p->side = FW_SIDE_NONE;
    p->helm = 0.0;
    p->primary = -1;
    p->primary_id[0] = '\0';
    p->t_mode = 0.0;
    p->t_blocked = -1.0;
    p->t_given_up = -INFINITY;
    p->course_set = false;
    p->track_set = false;
    p->track_e = p->track_n = 0.0;
    p->leg = 0;
    p->wo_leg = -1;
    p->wo = 0.0;
    p->dev = p->psi_last = 0.0;
    p->unkept = p->no_room = p->r19e = false;
    p->lb_k = 0;
    p->lb_held = false;
    p->edge_side = FW_SIDE_NONE;
    p->slow = true;
    p->speed_order = 0.0;
    p->t_kept = p->t_19e = -1.0;
}

/* The planned track: leg k of the route. */
static void set_leg(fw_policy *p, int k)
{
    const fw_route_leg *l = &p->def.route.leg[k];
    double c_old = p->psi_ref;
    p->leg = k;
    p->track_e = l->east;
    p->track_n = l->north;
    p->psi_ref = l->course;
    fw_band_leg(p, c_old);
}

/* A steered route: on to the next leg once past the active leg's wheel-over
 * point (the ship's progress along the leg, wherever it is across it). */
static fw_status follow_route(fw_policy *p, const fw_policy_input *in, fw_error *err)
{
    const fw_route *r = &p->def.route;
    fw_steer_def ap = {.kp = p->def.ap_kp, .kd = p->def.ap_kd, .max_helm = p->def.ap_max_helm};
    while (p->leg + 1 < r->n) {
        if (p->wo_leg != p->leg) {
            fw_status st = fw_wheel_over(in->ctx, r, p->leg, &ap, &p->wo, err);
            if (st)
                return st;
            p->wo_leg = p->leg;
        }
        if (fw_route_along(r, p->leg, in->own->east, in->own->north) <
            r->leg[p->leg].length - p->wo)
            break;
        set_leg(p, p->leg + 1);
    }
    return FW_OK;
}

/* PD on the heading error to psi, limited, with the autopilot's dead band. */
static double autopilot(const fw_policy *p, const fw_own_state *own, double psi)
{
    double e = fw_wrap_pi(own->psi - psi);
    /* turned more than 90 deg from the route's course: the error counted
     * through the turns (band.h), so that the way back unwinds them rather
     * than going on round the short way */
    if (p->def.band_xte > 0.0 && p->def.route.n > 0 && fabs(p->dev) > 0.5 * M_PI)
        e = p->dev - fw_wrap_pi(psi - p->psi_ref);
    double h = -p->def.ap_kp * e - p->def.ap_kd * own->r;
    if (own->delta_wind != 0.0)
        h += own->delta_wind; /* the rudder that holds the heading in the wind (track.h) */
    h = fmax(-p->def.ap_max_helm, fmin(p->def.ap_max_helm, h));
    /* within the dead band of the order in force: no new order (policy.h) */
    return fabs(h - p->helm) < p->def.ap_deadband ? p->helm : h;
}

/* Clearance of steering with the autopilot on heading psi from now, over
 * the decision horizon (beyond 0) or on past it (1: for the return). */
static fw_status steer(const fw_policy *p, fw_helm_ctx *ctx, const fw_target *tg, int n,
                       double psi, int beyond, double *clearance, fw_error *err)
{
    fw_steer_def ap = {.psi_ref = psi, .kp = p->def.ap_kp, .kd = p->def.ap_kd,
                       .max_helm = p->def.ap_max_helm};
    return fw_helm_steer_clearance(ctx, tg, n, &ap, beyond != 0, clearance, err);
}

/* t_blocked is kept through a return that is then given up: the pacing ship
 * that blocks the return for good does so by letting it start and stop */
static void start_return(fw_policy *p, double t)
{
    p->edge_side = FW_SIDE_NONE;
    fw_policy_set_mode(p, FW_MODE_AUTOPILOT, t);
}

/* Returning: on while the rest of the return keeps every target out, or
 * while stopping it would do no better (else back to STEADY).  *ret: the
 * return's clearance. */
static fw_status check_return(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                              double *ret_out, fw_error *err)
{
    double ret, hold;
    fw_status st = steer(p, in->ctx, in->targets, in->n, home(p, in->own), 1, &ret, err);
    *ret_out = ret;
    if (st || ret >= 1.0)
        return st;
    if ((st = steer(p, in->ctx, in->targets, in->n, in->own->psi, 1, &hold, err)))
        return st;
    if (hold > ret) {
        p->psi_hold = in->own->psi;
        if (p->t_blocked < 0.0)
            p->t_blocked = in->t;
        fw_policy_set_mode(p, FW_MODE_STEADY, in->t);
        p->t_given_up = in->t;
        d->reason = "the rest of the return would let a target in: steadying";
    }
    return FW_OK;
}

static fw_status step_standby(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                              fw_error *err)
{
    p->helm = p->course_set ? autopilot(p, in->own, home(p, in->own)) : 0.0;
    if (!d->search.threat) {
        d->reason = p->course_set ? "no target enters the domain: keeping the course"
                                  : "no target enters the domain on the present course";
        return FW_OK;
    }
    return fw_policy_maybe_act(p, in->ctx, in->t, in->own, in->targets, in->n, in->as, d, err);
}

static fw_status step_avoid(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                            fw_error *err)
{
    const fw_own_state *own = in->own;
    const fw_helm_result *res = &d->search;
    double turned = fabs(fw_wrap_pi(own->psi - p->psi_ref)), hold;
    /* this manoeuvre has turned as far as the predictions go: steady
     * and decide again from there rather than turn round in the traffic */
    double max_turn = in->helm->track.max_turn;
    bool far_enough = max_turn > 0.0 && fabs(fw_wrap_pi(own->psi - p->psi_act)) >= max_turn;
    bool edge = fw_band_edge(p, own, p->side);
    /* rule 8(b): one alteration large enough to be readily apparent,
     * not a succession of small ones; less only once the target passes */
    int k = p->primary_id[0] ? fw_target_find(in->targets, in->n, p->primary_id)
                             : (p->primary < in->n ? p->primary : -1);
    bool apparent = turned >= p->def.min_alteration || k < 0 || in->as[k].tcpa < 0.0;
    fw_status st = steer(p, in->ctx, in->targets, in->n, own->psi, 0, &hold, err);
    if (st)
        return st;
    /* a minimum time at the helm: ships on SUMO's polyline lanes change
     * course at each vertex, and their constant-velocity tracks swing
     * with it; without it the order would follow every swing */
    bool dwelt = in->t - p->t_mode >= p->def.min_avoid_time;
    if (dwelt && p->def.tss && fw_band_active(p) && res->threat && !res->feasible &&
        hold < 1.0) {
        /* no helm clears any more and holding this heading lets a target
         * in: within a route's band the domain cannot be kept, and the turn
         * (chosen to keep it) is not held on through the traffic to the
         * band's edge: the least bad manoeuvre instead (step_steady) */
        d->reason = "avoiding: no helm clears any more: the domain cannot be kept within the "
                    "route's band: the least bad heading and speed within it";
        p->unkept = true;
        p->psi_hold = own->psi;
        p->helm = autopilot(p, own, p->psi_hold);
        fw_policy_set_mode(p, FW_MODE_STEADY, in->t);
        return FW_OK;
    }
    /* holding this heading would leave a channel: steady parallel to its
     * edges (below) */
    bool parallel = hold < 0.0 && in->ctx->band.on;
    edge = edge || hold < 0.0; /* turning on would leave the band sooner still */
    if (edge || (dwelt && ((apparent && hold >= p->def.steady_margin) || far_enough))) {
        d->reason = parallel ? "at the edge of the route's channel: steadying parallel to it"
                    : edge ? "at the edge of the route's band: steadying"
                    : far_enough ? "turned as far as the prediction goes: steadying"
                                 : "steadying on this heading keeps every target out: steadying";
        p->unkept = p->unkept || (edge && hold < 1.0);
        p->psi_hold = parallel ? p->psi_ref : own->psi;
        if (parallel)
            p->edge_side = fw_wrap_pi(own->psi - p->psi_ref) > 0.0 ? FW_SIDE_STARBOARD
                                                                  : FW_SIDE_PORT;
        p->helm = autopilot(p, own, p->psi_hold);
        fw_policy_set_mode(p, FW_MODE_STEADY, in->t);
    } else {
        d->reason = "avoiding: holding the helm";
        if (res->side == p->side && fabs(res->helm) > fabs(p->helm)) {
            p->helm = res->helm;
            d->reason = "avoiding: the search asks for more helm";
        }
    }
    return FW_OK;
}

/* STEADY with the return blocked: a ship pacing the own ship on a converging
 * course blocks it for as long as it stays; open the range by altering
 * further away (while that is clear and within max_turn). */
static fw_status reopen(fw_policy *p, const fw_policy_input *in, fw_decision *d, fw_error *err)
{
    double away = fw_wrap_pi(p->psi_hold - p->psi_ref);
    if (!(in->t - p->t_blocked >= p->def.blocked_time && away != 0.0))
        return FW_OK;
    if (!(fw_band_sides(p, in->own) & (away > 0.0 ? FW_ALLOW_STARBOARD : FW_ALLOW_PORT)))
        return FW_OK; /* no room left in the route's band that way */
    double next = p->psi_hold + copysign(p->def.reopen_step, away), cl;
    double max_turn = in->helm->track.max_turn;
    bool within = max_turn <= 0.0 || fabs(fw_wrap_pi(next - p->psi_ref)) <= max_turn;
    if (!within)
        return FW_OK;
    fw_status st = steer(p, in->ctx, in->targets, in->n, next, 1, &cl, err);
    if (st)
        return st;
    if (cl >= p->def.steady_margin) {
        p->psi_hold = fw_wrap_pi(next);
        p->t_blocked = in->t;
        d->reason = "steady: the return stays blocked: altering further to open the range";
    }
    return FW_OK;
}

/* *out: in a channel (the search's band on), holding the present heading
 * would leave it (false without a channel). */
static fw_status leaves_channel(const fw_policy *p, const fw_policy_input *in, bool *out,
                                fw_error *err)
{
    double cl = 0.0;
    *out = false;
    if (!in->ctx->band.on)
        return FW_OK;
    fw_status st = steer(p, in->ctx, in->targets, in->n, in->own->psi, 0, &cl, err);
    *out = !st && cl < 0.0;
    return st;
}

static fw_status step_steady(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                             fw_error *err)
{
    const fw_own_state *own = in->own;
    double hold, ret;
    fw_status st = p->unkept ? fw_band_least_bad(p, in, err) : fw_band_hold(p, in, err);
    if (st)
        return st;
    p->helm = autopilot(p, own, p->psi_hold);
    if ((st = steer(p, in->ctx, in->targets, in->n, p->psi_hold, 0, &hold, err)))
        return st;
    if (hold < 0.0) {
        /* holding it leaves the band: the least bad heading within it; in a
         * channel (whose edges any other heading meets within minutes) the
         * heading parallel to its edges, the leg's course, as a master
         * steadies there: the least bad heading judged at the slowed speed
         * left it at the present one, and the ship acted and steadied by
         * turns every 2 s (policy.h) */
        if (in->ctx->band.on)
            p->psi_hold = p->psi_ref;
        else if ((st = fw_band_least_bad(p, in, err)))
            return st;
        if ((st = steer(p, in->ctx, in->targets, in->n, p->psi_hold, 0, &hold, err)))
            return st;
        p->helm = autopilot(p, own, p->psi_hold);
    }
    if (hold < 1.0) {
        bool out = false;
        if (!d->search.threat && (st = leaves_channel(p, in, &out, err)))
            return st;
        if (out) {
            /* the heading reached would leave the channel (as after a leg
             * change: the last leg's course held on round a bend took a
             * ship 2.4 km out of it): its course, parallel to its edges,
             * though a target enters the domain there */
            d->reason = "steady: the domain cannot be kept within the route's channel: holding "
                        "the least bad heading";
            p->unkept = true;
            return FW_OK;
        }
        if (!d->search.threat) {
            /* easing the rudder keeps them out where steering back to
             * psi_hold would not: hold the heading reached instead */
            d->reason = "steady: holding the present heading keeps every target out";
            p->psi_hold = own->psi;
            if ((st = fw_band_hold(p, in, err)))
                return st;
            p->helm = autopilot(p, own, p->psi_hold);
            return FW_OK;
        }
        d->reason = "steady: a target would enter the domain";
        p->unkept = p->unkept || fw_band_edge(p, own, p->dev > 0.0 ? FW_SIDE_STARBOARD
                                                                     : FW_SIDE_PORT);
        return fw_policy_maybe_act(p, in->ctx, in->t, own, in->targets, in->n, in->as, d, err);
    }
    /* no wait for TCPA < 0 here: a ship that keeps pacing the own ship
     * may never pass, and the return is checked against every target
     * over the horizon.  The margin: a return that only just clears
     * would be abandoned at the next step's slightly different
     * prediction */
    if ((st = steer(p, in->ctx, in->targets, in->n, home(p, own), 1, &ret, err)))
        return st;
    if (ret >= p->def.steady_margin && in->t - p->t_given_up >= p->def.return_retry) {
        d->reason = p->def.ret == FW_RETURN_TRACK ? "the return is clear: back to the track"
                                                  : "the return is clear: back to the course";
        p->helm = autopilot(p, own, home(p, own));
        start_return(p, in->t);
        return FW_OK;
    }
    d->reason = ret >= p->def.steady_margin ? "steady: a return given up just now is not "
                                               "started again yet"
                                             : "steady: returning now would let a target in";
    if (p->t_blocked < 0.0)
        p->t_blocked = in->t;
    return reopen(p, in, d, err);
}

/* Returning, with the rest of the return letting a target in and holding
 * the heading no better: a new threat is acted on as from STANDBY (the
 * return gives way to it like any other course would). */
static fw_status threat_on_return(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                                  fw_error *err)
{
    if (!d->search.threat)
        return FW_OK;
    d->reason = "returning: a target would enter the domain";
    return fw_policy_maybe_act(p, in->ctx, in->t, in->own, in->targets, in->n, in->as, d, err);
}

static void step_autopilot(fw_policy *p, const fw_policy_input *in, fw_decision *d)
{
    bool track = p->def.ret == FW_RETURN_TRACK;
    double psi = home(p, in->own);
    d->reason = track ? "returning: to the track" : "returning: heading autopilot";
    p->helm = autopilot(p, in->own, psi);
    if (fabs(fw_wrap_pi(in->own->psi - psi)) < p->def.ap_done_heading &&
        fabs(in->own->r) < p->def.ap_done_rate &&
        (!track || fabs(fw_policy_cross_track(p, in->own)) < p->def.track_done)) {
        d->reason = track ? "back on the track" : "back on the original course";
        p->t_blocked = -1.0;
        p->side = FW_SIDE_NONE;
        p->course_set = true;
        fw_policy_set_mode(p, FW_MODE_STANDBY, in->t);
    }
}

/* The targets met along the waterway the route follows, judged by their
 * lanes (encounter.h fw_assess_lanes): the route's legs, or without one the
 * planned track's line, as the own ship's lane. */
static void assess_lanes(const fw_policy *p, const fw_colregs_def *colregs,
                         const fw_policy_input *in)
{
    fw_route line = fw_route_line(p->track_e, p->track_n, p->psi_ref, 0.0, 1852.0);
    fw_lane_info own_lane;
    fw_route_lane(p->def.route.n > 0 ? &p->def.route : &line, &own_lane);
    fw_assess_lanes(colregs, in->own, &own_lane, in->targets, in->lanes, in->n, in->as);
}

fw_status fw_policy_step(fw_policy *p, const fw_policy_input *in, fw_decision *d,
                         fw_error *err)
{
    const fw_helm_def *hdef = in->helm;
    if (!p->track_set) {
        /* the planned track: the route's first leg (route.h), or where the
         * ship is and heads at the first step when none was given */
        const fw_route *r = &p->def.route;
        p->track_set = true;
        p->track_e = r->n > 0 ? r->leg[0].east : in->own->east;
        p->track_n = r->n > 0 ? r->leg[0].north : in->own->north;
        p->psi_ref = r->n > 0 ? r->leg[0].course : in->own->psi;
        /* a steered route is steered from the start */
        p->course_set = r->steered && p->def.ret == FW_RETURN_TRACK;
        p->psi_last = in->own->psi;
        p->dev = fw_wrap_pi(in->own->psi - p->psi_ref);
    }
    fw_band_track(p, in->own);
    fw_status st;
    if (p->course_set && p->def.route.steered && (st = follow_route(p, in, err)))
        return st;
    fw_colregs_def colregs = hdef->colregs;
    if (colregs.rank_range_m <= 0.0)
        colregs.rank_range_m = p->def.act_range; /* the paper's ranking rule (encounter.h) */
    fw_assess(&colregs, &hdef->domain, hdef->track.horizon, in->own, in->targets, in->n, in->as,
              in->order);
    if (in->lanes)
        assess_lanes(p, &colregs, in);
    fw_helm_begin(in->ctx, in->own);
    fw_helm_band band = fw_band_of(p);
    fw_helm_set_band(in->ctx, &band);
    int allowed = fw_permitted_sides(hdef, in->as, in->n);
    int room = allowed & fw_band_sides(p, in->own) & fw_band_overtaking_sides(p, in);
    p->no_room = room == 0;
    if ((st = fw_helm_search(in->ctx, in->targets, in->n, room ? room : allowed, &d->search, err)))
        return st;
    /* a side the band took away, and no helm on the others clears: the
     * domain cannot be kept within the band either (band.h: the least bad
     * heading, not the best available helm on the side left, which is held
     * through up to 90 deg of turn: in the strait study port turns of 10-17
     * deg held for 7-10 minutes across the lanes, 5 before the band, 63 with
     * it, and most of its collisions) */
    if ((room != allowed && d->search.threat && !d->search.feasible) || d->search.band_left)
        p->no_room = true;
    d->primary = in->n > 0 ? in->order[0] : -1;
    d->acted = false;
    d->reason = "";
    double ret = INFINITY;
    if (p->mode == FW_MODE_AUTOPILOT && (st = check_return(p, in, d, &ret, err)))
        return st;
    switch (p->mode) {
    case FW_MODE_STANDBY: st = step_standby(p, in, d, err); break;
    case FW_MODE_AVOID: st = step_avoid(p, in, d, err); break;
    case FW_MODE_STEADY: st = step_steady(p, in, d, err); break;
    case FW_MODE_AUTOPILOT:
        step_autopilot(p, in, d);
        if (p->mode == FW_MODE_AUTOPILOT && ret < 1.0)
            st = threat_on_return(p, in, d, err);
        break;
    }
    if (st)
        return st;
    d->mode = p->mode;
    d->helm = p->helm;
    d->leg = p->leg;
    fw_policy_order_speed(p, in, d);
    return FW_OK;
}
