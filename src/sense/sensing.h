/* sensing.h - what a ship knows of the others: the truth, their AIS reports,
 * its radar's tracks, or both.
 *
 * A sensor turns the ships a vessel could see (the truth, world.h) into the
 * ships it knows of, which its controller decides on.  Modes:
 *
 *   perfect  every ship's exact position, course and speed every step (the
 *            default, and all fairway had before)
 *   ais      each ship's AIS reports (ITU-R M.1371-5, Table 1, Class A):
 *            every 10 s at 0-14 kn (3 1/3 s while changing course), 6 s at
 *            14-23 kn (2 s while changing course), 2 s above 23 kn, 3 min
 *            below 3 kn; a ship changes course when its course over ground
 *            turned more than kTurning since the last step.  Each report holds
 *            the ship's position with GNSS noise (position_sd_m in east and in
 *            north), SOG (sog_sd_kn) and COG (cog_sd_deg) with noise, and its
 *            heading (heading_sd_deg, the gyro's); it is lost with probability
 *            dropout and arrives latency_s after it was sent.  A ship is known
 *            from its first report that arrives; between reports it is dead
 *            reckoned from its last one (position + SOG x age along COG), and
 *            forgotten when its last report is older than stale_s.  A ship's
 *            first report comes at a random phase of its interval.
 *   radar    the own ship's radar and its tracker (arpa.h): a scan every
 *            radar.scan s (at multiples of it, every target at once: the
 *            sweep's spread over the scan is not modelled), each ship within
 *            the radar horizon detected with the probability arpa.h gives
 *            by its length and range; a detection is a plot (range and
 *            bearing noise) at the scan's time (the truth of the step moved
 *            back along its velocity to it, the antenna likewise), fed to the
 *            ship's alpha-beta track.  A track is shown (known) once it is
 *            60 s old (MSC.192(79) 5.25.4.1: the trend of a target's motion
 *            within one minute), and lost when more than 5 of its last 10
 *            scans missed it (5.25.4.3: tracking continues while a target is
 *            seen in 5 scans of 10), or when it was out of the sensor's
 *            sight (not among the ships given) for more than 5 scans; a ship
 *            seen again starts a new track.
 *            The known ship: the track's position dead reckoned to now, its
 *            course and speed over ground from the track's velocity, its
 *            heading = its course (a radar sees no heading); its id, type
 *            and size are the truth's (the association of a track with its
 *            ship is perfect: no swaps, no false tracks).  Positions are the
 *            antenna's own (own ship's GNSS) plus the plot: own navigation is
 *            exact.  Restricted visibility does not change it (arpa.h).
 *   ais+radar  both, fused by MSC.192(79) 5.29 (target association): a
 *            ship with a current AIS report is shown by its AIS, else by its
 *            radar track; AIS is VHF and is received in fog as in clear air.
 *
 * Randomness: the noise and the phase are the transmitting ship's (its GNSS,
 * its slot), from its own stream (FW_PURPOSE_SENSING, key: rng.h
 * fw_rng_vessel_key of its id); a lost report is the receiver's
 * (FW_PURPOSE_AIS_DROPOUT, the same key).  The own ship's sensor (world.h)
 * keys a link by the target; a background ship's (fw_sensor_set_salt) by
 * the pair, so a key names one link.
 *
 * The radar's noise and detections draw from the target's
 * FW_PURPOSE_RADAR and FW_PURPOSE_RADAR_DETECT streams: one uniform a scan
 * for the detection (drawn whether or not it is within the horizon), two
 * normals a plot.
 *
 * What it does not model: Class B transponders, ships without AIS,
 * range-dependent AIS reception, radar clutter and track swaps.
 */
#ifndef FW_SENSE_SENSING_H
#define FW_SENSE_SENSING_H

#include <stdbool.h>

#include "core/error.h"
#include "core/rng.h"
#include "geom/target.h"
#include "sense/arpa.h"

typedef enum fw_sensing_mode {
    FW_SENSE_PERFECT,
    FW_SENSE_AIS,
    FW_SENSE_RADAR,
    FW_SENSE_AIS_RADAR
} fw_sensing_mode;

typedef struct fw_sensing_def {
    fw_sensing_mode mode;
    double position_sd;  /* m, 1 sigma in east and in north: 10 */
    double sog_sd;       /* m/s, 1 sigma: 0.1 kn */
    double cog_sd;       /* rad, 1 sigma: 1 deg */
    double heading_sd;   /* rad, 1 sigma: 0.5 deg */
    double dropout;      /* probability a report is lost: 0 */
    double latency;      /* s, from sending to arriving: 0 */
    double stale;        /* s, a ship whose last report is older is forgotten: 360 */
    fw_radar_def radar;  /* the radar and its tracker (arpa.h's defaults) */
} fw_sensing_def;

/* perfect, with the AIS and radar values above for when the mode is changed. */
fw_sensing_def fw_default_sensing_def(void);

/* "perfect", "ais", "radar", "ais+radar"; parse: FW_EINPUT for anything else. */
const char *fw_sensing_mode_name(fw_sensing_mode m);
fw_status fw_sensing_mode_parse(const char *text, fw_sensing_mode *out);

/* FW_EINPUT naming the field for a negative or non-finite value, a
 * dropout outside [0, 1], a radar scan not positive or a gain outside
 * (0, 1] (alpha) or (0, 2) (beta). */
fw_status fw_sensing_check(const fw_sensing_def *def, fw_error *err);

/* The AIS Class A reporting interval (s) of a ship at speed (m/s), turning or
 * not. */
double fw_ais_interval(double speed, bool turning);

/* Counts so far: AIS reports sent, lost, arrived; radar: ships scanned
 * (within the horizon), plotted, tracks started and lost; and the squared
 * error of what was known against the truth (m^2, summed over err_n ships
 * known at updates), for the radar modes. */
typedef struct fw_sensing_counts {
    long sent, lost, arrived;
    long scanned, plotted, tracks, tracks_lost;
    double err_sq;
    long err_n;
} fw_sensing_counts;
/* One ship's AIS transmissions as a receiver hears them (the modes with
 * AIS, above): its reports' schedule and noise (streams noise and loss, set
 * by the caller before the first step), those on their way, the last that
 * arrived. */
typedef struct fw_ais_sent {
    double t, east, north, sog, cog, heading;
    double sog_e, sog_n; /* m/s, its velocity over ground (SOG along COG), for dead reckoning */
} fw_ais_sent;
/* Reports on their way at once: the latency is at most 2 s, the shortest
 * interval 2 s (and a first phase may be shorter). */
enum { FW_AIS_IN_FLIGHT = 4 };
typedef struct fw_ais_tx {
    bool started, known;
    double t_next;              /* s, its next report */
    double t_prev, course_prev; /* its course over ground when last seen */
    fw_ais_sent last;         /* the last that arrived */
    fw_ais_sent queued[FW_AIS_IN_FLIGHT]; /* on their way, oldest first */
    int n_queued;
    fw_rng *noise, *loss;
} fw_ais_tx;

/* Ship a (the truth) at t: its reports sent when due, lost or on their way,
 * arrived (counted into c). */
void fw_ais_tx_step(const fw_sensing_def *d, fw_ais_tx *tx, const fw_target *a, double t,
                    fw_sensing_counts *c);
/* What its last report says of a at t (dead reckoned, a's static data), if
 * one has arrived and is not older than d->stale. */
bool fw_ais_tx_known(const fw_sensing_def *d, const fw_ais_tx *tx, const fw_target *a, double t,
                     fw_target *out);

typedef struct fw_sensor fw_sensor;

fw_status fw_sensor_create(const fw_sensing_def *def, fw_rng_getter rng, void *rng_ctx,
                           fw_sensor **out, fw_error *err);
void fw_sensor_destroy(fw_sensor *s);

/* A sensor of a ship other than the own ship (the reacting traffic's,
 * world/reactions.h): its links draw from the streams of key
 * fw_rng_link_key(receiver, target key), not the target's own (0: the own
 * ship's sensor, the default). */
void fw_sensor_set_salt(fw_sensor *s, uint32_t receiver);

/* Where the sensor is (the own ship's record: position, course and speed
 * over ground), before each update; the radar modes need it. */
void fw_sensor_place(fw_sensor *s, const fw_target *own);

/* At time t the ships truth[0..n-1] (sorted by id) could be seen: what the
 * sensor knows of them into known (room for n), sorted by id, *n_known of
 * them.  Perfect: a copy. */
fw_status fw_sensor_update(fw_sensor *s, double t, const fw_target *truth, int n,
                           fw_target *known, int *n_known, fw_error *err);

fw_sensing_counts fw_sensor_counts(const fw_sensor *s);

#endif
