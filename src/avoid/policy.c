#include "avoid/policy.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "core/units.h"

fw_policy_def fw_default_policy_def(void)
{
    return (fw_policy_def){.act_range = FW_NMILE,
                           .act_lookahead = 10.0,
                           .standon_act_range = 0.5 * FW_NMILE,
                           .standon_act_time = 120.0,
                           .ap_kp = 1.0,
                           .ap_kd = 20.0,
                           .ap_max_helm = fw_deg_to_rad(20.0),
                           .ap_done_heading = fw_deg_to_rad(1.0),
                           .ap_done_rate = fw_deg_to_rad(0.005)};
}

const char *fw_policy_mode_name(fw_policy_mode m)
{
    switch (m) {
    case FW_MODE_STANDBY: return "standby";
    case FW_MODE_AVOID: return "avoid";
    case FW_MODE_COUNTER: return "counter";
    case FW_MODE_AUTOPILOT: return "autopilot";
    }
    return "?";
}

void fw_policy_init(fw_policy *p, const fw_policy_def *def)
{
    p->def = *def;
    p->mode = FW_MODE_STANDBY;
    p->psi_ref = 0.0;
    p->side = FW_SIDE_NONE;
    p->helm = 0.0;
    p->primary = -1;
    p->primary_id[0] = '\0';
    p->t_mode = 0.0;
    p->course_set = false;
}

static void set_mode(fw_policy *p, fw_policy_mode m, double t)
{
    p->mode = m;
    p->t_mode = t;
}

static bool gives_way(fw_situation s)
{
    return s == FW_SIT_HEAD_ON || s == FW_SIT_GIVE_WAY || s == FW_SIT_OVERTAKING;
}

/* Should a STANDBY ship act now against the threats?  Sets *why. */
static fw_status should_act(fw_policy *p, fw_helm_ctx *ctx, const fw_target *tg, int n,
                            const fw_assessment *as, int primary, const fw_helm_result *res,
                            bool *act, const char **why, fw_error *err)
{
    *act = false;
    bool give_way = false;
    for (int i = 0; i < n; i++)
        if (as[i].enters_domain && gives_way(as[i].situation))
            give_way = true;
    const fw_assessment *a = &as[primary];
    if (!give_way) {
        if (a->range <= p->def.standon_act_range) {
            *act = true, *why = "stand-on: give-way ship has not acted, range below the stand-on limit";
        } else if (a->t_enter <= p->def.standon_act_time) {
            *act = true, *why = "stand-on: give-way ship has not acted, domain entry imminent";
        } else {
            *why = "stand-on: keeping course and speed (rule 17)";
        }
        return FW_OK;
    }
    if (!res->feasible) {
        *act = true, *why = "no helm up to the maximum clears: best available action now";
        return FW_OK;
    }
    if (a->range <= p->def.act_range) {
        *act = true, *why = "give-way: range within the action distance";
        return FW_OK;
    }
    if (p->def.act_lookahead > 0.0) {
        bool later;
        double h = fw_helm_value(ctx, res->side, 0);
        fw_status st = fw_helm_clears_after(ctx, tg, n, h, p->def.act_lookahead, &later, err);
        if (st)
            return st;
        if (!later) {
            *act = true, *why = "give-way: waiting longer would need more than the minimum helm";
            return FW_OK;
        }
    }
    *why = "give-way: minimum helm still enough later, waiting";
    return FW_OK;
}

fw_status fw_policy_step(fw_policy *p, fw_helm_ctx *ctx, const fw_helm_def *hdef, double t,
                         const fw_own_state *own, const fw_target *tg, int n,
                         fw_assessment *as, int *order, fw_decision *d, fw_error *err)
{
    fw_assess(&hdef->colregs, &hdef->domain, hdef->track.horizon, own, tg, n, as, order);
    fw_helm_begin(ctx, own);
    int allowed = fw_permitted_sides(hdef, as, n);
    fw_status st = fw_helm_search(ctx, tg, n, allowed, &d->search, err);
    if (st)
        return st;
    const fw_helm_result *res = &d->search;
    d->primary = n > 0 ? order[0] : -1;
    d->acted = false;
    d->reason = "";
    double err_psi = fw_wrap_pi(own->psi - p->psi_ref);

    /* a threat while returning: back to avoiding if it is close */
    if ((p->mode == FW_MODE_COUNTER || p->mode == FW_MODE_AUTOPILOT) && res->threat &&
        d->primary >= 0 && as[d->primary].range <= p->def.act_range) {
        set_mode(p, FW_MODE_STANDBY, t);
    }
    switch (p->mode) {
    case FW_MODE_STANDBY: {
        p->helm = 0.0;
        if (p->course_set) {
            /* after a return the autopilot keeps the course: with the rudder
             * amidships the residual yaw would drift about r (T1 + T2) */
            double h = -p->def.ap_kp * err_psi - p->def.ap_kd * own->r;
            p->helm = fmax(-p->def.ap_max_helm, fmin(p->def.ap_max_helm, h));
        }
        if (!res->threat) {
            d->reason = p->course_set ? "no target enters the domain: keeping the course"
                                      : "no target enters the domain on the present course";
            break;
        }
        bool act;
        if ((st = should_act(p, ctx, tg, n, as, d->primary, res, &act, &d->reason, err)))
            return st;
        if (act) {
            d->acted = true;
            if (p->side == FW_SIDE_NONE && !p->course_set)
                p->psi_ref = own->psi;
            p->side = res->side;
            p->helm = res->helm;
            p->primary = d->primary;
            snprintf(p->primary_id, sizeof p->primary_id, "%s", tg[d->primary].id);
            set_mode(p, FW_MODE_AVOID, t);
        }
        break;
    }
    case FW_MODE_AVOID: {
        int k = p->primary_id[0] ? fw_target_find(tg, n, p->primary_id)
                                 : (p->primary < n ? p->primary : -1);
        const fw_assessment *a = k >= 0 ? &as[k] : NULL;
        bool passed = !a || a->tcpa < 0.0;
        if (!res->threat && passed) {
            d->reason = "domain clear and target passing: opposite helm to return";
            p->helm = -p->helm;
            set_mode(p, FW_MODE_COUNTER, t);
        } else {
            d->reason = "avoiding: holding the helm";
            if (res->side == p->side && fabs(res->helm) > fabs(p->helm)) {
                p->helm = res->helm;
                d->reason = "avoiding: the search asks for more helm";
            }
        }
        break;
    }
    case FW_MODE_COUNTER:
        d->reason = "returning: opposite helm";
        /* the yaw rate has reversed, or the course is already regained */
        if (own->r * p->side <= 0.0 || err_psi * p->side <= 0.0) {
            set_mode(p, FW_MODE_AUTOPILOT, t);
        } else {
            break;
        }
        /* fall through */
    case FW_MODE_AUTOPILOT: {
        d->reason = "returning: heading autopilot";
        double h = -p->def.ap_kp * err_psi - p->def.ap_kd * own->r;
        h = fmax(-p->def.ap_max_helm, fmin(p->def.ap_max_helm, h));
        p->helm = h;
        if (fabs(err_psi) < p->def.ap_done_heading && fabs(own->r) < p->def.ap_done_rate) {
            d->reason = "back on the original course";
            p->side = FW_SIDE_NONE;
            p->course_set = true;
            set_mode(p, FW_MODE_STANDBY, t);
        }
        break;
    }
    }
    d->mode = p->mode;
    d->helm = p->helm;
    return FW_OK;
}
