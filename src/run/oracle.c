/* oracle.c - the best fixed manoeuvre (oracle.h), each tried in a world of
 * its own: the kinematic source for the targets, the MMG ship under the
 * manoeuvre controller. */
#include "run/oracle.h"
#include "run/run.h"

#include <math.h>
#include <stddef.h>

#include "core/units.h"
#include "world/controllers.h"
#include "world/world.h"

fw_oracle_def fw_default_oracle_def(void)
{
    return (fw_oracle_def){.t_act = 0.0, .helm = 0.0, .step = 1.0, .after = 0.0};
}

/* The scenario's targets at constant velocity (all seen, whatever the range)
 * and the own ship under one fixed manoeuvre, in a world of their own. */
static fw_status make_world(const fw_scenario *s, double step, const fw_manoeuvre_def *md,
                            fw_world **w, fw_vessel **own, fw_error *err)
{
    fw_world_def wd = fw_default_world_def();
    wd.step = step;
    fw_controller *ctl = NULL;
    fw_status st;
    if ((st = fw_run_kinematic_source(s, step, INFINITY, &wd.source, err)) ||
        (st = fw_world_create(&wd, w, err)) ||
        (st = fw_manoeuvre_controller_create(md, &ctl, err)))
        return st;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &s->ship;
    vd.east = s->east;
    vd.north = s->north;
    vd.course = s->course;
    vd.speed = s->speed;
    vd.radius = INFINITY;
    vd.controller = ctl;
    fw_vessel_handle h;
    if ((st = fw_world_add_vessel(*w, &vd, &h, err)))
        return st;
    *own = fw_world_vessel(*w, h); /* never removed: borrowed for the run */
    return FW_OK;
}

/* One manoeuvre: smallest normalised domain radius and centre distance. */
static fw_status follow(const fw_scenario *s, const fw_oracle_def *def, double helm,
                        double alteration, double *lam_out, double *dist_out, fw_error *err)
{
    fw_manoeuvre_def md = {.t_act = def->t_act, .helm = helm, .course = s->course,
                           .alteration = alteration};
    fw_world *w = NULL;
    fw_vessel *own = NULL;
    fw_status rc = make_world(s, def->step, &md, &w, &own, err);
    if (!rc)
        rc = fw_world_start(w, err);
    double t_end = def->after > 0.0 ? fmin(s->duration, def->t_act + def->after) : s->duration;
    double lam = INFINITY, dist = INFINITY;
    long n = lround(t_end / def->step);
    for (long k = 0; !rc && k <= n; k++) {
        const fw_mmg_state *x = fw_vessel_motion(own);
        const fw_target *tg;
        const fw_assessment *as;
        int nt;
        fw_vessel_view(own, &tg, &as, &nt);
        for (int i = 0; i < nt; i++) {
            lam = fmin(lam, fw_domain_lambda(&s->helm.domain, x->east, x->north, x->psi, &tg[i]));
            dist = fmin(dist, hypot(tg[i].east - x->east, tg[i].north - x->north));
        }
        if (k < n)
            rc = fw_world_step(w, def->step, err);
    }
    fw_world_destroy(w);
    *lam_out = lam;
    *dist_out = dist;
    return rc;
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
