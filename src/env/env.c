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
    return fw_current_tidal_sn(rate, rate, set, period, t_max, 0.0);
}

fw_current fw_current_tidal_sn(double spring, double neap, double set, double period,
                               double t_max, double t_spring)
{
    return (fw_current){.kind = FW_FIELD_TIDAL, .set = set, .rate = spring, .period = period,
                        .t_max = t_max, .neap_rate = neap,
                        .spring_period = FW_SPRING_NEAP_S, .t_spring = t_spring};
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
        if (!(c->neap_rate >= 0.0 && c->neap_rate <= c->rate) || !(c->spring_period > 0.0) ||
            !isfinite(c->spring_period) || !isfinite(c->t_spring))
            return fw_fail(err, FW_EINPUT,
                           "tidal current: neap rate %g m/s (spring %g), spring-neap period %g "
                           "s, t_spring %g s: needs 0 <= neap <= spring, a period > 0",
                           c->neap_rate, c->rate, c->spring_period, c->t_spring);
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
    if (!(w->gust_intensity >= 0.0 && w->gust_intensity <= FW_GUST_INTENSITY_MAX) ||
        (w->gust_intensity > 0.0 &&
         !(w->gust_time >= FW_GUST_TIME_MIN_S && w->gust_time <= FW_GUST_TIME_MAX_S)))
        return fw_fail(err, FW_EINPUT,
                       "wind: gust intensity %g, time %g s: needs an intensity of 0 to %g and, "
                       "with gusts, a time of %g to %g s",
                       w->gust_intensity, w->gust_time, FW_GUST_INTENSITY_MAX,
                       FW_GUST_TIME_MIN_S, FW_GUST_TIME_MAX_S);
    return FW_OK;
}

/* The tidal stream's phase at t, rad. */
static double tidal_phase(const fw_current *c, double t)
{
    return 2.0 * FW_PI * (t - c->t_max) / c->period;
}

static bool modulated(const fw_current *c) { return c->neap_rate != c->rate; }

/* Its spring-neap phase at t, rad. */
static double spring_phase(const fw_current *c, double t)
{
    return 2.0 * FW_PI * (t - c->t_spring) / c->spring_period;
}

/* Its greatest rate A(t) (env.h); the rate itself without modulation. */
static double tidal_rate(const fw_current *c, double t)
{
    if (!modulated(c))
        return c->rate;
    return 0.5 * (c->rate + c->neap_rate) +
           0.5 * (c->rate - c->neap_rate) * cos(spring_phase(c, t));
}

/* The modulated stream's integral of A(t) cos(phase) up to t (a primitive):
 * m/w sin(p) + a/2 (sin(p + q)/(w + W) + sin(p - q)/(w - W)), p and q the
 * tidal and spring-neap phases, w and W their rates. */
static double tidal_primitive(const fw_current *c, double t)
{
    double m = 0.5 * (c->rate + c->neap_rate), a = 0.5 * (c->rate - c->neap_rate);
    double w = 2.0 * FW_PI / c->period, W = 2.0 * FW_PI / c->spring_period;
    double p = tidal_phase(c, t), q = spring_phase(c, t);
    return m / w * sin(p) + 0.5 * a * (sin(p + q) / (w + W) + sin(p - q) / (w - W));
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
        double v = tidal_rate(c, t) * cos(tidal_phase(c, t));
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
    if (c->kind == FW_FIELD_TIDAL && modulated(c)) {
        double s = tidal_primitive(c, t1) - tidal_primitive(c, t0);
        *de = s * sin(c->set), *dn = s * cos(c->set);
        return;
    }
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
        return c->rate == 0.0; /* and so the neap rate */
    }
    return false;
}

void fw_wind_at(const fw_wind *w, double east, double north, double t, double *speed,
                double *from)
{
    (void)east, (void)north, (void)t; /* uniform; its gust is the world's now */
    if (w->kind == FW_FIELD_UNIFORM) {
        *speed = w->gust_intensity > 0.0 ? fmax(0.0, w->speed + w->gust) : w->speed;
        *from = w->from;
        return;
    }
    *speed = 0.0, *from = 0.0;
}

bool fw_wind_gusty(const fw_wind *w) { return !fw_wind_is_calm(w) && w->gust_intensity > 0.0; }

void fw_wind_gust_start(fw_wind *w, fw_rng *r)
{
    if (fw_wind_gusty(w))
        w->gust = w->gust_intensity * w->speed * fw_rng_normal(r);
}

void fw_wind_gust_step(fw_wind *w, double dt, fw_rng *r)
{
    if (!fw_wind_gusty(w))
        return;
    double a = exp(-dt / w->gust_time), sigma = w->gust_intensity * w->speed;
    w->gust = a * w->gust + sigma * sqrt(1.0 - a * a) * fw_rng_normal(r);
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
