/* test_steer.c - background ships that alter course (world/steer.h, reactions.h give_way course).
 *
 *   model: the indices steer.h states are the C-3's (c3-mmg's knowledge base
 *     at 12 kn and 15 deg, made non-dimensional) to 0.5 %; a steered ship's
 *     steady rate at a held helm is K' U / L x helm, its time constant T' L / U
 *   crossing (kinematic source, open water): a ship with the own ship on its
 *     starboard bow on a collision course alters course to starboard by at
 *     least 20 deg (readily apparent), the own ship passes it at the passing
 *     distance or more, it turns no faster than its model can, comes back to
 *     its lane and is given back on its line (within the source's 1 m), and
 *     nothing jumps: its hull centre moves at its speed every step
 *   the same in a set across its lane (1 m/s): it crabs along its line and
 *     is given back there
 *   no sea room (the kinematic lane 100 m each side): it slows down instead
 *   head-on with the own ship (rule 14): it alters to starboard
 *   give_way speed (the default): no alteration, the slow-down of before
 *   the predictor: a turning ship is expected to finish its turn (arc, then
 *     straight), a steady one to go on at constant velocity
 *   close quarters: a steered ship at steerage way in a lane ship's path gets
 *     its way back and passes ahead 0.25 nm off (before: it stayed stopped
 *     and was run onto); a ship converging from abeam at 33 deg is crossing
 *     (rule 13's sectors), not a ship going its way: they pass 0.25 nm off
 */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "fit/identify.h"
#include "nomoto/nomoto.h"
#include "test.h"
#include "traffic/source.h"
#include "world/controllers.h"
#include "world/steer.h"
#include "world/world.h"

static fw_ship own_ship;

/* The steered ships' model is the C-3's at 12 kn and 15 deg: K' is its
 * knowledge base's (c3-mmg) within 0.5 %, and the first-order model follows
 * the C-3's own MMG turning test there (rudder ramped at 2.32 deg/s) within
 * 10 % RMS of the final rate over 5 minutes and 10 % of the heading change
 * (measured: 8.2 % and 43.3 against 47.2 deg).  T' (0.497) is the 8-14 kn
 * knowledge base's T1 + T2 - T3; the 4-20 kn one gives 0.37 there (terms of
 * 20-300 s that nearly cancel move with the fit), the best first-order fit of
 * the MMG test 0.35 (6.6 % RMS): the background ships are left as they were. */
static void test_indices_are_the_c3s(void)
{
    fw_ship c3;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-mmg", &c3, &err) == FW_OK, "%s", err.msg);
    fw_nomoto_indices ix;
    CHECK(fw_nomoto_indices_at(&c3.nomoto, 12.0, 15.0, &ix, &err) == FW_OK);
    double U = fw_kn_to_ms(12.0), helm = fw_deg_to_rad(15.0);
    CHECK_NEAR(ix.K * c3.L / U, FW_STEER_K_ND, 0.005 * FW_STEER_K_ND);
    enum { N = 301 };
    double r[N], q[N], ss = 0.0, hr = 0.0, hq = 0.0;
    fw_nomoto_indices fo = {.K = FW_STEER_K_ND * U / c3.L, .T1 = FW_STEER_T_ND * c3.L / U,
                            .T2 = 50.0, .T3 = 50.0};
    CHECK_MSG(fw_ident_turning(&c3, U, helm, 1.0, N, r, &err) == FW_OK, "%s", err.msg);
    fw_ident_response(&fo, helm, fw_deg_to_rad(2.32), 1.0, N, q);
    for (int k = 0; k < N; k++)
        ss += (q[k] - r[k]) * (q[k] - r[k]), hr += r[k], hq += q[k];
    double rms = sqrt(ss / N) / fabs(r[N - 1]);
    CHECK_MSG(rms < 0.10 && fabs(hq - hr) < 0.10 * fabs(hr),
              "first-order model against the MMG C-3: RMS %.1f %%, heading %.1f vs %.1f deg",
              100 * rms, fw_rad_to_deg(hq), fw_rad_to_deg(hr));
}

/* A steered 150 m ship at 12 kn, helm 15 deg held: its rate after 5 time
 * constants is K' U / L x 15 deg (1 %), and after the rudder is over
 * (15 deg at 2.32 deg/s) it rises as 1 - exp(-t / T) would (5 %). */
static void test_model_turns_as_stated(void)
{
    fw_ship s;
    fw_steer_ship(150.0, 25.0, "feeder", &s);
    double U = fw_kn_to_ms(12.0), K = FW_STEER_K_ND * U / 150.0, T = FW_STEER_T_ND * 150.0 / U;
    fw_world_def wd = fw_default_world_def();
    fw_world *w = NULL;
    fw_error err = {0};
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_manoeuvre_def md = {.t_act = 0.0, .helm = fw_deg_to_rad(15.0), .course = 0.0,
                           .alteration = fw_deg_to_rad(350.0)};
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &s;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.speed = U;
    CHECK(fw_manoeuvre_controller_create(&md, &vd.controller, &err) == FW_OK);
    fw_vessel_handle h;
    CHECK(fw_world_add_vessel(w, &vd, &h, &err) == FW_OK);
    CHECK(fw_world_start(w, &err) == FW_OK);
    double ramp = 15.0 / (65.0 / 28.0), r_ramp_end = NAN;
    for (int k = 1; k <= (int)(ramp + 5.0 * T) + 1; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        if (k == (int)ceil(ramp))
            r_ramp_end = fw_vessel_motion(fw_world_vessel(w, h))->r;
        if (k == (int)ceil(ramp) + (int)round(T)) {
            double r = fw_vessel_motion(fw_world_vessel(w, h))->r;
            double want = K * fw_deg_to_rad(15.0) - (K * fw_deg_to_rad(15.0) - r_ramp_end) *
                                                         exp(-round(T) / T);
            CHECK_NEAR(r, want, 0.05 * want);
        }
    }
    double r = fw_vessel_motion(fw_world_vessel(w, h))->r;
    CHECK_NEAR(r, K * fw_deg_to_rad(15.0), 0.01 * K * fw_deg_to_rad(15.0));
    fw_world_destroy(w);
}

/* A world: the background ships ks (nks) and the own ship (a Nomoto C-3
 * without a controller: it holds its course) from (e, n) on course_deg at
 * kn; give_way as given, sea room, a current to the east. */
static fw_world *world_of(const fw_kin_ship *ks, int nks, fw_give_way gw, double room, double e,
                          double n, double course_deg, double kn, double cur_e)
{
    fw_error err = {0};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ks;
    kd.n = nks;
    kd.room = room;
    fw_world_def wd = fw_default_world_def();
    wd.reactions = fw_default_reactions_def(); /* colregs */
    wd.reactions.give_way = gw;
    if (cur_e != 0.0)
        wd.env.current = (fw_current){.kind = FW_FIELD_UNIFORM, .east = cur_e};
    fw_world *w = NULL;
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK);
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def own = fw_default_vessel_def();
    own.ship = &own_ship;
    own.dynamics = FW_DYN_NOMOTO;
    own.east = e, own.north = n, own.course = fw_deg_to_rad(course_deg);
    own.speed = fw_kn_to_ms(kn);
    CHECK(fw_world_add_vessel(w, &own, NULL, &err) == FW_OK);
    CHECK(fw_world_start(w, &err) == FW_OK);
    return w;
}

/* The world with one background ship g (150 x 25 m, 10 kn, going north
 * from the origin). */
static fw_world *scene_in(fw_give_way gw, double room, double e, double n, double course_deg,
                          double kn, double cur_e)
{
    fw_kin_ship ks[1] = {{.start = {.id = "g", .east = 0, .north = 0, .course = 0.0,
                                    .speed = fw_kn_to_ms(10), .length = 150, .breadth = 25,
                                    .type = "container_feeder"}}};
    return world_of(ks, 1, gw, room, e, n, course_deg, kn, cur_e);
}

static fw_world *scene(fw_give_way gw, double room, double e, double n, double course_deg,
                       double kn)
{
    return scene_in(gw, room, e, n, course_deg, kn, 0.0);
}

/* What happened to g in steps of 1 s for up to `steps`. */
typedef struct track_stats {
    int alters, rejoins, slows;
    double alter_deg;          /* the first alteration */
    double max_rate_degps;     /* its largest heading change in a step */
    double max_jump_m;         /* its largest move beyond speed x step */
    double min_range_m;        /* from the own ship, hull centres */
    double rejoin_off_m;       /* its distance from its lane (east = 0) when given back */
} track_stats;

/* g's record: a vessel's while taken, else the source's. */
static bool g_now(fw_world *w, fw_target *out)
{
    const fw_target *v;
    int n;
    fw_error err = {0};
    fw_source *src = fw_world_source(w);
    for (int i = 0; i < fw_world_vessel_count(w); i++) {
        const fw_vessel *vs = fw_world_vessel(w, fw_world_vessel_at(w, i));
        if (strcmp(fw_vessel_id(vs), "g") == 0) {
            *out = *fw_vessel_record(vs);
            return true;
        }
    }
    if (src->ops->within(src, 0.0, 0.0, INFINITY, &v, &n, &err) == FW_OK)
        for (int i = 0; i < n; i++)
            if (strcmp(v[i].id, "g") == 0) {
                *out = v[i];
                return true;
            }
    return false;
}

static track_stats sail(fw_world *w, int steps)
{
    track_stats s = {.min_range_m = INFINITY, .rejoin_off_m = NAN, .alter_deg = NAN};
    fw_error err = {0};
    fw_target prev = {0}, now;
    bool have = g_now(w, &prev);
    CHECK(have);
    for (int k = 0; k < steps; k++) {
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
        CHECK(g_now(w, &now));
        double rate = fabs(fw_rad_to_deg(fw_wrap_pi(now.heading - prev.heading)));
        double moved = hypot(now.east - prev.east, now.north - prev.north);
        s.max_rate_degps = fmax(s.max_rate_degps, rate);
        s.max_jump_m = fmax(s.max_jump_m, moved - fmax(now.speed, prev.speed));
        const fw_target *own = fw_vessel_record(fw_world_vessel(w, fw_world_own(w)));
        s.min_range_m = fmin(s.min_range_m, hypot(own->east - now.east, own->north - now.north));
        prev = now;
    }
    int n;
    const fw_reaction *r = fw_world_reactions(w, &n);
    for (int i = 0; i < n; i++) {
        if (strcmp(r[i].ship, "g") != 0)
            continue;
        if (r[i].kind == FW_REACT_ALTER && s.alters++ == 0)
            s.alter_deg = fw_rad_to_deg(fw_wrap_pi(r[i].course_to - r[i].course_from));
        s.rejoins += r[i].kind == FW_REACT_REJOIN;
        s.slows += r[i].kind == FW_REACT_SLOW;
    }
    return s;
}

/* Own ship from the east going west at 12 kn, meeting g (10 kn north) at
 * (0, 4000) in 1200 s: g has it on its starboard bow and gives way. */
static fw_world *crossing(fw_give_way gw, double room)
{
    double v = fw_kn_to_ms(12.0), t = 4000.0 / fw_kn_to_ms(10.0);
    return scene(gw, room, v * t, 4000.0, 270.0, 12.0);
}

static void test_crossing_alters_and_comes_back(void)
{
    fw_world *w = crossing(FW_GIVE_WAY_COURSE, INFINITY);
    track_stats s = sail(w, 3600);
    CHECK_MSG(s.alters == 1, "%d alterations", s.alters);
    CHECK_MSG(s.alter_deg >= 20.0 - 1e-9 && s.alter_deg <= 60.0 + 1e-9, "%.1f deg", s.alter_deg);
    CHECK_MSG(s.slows == 0, "%d slow-downs", s.slows);
    /* the own ship holds on; the passing distance (926 m) less the turn's lag */
    CHECK_MSG(s.min_range_m > 800.0, "closest %.0f m", s.min_range_m);
    /* 35 deg of rudder at most: K' U / L x 35 deg = 0.56 deg/s */
    double rmax = fw_rad_to_deg(FW_STEER_K_ND * fw_kn_to_ms(10) / 150.0 * fw_deg_to_rad(35.0));
    CHECK_MSG(s.max_rate_degps <= rmax, "%.2f deg/s (at most %.2f)", s.max_rate_degps, rmax);
    CHECK_MSG(s.max_jump_m < 0.05, "moved %.2f m beyond its speed in a step", s.max_jump_m);
    CHECK_MSG(s.rejoins == 1, "%d rejoins", s.rejoins);
    fw_target g;
    CHECK(g_now(w, &g));
    CHECK_MSG(fabs(g.east) <= FW_SOURCE_REJOIN_MAX, "given back %.2f m off its lane", g.east);
    CHECK_NEAR(fw_rad_to_deg(fw_wrap_pi(g.course)), 0.0, 1e-6);
    CHECK(fw_world_vessel_count(w) == 1); /* only the own ship: g is the source's again */
    fw_world_destroy(w);
}

/* The crossing in a 1 m/s set to the east, across g's lane: back on its
 * line g crabs 11 deg into the set (asin(1 / 5.1)), its bow 15 m to port
 * of the line along its heading; it makes good the line and is given back
 * there (before, its bow was looked for along its heading and it never was:
 * 1 of 51 altered ships given back in an hour in Dover's spring stream). */
static void test_cross_set_comes_back(void)
{
    double v = fw_kn_to_ms(12.0), t = 4000.0 / fw_kn_to_ms(10.0);
    fw_world *w = scene_in(FW_GIVE_WAY_COURSE, INFINITY, v * t, 4000.0, 270.0, 12.0, 1.0);
    track_stats s = sail(w, 3600);
    CHECK_MSG(s.alters >= 1, "%d alterations", s.alters);
    CHECK_MSG(s.rejoins == 1, "%d rejoins", s.rejoins);
    CHECK_MSG(s.max_jump_m < 0.05, "moved %.2f m beyond its speed in a step", s.max_jump_m);
    fw_target g;
    CHECK(g_now(w, &g));
    CHECK_MSG(fabs(g.east) <= FW_SOURCE_REJOIN_MAX, "given back %.2f m off its lane", g.east);
    CHECK(fw_world_vessel_count(w) == 1);
    fw_world_destroy(w);
}

static void test_no_room_slows(void)
{
    fw_world *w = crossing(FW_GIVE_WAY_COURSE, 100.0);
    track_stats s = sail(w, 600);
    CHECK_MSG(s.alters == 0 && s.slows >= 1, "%d alterations, %d slow-downs", s.alters, s.slows);
    fw_world_destroy(w);
}

static void test_speed_mode_unchanged(void)
{
    fw_world *w = crossing(FW_GIVE_WAY_SPEED, INFINITY);
    track_stats s = sail(w, 600);
    CHECK_MSG(s.alters == 0 && s.slows >= 1, "%d alterations, %d slow-downs", s.alters, s.slows);
    fw_world_destroy(w);
}

/* The own ship 6 km ahead of g, coming south, 100 m to g's starboard side:
 * head-on (rule 14); g alters to starboard. */
static void test_head_on_alters(void)
{
    fw_world *w = scene(FW_GIVE_WAY_COURSE, INFINITY, 100.0, 6000.0, 180.0, 12.0);
    track_stats s = sail(w, 1800);
    CHECK_MSG(s.alters == 1 && s.alter_deg >= 20.0 - 1e-9, "%d alterations (%.1f deg)", s.alters,
              s.alter_deg);
    CHECK_MSG(s.min_range_m > 700.0, "closest %.0f m", s.min_range_m);
    fw_world_destroy(w);
}

/* A steered 150 m ship (speed m/s its own) on a lane north along east 0,
 * the ship it gave way to past (it comes back at once). */
static fw_controller *past_on_lane(double speed)
{
    fw_alter_def def = fw_default_alter_def();
    def.lane = (fw_lane_info){.np = 2, .e = {0.0, 0.0}, .n = {-1e4, 5e4}};
    def.length = 150.0, def.breadth = 25.0, def.speed = speed;
    snprintf(def.other, sizeof def.other, "%s", "gone");
    fw_controller *c = NULL;
    fw_error err = {0};
    CHECK(fw_steer_controller_create(&def, &c, &err) == FW_OK);
    return c;
}

/* Keeping its distance: a steered ship (150 x 25 m, its own speed 6 m/s) on
 * its lane's line going north, a lane-mate 1 km ahead at 3 m/s.  It slows
 * at no more than 0.1 m/s^2, never comes within SUMO's gap of 200 m hull to
 * hull, and settles behind it at 200 m + 30 s x 3 m/s = 290 m at the
 * lane-mate's speed (kinematic: it makes good its order along the line). */
static void test_follows_a_slower_ship_ahead(void)
{
    fw_controller *c = past_on_lane(6.0);
    fw_error err = {0};
    fw_own_state o = {.U = 6.0};
    fw_target lead = {.id = "lead", .north = 1000.0, .speed = 3.0, .stw = 3.0, .length = 150.0,
                      .breadth = 25.0};
    fw_assessment as[1];
    int order[2];
    double least = INFINITY, u_prev = 6.0, worst_rate = 0.0;
    for (int k = 0; k < 1800; k++) {
        fw_sense in = {.t = k, .own = &o, .targets = &lead, .n = 1, .as = as, .order = order};
        fw_decision d;
        CHECK(c->ops->decide(c, &in, &d, &err) == FW_OK);
        CHECK_MSG(d.speed > 0.0, "t %d: no speed order", k);
        worst_rate = fmax(worst_rate, u_prev - d.speed);
        u_prev = o.U = d.speed;
        o.north += o.U, lead.north += lead.speed;
        least = fmin(least, lead.north - o.north - 150.0);
    }
    CHECK_MSG(worst_rate <= 0.1 + 1e-12, "slowed %.3f m/s in a second", worst_rate);
    CHECK_MSG(least >= 200.0, "came within %.1f m of the ship ahead", least);
    CHECK_NEAR(lead.north - o.north - 150.0, 290.0, 5.0);
    CHECK_NEAR(o.U, 3.0, 0.02);
    /* the lane-mate gone: back up to its own speed at 0.05 m/s^2 */
    lead.north = 1e6;
    for (int k = 1800; k < 1800 + 30; k++) {
        fw_sense in = {.t = k, .own = &o, .targets = &lead, .n = 1, .as = as, .order = order};
        fw_decision d;
        CHECK(c->ops->decide(c, &in, &d, &err) == FW_OK);
        o.U = d.speed;
    }
    CHECK_NEAR(o.U, 3.0 + 0.05 * 30, 0.051);
    fw_controller_destroy(c);
}

/* Steerage way over ground in a head stream: the steered ship of
 * test_follows_a_slower_ship_ahead behind a lane-mate 600 m ahead at 0.3 m/s
 * over ground, stemming a 1 m/s stream.  Following it, the ship slows, but
 * never below 1 m/s over ground (2 m/s through the water); in still water the
 * floor is 1 m/s through the water, as before.  Before, it was 1 m/s through
 * the water in any stream: in dover-imperfect steered ships stemming the
 * spring stream made 0.2-0.3 kn over ground for minutes (46 "stopped" monitor
 * events in seeds 1-4 at 64 replications). */
static double slowest_behind(double cur_n)
{
    fw_controller *c = past_on_lane(6.0);
    fw_error err = {0};
    fw_own_state o = {.U = 6.0, .cur_n = cur_n};
    fw_target lead = {.id = "lead", .north = 600.0, .speed = 0.3, .stw = 0.3 - cur_n,
                      .length = 150.0, .breadth = 25.0};
    fw_assessment as[1];
    int order[2];
    double slowest = INFINITY;
    for (int k = 0; k < 1200; k++) {
        fw_sense in = {.t = k, .own = &o, .targets = &lead, .n = 1, .as = as, .order = order};
        fw_decision d;
        CHECK(c->ops->decide(c, &in, &d, &err) == FW_OK);
        o.U = d.speed;
        slowest = fmin(slowest, d.speed);
        o.north += o.U + cur_n, lead.north += lead.speed;
    }
    fw_controller_destroy(c);
    return slowest;
}

static void test_steerage_way_over_ground_in_a_head_stream(void)
{
    double head = slowest_behind(-1.0), still = slowest_behind(0.0);
    CHECK_MSG(head >= 2.0 - 1e-9, "%.3f m/s through the water: %.3f over ground", head,
              head - 1.0);
    CHECK_NEAR(still, 1.0, 1e-9);
}

/* Sails steered ship c (its lane's course north) against target t (constant
 * velocity) for n s, the ship moving as its model turns at the helm ordered
 * (steady rate K' U / L x helm) at the speed ordered; the least distance
 * between the centres and the least speed ordered. */
static void sail_from(fw_controller *c, fw_own_state *o, fw_target *t, int k0, int n,
                      double *least, double *slowest)
{
    fw_assessment as[1];
    int order[2];
    fw_error err = {0};
    *least = *slowest = INFINITY;
    for (int k = k0; k < k0 + n; k++) {
        fw_sense in = {.t = k, .own = o, .targets = t, .n = 1, .as = as, .order = order};
        fw_decision d;
        CHECK(c->ops->decide(c, &in, &d, &err) == FW_OK);
        o->U = d.speed;
        o->psi += FW_STEER_K_ND * o->U / 150.0 * d.helm;
        o->east += o->U * sin(o->psi), o->north += o->U * cos(o->psi);
        t->east += t->speed * sin(t->course), t->north += t->speed * cos(t->course);
        *least = fmin(*least, hypot(t->east - o->east, t->north - o->north));
        *slowest = fmin(*slowest, d.speed);
    }
}

static void sail_pair(fw_controller *c, fw_own_state *o, fw_target *t, int n, double *least,
                      double *slowest)
{
    sail_from(c, o, t, 0, n, least, slowest);
}

/* Close quarters (steer.h, rules 8(e) and 17(b)): a steered 150 m ship
 * (own speed 8 m/s) slowed to steerage way on its lane, a lane ship (6 m/s,
 * 150 m) coming from the west along a line 150 m ahead of it, 1500 m off:
 * at steerage way it would be run onto (centres 100 m apart at 250 s), and
 * a stopped ship hardly turns.  It gets its way back and passes ahead:
 * centres at least 463 m (0.25 nm) apart; before, it took the way off,
 * finding no turn that gained, and the hulls met (strait-domain, 17 of 19
 * background overlaps in seeds 1-4 on a93facc). */
static void test_close_quarters_keeps_way_out_of_a_lane(void)
{
    fw_controller *c = past_on_lane(8.0);
    fw_own_state o = {.U = 1.0};
    fw_target t = {.id = "lane", .east = -1500.0, .north = 150.0, .course = 0.5 * FW_PI,
                   .heading = 0.5 * FW_PI, .speed = 6.0, .stw = 6.0, .length = 150.0,
                   .breadth = 25.0};
    double least, slowest;
    sail_pair(c, &o, &t, 600, &least, &slowest);
    CHECK_MSG(least >= 463.0, "passed %.0f m off", least);
    CHECK_MSG(o.U > 7.9, "at %.1f m/s after 10 minutes", o.U);
    fw_controller_destroy(c);
}

/* Going its way is rule 13's: a ship converging from abeam at 33 deg (19 kn
 * against its 15, both 200 m) is crossing from its starboard side: the
 * steered ship acts (it altered course or slowed) and they pass 0.25 nm or
 * more apart; before, courses within 45 deg alone made it a ship going its
 * way and neither saw the other (strait-domain, seed 4, replication 4). */
static void test_converging_from_abeam_is_crossing(void)
{
    const double speed = fw_kn_to_ms(15.0);
    fw_controller *c = past_on_lane(speed);
    fw_own_state o = {.U = speed};
    /* meeting at (0, 3000) in 390 s: it from due east of that point's
     * approach, on 327 deg */
    double v = fw_kn_to_ms(19.0), tm = 3000.0 / speed, crs = fw_deg_to_rad(327.0);
    fw_target t = {.id = "ferry", .course = crs, .heading = crs, .speed = v, .stw = v,
                   .length = 150.0, .breadth = 25.0};
    t.east = -v * tm * sin(crs), t.north = 3000.0 - v * tm * cos(crs);
    double least, slowest;
    sail_pair(c, &o, &t, 900, &least, &slowest);
    CHECK_MSG(least >= 463.0, "passed %.0f m off", least);
    fw_controller_destroy(c);
}

/* Ships of one lane (north from the origin's meridian, x = 0), each
 * (id, north m, kn; 150 x 25 m), and the own ship crossing as crossing()
 * does: from (e, 4000) going west at kn_own so as to be at (0, 4000) when g
 * (10 kn, from the origin) would be. */
static fw_world *lane_scene(const fw_kin_ship *ks, int n, double kn_own)
{
    return world_of(ks, n, FW_GIVE_WAY_COURSE, INFINITY,
                    fw_kn_to_ms(kn_own) * 4000.0 / fw_kn_to_ms(10.0), 4000.0, 270.0, kn_own, 0.0);
}

static fw_kin_ship lane_ship(const char *id, double north, double kn)
{
    fw_kin_ship k = {.start = {.east = 0, .north = north, .course = 0.0, .speed = fw_kn_to_ms(kn),
                               .length = 150, .breadth = 25, .type = "container_feeder"}};
    snprintf(k.start.id, sizeof k.start.id, "%s", id);
    return k;
}

/* g (10 kn) gives way to the crossing own ship by altering to starboard;
 * h, 14 kn, 1.5 km astern of it in its lane, overtakes it as it moves off
 * (rule 13): h keeps its lane and speed, passing g (steered off to its
 * starboard) at half a mile or more, where before it slowed for it.  g
 * comes back and is given back. */
static void test_overtaking_a_ship_moving_off(void)
{
    fw_kin_ship ks[2] = {lane_ship("g", 0.0, 10.0), lane_ship("h", -1500.0, 14.0)};
    fw_world *w = lane_scene(ks, 2, 12.0);
    fw_error err = {0};
    double closest = INFINITY;
    for (int k = 0; k < 3600; k++) {
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
        fw_target g;
        const fw_target *v;
        int n;
        fw_source *src = fw_world_source(w);
        if (!g_now(w, &g) || src->ops->within(src, 0.0, 0.0, INFINITY, &v, &n, &err))
            continue;
        for (int i = 0; i < n; i++)
            if (strcmp(v[i].id, "h") == 0)
                closest = fmin(closest, hypot(v[i].east - g.east, v[i].north - g.north));
    }
    int n, g_alters = 0, g_back = 0, h_slows = 0;
    const fw_reaction *r = fw_world_reactions(w, &n);
    for (int i = 0; i < n; i++) {
        g_alters += strcmp(r[i].ship, "g") == 0 && r[i].kind == FW_REACT_ALTER;
        g_back += strcmp(r[i].ship, "g") == 0 && r[i].kind == FW_REACT_REJOIN;
        h_slows += strcmp(r[i].ship, "h") == 0 && r[i].kind == FW_REACT_SLOW;
    }
    CHECK_MSG(g_alters >= 1 && g_back == 1, "g: %d alterations, %d given back", g_alters, g_back);
    CHECK_MSG(h_slows == 0, "h slowed %d times", h_slows);
    /* h passed g abeam at the half mile or more that g's way back waits for */
    CHECK_MSG(closest >= 0.5 * 926.0, "h came within %.0f m of g", closest);
    fw_world_destroy(w);
}

/* A 150 m ship at (e, n) m on course deg at v m/s. */

static fw_target ship_at(double e, double n, double deg, double v)
{
    double crs = fw_deg_to_rad(deg);
    return (fw_target){.id = "other", .east = e, .north = n, .course = crs, .heading = crs,
                       .speed = v, .stw = v, .length = 150.0, .breadth = 25.0};
}

/* Coming back (steer.h, return): a steered 150 m ship 200 m to starboard of
 * its lane (course north), heading 038 at 11 m/s, the ship it gave way to
 * past; a slowed lane ship (2 m/s, 150 m) crossing ahead from starboard to
 * port, 1000 m ahead and 300 m to starboard of it.  Its way back (to port)
 * and its lane's course both pass that ship within half the passing
 * distance: it holds its course (rule 8(d)) and passes astern of it, 463 m
 * (0.25 nm) or more between centres, and is back on its lane within 20
 * minutes.  Before, it turned back across the other's bow and their centres
 * came 214 m apart (strait-domain seed 3, replication 7: a ferry's 45 deg
 * return to port onto a lane ship crossing ahead at 4 kn). */
static void test_return_holds_course_across_a_ship_ahead(void)
{
    fw_controller *c = past_on_lane(11.0);
    fw_own_state o = {.east = 200.0, .psi = fw_deg_to_rad(38.0), .U = 11.0};
    fw_target t = ship_at(500.0, 1000.0, 270.0, 2.0);
    double least, slowest;
    sail_pair(c, &o, &t, 1200, &least, &slowest);
    CHECK_MSG(least >= 463.0, "passed %.0f m off", least);
    CHECK_MSG(fabs(o.east) < 10.0, "%.0f m off its lane after 20 minutes", o.east);
    fw_controller_destroy(c);
}

/* Close quarters judged along the turn the ship makes (steer.h): a steered
 * 150 m ship at 10.6 m/s (20.6 kn) on its lane, a slow ship (2 m/s, 150 m)
 * 600 m ahead, 10 deg on its starboard bow, going east across its bow to
 * starboard.  Its turns to starboard swing it round in 150-250 m radius
 * (K' U / L x 20 deg of helm), through the other's path: it takes the
 * action that passes farthest along that swing, centres 0.1 nm (185 m) or
 * more apart.  Before, each turn was judged as made at once: it swung 90
 * deg to starboard onto the slow ship, centres 17 m apart (strait-domain
 * seed 1, replication 12: a ferry's 70 deg turn onto a ship crossing slowly
 * ahead). */
static void test_close_quarters_judged_along_the_turn(void)
{
    fw_controller *c = past_on_lane(10.6);
    fw_own_state o = {.U = 10.6};
    double brg = fw_deg_to_rad(10.0);
    fw_target t = ship_at(600.0 * sin(brg), 600.0 * cos(brg), 90.0, 2.0);
    double least, slowest;
    sail_pair(c, &o, &t, 600, &least, &slowest);
    CHECK_MSG(least >= 185.2, "passed %.0f m off", least);
    fw_controller_destroy(c);
}

/* g gives way to the own ship (10 kn) crossing from its starboard side
 * and passes astern of it.  Once the own ship is past but g's way back
 * would still pass it within the passing distance, g sails its lane's
 * course where it is until it can come back (before, it held its
 * alteration on and went 1908 m off its lane; now 1181 m), is given back
 * on its lane within the hour (1820 s; before 1719 s) and is never more than
 * 1500 m (0.8 of a Dover lane's 1852 m) off it. */
static void test_comes_back_when_clear(void)
{
    fw_kin_ship ks[1] = {lane_ship("g", 0.0, 10.0)};
    fw_world *w = lane_scene(ks, 1, 10.0);
    fw_error err = {0};
    double far = 0.0, t_back = NAN;
    for (int k = 0; k < 3600; k++) {
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
        fw_target g;
        CHECK(g_now(w, &g));
        far = fmax(far, fabs(g.east));
        if (isnan(t_back) && fw_world_vessel_count(w) == 1 && far > 0.0)
            t_back = k + 1.0;
    }
    printf("comes back when clear: %.0f m off its lane at most, given back at %.0f s\n", far,
           t_back);
    CHECK_MSG(far > 100.0 && far < 1500.0, "%.0f m off its lane at most", far);
    CHECK_MSG(t_back < 3600.0, "given back at %.0f s", t_back);
    fw_target g;
    CHECK(g_now(w, &g));
    CHECK_MSG(fabs(g.east) <= FW_SOURCE_REJOIN_MAX, "given back %.2f m off its lane", g.east);
    fw_world_destroy(w);
}

/* The steepest way back that is clear (steer.h, alter): a steered 150 m
 * ship 1000 m to starboard of its lane (course north) on its 20 deg
 * alteration at 10 m/s, the ship it gave way to past (the range opening)
 * 2 km off on its port quarter, going 345 at 10 m/s, converging on its
 * lane.  Neither its line of sight back nor its lane's course passes that
 * ship at the passing distance; a course between them does.  It comes back
 * on the steepest clear one, passes the other at the passing distance or
 * more and is on its lane within 15 minutes (measured: 681 s).  Before, it
 * held its alteration while neither cleared, and was not back in 20
 * minutes. */
static void test_steepest_clear_way_back(void)
{
    fw_alter_def def = fw_default_alter_def();
    def.lane = (fw_lane_info){.np = 2, .e = {0.0, 0.0}, .n = {-1e4, 5e4}};
    def.length = 150.0, def.breadth = 25.0, def.speed = 10.0;
    def.alteration = fw_deg_to_rad(20.0);
    snprintf(def.other, sizeof def.other, "%s", "other");
    fw_controller *c = NULL;
    fw_error err = {0};
    CHECK(fw_steer_controller_create(&def, &c, &err) == FW_OK);
    fw_own_state o = {.east = 1000.0, .psi = fw_deg_to_rad(20.0), .U = 10.0};
    fw_target t = ship_at(-1000.0, -500.0, 345.0, 10.0);
    double least = INFINITY, t_on = NAN, far = 0.0;
    fw_assessment as[1];
    int order[2];
    for (int k = 0; k < 1200; k++) {
        fw_sense in = {.t = k, .own = &o, .targets = &t, .n = 1, .as = as, .order = order};
        fw_decision d;
        CHECK(c->ops->decide(c, &in, &d, &err) == FW_OK);
        if (isnan(t_on) && strstr(d.reason, "to be given back"))
            t_on = k;
        o.U = d.speed;
        o.psi += FW_STEER_K_ND * o.U / 150.0 * d.helm;
        o.east += o.U * sin(o.psi), o.north += o.U * cos(o.psi);
        t.east += t.speed * sin(t.course), t.north += t.speed * cos(t.course);
        least = fmin(least, hypot(t.east - o.east, t.north - o.north));
        far = fmax(far, o.east);
    }
    printf("steepest clear way back: %.0f m off its lane at most, %.0f m from the other at "
           "least, on its lane at %.0f s\n", far, least, t_on);
    CHECK_MSG(least >= def.cpa, "passed %.0f m off", least);
    CHECK_MSG(t_on < 900.0, "on its lane at %.0f s", t_on);
    fw_controller_destroy(c);
}

/* Rule 17(a)(i) coming back (steer.h, return): a steered 150 m ship 800 m to
 * starboard of its lane, on its altered course 030 at 11 m/s, the ship it
 * gave way to past; a ship (6 m/s) crossing from its port side, 4.6 km off
 * 13 deg on its port bow, would pass 813 m off in 8 minutes on that course:
 * it is the stand-on ship and keeps its course (within 2 deg) until the
 * other is past, then comes back to its lane.  Before, it turned back at
 * once, 30 deg to port, under the bow of the ship giving way to it (a ferry
 * coming back onto the own ship turning to pass astern of it: dover-domain
 * seed 4, replication 18, on 8f2a074). */
static void test_return_stands_on(void)
{
    fw_controller *c = past_on_lane(11.0);
    fw_own_state o = {.east = 800.0, .psi = fw_deg_to_rad(30.0), .U = 11.0};
    fw_target t = ship_at(-250.0, 4500.0, 90.0, 6.0);
    double least, slowest, worst = 0.0;
    for (int k = 0; k < 470; k++) {
        sail_from(c, &o, &t, k, 1, &least, &slowest);
        worst = fmax(worst, fabs(fw_wrap_pi(o.psi - fw_deg_to_rad(30.0))));
    }
    CHECK_MSG(worst < fw_deg_to_rad(2.0), "turned %.1f deg off its course", fw_rad_to_deg(worst));
    sail_from(c, &o, &t, 470, 1500, &least, &slowest);
    CHECK_MSG(fabs(o.east) < 10.0, "%.0f m off its lane", o.east);
    fw_controller_destroy(c);
}

/* Coming back judged along the turn it makes (steer.h, alter and return):
 * a steered 150 m ship at 11.5 m/s (22 kn) 2 km to starboard of its lane
 * (course north), heading 045, the ship it gave way to past; a ship (2 m/s,
 * 150 m, heading 060) crawling 1273 m ahead of it.  Its way back, 90 deg
 * and less to port at the rate its helm turns it (K' U / L x 20 deg: a
 * radius of about 780 m), swings it north through the other's water; judged
 * along that swing it comes back only where that clears, and passes the
 * other 463 m (0.25 nm) or more between centres (measured: 854 m), back on
 * its lane within 25 minutes.  Before, each course back was judged as
 * steered at once (a straight line from where it was): their centres came
 * 250 m apart (strait-domain seed 3, replication 0: a 22 kn ferry swinging
 * back onto a ferry crawling ahead, hulls overlapping at 1813 s). */
static void test_way_back_judged_along_the_turn(void)
{
    fw_controller *c = past_on_lane(11.5);
    fw_own_state o = {.east = 2000.0, .psi = fw_deg_to_rad(45.0), .U = 11.5};
    fw_target t = ship_at(1992.0, 1273.0, 60.0, 2.0);
    double least, slowest;
    sail_pair(c, &o, &t, 1500, &least, &slowest);
    printf("way back along the turn: passed %.0f m off, %.0f m off its lane after 25 minutes\n",
           least, o.east);
    CHECK_MSG(least >= 463.0, "passed %.0f m off", least);
    CHECK_MSG(fabs(o.east) < 10.0, "%.0f m off its lane after 25 minutes", o.east);
    fw_controller_destroy(c);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3-paper", &own_ship, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_indices_are_the_c3s);
    TEST_RUN(test_model_turns_as_stated);
    TEST_RUN(test_crossing_alters_and_comes_back);
    TEST_RUN(test_cross_set_comes_back);
    TEST_RUN(test_no_room_slows);
    TEST_RUN(test_speed_mode_unchanged);
    TEST_RUN(test_head_on_alters);
    TEST_RUN(test_follows_a_slower_ship_ahead);
    TEST_RUN(test_steerage_way_over_ground_in_a_head_stream);
    TEST_RUN(test_close_quarters_keeps_way_out_of_a_lane);
    TEST_RUN(test_converging_from_abeam_is_crossing);
    TEST_RUN(test_overtaking_a_ship_moving_off);
    TEST_RUN(test_return_holds_course_across_a_ship_ahead);
    TEST_RUN(test_close_quarters_judged_along_the_turn);
    TEST_RUN(test_comes_back_when_clear);
    TEST_RUN(test_steepest_clear_way_back);
    TEST_RUN(test_return_stands_on);
    TEST_RUN(test_way_back_judged_along_the_turn);
    return TEST_EXIT();
}
