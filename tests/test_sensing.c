/* test_sensing.c - what the own ship knows of the others (sense/sensing.h):
 *   the AIS Class A reporting intervals of ITU-R M.1371-5 Table 1, as the
 *     function gives them and as reports are sent by ships sailing straight,
 *     faster, and turning (1 s steps: a 3 1/3 s interval is 3 or 4 s)
 *   the dead-reckoned position's error on a straight pass against its theory:
 *     E|e|^2 = 2 sp^2 + E[age^2] (s_sog^2 + v^2 s_cog^2), within 10%
 *   dropouts: a probability of 1 and none is known; 0.3 loses about 30%
 *   latency: a report is known latency_s after it is sent
 *   the same seed gives the same estimates; perfect sensing is the truth */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/streams.h"
#include "core/units.h"
#include "sense/sensing.h"
#include "test.h"

static fw_rng *streams_rng(void *ctx, uint32_t key, fw_purpose p)
{
    return fw_streams_get(ctx, key, p);
}

/* Ship k of a fleet sailing north at speed from (1000 k, 0), turning at
 * rate (rad/s) if not 0. */
static fw_target ship_at(int k, double t, double speed, double rate)
{
    fw_target a = {.length = 200.0, .breadth = 32.0};
    snprintf(a.id, sizeof a.id, "ship%03d", k);
    double c = rate * t;
    a.east = 1000.0 * k + (rate ? speed / rate * (1.0 - cos(c)) : 0.0);
    a.north = rate ? speed / rate * sin(c) : speed * t;
    a.course = a.heading = fw_wrap_2pi(c);
    a.speed = a.stw = speed;
    return a;
}

static void test_intervals_table(void)
{
    CHECK(fw_ais_interval(fw_kn_to_ms(2.0), false) == 180.0);
    CHECK(fw_ais_interval(fw_kn_to_ms(12.0), false) == 10.0);
    CHECK_NEAR(fw_ais_interval(fw_kn_to_ms(12.0), true), 10.0 / 3.0, 1e-12);
    CHECK(fw_ais_interval(fw_kn_to_ms(18.0), false) == 6.0);
    CHECK(fw_ais_interval(fw_kn_to_ms(18.0), true) == 2.0);
    CHECK(fw_ais_interval(fw_kn_to_ms(25.0), false) == 2.0);
}

/* The mean time between successive reports of one ship over an hour. */
static double mean_spacing(double speed, double rate)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS;
    d.position_sd = d.sog_sd = d.cog_sd = d.heading_sd = 0.0;
    fw_streams *st = fw_streams_create(11);
    fw_sensor *s;
    fw_error err = {0};
    CHECK(fw_sensor_create(&d, streams_rng, st, &s, &err) == FW_OK);
    fw_target known[1];
    double first = NAN, last = NAN;
    long sent0 = 0;
    for (int k = 0; k <= 3600; k++) {
        fw_target a = ship_at(0, k, speed, rate);
        int n;
        CHECK(fw_sensor_update(s, k, &a, 1, known, &n, &err) == FW_OK && n == 1);
        long sent = fw_sensor_counts(s).sent;
        if (sent > sent0 && sent > 1) /* the first report, on sight, does not count */
            last = k, first = isnan(first) ? k : first;
        sent0 = sent;
    }
    long n = fw_sensor_counts(s).sent - 2;
    fw_sensor_destroy(s);
    fw_streams_free(st);
    return (last - first) / (double)n;
}

static void test_reports_at_intervals(void)
{
    double straight12 = mean_spacing(fw_kn_to_ms(12.0), 0.0);
    double straight18 = mean_spacing(fw_kn_to_ms(18.0), 0.0);
    double turning12 = mean_spacing(fw_kn_to_ms(12.0), fw_deg_to_rad(0.5));
    double straight25 = mean_spacing(fw_kn_to_ms(25.0), 0.0);
    printf("mean report spacing: 12 kn %.3f s, 18 kn %.3f s, 12 kn turning %.3f s, 25 kn %.3f s\n",
           straight12, straight18, turning12, straight25);
    CHECK_NEAR(straight12, 10.0, 1e-9);
    CHECK_NEAR(straight18, 6.0, 1e-9);
    CHECK_NEAR(straight25, 2.0, 1e-9);
    /* 3 1/3 s on a 1 s grid: every 4 s (the next step at or after the time) */
    CHECK(turning12 >= 10.0 / 3.0 - 1e-9 && turning12 <= 4.0 + 1e-9);
}

/* 50 ships sailing north at 12 kn, 5000 s: the squared error of each
 * estimate against the truth, averaged, against its theory. */
static void test_error_theory(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS;
    fw_streams *st = fw_streams_create(3);
    fw_sensor *s;
    fw_error err = {0};
    CHECK(fw_sensor_create(&d, streams_rng, st, &s, &err) == FW_OK);
    enum { N = 50 };
    fw_target truth[N], known[N];
    double v = fw_kn_to_ms(12.0), sum = 0.0;
    long m = 0;
    for (int k = 0; k <= 5000; k++) {
        for (int j = 0; j < N; j++)
            truth[j] = ship_at(j, k, v, 0.0);
        int n;
        CHECK(fw_sensor_update(s, k, truth, N, known, &n, &err) == FW_OK && n == N);
        for (int j = 0; j < n && k >= 10; j++) {
            double de = known[j].east - truth[j].east, dn = known[j].north - truth[j].north;
            sum += de * de + dn * dn;
            m++;
        }
    }
    /* ages 0..9 s equally often (a 10 s interval on a 1 s grid): E[age^2] = 28.5 s^2 */
    double theory = 2.0 * d.position_sd * d.position_sd +
                    28.5 * (d.sog_sd * d.sog_sd + v * v * d.cog_sd * d.cog_sd);
    double mse = sum / (double)m;
    printf("dead-reckoned error: %.1f m^2 mean square (rms %.2f m) against %.1f m^2 in theory\n",
           mse, sqrt(mse), theory);
    CHECK(fabs(mse / theory - 1.0) < 0.10);
    fw_sensor_destroy(s);
    fw_streams_free(st);
}

/* n_known at each step for 600 s, the counts at the end. */
static fw_sensing_counts run_one(const fw_sensing_def *d, uint64_t seed, int *known_at,
                                 fw_target *last)
{
    fw_streams *st = fw_streams_create(seed);
    fw_sensor *s;
    fw_error err = {0};
    CHECK(fw_sensor_create(d, streams_rng, st, &s, &err) == FW_OK);
    fw_target truth[20], known[20];
    for (int k = 0; k <= 600; k++) {
        for (int j = 0; j < 20; j++)
            truth[j] = ship_at(j, k, fw_kn_to_ms(12.0), 0.0);
        CHECK(fw_sensor_update(s, k, truth, 20, known, &known_at[k], &err) == FW_OK);
    }
    if (last)
        memcpy(last, known, sizeof known);
    fw_sensing_counts c = fw_sensor_counts(s);
    fw_sensor_destroy(s);
    fw_streams_free(st);
    return c;
}

static void test_dropout_latency_seed(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS;
    static int known[601], again[601];
    d.dropout = 1.0;
    fw_sensing_counts c = run_one(&d, 5, known, NULL);
    CHECK(c.arrived == 0 && c.lost == c.sent && c.sent > 0);
    for (int k = 0; k <= 600; k++)
        CHECK(known[k] == 0);
    d.dropout = 0.3;
    c = run_one(&d, 5, known, NULL);
    double share = (double)c.lost / (double)c.sent;
    printf("dropout 0.3: %ld of %ld lost (%.3f)\n", c.lost, c.sent, share);
    CHECK(fabs(share - 0.3) < 5.0 * sqrt(0.3 * 0.7 / (double)c.sent));
    /* latency: the ships first seen at t = 0 are known from t = 1.5 s on */
    d.dropout = 0.0;
    d.latency = 1.5;
    run_one(&d, 5, known, NULL);
    CHECK(known[0] == 0 && known[1] == 0 && known[2] == 20);
    /* the same seed: the same estimates, to the bit; another seed: others */
    fw_target a[20], b[20];
    run_one(&d, 9, known, a);
    run_one(&d, 9, again, b);
    CHECK(memcmp(a, b, sizeof a) == 0 && memcmp(known, again, sizeof known) == 0);
    run_one(&d, 10, again, b);
    CHECK(a[0].east != b[0].east);
    /* perfect: the truth */
    d.mode = FW_SENSE_PERFECT;
    run_one(&d, 9, known, a);
    fw_target t0 = ship_at(0, 600, fw_kn_to_ms(12.0), 0.0);
    CHECK(known[600] == 20 && memcmp(&a[0], &t0, sizeof t0) == 0);
}

static void test_check(void)
{
    fw_error err = {0};
    fw_sensing_def d = fw_default_sensing_def();
    d.dropout = 1.5;
    CHECK(fw_sensing_check(&d, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "dropout 1.5: a probability");
    d = fw_default_sensing_def();
    d.position_sd = -1.0;
    CHECK(fw_sensing_check(&d, &err) == FW_EINPUT);
    fw_sensing_mode m;
    CHECK(fw_sensing_mode_parse("sonar", &m) == FW_EINPUT);
    CHECK(fw_sensing_mode_parse("ais", &m) == FW_OK && m == FW_SENSE_AIS);
    CHECK(fw_sensing_mode_parse("radar", &m) == FW_OK && m == FW_SENSE_RADAR);
    CHECK(fw_sensing_mode_parse("ais+radar", &m) == FW_OK && m == FW_SENSE_AIS_RADAR);
    d = fw_default_sensing_def();
    d.radar.alpha = 0.0;
    CHECK(fw_sensing_check(&d, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "alpha 0");
}

int main(void)
{
    TEST_RUN(test_intervals_table);
    TEST_RUN(test_reports_at_intervals);
    TEST_RUN(test_error_theory);
    TEST_RUN(test_dropout_latency_seed);
    TEST_RUN(test_check);
    return TEST_EXIT();
}
