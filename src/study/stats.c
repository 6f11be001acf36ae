#include "study/stats.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

double fw_mean(const double *x, int n)
{
    double s = 0.0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (!isnan(x[i])) {
            s += x[i];
            k++;
        }
    return k ? s / k : NAN;
}

double fw_sd(const double *x, int n)
{
    /* two passes: the sum of squared deviations does not cancel catastrophically */
    double m = fw_mean(x, n), ss = 0.0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (!isnan(x[i])) {
            ss += (x[i] - m) * (x[i] - m);
            k++;
        }
    return k > 1 ? sqrt(ss / (k - 1)) : NAN;
}

/* Continued fraction of the incomplete beta function (modified Lentz), which
 * converges fast for x < (a + 1) / (a + b + 2). */
static double beta_cf(double a, double b, double x)
{
    const double tiny = 1e-300, eps = 1e-16;
    double qab = a + b, qap = a + 1.0, qam = a - 1.0;
    double c = 1.0, d = 1.0 - qab * x / qap;
    if (fabs(d) < tiny)
        d = tiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m <= 1000; m++) {
        int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        d = fabs(d) < tiny ? 1.0 / tiny : 1.0 / d;
        c = 1.0 + aa / c;
        if (fabs(c) < tiny)
            c = tiny;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        d = fabs(d) < tiny ? 1.0 / tiny : 1.0 / d;
        c = 1.0 + aa / c;
        if (fabs(c) < tiny)
            c = tiny;
        double del = d * c;
        h *= del;
        if (fabs(del - 1.0) < eps)
            break;
    }
    return h;
}

double fw_inc_beta(double a, double b, double x)
{
    if (!(a > 0.0) || !(b > 0.0) || isnan(x))
        return NAN;
    if (x <= 0.0)
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    double lbt = lgamma(a + b) - lgamma(a) - lgamma(b) + a * log(x) + b * log1p(-x);
    double bt = exp(lbt);
    /* the symmetry I_x(a, b) = 1 - I_{1-x}(b, a) keeps the fraction in its fast range */
    if (x < (a + 1.0) / (a + b + 2.0))
        return bt * beta_cf(a, b, x) / a;
    return 1.0 - bt * beta_cf(b, a, 1.0 - x) / b;
}

/* P(|T| < t) for t >= 0, finite df. */
static double t_central(double t, double df)
{
    return fw_inc_beta(0.5, 0.5 * df, t * t / (df + t * t));
}

/* P(T > t) for t >= 0. */
static double t_upper(double t, double df)
{
    if (isinf(df))
        return 0.5 * erfc(t / sqrt(2.0));
    /* near zero df / (df + t^2) rounds to 1 and loses t: use the central
     * probability P(|T| < t) = I_y(1/2, df/2), y = t^2 / (df + t^2), instead */
    if (t * t < df)
        return 0.5 - 0.5 * t_central(t, df);
    return 0.5 * fw_inc_beta(0.5 * df, 0.5, df / (df + t * t));
}

double fw_t_cdf(double t, double df)
{
    if (isnan(t) || !(df > 0.0))
        return NAN;
    double up = t_upper(fabs(t), df);
    return t >= 0.0 ? 1.0 - up : up;
}

double fw_normal_quantile(double p)
{
    if (isnan(p) || p < 0.0 || p > 1.0)
        return NAN;
    if (p == 0.0)
        return -INFINITY;
    if (p == 1.0)
        return INFINITY;
    /* Acklam's rational approximation (relative error 1.2e-9) ... */
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                               -2.759285104469687e+02, 1.383577518672690e+02,
                               -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                               -1.556989798598866e+02, 6.680131188771972e+01,
                               -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                               -2.400758277161838e+00, -2.549732539343734e+00,
                               4.374664141464968e+00, 2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                               2.445134137142996e+00, 3.754408661907416e+00};
    double x, q, r;
    if (p < 0.02425) {
        q = sqrt(-2.0 * log(p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    } else if (p > 1.0 - 0.02425) {
        q = sqrt(-2.0 * log1p(-p));
        x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    } else {
        q = p - 0.5;
        r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    /* ... and one Halley step against erfc brings it to full double precision */
    double e = 0.5 * erfc(-x / sqrt(2.0)) - p;
    double u = e * sqrt(2.0 * M_PI) * exp(0.5 * x * x);
    return x - u / (1.0 + 0.5 * x * u);
}

double fw_t_quantile(double p, double df)
{
    if (isnan(p) || p < 0.0 || p > 1.0 || !(df > 0.0))
        return NAN;
    if (isinf(df))
        return fw_normal_quantile(p);
    if (p == 0.5)
        return 0.0;
    if (p == 0.0 || p == 1.0)
        return p == 0.0 ? -INFINITY : INFINITY;
    /* Bisection on t > 0 (the bracket grows by doubling, so heavy tails at
     * df < 1 cannot escape it).  Near the centre the equation is written for
     * P(|T| < t) = |2p - 1|, which is exact in floating point; in the tails
     * for P(T > t), so neither side is lost to rounding against 0.5. */
    double c = fabs(2.0 * p - 1.0), tail = p > 0.5 ? 1.0 - p : p;
    bool centre = c < 0.5;
    double lo = 0.0, hi = 1.0;
    while ((centre ? t_central(hi, df) < c : t_upper(hi, df) > tail) && hi < 1e300)
        hi *= 2.0;
    for (int i = 0; i < 2000 && hi - lo > 1e-15 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if (centre ? t_central(mid, df) < c : t_upper(mid, df) > tail)
            lo = mid;
        else
            hi = mid;
    }
    double t = 0.5 * (lo + hi);
    return p > 0.5 ? t : -t;
}

fw_estimate fw_mean_ci(const double *x, int n, double level)
{
    fw_estimate e = {0, NAN, NAN, NAN, NAN};
    for (int i = 0; i < n; i++)
        e.n += !isnan(x[i]);
    if (e.n == 0)
        return e;
    e.mean = fw_mean(x, n);
    if (e.n < 2)
        return e;
    e.sd = fw_sd(x, n);
    double h = fw_t_quantile(0.5 + 0.5 * level, e.n - 1) * e.sd / sqrt(e.n);
    e.lo = e.mean - h;
    e.hi = e.mean + h;
    return e;
}

fw_estimate fw_paired_ci(const double *a, const double *b, int n, double level)
{
    double *d = malloc((size_t)(n > 0 ? n : 1) * sizeof *d);
    if (!d) {
        fw_estimate e = {0, NAN, NAN, NAN, NAN};
        return e;
    }
    for (int i = 0; i < n; i++)
        d[i] = a[i] - b[i]; /* NaN if either is missing */
    fw_estimate e = fw_mean_ci(d, n, level);
    free(d);
    return e;
}

fw_estimate fw_wilson(int k, int n, double level)
{
    fw_estimate e = {n, NAN, NAN, NAN, NAN};
    if (n <= 0 || k < 0 || k > n)
        return e;
    double p = (double)k / n, z = fw_normal_quantile(0.5 + 0.5 * level), z2 = z * z;
    e.mean = p;
    if (n > 1)
        e.sd = sqrt(p * (1.0 - p) * n / (n - 1.0)); /* of the 0/1 outcomes */
    double den = 1.0 + z2 / n;
    double centre = (p + z2 / (2.0 * n)) / den;
    double half = z / den * sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * (double)n));
    /* at k = 0 (k = n) the bound is 0 (1) exactly; rounding must not move it */
    e.lo = k == 0 ? 0.0 : fmax(0.0, centre - half);
    e.hi = k == n ? 1.0 : fmin(1.0, centre + half);
    return e;
}

static int cmp_nan_last(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    if (isnan(a) || isnan(b))
        return isnan(a) - isnan(b);
    return (a > b) - (a < b);
}

int fw_sort(double *x, int n)
{
    if (n <= 0)
        return 0;
    qsort(x, (size_t)n, sizeof *x, cmp_nan_last);
    int k = n;
    while (k > 0 && isnan(x[k - 1]))
        k--;
    return k;
}

double fw_quantile_sorted(const double *sorted, int n, double q)
{
    if (n <= 0 || isnan(q))
        return NAN;
    q = fmin(1.0, fmax(0.0, q));
    double h = (n - 1) * q;
    int i = (int)floor(h);
    if (i >= n - 1)
        return sorted[n - 1];
    return sorted[i] + (h - i) * (sorted[i + 1] - sorted[i]);
}
