/* hull_track.c - a SUMO ship's hull from its bow's track (hull_track.h). */
#include "traffic/hull_track.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"

/* m: the bow's points are kept this far apart at least.  A 300 m hull's
 * chord is then placed to a few centimetres on a 30 deg bend's arc. */
static const double kMinStep = 2.0;

static bool room(fw_hull_track *tr, int n)
{
    if (n <= tr->cap)
        return true;
    int cap = tr->cap ? 2 * tr->cap : 16;
    while (cap < n)
        cap *= 2;
    double *x = realloc(tr->x, (size_t)cap * sizeof *x);
    if (x)
        tr->x = x;
    double *y = x ? realloc(tr->y, (size_t)cap * sizeof *y) : NULL;
    if (y)
        tr->y = y;
    double *s = y ? realloc(tr->s, (size_t)cap * sizeof *s) : NULL;
    if (s)
        tr->s = s;
    if (!s)
        return false;
    tr->cap = cap;
    return true;
}

bool fw_hull_track_start(fw_hull_track *tr, double bx, double by, double heading,
                         double length)
{
    if (!room(tr, 2))
        return false;
    double sh = sin(heading), ch = cos(heading);
    tr->x[0] = bx - length * sh, tr->y[0] = by - length * ch, tr->s[0] = 0.0;
    tr->x[1] = bx, tr->y[1] = by, tr->s[1] = length;
    tr->n = 2;
    tr->provisional = false;
    return true;
}

bool fw_hull_track_push(fw_hull_track *tr, double bx, double by, double length)
{
    if (tr->provisional && tr->n > 2)
        tr->n--; /* the last step's bow, kept only until now */
    tr->provisional = false;
    int last = tr->n - 1;
    double d = hypot(bx - tr->x[last], by - tr->y[last]);
    if (d < 1e-9)
        return true;
    bool close = d < kMinStep;
    /* drop what lies wholly behind the stern (keep one point before it) */
    double keep_from = tr->s[last] + d - length;
    int k = 0;
    while (k + 1 < tr->n && tr->s[k + 1] <= keep_from)
        k++;
    if (k > 0) {
        tr->n -= k;
        memmove(tr->x, tr->x + k, (size_t)tr->n * sizeof *tr->x);
        memmove(tr->y, tr->y + k, (size_t)tr->n * sizeof *tr->y);
        memmove(tr->s, tr->s + k, (size_t)tr->n * sizeof *tr->s);
    }
    if (!room(tr, tr->n + 1))
        return false;
    tr->x[tr->n] = bx, tr->y[tr->n] = by, tr->s[tr->n] = tr->s[tr->n - 1] + d;
    tr->n++;
    tr->provisional = close;
    return true;
}

void fw_hull_track_hull(const fw_hull_track *tr, double length, double *cx, double *cy,
                        double *heading)
{
    int last = tr->n - 1;
    double bx = tr->x[last], by = tr->y[last];
    double want = tr->s[last] - length;
    /* the stern: the track's point `length` behind the bow, interpolated;
     * the track's start when it is shorter (it never is after a start) */
    double sx = tr->x[0], sy = tr->y[0];
    for (int k = last; k > 0; k--)
        if (tr->s[k - 1] <= want) {
            double u = (want - tr->s[k - 1]) / (tr->s[k] - tr->s[k - 1]);
            sx = tr->x[k - 1] + u * (tr->x[k] - tr->x[k - 1]);
            sy = tr->y[k - 1] + u * (tr->y[k] - tr->y[k - 1]);
            break;
        }
    *heading = fw_wrap_2pi(atan2(bx - sx, by - sy));
    /* the centre half a hull length behind the bow along the chord (the
     * chord is shorter than the hull on a bend: the hull keeps its length) */
    double cl = hypot(bx - sx, by - sy);
    double u = cl > 0.0 ? 0.5 * length / cl : 0.5;
    *cx = bx - u * (bx - sx);
    *cy = by - u * (by - sy);
}

void fw_hull_track_free(fw_hull_track *tr)
{
    free(tr->x);
    free(tr->y);
    free(tr->s);
    memset(tr, 0, sizeof *tr);
}
