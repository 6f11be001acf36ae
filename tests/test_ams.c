/* test_ams.c - adaptive multilevel splitting (study/ams.h) against an answer
 * known in closed form: the Brownian cross-track case of ams_walk.h.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ams_walk.h"
#include "study/ams.h"
#include "test.h"

/* Crude Monte Carlo on a case within its reach agrees with the formula:
 * the bridge test makes the simulated event the continuous one. */
static void test_model_exact(void)
{
    walk_def w = walk_case(4);
    w.x0 = 1.6 * w.sigma * sqrt(w.dt * w.steps); /* p = 0.1096 */
    double p = walk_exact_p(&w);
    CHECK_NEAR(p, 0.109599, 1e-6);
    fw_rng r = fw_rng_make(5, 0, FW_PURPOSE_TEST);
    int n = 40000, hits = 0;
    for (int i = 0; i < n; i++) {
        fw_rng ri = fw_rng_branch(&r, (uint32_t)i);
        hits += walk_touches(&w, &ri);
    }
    double se = sqrt(p * (1 - p) / n);
    CHECK_MSG(fabs((double)hits / n - p) < 3.5 * se, "crude %g against %g (se %g)", (double)hits / n,
              p, se);
}

typedef struct coverage {
    int held;
    double mean, re, cost, crude;
    int level_held;     /* intervals of the lower level holding level_p */
    double level_mean;
} coverage;

/* The lower level cover() also estimates, and its probability by crude
 * Monte Carlo (the score is looked at once a step, so the closed form of
 * the continuous walk does not hold for it; 400000 walks: standard error
 * about 1.6% of a 1e-2). */
#define LEVEL_Q 0.66
static double level_p(const walk_def *w)
{
    fw_ams_model m = walk_model((walk_def *)w);
    fw_rng r = fw_rng_make(11, 0, FW_PURPOSE_TEST);
    int n = 400000, hits = 0;
    fw_error err = {0};
    for (int i = 0; i < n; i++) {
        fw_ams_sim sim;
        CHECK(m.start(m.ctx, fw_rng_branch(&r, (uint32_t)i), &sim, &err) == FW_OK);
        hits += sim.score >= LEVEL_Q;
        m.drop(m.ctx, sim.traj);
    }
    return (double)hits / n;
}

/* reps independent estimates, each the mean of `batches` batches of n
 * particles with its 95% t interval, on case w. */
static coverage cover(walk_def w, int n, int batches, int reps)
{
    double p = walk_exact_p(&w);
    fw_ams_model m = walk_model(&w);
    fw_ams_def def = fw_default_ams_def();
    def.particles = n;
    def.n_levels = 1;
    def.levels[0] = LEVEL_Q;
    double pq = level_p(&w);
    coverage c = {0};
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < reps; i++) {
        def.seed = 1000 + (uint64_t)i;
        fw_estimate est[2], e;
        double cost;
        fw_error err = {0};
        CHECK_MSG(fw_ams_batches(&def, &m, batches, 0.95, est, &cost, &err) == FW_OK, "%s",
                  err.msg);
        e = est[0];
        c.held += e.lo <= p && p <= e.hi;
        c.level_held += est[1].lo <= pq && pq <= est[1].hi;
        c.level_mean += est[1].mean / reps;
        sum += e.mean;
        sum2 += e.mean * e.mean;
        c.cost += cost / reps;
    }
    c.mean = sum / reps;
    c.re = sqrt((sum2 - reps * c.mean * c.mean) / (reps - 1)) / p;
    c.crude = fw_crude_runs(p, c.re);
    printf("p = %.3g, %s score, %d x %d particles: mean of %d estimates %+.1f%%, %d of %d "
           "intervals hold p; relative error %.3f for %.0f trajectories; crude Monte Carlo "
           "%.3g (%.0fx)\n",
           p, w.timed ? "timed" : "plain", batches, n, reps, 100 * (c.mean / p - 1), c.held, reps,
           c.re, c.cost, c.crude, c.crude / c.cost);
    printf("level %.2f (crude %.4g): mean %+.1f%%, %d of %d intervals hold it\n", LEVEL_Q, pq,
           100 * (c.level_mean / pq - 1), c.level_held, reps);
    c.level_mean /= pq;
    return c;
}

/* 100 independent splitting estimates at p = 1e-4, each the mean of 8
 * batches of 100 particles with its 95% interval, scored by the plain
 * closeness (not the ideal score: a fairway run has no better one): at least
 * 90 of the intervals hold the exact value, and the mean of the estimates is
 * within 10% of it.  (The ideal, timed score and the costs against crude
 * Monte Carlo: bench/bench_ams.c.) */
static void test_coverage(void)
{
    walk_def w = walk_case(4);
    CHECK_NEAR(walk_exact_p(&w), 1e-4, 1e-8);
    coverage c = cover(w, 100, 12, 100);
    CHECK(c.held >= 90);
    CHECK(fabs(c.mean / walk_exact_p(&w) - 1.0) < 0.10);
    /* the lower level's estimate from the same runs (a near miss's beside a
     * collision's) */
    CHECK(c.level_held >= 90);
    CHECK(fabs(c.level_mean - 1.0) < 0.10);
}

/* Exact small cases: a certain event (p = 1 without a round) and extinction. */
static void test_edges(void)
{
    walk_def w = walk_case(4);
    fw_ams_model m = walk_model(&w);
    fw_ams_def def = fw_default_ams_def();
    fw_ams_result r;
    fw_error err = {0};
    w.x0 = w.clear; /* every trajectory starts in contact */
    CHECK(fw_ams_run(&def, &m, &r, &err) == FW_OK);
    CHECK(r.p == 1.0 && r.rounds == 0 && r.reached == def.particles);
    w = walk_case(4);
    w.sigma = 0.0; /* nothing moves: every score stays 0, the event cannot happen */
    CHECK(fw_ams_run(&def, &m, &r, &err) == FW_OK);
    CHECK(r.p == 0.0 && r.rounds == 0);
    def.particles = 1;
    CHECK(fw_ams_run(&def, &m, &r, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "particles: 1") != NULL);
    /* the same seed, the same estimate */
    w = walk_case(4);
    def = fw_default_ams_def();
    fw_ams_result a, b;
    CHECK(fw_ams_run(&def, &m, &a, &err) == FW_OK && fw_ams_run(&def, &m, &b, &err) == FW_OK);
    CHECK(a.p == b.p && a.rounds == b.rounds && a.cost == b.cost);
}

int main(void)
{
    TEST_RUN(test_model_exact);
    TEST_RUN(test_coverage);
    TEST_RUN(test_edges);
    return TEST_EXIT();
}
