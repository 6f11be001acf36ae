/* ais_demand.c - a network's demand from AIS passes (ais_demand.h). */
#include "ais/ais_demand.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ais/ais_routes.h"
#include "core/files.h"
#include "core/mem.h"
#include "core/units.h"

fw_ais_demand_def fw_default_ais_demand_def(void)
{
    return (fw_ais_demand_def){.network = NULL, .tolerance = FW_NMILE, .along = 0.7,
                               .min_pass = 1000.0};
}

/* One matched pass. */
typedef struct pass {
    int route, vtype; /* vtype -1: the route's own types */
    double sog;       /* m/s, median */
    fw_ais_kind kind;
} pass;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The route p[0..n-1] matches (-1: none). */
static int match(const fw_net_routes *nr, const fw_rec_point *p, int n,
                 const fw_ais_demand_def *def)
{
    double span = hypot(p[n - 1].east - p[0].east, p[n - 1].north - p[0].north);
    if (n < 2 || span < def->min_pass)
        return -1;
    int best = -1;
    double best_d = INFINITY;
    for (int r = 0; r < nr->demand.n; r++) {
        double sum = 0.0, a0 = 0.0, a1 = 0.0, along;
        for (int j = 0; j < n; j++) {
            sum += fw_route_distance(&nr->line[r], p[j].east, p[j].north, &along);
            if (j == 0)
                a0 = along;
            a1 = along;
        }
        double mean = sum / n;
        if (mean <= def->tolerance && a1 - a0 >= def->along * span && mean < best_d) {
            best = r;
            best_d = mean;
        }
    }
    return best;
}

static bool has_prefix(const char *s, const char *const *pre)
{
    for (; *pre; pre++)
        if (strncmp(s, *pre, strlen(*pre)) == 0)
            return true;
    return false;
}

/* The vType a ship of this kind, length and speed becomes (-1: the route's
 * own types). */
static int vtype_of(const fw_net_routes *nr, fw_ais_kind kind, double length, double sog)
{
    static const char *const cargo[] = {"bulk_", "cargo_", "container_", NULL};
    static const char *const tanker[] = {"tanker_", NULL};
    static const char *const ferry[] = {"ferry_", NULL};
    static const char *const small[] = {"small_craft", NULL};
    const char *const *pre = kind == FW_AIS_CARGO                              ? cargo
                             : kind == FW_AIS_TANKER                           ? tanker
                             : kind == FW_AIS_PASSENGER || kind == FW_AIS_HSC ? ferry
                             : kind == FW_AIS_UNKNOWN                          ? NULL
                                                                               : small;
    int best = -1;
    double best_c = INFINITY;
    for (int i = 0; pre && i < nr->n_vtypes; i++) {
        const fw_vtype_info *v = &nr->vtypes[i];
        if (!has_prefix(v->id, pre))
            continue;
        double c = (length > 0 && v->length > 0 ? fabs(length - v->length) / v->length : 0) +
                   (sog > 0 && v->speed > 0 ? fabs(sog - v->speed) / v->speed : 0);
        if (c < best_c) {
            best = i;
            best_c = c;
        }
    }
    return best;
}

/* A pass's median speed (m/s). */
static double median_speed(const fw_rec_point *p, int n)
{
    double *v = malloc((size_t)n * sizeof *v);
    if (!v)
        return 0.0;
    for (int j = 0; j < n; j++)
        v[j] = p[j].speed;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    double m = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    free(v);
    return m;
}

/* Every pass of every ship: matched ones into *out. */
static fw_status passes(const fw_ais_tracks *t, const fw_net_routes *nr,
                        const fw_ais_demand_def *def, pass **out, int *n_out,
                        fw_ais_demand_result *res, fw_error *err)
{
    int cap = 0;
    for (int i = 0; i < t->n; i++) {
        const fw_rec_track *tr = &t->v[i];
        for (int a = 0, b; a < tr->n; a = b) {
            for (b = a + 1; b < tr->n && tr->p[b].t - tr->p[b - 1].t <= t->max_gap; b++)
                ;
            res->n_passes++;
            int r = match(nr, tr->p + a, b - a, def);
            if (r < 0)
                continue;
            if (*n_out == cap &&
                !fw_resize((void **)out, sizeof **out, (size_t)(cap = fw_grown_cap(cap, 16))))
                return fw_fail(err, FW_ERUN, "out of memory");
            double sog = median_speed(tr->p + a, b - a);
            (*out)[(*n_out)++] = (pass){r, vtype_of(nr, t->ships[i].kind, tr->info.length, sog),
                                        sog, t->ships[i].kind};
            res->n_matched++;
            res->passes[r]++;
        }
    }
    return FW_OK;
}

/* The streams of route r: one per vType its passes took (and the route's
 * own types for ships of unknown type), or its own at rate 0. */
static int write_route(FILE *f, const fw_net_routes *nr, int r, const pass *p, int n,
                       double hours)
{
    const fw_stream *s = &nr->demand.streams[r];
    int written = 0;
    fprintf(f, "  # route %s:", s->id);
    for (int k = 0; k < s->n_edges; k++)
        fprintf(f, " %s", s->edges[k]);
    int total = 0;
    for (int i = 0; i < n; i++)
        total += p[i].route == r;
    fprintf(f, ": %d passes, %.6g per hour\n", total, total / hours);
    for (int v = -1; v < nr->n_vtypes; v++) {
        int count = 0;
        double lo = INFINITY, hi = 0, sum = 0;
        for (int i = 0; i < n; i++)
            if (p[i].route == r && p[i].vtype == v) {
                count++;
                sum += p[i].sog;
                lo = fmin(lo, p[i].sog);
                hi = fmax(hi, p[i].sog);
            }
        if (count == 0 && !(v == -1 && total == 0))
            continue;
        const char *ty = v < 0 ? s->types : nr->vtypes[v].id;
        fprintf(f, "  - {id: %s%s%s, edges: [", s->id, v < 0 ? "" : "_", v < 0 ? "" : ty);
        for (int k = 0; k < s->n_edges; k++)
            fprintf(f, "%s%s", k ? ", " : "", s->edges[k]);
        fprintf(f, "], per_hour: %.6g, types: %s}", count / hours, ty);
        if (count)
            fprintf(f, "  # passes: %d, SOG %.1f kn mean, %.1f-%.1f", count,
                    fw_ms_to_kn(sum / count), fw_ms_to_kn(lo), fw_ms_to_kn(hi));
        fputc('\n', f);
        written++;
    }
    return written;
}

static fw_status write_file(FILE *f, const fw_ais_tracks *t, const fw_net_routes *nr,
                            const fw_ais_demand_def *def, const pass *p, int n,
                            fw_ais_demand_result *res, fw_error *err)
{
    char a[32], b[32];
    fw_ais_format_time(t->t0, a, sizeof a);
    fw_ais_format_time(t->t0 + t->t_end, b, sizeof b);
    fprintf(f, "# Demand of network %s from AIS: written by `fairway ais demand`.\n"
               "# Window %s to %s UTC (%.4g h); %d passes (reports up to %g s apart), %d "
               "matched to a route\n# within %.0f m on average, %d unmatched.  Ships per hour = "
               "passes / hours; each route's ships\n# split by AIS type, length and SOG onto "
               "the network's vTypes (src/ais/ais_demand.h).\n",
            nr->name, a, b, res->hours, res->n_passes, t->max_gap, res->n_matched,
            def->tolerance, res->n_passes - res->n_matched);
    if (nr->demand.lane_change_s > 0)
        fprintf(f, "lane_change_s: %g\n", nr->demand.lane_change_s);
    fprintf(f, "streams:\n");
    for (int r = 0; r < nr->demand.n; r++)
        res->n_streams += write_route(f, nr, r, p, n, res->hours);
    if (res->n_streams > FW_DEMAND_MAX_STREAMS)
        return fw_fail(err, FW_EINPUT, "%d streams (routes x ship types): a demand holds at most "
                                       "%d", res->n_streams, FW_DEMAND_MAX_STREAMS);
    return FW_OK;
}

/* The written file loads as a demand of the network. */
static fw_status check_written(const char *tmp, const char *network, fw_error *err)
{
    fw_demand *d = malloc(sizeof *d);
    fw_network_files *nf = malloc(sizeof *nf);
    fw_status st = d && nf ? FW_OK : fw_fail(err, FW_ERUN, "out of memory");
    if (!st && !(st = fw_demand_load(tmp, d, err)) && !(st = fw_network_find(network, nf, err)))
        st = fw_network_check_demand(nf, d, err);
    free(d);
    free(nf);
    return st;
}

fw_status fw_ais_demand_write(const fw_ais_tracks *t, const fw_ais_demand_def *def,
                              const char *path, fw_ais_demand_result *res, fw_error *err)
{
    memset(res, 0, sizeof *res);
    res->hours = t->t_end / 3600.0;
    if (!(res->hours > 0))
        return fw_fail(err, FW_EINPUT, "AIS demand: the window is empty (no time between the "
                                       "first and the last report)");
    fw_net_routes *nr = malloc(sizeof *nr);
    if (!nr)
        return fw_fail(err, FW_ERUN, "out of memory");
    pass *p = NULL;
    int n = 0;
    char tmp[1100];
    FILE *f = NULL;
    fw_status st;
    if ((st = fw_net_routes_load(def->network, nr, err)) ||
        (st = passes(t, nr, def, &p, &n, res, err)))
        goto out;
    res->n_routes = nr->demand.n;
    for (int r = 0; r < nr->demand.n; r++)
        snprintf(res->route[r], sizeof res->route[r], "%s", nr->demand.streams[r].id);
    if (!(f = fw_file_begin(path, tmp, sizeof tmp, err))) {
        st = err->status;
        goto out;
    }
    if ((st = write_file(f, t, nr, def, p, n, res, err)) || fflush(f) != 0 ||
        (st = check_written(tmp, def->network, err))) {
        st = st ? st : fw_fail(err, FW_ERUN, "%s: cannot write", path);
        fw_file_abort(f, tmp);
        goto out;
    }
    st = fw_file_commit(f, tmp, path, err);
out:
    free(p);
    free(nr);
    return st;
}
