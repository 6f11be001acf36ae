/* arpa.h - radar plots, their detection, and the ARPA tracker that follows
 * them (issue 24 item 4, the radar half; the own ship's sensor, sensing.h,
 * runs them in its radar modes).
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
 * Default alpha 0.1 with the Benedict-Bordner beta = alpha^2/(2 - alpha):
 * its transient decays as (1 - alpha)^(k/2) a scan, by e in 19 scans (48 s),
 * to 5% in 2.4 min, in keeping with MSC.192(79) 5.25.4.1 (the prediction of
 * a target's motion within 3 min of its acquisition); with the noise below
 * its velocity's sigma on a target 3 nm off is 0.23 m/s across the line of
 * sight (0.45 kn), 0.07 m/s along it.  A faster filter (alpha 0.5) follows a
 * turn sooner but shakes: 3.8 m/s across at 3 nm.  Until the steady gains are
 * reached the filter takes the least-squares (expanding-memory) gains of its
 * k-th plot, g = 2 (2k + 1) / ((k + 2)(k + 1)), h = 6 / ((k + 2)(k + 1))
 * (Brookner, section 1.2.10): the first two plots give the position and the
 * velocity (g = h = 1), and the track is a straight line fitted to its plots
 * until g falls to alpha (k = 38 for 0.1).
 * Its stated theory, in steady state on a target at constant velocity with
 * measurement noise sigma on an axis (the variance reduction ratios, VRR):
 *   filtered position  var = sigma^2 (2a^2 + 2b - 3ab) / (a (4 - 2a - b))
 * and its lag on a target accelerating at acc along an axis (no noise):
 *   filtered position  bias = -(1 - a) acc T^2 / b   (the track trails).
 * Randomness: the caller passes the stream (the world's FW_PURPOSE_RADAR
 * stream of the target's key); one normal draw for range, one for bearing.
 *
 * Detection (MSC.192(79) 5.3.1.1 and Table 2: a target is detected in at
 * least 8 scans of 10, false alarms 1e-4, antenna 15 m above the sea, no
 * clutter): a target's class by its length (an estimate: a ship of 5000 GT
 * is about 100 m long, of 500 GT about 45 m) gives the range R0 at which its
 * detection probability per scan is 0.8 and its height ht above the sea:
 *   L >= 100 m  SOLAS ship > 5000 GT     R0 11 nm, ht 10 m
 *   L >=  45 m  SOLAS ship > 500 GT      R0  8 nm, ht  5 m
 *   L >=  15 m  small, radar reflector   R0  5 nm, ht  4 m
 *   L <   15 m  small, no reflector      R0 3.4 nm, ht 2 m
 * At range R the probability per scan is that of a Swerling I target (a
 * fluctuating echo, the usual model of a ship; Skolnik, Introduction to Radar
 * Systems, 3rd ed., 2.8) at a signal-to-noise ratio falling as R^-4 (the
 * radar equation): Pd = Pfa^(1 / (1 + S)), S = S0 (R0 / R)^4, S0 set so that
 * Pd(R0) = 0.8 (S0 = 40.3, 16 dB); so Pd is 0.986 at R0 / 2, 0.36 at 1.5 R0
 * (the small no-reflector class: 5 nm), 0.07 at 2 R0.  Beyond the radar
 * horizon, 2.21 (sqrt(ha) + sqrt(ht)) nm for heights in metres (standard
 * refraction, Bowditch, The American Practical Navigator, table 12: 1.22
 * sqrt(h ft) nm), nothing is detected.  The antenna height ha (15 m) moves
 * only the horizon, not R0.  Visibility does not enter: fog attenuates X-band
 * by a fraction of a dB over 10 nm (ITU-R P.840: about 0.1 dB/km per g/m^3
 * of liquid water, fog that leaves 0.5 nm visibility holding some 0.05
 * g/m^3; an estimate).  Sea clutter, rain and shadowing by other ships are
 * not modelled.
 *
 * Not modelled: track swap, clutter. */
#ifndef FW_SENSE_ARPA_H
#define FW_SENSE_ARPA_H

#include "core/rng.h"

typedef struct fw_radar_def {
    double range_sd;   /* m, 1 sigma: 15 */
    double bearing_sd; /* rad, 1 sigma: 0.5 deg */
    double scan;       /* s between plots of one target: 2.5 */
    double alpha;      /* tracker position gain, (0, 1]: 0.5 */
    double beta;       /* tracker velocity gain, (0, 2): alpha^2 / (2 - alpha) */
    double antenna;    /* m, the antenna's height above the sea: 15 */
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

/* Takes the plot (ze, zn) made at time t (after the last one), with the
 * least-squares gains until they fall to the steady ones (above). */
void fw_ab_update(fw_ab_track *tr, const fw_radar_def *def, double t, double ze, double zn);

/* The track at time t >= tr->t, dead reckoned: east, north. */
void fw_ab_predict(const fw_ab_track *tr, double t, double *e, double *n);

/* The detection model above: R0 (m) and the target's height (m) by its
 * length (m); the radar horizon (m) between heights ha and ht (m); the
 * probability per scan of detecting a target of length L at range R (m). */
double fw_radar_class_range(double length, double *height);
double fw_radar_horizon(double ha, double ht);
double fw_radar_pd(const fw_radar_def *def, double range, double length);

/* The theory above: the filtered position's variance over sigma^2, and the
 * lag for acceleration acc at plot interval T. */
double fw_ab_position_vrr(double alpha, double beta);
double fw_ab_accel_lag(double alpha, double beta, double acc, double T);

#endif
