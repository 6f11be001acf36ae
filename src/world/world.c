/* world.c - the world and its step (world.h). */
#include "world/world.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "world/vessel_internal.h"

enum { MAX_VESSELS = 64 };

struct fw_world {
    fw_world_def def;
    fw_source *source;
    fw_vessel *v[MAX_VESSELS];
    int nv;
    long steps;
    bool started, broken;
    fw_reactions *react;
    fw_world_timing timing;
};

/* The CPU clock when the def keeps timings, else 0 (no system calls). */
static double tick(const fw_world *w) { return w->def.timing ? fw_cpu_s() : 0.0; }

/* Adds the time since *t to *acc and moves *t to now. */
static void lap(const fw_world *w, double *acc, double *t)
{
    double now = tick(w);
    *acc += now - *t;
    *t = now;
}

fw_world_def fw_default_world_def(void)
{
    fw_world_def d = {.step = 1.0, .source = NULL, .reactions = fw_default_reactions_def()};
    d.reactions.behaviour = FW_BEHAVIOUR_BLIND;
    return d;
}

void fw_world_destroy(fw_world *w)
{
    if (!w)
        return;
    for (int i = 0; i < w->nv; i++) {
        fw_vessel_free(w->v[i]);
        free(w->v[i]);
    }
    fw_source_destroy(w->source);
    fw_reactions_destroy(w->react);
    free(w);
}

fw_status fw_world_create(const fw_world_def *def, fw_world **out, fw_error *err)
{
    *out = NULL;
    if (!(def->step > 0.0 && isfinite(def->step))) {
        fw_source_destroy(def->source);
        return fw_fail(err, FW_EINPUT, "world step %g s: must be positive", def->step);
    }
    if (def->source && fabs(fw_source_step_length(def->source) - def->step) > 1e-9) {
        double s = fw_source_step_length(def->source);
        fw_source_destroy(def->source);
        return fw_fail(err, FW_EINPUT, "the traffic source steps %g s, the world %g s", s,
                       def->step);
    }
    fw_world *w = calloc(1, sizeof *w);
    if (!w) {
        fw_source_destroy(def->source);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    w->def = *def;
    w->source = def->source;
    fw_status st = fw_reactions_create(&def->reactions, &w->react, err);
    if (st) {
        fw_world_destroy(w);
        return st;
    }
    *out = w;
    return FW_OK;
}

fw_status fw_world_add_vessel(fw_world *w, const fw_vessel_def *def, fw_vessel **out,
                              fw_error *err)
{
    if (out)
        *out = NULL;
    fw_vessel *v = NULL;
    fw_status st = FW_OK;
    if (w->started)
        st = fw_fail(err, FW_EINPUT, "vessels are added before the world starts");
    else if (w->nv == MAX_VESSELS)
        st = fw_fail(err, FW_EINPUT, "a world holds at most %d vessels", MAX_VESSELS);
    else if (!(v = calloc(1, sizeof *v)))
        st = fw_fail(err, FW_ERUN, "out of memory");
    for (int i = 0; !st && i < w->nv; i++)
        if (def->id && strcmp(w->v[i]->id, def->id) == 0)
            st = fw_fail(err, FW_EINPUT, "vessel '%s' added twice", def->id);
    if (!st && v)
        st = fw_vessel_init(v, def, w->def.step, err);
    if (st) {
        /* taken over also on failure: v->ctl is not set yet, so v's free
         * leaves it alone */
        fw_controller_destroy(def->controller);
        if (v)
            fw_vessel_free(v);
        free(v);
        return st;
    }
    v->ctl = def->controller;
    w->v[w->nv++] = v;
    if (out)
        *out = v;
    return FW_OK;
}

static int cmp_id(const void *a, const void *b)
{
    return strcmp(((const fw_target *)a)->id, ((const fw_target *)b)->id);
}

/* Vessel i's view: the source's ships (the own ship's only), then the other
 * vessels within its sight; sorted by id. */
static fw_status sense(fw_world *w, int i, const fw_target *src, int n_src, fw_error *err)
{
    fw_vessel *v = w->v[i];
    fw_status st = fw_vessel_reserve(v, n_src + w->nv, err);
    if (st)
        return st;
    int n = 0;
    if (i == 0 && n_src > 0) {
        memcpy(v->view, src, sizeof *src * (size_t)n_src);
        n = n_src;
    }
    bool extra = false;
    for (int j = 0; j < w->nv; j++) {
        const fw_target *o = &w->v[j]->record;
        if (j == i || hypot(o->east - v->record.east, o->north - v->record.north) > v->radius)
            continue;
        v->view[n++] = *o;
        extra = true;
    }
    if (extra)
        qsort(v->view, (size_t)n, sizeof *v->view, cmp_id);
    v->n_view = n;
    return FW_OK;
}

static fw_status decide(fw_world *w, int i, fw_error *err)
{
    fw_vessel *v = w->v[i];
    if (!v->ctl) {
        v->d = (fw_decision){.mode = FW_MODE_STANDBY, .helm = 0.0, .reason = "no controller",
                             .primary = -1};
        return FW_OK;
    }
    fw_sense in = {.t = fw_world_time(w), .own = &v->own, .targets = v->view, .n = v->n_view,
                   .as = v->as, .order = v->order};
    return v->ctl->ops->decide(v->ctl, &in, &v->d, err);
}

static fw_status sense_and_decide(fw_world *w, fw_error *err)
{
    const fw_target *src = NULL;
    int n_src = 0;
    fw_status st = FW_OK;
    fw_world_timing *tm = &w->timing;
    double t = tick(w);
    if (w->source && w->nv > 0)
        st = fw_source_around(w->source, &src, &n_src, err);
    lap(w, &tm->read, &t);
    for (int i = 0; !st && i < w->nv; i++)
        st = sense(w, i, src, n_src, err);
    for (int i = 0; !st && i < w->nv; i++)
        st = decide(w, i, err);
    lap(w, &tm->decide, &t);
    /* the reactive traffic watches its own, wider circle (traffic/source.h) */
    if (!st && w->source && fw_reactions_active(w->react)) {
        if (w->nv > 0)
            st = fw_source_nearby(w->source, &src, &n_src, err);
        if (!st)
            st = fw_reactions_step(w->react, fw_world_time(w),
                                   w->nv > 0 ? &w->v[0]->record : NULL, src, n_src, w->source,
                                   err);
        lap(w, &tm->reactions, &t);
    }
    return st;
}

fw_status fw_world_start(fw_world *w, fw_error *err)
{
    if (w->started)
        return fw_fail(err, FW_EINPUT, "the world has already started");
    w->started = true;
    fw_status st = FW_OK;
    if (w->source && w->nv > 0)
        st = fw_source_place(w->source, &w->v[0]->record, err);
    if (!st)
        st = sense_and_decide(w, err);
    w->broken = st != FW_OK;
    return st;
}

fw_status fw_world_step(fw_world *w, double dt, fw_error *err)
{
    if (!w->started || w->broken)
        return fw_fail(err, FW_ERUN, w->broken ? "the world failed in an earlier step"
                                              : "fw_world_start first");
    if (fabs(dt - w->def.step) > 1e-9 * w->def.step)
        return fw_fail(err, FW_EINPUT, "step %g s: this world steps %g s", dt, w->def.step);
    fw_status st = FW_OK;
    fw_world_timing *tm = &w->timing;
    double t = tick(w);
    for (int i = 0; !st && i < w->nv; i++)
        st = fw_vessel_advance(w->v[i], w->def.step, err);
    lap(w, &tm->dynamics, &t);
    if (!st && w->source) {
        if (w->nv > 0)
            st = fw_source_place(w->source, &w->v[0]->record, err);
        lap(w, &tm->place, &t);
        if (!st)
            st = fw_source_advance(w->source, err);
        lap(w, &tm->traffic, &t);
    }
    if (!st) {
        w->steps++;
        st = sense_and_decide(w, err);
    }
    w->broken = st != FW_OK;
    return st;
}

const fw_world_timing *fw_world_timing_of(const fw_world *w) { return &w->timing; }
double fw_world_time(const fw_world *w) { return (double)w->steps * w->def.step; }
long fw_world_steps(const fw_world *w) { return w->steps; }
int fw_world_vessel_count(const fw_world *w) { return w->nv; }
fw_vessel *fw_world_vessel(fw_world *w, int i) { return i >= 0 && i < w->nv ? w->v[i] : NULL; }
fw_source *fw_world_source(fw_world *w) { return w->source; }

const fw_reaction *fw_world_reactions(const fw_world *w, int *n)
{
    return fw_reactions_list(w->react, n);
}

fw_status fw_world_area(fw_world *w, const fw_target **ships, int *n, fw_error *err)
{
    *ships = NULL;
    *n = 0;
    if (!w->source)
        return fw_fail(err, FW_ERUN, "no area query without a traffic source");
    return fw_source_area(w->source, ships, n, err);
}
