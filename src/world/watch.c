/* watch.c - the background ships' watchkeeping (watch.h). */
#include "world/watch.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/idmap.h"
#include "core/mem.h"

/* One ship and one other it had to give way to. */
typedef struct pair {
    double t_first; /* s, when the other first was a threat */
    bool lapsed;
} pair;

struct fw_watch {
    fw_watch_def def;
    fw_rng_getter rng;
    void *ctx;
    fw_idmap ids; /* "a\nb" -> pair */
    pair *pairs;
    int cap;
    long n_pairs, n_lapsed;
};

fw_watch_def fw_default_watch_def(void) { return (fw_watch_def){.delay = 0.0, .lapse = 0.0}; }

fw_status fw_watch_check(const fw_watch_def *d, fw_error *err)
{
    if (!(d->delay >= 0.0 && isfinite(d->delay)))
        return fw_fail(err, FW_EINPUT, "watch delay %g s: must be 0 or more", d->delay);
    if (!(d->lapse >= 0.0 && d->lapse <= 1.0))
        return fw_fail(err, FW_EINPUT, "watch lapse %g: a probability, in [0, 1]", d->lapse);
    return FW_OK;
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
    free(w->pairs);
    free(w);
}

void fw_watch_set_rng(fw_watch *w, fw_rng_getter rng, void *ctx)
{
    w->rng = rng;
    w->ctx = ctx;
}

bool fw_watch_active(const fw_watch *w)
{
    return w && (w->def.delay > 0.0 || w->def.lapse > 0.0);
}

int fw_watch_noticed(fw_watch *w, const fw_target *a, const fw_target *b, double t)
{
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
    if (w->ids.n > before) { /* a new encounter: its clock, its lapse */
        fw_rng *s = w->rng ? w->rng(w->ctx, fw_rng_vessel_key(a->id), FW_PURPOSE_WATCH) : NULL;
        if (!s)
            return -1;
        *p = (pair){.t_first = t, .lapsed = w->def.lapse > 0.0 && fw_rng_uniform(s) < w->def.lapse};
        w->n_pairs++;
        w->n_lapsed += p->lapsed;
    }
    return !p->lapsed && t >= p->t_first + w->def.delay - 1e-9;
}

void fw_watch_counts(const fw_watch *w, long *pairs, long *lapsed)
{
    *pairs = w ? w->n_pairs : 0;
    *lapsed = w ? w->n_lapsed : 0;
}
