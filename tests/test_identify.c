/* Identification: Nomoto indices fitted to MMG turning tests (small grid). */
#include <math.h>
#include <stdlib.h>

#include "core/units.h"
#include "dynamics/stepper.h"
#include "fit/identify.h"
#include "avoid/helm_search.h"
#include "nomoto/track.h"
#include "test.h"

static fw_ship c3;

static void test_fit_recovers_known_indices(void)
{
    /* a synthetic history from known indices is fitted back exactly */
    fw_nomoto_indices truth = {.K = 0.02, .T1 = 12, .T2 = 70, .T3 = 80}, fit;
    double r[400], rms;
    fw_ident_response(&truth, fw_deg_to_rad(20), c3.rudder_rate, 1.0, 400, r);
    CHECK(fw_ident_fit(r, 400, 1.0, fw_deg_to_rad(20), c3.rudder_rate, &fit, &rms, NULL) == FW_OK);
    CHECK_REL(fit.K, truth.K, 1e-4);
    CHECK_REL(fit.T1, truth.T1, 1e-3);
    CHECK_REL(fit.T2, truth.T2, 1e-3);
    CHECK_REL(fit.T3, truth.T3, 1e-3);
    CHECK(rms < 1e-5);
}

static void test_fit_mmg_histories(void)
{
    /* floor: each MMG history reproduced within 5% RMS of its steady rate */
    static const double grid[][2] = {{20.12, 10}, {20.12, 30}, {14.55, -20}};
    enum { N = 700 };
    double *r = malloc(sizeof(double) * N);
    for (size_t i = 0; i < sizeof grid / sizeof grid[0]; i++) {
        fw_error err = {0};
        double helm = fw_deg_to_rad(grid[i][1]);
        CHECK_MSG(fw_ident_turning(&c3, fw_kn_to_ms(grid[i][0]), helm, 1.0, N, r, &err) == FW_OK,
                  "%s", err.msg);
        fw_nomoto_indices fit;
        double rms;
        CHECK(fw_ident_fit(r, N, 1.0, helm, c3.rudder_rate, &fit, &rms, &err) == FW_OK);
        CHECK_MSG(rms < 0.05, "%.2f kn %.0f deg: RMS %.1f%%", grid[i][0], grid[i][1], 100 * rms);
        CHECK(fit.K > 0 && fit.T1 > 0 && fit.T2 >= fit.T1);
        printf("  %.2f kn %+3.0f deg: K %.5f T1 %.1f T2 %.1f T3 %.1f rms %.2f%%\n", grid[i][0],
               grid[i][1], fit.K, fit.T1, fit.T2, fit.T3, 100 * rms);
    }
    free(r);
}

/* Largest distance between the predicted track and the MMG ship over the
 * first `until` seconds of a turn from straight running. */
static double track_error(const fw_ship *ship, double U_kn, double helm_deg, double until)
{
    fw_error err = {0};
    double U = fw_kn_to_ms(U_kn), prop;
    fw_stepper *st = NULL;
    fw_stepper_def sd = fw_default_stepper_def();
    fw_mmg_state x0 = fw_mmg_straight(U, 0.0, 0.0, 0.0);
    fw_track_def td = fw_default_track_def();
    td.max_turn = 0.0;
    fw_track tr = {0};
    fw_own_state own = {.U = U};
    double worst = INFINITY;
    if (fw_mmg_propeller_for_speed(ship, U, &prop, &err) ||
        fw_stepper_create(ship, &sd, &st, &err) || fw_stepper_start(st, 0.0, &x0, prop, &err) ||
        fw_track_alloc(&tr, fw_track_samples(&td), &err) ||
        fw_track_predict(ship, &td, &own, fw_deg_to_rad(helm_deg), &tr, &err)) {
        CHECK_MSG(0, "%s", err.msg);
        goto out;
    }
    fw_stepper_set_helm(st, fw_deg_to_rad(helm_deg));
    worst = 0.0;
    for (int k = 1; k * tr.dt <= until; k++) {
        if (fw_stepper_advance(st, tr.dt, &err)) {
            CHECK_MSG(0, "%s", err.msg);
            break;
        }
        const fw_mmg_state *x = fw_stepper_state(st);
        worst = fmax(worst, hypot(x->east - tr.east[k], x->north - tr.north[k]));
    }
out:
    fw_stepper_destroy(st);
    fw_track_free(&tr);
    return worst;
}

static void test_slip_terms_bring_the_track_to_the_mmg_ship(void)
{
    /* the C-3 with the knowledge base identified from its MMG model: with the
     * drift and speed-loss terms the predicted track stays within 40 m of the
     * MMG ship for 3 minutes and 80 m for 5 (the decisions that matter are
     * made 2-6 minutes before the closest approach); without them it is off
     * by 90-600 m at 5 minutes */
    fw_ship ship, bare;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-mmg", &ship, &err) == FW_OK, "%s", err.msg);
    CHECK(ship.nomoto.drift > 0.3 && ship.nomoto.speed_loss > 0.3);
    bare = ship;
    bare.nomoto.drift = bare.nomoto.speed_loss = 0.0;
    static const double grid[][2] = {{10, 10}, {10, 20}, {10, 35}, {12, 10}, {12, 20}, {12, 35}};
    for (size_t i = 0; i < sizeof grid / sizeof grid[0]; i++) {
        double e3 = track_error(&ship, grid[i][0], grid[i][1], 180.0);
        double e5 = track_error(&ship, grid[i][0], grid[i][1], 300.0);
        double b5 = track_error(&bare, grid[i][0], grid[i][1], 300.0);
        CHECK_MSG(e3 < 40.0 && e5 < 80.0, "%.0f kn %.0f deg: %.0f m at 3 min, %.0f m at 5 min",
                  grid[i][0], grid[i][1], e3, e5);
        CHECK_MSG(b5 > 80.0 && b5 > 2.5 * e5, "%.0f kn %.0f deg: without slip %.0f m", grid[i][0],
                  grid[i][1], b5);
        printf("  %2.0f kn %2.0f deg: track vs MMG %3.0f m at 3 min, %3.0f m at 5 min "
               "(without drift and speed loss %3.0f m)\n",
               grid[i][0], grid[i][1], e3, e5, b5);
    }
}

/* c3-mmg's knowledge base covers the speeds its studies and scenarios use
 * (10-16 kn, and half of 12 kn when the band about the route slows it): it is
 * fitted over 4-20 kn, every index a stable system there at 1-35 deg either
 * side, and from straight running at 6-16 kn with 10-35 deg either side the
 * predicted track stays within 80 m of the MMG ship for 3 minutes and 140 m
 * for 5 (measured 76 and 130 m, at 16 kn; the 8-14 kn base it replaced: 85
 * and 218 m, and not a stable system below 5.5 kn). */
static void test_c3_mmg_covers_its_speeds(void)
{
    fw_ship ship;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-mmg", &ship, &err) == FW_OK, "%s", err.msg);
    CHECK(ship.nomoto_port.present);
    for (int side = -1; side <= 1; side += 2) {
        const fw_nomoto_kb *kb = fw_ship_kb(&ship, side);
        CHECK(kb->speed_min_kn <= 6.0 && kb->speed_max_kn >= 16.0);
        for (double u = kb->speed_min_kn; u <= kb->speed_max_kn + 1e-9; u += 0.5)
            for (double d = 1.0; d <= 35.0; d += 1.0) {
                fw_nomoto_indices ix;
                CHECK_MSG(fw_nomoto_indices_at(kb, u, d, &ix, &err) == FW_OK, "%s", err.msg);
            }
    }
    double w3 = 0.0, w5 = 0.0;
    for (double u = 6.0; u <= 16.0; u += 2.0)
        for (int side = -1; side <= 1; side += 2)
            for (int d = 10; d <= 35; d += 5) {
                w3 = fmax(w3, track_error(&ship, u, side * d, 180.0));
                w5 = fmax(w5, track_error(&ship, u, side * d, 300.0));
            }
    CHECK_MSG(w3 < 80.0 && w5 < 140.0, "6-16 kn: %.0f m at 3 min, %.0f m at 5 min", w3, w5);
    printf("  c3-mmg at 6-16 kn, 10-35 deg both sides: track within %.0f m of the MMG ship for 3 "
           "minutes, %.0f m for 5\n", w3, w5);
}

/* Floor of issue 17: for the paper's ship (c3-paper-mmg, its knowledge base
 * regenerated by `fairway identify`: both sides, the first 300 s of each turn,
 * the speed loss driven by |r'| and |beta r'|) at the paper's 10 kn the
 * predicted track stays within 30 m of the MMG ship for 3 minutes at every
 * rudder angle from 10 to 35 deg to either side.  Before (one side, 900 s
 * fits, the loss by |r'| alone) it was 9-44 m off at 3 minutes. */
static void test_paper_ship_track_within_30_m(void)
{
    fw_ship ship;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-paper-mmg", &ship, &err) == FW_OK, "%s", err.msg);
    CHECK(ship.nomoto_port.present && ship.nomoto.speed_loss_drift > 0.0);
    double worst = 0.0, at = 0.0;
    for (int side = -1; side <= 1; side += 2)
        for (int d = 10; d <= 35; d++) {
            double e3 = track_error(&ship, 10.0, side * d, 180.0);
            CHECK_MSG(e3 < 30.0, "10 kn %+d deg: %.1f m off after 3 minutes", side * d, e3);
            if (e3 > worst)
                worst = e3, at = side * d;
        }
    printf("  c3-paper-mmg at 10 kn, 10-35 deg both sides: track within %.1f m of the MMG ship "
           "for 3 minutes (worst at %+.0f deg)\n", worst, at);
}

/* The policy's steadying and return are predicted with its own autopilot
 * (fw_track_predict_steer): from straight running 40 deg off, the MMG ship
 * under that autopilot and the prediction stay within 60 m over 5 minutes and
 * 120 m over 10 (the last degrees come back slower in the prediction: the
 * knowledge base is fitted from 5 deg of rudder up and the autopilot's last
 * orders are smaller). */
static void test_autopilot_prediction_against_the_mmg_ship(void)
{
    fw_ship ship;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-mmg", &ship, &err) == FW_OK, "%s", err.msg);
    double U = fw_kn_to_ms(12), prop;
    fw_stepper *st = NULL;
    fw_stepper_def sd = fw_default_stepper_def();
    fw_mmg_state x0 = fw_mmg_straight(U, 0.0, 0.0, fw_deg_to_rad(40));
    fw_track_def td = fw_default_track_def();
    fw_track tr = {0};
    fw_own_state own = {.psi = fw_deg_to_rad(40), .U = U, .U0 = U};
    fw_steer_def ap = {.psi_ref = 0.0, .kp = 1.0, .kd = 20.0, .max_helm = fw_deg_to_rad(20)};
    if (fw_mmg_propeller_for_speed(&ship, U, &prop, &err) ||
        fw_stepper_create(&ship, &sd, &st, &err) || fw_stepper_start(st, 0.0, &x0, prop, &err) ||
        fw_track_alloc(&tr, fw_track_samples(&td), &err) ||
        fw_track_predict_steer(&ship, &td, &own, &ap, &tr, &err)) {
        CHECK_MSG(0, "%s", err.msg);
        fw_stepper_destroy(st);
        fw_track_free(&tr);
        return;
    }
    double worst = 0.0, worst5 = 0.0;
    for (int k = 1; k <= 600; k++) {
        const fw_mmg_state *x = fw_stepper_state(st);
        double h = -ap.kp * fw_wrap_pi(x->psi - ap.psi_ref) - ap.kd * x->r;
        fw_stepper_set_helm(st, fmax(-ap.max_helm, fmin(ap.max_helm, h)));
        if (fw_stepper_advance(st, 1.0, &err)) {
            CHECK_MSG(0, "%s", err.msg);
            break;
        }
        x = fw_stepper_state(st);
        if (k % 5 == 0)
            worst = fmax(worst, hypot(x->east - tr.east[k / 5], x->north - tr.north[k / 5]));
        if (k == 300)
            worst5 = worst;
    }
    CHECK_MSG(worst5 < 60.0 && worst < 120.0, "%.0f m apart in 5 minutes, %.0f m in 10", worst5,
              worst);
    printf("  autopilot return from 40 deg off at 12 kn: prediction within %.0f m of the MMG ship "
           "over 5 minutes, %.0f m over 10\n", worst5, worst);
    fw_stepper_destroy(st);
    fw_track_free(&tr);
}

static void test_slip_fit_recovers_the_ship_file(void)
{
    /* identification is deterministic: a smaller grid of the same tests gives
     * the file's values within a few percent (c3-paper-mmg: its knowledge
     * base is the one made by the present fw_ident_slip) */
    const double U[] = {fw_kn_to_ms(10), fw_kn_to_ms(12), fw_kn_to_ms(12)};
    const double h[] = {fw_deg_to_rad(20), fw_deg_to_rad(10), fw_deg_to_rad(35)};
    fw_ship ship;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-paper-mmg", &ship, &err) == FW_OK, "%s", err.msg);
    fw_nomoto_kb kb = {0};
    double rb, ru;
    CHECK_MSG(fw_ident_slip(&ship, U, h, 3, 1.0, 901, &kb, &rb, &ru, &err) == FW_OK, "%s", err.msg);
    CHECK_REL(kb.drift, ship.nomoto.drift, 0.1);
    /* the two loss gains trade against each other: compare the steady loss
     * they give at a small and a large turn (r' 0.2 and 0.45, 10 and 35 deg
     * at 10 kn) */
    for (double rn = 0.2; rn < 0.5; rn += 0.25) {
        double a = kb.speed_loss * rn + kb.speed_loss_drift * kb.drift * rn * rn;
        double b = ship.nomoto.speed_loss * rn +
                   ship.nomoto.speed_loss_drift * ship.nomoto.drift * rn * rn;
        CHECK_REL(a, b, 0.1);
    }
    CHECK(fabs(kb.drift_lag_s - ship.nomoto.drift_lag_s) < 10.0);
    CHECK(fabs(kb.speed_lag_s - ship.nomoto.speed_lag_s) < 20.0);
    CHECK(fw_rad_to_deg(rb) < 1.5 && fw_ms_to_kn(ru) < 0.2);
    printf("  drift %.3f lag %.1f s, speed loss %.3f |r'| + %.3f |beta r'| lag %.0f s (file %.3f "
           "%.1f %.3f %.3f %.0f)\n",
           kb.drift, kb.drift_lag_s, kb.speed_loss, kb.speed_loss_drift, kb.speed_lag_s,
           ship.nomoto.drift, ship.nomoto.drift_lag_s, ship.nomoto.speed_loss,
           ship.nomoto.speed_loss_drift, ship.nomoto.speed_lag_s);
}

static void test_regression_reproduces_paper(void)
{
    /* regressing the paper's own equations sampled on its grid returns them */
    double U[21], d[21], v[21];
    int m = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 7; j++, m++) {
            U[m] = (double[]){14.55, 20.12, 26.7}[i];
            d[m] = 5 + 5 * j;
        }
    const fw_nomoto_index *src[4] = {&c3.nomoto.K, &c3.nomoto.T1, &c3.nomoto.T2, &c3.nomoto.T3};
    for (int x = 0; x < 4; x++) {
        fw_nomoto_index ix = *src[x];
        for (int i = 0; i < m; i++)
            v[i] = fw_nomoto_index_eval(src[x], U[i], d[i]);
        CHECK(fw_ident_regress(&ix, U, d, v, m, NULL) == FW_OK);
        for (int k = 0; k < ix.n; k++)
            CHECK_NEAR(ix.coef[k], src[x]->coef[k], 1e-6 * fmax(1.0, fabs(src[x]->coef[k])));
    }
}

/* A ship file's nomoto_port: block serves the port helms and only them: a
 * port base 30 % quicker (K x1.3) makes the port track turn further, the
 * starboard one is the same to the bit, and the helm search computes the
 * port tracks instead of mirroring the starboard ones. */
static void test_port_knowledge_base(void)
{
    fw_ship one, two;
    fw_error err = {0};
    CHECK_MSG(fw_ship_load("c3-paper-mmg", &one, &err) == FW_OK, "%s", err.msg);
    /* one side's base only (the file has both since identify --sides both) */
    one.nomoto_port.present = false;
    CHECK(fw_ship_kb(&one, -0.1) == &one.nomoto);
    two = one;
    two.nomoto_port = one.nomoto;
    for (int k = 0; k < two.nomoto_port.K.n; k++)
        two.nomoto_port.K.coef[k] *= 1.3;
    CHECK(fw_ship_kb(&two, -0.1) == &two.nomoto_port && fw_ship_kb(&two, 0.1) == &two.nomoto);
    fw_track_def td = fw_default_track_def();
    td.max_turn = 0.0;
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    fw_track a = {0}, b = {0};
    CHECK(fw_track_alloc(&a, fw_track_samples(&td), &err) == FW_OK);
    CHECK(fw_track_alloc(&b, fw_track_samples(&td), &err) == FW_OK);
    for (int side = -1; side <= 1; side += 2) {
        double helm = side * fw_deg_to_rad(20);
        CHECK(fw_track_predict(&one, &td, &own, helm, &a, &err) == FW_OK);
        CHECK(fw_track_predict(&two, &td, &own, helm, &b, &err) == FW_OK);
        int k = (int)(120.0 / td.dt);
        double ta = fabs(atan2(a.east[k + 1] - a.east[k], a.north[k + 1] - a.north[k]));
        double tb = fabs(atan2(b.east[k + 1] - b.east[k], b.north[k + 1] - b.north[k]));
        if (side < 0)
            CHECK_MSG(tb > 1.15 * ta, "port course at 120 s: %.1f deg against %.1f",
                      fw_rad_to_deg(tb), fw_rad_to_deg(ta));
        else
            CHECK(a.east[k] == b.east[k] && a.north[k] == b.north[k]);
    }
    fw_helm_def hd = fw_default_helm_def();
    fw_helm_ctx *ctx;
    CHECK(fw_helm_ctx_create(&two, &hd, &ctx, &err) == FW_OK);
    fw_helm_begin(ctx, &own);
    const fw_track *tr;
    CHECK(fw_helm_track(ctx, FW_SIDE_STARBOARD, 10, &tr, &err) == FW_OK);
    CHECK(fw_helm_track(ctx, FW_SIDE_PORT, 10, &tr, &err) == FW_OK);
    CHECK(fw_helm_tracks_computed(ctx) == 2);
    /* the search's own track settings (its 90 deg max_turn is reached by
     * 300 s at 20 deg to port) */
    CHECK(fw_track_predict(&two, &hd.track, &own, fw_helm_value(ctx, FW_SIDE_PORT, 10), &b,
                           &err) == FW_OK);
    CHECK(tr->east[60] == b.east[60] && tr->north[60] == b.north[60]);
    fw_helm_ctx_destroy(ctx);
    fw_track_free(&a);
    fw_track_free(&b);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_fit_recovers_known_indices);
    TEST_RUN(test_fit_mmg_histories);
    TEST_RUN(test_regression_reproduces_paper);
    TEST_RUN(test_slip_terms_bring_the_track_to_the_mmg_ship);
    TEST_RUN(test_slip_fit_recovers_the_ship_file);
    TEST_RUN(test_c3_mmg_covers_its_speeds);
    TEST_RUN(test_paper_ship_track_within_30_m);
    TEST_RUN(test_autopilot_prediction_against_the_mmg_ship);
    TEST_RUN(test_port_knowledge_base);
    return TEST_EXIT();
}
