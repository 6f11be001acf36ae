/* test_ramp.c - a ship whose speed changes at a rate (geom/ramp.h): how far
 * it runs, and its closest approach to another ship, against the same found
 * by brute force (every 0.01 s), and the strait case that made it needed. */
#include <math.h>
#include <stdio.h>

#include "core/units.h"
#include "geom/geom.h"
#include "geom/ramp.h"
#include "test.h"

static const double kAcc = 0.05, kDec = 0.1;

/* The closest approach by brute force over [0, 3000] s, every 0.01 s. */
static void brute(double dx, double dy, double vx, double vy, double hx, double hy, double u,
                  double v, double *t_min, double *d_min)
{
    *d_min = INFINITY;
    *t_min = 0.0;
    for (int k = 0; k <= 300000; k++) {
        double t = 0.01 * k, s = fw_ramp_run(u, v, kAcc, kDec, t);
        double d = hypot(dx + vx * t - hx * s, dy + vy * t - hy * s);
        if (d < *d_min)
            *d_min = d, *t_min = t;
    }
}

static void test_run(void)
{
    /* 2 to 7 m/s at 0.05 m/s^2: 100 s and 450 m, then 7 m/s */
    CHECK_NEAR(fw_ramp_run(2.0, 7.0, kAcc, kDec, 100.0), 450.0, 1e-9);
    CHECK_NEAR(fw_ramp_run(2.0, 7.0, kAcc, kDec, 150.0), 800.0, 1e-9);
    CHECK_NEAR(fw_ramp_run(2.0, 7.0, kAcc, kDec, 40.0), 120.0, 1e-9);
    /* 7 to 2 m/s at 0.1 m/s^2: 50 s and 225 m */
    CHECK_NEAR(fw_ramp_run(7.0, 2.0, kAcc, kDec, 50.0), 225.0, 1e-9);
    CHECK_NEAR(fw_ramp_run(5.0, 5.0, kAcc, kDec, 10.0), 50.0, 1e-9);
}

/* u == v: fw_cpa_sq's answer, exactly */
static void test_constant(void)
{
    double tc, d2, tr, dr2;
    fw_cpa_ramp_sq(1000.0, 500.0, -3.0, 1.0, 0.6, 0.8, 6.0, 6.0, kAcc, kDec, 5.0, &tc, &d2);
    fw_cpa_sq(1000.0, 500.0, -3.0 - 6.0 * 0.6, 1.0 - 6.0 * 0.8, &tr, &dr2);
    CHECK(tc == tr && d2 == dr2);
}

/* against brute force: speeding up and slowing down, crossing, meeting,
 * overtaking, opening; 0.5 m and 1 s (the ramp's 5 s chords are within
 * 0.16 m of the curve) */
static void test_brute(void)
{
    const double c[][8] = {
        /* dx, dy, vx, vy, course deg, u, v */
        {-935.0, -294.0, 1.22, 1.00, 270.0, 1.07, 7.15},
        {2000.0, 1500.0, 0.0, -6.0, 90.0, 2.0, 8.0},
        {3000.0, 0.0, -5.0, 0.0, 90.0, 1.0, 6.0},
        {1500.0, 800.0, -2.0, -3.0, 45.0, 7.0, 2.0},
        {-500.0, -500.0, -1.0, -1.0, 0.0, 3.0, 9.0},
        {800.0, 20.0, 2.0, 0.0, 90.0, 1.0, 7.0},
    };
    for (int i = 0; i < (int)(sizeof c / sizeof c[0]); i++) {
        const double *x = c[i];
        double hx = sin(fw_deg_to_rad(x[4])), hy = cos(fw_deg_to_rad(x[4]));
        double tc, d2, tb, db;
        fw_cpa_ramp_sq(x[0], x[1], x[2], x[3], hx, hy, x[5], x[6], kAcc, kDec, 5.0, &tc, &d2);
        brute(x[0], x[1], x[2], x[3], hx, hy, x[5], x[6], &tb, &db);
        CHECK_MSG(fabs(sqrt(d2) - db) < 0.5 && fabs(tc - tb) < 1.0,
                  "case %d: %.2f m at %.2f s, brute force %.2f m at %.2f s", i, sqrt(d2), tc, db,
                  tb);
    }
}

/* strait-domain seed 3, replication 0, t = 2672 s: west.3 (a VLCC, 270 deg,
 * held at 2.1 kn) resumes 13.9 kn; ferry_north_fill0 crawls across its lane
 * 935 m ahead, 294 m to port, at 3.1 kn, 050.6 deg.  Judged at 13.9 kn from
 * the start it passes 180 m ahead in 114 s, farther than at the speed it
 * holds (105 m): rule 17(b)'s "passes farthest" gave it its speed back; at
 * SUMO's 0.05 m/s^2 it passes 137 m off, 44 s later (they overlapped 160 s
 * after, the ferry's speed having changed meanwhile). */
static void test_strait_resume(void)
{
    double u = fw_kn_to_ms(2.086), v = fw_kn_to_ms(13.9), fe = fw_kn_to_ms(3.074);
    double ce = sin(fw_deg_to_rad(50.618)), cn = cos(fw_deg_to_rad(50.618));
    double dx = 22375.33 - 23309.97, dy = 2006.25 - 2300.0, tc, d2, ti, di2;
    fw_cpa_sq(dx, dy, fe * ce + v, fe * cn, &ti, &di2);
    CHECK_NEAR(sqrt(di2), 180.0, 2.0);
    CHECK_NEAR(ti, 114.0, 1.0);
    fw_cpa_ramp_sq(dx, dy, fe * ce, fe * cn, -1.0, 0.0, u, v, kAcc, kDec, 5.0, &tc, &d2);
    printf("west.3 resuming: instantly %.0f m at %.0f s, at 0.05 m/s^2 %.0f m at %.0f s\n",
           sqrt(di2), ti, sqrt(d2), tc);
    CHECK_NEAR(sqrt(d2), 137.0, 2.0);
    CHECK_NEAR(tc, 158.0, 2.0);
}

int main(void)
{
    TEST_RUN(test_run);
    TEST_RUN(test_constant);
    TEST_RUN(test_brute);
    TEST_RUN(test_strait_resume);
    return TEST_EXIT();
}
