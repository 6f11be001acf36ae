/* test_env.c - the environment in the world (env/env.h): current and wind.
 *
 *   an MMG ship (c3-mmg) under helm manoeuvres (turns both ways, a 10/10
 *     zigzag, hard over) for one simulated hour in a uniform current: its
 *     ground track is the calm-water track shifted by current x time, to
 *     0.1 m at every step, its heading the calm one (the MMG equations see
 *     only the velocity through the water, dynamics/stepper.h)
 *   the same in a tidal stream whose rate changes over the hour: the shift
 *     is the current's integral, computed in closed form (fw_current_drift)
 *   a current of zero takes the calm path: every state bit-identical
 *   the record of a ship set sideways: heading and stw through the water,
 *     course and speed over ground by the triangle of velocities (atan2)
 *   the Nomoto track prediction in a current is the calm one plus current x t
 *   the helm search in a current (its speed bound and mirror shortcut
 *     generalised) decides as the plain reference search does, to the bit
 *   a steered leg in a cross current: the ship crabs by asin(c across / U)
 *     and keeps its track, its autopilot's orders outside the dead band
 *   a turning circle in a uniform current: its 360 and 720 deg points
 *     current x time apart, its IMO measures (in the water) the calm ones
 *   a world refuses a wind on a ship without windage or with Nomoto
 *     dynamics, and a bad field
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/helm_search.h"
#include "avoid/route.h"
#include "core/units.h"
#include "decide_scenes.h"
#include "dynamics/manoeuvre.h"
#include "env/env.h"
#include "helm_reference.h"
#include "nomoto/track.h"
#include "test.h"
#include "test_ship.h"
#include "world/controllers.h"
#include "world/world.h"


/* fw_world_add_vessel, the vessel borrowed by pointer (world.h: valid until
 * it is removed; these tests remove none). */
static fw_status add_vessel(fw_world *w, const fw_vessel_def *vd, fw_vessel **v, fw_error *err)
{
    fw_vessel_handle h;
    fw_status st = fw_world_add_vessel(w, vd, &h, err);
    *v = st ? NULL : fw_world_vessel(w, h);
    return st;
}

static fw_ship mmg;

/* A helm by the clock and the heading: 20 deg starboard for 5 minutes, a
 * 10/10 zigzag for 20 minutes, 35 deg port for 5 minutes, amidships, then
 * 20 deg starboard again to the end. */
typedef struct helm_script {
    fw_controller base;
    double psi0;
    double zig; /* the zigzag's present helm */
} helm_script;

static fw_status script_decide(fw_controller *c, const fw_sense *in, fw_decision *d,
                               fw_error *err)
{
    (void)err;
    helm_script *h = (helm_script *)c;
    double t = in->t, helm = 0.0, ten = fw_deg_to_rad(10.0);
    if (t >= 300.0 && t < 600.0) {
        helm = fw_deg_to_rad(20.0);
    } else if (t >= 600.0 && t < 1800.0) {
        if (h->zig == 0.0)
            h->zig = ten, h->psi0 = in->own->psi;
        double dev = in->own->psi - h->psi0;
        if (h->zig > 0.0 && dev > ten)
            h->zig = -ten;
        else if (h->zig < 0.0 && dev < -ten)
            h->zig = ten;
        helm = h->zig;
    } else if (t >= 1800.0 && t < 2100.0) {
        helm = -fw_deg_to_rad(35.0);
    } else if (t >= 2700.0) {
        helm = fw_deg_to_rad(20.0);
    }
    *d = (fw_decision){.mode = FW_MODE_AVOID, .helm = helm, .primary = -1};
    return FW_OK;
}

static void script_destroy(fw_controller *c) { free(c); }

static const fw_controller_ops script_ops = {.name = "script", .decide = script_decide,
                                             .destroy = script_destroy};

static fw_controller *script(void)
{
    helm_script *h = calloc(1, sizeof *h);
    h->base.ops = &script_ops;
    return &h->base;
}

/* A world with one MMG vessel of `mmg` at 12 kn heading 030 under the script. */
static fw_world *world_in(const fw_env *env, fw_vessel **v)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env = *env;
    fw_world *w = NULL;
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &mmg;
    vd.east = 100.0, vd.north = -200.0, vd.course = fw_deg_to_rad(30.0);
    vd.speed = fw_kn_to_ms(12.0);
    vd.controller = script();
    CHECK_MSG(add_vessel(w, &vd, v, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    return w;
}

/* Steps a calm world and one in `cur` side by side for an hour: the worst
 * offset of the ground track from calm + drift, and of the heading. */
static void hour_in(const fw_current *cur, double *worst_pos, double *worst_psi,
                    double *turned)
{
    fw_env calm = fw_default_env(), env = fw_default_env();
    env.current = *cur;
    fw_vessel *a, *b;
    fw_world *wa = world_in(&calm, &a), *wb = world_in(&env, &b);
    fw_error err = {0};
    *worst_pos = *worst_psi = 0.0;
    double psi_min = INFINITY, psi_max = -INFINITY;
    for (int k = 1; k <= 3600; k++) {
        CHECK_MSG(fw_world_step(wa, 1.0, &err) == FW_OK, "%s", err.msg);
        CHECK_MSG(fw_world_step(wb, 1.0, &err) == FW_OK, "%s", err.msg);
        const fw_mmg_state *x = fw_vessel_motion(a), *y = fw_vessel_motion(b);
        double de, dn;
        fw_current_drift(cur, 0.0, 0.0, 0.0, k * 1.0, &de, &dn);
        double off = hypot(y->east - (x->east + de), y->north - (x->north + dn));
        *worst_pos = fmax(*worst_pos, off);
        *worst_psi = fmax(*worst_psi, fabs(y->psi - x->psi));
        psi_min = fmin(psi_min, x->psi), psi_max = fmax(psi_max, x->psi);
    }
    *turned = psi_max - psi_min;
    fw_world_destroy(wa);
    fw_world_destroy(wb);
}

static void test_uniform_current_shifts_track(void)
{
    fw_current cur = fw_current_uniform(1.5, fw_deg_to_rad(100.0));
    double pos, psi, turned;
    hour_in(&cur, &pos, &psi, &turned);
    printf("uniform 1.5 m/s: worst offset from calm + c t %.3g m, heading %.3g rad; "
           "heading range %.0f deg\n", pos, psi, fw_rad_to_deg(turned));
    CHECK(turned > fw_deg_to_rad(180.0)); /* the script did turn the ship round */
    CHECK_NEAR(pos, 0.0, 0.1);
    CHECK_NEAR(psi, 0.0, 1e-6);
}

static void test_tidal_current_shifts_track(void)
{
    /* a stream that turns within the hour: rate 2 m/s, period 40 min */
    fw_current cur = fw_current_tidal(2.0, fw_deg_to_rad(200.0), 2400.0, 500.0);
    double pos, psi, turned;
    hour_in(&cur, &pos, &psi, &turned);
    printf("tidal 2 m/s, 40 min: worst offset from calm + integral %.3g m, heading %.3g rad\n",
           pos, psi);
    CHECK_NEAR(pos, 0.0, 0.1);
    CHECK_NEAR(psi, 0.0, 1e-6);
    /* the closed-form drift is the integral of the velocity (Simpson, 1 s) */
    double se = 0.0, sn = 0.0;
    for (int k = 0; k < 3600; k++) {
        double e0, n0, e1, n1, em, nm;
        fw_current_at(&cur, 0, 0, k, &e0, &n0);
        fw_current_at(&cur, 0, 0, k + 0.5, &em, &nm);
        fw_current_at(&cur, 0, 0, k + 1.0, &e1, &n1);
        se += (e0 + 4 * em + e1) / 6.0, sn += (n0 + 4 * nm + n1) / 6.0;
    }
    double de, dn;
    fw_current_drift(&cur, 0, 0, 0.0, 3600.0, &de, &dn);
    CHECK_NEAR(de, se, 1e-6);
    CHECK_NEAR(dn, sn, 1e-6);
}

/* A current of exactly zero is calm water: the same bits. */
static void test_zero_current_is_calm(void)
{
    fw_env calm = fw_default_env(), zero = fw_default_env();
    zero.current = fw_current_uniform(0.0, 1.0);
    fw_vessel *a, *b;
    fw_world *wa = world_in(&calm, &a), *wb = world_in(&zero, &b);
    fw_error err = {0};
    bool same = true;
    for (int k = 0; k < 1200; k++) {
        CHECK(fw_world_step(wa, 1.0, &err) == FW_OK && fw_world_step(wb, 1.0, &err) == FW_OK);
        same = same && memcmp(fw_vessel_motion(a), fw_vessel_motion(b), sizeof(fw_mmg_state)) == 0 &&
               memcmp(fw_vessel_record(a), fw_vessel_record(b), sizeof(fw_target)) == 0;
    }
    CHECK(same);
    fw_world_destroy(wa);
    fw_world_destroy(wb);
}

/* Straight running heading 030 at 12 kn through a 2 m/s stream setting 120
 * (square across): over ground the ship goes 030 + atan2(2, U). */
static void test_record_heading_and_course(void)
{
    fw_env env = fw_default_env();
    env.current = fw_current_uniform(2.0, fw_deg_to_rad(120.0));
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env = env;
    fw_world *w;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &mmg;
    vd.course = fw_deg_to_rad(30.0), vd.speed = fw_kn_to_ms(12.0);
    fw_vessel *v;
    CHECK_MSG(add_vessel(w, &vd, &v, &err) == FW_OK, "%s", err.msg);
    CHECK(fw_world_start(w, &err) == FW_OK);
    for (int k = 0; k < 600; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    const fw_target *t = fw_vessel_record(v);
    double U = fw_kn_to_ms(12.0);
    CHECK_NEAR(t->heading, fw_deg_to_rad(30.0), 1e-9);
    CHECK_NEAR(t->stw, U, 1e-6);
    CHECK_NEAR(t->course, fw_deg_to_rad(30.0) + atan2(2.0, U), 1e-7);
    CHECK_NEAR(t->speed, hypot(U, 2.0), 1e-6);
    /* and it has gone there: 600 s of the ground velocity */
    CHECK_NEAR(t->east, 600.0 * (U * sin(vd.course) + 2.0 * sin(fw_deg_to_rad(120.0))), 1e-3);
    CHECK_NEAR(t->north, 600.0 * (U * cos(vd.course) + 2.0 * cos(fw_deg_to_rad(120.0))), 1e-3);
    /* the policy's state: through the water, with the current it knows */
    const fw_own_state *o = fw_vessel_own_state(v);
    CHECK_NEAR(o->U, U, 1e-6);
    CHECK_NEAR(o->cur_e, 2.0 * sin(fw_deg_to_rad(120.0)), 1e-12);
    CHECK_NEAR(o->cur_n, 2.0 * cos(fw_deg_to_rad(120.0)), 1e-12);
    fw_world_destroy(w);
}

/* A Nomoto vessel (the light plant) is carried by the current too: its
 * track under the script is the calm one plus c t. */
static void test_nomoto_vessel_in_current(void)
{
    fw_error err = {0};
    fw_vessel *v[2];
    fw_world *w[2];
    fw_current cur = fw_current_uniform(1.2, fw_deg_to_rad(250.0));
    for (int i = 0; i < 2; i++) {
        fw_world_def wd = fw_default_world_def();
        if (i)
            wd.env.current = cur;
        CHECK(fw_world_create(&wd, &w[i], &err) == FW_OK);
        fw_vessel_def vd = fw_default_vessel_def();
        vd.ship = &mmg;
        vd.dynamics = FW_DYN_NOMOTO;
        vd.course = 0.3, vd.speed = 6.0;
        vd.controller = script();
        CHECK_MSG(add_vessel(w[i], &vd, &v[i], &err) == FW_OK, "%s", err.msg);
        CHECK(fw_world_start(w[i], &err) == FW_OK);
    }
    double worst = 0.0, worst_psi = 0.0;
    for (int k = 1; k <= 3600; k++) {
        CHECK(fw_world_step(w[0], 1.0, &err) == FW_OK && fw_world_step(w[1], 1.0, &err) == FW_OK);
        const fw_target *a = fw_vessel_record(v[0]), *b = fw_vessel_record(v[1]);
        worst = fmax(worst, hypot(b->east - (a->east + cur.east * k), b->north - (a->north + cur.north * k)));
        worst_psi = fmax(worst_psi, fabs(b->heading - a->heading));
    }
    printf("  Nomoto vessel: worst offset from calm + c t %.3g m\n", worst);
    CHECK_NEAR(worst, 0.0, 1e-6);
    CHECK(worst_psi == 0.0);
    for (int i = 0; i < 2; i++)
        fw_world_destroy(w[i]);
}

/* Two MMG ships under the avoidance policy meeting head-on, in calm water
 * and in a uniform current: in the water's frame the encounter is the same
 * (both are carried alike, and each sees the other's motion over ground and
 * knows the current), so each acts at the same step to the same side with
 * the same helm, and the tracks are the calm ones plus c t until the return
 * (which steers back to a track fixed over ground, so there the two differ). */
static void test_avoidance_in_current(void)
{
    fw_current cur = fw_current_uniform(1.5, fw_deg_to_rad(300.0));
    fw_error err = {0};
    fw_world *w[2];
    fw_vessel *v[2][2];
    fw_policy_controller_def pd = {.ship = &mmg, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    for (int e = 0; e < 2; e++) {
        fw_world_def wd = fw_default_world_def();
        if (e)
            wd.env.current = cur;
        CHECK(fw_world_create(&wd, &w[e], &err) == FW_OK);
        for (int i = 0; i < 2; i++) {
            fw_vessel_def vd = fw_default_vessel_def();
            vd.id = i ? "B" : "A";
            vd.ship = &mmg;
            vd.north = i ? 9000.0 : 0.0, vd.east = i ? 200.0 : 0.0;
            vd.course = i ? FW_PI : 0.0;
            vd.role = i ? FW_ROLE_OTHER : FW_ROLE_OWN;
            vd.speed = fw_kn_to_ms(10);
            CHECK(fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK);
            CHECK_MSG(add_vessel(w[e], &vd, &v[e][i], &err) == FW_OK, "%s", err.msg);
        }
        CHECK(fw_world_start(w[e], &err) == FW_OK);
    }
    double t_act[2][2] = {{-1, -1}, {-1, -1}}, helm[2][2] = {{0}}, worst = 0.0, dmin = INFINITY;
    bool returning = false;
    int same_orders = 0, steps = 0;
    for (int k = 0; k <= 2400; k++) {
        for (int e = 0; e < 2 && k > 0; e++)
            CHECK(fw_world_step(w[e], 1.0, &err) == FW_OK);
        for (int i = 0; i < 2; i++) {
            for (int e = 0; e < 2; e++) {
                const fw_decision *d = fw_vessel_decision(v[e][i]);
                if (d->acted && t_act[e][i] < 0)
                    t_act[e][i] = k, helm[e][i] = d->helm;
                returning = returning || d->mode == FW_MODE_AUTOPILOT || d->mode == FW_MODE_STEADY;
            }
            if (returning)
                continue;
            const fw_target *a = fw_vessel_record(v[0][i]), *b = fw_vessel_record(v[1][i]);
            worst = fmax(worst, hypot(b->east - (a->east + cur.east * k),
                                      b->north - (a->north + cur.north * k)));
            same_orders += fw_vessel_decision(v[0][i])->helm == fw_vessel_decision(v[1][i])->helm;
            steps++;
        }
        const fw_target *a = fw_vessel_record(v[1][0]), *b = fw_vessel_record(v[1][1]);
        dmin = fmin(dmin, hypot(a->east - b->east, a->north - b->north));
    }
    printf("  avoidance head-on in 1.5 m/s: acted at %.0f/%.0f s (calm %.0f/%.0f s), helm "
           "%.0f/%.0f deg; until the return (%d vessel-steps) %d orders alike, tracks within "
           "%.3g m of calm + c t; closest %.0f m\n",
           t_act[1][0], t_act[1][1], t_act[0][0], t_act[0][1], fw_rad_to_deg(helm[1][0]),
           fw_rad_to_deg(helm[1][1]), steps, same_orders, worst, dmin);
    /* after the return, the current's run steers back to its track over
     * ground (crabbing into the current), the calm one to its own: they
     * part; both get back onto their tracks */
    const fw_target *a = fw_vessel_record(v[0][0]), *b = fw_vessel_record(v[1][0]);
    const fw_policy *pa = fw_policy_controller_policy(fw_vessel_controller(v[1][0]));
    printf("  at 2400 s A is %.0f m from calm + c t (returning to its track over ground: "
           "%.0f m off it, mode %s; in calm water %.0f m)\n",
           hypot(b->east - (a->east + cur.east * 2400), b->north - (a->north + cur.north * 2400)),
           fw_policy_cross_track(pa, fw_vessel_own_state(v[1][0])),
           fw_policy_mode_name(fw_vessel_decision(v[1][0])->mode),
           fw_policy_cross_track(fw_policy_controller_policy(fw_vessel_controller(v[0][0])),
                                 fw_vessel_own_state(v[0][0])));
    CHECK(fabs(fw_policy_cross_track(pa, fw_vessel_own_state(v[1][0]))) < 100.0);
    for (int i = 0; i < 2; i++) {
        CHECK(t_act[0][i] > 0 && t_act[1][i] == t_act[0][i]);
        CHECK(helm[1][i] == helm[0][i] && helm[1][i] > 0.0); /* starboard */
    }
    CHECK(steps > 400 && same_orders == steps);
    CHECK_NEAR(worst, 0.0, 0.1);
    CHECK(dmin > 300.0);
    for (int e = 0; e < 2; e++)
        fw_world_destroy(w[e]);
}

/* The predicted track in a current is the calm one carried by it. */
/* An own ship whose one leg is steered (run_world.c: in a current or a
 * wind) makes good its track over ground.  Alone in 1.5 m/s towards 300 deg
 * at 10 kn on 000, it heads into the set by the crab angle
 * asin(c across / U) = asin(1.3 / 5.14) = 14.7 deg to starboard (with the
 * rudder amidships it held 000 and was set 2.3 km west in half an hour), and
 * the autopilot keeps its dead band (policy.h): no order within 0.1 deg of
 * the one before, where without it every second brought a new order. */
static void test_track_kept_in_current(void)
{
    fw_current cur = fw_current_uniform(1.5, fw_deg_to_rad(300.0));
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env.current = cur;
    fw_world *w;
    fw_vessel *v;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    fw_policy_controller_def pd = {.ship = &mmg, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    pd.policy.route = fw_route_line(0.0, 0.0, 0.0, fw_kn_to_ms(10), 20000.0);
    pd.policy.route.steered = true;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.id = "A", vd.ship = &mmg, vd.course = 0.0, vd.role = FW_ROLE_OWN;
    vd.speed = fw_kn_to_ms(10);
    CHECK(fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK);
    CHECK_MSG(add_vessel(w, &vd, &v, &err) == FW_OK, "%s", err.msg);
    CHECK(fw_world_start(w, &err) == FW_OK);
    const fw_policy *p = fw_policy_controller_policy(fw_vessel_controller(v));
    double crab = asin(-cur.east / fw_kn_to_ms(10)), xte_max = 0.0, xte_late = 0.0;
    double psi_late = 0.0, helm = 0.0, least_step = INFINITY;
    int orders = 0;
    for (int k = 1; k <= 1800; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        double xte = fw_policy_cross_track(p, fw_vessel_own_state(v));
        xte_max = fmax(xte_max, fabs(xte));
        if (k >= 1200) {
            xte_late = fmax(xte_late, fabs(xte));
            psi_late = fmax(psi_late, fabs(fw_wrap_pi(fw_vessel_record(v)->heading - crab)));
        }
        double h = fw_vessel_decision(v)->helm;
        if (h != helm)
            orders++, least_step = fmin(least_step, fabs(h - helm));
        helm = h;
    }
    printf("  steered leg: crab %.2f deg; off the track at most %.0f m, after 20 min %.2f m, "
           "heading within %.3f deg of the crab; %d helm orders in 30 min, the smallest step "
           "%.3f deg\n", fw_rad_to_deg(crab), xte_max, xte_late, fw_rad_to_deg(psi_late),
           orders, fw_rad_to_deg(least_step));
    CHECK(xte_max < 250.0);
    CHECK(xte_late < 5.0);
    CHECK(psi_late < fw_deg_to_rad(0.5));
    CHECK(orders < 300);
    CHECK(least_step >= pd.policy.ap_deadband);
    fw_world_destroy(w);
}

static void test_track_prediction_in_current(void)
{
    fw_error err = {0};
    fw_track_def td = fw_default_track_def();
    int n = fw_track_samples(&td);
    fw_track a, b;
    CHECK(fw_track_alloc(&a, n, &err) == FW_OK && fw_track_alloc(&b, n, &err) == FW_OK);
    fw_own_state s = {.east = 50, .north = 20, .psi = 1.0, .U = 6.0, .U0 = 6.0, .r = 0.002,
                      .delta = 0.1};
    fw_own_state c = s;
    c.cur_e = -0.7, c.cur_n = 1.1;
    double worst = 0.0, worst_psi = 0.0;
    for (int h = -35; h <= 35; h += 35) {
        CHECK(fw_track_predict(&mmg, &td, &s, fw_deg_to_rad(h), &a, &err) == FW_OK);
        CHECK(fw_track_predict(&mmg, &td, &c, fw_deg_to_rad(h), &b, &err) == FW_OK);
        for (int k = 0; k < n; k++) {
            double t = k * td.dt;
            worst = fmax(worst, hypot(b.east[k] - (a.east[k] - 0.7 * t),
                                      b.north[k] - (a.north[k] + 1.1 * t)));
            worst_psi = fmax(worst_psi, fabs(b.psi[k] - a.psi[k]));
        }
    }
    CHECK_NEAR(worst, 0.0, 1e-9);
    CHECK(worst_psi == 0.0);
    fw_track_free(&a);
    fw_track_free(&b);
}

/* The helm search's shortcuts in a current: its decisions are the plain
 * reference search's (which predicts every candidate and checks every target)
 * bit for bit, on straight and turning own ships in currents up to 2.5 m/s
 * from any direction. */
static void test_helm_search_in_current(void)
{
    fw_error err = {0};
    fw_helm_def hdef = fw_default_helm_def();
    fw_helm_ctx *ctx = NULL;
    fw_helm_ref *ref = NULL;
    CHECK(fw_helm_ctx_create(&mmg, &hdef, &ctx, &err) == FW_OK);
    CHECK(ctx && fw_helm_ref_create(&hdef, fw_helm_count(ctx), &ref, &err) == FW_OK);
    if (!ctx || !ref) {
        fw_helm_ctx_destroy(ctx);
        return;
    }
    static fw_target tg[40];
    decide_seed(0x5eaULL);
    int scenes = 0, same = 0, threats = 0, sides[2] = {0, 0}, differs_calm = 0, same_tracks = 0;
    fw_track tr;
    CHECK(fw_track_alloc(&tr, fw_track_samples(&hdef.track), &err) == FW_OK);
    for (int s = 0; s < 160; s++, scenes++) {
        fw_own_state own = decide_own(s % 3 == 0);
        int n = 1 + s % 40;
        decide_scene(&own, s % 2 == 1, tg, n);
        double c = 2.5 * decide_uniform(), set = 2 * FW_PI * decide_uniform();
        own.cur_e = c * sin(set), own.cur_n = c * cos(set);
        fw_helm_result rn, rr, calm;
        fw_helm_begin(ctx, &own);
        CHECK(fw_helm_search(ctx, tg, n, FW_ALLOW_EITHER, &rn, &err) == FW_OK);
        fw_helm_begin(ctx, &own);
        CHECK(fw_helm_search_reference(ref, ctx, tg, n, FW_ALLOW_EITHER, &rr, &err) == FW_OK);
        same += rn.threat == rr.threat && rn.feasible == rr.feasible && rn.side == rr.side &&
                memcmp(&rn.helm, &rr.helm, sizeof rn.helm) == 0 &&
                memcmp(&rn.clearance, &rr.clearance, sizeof rn.clearance) == 0 &&
                memcmp(&rn.keep_clearance, &rr.keep_clearance, sizeof rn.keep_clearance) == 0;
        /* a port candidate is predicted, not mirrored from starboard (the
         * mirror is not the track in a current): fw_track_predict's */
        const fw_track *got;
        int i = s % fw_helm_count(ctx);
        CHECK(fw_helm_track(ctx, FW_SIDE_STARBOARD, i, &got, &err) == FW_OK);
        CHECK(fw_helm_track(ctx, FW_SIDE_PORT, i, &got, &err) == FW_OK);
        CHECK(fw_track_predict(&mmg, &hdef.track, &own, fw_helm_value(ctx, FW_SIDE_PORT, i), &tr,
                               &err) == FW_OK);
        size_t len = sizeof(double) * (size_t)tr.n;
        same_tracks += got->n == tr.n && memcmp(got->east, tr.east, len) == 0 &&
                       memcmp(got->north, tr.north, len) == 0;
        threats += rn.threat;
        sides[rn.side == FW_SIDE_PORT] += rn.side != FW_SIDE_NONE;
        fw_own_state still = own;
        still.cur_e = still.cur_n = 0.0;
        fw_helm_begin(ctx, &still);
        CHECK(fw_helm_search(ctx, tg, n, FW_ALLOW_EITHER, &calm, &err) == FW_OK);
        differs_calm += memcmp(&calm.keep_clearance, &rn.keep_clearance, sizeof calm.keep_clearance) != 0;
    }
    printf("  %d scenes in a current: %d decided as the reference; %d threats, sides %d "
           "starboard %d port; %d whose keep clearance the current changed\n",
           scenes, same, threats, sides[0], sides[1], differs_calm);
    CHECK(same == scenes);
    CHECK(same_tracks == scenes);
    fw_track_free(&tr);
    /* not vacuous: threats, both sides, and the current matters */
    CHECK(threats > scenes / 3 && sides[0] > 0 && sides[1] > 0 && differs_calm > scenes / 2);
    fw_helm_ref_destroy(ref);
    fw_helm_ctx_destroy(ctx);
}

/* A 35 deg turning circle (c3-mmg, 12 kn) in a uniform current of 2 kn
 * towards 090: its 720 deg point lies current x time from its 360 deg point
 * (MSC/Circ.1053 3.4.2.5), to 1 m; in calm water the two coincide; advance,
 * transfer and tactical diameter, measured in the water, are the calm ones. */
static void test_turning_circle_drift(void)
{
    fw_error err = {0};
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(12.0);
    d.rudder = fw_deg_to_rad(35.0);
    d.max_turn = fw_deg_to_rad(730.0);
    fw_turning_result calm, drift;
    CHECK(fw_turning_run(&mmg, &d, &calm, NULL, &err) == FW_OK);
    d.stepper.current = fw_current_uniform(fw_kn_to_ms(2.0), fw_deg_to_rad(90.0));
    CHECK(fw_turning_run(&mmg, &d, &drift, NULL, &err) == FW_OK);
    CHECK(calm.drift < 1.0);
    CHECK_NEAR(drift.drift, fw_kn_to_ms(2.0) * drift.t_drift, 1.0);
    CHECK_NEAR(fw_rad_to_deg(drift.drift_towards), 90.0, 0.1);
    CHECK_NEAR(drift.t_drift, calm.t_drift, 1e-3);
    CHECK_NEAR(drift.advance, calm.advance, 1e-6 * calm.advance);
    CHECK_NEAR(drift.transfer, calm.transfer, 1e-6 * calm.transfer);
    CHECK_NEAR(drift.tactical_diameter, calm.tactical_diameter, 1e-6 * calm.tactical_diameter);
    printf("turning circle in 2 kn towards 090: 360 -> 720 deg %.1f m in %.1f s (%.3f kn); "
           "calm %.2f m\n", drift.drift, drift.t_drift, fw_ms_to_kn(drift.drift / drift.t_drift),
           calm.drift);
}

static void test_refusals(void)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = 10.0, .from = 0.5};
    fw_world *w;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK); /* the field alone is fine */
    double ws, wf;
    fw_wind_at(&wd.env.wind, 1e4, -3e3, 500.0, &ws, &wf);
    CHECK(ws == 10.0 && wf == 0.5);
    fw_env still = fw_default_env();
    fw_wind_at(&still.wind, 0, 0, 0, &ws, &wf);
    CHECK(ws == 0.0);
    fw_ship bare = mmg;
    bare.windage.present = false;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &bare;
    fw_vessel *v = NULL;
    CHECK(add_vessel(w, &vd, &v, &err) == FW_EINPUT && v == NULL);
    CHECK_MSG(strstr(err.msg, "windage") && strstr(err.msg, "refused"), "%s", err.msg);
    vd.ship = &mmg; /* with windage, but Nomoto dynamics: no wind term */
    vd.dynamics = FW_DYN_NOMOTO;
    CHECK(add_vessel(w, &vd, &v, &err) == FW_EINPUT && v == NULL);
    CHECK_MSG(strstr(err.msg, "Nomoto") && strstr(err.msg, "refused"), "%s", err.msg);
    vd.dynamics = FW_DYN_MMG; /* an MMG ship with windage sails in it */
    CHECK_MSG(add_vessel(w, &vd, &v, &err) == FW_OK, "%s", err.msg);
    fw_world_destroy(w);
    vd.ship = &bare;
    /* still air and a calm wind of 0 m/s are accepted */
    wd.env.wind.speed = 0.0;
    CHECK(fw_world_create(&wd, &w, &err) == FW_OK);
    CHECK(add_vessel(w, &vd, &v, &err) == FW_OK);
    fw_world_destroy(w);
    /* bad fields */
    wd = fw_default_world_def();
    wd.env.current = fw_current_tidal(-1.0, 0.0, FW_M2_PERIOD_S, 0.0);
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT && w == NULL);
    CHECK_MSG(strstr(err.msg, "tidal current"), "%s", err.msg);
    wd.env.current = fw_current_uniform(NAN, 0.0);
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT);
    wd.env.current = (fw_current){.kind = 7};
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT);
    wd.env.current = fw_current_tidal(1.0, 0.0, 0.0, 0.0);
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT);
    wd.env = fw_default_env();
    wd.env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = -1.0};
    CHECK(fw_world_create(&wd, &w, &err) == FW_EINPUT);
}

int main(void)
{
    mmg = test_load_ship("c3-mmg");
    TEST_RUN(test_uniform_current_shifts_track);
    TEST_RUN(test_tidal_current_shifts_track);
    TEST_RUN(test_zero_current_is_calm);
    TEST_RUN(test_record_heading_and_course);
    TEST_RUN(test_nomoto_vessel_in_current);
    TEST_RUN(test_track_prediction_in_current);
    TEST_RUN(test_helm_search_in_current);
    TEST_RUN(test_avoidance_in_current);
    TEST_RUN(test_track_kept_in_current);
    TEST_RUN(test_turning_circle_drift);
    TEST_RUN(test_refusals);
    return TEST_EXIT();
}
