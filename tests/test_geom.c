/* test_geom.c - the plane geometry of ships (geom/geom.h) against worked answers. */
#include "core/units.h"
#include "geom/geom.h"
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
    fw_target t = {.east = 0, .north = 600, .course = 0, .length = 0, .breadth = 0};
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

int main(void)
{
    TEST_RUN(test_body_frame_and_cpa);
    TEST_RUN(test_hull_distance);
    TEST_RUN(test_domain);
    return TEST_EXIT();
}
