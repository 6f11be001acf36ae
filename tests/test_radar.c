/* test_radar.c - the own ship's radar and its tracks (sense/sensing.h, mode
 * radar and ais+radar, on arpa.h's plots, detection and alpha-beta tracker):
 *   a straight pass: 40 ships at 12 kn past a stationary antenna, 1 to 3 nm
 *     abeam: the known positions' squared error against the truth, averaged
 *     at the scans, equals the stated steady-state theory
 *     VRR(alpha, beta) (range_sd^2 + (R bearing_sd)^2) within 10%
 *   detection: no ship is known beyond its radar horizon (a 200 m ship
 *     15.5 nm, a 10 m boat 11.7 nm, antenna 15 m); every one is known well
 *     inside its class's range (11 nm, 3.4 nm); a track is shown 60 s after
 *     its first plot; a ship that sails off beyond the horizon is lost, and
 *     so is one out of the sensor's sight for more than 5 scans
 *   fusion: with AIS reports current the known ship is the AIS one; with
 *     every report lost, the radar's track
 *   the same seed gives the same tracks */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/streams.h"
#include "core/units.h"
#include "sense/sensing.h"
#include "test.h"

static fw_rng *streams_rng(void *ctx, uint32_t key, fw_purpose p)
{
    return fw_streams_get(ctx, key, p);
}

/* Ship k, length len, at (east, north0 + v t) heading north (v < 0: south). */
static fw_target ship(int k, double len, double east, double north0, double v, double t)
{
    fw_target a = {.length = len, .breadth = len / 6.0};
    snprintf(a.id, sizeof a.id, "ship%03d", k);
    a.east = east;
    a.north = north0 + v * t;
    a.course = a.heading = v >= 0.0 ? 0.0 : FW_PI;
    a.speed = a.stw = fabs(v);
    return a;
}

static fw_sensor *make(fw_sensing_mode mode, fw_streams *st)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = mode;
    fw_sensor *s = NULL;
    fw_error err = {0};
    CHECK(fw_sensor_create(&d, streams_rng, st, &s, &err) == FW_OK);
    fw_target own = {.id = "own"};
    fw_sensor_place(s, &own); /* stationary at the origin */
    return s;
}

enum { N = 40 };

static void test_straight_pass_theory(void)
{
    fw_streams *st = fw_streams_create(5);
    fw_sensor *s = make(FW_SENSE_RADAR, st);
    fw_radar_def r = fw_default_radar_def();
    double vrr = fw_ab_position_vrr(r.alpha, r.beta), v = fw_kn_to_ms(12.0);
    double sum = 0.0, theory = 0.0;
    long m = 0;
    fw_target truth[N], known[N];
    fw_error err = {0};
    for (int k = 0; k <= 1800; k++) { /* 6 nm at 12 kn: from 3 nm south to 3 nm north */
        for (int j = 0; j < N; j++)
            truth[j] = ship(j, 200.0, fw_nm_to_m(1.0 + 2.0 * j / (N - 1)), -fw_nm_to_m(3.0), v, k);
        int n;
        CHECK(fw_sensor_update(s, k, truth, N, known, &n, &err) == FW_OK);
        if (k < 300 || k % 5 != 0) /* steady: after 120 scans; at a scan (every 2.5 s) */
            continue;
        CHECK(n == N);
        for (int j = 0; j < n; j++) {
            double de = known[j].east - truth[j].east, dn = known[j].north - truth[j].north;
            double R = hypot(truth[j].east, truth[j].north), sb = R * r.bearing_sd;
            sum += de * de + dn * dn;
            theory += vrr * (r.range_sd * r.range_sd + sb * sb);
            m++;
        }
    }
    fw_sensing_counts c = fw_sensor_counts(s);
    printf("straight pass: %ld samples, mean squared error %.1f m^2 (rms %.1f m), theory %.1f "
           "m^2 (VRR %.4f); %ld plots of %ld scans, %ld tracks, %ld lost\n",
           m, sum / m, sqrt(sum / m), theory / m, vrr, c.plotted, c.scanned, c.tracks,
           c.tracks_lost);
    CHECK_REL(sum / m, theory / m, 0.10);
    CHECK(c.tracks == N && c.tracks_lost == 0);
    fw_sensor_destroy(s);
    fw_streams_free(st);
}

/* 20 ships of length len, head-on from 20 nm at 20 kn past 0.5 nm abeam
 * and on to 20 nm beyond: the largest range at which any is known while
 * approaching, the smallest range at which one is first known, and whether
 * every one is forgotten by the end. */
static void approach(double len, double *known_max, double *first_min, double *first_mean,
                     bool *all_lost)
{
    fw_streams *st = fw_streams_create(8);
    fw_sensor *s = make(FW_SENSE_RADAR, st);
    double v = -fw_kn_to_ms(20.0), start = fw_nm_to_m(20.0), first[20];
    fw_target truth[20], known[20];
    fw_error err = {0};
    *known_max = 0.0;
    for (int j = 0; j < 20; j++)
        first[j] = -1.0;
    int n = 0, steps = (int)(2.0 * start / -v);
    for (int k = 0; k <= steps; k++) {
        for (int j = 0; j < 20; j++)
            truth[j] = ship(j, len, fw_nm_to_m(0.5) + 10.0 * j, start, v, k);
        CHECK(fw_sensor_update(s, k, truth, 20, known, &n, &err) == FW_OK);
        for (int i = 0; i < n; i++) {
            int j = atoi(known[i].id + 4);
            double R = hypot(truth[j].east, truth[j].north);
            if (truth[j].north > 0.0)
                *known_max = fmax(*known_max, R);
            if (first[j] < 0.0)
                first[j] = R;
        }
    }
    *first_min = INFINITY, *first_mean = 0.0;
    for (int j = 0; j < 20; j++)
        *first_min = fmin(*first_min, first[j] < 0.0 ? 0.0 : first[j]), *first_mean += first[j] / 20;
    *all_lost = n == 0;
    fw_sensor_destroy(s);
    fw_streams_free(st);
}

static void test_detection_range(void)
{
    double kmax, fmin_, fmean;
    bool lost;
    approach(200.0, &kmax, &fmin_, &fmean, &lost);
    printf("200 m ships: known first at %.2f nm on average (%.2f nm the nearest), none beyond "
           "%.2f nm\n", fw_m_to_nm(fmean), fw_m_to_nm(fmin_), fw_m_to_nm(kmax));
    CHECK(kmax <= fw_nm_to_m(15.548));
    CHECK(fmin_ >= fw_nm_to_m(10.0)); /* Pd 0.8 and more within 11 nm */
    CHECK(lost);
    approach(10.0, &kmax, &fmin_, &fmean, &lost);
    printf("10 m boats: known first at %.2f nm on average (%.2f nm the nearest), none beyond "
           "%.2f nm\n", fw_m_to_nm(fmean), fw_m_to_nm(fmin_), fw_m_to_nm(kmax));
    CHECK(kmax <= fw_nm_to_m(11.68));
    CHECK(fmin_ >= fw_nm_to_m(2.5)); /* Pd 0.8 and more within 3.4 nm */
    CHECK(fmean < fw_nm_to_m(6.0));
    CHECK(lost);
}

/* A track is shown 60 s after its first plot (a ship 2 nm off from t = 0:
 * detected at the first scan almost surely); the ship out of the sensor's
 * sight (not in the truth it is given) for 30 s, 12 scans: its track is lost,
 * and on its return a new one is shown a minute after its first plot. */
static void test_gap_loses_track(void)
{
    fw_streams *st = fw_streams_create(2);
    fw_sensor *s = make(FW_SENSE_RADAR, st);
    fw_target a, known[1];
    fw_error err = {0};
    int n = 0, first = -1, back = -1;
    for (int k = 0; k <= 250; k++) {
        a = ship(0, 200.0, fw_nm_to_m(2.0), 0.0, fw_kn_to_ms(10.0), k);
        bool there = k < 100 || k >= 130;
        CHECK(fw_sensor_update(s, k, &a, there ? 1 : 0, known, &n, &err) == FW_OK);
        if (n && first < 0)
            first = k;
        if (k >= 130 && n && back < 0)
            back = k;
    }
    fw_sensing_counts c = fw_sensor_counts(s);
    printf("a 200 m ship at 2 nm: shown at t = %d s; gone 30 s: shown again at t = %d s; %ld "
           "tracks, %ld lost\n", first, back, c.tracks, c.tracks_lost);
    CHECK(first == 60);
    CHECK(back >= 130 + 60 && back <= 130 + 63);
    CHECK(c.tracks == 2 && c.tracks_lost == 1);
    fw_sensor_destroy(s);
    fw_streams_free(st);
}

/* ais+radar: AIS first; with every report lost, the radar track. */
static double fused_error(double dropout)
{
    fw_streams *st = fw_streams_create(4);
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS_RADAR;
    d.position_sd = d.sog_sd = d.cog_sd = d.heading_sd = 0.0;
    d.dropout = dropout;
    fw_sensor *s = NULL;
    fw_error err = {0};
    CHECK(fw_sensor_create(&d, streams_rng, st, &s, &err) == FW_OK);
    fw_target own = {.id = "own"}, a, known[1];
    double e2 = 0.0;
    int n, m = 0;
    for (int k = 0; k <= 600; k++) {
        fw_sensor_place(s, &own);
        a = ship(0, 200.0, fw_nm_to_m(3.0), 0.0, fw_kn_to_ms(12.0), k);
        CHECK(fw_sensor_update(s, k, &a, 1, known, &n, &err) == FW_OK);
        if (n && k >= 300)
            e2 += pow(known[0].east - a.east, 2) + pow(known[0].north - a.north, 2), m++;
    }
    fw_sensor_destroy(s);
    fw_streams_free(st);
    CHECK(m == 301);
    return sqrt(e2 / m);
}

static void test_fusion(void)
{
    double ais = fused_error(0.0), radar = fused_error(1.0);
    printf("ais+radar, a ship 3 nm off: rms error %.3f m with AIS (noise 0), %.1f m on radar "
           "alone (every report lost)\n", ais, radar);
    CHECK(ais < 1e-6);
    CHECK(radar > 5.0 && radar < 60.0);
}

static void test_same_seed(void)
{
    fw_target truth[3], k1[3], k2[3];
    int n1 = 0, n2 = 0;
    fw_error err = {0};
    fw_streams *a = fw_streams_create(9), *b = fw_streams_create(9);
    fw_sensor *s1 = make(FW_SENSE_RADAR, a), *s2 = make(FW_SENSE_RADAR, b);
    for (int k = 0; k <= 200; k++) {
        for (int j = 0; j < 3; j++)
            truth[j] = ship(j, 100.0, 2000.0 * (j + 1), 0.0, 5.0, k);
        CHECK(fw_sensor_update(s1, k, truth, 3, k1, &n1, &err) == FW_OK);
        CHECK(fw_sensor_update(s2, k, truth, 3, k2, &n2, &err) == FW_OK);
    }
    CHECK(n1 == 3 && n2 == 3 && memcmp(k1, k2, sizeof k1) == 0);
    fw_sensor_destroy(s1);
    fw_sensor_destroy(s2);
    fw_streams_free(a);
    fw_streams_free(b);
}

int main(void)
{
    TEST_RUN(test_straight_pass_theory);
    TEST_RUN(test_detection_range);
    TEST_RUN(test_gap_loses_track);
    TEST_RUN(test_fusion);
    TEST_RUN(test_same_seed);
    return TEST_EXIT();
}
