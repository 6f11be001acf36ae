#include "avoid/clearance.h"

#include <math.h>
#include <string.h>

/* fmin/fmax are library calls at -O2 (they must handle NaN); these are
 * inlined, and the track and target data here are finite. */
static inline double mn(double a, double b) { return a < b ? a : b; }
static inline double mx(double a, double b) { return a > b ? a : b; }

int fw_prep_path_len(const fw_track_def *def) { return 4 * fw_track_samples(def); }

/* The predictor's path (see fw_prep_target.path): the heading goes into the
 * cosine run and is replaced by its sine and cosine. */
static void fill_path(const fw_target *g, const fw_track_def *tdef, int ns, double *p)
{
    fw_target_path(g, tdef->dt, ns, p, p + ns, p + 3 * ns);
    for (int k = 0; k < ns; k++) {
        double c = p[3 * ns + k];
        p[2 * ns + k] = sin(c);
        p[3 * ns + k] = cos(c);
    }
}

/* 1 / the largest squared axes fw_domain_grown can give this target (at any
 * relative heading: |c| hl + |s| hb <= hypot(hl, hb)), a little smaller
 * still: a lower bound of the normalised radius from them is never above the
 * exact one. */
static void axes_bound(const fw_domain_def *dom, fw_prep_target *g)
{
    double a, b;
    if (dom->reading == FW_DOMAIN_TRANSVERSE) {
        double own = hypot(dom->own_half_length, dom->own_half_breadth);
        a = dom->size * dom->fore_aft_ratio + g->hl + own;
        b = dom->size + g->hb + own;
    } else {
        double hull = hypot(g->hl, g->hb);
        a = dom->size * dom->fore_aft_ratio + dom->own_half_length + hull;
        b = dom->size + dom->own_half_breadth + hull;
    }
    g->ia_min = (1.0 - 1e-9) / (a * a);
    g->ib_min = (1.0 - 1e-9) / (b * b);
}

/* Is m made from g's course, heading, length and breadth (bit for bit)?  If
 * not it is made now: what fw_prep_targets computes from them alone. */
static void memo_fill(const fw_domain_def *dom, const fw_target *g, fw_prep_memo *m)
{
    if (m->valid && memcmp(&m->course, &g->course, sizeof m->course) == 0 &&
        memcmp(&m->heading, &g->heading, sizeof m->heading) == 0 &&
        memcmp(&m->length, &g->length, sizeof m->length) == 0 &&
        memcmp(&m->breadth, &g->breadth, sizeof m->breadth) == 0)
        return;
    fw_prep_target q = {.hl = 0.5 * g->length, .hb = 0.5 * g->breadth};
    axes_bound(dom, &q);
    *m = (fw_prep_memo){.valid = true, .course = g->course, .heading = g->heading,
                        .length = g->length, .breadth = g->breadth, .sc = sin(g->heading),
                        .cc = cos(g->heading), .reach = fw_domain_reach(dom, g),
                        .ia_min = q.ia_min, .ib_min = q.ib_min};
    bool same = memcmp(&g->course, &g->heading, sizeof g->course) == 0;
    m->vs = same ? m->sc : sin(g->course);
    m->vc = same ? m->cc : cos(g->course);
}

void fw_prep_targets_memo(const fw_domain_def *dom, const fw_track_def *tdef,
                          const fw_target *t, int n, fw_prep_target *out, double *paths,
                          fw_prep_memo *memo)
{
    int len = fw_prep_path_len(tdef);
    for (int i = 0; i < n; i++) {
        const fw_target *g = &t[i];
        fw_prep_memo here = {.valid = false}, *m = memo ? &memo[i] : &here;
        memo_fill(dom, g, m);
        out[i] = (fw_prep_target){.east = g->east, .north = g->north,
                                  .ve = g->speed * m->vs, .vn = g->speed * m->vc, .sc = m->sc,
                                  .cc = m->cc, .hl = 0.5 * g->length, .hb = 0.5 * g->breadth,
                                  .reach = m->reach, .ia_min = m->ia_min, .ib_min = m->ib_min};
        if (g->pred && paths) {
            out[i].ns = len / 4;
            fill_path(g, tdef, out[i].ns, paths);
            out[i].path = paths;
            paths += len;
        }
    }
}

void fw_prep_targets(const fw_domain_def *dom, const fw_track_def *tdef, const fw_target *t,
                     int n, fw_prep_target *out, double *paths)
{
    fw_prep_targets_memo(dom, tdef, t, n, out, paths, NULL);
}

/* The most the unit vector (s, c) moves in a step over samples k0..k1. */
static double unit_step(const double *s, const double *c, int k0, int k1)
{
    double w2 = 0.0;
    for (int k = k0 + 1; k <= k1; k++) {
        double ds = s[k] - s[k - 1], dc = c[k] - c[k - 1];
        w2 = mx(w2, ds * ds + dc * dc);
    }
    return sqrt(w2);
}

void fw_track_boxes_init(const fw_track *tr, fw_chunk_boxes *cb)
{
    cb->nseg = tr->n - 1;
    cb->nch = (cb->nseg + FW_CHUNK - 1) / FW_CHUNK;
    if (cb->nch > FW_MAX_CHUNKS)
        cb->nch = FW_MAX_CHUNKS;
}

void fw_track_box(const fw_track *tr, fw_chunk_boxes *cb, int j)
{
    int k0 = j * FW_CHUNK, k1 = k0 + FW_CHUNK < cb->nseg ? k0 + FW_CHUNK : cb->nseg;
    double e0 = tr->east[k0], e1 = e0, n0 = tr->north[k0], n1 = n0;
    for (int k = k0 + 1; k <= k1; k++) {
        e0 = mn(e0, tr->east[k]);
        e1 = mx(e1, tr->east[k]);
        n0 = mn(n0, tr->north[k]);
        n1 = mx(n1, tr->north[k]);
    }
    cb->b[j][0] = e0, cb->b[j][1] = e1, cb->b[j][2] = n0, cb->b[j][3] = n1;
}

void fw_track_boxes(const fw_track *tr, fw_chunk_boxes *cb)
{
    fw_track_boxes_init(tr, cb);
    for (int j = 0; j < cb->nch; j++)
        fw_track_box(tr, cb, j);
}

/* The bounding box of the target's path over samples k0..k1. */
static void path_box_over(double dt, const fw_prep_target *g, int k0, int k1, double t[4])
{
    if (g->path) {
        const double *e = g->path, *n = g->path + g->ns;
        t[0] = e[k0], t[1] = t[0], t[2] = n[k0], t[3] = t[2];
        for (int k = k0 + 1; k <= k1; k++) {
            t[0] = mn(t[0], e[k]);
            t[1] = mx(t[1], e[k]);
            t[2] = mn(t[2], n[k]);
            t[3] = mx(t[3], n[k]);
        }
    } else {
        double ta = k0 * dt, tb = k1 * dt;
        double ea = g->east + g->ve * ta, eb = g->east + g->ve * tb;
        double na = g->north + g->vn * ta, nb = g->north + g->vn * tb;
        t[0] = mn(ea, eb), t[1] = mx(ea, eb), t[2] = mn(na, nb), t[3] = mx(na, nb);
    }
}

/* The bounding box of the target's path over chunk j of a track of nseg
 * segments (as fw_prep_target.box, without the heading's step). */
static void path_box(double dt, const fw_prep_target *g, int j, int nseg, double t[4])
{
    int k0 = j * FW_CHUNK, k1 = k0 + FW_CHUNK < nseg ? k0 + FW_CHUNK : nseg;
    path_box_over(dt, g, k0, k1, t);
}

/* Inlined in the scans: the prepared box when there is one. */
static inline bool chunk_misses(double dt, const fw_prep_target *g, int j, int nseg,
                                const double b[4])
{
    if (g->box && j < g->nbox && nseg == g->box_nseg)
        return fw_box_misses(g->box + FW_PBOX * j, g->reach, b);
    double t[4];
    path_box(dt, g, j, nseg, t);
    return fw_box_misses(t, g->reach, b);
}

bool fw_chunk_misses(double dt, const fw_prep_target *g, int j, int nseg, const double b[4])
{
    return chunk_misses(dt, g, j, nseg, b);
}

static int box_chunks(int nseg)
{
    int nch = (nseg + FW_CHUNK - 1) / FW_CHUNK;
    return nch < FW_MAX_CHUNKS ? nch : FW_MAX_CHUNKS;
}

int fw_prep_box_len(int nseg) { return FW_PBOX * box_chunks(nseg); }

/* fw_prep_boxes of a constant-velocity target: path_box_over's ends, each
 * made once (chunk j's last sample is chunk j + 1's first, by the same
 * expression: the same bits), for the n chunks. */
static void cv_boxes(double dt, const fw_prep_target *g, int nseg, int n, double *room)
{
    int k0 = 0;
    double ta = k0 * dt, ea = g->east + g->ve * ta, na = g->north + g->vn * ta;
    for (int j = 0; j < n; j++) {
        int k1 = k0 + FW_CHUNK < nseg ? k0 + FW_CHUNK : nseg;
        double tb = k1 * dt, eb = g->east + g->ve * tb, nb = g->north + g->vn * tb;
        double *t = room + FW_PBOX * j;
        t[0] = mn(ea, eb), t[1] = mx(ea, eb), t[2] = mn(na, nb), t[3] = mx(na, nb), t[4] = 0.0;
        k0 = k1, ea = eb, na = nb;
    }
}

void fw_prep_boxes(double dt, fw_prep_target *g, int nseg, double *room)
{
    int nch = box_chunks(nseg);
    if (!g->path)
        cv_boxes(dt, g, nseg, nch, room);
    for (int j = 0; j < nch && g->path; j++) {
        double *t = room + FW_PBOX * j;
        path_box(dt, g, j, nseg, t);
        int k0 = j * FW_CHUNK, k1 = k0 + FW_CHUNK < nseg ? k0 + FW_CHUNK : nseg;
        t[4] = unit_step(g->path + 2 * g->ns, g->path + 3 * g->ns, k0, k1);
    }
    g->box = room, g->nbox = nch, g->box_nseg = nseg;
}

/* Every sample of a track's chunk ending at sample k1 is within R of the
 * start; the margin covers the rounding of the positions summed step by step. */
static inline double reach_radius(double dt, double umax, int k1)
{
    return umax * (k1 * dt) * (1.0 + 1e-9) + 1e-6;
}

/* Does g's path over chunk j, grown by its reach, meet the square of the
 * chunk's reach radius about (e0, n0)? */
static inline bool in_reach(double dt, const fw_prep_target *g, int j, int nseg, double e0,
                            double n0, double umax)
{
    int k1 = j * FW_CHUNK + FW_CHUNK < nseg ? j * FW_CHUNK + FW_CHUNK : nseg;
    double R = reach_radius(dt, umax, k1);
    double env[4] = {e0 - R, e0 + R, n0 - R, n0 + R};
    return !chunk_misses(dt, g, j, nseg, env);
}

void fw_reach_window(double dt, const fw_prep_target *g, int nseg, double e0, double n0,
                     double umax, int *lo, int *hi)
{
    int nchunks = (nseg + FW_CHUNK - 1) / FW_CHUNK;
    int nch = nchunks < FW_MAX_CHUNKS ? nchunks : FW_MAX_CHUNKS;
    if (!(umax >= 0.0)) {
        *lo = 0, *hi = nchunks;
        return;
    }
    /* only the first and the last chunk in reach matter: looked for from
     * either end (the chunks between are not tested) */
    *lo = -1, *hi = 0;
    for (int j = 0; j < nch && *lo < 0; j++)
        if (in_reach(dt, g, j, nseg, e0, n0, umax))
            *lo = j;
    for (int j = nch - 1; *lo >= 0 && j >= *lo && *hi == 0; j--)
        if (in_reach(dt, g, j, nseg, e0, n0, umax))
            *hi = j + 1;
    if (nchunks > nch) { /* chunks without boxes are never culled */
        if (*lo < 0)
            *lo = nch;
        *hi = nchunks;
    }
    if (*lo < 0)
        *lo = 0;
}

/* Does the box of g's whole path over a track of nseg segments, grown by its
 * reach, miss the square of the last chunk's radius about (e0, n0)?  Then
 * every chunk's test in fw_reach_window misses too, on the same side: each
 * chunk's box lies within the whole one (its samples are among the whole
 * path's, or its ends east + ve t at times between 0 and nseg dt, and that
 * rounds monotonically in t), each chunk's radius is at most the last one's,
 * and the roundings of the grown box and of the square are monotonic. */
static bool out_of_reach(double dt, const fw_prep_target *g, int nseg, double e0, double n0,
                         double umax)
{
    double t[4];
    path_box_over(dt, g, 0, nseg, t);
    double R = reach_radius(dt, umax, nseg);
    double env[4] = {e0 - R, e0 + R, n0 - R, n0 + R};
    return fw_box_misses(t, g->reach, env);
}

void fw_prep_reach(double dt, fw_prep_target *g, int nseg, double e0, double n0, double umax,
                   double *room, int *lo, int *hi)
{
    int nchunks = (nseg + FW_CHUNK - 1) / FW_CHUNK;
    if (umax >= 0.0 && nchunks <= FW_MAX_CHUNKS && out_of_reach(dt, g, nseg, e0, n0, umax)) {
        /* no chunk in the window: no box is ever looked at (none made;
         * fw_chunk_misses_in would make one) */
        g->box = room, g->nbox = 0, g->box_nseg = nseg;
        *lo = 0, *hi = 0;
        return;
    }
    fw_prep_boxes(dt, g, nseg, room);
    fw_reach_window(dt, g, nseg, e0, n0, umax, lo, hi);
}

void fw_boxes_union(fw_chunk_boxes *u, const fw_chunk_boxes *cb)
{
    for (int j = 0; j < cb->nch && j < u->nch; j++) {
        u->b[j][0] = mn(u->b[j][0], cb->b[j][0]);
        u->b[j][1] = mx(u->b[j][1], cb->b[j][1]);
        u->b[j][2] = mn(u->b[j][2], cb->b[j][2]);
        u->b[j][3] = mx(u->b[j][3], cb->b[j][3]);
    }
}

/* Smallest lambda^2 = (x/a)^2 + (y/b)^2 on the segment from (x0, y0) to (x1, y1). */
static double seg_min_lambda2(double x0, double y0, double x1, double y1, double a, double b)
{
    double ia = 1.0 / (a * a), ib = 1.0 / (b * b);
    double dx = x1 - x0, dy = y1 - y0;
    double q = dx * dx * ia + dy * dy * ib;
    double s = q > 0.0 ? -(x0 * dx * ia + y0 * dy * ib) / q : 0.0;
    if (s < 0.0)
        s = 0.0;
    if (s > 1.0)
        s = 1.0;
    double x = x0 + s * dx, y = y0 + s * dy;
    return x * x * ia + y * y * ib;
}

/* A lower bound of seg_min_lambda2 over the segment: each coordinate's
 * smallest magnitude on it (0 if it changes sign) over the largest axes the
 * target can give. */
static inline double seg_lower(double x0, double y0, double x1, double y1, const fw_prep_target *g)
{
    double xm = x0 * x1 > 0.0 ? mn(fabs(x0), fabs(x1)) : 0.0;
    double ym = y0 * y1 > 0.0 ? mn(fabs(y0), fabs(y1)) : 0.0;
    return xm * xm * g->ia_min + ym * ym * g->ib_min;
}

/* Body-frame offsets (x, y) of target g at samples k0..k1 of the track, and
 * the sine and cosine of its heading there (gs, gc). */
static void chunk_offsets(const fw_domain_def *dom, const fw_track *tr, const fw_prep_target *g,
                          int k0, int k1, double *x, double *y, double *gs, double *gc)
{
    bool tv = dom->reading == FW_DOMAIN_TRANSVERSE;
    for (int k = k0, q = 0; k <= k1; k++, q++) {
        double tk = k * tr->dt, ge, gn;
        fw_prep_at(g, k, tk, &ge, &gn);
        gs[q] = g->path ? g->path[2 * g->ns + k] : g->sc;
        gc[q] = g->path ? g->path[3 * g->ns + k] : g->cc;
        double dx = ge - tr->east[k], dy = gn - tr->north[k];
        /* fw_domain_frame: the own heading's frame, or the target's */
        double fs = tv ? gs[q] : tr->sin_psi[k], fc = tv ? gc[q] : tr->cos_psi[k];
        fw_to_body(dx, dy, fs, fc, &x[q], &y[q]);
    }
}

/* Grown axes at sample k (offset q in the chunk), from the relative heading's
 * cosine and sine by the angle sums. */
static inline void axes_at(const fw_domain_def *dom, const fw_track *tr, const fw_prep_target *g,
                           int k, double gs, double gc, double *a, double *b)
{
    double s = tr->sin_psi[k], c = tr->cos_psi[k];
    fw_domain_grown(dom, g->hl, g->hb, gc * c + gs * s, gs * c - gc * s, a, b);
}

/* Is every value the exact tests of chunk j (g's prepared box) could give
 * above cap?  A segment's point is (1 - s) M0 D0 + s M1 D1, D the world
 * offsets at its samples and M the frame's reflection there; that is M0 D(s)
 * + s (M1 - M0) D1 with D(s) in the difference of the two boxes, so its
 * length is at least the boxes' distance less |u1 - u0| (the frame's unit
 * vector's step, w) times their largest distance (here its L1 norm, which
 * is more), and lambda^2 at least that squared over the largest axes.  The
 * margins (1e-6 relative, 1e-6 m) cover the rounding of the offsets and of
 * the unit vectors' lengths (1e-10). */
static inline bool chunk_above(const fw_domain_def *dom, const fw_track *tr,
                               const fw_prep_target *g, const fw_chunk_boxes *cb, int j, int k0,
                               int k1, double cap)
{
    const double *t = g->box + FW_PBOX * j, *b = cb->b[j];
    double gx = mx(0.0, mx(t[0] - b[1], b[0] - t[1])), gy = mx(0.0, mx(t[2] - b[3], b[2] - t[3]));
    double m = mn(g->ia_min, g->ib_min), d2 = gx * gx + gy * gy;
    if (!(d2 * m * (1.0 - 1e-6) > cap))
        return false; /* not even without the frame's turn */
    /* the own heading's step made here, where it is needed (a chunk in six
     * of those boxed gets this far) */
    double w = dom->reading == FW_DOMAIN_TRANSVERSE ? t[4]
                                                    : unit_step(tr->sin_psi, tr->cos_psi, k0, k1);
    /* the largest distance over by its L1 norm (no second root) */
    double hx = mx(t[1] - b[0], b[1] - t[0]), hy = mx(t[3] - b[2], b[3] - t[2]);
    double d = sqrt(d2) * (1.0 - 1e-6) - w * (1.0 + 1e-6) * (hx + hy) - 1e-6;
    return d > 0.0 && d * d * m * (1.0 - 1e-6) - 1e-12 > cap;
}

double fw_target_min2_cap(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                          const fw_prep_target *g, int j0, int j1, double stop2, double cap2)
{
    double tmin2 = INFINITY;
    double x[FW_CHUNK + 1], y[FW_CHUNK + 1], gs[FW_CHUNK + 1], gc[FW_CHUNK + 1];
    for (int j = j0; j < j1 && j * FW_CHUNK < cb->nseg; j++) {
        int k0 = j * FW_CHUNK, k1 = k0 + FW_CHUNK < cb->nseg ? k0 + FW_CHUNK : cb->nseg;
        if (j < cb->nch && chunk_misses(tr->dt, g, j, cb->nseg, cb->b[j]))
            continue;
        /* (below 1 only: the box test has culled what lies farther out) */
        double cap = tmin2 < cap2 ? tmin2 : cap2;
        if (cap < 1.0 && j < cb->nch && g->box && j < g->nbox && cb->nseg == g->box_nseg &&
            chunk_above(dom, tr, g, cb, j, k0, k1, cap))
            continue;
        chunk_offsets(dom, tr, g, k0, k1, x, y, gs, gc);
        double pa = 0, pb = 0; /* axes of the segment's first sample, when made */
        int have = -1;
        for (int q = 1; q <= k1 - k0; q++) {
            /* a segment that cannot come below the smallest value found (or
             * cap2) cannot change the result: skipped.  The margins cover
             * the rounding of both (see clearance.h) */
            double lo = seg_lower(x[q - 1], y[q - 1], x[q], y[q], g);
            double cap = tmin2 < cap2 ? tmin2 : cap2;
            if (lo * (1.0 - 1e-6) - 1e-12 > cap)
                continue;
            double a, b;
            if (have != q - 1)
                axes_at(dom, tr, g, k0 + q - 1, gs[q - 1], gc[q - 1], &pa, &pb);
            axes_at(dom, tr, g, k0 + q, gs[q], gc[q], &a, &b);
            /* body-frame offsets interpolated linearly over the segment: the
             * frame turns by r dt (about 1 deg), a sub-metre error (the
             * transverse reading's target frame does not turn) */
            double l2 = seg_min_lambda2(x[q - 1], y[q - 1], x[q], y[q], 0.5 * (pa + a),
                                        0.5 * (pb + b));
            if (l2 < tmin2)
                tmin2 = l2;
            pa = a, pb = b, have = q;
        }
        if (tmin2 < stop2)
            break;
    }
    return tmin2;
}

double fw_target_min2(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                      const fw_prep_target *g, int j0, int j1, double stop2)
{
    return fw_target_min2_cap(dom, tr, cb, g, j0, j1, stop2, INFINITY);
}
