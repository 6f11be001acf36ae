/* wheel_over.c - the wheel-over point of a route's next leg (wheel_over.h). */
#include "avoid/wheel_over.h"

#include <math.h>

#include "core/units.h"

fw_status fw_wheel_over(fw_helm_ctx *ctx, const fw_route *r, int k, const fw_steer_def *ap,
                        double *d, fw_error *err)
{
    *d = 0.0;
    if (k + 1 >= r->n)
        return FW_OK;
    double c1 = r->leg[k].course, c2 = r->leg[k + 1].course, s12 = sin(c1 - c2);
    if (fabs(s12) < 1e-6 && cos(c1 - c2) > 0.0)
        return FW_OK; /* no turn */
    double U = fmax(r->leg[k].speed, 0.5);
    fw_own_state s = {.psi = c1, .U = U, .U0 = U};
    fw_steer_def turn = *ap;
    turn.psi_ref = c1 + fw_wrap_pi(c2 - c1);
    fw_track *tr = &ctx->tracks[2 * ctx->nh + 1];
    fw_status st = fw_track_predict_steer(ctx->ship, &ctx->def.track, &s, &turn, tr, err);
    if (st)
        return st;
    /* the origin's distance to starboard of the settled line (through the
     * last sample on c2), and of the line through the waypoint d ahead:
     * -d sin(c1 - c2); a turn of 180 deg or more has no such point: the
     * whole leg's length is left for it */
    double pe = tr->east[tr->n - 1], pn = tr->north[tr->n - 1];
    double x0 = -pe * cos(c2) + pn * sin(c2);
    double wo = fabs(s12) < 1e-6 ? r->leg[k].length : -x0 / s12;
    *d = fmax(0.0, fmin(r->leg[k].length, wo));
    return FW_OK;
}
