/* vessel_internal.h - the vessel as the world keeps it (internal to src/world). */
#ifndef FW_WORLD_VESSEL_INTERNAL_H
#define FW_WORLD_VESSEL_INTERNAL_H

#include "dynamics/stepper.h"
#include "env/env.h"
#include "nomoto/track.h"
#include "world/vessel.h"

struct fw_vessel {
    char id[FW_TARGET_ID_MAX];
    const fw_ship *ship;
    fw_dynamics_kind dyn;
    fw_vessel_role role;
    bool taken;                /* from the source, told where it is every step */
    double radius;
    const fw_env *env;         /* the world's */
    double t;                  /* s, the time of the motion state */
    double U0;                 /* m/s, the speed on a straight course */
    /* dynamics */
    fw_stepper *st;            /* MMG */
    double n_prop;             /* rev/s */
    double r_prev;             /* rad/s, before the last advance (for rdot) */
    bool advanced;             /* rdot is known once it has advanced */
    fw_track one;              /* Nomoto: one step of the predicted track */
    fw_own_state nom;          /* Nomoto: the state */
    /* the current refresh last found at (east, north) at t: the next step
     * starts there and then (vessel.c) */
    struct {
        bool valid;
        double t, east, north, ce, cn;
    } cur;
    /* MMG with windage in a wind: the steady leeway of straight running on
     * the heading psi at propeller n in the current (ce, cn) (x: u, vm,
     * delta; ok: found), made again when any of them has moved (vessel.c) */
    struct {
        bool valid, ok;
        double psi, n, ce, cn;
        fw_mmg_state x;
    } drift;
    /* what the others and the controller see */
    fw_mmg_state motion;
    fw_own_state own;
    fw_target record;
    const fw_predictor *pred; /* its predictor, in the record only when not steady */
    /* control */
    fw_controller *ctl;
    fw_decision d;
    /* the view of the last sensing: targets sorted by id, their assessments */
    fw_target *view;
    fw_assessment *as;
    int *order;
    const fw_lane_info **lanes; /* each viewed target's lane (decide(): world.c) */
    int n_view, cap;
    /* with a sensor (world.h own_sensing): what was there, sorted by id,
     * while the view is what the sensor knew of it */
    fw_target *truth;
    int n_truth;
    bool sensed;
};

/* Creates the dynamics and the first state in the environment env (which
 * must outlive the vessel); v->ctl is set by the caller. */
fw_status fw_vessel_init(fw_vessel *v, const fw_vessel_def *def, double dt, const fw_env *env,
                         fw_error *err);
void fw_vessel_free(fw_vessel *v);
/* Advances the dynamics by dt under the last decision's helm. */
fw_status fw_vessel_advance(fw_vessel *v, double dt, fw_error *err);
/* Room for n targets in the view. */
fw_status fw_vessel_reserve(fw_vessel *v, int n, fw_error *err);

#endif
