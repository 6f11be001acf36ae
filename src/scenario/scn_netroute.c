/* scn_netroute.c - the own ship's route on a network (scn_netroute.h). */
#include "scenario/scn_netroute.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "scenario/scn_ais.h"
#include "scenario/scn_route.h"
#include "traffic/netshape.h"

#define P "own_ship.network_route"

typedef struct net_edges {
    int n;
    char id[FW_DEMAND_MAX_EDGES][64];
    int line[FW_DEMAND_MAX_EDGES];
    double speed[FW_DEMAND_MAX_EDGES]; /* m/s */
} net_edges;

/* The line of points a route is made from, each with the edge it lies on. */
typedef struct polyline {
    int n, cap;
    double *x, *y;
    int *edge;
} polyline;

/* traffic.network, found and built. */
static fw_status find_network(const yt_doc *doc, const yt_node *root, const yt_node *own,
                              fw_network_files *nf, fw_error *err)
{
    const yt_node *tr = yt_get(root, "traffic"), *net = tr ? yt_get(tr, "network") : NULL;
    char ref[1024];
    fw_error nerr = {0};
    if (!net || !net->str || !net->str[0])
        return yt_fail_key(doc, own, "own_ship", "network_route", err,
                           "the route is a network's edges: the scenario needs traffic.network");
    if (!fw_scn_network_ref(doc->file, net->str, ref, sizeof ref))
        return fw_fail_at(err, doc->file, net->line, "traffic.network", "path too long");
    if (fw_network_find(ref, nf, &nerr))
        return fw_fail_at(err, doc->file, net->line, "traffic.network", "%s", nerr.msg);
    return FW_OK;
}

/* The edges' ids and lines: edges: [...] or stream: NAME of demand.yaml. */
static fw_status edge_ids(const yt_doc *doc, const yt_node *nr, const fw_network_files *nf,
                          net_edges *ne, fw_error *err)
{
    const yt_node *seq = yt_get(nr, "edges"), *stream = yt_get(nr, "stream");
    if ((seq != NULL) == (stream != NULL))
        return fw_fail_at(err, doc->file, nr->line, P, "give exactly one of edges or stream");
    if (seq) {
        if (seq->kind != YT_SEQ || seq->n < 1 || seq->n > FW_DEMAND_MAX_EDGES)
            return yt_fail_key(doc, nr, P, "edges", err, "a list of 1..%d edge ids",
                               FW_DEMAND_MAX_EDGES);
        for (size_t i = 0; i < seq->n; i++) {
            const yt_node *it = seq->items[i];
            if (!it->str || !it->str[0] || strlen(it->str) >= sizeof ne->id[0])
                return fw_fail_at(err, doc->file, it->line, P ".edges", "item %zu: an edge id", i);
            snprintf(ne->id[i], sizeof ne->id[i], "%s", it->str);
            ne->line[i] = it->line;
        }
        ne->n = (int)seq->n;
        return FW_OK;
    }
    fw_demand *dm = malloc(sizeof *dm);
    fw_error derr = {0};
    fw_status st = !dm ? fw_fail(err, FW_ERUN, "out of memory") : FW_OK;
    if (!st && fw_demand_load(nf->demand, dm, &derr))
        st = fw_fail_at(err, doc->file, stream->line, P ".stream", "%s", derr.msg);
    int k = -1;
    for (int i = 0; !st && i < dm->n && k < 0; i++)
        if (stream->str && strcmp(dm->streams[i].id, stream->str) == 0)
            k = i;
    if (!st && k < 0)
        st = fw_fail_at(err, doc->file, stream->line, P ".stream",
                        "'%s' is not a stream of %s", stream->str ? stream->str : "", nf->demand);
    for (int i = 0; !st && i < dm->streams[k].n_edges; i++) {
        snprintf(ne->id[i], sizeof ne->id[i], "%s", dm->streams[k].edges[i]);
        ne->line[i] = stream->line;
    }
    if (!st)
        ne->n = dm->streams[k].n_edges;
    free(dm);
    return st;
}

/* speeds_kn: one number, or one per edge. */
static fw_status edge_speeds(const yt_doc *doc, const yt_node *nr, const fw_scenario *s,
                             net_edges *ne, fw_error *err)
{
    const yt_node *v = yt_get(nr, "speeds_kn");
    char path[96];
    if (!v)
        return fw_fail_at(err, doc->file, nr->line, P ".speeds_kn",
                          "missing: the speed on each edge (one number: all)");
    if (v->kind == YT_SEQ && v->n != (size_t)ne->n)
        return yt_fail_key(doc, nr, P, "speeds_kn", err, "%zu speeds for %d edges", v->n, ne->n);
    for (int i = 0; i < ne->n; i++) {
        const yt_node *it = v->kind == YT_SEQ ? v->items[i] : v;
        double kn;
        fw_status st;
        if (v->kind == YT_SEQ)
            snprintf(path, sizeof path, P ".speeds_kn[%d]", i);
        else
            snprintf(path, sizeof path, P ".speeds_kn");
        if ((st = yt_number(doc, it, path, &kn, err)))
            return st;
        if (!(kn >= 1.0 && kn <= 40.0))
            return fw_fail_at(err, doc->file, it->line, path, "%g kn: a speed is 1 to 40 kn", kn);
        if ((st = fw_scn_leg_speed(doc, it->line, path, "", kn, s, err)))
            return st;
        ne->speed[i] = fw_kn_to_ms(kn);
    }
    return FW_OK;
}

static int push(polyline *pl, double x, double y, int edge)
{
    if (pl->n == pl->cap) {
        int cap = pl->cap ? 2 * pl->cap : 64;
        double *nx = realloc(pl->x, sizeof(double) * (size_t)cap);
        if (nx)
            pl->x = nx;
        double *ny = nx ? realloc(pl->y, sizeof(double) * (size_t)cap) : NULL;
        if (ny)
            pl->y = ny;
        int *ne = ny ? realloc(pl->edge, sizeof(int) * (size_t)cap) : NULL;
        if (!ne)
            return -1;
        pl->edge = ne, pl->cap = cap;
    }
    pl->x[pl->n] = x, pl->y[pl->n] = y, pl->edge[pl->n] = edge;
    pl->n++;
    return 0;
}

/* Appends edge k's starboard lane's line (the route's, scn_netroute.h);
 * where it does not begin at the line's end, the end is moved to where the
 * two segments' lines cross when that lies within 1 km of both (else the gap
 * is a leg of its own). */
static int append_edge(polyline *pl, const fw_net_edge *e, int k)
{
    const double *x = e->sx, *y = e->sy;
    int from = 0;
    if (pl->n >= 2) {
        double px = pl->x[pl->n - 1], py = pl->y[pl->n - 1];
        double ax = px - pl->x[pl->n - 2], ay = py - pl->y[pl->n - 2];
        double bx = x[1] - x[0], by = y[1] - y[0];
        double gx = x[0] - px, gy = y[0] - py, cr = ax * by - ay * bx;
        if (hypot(gx, gy) < 1.0) {
            from = 1; /* the same point */
        } else if (fabs(cr) > 1e-9 * hypot(ax, ay) * hypot(bx, by)) {
            double t = (gx * by - gy * bx) / cr, u = (gx * ay - gy * ax) / cr;
            double xx = px + t * ax, xy = py + t * ay;
            if (hypot(xx - px, xy - py) < 1000.0 && hypot(xx - x[0], xy - y[0]) < 1000.0 &&
                t > -1.0 && u < 1.0) {
                pl->x[pl->n - 1] = xx, pl->y[pl->n - 1] = xy, pl->edge[pl->n - 1] = k;
                from = 1;
            }
        }
    }
    for (int i = from; i < e->sn; i++)
        if (push(pl, x[i], y[i], k))
            return -1;
    return 0;
}

/* Are the points of pl between a and b within tol of the segment a-b? */
static bool within(const polyline *pl, int a, int b, double tol)
{
    double dx = pl->x[b] - pl->x[a], dy = pl->y[b] - pl->y[a], len2 = dx * dx + dy * dy;
    for (int i = a + 1; i < b; i++) {
        double ex = pl->x[i] - pl->x[a], ey = pl->y[i] - pl->y[a];
        double t = len2 > 0.0 ? fmax(0.0, fmin(1.0, (ex * dx + ey * dy) / len2)) : 0.0;
        if (hypot(ex - t * dx, ey - t * dy) > tol)
            return false;
    }
    return true;
}

/* keep[] marks the points of pl a line within tol of it goes through: from
 * each kept point the farthest on whose chord every point between lies
 * within tol (on a curve, the fewest points: Douglas-Peucker halves arcs). */
static void simplify(const polyline *pl, double tol, char *keep)
{
    for (int a = 0; a + 1 < pl->n;) {
        int b = a + 1;
        while (b + 1 < pl->n && within(pl, a, b + 1, tol))
            b++;
        keep[b] = 1;
        a = b;
    }
}

/* The kept points, without interior ones that leave a leg under 0.1 nm. */
static int reduce(polyline *pl, double tol, fw_error *err)
{
    if (pl->n < 2)
        return FW_OK;
    char *keep = calloc((size_t)pl->n, 1);
    if (!keep)
        return fw_fail(err, FW_ERUN, "out of memory");
    keep[0] = keep[pl->n - 1] = 1;
    simplify(pl, tol, keep);
    int m = 0;
    for (int i = 0; i < pl->n; i++)
        if (keep[i])
            pl->x[m] = pl->x[i], pl->y[m] = pl->y[i], pl->edge[m] = pl->edge[i], m++;
    free(keep);
    pl->n = m;
    for (int i = 1; i < pl->n && pl->n > 2;) {
        if (hypot(pl->x[i] - pl->x[i - 1], pl->y[i] - pl->y[i - 1]) >= 0.1 * FW_NMILE) {
            i++;
            continue;
        }
        int drop = i == pl->n - 1 ? i - 1 : i; /* never the end points */
        if (drop == 0)
            drop = 1;
        memmove(pl->x + drop, pl->x + drop + 1, sizeof(double) * (size_t)(pl->n - drop - 1));
        memmove(pl->y + drop, pl->y + drop + 1, sizeof(double) * (size_t)(pl->n - drop - 1));
        memmove(pl->edge + drop, pl->edge + drop + 1, sizeof(int) * (size_t)(pl->n - drop - 1));
        pl->n--;
        i = 1;
    }
    return FW_OK;
}

/* The edges, each in the net and beginning where the one before ends, into
 * the line pl. */
static fw_status edges_line(const yt_doc *doc, const fw_net_shape *ns, const fw_network_files *nf,
                            const net_edges *ne, polyline *pl, fw_error *err)
{
    const fw_net_edge *prev = NULL;
    for (int i = 0; i < ne->n; i++) {
        const fw_net_edge *e = fw_net_shape_edge(ns, ne->id[i]);
        if (!e)
            return fw_fail_at(err, doc->file, ne->line[i], P ".edges",
                              "no edge '%s' in network '%s'", ne->id[i], nf->name);
        if (prev && strcmp(prev->to, e->from) != 0)
            return fw_fail_at(err, doc->file, ne->line[i], P ".edges",
                              "edge '%s' begins at junction '%s', not where '%s' ends ('%s')",
                              e->id, e->from, prev->id, prev->to);
        if (append_edge(pl, e, i))
            return fw_fail(err, FW_ERUN, "out of memory");
        prev = e;
    }
    return FW_OK;
}

/* m: the narrowest width of the edges' starboard lanes. */
static double narrowest(const fw_net_shape *ns, const net_edges *ne)
{
    double w = INFINITY;
    for (int i = 0; i < ne->n; i++)
        w = fmin(w, fw_net_shape_edge(ns, ne->id[i])->s_width);
    return w;
}

/* pl reduced into r within *tol of it, the tolerance doubled from
 * FW_NETROUTE_TOL_M up to max_tol while the route would need more waypoints
 * than a route has. */
static fw_status fit_line(const polyline *pl, polyline *r, double *tol, double max_tol,
                          fw_error *err)
{
    for (;;) {
        r->n = 0;
        for (int i = 0; i < pl->n; i++)
            if (push(r, pl->x[i], pl->y[i], pl->edge[i]))
                return fw_fail(err, FW_ERUN, "out of memory");
        fw_status st = reduce(r, *tol, err);
        if (st || r->n <= FW_ROUTE_MAX_LEGS + 1 || 2.0 * *tol > max_tol)
            return st;
        *tol *= 2.0;
    }
}

/* The water either side of edge e's starboard lane's line (route.h
 * room_starboard, room_port): half that lane's width to starboard, the rest
 * of the edge to port.  An edge is one direction's lanes: in a narrow
 * channel a ship keeps to its starboard side (rule 9(a)), in a separation
 * scheme to its traffic lane (rule 10(b)), so the other direction's lanes
 * are not its room; its own direction's other lanes are, to overtake or to
 * give way in. */
static void edge_room(const fw_net_edge *e, fw_route_leg *l)
{
    l->room_starboard = 0.5 * e->s_width;
    l->room_port = e->width - 0.5 * e->s_width;
}

/* The route from the reduced line pl, into s. */
static fw_status make_route(const yt_doc *doc, const yt_node *own, const polyline *pl,
                            double tol, const fw_net_shape *ns, const net_edges *ne,
                            fw_scenario *s, fw_error *err)
{
    if (pl->n > FW_ROUTE_MAX_LEGS + 1)
        return yt_fail_key(doc, own, "own_ship", "network_route", err,
                           "its starboard lanes' line needs %d waypoints to stay within %.0f m of "
                           "it (a quarter of the narrowest one's width), a route has at most %d",
                           pl->n, tol, FW_ROUTE_MAX_LEGS + 1);
    if (pl->n < 2 || hypot(pl->x[1] - pl->x[0], pl->y[1] - pl->y[0]) < 0.1 * FW_NMILE)
        return yt_fail_key(doc, own, "own_ship", "network_route", err,
                           "the edges are shorter than 0.1 nm");
    double v[FW_ROUTE_MAX_LEGS + 1];
    for (int i = 0; i < pl->n; i++)
        v[i] = ne->speed[pl->edge[i]];
    fw_error rerr = {0};
    if (fw_route_from_waypoints(pl->x, pl->y, v, pl->n, &s->route, &rerr))
        return yt_fail_key(doc, own, "own_ship", "network_route", err, "%s", rerr.msg);
    for (int k = 0; k < s->route.n; k++)
        edge_room(fw_net_shape_edge(ns, ne->id[pl->edge[k]]), &s->route.leg[k]);
    fw_scn_route_start(s);
    return FW_OK;
}

fw_status fw_scn_load_net_route(const yt_doc *doc, const yt_node *root, const yt_node *own,
                                fw_scenario *s, fw_error *err)
{
    static const char *const keys[] = {"edges", "stream", "speeds_kn", NULL};
    const yt_node *nr;
    fw_network_files nf;
    net_edges ne = {0};
    fw_status st;
    if ((st = fw_scn_route_no_line_keys(doc, own, err)) ||
        (st = yt_req_map(doc, own, "own_ship", "network_route", &nr, err)) ||
        (st = yt_check_keys(doc, nr, P, keys, err)))
        return st;
    if (yt_get(own, "route"))
        return yt_fail_key(doc, own, "own_ship", "route", err,
                           "not with network_route: give the route one way");
    if ((st = find_network(doc, root, own, &nf, err)) || (st = edge_ids(doc, nr, &nf, &ne, err)) ||
        (st = edge_speeds(doc, nr, s, &ne, err)))
        return st;
    fw_net_shape ns;
    fw_error nerr = {0};
    if (fw_net_shape_load(nf.net, &ns, &nerr))
        return fw_fail_at(err, doc->file, yt_key_line(own, "network_route"), P, "%s", nerr.msg);
    polyline pl = {0}, r = {0};
    double tol = FW_NETROUTE_TOL_M;
    if (!(st = edges_line(doc, &ns, &nf, &ne, &pl, err)) &&
        !(st = fit_line(&pl, &r, &tol, narrowest(&ns, &ne) / 4.0, err)))
        st = make_route(doc, own, &r, tol, &ns, &ne, s, err);
    free(pl.x), free(pl.y), free(pl.edge);
    free(r.x), free(r.y), free(r.edge);
    fw_net_shape_free(&ns);
    return st;
}

fw_status fw_scn_route_on_network(const yt_doc *doc, const yt_node *root, const fw_scenario *s,
                                  const fw_network_files *nf, fw_error *err)
{
    const yt_node *own = yt_get(root, "own_ship"), *seq = own ? yt_get(own, "route") : NULL;
    if (!seq || seq->kind != YT_SEQ || !s->route.steered || (int)seq->n != s->route.n + 1)
        return FW_OK;
    fw_net_shape ns;
    fw_error nerr = {0};
    if (fw_net_shape_load(nf->net, &ns, &nerr))
        return fw_fail_at(err, doc->file, yt_key_line(yt_get(root, "traffic"), "network"),
                          "traffic.network", "%s", nerr.msg);
    fw_status st = FW_OK;
    char path[48];
    for (int i = 0; i <= s->route.n && !st; i++) {
        const fw_route_leg *l = &s->route.leg[i < s->route.n ? i : i - 1];
        double x = i < s->route.n ? l->east : l->east + l->length * sin(l->course);
        double y = i < s->route.n ? l->north : l->north + l->length * cos(l->course);
        double off = fw_net_shape_outside(&ns, x, y);
        snprintf(path, sizeof path, "own_ship.route[%d]", i);
        if (off > FW_ROUTE_OFF_NETWORK_M)
            st = fw_fail_at(err, doc->file, seq->items[i]->line, path,
                            "waypoint %d (%.0f, %.0f m) is %.0f m outside network '%s' (its "
                            "lanes span east %.0f to %.0f m, north %.0f to %.0f m): more than "
                            "%.0f m (1 nm) off it", i, x, y, off, nf->name, ns.box[0], ns.box[2],
                            ns.box[1], ns.box[3], FW_ROUTE_OFF_NETWORK_M);
    }
    fw_net_shape_free(&ns);
    return st;
}
