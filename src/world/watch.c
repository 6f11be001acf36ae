/* watch.c - the background ships' watchkeeping (watch.h). */
#include "world/watch.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/idmap.h"
#include "core/mem.h"

/* One ship and one other it had to give way to. */
typedef struct pair {
    double t_detect; /* s, when it is detected */
    double t_act;    /* s, when it may act at the earliest: detected + decided */
    double r0;       /* m, the range when first met */
    uint32_t key;    /* the acting ship's stream key */
    bool lapsed;
    bool late;    /* acts only within the late range */
} pair;

struct fw_watch {
    fw_watch_def def;
    fw_rng_getter rng;
    void *ctx;
    fw_idmap ids; /* "a\nb" -> pair */
    pair *pairs;
    int cap;
    long n_pairs, n_lapsed;
    double unseen; /* the largest 1 - range / first range of a ship not yet acted for */
    fw_idmap ships; /* id -> its behaviour (the mix) */
    unsigned char *beh;
    int beh_cap;
    long n_beh[FW_BEH_N];
};

fw_watch_def fw_default_watch_def(void)
{
    return (fw_watch_def){.delay = 0.0, .lapse = 0.0, .detect = 0.0, .late = 0.0,
                          .late_range = 0.0};
}

fw_status fw_watch_check(const fw_watch_def *d, fw_error *err)
{
    if (!(d->delay >= 0.0 && isfinite(d->delay)))
        return fw_fail(err, FW_EINPUT, "watch delay %g s: must be 0 or more", d->delay);
    if (!(d->detect >= 0.0 && isfinite(d->detect)))
        return fw_fail(err, FW_EINPUT, "watch detect %g s: must be 0 or more", d->detect);
    if (!(d->lapse >= 0.0 && d->lapse <= 1.0))
        return fw_fail(err, FW_EINPUT, "watch lapse %g: a probability, in [0, 1]", d->lapse);
    if (!(d->late >= 0.0 && d->late <= 1.0))
        return fw_fail(err, FW_EINPUT, "watch late %g: a probability, in [0, 1]", d->late);
    if (d->late > 0.0 && !(d->late_range > 0.0 && isfinite(d->late_range)))
        return fw_fail(err, FW_EINPUT, "watch late range %g m: must be more than 0",
                       d->late_range);
    if (!(d->mix_late >= 0.0 && d->mix_passive >= 0.0 &&
          d->mix_late + d->mix_passive <= 1.0 + 1e-9))
        return fw_fail(err, FW_EINPUT, "mix late %g, passive %g: shares in [0, 1], at most 1 "
                                       "together", d->mix_late, d->mix_passive);
    if (d->mix_late > 0.0 && !(d->mix_range > 0.0 && isfinite(d->mix_range)))
        return fw_fail(err, FW_EINPUT, "mix late range %g m: must be more than 0", d->mix_range);
    return FW_OK;
}

bool fw_watch_def_mixed(const fw_watch_def *d)
{
    return d->mix_late > 0.0 || d->mix_passive > 0.0;
}

bool fw_watch_def_draws(const fw_watch_def *d)
{
    return d->lapse > 0.0 || d->detect > 0.0 || d->late > 0.0 || fw_watch_def_mixed(d);
}

bool fw_watch_def_active(const fw_watch_def *d)
{
    return d->delay > 0.0 || fw_watch_def_draws(d);
}

fw_status fw_watch_create(const fw_watch_def *def, fw_watch **out, fw_error *err)
{
    *out = NULL;
    fw_status st = fw_watch_check(def, err);
    if (st)
        return st;
    fw_watch *w = calloc(1, sizeof *w);
    if (!w)
        return fw_fail(err, FW_ERUN, "out of memory");
    w->def = *def;
    *out = w;
    return FW_OK;
}

void fw_watch_destroy(fw_watch *w)
{
    if (!w)
        return;
    fw_idmap_free(&w->ids);
    fw_idmap_free(&w->ships);
    free(w->pairs);
    free(w->beh);
    free(w);
}

void fw_watch_set_rng(fw_watch *w, fw_rng_getter rng, void *ctx)
{
    w->rng = rng;
    w->ctx = ctx;
}

bool fw_watch_active(const fw_watch *w)
{
    return w && fw_watch_def_active(&w->def);
}

/* Ship a's behaviour, drawn from its own stream the first time (watch.h);
 * -1 when out of memory or without streams. */
static int behaviour(fw_watch *w, const fw_target *a)
{
    int before = w->ships.n, k;
    if (fw_idmap_intern(&w->ships, a->id, &k))
        return -1;
    if (k >= w->beh_cap) {
        int cap = fw_grown_cap(w->beh_cap, k + 1);
        if (!fw_resize((void **)&w->beh, sizeof *w->beh, (size_t)cap))
            return -1;
        w->beh_cap = cap;
    }
    if (w->ships.n > before) {
        fw_rng *s = w->rng ? w->rng(w->ctx, fw_rng_vessel_key(a->id), FW_PURPOSE_BEHAVIOUR) : NULL;
        if (!s)
            return -1;
        double u = fw_rng_uniform(s);
        w->beh[k] = u < w->def.mix_passive                    ? FW_BEH_PASSIVE
                    : u < w->def.mix_passive + w->def.mix_late ? FW_BEH_LATE
                                                               : FW_BEH_COMPLIANT;
        w->n_beh[w->beh[k]]++;
    }
    return w->beh[k];
}

int fw_watch_noticed(fw_watch *w, const fw_target *a, const fw_target *b, double t)
{
    int beh = fw_watch_def_mixed(&w->def) ? behaviour(w, a) : FW_BEH_COMPLIANT;
    if (beh < 0)
        return -1;
    if (beh == FW_BEH_PASSIVE)
        return 0;
    if (beh == FW_BEH_LATE && hypot(b->east - a->east, b->north - a->north) > w->def.mix_range)
        return 0;
    const fw_watch_def *d0 = &w->def;
    if (d0->delay == 0.0 && d0->lapse == 0.0 && d0->detect == 0.0 && d0->late == 0.0)
        return 1; /* a mix alone: no encounter to draw for, none counted */
    char key[2 * FW_TARGET_ID_MAX + 2];
    snprintf(key, sizeof key, "%s\n%s", a->id, b->id);
    int before = w->ids.n, k;
    if (fw_idmap_intern(&w->ids, key, &k))
        return -1;
    if (k >= w->cap) {
        int cap = fw_grown_cap(w->cap, k + 1);
        if (!fw_resize((void **)&w->pairs, sizeof *w->pairs, (size_t)cap))
            return -1;
        w->cap = cap;
    }
    pair *p = &w->pairs[k];
    double r = hypot(b->east - a->east, b->north - a->north);
    if (w->ids.n > before) { /* a new encounter: its clock, its draws (watch.h) */
        uint32_t key = fw_rng_vessel_key(a->id);
        fw_rng *s = w->rng ? w->rng(w->ctx, key, FW_PURPOSE_WATCH) : NULL;
        if (!s)
            return -1;
        const fw_watch_def *d = &w->def;
        bool lapsed = d->lapse > 0.0 && fw_rng_uniform(s) < d->lapse;
        double detect = d->detect > 0.0 ? d->detect * fw_rng_exponential(s) : 0.0;
        bool late = d->late > 0.0 && fw_rng_uniform(s) < d->late;
        *p = (pair){.t_detect = t + detect, .t_act = t + detect + d->delay, .r0 = r, .key = key,
                    .lapsed = lapsed, .late = late};
        w->n_pairs++;
        w->n_lapsed += p->lapsed;
    }
    int noticed = !p->lapsed && t >= p->t_act - 1e-9 && (!p->late || r <= w->def.late_range);
    if (!noticed && p->r0 > 0.0)
        w->unseen = fmax(w->unseen, 1.0 - r / p->r0);
    return noticed;
}

double fw_watch_unseen(const fw_watch *w) { return w ? w->unseen : 0.0; }

int fw_watch_redraw(fw_watch *w, double t)
{
    int n = 0;
    for (int k = 0; w && w->def.detect > 0.0 && k < w->ids.n; k++) {
        pair *p = &w->pairs[k];
        if (p->lapsed || p->t_detect <= t + 1e-9)
            continue;
        fw_rng *s = w->rng ? w->rng(w->ctx, p->key, FW_PURPOSE_WATCH) : NULL;
        if (!s)
            return -1;
        p->t_detect = t + w->def.detect * fw_rng_exponential(s);
        p->t_act = p->t_detect + w->def.delay;
        n++;
    }
    return n;
}

void fw_watch_mix_counts(const fw_watch *w, long counts[FW_BEH_N])
{
    for (int i = 0; i < FW_BEH_N; i++)
        counts[i] = w ? w->n_beh[i] : 0;
}

void fw_watch_counts(const fw_watch *w, long *pairs, long *lapsed)
{
    *pairs = w ? w->n_pairs : 0;
    *lapsed = w ? w->n_lapsed : 0;
}
