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
 *   V(t) = A(t) cos(2 pi (t - t_max) / period) (sin set, cos set),
 * flooding along `set` at +A and ebbing at -A (period M2 = 12.42 h by
 * default), its greatest rate A(t) modulated between springs and neaps as
 * the charts give them (a spring rate and a neap rate):
 *   A(t) = (spring + neap)/2 + (spring - neap)/2 cos(2 pi (t - t_spring) / T_sn),
 * T_sn = 1 / (1/T_M2 - 1/T_S2) = 14.77 days, the beat of the lunar M2 and
 * solar S2 constituents (S2: 12 h).  As constituents this is M2 of amplitude
 * (spring + neap)/2 with sidebands of (spring - neap)/4 at S2 and at
 * 2 M2 - S2.  A flood greatest at t_spring runs at the spring rate exactly;
 * the greatest flood nearest neaps (t_spring + T_sn/2) at the neap rate to
 * 0.3% of spring - neap (the envelope's change within half a tide).  neap = spring (fw_current_tidal):
 * no modulation, the earlier stream bit for bit.
 *
 * Gusts: the wind's speed U(t) = max(0, U + g(t)), g a first-order
 * Gauss-Markov (Ornstein-Uhlenbeck) process of standard deviation
 * sigma = I U (I: the turbulence intensity, gust_intensity) and time scale
 * T (gust_time): E g = 0, E g(t) g(t + s) = sigma^2 exp(-|s|/T).  Sampled
 * exactly at the world's step dt, g' = g exp(-dt/T) + sigma sqrt(1 -
 * exp(-2 dt/T)) N(0, 1), and held over the step; started from its stationary
 * law, g0 = sigma N(0, 1), so the series is stationary from t = 0.  The
 * draws come from the world's stream (vessel key 0, FW_PURPOSE_GUST,
 * core/rng.h), so a seed gives its gusts.  Offshore turbulence intensities
 * are about 0.06-0.12 at 10 m (DNV-RP-C205, 2.3.2.9: I_u about 0.1 over open
 * sea; IEC 61400-3 likewise); T about 10-60 s for the gusts that matter to a
 * ship's yaw.  No defaults: gusts only when given.  I up to 0.3: the speed is
 * then clipped at zero less than 0.05% of the time.  The direction is steady.
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
 * tracks are the source's.  Nor to a ship the world takes from the source to
 * steer (world/steer.h): a background ship still, Nomoto-stepped, not
 * checked (world.c).
 */
#ifndef FW_ENV_H
#define FW_ENV_H

#include <stdbool.h>

#include "core/error.h"
#include "core/rng.h"
#include "ship/ship.h"

typedef enum fw_field_kind {
    FW_FIELD_NONE,     /* calm water / still air */
    FW_FIELD_UNIFORM,  /* the same everywhere and at all times */
    FW_FIELD_TIDAL,    /* current only: rectilinear stream, uniform in space */
} fw_field_kind;

/* M2, the principal lunar semi-diurnal period: 12.42 h. */
#define FW_M2_PERIOD_S (12.4206012 * 3600.0)
/* S2, the principal solar semi-diurnal period: 12 h. */
#define FW_S2_PERIOD_S (12.0 * 3600.0)
/* Springs to springs: the M2-S2 beat, 14.77 days. */
#define FW_SPRING_NEAP_S (1.0 / (1.0 / FW_S2_PERIOD_S - 1.0 / FW_M2_PERIOD_S))
/* Bounds a gust's parameters must keep (the scenario's too). */
#define FW_GUST_INTENSITY_MAX 0.3
#define FW_GUST_TIME_MIN_S 1.0
#define FW_GUST_TIME_MAX_S 3600.0

typedef struct fw_current {
    fw_field_kind kind;
    double east, north;  /* m/s, uniform: the velocity it sets towards */
    /* tidal: */
    double set;          /* rad, navigational, the direction of the flood */
    double rate;         /* m/s, the flood's greatest rate at springs (>= 0) */
    double period;       /* s, > 0 (FW_M2_PERIOD_S) */
    double t_max;        /* s, a time of greatest flood */
    double neap_rate;    /* m/s, at neaps (0 <= neap_rate <= rate; = rate: none) */
    double spring_period;/* s, > 0 (FW_SPRING_NEAP_S) */
    double t_spring;     /* s, a time of springs */
} fw_current;

typedef struct fw_wind {
    fw_field_kind kind;  /* none or uniform */
    double speed;        /* m/s, >= 0: the mean */
    double from;         /* rad, navigational: the direction it blows from */
    double gust_intensity; /* sigma / speed, 0 (steady) to FW_GUST_INTENSITY_MAX */
    double gust_time;    /* s, the gusts' time scale T (with an intensity > 0) */
    double gust;         /* m/s, g now (the world's: fw_wind_gust_start, _step) */
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
/* The same with its rate `spring` at springs (t_spring) and `neap` at neaps,
 * the spring-neap period FW_SPRING_NEAP_S. */
fw_current fw_current_tidal_sn(double spring, double neap, double set, double period,
                               double t_max, double t_spring);

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
/* Not calm, with gusts (an intensity > 0). */
bool fw_wind_gusty(const fw_wind *w);
/* g from its stationary law, one draw of r; nothing when not gusty. */
void fw_wind_gust_start(fw_wind *w, fw_rng *r);
/* g advanced by dt seconds, one draw of r; nothing when not gusty. */
void fw_wind_gust_step(fw_wind *w, double dt, fw_rng *r);

/* Can a vessel of this ship (vessel: its name, for the message) sail in e?
 * mmg: its dynamics are MMG's (else Nomoto's, which have no wind term).
 * FW_EINPUT, saying why, while the wind is not calm and the vessel is not an
 * MMG ship with windage particulars. */
fw_status fw_env_check_vessel(const fw_env *e, const char *vessel, const fw_ship *ship, bool mmg,
                              fw_error *err);

#endif
