#include "avoid/encounter.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"

fw_colregs_def fw_default_colregs_def(void)
{
    return (fw_colregs_def){.head_on_bearing_deg = 6.0, .head_on_course_tol_deg = 15.0,
                            .overtake_sector_deg = 112.5};
}

const char *fw_situation_name(fw_situation s)
{
    switch (s) {
    case FW_SIT_HEAD_ON: return "head-on";
    case FW_SIT_OVERTAKING: return "overtaking";
    case FW_SIT_OVERTAKEN: return "being overtaken";
    case FW_SIT_GIVE_WAY: return "crossing give-way";
    case FW_SIT_STAND_ON: return "crossing stand-on";
    }
    return "?";
}

/* Relative bearing (deg) of a point whose true bearing is a (atan2 of the
 * east and north offsets) from a ship heading h. */
static double rel_bearing_deg(double a, double h) { return fw_rad_to_deg(fw_wrap_2pi(a - h)); }

/* Angular distance in degrees of bearing b from dead ahead. */
static double off_bow(double b) { return b <= 180.0 ? b : 360.0 - b; }

/* fw_classify with the target's true bearing from the own ship, a. */
static fw_situation classify(const fw_colregs_def *def, const fw_own_state *own,
                             const fw_target *t, double a)
{
    /* bearings and aspect from the hulls' headings (the lights a watch sees) */
    double beta = rel_bearing_deg(a, own->psi);
    double alpha = rel_bearing_deg(atan2(own->east - t->east, own->north - t->north), t->heading);
    double course_diff = fw_rad_to_deg(fabs(fw_wrap_pi(t->heading - own->psi)));
    if (off_bow(beta) <= def->head_on_bearing_deg && off_bow(alpha) <= def->head_on_bearing_deg &&
        course_diff >= 180.0 - def->head_on_course_tol_deg)
        return FW_SIT_HEAD_ON;
    double sector = def->overtake_sector_deg;
    if (alpha > sector && alpha < 360.0 - sector && own->U > t->speed)
        return FW_SIT_OVERTAKING;
    if (beta > sector && beta < 360.0 - sector && t->speed > own->U)
        return FW_SIT_OVERTAKEN;
    /* dead ahead counts as starboard: a crossing ship on the bow is given way to */
    return beta < 180.0 ? FW_SIT_GIVE_WAY : FW_SIT_STAND_ON;
}

fw_situation fw_classify(const fw_colregs_def *def, const fw_own_state *own,
                         const fw_target *t)
{
    return classify(def, own, t, atan2(t->east - own->east, t->north - own->north));
}

fw_situation fw_classify_lanes(const fw_colregs_def *def, const fw_own_state *own,
                               const fw_target *own_ship, const fw_lane_info *own_lane,
                               const fw_target *t, const fw_lane_info *t_lane)
{
    if (own_lane && t_lane && fw_lanes_meet(own_ship, own_lane, t, t_lane))
        return FW_SIT_HEAD_ON;
    fw_situation s = fw_classify(def, own, t);
    /* one ahead of the other along one waterway round a bend: overtaking
     * (rule 13), whatever their bearings and courses say */
    if ((s == FW_SIT_GIVE_WAY || s == FW_SIT_STAND_ON) && own_lane && t_lane &&
        fw_lanes_along(own_ship, own_lane, t, t_lane))
        return own->U > t->speed ? FW_SIT_OVERTAKING : FW_SIT_OVERTAKEN;
    return s;
}

void fw_assess_lanes(const fw_colregs_def *def, const fw_own_state *own,
                     const fw_lane_info *own_lane, const fw_target *t,
                     const fw_lane_info *const *lanes, int n, fw_assessment *as)
{
    fw_target me = {.east = own->east, .north = own->north, .heading = own->psi,
                    .course = own->psi, .speed = own->U, .own = true};
    for (int i = 0; i < n; i++)
        if (lanes[i])
            as[i].situation = fw_classify_lanes(def, own, &me, own_lane, &t[i], lanes[i]);
}

static bool more_dangerous(const fw_assessment *p, int i, const fw_assessment *q, int j)
{
    if (p->enters_domain != q->enters_domain)
        return p->enters_domain;
    if (p->enters_domain && p->t_range != q->t_range)
        return p->t_range < q->t_range;
    if (p->enters_domain && p->t_enter != q->t_enter)
        return p->t_enter < q->t_enter;
    if (p->dcpa != q->dcpa)
        return p->dcpa < q->dcpa;
    if (p->range != q->range)
        return p->range < q->range;
    return i < j;
}

/* Stable merge sort of index array a (scratch b, same length) by danger. */
static void merge_sort(int *a, int *b, int n, const fw_assessment *as)
{
    if (n < 2)
        return;
    int h = n / 2;
    merge_sort(a, b, h, as);
    merge_sort(a + h, b + h, n - h, as);
    int i = 0, j = h, k = 0;
    while (i < h && j < n)
        b[k++] = more_dangerous(&as[a[j]], a[j], &as[a[i]], a[i]) ? a[j++] : a[i++];
    while (i < h)
        b[k++] = a[i++];
    while (j < n)
        b[k++] = a[j++];
    for (k = 0; k < n; k++)
        a[k] = b[k];
}

/* The danger order of order[0..n-1]: by insertion for a few targets with
 * no NaN among the keys (more_dangerous is then a strict total order, the
 * index breaking every tie, so any sort gives its one order, merge_sort's),
 * else merge_sort.  In the base run a decision ranks ~10 targets. */
static void sort_by_danger(int *order, int n, const fw_assessment *as)
{
    bool plain = n <= 32;
    for (int i = 0; i < n && plain; i++)
        plain = !isnan(as[i].t_range) && !isnan(as[i].t_enter) && !isnan(as[i].dcpa) &&
                !isnan(as[i].range);
    if (!plain) {
        merge_sort(order, order + n, n, as);
        return;
    }
    for (int i = 1; i < n; i++) {
        int x = order[i], j = i;
        for (; j > 0 && more_dangerous(&as[x], x, &as[order[j - 1]], order[j - 1]); j--)
            order[j] = order[j - 1];
        order[j] = x;
    }
}

/* Domain entry against a target with a predictor: its path sampled every
 * kPathDt seconds, the own ship on its present course and speed; between
 * samples the body-frame offset and the hull-grown axes are interpolated
 * linearly (the own frame does not turn on a straight course). */
static const double kPathDt = 5.0;

/* The own ship's velocity over ground as the assessment takes it: its speed
 * through the water along its heading (so, co: its sine and cosine), plus
 * the current it knows; in calm water the plain product, to the bit. */
static inline void own_velocity(const fw_own_state *own, double so, double co, double *ve,
                                double *vn)
{
    *ve = own->U * so, *vn = own->U * co;
    if (own->cur_e != 0.0 || own->cur_n != 0.0)
        *ve += own->cur_e, *vn += own->cur_n;
}

/* Sample k of assess_path's loop: the target's offset in the domain's frame
 * (x, y) and the grown axes (a, b); one place, so that the entry-only form
 * below computes every sample it looks at to the same bits. */
static inline void path_sample(const fw_domain_def *dom, const fw_own_state *own,
                               const fw_target *t, double so, double co, double ve, double vn,
                               double e, double n, double c, double tk, double *x, double *y,
                               double *a, double *b)
{
    double rel = c - own->psi, fs, fc;
    fw_domain_frame(dom, so, co, sin(c), cos(c), &fs, &fc);
    fw_to_body(e - (own->east + ve * tk), n - (own->north + vn * tk), fs, fc, x, y);
    fw_domain_axes(dom, t, cos(rel), sin(rel), a, b);
}

/* A target's path over the horizon and the own ship's straight course. */
enum { MAX_SAMPLES = 1024 };
typedef struct path_in {
    int ns;
    double e[MAX_SAMPLES], n[MAX_SAMPLES], c[MAX_SAMPLES];
    double so, co, ve, vn; /* the own heading's sine, cosine; its velocity */
} path_in;

static void path_begin(double horizon, const fw_own_state *own, const fw_target *t, path_in *p)
{
    p->ns = (int)ceil(horizon / kPathDt) + 1;
    if (p->ns > MAX_SAMPLES)
        p->ns = MAX_SAMPLES;
    fw_target_path(t, kPathDt, p->ns, p->e, p->n, p->c);
    p->so = sin(own->psi), p->co = cos(own->psi);
    own_velocity(own, p->so, p->co, &p->ve, &p->vn);
}

/* The segment from (px, py) (axes pa, pb) to (x, y) (a, b): lambda^2 along
 * it, with the axes' mean, is C + s B + s^2 A for s in [0, 1]. */
static inline void segment(double px, double py, double pa, double pb, double x, double y,
                           double a, double b, double *A, double *B, double *C)
{
    double ma = 0.5 * (pa + a), mb = 0.5 * (pb + b);
    double dx = x - px, dy = y - py;
    *A = (dx / ma) * (dx / ma) + (dy / mb) * (dy / mb);
    *B = 2.0 * (px * dx / (ma * ma) + py * dy / (mb * mb));
    *C = (px / ma) * (px / ma) + (py / mb) * (py / mb);
}

static void assess_path(const fw_domain_def *dom, double horizon, const fw_own_state *own,
                        const fw_target *t, fw_assessment *as)
{
    path_in P;
    path_begin(horizon, own, t, &P);
    const int ns = P.ns;
    const double *e = P.e, *n = P.n, *c = P.c, so = P.so, co = P.co, ve = P.ve, vn = P.vn;
    double best = INFINITY, px = 0, py = 0, pa = 1, pb = 1;
    as->t_enter = INFINITY;
    for (int k = 0; k < ns; k++) {
        double tk = k * kPathDt, x, y, a, b;
        path_sample(dom, own, t, so, co, ve, vn, e[k], n[k], c[k], tk, &x, &y, &a, &b);
        double l2 = (x / a) * (x / a) + (y / b) * (y / b);
        if (k == 0 && l2 < 1.0)
            as->t_enter = 0.0;
        if (k > 0) {
            /* the smallest normalised radius on the segment, and where it
             * first crosses 1 */
            double A, B, C;
            segment(px, py, pa, pb, x, y, a, b, &A, &B, &C);
            double s = A > 0.0 ? fmin(1.0, fmax(0.0, -B / (2.0 * A))) : 0.0;
            best = fmin(best, C + s * (B + s * A));
            double disc = B * B - 4.0 * A * (C - 1.0);
            if (isinf(as->t_enter) && C >= 1.0 && A > 0.0 && disc >= 0.0) {
                double se = (-B - sqrt(disc)) / (2.0 * A);
                if (se >= 0.0 && se <= 1.0)
                    as->t_enter = (k - 1 + se) * kPathDt;
            }
        }
        best = fmin(best, l2);
        px = x, py = y, pa = a, pb = b;
    }
    as->min_lambda = sqrt(fmax(0.0, best));
}

/* assess_path for whether and when the target enters the domain alone
 * (min_lambda NAN): the same t_enter to the bit, the samples and segments
 * that cannot be within the domain skipped.  A segment's body-frame offsets
 * x0, x1 have the lengths L0, L1 of the plane offsets (a rotation), and
 * |x1 - x0| <= D = |p1 - p0| + |dtheta| L0 (dtheta: the frame's turn over
 * the segment, 0 in the own ship's frame); on the segment |x| >= (L0 + L1 -
 * D) / 2, and the (interpolated) axes are at most fw_domain_reach, so where
 * that bound exceeds the reach the normalised radius stays above 1: no
 * entry, no crossing.  In the own ship's frame (which does not turn) a
 * cheaper bound without a root a sample: every point of a segment is within
 * S of its end, S a bound on the offset's move over any one step
 * (offset_step); where the end is farther than reach + S, the segment is
 * out of reach, and so are the segments up to the sample whose end it can
 * come within reach + S of at the soonest (skipped unread).  A segment either bound lets through is evaluated; one out
 * of reach finds no entry when evaluated, so both give the same t_enter.
 * Evaluated segments are assess_path's arithmetic. */
/* A bound on how far the target's offset from the own ship moves over one
 * step of its path: the path's longest step (squares compared, one root)
 * and the own ship's run, with a margin far above their rounding. */
static double offset_step(const path_in *p)
{
    double m2 = 0.0;
    for (int k = 1; k < p->ns; k++) {
        double se = p->e[k] - p->e[k - 1], sn = p->n[k] - p->n[k - 1], s2 = se * se + sn * sn;
        m2 = s2 > m2 ? s2 : m2;
    }
    return (sqrt(m2) + hypot(p->ve, p->vn) * kPathDt) * (1.0 + 1e-9) + 1e-6;
}

static void assess_path_entry(const fw_domain_def *dom, double horizon, const fw_own_state *own,
                              const fw_target *t, fw_assessment *as)
{
    path_in P;
    path_begin(horizon, own, t, &P);
    const int ns = P.ns;
    const double *e = P.e, *n = P.n, *c = P.c, so = P.so, co = P.co, ve = P.ve, vn = P.vn;
    bool turning_frame = dom->reading == FW_DOMAIN_TRANSVERSE;
    /* a margin far above the rounding of the bound's terms */
    double reach = fw_domain_reach(dom, t) * (1.0 + 1e-9) + 1e-6;
    double S = turning_frame ? 0.0 : offset_step(&P), R = reach + S, R2 = R * R;
    as->t_enter = INFINITY;
    as->min_lambda = NAN;
    double px = 0, py = 0, pa = 1, pb = 1, pdx = 0, pdy = 0, pL = 0;
    int have = -1; /* the sample px .. pb hold */
    for (int k = 0; k < ns; k++) {
        double tk = k * kPathDt;
        double dx = e[k] - (own->east + ve * tk), dy = n[k] - (own->north + vn * tk);
        double L2 = dx * dx + dy * dy;
        bool near = L2 <= R2;
        if (!turning_frame && !near && S > 0.0) {
            /* |offset| falls by at most S a sample: the next q - 1 samples,
             * q = (L - R) / S, are all farther than R + S */
            double q = (sqrt(L2) - R) / S;
            if (q >= 2.0)
                k += q < ns ? (int)q - 1 : ns;
            continue;
        }
        if (turning_frame) {
            double L = sqrt(dx * dx + dy * dy);
            near = L <= reach;
            if (k > 0 && !near) {
                double turn = fabs(fw_wrap_pi(c[k] - c[k - 1]));
                double sx = dx - pdx, sy = dy - pdy, D = sqrt(sx * sx + sy * sy) + turn * pL;
                near = 0.5 * (pL + L - D) <= reach;
            }
            pdx = dx, pdy = dy, pL = L;
        }
        if (near) {
            if (k > 0 && have != k - 1)
                path_sample(dom, own, t, so, co, ve, vn, e[k - 1], n[k - 1], c[k - 1],
                            (k - 1) * kPathDt, &px, &py, &pa, &pb);
            double x, y, a, b;
            path_sample(dom, own, t, so, co, ve, vn, e[k], n[k], c[k], tk, &x, &y, &a, &b);
            double l2 = (x / a) * (x / a) + (y / b) * (y / b);
            if (k == 0 && l2 < 1.0) {
                as->t_enter = 0.0;
                return;
            }
            if (k > 0) {
                double A, B, C;
                segment(px, py, pa, pb, x, y, a, b, &A, &B, &C);
                double disc = B * B - 4.0 * A * (C - 1.0);
                if (C >= 1.0 && A > 0.0 && disc >= 0.0) {
                    double se = (-B - sqrt(disc)) / (2.0 * A);
                    if (se >= 0.0 && se <= 1.0) {
                        as->t_enter = (k - 1 + se) * kPathDt;
                        return;
                    }
                }
            }
            px = x, py = y, pa = a, pb = b;
            have = k;
        }
    }
}

/* When |d + v t| first falls to R (0 if it is within R now or R is 0,
 * INFINITY if it never does). */
static double time_to_range(double dx, double dy, double vx, double vy, double R)
{
    double C = dx * dx + dy * dy - R * R;
    if (R <= 0.0 || C <= 0.0)
        return 0.0;
    double A = vx * vx + vy * vy, B = 2.0 * (dx * vx + dy * vy), disc = B * B - 4.0 * A * C;
    if (!(A > 0.0) || B >= 0.0 || disc < 0.0)
        return INFINITY;
    return (-B - sqrt(disc)) / (2.0 * A);
}

static void assess(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
                   const fw_own_state *own, const fw_target *t, int n, fw_assessment *out,
                   int *order, bool lambda)
{
    double so = sin(own->psi), co = cos(own->psi);
    for (int i = 0; i < n; i++) {
        fw_assessment *as = &out[i];
        double dx = t[i].east - own->east, dy = t[i].north - own->north;
        /* the course's sine and cosine once (fw_velocity's, and the frame's
         * when the heading is the course) */
        double sc = sin(t[i].course), cc = cos(t[i].course), oe, on;
        double ve = t[i].speed * sc, vn = t[i].speed * cc;
        own_velocity(own, so, co, &oe, &on);
        double vx = ve - oe, vy = vn - on, brg = atan2(dx, dy);
        as->range = hypot(dx, dy);
        as->bearing = fw_wrap_2pi(brg);
        as->rel_bearing = fw_wrap_2pi(as->bearing - own->psi);
        fw_cpa(dx, dy, vx, vy, &as->tcpa, &as->dcpa);
        as->t_range = time_to_range(dx, dy, vx, vy, cdef->rank_range_m);
        as->situation = classify(cdef, own, &t[i], brg);
        as->rule19 = fw_not_in_sight(cdef, as->range);
        as->rank = 0;
        if (t[i].pred) {
            if (lambda)
                assess_path(dom, horizon, own, &t[i], as);
            else
                assess_path_entry(dom, horizon, own, &t[i], as);
            as->enters_domain = isfinite(as->t_enter);
            continue;
        }
        /* Domain on the straight course: in the domain's frame (the own
         * heading's or the target's, both fixed while both keep course) the
         * target moves on a line, and lambda^2(t) is a quadratic. */
        double a, b, fs, fc;
        double rel = t[i].heading - own->psi;
        fw_domain_axes(dom, &t[i], cos(rel), sin(rel), &a, &b);
        if (t[i].heading != t[i].course)
            sc = sin(t[i].heading), cc = cos(t[i].heading);
        fw_domain_frame(dom, so, co, sc, cc, &fs, &fc);
        double x, y, ux, uy;
        fw_to_body(dx, dy, fs, fc, &x, &y);
        fw_to_body(vx, vy, fs, fc, &ux, &uy);
        double A = ux * ux / (a * a) + uy * uy / (b * b);
        double B = 2.0 * (x * ux / (a * a) + y * uy / (b * b));
        double C = x * x / (a * a) + y * y / (b * b);
        double tm = A > 0.0 ? -B / (2.0 * A) : 0.0;
        if (tm < 0.0)
            tm = 0.0;
        if (tm > horizon)
            tm = horizon;
        as->min_lambda = sqrt(fmax(0.0, C + tm * (B + tm * A)));
        as->t_enter = INFINITY;
        if (C < 1.0) {
            as->t_enter = 0.0;
        } else if (A > 0.0 && B * B - 4.0 * A * (C - 1.0) >= 0.0) {
            double te = (-B - sqrt(B * B - 4.0 * A * (C - 1.0))) / (2.0 * A);
            if (te >= 0.0 && te <= horizon)
                as->t_enter = te;
        }
        as->enters_domain = isfinite(as->t_enter);
        as->rank = 0;
    }
    if (order) {
        for (int i = 0; i < n; i++)
            order[i] = i;
        sort_by_danger(order, n, out);
        for (int i = 0; i < n; i++)
            out[order[i]].rank = i;
    }
}

void fw_assess(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
               const fw_own_state *own, const fw_target *t, int n, fw_assessment *out,
               int *order)
{
    assess(cdef, dom, horizon, own, t, n, out, order, true);
}

void fw_assess_entries(const fw_colregs_def *cdef, const fw_domain_def *dom, double horizon,
                       const fw_own_state *own, const fw_target *t, int n, fw_assessment *out)
{
    assess(cdef, dom, horizon, own, t, n, out, NULL, false);
}

double fw_fog_signal_range(double length)
{
    /* COLREGs Annex III 1(c): the range of audibility of a whistle by the
     * ship's length (200 m or more: 2 nm; 75 m: 1.5; 20 m: 1; less: 0.5) */
    return fw_nm_to_m(length >= 200.0 ? 2.0 : length >= 75.0 ? 1.5 : length >= 20.0 ? 1.0 : 0.5);
}
