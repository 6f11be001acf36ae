/* within.h - is a point within a range of another, as hypot says, cheaply. */
#ifndef FW_CORE_WITHIN_H
#define FW_CORE_WITHIN_H

#include <math.h>
#include <stdbool.h>

/* hypot(dx, dy) <= r, to the bit, without hypot where the sum of squares
 * decides it (r >= 0): off by more than 1e-12 relative (far beyond its rounding and
 * hypot's), the answer is the same; within that, or for a NaN, hypot
 * decides.  glibc's hypot costs several times a square root, and the
 * world's views and the traffic's range queries ask it for every ship
 * every step. */
static inline bool fw_within_range(double dx, double dy, double r)
{
    if (!(r >= 0.0))
        return hypot(dx, dy) <= r;
    double s = dx * dx + dy * dy, r2 = r * r;
    if (s > r2 * (1.0 + 1e-12))
        return false;
    if (s < r2 * (1.0 - 1e-12))
        return true;
    return hypot(dx, dy) <= r;
}

#endif
