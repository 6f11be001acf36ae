/* steer.c - a background ship that alters course (steer.h). */
#include "world/steer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"

/* knots per m/s in the knowledge base's terms (its U is in knots) */
static const double kKnot = FW_KNOT;

void fw_steer_ship(double length, double breadth, const char *type, fw_ship *out)
{
    *out = (fw_ship){0};
    snprintf(out->name, sizeof out->name, "%s", type ? type : "background");
    snprintf(out->file, sizeof out->file, "%s", "(world/steer.h: a C-3 of its length)");
    out->L = out->Loa = length;
    out->B = breadth;
    out->rho = 1025.0;
    out->rudder_max = fw_deg_to_rad(35.0);
    out->rudder_rate = fw_deg_to_rad(35.0 + 30.0) / 28.0;
    fw_nomoto_kb *kb = &out->nomoto;
    kb->present = true;
    /* K = K' U / L (U in knots: U kKnot m/s), T1 = T' L / U; T2 = T3 cancel */
    kb->K = (fw_nomoto_index){.n = 1, .basis = {FW_NB_U}, .coef = {FW_STEER_K_ND * kKnot / length}};
    kb->T1 = (fw_nomoto_index){.n = 1, .basis = {FW_NB_INV_U},
                               .coef = {FW_STEER_T_ND * length / kKnot}};
    kb->T2 = kb->T3 = (fw_nomoto_index){.n = 1, .basis = {FW_NB_ONE}, .coef = {1.0}};
    /* the forms are exact in U: any speed a ship sails */
    kb->speed_min_kn = 0.5, kb->speed_max_kn = 40.0;
    kb->rudder_min_deg = 1.0, kb->rudder_max_deg = 35.0;
}

fw_alter_def fw_default_alter_def(void)
{
    return (fw_alter_def){.alteration = fw_deg_to_rad(30.0), .cpa = 0.5 * FW_NMILE,
                          .room = INFINITY, .length = 100.0, .helm_max = fw_deg_to_rad(20.0)};
}

void fw_lane_where(const fw_lane_info *lane, double e, double n, double *course, double *xtrack,
                   int *seg)
{
    double best = INFINITY;
    *course = 0.0, *xtrack = 0.0, *seg = 0;
    for (int i = 0; i + 1 < lane->np; i++) {
        double ax = lane->e[i], ay = lane->n[i];
        double dx = lane->e[i + 1] - ax, dy = lane->n[i + 1] - ay, l2 = dx * dx + dy * dy;
        if (!(l2 > 0.0))
            continue;
        double s = ((e - ax) * dx + (n - ay) * dy) / l2;
        /* the last segment goes on beyond its end, the first before its start */
        double sc = s < 0.0 && i > 0 ? 0.0 : s > 1.0 && i + 2 < lane->np ? 1.0 : s;
        double px = ax + sc * dx - e, py = ay + sc * dy - n, d2 = px * px + py * py;
        if (d2 < best) {
            double l = sqrt(l2);
            best = d2;
            *course = atan2(dx, dy);
            /* to starboard of the line: the cross product's sign */
            *xtrack = ((e - ax) * dy - (n - ay) * dx) / l;
            *seg = i;
        }
    }
}

/* s: how far ahead a ship coming back to its lane looks for ships in its way */
static const double kConflictS = 600.0;

typedef struct steer_ctl {
    fw_controller base;
    fw_alter_def def;
    fw_steer_phase phase;
} steer_ctl;

/* The heading that makes good course chi over ground at speed U in the
 * current (ce, cn) the ship knows. */
static double heading_for(double chi, double U, double ce, double cn)
{
    double across = ce * cos(chi) - cn * sin(chi); /* to starboard of chi */
    double s = U > 0.1 ? across / U : 0.0;
    return chi - asin(fmax(-0.9, fmin(0.9, s)));
}

/* The helm for heading psi_d: proportional, the gain T / (K tau^2) with tau
 * = L / U (critically damped with the model's T = T' L / U), limited. */
static double helm_for(const steer_ctl *c, const fw_own_state *o, double psi_d)
{
    double gain = FW_STEER_T_ND / FW_STEER_K_ND;
    double h = gain * fw_wrap_pi(psi_d - o->psi);
    return fmax(-c->def.helm_max, fmin(c->def.helm_max, h));
}

/* Is the ship it gives way to past and clear, should it steer chi now? */
static bool past_and_clear(const steer_ctl *c, const fw_sense *in, double chi)
{
    const fw_own_state *o = in->own;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        if (strcmp(t->id, c->def.other) != 0)
            continue;
        double oe, on, te, tn, tc, dc;
        /* over ground, as the target's course and speed are */
        fw_velocity(o->U, o->psi, &oe, &on);
        oe += o->cur_e, on += o->cur_n;
        fw_velocity(t->speed, t->course, &te, &tn);
        double dx = t->east - o->east, dy = t->north - o->north;
        if (dx * (te - oe) + dy * (tn - on) < 0.0)
            return false; /* still closing */
        fw_velocity(o->U, chi, &oe, &on);
        oe += o->cur_e, on += o->cur_n;
        fw_cpa(dx, dy, te - oe, tn - on, &tc, &dc);
        return tc <= 0.0 || dc >= c->def.cpa;
    }
    return true; /* out of sight: past */
}

/* Would course chi over ground bring it within half the passing distance of
 * a ship it sees, in the next 10 minutes (constant velocities)? */
static bool conflicts(const steer_ctl *c, const fw_sense *in, double chi)
{
    const fw_own_state *o = in->own;
    double oe, on, lim = 0.5 * c->def.cpa;
    fw_velocity(o->U, chi, &oe, &on);
    oe += o->cur_e, on += o->cur_n;
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double te, tn, tc, dc;
        fw_velocity(t->speed, t->course, &te, &tn);
        fw_cpa(t->east - o->east, t->north - o->north, te - oe, tn - on, &tc, &dc);
        if (tc > 0.0 && tc < kConflictS && dc < lim)
            return true;
    }
    return false;
}

/* The course over ground to a line `offset` m to starboard of the lane's
 * (line-of-sight), never more than the alteration off the line's course. */
static double los_course(const steer_ctl *c, double course, double xtrack, double offset)
{
    double look = fmax(4.0 * c->def.length, 400.0);
    double off = atan2(-(xtrack - offset), look);
    double lim = c->def.alteration;
    return course + fmax(-lim, fmin(lim, off));
}

static fw_status steer_decide(fw_controller *ctl, const fw_sense *in, fw_decision *d,
                              fw_error *err)
{
    (void)err;
    steer_ctl *c = (steer_ctl *)ctl;
    const fw_own_state *o = in->own;
    double course, xt;
    int seg;
    fw_lane_where(&c->def.lane, o->east, o->north, &course, &xt, &seg);
    double back = los_course(c, course, xt, 0.0);
    if (c->phase == FW_STEER_ALTER && past_and_clear(c, in, back))
        c->phase = FW_STEER_RETURN;
    if (c->phase == FW_STEER_RETURN) {
        double bc, bxt;
        double half = 0.5 * c->def.length;
        fw_lane_where(&c->def.lane, o->east + half * sin(o->psi), o->north + half * cos(o->psi),
                      &bc, &bxt, &seg);
        if (fabs(xt) < 0.3 && fabs(bxt) < 0.3 && fabs(o->r) < fw_deg_to_rad(0.05))
            c->phase = FW_STEER_DONE;
    }
    /* altered: the alteration, or along the edge of its room once there */
    double chi = c->phase != FW_STEER_ALTER ? back
                 : isfinite(c->def.room)    ? fmin(course + c->def.alteration,
                                                   los_course(c, course, xt, c->def.room))
                                            : course + c->def.alteration;
    /* coming back across ships in its way (a ship of its lane, another
     * coming back): along its lane where it is until they are by */
    if (c->phase == FW_STEER_RETURN && conflicts(c, in, chi) && !conflicts(c, in, course))
        chi = course;
    double psi_d = heading_for(chi, o->U, o->cur_e, o->cur_n);
    *d = (fw_decision){.mode = c->phase == FW_STEER_ALTER ? FW_MODE_AVOID : FW_MODE_AUTOPILOT,
                       .helm = helm_for(c, o, psi_d), .primary = -1,
                       .reason = c->phase == FW_STEER_ALTER    ? "gives way: course altered"
                                 : c->phase == FW_STEER_RETURN ? "back to its lane"
                                                               : "on its lane: to be given back"};
    return FW_OK;
}

static void steer_destroy(fw_controller *c) { free(c); }

static const fw_controller_ops steer_ops = {.name = "steer", .decide = steer_decide,
                                            .assesses = false, .destroy = steer_destroy};

fw_status fw_steer_controller_create(const fw_alter_def *def, fw_controller **out, fw_error *err)
{
    *out = NULL;
    if (def->lane.np < 2 || def->lane.np > FW_LANE_POINTS ||
        !(def->alteration > 0.0 && def->alteration < 0.5 * FW_PI) || !(def->cpa > 0.0) ||
        !(def->room >= 0.0) ||
        !(def->length > 0.0) || !(def->helm_max > 0.0))
        return fw_fail(err, FW_EINPUT, "steer: a lane of 2 or more points, an alteration "
                                       "between 0 and 90 deg, cpa, length and helm positive, room >= 0");
    steer_ctl *c = calloc(1, sizeof *c);
    if (!c)
        return fw_fail(err, FW_ERUN, "out of memory");
    c->base.ops = &steer_ops;
    c->def = *def;
    c->phase = FW_STEER_ALTER;
    *out = &c->base;
    return FW_OK;
}

bool fw_steer_controller_is(const fw_controller *c) { return c && c->ops == &steer_ops; }

fw_steer_phase fw_steer_controller_phase(const fw_controller *c)
{
    return ((const steer_ctl *)c)->phase;
}
