/* stats.h - the statistics of a study report: means, intervals, percentiles.
 *
 * A study repeats each setting over replications; what it reports is the mean
 * over replications with a Student-t interval, the paired difference between
 * two settings that shared their random numbers, pooled percentiles and, for
 * rare yes/no outcomes, a Wilson interval; for rare events, exact Poisson,
 * exact binomial and conditional-binomial intervals and a fixed-seed
 * bootstrap (stats_exact.c).  Everything is self-contained (the
 * t quantile comes from our own incomplete beta function), so the numbers can
 * be checked against printed tables.  NaN marks a missing value and is skipped
 * wherever a function takes an array.
 */
#ifndef FW_STATS_H
#define FW_STATS_H

#include <stdint.h>

/* A mean (or a proportion) with its interval. */
typedef struct fw_estimate {
    int n;           /* values used */
    double mean;     /* NAN if n == 0 */
    double sd;       /* sample standard deviation (n - 1); NAN if n < 2 */
    double lo, hi;   /* the interval; NAN if it cannot be given (n < 2 for a mean) */
} fw_estimate;

double fw_mean(const double *x, int n);
/* Sample standard deviation, divisor n - 1. */
double fw_sd(const double *x, int n);

/* Regularized incomplete beta function I_x(a, b), a, b > 0, 0 <= x <= 1. */
double fw_inc_beta(double a, double b, double x);
/* Student-t distribution with df > 0 degrees of freedom (df = INFINITY: normal). */
double fw_t_cdf(double t, double df);
double fw_t_quantile(double p, double df);
double fw_normal_quantile(double p);

/* Mean of x with its two-sided interval at `level` (e.g. 0.95): mean +- t(df = n - 1) s / sqrt n. */
fw_estimate fw_mean_ci(const double *x, int n, double level);
/* The same for the differences a[i] - b[i] over the i where both are present. */
fw_estimate fw_paired_ci(const double *a, const double *b, int n, double level);
/* k successes in n independent trials: the proportion with its Wilson score
 * interval, which stays inside [0, 1] and is not empty at k = 0 or k = n. */
fw_estimate fw_wilson(int k, int n, double level);

/* stats_exact.c: intervals that are right for rare events and ratios. */

/* Regularized lower incomplete gamma function P(a, x), a > 0, x >= 0. */
double fw_inc_gamma(double a, double x);
/* Quantiles of the gamma (shape a, scale 1), chi-square and beta distributions. */
double fw_gamma_quantile(double p, double a);
double fw_chi2_quantile(double p, double df);
double fw_beta_quantile(double p, double a, double b);
/* k events in `exposure` (hours, ship-hours, ...): the rate k / exposure with
 * Garwood's exact Poisson interval, lower end 0 at k = 0.  n holds k. */
fw_estimate fw_poisson_exact(long long k, double exposure, double level);
/* k successes in n trials: k / n with the exact (Clopper-Pearson) interval. */
fw_estimate fw_clopper_pearson(int k, int n, double level);
/* A difference of two counts, (x - y) * scale, with the exact conditional
 * interval: given the n = x + y events, x is binomial(n, p); the
 * Clopper-Pearson interval of p is mapped through n (2p - 1) * scale.  It
 * excludes 0 exactly when the exact binomial test of p = 1/2 (equal rates)
 * rejects.  Paired runs: x and y summed over the replications (stratified by
 * replication, each one's own traffic intensity cancels when the ratio of the
 * rates is common); discordant pairs of a yes/no outcome: x, y the pairs
 * where only one side had it, scale 1 / pairs (exact McNemar).  n holds
 * x + y; no interval when both are 0. */
fw_estimate fw_count_difference(long long x, long long y, double scale, double level);
/* Percentile bootstrap with `reps` resamples of the n units from a fixed
 * seed (the same numbers on every machine): the ratio of sums
 * sum num / sum den, and the median.  Units with a NaN are left out. */
fw_estimate fw_bootstrap_ratio(const double *num, const double *den, int n, int reps,
                               uint64_t seed, double level);
fw_estimate fw_bootstrap_median(const double *x, int n, int reps, uint64_t seed, double level);

/* Sorts ascending, NaNs last; returns the number of non-NaN values. */
int fw_sort(double *x, int n);
/* Quantile q in [0, 1] of sorted values with linear interpolation between
 * order statistics (numpy's default): x[(n - 1) q]. NAN if n == 0. */
double fw_quantile_sorted(const double *sorted, int n, double q);

#endif
