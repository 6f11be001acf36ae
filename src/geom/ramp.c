/* ramp.c - a ship whose speed changes at a rate (ramp.h). */
#include "geom/ramp.h"

#include <math.h>

#include "geom/geom.h"

/* The point of the segment p + s q, s in [0, 1], nearest the origin: s. */
static double nearest_on(double px, double py, double qx, double qy)
{
    double q2 = qx * qx + qy * qy;
    double s = q2 > 1e-12 ? -(px * qx + py * qy) / q2 : 0.0;
    return s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
}

void fw_cpa_ramp_sq(double dx, double dy, double vx, double vy, double hx, double hy, double u,
                    double v, double acc, double dec, double step, double *tcpa, double *d2)
{
    double a = v >= u ? acc : -dec, tr = a != 0.0 ? (v - u) / a : 0.0;
    if (!(tr > 1e-9)) {
        fw_cpa_sq(dx, dy, vx - v * hx, vy - v * hy, tcpa, d2);
        return;
    }
    /* while the speed changes: the relative position at each step's ends */
    double best = dx * dx + dy * dy, tbest = 0.0, t0 = 0.0;
    double rx = dx, ry = dy;
    while (t0 < tr) {
        double t1 = fmin(t0 + step, tr), s1 = fw_ramp_run(u, v, acc, dec, t1);
        double x1 = dx + vx * t1 - hx * s1, y1 = dy + vy * t1 - hy * s1;
        double s = nearest_on(rx, ry, x1 - rx, y1 - ry);
        double px = rx + s * (x1 - rx), py = ry + s * (y1 - ry), q = px * px + py * py;
        if (q < best)
            best = q, tbest = t0 + s * (t1 - t0);
        rx = x1, ry = y1, t0 = t1;
    }
    /* then at v: from where it is at tr, constant velocity */
    double wx = vx - v * hx, wy = vy - v * hy, tc, q;
    fw_cpa_sq(rx, ry, wx, wy, &tc, &q);
    if (tc > 0.0 && q < best)
        best = q, tbest = tr + tc;
    *tcpa = tbest;
    *d2 = best;
}
