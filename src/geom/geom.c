/* geom.c - see geom.h. */
#include "geom/geom.h"

#include <stdio.h>
#include <string.h>

fw_domain_def fw_default_domain_def(void)
{
    return (fw_domain_def){.size = 300.0, .fore_aft_ratio = 1.0};
}

void fw_domain_axes(const fw_domain_def *dom, const fw_target *t, double cos_rel,
                    double sin_rel, double *a, double *b)
{
    fw_domain_grown(dom, 0.5 * t->length, 0.5 * t->breadth, cos_rel, sin_rel, a, b);
}

double fw_domain_lambda(const fw_domain_def *dom, double east, double north, double psi,
                        const fw_target *t)
{
    double rel = t->course - psi, a, b, x, y;
    fw_domain_axes(dom, t, cos(rel), sin(rel), &a, &b);
    fw_to_body(t->east - east, t->north - north, sin(psi), cos(psi), &x, &y);
    return sqrt((x / a) * (x / a) + (y / b) * (y / b));
}

double fw_domain_reach(const fw_domain_def *dom, const fw_target *t)
{
    double ratio = dom->fore_aft_ratio > 1.0 ? dom->fore_aft_ratio : 1.0;
    return dom->size * ratio + 0.5 * hypot(t->length, t->breadth);
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

void fw_target_path(const fw_target *t, double dt, int n, double *east, double *north,
                    double *course)
{
    if (t->pred) {
        t->pred->path(t->pred, t, dt, n, east, north, course);
        return;
    }
    double ve, vn;
    fw_velocity(t->speed, t->course, &ve, &vn);
    for (int k = 0; k < n; k++) {
        double tk = k * dt;
        east[k] = t->east + ve * tk;
        north[k] = t->north + vn * tk;
        course[k] = t->course;
    }
}

fw_target fw_target_named(const char *id, fw_target t)
{
    snprintf(t.id, sizeof t.id, "%s", id);
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
