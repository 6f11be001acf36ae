/* dnv_situation.c - encounters written as DNV traffic situations (dnv_situation.h). */
#include "run/dnv_situation.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/files.h"
#include "core/json.h"
#include "core/units.h"
#include "geom/geo.h"

typedef struct writer {
    FILE *f;
    fw_geo *g;
} writer;

static int cmp_t(const void *a, const void *b)
{
    double x = ((const fw_rec_point *)a)->t, y = ((const fw_rec_point *)b)->t;
    return (x > y) - (x < y);
}

/* m: how far p is from where the straight leg a-b at constant speed puts
 * the ship at p's time. */
static double sed(const fw_rec_point *a, const fw_rec_point *b, const fw_rec_point *p)
{
    double u = b->t > a->t ? (p->t - a->t) / (b->t - a->t) : 0.0;
    return hypot(a->east + u * (b->east - a->east) - p->east,
                 a->north + u * (b->north - a->north) - p->north);
}

/* Marks keep[k] for the points of p[i..j] the simplification keeps. */
static void simplify(const fw_rec_point *p, int i, int j, double tol, bool *keep)
{
    while (j > i + 1) {
        int worst = -1;
        double dmax = tol;
        for (int k = i + 1; k < j; k++) {
            double d = sed(&p[i], &p[j], &p[k]);
            if (d > dmax)
                dmax = d, worst = k;
        }
        if (worst < 0)
            return;
        keep[worst] = true;
        simplify(p, i, worst, tol, keep);
        i = worst; /* the second half in this frame */
    }
}

fw_status fw_dnv_position(FILE *f, const fw_geo *g, double e, double n, int digits,
                          double *gamma, fw_error *err)
{
    double lat, lon;
    fw_status st = fw_geo_to_latlon(g, e, n, &lat, &lon, err);
    if (!st && gamma)
        st = fw_geo_convergence(g, lat, lon, gamma, err);
    if (!st)
        fprintf(f, "\"position\": {\"lat\": %.*f, \"lon\": %.*f}", digits, lat, digits, lon);
    return st;
}

static fw_status position(writer *w, double e, double n, double *gamma, fw_error *err)
{
    return fw_dnv_position(w->f, w->g, e, n, 10, gamma, err);
}

/* "initial": position, sog, cog, heading (true degrees). */
static fw_status initial(writer *w, double e, double n, double course, double speed,
                         fw_error *err)
{
    double gamma;
    fprintf(w->f, "      \"initial\": {");
    fw_status st = position(w, e, n, &gamma, err);
    double c = fw_heading_deg(fw_wrap_2pi(course + gamma));
    if (!st)
        fprintf(w->f, ", \"sog\": %.6f, \"cog\": %.6f, \"heading\": %.6f, "
                      "\"navStatus\": \"Under way using engine\"},\n",
                fw_ms_to_kn(speed), c, c);
    return st;
}

/* "waypoints" through p[0..m-1] (sorted, kept ones only). */
static fw_status waypoints(writer *w, const fw_rec_point *p, int m, fw_error *err)
{
    fprintf(w->f, "      \"waypoints\": [");
    fw_status st = FW_OK;
    for (int k = 0; k < m && !st; k++) {
        fprintf(w->f, "%s\n        {", k ? "," : "");
        st = position(w, p[k].east, p[k].north, NULL, err);
        if (k > 0)
            fprintf(w->f, ", \"leg\": {\"sog\": %.9f}",
                    fw_ms_to_kn(hypot(p[k].east - p[k - 1].east, p[k].north - p[k - 1].north) /
                                (p[k].t - p[k - 1].t)));
        fprintf(w->f, "}");
    }
    fprintf(w->f, "\n      ],\n");
    return st;
}

/* DNV's AIS ship type of a fairway label. */
static const char *ship_type(const char *label)
{
    static const char *const map[][2] = {{"pass", "Passenger"}, {"ferry", "Passenger"},
                                         {"tank", "Tanker"},    {"tug", "Tug"},
                                         {"fish", "Fishing"},   {"sail", "Sailing"},
                                         {"pilot", "Pilot vessel"}};
    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
        if (strstr(label, map[i][0]))
            return map[i][1];
    return "Cargo";
}

static void static_data(writer *w, int id, const char *name, const char *type, double length,
                        double breadth, bool more)
{
    fprintf(w->f, "      \"static\": {\"id\": %d, \"name\": ", id);
    fw_json_string(w->f, name);
    fprintf(w->f, ", \"shipType\": \"%s\", \"dimensions\": {\"length\": %.2f, \"width\": %.2f, "
                  "\"a\": %.2f, \"b\": %.2f, \"c\": %.2f, \"d\": %.2f}}%s\n",
            ship_type(type), length, breadth, length / 2, length / 2, breadth / 2, breadth / 2,
            more ? "," : "");
}

/* The track's points from its appearance to its end (the duration when
 * it was there to the end), simplified (header); *appear, *vanish: s, 0 and
 * INFINITY for a ship there all the time. */
static fw_status track_points(const fw_rec_track *tr, double duration, double tol,
                              fw_rec_point **out, int *m, double *appear, double *vanish,
                              double *tol_used, fw_error *err)
{
    int n = tr->n;
    fw_rec_point *p = malloc(sizeof *p * (size_t)(n + 1));
    bool *keep = calloc((size_t)n + 1, sizeof *keep);
    if (!p || !keep || n < 1) {
        free(p), free(keep);
        return fw_fail(err, n < 1 ? FW_EINPUT : FW_ERUN, "track of %s: %s", tr->info.id,
                       n < 1 ? "no points" : "out of memory");
    }
    memcpy(p, tr->p, sizeof *p * (size_t)n);
    qsort(p, (size_t)n, sizeof *p, cmp_t);
    fw_rec_point z = p[n - 1];
    *appear = p[0].t;
    /* gone before the end (a recorded track ends where its ship left the
     * sight or the network; one there to the end goes on along its last leg) */
    bool left = z.t < duration - 1.5;
    *vanish = left ? z.t : INFINITY;
    p[n] = z;
    p[n].t = fmax(duration, z.t + 1.0);
    double dz = (p[n].t - z.t) * z.speed;
    p[n].east += dz * sin(z.course), p[n].north += dz * cos(z.course);
    int hi = !left && dz > 1.0 ? n : n - 1;
    /* a reader holds FW_SCN_MAX_WAYPOINTS a ship: a track that needs more
     * (a ship that changed speed for long, each change a leg of its own) is
     * simplified again at twice the tolerance until it fits (*tol_used) */
    *tol_used = tol;
    int kept;
    do {
        memset(keep, 0, sizeof *keep * (size_t)(n + 1));
        keep[0] = keep[hi] = true;
        simplify(p, 0, hi, *tol_used, keep);
        kept = 0;
        for (int k = 0; k <= hi; k++)
            kept += keep[k];
    } while (kept > FW_SCN_MAX_WAYPOINTS && (*tol_used *= 2.0) < 1e4);
    *m = 0;
    for (int k = 0; k <= hi; k++) /* the reader wants legs of 1 m at least */
        if (keep[k] && (*m == 0 || hypot(p[k].east - p[*m - 1].east,
                                         p[k].north - p[*m - 1].north) >= 1.0))
            p[(*m)++] = p[k];
    free(keep);
    *out = p;
    if (*m < 2)
        return fw_fail(err, FW_EINPUT, "track of %s: it does not move (a situation's ships "
                                       "sail from waypoint to waypoint)", tr->info.id);
    return FW_OK;
}

static fw_status own_ship(writer *w, const fw_scenario *s, fw_error *err)
{
    double len = fmax(s->leg, s->speed * s->duration);
    fw_rec_point p[2] = {{.east = s->east, .north = s->north},
                         {.t = len / s->speed, .east = s->east + len * sin(s->course),
                          .north = s->north + len * cos(s->course)}};
    fprintf(w->f, "  \"ownShip\": {\n");
    fw_status st = initial(w, s->east, s->north, s->course, s->speed, err);
    if (!st && !(st = waypoints(w, p, 2, err)))
        static_data(w, 1, s->ship.name, "cargo", s->ship.Loa, s->ship.B, false);
    fprintf(w->f, "  },\n");
    return st;
}

/* A course and speed the reader takes as the one recorded: what a
 * situation's numbers carry (6 decimals of degrees and knots) with room. */
#define MOTION_TOL_DEG 1e-2
#define MOTION_TOL_KN 1e-2
/* s: a motion entry and a waypoint at one time (times are written to ms) */
#define MOTION_SAME_T 1e-3

/* The motion the reader gives the ship from waypoint j of wp[0..m-1] on
 * (scenario/scn_dnv.h: the chord of its leg at the leg's mean speed; the
 * last waypoint, its last leg's). */
static void leg_motion(const fw_rec_point *wp, int m, int j, double *course, double *speed)
{
    int a = j < m - 1 ? j : m - 2;
    double de = wp[a + 1].east - wp[a].east, dn = wp[a + 1].north - wp[a].north;
    *course = atan2(de, dn);
    *speed = hypot(de, dn) / (wp[a + 1].t - wp[a].t);
}

/* The track's recorded motion where the reader would not give it (header:
 * "turns"): every point of a turn, where one ends, and where the recorded
 * course or speed is not what the reader has from the waypoints wp[0..m-1]
 * and the entries before (a ship slowing or speeding up along a leg, or
 * crabbing); *out (malloc'd) the points, *n_out of them. */
static fw_status motion_entries(const fw_rec_track *tr, const fw_rec_point *wp, int m,
                                fw_rec_point **out, int *n_out, fw_error *err)
{
    fw_rec_point *p = malloc(sizeof *p * (size_t)tr->n);
    *out = NULL, *n_out = 0;
    if (!p)
        return fw_fail(err, FW_ERUN, "out of memory");
    memcpy(p, tr->p, sizeof *p * (size_t)tr->n);
    qsort(p, (size_t)tr->n, sizeof *p, cmp_t);
    double course = 0.0, speed = 0.0, rate = 0.0;
    int n = 0;
    for (int k = 0, j = 0; k < tr->n; k++) {
        for (; j < m && wp[j].t <= p[k].t + MOTION_SAME_T; j++)
            leg_motion(wp, m, j, &course, &speed); /* a turn in force goes on */
        bool differs = fabs(fw_wrap_pi(p[k].course - course)) > fw_deg_to_rad(MOTION_TOL_DEG) ||
                       fabs(fw_ms_to_kn(p[k].speed - speed)) > MOTION_TOL_KN;
        if (p[k].turn_rate > 0.0 || rate > 0.0 || differs) {
            p[n++] = p[k];
            course = p[k].course, speed = p[k].speed, rate = p[k].turn_rate;
        }
    }
    *out = p, *n_out = n;
    return FW_OK;
}

/* ", "turns": [[t_s, heading_deg, sog_kn, rate_degps, to_deg], ...]": the
 * motion entries e[0..n-1] (motion_entries, rate 0: at constant velocity
 * from then). */
static void turns(writer *w, const fw_rec_point *e, int n)
{
    fprintf(w->f, ", \"turns\": [");
    for (int k = 0; k < n; k++) {
        double r = e[k].turn_rate;
        fprintf(w->f, "%s[%.3f, %.6f, %.6f, %.6f, %.6f]", k ? ", " : "", e[k].t,
                fw_heading_deg(e[k].course), fw_ms_to_kn(e[k].speed), fw_rad_to_deg(r),
                r > 0.0 ? fw_heading_deg(e[k].turn_to) : 0.0);
    }
    fprintf(w->f, "]");
}

/* fairway's own member of a target (header), when it needs one. */
static void target_fairway(writer *w, const fw_rec_point *e, int n_e, double appear,
                           double vanish, double used, double tol)
{
    fprintf(w->f, "      \"fairway\": {\"appearS\": %.3f", appear);
    if (isfinite(vanish))
        fprintf(w->f, ", \"vanishS\": %.3f", vanish);
    if (used > tol)
        fprintf(w->f, ", \"toleranceM\": %.17g", used);
    if (n_e > 0)
        turns(w, e, n_e);
    fprintf(w->f, "}\n");
}

static fw_status targets(writer *w, const fw_scenario *s, const fw_rec_track *tracks, int n,
                         double tol, fw_error *err)
{
    fprintf(w->f, "  \"targetShips\": [");
    fw_status st = FW_OK;
    for (int i = 0; i < n && !st; i++) {
        fw_rec_point *p = NULL, *e = NULL;
        int m = 0, n_e = 0;
        double appear = 0.0, vanish = INFINITY, used = tol;
        if (!(st = track_points(&tracks[i], s->duration, tol, &p, &m, &appear, &vanish, &used,
                                err)) &&
            !(st = motion_entries(&tracks[i], p, m, &e, &n_e, err))) {
            bool more = appear > 0.0 || isfinite(vanish) || used > tol || n_e > 0;
            fprintf(w->f, "%s\n    {\n", i ? "," : "");
            double c = atan2(p[1].east - p[0].east, p[1].north - p[0].north);
            double v = hypot(p[1].east - p[0].east, p[1].north - p[0].north) / (p[1].t - p[0].t);
            if (!(st = initial(w, p[0].east, p[0].north, c, v, err)) &&
                !(st = waypoints(w, p, m, err)))
                static_data(w, i + 2, tracks[i].info.id, tracks[i].info.type,
                            tracks[i].info.length, tracks[i].info.breadth, more);
            if (!st && more)
                target_fairway(w, e, n_e, appear, vanish, used, tol);
            fprintf(w->f, "    }");
        }
        free(p);
        free(e);
    }
    fprintf(w->f, "\n  ]\n");
    return st;
}

fw_status fw_dnv_situation_write(const fw_scenario *s, const fw_rec_track *tracks, int n,
                                 double tolerance, const char *path, fw_error *err)
{
    writer w = {0};
    fw_status st = fw_scenario_plane(s, &w.g, err);
    if (!st && !w.g)
        st = fw_geo_create(0.0, 0.0, &w.g, err);
    char tmp[1200];
    if (st || !(w.f = fw_file_begin(path, tmp, sizeof tmp, err))) {
        fw_geo_destroy(w.g);
        return st ? st : err->status;
    }
    time_t start = (time_t)(s->situation_output ? s->utc_start : 946684800.0);
    char when[40];
    strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", gmtime(&start));
    fprintf(w.f, "{\n  \"version\": \"0.2.0\",\n  \"title\": ");
    fw_json_string(w.f, s->name);
    fprintf(w.f, ",\n  \"description\": ");
    fw_json_string(w.f, s->description);
    fprintf(w.f, ",\n  \"startTime\": \"%s\",\n", when);
    fprintf(w.f, "  \"fairway\": {\"durationS\": %.17g, \"domainM\": %.17g, "
                 "\"foreAftRatio\": %.17g},\n",
            s->duration, s->helm.domain.size, s->helm.domain.fore_aft_ratio);
    if (!(st = own_ship(&w, s, err)))
        st = targets(&w, s, tracks, n, tolerance, err);
    fprintf(w.f, "}\n");
    fw_geo_destroy(w.g);
    if (st) {
        fw_file_abort(w.f, tmp);
        return st;
    }
    return fw_file_commit(w.f, tmp, path, err);
}

fw_status fw_dnv_situation_of_scenario(const fw_scenario *s, const char *path, fw_error *err)
{
    fw_rec_track *tr = calloc((size_t)s->n_targets + 1, sizeof *tr);
    if (!tr)
        return fw_fail(err, FW_ERUN, "out of memory");
    fw_status st = FW_OK;
    for (int i = 0; i < s->n_targets && !st; i++) {
        const fw_target *t = &s->targets[i];
        tr[i].info = *t;
        tr[i].n = tr[i].cap = 2;
        if (!(tr[i].p = malloc(2 * sizeof *tr[i].p))) {
            st = fw_fail(err, FW_ERUN, "out of memory");
            break;
        }
        double d = t->speed * s->duration;
        tr[i].p[0] = (fw_rec_point){.t = 0.0, .east = t->east, .north = t->north,
                                    .course = t->course, .speed = t->speed};
        tr[i].p[1] = (fw_rec_point){.t = s->duration, .east = t->east + d * sin(t->course),
                                    .north = t->north + d * cos(t->course),
                                    .course = t->course, .speed = t->speed};
    }
    if (!st)
        st = fw_dnv_situation_write(s, tr, s->n_targets, FW_DNV_TOLERANCE_M, path, err);
    fw_rec_tracks_free(tr, s->n_targets);
    return st;
}
