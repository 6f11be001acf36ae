/* stepper.h - a ship stepped in time: MMG + rudder servo, integrated by ARKODE.
 *
 * What a world's MMG vessel calls (world/vessel.c): set the helm order and
 * propeller speed, advance by dt, read the state.  The rudder follows the helm
 * order at the ship's rate limit up to its maximum angle.  The integrator
 * (ARKODE's explicit Runge-Kutta ERKStep, Cash-Karp 5(4); stepper.c says why
 * not CVODE) is re-initialised only where an input jumps (new helm order, new
 * propeller speed) or where the rudder reaches its order: that instant is
 * known in advance (the rudder angle is piecewise linear in time), so the
 * integration stops there exactly, with no root finding; in between it keeps
 * its step size across calls.
 */
#ifndef FW_STEPPER_H
#define FW_STEPPER_H

#include "core/error.h"
#include "dynamics/mmg.h"
#include "ship/ship.h"

typedef struct fw_stepper_def {
    double rtol;      /* relative tolerance */
    double atol_vel;  /* m/s and rad/s scaled: absolute tolerance on u, vm, r*L */
    double atol_pos;  /* m: absolute tolerance on east, north, and psi*L */
    double max_step;  /* s, 0 = no limit */
} fw_stepper_def;

fw_stepper_def fw_default_stepper_def(void);

typedef struct fw_stepper fw_stepper;

/* The ship must outlive the stepper (it is not copied). */
fw_status fw_stepper_create(const fw_ship *ship, const fw_stepper_def *def, fw_stepper **out,
                            fw_error *err);
void fw_stepper_destroy(fw_stepper *st);

/* Sets the state at time t0 with propeller speed n (rev/s); the helm order is
 * set to the state's rudder angle. */
fw_status fw_stepper_start(fw_stepper *st, double t0, const fw_mmg_state *s0, double n,
                           fw_error *err);

/* Helm order (rad, clamped to +-rudder_max).  Takes effect at the current time. */
void fw_stepper_set_helm(fw_stepper *st, double helm);
void fw_stepper_set_propeller(fw_stepper *st, double n);

/* Advances by dt seconds.  FW_ERUN with a message if the integration fails. */
fw_status fw_stepper_advance(fw_stepper *st, double dt, fw_error *err);

const fw_mmg_state *fw_stepper_state(const fw_stepper *st);
double fw_stepper_time(const fw_stepper *st);
double fw_stepper_helm(const fw_stepper *st);
double fw_stepper_propeller(const fw_stepper *st);

/* Counters for benchmarks: right-hand-side evaluations and re-initialisations. */
long fw_stepper_rhs_evals(const fw_stepper *st);
long fw_stepper_reinits(const fw_stepper *st);

#endif
