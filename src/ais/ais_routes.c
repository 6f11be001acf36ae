/* ais_routes.c - a network's routes as lines and its ship types (ais_routes.h). */
#include "ais/ais_routes.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"

/* The value of attribute name in the tag [tag, end) into out; false if the
 * tag has none. */
static bool attr(const char *tag, const char *end, const char *name, char *out, size_t n)
{
    char key[64];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *a = strstr(tag, key);
    if (!a || a > end)
        return false;
    a += strlen(key);
    const char *q = strchr(a, '"');
    if (!q || q > end || (size_t)(q - a) >= n)
        return false;
    memcpy(out, a, (size_t)(q - a));
    out[q - a] = '\0';
    return true;
}

/* The element <tag ... id="id" ...> of xml: its start and end (NULL if none). */
static const char *element(const char *xml, const char *tag, const char *id, const char **end)
{
    char open[32], v[128];
    snprintf(open, sizeof open, "<%s ", tag);
    for (const char *p = strstr(xml, open); p; p = strstr(p + 1, open)) {
        const char *e = strchr(p, '>');
        if (!e)
            return NULL;
        if (attr(p, e, "id", v, sizeof v) && strcmp(v, id) == 0) {
            *end = e;
            return p;
        }
    }
    return NULL;
}

static bool add_point(fw_route_line *r, double x, double y)
{
    if (r->n > 0 && r->x[r->n - 1] == x && r->y[r->n - 1] == y)
        return true; /* the next edge starts where the last ended */
    if (r->n == FW_ROUTE_MAX_POINTS)
        return false;
    r->x[r->n] = x;
    r->y[r->n++] = y;
    return true;
}

static bool node_xy(const char *nodes, const char *id, double *x, double *y)
{
    const char *end, *n = element(nodes, "node", id, &end);
    char vx[64], vy[64];
    return n && attr(n, end, "x", vx, sizeof vx) && attr(n, end, "y", vy, sizeof vy) &&
           sscanf(vx, "%lf", x) == 1 && sscanf(vy, "%lf", y) == 1;
}

/* One edge's geometry onto r: its shape, else from-node to to-node. */
static fw_status edge_line(const char *nodes, const char *edges, const char *id,
                           const char *what, fw_route_line *r, fw_error *err)
{
    const char *end, *e = element(edges, "edge", id, &end);
    char from[128], to[128], shape[4096];
    if (!e || !attr(e, end, "from", from, sizeof from) || !attr(e, end, "to", to, sizeof to))
        return fw_fail(err, FW_EINPUT, "%s: edge '%s' with from and to not found", what, id);
    if (attr(e, end, "shape", shape, sizeof shape)) {
        double x, y;
        int k;
        for (const char *p = shape; sscanf(p, "%lf,%lf%n", &x, &y, &k) == 2; p += k)
            if (!add_point(r, x, y))
                return fw_fail(err, FW_EINPUT, "%s: route longer than %d points", what,
                               FW_ROUTE_MAX_POINTS);
        return FW_OK;
    }
    double x0, y0, x1, y1;
    if (!node_xy(nodes, from, &x0, &y0) || !node_xy(nodes, to, &x1, &y1))
        return fw_fail(err, FW_EINPUT, "%s: edge '%s': node '%s' or '%s' without x and y", what,
                       id, from, to);
    if (!add_point(r, x0, y0) || !add_point(r, x1, y1))
        return fw_fail(err, FW_EINPUT, "%s: route longer than %d points", what,
                       FW_ROUTE_MAX_POINTS);
    return FW_OK;
}

/* The fastest lane speed of the network's types (SUMO's speed limit). */
static double lane_speed(const char *typ)
{
    double best = 0.0;
    char v[64];
    for (const char *p = strstr(typ, "<type "); p; p = strstr(p + 1, "<type ")) {
        const char *e = strchr(p, '>');
        double s;
        if (e && attr(p, e, "speed", v, sizeof v) && sscanf(v, "%lf", &s) == 1 && s > best)
            best = s;
    }
    return best;
}

static void load_vtypes(const char *xml, double lane, fw_net_routes *out)
{
    char v[256];
    for (const char *p = strstr(xml, "<vType "); p && out->n_vtypes < FW_MAX_VTYPES;
         p = strstr(p + 1, "<vType ")) {
        const char *e = strchr(p, '>');
        fw_vtype_info *t = &out->vtypes[out->n_vtypes];
        double f = 1.0;
        if (!e || !attr(p, e, "id", t->id, sizeof t->id) || !attr(p, e, "length", v, sizeof v) ||
            sscanf(v, "%lf", &t->length) != 1)
            continue;
        if (attr(p, e, "speedFactor", v, sizeof v) && sscanf(v, "normc(%lf", &f) != 1 &&
            sscanf(v, "%lf", &f) != 1)
            f = 1.0;
        t->speed = f * lane;
        out->n_vtypes++;
    }
}

double fw_route_distance(const fw_route_line *r, double x, double y, double *along)
{
    double best = INFINITY, s0 = 0.0;
    *along = 0.0;
    for (int i = 0; i + 1 < r->n; i++) {
        double dx = r->x[i + 1] - r->x[i], dy = r->y[i + 1] - r->y[i];
        double len2 = dx * dx + dy * dy, len = sqrt(len2);
        double u = len2 > 0 ? ((x - r->x[i]) * dx + (y - r->y[i]) * dy) / len2 : 0.0;
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        double d = hypot(x - (r->x[i] + u * dx), y - (r->y[i] + u * dy));
        if (d < best) {
            best = d;
            *along = s0 + u * len;
        }
        s0 += len;
    }
    return best;
}

/* The network's plain XML (its types "" when it has none). */
static fw_status read_sources(const fw_network_files *nf, char **nodes, char **edges, char **typ,
                              fw_error *err)
{
    fw_status st;
    if ((st = fw_read_text(nf->nodes, nodes, NULL, err)) ||
        (st = fw_read_text(nf->edges, edges, NULL, err)))
        return st;
    if (!nf->typ[0])
        return (*typ = calloc(1, 1)) ? FW_OK : fw_fail(err, FW_ERUN, "out of memory");
    return fw_read_text(nf->typ, typ, NULL, err);
}

fw_status fw_net_routes_load(const char *name, fw_net_routes *out, fw_error *err)
{
    memset(out, 0, sizeof *out);
    snprintf(out->name, sizeof out->name, "%s", name);
    fw_network_files nf;
    char *nodes = NULL, *edges = NULL, *typ = NULL, *types = NULL;
    fw_status st;
    if ((st = fw_network_find(name, &nf, err)) || (st = fw_demand_load(nf.demand, &out->demand, err)) ||
        (st = read_sources(&nf, &nodes, &edges, &typ, err)) ||
        (st = fw_read_text(nf.types, &types, NULL, err)))
        goto out;
    for (int i = 0; !st && i < out->demand.n; i++) {
        const fw_stream *s = &out->demand.streams[i];
        fw_route_line *r = &out->line[i];
        for (int k = 0; !st && k < s->n_edges; k++)
            st = edge_line(nodes, edges, s->edges[k], nf.demand, r, err);
        for (int k = 0; k + 1 < r->n; k++)
            r->length += hypot(r->x[k + 1] - r->x[k], r->y[k + 1] - r->y[k]);
    }
    load_vtypes(types, lane_speed(typ), out);
out:
    free(nodes);
    free(edges);
    free(typ);
    free(types);
    return st;
}
