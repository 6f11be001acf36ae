/* test_arpa.c - radar plots and the alpha-beta tracker (sense/arpa.h):
 *   a straight radial pass with range noise only: the filtered position's
 *     error variance along the line of sight equals the stated VRR x sigma^2
 *     within 10% (20 000 scans after the track settles); across it, 0
 *   a slow tangential pass at 6 nm with bearing noise only: the cross-range error
 *     variance equals VRR x (r sigma_b)^2 within 10%
 *   the lag on an accelerating target (no noise) equals the stated bias to 1e-6
 *   the same seed gives the same plots */
#include <math.h>
#include <stdio.h>

#include "core/streams.h"
#include "core/units.h"
#include "sense/arpa.h"
#include "test.h"

/* The tracker these tests were written for: alpha 0.5 (Benedict-Bordner),
 * whose short memory lets 20 000 scans measure its variance to a few per
 * cent; the default, 0.1, is checked through the sensor (test_radar.c). */
static fw_radar_def fast_def(void)
{
    fw_radar_def d = fw_default_radar_def();
    d.alpha = 0.5;
    d.beta = d.alpha * d.alpha / (2.0 - d.alpha);
    return d;
}

/* Tracks a target at (e0 + ve t, n0 + vn t) from the origin for scans plots;
 * returns the mean squared filtered error east and north after 50 plots. */
static void pass(const fw_radar_def *d, uint64_t seed, double e0, double n0, double ve, double vn,
                 int scans, double *mse_e, double *mse_n)
{
    fw_streams *st = fw_streams_create(seed);
    fw_rng *rng = fw_streams_get(st, fw_rng_vessel_key("target"), FW_PURPOSE_SENSING);
    fw_ab_track tr = {0};
    double se = 0.0, sn = 0.0;
    int m = 0;
    for (int k = 0; k < scans + 50; k++) {
        double t = k * d->scan, te = e0 + ve * t, tn = n0 + vn * t, ze, zn;
        fw_radar_plot(d, rng, 0.0, 0.0, te, tn, &ze, &zn);
        fw_ab_update(&tr, d, t, ze, zn);
        if (k >= 50) {
            se += (tr.e - te) * (tr.e - te);
            sn += (tr.n - tn) * (tr.n - tn);
            m++;
        }
    }
    *mse_e = se / m;
    *mse_n = sn / m;
    fw_streams_free(st);
}

static void test_radial_range_noise(void)
{
    fw_radar_def d = fast_def();
    d.bearing_sd = 0.0;
    double e, n, vrr = fw_ab_position_vrr(d.alpha, d.beta);
    pass(&d, 7, 0.0, 1000.0, 0.0, 0.5, 20000, &e, &n); /* 1 kn away, due north */
    fprintf(stderr, "radial: measured %.2f m^2, theory %.2f m^2\n", n, vrr * d.range_sd * d.range_sd);
    CHECK_REL(n, vrr * d.range_sd * d.range_sd, 0.10);
    CHECK(e < 1e-12);
    /* alpha 0.5, Benedict-Bordner: (0.5 + 1/3 - 0.25) / (0.5 (3 - 1/6)) = 0.4118 */
    CHECK_NEAR(vrr, 0.7 / 1.7, 1e-12);
}

static void test_tangential_bearing_noise(void)
{
    fw_radar_def d = fast_def();
    d.range_sd = 0.0;
    double r = fw_nm_to_m(6.0), e, n, vrr = fw_ab_position_vrr(d.alpha, d.beta);
    /* 0.05 m/s east, 1250 m either side of due north: the range stays
     * within 0.7% of 6 nm and the line of sight within 6.5 deg of north */
    pass(&d, 9, -1250.0 - 50 * d.scan * 0.05, r, 0.05, 0.0, 20000, &e, &n);
    double sb = r * d.bearing_sd;
    fprintf(stderr, "tangential: measured %.2f m^2, theory %.2f m^2\n", e, vrr * sb * sb);
    CHECK_REL(e, vrr * sb * sb, 0.10);
}

static void test_lag(void)
{
    fw_radar_def d = fast_def();
    d.range_sd = d.bearing_sd = 0.0;
    double acc = 0.05, T = d.scan;
    fw_ab_track tr = {0};
    double te = 0.0;
    fw_streams *st = fw_streams_create(1);
    fw_rng *rng = fw_streams_get(st, 1, FW_PURPOSE_SENSING);
    for (int k = 0; k < 400; k++) {
        double t = k * T, ze, zn;
        te = 0.5 * acc * t * t;
        fw_radar_plot(&d, rng, 0.0, -5000.0, te, 0.0, &ze, &zn);
        fw_ab_update(&tr, &d, t, ze, zn);
    }
    fprintf(stderr, "lag: %.4f m, theory %.4f m\n", tr.e - te, fw_ab_accel_lag(d.alpha, d.beta, acc, T));
    CHECK_NEAR(tr.e - te, fw_ab_accel_lag(d.alpha, d.beta, acc, T), 1e-6 * fabs(te) + 1e-6);
    fw_streams_free(st);
}

static void test_same_seed(void)
{
    fw_radar_def d = fast_def();
    double a[4], b[4];
    pass(&d, 42, 100.0, 3000.0, 1.0, 2.0, 300, &a[0], &a[1]);
    pass(&d, 42, 100.0, 3000.0, 1.0, 2.0, 300, &b[0], &b[1]);
    pass(&d, 43, 100.0, 3000.0, 1.0, 2.0, 300, &a[2], &a[3]);
    CHECK(a[0] == b[0] && a[1] == b[1]);
    CHECK(a[0] != a[2]);
}

/* MSC.192(79) Table 2: Pd 0.8 at each class's range; the horizon. */
static void test_detection(void)
{
    fw_radar_def d = fw_default_radar_def();
    double h;
    CHECK_NEAR(fw_radar_pd(&d, fw_nm_to_m(11.0), 200.0), 0.8, 1e-12);
    CHECK_NEAR(fw_radar_pd(&d, fw_nm_to_m(8.0), 60.0), 0.8, 1e-12);
    CHECK_NEAR(fw_radar_pd(&d, fw_nm_to_m(3.4), 10.0), 0.8, 1e-12);
    CHECK_NEAR(fw_radar_pd(&d, fw_nm_to_m(5.5), 200.0), 0.986, 1e-3);
    CHECK_NEAR(fw_radar_pd(&d, fw_nm_to_m(16.5), 200.0), 0.0, 0.0); /* beyond 15.5 nm */
    CHECK(fw_radar_pd(&d, fw_nm_to_m(15.4), 200.0) > 0.0);
    CHECK(fw_radar_class_range(100.0, &h) == fw_nm_to_m(11.0) && h == 10.0);
    CHECK(fw_radar_class_range(99.0, &h) == fw_nm_to_m(8.0) && h == 5.0);
    /* 15 m and 10 m: 2.21 (3.873 + 3.162) = 15.55 nm */
    CHECK_NEAR(fw_radar_horizon(15.0, 10.0), fw_nm_to_m(15.548), 1.0);
}

int main(void)
{
    TEST_RUN(test_detection);
    TEST_RUN(test_radial_range_noise);
    TEST_RUN(test_tangential_bearing_noise);
    TEST_RUN(test_lag);
    TEST_RUN(test_same_seed);
    return TEST_EXIT();
}
