/* test_react_judge.c - a give-way background ship judges every ship it must
 * give way to, not only the closest pass (world/reactions.h, the speed that
 * passes farthest when none keeps the passing distance); and a speed faster
 * than it goes along its acceleration (test_stand_on_judged_along_its_
 * acceleration, below).
 *
 * g (the kinematic source's, 090 at 16 kn from the origin) overtakes the own
 * ship (fairway's, Nomoto c3-paper holding 090 at 6 kn, 1500 m ahead and
 * `own_off` m to g's port side): by rule 13 it must keep out of the way.
 * y (the source's, 270 at 12 kn from 4000 m east) meets g nearly head-on,
 * passing 30 m to its port side whatever speed g takes (the relative
 * motion stays along one line): no speed keeps 0.5 nm from every ship.
 *
 *   without y, g slows at its first look to the fastest speed that keeps
 *     0.5 nm from the own ship (8.8 kn: the plain case)
 *   with y, the own ship passing 120 m off at g's speed, g slows to that
 *     same speed (y's 30 m is the same at every speed; the next closest
 *     pass, the own ship's, decides); compared by the closest pass alone
 *     it found no speed better than its 16 kn and ran on to pass the own
 *     ship at 120 m
 */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "test.h"
#include "test_ship.h"
#include "traffic/source.h"
#include "world/world.h"

static fw_ship c3p;

/* The world of the source's ships ks (n of them) and the own ship (c3-paper,
 * Nomoto, no controller) from (e, no) on course at speed, stepped steps s
 * with the reactions' give-way kind gw; g's first slow-down (false: none). */
static bool g_slows(const fw_kin_ship *ks, int n, fw_give_way gw, double e, double no,
                    double course, double speed, int steps, fw_reaction *out)
{
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ks;
    kd.n = n;
    fw_world_def wd = fw_default_world_def();
    wd.reactions = fw_default_reactions_def();
    wd.reactions.give_way = gw;
    fw_world *w = NULL;
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK);
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    fw_vessel_def own = fw_default_vessel_def();
    own.id = "own", own.role = FW_ROLE_OWN, own.ship = &c3p, own.dynamics = FW_DYN_NOMOTO;
    own.east = e, own.north = no, own.course = course, own.speed = speed;
    CHECK(fw_world_add_vessel(w, &own, NULL, &err) == FW_OK);
    CHECK(fw_world_start(w, &err) == FW_OK);
    for (int k = 0; k < steps; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    int nr;
    const fw_reaction *r = fw_world_reactions(w, &nr);
    bool found = false;
    for (int i = 0; i < nr && !found; i++)
        if (strcmp(r[i].ship, "g") == 0 && r[i].kind == FW_REACT_SLOW)
            *out = r[i], found = true;
    fw_world_destroy(w);
    return found;
}

/* g's first order in 30 s (false: none). */
static bool first_order(bool with_y, fw_reaction *out)
{
    fw_kin_ship ks[2] = {
        {.start = {.id = "g", .east = 0, .north = 0, .course = 0.5 * FW_PI,
                   .speed = fw_kn_to_ms(16), .length = 150, .breadth = 25}},
        {.start = {.id = "y", .east = 4000, .north = 30, .course = 1.5 * FW_PI,
                   .speed = fw_kn_to_ms(12), .length = 150, .breadth = 25}}};
    /* the speed orders this test reads */
    return g_slows(ks, with_y ? 2 : 1, FW_GIVE_WAY_SPEED, 1500, 120, 0.5 * FW_PI,
                   fw_kn_to_ms(6), 30, out);
}

static void test_masked_by_a_close_pass(void)
{
    fw_reaction a = {0}, b = {0};
    CHECK(first_order(true, &a));
    CHECK(first_order(false, &b));
    printf("  with y: g slows from %.1f to %.1f kn for %s at %.0f s (enough: %d); without y: "
           "to %.1f kn for %s (enough: %d)\n",
           fw_ms_to_kn(a.speed_from), fw_ms_to_kn(a.speed_to), a.other, a.t, a.enough,
           fw_ms_to_kn(b.speed_to), b.other, b.enough);
    CHECK(strcmp(a.other, "own") == 0 && !a.enough);
    CHECK(strcmp(b.other, "own") == 0 && b.enough);
    CHECK(b.speed_to < fw_kn_to_ms(16) * 0.96);
    CHECK_NEAR(fw_ms_to_kn(a.speed_to), fw_ms_to_kn(b.speed_to), 1e-9);
}

/* g (the source's, 090 from the origin, meaning to go 7 m/s) and the own
 * ship (straight on 180 at 7 m/s from (800, 1600), crossing from g's port
 * side: g stands on, rule 17) in the first minute; g crawls at 1 m/s from
 * 1 s (crawling) or goes its 7 m/s.  g's rule 17(b) order (false: none). */
static bool stand_on_order(bool crawling, fw_reaction *out)
{
    fw_kin_ship ks[1] = {{.start = {.id = "g", .east = 0, .north = 0, .course = 0.5 * FW_PI,
                                    .speed = 7.0, .length = 150, .breadth = 25},
                          .n_legs = crawling ? 1 : 0,
                          .legs = {{.t_start = 1.0, .course = 0.5 * FW_PI, .speed = 1.0}}}};
    return g_slows(ks, 1, fw_default_reactions_def().give_way, 800, 1600, FW_PI, 7.0, 60, out);
}

/* A ship judges a speed faster than it goes along its acceleration
 * (0.05 m/s^2, reactions_judge.c): going its 7 m/s, g passes ahead of the
 * own ship 530 m off and does nothing (rule 17(a)); crawling at 1 m/s (at
 * its look at 10 s) it would take two minutes to get back to 7 m/s and pass
 * 273 m ahead, 191 s on: it acts (rule 17(b)), and the speed it takes
 * passes farther.  Judged at 7 m/s from the start, as before, it passed
 * 528 m off and did nothing until its look at 30 s (443 m). */
static void test_stand_on_judged_along_its_acceleration(void)
{
    fw_reaction a = {0}, b = {0};
    CHECK(!stand_on_order(false, &b));
    CHECK(stand_on_order(true, &a));
    printf("  crawling: g slows from %.1f to %.1f m/s at %.0f s for %s, CPA %.0f -> %.0f m (%s)\n",
           a.speed_from, a.speed_to, a.t, a.other, a.dcpa_before, a.dcpa_after,
           fw_speed_why_name(a.why));
    CHECK(strcmp(a.other, "own") == 0 && a.why == FW_WHY_RULE17);
    CHECK_NEAR(a.t, 10.0, 1e-9);
    CHECK_NEAR(a.dcpa_before, 273.0, 10.0);
    CHECK(a.dcpa_after > a.dcpa_before + 100.0);
    CHECK(a.speed_to < 7.0 * 0.5);
}

int main(void)
{
    c3p = test_load_ship("c3-paper");
    TEST_RUN(test_masked_by_a_close_pass);
    TEST_RUN(test_stand_on_judged_along_its_acceleration);
    return TEST_EXIT();
}
