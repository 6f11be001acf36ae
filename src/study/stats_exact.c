/* stats_exact.c - intervals for rare events and for ratios (see stats.h):
 * exact Poisson (Garwood), exact binomial (Clopper-Pearson), the conditional
 * binomial for a difference of two counts, and a fixed-seed bootstrap.
 *
 * The quantiles of the gamma and beta distributions are found by bisection
 * on their distribution functions (the regularized incomplete gamma below,
 * fw_inc_beta in stats.c): slower than Newton, but it cannot leave [0, 1] or
 * diverge, and 200 halvings reach the bracket's rounding on any input.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/rng.h"
#include "study/stats.h"

/* P(a, x) by its series, good for x < a + 1. */
static double gamma_series(double a, double x)
{
    double sum = 1.0 / a, term = sum, ap = a;
    for (int n = 0; n < 10000; n++) {
        ap += 1.0;
        term *= x / ap;
        sum += term;
        if (fabs(term) < fabs(sum) * 1e-17)
            break;
    }
    return sum * exp(-x + a * log(x) - lgamma(a));
}

/* Q(a, x) = 1 - P(a, x) by its continued fraction (modified Lentz), x >= a + 1. */
static double gamma_cf(double a, double x)
{
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; i++) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < tiny)
            d = tiny;
        c = b + an / c;
        if (fabs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (fabs(del - 1.0) < 1e-16)
            break;
    }
    return exp(-x + a * log(x) - lgamma(a)) * h;
}

double fw_inc_gamma(double a, double x)
{
    if (!(a > 0.0) || isnan(x))
        return NAN;
    if (x <= 0.0)
        return 0.0;
    if (isinf(x))
        return 1.0;
    return x < a + 1.0 ? gamma_series(a, x) : 1.0 - gamma_cf(a, x);
}

/* The x in [lo, hi] where the increasing cdf(x) crosses p, by bisection. */
static double bisect(double (*cdf)(double, double, double), double a, double b, double p,
                     double lo, double hi)
{
    for (int i = 0; i < 200 && hi - lo > 1e-15 * fmax(hi, 1e-300); i++) {
        double mid = 0.5 * (lo + hi);
        if (cdf(a, b, mid) < p)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

static double gamma_cdf3(double a, double unused, double x)
{
    (void)unused;
    return fw_inc_gamma(a, x);
}

double fw_gamma_quantile(double p, double a)
{
    if (isnan(p) || p < 0.0 || p > 1.0 || !(a > 0.0))
        return NAN;
    if (p == 0.0)
        return 0.0;
    if (p == 1.0)
        return INFINITY;
    double hi = a + 1.0;
    while (fw_inc_gamma(a, hi) < p && hi < 1e300)
        hi *= 2.0;
    return bisect(gamma_cdf3, a, 0.0, p, 0.0, hi);
}

double fw_chi2_quantile(double p, double df)
{
    return 2.0 * fw_gamma_quantile(p, 0.5 * df);
}

double fw_beta_quantile(double p, double a, double b)
{
    if (isnan(p) || p < 0.0 || p > 1.0 || !(a > 0.0) || !(b > 0.0))
        return NAN;
    if (p == 0.0 || p == 1.0)
        return p;
    return bisect(fw_inc_beta, a, b, p, 0.0, 1.0);
}

fw_estimate fw_poisson_exact(long long k, double exposure, double level)
{
    fw_estimate e = {0, NAN, NAN, NAN, NAN};
    if (k < 0 || !(exposure > 0.0) || !(level > 0.0 && level < 1.0))
        return e;
    double alpha = 1.0 - level;
    e.n = (int)(k < 2147483647LL ? k : 2147483647LL);
    e.mean = (double)k / exposure;
    /* Garwood (1936): the means whose Poisson tail just reaches k, written
     * with the gamma function's quantiles (chi-square 2k and 2k + 2, halved) */
    e.lo = k == 0 ? 0.0 : fw_gamma_quantile(0.5 * alpha, (double)k) / exposure;
    e.hi = fw_gamma_quantile(1.0 - 0.5 * alpha, (double)k + 1.0) / exposure;
    return e;
}

fw_estimate fw_clopper_pearson(int k, int n, double level)
{
    fw_estimate e = {n, NAN, NAN, NAN, NAN};
    if (n <= 0 || k < 0 || k > n || !(level > 0.0 && level < 1.0))
        return e;
    double alpha = 1.0 - level;
    e.mean = (double)k / n;
    e.lo = k == 0 ? 0.0 : fw_beta_quantile(0.5 * alpha, k, n - k + 1.0);
    e.hi = k == n ? 1.0 : fw_beta_quantile(1.0 - 0.5 * alpha, k + 1.0, n - k);
    return e;
}

fw_estimate fw_count_difference(long long x, long long y, double scale, double level)
{
    fw_estimate e = {0, NAN, NAN, NAN, NAN};
    long long n = x + y;
    if (x < 0 || y < 0 || !(scale > 0.0) || n > 2147483647LL)
        return e;
    e.n = (int)n;
    e.mean = (double)(x - y) * scale;
    if (n == 0) {
        /* no events on either side: the difference is 0, but the data bound
         * it only through the exposure, which this test does not see */
        e.lo = e.hi = NAN;
        return e;
    }
    /* given the n events of both, x is binomial(n, p), p = rate_x / (rate_x +
     * rate_y); the exact interval of p mapped through n (2p - 1) */
    fw_estimate p = fw_clopper_pearson((int)x, (int)n, level);
    e.lo = (double)n * (2.0 * p.lo - 1.0) * scale;
    e.hi = (double)n * (2.0 * p.hi - 1.0) * scale;
    return e;
}

static double stat_of(const double *a, const double *b, const int *idx, int n, double *tmp)
{
    if (b) { /* ratio of sums */
        double sa = 0.0, sb = 0.0;
        for (int i = 0; i < n; i++) {
            sa += a[idx[i]];
            sb += b[idx[i]];
        }
        return sb > 0.0 ? sa / sb : NAN;
    }
    for (int i = 0; i < n; i++)
        tmp[i] = a[idx[i]];
    int k = fw_sort(tmp, n);
    return fw_quantile_sorted(tmp, k, 0.5);
}

/* Percentile bootstrap of a ratio of sums (b given) or of a median (b NULL)
 * over the n units; NaN units are left out first. */
static fw_estimate bootstrap(const double *a0, const double *b0, int n0, int reps,
                             uint64_t seed, double level)
{
    fw_estimate e = {0, NAN, NAN, NAN, NAN};
    double *a = malloc((size_t)(n0 > 0 ? n0 : 1) * 3 * sizeof *a);
    int *idx = malloc((size_t)(n0 > 0 ? n0 : 1) * sizeof *idx);
    double *st = malloc((size_t)(reps > 0 ? reps : 1) * sizeof *st);
    if (!a || !idx || !st || reps < 1)
        goto out;
    double *b = a + n0, *tmp = a + 2 * n0;
    int n = 0;
    for (int i = 0; i < n0; i++)
        if (!isnan(a0[i]) && (!b0 || !isnan(b0[i]))) {
            a[n] = a0[i];
            b[n++] = b0 ? b0[i] : 0.0;
        }
    e.n = n;
    if (n == 0)
        goto out;
    for (int i = 0; i < n; i++)
        idx[i] = i;
    e.mean = stat_of(a, b0 ? b : NULL, idx, n, tmp);
    uint64_t s = seed;
    int k = 0;
    for (int r = 0; r < reps; r++) {
        for (int i = 0; i < n; i++)
            idx[i] = (int)(fw_splitmix64(&s) % (uint64_t)n);
        double v = stat_of(a, b0 ? b : NULL, idx, n, tmp);
        if (!isnan(v))
            st[k++] = v;
    }
    k = fw_sort(st, k);
    if (n > 1 && k > 0) {
        e.lo = fw_quantile_sorted(st, k, 0.5 * (1.0 - level));
        e.hi = fw_quantile_sorted(st, k, 0.5 * (1.0 + level));
    }
out:
    free(a);
    free(idx);
    free(st);
    return e;
}

fw_estimate fw_bootstrap_ratio(const double *num, const double *den, int n, int reps,
                               uint64_t seed, double level)
{
    return bootstrap(num, den, n, reps, seed, level);
}

fw_estimate fw_bootstrap_median(const double *x, int n, int reps, uint64_t seed, double level)
{
    return bootstrap(x, NULL, n, reps, seed, level);
}
