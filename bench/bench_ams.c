/* bench_ams.c - what splitting (study/ams.h) costs against crude Monte Carlo
 * for the same relative error, on the Brownian cross-track case whose
 * answer is exact (tests/ams_walk.h).
 *
 * For each probability (1e-2, 1e-4, 1e-5) and score (plain closeness, and
 * the ideal "timed" one), R independent estimates, each the mean of B
 * batches of N = 100 particles: their mean against the exact p, their
 * relative error (sd / p over the R), how many of their intervals hold p,
 * and the trajectories one estimate simulated.  Crude Monte Carlo needs
 * (1 - p) / (p RE^2) runs for the same relative error; the ratio is the
 * speed-up.  At 1e-2 a crude estimate of 2e4 runs is made too, and the two
 * must agree within their intervals.  Costs are in trajectory equivalents
 * (a branch simulates only what follows its branch point), the same unit
 * crude Monte Carlo's runs are in; wall-clock medians are printed as well.
 * Usage: bench_ams [R] > bench/results/ams.txt
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../tests/ams_walk.h"
#include "bench.h"
#include "study/ams.h"

static void row(double e, bool timed, int reps, int batches)
{
    walk_def w = walk_case(e);
    w.timed = timed;
    double p = walk_exact_p(&w), sum = 0.0, sum2 = 0.0, cost = 0.0;
    int held = 0;
    fw_ams_model m = walk_model(&w);
    fw_ams_def def = fw_default_ams_def();
    double *wall = malloc((size_t)reps * sizeof *wall);
    for (int i = 0; i < reps; i++) {
        def.seed = 50000 + (uint64_t)i;
        fw_estimate est;
        double c, t0 = bench_now();
        fw_error err = {0};
        if (fw_ams_batches(&def, &m, batches, 0.95, &est, &c, &err)) {
            fprintf(stderr, "bench_ams: %s\n", err.msg);
            exit(1);
        }
        wall[i] = bench_now() - t0;
        held += est.lo <= p && p <= est.hi;
        sum += est.mean;
        sum2 += est.mean * est.mean;
        cost += c / reps;
    }
    double mean = sum / reps, re = sqrt((sum2 - reps * mean * mean) / (reps - 1)) / p;
    double crude = fw_crude_runs(p, re);
    printf("%-8.0e %-6s %3d x 100 %+7.1f%% %6.3f %4d/%-4d %10.0f %12.4g %9.0fx %9.4f\n", p,
           timed ? "timed" : "plain", batches, 100 * (mean / p - 1), re, held, reps, cost, crude,
           crude / cost, bench_median(wall, reps));
    free(wall);
}

/* Crude Monte Carlo at 1e-2 against splitting's interval there. */
static void crude_check(void)
{
    walk_def w = walk_case(2);
    double p = walk_exact_p(&w);
    fw_rng r = fw_rng_make(77, 0, FW_PURPOSE_TEST);
    int n = 20000, hits = 0;
    for (int i = 0; i < n; i++) {
        fw_rng ri = fw_rng_branch(&r, (uint32_t)i);
        hits += walk_touches(&w, &ri);
    }
    fw_estimate c = fw_clopper_pearson(hits, n, 0.95);
    fw_ams_model m = walk_model(&w);
    fw_ams_def def = fw_default_ams_def();
    fw_estimate s;
    double cost;
    fw_error err = {0};
    if (fw_ams_batches(&def, &m, 8, 0.95, &s, &cost, &err))
        exit(1);
    bool agree = c.lo <= s.hi && s.lo <= c.hi;
    printf("\nAt p = %.4g: crude %d runs %.4g [%.4g, %.4g]; splitting 8 x 100 %.4g [%.4g, %.4g] "
           "for %.0f trajectories: %s\n",
           p, n, c.mean, c.lo, c.hi, s.mean, s.lo, s.hi, cost,
           agree ? "the intervals overlap" : "THE INTERVALS DO NOT OVERLAP");
}

int main(int argc, char **argv)
{
    int reps = argc > 1 ? atoi(argv[1]) : 40;
    printf("Splitting against crude Monte Carlo, Brownian cross-track case (tests/ams_walk.h), "
           "%d estimates per row\n\n", reps);
    printf("%-8s %-6s %-9s %8s %6s %9s %10s %12s %10s %9s\n", "p", "score", "batches", "bias",
           "RE", "held", "cost", "crude_runs", "speed-up", "wall_s");
    static const struct {
        double e;
        bool timed;
        int batches;
    } rows[] = {{2, false, 4}, {2, true, 4},  {4, false, 4},  {4, true, 4},
                {5, false, 4}, {5, true, 4},  {5, false, 16}};
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++)
        row(rows[k].e, rows[k].timed, reps, rows[k].batches);
    crude_check();
    return 0;
}
