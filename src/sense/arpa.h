/* arpa.h - radar plots and the ARPA tracker that follows them (issue 24 item 4,
 * the radar half; not yet wired into the world: sensing.h has perfect and AIS).
 *
 * A radar measures a target's range and bearing from the own antenna once a
 * scan, with independent normal errors range_sd (m) and bearing_sd (rad).
 * Defaults: IMO MSC.192(79) requires a range accuracy of 30 m (or 1% of the
 * range scale) and a bearing accuracy of 1 deg; those limits are taken here as
 * 2 sigma (an estimate, not a published sigma): 15 m and 0.5 deg.  A scan
 * every 2.5 s (24 rpm, a common antenna speed).
 *
 * The tracker is an alpha-beta (g-h) filter on east and north separately
 * (Brookner, Tracking and Kalman Filtering Made Easy, 1998, ch. 1):
 *   predict  x- = x + v T
 *   correct  x = x- + alpha (z - x-),  v = v + beta/T (z - x-)
 * started from the first plot (v = 0) and the second (v from the two plots).
 * Default alpha 0.5 with the Benedict-Bordner beta = alpha^2/(2 - alpha).
 * Its stated theory, in steady state on a target at constant velocity with
 * measurement noise sigma on an axis (the variance reduction ratios, VRR):
 *   filtered position  var = sigma^2 (2a^2 + 2b - 3ab) / (a (4 - 2a - b))
 * and its lag on a target accelerating at acc along an axis (no noise):
 *   filtered position  bias = -(1 - a) acc T^2 / b   (the track trails).
 * Randomness: the caller passes the stream (the world's FW_PURPOSE_SENSING
 * stream of the target's key); one normal draw for range, one for bearing.
 *
 * Not modelled yet: detection range (target size, sea clutter, visibility),
 * track loss and swap, the world hook (own ship and background ships). */
#ifndef FW_SENSE_ARPA_H
#define FW_SENSE_ARPA_H

#include "core/rng.h"

typedef struct fw_radar_def {
    double range_sd;   /* m, 1 sigma: 15 */
    double bearing_sd; /* rad, 1 sigma: 0.5 deg */
    double scan;       /* s between plots of one target: 2.5 */
    double alpha;      /* tracker position gain, (0, 1]: 0.5 */
    double beta;       /* tracker velocity gain, (0, 2): alpha^2 / (2 - alpha) */
} fw_radar_def;

fw_radar_def fw_default_radar_def(void);

/* One plot: the target at (te, tn) seen from the antenna at (oe, on) with
 * range and bearing noise drawn from rng (two normal draws), as east/north. */
void fw_radar_plot(const fw_radar_def *def, fw_rng *rng, double oe, double on, double te,
                   double tn, double *ze, double *zn);

typedef struct fw_ab_track {
    double t;      /* s, time of the last plot */
    double e, n;   /* m, filtered position */
    double ve, vn; /* m/s, filtered velocity */
    int plots;     /* plots taken so far */
} fw_ab_track;

/* Takes the plot (ze, zn) made at time t (after the last one). */
void fw_ab_update(fw_ab_track *tr, const fw_radar_def *def, double t, double ze, double zn);

/* The track at time t >= tr->t, dead reckoned: east, north. */
void fw_ab_predict(const fw_ab_track *tr, double t, double *e, double *n);

/* The theory above: the filtered position's variance over sigma^2, and the
 * lag for acceleration acc at plot interval T. */
double fw_ab_position_vrr(double alpha, double beta);
double fw_ab_accel_lag(double alpha, double beta, double acc, double T);

#endif
