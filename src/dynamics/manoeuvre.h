/* manoeuvre.h - standard manoeuvres (IMO MSC.137(76)) run on the MMG model.
 *
 * A turning circle (helm to the given angle from straight steady running) and
 * a zig-zag (helm reversed whenever the heading change reaches the angle),
 * measured as the IMO standard defines them, with the verdicts of the
 * standard.  Position is the midship point; advance is measured along the
 * approach course, transfer and tactical diameter across it.
 */
#ifndef FW_MANOEUVRE_H
#define FW_MANOEUVRE_H

#include <stdbool.h>
#include <stddef.h>

#include "dynamics/stepper.h"

typedef struct fw_sample {
    double t, east, north, psi, u, vm, r, delta, helm, n;
} fw_sample;

/* A growing time history; zero-initialise, free with fw_history_free. */
typedef struct fw_history {
    fw_sample *s;
    size_t n, cap;
} fw_history;

void fw_history_free(fw_history *h);
fw_status fw_history_write_csv(const fw_history *h, const char *path, fw_error *err);

typedef struct fw_turning_def {
    double speed;        /* m/s, approach speed */
    double rudder;       /* rad, signed: > 0 starboard */
    double sample_dt;    /* s, control and sampling step */
    double max_time;     /* s, gives up after this */
    double max_turn;     /* rad of heading change to simulate */
    fw_stepper_def stepper;
} fw_turning_def;

fw_turning_def fw_default_turning_def(void);

typedef struct fw_turning_result {
    double advance, transfer, tactical_diameter; /* m */
    double t90, t180;        /* s, times to 90 and 180 deg heading change */
    double steady_rate;      /* rad/s, magnitude, mean over the last full circle */
    double steady_speed;     /* m/s, mean over the last full circle */
    double propeller;        /* rev/s, from surge balance at the approach speed */
    double L;                /* m, for the IMO ratios */
    /* the ground track's 720 deg point from its 360 deg point (a turn of at
     * least 720 deg: max_turn): the drift of the steady circle, zero in calm
     * water and current x t_drift in a uniform current, plus the wind's drift
     * in a wind (stepper def); NAN when not reached.
     * advance, transfer and tactical diameter are the water's (the
     * current's drift taken out, MSC/Circ.1053 3.4.2.3). */
    double drift, t_drift;   /* m, s */
    double drift_towards;    /* rad, navigational */
    bool advance_ok, tactical_ok; /* IMO: advance <= 4.5 L, tactical diameter <= 5 L */
} fw_turning_result;

/* hist may be NULL. */
fw_status fw_turning_run(const fw_ship *ship, const fw_turning_def *def, fw_turning_result *res,
                         fw_history *hist, fw_error *err);

typedef struct fw_zigzag_def {
    double speed;      /* m/s */
    double angle;      /* rad, both the helm angle and the heading-change trigger */
    int first_side;    /* +1 starboard first, -1 port first */
    int executes;      /* number of helm reversals to simulate (>= 2) */
    double sample_dt;
    double max_time;
    fw_stepper_def stepper;
} fw_zigzag_def;

fw_zigzag_def fw_default_zigzag_def(void);

typedef struct fw_zigzag_result {
    double overshoot1, overshoot2; /* rad */
    double t_first_execute;        /* s, initial turning time (heading change reaches angle) */
    double L_over_V;               /* s */
    double limit1, limit2;         /* rad, IMO limits (limit2 < 0: the standard sets none) */
    bool ok1, ok2;
    double propeller;
} fw_zigzag_result;

fw_status fw_zigzag_run(const fw_ship *ship, const fw_zigzag_def *def, fw_zigzag_result *res,
                        fw_history *hist, fw_error *err);

/* IMO MSC.137(76) overshoot limits in degrees for a zig-zag of angle_deg at
 * L/V seconds; *limit2 is negative where the standard sets no second limit. */
void fw_imo_overshoot_limits(double angle_deg, double L_over_V, double *limit1, double *limit2);

#endif
