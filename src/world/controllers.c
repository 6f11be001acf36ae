/* controllers.c - the policy and manoeuvre controllers (controllers.h). */
#include "world/controllers.h"

#include <math.h>
#include <stdlib.h>

void fw_controller_destroy(fw_controller *c)
{
    if (c)
        c->ops->destroy(c);
}

/* ---- policy ---- */

typedef struct policy_ctl {
    fw_controller base;
    fw_helm_def helm;
    fw_policy pol;
    fw_helm_ctx *ctx;
} policy_ctl;

static fw_status policy_decide(fw_controller *c, const fw_sense *in, fw_decision *d,
                               fw_error *err)
{
    policy_ctl *p = (policy_ctl *)c;
    fw_policy_input pi = {.ctx = p->ctx, .helm = &p->helm, .t = in->t, .own = in->own,
                          .targets = in->targets, .n = in->n, .as = in->as, .order = in->order,
                          .lanes = in->lanes};
    return fw_policy_step(&p->pol, &pi, d, err);
}

static void policy_destroy(fw_controller *c)
{
    policy_ctl *p = (policy_ctl *)c;
    fw_helm_ctx_destroy(p->ctx);
    free(p);
}

static const fw_controller_ops policy_ops = {.name = "policy", .decide = policy_decide,
                                             .assesses = true, .destroy = policy_destroy};

fw_status fw_policy_controller_create(const fw_policy_controller_def *def,
                                      fw_controller **out, fw_error *err)
{
    *out = NULL;
    policy_ctl *p = calloc(1, sizeof *p);
    if (!p)
        return fw_fail(err, FW_ERUN, "out of memory");
    p->base.ops = &policy_ops;
    p->helm = def->helm;
    fw_policy_init(&p->pol, &def->policy);
    fw_status st = fw_helm_ctx_create(def->ship, &p->helm, &p->ctx, err);
    if (st) {
        free(p);
        return st;
    }
    *out = &p->base;
    return FW_OK;
}

const fw_policy *fw_policy_controller_policy(const fw_controller *c)
{
    return c && c->ops == &policy_ops ? &((const policy_ctl *)c)->pol : NULL;
}

/* ---- manoeuvre ---- */

typedef struct manoeuvre_ctl {
    fw_controller base;
    fw_manoeuvre_def def;
    bool turning, steady;
    double psi_hold;
} manoeuvre_ctl;

static fw_status manoeuvre_decide(fw_controller *c, const fw_sense *in, fw_decision *d,
                                  fw_error *err)
{
    (void)err;
    manoeuvre_ctl *m = (manoeuvre_ctl *)c;
    const fw_manoeuvre_def *md = &m->def;
    double order = 0.0;
    if (!m->steady && in->t >= md->t_act) {
        m->turning = true;
        if (fabs(in->own->psi - md->course) >= md->alteration) {
            m->steady = true;
            m->psi_hold = md->course + copysign(md->alteration, md->helm);
        }
    }
    if (m->turning && !m->steady) {
        order = md->helm;
    } else if (m->steady && md->alteration > 0.0) {
        /* hold the new heading: PD, 1 deg/deg, 20 s */
        double h = fabs(md->helm);
        order = fmax(-h, fmin(h, -(in->own->psi - m->psi_hold) - 20.0 * in->own->r));
    }
    *d = (fw_decision){.mode = m->turning && !m->steady ? FW_MODE_AVOID : FW_MODE_STANDBY,
                       .helm = order, .reason = "fixed manoeuvre", .primary = -1};
    return FW_OK;
}

static void manoeuvre_destroy(fw_controller *c) { free(c); }

static const fw_controller_ops manoeuvre_ops = {.name = "manoeuvre", .decide = manoeuvre_decide,
                                                .assesses = false,
                                                .destroy = manoeuvre_destroy};

fw_status fw_manoeuvre_controller_create(const fw_manoeuvre_def *def, fw_controller **out,
                                         fw_error *err)
{
    *out = NULL;
    if (!(def->alteration >= 0.0) || !isfinite(def->helm) || !(def->t_act >= 0.0))
        return fw_fail(err, FW_EINPUT, "manoeuvre: need alteration >= 0, t_act >= 0, a finite helm");
    manoeuvre_ctl *m = calloc(1, sizeof *m);
    if (!m)
        return fw_fail(err, FW_ERUN, "out of memory");
    m->base.ops = &manoeuvre_ops;
    m->def = *def;
    m->steady = def->alteration <= 0.0;
    *out = &m->base;
    return FW_OK;
}
