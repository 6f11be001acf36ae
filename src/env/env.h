/* env.h - the sea and air the vessels sail in: a current field and a wind field.
 *
 * Each is a function of position (m east, north) and time (s), with a kind so
 * that a new shape (a spatial field from a tidal atlas, spring/neap rates)
 * is a new kind and a new case here, and the callers (the world, the MMG
 * stepper, the prediction) do not change.  The default is none: calm water,
 * still air; every path then does literally what it did before the
 * environment existed, so calm-water outputs stay byte-identical.
 *
 * Current: the velocity of the water over ground, the direction it sets
 * TOWARDS (m/s east, north).  Kinds: none; uniform (steady, the same
 * everywhere); tidal, a rectilinear stream uniform in space,
 *   V(t) = rate cos(2 pi (t - t_max) / period) (sin set, cos set),
 * flooding along `set` at +rate and ebbing at -rate (period M2 = 12.42 h by
 * default; spring/neap modulation of the rate is for the next issue).
 *
 * Wind: speed (m/s) and the direction it blows FROM (navigational, rad), the
 * convention of weather reports and of the DNV schema's windDirection.  It
 * acts on MMG hulls whose ship has windage particulars (ship/windage.h:
 * Blendermann 1994, from the apparent wind; dynamics/stepper.h).  A vessel
 * the wind could not act on -- an MMG ship without windage, or a vessel with
 * Nomoto dynamics, which have no wind term -- is refused while the wind is
 * not calm (fw_env_check_vessel), so that a wind is never silently ignored.
 * Background ships of the traffic source (SUMO, a track, the kinematic
 * lanes) are not vessels of the world: wind does nothing to them; their
 * tracks are the source's (the current does not move them either).
 */
#ifndef FW_ENV_H
#define FW_ENV_H

#include <stdbool.h>

#include "core/error.h"
#include "ship/ship.h"

typedef enum fw_field_kind {
    FW_FIELD_NONE,     /* calm water / still air */
    FW_FIELD_UNIFORM,  /* the same everywhere and at all times */
    FW_FIELD_TIDAL,    /* current only: rectilinear stream, uniform in space */
} fw_field_kind;

/* M2, the principal lunar semi-diurnal period: 12.42 h. */
#define FW_M2_PERIOD_S (12.4206012 * 3600.0)

typedef struct fw_current {
    fw_field_kind kind;
    double east, north;  /* m/s, uniform: the velocity it sets towards */
    /* tidal: */
    double set;          /* rad, navigational, the direction of the flood */
    double rate;         /* m/s, the flood's greatest rate (>= 0) */
    double period;       /* s, > 0 (FW_M2_PERIOD_S) */
    double t_max;        /* s, a time of greatest flood */
} fw_current;

typedef struct fw_wind {
    fw_field_kind kind;  /* none or uniform */
    double speed;        /* m/s, >= 0 */
    double from;         /* rad, navigational: the direction it blows from */
} fw_wind;

typedef struct fw_env {
    fw_current current;
    fw_wind wind;
} fw_env;

/* No current, no wind. */
fw_env fw_default_env(void);

/* Uniform current of `speed` m/s setting towards `set` (rad, navigational). */
fw_current fw_current_uniform(double speed, double set);
/* Rectilinear tidal stream: flood towards `set` at up to `rate`, greatest at t_max. */
fw_current fw_current_tidal(double rate, double set, double period, double t_max);

/* FW_EINPUT, naming the field, for a kind that is not known, a non-finite
 * value, a negative speed or rate, a period <= 0, or a tidal wind. */
fw_status fw_env_check(const fw_env *e, fw_error *err);

/* The current's velocity (m/s east, north) at (east, north) at time t. */
void fw_current_at(const fw_current *c, double east, double north, double t, double *ve,
                   double *vn);
/* Its integral over [t0, t1] at a fixed point (m east, north): the drift of
 * anything carried by the water for that time (exact for the kinds here). */
void fw_current_drift(const fw_current *c, double east, double north, double t0, double t1,
                      double *de, double *dn);

/* None, or a velocity of exactly zero: the hydrodynamics are those of calm water. */
bool fw_current_is_none(const fw_current *c);

/* Wind at (east, north) at time t: speed (m/s) and direction from (rad). */
void fw_wind_at(const fw_wind *w, double east, double north, double t, double *speed,
                double *from);
/* None, or a speed of exactly zero. */
bool fw_wind_is_calm(const fw_wind *w);

/* Can a vessel of this ship (vessel: its name, for the message) sail in e?
 * mmg: its dynamics are MMG's (else Nomoto's, which have no wind term).
 * FW_EINPUT, saying why, while the wind is not calm and the vessel is not an
 * MMG ship with windage particulars. */
fw_status fw_env_check_vessel(const fw_env *e, const char *vessel, const fw_ship *ship, bool mmg,
                              fw_error *err);

#endif
