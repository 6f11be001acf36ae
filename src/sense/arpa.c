/* arpa.c - radar plots and the alpha-beta tracker: see arpa.h. */
#include "sense/arpa.h"

#include <math.h>

#include "core/units.h"

fw_radar_def fw_default_radar_def(void)
{
    double a = 0.5;
    return (fw_radar_def){
        .range_sd = 15.0,
        .bearing_sd = fw_deg_to_rad(0.5),
        .scan = 2.5,
        .alpha = a,
        .beta = a * a / (2.0 - a),
    };
}

void fw_radar_plot(const fw_radar_def *def, fw_rng *rng, double oe, double on, double te,
                   double tn, double *ze, double *zn)
{
    double de = te - oe, dn = tn - on;
    double r = hypot(de, dn) + def->range_sd * fw_rng_normal(rng);
    double b = atan2(de, dn) + def->bearing_sd * fw_rng_normal(rng);
    *ze = oe + r * sin(b);
    *zn = on + r * cos(b);
}

void fw_ab_update(fw_ab_track *tr, const fw_radar_def *def, double t, double ze, double zn)
{
    double dt = t - tr->t;
    if (tr->plots == 0 || dt <= 0.0) {
        *tr = (fw_ab_track){.t = t, .e = ze, .n = zn, .plots = tr->plots + 1};
        return;
    }
    if (tr->plots == 1) {
        tr->ve = (ze - tr->e) / dt;
        tr->vn = (zn - tr->n) / dt;
        tr->e = ze;
        tr->n = zn;
    } else {
        double pe = tr->e + tr->ve * dt, pn = tr->n + tr->vn * dt;
        double re = ze - pe, rn = zn - pn;
        tr->e = pe + def->alpha * re;
        tr->n = pn + def->alpha * rn;
        tr->ve += def->beta / dt * re;
        tr->vn += def->beta / dt * rn;
    }
    tr->t = t;
    tr->plots++;
}

void fw_ab_predict(const fw_ab_track *tr, double t, double *e, double *n)
{
    *e = tr->e + tr->ve * (t - tr->t);
    *n = tr->n + tr->vn * (t - tr->t);
}

double fw_ab_position_vrr(double a, double b)
{
    return (2.0 * a * a + 2.0 * b - 3.0 * a * b) / (a * (4.0 - 2.0 * a - b));
}

double fw_ab_accel_lag(double a, double b, double acc, double T)
{
    return -(1.0 - a) * acc * T * T / b;
}
