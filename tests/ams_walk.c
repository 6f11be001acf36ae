/* ams_walk.c - the Brownian cross-track case with a known answer (ams_walk.h). */
#include "ams_walk.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct walk {
    int n;       /* points stored: x[0 .. n-1]; ends at the horizon or at contact */
    double best; /* largest score */
    double x[];
} walk;

static double score_at(const walk_def *w, double x, int i)
{
    double s = 1.0 - (x - w->clear) / (w->x0 - w->clear);
    if (w->timed && s < 1.0)
        s = i < w->steps ? 1.0 - (1.0 - s) * sqrt((double)w->steps / (w->steps - i)) : 0.0;
    return s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
}

/* Steps from point k of t (whose first k + 1 points are set) to the horizon. */
static void walk_on(const walk_def *w, walk *t, int k, fw_rng *r)
{
    double q = w->sigma * sqrt(w->dt), var = w->sigma * w->sigma * w->dt;
    t->best = 0.0;
    for (int i = 0; i <= k; i++)
        t->best = fmax(t->best, score_at(w, t->x[i], i));
    t->n = k + 1;
    for (int i = k; i < w->steps && t->best < 1.0; i++) {
        double a = t->x[i], b = a + q * fw_rng_normal(r);
        double u = fw_rng_uniform(r); /* one draw whether it is used or not */
        bool dipped = b <= w->clear || u < exp(-2.0 * (a - w->clear) * (b - w->clear) / var);
        t->x[t->n++] = dipped ? fmin(b, w->clear) : b;
        t->best = dipped ? 1.0 : fmax(t->best, score_at(w, b, i + 1));
    }
}

static walk *walk_new(const walk_def *w)
{
    return malloc(sizeof(walk) + (size_t)(w->steps + 1) * sizeof(double));
}

static fw_status w_start(void *ctx, fw_rng r, fw_ams_sim *out, fw_error *err)
{
    const walk_def *w = ctx;
    walk *t = walk_new(w);
    if (!t)
        return fw_fail(err, FW_ERUN, "out of memory");
    t->x[0] = w->x0;
    walk_on(w, t, 0, &r);
    *out = (fw_ams_sim){t, t->best, (double)(t->n - 1) / w->steps};
    return FW_OK;
}

static fw_status w_branch(void *ctx, const void *parent, double level, fw_rng r, fw_ams_sim *out,
                          fw_error *err)
{
    const walk_def *w = ctx;
    const walk *p = parent;
    int k = 0;
    while (k < p->n - 1 && !(score_at(w, p->x[k], k) > level))
        k++;
    walk *t = walk_new(w);
    if (!t)
        return fw_fail(err, FW_ERUN, "out of memory");
    memcpy(t->x, p->x, (size_t)(k + 1) * sizeof(double));
    walk_on(w, t, k, &r);
    *out = (fw_ams_sim){t, t->best, (double)(t->n - 1 - k) / w->steps};
    return FW_OK;
}

static void w_drop(void *ctx, void *t)
{
    (void)ctx;
    free(t);
}

fw_ams_model walk_model(walk_def *w)
{
    return (fw_ams_model){.ctx = w, .start = w_start, .branch = w_branch, .drop = w_drop};
}

double walk_exact_p(const walk_def *w)
{
    double d = (w->x0 - w->clear) / (w->sigma * sqrt(w->dt * w->steps));
    return erfc(d / sqrt(2.0));
}

/* d with erfc(d / sqrt 2) = p, by bisection (erfc is monotone). */
static double d_for(double p)
{
    double lo = 0.0, hi = 10.0;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (erfc(mid / sqrt(2.0)) > p)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

walk_def walk_case(double e)
{
    walk_def w = {.clear = 0.0, .sigma = 2.0, .dt = 10.0, .steps = 120};
    w.x0 = d_for(pow(10.0, -e)) * w.sigma * sqrt(w.dt * w.steps);
    return w;
}

bool walk_touches(const walk_def *w, fw_rng *r)
{
    walk *t = walk_new(w);
    if (!t)
        return false;
    t->x[0] = w->x0;
    walk_on(w, t, 0, r);
    bool hit = t->best >= 1.0;
    free(t);
    return hit;
}
