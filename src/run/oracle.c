#include "run/oracle.h"

#include <math.h>

#include "avoid/encounter.h"
#include "core/units.h"
#include "dynamics/stepper.h"

fw_oracle_def fw_default_oracle_def(void)
{
    return (fw_oracle_def){.t_act = 0.0, .helm = 0.0, .step = 1.0, .after = 0.0};
}

/* One manoeuvre: smallest normalised domain radius and centre distance. */
static fw_status follow(const fw_scenario *s, const fw_oracle_def *def, double helm,
                        double alteration, double prop, double *lam_out, double *dist_out,
                        fw_error *err)
{
    fw_stepper_def sd = fw_default_stepper_def();
    fw_stepper *st;
    fw_status rc = fw_stepper_create(&s->ship, &sd, &st, err);
    if (rc)
        return rc;
    fw_mmg_state x0 = fw_mmg_straight(s->speed, s->east, s->north, s->course);
    if ((rc = fw_stepper_start(st, 0.0, &x0, prop, err)))
        goto out;
    double t_end = def->after > 0.0 ? fmin(s->duration, def->t_act + def->after) : s->duration;
    double lam = INFINITY, dist = INFINITY, psi_hold = s->course;
    bool turning = false, steady = alteration <= 0.0;
    long n = lround(t_end / def->step);
    for (long k = 0; k <= n; k++) {
        double t = k * def->step;
        const fw_mmg_state *x = fw_stepper_state(st);
        for (int i = 0; i < s->n_targets; i++) {
            const fw_scn_target *g = &s->targets[i];
            fw_target tg = {.east = g->east + g->speed * sin(g->course) * t,
                            .north = g->north + g->speed * cos(g->course) * t,
                            .course = g->course, .speed = g->speed, .length = g->length,
                            .breadth = g->breadth};
            lam = fmin(lam, fw_domain_lambda(&s->helm.domain, x->east, x->north, x->psi, &tg));
            dist = fmin(dist, hypot(tg.east - x->east, tg.north - x->north));
        }
        if (k == n)
            break;
        double order = 0.0;
        if (!steady && t >= def->t_act) {
            turning = true;
            if (fabs(x->psi - s->course) >= alteration) {
                steady = true;
                psi_hold = s->course + copysign(alteration, helm);
            }
        }
        if (turning && !steady)
            order = helm;
        else if (steady && alteration > 0.0) /* hold the new heading: PD, 1 deg/deg, 20 s */
            order = fmax(-fabs(helm), fmin(fabs(helm), -(x->psi - psi_hold) - 20.0 * x->r));
        fw_stepper_set_helm(st, order);
        if ((rc = fw_stepper_advance(st, def->step, err)))
            break;
    }
    *lam_out = lam;
    *dist_out = dist;
out:
    fw_stepper_destroy(st);
    return rc;
}

fw_status fw_oracle_best(const fw_scenario *s, const fw_oracle_def *def, fw_oracle_result *out,
                         fw_error *err)
{
    if (!(def->step > 0.0) || def->t_act < 0.0)
        return fw_fail(err, FW_EINPUT, "oracle: need step > 0 and t_act >= 0");
    double helm = def->helm > 0.0 ? fmin(def->helm, s->ship.rudder_max) : s->ship.rudder_max;
    double prop;
    fw_status rc = fw_mmg_propeller_for_speed(&s->ship, s->speed, &prop, err);
    if (rc)
        return rc;
    *out = (fw_oracle_result){.best_lambda = -1.0, .best_dist = 0.0};
    for (int side = 0; side <= 2; side++) {
        int nalt = side == 0 ? 1 : 12;
        for (int a = 1; a <= nalt; a++) {
            double alt = side == 0 ? 0.0 : fw_deg_to_rad(15.0 * a);
            double h = side == 2 ? -helm : helm, lam, dist;
            if ((rc = follow(s, def, h, alt, prop, &lam, &dist, err)))
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
