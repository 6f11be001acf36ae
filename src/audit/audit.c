/* audit.c - the COLREGs audit of an own-ship encounter (see audit.h). */
#include "audit/audit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "avoid/helm_search.h"
#include "core/units.h"

fw_audit_def fw_default_audit_def(void)
{
    fw_audit_def d = {.risk_dcpa = 926.0,
                      .risk_tcpa = 1200.0,
                      .course_change = fw_deg_to_rad(30.0),
                      .speed_change = 0.25,
                      .early_tcpa = 480.0,
                      .prompt = 60.0,
                      .may_tcpa = 600.0,
                      .must_tcpa = 240.0};
    return d;
}

static const char *const kWaterways[] = {"open-sea", "tss", "channel"};

const char *fw_waterway_name(fw_waterway w)
{
    return kWaterways[w];
}

int fw_waterway_parse(const char *name, fw_waterway *w)
{
    for (int i = 0; i < 3; i++)
        if (strcmp(name, kWaterways[i]) == 0) {
            *w = (fw_waterway)i;
            return 0;
        }
    return -1;
}

fw_audit_def fw_audit_def_for(fw_waterway w, double own_length)
{
    fw_audit_def d = fw_default_audit_def();
    if (w == FW_WATERWAY_TSS)
        d.risk_dcpa = 1.6 * own_length; /* Fujii and Tanaka (1971), coastal: audit.h */
    else if (w == FW_WATERWAY_CHANNEL)
        d.risk_dcpa = 0.8 * own_length; /* ... harbours and narrow waters */
    return d;
}

fw_status fw_audit_check(const fw_audit_def *d, char *field, size_t fieldsz, fw_error *err)
{
    const char *f = NULL, *why = NULL;
    if (!(d->risk_dcpa > 0.0 && d->risk_dcpa <= 20000.0))
        f = "risk_dcpa_m", why = "give (0, 20000] m";
    else if (!(d->risk_tcpa > 0.0 && d->risk_tcpa <= 7200.0))
        f = "risk_tcpa_s", why = "give (0, 7200] s";
    else if (!(d->course_change > 0.0 && d->course_change <= M_PI))
        f = "course_change_deg", why = "give (0, 180] deg";
    else if (!(d->speed_change > 0.0 && d->speed_change <= 1.0))
        f = "speed_change", why = "give a fraction in (0, 1]";
    else if (!(d->early_tcpa >= 0.0 && d->early_tcpa < d->risk_tcpa))
        f = "early_tcpa_s", why = "give [0, risk_tcpa_s)";
    else if (!(d->prompt >= 0.0 && d->prompt <= 600.0))
        f = "prompt_s", why = "give [0, 600] s";
    else if (!(d->must_tcpa >= 0.0 && d->must_tcpa < d->may_tcpa && d->may_tcpa <= d->risk_tcpa))
        f = "rule17_may_tcpa_s",
        why = "give 0 <= rule17_must_tcpa_s < rule17_may_tcpa_s <= risk_tcpa_s";
    if (!f)
        return FW_OK;
    snprintf(field, fieldsz, "%s", f);
    return fw_fail(err, FW_EINPUT, "%s: %s", f, why);
}

void fw_audit_obs_init(fw_audit_obs *o)
{
    memset(o, 0, sizeof *o);
    o->t_risk = o->tcpa_risk = o->tcpa_act = NAN;
}

void fw_audit_observe(fw_audit_obs *o, const fw_audit_def *d, double t, double dcpa, double tcpa)
{
    bool close = dcpa < d->risk_dcpa && tcpa > 0.0;
    if (!o->risk && close && tcpa < d->risk_tcpa) {
        o->risk = true;
        o->t_risk = t;
        o->tcpa_risk = tcpa;
    }
    if (!o->must_seen && tcpa > 0.0 && tcpa <= d->must_tcpa && o->risk) {
        o->must_seen = true;
        o->risk_at_must = close;
    }
}

const char *fw_audit_role_name(fw_audit_role r)
{
    return r == FW_ROLE_GIVE_WAY ? "give-way" : "stand-on";
}

/* Largest heading change and speed reduction from t_act to t_cpa. */
static void manoeuvre(const fw_audit_history *h, double t_act, double t_cpa, double *course,
                      double *speed)
{
    *course = 0.0;
    *speed = 0.0;
    int i0 = 0;
    while (i0 < h->n && h->t[i0] < t_act)
        i0++;
    if (i0 >= h->n)
        return;
    double psi0 = h->psi[i0], v0 = h->speed[i0];
    for (int i = i0; i < h->n && h->t[i] <= t_cpa; i++) {
        double dpsi = remainder(h->psi[i] - psi0, 2.0 * M_PI);
        *course = fmax(*course, fabs(dpsi));
        if (v0 > 0.0)
            *speed = fmax(*speed, 1.0 - h->speed[i] / v0);
    }
}

static void verdict(fw_audit_result *r, bool ok, const char *note)
{
    r->compliant = ok;
    snprintf(r->note, sizeof r->note, "%s", ok ? "" : note);
}

static void give_way(const fw_audit_def *d, fw_situation sit, const fw_audit_obs *o, int side,
                     double t_act, fw_audit_result *r)
{
    if (!r->acted) {
        /* the risk lasted to the last minutes and nothing was done: rule 16 */
        verdict(r, !o->risk_at_must, "no action");
        return;
    }
    r->early = r->tcpa_act >= d->early_tcpa || t_act - o->t_risk <= d->prompt;
    r->substantial = r->course_change >= d->course_change || r->speed_change >= d->speed_change;
    /* head-on: each alters to starboard (14(a)); crossing: not across the
     * other's bow (15), which a starboard turn or slowing down keeps */
    bool ok_side = side == FW_SIDE_STARBOARD ||
                   (sit == FW_SIT_GIVE_WAY && r->speed_change >= d->speed_change);
    if ((sit == FW_SIT_HEAD_ON || sit == FW_SIT_GIVE_WAY) && !ok_side)
        verdict(r, false, sit == FW_SIT_HEAD_ON ? "to port (rule 14)" : "to port (rule 15)");
    else if (!r->early)
        verdict(r, false, "late (rules 8, 16)");
    else if (!r->substantial)
        verdict(r, false, "not substantial (rule 8)");
    else
        verdict(r, true, "");
}

static void stand_on(const fw_audit_def *d, fw_situation sit, const fw_audit_obs *o, int side,
                     fw_audit_result *r)
{
    if (!r->acted) {
        verdict(r, !o->risk_at_must, "no action in phase 3 (rule 17(b))");
        return;
    }
    r->phase = r->tcpa_act > d->may_tcpa ? 1 : r->tcpa_act > d->must_tcpa ? 2 : 3;
    if (r->phase == 1)
        verdict(r, false, "acted in phase 1 (rule 17(a)(i))");
    else if (sit == FW_SIT_STAND_ON && side == FW_SIDE_PORT)
        verdict(r, false, "to port (rule 17(c))");
    else
        verdict(r, true, "");
}

void fw_audit_evaluate(const fw_audit_def *d, fw_situation situation, const fw_audit_obs *o,
                       bool acted, double t_act, int side, double t_cpa,
                       const fw_audit_history *h, fw_audit_result *out)
{
    memset(out, 0, sizeof *out);
    static const int rule[] = {[FW_SIT_HEAD_ON] = 14, [FW_SIT_OVERTAKING] = 13,
                               [FW_SIT_OVERTAKEN] = 13, [FW_SIT_GIVE_WAY] = 15,
                               [FW_SIT_STAND_ON] = 15};
    out->rule = rule[situation];
    out->role = situation == FW_SIT_OVERTAKEN || situation == FW_SIT_STAND_ON ? FW_ROLE_STAND_ON
                                                                              : FW_ROLE_GIVE_WAY;
    out->risk = o->risk;
    out->t_risk = o->t_risk;
    out->tcpa_risk = o->tcpa_risk;
    out->acted = acted;
    out->tcpa_act = acted ? o->tcpa_act : NAN;
    if (acted)
        manoeuvre(h, t_act, t_cpa, &out->course_change, &out->speed_change);
    if (!o->risk) {
        out->compliant = -1; /* no risk of collision: the rules ask nothing */
        snprintf(out->note, sizeof out->note, "no risk");
        return;
    }
    if (out->role == FW_ROLE_GIVE_WAY)
        give_way(d, situation, o, side, t_act, out);
    else
        stand_on(d, situation, o, side, out);
}

void fw_audit_evaluate_rule19(const fw_audit_def *d, const fw_audit_obs *o, bool acted,
                              double t_act, bool side_ok, double t_cpa,
                              const fw_audit_history *h, fw_audit_result *out)
{
    /* a give-way ship's reading (early, substantial), the side judged here */
    fw_audit_evaluate(d, FW_SIT_GIVE_WAY, o, acted, t_act, FW_SIDE_STARBOARD, t_cpa, h, out);
    out->rule = 19;
    if (out->compliant < 0)
        return;
    if (acted && !side_ok)
        verdict(out, false, "to port or towards it (rule 19(d))");
    else if (!acted && !out->compliant)
        verdict(out, false, "no action (rule 19(d))");
    else if (!out->compliant && !out->early)
        verdict(out, false, "late (rule 19(d): in ample time)");
}
