/* test_hull_track.c - a hull placed on its bow's track (traffic/hull_track.h):
 * on a straight track the hull is the bow's line (SUMO's own geometry); round
 * a 30 deg corner its heading turns by 30 deg, steadily, over the hull
 * length the bow sails past the corner, and its centre moves sideways only
 * as a turning hull's does; the track stays short. */
#include <math.h>

#include "core/units.h"
#include "test.h"
#include "traffic/hull_track.h"

static void test_straight(void)
{
    fw_hull_track tr = {0};
    double h = fw_deg_to_rad(250.0), L = 300.0;
    CHECK(fw_hull_track_start(&tr, 1000.0, 2000.0, h, L));
    for (int k = 1; k <= 400; k++)
        CHECK(fw_hull_track_push(&tr, 1000.0 + 6.0 * k * sin(h), 2000.0 + 6.0 * k * cos(h), L));
    double cx, cy, hh;
    fw_hull_track_hull(&tr, L, &cx, &cy, &hh);
    double bx = 1000.0 + 2400.0 * sin(h), by = 2000.0 + 2400.0 * cos(h);
    CHECK_NEAR(cx, bx - 150.0 * sin(h), 1e-9);
    CHECK_NEAR(cy, by - 150.0 * cos(h), 1e-9);
    CHECK_NEAR(hh, h, 1e-12);
    /* only what the hull needs is kept: one length of points 6 m apart */
    CHECK(tr.n <= 300.0 / 6.0 + 3);
    fw_hull_track_free(&tr);
}

/* The bow sails east 3 km, then 3 km towards 060 (30 deg to port), at 6 m/s
 * in 1 s steps, as SUMO's bumper would on a bent lane's line. */
static void test_corner(void)
{
    fw_hull_track tr = {0};
    double L = 300.0, v = 6.0, h0 = M_PI / 2.0, h1 = M_PI / 3.0;
    CHECK(fw_hull_track_start(&tr, 0.0, 0.0, h0, L));
    double px = NAN, py = NAN, ph = h0, max_lat = 0.0, max_rate = 0.0, turn_from = NAN,
           turn_to = NAN;
    for (int k = 1; k <= 1000; k++) {
        double s = v * k, bx, by;
        if (s <= 3000.0)
            bx = s, by = 0.0;
        else
            bx = 3000.0 + (s - 3000.0) * sin(h1), by = (s - 3000.0) * cos(h1);
        CHECK(fw_hull_track_push(&tr, bx, by, L));
        double cx, cy, h;
        fw_hull_track_hull(&tr, L, &cx, &cy, &h);
        if (!isnan(px)) {
            double dx = cx - px, dy = cy - py;
            max_lat = fmax(max_lat, fabs(dx * cos(h) - dy * sin(h)));
            double rate = fabs(remainder(h - ph, 2.0 * M_PI));
            max_rate = fmax(max_rate, rate);
            if (rate > 1e-9 && isnan(turn_from))
                turn_from = s;
            if (rate > 1e-9)
                turn_to = s;
            CHECK(h <= ph + 1e-12); /* to port, steadily: never back */
        }
        px = cx, py = cy, ph = h;
    }
    /* the heading turned 30 deg, while the bow sailed the hull length past
     * the corner, at about 30 deg / (L / v) = 0.6 deg/s */
    CHECK_NEAR(ph, h1, 1e-9);
    CHECK_NEAR(turn_from, 3000.0 + v, v);
    CHECK_NEAR(turn_to, 3000.0 + L, v);
    CHECK(fw_rad_to_deg(max_rate) < 1.2 * 30.0 * v / L);
    /* the centre moves sideways only as a turning hull's does: the chord
     * sweeping about the bow, at most the turn rate times half the length
     * (a drift angle of about 14 deg at r' = r L / v = 0.53, as a ship's in
     * a turn that tight), where SUMO's geometry threw it 75 m in one step */
    CHECK(max_lat <= 1.02 * max_rate * 0.5 * L);
    CHECK(max_lat < 2.0); /* the traffic monitors' sideways threshold (survey/monitor.h) */
    printf("corner: turned 30 deg from %.0f m to %.0f m along, at most %.2f deg/s, "
           "at most %.2f m/s sideways\n", turn_from - 3000.0, turn_to - 3000.0,
           fw_rad_to_deg(max_rate), max_lat);
    fw_hull_track_free(&tr);
}

/* A slow ship: its bow 0.7 m a step (1.4 kn), less than the points' spacing.
 * Its hull moves with its bow every step, 0.7 m, never 0 then 1.4 m (on
 * main before: the hull stood still every other step at 1.5 m a step, and
 * the records showed a ship stopping and jumping). */
static void test_slow_ship_moves_every_step(void)
{
    fw_hull_track tr = {0};
    double L = 90.0, cx, cy, hh, prev_y;
    CHECK(fw_hull_track_start(&tr, 0.0, 0.0, 0.0, L));
    fw_hull_track_hull(&tr, L, &cx, &prev_y, &hh);
    for (int k = 1; k <= 600; k++) {
        CHECK(fw_hull_track_push(&tr, 0.0, 0.7 * k, L));
        fw_hull_track_hull(&tr, L, &cx, &cy, &hh);
        CHECK_NEAR(cy - prev_y, 0.7, 1e-9);
        CHECK_NEAR(cx, 0.0, 1e-12);
        prev_y = cy;
    }
    CHECK(tr.n <= 90.0 / 2.0 + 4);
    fw_hull_track_free(&tr);
}

int main(void)
{
    TEST_RUN(test_straight);
    TEST_RUN(test_corner);
    TEST_RUN(test_slow_ship_moves_every_step);
    return TEST_EXIT();
}
