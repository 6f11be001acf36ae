/* test_geom.c - the plane geometry of ships (geom/geom.h) and the turn predictor (geom/turn.h)
 * against worked answers. */
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"
#include "geom/turn.h"
#include "test.h"

static void test_body_frame_and_cpa(void)
{
    double x, y;
    /* a point 100 m east of a ship heading east is 100 m ahead */
    fw_to_body(100.0, 0.0, sin(0.5 * FW_PI), cos(0.5 * FW_PI), &x, &y);
    CHECK_NEAR(x, 100.0, 1e-12);
    CHECK_NEAR(y, 0.0, 1e-12);
    /* ... and one 100 m south of it is 100 m to starboard */
    fw_to_body(0.0, -100.0, sin(0.5 * FW_PI), cos(0.5 * FW_PI), &x, &y);
    CHECK_NEAR(y, 100.0, 1e-12);
    /* 1000 m ahead closing at 10 m/s with a 300 m offset: CPA 300 m at 100 s */
    double t, d;
    fw_cpa(300.0, 1000.0, 0.0, -10.0, &t, &d);
    CHECK_NEAR(t, 100.0, 1e-12);
    CHECK_NEAR(d, 300.0, 1e-12);
    fw_cpa(5.0, 5.0, 0.0, 0.0, &t, &d); /* no relative motion: now */
    CHECK(t == 0.0);
    CHECK_NEAR(d, hypot(5.0, 5.0), 1e-12);
}

static void test_hull_distance(void)
{
    /* two 100 x 20 m hulls side by side, heading north, 50 m between centres */
    CHECK_NEAR(fw_hull_distance(0, 0, 0, 100, 20, 50, 0, 0, 100, 20), 30.0, 1e-9);
    /* bow to stern, 150 m apart: 50 m of water */
    CHECK_NEAR(fw_hull_distance(0, 0, 0, 100, 20, 0, 150, 0, 100, 20), 50.0, 1e-9);
    /* corner to corner on the diagonal: (10, 50) to (40, 90) */
    CHECK_NEAR(fw_hull_distance(0, 0, 0, 100, 20, 50, 140, 0, 100, 20), 50.0, 1e-9);
    /* overlapping: 0, and symmetric */
    CHECK(fw_hull_distance(0, 0, 0, 100, 20, 10, 10, 1.0, 100, 20) == 0.0);
    double a = fw_hull_distance(0, 0, 0.3, 200, 30, 400, 100, 2.0, 150, 25);
    double b = fw_hull_distance(400, 100, 2.0, 150, 25, 0, 0, 0.3, 200, 30);
    CHECK_NEAR(a, b, 1e-9);
    /* crossing at right angles, bow 25 m from the other's side */
    CHECK_NEAR(fw_hull_distance(0, 0, 0, 100, 20, 85, 0, 0.5 * FW_PI, 100, 20), 25.0, 1e-9);
}

static void test_domain(void)
{
    fw_domain_def dom = {.size = 300.0, .fore_aft_ratio = 2.0};
    fw_target t = {.east = 0, .north = 600, .course = 0, .heading = 0, .length = 0, .breadth = 0};
    /* a point target 600 m ahead sits on the 600 m fore-aft semi-axis */
    CHECK_NEAR(fw_domain_lambda(&dom, 0, 0, 0, &t), 1.0, 1e-12);
    /* abeam at 300 m: on the transverse one */
    t.east = 300, t.north = 0;
    CHECK_NEAR(fw_domain_lambda(&dom, 0, 0, 0, &t), 1.0, 1e-12);
    /* a 200 x 32 m hull abeam, parallel, grows the transverse axis by 16 m */
    t.length = 200, t.breadth = 32, t.east = 316;
    CHECK_NEAR(fw_domain_lambda(&dom, 0, 0, 0, &t), 1.0, 1e-12);
    /* the same seen from a ship turned round: symmetric */
    CHECK_NEAR(fw_domain_lambda(&dom, 0, 0, FW_PI, &t), 1.0, 1e-12);
}

/* The paper's transverse reading (geom.h): the clearance from the target's
 * side, in the target's frame. */
static void test_domain_transverse(void)
{
    fw_domain_def el = {.size = 300.0, .fore_aft_ratio = 1.0};
    fw_domain_def tv = el;
    tv.reading = FW_DOMAIN_TRANSVERSE;
    CHECK(fw_domain_reading_parse("transverse") == FW_DOMAIN_TRANSVERSE &&
          fw_domain_reading_parse("ellipse") == FW_DOMAIN_ELLIPSE &&
          fw_domain_reading_parse("circle") == -1);
    CHECK(strcmp(fw_domain_reading_name(FW_DOMAIN_TRANSVERSE), "transverse") == 0);
    /* a 200 x 32 m target heading south at the origin; the own ship abeam of
     * it, 316 m east (300 m from its port side): on the boundary whatever the
     * own heading, and 1 m either way inside or out */
    fw_target t = {.east = 0, .north = 0, .course = FW_PI, .heading = FW_PI, .length = 200, .breadth = 32};
    for (int h = 0; h < 360; h += 15) {
        double psi = fw_deg_to_rad(h);
        CHECK_NEAR(fw_domain_lambda(&tv, 316, 0, psi, &t), 1.0, 1e-12);
        CHECK(fw_domain_lambda(&tv, 315, 0, psi, &t) < 1.0);
        CHECK(fw_domain_lambda(&tv, 317, 0, psi, &t) > 1.0);
        /* symmetric: the starboard side, and ahead and astern alike */
        CHECK_NEAR(fw_domain_lambda(&tv, -316, 0, psi, &t), 1.0, 1e-12);
        CHECK_NEAR(fw_domain_lambda(&tv, 0, 400, psi, &t), 1.0, 1e-12);
        CHECK_NEAR(fw_domain_lambda(&tv, 0, -400, psi, &t), 1.0, 1e-12);
        double l1 = fw_domain_lambda(&tv, 150, 250, psi, &t);
        CHECK_NEAR(fw_domain_lambda(&tv, -150, -250, psi, &t), l1, 1e-12);
        CHECK_NEAR(fw_domain_lambda(&tv, -150, 250, psi, &t), l1, 1e-12);
    }
    /* the own ship turned 45 deg away: the ellipse reading projects the
     * target's hull on the own axes and asks 300 + 116 x 0.707 = 382 m */
    double psi45 = fw_deg_to_rad(45);
    double grown = 300.0 + (100.0 + 16.0) * sqrt(0.5);
    CHECK_NEAR(fw_domain_lambda(&el, 316, 0, psi45, &t), 316.0 / grown, 1e-12);
    CHECK_NEAR(fw_domain_lambda(&el, grown, 0, psi45, &t), 1.0, 1e-12);
    /* where they agree: parallel and reciprocal courses, anywhere, with
     * the domain about the centre and about the hulls */
    for (int hull = 0; hull < 2; hull++) {
        el.own_half_length = tv.own_half_length = hull ? 166.6 : 0.0;
        el.own_half_breadth = tv.own_half_breadth = hull ? 21.4 : 0.0;
        for (int c = 0; c < 2; c++) {
            t.course = t.heading = c ? FW_PI : 0.0;
            for (double e = -500; e <= 500; e += 125)
                for (double n = -600; n <= 600; n += 150) {
                    double a = fw_domain_lambda(&el, e, n, 0.0, &t);
                    CHECK_NEAR(fw_domain_lambda(&tv, e, n, 0.0, &t), a, 1e-12 * a);
                }
        }
    }
    /* a fore-aft ratio stretches the target's bow and stern clearance, not
     * its side: 600 m beyond the bow with ratio 2 */
    tv.own_half_length = tv.own_half_breadth = 0.0;
    tv.fore_aft_ratio = 2.0;
    t.course = t.heading = 0.0;
    CHECK_NEAR(fw_domain_lambda(&tv, 0, 700, 1.0, &t), 1.0, 1e-12);
    CHECK_NEAR(fw_domain_lambda(&tv, 316, 0, 1.0, &t), 1.0, 1e-12);
    /* reach bounds it */
    CHECK(fw_domain_reach(&tv, &t) >= 700.0);
}

static fw_hull_track track(double e, double n, double hdg_deg, double v, double l, double b)
{
    double h = hdg_deg * M_PI / 180.0;
    fw_hull_track k = {e, n, h, v * sin(h), v * cos(h), l, b};
    return k;
}

/* Brute force: the smallest hull distance sampled every dt up to t_end. */
static double sampled_min(const fw_hull_track *a, const fw_hull_track *b, double t_end, double dt)
{
    double m = INFINITY;
    for (double t = 0.0; t <= t_end; t += dt)
        m = fmin(m, fw_hull_distance(a->east + a->ve * t, a->north + a->vn * t, a->heading,
                                     a->length, a->breadth, b->east + b->ve * t,
                                     b->north + b->vn * t, b->heading, b->length, b->breadth));
    return m;
}

/* Geometric collision candidates on hand-built tracks: a hit, a miss by a
 * metre, parallel tracks, a crossing, a pair already past. */
static void test_hull_cpa(void)
{
    /* head-on on one line, two 100 x 20 m hulls closing at 10 m/s from 2000 m:
     * bows meet at 190 s, sterns part at 210 s */
    fw_hull_track a = track(0, 0, 0, 5, 100, 20), b = track(0, 2000, 180, 5, 100, 20);
    double t = -1.0;
    CHECK(fw_hull_cpa(&a, &b, INFINITY, &t) == 0.0);
    CHECK(t >= 190.0 - 1e-6 && t <= 210.0 + 1e-6);
    /* the same 21 m apart abeam: the sides pass 1 m apart (half breadths 10 + 10) */
    b = track(21, 2000, 180, 5, 100, 20);
    CHECK_NEAR(fw_hull_cpa(&a, &b, INFINITY, &t), 1.0, 1e-6);
    CHECK(t >= 190.0 && t <= 210.0);
    /* 19 m apart: contact by a metre */
    b = track(19, 2000, 180, 5, 100, 20);
    CHECK(fw_hull_cpa(&a, &b, INFINITY, NULL) == 0.0);
    /* a horizon before the meeting: not yet */
    b = track(0, 2000, 180, 5, 100, 20);
    CHECK_NEAR(fw_hull_cpa(&a, &b, 100.0, &t), 2000.0 - 100.0 - 1000.0, 1e-6);
    CHECK_NEAR(t, 100.0, 1e-9);
    /* parallel, same speed, 50 m apart: no relative motion, 30 m for ever */
    b = track(50, 0, 0, 5, 100, 20);
    CHECK_NEAR(fw_hull_cpa(&a, &b, INFINITY, &t), 30.0, 1e-9);
    CHECK(t == 0.0);
    /* parallel, overtaking at 2 m/s more, 25 m apart: sides 5 m apart while alongside */
    b = track(25, -500, 0, 7, 100, 20);
    CHECK_NEAR(fw_hull_cpa(&a, &b, INFINITY, NULL), 5.0, 1e-6);
    /* crossing at right angles, both at the origin at 200 s: a hit */
    a = track(0, -1000, 0, 5, 100, 20);
    b = track(1000, 0, 270, 5, 80, 15);
    CHECK(fw_hull_cpa(&a, &b, INFINITY, NULL) == 0.0);
    /* the crossing ship 150 m later: it passes astern, against brute force */
    b = track(1150, 0, 270, 5, 80, 15);
    double m = fw_hull_cpa(&a, &b, INFINITY, &t);
    CHECK(m > 0.0);
    CHECK_NEAR(m, sampled_min(&a, &b, 400.0, 0.001), 1e-3);
    /* rotated hulls on an oblique crossing, against brute force */
    a = track(-300, -900, 35, 6, 250, 40);
    b = track(900, -100, 290, 4, 180, 30);
    m = fw_hull_cpa(&a, &b, INFINITY, &t);
    CHECK_NEAR(m, sampled_min(&a, &b, 600.0, 0.001), 1e-3);
    /* already past and opening: the distance now */
    a = track(0, 0, 0, 5, 100, 20);
    b = track(0, -500, 180, 5, 100, 20);
    CHECK_NEAR(fw_hull_cpa(&a, &b, INFINITY, &t), 400.0, 1e-9);
    CHECK(t == 0.0);
}

/* The angle wraps: in range, and the same bits as the plain fmod formulas
 * they skip fmod in (units.h), at the edges and over many turns. */
static double wrap_pi_ref(double a)
{
    a = fmod(a + FW_PI, 2.0 * FW_PI);
    if (a <= 0.0)
        a += 2.0 * FW_PI;
    return a - FW_PI;
}

static double wrap_2pi_ref(double a)
{
    a = fmod(a, 2.0 * FW_PI);
    if (a < 0.0)
        a += 2.0 * FW_PI;
    return a;
}

static bool same_bits(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

static void test_wraps(void)
{
    const double tp = 2.0 * FW_PI;
    const double edge[] = {0.0, -0.0, FW_PI, -FW_PI, tp, -tp, nextafter(tp, 0.0),
                           nextafter(-tp, 0.0), nextafter(tp, 10.0), nextafter(-tp, -10.0),
                           nextafter(FW_PI, 0.0), nextafter(-FW_PI, 0.0), nextafter(FW_PI, 10.0),
                           nextafter(-FW_PI, -10.0), 3.0 * FW_PI, -3.0 * FW_PI, DBL_MIN, -DBL_MIN,
                           1e300, -1e300, INFINITY, -INFINITY, NAN};
    int n = (int)(sizeof edge / sizeof *edge), bad = 0;
    for (int i = 0; i < n; i++)
        bad += !same_bits(fw_wrap_pi(edge[i]), wrap_pi_ref(edge[i])) +
               !same_bits(fw_wrap_2pi(edge[i]), wrap_2pi_ref(edge[i]));
    uint64_t x = 88172645463325252u; /* xorshift64: fixed angles over +-20 turns */
    for (int i = 0; i < 200000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        double a = ((double)(x >> 11) / 9007199254740992.0 - 0.5) * 80.0 * FW_PI;
        double p = fw_wrap_pi(a), q = fw_wrap_2pi(a);
        bad += !same_bits(p, wrap_pi_ref(a)) + !same_bits(q, wrap_2pi_ref(a));
        bad += !(p > -FW_PI && p <= FW_PI) + !(q >= 0.0 && q < tp);
    }
    CHECK(bad == 0);
    CHECK(fw_wrap_pi(-FW_PI) == FW_PI); /* (-pi, pi]: -pi is pi */
    CHECK_NEAR(fw_wrap_2pi(-0.5), tp - 0.5, 1e-15);
}

/* The predictor: a ship turning at 0.5 deg/s towards 030 from 000 at 5 m/s
 * is expected to head 030 after 60 s and then run straight: its heading
 * exactly so, its position the arc's (radius U / r) then the straight line,
 * to 0.5 m (the midpoint rule on 1 s steps). */
static void test_predictor_finishes_the_turn(void)
{
    fw_turn_pred p;
    fw_turn_pred_init(&p);
    p.turning = true, p.rate = fw_deg_to_rad(0.5), p.heading = fw_deg_to_rad(30.0);
    fw_target now = {.speed = 5.0, .stw = 5.0, .pred = &p.base};
    double e[121], n[121], h[121];
    fw_target_path(&now, 1.0, 121, e, n, h);
    CHECK_NEAR(h[30], fw_deg_to_rad(15.0), 1e-12);
    CHECK_NEAR(h[60], fw_deg_to_rad(30.0), 1e-12);
    CHECK_NEAR(h[120], fw_deg_to_rad(30.0), 1e-12);
    double R = 5.0 / fw_deg_to_rad(0.5), a = fw_deg_to_rad(30.0);
    double e60 = R * (1.0 - cos(a)), n60 = R * sin(a);
    CHECK_NEAR(e[60], e60, 0.5);
    CHECK_NEAR(n[60], n60, 0.5);
    CHECK_NEAR(e[120], e60 + 300.0 * sin(a), 0.5);
    CHECK_NEAR(n[120], n60 + 300.0 * cos(a), 0.5);
    CHECK(fw_turn_pred_of(&p.base) == &p && !p.base.steady(&p.base));
    CHECK(fw_turn_pred_of(NULL) == NULL);
    p.turning = false; /* steady: constant velocity */
    CHECK(p.base.steady(&p.base));
    fw_target_path(&now, 1.0, 121, e, n, h);
    CHECK_NEAR(n[120], 600.0, 1e-9);
    CHECK_NEAR(e[120], 0.0, 1e-9);
}

int main(void)
{
    TEST_RUN(test_body_frame_and_cpa);
    TEST_RUN(test_wraps);
    TEST_RUN(test_hull_distance);
    TEST_RUN(test_hull_cpa);
    TEST_RUN(test_domain);
    TEST_RUN(test_domain_transverse);
    TEST_RUN(test_predictor_finishes_the_turn);
    return TEST_EXIT();
}
