/* vessel.h - a ship the world steps: static data, dynamics, a controller, a predictor.
 *
 * A vessel is owned by its world (world.h).  Each has
 *   static data   id, the ship's particulars (ship/ship.h), its sight radius
 *   dynamics      FW_DYN_MMG: the MMG model with the rudder servo, integrated
 *                 by ARKODE (dynamics/stepper.h), the own ship's;
 *                 FW_DYN_NOMOTO: the ship's Nomoto model advanced one step of
 *                 the predicted track (nomoto/track.h), a light plant for tests
 *                 and for the reactive background ships to come
 *   a controller  what turns what the vessel senses into a helm order: the
 *                 avoidance policy (world/controllers.h), a fixed manoeuvre
 *                 (the oracle's), or none (helm amidships)
 *   a predictor   how the others expect it to move (geom/target.h): NULL,
 *                 constant velocity
 *
 * What others see of it is its record (fw_target): hull centre, course and
 * speed over ground, heading and speed through the water, Loa and B.  In a
 * current (the world's, env/env.h) an MMG vessel moves through the water and
 * is carried by it (dynamics/stepper.h); a Nomoto vessel's step is carried by
 * the current at its start.
 *
 * Wind drift: the state an MMG vessel with windage gives its controller in
 * a wind (fw_vessel_own_state) carries the steady drift of straight running
 * on its present heading under the world's MEAN wind (gusts left out) at
 * its present propeller revolutions, the MMG model's steady state
 * (dynamics/mmg.h fw_mmg_steady_wind: surge, sway and the rudder that holds
 * the heading, forces and moment balanced, Blendermann's wind from the ship
 * file's windage): the sway across the heading is added to the current it
 * knows (cur_e, cur_n: the prediction carries it as the water), the drift
 * angle is taken beyond that leeway's (beta), the straight-course speed is
 * the surge the wind leaves (U0), and delta_wind is the rudder that holds
 * the heading, beyond which the (windless) Nomoto model turns; the policy's
 * heading autopilot adds it to its order (avoid/policy.h), and so does the
 * autopilot the prediction follows (nomoto/track.h), so that the heading it
 * holds is the one asked for, not one off by delta_wind / kp.  Made again
 * when the heading moves 0.25 deg, the current 0.01 m/s or the propeller
 * changes.  In still air, for a ship without windage and for a Nomoto
 * vessel, nothing: the state as before to the bit.  Approximations: the
 * drift of the present heading is held over the whole prediction (in a turn
 * the relative wind and so the leeway change; not followed); where no
 * steady straight running exists (the rudder needed beyond the ship's) no
 * drift.  tests/test_env_predict.c: c3-mmg at 12 kn holding 000 in 20-30 kn
 * beam and quartering winds, the policy's hold prediction is 0.6-3.5 m off
 * the MMG ship over 10 minutes, 148-775 m without the drift.
 */
#ifndef FW_WORLD_VESSEL_H
#define FW_WORLD_VESSEL_H

#include "avoid/policy.h"
#include "dynamics/mmg.h"
#include "geom/target.h"
#include "ship/ship.h"

typedef enum fw_dynamics_kind { FW_DYN_MMG, FW_DYN_NOMOTO } fw_dynamics_kind;

/* What a vessel is to the world (world.h): FW_ROLE_OWN, the own ship (at
 * most one: placed into the traffic source, the one whose sight the source's
 * around() serves and the records and the survey follow), or FW_ROLE_OTHER,
 * another ship fairway steps (seen by all, seeing the source's ships through
 * within()). */
typedef enum fw_vessel_role { FW_ROLE_OWN, FW_ROLE_OTHER } fw_vessel_role;

/* What a controller is given each step. */
typedef struct fw_sense {
    double t;                  /* s */
    const fw_own_state *own;   /* the vessel, as the predictor needs it */
    const fw_target *targets;  /* the ships it sees, sorted by id */
    int n;
    fw_assessment *as;         /* room for n assessments (the controller may fill them) */
    int *order;                /* room for 2 n ints (scratch for the ranking) */
    /* each target's lane as the traffic source says it (traffic/lane.h;
     * NULL entries: none known), NULL when the world has no lanes */
    const fw_lane_info *const *lanes;
} fw_sense;

typedef struct fw_controller fw_controller;

typedef struct fw_controller_ops {
    const char *name;
    /* The order for the next step, and why, into d (d->helm the helm, rad,
     * signed; the rest as fw_decision says, or zero).  Fills in->as[0..n-1]
     * if it assesses the targets (and then returns true from assesses). */
    fw_status (*decide)(fw_controller *c, const fw_sense *in, fw_decision *d, fw_error *err);
    bool assesses;
    void (*destroy)(fw_controller *c);
} fw_controller_ops;

/* Every controller begins with this header. */
struct fw_controller {
    const fw_controller_ops *ops;
};

/* Safe on NULL. */
void fw_controller_destroy(fw_controller *c);

typedef struct fw_vessel_def {
    const char *id;            /* 1..63 characters, unique in the world */
    fw_vessel_role role;
    const fw_ship *ship;       /* must outlive the world */
    fw_dynamics_kind dynamics;
    /* start: MMG from straight running at speed (through the water) on
     * course (its heading); Nomoto from `start` as given (when start_state
     * is set) */
    double east, north, course, speed;
    const fw_own_state *start_state; /* FW_DYN_NOMOTO: the exact start (NULL: from the above) */
    double radius;             /* m, sight (other vessels, hull centre to hull centre) */
    fw_controller *controller; /* taken over; NULL = helm amidships */
    const fw_predictor *predictor; /* NULL: constant velocity */
} fw_vessel_def;

/* The own ship (id "own", FW_ROLE_OWN), MMG, at rest at the origin heading
 * north, sight 6 nm, no controller. */
fw_vessel_def fw_default_vessel_def(void);

typedef struct fw_vessel fw_vessel;

const char *fw_vessel_id(const fw_vessel *v);
const fw_ship *fw_vessel_ship(const fw_vessel *v);
/* Motion state: position, heading, u, v (through the water), r, rudder
 * (Nomoto: u = U, v = 0). */
const fw_mmg_state *fw_vessel_motion(const fw_vessel *v);
/* What the predictor and the policy need of it. */
const fw_own_state *fw_vessel_own_state(const fw_vessel *v);
/* Its record as the others see it. */
const fw_target *fw_vessel_record(const fw_vessel *v);
double fw_vessel_propeller(const fw_vessel *v); /* rev/s (MMG), 0 (Nomoto) */
/* The last decision, what it saw then, and (if the controller assesses) the
 * assessment of each target seen, all of the same instant. */
const fw_decision *fw_vessel_decision(const fw_vessel *v);
void fw_vessel_view(const fw_vessel *v, const fw_target **targets, const fw_assessment **as,
                    int *n);
/* The ships that were within its sight at that instant, as they were, sorted
 * by id: the view itself, unless the vessel has a sensor (world.h
 * own_sensing), when the view is what it knew and *sensed is true. */
void fw_vessel_truth(const fw_vessel *v, const fw_target **targets, int *n, bool *sensed);
fw_controller *fw_vessel_controller(fw_vessel *v);
fw_vessel_role fw_vessel_role_of(const fw_vessel *v);
/* Taken from the traffic source (world.h fw_world_take)? */
bool fw_vessel_taken(const fw_vessel *v);

#endif
