/* test_split_run.c - splitting over fairway runs (study/split_run.h): a
 * head-on pass with a wandering helmsman, within crude Monte Carlo's reach,
 * estimated both ways; a run with no randomness refused; the same seed, the
 * same estimate.
 *
 * The case (tests/data/split_pass.yaml, kinematic traffic, no SUMO): the C-3
 * at 12 kn meets a ship on the reciprocal course 600 m to starboard at
 * t = 1800 s.  Its helmsman is the test's controller: every 60 s a helm order
 * drawn normal with sd SIGMA_DEG (the run's stream of purpose TEST, taken
 * from the world's table so splitting re-keys it), held.  The ship wanders;
 * sometimes it wanders into the other's path.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"
#include "study/outcome.h"
#include "study/split_run.h"
#include "test.h"

#define SIGMA_DEG 1.5
#define HOLD_S 60.0

typedef struct wander {
    fw_controller base;
    fw_rng *rng; /* the world's: set once the run is open */
    double helm, next_t;
} wander;

static fw_status wander_decide(fw_controller *c, const fw_sense *in, fw_decision *d,
                               fw_error *err)
{
    (void)err;
    wander *w = (wander *)c;
    if (w->rng && in->t >= w->next_t) {
        w->helm = fmax(-0.6, fmin(0.6, fw_rng_normal(w->rng) * SIGMA_DEG * M_PI / 180.0));
        w->next_t += HOLD_S;
    }
    *d = (fw_decision){.helm = w->helm, .reason = "wandering", .primary = -1};
    return FW_OK;
}

static void wander_destroy(fw_controller *c) { free(c); }

static const fw_controller_ops wander_ops = {.name = "wander", .decide = wander_decide,
                                             .assesses = false, .destroy = wander_destroy};

typedef struct tcase {
    fw_scenario base;
    wander *last;  /* the controller of the run in this (child) process */
    bool random;   /* false: the helmsman never draws (a run with no randomness) */
} tcase;

static void make_scenario(void *ctx, uint64_t draw, fw_scenario *out)
{
    tcase *tc = ctx;
    *out = tc->base;
    out->seed = 1 + (unsigned long)(draw % 2147483646ull);
}

static fw_status make_controller(void *ctx, fw_controller **out, fw_error *err)
{
    tcase *tc = ctx;
    wander *w = calloc(1, sizeof *w);
    if (!w)
        return fw_fail(err, FW_ERUN, "out of memory");
    w->base.ops = &wander_ops;
    tc->last = w;
    *out = &w->base;
    return FW_OK;
}

static void opened(void *ctx, fw_run *r)
{
    tcase *tc = ctx;
    if (tc->random)
        tc->last->rng = fw_world_rng(fw_run_world(r), 0, FW_PURPOSE_TEST);
}

static fw_split_run_def case_def(tcase *tc)
{
    fw_error err = {0};
    char file[512];
    snprintf(file, sizeof file, "%s/tests/data/split_pass.yaml", fw_data_root());
    CHECK_MSG(fw_scenario_load(file, &tc->base, &err) == FW_OK, "%s",
              err.msg);
    tc->random = true;
    fw_split_run_def d = {.scenario = make_scenario, .ctx = tc, .make_controller = make_controller,
                          .opened = opened};
    d.run = fw_default_run_def();
    d.run.traffic = FW_RUN_TRAFFIC_KINEMATIC;
    return d;
}

/* Crude Monte Carlo: of n runs (each a start of the model), how many reach
 * closeness q and how many contact. */
static void crude(fw_ams_model *m, int n, double q, int *k_q, int *k_hit)
{
    fw_rng r = fw_rng_make(3, 0, FW_PURPOSE_TEST);
    int hits = 0, hits1 = 0;
    fw_error err = {0};
    for (int i = 0; i < n; i++) {
        fw_ams_sim s;
        CHECK_MSG(m->start(m->ctx, fw_rng_branch(&r, (uint32_t)i), &s, &err) == FW_OK, "%s",
                  err.msg);
        hits += s.score >= q;
        hits1 += s.score >= 1.0;
        m->drop(m->ctx, s.traj);
    }
    *k_q = hits;
    *k_hit = hits1;
}

/* Exact interval for a binomial share (Clopper-Pearson by bisection). */
static double beta_tail(int k, int n, double p, bool upper)
{
    /* P(X >= k) for upper, P(X <= k) otherwise, by summing terms in logs */
    double sum = 0.0;
    for (int i = upper ? k : 0; i <= (upper ? n : k); i++)
        sum += exp(lgamma(n + 1.0) - lgamma(i + 1.0) - lgamma(n - i + 1.0) + i * log(p) +
                   (n - i) * log1p(-p));
    return sum;
}

static void exact_interval(int k, int n, double *lo, double *hi)
{
    double a = 0.025, l = 0.0, h = 1.0;
    for (int it = 0; it < 60; it++) { /* lo: P(X >= k | lo) = a */
        double m = 0.5 * (l + h);
        (k > 0 && beta_tail(k, n, m, true) < a ? (l = m) : (h = m));
    }
    *lo = k > 0 ? l : 0.0;
    l = 0.0, h = 1.0;
    for (int it = 0; it < 60; it++) { /* hi: P(X <= k | hi) = a */
        double m = 0.5 * (l + h);
        (k < n && beta_tail(k, n, m, false) > a ? (l = m) : (h = m));
    }
    *hi = k < n ? h : 1.0;
}

/* Within crude Monte Carlo's reach (contact about 2.5e-2, near miss about
 * 0.12): splitting's estimates and crude counting agree within their 95%
 * intervals, for contact and for the near-miss level it gives beside it. */
static void test_agrees_with_crude(fw_ams_model *m, const fw_split_run *S)
{
    int n = 2000, k_nm, k_hit;
    double q = fw_closeness(185.2);
    crude(m, n, q, &k_nm, &k_hit);
    double lo1, hi1, loq, hiq;
    exact_interval(k_hit, n, &lo1, &hi1);
    exact_interval(k_nm, n, &loq, &hiq);
    fw_ams_def def = fw_default_ams_def();
    def.particles = 40;
    def.seed = 7;
    def.n_levels = 1;
    def.levels[0] = q;
    fw_estimate est[2];
    double cost;
    fw_error err = {0};
    long before = fw_split_run_count(S);
    CHECK_MSG(fw_ams_batches(&def, m, getenv("SPLIT_B") ? atoi(getenv("SPLIT_B")) : 6, 0.95, est, &cost, &err) == FW_OK, "%s", err.msg);
    printf("contact: crude %d/%d [%.4f, %.4f]; splitting %.4f [%.4f, %.4f] for %.0f runs\n",
           k_hit, n, lo1, hi1, est[0].mean, est[0].lo, est[0].hi, cost);
    printf("near miss: crude %d/%d [%.4f, %.4f]; splitting %.4f [%.4f, %.4f]\n", k_nm, n, loq, hiq,
           est[1].mean, est[1].lo, est[1].hi);
    CHECK(fw_split_run_count(S) - before == (long)cost);
    CHECK(est[0].lo <= hi1 && lo1 <= est[0].hi);
    CHECK(est[1].lo <= hiq && loq <= est[1].hi);
    CHECK(est[0].mean > 0.0 && est[1].mean > est[0].mean);
    /* the same seed, the same estimate: replayed branches are their parents
     * to the bit up to the level crossing */
    fw_ams_result a, b;
    def.particles = 10;
    CHECK(fw_ams_run(&def, m, &a, &err) == FW_OK && fw_ams_run(&def, m, &b, &err) == FW_OK);
    CHECK(a.p == b.p && a.rounds == b.rounds && a.p_level[0] == b.p_level[0]);
    CHECK(a.rounds > 0);
}

/* A run nothing in which draws cannot be split: the model says so. */
static void test_no_randomness(tcase *tc, fw_ams_model *m)
{
    tc->random = false;
    fw_ams_def def = fw_default_ams_def();
    def.particles = 4;
    fw_ams_result r;
    fw_error err = {0};
    CHECK(fw_ams_run(&def, m, &r, &err) == FW_EINPUT);
    CHECK_MSG(strstr(err.msg, "no randomness after t = 0") != NULL, "%s", err.msg);
    tc->random = true;
}

int main(void)
{
    tcase tc = {0};
    fw_split_run_def d = case_def(&tc);
    fw_split_run *S;
    fw_ams_model m;
    fw_error err = {0};
    CHECK(fw_split_run_create(&d, &S, &m, &err) == FW_OK);
    if (getenv("SPLIT_CRUDE")) { /* exploring the case */
        int n = atoi(getenv("SPLIT_CRUDE")), k_nm, k_hit;
        crude(&m, n, fw_closeness(185.2), &k_nm, &k_hit);
        printf("crude: %d runs, P(near miss) %.4f, P(contact) %.4f\n", n, (double)k_nm / n,
               (double)k_hit / n);
    } else {
        test_agrees_with_crude(&m, S);
        test_no_randomness(&tc, &m);
    }
    fw_split_run_destroy(S);
    return TEST_EXIT();
}
