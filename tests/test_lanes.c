/* Ships meeting along one waterway (traffic/lane.h, avoid/encounter.h
 * fw_classify_lanes): on a two-way channel with a 30 deg bend (networks/bend's
 * geometry: 10 km east, then towards 060; two 250 m lanes each way, to
 * starboard of the centre line), an east-going ship before the bend and a
 * west-going one past it are head-on, though their headings are 150 deg
 * apart and fw_classify alone calls them crossing; two ships of one stream
 * either side of the bend are overtaking, not crossing; a ship crossing the
 * channel, and ships in open water (no lane edges), are classed by their
 * bearings and headings as before.  The own ship, which has no lane, is
 * judged by its route's line (route.h fw_route_lane). */
#include <math.h>

#include "avoid/encounter.h"
#include "avoid/route.h"
#include "core/units.h"
#include "test.h"
#include "traffic/lane.h"

/* The channel's centre line W-B-E offset by d to starboard (d < 0: to port)
 * of the direction of travel, the corner mitred; westward: E-B-W. */
static fw_lane_info lane(double d, bool westward)
{
    double e[3] = {0.0, 10000.0, 10000.0 + 10000.0 * cos(fw_deg_to_rad(30.0))};
    double n[3] = {0.0, 0.0, 5000.0};
    /* the edge runs from the centre line to 500 m to starboard */
    fw_lane_info L = {.np = 3, .room_starboard = 500.0 - d, .room_port = d};
    for (int k = 0; k < 3; k++) {
        int i = westward ? 2 - k : k;
        /* the normal to starboard of each leg (courses 090 and 060, or 240 and 270) */
        double c0 = westward ? fw_deg_to_rad(240.0) : fw_deg_to_rad(90.0);
        double c1 = westward ? fw_deg_to_rad(270.0) : fw_deg_to_rad(60.0);
        double c = k == 0 ? c0 : k == 2 ? c1 : 0.5 * (c0 + c1);
        double m = k == 1 ? d / cos(0.5 * (c1 - c0)) : d;
        L.e[k] = e[i] + m * cos(c), L.n[k] = n[i] - m * sin(c);
    }
    return L;
}

static fw_target ship(double e, double n, double heading_deg, double speed_kn)
{
    double h = fw_deg_to_rad(heading_deg);
    return (fw_target){.east = e, .north = n, .course = h, .heading = h,
                       .speed = fw_kn_to_ms(speed_kn), .stw = fw_kn_to_ms(speed_kn),
                       .length = 200, .breadth = 30, .key = 1};
}

static fw_situation classify(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                             const fw_lane_info *lb)
{
    fw_colregs_def def = fw_default_colregs_def();
    fw_own_state me = {.east = a->east, .north = a->north, .psi = a->heading, .U = a->speed};
    return fw_classify_lanes(&def, &me, a, la, b, lb);
}

static void test_meeting_round_the_bend(void)
{
    fw_lane_info le = lane(125.0, false), lw = lane(125.0, true);
    /* east-going 1500 m before the bend, its lane 125 m south of the line */
    fw_target a = ship(8500.0, -125.0, 90.0, 12.0);
    /* west-going 1000 m past the bend on the 060 leg, 125 m to its starboard */
    double s = 1000.0, c = fw_deg_to_rad(60.0);
    fw_target b = ship(10000.0 + s * sin(c) - 125.0 * cos(c), s * cos(c) + 125.0 * sin(c), 240.0,
                       14.0);
    fw_colregs_def def = fw_default_colregs_def();
    fw_own_state me = {.east = a.east, .north = a.north, .psi = a.heading, .U = a.speed};
    CHECK(fw_classify(&def, &me, &b) != FW_SIT_HEAD_ON); /* the bearings alone: crossing */
    CHECK(fw_lanes_meet(&a, &le, &b, &lw));
    CHECK(fw_lanes_meet(&b, &lw, &a, &le)); /* symmetric */
    CHECK(classify(&a, &le, &b, &lw) == FW_SIT_HEAD_ON);
    CHECK(classify(&b, &lw, &a, &le) == FW_SIT_HEAD_ON);
    /* on a straight stretch as before */
    fw_target b2 = ship(9200.0, 125.0, 270.0, 14.0);
    CHECK(classify(&a, &le, &b2, &lw) == FW_SIT_HEAD_ON);
    /* passed each other: b astern of a by more than the channel's width */
    fw_target b4 = ship(a.east - 2000.0, 125.0, 270.0, 14.0);
    CHECK(!fw_lanes_meet(&a, &le, &b4, &lw));
    /* no lane known: the bearings alone */
    CHECK(classify(&a, &le, &b, NULL) == fw_classify(&def, &me, &b));
    /* open water (no edges): never meeting by lanes */
    fw_lane_info oe = le, ow = lw;
    oe.room_port = ow.room_port = INFINITY;
    CHECK(!fw_lanes_meet(&a, &oe, &b, &ow));
}

static void test_one_stream_round_the_bend(void)
{
    fw_lane_info le = lane(125.0, false);
    fw_target a = ship(9500.0, -125.0, 90.0, 14.0);
    double s = 700.0, c = fw_deg_to_rad(60.0);
    fw_target d = ship(10000.0 + s * sin(c) + 125.0 * cos(c), s * cos(c) - 125.0 * sin(c), 60.0,
                       10.0);
    fw_lane_info ld = le; /* d's lane line runs on from the bend (its own from B) */
    ld.np = 2;
    ld.e[0] = le.e[1], ld.n[0] = le.n[1], ld.e[1] = le.e[2], ld.n[1] = le.n[2];
    CHECK(fw_lanes_along(&a, &le, &d, &ld));
    CHECK(fw_lanes_along(&d, &ld, &a, &le));
    CHECK(!fw_lanes_meet(&a, &le, &d, &ld));
    fw_situation s1 = classify(&a, &le, &d, &ld), s2 = classify(&d, &ld, &a, &le);
    CHECK(s1 == FW_SIT_OVERTAKING);
    CHECK(s2 == FW_SIT_OVERTAKEN);
}

static void test_crossing_ship_is_crossing(void)
{
    fw_lane_info le = lane(125.0, false);
    fw_target a = ship(8500.0, -125.0, 90.0, 12.0);
    /* a ship crossing the channel northwards 1 km ahead, on a lane of its own */
    fw_target x = ship(9500.0, -1000.0, 0.0, 12.0);
    fw_lane_info lx = {.np = 2, .e = {9500.0, 9500.0}, .n = {-5000.0, 5000.0},
                       .room_starboard = 250.0, .room_port = 250.0};
    CHECK(!fw_lanes_meet(&a, &le, &x, &lx));
    CHECK(!fw_lanes_along(&a, &le, &x, &lx));
    fw_colregs_def def = fw_default_colregs_def();
    fw_own_state me = {.east = a.east, .north = a.north, .psi = a.heading, .U = a.speed};
    CHECK(classify(&a, &le, &x, &lx) == fw_classify(&def, &me, &x));
    CHECK(classify(&a, &le, &x, &lx) == FW_SIT_GIVE_WAY); /* from a's starboard side */
}

/* The own ship has no lane of its own: its route is its line (route.h
 * fw_route_lane, no room: the width is the other ship's waterway's), and
 * fw_assess_lanes judges the targets whose lanes are known by it. */
static void test_own_ship_by_its_route(void)
{
    /* the route along the east-going lanes' middle round the bend */
    fw_lane_info le = lane(125.0, false), lw = lane(125.0, true);
    double we[3], wn[3], sp[3] = {6.0, 6.0, 6.0};
    for (int k = 0; k < 3; k++)
        we[k] = le.e[k], wn[k] = le.n[k];
    fw_route r;
    fw_error err = {0};
    CHECK(fw_route_from_waypoints(we, wn, sp, 3, &r, &err) == FW_OK);
    fw_lane_info own_lane;
    fw_route_lane(&r, &own_lane);
    CHECK(own_lane.np == 3 && own_lane.room_port == 0.0 && own_lane.room_starboard == 0.0);
    CHECK(fabs(own_lane.e[2] - le.e[2]) < 1e-6 && fabs(own_lane.n[2] - le.n[2]) < 1e-6);
    fw_own_state me = {.east = 8500.0, .north = -125.0, .psi = fw_deg_to_rad(90.0),
                       .U = fw_kn_to_ms(12.0)};
    double s = 1000.0, c = fw_deg_to_rad(60.0);
    fw_target t[3] = {
        /* coming round the bend the other way: head-on though 150 deg apart */
        ship(10000.0 + s * sin(c) - 125.0 * cos(c), s * cos(c) + 125.0 * sin(c), 240.0, 14.0),
        /* the same ship with no lane known: judged by bearings */
        ship(10000.0 + s * sin(c) - 125.0 * cos(c), s * cos(c) + 125.0 * sin(c), 240.0, 14.0),
        /* crossing the channel from the south, on the own starboard bow */
        ship(9500.0, -1500.0, 0.0, 12.0)};
    const fw_lane_info *lanes[3] = {&lw, NULL, NULL};
    fw_lane_info lx = {.np = 2, .e = {9500.0, 9500.0}, .n = {-5000.0, 5000.0},
                       .room_starboard = 250.0, .room_port = 250.0};
    lanes[2] = &lx;
    fw_colregs_def def = fw_default_colregs_def();
    fw_assessment as[3];
    int order[6];
    fw_domain_def dom = fw_default_domain_def();
    fw_assess(&def, &dom, 600.0, &me, t, 3, as, order);
    CHECK(as[0].situation != FW_SIT_HEAD_ON && as[1].situation == as[0].situation);
    fw_situation crossing = as[2].situation;
    fw_assess_lanes(&def, &me, &own_lane, t, lanes, 3, as);
    CHECK(as[0].situation == FW_SIT_HEAD_ON);
    CHECK(as[1].situation != FW_SIT_HEAD_ON); /* no lane: as fw_assess said */
    CHECK(as[2].situation == crossing && crossing == FW_SIT_GIVE_WAY);
    /* the own ship 150 m off its route towards the other lanes, still to
     * port of the other's lane: still meeting; 300 m off, beyond it, they
     * would pass starboard to starboard: not meeting ships by lanes */
    me.north += 150.0;
    fw_assess(&def, &dom, 600.0, &me, t, 1, as, order);
    fw_assess_lanes(&def, &me, &own_lane, t, lanes, 1, as);
    CHECK(as[0].situation == FW_SIT_HEAD_ON);
    me.north += 150.0;
    fw_assess(&def, &dom, 600.0, &me, t, 1, as, order);
    fw_situation by_bearings = as[0].situation;
    fw_assess_lanes(&def, &me, &own_lane, t, lanes, 1, as);
    CHECK(as[0].situation == by_bearings);
}

int main(void)
{
    TEST_RUN(test_own_ship_by_its_route);
    TEST_RUN(test_meeting_round_the_bend);
    TEST_RUN(test_one_stream_round_the_bend);
    TEST_RUN(test_crossing_ship_is_crossing);
    return TEST_EXIT();
}
