/* MMG model and stepper: sea trial, IMO criteria, Froude scaling, mirror
 * symmetry, surge balance, integration accuracy and re-initialisation policy. */
#include <stdlib.h>

#include "core/units.h"
#include "dynamics/manoeuvre.h"
#include "test.h"
#include "test_ship.h"


static fw_turning_result turn(const fw_ship *s, double kn, double deg)
{
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(kn);
    d.rudder = fw_deg_to_rad(deg);
    d.max_turn = fw_deg_to_rad(540.0);
    fw_turning_result r;
    fw_error err = {0};
    fw_status st = fw_turning_run(s, &d, &r, NULL, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    return r;
}

/* The paper's Table 2 and steady rates: the C-3 within 10 percent on every row. */
static void test_c3_sea_trial(void)
{
    fw_ship c3 = test_load_ship("c3");
    fw_turning_result s = turn(&c3, 26.7, 35.0);
    CHECK_REL(s.advance, 1125.0, 0.10);
    CHECK_REL(s.transfer, 543.0, 0.10);
    CHECK_REL(s.tactical_diameter, 1451.0, 0.10);
    CHECK_REL(fw_rad_to_deg(s.steady_rate), 0.690, 0.10);
    fw_turning_result p = turn(&c3, 27.16, -35.0);
    CHECK_REL(p.advance, 1204.0, 0.10);
    CHECK_REL(p.transfer, 468.0, 0.10);
    CHECK_REL(p.tactical_diameter, 1336.0, 0.10);
    CHECK_REL(fw_rad_to_deg(p.steady_rate), 0.746, 0.10);
    /* better than the paper's simulator on transfer, where it was 12 and 30% off */
    CHECK(fabs(s.transfer / 543.0 - 1) < fabs(609.5 / 543.0 - 1));
    CHECK(fabs(p.transfer / 468.0 - 1) < fabs(608.32 / 468.0 - 1));
    /* speed falls in a hard turn, and the heading keeps increasing */
    CHECK(s.steady_speed < fw_kn_to_ms(26.7) * 0.8 && s.steady_speed > fw_kn_to_ms(26.7) * 0.3);
    CHECK(s.t180 > s.t90 && s.t90 > 0);
}

static void test_c3_imo(void)
{
    fw_ship c3 = test_load_ship("c3");
    fw_turning_result s = turn(&c3, 26.7, 35.0), p = turn(&c3, 27.16, -35.0);
    CHECK(s.advance_ok && s.tactical_ok && p.advance_ok && p.tactical_ok);
    const double angles[2] = {10.0, 20.0};
    for (int k = 0; k < 2; k++) {
        fw_zigzag_def d = fw_default_zigzag_def();
        d.speed = fw_kn_to_ms(26.7);
        d.angle = fw_deg_to_rad(angles[k]);
        fw_zigzag_result r;
        fw_error err = {0};
        CHECK_MSG(fw_zigzag_run(&c3, &d, &r, NULL, &err) == FW_OK, "%s", err.msg);
        CHECK(r.ok1 && r.ok2);
        CHECK(r.overshoot1 > 0.0 && r.overshoot2 > 0.0);
        CHECK_NEAR(r.L_over_V, 23.16, 0.01);
    }
    double l1, l2;
    fw_imo_overshoot_limits(10.0, 23.2, &l1, &l2);
    CHECK_NEAR(l1, 16.6, 1e-9);
    CHECK_NEAR(l2, 34.9, 1e-9);
    fw_imo_overshoot_limits(10.0, 5.0, &l1, &l2);
    CHECK_NEAR(l1, 10.0, 0);
    CHECK_NEAR(l2, 25.0, 0);
    fw_imo_overshoot_limits(20.0, 23.2, &l1, &l2);
    CHECK_NEAR(l1, 25.0, 0);
    CHECK(l2 < 0);
}

/* Same Froude number, geometrically similar hulls: same non-dimensional turn. */
static void compare_scaled(const fw_ship *m, const fw_ship *f, double fn, double rel)
{
    double Um = fn * sqrt(FW_G * m->L), Uf = fn * sqrt(FW_G * f->L);
    fw_turning_result a = turn(m, fw_ms_to_kn(Um), 35.0), b = turn(f, fw_ms_to_kn(Uf), 35.0);
    CHECK_REL(b.advance / f->L, a.advance / m->L, rel);
    CHECK_REL(b.transfer / f->L, a.transfer / m->L, rel);
    CHECK_REL(b.tactical_diameter / f->L, a.tactical_diameter / m->L, rel);
    CHECK_REL(b.t90 * Uf / f->L, a.t90 * Um / m->L, rel);
    CHECK_REL(b.steady_rate * f->L / Uf, a.steady_rate * m->L / Um, rel);
    CHECK_REL(b.steady_speed / Uf, a.steady_speed / Um, rel);
}

static void test_kvlcc2_froude(void)
{
    fw_ship m = test_load_ship("kvlcc2-l7"), f = test_load_ship("kvlcc2");
    compare_scaled(&m, &f, 0.142, 0.005); /* the two ship files: the 0.5% */
    /* exactly similar (scaled in code): what is left is the integrator's
     * absolute tolerances and the 0.5 s sampling, which do not scale */
    fw_ship g = m;
    double lam = 320.0 / 7.0;
    g.L *= lam;
    g.Loa *= lam;
    g.B *= lam;
    g.d *= lam;
    g.volume *= lam * lam * lam;
    g.x_G *= lam;
    g.D_P *= lam;
    g.H_R *= lam;
    g.A_R *= lam * lam;
    g.rudder_rate /= sqrt(lam);
    compare_scaled(&m, &g, 0.142, 1e-3);
    /* the KVLCC2 free-running turning reference is about 3.1 L advance and
     * 3.2 L tactical diameter: a coarse sanity check of the whole model */
    fw_turning_result r = turn(&f, 15.5, 35.0);
    CHECK_NEAR(r.advance / f.L, 3.1, 0.3);
    CHECK_NEAR(r.tactical_diameter / f.L, 3.2, 0.4);
}

static void test_mirror(void)
{
    fw_ship s = test_load_ship("kvlcc2");
    s.gamma_R_minus = s.gamma_R_plus;
    s.C_2_minus = s.C_2_plus;
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(15.5);
    fw_history hs = {0}, hp = {0};
    fw_turning_result rs, rp;
    fw_error err = {0};
    d.rudder = fw_deg_to_rad(35.0);
    CHECK(fw_turning_run(&s, &d, &rs, &hs, &err) == FW_OK);
    d.rudder = -d.rudder;
    CHECK(fw_turning_run(&s, &d, &rp, &hp, &err) == FW_OK);
    CHECK(hs.n == hp.n && hs.n > 100);
    double worst = 0.0;
    for (size_t i = 0; i < hs.n && i < hp.n; i++) {
        worst = fmax(worst, fabs(hs.s[i].east + hp.s[i].east));
        worst = fmax(worst, fabs(hs.s[i].north - hp.s[i].north));
        worst = fmax(worst, fabs(hs.s[i].psi + hp.s[i].psi) * s.L);
        worst = fmax(worst, fabs(hs.s[i].vm + hp.s[i].vm));
    }
    CHECK_NEAR(worst, 0.0, 1e-6);
    fw_history_free(&hs);
    fw_history_free(&hp);
    /* and the C-3's asymmetric coefficients do make the two sides differ */
    fw_ship c3 = test_load_ship("c3");
    fw_turning_result a = turn(&c3, 26.7, 35.0), b = turn(&c3, 26.7, -35.0);
    CHECK(fabs(a.tactical_diameter - b.tactical_diameter) > 10.0);
}

/* The propeller speed from surge balance keeps the ship at its speed. */
static void test_surge_balance(void)
{
    const char *names[3] = {"c3", "kvlcc2", "kvlcc2-l7"};
    for (int k = 0; k < 3; k++) {
        fw_ship s = test_load_ship(names[k]);
        double U = 0.15 * sqrt(FW_G * s.L), n;
        fw_error err = {0};
        CHECK(fw_mmg_propeller_for_speed(&s, U, &n, &err) == FW_OK);
        fw_mmg_state x = fw_mmg_straight(U, 0, 0, 0.3);
        double dx[6];
        fw_mmg_derivs(&s, &x, n, dx);
        CHECK_NEAR(dx[0], 0.0, 1e-12 * U);
        CHECK_NEAR(dx[1], 0.0, 1e-15);
        CHECK_NEAR(dx[2], 0.0, 1e-15);
        CHECK_NEAR(dx[3], U * sin(0.3), 1e-12);
        CHECK_NEAR(dx[4], U * cos(0.3), 1e-12);
        /* more propeller, more speed */
        fw_mmg_derivs(&s, &x, 1.1 * n, dx);
        CHECK(dx[0] > 0.0);
    }
    fw_ship c3 = test_load_ship("c3");
    double n;
    fw_error err = {0};
    CHECK(fw_mmg_propeller_for_speed(&c3, -1.0, &n, &err) == FW_EINPUT);
    CHECK(fw_mmg_propeller_for_speed(&c3, 0.0, &n, &err) == FW_OK && n == 0.0);
    /* forces stay finite at rest, with or without the propeller turning */
    fw_mmg_state rest = fw_mmg_straight(0.0, 0, 0, 0);
    rest.delta = 0.5;
    double dx[6];
    fw_mmg_derivs(&c3, &rest, 0.0, dx);
    for (int i = 0; i < 6; i++)
        CHECK(isfinite(dx[i]));
    fw_mmg_derivs(&c3, &rest, 1.0, dx);
    for (int i = 0; i < 6; i++)
        CHECK(isfinite(dx[i]));
    CHECK(dx[0] > 0.0); /* the propeller pushes a ship at rest ahead */
    CHECK(dx[2] > 0.0); /* and starboard rudder in its slipstream turns it to starboard */
}

/* One hour of turning and zig-zagging: helm orders every 60 s (and rudder
 * kinks in between).  Returns the final state. */
static fw_mmg_state hour(const fw_ship *s, const fw_stepper_def *def, long *reinits)
{
    static const double orders[] = {20, -10, 35, 0, -35, 5, 15, -25, 0, 30, -5, -20};
    fw_stepper *st;
    fw_error err = {0};
    double n;
    fw_mmg_propeller_for_speed(s, fw_kn_to_ms(20.0), &n, &err);
    CHECK(fw_stepper_create(s, def, &st, &err) == FW_OK);
    fw_mmg_state x0 = fw_mmg_straight(fw_kn_to_ms(20.0), 0, 0, 0);
    CHECK(fw_stepper_start(st, 0.0, &x0, n, &err) == FW_OK);
    for (int k = 0; k < 3600; k++) {
        if (k % 60 == 0)
            fw_stepper_set_helm(st, fw_deg_to_rad(orders[(k / 60) % 12]));
        if (k == 1800)
            fw_stepper_set_propeller(st, 0.8 * n);
        fw_status r = fw_stepper_advance(st, 1.0, &err);
        CHECK_MSG(r == FW_OK, "%s", err.msg);
        if (r)
            break;
    }
    CHECK_NEAR(fw_stepper_time(st), 3600.0, 1e-9);
    fw_mmg_state out = *fw_stepper_state(st);
    if (reinits)
        *reinits = fw_stepper_reinits(st);
    fw_stepper_destroy(st);
    return out;
}

static void test_accuracy(void)
{
    fw_ship c3 = test_load_ship("c3");
    fw_stepper_def tight = fw_default_stepper_def();
    tight.rtol = 1e-11;
    tight.atol_vel = 1e-10;
    tight.atol_pos = 1e-8;
    fw_mmg_state ref = hour(&c3, &tight, NULL);
    fw_stepper_def def = fw_default_stepper_def();
    long reinits = 0;
    fw_mmg_state got = hour(&c3, &def, &reinits);
    CHECK_NEAR(hypot(got.east - ref.east, got.north - ref.north), 0.0, 0.1);
    CHECK_NEAR(got.psi, ref.psi, 0.1 / c3.L);
    /* re-initialised where inputs jump (60 helm orders, their kinks, one
     * propeller change), not at each of the 3600 steps */
    CHECK_MSG(reinits >= 60 && reinits <= 125, "reinits = %ld", reinits);
}

static void test_rudder_servo(void)
{
    fw_ship c3 = test_load_ship("c3");
    fw_stepper *st;
    fw_error err = {0};
    CHECK(fw_stepper_create(&c3, NULL, &st, &err) == FW_OK);
    fw_mmg_state x0 = fw_mmg_straight(fw_kn_to_ms(10.0), 0, 0, 0);
    double n;
    fw_mmg_propeller_for_speed(&c3, x0.u, &n, &err);
    CHECK(fw_stepper_start(st, 0.0, &x0, n, &err) == FW_OK);
    fw_stepper_set_helm(st, fw_deg_to_rad(20.0));
    fw_stepper_advance(st, 1.0, &err);
    CHECK_NEAR(fw_rad_to_deg(fw_stepper_state(st)->delta), 3.0, 1e-9); /* 3 deg/s */
    fw_stepper_advance(st, 5.0, &err);
    CHECK_NEAR(fw_rad_to_deg(fw_stepper_state(st)->delta), 18.0, 1e-9);
    fw_stepper_advance(st, 1.0, &err);
    CHECK_NEAR(fw_rad_to_deg(fw_stepper_state(st)->delta), 20.0, 1e-9);
    fw_stepper_set_helm(st, fw_deg_to_rad(90.0)); /* clamped to the maximum */
    CHECK_NEAR(fw_rad_to_deg(fw_stepper_helm(st)), 35.0, 1e-9);
    fw_stepper_advance(st, 10.0, &err);
    CHECK_NEAR(fw_rad_to_deg(fw_stepper_state(st)->delta), 35.0, 1e-9);
    long before = fw_stepper_reinits(st);
    for (int k = 0; k < 100; k++)
        fw_stepper_advance(st, 1.0, &err);
    CHECK(fw_stepper_reinits(st) - before <= 1); /* nothing changed: no re-initialisation */
    CHECK(fw_stepper_state(st)->r > 0.0);
    CHECK(fw_stepper_advance(st, -1.0, &err) == FW_EINPUT);
    fw_stepper_destroy(st);
}

int main(void)
{
    TEST_RUN(test_c3_sea_trial);
    TEST_RUN(test_c3_imo);
    TEST_RUN(test_kvlcc2_froude);
    TEST_RUN(test_mirror);
    TEST_RUN(test_surge_balance);
    TEST_RUN(test_accuracy);
    TEST_RUN(test_rudder_servo);
    return TEST_EXIT();
}
