/* survey.c - pair episodes of the traffic survey (see survey.h). */
#include "survey/survey.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mem.h"
#include "survey/survey_index.h"

/* Coordinates beyond this are no position on Earth (and would overflow the
 * grid's cell numbers). */
static const double kMaxCoord = 1e9;

struct fw_survey {
    fw_survey_def def;
    double release;      /* m, range + hysteresis */
    bool finished;
    long steps;          /* accepted steps */
    long stamp;          /* every step call, refused ones too: marks "seen now" */
    double t;            /* s, time of the step being taken */
    double t_prev;
    int n_prev;
    double ship_s;
    fw_idmap ids; /* ship ids interned (core/idmap.h) */
    long *seen;          /* per interned id: stamp of the last step it was in */
    int seen_cap;
    /* the step being taken, by position in the caller's array */
    const fw_target *in;
    int *cid;            /* interned id */
    double *x, *y, *vx, *vy;
    int cap;
    sv_pairs pairs;      /* pair -> its latest record */
    sv_grid grid;
    /* one record per episode, in creation order until finished */
    fw_survey_record *rec;
    int *rec_a, *rec_b;  /* interned ids of the pair */
    long *touched;       /* stamp of the last step the pair was within release */
    double *t_seen;      /* s, and that step's time */
    int nrec, rec_cap;
    int *active;         /* records whose episode is open */
    bool *is_open;
    int nactive;
    bool oom;            /* set inside the pair callback */
    fw_error lane_err;   /* the first failure of def.lane in a step */
};

fw_survey_def fw_default_survey_def(void)
{
    fw_survey_def d = {.range = 2000.0, .dcpa = 1000.0, .tcpa = 1000.0, .hysteresis = 500.0,
                       .max_gap = 60.0, .colregs = fw_default_colregs_def(), .brute_force = false};
    /* fw_classify's head-on bearing test (each ship within 6 deg of the
     * other's bow) is made for the own ship deciding at several miles; inside
     * the survey's range a reciprocal pair passing d apart is asin(d / range)
     * off the bow (14 deg for 500 m at 2000 m).  Here head-on is the course
     * test alone (reciprocal within head_on_course_tol_deg); overtaking and
     * crossing are fw_classify's. */
    d.colregs.head_on_bearing_deg = 180.0;
    return d;
}

const char *fw_survey_type_name(fw_survey_type t)
{
    switch (t) {
    case FW_SURVEY_HEAD_ON: return "head-on";
    case FW_SURVEY_OVERTAKING: return "overtaking";
    case FW_SURVEY_CROSSING: return "crossing";
    }
    return "?";
}

static bool positive(double v) { return isfinite(v) && v > 0.0; }

fw_status fw_survey_create(const fw_survey_def *def, fw_survey **out, fw_error *err)
{
    *out = NULL;
    if (!positive(def->range) || def->range > 1e6)
        return fw_fail(err, FW_EINPUT, "survey range %g m: must be in (0, 1e6]", def->range);
    if (!positive(def->dcpa))
        return fw_fail(err, FW_EINPUT, "survey DCPA %g m: must be positive", def->dcpa);
    if (!positive(def->tcpa))
        return fw_fail(err, FW_EINPUT, "survey TCPA %g s: must be positive", def->tcpa);
    if (!isfinite(def->hysteresis) || def->hysteresis < 0.0 || def->hysteresis > 1e6)
        return fw_fail(err, FW_EINPUT, "survey hysteresis %g m: must be in [0, 1e6]",
                       def->hysteresis);
    if (!isfinite(def->max_gap) || def->max_gap < 0.0)
        return fw_fail(err, FW_EINPUT, "survey gap %g s: must be finite and >= 0", def->max_gap);
    const fw_colregs_def *c = &def->colregs;
    if (!(c->head_on_bearing_deg >= 0.0 && c->head_on_bearing_deg <= 180.0) ||
        !(c->head_on_course_tol_deg >= 0.0 && c->head_on_course_tol_deg <= 90.0) ||
        !(c->overtake_sector_deg >= 90.0 && c->overtake_sector_deg <= 180.0))
        return fw_fail(err, FW_EINPUT, "survey COLREGs thresholds out of range");
    fw_survey *sv = calloc(1, sizeof *sv);
    if (!sv)
        return fw_fail(err, FW_ERUN, "out of memory");
    sv->def = *def;
    sv->release = def->range + def->hysteresis;
    *out = sv;
    return FW_OK;
}

void fw_survey_destroy(fw_survey *sv)
{
    if (!sv)
        return;
    fw_idmap_free(&sv->ids);
    sv_pairs_free(&sv->pairs);
    sv_grid_free(&sv->grid);
    fw_free_each(14, sv->seen, sv->cid, sv->x, sv->y, sv->vx, sv->vy, sv->rec, sv->rec_a,
                     sv->rec_b, sv->touched, sv->t_seen, sv->active, sv->is_open, sv);
}

static bool reserve_step(fw_survey *sv, int n)
{
    if (n <= sv->cap)
        return true;
    int cap = fw_grown_cap(sv->cap, n);
    if (!fw_resize_each((size_t)cap, 5, (void **)&sv->cid, sizeof *sv->cid,
                        (void **)&sv->x, sizeof *sv->x, (void **)&sv->y, sizeof *sv->y,
                        (void **)&sv->vx, sizeof *sv->vx, (void **)&sv->vy, sizeof *sv->vy))
        return false;
    sv->cap = cap;
    return true;
}

static bool reserve_records(fw_survey *sv)
{
    if (sv->nrec < sv->rec_cap)
        return true;
    int cap = sv->rec_cap ? 2 * sv->rec_cap : 64;
    if (!fw_resize_each((size_t)cap, 7, (void **)&sv->rec, sizeof *sv->rec,
                        (void **)&sv->rec_a, sizeof *sv->rec_a,
                        (void **)&sv->rec_b, sizeof *sv->rec_b,
                        (void **)&sv->touched, sizeof *sv->touched,
                        (void **)&sv->t_seen, sizeof *sv->t_seen,
                        (void **)&sv->active, sizeof *sv->active,
                        (void **)&sv->is_open, sizeof *sv->is_open))
        return false;
    sv->rec_cap = cap;
    return true;
}

static fw_survey_type pair_type(fw_survey *sv, const fw_target *a, const fw_target *b)
{
    fw_own_state own = {.east = a->east, .north = a->north, .psi = a->heading, .U = a->speed};
    const fw_lane_info *la = NULL, *lb = NULL;
    if (sv->def.lane && !sv->lane_err.status &&
        (sv->def.lane(sv->def.lane_ctx, a, &la, &sv->lane_err) ||
         sv->def.lane(sv->def.lane_ctx, b, &lb, &sv->lane_err)))
        la = lb = NULL; /* the step fails with lane_err */
    /* fw_classify's roles swap with the ships (give-way <-> stand-on,
     * overtaking <-> being overtaken), so the pair's type is symmetric
     * (fw_lanes_meet is) */
    switch (fw_classify_lanes(&sv->def.colregs, &own, a, la, b, lb)) {
    case FW_SIT_HEAD_ON: return FW_SURVEY_HEAD_ON;
    case FW_SIT_OVERTAKING:
    case FW_SIT_OVERTAKEN: return FW_SURVEY_OVERTAKING;
    case FW_SIT_GIVE_WAY:
    case FW_SIT_STAND_ON: break;
    }
    return FW_SURVEY_CROSSING;
}

/* Hull to hull for a pair whose centres are d apart, INFINITY when they are
 * too far apart to be within FW_SURVEY_HULL_WATCH of touching. */
static double hull_gap(const fw_target *a, const fw_target *b, double d)
{
    double reach = 0.5 * (hypot(a->length, a->breadth) + hypot(b->length, b->breadth));
    if (d > reach + FW_SURVEY_HULL_WATCH)
        return INFINITY;
    return fw_hull_distance(a->east, a->north, a->heading, a->length, a->breadth, b->east,
                            b->north, b->heading, b->length, b->breadth);
}

/* A pair within release range this step (i, j: positions in the step). */
static void on_pair(void *ctx, int i, int j, double d2)
{
    fw_survey *sv = ctx;
    if (sv->oom)
        return;
    double d = sqrt(d2);
    uint64_t key = sv_pair_key(sv->cid[i], sv->cid[j]);
    int e = sv_pairs_get(&sv->pairs, key);
    if (e >= 0 && sv->is_open[e]) {
        sv->touched[e] = sv->stamp;
        sv->t_seen[e] = sv->t;
        if (d < sv->rec[e].min_dist) {
            sv->rec[e].min_dist = d;
            sv->rec[e].t_min = sv->t;
        }
        sv->rec[e].min_hull = fmin(sv->rec[e].min_hull, hull_gap(&sv->in[i], &sv->in[j], d));
        return;
    }
    if (!(d < sv->def.range))
        return;
    /* swapping i and j negates dx, dy, ux, uy exactly: TCPA and DCPA have
     * the same bits whatever the order of the input */
    double dx = sv->x[j] - sv->x[i], dy = sv->y[j] - sv->y[i];
    double ux = sv->vx[j] - sv->vx[i], uy = sv->vy[j] - sv->vy[i];
    double u2 = ux * ux + uy * uy;
    if (u2 < 1e-12)
        return; /* no relative motion: no closest point ahead */
    double tcpa, dcpa;
    fw_cpa(dx, dy, ux, uy, &tcpa, &dcpa);
    if (!(tcpa > 0.0 && tcpa < sv->def.tcpa))
        return;
    if (!fw_clearly_below(dcpa, sv->def.dcpa)) /* not by rounding: geom.h */
        return;
    /* a new episode: named and classified from the smaller id's side */
    int a = i, b = j;
    if (strcmp(sv->in[i].id, sv->in[j].id) > 0) {
        a = j;
        b = i;
    }
    if (!reserve_records(sv)) {
        sv->oom = true;
        return;
    }
    int r = sv->nrec;
    if (sv_pairs_put(&sv->pairs, key, r)) {
        sv->oom = true;
        return;
    }
    sv->nrec++;
    const fw_target *sa = &sv->in[a], *sb = &sv->in[b];
    fw_survey_record *o = &sv->rec[r];
    memset(o, 0, sizeof *o);
    snprintf(o->ship_a, sizeof o->ship_a, "%s", sa->id);
    snprintf(o->ship_b, sizeof o->ship_b, "%s", sb->id);
    o->type = pair_type(sv, sa, sb);
    o->own = sa->own || sb->own;
    o->t_first = sv->t;
    o->range0 = d;
    o->dcpa0 = dcpa;
    o->tcpa0 = tcpa;
    o->min_dist = d;
    o->t_min = sv->t;
    o->min_hull = hull_gap(sa, sb, d);
    fw_hull_track ka = fw_hull_track_of(sa), kb = fw_hull_track_of(sb);
    o->cand_miss = fw_hull_cpa(&ka, &kb, INFINITY, NULL);
    o->length_a = sa->length;
    o->breadth_a = sa->breadth;
    o->length_b = sb->length;
    o->breadth_b = sb->breadth;
    sv->rec_a[r] = sv->cid[a];
    sv->rec_b[r] = sv->cid[b];
    sv->touched[r] = sv->stamp;
    sv->t_seen[r] = sv->t;
    sv->is_open[r] = true;
    sv->active[sv->nactive++] = r;
}

/* Ships up to which a step tests all pairs: the grid's set-up (cells over
 * the area, a counting sort) costs more below (measured on points in a 6 nm
 * circle, range 2500 m: 4 ships 110 ns by the grid, 19 ns all pairs; 19
 * ships 600 against 430 ns; the two meet some way above, where the grid's
 * linear growth starts to pay). */
enum { kAllPairsUpTo = 24 };

static fw_status check_ship(const fw_target *s, int k, fw_error *err)
{
    size_t len = strnlen(s->id, sizeof s->id);
    if (len == 0 || len >= FW_SURVEY_ID_MAX)
        return fw_fail(err, FW_ERUN, "survey: ship %d has %s id", k,
                       len ? "a too long" : "no");
    if (!(fabs(s->east) <= kMaxCoord && fabs(s->north) <= kMaxCoord) || !isfinite(s->course) ||
        !isfinite(s->heading) ||
        !(s->speed >= 0.0 && s->speed < 1e3) || !(s->length >= 0.0 && s->length < 1e4) ||
        !(s->breadth >= 0.0 && s->breadth < 1e4))
        return fw_fail(err, FW_ERUN,
                       "survey: ship '%s' at (%g, %g) heading %g speed %g size %g x %g: "
                       "not a ship state", s->id, s->east, s->north, s->course, s->speed,
                       s->length, s->breadth);
    return FW_OK;
}

fw_status fw_survey_step(fw_survey *sv, double t, const fw_target *ships, int n,
                         fw_error *err)
{
    sv->stamp++;
    if (sv->finished)
        return fw_fail(err, FW_ERUN, "survey: step after the survey finished");
    if (!isfinite(t) || (sv->steps > 0 && !(t > sv->t_prev)))
        return fw_fail(err, FW_ERUN, "survey: time %g s does not follow %g s", t, sv->t_prev);
    if (n < 0 || (n > 0 && !ships))
        return fw_fail(err, FW_ERUN, "survey: %d ships", n);
    for (int k = 0; k < n; k++)
        if (check_ship(&ships[k], k, err))
            return FW_ERUN;
    if (!reserve_step(sv, n))
        return fw_fail(err, FW_ERUN, "survey: out of memory for %d ships", n);
    for (int k = 0; k < n; k++) {
        int id;
        if (fw_idmap_intern_keyed(&sv->ids, ships[k].key, ships[k].id, &id))
            return fw_fail(err, FW_ERUN, "survey: out of memory for ship ids");
        if (sv->ids.n > sv->seen_cap) {
            int cap = 2 * sv->ids.n;
            long *seen = realloc(sv->seen, sizeof *seen * (size_t)cap);
            if (!seen)
                return fw_fail(err, FW_ERUN, "survey: out of memory for ship ids");
            for (int q = sv->seen_cap; q < cap; q++)
                seen[q] = 0;
            sv->seen = seen;
            sv->seen_cap = cap;
        }
        /* the stamp is new for every call, so a refused step leaves no mark */
        if (sv->seen[id] == sv->stamp)
            return fw_fail(err, FW_ERUN, "survey: ship '%s' twice at t = %g s", ships[k].id, t);
        sv->seen[id] = sv->stamp;
        const fw_target *s = &ships[k];
        sv->cid[k] = id;
        sv->x[k] = s->east;
        sv->y[k] = s->north;
        fw_velocity(s->speed, s->course, &sv->vx[k], &sv->vy[k]);
    }
    /* accepted from here on */
    sv->in = ships;
    sv->t = t;
    sv->oom = false;
    sv->lane_err = (fw_error){0};
    /* a handful of ships (the usual area about one own ship): all pairs
     * cost less than building the grid; the records are the same either
     * way (the pair order is lost in the final sort, test_survey) */
    if (sv->def.brute_force || n <= kAllPairsUpTo)
        sv_brute_pairs(sv->x, sv->y, n, sv->release, on_pair, sv);
    else if (sv_grid_pairs(&sv->grid, sv->x, sv->y, n, sv->release, on_pair, sv))
        sv->oom = true;
    sv->in = NULL;
    if (sv->oom)
        return fw_fail(err, FW_ERUN, "survey: out of memory at t = %g s", t);
    if (sv->lane_err.status) {
        *err = sv->lane_err;
        return err->status;
    }
    /* an episode ends when both ships are here and no longer close, or when
     * one has been missing longer than max_gap (it left the area): a short
     * absence keeps it open, and the open list stays as long as the traffic
     * is dense, not as long as the run */
    int m = 0;
    for (int q = 0; q < sv->nactive; q++) {
        int r = sv->active[q];
        bool keep = sv->touched[r] == sv->stamp;
        if (!keep) {
            bool both = sv->seen[sv->rec_a[r]] == sv->stamp && sv->seen[sv->rec_b[r]] == sv->stamp;
            keep = !both && t - sv->t_seen[r] <= sv->def.max_gap;
        }
        if (keep)
            sv->active[m++] = r;
        else
            sv->is_open[r] = false;
    }
    sv->nactive = m;
    if (sv->steps > 0)
        sv->ship_s += sv->n_prev * (t - sv->t_prev);
    sv->t_prev = t;
    sv->n_prev = n;
    sv->steps++;
    return FW_OK;
}

static int cmp_record(const void *p, const void *q)
{
    const fw_survey_record *a = p, *b = q;
    if (a->t_first != b->t_first)
        return a->t_first < b->t_first ? -1 : 1;
    int c = strcmp(a->ship_a, b->ship_a);
    return c ? c : strcmp(a->ship_b, b->ship_b);
}

void fw_survey_count(const fw_survey_record *r, int n, fw_survey_totals *tot)
{
    tot->n = n;
    tot->n_own = 0;
    for (int k = 0; k < FW_SURVEY_NTYPES; k++)
        tot->by_type[k] = 0;
    for (int i = 0; i < n; i++) {
        if ((unsigned)r[i].type < FW_SURVEY_NTYPES)
            tot->by_type[r[i].type]++;
        tot->n_own += r[i].own;
    }
}

void fw_survey_finish(fw_survey *sv, fw_survey_totals *tot)
{
    if (!sv->finished) {
        /* the bookkeeping arrays are indexed by creation order: no use after this */
        if (sv->nrec > 1)
            qsort(sv->rec, (size_t)sv->nrec, sizeof *sv->rec, cmp_record);
        sv->nactive = 0;
        sv->finished = true;
    }
    if (tot) {
        tot->steps = sv->steps;
        tot->ship_s = sv->ship_s;
        fw_survey_count(sv->rec, sv->nrec, tot);
    }
}

const fw_survey_record *fw_survey_records(const fw_survey *sv, int *n)
{
    *n = sv->nrec;
    return sv->rec;
}
