/* c3-paper against the paper's ship (Table 2, equations 9 and 10) and the
 * calibration's targets, bounds and pull towards the regression values. */
#include <math.h>
#include <stdlib.h>

#include "core/units.h"
#include "fit/calibrate.h"
#include "nomoto/nomoto.h"
#include "test.h"
#include "test_ship.h"


static fw_turning_result turn(const fw_ship *s, double kn, double deg, fw_history *h)
{
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(kn);
    d.rudder = fw_deg_to_rad(deg);
    d.max_turn = fw_deg_to_rad(540.0);
    d.max_time = 10000.0;
    fw_turning_result r;
    fw_error err = {0};
    CHECK_MSG(fw_turning_run(s, &d, &r, h, &err) == FW_OK, "%s", err.msg);
    return r;
}

/* Table 2, both sides: every row within 10 percent. */
static void test_c3_paper_trial(void)
{
    fw_ship c = test_load_ship("c3-paper");
    fw_turning_result s = turn(&c, 26.7, 35.0, NULL), p = turn(&c, 27.16, -35.0, NULL);
    CHECK_REL(s.advance, 1125.0, 0.10);
    CHECK_REL(s.transfer, 543.0, 0.10);
    CHECK_REL(s.tactical_diameter, 1451.0, 0.10);
    CHECK_REL(fw_rad_to_deg(s.steady_rate), 0.690, 0.10);
    CHECK_REL(p.advance, 1204.0, 0.10);
    CHECK_REL(p.transfer, 468.0, 0.10);
    CHECK_REL(p.tactical_diameter, 1336.0, 0.10);
    CHECK_REL(fw_rad_to_deg(p.steady_rate), 0.746, 0.10);
}

/* Equation 10 written out here, not read from a ship file: U kn, d deg. */
static double eq10_rate(double U, double d)
{
    return (0.002679 + 0.003435 * U - 0.000793 * U * log(d)) * d;
}

/* Equation 10's steady rate over the paper's fitted grid within 10 percent,
 * and equation 9's first 150 s within 10 percent of K delta (RMS). */
static void test_c3_paper_eq10(void)
{
    fw_ship c = test_load_ship("c3-paper"), c3 = test_load_ship("c3");
    const double speeds[3] = {14.55, 20.12, 26.7};
    for (int i = 0; i < 3; i++)
        for (double d = 5.0; d <= 35.0; d += 5.0) {
            fw_history h = {0};
            fw_turning_result r = turn(&c, speeds[i], d, &h);
            double target = eq10_rate(speeds[i], d);
            CHECK_REL(fw_rad_to_deg(r.steady_rate), target, 0.10);
            fw_nomoto_indices ix;
            fw_error err = {0};
            CHECK(fw_nomoto_indices_at(&c3.nomoto, speeds[i], d, &ix, &err) == FW_OK);
            CHECK_REL(ix.K * d, target, 1e-9); /* c3's knowledge base is equation 10 */
            double ss = 0.0;
            int n = 0;
            for (size_t k = 10; k < h.n && h.s[k].t <= 150.0 + 1e-9; k += 10, n++) {
                double e = fw_rad_to_deg(h.s[k].r) - fw_nomoto_step_rate(&ix, d, h.s[k].t);
                ss += e * e;
            }
            CHECK(n == 30);
            CHECK_MSG(sqrt(ss / n) < 0.10 * target, "%.2f kn %.0f deg: eq 9 RMS %.3f deg/s",
                      speeds[i], d, sqrt(ss / n));
            fw_history_free(&h);
        }
}

static fw_trial small_trial(double prior_weight)
{
    fw_trial t;
    fw_error err = {0};
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/data/c3-paper-trial-small.yaml", fw_data_root());
    CHECK_MSG(fw_trial_load(path, &t, &err) == FW_OK, "%s", err.msg);
    t.prior_weight = prior_weight;
    return t;
}

/* One coefficient, one equation-10 target: the fit meets it; a strong pull
 * keeps the coefficient at its regression value instead; bounds hold. */
static void test_calibrate_targets(void)
{
    fw_trial t = small_trial(0.0);
    CHECK(t.nturns == 1 && t.turns[0].from_kb && t.ntune == 1);
    CHECK_REL(fw_rad_to_deg(t.turns[0].steady_rate), eq10_rate(20.12, 10.0), 1e-9);
    CHECK(fw_trial_row_history(&t.turns[0]) == 0);
    fw_ship c = test_load_ship("c3-paper");
    fw_calibration cal;
    fw_error err = {0};
    CHECK_MSG(fw_calibrate(&c, &t, &cal, &err) == FW_OK, "%s", err.msg);
    CHECK(cal.max_after < 0.002);
    CHECK(cal.max_after < cal.max_before);
    fw_ship pulled = test_load_ship("c3-paper");
    fw_trial strong = small_trial(100.0);
    CHECK(fw_calibrate(&pulled, &strong, &cal, &err) == FW_OK);
    CHECK_REL(cal.after[0], cal.regression[0], 0.02);
    CHECK(cal.max_after > 0.01); /* the pull wins, the target is missed */
    fw_ship bounded = test_load_ship("c3-paper");
    fw_trial narrow = small_trial(0.0);
    narrow.factor[0] = 1.05;
    CHECK(fw_calibrate(&bounded, &narrow, &cal, &err) == FW_OK);
    CHECK(cal.after[0] / cal.regression[0] <= 1.05 + 1e-9 &&
          cal.after[0] / cal.regression[0] >= 1 / 1.05 - 1e-9);
}

int main(void)
{
    TEST_RUN(test_c3_paper_trial);
    TEST_RUN(test_c3_paper_eq10);
    TEST_RUN(test_calibrate_targets);
    return TEST_EXIT();
}
