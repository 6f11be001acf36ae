/* bench.h - what every benchmark needs: a monotonic clock and medians.
 * Benchmarks report medians of repeated runs because these machines are noisy. */
#ifndef FW_BENCH_H
#define FW_BENCH_H

#include <stdlib.h>

#include "core/clock.h"

/* Seconds on the monotonic clock. */
static inline double bench_now(void) { return fw_clock_s(); }

static inline int bench_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of v[0..n); sorts v. */
static inline double bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif
