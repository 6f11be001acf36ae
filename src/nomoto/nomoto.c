#include "nomoto/nomoto.h"

#include <math.h>
#include <stddef.h>

fw_status fw_nomoto_indices_at(const fw_nomoto_kb *kb, double U_kn, double helm_deg,
                               fw_nomoto_indices *out, fw_error *err)
{
    if (!kb->present)
        return fw_fail(err, FW_EINPUT, "the ship file has no nomoto: knowledge base");
    double d = fabs(helm_deg);
    double d_min = kb->rudder_min_deg > 1.0 ? kb->rudder_min_deg : 1.0;
    if (d < d_min)
        d = d_min;
    double U = U_kn < 1.0 ? 1.0 : U_kn;
    out->K = fw_nomoto_index_eval(&kb->K, U, d);
    out->T1 = fw_nomoto_index_eval(&kb->T1, U, d);
    out->T2 = fw_nomoto_index_eval(&kb->T2, U, d);
    out->T3 = fw_nomoto_index_eval(&kb->T3, U, d);
    out->U_kn = U;
    out->d_deg = d;
    /* a small tolerance so the fitted grid's own end points count as inside */
    out->speed_in_range = U >= kb->speed_min_kn - 1e-9 && U <= kb->speed_max_kn + 1e-9;
    out->rudder_in_range = fabs(helm_deg) >= kb->rudder_min_deg - 1e-9 &&
                           fabs(helm_deg) <= kb->rudder_max_deg + 1e-9;
    if (!(out->K > 0.0) || !(out->T1 > 0.0) || !(out->T2 > 0.0) || !isfinite(out->T3))
        return fw_fail(err, FW_ERUN,
                       "Nomoto indices at %.2f kn, %.1f deg are not a stable system "
                       "(K %.4g, T1 %.4g, T2 %.4g): the knowledge base is extrapolated too far",
                       U, d, out->K, out->T1, out->T2);
    return FW_OK;
}

fw_kb_speed fw_nomoto_kb_speed(const fw_nomoto_kb *kb, double U_kn)
{
    if (!kb->present || (U_kn >= kb->speed_min_kn - 1e-9 && U_kn <= kb->speed_max_kn + 1e-9))
        return FW_KB_SPEED_IN;
    if (U_kn < kb->speed_min_kn / FW_KB_SPEED_MARGIN - 1e-9 ||
        U_kn > kb->speed_max_kn * FW_KB_SPEED_MARGIN + 1e-9)
        return FW_KB_SPEED_REFUSED;
    return FW_KB_SPEED_OUTSIDE;
}

double fw_nomoto_phi(double T1, double T2, double t)
{
    double dT = T1 - T2;
    double x = t * dT / (T1 * T2);
    /* Near T1 = T2 the difference of exponentials cancels; there the series of
     * expm1(x)/x (error below x^4/120 ~ 1e-14 for |x| < 1e-3) gives the limit
     * t exp(-t/T2)/(T1 T2) and its first corrections.  Away from it the direct
     * difference loses at most eps/|x| ~ 1e-13 relative. */
    if (fabs(x) < 1e-3) {
        double s = 1.0 + x * (0.5 + x * (1.0 / 6.0 + x / 24.0));
        return exp(-t / T2) * t / (T1 * T2) * s;
    }
    return (exp(-t / T1) - exp(-t / T2)) / dT;
}

void fw_nomoto_piece_init(fw_nomoto_piece *p, const fw_nomoto_indices *ix, double delta0,
                          double rho, double r0, double v0)
{
    double T1 = ix->T1, T2 = ix->T2;
    p->T1 = T1;
    p->T2 = T2;
    /* forcing a + b t with a = K (delta0 + T3 rho), b = K rho; the linear
     * particular solution is r_p = (a - b (T1 + T2)) + b t */
    double a = ix->K * (delta0 + ix->T3 * rho);
    p->b = ix->K * rho;
    p->c0 = a - p->b * (T1 + T2);
    p->h0 = r0 - p->c0;
    p->h1 = v0 - p->b;
    p->h2 = -(p->h0 + (T1 + T2) * p->h1) / (T1 * T2);
}

void fw_nomoto_piece_eval(const fw_nomoto_piece *p, double t, double *r, double *rdot,
                          double *turned)
{
    /* Any homogeneous solution with value y0 and slope y1 at 0 is
     * y0 e2 + T1 (T2 y1 + y0) phi(t): the two-exponential solution rewritten
     * so that it has no 1/(T1 - T2) left outside phi.  Its integral follows
     * from integrating the ODE once. */
    double T1 = p->T1, T2 = p->T2;
    double e2 = exp(-t / T2), ph = fw_nomoto_phi(T1, T2, t);
    double h = p->h0 * e2 + T1 * (T2 * p->h1 + p->h0) * ph;
    double hd = p->h1 * e2 + T1 * (T2 * p->h2 + p->h1) * ph;
    double H = -T1 * T2 * (hd - p->h1) - (T1 + T2) * (h - p->h0);
    if (r)
        *r = p->c0 + p->b * t + h;
    if (rdot)
        *rdot = p->b + hd;
    if (turned)
        *turned = p->c0 * t + 0.5 * p->b * t * t + H;
}

double fw_nomoto_step_rate(const fw_nomoto_indices *ix, double delta, double t)
{
    /* A step of delta at t = 0 is an impulse in delta': it leaves r(0+) = 0
     * and kicks r'(0+) to K T3 delta / (T1 T2); after it the rudder is held. */
    fw_nomoto_piece p;
    fw_nomoto_piece_init(&p, ix, delta, 0.0, 0.0, ix->K * ix->T3 * delta / (ix->T1 * ix->T2));
    double r;
    fw_nomoto_piece_eval(&p, t, &r, NULL, NULL);
    return r;
}
