/* calibrate.h - fitting named MMG coefficients of a ship to its sea trial.
 *
 * A trial file (YAML) lists turning-circle results measured at sea and the
 * names of the ship-file fields to tune.  The fit scales each tuned field by
 * a factor (searched in log space, so signs never flip) to minimise the sum of
 * squared relative errors of advance, transfer, tactical diameter and steady
 * turning rate over all rows, by Levenberg-Marquardt.
 */
#ifndef FW_CALIBRATE_H
#define FW_CALIBRATE_H

#include "core/lsq.h"
#include "dynamics/manoeuvre.h"

enum { FW_TRIAL_MAX_TURNS = 8 };

typedef struct fw_trial_turn {
    double speed;   /* m/s, approach */
    double rudder;  /* rad, signed: > 0 starboard */
    double advance, transfer, tactical_diameter; /* m, 0 = not measured */
    double steady_rate; /* rad/s, magnitude, 0 = not measured */
    /* another simulator's results for the same row, for comparison only
     * (the paper's UMS for the C-3); 0 = not given */
    double sim_advance, sim_transfer, sim_tactical_diameter, sim_steady_rate;
} fw_trial_turn;

/* The turning test that reproduces a trial row: its speed and rudder, on to
 * 540 deg of heading change (the tactical diameter needs 180). */
fw_turning_def fw_trial_turning_def(const fw_trial_turn *t);

typedef struct fw_trial {
    char file[512];
    char ship[64];
    char source[256];
    int nturns;
    fw_trial_turn turns[FW_TRIAL_MAX_TURNS];
    int ntune;
    char tune[FW_LSQ_MAX_P][32];
    double max_factor; /* tuned values stay within [base / f, base * f] */
} fw_trial;

fw_status fw_trial_load(const char *path, fw_trial *trial, fw_error *err);

typedef struct fw_calibration {
    int n;
    double before[FW_LSQ_MAX_P], after[FW_LSQ_MAX_P];
    fw_turning_result before_res[FW_TRIAL_MAX_TURNS], after_res[FW_TRIAL_MAX_TURNS];
    double rms_before, rms_after; /* RMS relative error over all measured values */
    double max_before, max_after; /* largest relative error */
    fw_lsq_result lsq;
} fw_calibration;

/* Runs the fit; on success the ship holds the tuned values. */
fw_status fw_calibrate(fw_ship *ship, const fw_trial *trial, fw_calibration *cal, fw_error *err);

/* Writes the tuned values into the ship file, each with a comment saying it was
 * calibrated and from what value, and a summary block in the file's header. */
fw_status fw_calibration_write(const fw_ship *ship, const fw_trial *trial,
                               const fw_calibration *cal, fw_error *err);

#endif
