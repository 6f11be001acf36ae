/* Nomoto model: the paper's indices, eq 9 and its T1 = T2 limit, ramp tracks. */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "nomoto/nomoto.h"
#include "nomoto/track.h"
#include "ship/ship.h"
#include "test.h"

static fw_ship c3;

static void test_indices_worked_values(void)
{
    /* c3-container-ship.md, the five worked rows */
    static const double rows[5][7] = {
        {26.7, 35, 0.01912, 18.59, 63.62, 100.71, 0.669}, {26.7, 20, 0.03096, 10.94, 60.04, 71.95, 0.619},
        {20.12, 20, 0.02399, 12.55, 77.85, 93.16, 0.480}, {14.55, 10, 0.02609, 21.06, 131.46, 130.87, 0.261},
        {10, 20, 0.01327, 20.94, 151.01, 180.25, 0.265},
    };
    for (int i = 0; i < 5; i++) {
        fw_nomoto_indices ix;
        fw_error err = {0};
        CHECK(fw_nomoto_indices_at(&c3.nomoto, rows[i][0], rows[i][1], &ix, &err) == FW_OK);
        CHECK_NEAR(ix.K, rows[i][2], 5e-6);
        CHECK_NEAR(ix.T1, rows[i][3], 5e-3);
        CHECK_NEAR(ix.T2, rows[i][4], 5e-3);
        CHECK_NEAR(ix.T3, rows[i][5], 5e-3);
        CHECK_NEAR(ix.K * rows[i][1], rows[i][6], 5e-4);
        CHECK(ix.speed_in_range == (rows[i][0] >= 14.55));
        /* a negative helm gives the same indices (magnitude) */
        fw_nomoto_indices jx;
        fw_nomoto_indices_at(&c3.nomoto, rows[i][0], -rows[i][1], &jx, &err);
        CHECK(jx.K == ix.K && jx.T2 == ix.T2);
    }
    /* ln(d) clamped to the fitted minimum: 0 and 2 deg give the 5 deg indices */
    fw_nomoto_indices a, b;
    fw_nomoto_indices_at(&c3.nomoto, 10, 0.0, &a, NULL);
    fw_nomoto_indices_at(&c3.nomoto, 10, 5.0, &b, NULL);
    CHECK(a.K == b.K && a.d_deg == 5.0 && !a.rudder_in_range && b.rudder_in_range);
}

/* eq 9 written out, for distinct T1, T2 */
static double eq9(double K, double T1, double T2, double T3, double d, double t)
{
    return K * d * (1 - (T1 - T3) / (T1 - T2) * exp(-t / T1) - (T3 - T2) / (T1 - T2) * exp(-t / T2));
}

static void test_step_response(void)
{
    fw_nomoto_indices ix;
    fw_nomoto_indices_at(&c3.nomoto, 26.7, 20, &ix, NULL);
    CHECK_NEAR(fw_nomoto_step_rate(&ix, 20, 0.0), 0.0, 1e-14);
    CHECK_REL(fw_nomoto_step_rate(&ix, 20, 5000.0), ix.K * 20, 1e-12);
    for (double t = 1; t < 400; t *= 1.7)
        CHECK_REL(fw_nomoto_step_rate(&ix, 20, t), eq9(ix.K, ix.T1, ix.T2, ix.T3, 20, t), 1e-10);
    /* symmetric in T1 and T2 */
    fw_nomoto_indices sw = ix;
    sw.T1 = ix.T2, sw.T2 = ix.T1;
    for (double t = 0.5; t < 400; t *= 1.9)
        CHECK_REL(fw_nomoto_step_rate(&sw, 20, t), fw_nomoto_step_rate(&ix, 20, t), 1e-12);
    /* continuity through T1 = T2: the limit K d (1 - e (1 + (T - T3) t / T^2)) at
     * equality, and both sides of the series/direct switch agree with it */
    fw_nomoto_indices eq = ix;
    eq.T1 = eq.T2 = 40.0;
    for (double t = 0.5; t < 400; t *= 1.9) {
        double T = 40.0, lim = ix.K * 20 * (1 - exp(-t / T) * (1 + (T - ix.T3) * t / (T * T)));
        CHECK_REL(fw_nomoto_step_rate(&eq, 20, t), lim, 1e-12);
        for (double eps = 1e-9; eps < 1e-2; eps *= 10) {
            fw_nomoto_indices near = eq;
            near.T1 = T * (1 + eps);
            CHECK_NEAR(fw_nomoto_step_rate(&near, 20, t), lim, 20 * eps * fabs(lim) + 1e-13);
        }
    }
    /* phi on both sides of its switch (x = t dT / (T1 T2) = 1e-3) */
    double T1 = 50.0, t = 100.0, dT = 1e-3 * 50.0 * 50.0 / t;
    CHECK_REL(fw_nomoto_phi(T1 + dT * 0.999, T1, t), fw_nomoto_phi(T1 + dT * 1.001, T1, t), 1e-5);
}

/* Reference: RK4 with a tiny step on state (r, r', psi, x, y), rudder ramp. */
static void reference_track(const fw_nomoto_indices *ix, const fw_own_state *s, double helm,
                            double rate, double T, double out[5])
{
    double y[5] = {s->r, s->rdot, 0.0, 0.0, 0.0};
    /* two legs so the end of the ramp (a jump in delta') is a grid point */
    double t_ramp = fabs(helm - s->delta) / rate, legs[2][2] = {{0, t_ramp}, {t_ramp, T}};
    for (int leg = 0; leg < 2; leg++) {
    int steps = (int)ceil((legs[leg][1] - legs[leg][0]) / 0.01);
    double h = (legs[leg][1] - legs[leg][0]) / steps;
    for (int step = 0; step < steps; step++) {
        double t = legs[leg][0] + step * h;
        double k[4][5], tmp[5];
        for (int st = 0; st < 4; st++) {
            double tt = t + (st == 0 ? 0 : (st == 3 ? h : h / 2));
            /* the ramp rate applies strictly inside the first leg */
            if (leg == 1 && tt < t_ramp)
                tt = t_ramp;
            if (leg == 0 && tt >= t_ramp)
                tt = t_ramp * (1 - 1e-15);
            const double *yy = y;
            if (st > 0) {
                for (int j = 0; j < 5; j++)
                    tmp[j] = y[j] + (st == 3 ? h : h / 2) * k[st - 1][j];
                yy = tmp;
            }
            double tr = fabs(helm - s->delta) / rate;
            double d = tt < tr ? s->delta + copysign(rate, helm - s->delta) * tt : helm;
            double dd = tt < tr ? copysign(rate, helm - s->delta) : 0.0;
            k[st][0] = yy[1];
            k[st][1] = (ix->K * d + ix->K * ix->T3 * dd - yy[0] - (ix->T1 + ix->T2) * yy[1]) /
                       (ix->T1 * ix->T2);
            k[st][2] = yy[0];
            k[st][3] = s->U * sin(s->psi + yy[2]);
            k[st][4] = s->U * cos(s->psi + yy[2]);
        }
        for (int j = 0; j < 5; j++)
            y[j] += h / 6 * (k[0][j] + 2 * k[1][j] + 2 * k[2][j] + k[3][j]);
    }
    }
    for (int j = 0; j < 5; j++)
        out[j] = y[j];
}

static void test_track_against_rk4(void)
{
    fw_track_def def = fw_default_track_def();
    def.max_turn = 0.0;
    def.horizon = 300.0;
    fw_track tr;
    CHECK(fw_track_alloc(&tr, fw_track_samples(&def), NULL) == FW_OK);
    /* from rest, and from a port turn with port rudder (helm reversal) */
    fw_own_state starts[2] = {
        {.east = 10, .north = -20, .psi = 0.3, .U = fw_kn_to_ms(10)},
        {.east = 0, .north = 0, .psi = 1.0, .U = fw_kn_to_ms(10), .r = fw_deg_to_rad(-0.2),
         .rdot = fw_deg_to_rad(-0.001), .delta = fw_deg_to_rad(-15)},
    };
    for (int c = 0; c < 2; c++) {
        double helm = fw_deg_to_rad(25);
        CHECK(fw_track_predict(&c3, &def, &starts[c], helm, &tr, NULL) == FW_OK);
        fw_nomoto_indices ix;
        fw_nomoto_indices_at(&c3.nomoto, 10, 25, &ix, NULL);
        double ref[5];
        reference_track(&ix, &starts[c], helm, c3.rudder_rate, 300.0, ref);
        int k = tr.n - 1;
        CHECK_NEAR(tr.r[k], ref[0], 1e-9);
        CHECK_NEAR(tr.psi[k] - starts[c].psi, ref[2], 1e-8);
        CHECK_NEAR(tr.east[k] - starts[c].east, ref[3], 0.5);
        CHECK_NEAR(tr.north[k] - starts[c].north, ref[4], 0.5);
        CHECK_NEAR(tr.sin_psi[k], sin(tr.psi[k]), 1e-9);
        CHECK_NEAR(tr.cos_psi[k], cos(tr.psi[k]), 1e-9);
        CHECK_NEAR(tr.delta[k], helm, 1e-12);
    }
    fw_track_free(&tr);
}

static void test_track_mirror_and_limit(void)
{
    fw_track_def def = fw_default_track_def();
    fw_track a, b, m;
    int n = fw_track_samples(&def);
    fw_track_alloc(&a, n, NULL);
    fw_track_alloc(&b, n, NULL);
    fw_track_alloc(&m, n, NULL);
    fw_own_state s = {.east = 100, .north = 50, .psi = fw_deg_to_rad(40), .U = fw_kn_to_ms(10)};
    for (double h = 10; h <= 35; h += 5) {
        fw_track_predict(&c3, &def, &s, fw_deg_to_rad(h), &a, NULL);
        fw_track_predict(&c3, &def, &s, fw_deg_to_rad(-h), &b, NULL);
        fw_track_mirror(&a, &s, &m);
        double worst = 0, worst_psi = 0;
        for (int k = 0; k < n; k++) {
            worst = fmax(worst, hypot(m.east[k] - b.east[k], m.north[k] - b.north[k]));
            worst_psi = fmax(worst_psi, fabs(m.psi[k] - b.psi[k]));
        }
        CHECK_NEAR(worst, 0.0, 1e-6);
        CHECK_NEAR(worst_psi, 0.0, 1e-12);
        /* the prediction steadies at 90 deg of turn */
        CHECK_NEAR(a.psi[n - 1] - s.psi, def.max_turn, 1e-12);
        CHECK(a.psi[n / 3] - s.psi > 0.0);
    }
    fw_track_free(&a);
    fw_track_free(&b);
    fw_track_free(&m);
}

/* A prediction made a few samples at a time (fw_track_extend, as the helm
 * search makes its candidates) is the whole prediction to the bit, however
 * the extensions are cut: c3 and c3-mmg (drift and speed loss), a delay (three
 * rudder pieces), turning starts, every cut from 1 to 17 samples; and a
 * mirrored range is the mirrored whole. */
static void test_track_in_pieces_is_the_track(void)
{
    fw_ship mmg;
    fw_error err = {0};
    CHECK(fw_ship_load("c3-mmg", &mmg, &err) == FW_OK);
    const fw_ship *ships[2] = {&c3, &mmg};
    fw_track_def def = fw_default_track_def();
    int n = fw_track_samples(&def), differ = 0, cases = 0;
    fw_track whole, part, m1, m2;
    fw_track_alloc(&whole, n, NULL);
    fw_track_alloc(&part, n, NULL);
    fw_track_alloc(&m1, n, NULL);
    fw_track_alloc(&m2, n, NULL);
    for (int sh = 0; sh < 2; sh++)
        for (int c = 0; c < 4; c++) {
            fw_own_state s = {.east = 10, .north = -20, .psi = fw_deg_to_rad(70 * c),
                              .U = fw_kn_to_ms(8 + c), .r = c % 2 ? fw_deg_to_rad(0.2) : 0.0,
                              .delta = c % 2 ? fw_deg_to_rad(-10) : 0.0,
                              .beta = c % 2 ? 0.02 : 0.0};
            fw_track_def d = def;
            d.delay = c >= 2 ? 12.5 : 0.0;
            double helm = fw_deg_to_rad(c % 2 ? -27 : 18);
            CHECK(fw_track_predict(ships[sh], &d, &s, helm, &whole, NULL) == FW_OK);
            fw_track_mirror(&whole, &s, &m1);
            for (int cut = 1; cut <= 17; cut++) {
                fw_track_gen g;
                CHECK(fw_track_start(ships[sh], &d, &s, helm, &part, &g, NULL) == FW_OK);
                for (int k = 0; k < n; k += cut) {
                    fw_track_extend(&g, &part, k + cut);
                    fw_track_mirror_range(&part, &s, &m2, k, k + cut < n ? k + cut : n);
                }
                fw_track_extend(&g, &part, n + 5); /* past the end: nothing more */
                cases++;
                differ += part.n != n || g.k != n ||
                          memcmp(part.east, whole.east, sizeof(double) * 8 * (size_t)n) != 0 ||
                          memcmp(m2.east, m1.east, sizeof(double) * 8 * (size_t)n) != 0;
            }
        }
    CHECK_MSG(differ == 0, "%d of %d piecewise predictions differ from the whole", differ, cases);
    fw_track_free(&whole);
    fw_track_free(&part);
    fw_track_free(&m1);
    fw_track_free(&m2);
}

/* The autopilot prediction is the closed loop it stands for: one-second
 * steps of the fixed-helm predictor with the PD order recomputed each second
 * give nearly the same track (no drift terms in c3, so nothing is lost
 * between calls; the predictor updates the order every 5 s and rounds it to
 * whole degrees for the indices: 2.7 m apart after 10 minutes), and it
 * settles on the ordered heading. */
static void test_steer_prediction_is_the_closed_loop(void)
{
    fw_track_def def = fw_default_track_def();
    fw_own_state s0 = {.psi = fw_deg_to_rad(40), .U = fw_kn_to_ms(10), .r = fw_deg_to_rad(0.2),
                       .delta = fw_deg_to_rad(15)};
    fw_steer_def ap = {.psi_ref = 0.0, .kp = 1.0, .kd = 20.0, .max_helm = fw_deg_to_rad(20)};
    fw_track pred, one;
    fw_error err = {0};
    fw_track_alloc(&pred, fw_track_samples(&def), NULL);
    fw_track_alloc(&one, 2, NULL);
    CHECK(fw_track_predict_steer(&c3, &def, &s0, &ap, &pred, &err) == FW_OK);
    fw_track_def sec = {.dt = 1.0, .horizon = 1.0};
    fw_own_state x = s0;
    double worst = 0.0;
    for (int k = 1; k <= 600; k++) {
        double h = -ap.kp * fw_wrap_pi(x.psi - ap.psi_ref) - ap.kd * x.r;
        h = fmax(-ap.max_helm, fmin(ap.max_helm, h));
        CHECK(fw_track_predict(&c3, &sec, &x, h, &one, &err) == FW_OK);
        x.east = one.east[1], x.north = one.north[1], x.psi = one.psi[1];
        x.r = one.r[1], x.rdot = one.rdot[1], x.delta = one.delta[1];
        if (k % 5 == 0)
            worst = fmax(worst, hypot(x.east - pred.east[k / 5], x.north - pred.north[k / 5]));
    }
    int last = pred.n - 1;
    CHECK_NEAR(fw_wrap_pi(pred.psi[last]), 0.0, fw_deg_to_rad(1.0));
    CHECK_MSG(worst < 10.0, "%.1f m apart", worst);
    printf("  autopilot prediction vs one-second closed loop: %.1f m at most over 600 s, "
           "heading %.2f deg at the end\n", worst, fw_rad_to_deg(fw_wrap_pi(pred.psi[last])));
    fw_track_free(&pred);
    fw_track_free(&one);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_indices_worked_values);
    TEST_RUN(test_step_response);
    TEST_RUN(test_track_against_rk4);
    TEST_RUN(test_track_mirror_and_limit);
    TEST_RUN(test_steer_prediction_is_the_closed_loop);
    TEST_RUN(test_track_in_pieces_is_the_track);
    return TEST_EXIT();
}
