/* netshape.c - a built network's edges as lines (netshape.h). */
#include "traffic/netshape.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"

enum { MAX_LANES = 16 };

/* Attribute name="..." of the element from p to end, copied to the heap
 * (free it); NULL when absent. */
static char *attr_dup(const char *p, const char *end, const char *name)
{
    size_t k = strlen(name);
    for (const char *a = p; (a = strstr(a, name)) && a < end; a += k) {
        if ((a[-1] != ' ' && a[-1] != '\t' && a[-1] != '\n' && a[-1] != '\r') || a[k] != '=' ||
            a[k + 1] != '"')
            continue;
        const char *v = a + k + 2, *q = strchr(v, '"');
        char *out = q && q < end ? malloc((size_t)(q - v) + 1) : NULL;
        if (out) {
            memcpy(out, v, (size_t)(q - v));
            out[q - v] = '\0';
        }
        return out;
    }
    return NULL;
}

/* The same into out (n bytes); false when absent or too long. */
static bool attr(const char *p, const char *end, const char *name, char *out, size_t n)
{
    char *v = attr_dup(p, end, name);
    bool ok = v && strlen(v) < n;
    if (ok)
        memcpy(out, v, strlen(v) + 1);
    free(v);
    return ok;
}

/* The box grown by (x, y) with a half width h. */
static void grow(double box[4], double x, double y, double h)
{
    box[0] = fmin(box[0], x - h), box[2] = fmax(box[2], x + h);
    box[1] = fmin(box[1], y - h), box[3] = fmax(box[3], y + h);
}

/* The points of a shape "x,y x,y ..." (heap arrays); 0 when unreadable. */
static int parse_shape(const char *s, double **x, double **y)
{
    int cap = 16, n = 0;
    *x = malloc(sizeof(double) * (size_t)cap), *y = malloc(sizeof(double) * (size_t)cap);
    const char *p = s;
    while (*x && *y && *p) {
        char *e1, *e2;
        double a = strtod(p, &e1);
        if (e1 == p || *e1 != ',')
            break;
        double b = strtod(e1 + 1, &e2);
        if (e2 == e1 + 1 || !isfinite(a) || !isfinite(b))
            break;
        if (n == cap) {
            cap *= 2;
            double *nx = realloc(*x, sizeof(double) * (size_t)cap);
            if (nx)
                *x = nx;
            double *ny = nx ? realloc(*y, sizeof(double) * (size_t)cap) : NULL;
            if (!ny)
                break;
            *y = ny;
        }
        (*x)[n] = a, (*y)[n] = b, n++;
        p = e2 + strspn(e2, " \t\r\n");
        if (!*p)
            return n >= 2 ? n : 0;
    }
    return 0;
}

typedef struct lane_pts {
    int n;
    double *x, *y, w;
} lane_pts;

/* The lanes between p and the edge's end into the box and lanes[]. */
static int read_lanes(fw_net_shape *ns, const char *p, const char *stop, lane_pts *lanes)
{
    int m = 0;
    for (const char *l = strstr(p, "<lane "); l && l < stop; l = strstr(l + 6, "<lane ")) {
        const char *end = strchr(l, '>');
        char w[32], *shape = end ? attr_dup(l, end, "shape") : NULL;
        lane_pts lp = {.w = end && attr(l, end, "width", w, sizeof w) ? atof(w) : 0.0};
        lp.n = shape ? parse_shape(shape, &lp.x, &lp.y) : 0;
        free(shape);
        if (!lp.n) {
            free(lp.x), free(lp.y);
            for (int i = 0; i < m; i++)
                free(lanes[i].x), free(lanes[i].y);
            return -1;
        }
        for (int k = 0; k < lp.n; k++)
            grow(ns->box, lp.x[k], lp.y[k], lp.w / 2);
        if (m < MAX_LANES)
            lanes[m++] = lp;
        else
            free(lp.x), free(lp.y);
    }
    return m;
}

/* The centre line from the lanes (taken over or freed), and a copy of the
 * first lane's (index 0: SUMO writes an edge's lanes in index order, the
 * rightmost first); -1 out of memory (all freed). */
static int centre_line(fw_net_edge *e, lane_pts *lanes, int m)
{
    e->sn = lanes[0].n, e->s_width = lanes[0].w;
    e->sx = malloc(sizeof(double) * (size_t)e->sn), e->sy = malloc(sizeof(double) * (size_t)e->sn);
    if (!e->sx || !e->sy) {
        for (int i = 0; i < m; i++)
            free(lanes[i].x), free(lanes[i].y);
        return -1;
    }
    memcpy(e->sx, lanes[0].x, sizeof(double) * (size_t)e->sn);
    memcpy(e->sy, lanes[0].y, sizeof(double) * (size_t)e->sn);
    bool same = true;
    for (int i = 1; i < m; i++)
        same = same && lanes[i].n == lanes[0].n;
    int mid = m / 2;
    e->n_lanes = m, e->width = 0.0;
    for (int i = 0; i < m; i++)
        e->width += lanes[i].w;
    if (same && m > 1)
        for (int k = 0; k < lanes[0].n; k++) {
            double sx = 0.0, sy = 0.0;
            for (int i = 0; i < m; i++)
                sx += lanes[i].x[k], sy += lanes[i].y[k];
            lanes[mid].x[k] = sx / m, lanes[mid].y[k] = sy / m;
        }
    e->n = lanes[mid].n, e->x = lanes[mid].x, e->y = lanes[mid].y;
    for (int i = 0; i < m; i++)
        if (i != mid)
            free(lanes[i].x), free(lanes[i].y);
    return 0;
}

static fw_status parse(const char *path, const char *xml, fw_net_shape *ns, fw_error *err)
{
    int cap = 0;
    ns->box[0] = ns->box[1] = INFINITY, ns->box[2] = ns->box[3] = -INFINITY;
    for (const char *p = strstr(xml, "<edge "); p; p = strstr(p + 6, "<edge ")) {
        const char *end = strchr(p, '>'), *stop = strstr(p, "</edge>");
        char fn[32], id[64], from[64], to[64];
        if (!end || !stop)
            break;
        bool normal = !attr(p, end, "function", fn, sizeof fn) || strcmp(fn, "normal") == 0;
        lane_pts lanes[MAX_LANES];
        int m = read_lanes(ns, end, stop, lanes);
        if (m < 0)
            return fw_fail(err, FW_EINPUT, "%s: a lane of edge near byte %ld has no shape", path,
                           (long)(p - xml));
        if (!normal || m == 0 || !attr(p, end, "id", id, sizeof id) ||
            !attr(p, end, "from", from, sizeof from) || !attr(p, end, "to", to, sizeof to)) {
            for (int i = 0; i < m; i++)
                free(lanes[i].x), free(lanes[i].y);
            continue;
        }
        if (ns->n == cap) {
            fw_net_edge *ne = realloc(ns->edges, sizeof *ne * (size_t)(cap = cap ? 2 * cap : 16));
            if (!ne) {
                for (int i = 0; i < m; i++)
                    free(lanes[i].x), free(lanes[i].y);
                return fw_fail(err, FW_ERUN, "out of memory reading %s", path);
            }
            ns->edges = ne;
        }
        fw_net_edge *e = &ns->edges[ns->n++];
        memset(e, 0, sizeof *e);
        snprintf(e->id, sizeof e->id, "%s", id);
        snprintf(e->from, sizeof e->from, "%s", from);
        snprintf(e->to, sizeof e->to, "%s", to);
        if (centre_line(e, lanes, m))
            return fw_fail(err, FW_ERUN, "out of memory reading %s", path);
    }
    return ns->n ? FW_OK : fw_fail(err, FW_EINPUT, "%s: no edge with lanes", path);
}

fw_status fw_net_shape_load(const char *path, fw_net_shape *out, fw_error *err)
{
    memset(out, 0, sizeof *out);
    char *xml = NULL;
    fw_status st = fw_read_text(path, &xml, NULL, err);
    if (!st)
        st = parse(path, xml, out, err);
    free(xml);
    if (st)
        fw_net_shape_free(out);
    return st;
}

void fw_net_shape_free(fw_net_shape *ns)
{
    for (int i = 0; i < ns->n; i++)
        free(ns->edges[i].x), free(ns->edges[i].y), free(ns->edges[i].sx), free(ns->edges[i].sy);
    free(ns->edges);
    memset(ns, 0, sizeof *ns);
}

const fw_net_edge *fw_net_shape_edge(const fw_net_shape *ns, const char *id)
{
    for (int i = 0; i < ns->n; i++)
        if (strcmp(ns->edges[i].id, id) == 0)
            return &ns->edges[i];
    return NULL;
}

double fw_net_shape_outside(const fw_net_shape *ns, double x, double y)
{
    double dx = fmax(0.0, fmax(ns->box[0] - x, x - ns->box[2]));
    double dy = fmax(0.0, fmax(ns->box[1] - y, y - ns->box[3]));
    return hypot(dx, dy);
}
