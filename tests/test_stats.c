/* Statistics of the study report (src/study/stats.c) against known answers:
 * printed t tables and closed forms, interval coverage on synthetic samples
 * from a fixed-seed generator, hand-worked paired differences, numpy's
 * percentiles and the Wilson interval's textbook values. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "study/stats.h"
#include "test.h"

/* splitmix64: a fixed-seed generator, so the coverage checks give the same
 * verdict on every machine. */
static uint64_t rng_state;
static uint64_t rng_next(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double uniform(void) /* (0, 1) */
{
    return ((rng_next() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}
static double normal(void) /* Box-Muller */
{
    return sqrt(-2.0 * log(uniform())) * cos(2.0 * M_PI * uniform());
}

static void test_t_table(void)
{
    /* the two-sided 95% column of a printed t table */
    CHECK_NEAR(fw_t_quantile(0.975, 1), 12.706, 5e-4);
    CHECK_NEAR(fw_t_quantile(0.975, 2), 4.303, 5e-4);
    CHECK_NEAR(fw_t_quantile(0.975, 5), 2.571, 5e-4);
    CHECK_NEAR(fw_t_quantile(0.975, 10), 2.228, 5e-4);
    CHECK_NEAR(fw_t_quantile(0.975, 30), 2.042, 5e-4);
    CHECK_NEAR(fw_t_quantile(0.975, INFINITY), 1.960, 5e-4);
    /* more digits (R's qt) and other columns */
    CHECK_NEAR(fw_t_quantile(0.975, 1), 12.70620474, 1e-7);
    CHECK_NEAR(fw_t_quantile(0.975, 7), 2.364624252, 1e-8);
    CHECK_NEAR(fw_t_quantile(0.995, 4), 4.604094871, 1e-8);
    CHECK_NEAR(fw_t_quantile(0.9995, 1), 636.6192487, 1e-5);
    CHECK_NEAR(fw_t_quantile(0.95, 20), 1.724718243, 1e-8);
    CHECK_NEAR(fw_t_quantile(0.975, 1000), 1.962339081, 1e-8);
    CHECK_NEAR(fw_t_quantile(0.025, 5), -2.570581836, 1e-8);
    CHECK(fw_t_quantile(0.5, 3) == 0.0);
    CHECK(isnan(fw_t_quantile(1.5, 3)) && isnan(fw_t_quantile(0.9, 0)));
    /* t(1) is Cauchy and t(2) has a closed form: every p, not just the table's */
    for (double p = 0.01; p < 1.0; p += 0.049) {
        CHECK_REL(fw_t_quantile(p, 1), tan(M_PI * (p - 0.5)), 1e-10);
        CHECK_REL(fw_t_quantile(p, 2), (2 * p - 1) / sqrt(2 * p * (1 - p)), 1e-10);
        CHECK_NEAR(fw_t_cdf(fw_t_quantile(p, 3.5), 3.5), p, 1e-12);
    }
    /* the t quantile falls to the normal's as df grows */
    CHECK(fw_t_quantile(0.975, 1e6) > fw_t_quantile(0.975, INFINITY));
    CHECK_NEAR(fw_t_quantile(0.975, 1e6), 1.959966, 1e-5);
}

static void test_normal_and_beta(void)
{
    CHECK_NEAR(fw_normal_quantile(0.975), 1.959963985, 1e-9);
    CHECK_NEAR(fw_normal_quantile(0.5), 0.0, 1e-15);
    CHECK_NEAR(fw_normal_quantile(1e-10), -6.361340902, 1e-8);
    CHECK_NEAR(fw_normal_quantile(0.9), 1.281551566, 1e-9);
    /* closed forms of I_x(a, b) */
    for (double x = 0.05; x < 1.0; x += 0.1) {
        CHECK_NEAR(fw_inc_beta(1.0, 3.5, x), 1.0 - pow(1.0 - x, 3.5), 1e-13);
        CHECK_NEAR(fw_inc_beta(2.5, 1.0, x), pow(x, 2.5), 1e-13);
    }
    CHECK_NEAR(fw_inc_beta(7.0, 7.0, 0.5), 0.5, 1e-14);
    CHECK_NEAR(fw_inc_beta(0.5, 0.5, 0.25), 1.0 / 3.0, 1e-13); /* arcsine law: 2/pi asin(sqrt x) */
    CHECK(fw_inc_beta(2, 3, 0) == 0.0 && fw_inc_beta(2, 3, 1) == 1.0);
}

static void test_mean_sd(void)
{
    double x[] = {2, 4, 4, 4, 5, 5, 7, 9};
    CHECK_NEAR(fw_mean(x, 8), 5.0, 1e-15);
    CHECK_NEAR(fw_sd(x, 8), sqrt(32.0 / 7.0), 1e-14);
    double y[] = {1, NAN, 3};
    CHECK_NEAR(fw_mean(y, 3), 2.0, 1e-15);
    CHECK_NEAR(fw_sd(y, 3), sqrt(2.0), 1e-15);
    CHECK(isnan(fw_mean(y + 1, 1)) && isnan(fw_sd(x, 1)));
    /* large offsets do not eat the spread */
    double z[] = {1e9 + 1, 1e9 + 2, 1e9 + 3};
    CHECK_NEAR(fw_sd(z, 3), 1.0, 1e-9);
}

static void test_mean_ci(void)
{
    /* 8, 12, 10: mean 10, s 2, half width t(0.975; 2) 2 / sqrt 3 */
    double x[] = {8, 12, 10};
    fw_estimate e = fw_mean_ci(x, 3, 0.95);
    CHECK(e.n == 3);
    CHECK_NEAR(e.mean, 10.0, 1e-12);
    CHECK_NEAR(e.sd, 2.0, 1e-12);
    CHECK_NEAR(e.hi - e.mean, 4.302652730 * 2.0 / sqrt(3.0), 1e-8);
    CHECK_NEAR(e.mean - e.lo, e.hi - e.mean, 1e-12);
    fw_estimate one = fw_mean_ci(x, 1, 0.95);
    CHECK(one.n == 1 && one.mean == 8.0 && isnan(one.lo) && isnan(one.hi));
    fw_estimate none = fw_mean_ci(x, 0, 0.95);
    CHECK(none.n == 0 && isnan(none.mean));
    double same[] = {3, 3, 3, 3};
    fw_estimate s = fw_mean_ci(same, 4, 0.95);
    CHECK(s.lo == 3.0 && s.hi == 3.0);
}

/* Share of `reps` intervals of n draws that contain the true mean. */
static double coverage(int reps, int n, double (*draw)(void), double mu)
{
    double x[64];
    int hit = 0;
    for (int r = 0; r < reps; r++) {
        for (int i = 0; i < n; i++)
            x[i] = draw();
        fw_estimate e = fw_mean_ci(x, n, 0.95);
        hit += e.lo <= mu && mu <= e.hi;
    }
    return (double)hit / reps;
}

static double draw_normal(void) { return 10.0 + 3.0 * normal(); }
static double draw_exponential(void) { return -2.0 * log(uniform()); } /* mean 2, skew 2 */

static void test_ci_coverage(void)
{
    rng_state = 20240611;
    /* 4000 intervals: the coverage estimate has a standard error of 0.0034, so
     * +-0.012 is 3.5 of them: a wrong t quantile (1.96 at n = 8 gives 0.91) fails */
    double c = coverage(4000, 8, draw_normal, 10.0);
    printf("  coverage, normal n = 8:      %.4f\n", c);
    CHECK_NEAR(c, 0.95, 0.012);
    c = coverage(4000, 3, draw_normal, 10.0);
    printf("  coverage, normal n = 3:      %.4f\n", c);
    CHECK_NEAR(c, 0.95, 0.012);
    /* Skewed data: the t interval undercovers at small n (about 0.90 for the
     * exponential at n = 8) and recovers as n grows - what the report's
     * intervals mean for rare-event counts with few replications. */
    double c8 = coverage(4000, 8, draw_exponential, 2.0);
    double c40 = coverage(4000, 40, draw_exponential, 2.0);
    printf("  coverage, exponential n = 8: %.4f, n = 40: %.4f\n", c8, c40);
    CHECK(c8 > 0.87 && c8 < 0.93);
    CHECK(c40 > c8 && c40 > 0.925);
}

static void test_paired(void)
{
    /* manoeuvres per hour at 500 m and 100 m in three shared-traffic replications */
    double a[] = {12, 14, 18}, b[] = {6, 8, 10};
    fw_estimate d = fw_paired_ci(a, b, 3, 0.95);
    CHECK(d.n == 3);
    CHECK_NEAR(d.mean, 20.0 / 3.0, 1e-12);
    CHECK_NEAR(d.sd, sqrt(4.0 / 3.0), 1e-12);
    CHECK_NEAR(d.lo, 20.0 / 3.0 - 4.302652730 * sqrt(4.0 / 3.0) / sqrt(3.0), 1e-8);
    CHECK_NEAR(d.hi, 20.0 / 3.0 + 4.302652730 * sqrt(4.0 / 3.0) / sqrt(3.0), 1e-8);
    /* unpaired, the same numbers give an interval that includes zero: pairing
     * removes the replication-to-replication variation */
    fw_estimate ea = fw_mean_ci(a, 3, 0.95), eb = fw_mean_ci(b, 3, 0.95);
    CHECK(ea.lo < eb.hi);
    /* a replication missing on either side drops out of the pairs */
    double a2[] = {12, NAN, 18, 5}, b2[] = {6, 8, 10, NAN};
    fw_estimate d2 = fw_paired_ci(a2, b2, 4, 0.95);
    CHECK(d2.n == 2);
    CHECK_NEAR(d2.mean, 7.0, 1e-12);
    CHECK_NEAR(d2.hi - d2.mean, 12.70620474 * sqrt(2.0) / sqrt(2.0), 1e-6);
}

static void test_percentiles(void)
{
    /* numpy.percentile([1, 2, 3, 4], [0, 25, 50, 90, 100]) = 1, 1.75, 2.5, 3.7, 4 */
    double x[] = {4, NAN, 2, 1, 3};
    int n = fw_sort(x, 5);
    CHECK(n == 4 && x[0] == 1 && x[3] == 4 && isnan(x[4]));
    CHECK_NEAR(fw_quantile_sorted(x, n, 0.0), 1.0, 1e-15);
    CHECK_NEAR(fw_quantile_sorted(x, n, 0.25), 1.75, 1e-15);
    CHECK_NEAR(fw_quantile_sorted(x, n, 0.5), 2.5, 1e-15);
    CHECK_NEAR(fw_quantile_sorted(x, n, 0.9), 3.7, 1e-14);
    CHECK_NEAR(fw_quantile_sorted(x, n, 1.0), 4.0, 1e-15);
    /* 100, 200, ..., 1500: p5 170, p25 450, p50 800, p75 1150, p95 1430 */
    double y[15];
    for (int i = 0; i < 15; i++)
        y[i] = 100.0 * (15 - i);
    fw_sort(y, 15);
    CHECK_NEAR(fw_quantile_sorted(y, 15, 0.05), 170.0, 1e-9);
    CHECK_NEAR(fw_quantile_sorted(y, 15, 0.25), 450.0, 1e-9);
    CHECK_NEAR(fw_quantile_sorted(y, 15, 0.50), 800.0, 1e-9);
    CHECK_NEAR(fw_quantile_sorted(y, 15, 0.75), 1150.0, 1e-9);
    CHECK_NEAR(fw_quantile_sorted(y, 15, 0.95), 1430.0, 1e-9);
    double one = 7.0;
    CHECK(fw_quantile_sorted(&one, 1, 0.3) == 7.0);
    CHECK(isnan(fw_quantile_sorted(x, 0, 0.5)));
}

static void test_wilson(void)
{
    /* 1 of 3: (0.0615, 0.7923); 0 of 10: upper z^2 / (n + z^2) = 0.2775 */
    fw_estimate w = fw_wilson(1, 3, 0.95);
    CHECK_NEAR(w.mean, 1.0 / 3.0, 1e-15);
    CHECK_NEAR(w.lo, 0.06149, 5e-5);
    CHECK_NEAR(w.hi, 0.79234, 5e-5);
    fw_estimate z = fw_wilson(0, 10, 0.95);
    double z2 = 1.959963985 * 1.959963985;
    CHECK(z.lo == 0.0);
    CHECK_NEAR(z.hi, z2 / (10 + z2), 1e-9);
    fw_estimate all = fw_wilson(10, 10, 0.95);
    CHECK_NEAR(all.lo, 10 / (10 + z2), 1e-9);
    CHECK(all.hi == 1.0);
    CHECK(fw_wilson(0, 0, 0.95).n == 0 && isnan(fw_wilson(0, 0, 0.95).mean));
    /* coverage over many binomial samples stays near the level (p = 0.1, n = 30) */
    rng_state = 7;
    int hit = 0;
    for (int r = 0; r < 4000; r++) {
        int k = 0;
        for (int i = 0; i < 30; i++)
            k += uniform() < 0.1;
        fw_estimate e = fw_wilson(k, 30, 0.95);
        hit += e.lo <= 0.1 && 0.1 <= e.hi;
    }
    printf("  Wilson coverage, p = 0.1, n = 30: %.4f\n", hit / 4000.0);
    CHECK_NEAR(hit / 4000.0, 0.95, 0.03);
}

/* The gamma function's pieces against closed forms: P(1, x) = 1 - e^-x,
 * P(2, x) = 1 - (1 + x) e^-x; the quantile inverts the function. */
static void test_gamma(void)
{
    CHECK_NEAR(fw_inc_gamma(1.0, 0.7), 1.0 - exp(-0.7), 1e-14);
    CHECK_NEAR(fw_inc_gamma(2.0, 3.0), 1.0 - 4.0 * exp(-3.0), 1e-14);
    CHECK_NEAR(fw_inc_gamma(2.0, 30.0), 1.0 - 31.0 * exp(-30.0), 1e-14);
    /* P(1/2, x) = erf(sqrt x) */
    CHECK_NEAR(fw_inc_gamma(0.5, 2.0), erf(sqrt(2.0)), 1e-14);
    for (double a = 0.5; a < 200.0; a *= 3.0)
        for (double p = 0.01; p < 1.0; p += 0.245)
            CHECK_NEAR(fw_inc_gamma(a, fw_gamma_quantile(p, a)), p, 1e-12);
    /* chi-square table (any statistics text): 95th percentile of 1, 10 df */
    CHECK_NEAR(fw_chi2_quantile(0.95, 1), 3.841, 5e-4);
    CHECK_NEAR(fw_chi2_quantile(0.95, 10), 18.307, 5e-4);
    CHECK_NEAR(fw_chi2_quantile(0.025, 6), 1.237, 5e-4);
    CHECK(isnan(fw_gamma_quantile(0.5, 0.0)) && fw_gamma_quantile(0.0, 2.0) == 0.0);
}

/* Garwood's exact Poisson interval against the published 95% table (e.g.
 * Ulm 1990, Am J Epidemiol 131:373): k = 0 gives [0, 3.689], the "rule of
 * three" with its exact value -ln 0.025. */
static void test_poisson_exact(void)
{
    static const double tab[][3] = {{0, 0.0, 3.689}, {1, 0.0253, 5.572}, {2, 0.242, 7.225},
                                    {3, 0.619, 8.767}, {5, 1.623, 11.668}, {10, 4.795, 18.390}};
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        fw_estimate e = fw_poisson_exact((long long)tab[i][0], 1.0, 0.95);
        CHECK_NEAR(e.lo, tab[i][1], 5e-4 * fmax(1.0, tab[i][1]));
        CHECK_NEAR(e.hi, tab[i][2], 5e-4 * tab[i][2]);
        CHECK(e.mean == tab[i][0]);
    }
    CHECK_NEAR(fw_poisson_exact(0, 1.0, 0.95).hi, -log(0.025), 1e-10);
    /* 3 events in 10 hours: 0.3 per hour, [0.0619, 0.877] */
    fw_estimate e = fw_poisson_exact(3, 10.0, 0.95);
    CHECK_NEAR(e.mean, 0.3, 1e-15);
    CHECK_NEAR(e.lo, 0.0619, 5e-5);
    CHECK_NEAR(e.hi, 0.8767, 5e-5);
    /* 90%: k = 0 gives -ln 0.05 = 2.996 */
    CHECK_NEAR(fw_poisson_exact(0, 1.0, 0.90).hi, 2.996, 5e-4);
    CHECK(isnan(fw_poisson_exact(1, 0.0, 0.95).mean) && isnan(fw_poisson_exact(-1, 1, 0.95).hi));
}

/* Clopper-Pearson against its closed form at k = 0 (1 - (alpha/2)^(1/n))
 * and published values (e.g. Newcombe 1998, Stat Med 17:857, table I). */
static void test_clopper_pearson(void)
{
    fw_estimate e = fw_clopper_pearson(0, 10, 0.95);
    CHECK(e.lo == 0.0 && e.mean == 0.0);
    CHECK_NEAR(e.hi, 0.3085, 5e-5);
    CHECK_NEAR(fw_clopper_pearson(0, 20, 0.95).hi, 1.0 - pow(0.025, 1.0 / 20), 1e-10);
    CHECK_NEAR(fw_clopper_pearson(0, 20, 0.95).hi, 0.1684, 5e-5);
    e = fw_clopper_pearson(3, 10, 0.95);
    CHECK_NEAR(e.lo, 0.0667, 5e-5);
    CHECK_NEAR(e.hi, 0.6525, 5e-5);
    e = fw_clopper_pearson(1, 20, 0.95);
    CHECK_NEAR(e.lo, 0.00127, 5e-6);
    CHECK_NEAR(e.hi, 0.2487, 5e-5);
    /* symmetric: k of n mirrors n - k */
    fw_estimate a = fw_clopper_pearson(4, 17, 0.95), b = fw_clopper_pearson(13, 17, 0.95);
    CHECK_NEAR(a.lo, 1.0 - b.hi, 1e-12);
    CHECK_NEAR(a.hi, 1.0 - b.lo, 1e-12);
    CHECK(fw_clopper_pearson(5, 5, 0.95).hi == 1.0);
    CHECK(isnan(fw_clopper_pearson(1, 0, 0.95).mean));
}

/* The conditional binomial difference: 6 events against 0 is significant at
 * 95% (two-sided binomial p = 2 / 64 = 0.031), 5 against 0 is not (0.0625). */
static void test_count_difference(void)
{
    fw_estimate e = fw_count_difference(0, 6, 1.0, 0.95);
    CHECK(e.mean == -6.0 && e.n == 6);
    CHECK_NEAR(e.lo, -6.0, 1e-12);
    CHECK_NEAR(e.hi, 6.0 * (2.0 * (1.0 - pow(0.025, 1.0 / 6)) - 1.0), 1e-10);
    CHECK(e.hi < 0.0);
    e = fw_count_difference(0, 5, 1.0, 0.95);
    CHECK(e.lo < 0.0 && e.hi > 0.0);
    /* scaled to a rate: 12 - 4 events in 20 hours is 0.4 per hour */
    e = fw_count_difference(12, 4, 1.0 / 20.0, 0.95);
    CHECK_NEAR(e.mean, 0.4, 1e-15);
    fw_estimate p = fw_clopper_pearson(12, 16, 0.95);
    CHECK_NEAR(e.lo, 16.0 * (2.0 * p.lo - 1.0) / 20.0, 1e-12);
    /* binomial test of 12 of 16 at p = 1/2: two-sided 0.077, not significant */
    CHECK(e.lo < 0.0);
    e = fw_count_difference(0, 0, 1.0, 0.95);
    CHECK(e.mean == 0.0 && isnan(e.lo) && isnan(e.hi));
}

/* The bootstrap: reproducible from its seed, another seed another interval,
 * the point estimate the statistic of the data, the interval around it. */
static void test_bootstrap(void)
{
    double x[30], y[30];
    rng_state = 99;
    for (int i = 0; i < 30; i++) {
        x[i] = 100.0 + 20.0 * normal();
        y[i] = 1.0 + (double)(i % 4);
    }
    fw_estimate a = fw_bootstrap_median(x, 30, 2000, 1, 0.95);
    fw_estimate b = fw_bootstrap_median(x, 30, 2000, 1, 0.95);
    CHECK(a.lo == b.lo && a.hi == b.hi && a.mean == b.mean);
    double s[30];
    for (int i = 0; i < 30; i++)
        s[i] = x[i];
    int k = fw_sort(s, 30);
    CHECK(a.mean == fw_quantile_sorted(s, k, 0.5) && a.n == 30);
    CHECK(a.lo <= a.mean && a.mean <= a.hi && a.hi - a.lo < 40.0);
    /* the ratio of sums; a constant ratio has a zero-width interval */
    double num[30], sx = 0.0, sy = 0.0;
    for (int i = 0; i < 30; i++) {
        num[i] = 0.25 * y[i];
        sx += x[i];
        sy += y[i];
    }
    fw_estimate r = fw_bootstrap_ratio(num, y, 30, 500, 7, 0.95);
    CHECK_NEAR(r.mean, 0.25, 1e-15);
    CHECK_NEAR(r.lo, 0.25, 1e-15);
    CHECK_NEAR(r.hi, 0.25, 1e-15);
    r = fw_bootstrap_ratio(x, y, 30, 500, 7, 0.95);
    CHECK_NEAR(r.mean, sx / sy, 1e-12);
    CHECK(r.lo < r.mean && r.mean < r.hi);
    /* a ratio's resampled values are all different: another seed moves the ends */
    fw_estimate r2 = fw_bootstrap_ratio(x, y, 30, 500, 8, 0.95);
    CHECK(r2.lo != r.lo && r2.hi != r.hi);
    CHECK(fw_bootstrap_ratio(x, y, 30, 500, 7, 0.95).lo == r.lo);
    /* NaN units are left out */
    x[3] = NAN;
    CHECK(fw_bootstrap_median(x, 30, 100, 1, 0.95).n == 29);
}

int main(void)
{
    TEST_RUN(test_t_table);
    TEST_RUN(test_normal_and_beta);
    TEST_RUN(test_mean_sd);
    TEST_RUN(test_mean_ci);
    TEST_RUN(test_ci_coverage);
    TEST_RUN(test_paired);
    TEST_RUN(test_percentiles);
    TEST_RUN(test_wilson);
    TEST_RUN(test_gamma);
    TEST_RUN(test_poisson_exact);
    TEST_RUN(test_clopper_pearson);
    TEST_RUN(test_count_difference);
    TEST_RUN(test_bootstrap);
    return TEST_EXIT();
}
