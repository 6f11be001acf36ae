/* stats.h - the statistics of a study report: means, intervals, percentiles.
 *
 * A study repeats each setting over replications; what it reports is the mean
 * over replications with a Student-t interval, the paired difference between
 * two settings that shared their random numbers, pooled percentiles and, for
 * rare yes/no outcomes, a Wilson interval.  Everything is self-contained (the
 * t quantile comes from our own incomplete beta function), so the numbers can
 * be checked against printed tables.  NaN marks a missing value and is skipped
 * wherever a function takes an array.
 */
#ifndef FW_STATS_H
#define FW_STATS_H

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

/* Sorts ascending, NaNs last; returns the number of non-NaN values. */
int fw_sort(double *x, int n);
/* Quantile q in [0, 1] of sorted values with linear interpolation between
 * order statistics (numpy's default): x[(n - 1) q]. NAN if n == 0. */
double fw_quantile_sorted(const double *sorted, int n, double q);

#endif
