/* test_vessels.c - vessels that come and go (world.h handles, roles, take and give back).
 *
 *   handles: a vessel added mid-run and one removed mid-run; a stale handle
 *     refused (also once its slot holds another vessel); the other vessels'
 *     tracks bit for bit those of a world that never had the removed one;
 *     the removed vessel in nobody's view after the next step
 *   sensing: a vessel other than the own ship sees the source's ships
 *     within its sight; a world without an own ship works
 *   take and give back (the kinematic source): the ship becomes a vessel at
 *     its exact state, is stepped by fairway (a Nomoto c3-paper), is seen
 *     once (as a vessel, not also as the source's), and is given back onto
 *     its route; the traffic monitors (survey/monitor.h) count no sideways
 *     move, no teleport throughout; a vessel off its route is refused
 *   the recorded-track source refuses take, saying why
 *   sumo (argument "sumo", embedded libsumo): the same take and give back of
 *     a network ship, which then is on a lane of its route, heading within a
 *     few degrees of the lane's, at its speed, and SUMO drives it again
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/units.h"
#include "survey/monitor.h"
#include "test.h"
#include "traffic/source.h"
#include "traffic/source_sumo.h"
#include "traffic/source_track.h"
#include "world/controllers.h"
#include "world/watch.h"
#include "world/world.h"
#include "world_view.h"

static fw_ship c3, c3p;

/* A ship with id in a view? */
static int seen(const fw_vessel *v, const char *id)
{
    const fw_target *tg;
    const fw_assessment *as;
    int n, k = 0;
    fw_vessel_view(v, &tg, &as, &n);
    for (int i = 0; i < n; i++)
        k += strcmp(tg[i].id, id) == 0;
    return k;
}

static fw_vessel_def nomoto_def(const char *id, fw_vessel_role role, double e, double n,
                                double course_deg, double kn)
{
    fw_vessel_def vd = fw_default_vessel_def();
    vd.id = id;
    vd.role = role;
    vd.ship = &c3;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.east = e, vd.north = n, vd.course = fw_deg_to_rad(course_deg), vd.speed = fw_kn_to_ms(kn);
    return vd;
}

/* One source ship far east, going north. */
static fw_status make_source(fw_source **out, fw_error *err)
{
    fw_kin_ship ks = {.start = {.id = "k1", .east = 8000, .north = 0, .course = 0.0,
                                .speed = fw_kn_to_ms(8), .length = 150, .breadth = 25}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = &ks;
    kd.n = 1;
    kd.radius = 6.0 * 1852.0;
    return fw_kinematic_source_create(&kd, out, err);
}

typedef struct tracks {
    double own_e[400], own_n[400], b_e[400], b_n[400];
} tracks;

/* own (policy) and B (policy, added at 60 s) sail north 6 km apart with the
 * source's k1; with_c: C (policy) beside them from the start, removed at
 * 120 s.  The three are far beyond each other's act range: nobody alters. */
static void come_and_go(bool with_c, tracks *tr)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    fw_world *w = NULL;
    CHECK(make_source(&wd.source, &err) == FW_OK);
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    fw_vessel_def own = nomoto_def("own", FW_ROLE_OWN, 0, 0, 0, 10);
    fw_vessel_def b = nomoto_def("B", FW_ROLE_OTHER, 5000, 0, 0, 10);
    fw_vessel_def c = nomoto_def("C", FW_ROLE_OTHER, -5000, 0, 0, 10);
    fw_vessel_handle ho, hb = {0}, hc = {0};
    CHECK(fw_policy_controller_create(&pd, &own.controller, &err) == FW_OK);
    CHECK(fw_world_add_vessel(w, &own, &ho, &err) == FW_OK);
    if (with_c) {
        CHECK(fw_policy_controller_create(&pd, &c.controller, &err) == FW_OK);
        CHECK(fw_world_add_vessel(w, &c, &hc, &err) == FW_OK);
    }
    CHECK(fw_world_start(w, &err) == FW_OK);
    for (int k = 0; k < 400; k++) {
        if (k == 60) {
            CHECK(fw_policy_controller_create(&pd, &b.controller, &err) == FW_OK);
            CHECK_MSG(fw_world_add_vessel(w, &b, &hb, &err) == FW_OK, "%s", err.msg);
            /* B senses at once: the source's k1 (3 km off) and the own ship */
            CHECK(seen(fw_world_vessel(w, hb), "k1") == 1);
            CHECK(seen(fw_world_vessel(w, hb), "own") == 1);
            CHECK(seen(fw_world_vessel(w, ho), "B") == 0); /* the own ship: next step */
        }
        if (k == 61)
            CHECK(seen(fw_world_vessel(w, ho), "B") == 1);
        if (with_c && k == 119)
            CHECK(seen(fw_world_vessel(w, ho), "C") == 1 && seen(fw_world_vessel(w, hb), "C") == 1);
        if (with_c && k == 120) {
            CHECK(fw_world_remove_vessel(w, hc, &err) == FW_OK);
            CHECK(fw_world_remove_vessel(w, hc, &err) == FW_EINPUT); /* stale */
            CHECK(strstr(err.msg, "stale") != NULL);
            CHECK(!fw_world_vessel_valid(w, hc) && fw_world_vessel(w, hc) == NULL);
            /* the freed slot serves a new vessel; the old handle still refused */
            fw_vessel_def d = nomoto_def("D", FW_ROLE_OTHER, -9e5, 0, 0, 1);
            fw_vessel_handle hd;
            CHECK(fw_world_add_vessel(w, &d, &hd, &err) == FW_OK);
            CHECK(hd.index1 == hc.index1 && hd.generation != hc.generation);
            CHECK(fw_world_vessel(w, hc) == NULL && fw_world_vessel(w, hd) != NULL);
            CHECK(fw_world_remove_vessel(w, hc, &err) == FW_EINPUT);
            CHECK(fw_world_remove_vessel(w, hd, &err) == FW_OK);
        }
        if (with_c && k == 121) {
            CHECK(seen(fw_world_vessel(w, ho), "C") == 0 && seen(fw_world_vessel(w, hb), "C") == 0);
            /* walking the vessels: the own ship (slot 1), B (slot 3); C's slot empty */
            CHECK(fw_world_vessel_count(w) == 2);
            fw_vessel_handle h0 = fw_world_vessel_at(w, 0), h1 = fw_world_vessel_at(w, 1);
            CHECK(h0.index1 == ho.index1 && h0.generation == ho.generation);
            CHECK(h1.index1 == hb.index1 && h1.generation == hb.generation);
            CHECK(fw_vessel_handle_null(fw_world_vessel_at(w, 2)));
            CHECK(fw_world_own(w).index1 == ho.index1);
        }
        const fw_target *o = fw_vessel_record(fw_world_vessel(w, ho));
        tr->own_e[k] = o->east, tr->own_n[k] = o->north;
        if (k >= 60) {
            const fw_target *r = fw_vessel_record(fw_world_vessel(w, hb));
            tr->b_e[k] = r->east, tr->b_n[k] = r->north;
        }
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    CHECK(fw_vessel_decision(fw_world_vessel(w, ho))->mode == FW_MODE_STANDBY);
    fw_world_destroy(w);
}

static void test_come_and_go(void)
{
    static tracks with, without;
    come_and_go(true, &with);
    come_and_go(false, &without);
    /* bit for bit: adding, removing and reusing a slot perturbs nobody */
    CHECK(memcmp(with.own_e, without.own_e, sizeof with.own_e) == 0);
    CHECK(memcmp(with.own_n, without.own_n, sizeof with.own_n) == 0);
    CHECK(memcmp(&with.b_e[60], &without.b_e[60], sizeof(double) * 340) == 0);
    CHECK(memcmp(&with.b_n[60], &without.b_n[60], sizeof(double) * 340) == 0);
    CHECK_NEAR(with.own_n[399], 399 * fw_kn_to_ms(10), 1e-6); /* straight on */
}

/* No own ship: two vessels see the source's ship through within(). */
static void test_no_own_ship(void)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    fw_world *w = NULL;
    CHECK(make_source(&wd.source, &err) == FW_OK);
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def a = nomoto_def("A", FW_ROLE_OTHER, 6000, 0, 0, 8);
    fw_vessel_def z = nomoto_def("Z", FW_ROLE_OTHER, -6000, 0, 0, 8);
    a.radius = z.radius = 5000.0;
    fw_vessel_handle ha, hz;
    CHECK(fw_world_add_vessel(w, &a, &ha, &err) == FW_OK);
    CHECK(fw_world_add_vessel(w, &z, &hz, &err) == FW_OK);
    CHECK(fw_vessel_handle_null(fw_world_own(w)));
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    for (int k = 0; k < 10; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    /* A (2 km from k1) sees it, Z (14 km) does not; they are 12 km apart */
    CHECK(seen(fw_world_vessel(w, ha), "k1") == 1 && seen(fw_world_vessel(w, ha), "Z") == 0);
    CHECK(seen(fw_world_vessel(w, hz), "k1") == 0);
    /* an own ship added mid-run sees the source's ships (around()) at once */
    fw_vessel_def own = nomoto_def("own", FW_ROLE_OWN, 8000, -1000, 0, 8);
    fw_vessel_handle ho;
    CHECK(fw_world_add_vessel(w, &own, &ho, &err) == FW_OK);
    CHECK(seen(fw_world_vessel(w, ho), "k1") == 1 && seen(fw_world_vessel(w, ho), "A") == 1);
    CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    CHECK(seen(fw_world_vessel(w, ho), "k1") == 1);
    fw_world_destroy(w);
}

static void test_take_give_back_kinematic(void)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    fw_world *w = NULL;
    CHECK(make_source(&wd.source, &err) == FW_OK);
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def own = nomoto_def("own", FW_ROLE_OWN, 0, 0, 0, 10);
    fw_vessel_handle ho, ht = {0};
    CHECK(fw_world_add_vessel(w, &own, &ho, &err) == FW_OK);
    CHECK(fw_world_start(w, &err) == FW_OK);
    fw_monitor_def md = fw_default_monitor_def();
    fw_monitor *mon = NULL;
    CHECK(fw_monitor_create(&md, NULL, &mon, &err) == FW_OK);
    fw_vessel_def td = fw_default_vessel_def(); /* the ship model for the taken ship */
    td.ship = &c3p;
    td.dynamics = FW_DYN_NOMOTO;
    fw_target last = {0};
    for (int k = 0; k <= 300; k++) {
        monitor_step(mon, w, &err);
        if (k == 30) {
            const fw_target *src;
            int n;
            /* refused (no ship model): undone, still the source's */
            td.ship = NULL;
            CHECK(fw_world_take(w, "k1", &td, &ht, &err) == FW_EINPUT);
            CHECK(fw_vessel_handle_null(ht) && fw_world_vessel_count(w) == 1);
            CHECK(fw_world_take(w, "nobody", &td, &ht, &err) == FW_EINPUT);
            td.ship = &c3p;
            CHECK(fw_source_around(fw_world_source(w), &src, &n, &err) == FW_OK && n == 1);
            fw_target before = src[0];
            CHECK_MSG(fw_world_take(w, "k1", &td, &ht, &err) == FW_OK, "%s", err.msg);
            const fw_target *r = fw_vessel_record(fw_world_vessel(w, ht));
            /* its exact state */
            CHECK(r->east == before.east && r->north == before.north &&
                  r->course == before.course && r->speed == before.speed);
            CHECK(fw_vessel_taken(fw_world_vessel(w, ht)) &&
                  fw_vessel_role_of(fw_world_vessel(w, ht)) == FW_ROLE_OTHER);
            CHECK(fw_world_take(w, "k1", &td, NULL, &err) == FW_EINPUT); /* a vessel already */
            CHECK(fw_world_remove_vessel(w, ht, &err) == FW_EINPUT);     /* give it back */
        }
        if (k > 30 && k < 210) {
            /* seen once, as the vessel: the source lists it no more */
            CHECK(seen(fw_world_vessel(w, ho), "k1") == 1);
            const fw_target *src;
            int n;
            CHECK(fw_source_around(fw_world_source(w), &src, &n, &err) == FW_OK && n == 0);
        }
        if (k == 210) {
            last = *fw_vessel_record(fw_world_vessel(w, ht));
            CHECK_MSG(fw_world_give_back(w, ht, &err) == FW_OK, "%s", err.msg);
            CHECK(fw_world_give_back(w, ht, &err) == FW_EINPUT); /* stale */
        }
        if (k == 211) {
            /* driven by its script again, from where it was, at its speed */
            const fw_target *src;
            int n;
            CHECK(fw_source_around(fw_world_source(w), &src, &n, &err) == FW_OK && n == 1);
            CHECK_NEAR(src[0].north, last.north + fw_kn_to_ms(8), 1e-6);
            CHECK_NEAR(src[0].east, 8000.0, 1e-6);
            CHECK_NEAR(src[0].speed, fw_kn_to_ms(8), 1e-12);
        }
        if (k < 300)
            CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    const fw_monitor_counts *c = fw_monitor_counts_of(mon);
    CHECK_MSG(c->sideways == 0 && c->teleport == 0 && c->vanish == 0 && c->appear == 0,
              "sideways %d teleport %d vanish %d appear %d", c->sideways, c->teleport, c->vanish,
              c->appear);
    CHECK(c->max_lateral < 1e-6);
    fw_monitor_destroy(mon);
    /* a vessel off its route is refused, and stays a vessel */
    fw_manoeuvre_def turn = {.t_act = 0.0, .helm = fw_deg_to_rad(20), .course = 0.0,
                             .alteration = fw_deg_to_rad(30)};
    CHECK(fw_manoeuvre_controller_create(&turn, &td.controller, &err) == FW_OK);
    CHECK(fw_world_take(w, "k1", &td, &ht, &err) == FW_OK);
    for (int k = 0; k < 120; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    CHECK(fw_world_give_back(w, ht, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "off its route") != NULL);
    CHECK(fw_world_vessel_valid(w, ht));
    fw_world_destroy(w);
}

/* The crossing: t (taken by fairway, a Nomoto vessel) sailing north, g
 * (the source's) crossing ahead of it from its port side; the own ship far
 * away; g's watch as given, the world started. */
/* ... g from the side `side` (-1: from the west, t on its starboard side; 1:
 * from the east, t on its port side) in visibility (m, 0: clear). */
static fw_world *crossing_world_in(fw_watch_def watch, uint64_t seed, double side,
                                   double visibility)
{
    fw_error err = {0};
    double v = fw_kn_to_ms(8);
    fw_kin_ship ks[2] = {
        {.start = {.id = "t", .east = 0, .north = 0, .course = 0.0, .speed = v, .length = 150,
                   .breadth = 25}},
        {.start = {.id = "g", .east = 3000 * side, .north = 3000,
                   .course = side < 0 ? 0.5 * FW_PI : 1.5 * FW_PI, .speed = v, .length = 150,
                   .breadth = 25}}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ks;
    kd.n = 2;
    fw_world_def wd = fw_default_world_def();
    wd.reactions = fw_default_reactions_def(); /* colregs */
    /* the watch's timing is read off g's first slow-down order */
    wd.reactions.give_way = FW_GIVE_WAY_SPEED;
    wd.reactions.watch = watch;
    wd.reactions.colregs.visibility = visibility;
    wd.seed = seed;
    fw_world *w = NULL;
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK);
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def own = nomoto_def("own", FW_ROLE_OWN, 0, -30000, 180, 5); /* far away */
    CHECK(fw_world_add_vessel(w, &own, NULL, &err) == FW_OK);
    fw_vessel_def td = fw_default_vessel_def();
    td.ship = &c3p;
    td.dynamics = FW_DYN_NOMOTO;
    CHECK_MSG(fw_world_take(w, "t", &td, NULL, &err) == FW_OK, "%s", err.msg);
    CHECK(fw_world_start(w, &err) == FW_OK);
    return w;
}

static fw_world *crossing_world(fw_watch_def watch, uint64_t seed)
{
    return crossing_world_in(watch, seed, -1.0, 0.0);
}

/* Rule 19 (reactions.h): g crosses from the east, t on its port side: in
 * clear weather g is the stand-on ship and keeps its speed (120 s, far from
 * rule 17(b)'s last moment); with a visibility of 1 km (t 4.2 km off, out
 * of sight, forward of g's beam) g slows at once. */
static void test_traffic_rule19(void)
{
    fw_error err = {0};
    for (int fog = 0; fog < 2; fog++) {
        fw_world *w = crossing_world_in(fw_default_watch_def(), 1, 1.0, fog ? 1000.0 : 0.0);
        for (int k = 0; k < 120; k++)
            CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        int n;
        const fw_reaction *r = fw_world_reactions(w, &n);
        printf("g stand-on by rule 15, %s: %d orders%s\n", fog ? "fog (1 km)" : "clear", n,
               n > 0 && r[0].kind == FW_REACT_SLOW ? ", the first slows" : "");
        if (fog)
            CHECK(n >= 1 && strcmp(r[0].ship, "g") == 0 && r[0].kind == FW_REACT_SLOW &&
                  r[0].t < 10.0);
        else
            CHECK(n == 0);
        fw_world_destroy(w);
    }
}

/* The reactive traffic gives way to a taken ship: g crosses ahead of t,
 * which is on its starboard side (rule 15), on a collision course; t is a
 * vessel from t = 0, so only the world's vessels can show it to g. */
static void test_traffic_reacts_to_taken(void)
{
    fw_error err = {0};
    fw_world *w = crossing_world(fw_default_watch_def(), fw_default_world_def().seed);
    for (int k = 0; k < 30; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    int n;
    const fw_reaction *r = fw_world_reactions(w, &n);
    CHECK_MSG(n >= 1, "%d reactions", n);
    if (n >= 1) {
        CHECK(strcmp(r[0].ship, "g") == 0 && strcmp(r[0].other, "t") == 0);
        CHECK(r[0].kind == FW_REACT_SLOW && r[0].speed_to < fw_kn_to_ms(8));
    }
    fw_world_destroy(w);
}

/* The crossing of test_traffic_reacts_to_taken (g must give way to t, taken
 * by fairway) with g's watch as given: g's first slow-down order's time (NAN:
 * none in 120 s), and the watch's counts. */
static double first_give_way_seed(fw_watch_def watch, uint64_t seed, long *pairs, long *lapsed)
{
    fw_error err = {0};
    fw_world *w = crossing_world(watch, seed);
    for (int k = 0; k < 120; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    int n;
    const fw_reaction *r = fw_world_reactions(w, &n);
    double first = NAN;
    for (int i = 0; i < n && isnan(first); i++)
        if (strcmp(r[i].ship, "g") == 0 && r[i].kind == FW_REACT_SLOW)
            first = r[i].t;
    fw_world_watch_counts(w, pairs, lapsed);
    fw_world_destroy(w);
    return first;
}

static double first_give_way(fw_watch_def watch, long *pairs, long *lapsed)
{
    return first_give_way_seed(watch, fw_default_world_def().seed, pairs, lapsed);
}

/* The watch (world/watch.h): flawless, g gives way at its first look; with a
 * 40 s delay, not before 40 s after it first found t a threat, and at its
 * next look after that; with a lapse probability of 1, never. */
static void test_watch(void)
{
    long pairs, lapsed;
    double flawless = first_give_way(fw_default_watch_def(), &pairs, &lapsed);
    CHECK(!isnan(flawless) && flawless < 10.0);
    CHECK(pairs == 0 && lapsed == 0);
    double late = first_give_way((fw_watch_def){.delay = 40.0}, &pairs, &lapsed);
    printf("watch: flawless gives way at %.0f s, with a 40 s delay at %.0f s\n", flawless, late);
    CHECK(late >= flawless + 40.0 && late <= flawless + 40.0 + 10.0);
    CHECK(pairs == 1 && lapsed == 0);
    double never = first_give_way((fw_watch_def){.lapse = 1.0}, &pairs, &lapsed);
    CHECK(isnan(never));
    CHECK(pairs == 1 && lapsed == 1);
}

/* The rest of the watch: a time to detect drawn per encounter (the same seed,
 * the same time; another seed, another), and a late action at the range it
 * is given: the crossing closes at sqrt(2) x 8 kn from 4243 m, so within
 * 3800 m from 76 s on. */
static void test_watch_detect_late(void)
{
    long pairs, lapsed;
    fw_watch_def d = fw_default_watch_def();
    d.detect = 30.0;
    double a = first_give_way_seed(d, 11, &pairs, &lapsed);
    double b = first_give_way_seed(d, 11, &pairs, &lapsed);
    double flawless = first_give_way(fw_default_watch_def(), &pairs, &lapsed);
    printf("watch: detection (mean 30 s) at seed 11: gives way at %.0f s (flawless %.0f s)\n", a,
           flawless);
    CHECK(!isnan(a) && a == b && a >= flawless);
    bool differs = false;
    for (uint64_t seed = 12; seed < 20 && !differs; seed++)
        differs = first_give_way_seed(d, seed, &pairs, &lapsed) != a;
    CHECK(differs);
    fw_watch_def l = fw_default_watch_def();
    l.late = 1.0;
    l.late_range = 3800.0;
    double late = first_give_way(l, &pairs, &lapsed);
    printf("watch: acting only within 3800 m: gives way at %.0f s\n", late);
    CHECK(late >= 76.0 - 1.0 && late <= 76.0 + 11.0);
    CHECK(pairs == 1 && lapsed == 0);
}

/* The mix (world/watch.h): all passive, g never gives way; all late (3800 m),
 * it gives way at the late range as a late watch does (76 s); with shares
 * 0.2 passive and 0.1 late, over 2000 seeds the crossing's g is drawn
 * passive, late and compliant as often as the shares say (within 4 sd of a
 * binomial count) and acts accordingly; the same seed, the same draw. */
static void test_mix(void)
{
    long pairs, lapsed;
    fw_watch_def p = fw_default_watch_def();
    p.mix_passive = 1.0;
    CHECK(isnan(first_give_way(p, &pairs, &lapsed)));
    fw_watch_def l = fw_default_watch_def();
    l.mix_late = 1.0;
    l.mix_range = 3800.0;
    double late = first_give_way(l, &pairs, &lapsed);
    CHECK(late >= 76.0 - 1.0 && late <= 76.0 + 11.0);
    CHECK(pairs == 0 && lapsed == 0); /* a mix alone draws no encounter */
    fw_watch_def m = fw_default_watch_def();
    m.mix_passive = 0.2, m.mix_late = 0.1, m.mix_range = 1000.0;
    int n = 2000, never = 0, early = 0;
    for (int seed = 1; seed <= n; seed++) {
        double t = first_give_way_seed(m, (uint64_t)seed, &pairs, &lapsed);
        never += isnan(t);
        early += !isnan(t) && t < 10.0;
        if (seed <= 5) { /* the same seed, the same draw */
            double again = first_give_way_seed(m, (uint64_t)seed, &pairs, &lapsed);
            CHECK(isnan(t) ? isnan(again) : t == again);
        }
    }
    /* passive and late both never act in 120 s (late: 1000 m is reached at
     * 4243 - 1000 = 3243 m closed at 5.82 m/s, 557 s); compliant at once */
    double exp_never = 0.3 * n, sd = sqrt(n * 0.3 * 0.7);
    printf("mix 0.2 passive, 0.1 late: %d of %d acted at once, %d not in 120 s (expected %.0f "
           "+- %.0f)\n", early, n, never, exp_never, sd);
    CHECK(fabs(never - exp_never) < 4.0 * sd);
    CHECK(early + never == n);
}

/* A started world of wd (its source set here): the own ship (policy, c3 on
 * Nomoto, the route given or its own line) at the origin heading north at
 * 10 kn, and T1 (kinematic) `north` m ahead heading south at 10 kn. */
static fw_world *head_on_world(double north, fw_world_def *wd, const fw_route *route,
                               fw_vessel_handle *h)
{
    fw_error err = {0};
    fw_kin_ship sh = {.start = {.id = "T1", .east = 0, .north = north, .course = FW_PI,
                                .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = &sh;
    kd.n = 1;
    fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    if (route)
        pd.policy.route = *route;
    fw_world *w = NULL;
    fw_vessel_def vd = nomoto_def("own", FW_ROLE_OWN, 0, 0, 0, 10);
    CHECK(fw_kinematic_source_create(&kd, &wd->source, &err) == FW_OK &&
          fw_world_create(wd, &w, &err) == FW_OK &&
          fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK &&
          fw_world_add_vessel(w, &vd, h, &err) == FW_OK && fw_world_start(w, &err) == FW_OK);
    return w;
}

/* The own ship (policy, c3 on Nomoto) meets T1 head-on 6 km off at 10 kn
 * each, its watch as given, for 700 s: the first time T1 is in its view (the
 * policy's), the time it first turns off its line by 5 m (NAN: never), and
 * the closest approach. */
static void own_head_on(fw_watch_def watch, double *seen, double *turned, double *closest)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.own_watch = watch;
    fw_vessel_handle h;
    fw_world *w = head_on_world(6000.0, &wd, NULL, &h);
    *seen = *turned = NAN;
    *closest = INFINITY;
    for (int k = 0; k < 700; k++) {
        const fw_vessel *o = fw_world_vessel(w, h);
        const fw_target *view, *truth;
        const fw_assessment *as;
        int nv, nt;
        bool sensed;
        fw_vessel_view(o, &view, &as, &nv);
        fw_vessel_truth(o, &truth, &nt, &sensed);
        const fw_target *r = fw_vessel_record(o);
        if (nv > 0 && isnan(*seen))
            *seen = k;
        if (fabs(r->east) > 5.0 && isnan(*turned))
            *turned = k;
        for (int j = 0; j < nt; j++)
            *closest = fmin(*closest, hypot(truth[j].east - r->east, truth[j].north - r->north));
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    fw_world_destroy(w);
}

/* The own ship's watch (world.h own_watch): perfect, it sees T1 at once and
 * turns away (at 376 s: the policy's own timing); a 420 s time to decide
 * hides T1 from its policy for 420 s, past that, and the turn comes once
 * it is seen, closer; a lapse of 1 hides it for good: no action, and T1 runs
 * into it. */
static void test_own_watch(void)
{
    double seen0, turned0, closest0, seen1, turned1, closest1, seen2, turned2, closest2;
    own_head_on(fw_default_watch_def(), &seen0, &turned0, &closest0);
    own_head_on((fw_watch_def){.delay = 420.0}, &seen1, &turned1, &closest1);
    own_head_on((fw_watch_def){.lapse = 1.0}, &seen2, &turned2, &closest2);
    printf("own watch: perfect sees T1 at %.0f s, turns at %.0f s, closest %.0f m; deciding in 420 s: "
           "%.0f s, %.0f s, %.0f m; lapsed: never sees it (%g), turns %g, closest %.0f m\n",
           seen0, turned0, closest0, seen1, turned1, closest1, seen2, turned2, closest2);
    CHECK(seen0 == 0.0 && !isnan(turned0) && closest0 > 300.0);
    CHECK(seen1 == seen0 + 420.0 && turned1 >= 420.0 && turned1 <= 420.0 + (turned0 - seen0));
    CHECK(closest1 < closest0 && closest1 > closest2);
    CHECK(isnan(seen2) && isnan(turned2) && closest2 < 50.0);
}

/* One stream for every ship (the law of the draws, not whose they are). */
static fw_rng *one_stream(void *ctx, uint32_t key, fw_purpose purpose)
{
    (void)key;
    (void)purpose;
    return ctx;
}

/* The time to detect is exponential with the mean given (watch.h): of 4000
 * encounters met at t = 0 with a mean of 100 s, 1 - 1/e are noticed at
 * 100 s and 1 - 1/e^3 at 300 s, each to within 4 standard errors; none at
 * 0 s.  A lapse of 0.25 leaves a quarter never noticed. */
static void test_watch_detect_law(void)
{
    fw_error err = {0};
    fw_rng s = fw_rng_make(7, 0, FW_PURPOSE_WATCH);
    fw_watch_def d = fw_default_watch_def();
    d.detect = 100.0;
    d.lapse = 0.25;
    fw_watch *w = NULL;
    CHECK(fw_watch_create(&d, &w, &err) == FW_OK);
    fw_watch_set_rng(w, one_stream, &s);
    enum { N = 4000 };
    fw_target b = {.id = "other", .east = 1000.0};
    int at0 = 0, at1 = 0, at3 = 0, never = 0;
    for (int i = 0; i < N; i++) {
        fw_target a = {.east = 0.0};
        snprintf(a.id, sizeof a.id, "s%d", i);
        at0 += fw_watch_noticed(w, &a, &b, 0.0);
        at1 += fw_watch_noticed(w, &a, &b, 100.0);
        at3 += fw_watch_noticed(w, &a, &b, 300.0);
        never += !fw_watch_noticed(w, &a, &b, 1e6);
    }
    long pairs, lapsed;
    fw_watch_counts(w, &pairs, &lapsed);
    fw_watch_destroy(w);
    double kept = N - lapsed, p1 = 1.0 - exp(-1.0), p3 = 1.0 - exp(-3.0);
    printf("watch: of %ld encounters %ld lapsed; of the rest %.4f noticed at the mean (%.4f), "
           "%.4f at 3x (%.4f)\n", pairs, lapsed, at1 / kept, p1, at3 / kept, p3);
    CHECK(pairs == N && at0 == 0 && never == lapsed);
    CHECK(fabs(lapsed / (double)N - 0.25) < 4.0 * sqrt(0.25 * 0.75 / N));
    CHECK(fabs(at1 / kept - p1) < 4.0 * sqrt(p1 * (1 - p1) / kept));
    CHECK(fabs(at3 / kept - p3) < 4.0 * sqrt(p3 * (1 - p3) / kept));
}

/* The policy returns to the route it is given, not to the line through its
 * first position: the own ship starts 300 m west of its route's line (north,
 * x = 300), avoids a head-on ship, and ends on the route. */
static void test_returns_to_given_route(void)
{
    double v = fw_kn_to_ms(10), end_e[2] = {NAN, NAN};
    for (int given = 0; given < 2; given++) {
        fw_error err = {0};
        fw_route route;
        double we[3] = {300, 300, 300}, wn[3] = {-1000, 5000, 20000}, sp[2] = {v, v};
        if (given)
            CHECK(fw_route_from_waypoints(we, wn, sp, 3, &route, &err) == FW_OK);
        fw_world_def wd = fw_default_world_def();
        fw_vessel_handle h;
        fw_world *w = head_on_world(3000.0, &wd, given ? &route : NULL, &h);
        for (int k = 0; k < 2400; k++)
            CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        const fw_vessel *o = fw_world_vessel(w, h);
        end_e[given] = o ? fw_vessel_own_state(o)->east : NAN;
        fw_world_destroy(w);
    }
    CHECK_MSG(fabs(end_e[0]) < 50.0, "no route given: %.0f m from the start's line", end_e[0]);
    CHECK_MSG(fabs(end_e[1] - 300.0) < 50.0, "route given: %.0f m east, its line at 300 m",
              end_e[1]);
    /* bad routes */
    fw_route r;
    fw_error err = {0};
    double e[2] = {0, 0}, n[2] = {0, 0}, sp[1] = {1};
    CHECK(fw_route_from_waypoints(e, n, sp, 2, &r, &err) == FW_EINPUT); /* coincide */
    CHECK(fw_route_from_waypoints(e, n, sp, 1, &r, &err) == FW_EINPUT);
}

/* A recorded ship cannot be given back: its recording says where it is at
 * every later time, whatever fairway did with it. */
static void test_track_refuses_take(void)
{
    fw_error err = {0};
    fw_rec_track *t = calloc(1, sizeof *t);
    snprintf(t->info.id, sizeof t->info.id, "r1");
    t->p = malloc(2 * sizeof *t->p);
    t->p[0] = (fw_rec_point){.t = 0, .speed = 5};
    t->p[1] = (fw_rec_point){.t = 100, .north = 500, .speed = 5};
    t->n = t->cap = 2;
    fw_replay_def rd = fw_default_replay_def();
    fw_source *s = NULL;
    CHECK_MSG(fw_track_source_create(t, 1, &rd, "test", &s, &err) == FW_OK, "%s", err.msg);
    fw_target at;
    CHECK(s && fw_source_take(s, "r1", &at, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "recording") != NULL);
    fw_source_destroy(s);
}

/* Lane centre lines of networks/channel (its net.xml): eastbound y -375 and
 * -125, westbound 125 and 375. */
static double lane_off(double north)
{
    static const double lanes[4] = {-375.0, -125.0, 125.0, 375.0};
    double best = INFINITY;
    for (int i = 0; i < 4; i++)
        best = fmin(best, fabs(north - lanes[i]));
    return best;
}

/* Sideways speed (m/s) between two records of one ship a step dt apart:
 * the monitors' measure (survey/monitor.h), across the earlier heading. */
static double lateral(const fw_target *a, const fw_target *b, double dt)
{
    double de = b->east - a->east, dn = b->north - a->north;
    return fabs(de * cos(a->course) - dn * sin(a->course)) / dt;
}

/* A ship of the channel network taken for 3 minutes and given back. */
static void test_take_give_back_sumo(void)
{
    fw_error err = {0};
    char dir[] = "/tmp/fw_test_vessels.XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    fw_sumo_source_def sd = fw_default_sumo_source_def();
    sd.dir = dir;
    sd.network = "channel";
    sd.fill = 20;
    sd.duration = 600.0;
    sd.own = (fw_target){.id = "fw_own", .east = 4000, .north = -1500, .course = 0.5 * FW_PI,
                         .speed = fw_kn_to_ms(10), .length = c3.Loa, .breadth = c3.B};
    sd.clear_range = 10.0; /* keep the fill near the own ship: ships to take */
    sd.clear_cpa = 0.0;
    fw_world_def wd = fw_default_world_def();
    fw_world *w = NULL;
    CHECK_MSG(fw_sumo_source_create(&sd, &wd.source, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(wd.source && fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    if (!w)
        return;
    fw_vessel_def own = nomoto_def("fw_own", FW_ROLE_OWN, 4000, -1500, 90, 10);
    fw_vessel_handle ho, ht = {0};
    CHECK(fw_world_add_vessel(w, &own, &ho, &err) == FW_OK);
    CHECK(fw_world_start(w, &err) == FW_OK);
    fw_monitor_def md = fw_default_monitor_def();
    fw_monitor *mon = NULL;
    CHECK(fw_monitor_create(&md, NULL, &mon, &err) == FW_OK);
    fw_vessel_def td = fw_default_vessel_def();
    td.ship = &c3p;
    td.dynamics = FW_DYN_NOMOTO;
    char id[FW_TARGET_ID_MAX] = "";
    fw_target prev = {0}, at_back = {0};
    double lat_max = 0.0, lane_back = 0.0;
    int seen_steps = 0;
    for (int k = 0; k <= 300; k++) {
        const fw_vessel *o = fw_world_vessel(w, ho);
        monitor_step(mon, w, &err);
        if (k == 30) {
            /* a ship on its lane's line, under way, not changing lanes */
            const fw_target *tg;
            const fw_assessment *as;
            int n;
            fw_vessel_view(o, &tg, &as, &n);
            for (int i = 0; i < n && !id[0]; i++)
                if (lane_off(tg[i].north) < 0.01 && tg[i].speed > 2.0 &&
                    fabs(sin(tg[i].course)) > 0.99999 && fabs(tg[i].east - 4000) < 6000)
                    snprintf(id, sizeof id, "%s", tg[i].id);
            CHECK_MSG(id[0], "no ship to take among %d", n);
            if (!id[0])
                break;
            const fw_target before = *in_view(o, id);
            CHECK_MSG(fw_world_take(w, id, &td, &ht, &err) == FW_OK, "%s", err.msg);
            const fw_target *r = fw_vessel_record(fw_world_vessel(w, ht));
            CHECK(r->east == before.east && r->north == before.north &&
                  r->course == before.course && r->speed == before.speed);
            lane_back = before.north;
        }
        if (id[0] && k > 30) {
            const fw_target *now = in_view(o, id);
            CHECK_MSG(now != NULL, "t %d: '%s' not seen", k, id);
            if (now && prev.id[0]) {
                lat_max = fmax(lat_max, lateral(&prev, now, 1.0));
                seen_steps++;
            }
            if (now)
                prev = *now;
        }
        if (id[0] && k > 30 && k < 210) {
            /* seen once: as the vessel, not also as SUMO's */
            CHECK(seen(o, id) == 1);
            const fw_target *src;
            int n;
            CHECK(fw_source_around(fw_world_source(w), &src, &n, &err) == FW_OK &&
                  fw_target_find(src, n, id) < 0);
        }
        if (id[0] && k == 210) {
            at_back = *fw_vessel_record(fw_world_vessel(w, ht));
            CHECK_MSG(fw_world_give_back(w, ht, &err) == FW_OK, "%s", err.msg);
            CHECK(fw_world_give_back(w, ht, &err) == FW_EINPUT); /* stale */
        }
        if (id[0] && k > 210) {
            /* SUMO's again: on its lane, along it, at its speed, moving on */
            const fw_target *now = in_view(o, id);
            CHECK(now && fabs(now->north - lane_back) < 1.0);
            CHECK(now && fabs(sin(now->course)) > cos(fw_deg_to_rad(3.0)));
            CHECK(now && fabs(now->speed - at_back.speed) < 0.1 * at_back.speed);
            if (now && k == 300)
                CHECK_NEAR(fabs(now->east - at_back.east), 90.0 * at_back.speed,
                           0.05 * 90.0 * at_back.speed);
        }
        if (k < 300)
            CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
    }
    /* no sideways speed above the monitors' bound: at the take, during, at
     * the give back and after; nor any sideways move or jump of any ship */
    CHECK_MSG(lat_max < md.lateral_max, "largest sideways speed %.3f m/s", lat_max);
    CHECK(seen_steps == 269);
    const fw_monitor_counts *c = fw_monitor_counts_of(mon);
    CHECK_MSG(c->sideways == 0 && c->teleport == 0, "sideways %d teleport %d", c->sideways,
              c->teleport);
    printf("took '%s': largest sideways speed %.4f m/s (monitors' bound %.1f)\n", id, lat_max,
           md.lateral_max);
    /* taken again, turned 20 deg off its lane: refused, still a vessel */
    fw_manoeuvre_def turn = {.t_act = 0.0, .helm = fw_deg_to_rad(20), .course = 0.5 * FW_PI,
                             .alteration = fw_deg_to_rad(20)};
    CHECK(fw_manoeuvre_controller_create(&turn, &td.controller, &err) == FW_OK);
    CHECK_MSG(id[0] && fw_world_take(w, id, &td, &ht, &err) == FW_OK, "%s", err.msg);
    for (int k = 0; id[0] && k < 90; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    CHECK(fw_world_give_back(w, ht, &err) == FW_EINPUT);
    CHECK_MSG(strstr(err.msg, "off the nearest lane") != NULL, "%s", err.msg);
    CHECK(fw_world_vessel_valid(w, ht));
    fw_monitor_destroy(mon);
    fw_world_destroy(w);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (test_failures_ == 0 && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
}

int main(int argc, char **argv)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err) || fw_ship_load("c3-paper", &c3p, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    if (argc > 1 && strcmp(argv[1], "sumo") == 0) {
        TEST_RUN(test_take_give_back_sumo);
        return TEST_EXIT();
    }
    TEST_RUN(test_come_and_go);
    TEST_RUN(test_no_own_ship);
    TEST_RUN(test_take_give_back_kinematic);
    TEST_RUN(test_traffic_reacts_to_taken);
    TEST_RUN(test_watch);
    TEST_RUN(test_traffic_rule19);
    TEST_RUN(test_watch_detect_late);
    TEST_RUN(test_mix);
    TEST_RUN(test_watch_detect_law);
    TEST_RUN(test_own_watch);
    TEST_RUN(test_returns_to_given_route);
    TEST_RUN(test_track_refuses_take);
    return TEST_EXIT();
}
