/* band.c - the band about the route (band.h). */
#include "avoid/band.h"

#include "avoid/helm_ctx.h"

#include <math.h>

#include "core/units.h"
#include "nomoto/nomoto.h"

/* Clearance of steering heading psi with the policy's autopilot (policy.c's
 * steer, the same prediction), at the straight-course speed U0 (0: the
 * present one). */
static fw_status steer(const fw_policy *p, const fw_policy_input *in, double psi, double U0,
                       bool beyond, double *clearance, fw_error *err)
{
    fw_steer_def ap = {.psi_ref = psi, .kp = p->def.ap_kp, .kd = p->def.ap_kd,
                       .max_helm = p->def.ap_max_helm, .U0 = U0};
    return fw_helm_steer_clearance(in->ctx, in->targets, in->n, &ap, beyond, clearance, err);
}

bool fw_band_active(const fw_policy *p) { return p->def.band_xte > 0.0 && p->def.route.n > 0; }

void fw_band_track(fw_policy *p, const fw_own_state *own)
{
    p->dev += fw_wrap_pi(own->psi - p->psi_last);
    p->psi_last = own->psi;
}

void fw_band_leg(fw_policy *p, double c_old) { p->dev -= fw_wrap_pi(p->psi_ref - c_old); }

/* m across from the route's active leg, + to starboard (the policy's track) */
static double across(const fw_policy *p, const fw_own_state *own)
{
    const fw_route_leg *l = &p->def.route.leg[p->leg];
    return (own->east - l->east) * cos(l->course) - (own->north - l->north) * sin(l->course);
}

fw_helm_band fw_band_of(const fw_policy *p)
{
    if (!fw_band_active(p))
        return (fw_helm_band){.on = false};
    const fw_route_leg *l = &p->def.route.leg[p->leg];
    return (fw_helm_band){.on = l->room_starboard > 0.0 || l->room_port > 0.0,
                          .east = l->east, .north = l->north, .course = l->course,
                          .room_starboard = l->room_starboard, .room_port = l->room_port};
}

int fw_band_sides(const fw_policy *p, const fw_own_state *own)
{
    if (!fw_band_active(p))
        return FW_ALLOW_EITHER;
    double room = p->def.band_turn - p->def.min_alteration, x = across(p, own);
    int sides = 0;
    if (p->dev < room && x < p->def.band_xte)
        sides |= FW_ALLOW_STARBOARD;
    if (-p->dev < room && -x < p->def.band_xte)
        sides |= FW_ALLOW_PORT;
    return sides;
}

bool fw_band_edge(const fw_policy *p, const fw_own_state *own, int side)
{
    if (!fw_band_active(p) || side == FW_SIDE_NONE)
        return false;
    double s = side == FW_SIDE_STARBOARD ? 1.0 : -1.0;
    return s * p->dev >= p->def.band_turn || s * across(p, own) >= p->def.band_xte;
}

double fw_band_planned(const fw_policy *p)
{
    return p->def.route.n > 0 ? p->def.route.leg[p->leg].speed : 0.0;
}

double fw_band_slow(const fw_policy *p, const fw_nomoto_kb *kb)
{
    double planned = fw_band_planned(p);
    /* not below the knowledge base's fitted speeds: the helm search predicts
     * with it, and its regressions extrapolated to 5.4 kn gave c3-mmg an
     * unstable model (a Dover run at 1000 m domain failed so) */
    double floor = fw_kn_to_ms(kb->speed_min_kn);
    return fmax(p->def.slow_factor * planned, fmin(floor, planned));
}

double fw_rule19e_speed(const fw_nomoto_kb *kb, double planned)
{
    return fmin(fw_kn_to_ms(kb->speed_min_kn), planned);
}

/* STEADY at the route's band's edge: the heading held stays within band_turn
 * of the leg's course; once band_xte across, it becomes the leg's course if
 * that keeps every target out, else the heading is held and the domain
 * cannot be kept (turning back into the traffic would be worse). */
fw_status fw_band_hold(fw_policy *p, const fw_policy_input *in, fw_error *err)
{
    int side = p->dev > 0.0 ? FW_SIDE_STARBOARD : FW_SIDE_PORT;
    if (!fw_band_edge(p, in->own, side))
        return FW_OK;
    if (fabs(p->dev) >= p->def.band_turn) {
        p->psi_hold = fw_wrap_2pi(p->psi_ref + copysign(p->def.band_turn, p->dev));
        return FW_OK;
    }
    double cl;
    fw_status st = steer(p, in, p->psi_ref, 0.0, false, &cl, err);
    if (!st && cl >= 1.0)
        p->psi_hold = p->psi_ref;
    else if (!st)
        p->unkept = true;
    return st;
}

/* Normalised domain radius by which another least bad heading and speed must
 * keep the targets farther out than the ones in force to replace them.
 * Without it the choice was made afresh every step, and the rudder's and the
 * propeller's own response to the last order tipped it: in the strait study
 * (seed 1, run 61, 300 m) the ship was ordered 12 and 6 kn by turns every
 * second for minutes, between 55-70 deg at full speed and 355 deg slowed, so
 * it did neither (its speed stayed near 9.5 kn) and was run into.  The same
 * option's clearance moved by up to 0.075 from one step to the next there:
 * 0.1 is above that, and a small part of the domain. */
#define LEAST_BAD_KEEP 0.1

/* The domain cannot be kept: the least bad heading within the band, the one
 * of the leg's course +-15, 30 .. band_turn (none further out past
 * band_xte) whose steering keeps the targets farthest out (to the horizon
 * and beyond, the return's check), the nearest the course among equals;
 * and the speed, slowed or the planned one, that keeps them farther out on
 * it (slowed among equals). */
fw_status fw_band_least_bad(fw_policy *p, const fw_policy_input *in, fw_error *err)
{
    const double step = fw_deg_to_rad(15.0);
    /* in a channel (a band with edges) the heading parallel to them alone:
     * any other meets an edge within minutes, and steering it, steadying
     * back at the edge and steering it again swung the rudder every few
     * seconds (band.h) */
    int kmax = in->ctx->band.on ? 0 : (int)floor(p->def.band_turn / step + 1e-9);
    double best = -1.0, psi = p->psi_hold, held = -INFINITY;
    double speed[2] = {fw_band_slow(p, &in->ctx->ship->nomoto), fw_band_planned(p)};
    bool slow = true;
    int best_k = 0;
    for (int m = 0; m <= 2 * kmax; m++) {
        int k = (m + 1) / 2 * (m % 2 ? 1 : -1); /* 0, 1, -1, 2, -2 ... */
        if (k != 0 && fw_band_edge(p, in->own, k > 0 ? FW_SIDE_STARBOARD : FW_SIDE_PORT) &&
            fabs(fw_wrap_pi(p->psi_ref + k * step - in->own->psi)) > 0.5 * step &&
            k * fw_wrap_pi(p->psi_ref + k * step - in->own->psi) > 0.0)
            continue; /* at that side's edge: no heading further out */
        for (int s = 0; s < (speed[1] > speed[0] ? 2 : 1); s++) {
            double cl;
            fw_status st = steer(p, in, p->psi_ref + k * step, speed[s], true, &cl, err);
            if (st)
                return st;
            if (cl > best + 0.02)
                best = cl, psi = p->psi_ref + k * step, slow = s == 0, best_k = k;
            if (p->lb_held && k == p->lb_k && (s == 0) == p->slow)
                held = cl;
        }
    }
    if (best < held + LEAST_BAD_KEEP) /* the manoeuvre in force, kept */
        best_k = p->lb_k, psi = p->psi_ref + p->lb_k * step, slow = p->slow;
    p->lb_k = best_k;
    p->lb_held = true;
    p->psi_hold = fw_wrap_2pi(psi);
    p->slow = slow;
    return FW_OK;
}

int fw_band_overtaking_sides(const fw_policy *p, const fw_policy_input *in)
{
    int sides = FW_ALLOW_EITHER;
    if (!in->ctx->band.on)
        return sides;
    const fw_route *r = &p->def.route;
    double own_x = fw_route_cross(r, p->leg, in->own->east, in->own->north);
    for (int i = 0; i < in->n; i++)
        if (in->as[i].situation == FW_SIT_OVERTAKING && in->as[i].enters_domain)
            sides &= fw_route_cross(r, p->leg, in->targets[i].east, in->targets[i].north) < own_x
                         ? FW_ALLOW_STARBOARD
                         : FW_ALLOW_PORT;
    return sides;
}
