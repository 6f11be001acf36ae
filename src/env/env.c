/* env.c - current and wind fields (env.h). */
#include "env/env.h"

#include <math.h>

#include "core/units.h"

fw_env fw_default_env(void)
{
    return (fw_env){.current = {.kind = FW_FIELD_NONE}, .wind = {.kind = FW_FIELD_NONE}};
}

fw_current fw_current_uniform(double speed, double set)
{
    return (fw_current){.kind = FW_FIELD_UNIFORM, .east = speed * sin(set),
                        .north = speed * cos(set)};
}

fw_current fw_current_tidal(double rate, double set, double period, double t_max)
{
    return (fw_current){.kind = FW_FIELD_TIDAL, .set = set, .rate = rate, .period = period,
                        .t_max = t_max};
}

static fw_status check_current(const fw_current *c, fw_error *err)
{
    switch (c->kind) {
    case FW_FIELD_NONE:
        return FW_OK;
    case FW_FIELD_UNIFORM:
        if (!isfinite(c->east) || !isfinite(c->north))
            return fw_fail(err, FW_EINPUT, "current: velocity (%g, %g) m/s is not finite",
                           c->east, c->north);
        return FW_OK;
    case FW_FIELD_TIDAL:
        if (!isfinite(c->set) || !(c->rate >= 0.0) || !isfinite(c->rate) ||
            !(c->period > 0.0) || !isfinite(c->period) || !isfinite(c->t_max))
            return fw_fail(err, FW_EINPUT,
                           "tidal current: set %g rad, rate %g m/s, period %g s, t_max %g s: "
                           "needs a finite set and t_max, a rate >= 0 and a period > 0",
                           c->set, c->rate, c->period, c->t_max);
        return FW_OK;
    }
    return fw_fail(err, FW_EINPUT, "current: unknown kind %d", (int)c->kind);
}

fw_status fw_env_check(const fw_env *e, fw_error *err)
{
    fw_status st = check_current(&e->current, err);
    if (st)
        return st;
    const fw_wind *w = &e->wind;
    if (w->kind == FW_FIELD_NONE)
        return FW_OK;
    if (w->kind != FW_FIELD_UNIFORM)
        return fw_fail(err, FW_EINPUT, "wind: kind %d is not none or uniform", (int)w->kind);
    if (!(w->speed >= 0.0) || !isfinite(w->speed) || !isfinite(w->from))
        return fw_fail(err, FW_EINPUT, "wind: speed %g m/s from %g rad: needs a finite speed >= 0",
                       w->speed, w->from);
    return FW_OK;
}

/* The tidal stream's phase at t, rad. */
static double tidal_phase(const fw_current *c, double t)
{
    return 2.0 * FW_PI * (t - c->t_max) / c->period;
}

void fw_current_at(const fw_current *c, double east, double north, double t, double *ve,
                   double *vn)
{
    (void)east, (void)north; /* no kind here varies in space */
    switch (c->kind) {
    case FW_FIELD_UNIFORM:
        *ve = c->east, *vn = c->north;
        return;
    case FW_FIELD_TIDAL: {
        double v = c->rate * cos(tidal_phase(c, t));
        *ve = v * sin(c->set), *vn = v * cos(c->set);
        return;
    }
    case FW_FIELD_NONE:
        break;
    }
    *ve = *vn = 0.0;
}

void fw_current_drift(const fw_current *c, double east, double north, double t0, double t1,
                      double *de, double *dn)
{
    if (c->kind == FW_FIELD_TIDAL) {
        /* rate period / 2 pi (sin phase(t1) - sin phase(t0)) */
        double s = c->rate * c->period / (2.0 * FW_PI) *
                   (sin(tidal_phase(c, t1)) - sin(tidal_phase(c, t0)));
        *de = s * sin(c->set), *dn = s * cos(c->set);
        return;
    }
    double ve, vn;
    fw_current_at(c, east, north, t0, &ve, &vn);
    *de = ve * (t1 - t0), *dn = vn * (t1 - t0);
}

bool fw_current_is_none(const fw_current *c)
{
    switch (c->kind) {
    case FW_FIELD_NONE:
        return true;
    case FW_FIELD_UNIFORM:
        return c->east == 0.0 && c->north == 0.0;
    case FW_FIELD_TIDAL:
        return c->rate == 0.0;
    }
    return false;
}

void fw_wind_at(const fw_wind *w, double east, double north, double t, double *speed,
                double *from)
{
    (void)east, (void)north, (void)t; /* uniform and steady: the only kind yet */
    if (w->kind == FW_FIELD_UNIFORM) {
        *speed = w->speed, *from = w->from;
        return;
    }
    *speed = 0.0, *from = 0.0;
}

bool fw_wind_is_calm(const fw_wind *w)
{
    return w->kind == FW_FIELD_NONE || w->speed == 0.0;
}

fw_status fw_env_check_vessel(const fw_env *e, const char *vessel, const fw_ship *ship, bool mmg,
                              fw_error *err)
{
    if (fw_wind_is_calm(&e->wind) || (mmg && ship->windage.present))
        return FW_OK;
    if (!mmg)
        return fw_fail(err, FW_EINPUT,
                       "vessel '%s' (ship '%s'): the world has a wind of %.3g m/s, but Nomoto "
                       "dynamics have no wind force; a wind would be ignored, so it is refused "
                       "(give the vessel MMG dynamics)",
                       vessel, ship->name, e->wind.speed);
    return fw_fail(err, FW_EINPUT,
                   "vessel '%s' (ship '%s'): the world has a wind of %.3g m/s, but the ship file "
                   "%s has no windage: section (type, A_F, A_L, s_L: ship/windage.h); a wind "
                   "would be ignored, so it is refused",
                   vessel, ship->name, e->wind.speed, ship->file);
}
