/* oracle.c - the best fixed manoeuvre (oracle.h), each tried in a run of its
 * own (run.h): the kinematic source for the targets, the MMG ship under the
 * manoeuvre controller, no files. */
#include "run/oracle.h"
#include "run/run.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "core/units.h"
#include "world/controllers.h"
#include "world/world.h"

fw_oracle_def fw_default_oracle_def(void)
{
    return (fw_oracle_def){.t_act = 0.0, .helm = 0.0, .step = 1.0, .after = 0.0};
}

/* One manoeuvre: smallest normalised domain radius and centre distance, over
 * all targets and instants.  A run (run.h) of the scenario as the oracle sails
 * it: every target at constant velocity (the kinematic source) and seen
 * whatever the range, blind traffic, the MMG ship under the fixed manoeuvre,
 * steps of def->step to t_act + after, no files.  Its encounter book measures
 * what the oracle asks (min_lambda, min_dist: the run's own domain reading). */
static fw_status follow(const fw_scenario *s, const fw_oracle_def *def, double helm,
                        double alteration, double *lam_out, double *dist_out, fw_error *err)
{
    *lam_out = *dist_out = INFINITY;
    fw_scenario *sail = malloc(sizeof *sail);
    if (!sail)
        return fw_fail(err, FW_ERUN, "oracle: out of memory");
    *sail = *s;
    sail->step = def->step;
    sail->record_every = def->step;
    sail->duration = def->after > 0.0 ? fmin(s->duration, def->t_act + def->after) : s->duration;
    sail->radius = INFINITY;
    sail->tracks[0] = '\0';
    sail->ais.file[0] = '\0';
    sail->survey = false;
    sail->nomoto_plant = false;
    sail->reactions = fw_default_world_def().reactions;
    fw_manoeuvre_def md = {.t_act = def->t_act, .helm = helm, .course = s->course,
                           .alteration = alteration};
    fw_run_def rd = fw_default_run_def();
    rd.scenario = sail;
    rd.dir = NULL;
    rd.traffic = FW_RUN_TRAFFIC_KINEMATIC;
    fw_status st = fw_manoeuvre_controller_create(&md, &rd.controller, err);
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int n = 0;
    if (!st)
        st = fw_run_scenario(&rd, &sum, &e, &n, err);
    for (int i = 0; !st && i < n; i++) {
        *lam_out = fmin(*lam_out, e[i].min_lambda);
        *dist_out = fmin(*dist_out, e[i].min_dist);
    }
    free(e);
    free(sail);
    return st;
}

fw_status fw_oracle_best(const fw_scenario *s, const fw_oracle_def *def, fw_oracle_result *out,
                         fw_error *err)
{
    if (!(def->step > 0.0) || def->t_act < 0.0)
        return fw_fail(err, FW_EINPUT, "oracle: need step > 0 and t_act >= 0");
    double helm = def->helm > 0.0 ? fmin(def->helm, s->ship.rudder_max) : s->ship.rudder_max;
    fw_status rc;
    *out = (fw_oracle_result){.best_lambda = -1.0, .best_dist = 0.0};
    for (int side = 0; side <= 2; side++) {
        int nalt = side == 0 ? 1 : 12;
        for (int a = 1; a <= nalt; a++) {
            double alt = side == 0 ? 0.0 : fw_deg_to_rad(15.0 * a);
            double h = side == 2 ? -helm : helm, lam, dist;
            if ((rc = follow(s, def, h, alt, &lam, &dist, err)))
                return rc;
            out->manoeuvres++;
            if (lam > out->best_lambda) {
                out->best_lambda = lam;
                out->best_dist = dist;
                out->side = side == 0 ? 0 : side == 1 ? 1 : -1;
                out->alteration = alt;
            }
        }
    }
    return FW_OK;
}
