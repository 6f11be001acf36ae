/* route.h - a vessel's planned route: legs of a course and a speed between waypoints.
 *
 * The route is what the avoidance policy (policy.h) returns to after
 * avoiding: explicit, given with the vessel, not the line through wherever
 * the ship happened to be at its first step.  Each leg begins at a waypoint
 * and runs on a course for a length at a speed; the next begins where it
 * ends.  Legs are kept in this form (not as bare waypoints) so that a route
 * made from a course keeps that course to the bit: the one-leg route of a
 * scenario's own ship (fw_route_line) steers exactly as the line it
 * replaces, and every output stays byte-identical.
 *
 * A route made from waypoints (fw_route_from_waypoints: a scenario's
 * own_ship.route, scenario/scn_route.h) is `steered`: the policy keeps the
 * ship on its active leg from the first step, by line-of-sight guidance on
 * the cross-track error to that leg, takes the next leg at the wheel-over
 * point (avoid/wheel_over.h) and orders each leg's speed; after avoiding it
 * returns to the active leg.  fw_route_line's one leg is not steered: the
 * rudder stays amidships until the first avoidance, as before routes.
 * Frame: metres east and north, navigational radians, m/s.
 */
#ifndef FW_AVOID_ROUTE_H
#define FW_AVOID_ROUTE_H

#include <math.h>
#include <stdbool.h>

#include "core/error.h"
#include "traffic/lane.h"

enum { FW_ROUTE_MAX_LEGS = 8 };

typedef struct fw_route_leg {
    double east, north; /* m, the waypoint it begins at */
    double course;      /* rad, towards the next waypoint */
    double length;      /* m, > 0 */
    double speed;       /* m/s, planned */
    /* m: the water the hull centre has from the leg's line to its
     * waterway's edges, to starboard and to port (a route along a network's
     * edges: scenario/scn_netroute.h, less half the ship's breadth); 0: not
     * known (open water, the band's band_xte alone: band.h) */
    double room_starboard, room_port;
} fw_route_leg;

typedef struct fw_route {
    int n; /* legs; 0: none given */
    bool steered; /* made from waypoints: followed leg by leg, speeds ordered */
    fw_route_leg leg[FW_ROUTE_MAX_LEGS];
} fw_route;

/* One leg from (east, north) on course at speed for length. */
static inline fw_route fw_route_line(double east, double north, double course, double speed,
                                     double length)
{
    fw_route r = {.n = 1};
    r.leg[0] = (fw_route_leg){east, north, course, length, speed, 0.0, 0.0};
    return r;
}

/* The legs between n waypoints (e[i], no[i]), speed[i] on the leg from
 * waypoint i; FW_EINPUT for fewer than 2 or more than FW_ROUTE_MAX_LEGS + 1
 * waypoints, two that coincide, or a value that is not finite. */
static inline fw_status fw_route_from_waypoints(const double *e, const double *no,
                                                const double *speed, int n, fw_route *out,
                                                fw_error *err)
{
    if (n < 2 || n > FW_ROUTE_MAX_LEGS + 1)
        return fw_fail(err, FW_EINPUT, "%d waypoints: a route has 2..%d", n,
                       FW_ROUTE_MAX_LEGS + 1);
    out->n = n - 1;
    out->steered = true;
    for (int i = 0; i + 1 < n; i++) {
        double de = e[i + 1] - e[i], dn = no[i + 1] - no[i], len = hypot(de, dn);
        if (!(len > 0.0 && isfinite(len)) || !(speed[i] >= 0.0 && isfinite(speed[i])))
            return fw_fail(err, FW_EINPUT, "leg %d (from waypoint %d) has no length or no speed",
                           i + 1, i + 1);
        double c = atan2(de, dn);
        out->leg[i] = (fw_route_leg){e[i], no[i], c < 0.0 ? c + 2.0 * M_PI : c, len, speed[i],
                                     0.0, 0.0};
    }
    return FW_OK;
}

/* m: position (e, n) along leg k from its waypoint, and to starboard of it. */
static inline double fw_route_along(const fw_route *r, int k, double e, double n)
{
    const fw_route_leg *l = &r->leg[k];
    return (e - l->east) * sin(l->course) + (n - l->north) * cos(l->course);
}
static inline double fw_route_cross(const fw_route *r, int k, double e, double n)
{
    const fw_route_leg *l = &r->leg[k];
    return (e - l->east) * cos(l->course) - (n - l->north) * sin(l->course);
}

/* m, the distance along the route to (e, n)'s foot on its nearest leg (the
 * legs before it counted whole); *off: the distance from that leg, *leg: it
 * (either may be NULL). */
static inline double fw_route_progress(const fw_route *r, double e, double n, double *off,
                                       int *leg)
{
    double best = INFINITY, run = 0.0, prog = 0.0;
    int kb = 0;
    for (int k = 0; k < r->n; k++) {
        double a = fmax(0.0, fmin(r->leg[k].length, fw_route_along(r, k, e, n)));
        double pe = r->leg[k].east + a * sin(r->leg[k].course);
        double pn = r->leg[k].north + a * cos(r->leg[k].course);
        double d = hypot(e - pe, n - pn);
        if (d < best)
            best = d, prog = run + a, kb = k;
        run += r->leg[k].length;
    }
    if (off)
        *off = best;
    if (leg)
        *leg = kb;
    return prog;
}

/* s, the planned time to sail distance `along` of the route at its legs'
 * speeds (beyond its end at the last leg's). */
static inline double fw_route_time(const fw_route *r, double along)
{
    double t = 0.0;
    for (int k = 0; k < r->n && along > 0.0; k++) {
        double d = k + 1 < r->n ? fmin(along, r->leg[k].length) : along;
        t += d / fmax(r->leg[k].speed, 1e-3);
        along -= d;
    }
    return t;
}

/* The route as a lane line (traffic/lane.h), for judging ships met along
 * a waterway the route follows (encounter.h fw_assess_lanes): its
 * waypoints, with no sea room of its own (a route is not a waterway: the
 * width is the other ship's waterway's). */
static inline void fw_route_lane(const fw_route *r, fw_lane_info *out)
{
    *out = (fw_lane_info){.np = 0, .room_starboard = 0.0, .room_port = 0.0};
    for (int k = 0; k < r->n; k++, out->np++)
        out->e[k] = r->leg[k].east, out->n[k] = r->leg[k].north;
    if (r->n > 0) {
        const fw_route_leg *l = &r->leg[r->n - 1];
        out->e[r->n] = l->east + l->length * sin(l->course);
        out->n[r->n] = l->north + l->length * cos(l->course);
        out->np++;
    }
}

#endif
