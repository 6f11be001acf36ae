/* test_world.c - the world and its traffic sources.
 *
 *   the kinematic source: positions on scripted legs, sight and area queries,
 *     sorting by id, bad definitions refused
 *   the world's contract: fixed step, vessels before the start, one instant
 *   two vessels under the same policy meeting head-on: both alter to
 *     starboard, and by symmetry their tracks are point mirror images
 *   a paper case stepped with the kinematic source (no SUMO process) takes the
 *     same decisions as its SUMO run: every helm order and mode, every action
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/units.h"
#include "run/run.h"
#include "test.h"
#include "test_tmp.h"
#include "traffic/source.h"
#include "world/controllers.h"
#include "world/world.h"

static char tmp_root[256];
static fw_ship c3;

static void test_kinematic_source(void)
{
    fw_error err = {0};
    fw_kin_ship ships[3] = {
        {.start = {.id = "b", .east = 0, .north = 1000, .course = FW_PI, .heading = FW_PI, .speed = 5.0,
                   .length = 100, .breadth = 20}},
        /* a, east-going, turns north at 100 s and stops at 200 s */
        {.start = {.id = "a", .east = -500, .north = 0, .course = 0.5 * FW_PI, .heading = 0.5 * FW_PI, .speed = 2.0,
                   .length = 50, .breadth = 10},
         .n_legs = 2,
         .legs = {{100.0, 0.0, 3.0}, {200.0, 0.0, 0.0}}},
        {.start = {.id = "c", .east = 9000, .north = 0, .course = 0.0, .heading = 0.0, .speed = 1.0}}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ships;
    kd.n = 3;
    kd.radius = 5000.0;
    kd.area_radius = 2000.0;
    kd.own_id = "me";
    fw_source *src;
    CHECK_MSG(fw_kinematic_source_create(&kd, &src, &err) == FW_OK, "%s", err.msg);
    fw_target own = {.east = 0, .north = 0, .course = 0, .heading = 0, .speed = 4, .length = 200, .breadth = 30};
    const fw_target *v;
    int n;
    CHECK(fw_source_around(src, &v, &n, &err) == FW_ERUN); /* not placed yet */
    CHECK(fw_source_place(src, &own, &err) == FW_OK);
    CHECK(fw_source_around(src, &v, &n, &err) == FW_OK);
    CHECK(n == 2 && strcmp(v[0].id, "a") == 0 && strcmp(v[1].id, "b") == 0); /* c is 9 km off */
    for (int k = 0; k < 250; k++)
        CHECK(fw_source_advance(src, &err) == FW_OK);
    CHECK_NEAR(fw_source_time(src), 250.0, 1e-12);
    CHECK(fw_source_area(src, &v, &n, &err) == FW_OK);
    /* a: 200 m east in 100 s, then 300 m north, then stopped */
    CHECK(n == 3 && strcmp(v[0].id, "a") == 0 && strcmp(v[1].id, "b") == 0 &&
          strcmp(v[2].id, "me") == 0 && v[2].own && !v[0].own);
    CHECK_NEAR(v[0].east, -300.0, 1e-9);
    CHECK_NEAR(v[0].north, 300.0, 1e-9);
    CHECK_NEAR(v[0].speed, 0.0, 0.0);
    CHECK_NEAR(v[1].north, 1000.0 - 1250.0, 1e-9); /* b, straight on */
    CHECK_NEAR(v[1].east, 0.0, 1e-9);
    fw_source_destroy(src);
    /* bad definitions */
    fw_kin_ship twice[2] = {ships[0], ships[0]};
    kd.ships = twice;
    kd.n = 2;
    CHECK(fw_kinematic_source_create(&kd, &src, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "'b' listed twice") != NULL);
    fw_kin_ship late = ships[1];
    late.legs[1].t_start = 50.0; /* before the first */
    kd.ships = &late;
    kd.n = 1;
    CHECK(fw_kinematic_source_create(&kd, &src, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "leg 2 out of order") != NULL);
    kd.ships = ships;
    kd.step = 0.0;
    CHECK(fw_kinematic_source_create(&kd, &src, &err) == FW_EINPUT);
}

static void test_world_contract(void)
{
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.step = 0.5;
    fw_world_def wd = fw_default_world_def(); /* step 1 s */
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK);
    fw_world *w;
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT); /* source 0.5 s, world 1 s */
    CHECK(strstr(err.msg, "steps 0.5 s, the world 1 s") != NULL);
    wd.source = NULL;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &c3;
    vd.speed = fw_kn_to_ms(10);
    vd.course = 0.5 * FW_PI;
    fw_vessel_handle h;
    CHECK(fw_world_step(w, 1.0, &err) == FW_ERUN); /* not started */
    CHECK(fw_world_add_vessel(w, &vd, &h, &err) == FW_OK);
    fw_vessel *v = fw_world_vessel(w, h);
    /* same id: refused, and the controller it was given freed (LeakSanitizer
     * in the sanitizer build) */
    fw_manoeuvre_def md = {.t_act = 0.0};
    CHECK(fw_manoeuvre_controller_create(&md, &vd.controller, &err) == FW_OK);
    CHECK(fw_world_add_vessel(w, &vd, NULL, &err) == FW_EINPUT);
    vd.controller = NULL;
    vd.id = "own2";
    CHECK(fw_world_add_vessel(w, &vd, NULL, &err) == FW_EINPUT); /* a second own ship */
    CHECK(strstr(err.msg, "an own ship already") != NULL);
    vd.id = "own";
    CHECK(fw_world_start(w, &err) == FW_OK);
    CHECK(fw_world_add_vessel(w, &vd, NULL, &err) == FW_EINPUT); /* same id, after the start */
    CHECK(fw_world_step(w, 0.5, &err) == FW_EINPUT);
    /* no controller: helm amidships, the MMG ship runs straight at its speed */
    for (int k = 0; k < 60; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    const fw_mmg_state *x = fw_vessel_motion(v);
    CHECK_NEAR(fw_world_time(w), 60.0, 1e-12);
    CHECK_NEAR(x->east, 60.0 * fw_kn_to_ms(10), 0.5);
    CHECK_NEAR(x->north, 0.0, 1e-6);
    CHECK_NEAR(fw_vessel_record(v)->speed, fw_kn_to_ms(10), 0.01);
    fw_world_destroy(w);
}

/* Two vessels, same ship and policy, head-on 4 km apart: each sees the other
 * through the world, both turn to starboard (rule 14), and the tracks are
 * point mirrors of each other about the midpoint. */
static void test_two_vessels_head_on(void)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    fw_world *w;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    const char *ids[2] = {"A", "B"};
    fw_vessel *v[2];
    for (int i = 0; i < 2; i++) {
        fw_vessel_def vd = fw_default_vessel_def();
        vd.id = ids[i];
        vd.role = FW_ROLE_OTHER; /* no own ship: two ships fairway steps */
        vd.ship = &c3;
        vd.dynamics = FW_DYN_NOMOTO;
        vd.north = i ? 4000.0 : 0.0;
        vd.course = i ? FW_PI : 0.0;
        vd.speed = fw_kn_to_ms(10);
        CHECK_MSG(fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK, "%s", err.msg);
        fw_vessel_handle h;
        CHECK_MSG(fw_world_add_vessel(w, &vd, &h, &err) == FW_OK, "%s", err.msg);
        v[i] = fw_world_vessel(w, h);
    }
    CHECK(fw_world_start(w, &err) == FW_OK);
    double dmin = INFINITY, asym = 0.0, t_act[2] = {-1, -1};
    int side[2] = {0, 0};
    for (int k = 0; k < 1200; k++) {
        for (int i = 0; i < 2; i++) {
            const fw_decision *d = fw_vessel_decision(v[i]);
            if (d->acted && t_act[i] < 0) {
                t_act[i] = k;
                side[i] = d->search.side;
            }
        }
        const fw_mmg_state *a = fw_vessel_motion(v[0]), *b = fw_vessel_motion(v[1]);
        dmin = fmin(dmin, hypot(a->east - b->east, a->north - b->north));
        /* B is A turned half round about (0, 2000) */
        asym = fmax(asym, hypot(a->east + b->east, a->north + b->north - 4000.0));
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    CHECK_MSG(t_act[0] >= 0 && t_act[0] == t_act[1], "acted at %.0f and %.0f s", t_act[0],
              t_act[1]);
    CHECK(side[0] == FW_SIDE_STARBOARD && side[1] == FW_SIDE_STARBOARD);
    CHECK_MSG(asym < 1e-6, "tracks not mirror images: %.3g m", asym);
    /* each keeps the other out of a 300 m domain grown by the hull */
    CHECK_MSG(dmin > 300.0, "closest approach %.0f m", dmin);
    printf("  two vessels head-on: both act at %.0f s to starboard, closest %.0f m, "
           "asymmetry %.1g m\n", t_act[0], dmin, asym);
    fw_world_destroy(w);
}

/* A world of one own ship on 000 at 10 kn, helm amidships, and scripted
 * background ships that react by COLREGs (or not): the smallest distance
 * between any two ships, and the orders given. */
typedef struct react_out {
    double dmin;
    int slow, resume, alter, rejoin;
    double first_slow_t, first_alter_t, tcpa_then;
    double speed_end[3];
} react_out;

/* m/s: the own ship's speed in react_world (10 kn unless a test says) */
static double g_react_own_speed = 0.0;

static react_out react_world_gw(const fw_kin_ship *ships, int n, fw_behaviour b, int seconds,
                                fw_give_way gw)
{
    react_out o = {.dmin = INFINITY, .first_slow_t = -1, .first_alter_t = -1};
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ships;
    kd.n = n;
    fw_world_def wd = fw_default_world_def();
    wd.reactions.behaviour = b;
    wd.reactions.give_way = gw;
    fw_world *w = NULL;
    fw_vessel *own = NULL;
    fw_vessel_handle oh = {0};
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &c3;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.speed = g_react_own_speed > 0.0 ? g_react_own_speed : fw_kn_to_ms(10);
    CHECK_MSG(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK &&
                  fw_world_create(&wd, &w, &err) == FW_OK &&
                  fw_world_add_vessel(w, &vd, &oh, &err) == FW_OK &&
                  fw_world_start(w, &err) == FW_OK,
              "%s", err.msg);
    own = w ? fw_world_vessel(w, oh) : NULL;
    for (int k = 0; own && k < seconds; k++) {
        const fw_target *tg, *me = fw_vessel_record(own);
        const fw_assessment *as;
        int m;
        fw_vessel_view(own, &tg, &as, &m);
        for (int i = 0; i < m; i++) {
            o.dmin = fmin(o.dmin, hypot(tg[i].east - me->east, tg[i].north - me->north));
            for (int j = i + 1; j < m; j++)
                o.dmin = fmin(o.dmin, hypot(tg[i].east - tg[j].east, tg[i].north - tg[j].north));
            if (i < 3)
                o.speed_end[i] = tg[i].speed;
        }
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    int nr;
    const fw_reaction *r = w ? fw_world_reactions(w, &nr) : NULL;
    for (int i = 0; r && i < nr; i++) {
        if (r[i].kind == FW_REACT_RESUME) {
            o.resume++;
            continue;
        }
        if (r[i].kind == FW_REACT_ALTER && o.alter++ == 0)
            o.first_alter_t = r[i].t;
        o.rejoin += r[i].kind == FW_REACT_REJOIN;
        if (r[i].kind != FW_REACT_SLOW)
            continue;
        if (o.slow++ == 0)
            o.first_slow_t = r[i].t;
    }
    fw_world_destroy(w);
    return o;
}

/* The speed orders' world (give_way speed: what these tests measure). */
static react_out react_world(const fw_kin_ship *ships, int n, fw_behaviour b, int seconds)
{
    return react_world_gw(ships, n, b, seconds, FW_GIVE_WAY_SPEED);
}

/* Background ships by COLREGs: one that must give way to the own ship (the
 * own ship on its starboard side, rule 15) slows at once, 583 s before the
 * collision it was heading for, and passes at half a mile; blind, it hits.
 * One that stands on (the own ship on its port side) keeps course and
 * speed.  Of two background ships crossing, the give-way one yields. */
static void test_reactive_traffic(void)
{
    double v = fw_kn_to_ms(10), tc = 3000.0 / v; /* both at (0, 3000) at 583 s */
    fw_kin_ship give = {.start = {.id = "G", .east = -3000.0, .north = 3000.0, .course = 0.5 * FW_PI, .heading = 0.5 * FW_PI,
                                  .speed = v, .length = 200, .breadth = 32}};
    react_out blind = react_world(&give, 1, FW_BEHAVIOUR_BLIND, 900);
    react_out col = react_world(&give, 1, FW_BEHAVIOUR_COLREGS, 900);
    CHECK_MSG(blind.dmin < 50.0 && blind.slow == 0, "blind: %.0f m, %d orders", blind.dmin,
              blind.slow);
    CHECK_MSG(col.slow >= 1 && col.first_slow_t == 0.0, "colregs: %d orders, first at %.0f s",
              col.slow, col.first_slow_t);
    CHECK_MSG(col.dmin > 0.99 * 926.0, "colregs: closest %.0f m", col.dmin);
    CHECK_MSG(col.resume == 1 && fabs(col.speed_end[0] - v) < 1e-9, "given its speed back: %d, %.2f",
              col.resume, col.speed_end[0]);
    /* give_way course (world/steer.h): it alters course instead (and may
     * alter again while it steers itself), passes at the passing distance
     * less its turn's lag (95 %), and is back on its lane within the hour */
    react_out alt = react_world_gw(&give, 1, FW_BEHAVIOUR_COLREGS, 3600, FW_GIVE_WAY_COURSE);
    CHECK_MSG(alt.alter >= 1 && alt.slow == 0 && alt.rejoin == 1,
              "course: %d alterations, %d slow-downs, %d back", alt.alter, alt.slow, alt.rejoin);
    CHECK_MSG(alt.dmin > 0.95 * 926.0, "course: closest %.0f m", alt.dmin);
    fw_kin_ship stand = {.start = {.id = "S", .east = 3000.0, .north = 3000.0, .course = 1.5 * FW_PI, .heading = 1.5 * FW_PI,
                                   .speed = v, .length = 200, .breadth = 32}};
    react_out st = react_world(&stand, 1, FW_BEHAVIOUR_COLREGS, 900);
    /* the own ship here never gives way: the stand-on ship keeps course and
     * speed until it is so close that only its own action can help (rule
     * 17(b): within 240 s of the closest approach), then it slows */
    fw_reactions_def rd = fw_default_reactions_def();
    CHECK_MSG(st.slow >= 1 && st.first_slow_t >= tc - rd.last_time - 1.0,
              "stand-on: %d orders, the first at %.0f s", st.slow, st.first_slow_t);
    /* two background ships far from the own ship crossing at (20000, 3000):
     * A heading east sees B (heading north) on its starboard side: A gives way */
    fw_kin_ship two[2] = {
        {.start = {.id = "A", .east = 17000.0, .north = 3000.0, .course = 0.5 * FW_PI, .heading = 0.5 * FW_PI, .speed = v,
                   .length = 200, .breadth = 32}},
        {.start = {.id = "B", .east = 20000.0, .north = 0.0, .course = 0.0, .heading = 0.0, .speed = v,
                   .length = 200, .breadth = 32}}};
    react_out pair = react_world(two, 2, FW_BEHAVIOUR_COLREGS, 1200);
    react_out pb = react_world(two, 2, FW_BEHAVIOUR_BLIND, 1200);
    CHECK_MSG(pb.dmin < 50.0, "blind pair: %.0f m", pb.dmin);
    CHECK_MSG(pair.slow >= 1 && pair.dmin > 0.99 * 926.0, "pair: %d orders, closest %.0f m",
              pair.slow, pair.dmin);
    CHECK_MSG(fabs(pair.speed_end[1] - v) < 1e-12, "the stand-on ship B kept its speed (%.2f)",
              pair.speed_end[1]);
    printf("  give-way ship: blind %.0f m, colregs %.0f m (%d orders from %.0f s, %.0f s before "
           "the collision point); stand-on: kept course and speed until %.0f s (rule 17(b)), closest "
           "%.0f m; pair: blind %.0f m, colregs %.0f m\n",
           blind.dmin, col.dmin, col.slow, col.first_slow_t, tc, st.first_slow_t, st.dmin, pb.dmin,
           pair.dmin);
}

/* A give-way ship that has slowed already and whose speed no longer keeps
 * the passing distance alters course where it can (reactions.c: rules 8(c)
 * and 8(d)): G (15 kn, north) must give way to C (10 kn, west, from its
 * starboard side); at first no alteration clears (O, 5 kn on 035, is on its
 * starboard bow) and it slows; 100 s later its speed no longer does and an
 * alteration clears: it alters to starboard (before, it slowed further and
 * further), and every ship passes the others at the passing distance less
 * its turn's lag (95 %). */
static void test_slowed_then_alters(void)
{
    double v = fw_kn_to_ms(10);
    fw_kin_ship s[3] = {
        {.start = {.id = "G", .east = 20000.0, .north = 0.0, .course = 0.0, .heading = 0.0,
                   .speed = 1.5 * v, .length = 200, .breadth = 32}},
        {.start = {.id = "O", .east = 20600.0, .north = 1500.0, .course = fw_deg_to_rad(35.0),
                   .heading = fw_deg_to_rad(35.0), .speed = 0.5 * v, .length = 100,
                   .breadth = 16}},
        {.start = {.id = "C", .east = 20000.0 + 1150.0 * v, .north = 8000.0,
                   .course = 1.5 * FW_PI, .heading = 1.5 * FW_PI, .speed = v, .length = 200,
                   .breadth = 32}}};
    react_out o = react_world_gw(s, 3, FW_BEHAVIOUR_COLREGS, 2000, FW_GIVE_WAY_COURSE);
    CHECK_MSG(o.slow == 1 && o.alter == 1 && o.first_slow_t < o.first_alter_t &&
                  o.dmin > 0.95 * 926.0,
              "%d slow-downs (the first at %.0f s), %d alterations (at %.0f s), closest %.0f m",
              o.slow, o.first_slow_t, o.alter, o.first_alter_t, o.dmin);
    printf("  slowed at %.0f s (no alteration clears), altered at %.0f s (its speed no longer "
           "clears): closest %.0f m\n", o.first_slow_t, o.first_alter_t, o.dmin);
}

/* A world of the kinematic source's ships and the own ship (the C-3's
 * Nomoto plant under the policy), heading north from the origin at 10 kn. */
static void own_world(const fw_kinematic_def *kd, const fw_policy_controller_def *pd,
                      fw_world **w, fw_vessel **own, fw_error *err)
{
    static fw_own_state start;
    start = (fw_own_state){.U = fw_kn_to_ms(10)};
    fw_vessel_handle oh = {0};
    fw_world_def wd = fw_default_world_def();
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &c3;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.start_state = &start;
    vd.radius = INFINITY;
    CHECK_MSG(fw_kinematic_source_create(kd, &wd.source, err) == FW_OK &&
                  fw_world_create(&wd, w, err) == FW_OK &&
                  fw_policy_controller_create(pd, &vd.controller, err) == FW_OK &&
                  fw_world_add_vessel(*w, &vd, &oh, err) == FW_OK &&
                  fw_world_start(*w, err) == FW_OK,
              "%s", err->msg);
    *own = *w ? fw_world_vessel(*w, oh) : NULL;
}

/* After avoiding a head-on ship the own ship comes back onto its planned
 * track (the default return), not only onto its heading: the heading return
 * of the paper leaves it on a parallel track hundreds of metres off. */
static void test_return_to_track(void)
{
    double v = fw_kn_to_ms(10), xte[2] = {0, 0}, lam[2] = {INFINITY, INFINITY};
    for (int mode = 0; mode < 2; mode++) {
        fw_kin_ship sh[1] = {{.start = {.id = "T1", .east = 0, .north = 3000, .course = FW_PI, .heading = FW_PI,
                                        .speed = v, .length = 200, .breadth = 32}}};
        fw_error err = {0};
        fw_kinematic_def kd = fw_default_kinematic_def();
        kd.ships = sh;
        kd.n = 1;
        fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                       .policy = fw_default_policy_def()};
        pd.policy.ret = mode == 0 ? FW_RETURN_TRACK : FW_RETURN_HEADING;
        fw_world *w = NULL;
        fw_vessel *own = NULL;
        own_world(&kd, &pd, &w, &own, &err);
        for (int k = 0; own && k < 2400; k++) {
            const fw_own_state *x = fw_vessel_own_state(own);
            const fw_target *tg;
            const fw_assessment *as;
            int m;
            fw_vessel_view(own, &tg, &as, &m);
            for (int i = 0; i < m; i++)
                lam[mode] = fmin(lam[mode], fw_domain_lambda(&pd.helm.domain, x->east, x->north,
                                                             x->psi, &tg[i]));
            CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        }
        const fw_own_state *x = own ? fw_vessel_own_state(own) : NULL;
        xte[mode] = x ? x->east : NAN; /* the track is the north-going line x = 0 */
        if (x)
            CHECK_MSG(fabs(fw_wrap_pi(x->psi)) < fw_deg_to_rad(2.0), "heading %.1f deg at the end",
                      fw_rad_to_deg(x->psi));
        fw_world_destroy(w);
    }
    CHECK_MSG(lam[0] >= 1.0 && lam[1] >= 1.0, "domain entered: %.2f, %.2f", lam[0], lam[1]);
    CHECK_MSG(fabs(xte[0]) < 50.0, "track return ends %.0f m off the track", xte[0]);
    CHECK_MSG(fabs(xte[1]) > 200.0, "heading return ends %.0f m off the track", xte[1]);
    printf("  return after a head-on avoidance: track return %.1f m off the track at 40 min, "
           "heading return %.0f m\n", xte[0], xte[1]);
}

/* The own ship returning to its course after avoiding a head-on target meets
 * a second ship that turns onto its return path at 300 s: it stops the return
 * the same step (a new threat is looked at in every mode), keeps the domain
 * and gets back on course afterwards. */
static void test_threat_during_return(void)
{
    double v = fw_kn_to_ms(10);
    fw_kin_ship sh[2] = {
        {.start = {.id = "T1", .east = 0, .north = 2000, .course = FW_PI, .heading = FW_PI, .speed = v,
                   .length = 200, .breadth = 32}},
        {.start = {.id = "T2", .east = -400, .north = 5000, .course = 0.5 * FW_PI, .heading = 0.5 * FW_PI, .speed = v,
                   .length = 200, .breadth = 32},
         .n_legs = 1,
         .legs = {{300.0, FW_PI, v}}}};
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = sh;
    kd.n = 2;
    fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    pd.policy.ret = FW_RETURN_HEADING; /* the geometry is the heading return's */
    fw_world *w = NULL;
    fw_vessel *own = NULL;
    own_world(&kd, &pd, &w, &own, &err);
    double lam = INFINITY, t_return = -1, t_stop = -1, t_back = -1;
    fw_policy_mode prev = FW_MODE_STANDBY;
    for (int k = 0; own && k < 1500; k++) {
        const fw_own_state *x = fw_vessel_own_state(own);
        const fw_decision *d = fw_vessel_decision(own);
        const fw_target *tg;
        const fw_assessment *as;
        int m;
        fw_vessel_view(own, &tg, &as, &m);
        for (int i = 0; i < m; i++)
            lam = fmin(lam, fw_domain_lambda(&pd.helm.domain, x->east, x->north, x->psi, &tg[i]));
        if (d->mode == FW_MODE_AUTOPILOT && t_return < 0)
            t_return = k;
        if (prev == FW_MODE_AUTOPILOT && d->mode != FW_MODE_AUTOPILOT && t_stop < 0 && k >= 300)
            t_stop = k;
        if (prev == FW_MODE_AUTOPILOT && d->mode == FW_MODE_STANDBY)
            t_back = k;
        prev = d->mode;
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    }
    CHECK_MSG(t_return > 0 && t_return < 300, "return began at %.0f s", t_return);
    CHECK_MSG(t_stop >= 300 && t_stop <= 305, "return stopped at %.0f s for the turn at 300 s",
              t_stop);
    CHECK_MSG(lam >= 1.0, "domain entered: %.2f", lam);
    CHECK_MSG(t_back > t_stop, "back on course at %.0f s", t_back);
    printf("  threat during the return: return from %.0f s, stopped at %.0f s (target turned at "
           "300 s), domain radius %.2f, back on course at %.0f s\n",
           t_return, t_stop, lam, t_back);
    fw_world_destroy(w);
}

/* Runs the scenario file rel (under the data root) through SUMO into
 * tmp_root/sub, for duration s (0: the file's). */
static void run_data_file(const char *rel, const char *sub, double duration, fw_run_summary *sum,
                          fw_encounter **e, int *ne)
{
    static fw_scenario s;
    char file[512], dir[600];
    fw_error err = {0};
    snprintf(file, sizeof file, "%s/%s", fw_data_root(), rel);
    CHECK_MSG(fw_scenario_load(file, &s, &err) == FW_OK, "%s", err.msg);
    if (duration > 0.0)
        s.duration = duration;
    snprintf(dir, sizeof dir, "%s/%s", tmp_root, sub);
    mkdir(dir, 0777);
    fw_run_def def = fw_default_run_def();
    def.scenario = &s;
    def.dir = dir;
    CHECK_MSG(fw_run_scenario(&def, sum, e, ne, &err) == FW_OK, "%s", err.msg);
}

/* The strait with its heavy traffic for 20 minutes: no ship moves sideways
 * faster than a lane change allows (1 m/s across 900 m lanes in 900 s), none
 * jumps, none appears, vanishes or starts within 2 nm of the own ship (the
 * routes end beyond its sight and the fill's close ships are taken out). */
static void test_strait_traffic_monitors(void)
{
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int ne = 0;
    run_data_file("scenarios/traffic/strait-crossing.yaml", "strait", 1200.0, &sum, &e, &ne);
    free(e);
    const fw_monitor_counts *m = &sum.monitors;
    CHECK_MSG(m->sideways == 0 && m->teleport == 0 && m->max_lateral <= 1.0 + 1e-6,
              "%d sideways, %d teleports, %.2f m/s", m->sideways, m->teleport, m->max_lateral);
    CHECK_MSG(m->appear == 0 && m->vanish == 0 && m->start_close == 0,
              "%d appear, %d vanish, %d at the start within 2 nm", m->appear, m->vanish,
              m->start_close);
    CHECK(ne > 5 && sum.n_give_way > 0);
    printf("  strait, 20 min: %d ships met, largest sideways %.2f m/s, %d give-way orders, "
           "%d background overlaps\n",
           ne, m->max_lateral, sum.n_give_way, m->overlap);
}

/* A scenario with a network and explicit targets: both kinds of traffic
 * come through SUMO (the route files are a list), the explicit one with its
 * scenario label. */
static void test_network_and_targets(void)
{
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int ne = 0;
    run_data_file("tests/data/network_targets.yaml", "nt", 0.0, &sum, &e, &ne);
    int explicit = -1, network = 0;
    for (int i = 0; i < ne; i++) {
        if (strcmp(e[i].id, "X1") == 0)
            explicit = i;
        else
            network++;
    }
    CHECK_MSG(explicit >= 0 && strcmp(e[explicit].type, "tug") == 0, "the explicit target: %s",
              explicit >= 0 ? e[explicit].type : "not met");
    CHECK_MSG(network > 0, "no network ship met (%d encounters)", ne);
    printf("  network and targets: %d network ships and the explicit target (%s) met\n", network,
           explicit >= 0 ? e[explicit].type : "-");
    free(e);
}

/* own.csv's helm order and mode columns, and the act lines of run.log. */
static int decisions(const char *dir, char *out, size_t size)
{
    char path[700], line[512];
    size_t used = 0;
    int rows = 0;
    snprintf(path, sizeof path, "%s/own.csv", dir);
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        /* t,east,north,heading,speed,u,v,r,rudder,helm,propeller,mode: keep t, helm, mode */
        char *col[13];
        int nc = 0;
        for (char *p = strtok(line, ",\n"); p && nc < 13; p = strtok(NULL, ",\n"))
            col[nc++] = p;
        if (nc == 12)
            used += (size_t)snprintf(out + used, size - used, "%s %s %s\n", col[0], col[9],
                                     col[11]);
        rows++;
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/run.log", dir);
    if (!(f = fopen(path, "r")))
        return -1;
    while (fgets(line, sizeof line, f) && used < size)
        if (strstr(line, "  act ") || strstr(line, " -> "))
            used += (size_t)snprintf(out + used, size - used, "%s", line);
    fclose(f);
    return rows;
}

static void test_paper_case_without_sumo(void)
{
    static const char *const cases[] = {"1-head-on", "2-overtaking", "3-crossing",
                                        "4-head-on-complex", "5-crossing-complex"};
    static fw_scenario s;
    static char a[1 << 17], b[1 << 17];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        char file[512], d1[512], d2[512];
        fw_error err = {0};
        snprintf(file, sizeof file, "%s/scenarios/paper/%s.yaml", fw_data_root(), cases[c]);
        CHECK_MSG(fw_scenario_load(file, &s, &err) == FW_OK, "%s", err.msg);
        fw_run_summary sum[2];
        for (int k = 0; k < 2; k++) {
            char *d = k ? d2 : d1;
            snprintf(d, 512, "%s/%s-%s", tmp_root, cases[c], k ? "kinematic" : "sumo");
            mkdir(d, 0777);
            fw_run_def def = fw_default_run_def();
            def.scenario = &s;
            def.dir = d;
            def.traffic = k ? FW_RUN_TRAFFIC_KINEMATIC : FW_RUN_TRAFFIC_SUMO;
            fw_encounter *e = NULL;
            int ne = 0;
            CHECK_MSG(fw_run_scenario(&def, &sum[k], &e, &ne, &err) == FW_OK, "%s", err.msg);
            free(e);
        }
        struct stat sb;
        char sumo_dir[600];
        snprintf(sumo_dir, sizeof sumo_dir, "%s/sumo", d2);
        CHECK_MSG(stat(d2, &sb) == 0 && stat(sumo_dir, &sb) != 0,
                  "the kinematic run wrote SUMO files");
        int ra = decisions(d1, a, sizeof a), rb = decisions(d2, b, sizeof b);
        CHECK_MSG(ra > 100 && ra == rb, "%s: %d and %d rows", cases[c], ra, rb);
        CHECK_MSG(strcmp(a, b) == 0, "%s: decisions differ between SUMO and the kinematic source",
                  cases[c]);
        CHECK_NEAR(sum[0].min_dist, sum[1].min_dist, 0.05);
        CHECK_NEAR(sum[0].t_act, sum[1].t_act, 0.0);
        CHECK(sum[0].n_actions == sum[1].n_actions && sum[0].n_actions > 0);
        printf("  %s: same decisions with and without SUMO (%d rows; first action %.0f s, "
               "%d actions; closest %.2f / %.2f m)\n",
               cases[c], ra, sum[0].t_act, sum[0].n_actions, sum[0].min_dist, sum[1].min_dist);
    }
}

/* Rule 17(b) and 8(e): a lane-bound stand-on ship S (8 m/s west, 200 m)
 * meets the own ship (the C-3, the give-way ship, from its port side) crawling
 * north at 0.4 m/s with its bow already across S's track, and acting not at
 * all.  At min_speed (2.4 m/s) S would pass 148 m centre to centre, its bow
 * into the C-3's side; none of its speeds down to min_speed passes at
 * last_cpa, so it slows further, to steerage way (1 m/s: 554 m), and the
 * C-3 clears its track first: centres at least 300 m apart (the half
 * lengths 166 + 100 m).  Before, S held min_speed and ran onto it (strait,
 * 10 of 25 background overlaps on a93facc). */
static void test_stand_on_takes_the_way_off(void)
{
    fw_kin_ship s = {.start = {.id = "S", .east = 1920.0, .north = 170.0, .course = 1.5 * FW_PI,
                               .heading = 1.5 * FW_PI, .speed = 8.0, .length = 200,
                               .breadth = 32}};
    g_react_own_speed = 0.4;
    react_out o = react_world(&s, 1, FW_BEHAVIOUR_COLREGS, 1500);
    g_react_own_speed = 0.0;
    CHECK_MSG(o.slow >= 1 && o.dmin > 300.0, "%d speed orders, closest %.0f m", o.slow, o.dmin);
}

int main(void)
{
    if (test_tmpdir("world", tmp_root, sizeof tmp_root))
        return 1;
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_kinematic_source);
    TEST_RUN(test_world_contract);
    TEST_RUN(test_two_vessels_head_on);
    TEST_RUN(test_reactive_traffic);
    TEST_RUN(test_stand_on_takes_the_way_off);
    TEST_RUN(test_slowed_then_alters);
    TEST_RUN(test_threat_during_return);
    TEST_RUN(test_return_to_track);
    TEST_RUN(test_strait_traffic_monitors);
    TEST_RUN(test_network_and_targets);
    TEST_RUN(test_paper_case_without_sumo);
    return TEST_EXIT();
}
