/* units.h - the one place where interface units meet SI.
 *
 * Inside fairway everything is SI (m, s, rad, m/s, rad/s).  Knots, nautical
 * miles and degrees exist only at interfaces (command line, files people write,
 * printed reports), and every conversion goes through these helpers.
 * Headings are navigational: 0 = north, clockwise positive, as in SUMO.
 */
#ifndef FW_UNITS_H
#define FW_UNITS_H

#include <math.h>

#define FW_PI 3.14159265358979323846
#define FW_KNOT 0.514444444444444444   /* m/s per knot (1852 m / 3600 s) */
#define FW_NMILE 1852.0                 /* m per nautical mile */
#define FW_G 9.80665                    /* m/s^2 */

static inline double fw_kn_to_ms(double kn) { return kn * FW_KNOT; }
static inline double fw_ms_to_kn(double ms) { return ms / FW_KNOT; }
static inline double fw_deg_to_rad(double deg) { return deg * (FW_PI / 180.0); }
static inline double fw_rad_to_deg(double rad) { return rad * (180.0 / FW_PI); }
static inline double fw_nm_to_m(double nm) { return nm * FW_NMILE; }
static inline double fw_m_to_nm(double m) { return m / FW_NMILE; }

/* The wraps run for every target in every decision, mostly on angles already
 * within one turn: fmod(x, y) is exact and returns x itself when |x| < |y|, so
 * skipping it there gives the same bits (and -0, NaN and inf take fmod as
 * before: NaN and inf fail the test). */

/* Wraps an angle to (-pi, pi]. */
static inline double fw_wrap_pi(double a)
{
    a += FW_PI;
    if (!(fabs(a) < 2.0 * FW_PI))
        a = fmod(a, 2.0 * FW_PI);
    if (a <= 0.0)
        a += 2.0 * FW_PI;
    return a - FW_PI;
}

/* Wraps an angle to [0, 2 pi). */
static inline double fw_wrap_2pi(double a)
{
    if (!(fabs(a) < 2.0 * FW_PI))
        a = fmod(a, 2.0 * FW_PI);
    if (a < 0.0)
        a += 2.0 * FW_PI;
    return a;
}
/* Navigational heading in degrees [0, 360) from radians. */
double fw_heading_deg(double psi_rad);

#endif
