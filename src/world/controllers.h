/* controllers.h - the controllers a vessel can have (vessel.h).
 *
 *   policy      the paper's avoidance: assessment, helm search and the action
 *               and return policy of avoid/policy.h, every step, on what the
 *               vessel sees
 *   manoeuvre   a fixed manoeuvre, the oracle's (run/oracle.h): helm hard
 *               over to one side at t_act, held until the heading has changed
 *               by `alteration`, then that heading held by a PD (1 deg per
 *               deg, 20 s); alteration 0 keeps the helm amidships
 */
#ifndef FW_WORLD_CONTROLLERS_H
#define FW_WORLD_CONTROLLERS_H

#include "world/vessel.h"

typedef struct fw_policy_controller_def {
    const fw_ship *ship;        /* for the predicted tracks; must outlive the controller */
    fw_helm_def helm;
    fw_policy_def policy;
} fw_policy_controller_def;

fw_status fw_policy_controller_create(const fw_policy_controller_def *def,
                                      fw_controller **out, fw_error *err);
/* The policy's state (for tests that look inside). */
const fw_policy *fw_policy_controller_policy(const fw_controller *c);

typedef struct fw_manoeuvre_def {
    double t_act;       /* s */
    double helm;        /* rad, signed: + starboard */
    double course;      /* rad, the course the alteration is counted from */
    double alteration;  /* rad, > 0; 0 = keep the helm amidships */
} fw_manoeuvre_def;

fw_status fw_manoeuvre_controller_create(const fw_manoeuvre_def *def, fw_controller **out,
                                         fw_error *err);

#endif
