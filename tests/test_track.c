/* test_track.c - the recorded-track traffic source (traffic/source_track.h):
 * positions between and at the points, passes split by a gap, the sight
 * radius, id order, the turns a track carries, and bad files named by line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/units.h"
#include "traffic/source_track.h"
#include "test.h"

static char path[64];

static void write_file(const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static fw_source *open_source(double radius, fw_error *err)
{
    fw_replay_def d = fw_default_replay_def();
    d.file = path;
    d.step = 0.5;
    d.radius = radius;
    fw_source *s = NULL;
    fw_status st = fw_replay_source_create(&d, &s, err);
    return st ? NULL : s;
}

static void test_replay(void)
{
    /* b (listed first) sails east 1 s apart; a has two passes, 0-1 s and 5-6 s */
    write_file("t_s,id,type,east_m,north_m,course_deg,speed_kn,length_m,breadth_m\n"
               "0,b,cargo,100,0,90,10,150,20\n1,b,cargo,110,0,90,10,150,20\n"
               "2,b,cargo,120,0,90,10,150,20\n"
               "0,a,ferry,0,500,180,5,80,12\n1,a,ferry,0,495,180,5,80,12\n"
               "5,a,ferry,0,400,180,5,80,12\n6,a,ferry,0,395,180,5,80,12\n");
    fw_error err = {0};
    fw_source *s = open_source(INFINITY, &err);
    CHECK_MSG(s != NULL, "%s", err.msg);
    if (!s)
        return;
    fw_target own = {.id = "own", .east = 0, .north = 0};
    CHECK(fw_source_place(s, &own, &err) == FW_OK);
    const fw_target *v;
    int n;
    CHECK(fw_source_around(s, &v, &n, &err) == FW_OK && n == 2);
    CHECK(strcmp(v[0].id, "a") == 0 && strcmp(v[1].id, "b") == 0); /* id order */
    CHECK(strcmp(v[1].type, "cargo") == 0 && v[1].length == 150.0 && v[1].breadth == 20.0);
    CHECK_NEAR(v[1].course, M_PI / 2, 1e-12);
    CHECK_NEAR(v[1].speed, fw_kn_to_ms(10.0), 1e-12);
    fw_source_advance(s, &err); /* t = 0.5: halfway between the points */
    CHECK_NEAR(fw_source_time(s), 0.5, 1e-12);
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 2);
    CHECK_NEAR(v[1].east, 105.0, 1e-9);
    CHECK_NEAR(v[0].north, 497.5, 1e-9);
    for (int k = 0; k < 3; k++)
        fw_source_advance(s, &err); /* t = 2: a between its passes, b at its last point */
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 1 && strcmp(v[0].id, "b") == 0);
    CHECK_NEAR(v[0].east, 120.0, 1e-9);
    fw_source_advance(s, &err); /* t = 2.5: b is gone */
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 0);
    for (int k = 0; k < 6; k++)
        fw_source_advance(s, &err); /* t = 5.5: a's second pass */
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 1 && strcmp(v[0].id, "a") == 0);
    CHECK_NEAR(v[0].north, 397.5, 1e-9);
    /* told to slow down: a recorded ship does what it did */
    CHECK(fw_source_set_speed(s, "a", 0.0, &err) == FW_OK);
    fw_source_destroy(s);
    /* sight: only b within 200 m of the own ship */
    s = open_source(200.0, &err);
    fw_source_place(s, &own, &err);
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 1 && strcmp(v[0].id, "b") == 0);
    fw_source_destroy(s);
}

static void test_bad_files(void)
{
    fw_error err = {0};
    write_file("t_s,id,east_m,north_m,course_deg\n0,a,0,0,90\n");
    CHECK(open_source(INFINITY, &err) == NULL && strstr(err.msg, ":1: no column speed_kn"));
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn\n0,a,0,0,90,5\n1,a,zero,0,90,5\n");
    CHECK(open_source(INFINITY, &err) == NULL && strstr(err.msg, ":3: east_m: not a number"));
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn\n0,a,0,0,90,5\n0,a,1,0,90,5\n");
    CHECK(open_source(INFINITY, &err) == NULL && strstr(err.msg, "two points at t = 0"));
    unlink(path);
    CHECK(open_source(INFINITY, &err) == NULL && strstr(err.msg, "cannot open"));
}

/* Turns (turn_rate_degps, turn_to_deg): a point with one gives its ship a
 * turn predictor until the next point, with the rate and heading as written
 * (to 1e-12), whose path heads exactly so after the turn (60 s at 0.5 deg/s
 * from 090 to 120); a point without one, none (constant velocity); both
 * columns or neither, a rate above 0. */
static void test_turns(void)
{
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn,turn_rate_degps,turn_to_deg\n"
               "0,a,0,0,90,10,,\n1,a,5,0,90,10,0.5,120\n2,a,10,0,90.5,10,,\n");
    fw_error err = {0};
    fw_source *s = open_source(INFINITY, &err);
    CHECK_MSG(s != NULL, "%s", err.msg);
    if (!s)
        return;
    fw_target own = {.id = "own", .north = -1000.0};
    const fw_target *v;
    int n;
    fw_source_place(s, &own, &err);
    CHECK(fw_source_around(s, &v, &n, &err) == FW_OK && n == 1 && v[0].pred == NULL);
    fw_source_advance(s, &err);
    fw_source_advance(s, &err); /* t = 1: turning */
    fw_source_around(s, &v, &n, &err);
    const fw_turn_pred *p = n == 1 ? fw_turn_pred_of(v[0].pred) : NULL;
    CHECK(p != NULL && p->turning);
    if (p) {
        CHECK_NEAR(p->rate, fw_deg_to_rad(0.5), 1e-12);
        CHECK_NEAR(p->heading, fw_deg_to_rad(120.0), 1e-12);
        double e[91], no[91], h[91];
        fw_target_path(&v[0], 1.0, 91, e, no, h);
        CHECK_NEAR(h[90], fw_deg_to_rad(120.0), 1e-12);
    }
    fw_source_advance(s, &err); /* t = 1.5: still that point's turn */
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 1 && fw_turn_pred_of(v[0].pred) != NULL);
    fw_source_advance(s, &err); /* t = 2: steady again */
    fw_source_around(s, &v, &n, &err);
    CHECK(n == 1 && v[0].pred == NULL);
    fw_source_destroy(s);
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn,turn_rate_degps\n0,a,0,0,90,5,1\n");
    CHECK(open_source(INFINITY, &err) == NULL &&
          strstr(err.msg, ":1: turn_to_deg: turn_rate_degps and turn_to_deg come together"));
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn,turn_rate_degps,turn_to_deg\n"
               "0,a,0,0,90,5,0,120\n");
    CHECK(open_source(INFINITY, &err) == NULL &&
          strstr(err.msg, ":2: turn_rate_degps: 0: a turn's rate is above 0"));
    write_file("t_s,id,east_m,north_m,course_deg,speed_kn,turn_rate_degps,turn_to_deg\n"
               "0,a,0,0,90,5,,120\n");
    CHECK(open_source(INFINITY, &err) == NULL &&
          strstr(err.msg, ":2: turn_rate_degps: not a number"));
}

/* n tracks of one point each at t = 0 (ids given), for the in-memory source. */
static fw_rec_track *tracks_of(const char *const *ids, int n, double east)
{
    fw_rec_track *t = calloc((size_t)n, sizeof *t);
    for (int i = 0; i < n; i++) {
        snprintf(t[i].info.id, sizeof t[i].info.id, "%s", ids[i]);
        fw_rec_track_reserve(&t[i]);
        t[i].p[t[i].n++] = (fw_rec_point){.t = 0.0, .east = east, .speed = 1.0};
    }
    return t;
}

/* Tracks in memory (the AIS replay's way in): taken over, checked, sorted. */
static void test_in_memory(void)
{
    static const char *const ids[] = {"b", "a"}, *const twice[] = {"a", "a"};
    fw_replay_def d = fw_default_replay_def();
    fw_source *s = NULL;
    fw_error err = {0};
    CHECK(fw_track_source_create(tracks_of(ids, 2, 5.0), 2, &d, "mem", &s, &err) == FW_OK);
    fw_target own = {.id = "own"};
    const fw_target *v;
    int n;
    CHECK(s && fw_source_place(s, &own, &err) == FW_OK &&
          fw_source_around(s, &v, &n, &err) == FW_OK && n == 2 && strcmp(v[0].id, "a") == 0);
    fw_source_destroy(s);
    CHECK(fw_track_source_create(tracks_of(twice, 2, 5.0), 2, &d, "mem", &s, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "mem: ship a listed twice");
    CHECK(fw_track_source_create(tracks_of(ids, 2, NAN), 2, &d, "mem", &s, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "has a point that is not a number");
    d.max_gap = 0;
    CHECK(fw_track_source_create(tracks_of(ids, 2, 5.0), 2, &d, "mem", &s, &err) == FW_EINPUT);
}

int main(void)
{
    snprintf(path, sizeof path, "/tmp/fw_test_track.%d.csv", (int)getpid());
    TEST_RUN(test_replay);
    TEST_RUN(test_bad_files);
    TEST_RUN(test_turns);
    TEST_RUN(test_in_memory);
    unlink(path);
    return TEST_EXIT();
}
