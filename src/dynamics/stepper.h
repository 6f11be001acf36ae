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
 *
 * In a current (env/env.h, the def's `current`) the state's u and vm are the
 * velocities through the WATER, and east, north the position over ground:
 * the hull, propeller and rudder forces depend on the relative velocity only,
 * so integrating it keeps the calm-water equations of motion unchanged, and
 * the position advances at the relative velocity turned to earth plus the
 * current at the ship.  Integrating the ground velocity instead would need
 * the current's rate of change in body axes, d(nu_c)/dt = [r v_c, -r u_c, 0]
 * plus R^T dV_c/dt, in the equations: for a uniform current these terms
 * cancel exactly in the relative form, ground = relative + current.  For a
 * current that changes in time (a tidal stream) the relative form is exact
 * too, because the horizontal pressure gradient that accelerates the water
 * also pushes the hull (the Froude-Krylov force, m dV_c/dt for a floating
 * hull of mass m = its displacement), so the hull's motion relative to the
 * water obeys the calm-water equations; Fossen's model (Handbook, 2011,
 * ch. 10.3), which leaves that force out, would add M_RB R^T dV_c/dt.  So
 * in any current uniform in space the ground track is the calm-water track
 * plus the water's drift, exactly (tests/test_env.c, to 0.1 m over an hour).
 * A field that varies in space adds (V_r . grad) V_c to what the hull sees
 * and is for the kind that brings it (env.h).  With no current the
 * right-hand side is the calm one, operation for operation.
 *
 * In a wind (the def's `wind`, not calm; the ship must have windage
 * particulars, ship/windage.h) Blendermann's forces from the apparent wind
 * (mmg.h fw_mmg_wind: true wind less the velocity over ground) are added to
 * the ship's.  The wind's speed and direction are inputs like the helm: held
 * between fw_stepper_set_wind calls (a gust, env.h), each change a
 * re-initialisation.  Still air: no wind term at all, the calm bits.
 */
#ifndef FW_STEPPER_H
#define FW_STEPPER_H

#include "core/error.h"
#include "dynamics/mmg.h"
#include "env/env.h"
#include "ship/ship.h"

typedef struct fw_stepper_def {
    double rtol;      /* relative tolerance */
    double atol_vel;  /* m/s and rad/s scaled: absolute tolerance on u, vm, r*L */
    double atol_pos;  /* m: absolute tolerance on east, north, and psi*L */
    double max_step;  /* s, 0 = no limit */
    fw_current current; /* the water's motion (none: calm water) */
    fw_wind wind;       /* the air's (none: still air; needs the ship's windage) */
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
/* The wind now (m/s, from rad), held until the next call; ignored (as is the
 * wind) when the def's wind is calm: a wind cannot start blowing later. */
void fw_stepper_set_wind(fw_stepper *st, double speed, double from);

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
