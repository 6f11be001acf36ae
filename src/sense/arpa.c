/* arpa.c - radar plots and the alpha-beta tracker: see arpa.h. */
#include "sense/arpa.h"

#include <math.h>

#include "core/units.h"

fw_radar_def fw_default_radar_def(void)
{
    double a = 0.1;
    return (fw_radar_def){
        .range_sd = 15.0,
        .bearing_sd = fw_deg_to_rad(0.5),
        .scan = 2.5,
        .alpha = a,
        .beta = a * a / (2.0 - a),
        .antenna = 15.0,
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
        /* the least-squares gains of plot k until they fall to the steady ones */
        double k = tr->plots, g = 2.0 * (2.0 * k + 1.0) / ((k + 2.0) * (k + 1.0));
        double h = 6.0 / ((k + 2.0) * (k + 1.0));
        if (g <= def->alpha)
            g = def->alpha, h = def->beta;
        double pe = tr->e + tr->ve * dt, pn = tr->n + tr->vn * dt;
        double re = ze - pe, rn = zn - pn;
        tr->e = pe + g * re;
        tr->n = pn + g * rn;
        tr->ve += h / dt * re;
        tr->vn += h / dt * rn;
    }
    tr->t = t;
    tr->plots++;
}

void fw_ab_predict(const fw_ab_track *tr, double t, double *e, double *n)
{
    *e = tr->e + tr->ve * (t - tr->t);
    *n = tr->n + tr->vn * (t - tr->t);
}

double fw_radar_class_range(double length, double *height)
{
    /* MSC.192(79) Table 2 (X-band), the class by length an estimate (arpa.h) */
    static const struct { double length, range_nm, height; } kClass[] = {
        {100.0, 11.0, 10.0}, {45.0, 8.0, 5.0}, {15.0, 5.0, 4.0}, {0.0, 3.4, 2.0}};
    int i = 0;
    while (i < 3 && length < kClass[i].length)
        i++;
    *height = kClass[i].height;
    return fw_nm_to_m(kClass[i].range_nm);
}

double fw_radar_horizon(double ha, double ht)
{
    return fw_nm_to_m(2.21 * (sqrt(fmax(ha, 0.0)) + sqrt(fmax(ht, 0.0))));
}

double fw_radar_pd(const fw_radar_def *def, double range, double length)
{
    /* MSC.192(79) 5.3.1.1: Pfa 1e-4, Pd 0.8 at R0; ln(Pfa) and S0 = ln(Pfa) /
     * ln(Pd0) - 1 as constants (a scan's cost: one exp, not two logs and a
     * pow) */
    static const double kLnPfa = -9.210340371976184; /* ln 1e-4 */
    static const double kS0 = -9.210340371976184 / -0.2231435513142098 - 1.0; /* ln 0.8 */
    double ht, r0 = fw_radar_class_range(length, &ht);
    if (range > fw_radar_horizon(def->antenna, ht))
        return 0.0;
    if (range <= 0.0)
        return 1.0;
    double q = r0 / range;
    return exp(kLnPfa / (1.0 + kS0 * q * q * q * q));
}

double fw_ab_position_vrr(double a, double b)
{
    return (2.0 * a * a + 2.0 * b - 3.0 * a * b) / (a * (4.0 - 2.0 * a - b));
}

double fw_ab_accel_lag(double a, double b, double acc, double T)
{
    return -(1.0 - a) * acc * T * T / b;
}
