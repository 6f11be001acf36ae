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
 * The policy follows the first leg only (its track and course); following a
 * route round its bends, and a speed per leg, are for the ship's steering
 * to come (issue 27).  Frame: metres east and north, navigational radians,
 * m/s.
 */
#ifndef FW_AVOID_ROUTE_H
#define FW_AVOID_ROUTE_H

#include <math.h>

#include "core/error.h"

enum { FW_ROUTE_MAX_LEGS = 8 };

typedef struct fw_route_leg {
    double east, north; /* m, the waypoint it begins at */
    double course;      /* rad, towards the next waypoint */
    double length;      /* m, > 0 */
    double speed;       /* m/s, planned */
} fw_route_leg;

typedef struct fw_route {
    int n; /* legs; 0: none given */
    fw_route_leg leg[FW_ROUTE_MAX_LEGS];
} fw_route;

/* One leg from (east, north) on course at speed for length. */
static inline fw_route fw_route_line(double east, double north, double course, double speed,
                                     double length)
{
    fw_route r = {.n = 1};
    r.leg[0] = (fw_route_leg){east, north, course, length, speed};
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
        return fw_fail(err, FW_EINPUT, "route: %d waypoints (2..%d)", n, FW_ROUTE_MAX_LEGS + 1);
    out->n = n - 1;
    for (int i = 0; i + 1 < n; i++) {
        double de = e[i + 1] - e[i], dn = no[i + 1] - no[i], len = hypot(de, dn);
        if (!(len > 0.0 && isfinite(len)) || !(speed[i] >= 0.0 && isfinite(speed[i])))
            return fw_fail(err, FW_EINPUT, "route: leg %d from waypoint %d is not a leg", i + 1,
                           i + 1);
        double c = atan2(de, dn);
        out->leg[i] = (fw_route_leg){e[i], no[i], c < 0.0 ? c + 2.0 * M_PI : c, len, speed[i]};
    }
    return FW_OK;
}

#endif
