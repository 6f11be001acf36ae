/* test_wind.c - wind on the own ship (ship/windage.h, dynamics/mmg.h).
 *
 *   Blendermann's coefficients at 0, 90 and 180 deg apparent wind equal his
 *     table (every ship type, to 1e-12): C_X(0) = -CD_lAF(bow), C_X(180) =
 *     +CD_lAF(stern), |C_Y(90)| = CD_t, and zero where the table says so;
 *     C_X even, C_Y and C_N odd in gamma
 *   the apparent wind: a ship at rest sees the true wind, a ship under way in
 *     still air a head wind of its own speed
 *   a beam wind (30 kn from 090) on the c3-mmg at rest and at 12 kn, rudder
 *     amidships: it drifts to leeward (west), sets to port of its heading
 *     (leeway), its heading starts to turn the way the wind's moment about
 *     the centre of gravity says, and after 10 minutes it has luffed up
 *     (turned into the wind) under the hull's own moment
 *   a calm wind (speed 0) is still air, bit for bit
 *   Froude similarity in a wind: kvlcc2 and its L7 model (windage scaled by
 *     1/lambda^2, wind by 1/sqrt(lambda)) turn the same in ship lengths:
 *     advance and tactical diameter to 0.5%, the circle's drift to 2% and 1
 *     deg, towards leeward
 *   a ship without windage, in a wind, is refused
 */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "dynamics/manoeuvre.h"
#include "dynamics/mmg.h"
#include "dynamics/stepper.h"
#include "ship/windage.h"
#include "test.h"
#include "test_ship.h"

static fw_ship c3;

static void test_table_at_0_90_180(void)
{
    const double tol = 1e-12, d = FW_PI / 180.0;
    for (int i = 0; i < FW_WT_COUNT; i++) {
        const fw_blendermann *b = &fw_blendermann_table[i];
        fw_windage w = {.present = true, .type = (fw_windage_type)i, .A_F = 1500.0,
                        .A_L = 9000.0, .s_L = -10.0, .Loa = 300.0};
        double CX, CY, CN;
        fw_windage_coeffs(&w, 0.0, &CX, &CY, &CN);
        CHECK_NEAR(CX, -b->CD_lAF_bow, tol);
        CHECK_NEAR(CY, 0.0, tol);
        CHECK_NEAR(CN, 0.0, tol);
        fw_windage_coeffs(&w, 90.0 * d, &CX, &CY, &CN);
        CHECK_NEAR(CX, 0.0, tol);
        CHECK_NEAR(CY, -b->CD_t, tol);
        /* beam wind: the side force at the centroid of A_L */
        CHECK_NEAR(CN, -b->CD_t * w.s_L / w.Loa, tol);
        fw_windage_coeffs(&w, 180.0 * d, &CX, &CY, &CN);
        CHECK_NEAR(CX, b->CD_lAF_stern, tol);
        CHECK_NEAR(CY, 0.0, tol);
        /* symmetry of the hull: C_X even, C_Y and C_N odd */
        double g = 37.0 * d, CX2, CY2, CN2;
        fw_windage_coeffs(&w, g, &CX, &CY, &CN);
        fw_windage_coeffs(&w, -g, &CX2, &CY2, &CN2);
        CHECK(CX == CX2 && CY == -CY2 && CN == -CN2);
    }
    /* the two types the ship files use, against the numbers printed in the
     * table (Fossen 2011 ch. 10 / MSS blendermann94.m) */
    const fw_blendermann *cs = &fw_blendermann_table[FW_WT_CONTAINER_LOADED];
    CHECK(strcmp(cs->name, "container_loaded") == 0 && cs->CD_t == 0.90 &&
          cs->CD_lAF_bow == 0.55 && cs->CD_lAF_stern == 0.55 && cs->delta == 0.40);
    const fw_blendermann *tk = &fw_blendermann_table[FW_WT_TANKER_LOADED];
    CHECK(strcmp(tk->name, "tanker_loaded") == 0 && tk->CD_t == 0.70 &&
          tk->CD_lAF_bow == 0.90 && tk->CD_lAF_stern == 0.55 && tk->delta == 0.40);
    fw_windage_type t;
    CHECK(fw_windage_type_parse("tanker_loaded", &t) && t == FW_WT_TANKER_LOADED);
    CHECK(!fw_windage_type_parse("tanker", &t));
}

static void test_apparent_wind(void)
{
    double V, g;
    /* at rest heading north, 10 m/s from the east: on the starboard beam */
    fw_apparent_wind(10.0, FW_PI / 2, 0.0, 0.0, 0.0, &V, &g);
    CHECK_NEAR(V, 10.0, 1e-12);
    CHECK_NEAR(g, FW_PI / 2, 1e-12);
    /* heading east at 6 m/s in still air: a head wind of 6 m/s */
    fw_apparent_wind(0.0, 0.0, FW_PI / 2, 6.0, 0.0, &V, &g);
    CHECK_NEAR(V, 6.0, 1e-12);
    CHECK_NEAR(g, 0.0, 1e-12);
    /* heading north at 5 m/s, 5 m/s from the south: no air over the ship */
    fw_apparent_wind(5.0, FW_PI, 0.0, 0.0, 5.0, &V, &g);
    CHECK_NEAR(V, 0.0, 1e-12);
    /* the force: a wind from starboard pushes to port */
    double X, Y, N;
    fw_windage_force(&c3.windage, 15.0, FW_PI / 2, &X, &Y, &N);
    CHECK(Y < 0.0);
    CHECK_REL(Y, -0.5 * FW_AIR_DENSITY * 225.0 * c3.windage.A_L * 0.90, 1e-12);
}

/* The c3-mmg from (0, 0) heading north at `kn` knots, rudder amidships, for
 * t seconds in `wind`; the final state, and the states at 10 s and 60 s in
 * xs[0], xs[1]. */
static fw_mmg_state run(double kn, const fw_wind *wind, double t, fw_mmg_state xs[2])
{
    fw_error err = {0};
    fw_stepper_def sd = fw_default_stepper_def();
    sd.wind = *wind;
    fw_stepper *st;
    double n = 0.0;
    CHECK_MSG(fw_mmg_propeller_for_speed(&c3, fw_kn_to_ms(kn), &n, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(fw_stepper_create(&c3, &sd, &st, &err) == FW_OK, "%s", err.msg);
    fw_mmg_state x0 = fw_mmg_straight(fw_kn_to_ms(kn), 0.0, 0.0, 0.0);
    CHECK_MSG(fw_stepper_start(st, 0.0, &x0, n, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(fw_stepper_advance(st, 10.0, &err) == FW_OK, "%s", err.msg);
    xs[0] = *fw_stepper_state(st);
    CHECK_MSG(fw_stepper_advance(st, 50.0, &err) == FW_OK, "%s", err.msg);
    xs[1] = *fw_stepper_state(st);
    CHECK_MSG(fw_stepper_advance(st, t - 60.0, &err) == FW_OK, "%s", err.msg);
    fw_mmg_state x = *fw_stepper_state(st);
    fw_stepper_destroy(st);
    return x;
}

static void beam_wind_at(double kn)
{
    fw_wind still = {.kind = FW_FIELD_NONE};
    fw_wind beam = {.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(30.0), .from = FW_PI / 2};
    fw_mmg_state ax[2], bx[2];
    fw_mmg_state a = run(kn, &still, 600.0, ax), b = run(kn, &beam, 600.0, bx);
    const fw_mmg_state a1 = ax[1], b1 = bx[1];
    /* the wind's force and moment at the start; the heading first turns (at
     * 10 s) as the moment about the centre of gravity, N - x_G Y, says (x_G
     * is aft of midship on this hull, so a side force at midship turns it
     * too); later the hull's own moment from its sideways motion (N_v v, the
     * Munk moment) turns the bow into the wind */
    fw_mmg_state x0 = fw_mmg_straight(fw_kn_to_ms(kn), 0.0, 0.0, 0.0);
    double f[3];
    fw_mmg_wind(&c3, &x0, 0.0, 0.0, beam.speed, beam.from, f);
    double N_G = f[2] - c3.x_G * f[1];
    double leeway = atan2(b1.vm, b1.u); /* through the water, off the heading: < 0 to port */
    double turn10 = bx[0].psi - ax[0].psi;
    printf("  %4.1f kn, 30 kn from 090: heading at 10 s %+.4f deg (N_G %+.3g N m); at 60 s "
           "%.1f m to leeward of the calm track, leeway %+.2f deg, heading %+.3f deg; at 600 s "
           "%+.1f m, heading %+.2f deg, sway %.3f m/s, speed %.2f kn\n",
           kn, fw_rad_to_deg(turn10), N_G, a1.east - b1.east, fw_rad_to_deg(leeway),
           fw_rad_to_deg(b1.psi - a1.psi),
           a.east - b.east, fw_rad_to_deg(b.psi - a.psi), b.vm, fw_ms_to_kn(hypot(b.u, b.vm)));
    CHECK(f[1] < 0.0);                 /* pushed to port, the lee side */
    CHECK(b1.east < a1.east - 1.0);    /* drifted to leeward: west */
    CHECK(b1.vm < 0.0 && b.vm < 0.0);  /* sideways to port */
    if (kn > 0.0)
        CHECK(leeway < 0.0);
    CHECK(turn10 * N_G > 0.0);
    CHECK(b.psi - a.psi > 0.0); /* then into the wind (starboard, where it comes from) */
    CHECK(fabs(a.east) < 1e-6); /* calm: straight north */
}

static void test_beam_wind(void)
{
    beam_wind_at(0.0);
    beam_wind_at(12.0);
}

static void test_calm_wind_is_still_air(void)
{
    fw_wind still = {.kind = FW_FIELD_NONE};
    fw_wind zero = {.kind = FW_FIELD_UNIFORM, .speed = 0.0, .from = 1.0};
    fw_mmg_state ax[2], bx[2];
    fw_mmg_state a = run(12.0, &still, 300.0, ax), b = run(12.0, &zero, 300.0, bx);
    CHECK(memcmp(&a, &b, sizeof a) == 0);
    /* and derivs_ext with NULL is derivs */
    fw_mmg_state x = fw_mmg_straight(5.0, 1.0, 2.0, 0.3);
    x.delta = 0.2, x.r = 0.01, x.vm = -0.3;
    double d1[6], d2[6];
    fw_mmg_derivs(&c3, &x, 1.0, d1);
    fw_mmg_derivs_ext(&c3, &x, 1.0, NULL, d2);
    CHECK(memcmp(d1, d2, sizeof d1) == 0);
}

/* A 35 deg starboard turn at U kn in a wind of W kn from 090 (on to 720 deg). */
static fw_turning_result windy_turn(const fw_ship *s, double U, double W)
{
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(U);
    d.rudder = fw_deg_to_rad(35.0);
    d.max_turn = fw_deg_to_rad(730.0);
    d.stepper.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(W),
                               .from = FW_PI / 2};
    fw_turning_result r;
    fw_error err = {0};
    CHECK_MSG(fw_turning_run(s, &d, &r, NULL, &err) == FW_OK, "%s", err.msg);
    return r;
}

/* Froude similarity with wind: the L7 model's windage is the full-scale
 * ship's scaled by 1/lambda^2, so in a wind scaled by 1/sqrt(lambda) (air
 * and water forces both then scale by lambda^3) the turn is the same in
 * ship lengths: advance, tactical diameter and the circle's drift. */
static void test_froude_with_wind(void)
{
    fw_ship m = test_load_ship("kvlcc2-l7"), f = test_load_ship("kvlcc2");
    double root = sqrt(320.0 / 7.0);
    fw_turning_result a = windy_turn(&m, 15.5 / root, 30.0 / root);
    fw_turning_result b = windy_turn(&f, 15.5, 30.0);
    printf("  kvlcc2 35 deg at 15.5 kn in 30 kn from 090 (L7 at 1/sqrt(lambda)): advance "
           "%.4f L / %.4f L, tactical diameter %.4f L / %.4f L, drift %.4f L / %.4f L towards "
           "%.1f / %.1f deg\n",
           b.advance / f.L, a.advance / m.L, b.tactical_diameter / f.L,
           a.tactical_diameter / m.L, b.drift / f.L, a.drift / m.L,
           fw_rad_to_deg(b.drift_towards), fw_rad_to_deg(a.drift_towards));
    CHECK_REL(b.advance / f.L, a.advance / m.L, 0.005);
    CHECK_REL(b.tactical_diameter / f.L, a.tactical_diameter / m.L, 0.005);
    CHECK_REL(b.drift / f.L, a.drift / m.L, 0.02);
    CHECK_NEAR(b.drift_towards, a.drift_towards, fw_deg_to_rad(1.0));
    /* to leeward: west, give or take the turn's own asymmetry */
    CHECK(fabs(fw_rad_to_deg(b.drift_towards) - 270.0) < 20.0);
}

static void test_no_windage_refused(void)
{
    fw_ship bare = c3;
    bare.windage.present = false;
    fw_error err = {0};
    fw_stepper_def sd = fw_default_stepper_def();
    sd.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = 5.0, .from = 0.0};
    fw_stepper *st = NULL;
    CHECK(fw_stepper_create(&bare, &sd, &st, &err) == FW_EINPUT && st == NULL);
    CHECK_MSG(strstr(err.msg, "windage") && strstr(err.msg, "refused"), "%s", err.msg);
    sd.wind.speed = 0.0; /* calm: fine */
    CHECK(fw_stepper_create(&bare, &sd, &st, &err) == FW_OK);
    fw_stepper_destroy(st);
}

int main(void)
{
    c3 = test_load_ship("c3-mmg");
    CHECK(c3.windage.present && c3.windage.type == FW_WT_CONTAINER_LOADED);
    TEST_RUN(test_table_at_0_90_180);
    TEST_RUN(test_apparent_wind);
    TEST_RUN(test_beam_wind);
    TEST_RUN(test_calm_wind_is_still_air);
    TEST_RUN(test_froude_with_wind);
    TEST_RUN(test_no_windage_refused);
    return TEST_EXIT();
}
