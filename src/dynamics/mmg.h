/* mmg.h - the MMG 3-DOF manoeuvring model (Yasukawa and Yoshimura 2015).
 *
 * Forces of hull, propeller (2015 wake form) and rudder (finite u_R form) on a
 * ship in calm deep water, and the accelerations they cause.  Frames: earth
 * positions in metres east and north, heading psi navigational (0 north,
 * clockwise); body x forward, y starboard, origin at midship; r > 0 and rudder
 * delta > 0 turn to starboard.  All SI.  The velocities are those through the
 * water: in a current (dynamics/stepper.h) the forces are the same functions
 * of them and fw_mmg_derivs' east and north rates are through the water (the
 * stepper adds the current).
 *
 * Wind (fw_mmg_wind): Blendermann's forces and moment (ship/windage.h) from
 * the apparent wind, the true wind less the ship's velocity OVER GROUND (the
 * air does not move with the water), acting at midship's axes and added to
 * the hull's, propeller's and rudder's (fw_mmg_derivs_ext).
 */
#ifndef FW_MMG_H
#define FW_MMG_H

#include "core/error.h"
#include "ship/ship.h"

typedef struct fw_mmg_state {
    double u;      /* m/s, surge through the water */
    double vm;     /* m/s, sway at midship through the water */
    double r;      /* rad/s, yaw rate */
    double east;   /* m, midship position */
    double north;  /* m */
    double psi;    /* rad, heading (navigational, not wrapped) */
    double delta;  /* rad, actual rudder angle */
} fw_mmg_state;

/* Forces on the ship for a state, propeller speed n (rev/s) and rudder delta. */
typedef struct fw_mmg_forces {
    double X_H, Y_H, N_H;
    double X_P;
    double X_R, Y_R, N_R;
    double K_T, J, w_P;  /* propeller operating point */
    double u_R, v_R, alpha_R, F_N;  /* rudder inflow */
} fw_mmg_forces;

void fw_mmg_forces_eval(const fw_ship *ship, const fw_mmg_state *s, double n,
                        fw_mmg_forces *f);

/* Time derivatives of u, vm, r, east, north, psi (6 values) for state s (its
 * delta is the rudder angle used) and propeller speed n; east and north
 * relative to the water. */
void fw_mmg_derivs(const fw_ship *ship, const fw_mmg_state *s, double n, double out[6]);

/* The same with external forces ext = {X, Y, N} (N, N, N m, body axes) added
 * to the ship's; ext NULL: fw_mmg_derivs, bit for bit. */
void fw_mmg_derivs_ext(const fw_ship *ship, const fw_mmg_state *s, double n, const double ext[3],
                       double out[6]);

/* The wind's X, Y, N on the ship (its windage must be present) in state s,
 * in a current (ce, cn) m/s east, north at the ship, for a true wind of
 * `speed` m/s from `from` (rad, navigational). */
void fw_mmg_wind(const fw_ship *ship, const fw_mmg_state *s, double ce, double cn, double speed,
                 double from, double out[3]);

/* Straight, steady running in a steady wind (speed m/s from `from`, rad)
 * and a uniform current (ce, cn m/s east, north) on heading x->psi at
 * propeller speed n: the surge x->u, sway x->vm and rudder angle x->delta
 * (r = 0) at which the hull's, propeller's, rudder's and the wind's forces
 * and moment balance, by Newton's method from x's u, vm and delta.  The
 * ship's leeway: it holds its heading with that rudder and moves through
 * the water at vm sideways.  FW_ERUN when Newton's method does not settle
 * (to 1e-9 m/s) or the rudder needed is beyond the ship's. */
fw_status fw_mmg_steady_wind(const fw_ship *s, double n, double ce, double cn, double speed,
                             double from, fw_mmg_state *x, fw_error *err);

/* Propeller speed (rev/s) that balances surge in straight running at U (m/s):
 * X_H(U, 0, 0) + X_P = 0.  Fails (FW_ERUN) if no positive solution exists. */
fw_status fw_mmg_propeller_for_speed(const fw_ship *ship, double U, double *n, fw_error *err);

/* Straight, steady running at speed U on heading psi from (east, north). */
fw_mmg_state fw_mmg_straight(double U, double east, double north, double psi);

#endif
