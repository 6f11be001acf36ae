/* policy_speed.c - the own ship's speed order (policy.h): slowed where the
 * domain cannot be kept, a route leg's speed, and rule 19(e)'s in restricted
 * visibility. */
#include <stdio.h>
#include <string.h>

#include "avoid/band.h"
#include "avoid/helm_ctx.h"
#include "avoid/encounter.h"
#include "avoid/policy_internal.h"
#include "core/units.h"

/* Rule 19(e) this step (policy.h): a target out of sight forward of the
 * beam, at risk (entering the domain), whose fog signal is heard (within its
 * whistle's range of audibility) or with which a close-quarters situation
 * cannot be avoided (the domain cannot be kept).  Its index, -1: none. */
static int rule19e_target(const fw_policy *p, const fw_policy_input *in)
{
    for (int i = 0; i < in->n; i++) {
        const fw_assessment *a = &in->as[i];
        double rb = a->rel_bearing;
        if (!a->rule19 || !a->enters_domain || (rb >= 0.5 * FW_PI && rb <= 1.5 * FW_PI))
            continue;
        if (p->unkept || a->range <= fw_fog_signal_range(in->targets[i].length))
            return i;
    }
    return -1;
}

/* Is the ship that called for rule 19(e) still coming (in view, its
 * closest approach ahead)?  Until it is past the danger is not over. */
static bool r19e_coming(const fw_policy *p, const fw_policy_input *in)
{
    for (int i = 0; i < in->n; i++)
        if (strcmp(in->targets[i].id, p->r19e_id) == 0)
            return in->as[i].tcpa > 0.0;
    return false;
}

/* Rule 19(e)'s speed held (p->r19e) from a step that finds it due until the
 * ship that called for it is past (or gone) and none has called for
 * min_avoid_time ("until danger of collision is over"). */
static void rule19e(fw_policy *p, const fw_policy_input *in, fw_decision *d)
{
    int i = rule19e_target(p, in);
    d->rule19e_target = i;
    if (i >= 0) {
        p->r19e = true;
        p->t_19e = -1.0;
        snprintf(p->r19e_id, sizeof p->r19e_id, "%s", in->targets[i].id);
    } else if (p->r19e && r19e_coming(p, in)) {
        p->t_19e = -1.0;
    } else if (p->r19e && p->t_19e < 0.0) {
        p->t_19e = in->t;
    }
    if (p->r19e && p->t_19e >= 0.0 && in->t - p->t_19e >= p->def.min_avoid_time)
        p->r19e = false;
}

/* The speed ordered: slowed while the domain cannot be kept (until keeping
 * the course lets no target in), else a steered route's leg's, or the
 * planned speed again after a slowing; in restricted visibility rule 19(e)'s
 * speed, the lowest. */
void fw_policy_order_speed(fw_policy *p, const fw_policy_input *in, fw_decision *d)
{
    const fw_route *r = &p->def.route;
    /* kept again once keeping the course has let no target in for
     * min_avoid_time (not at the first clear step: the verdict flickers) */
    if (!p->unkept || d->search.threat)
        p->t_kept = -1.0;
    else if (p->t_kept < 0.0)
        p->t_kept = in->t;
    if (p->unkept && p->t_kept >= 0.0 && in->t - p->t_kept >= p->def.min_avoid_time)
        p->unkept = p->lb_held = false;
    rule19e(p, in, d);
    if (p->r19e) /* below the planned speed, or the speed it goes at without a plan */
        p->speed_order = fw_rule19e_speed(&in->ctx->ship->nomoto,
                                          r->n > 0 ? r->leg[p->leg].speed : in->own->U);
    else if (p->unkept)
        p->speed_order = p->slow ? fw_band_slow(p, &in->ctx->ship->nomoto) : fw_band_planned(p);
    else if (r->steered || p->speed_order > 0.0)
        p->speed_order = r->leg[p->leg].speed;
    d->speed = p->speed_order;
    d->unkept = p->unkept;
    d->rule19e = p->r19e;
}
