/* geom.c - see geom.h. */
#include "geom/geom.h"

#include "core/names.h"

#include <stdio.h>
#include <string.h>

fw_domain_def fw_default_domain_def(void)
{
    return (fw_domain_def){.size = 300.0, .fore_aft_ratio = 1.0, .reading = FW_DOMAIN_ELLIPSE};
}

static const char *const kReadingNames[] = {"ellipse", "transverse"}; /* enum order */

const char *fw_domain_reading_name(fw_domain_reading r)
{
    return fw_name_of(kReadingNames, 2, (int)r);
}

int fw_domain_reading_parse(const char *text) { return fw_name_find(kReadingNames, 2, text); }

void fw_domain_axes(const fw_domain_def *dom, const fw_target *t, double cos_rel,
                    double sin_rel, double *a, double *b)
{
    fw_domain_grown(dom, 0.5 * t->length, 0.5 * t->breadth, cos_rel, sin_rel, a, b);
}

double fw_domain_lambda(const fw_domain_def *dom, double east, double north, double psi,
                        const fw_target *t)
{
    /* the domain is the hulls': their headings orient it */
    double rel = t->heading - psi, a, b, x, y, fs, fc;
    fw_domain_axes(dom, t, cos(rel), sin(rel), &a, &b);
    fw_domain_frame(dom, sin(psi), cos(psi), sin(t->heading), cos(t->heading), &fs, &fc);
    fw_to_body(t->east - east, t->north - north, fs, fc, &x, &y);
    return sqrt((x / a) * (x / a) + (y / b) * (y / b));
}

double fw_domain_reach(const fw_domain_def *dom, const fw_target *t)
{
    double ratio = dom->fore_aft_ratio > 1.0 ? dom->fore_aft_ratio : 1.0;
    return dom->size * ratio + hypot(dom->own_half_length, dom->own_half_breadth) +
           0.5 * hypot(t->length, t->breadth);
}

bool fw_hulls_overlap(double e1, double n1, double psi1, double l1, double b1, double e2,
                      double n2, double psi2, double l2, double b2)
{
    /* unit axes (east, north) along and across each hull */
    double ax[4][2] = {{sin(psi1), cos(psi1)}, {cos(psi1), -sin(psi1)},
                       {sin(psi2), cos(psi2)}, {cos(psi2), -sin(psi2)}};
    double de = e2 - e1, dn = n2 - n1;
    for (int k = 0; k < 4; k++) {
        double ue = ax[k][0], un = ax[k][1];
        double r1 = 0.5 * l1 * fabs(ax[0][0] * ue + ax[0][1] * un) +
                    0.5 * b1 * fabs(ax[1][0] * ue + ax[1][1] * un);
        double r2 = 0.5 * l2 * fabs(ax[2][0] * ue + ax[2][1] * un) +
                    0.5 * b2 * fabs(ax[3][0] * ue + ax[3][1] * un);
        if (fabs(de * ue + dn * un) > r1 + r2)
            return false;
    }
    return true;
}

/* The four corners (east, north) of a hull rectangle. */
static void corners(double e, double n, double psi, double l, double b, double c[4][2])
{
    double s = sin(psi), k = cos(psi);
    static const double sx[4] = {1, 1, -1, -1}, sy[4] = {1, -1, -1, 1};
    for (int i = 0; i < 4; i++) {
        double x = 0.5 * l * sx[i], y = 0.5 * b * sy[i]; /* ahead, to starboard */
        c[i][0] = e + x * s + y * k;
        c[i][1] = n + x * k - y * s;
    }
}

/* Distance from point p to the segment a-b. */
static double point_segment(const double p[2], const double a[2], const double b[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1], q = dx * dx + dy * dy;
    double t = q > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / q : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

double fw_hull_distance(double e1, double n1, double psi1, double l1, double b1, double e2,
                        double n2, double psi2, double l2, double b2)
{
    if (fw_hulls_overlap(e1, n1, psi1, l1, b1, e2, n2, psi2, l2, b2))
        return 0.0;
    /* apart: the closest points are a corner of one and an edge of the other */
    double c1[4][2], c2[4][2], d = INFINITY;
    corners(e1, n1, psi1, l1, b1, c1);
    corners(e2, n2, psi2, l2, b2, c2);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            d = fmin(d, point_segment(c1[i], c2[j], c2[(j + 1) % 4]));
            d = fmin(d, point_segment(c2[i], c1[j], c1[(j + 1) % 4]));
        }
    return d;
}

void fw_target_path(const fw_target *t, double dt, int n, double *east, double *north,
                    double *heading)
{
    if (t->pred) {
        t->pred->path(t->pred, t, dt, n, east, north, heading);
        return;
    }
    double ve, vn;
    fw_velocity(t->speed, t->course, &ve, &vn);
    for (int k = 0; k < n; k++) {
        double tk = k * dt;
        east[k] = t->east + ve * tk;
        north[k] = t->north + vn * tk;
        heading[k] = t->heading;
    }
}

fw_target fw_target_named(const char *id, fw_target t)
{
    snprintf(t.id, sizeof t.id, "%s", id);
    t.key = 0; /* another id: the key was the old one's */
    return t;
}

int fw_target_find(const fw_target *t, int n, const char *id)
{
    if (!id || !id[0])
        return -1;
    for (int i = 0; i < n; i++)
        if (strcmp(t[i].id, id) == 0)
            return i;
    return -1;
}

fw_hull_track fw_hull_track_of(const fw_target *t)
{
    fw_hull_track k = {.east = t->east, .north = t->north, .heading = t->heading,
                       .length = t->length, .breadth = t->breadth};
    fw_velocity(t->speed, t->course, &k.ve, &k.vn);
    return k;
}

static double track_distance(const fw_hull_track *a, const fw_hull_track *b, double t)
{
    return fw_hull_distance(a->east + a->ve * t, a->north + a->vn * t, a->heading, a->length,
                            a->breadth, b->east + b->ve * t, b->north + b->vn * t, b->heading,
                            b->length, b->breadth);
}

double fw_hull_cpa(const fw_hull_track *a, const fw_hull_track *b, double horizon, double *t_min)
{
    double dx = b->east - a->east, dy = b->north - a->north;
    double ux = b->ve - a->ve, uy = b->vn - a->vn, u = hypot(ux, uy);
    double tc, dc;
    fw_cpa(dx, dy, ux, uy, &tc, &dc);
    /* the hull distance h and the centre distance c satisfy c - R <= h <= c,
     * R the sum of the half diagonals, so a minimiser has c <= dcpa + R:
     * within w of the centres' TCPA */
    double R = 0.5 * (hypot(a->length, a->breadth) + hypot(b->length, b->breadth));
    double w = u > 1e-9 ? sqrt(fmax(0.0, (dc + R) * (dc + R) - dc * dc)) / u : 0.0;
    double lo = fmax(0.0, tc - w), hi = fmin(horizon, tc + w);
    if (!(u > 1e-9) || !(hi > lo)) {
        /* no relative motion, or the closest approach is behind (or beyond
         * the horizon): the nearest end of the interval */
        double t = !(u > 1e-9) || tc + w <= 0.0 ? 0.0 : fmin(horizon, fmax(0.0, lo));
        if (t_min)
            *t_min = t;
        return track_distance(a, b, t);
    }
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = track_distance(a, b, x1), f2 = track_distance(a, b, x2);
    for (int i = 0; i < 200 && hi - lo > 1e-9 && f1 + f2 > 0.0; i++) {
        if (f1 <= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = track_distance(a, b, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = track_distance(a, b, x2);
        }
    }
    double t = f1 <= f2 ? x1 : x2, f = fmin(f1, f2);
    if (t_min)
        *t_min = t;
    return f;
}
