/* policy_act.c - when the own ship acts (policy.h): give-way, stand-on
 * (rule 17) and rule 19 grounds for acting now, and the action taken, or the
 * least bad heading where the domain cannot be kept within the route's band. */
#include <math.h>
#include <stdio.h>

#include "avoid/band.h"
#include "avoid/helm_ctx.h"
#include "avoid/policy_internal.h"

static bool gives_way(fw_situation s)
{
    return s == FW_SIT_HEAD_ON || s == FW_SIT_GIVE_WAY || s == FW_SIT_OVERTAKING;
}

/* Rule 17(b) for a stand-on own ship: is this the last moment its action
 * alone still avoids one of the ships it stands on for, that is, would its
 * largest helm, ordered standon_lookahead s from now, no longer keep that
 * ship out of the domain?  Each such ship (entering the domain, the own ship
 * standing on) is judged alone: 17(b) is about a give-way ship so close that
 * its action alone can no longer avoid a collision, not about the crowd
 * around.  Judged against every target at once, a dense scheme made the
 * largest helm fail for ships that were not the give-way ship and the own
 * ship acted "alone" for a ferry 10.2 km off (TCPA 619 s: a Dover run at
 * 150 m domain); and no helm clearing every target (the search infeasible)
 * is no ground for a stand-on ship to act either (rule 17(a)(i)). */
static fw_status standon_last(const fw_policy *p, fw_helm_ctx *ctx, const fw_target *tg, int n,
                              const fw_assessment *as, const fw_helm_result *res, bool *last,
                              fw_error *err)
{
    *last = false;
    if (!(p->def.standon_lookahead > 0.0) || res->side == FW_SIDE_NONE)
        return FW_OK;
    double h = fw_helm_value(ctx, res->side, fw_helm_count(ctx) - 1);
    for (int i = 0; i < n && !*last; i++) {
        if (!as[i].enters_domain || as[i].rule19 ||
            (as[i].situation != FW_SIT_STAND_ON && as[i].situation != FW_SIT_OVERTAKEN))
            continue;
        bool later;
        fw_status st = fw_helm_clears_after(ctx, &tg[i], 1, h, p->def.standon_lookahead, &later,
                                            err);
        if (st)
            return st;
        *last = !later;
    }
    return FW_OK;
}

/* Should a STANDBY (or STEADY) ship act now against the threats?  Sets *why,
 * and *least: the smallest helm the action may take (rad). */
static fw_status should_act(fw_policy *p, fw_helm_ctx *ctx, const fw_target *tg, int n,
                            const fw_assessment *as, int primary, const fw_helm_result *res,
                            bool *act, double *least, const char **why, fw_error *err)
{
    *act = false;
    *least = 0.0;
    /* in the middle of its own manoeuvre the own ship is no stand-on ship:
     * its turn may have put the target it gives way to on its port side */
    bool by_rule = false, fog = false;
    for (int i = 0; i < n; i++)
        if (as[i].enters_domain && gives_way(as[i].situation) && !as[i].rule19)
            by_rule = true;
        else if (as[i].enters_domain && as[i].rule19)
            fog = true; /* rule 19(d): out of sight there is no stand-on ship */
    bool give_way = by_rule || fog || p->mode == FW_MODE_STEADY;
    /* The reason names the ground, so that it agrees with the situation the
     * log shows beside it: a give-way ship (rules 14-16), or one still in its
     * own manoeuvre whose target now lies to port ("crossing stand-on"). */
    static const char *const rule_why[3] = {
        "give-way: range within the action distance",
        "give-way: waiting longer would need more than the minimum helm",
        "give-way: minimum helm still enough later, waiting"};
    static const char *const own_why[3] = {
        "own manoeuvre under way (not a stand-on ship): range within the action distance",
        "own manoeuvre under way (not a stand-on ship): waiting longer would need more than "
        "the minimum helm",
        "own manoeuvre under way (not a stand-on ship): minimum helm still enough later, "
        "waiting"};
    static const char *const fog_why[3] = {
        "rule 19, not in sight: range within the action distance",
        "rule 19, not in sight: waiting longer would need more than the minimum helm",
        "rule 19, not in sight: minimum helm still enough later, waiting"};
    const char *const *gw_why = by_rule ? rule_why : fog ? fog_why : own_why;
    const fw_assessment *a = &as[primary];
    if (!give_way) {
        bool last = false;
        fw_status st = standon_last(p, ctx, tg, n, as, res, &last, err);
        if (st)
            return st;
        if (a->range <= p->def.standon_act_range) {
            *act = true, *why = "stand-on: give-way ship has not acted, range below the stand-on limit";
        } else if (a->t_enter <= p->def.standon_act_time) {
            *act = true, *why = "stand-on: give-way ship has not acted, domain entry imminent";
        } else if (last) {
            *act = true;
            *why = "stand-on: give-way ship has not acted, the own ship alone must act now "
                   "(rule 17(b))";
        } else {
            *why = "stand-on: keeping course and speed (rule 17)";
        }
        /* rule 17(b): the action that best aids, not the least that clears */
        if (*act)
            *least = p->def.standon_min_helm;
        return FW_OK;
    }
    if (!res->feasible) {
        *act = true, *why = "no helm up to the maximum clears: best available action now";
        return FW_OK;
    }
    if (a->range <= p->def.act_range) {
        *act = true, *why = gw_why[0];
        return FW_OK;
    }
    if (p->def.act_lookahead > 0.0) {
        bool later;
        double h = fw_helm_value(ctx, res->side, 0);
        fw_status st = fw_helm_clears_after(ctx, tg, n, h, p->def.act_lookahead, &later, err);
        if (st)
            return st;
        if (!later) {
            *act = true, *why = gw_why[1];
            return FW_OK;
        }
    }
    *why = gw_why[2];
    return FW_OK;
}

/* Does the least helm candidate of at least `least` (rad) on side leave the
 * search's band (helm_search.h)? */
static fw_status least_leaves_band(fw_helm_ctx *ctx, int side, double least, bool *out,
                                   fw_error *err)
{
    int i = 0, nh = fw_helm_count(ctx);
    while (i + 1 < nh && fabs(fw_helm_value(ctx, side, i)) < least - 1e-12)
        i++;
    const fw_track *tr;
    fw_status st = fw_helm_track(ctx, side, i, &tr, err);
    if (!st)
        *out = fw_track_band_excess(&ctx->band, tr) > FW_BAND_SLACK_M;
    return st;
}

/* STANDBY and STEADY: act against the threats if the rules say so. */
fw_status fw_policy_maybe_act(fw_policy *p, fw_helm_ctx *ctx, double t, const fw_own_state *own,
                              const fw_target *tg, int n, const fw_assessment *as,
                              fw_decision *d, fw_error *err)
{
    bool act;
    double least;
    fw_status st = should_act(p, ctx, tg, n, as, d->primary, &d->search, &act, &least, &d->reason,
                              err);
    if (st || !act)
        return st;
    /* a stand-on ship's least helm (rule 17(b)) out of the band: none in it */
    bool out = false;
    if (ctx->band.on && !p->no_room && d->search.side != FW_SIDE_NONE &&
        least > fabs(d->search.helm) &&
        (st = least_leaves_band(ctx, d->search.side, least, &out, err)))
        return st;
    if (ctx->band.on && p->mode == FW_MODE_STEADY &&
        ((p->unkept && !d->search.feasible) ||
         (p->edge_side != FW_SIDE_NONE && d->search.side == p->edge_side))) {
        /* in a channel whose domain already cannot be kept, no helm clears;
         * or the helm is towards the edge the ship has just steadied at,
         * where holding any heading it turns to would leave the channel
         * (the search's candidate, slowed by its hard turn, only seems to
         * stay in): the least bad heading is held (step_steady), not the
         * helm taken afresh (it turned the ship for a step, then steadied it
         * at the channel's edge, by turns every 2 s) */
        p->unkept = true;
        d->reason = "steady: the domain cannot be kept within the route's channel: holding the "
                    "least bad heading";
        return FW_OK;
    }
    /* no helm on the permitted sides clears: within a route's band the
     * domain cannot be kept, and the least bad manoeuvre is taken (a heading
     * within the band and a speed, judged by how far out they keep the
     * targets: policy.h), not the best available helm, a turn held until
     * steadying clears, the band's edge or max_turn (in the strait study it
     * turned the own ship 160-170 deg across the lanes, to run along them
     * or against their traffic, and most of its collisions followed) */
    bool none_clears =
        p->def.tss && fw_band_active(p) && d->search.threat && !d->search.feasible;
    if (p->no_room || out || none_clears) {
        /* no permitted side has room within the route's band (policy.h):
         * the least bad heading within it (step_steady), slower */
        p->unkept = true;
        d->reason = none_clears && !p->no_room && !out
                        ? "no helm clears: the domain cannot be kept within the route's band: "
                          "the least bad heading and speed within it"
                        : "the domain cannot be kept within the route's band: the least bad "
                          "heading within it, reducing speed";
        p->psi_hold = own->psi;
        fw_policy_set_mode(p, FW_MODE_STEADY, t);
        return FW_OK;
    }
    if (d->search.side == FW_SIDE_NONE)
        return FW_OK;
    d->acted = true;
    p->t_blocked = -1.0;
    p->psi_act = own->psi;
    if (p->mode == FW_MODE_STANDBY && !p->course_set && p->def.ret == FW_RETURN_HEADING)
        p->psi_ref = own->psi;
    p->side = d->search.side;
    p->helm = copysign(fmax(fabs(d->search.helm), least), d->search.helm);
    p->primary = d->primary;
    snprintf(p->primary_id, sizeof p->primary_id, "%s", tg[d->primary].id);
    fw_policy_set_mode(p, FW_MODE_AVOID, t);
    return FW_OK;
}
