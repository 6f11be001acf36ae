/* policy_internal.h - what policy.c shares with policy_act.c and
 * policy_speed.c, the parts of the own ship's policy (policy.h). */
#ifndef FW_POLICY_INTERNAL_H
#define FW_POLICY_INTERNAL_H

#include "avoid/policy.h"

static inline void fw_policy_set_mode(fw_policy *p, fw_policy_mode m, double t)
{
    p->mode = m;
    p->t_mode = t;
}

/* STANDBY and STEADY: act against the threats if the rules say so
 * (policy_act.c). */
fw_status fw_policy_maybe_act(fw_policy *p, fw_helm_ctx *ctx, double t, const fw_own_state *own,
                              const fw_target *tg, int n, const fw_assessment *as,
                              fw_decision *d, fw_error *err);

/* The speed ordered this step, rule 19(e) included (policy_speed.c). */
void fw_policy_order_speed(fw_policy *p, const fw_policy_input *in, fw_decision *d);

#endif
