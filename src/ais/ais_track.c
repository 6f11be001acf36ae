/* ais_track.c - AIS reports into per-ship tracks in the plane (ais_track.h). */
#include "ais/ais_track.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/idmap.h"
#include "core/mem.h"
#include "core/units.h"
#include "geom/geo.h"

fw_ais_track_def fw_default_ais_track_def(void)
{
    return (fw_ais_track_def){.start = NAN, .end = NAN, .max_gap = 300.0,
                              .area_radius = 100e3};
}

void fw_ais_tracks_free(fw_ais_tracks *t)
{
    fw_rec_tracks_free(t->v, t->n);
    free(t->ships);
    t->v = NULL;
    t->ships = NULL;
    t->n = 0;
}

/* What the reading collects. */
typedef struct collect {
    fw_ais_tracks *t;
    fw_idmap ids;
    double *last_t; /* per ship, the time of its previous row (out of order) */
    int cap;
    fw_geo *geo;
    double lo, hi;  /* s UTC, the points kept (the window widened by max_gap) */
    double radius;
    const char *file;
} collect;

static fw_status new_ship(collect *c, const fw_ais_report *r, int idx, fw_error *err)
{
    fw_ais_tracks *t = c->t;
    if (idx >= c->cap) {
        int cap = fw_grown_cap(c->cap, 64);
        if (!fw_resize_each((size_t)cap, 3, (void **)&t->v, sizeof *t->v, (void **)&t->ships,
                            sizeof *t->ships, (void **)&c->last_t, sizeof *c->last_t))
            return fw_fail(err, FW_ERUN, "out of memory for %d ships", idx + 1);
        c->cap = cap;
    }
    memset(&t->v[idx], 0, sizeof t->v[idx]);
    snprintf(t->v[idx].info.id, sizeof t->v[idx].info.id, "%ld", r->mmsi);
    t->ships[idx] = (fw_ais_ship){.mmsi = r->mmsi};
    c->last_t[idx] = -INFINITY;
    t->n = idx + 1;
    return FW_OK;
}

/* One kept report into its ship's track. */
static fw_status add(collect *c, const fw_ais_report *r, fw_error *err)
{
    fw_ais_tracks *t = c->t;
    if (r->t < c->lo || r->t > c->hi) {
        t->outside_window++;
        return FW_OK;
    }
    double e, n, gamma;
    fw_status st = FW_OK;
    fw_error perr = {0}; /* why PROJ failed: the count says it, not the read */
    if (fw_geo_to_plane(c->geo, r->lat, r->lon, &e, &n, &perr) ||
        (hypot(e, n) <= c->radius && fw_geo_convergence(c->geo, r->lat, r->lon, &gamma, &perr))) {
        if (t->unprojected++ == 0)
            snprintf(t->unprojected_at, sizeof t->unprojected_at, "%s:%d", c->file, r->line);
        return FW_OK;
    }
    if (!(hypot(e, n) <= c->radius)) {
        t->outside_area++;
        return FW_OK;
    }
    char id[24];
    snprintf(id, sizeof id, "%ld", r->mmsi);
    int idx;
    if (fw_idmap_intern(&c->ids, id, &idx) != 0 ||
        (idx >= t->n && (st = new_ship(c, r, idx, err))))
        return st ? st : fw_fail(err, FW_ERUN, "out of memory");
    fw_rec_track *tr = &t->v[idx];
    fw_ais_ship *sh = &t->ships[idx];
    if (!fw_rec_track_reserve(tr))
        return fw_fail(err, FW_ERUN, "out of memory for ship %s's reports", id);
    t->out_of_order += r->t < c->last_t[idx];
    c->last_t[idx] = r->t;
    double course = !isnan(r->cog) ? r->cog : r->heading;
    tr->p[tr->n++] = (fw_rec_point){.t = r->t, .east = e, .north = n,
                                    .course = isnan(course) ? NAN : fw_wrap_2pi(course - gamma),
                                    .speed = r->sog};
    sh->class_b = r->class_b;
    if (r->kind != FW_AIS_UNKNOWN) {
        sh->kind = r->kind;
        sh->type_code = r->type_code;
    }
    if (r->length > 0 && r->breadth > 0 && r->breadth <= r->length) {
        tr->info.length = r->length;
        tr->info.breadth = r->breadth;
    }
    return FW_OK;
}

static int cmp_point(const void *a, const void *b)
{
    double x = ((const fw_rec_point *)a)->t, y = ((const fw_rec_point *)b)->t;
    return (x > y) - (x < y);
}

/* Course and speed where the reports gave none: the motion between this
 * point and a neighbour within max_gap. */
static void fill_motion(fw_rec_track *tr, double max_gap)
{
    for (int j = 0; j < tr->n; j++) {
        fw_rec_point *p = &tr->p[j];
        if (!isnan(p->course) && !isnan(p->speed))
            continue;
        const fw_rec_point *a = NULL, *b = NULL;
        if (j + 1 < tr->n && tr->p[j + 1].t - p->t <= max_gap)
            a = p, b = p + 1;
        else if (j > 0 && p->t - tr->p[j - 1].t <= max_gap)
            a = p - 1, b = p;
        double de = a ? b->east - a->east : 0, dn = a ? b->north - a->north : 0;
        double d = hypot(de, dn);
        if (isnan(p->speed))
            p->speed = a ? d / (b->t - a->t) : 0.0;
        if (isnan(p->course))
            p->course = d > 0 ? fw_wrap_2pi(atan2(de, dn)) : j > 0 ? tr->p[j - 1].course : NAN;
    }
    /* a ship that never moved nor said where it headed: north */
    for (int j = tr->n - 1; j >= 0; j--)
        if (isnan(tr->p[j].course))
            tr->p[j].course = j + 1 < tr->n ? tr->p[j + 1].course : 0.0;
}

/* Sorts each ship's points, drops duplicates, fills course and speed, and
 * makes times relative to t0. */
static void finish(fw_ais_tracks *t, double max_gap)
{
    for (int i = 0; i < t->n; i++) {
        fw_rec_track *tr = &t->v[i];
        qsort(tr->p, (size_t)tr->n, sizeof *tr->p, cmp_point);
        int k = 0;
        long clashes = t->clashes;
        for (int j = 0; j < tr->n; j++) {
            const fw_rec_point *p = &tr->p[j], *q = &tr->p[k > 0 ? k - 1 : 0];
            if (k > 0 && p->t == q->t) {
                t->duplicates++;
                t->clashes += hypot(p->east - q->east, p->north - q->north) > FW_AIS_CLASH_M;
                continue;
            }
            tr->p[k++] = *p;
        }
        if (t->clashes > clashes && t->clash_ships++ == 0)
            t->clash_first = t->ships[i].mmsi;
        tr->n = k;
        fill_motion(tr, max_gap);
        for (int j = 0; j < tr->n; j++)
            tr->p[j].t -= t->t0;
        snprintf(tr->info.type, sizeof tr->info.type, "%s", fw_ais_kind_name(t->ships[i].kind));
        t->points += tr->n;
    }
}

/* The earliest kept report of the file (a first pass, for a window given
 * relative to it). */
static fw_status first_time(const char *path, const fw_ais_columns *cols, double *t0,
                            fw_error *err)
{
    fw_ais_reader *rd;
    fw_status st = fw_ais_open(path, cols, &rd, err);
    fw_ais_report r;
    bool got = true;
    while (!st && got)
        st = fw_ais_next(rd, &r, &got, err);
    if (!st)
        *t0 = fw_ais_counts_of(rd)->t_first;
    fw_ais_close(rd);
    return st;
}

/* The window in UTC seconds (NAN where open). */
static fw_status window(const char *path, const fw_ais_track_def *def, double *start,
                        double *end, fw_error *err)
{
    *start = def->start;
    *end = def->end;
    double first = NAN;
    fw_status st;
    if ((def->start_rel && !isnan(def->start)) || (def->end_rel && !isnan(def->end))) {
        if ((st = first_time(path, def->cols, &first, err)))
            return st;
        if (isnan(first))
            return fw_fail(err, FW_EINPUT, "%s: no ship reports", path);
        if (def->start_rel)
            *start += first;
        if (def->end_rel)
            *end += first;
    }
    if (!isnan(*start) && !isnan(*end) && !(*end > *start))
        return fw_fail(err, FW_EINPUT, "%s: the time window is empty (its end is not after its "
                                       "start)", path);
    return FW_OK;
}

fw_status fw_ais_tracks_load(const char *path, const fw_ais_track_def *def, fw_ais_tracks *out,
                             fw_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(def->max_gap > 0.0) || !(def->area_radius > 0.0))
        return fw_fail(err, FW_EINPUT, "AIS tracks: max_gap and area radius must be > 0");
    double start, end;
    fw_status st = window(path, def, &start, &end, err);
    if (st)
        return st;
    collect c = {.t = out, .lo = isnan(start) ? -INFINITY : start - def->max_gap,
                 .hi = isnan(end) ? INFINITY : end + def->max_gap, .radius = def->area_radius,
                 .file = path};
    fw_ais_reader *rd = NULL;
    if ((st = def->proj ? fw_geo_create_proj(def->proj, def->off_e, def->off_n, &c.geo, err)
                        : fw_geo_create(def->origin_lat, def->origin_lon, &c.geo, err)) ||
        (st = fw_ais_open(path, def->cols, &rd, err)))
        goto out;
    fw_ais_report r;
    bool got = true;
    while (!st && got)
        if (!(st = fw_ais_next(rd, &r, &got, err)) && got)
            st = add(&c, &r, err);
    if (st)
        goto out;
    out->counts = *fw_ais_counts_of(rd);
    out->max_gap = def->max_gap;
    out->t0 = !isnan(start) ? start : out->counts.t_first;
    if (isnan(out->t0))
        out->t0 = 0.0; /* no reports at all */
    finish(out, def->max_gap);
    out->t_end = (!isnan(end) ? end : out->counts.t_last) - out->t0;
    if (!(out->t_end >= 0))
        out->t_end = 0.0;
out:
    fw_ais_close(rd);
    fw_geo_destroy(c.geo);
    fw_idmap_free(&c.ids);
    free(c.last_t);
    return st;
}

fw_status fw_ais_replay_source_create(fw_ais_tracks *t, const fw_replay_def *def,
                                      fw_source **out, fw_error *err)
{
    fw_rec_track *v = t->v;
    t->v = NULL;
    int n = t->n;
    fw_status st = fw_track_source_create(v, n, def, "AIS tracks", out, err);
    free(t->ships);
    t->ships = NULL;
    t->n = 0;
    return st;
}

fw_status fw_ais_tracks_print_csv(const fw_ais_tracks *t, FILE *f, fw_error *err)
{
    fprintf(f, "t_s,id,east_m,north_m,course_deg,speed_kn,type,length_m,breadth_m\n");
    for (int i = 0; i < t->n; i++) {
        const fw_rec_track *tr = &t->v[i];
        for (int j = 0; j < tr->n; j++) {
            const fw_rec_point *p = &tr->p[j];
            fprintf(f, "%.3f,%s,%.3f,%.3f,%.3f,%.3f,%s,%.1f,%.1f\n", p->t, tr->info.id, p->east,
                    p->north, fw_rad_to_deg(p->course), fw_ms_to_kn(p->speed), tr->info.type,
                    tr->info.length, tr->info.breadth);
        }
    }
    return ferror(f) ? fw_fail(err, FW_ERUN, "cannot write the tracks: %s", strerror(errno ? errno : EIO))
                    : FW_OK;
}

fw_status fw_ais_tracks_write_csv(const fw_ais_tracks *t, const char *path, fw_error *err)
{
    char tmp[1100];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fw_status st;
    if ((st = fw_ais_tracks_print_csv(t, f, err))) {
        fw_file_abort(f, tmp);
        return st;
    }
    return fw_file_commit(f, tmp, path, err);
}

void fw_ais_tracks_print(FILE *out, const fw_ais_tracks *t)
{
    fw_ais_print_counts(out, &t->counts);
    char a[32];
    fw_ais_format_time(t->t0, a, sizeof a);
    fprintf(out, "out of order: %ld\nduplicates dropped: %ld\noutside the time window: %ld\n"
                 "outside the area: %ld\nships: %d, %ld points from %s UTC (t = 0) to t = %.0f s\n",
            t->out_of_order, t->duplicates, t->outside_window, t->outside_area, t->n, t->points,
            a, t->t_end);
    if (t->unprojected > 0)
        fprintf(out, "cannot be projected into the plane: %ld (the first at %s)\n", t->unprojected,
                t->unprojected_at);
    if (t->clashes > 0)
        fprintf(out, "two ships on one MMSI (reports at one instant more than %.0f m apart, one "
                     "dropped): %ld on %d MMSIs, the first %ld\n",
                FW_AIS_CLASH_M, t->clashes, t->clash_ships, t->clash_first);
}
