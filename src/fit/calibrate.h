/* calibrate.h - fitting named MMG coefficients of a ship to its sea trial
 * and to the steady rates and rate histories of a Nomoto knowledge base.
 *
 * A trial file (YAML) lists turning-circle results measured at sea, optional
 * targets taken from a ship's Nomoto regressions (the paper's equation 10 for
 * steady rates K delta and equation 9 for the first minutes of the rate
 * history), and the ship-file fields to tune.  Each tuned field is written as
 * regression value x exp(p) (log space, so signs never flip), p bounded by
 * +-ln(max_factor) around the regression value, and the fit minimises by
 * Levenberg-Marquardt the sum of squares of
 *   - each target's relative error (times the row's weight),
 *   - each history's error at every sampled second, relative to K delta and
 *     scaled so a whole history weighs like one value of history_weight,
 *   - prior_weight x p for every coefficient: a pull towards the regression
 *     value, so that coefficients the targets do not pin stay where the
 *     regressions put them instead of wandering to a bound.
 */
#ifndef FW_CALIBRATE_H
#define FW_CALIBRATE_H

#include <stdbool.h>

#include "core/lsq.h"
#include "dynamics/manoeuvre.h"

enum { FW_TRIAL_MAX_TURNS = 48, FW_TRIAL_MAX_HIST = 40 };

typedef struct fw_trial_turn {
    double speed;   /* m/s, approach */
    double rudder;  /* rad, signed: > 0 starboard */
    double advance, transfer, tactical_diameter; /* m, 0 = not measured */
    double steady_rate; /* rad/s, magnitude, 0 = not measured */
    /* another simulator's results for the same row, for comparison only
     * (the paper's UMS for the C-3); 0 = not given */
    double sim_advance, sim_transfer, sim_tactical_diameter, sim_steady_rate;
    double weight;      /* multiplies this row's residuals (1 unless given) */
    bool from_kb;       /* a target computed from a knowledge base, not measured */
    int line;           /* where the trial file gives it, for messages */
    /* equation 9 with the knowledge base's indices at this speed and rudder
     * (1/s and s; rates in rad/s for a rudder step of |rudder|): the rate
     * history target over the first history_s seconds, 0 = none */
    double K, T1, T2, T3;
    double history_s, history_weight;
} fw_trial_turn;

/* The turning test that reproduces a trial row: its speed and rudder, on to
 * 540 deg of heading change (the tactical diameter needs 180). */
fw_turning_def fw_trial_turning_def(const fw_trial_turn *t);

typedef struct fw_trial {
    char file[512];
    char ship[64];
    char source[256];
    char kb_source[256];  /* where the knowledge-base targets come from, "" = none */
    char kb_ship[64];     /* the ship file whose knowledge base they are, "" = none */
    int nturns;
    fw_trial_turn turns[FW_TRIAL_MAX_TURNS];
    int ntune;
    char tune[FW_LSQ_MAX_P][32];
    /* the value each coefficient is pulled towards and bounded around
     * (0 = the ship file's value when the fit starts), and its bound */
    double regression[FW_LSQ_MAX_P];
    double factor[FW_LSQ_MAX_P];
    double max_factor;   /* default bound, tuned values stay within [reg / f, reg * f] */
    double prior_weight; /* 0 = no pull */
    /* factors beyond this are curve fitting, not a correction a regression
     * admits: --write marks them [FIT] instead of [CAL] (default max_factor) */
    double physical_factor;
    bool check_only;     /* evaluate the ship as it is, no fit (after = before) */
} fw_trial;

fw_status fw_trial_load(const char *path, fw_trial *trial, fw_error *err);

/* Number of target values of a row (measured or from the knowledge base,
 * history not counted) and its history samples. */
int fw_trial_row_values(const fw_trial_turn *t);
int fw_trial_row_history(const fw_trial_turn *t);

typedef struct fw_calibration {
    int n;
    double regression[FW_LSQ_MAX_P];
    double before[FW_LSQ_MAX_P], after[FW_LSQ_MAX_P];
    fw_turning_result before_res[FW_TRIAL_MAX_TURNS], after_res[FW_TRIAL_MAX_TURNS];
    /* RMS error of each row's rate history against equation 9 (rad/s) */
    double hist_before[FW_TRIAL_MAX_TURNS], hist_after[FW_TRIAL_MAX_TURNS];
    double rms_before, rms_after; /* RMS relative error over all target values */
    double max_before, max_after; /* largest relative error */
    fw_lsq_result lsq;
} fw_calibration;

/* Runs the fit; on success the ship holds the tuned values. */
fw_status fw_calibrate(fw_ship *ship, const fw_trial *trial, fw_calibration *cal, fw_error *err);

/* Writes the tuned values into the ship file, each with a comment giving its
 * regression value and factor, and a summary block in the file's header. */
fw_status fw_calibration_write(const fw_ship *ship, const fw_trial *trial,
                               const fw_calibration *cal, fw_error *err);

#endif
