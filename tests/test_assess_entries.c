/* test_assess_entries.c - the cheap forms the imperfect sea's cost floor
 * brought (issue 24) decide exactly as the plain ones:
 *   fw_assess_entries (the records' assessment of the truth) against
 *   fw_assess: every field but min_lambda and rank to the bit, over random
 *   scenes of turning targets, both domain readings, still water and a
 *   current;
 *   fw_within_range against hypot(dx, dy) <= r, random and at the boundary.
 */
#include <math.h>
#include <string.h>

#include "avoid/encounter.h"
#include "core/rng.h"
#include "core/within.h"
#include "geom/geom.h"
#include "test.h"

/* A target turning at a constant rate r (rad/s) at its speed: an arc. */
typedef struct arc_pred {
    fw_predictor base;
    double r;
} arc_pred;

static void arc_path(const fw_predictor *self, const fw_target *now, double dt, int n,
                     double *east, double *north, double *heading)
{
    double r = ((const arc_pred *)self)->r, e = now->east, no = now->north, c = now->course;
    for (int k = 0; k < n; k++) {
        east[k] = e, north[k] = no, heading[k] = c + (now->heading - now->course);
        e += now->speed * dt * sin(c + 0.5 * r * dt);
        no += now->speed * dt * cos(c + 0.5 * r * dt);
        c += r * dt;
    }
}

static bool same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static double uni(fw_rng *g, double lo, double hi) { return lo + (hi - lo) * fw_rng_uniform(g); }

/* One scene of n targets: the two forms agree; counts the entries seen. */
static void scene(fw_rng *g, const arc_pred *preds, int *entered, int *clear)
{
    enum { N = 12 };
    fw_own_state own = {.east = 0.0, .north = 0.0, .psi = uni(g, 0.0, 2.0 * M_PI),
                        .U = uni(g, 2.0, 10.0)};
    if (fw_rng_uniform(g) < 0.5)
        own.cur_e = uni(g, -1.2, 1.2), own.cur_n = uni(g, -1.2, 1.2);
    fw_domain_def dom = fw_default_domain_def();
    dom.size = uni(g, 150.0, 1000.0);
    dom.fore_aft_ratio = fw_rng_uniform(g) < 0.5 ? 1.0 : 2.5;
    dom.own_half_length = 100.0, dom.own_half_breadth = 16.0;
    dom.reading = fw_rng_uniform(g) < 0.5 ? FW_DOMAIN_ELLIPSE : FW_DOMAIN_TRANSVERSE;
    fw_colregs_def cd = fw_default_colregs_def();
    cd.visibility = fw_rng_uniform(g) < 0.5 ? 1852.0 : 0.0;
    fw_target t[N];
    for (int i = 0; i < N; i++) {
        double range = uni(g, 0.0, 8000.0), brg = uni(g, 0.0, 2.0 * M_PI);
        t[i] = (fw_target){.east = range * sin(brg), .north = range * cos(brg),
                           .course = uni(g, 0.0, 2.0 * M_PI), .speed = uni(g, 0.0, 12.0),
                           .length = uni(g, 20.0, 350.0), .breadth = uni(g, 5.0, 50.0)};
        t[i].heading = t[i].course + uni(g, -0.1, 0.1);
        t[i].stw = t[i].speed;
        t[i].pred = fw_rng_uniform(g) < 0.8 ? &preds[i % 4].base : NULL;
    }
    fw_assessment a[N], b[N];
    fw_assess(&cd, &dom, 600.0, &own, t, N, a, NULL);
    fw_assess_entries(&cd, &dom, 600.0, &own, t, N, b);
    for (int i = 0; i < N; i++) {
        CHECK(same(a[i].range, b[i].range) && same(a[i].bearing, b[i].bearing) &&
              same(a[i].rel_bearing, b[i].rel_bearing) && same(a[i].dcpa, b[i].dcpa) &&
              same(a[i].tcpa, b[i].tcpa) && same(a[i].t_range, b[i].t_range));
        CHECK(a[i].situation == b[i].situation && a[i].rule19 == b[i].rule19);
        CHECK_MSG(a[i].enters_domain == b[i].enters_domain && same(a[i].t_enter, b[i].t_enter),
                  "t_enter %.17g against %.17g", b[i].t_enter, a[i].t_enter);
        if (t[i].pred)
            *(a[i].enters_domain ? entered : clear) += 1;
        else
            CHECK(same(a[i].min_lambda, b[i].min_lambda));
    }
}

static void test_entries_as_assess(void)
{
    arc_pred preds[4];
    const double rates[4] = {0.0, 0.01, -0.02, 0.005};
    for (int i = 0; i < 4; i++)
        preds[i] = (arc_pred){.base = {.path = arc_path}, .r = rates[i]};
    fw_rng g = fw_rng_make(24, 1, FW_PURPOSE_SENSING);
    int entered = 0, clear = 0;
    for (int s = 0; s < 3000; s++)
        scene(&g, preds, &entered, &clear);
    printf("predicted targets: %d entering the domain, %d not\n", entered, clear);
    /* both branches are exercised many times */
    CHECK(entered > 500 && clear > 5000);
}

static void test_within_range(void)
{
    fw_rng g = fw_rng_make(24, 2, FW_PURPOSE_SENSING);
    long differ = 0;
    for (int i = 0; i < 400000; i++) {
        double r = uni(&g, 0.0, 20000.0), a = uni(&g, 0.0, 2.0 * M_PI);
        /* half of them at the boundary, to a few ulps */
        double d = i % 2 ? uni(&g, 0.0, 2.0 * r) : r * (1.0 + uni(&g, -4.0, 4.0) * 1e-16);
        double dx = d * sin(a), dy = d * cos(a);
        differ += fw_within_range(dx, dy, r) != (hypot(dx, dy) <= r);
    }
    CHECK(differ == 0);
    const double odd[][3] = {{3.0, 4.0, 5.0}, {3.0, 4.0, nextafter(5.0, 0.0)}, {0.0, 0.0, 0.0},
                             {1e-300, 0.0, 0.0}, {1e200, 1e200, 1e300}, {1e200, 0.0, 1e199},
                             {1.0, 1.0, -1.0}, {NAN, 0.0, 1.0}, {0.0, 1.0, INFINITY},
                             {INFINITY, 0.0, INFINITY}};
    for (size_t i = 0; i < sizeof odd / sizeof odd[0]; i++)
        CHECK_MSG(fw_within_range(odd[i][0], odd[i][1], odd[i][2]) ==
                      (hypot(odd[i][0], odd[i][1]) <= odd[i][2]),
                  "case %zu", i);
}

int main(void)
{
    TEST_RUN(test_entries_as_assess);
    TEST_RUN(test_within_range);
    return TEST_EXIT();
}
