#include "core/files.h"
#include "core/rng.h"
#include "traffic/demand.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "yaml/yaml_tree.h"

fw_demand_def fw_default_demand_def(void)
{
    fw_demand_def d = {.density = 1.0, .begin = 0.0, .end = 86400.0, .fill = 0, .seed = 1};
    return d;
}

/* Ids land in XML attributes: keep them to characters that need no escaping. */
static bool plain_id(const char *s)
{
    if (!s[0])
        return false;
    for (; *s; s++)
        if (!isalnum((unsigned char)*s) && *s != '_' && *s != '-' && *s != '.')
            return false;
    return true;
}

static fw_status load_stream(const yt_doc *doc, const yt_node *m, const char *path,
                             fw_stream *s, fw_error *err)
{
    static const char *const keys[] = {"id", "edges", "per_hour", "types", NULL};
    const yt_node *edges;
    fw_status st;
    if ((st = yt_check_keys(doc, m, path, keys, err)) ||
        (st = yt_req_string(doc, m, path, "id", s->id, sizeof s->id, err)) ||
        (st = yt_req_string(doc, m, path, "types", s->types, sizeof s->types, err)) ||
        (st = yt_req_number(doc, m, path, "per_hour", 0.0, 1000.0, &s->per_hour, err)) ||
        (st = yt_req_seq(doc, m, path, "edges", &edges, err)))
        return st;
    if (!plain_id(s->id))
        return yt_fail_key(doc, m, path, "id", err, "'%s' must be letters, digits, '_', '-' or '.'",
                           s->id);
    if (!plain_id(s->types))
        return yt_fail_key(doc, m, path, "types", err,
                           "'%s' must be letters, digits, '_', '-' or '.'", s->types);
    char field[128];
    yt_path(field, sizeof field, path, "edges");
    if (edges->n < 1 || edges->n > FW_DEMAND_MAX_EDGES)
        return fw_fail_at(err, doc->file, edges->line, field, "needs 1 to %d edges",
                          FW_DEMAND_MAX_EDGES);
    s->n_edges = (int)edges->n;
    for (size_t i = 0; i < edges->n; i++) {
        const yt_node *e = edges->items[i];
        if (e->kind != YT_SCALAR || !plain_id(e->str) || strlen(e->str) >= 64)
            return fw_fail_at(err, doc->file, e->line, field, "edge %zu is not an edge id", i + 1);
        snprintf(s->edges[i], sizeof s->edges[i], "%s", e->str);
        s->edge_line[i] = e->line;
    }
    return FW_OK;
}

fw_status fw_demand_load(const char *path, fw_demand *out, fw_error *err)
{
    memset(out, 0, sizeof *out);
    fw_status st = fw_path(out->file, sizeof out->file, err, "%s", path);
    if (st)
        return st;
    yt_doc *doc = NULL;
    st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    static const char *const keys[] = {"streams", "lane_change_s", NULL};
    const yt_node *seq = NULL;
    if (doc->root->kind != YT_MAP)
        st = fw_fail_at(err, doc->file, doc->root->line, "", "expected a map with 'streams'");
    if (!st)
        st = yt_check_keys(doc, doc->root, "", keys, err);
    if (!st)
        st = yt_opt_number(doc, doc->root, "", "lane_change_s", 0.0, 7200.0,
                           &out->lane_change_s, err);
    if (!st)
        st = yt_req_seq(doc, doc->root, "", "streams", &seq, err);
    if (!st && (seq->n < 1 || seq->n > FW_DEMAND_MAX_STREAMS))
        st = fw_fail_at(err, doc->file, seq->line, "streams", "needs 1 to %d streams",
                        FW_DEMAND_MAX_STREAMS);
    for (size_t i = 0; !st && i < seq->n; i++) {
        char path_i[32];
        snprintf(path_i, sizeof path_i, "streams[%zu]", i);
        if (seq->items[i]->kind != YT_MAP) {
            st = fw_fail_at(err, doc->file, seq->items[i]->line, path_i, "expected a map");
            break;
        }
        st = load_stream(doc, seq->items[i], path_i, &out->streams[i], err);
        for (size_t j = 0; !st && j < i; j++)
            if (strcmp(out->streams[j].id, out->streams[i].id) == 0)
                st = fw_fail_at(err, doc->file, seq->items[i]->line, path_i,
                                "stream id '%s' used twice", out->streams[i].id);
        out->n = (int)i + 1;
    }
    yt_free(doc);
    return st;
}

double fw_demand_rate(const fw_demand *d)
{
    double r = 0.0;
    for (int i = 0; i < d->n; i++)
        r += d->streams[i].per_hour;
    return r;
}

static void route(FILE *f, const fw_stream *s, int from)
{
    fprintf(f, "    <route id=\"r_%s_%d\" edges=\"", s->id, from);
    for (int k = from; k < s->n_edges; k++)
        fprintf(f, "%s%s", k > from ? " " : "", s->edges[k]);
    fprintf(f, "\"/>\n");
}

fw_status fw_demand_write(const fw_demand *d, const fw_demand_def *def, const char *path,
                          fw_error *err)
{
    if (!(def->density >= 0.0 && isfinite(def->density)))
        return fw_fail(err, FW_EINPUT, "traffic density %g: must be 0 or more", def->density);
    if (!(def->end > def->begin && def->begin >= 0.0))
        return fw_fail(err, FW_EINPUT, "traffic period %g..%g s is empty", def->begin, def->end);
    if (def->fill < 0 || def->fill > 100000)
        return fw_fail(err, FW_EINPUT, "%d initial ships: must be 0..100000", def->fill);
    double total = fw_demand_rate(d);
    if (def->fill > 0 && total <= 0.0)
        return fw_fail(err, FW_EINPUT, "%s: no stream with ships to fill", d->file);
    char tmp[PATH_MAX + 32];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<!-- written by fairway from %s: density %g, %d initial ships, seed %lu -->\n"
               "<routes>\n",
            d->file, def->density, def->fill, def->seed);
    for (int i = 0; i < d->n; i++)
        for (int k = 0; k < d->streams[i].n_edges; k++)
            route(f, &d->streams[i], k);
    /* Fill ships: each stream gets its share of `fill` by rate (largest
     * remainder, so the total is exact), each ship a random edge of its
     * stream and a random free place on it. */
    int count[FW_DEMAND_MAX_STREAMS] = {0}, given = 0;
    double rem[FW_DEMAND_MAX_STREAMS] = {0};
    for (int i = 0; i < d->n && def->fill > 0; i++) {
        double share = def->fill * d->streams[i].per_hour / total;
        count[i] = (int)floor(share);
        rem[i] = share - count[i];
        given += count[i];
    }
    while (given < def->fill) {
        int best = 0;
        for (int i = 1; i < d->n; i++)
            if (rem[i] > rem[best])
                best = i;
        count[best]++;
        rem[best] = -1.0;
        given++;
    }
    uint64_t rng = def->seed;
    for (int i = 0; i < d->n; i++)
        for (int j = 0; j < count[i]; j++) {
            const fw_stream *s = &d->streams[i];
            int k = (int)(fw_splitmix64(&rng) % (uint64_t)s->n_edges);
            fprintf(f,
                    "    <vehicle id=\"%s_fill%d\" type=\"%s\" route=\"r_%s_%d\" depart=\"0\""
                    " departPos=\"random_free\" departLane=\"random\" departSpeed=\"desired\"/>\n",
                    s->id, j, s->types, s->id, k);
        }
    for (int i = 0; i < d->n && def->density > 0.0; i++) {
        const fw_stream *s = &d->streams[i];
        double rate = s->per_hour * def->density / 3600.0; /* ships per second */
        if (rate <= 0.0)
            continue;
        /* SUMO (to 1.19 at least, eclipse-sumo/sumo#14664) loads a flood of
         * ships for exp(X) with X below 1e-3 per second and runs out of
         * memory; below that a per-second insertion probability of the same
         * rate is the same arrival process to within rate^2 */
        fprintf(f,
                "    <flow id=\"%s\" type=\"%s\" route=\"r_%s_0\" begin=\"%.17g\" end=\"%.17g\""
                " %s=\"%s%.9g%s\" departLane=\"random\" departSpeed=\"desired\"/>\n",
                s->id, s->types, s->id, def->begin, def->end,
                rate < FW_SUMO_EXP_RATE_MIN ? "probability" : "period",
                rate < FW_SUMO_EXP_RATE_MIN ? "" : "exp(", rate,
                rate < FW_SUMO_EXP_RATE_MIN ? "" : ")");
    }
    fprintf(f, "</routes>\n");
    return fw_file_commit(f, tmp, path, err);
}
