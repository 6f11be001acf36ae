/* Encounter assessment, COLREGs classification, helm search, action policy. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/policy.h"
#include "core/units.h"
#include "nomoto/nomoto.h"
#include "test.h"
#include "traffic/source.h"
#include "world/controllers.h"
#include "world/world.h"

static fw_ship c3;

static fw_target target_at(double rel_bearing_deg, double range, double course_deg, double kn)
{
    double b = fw_deg_to_rad(rel_bearing_deg);
    return (fw_target){.east = range * sin(b), .north = range * cos(b),
                       .course = fw_deg_to_rad(course_deg), .heading = fw_deg_to_rad(course_deg), .speed = fw_kn_to_ms(kn)};
}

static void test_classification_table(void)
{
    fw_colregs_def def = fw_default_colregs_def();
    fw_own_state own = {.U = fw_kn_to_ms(10)}; /* at the origin, heading north */
    static const struct {
        double bearing, course, kn;
        fw_situation want;
    } rows[] = {
        {0, 180, 10, FW_SIT_HEAD_ON},
        {5.9, 180, 10, FW_SIT_HEAD_ON},         /* just inside the 6 deg head-on bearing */
        {6.5, 180, 10, FW_SIT_GIVE_WAY},        /* just outside: crossing from starboard */
        {354.1, 180, 10, FW_SIT_HEAD_ON},
        {353.5, 180, 10, FW_SIT_STAND_ON},
        {0, 175, 10, FW_SIT_HEAD_ON},           /* own ship 5 deg off the target's bow */
        {0, 173, 10, FW_SIT_GIVE_WAY},          /* 7 deg off: a crossing ship dead ahead */
        {0, 0, 6, FW_SIT_OVERTAKING},           /* slower ship dead ahead, same course */
        {0, 0, 14, FW_SIT_GIVE_WAY},            /* faster ahead: opening, not overtaking */
        {45, 270, 10, FW_SIT_GIVE_WAY},
        {315, 90, 10, FW_SIT_STAND_ON},
        {112.5, 0, 14, FW_SIT_GIVE_WAY},        /* exactly 22.5 abaft the beam: not "more than" */
        {113.0, 0, 14, FW_SIT_OVERTAKEN},
        {180, 0, 14, FW_SIT_OVERTAKEN},
        {247.0, 0, 14, FW_SIT_OVERTAKEN},
        {247.5, 0, 14, FW_SIT_STAND_ON},
        {180, 0, 6, FW_SIT_STAND_ON},           /* slower astern: not overtaking us */
        {90, 0, 10, FW_SIT_GIVE_WAY},
        {270, 0, 10, FW_SIT_STAND_ON},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        fw_target t = target_at(rows[i].bearing, 2000, rows[i].course, rows[i].kn);
        fw_situation got = fw_classify(&def, &own, &t);
        CHECK_MSG(got == rows[i].want, "bearing %.1f course %.0f %.0f kn: %s, want %s",
                  rows[i].bearing, rows[i].course, rows[i].kn, fw_situation_name(got),
                  fw_situation_name(rows[i].want));
    }
    /* own ship overtaking: own in the target's stern sector, own faster; the
     * boundary is the target's 112.5 deg bearing to the own ship */
    fw_target t = {.east = 2000 * sin(fw_deg_to_rad(67.4)), .north = 2000 * cos(fw_deg_to_rad(67.4)),
                   .course = 0, .heading = 0, .speed = fw_kn_to_ms(5)};
    CHECK(fw_classify(&def, &own, &t) == FW_SIT_OVERTAKING);
    t.east = 2000 * sin(fw_deg_to_rad(67.6)), t.north = 2000 * cos(fw_deg_to_rad(67.6));
    CHECK(fw_classify(&def, &own, &t) == FW_SIT_GIVE_WAY);
}

static void test_assessment_and_ranking(void)
{
    fw_colregs_def cdef = fw_default_colregs_def();
    fw_domain_def dom = fw_default_domain_def();
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    fw_target t[3] = {
        target_at(45, 2000, 270, 8),  /* passes well clear */
        {.east = 0, .north = 3000, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(8)}, /* head-on */
        {.east = 0, .north = 1500, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(8)}, /* head-on, nearer */
    };
    t[0].east = 3000; /* crossing far off: DCPA large */
    fw_assessment as[3];
    int order[6];
    fw_assess(&cdef, &dom, 600, &own, t, 3, as, order);
    double closing = fw_kn_to_ms(18);
    CHECK_NEAR(as[1].tcpa, 3000 / closing, 1e-9);
    CHECK_NEAR(as[1].dcpa, 0, 1e-9);
    CHECK_NEAR(as[1].t_enter, 2700 / closing, 1e-9);
    CHECK_NEAR(as[2].t_enter, 1200 / closing, 1e-9);
    CHECK(order[0] == 2 && order[1] == 1 && order[2] == 0);
    CHECK(as[2].rank == 0 && as[0].rank == 2);
    /* a target hull grows the domain: 300 m abeam + half its length when it lies
     * across the own ship */
    fw_target big = {.east = 0, .north = 0, .course = FW_PI / 2, .heading = FW_PI / 2, .length = 200, .breadth = 30};
    double a, b;
    fw_domain_axes(&dom, &big, cos(big.course), sin(big.course), &a, &b);
    CHECK_NEAR(a, 315, 1e-9);
    CHECK_NEAR(b, 400, 1e-9);
}

static fw_helm_ctx *make_ctx(fw_helm_def *def)
{
    fw_helm_ctx *ctx;
    fw_error err = {0};
    CHECK_MSG(fw_helm_ctx_create(&c3, def, &ctx, &err) == FW_OK, "%s", err.msg);
    return ctx;
}

static void test_more_helm_more_clearance(void)
{
    fw_helm_def def = fw_default_helm_def();
    fw_helm_ctx *ctx = make_ctx(&def);
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    fw_target cases[3] = {
        {.east = 0, .north = 1900, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(10)},
        {.east = 1300, .north = 1900, .course = 1.5 * FW_PI, .heading = 1.5 * FW_PI, .speed = fw_kn_to_ms(10)},
        {.east = 30, .north = 2500, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(8), .length = 300, .breadth = 40},
    };
    fw_helm_begin(ctx, &own);
    for (int c = 0; c < 3; c++) {
        double prev = 0, prev_d = 0;
        for (int i = 0; i < fw_helm_count(ctx); i++) {
            const fw_track *tr;
            CHECK(fw_helm_track(ctx, FW_SIDE_STARBOARD, i, &tr, NULL) == FW_OK);
            double cl = fw_track_clearance(&def, tr, &cases[c], 1, 0.0, NULL);
            double d = fw_track_min_distance(tr, &cases[c], NULL);
            /* Strictly non-decreasing up to just outside the domain.  Well outside
             * it a tighter turn can pass a few tenths of a percent closer: it has
             * less advance, so once the target is astern it lags less far behind
             * it; that never turns a clearing helm into a failing one. */
            if (prev < 1.1)
                CHECK_MSG(cl >= prev - 1e-9, "case %d helm %d: clearance %.4f < %.4f", c, i, cl, prev);
            else
                CHECK_MSG(cl >= prev * 0.99, "case %d helm %d: clearance %.4f < %.4f", c, i, cl, prev);
            CHECK_MSG(d >= prev_d * 0.99, "case %d helm %d: distance %.1f < %.1f", c, i, d, prev_d);
            CHECK(!(prev >= 1.0 && cl < 1.0));
            prev = cl, prev_d = d;
        }
    }
    /* port tracks were mirrored, not computed: 26 starboard tracks only */
    const fw_track *tr;
    for (int i = 0; i < fw_helm_count(ctx); i++)
        fw_helm_track(ctx, FW_SIDE_PORT, i, &tr, NULL);
    CHECK(fw_helm_tracks_computed(ctx) == fw_helm_count(ctx));
    fw_helm_ctx_destroy(ctx);
}

/* Rule 19(d) (helm_search.h fw_permitted_sides): one target at a time at
 * relative bearing rb, 3 km off, on a collision course (meeting the own ship
 * 600 s on), in clear weather and with a visibility of 500 m (out of sight). */
static int sides_for(double rb_deg, double visibility)
{
    fw_helm_def def = fw_default_helm_def();
    def.colregs.visibility = visibility;
    fw_own_state own = {.U = 6.0};
    double rb = fw_deg_to_rad(rb_deg), T = 600.0;
    fw_target t = {.east = 3000.0 * sin(rb), .north = 3000.0 * cos(rb)};
    double ve = -t.east / T, vn = (own.U * T - t.north) / T;
    t.course = t.heading = fw_wrap_2pi(atan2(ve, vn));
    t.speed = hypot(ve, vn);
    fw_assessment as;
    int order[2];
    fw_assess(&def.colregs, &def.domain, def.track.horizon, &own, &t, 1, &as, order);
    CHECK(as.enters_domain && as.rule19 == (visibility > 0.0));
    return fw_permitted_sides(&def, &as, 1);
}

static void test_rule19_sides(void)
{
    /* forward of the beam: never to port, but for a ship the own ship overtakes */
    CHECK(sides_for(45.0, 500.0) == FW_ALLOW_STARBOARD);
    CHECK(sides_for(315.0, 500.0) == FW_ALLOW_STARBOARD);
    CHECK(sides_for(0.0, 500.0) == FW_ALLOW_EITHER); /* slower, ahead: overtaken by us */
    /* abeam and abaft: not towards it */
    CHECK(sides_for(135.0, 0.0) == FW_ALLOW_EITHER); /* clear: being overtaken, to starboard */
    CHECK(sides_for(135.0, 500.0) == FW_ALLOW_PORT);
    CHECK(sides_for(90.0, 500.0) == FW_ALLOW_PORT);
    CHECK(sides_for(225.0, 500.0) == FW_ALLOW_STARBOARD);
}

static void test_only_one_side_works(void)
{
    fw_helm_def def = fw_default_helm_def();
    fw_helm_ctx *ctx = make_ctx(&def);
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    for (int mirror = 0; mirror < 2; mirror++) {
        double sgn = mirror ? -1 : 1;
        /* a slow ship ahead to overtake (either side allowed), and a ship
         * meeting 500 m off on one side (no threat on the present course) that
         * blocks a turn that way */
        fw_target t[2] = {
            {.east = 0, .north = 900, .course = 0, .heading = 0, .speed = fw_kn_to_ms(3)},
            {.east = -500 * sgn, .north = 2200, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(10)},
        };
        fw_assessment as[2];
        int order[4];
        fw_assess(&def.colregs, &def.domain, def.track.horizon, &own, t, 2, as, order);
        CHECK(as[0].situation == FW_SIT_OVERTAKING && as[0].enters_domain);
        CHECK(!as[1].enters_domain);
        int allowed = fw_permitted_sides(&def, as, 2);
        CHECK(allowed == FW_ALLOW_EITHER);
        fw_helm_result r;
        fw_helm_begin(ctx, &own);
        CHECK(fw_helm_search(ctx, t, 2, allowed, &r, NULL) == FW_OK);
        CHECK(r.threat && r.feasible);
        CHECK_MSG(r.side == (mirror ? FW_SIDE_PORT : FW_SIDE_STARBOARD), "mirror %d side %d", mirror, r.side);
        CHECK(r.clearance >= 1.0);
        CHECK(isnan(r.side_helm[mirror ? 0 : 1]));
        /* with starboard forced (mirror case), no helm clears: best action taken */
        if (mirror) {
            fw_helm_begin(ctx, &own);
            CHECK(fw_helm_search(ctx, t, 2, FW_ALLOW_STARBOARD, &r, NULL) == FW_OK);
            CHECK(!r.feasible && r.side == FW_SIDE_STARBOARD && r.clearance < 1.0);
        }
    }
    /* two head-on ships 300 m apart: starboard is required; only a hard turn
     * passes both (the paper's complex head-on case) */
    fw_target two[2] = {
        {.east = -150, .north = 1850, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(8)},
        {.east = 150, .north = 1850, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(8)},
    };
    fw_assessment as[2];
    int order[4];
    fw_assess(&def.colregs, &def.domain, def.track.horizon, &own, two, 2, as, order);
    CHECK(fw_permitted_sides(&def, as, 2) == FW_ALLOW_STARBOARD);
    fw_helm_result r;
    fw_helm_begin(ctx, &own);
    CHECK(fw_helm_search(ctx, two, 2, FW_ALLOW_STARBOARD, &r, NULL) == FW_OK);
    CHECK(r.feasible && r.side == FW_SIDE_STARBOARD && fw_rad_to_deg(r.helm) > 20);
    fw_helm_ctx_destroy(ctx);
}

/* The policy in closed loop with the Nomoto plant (one second per step) and
 * constant-velocity targets; what a scenario test asserts, without SUMO. */
typedef struct loop_out {
    double t_act, t_return, t_back, min_lambda, min_dist, max_psi, final_psi;
    int first_side, acts;
    fw_situation first_sit;
    fw_policy_mode final_mode;
} loop_out;

static loop_out closed_loop(const fw_target *t0, int n, int seconds)
{
    loop_out o = {.t_act = -1, .t_return = -1, .t_back = -1, .min_lambda = INFINITY,
                  .min_dist = INFINITY};
    fw_error err = {0};
    /* the world: the targets from the kinematic source (all seen), the own
     * ship a Nomoto plant under the policy */
    fw_kin_ship ships[4];
    for (int i = 0; i < n; i++) {
        ships[i] = (fw_kin_ship){.start = t0[i]};
        if (!ships[i].start.id[0])
            snprintf(ships[i].start.id, sizeof ships[i].start.id, "T%d", i + 1);
    }
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ships;
    kd.n = n;
    fw_world_def wd = fw_default_world_def();
    fw_policy_controller_def pd = {.ship = &c3, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    fw_own_state start = {.U = fw_kn_to_ms(10)};
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &c3;
    vd.dynamics = FW_DYN_NOMOTO;
    vd.start_state = &start;
    vd.radius = INFINITY;
    fw_world *w = NULL;
    fw_vessel *own = NULL;
    fw_vessel_handle oh = {0};
    CHECK_MSG(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK &&
                  fw_world_create(&wd, &w, &err) == FW_OK &&
                  fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK &&
                  fw_world_add_vessel(w, &vd, &oh, &err) == FW_OK &&
                  fw_world_start(w, &err) == FW_OK,
              "%s", err.msg);
    own = w ? fw_world_vessel(w, oh) : NULL;
    if (!own) {
        fw_world_destroy(w);
        return o;
    }
    const fw_policy *pol = fw_policy_controller_policy(fw_vessel_controller(own));
    fw_policy_mode before = FW_MODE_STANDBY;
    for (int k = 0; k < seconds; k++) {
        const fw_own_state *x = fw_vessel_own_state(own);
        const fw_target *now;
        const fw_assessment *as;
        int m;
        fw_vessel_view(own, &now, &as, &m);
        for (int i = 0; i < m; i++) {
            o.min_lambda = fmin(o.min_lambda,
                                fw_domain_lambda(&pd.helm.domain, x->east, x->north, x->psi, &now[i]));
            o.min_dist = fmin(o.min_dist, hypot(now[i].east - x->east, now[i].north - x->north));
        }
        const fw_decision *d = fw_vessel_decision(own);
        if (d->acted && o.acts++ == 0) {
            o.t_act = k;
            o.first_side = d->search.side;
            o.first_sit = as[d->primary].situation;
        }
        if ((before == FW_MODE_AVOID || before == FW_MODE_STEADY) &&
            d->mode == FW_MODE_AUTOPILOT && o.t_return < 0)
            o.t_return = k;
        if (before == FW_MODE_AUTOPILOT && d->mode == FW_MODE_STANDBY && o.t_back < 0)
            o.t_back = k;
        before = d->mode;
        o.final_mode = pol->mode;
        o.max_psi = fmax(o.max_psi, x->psi);
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
    }
    o.final_psi = fw_wrap_pi(fw_vessel_own_state(own)->psi);
    fw_world_destroy(w);
    return o;
}

/* Closed loop on the Nomoto plant itself: the head-on case from t = 0. */
static void test_policy_head_on_cycle(void)
{
    fw_target t = {.east = 0, .north = 2000, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(10)};
    loop_out o = closed_loop(&t, 1, 1500);
    CHECK_MSG(o.t_act >= 0 && o.t_act <= 20, "acted at %.0f s", o.t_act);
    CHECK_MSG(o.min_dist >= 295, "closest approach %.0f m", o.min_dist);
    CHECK_MSG(o.t_return > o.t_act && o.t_back > o.t_return, "return %.0f done %.0f", o.t_return,
              o.t_back);
    CHECK_NEAR(o.final_psi, 0.0, fw_deg_to_rad(1.5));
    CHECK(o.max_psi > fw_deg_to_rad(20)); /* a substantial, readily apparent alteration */
    CHECK(o.final_mode == FW_MODE_STANDBY);
    printf("  head-on closed loop: act %.0f s, return %.0f s, back on course %.0f s, "
           "closest %.0f m, max alteration %.0f deg\n",
           o.t_act, o.t_return, o.t_back, o.min_dist, fw_rad_to_deg(o.max_psi));
}

/* The policy follows the target it acted for by id while the caller reorders
 * the array every step (as a traffic layer may): it returns only once that
 * target is passing (TCPA < 0), not when the ship now at its old index is. */
static void test_policy_follows_target_id(void)
{
    fw_helm_def hdef = fw_default_helm_def();
    fw_helm_ctx *ctx = make_ctx(&hdef);
    fw_policy_def pdef = fw_default_policy_def();
    fw_policy pol;
    fw_policy_init(&pol, &pdef);
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    /* B: head-on; A: far off on the port quarter, opening (TCPA < 0 throughout) */
    fw_target b = {.id = "veh.B", .east = 0, .north = 2000, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(10)};
    fw_target a = {.id = "veh.A", .east = -4000, .north = -3000, .course = 1.5 * FW_PI, .heading = 1.5 * FW_PI,
                   .speed = fw_kn_to_ms(12)};
    fw_track_def one = {.dt = 1.0, .horizon = 1.0};
    fw_track step;
    fw_track_alloc(&step, 2, NULL);
    fw_assessment as[2];
    int order[4];
    bool acted = false, countered = false;
    for (int k = 0; k < 900 && !countered; k++) {
        fw_target now[2] = {b, a};
        for (int i = 0; i < 2; i++) {
            now[i].east += now[i].speed * sin(now[i].course) * k;
            now[i].north += now[i].speed * cos(now[i].course) * k;
        }
        if (k % 2) { /* swap the order every other step */
            fw_target tmp = now[0];
            now[0] = now[1], now[1] = tmp;
        }
        fw_decision d;
        fw_policy_mode before = pol.mode;
        fw_policy_input in = {.ctx = ctx, .helm = &hdef, .t = k, .own = &own, .targets = now,
                              .n = 2, .as = as, .order = order};
        CHECK(fw_policy_step(&pol, &in, &d, NULL) == FW_OK);
        if (d.acted) {
            acted = true;
            CHECK_MSG(strcmp(now[d.primary].id, "veh.B") == 0, "acted for %s", now[d.primary].id);
            CHECK(strcmp(pol.primary_id, "veh.B") == 0);
        }
        if ((before == FW_MODE_AVOID || before == FW_MODE_STEADY) && d.mode == FW_MODE_AUTOPILOT) {
            countered = true;
            int ib = fw_target_find(now, 2, "veh.B");
            CHECK(ib >= 0);
            CHECK_MSG(as[ib].tcpa < 0.0, "returned at %d s with B's TCPA %.0f s", k, as[ib].tcpa);
        }
        fw_track_predict(&c3, &one, &own, d.helm, &step, NULL);
        own.east = step.east[1], own.north = step.north[1], own.psi = step.psi[1];
        own.r = step.r[1], own.delta = step.delta[1], own.rdot = step.rdot[1];
    }
    CHECK(acted && countered);
    CHECK(fw_target_find(&a, 1, "") == -1 && fw_target_find(&a, 1, "veh.B") == -1);
    fw_track_free(&step);
    fw_helm_ctx_destroy(ctx);
}

/* Rule 17: a crossing ship on the port side that does not give way.  The own
 * ship keeps course and speed while its own action could still wait two
 * minutes, then turns to starboard, never to port, keeps the domain, and
 * comes back to its course. */
static void test_policy_stand_on_rule_17(void)
{
    /* on a collision course: both reach (0, 3000) at t = 583 s */
    fw_target t = {.id = "T", .east = -3000, .north = 3000, .course = FW_PI / 2, .heading = FW_PI / 2,
                   .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32};
    loop_out o = closed_loop(&t, 1, 2400);
    CHECK(o.first_sit == FW_SIT_STAND_ON);
    CHECK(o.first_side == FW_SIDE_STARBOARD);
    /* not before the give-way ship has had time: entry would be >= 2 min away */
    CHECK_MSG(o.t_act > 200 && o.t_act < 500, "acted at %.0f s", o.t_act);
    CHECK_MSG(o.min_lambda >= 1.0, "domain radius %.2f", o.min_lambda);
    CHECK_MSG(o.t_back > o.t_act, "back on course at %.0f s", o.t_back);
    CHECK_NEAR(o.final_psi, 0.0, fw_deg_to_rad(2.0));
    printf("  stand-on: acted at %.0f s (collision point at 583 s), closest radius %.2f, "
           "back on course at %.0f s\n", o.t_act, o.min_lambda, o.t_back);
}

/* A ship converging slowly from the port bow at the own speed (Imazu case 10's
 * second target) stays near: the own ship must not turn back into it, and must
 * still come back to its course once it is clear. */
static void test_policy_return_only_when_clear(void)
{
    fw_target t = {.id = "P", .east = -2876, .north = 378, .course = fw_deg_to_rad(15), .heading = fw_deg_to_rad(15),
                   .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32};
    loop_out o = closed_loop(&t, 1, 4000);
    CHECK(o.acts >= 1);
    CHECK_MSG(o.min_lambda >= 1.0, "domain radius %.2f", o.min_lambda);
    CHECK_MSG(o.t_back > 0, "never back on course (heading %.1f deg at the end)",
              fw_rad_to_deg(o.final_psi));
    CHECK_NEAR(o.final_psi, 0.0, fw_deg_to_rad(2.0));
    printf("  pacing ship: %d actions from %.0f s, closest radius %.2f, back on course at %.0f s\n",
           o.acts, o.t_act, o.min_lambda, o.t_back);
}

/* Predictors (geom/target.h): a ship that keeps its course until t_turn and
 * then takes new_course at the same speed. */
typedef struct turn_pred {
    fw_predictor base;
    double t_turn, new_course;
} turn_pred;

static void turn_path(const fw_predictor *self, const fw_target *now, double dt, int n,
                      double *east, double *north, double *course)
{
    const turn_pred *p = (const turn_pred *)self;
    double te = now->east + now->speed * sin(now->course) * p->t_turn;
    double tn = now->north + now->speed * cos(now->course) * p->t_turn;
    for (int k = 0; k < n; k++) {
        double t = k * dt;
        bool after = t > p->t_turn;
        double c = after ? p->new_course : now->course, s = after ? t - p->t_turn : t;
        east[k] = (after ? te : now->east) + now->speed * sin(c) * s;
        north[k] = (after ? tn : now->north) + now->speed * cos(c) * s;
        course[k] = c;
    }
}

/* The helm search and the assessment use a target's predictor: one that
 * only restates constant velocity changes nothing; one that turns the target
 * onto the own track makes a threat of a ship that would pass 2 km off, and
 * the helm found keeps the predicted ship out (checked sample by sample). */
static void test_predictor_is_used(void)
{
    fw_helm_def hdef = fw_default_helm_def();
    fw_helm_ctx *ctx = make_ctx(&hdef);
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    turn_pred never = {.base = {.path = turn_path}, .t_turn = 1e9};
    /* a crossing give-way, a head-on and one passing clear */
    fw_target scene[3] = {target_at(45, 3000, 270, 10), target_at(2, 4000, 180, 12),
                          target_at(300, 5000, 0, 8)};
    fw_assessment a0[3], a1[3];
    fw_helm_result r0, r1;
    fw_assess(&hdef.colregs, &hdef.domain, hdef.track.horizon, &own, scene, 3, a0, NULL);
    fw_helm_begin(ctx, &own);
    CHECK(fw_helm_search(ctx, scene, 3, FW_ALLOW_STARBOARD, &r0, NULL) == FW_OK);
    fw_target same[3];
    for (int i = 0; i < 3; i++) {
        same[i] = scene[i];
        same[i].pred = &never.base;
    }
    fw_assess(&hdef.colregs, &hdef.domain, hdef.track.horizon, &own, same, 3, a1, NULL);
    fw_helm_begin(ctx, &own);
    CHECK(fw_helm_search(ctx, same, 3, FW_ALLOW_STARBOARD, &r1, NULL) == FW_OK);
    CHECK(r0.threat && r0.threat == r1.threat && r0.feasible == r1.feasible && r0.helm == r1.helm);
    /* INFINITY where every chunk of the track was culled */
    CHECK(r0.clearance == r1.clearance || fabs(r0.clearance - r1.clearance) <= 1e-9);
    CHECK(r0.keep_clearance == r1.keep_clearance ||
          fabs(r0.keep_clearance - r1.keep_clearance) <= 1e-9);
    for (int i = 0; i < 3; i++) {
        CHECK(a0[i].enters_domain == a1[i].enters_domain);
        /* sampled every 5 s against the closed form */
        CHECK_NEAR(a0[i].min_lambda, a1[i].min_lambda, 0.01);
        if (a0[i].enters_domain)
            CHECK_NEAR(a0[i].t_enter, a1[i].t_enter, 5.0);
    }
    /* 2 km to starboard on a reciprocal course: passes clear at constant
     * velocity; the predictor turns it west at 146 s, which brings it across
     * the own track just as the own ship gets there (both at 10 kn: at 535 s) */
    fw_target t = {.id = "T", .east = 2000, .north = 3500, .course = FW_PI, .heading = FW_PI,
                   .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32};
    turn_pred turn = {.base = {.path = turn_path}, .t_turn = 146.0, .new_course = 1.5 * FW_PI};
    fw_assess(&hdef.colregs, &hdef.domain, hdef.track.horizon, &own, &t, 1, a0, NULL);
    CHECK(!a0[0].enters_domain);
    t.pred = &turn.base;
    fw_assess(&hdef.colregs, &hdef.domain, hdef.track.horizon, &own, &t, 1, a1, NULL);
    CHECK_MSG(a1[0].enters_domain && a1[0].t_enter > 150.0, "predicted entry at %.0f s",
              a1[0].t_enter);
    fw_helm_begin(ctx, &own);
    CHECK(fw_helm_search(ctx, &t, 1, FW_ALLOW_EITHER, &r1, NULL) == FW_OK);
    CHECK(r1.threat && r1.feasible && r1.side != FW_SIDE_NONE);
    const fw_track *tr;
    int side_i = (int)lround((fw_rad_to_deg(fabs(r1.helm)) - hdef.min_helm_deg) / hdef.step_deg);
    CHECK(fw_helm_track(ctx, r1.side, side_i, &tr, NULL) == FW_OK);
    double e[200], n[200], c[200], worst = INFINITY;
    fw_target_path(&t, tr->dt, tr->n, e, n, c);
    for (int k = 0; k < tr->n; k++) {
        fw_target at = t;
        at.east = e[k], at.north = n[k], at.course = at.heading = c[k], at.pred = NULL;
        worst = fmin(worst, fw_domain_lambda(&hdef.domain, tr->east[k], tr->north[k], tr->psi[k], &at));
    }
    CHECK_MSG(worst >= 0.99, "the chosen track lets the predicted ship in: %.3f", worst);
    printf("  predictor: entry at %.0f s predicted (none at constant velocity); %s %.0f deg "
           "keeps it at %.2f of the domain\n",
           a1[0].t_enter, fw_side_name(r1.side), fw_rad_to_deg(fabs(r1.helm)), worst);
    fw_helm_ctx_destroy(ctx);
}

/* Smallest normalised domain radius of target t (constant velocity) along
 * track tr, sampled every `sub`-th of the track's interval (the track's
 * positions interpolated linearly): the brute force the segment tests and the
 * closed form are checked against. */
static double sampled_lambda(const fw_domain_def *dom, const fw_track *tr, const fw_target *t,
                             int sub)
{
    double best = INFINITY;
    for (int k = 0; k + 1 < tr->n; k++)
        for (int j = 0; j < sub; j++) {
            double f = (double)j / sub, tk = (k + f) * tr->dt;
            double psi = tr->psi[k] + f * (tr->psi[k + 1] - tr->psi[k]);
            fw_target at = *t;
            at.east += t->speed * sin(t->course) * tk;
            at.north += t->speed * cos(t->course) * tk;
            best = fmin(best, fw_domain_lambda(dom, tr->east[k] + f * (tr->east[k + 1] - tr->east[k]),
                                               tr->north[k] + f * (tr->north[k + 1] - tr->north[k]),
                                               psi, &at));
        }
    return best;
}

/* The paper's transverse reading (geom.h) through the assessment's closed
 * form, the helm search's segment tests and its least helm. */
static void test_transverse_reading(void)
{
    fw_helm_def el = fw_default_helm_def(), tv = el;
    tv.domain.reading = FW_DOMAIN_TRANSVERSE;
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    fw_target t[2] = {
        {.id = "H", .east = 0, .north = 2000, .course = FW_PI, .heading = FW_PI, .speed = fw_kn_to_ms(10),
         .length = 200, .breadth = 32},
        {.id = "C", .east = 2000, .north = 2000, .course = 1.5 * FW_PI, .heading = 1.5 * FW_PI,
         .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32},
    };
    /* the assessment on the straight course against 0.5 s samples */
    fw_assessment as[2];
    fw_assess(&tv.colregs, &tv.domain, 600.0, &own, t, 2, as, NULL);
    for (int i = 0; i < 2; i++) {
        double best = INFINITY, t_in = INFINITY;
        for (double s = 0.0; s <= 600.0; s += 0.5) {
            fw_target at = t[i];
            at.east += t[i].speed * sin(t[i].course) * s;
            at.north += t[i].speed * cos(t[i].course) * s;
            double l = fw_domain_lambda(&tv.domain, 0.0, own.U * s, 0.0, &at);
            best = fmin(best, l);
            if (l < 1.0 && isinf(t_in))
                t_in = s;
        }
        /* a sample is at most 0.25 s (2.6 m, 0.008 of 316 m) from the minimum */
        CHECK_NEAR(as[i].min_lambda, best, 0.01);
        CHECK(as[i].enters_domain);
        CHECK_NEAR(as[i].t_enter, t_in, 0.5);
    }
    /* head-on, centre to centre 300 m + 16 m abeam: the target dead ahead on
     * the reciprocal enters 400 m from its centre (300 m off its bow) */
    CHECK_NEAR(as[0].t_enter, (2000.0 - 400.0) / (2 * own.U), 1e-9);
    /* the search's clearance of every starboard candidate against 10-per-
     * interval samples, and the least clearing helm of each reading */
    int least[2] = {-1, -1};
    for (int r = 0; r < 2; r++) {
        fw_helm_def *d = r ? &tv : &el;
        fw_helm_ctx *ctx = make_ctx(d);
        fw_helm_begin(ctx, &own);
        for (int i = 0; i < fw_helm_count(ctx); i++) {
            const fw_track *tr;
            CHECK(fw_helm_track(ctx, FW_SIDE_STARBOARD, i, &tr, NULL) == FW_OK);
            double cl = fw_track_clearance(d, tr, &t[0], 1, 0.0, NULL);
            double bf = sampled_lambda(&d->domain, tr, &t[0], 10);
            CHECK_MSG(fabs(cl - bf) < 0.01, "%s helm %d: clearance %.4f, sampled %.4f",
                      fw_domain_reading_name(d->domain.reading), i, cl, bf);
            if (least[r] < 0 && cl >= 1.0)
                least[r] = i;
        }
        fw_helm_ctx_destroy(ctx);
    }
    /* the ellipse turns with the own ship and projects the target's hull on
     * its axes (382 m abeam after a 45 deg turn): the transverse clearance
     * (316 m from the centre abeam of the target) needs less helm */
    CHECK_MSG(least[1] >= 0 && (least[0] < 0 || least[1] < least[0]),
              "least clearing helm: ellipse %d, transverse %d (index from 10 deg)", least[0],
              least[1]);
    printf("  head-on at 2000 m, 10 kn each: least clearing helm from t = 0: ellipse %d deg "
           "(-1: none), transverse %d deg\n", least[0] < 0 ? -1 : least[0] + 10, least[1] + 10);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_classification_table);
    TEST_RUN(test_assessment_and_ranking);
    TEST_RUN(test_more_helm_more_clearance);
    TEST_RUN(test_only_one_side_works);
    TEST_RUN(test_rule19_sides);
    TEST_RUN(test_predictor_is_used);
    TEST_RUN(test_transverse_reading);
    TEST_RUN(test_policy_head_on_cycle);
    TEST_RUN(test_policy_follows_target_id);
    TEST_RUN(test_policy_stand_on_rule_17);
    TEST_RUN(test_policy_return_only_when_clear);
    return TEST_EXIT();
}
