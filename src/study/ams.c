/* ams.c - adaptive multilevel splitting (ams.h). */
#include "study/ams.h"

#include <math.h>
#include <stdlib.h>

fw_ams_def fw_default_ams_def(void)
{
    return (fw_ams_def){.particles = 100, .max_rounds = 0, .seed = 1};
}

fw_status fw_ams_check(const fw_ams_def *def, fw_error *err)
{
    if (def->particles < 2 || def->particles > 1000000)
        return fw_fail(err, FW_EINPUT, "particles: %d: splitting needs at least 2 (and at most 1e6)",
                       def->particles);
    if (def->n_levels < 0 || def->n_levels > FW_AMS_MAX_LEVELS)
        return fw_fail(err, FW_EINPUT, "levels: %d: at most %d", def->n_levels, FW_AMS_MAX_LEVELS);
    for (int i = 0; i < def->n_levels; i++)
        if (!(def->levels[i] > 0.0 && def->levels[i] < 1.0) ||
            (i > 0 && !(def->levels[i] > def->levels[i - 1])))
            return fw_fail(err, FW_EINPUT, "levels[%d]: %g: levels lie in (0, 1), increasing", i,
                           def->levels[i]);
    if (def->max_rounds < 0)
        return fw_fail(err, FW_EINPUT, "max_rounds: %d: must be >= 0", def->max_rounds);
    return FW_OK;
}

/* The engine's state: the particles and its two kinds of randomness. */
typedef struct ams {
    const fw_ams_model *m;
    int n;
    fw_ams_sim *p;      /* the particles */
    int *alive;         /* scratch: indices of the survivors of a round */
    fw_rng pick;        /* which survivor a dropped particle copies */
    fw_rng fresh;       /* parent of every particle's own stream */
    uint32_t n_streams; /* streams handed out so far */
    double cost;
} ams;

static fw_rng next_stream(ams *a)
{
    return fw_rng_branch(&a->fresh, a->n_streams++);
}

static void ams_free(ams *a)
{
    for (int i = 0; a->p && i < a->n; i++)
        if (a->p[i].traj)
            a->m->drop(a->m->ctx, a->p[i].traj);
    free(a->p);
    free(a->alive);
}

/* One round at level z: every particle at or below it replaced by a branch
 * of a survivor.  k: how many were replaced. */
static fw_status round_at(ams *a, double z, int *k, fw_error *err)
{
    int n_alive = 0;
    for (int i = 0; i < a->n; i++)
        if (a->p[i].score > z)
            a->alive[n_alive++] = i;
    *k = a->n - n_alive;
    /* the branches are made from this round's survivors only, never from a
     * particle made in this round: the parents are fixed before any copy */
    if (a->n < 1) /* fw_ams_check holds particles >= 2: here for the compiler's bounds */
        return fw_fail(err, FW_ERUN, "splitting with %d particles", a->n);
    fw_ams_sim *made = calloc((size_t)a->n, sizeof *made);
    if (!made)
        return fw_fail(err, FW_ERUN, "out of memory");
    fw_status st = FW_OK;
    for (int i = 0; i < a->n && !st; i++) {
        if (a->p[i].score > z)
            continue;
        int j = a->alive[(int)(fw_rng_uniform(&a->pick) * n_alive)];
        st = a->m->branch(a->m->ctx, a->p[j].traj, z, next_stream(a), &made[i], err);
        a->cost += made[i].cost;
    }
    for (int i = 0; i < a->n; i++) {
        if (!made[i].traj)
            continue;
        if (st) { /* a failed round leaves the particles as they were */
            a->m->drop(a->m->ctx, made[i].traj);
            continue;
        }
        a->m->drop(a->m->ctx, a->p[i].traj);
        a->p[i] = made[i];
    }
    free(made);
    return st;
}

static fw_status ams_start(ams *a, const fw_ams_def *def, const fw_ams_model *m, fw_error *err)
{
    a->m = m;
    a->n = def->particles;
    a->pick = fw_rng_make(def->seed, 0, FW_PURPOSE_SPLIT);
    a->fresh = fw_rng_branch(&a->pick, 0xffffffffu);
    a->p = calloc((size_t)a->n, sizeof *a->p);
    a->alive = malloc((size_t)a->n * sizeof *a->alive);
    if (!a->p || !a->alive)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int i = 0; i < a->n; i++) {
        if (m->start(m->ctx, next_stream(a), &a->p[i], err))
            return err->status;
        a->cost += a->p[i].cost;
    }
    return FW_OK;
}

/* Share of the particles at or beyond q. */
static double share_at(const ams *a, double q)
{
    int c = 0;
    for (int i = 0; i < a->n; i++)
        c += a->p[i].score >= q;
    return (double)c / a->n;
}

/* The lower levels the lowest score z has reached take the product so far;
 * at the end (z < 0) every level left takes the product times its share. */
static void settle_levels(const fw_ams_def *def, const ams *a, double z, double p, bool *done,
                          fw_ams_result *out)
{
    for (int i = 0; i < def->n_levels; i++) {
        if (done[i])
            continue;
        if (z >= def->levels[i]) {
            out->p_level[i] = p;
            done[i] = true;
        } else if (z < 0.0) {
            out->p_level[i] = p * share_at(a, def->levels[i]);
            done[i] = true;
        }
    }
}

fw_status fw_ams_run(const fw_ams_def *def, const fw_ams_model *m, fw_ams_result *out,
                     fw_error *err)
{
    bool done[FW_AMS_MAX_LEVELS] = {false};
    if (fw_ams_check(def, err))
        return err->status;
    *out = (fw_ams_result){.p = 1.0};
    ams a = {0};
    fw_status st = ams_start(&a, def, m, err);
    long max_rounds = def->max_rounds ? def->max_rounds : 1000L * def->particles;
    while (!st) {
        double z = INFINITY;
        for (int i = 0; i < a.n; i++)
            z = fmin(z, a.p[i].score);
        settle_levels(def, &a, z, out->p, done, out);
        if (z >= 1.0)
            break; /* every particle has the event */
        int k = 0;
        for (int i = 0; i < a.n; i++)
            k += a.p[i].score <= z;
        if (k == a.n) { /* extinction: no particle went beyond the lowest */
            settle_levels(def, &a, -1.0, out->p, done, out);
            out->p = 0.0;
            break;
        }
        if (out->rounds >= max_rounds) {
            st = fw_fail(err, FW_ERUN, "splitting: %d rounds without reaching the event "
                                       "(max_rounds); the estimate so far is %.3g",
                         out->rounds, out->p);
            break;
        }
        out->p *= 1.0 - (double)k / a.n;
        out->rounds++;
        st = round_at(&a, z, &k, err);
    }
    if (!st)
        settle_levels(def, &a, -1.0, out->p, done, out);
    if (!st && out->p > 0.0) {
        for (int i = 0; i < a.n; i++)
            out->reached += a.p[i].score >= 1.0;
        out->p *= (double)out->reached / a.n;
    }
    out->cost = a.cost;
    if (!st && m->final)
        m->final(m->ctx, a.p, a.n);
    ams_free(&a);
    return st;
}

/* The batches' mean (unbiased) with an interval from their logarithms
 * (Cox's method for the mean of a log-normal: exp(m + s^2/2 +- t sqrt(s^2/B
 * + s^4/(2(B - 1))))), which a splitting estimate's right skew calls for:
 * the Student t interval on the estimates themselves held the true value in
 * 179 of 200 trials (8 batches of 100, tests/test_ams.c's case at 1e-4),
 * Cox's in 194.  A batch that died out (estimate 0) has no logarithm: then
 * the t interval, cut at 0. */
static fw_estimate batch_interval(const double *v, int b, double level)
{
    fw_estimate e = fw_mean_ci(v, b, level);
    if (e.lo < 0.0)
        e.lo = 0.0;
    double *y = malloc((size_t)b * sizeof *y);
    bool positive = y != NULL;
    for (int i = 0; positive && i < b; i++) {
        positive = v[i] > 0.0;
        y[i] = positive ? log(v[i]) : 0.0;
    }
    if (positive) {
        double m = fw_mean(y, b), s2 = fw_sd(y, b) * fw_sd(y, b);
        double h = fw_t_quantile(0.5 + 0.5 * level, b - 1) *
                   sqrt(s2 / b + s2 * s2 / (2.0 * (b - 1)));
        e.lo = fmin(exp(m + 0.5 * s2 - h), e.mean);
        e.hi = fmax(exp(m + 0.5 * s2 + h), e.mean);
    }
    free(y);
    return e;
}

fw_status fw_ams_batches(const fw_ams_def *def, const fw_ams_model *m, int batches, double level,
                         fw_estimate *est, double *cost, fw_error *err)
{
    if (batches < 2)
        return fw_fail(err, FW_EINPUT, "batches: %d: an interval needs at least 2", batches);
    if (fw_ams_check(def, err))
        return err->status;
    int nl = 1 + def->n_levels;
    double *v = malloc((size_t)(batches * nl) * sizeof *v);
    if (!v)
        return fw_fail(err, FW_ERUN, "out of memory");
    *cost = 0.0;
    fw_rng seeds = fw_rng_make(def->seed, 1, FW_PURPOSE_SPLIT);
    fw_status st = FW_OK;
    for (int b = 0; b < batches && !st; b++) {
        fw_ams_def d = *def;
        uint64_t hi, lo;
        fw_rng_block(&seeds, &hi, &lo);
        d.seed = hi;
        fw_ams_result r;
        st = fw_ams_run(&d, m, &r, err);
        v[b] = r.p;
        for (int i = 0; i < def->n_levels; i++)
            v[(1 + i) * batches + b] = r.p_level[i];
        *cost += r.cost;
    }
    for (int i = 0; !st && i < nl; i++)
        est[i] = batch_interval(v + i * batches, batches, level);
    free(v);
    return st;
}

fw_estimate fw_ams_interval(const double *v, int b, double level)
{
    return batch_interval(v, b, level);
}

double fw_crude_runs(double p, double re)
{
    return (1.0 - p) / (p * re * re);
}
