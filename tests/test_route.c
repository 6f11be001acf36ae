/* test_route.c - the own ship follows a route (issue 27 item 5): waypoints
 * with a speed per leg (scenario/scn_route.h), line-of-sight guidance to the
 * active leg, the wheel-over point predicted for the ship (avoid/wheel_over.h),
 * the return after avoiding to the route; bad routes refused at load.
 * Runs with the kinematic source (no SUMO), asserting on the track the own
 * ship sailed, step by step.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "avoid/route.h"
#include "core/files.h"
#include "core/units.h"
#include "run/run.h"
#include "world/world.h"
#include "test.h"

static fw_scenario s; /* large: a ship inside */

/* What the own ship sailed: the largest distance from the route's line, the
 * last state, the leg it ended on, the actions it took. */
typedef struct sailed {
    double max_off, max_off_t, last_psi, last_U, last_off;
    double max_turn;   /* rad, the most the heading turned from the start's, counted through */
    double min_dist;   /* m */
    double min_hull;   /* m, hull to hull (INFINITY: none within 1 nm) */
    int last_leg, n_actions, n_unkept;
} sailed;

static sailed sail(const char *rel)
{
    char file[512];
    fw_error err = {0};
    sailed out = {0};
    snprintf(file, sizeof file, "%s/%s", fw_data_root(), rel);
    CHECK_MSG(fw_scenario_load(file, &s, &err) == FW_OK, "%s", err.msg);
    fw_run_def def = fw_default_run_def();
    def.scenario = &s;
    def.traffic = FW_RUN_TRAFFIC_KINEMATIC;
    fw_run *r = NULL;
    CHECK_MSG(fw_run_open(&def, &r, &err) == FW_OK, "%s", err.msg);
    double psi_prev = s.course, turned = 0.0;
    while (r && !fw_run_done(r)) {
        CHECK_MSG(fw_run_step(r, &err) == FW_OK, "%s", err.msg);
        fw_world *w = fw_run_world(r);
        fw_vessel *own = fw_world_vessel(w, fw_world_own(w));
        const fw_mmg_state *x = fw_vessel_motion(own);
        const fw_decision *d = fw_vessel_decision(own);
        double off = 0.0;
        if (s.route.n > 0)
            fw_route_progress(&s.route, x->east, x->north, &off, NULL);
        turned += fw_wrap_pi(x->psi - psi_prev);
        psi_prev = x->psi;
        out.max_turn = fmax(out.max_turn, fabs(turned));
        if (off > out.max_off)
            out.max_off = off, out.max_off_t = fw_run_time(r);
        out.last_psi = x->psi, out.last_U = hypot(x->u, x->vm), out.last_off = off;
        out.last_leg = d->leg;
    }
    out.min_hull = r ? fw_run_min_hull(r) : 0.0;
    fw_run_summary sum;
    fw_encounter *enc = NULL;
    int n_enc = 0;
    CHECK_MSG(fw_run_close(r, &sum, &enc, &n_enc, &err) == FW_OK, "%s", err.msg);
    free(enc);
    out.n_actions = sum.n_actions;
    out.n_unkept = sum.n_unkept;
    out.min_dist = sum.min_dist;
    printf("  %s: %.1f m off the route at most (t %.0f s), at the end %.1f m, %03.1f deg, "
           "%.2f kn, leg %d, %d actions; turned %.0f deg at most, %d times the domain could not "
           "be kept, %.0f m the least distance\n",
           rel, out.max_off, out.max_off_t, out.last_off, fw_heading_deg(out.last_psi),
           fw_ms_to_kn(out.last_U), out.last_leg + 1, out.n_actions,
           fw_rad_to_deg(out.max_turn), out.n_unkept, out.min_dist);
    return out;
}

/* A 30 deg bend, nothing in the way: the track within 100 m of the route's
 * line (issue 27's floor), the turn onto the second leg made without
 * overshooting, the second leg's 12 kn ordered. */
static void test_bend(void)
{
    sailed a = sail("tests/data/route/bend.yaml");
    CHECK(a.n_actions == 0);
    CHECK_MSG(a.max_off < 100.0, "%.1f m", a.max_off);
    CHECK(a.last_leg == 1);
    CHECK_NEAR(fw_wrap_pi(a.last_psi - fw_deg_to_rad(60.0)), 0.0, fw_deg_to_rad(1.0));
    CHECK_MSG(a.last_off < 10.0, "%.1f m", a.last_off);
    /* gathering way towards 12 kn from 10 (the propeller's revolutions for 12) */
    CHECK_MSG(a.last_U > fw_kn_to_ms(11.5) && a.last_U < fw_kn_to_ms(12.05), "%.2f kn",
              fw_ms_to_kn(a.last_U));
}

/* Giving way on the first leg: the ship leaves the route, then comes back to
 * it (not to a line through where it acted) and follows it round the bend. */
static void test_avoid_returns(void)
{
    sailed a = sail("tests/data/route/avoid.yaml");
    CHECK(a.n_actions >= 1);
    CHECK_MSG(a.max_off > 300.0, "%.1f m: did it avoid?", a.max_off);
    CHECK(a.last_leg == 1);
    CHECK_MSG(a.last_off < 50.0, "%.1f m from the route at the end", a.last_off);
    CHECK_NEAR(fw_wrap_pi(a.last_psi - fw_deg_to_rad(30.0)), 0.0, fw_deg_to_rad(2.0));
}

/* A 1000 m domain that cannot be kept against a give-way ship that does not
 * act: no round turn (before the band: 369 deg away from the course), the
 * heading within the band (90 deg and the autopilot's overshoot), the
 * domain reported as not kept, the ship slowed, no collision. */
static void test_no_round_turn(void)
{
    sailed a = sail("tests/data/route/standon-loop.yaml");
    CHECK_MSG(a.max_turn < fw_deg_to_rad(100.0), "%.0f deg", fw_rad_to_deg(a.max_turn));
    CHECK(a.n_unkept >= 1);
    CHECK_MSG(a.min_dist > 500.0, "%.0f m", a.min_dist);
}

/* A westbound lane's stream of ships across the route at a 1000 m domain
 * (tests/data/route/lane-stream.yaml): no heading or helm keeps the domain,
 * and in a scheme the ship takes the least bad manoeuvre, not the best
 * available helm: no action (a turn held to the band's edge, before: 90 deg
 * on, head-on along the lane, and a collision, hulls 0 m apart, centres 25 m),
 * the domain reported as not kept, the heading within the band (90 deg and
 * the autopilot's overshoot), the hulls kept 20 m apart at least (after the
 * change 44 m; 20 m: under half of that, so that a change of the
 * prediction's details does not fail it, yet clear of contact). */
static void test_lane_stream(void)
{
    sailed a = sail("tests/data/route/lane-stream.yaml");
    CHECK(a.n_actions == 0);
    CHECK(a.n_unkept >= 1);
    CHECK_MSG(a.max_turn < fw_deg_to_rad(100.0), "%.0f deg", fw_rad_to_deg(a.max_turn));
    CHECK_MSG(a.min_hull > 20.0, "%.0f m hull to hull", a.min_hull);
}

/* A scenario with body as its own_ship: loads (0) or fails with FW_EINPUT and
 * a message holding want. */
static void bad_route(const char *own, const char *want)
{
    char path[] = "/tmp/fw-route-XXXXXX.yaml";
    int fd = mkstemps(path, 5);
    CHECK(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fprintf(f, "name: bad-route\nown_ship:\n  ship: c3-mmg\n%s"
               "traffic:\n  targets:\n    - {id: T1, type: cargo, east_m: 5000, north_m: 5000, "
               "course_deg: 0, speed_kn: 10, length_m: 100, breadth_m: 20}\n"
               "run:\n  duration_s: 10\n  step_s: 1\n  seed: 1\n",
            own);
    fclose(f);
    fw_error err = {0};
    fw_status st = fw_scenario_load(path, &s, &err);
    CHECK_MSG(st == FW_EINPUT, "status %d for %s", (int)st, own);
    char where[600];
    snprintf(where, sizeof where, "%s:%s", path, want);
    CHECK_CONTAINS(err.msg, where);
    unlink(path);
}

static void test_bad_routes(void)
{
    bad_route("  route:\n    - {east_m: 0, north_m: 0, speed_kn: 10}\n",
              "4: own_ship.route: 1 waypoints: a route has 2..9");
    bad_route("  route:\n    - {east_m: 0, north_m: 0, speed_kn: 10}\n"
              "    - {east_m: 0, north_m: 2000, speed_kn: -3}\n    - {east_m: 0, north_m: 4000}\n",
              "6: own_ship.route[1].speed_kn: -3 is out of range");
    bad_route("  route:\n    - {east_m: 0, north_m: 0}\n    - {east_m: 0, north_m: 2000}\n",
              "5: own_ship.route[0].speed_kn");
    bad_route("  course_deg: 0\n  route:\n    - {east_m: 0, north_m: 0, speed_kn: 10}\n"
              "    - {east_m: 0, north_m: 2000}\n",
              "4: own_ship.course_deg: not with a route");
    bad_route("  route:\n    - {east_m: 0, north_m: 0, speed_kn: 10}\n"
              "    - {east_m: 0, north_m: 2000, speed_kn: 10}\n",
              "6: own_ship.route[1].speed_kn: the last waypoint ends the route");
    bad_route("  route:\n    - {east_m: 0, north_m: 0, speed_kn: 10}\n"
              "    - {east_m: 0, north_m: 100}\n",
              "6: own_ship.route[1]: 100 m from the waypoint before");
}

int main(void)
{
    TEST_RUN(test_bad_routes);
    TEST_RUN(test_bend);
    TEST_RUN(test_avoid_returns);
    TEST_RUN(test_no_round_turn);
    TEST_RUN(test_lane_stream);
    return TEST_EXIT();
}
