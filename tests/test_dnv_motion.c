/* test_dnv_motion - a DNV situation carries the motion the own ship saw
 * (run/dnv_situation.h "turns"), read back by the waypoint targets
 * (run/run_world.c): a round trip.
 *
 * A situation's waypoints give a ship's position and time; read back, its
 * course and speed between two are the leg's chord and mean speed.  A ship
 * that speeds up along a leg, or crabs, was then seen otherwise than in the
 * run: `fairway worst`'s own ship, sailed again from the situation, ended
 * 32.6 m off the replay when a target slowed along a leg and its leg's
 * chord turned 3 deg a second before its turn did.  Here two recorded
 * tracks, written as a situation and read back as a run's traffic:
 *   - a ship at 16 kn that speeds up to 20 kn at 0.05 m/s^2 (t = 200 s to
 *     241 s) along a straight leg, then turns 30 deg to starboard at 0.5
 *     deg/s;
 *   - a ship making good 10 kn due north, its recorded course 5 deg off
 *     (a lane change's crab);
 * at every second of the 600 s each is where and as it was recorded: course
 * within 0.01 deg, speed within 0.01 kn (what the situation keeps), position
 * within 0.3 m (the simplification's 0.25 m).  Before, the first read back
 * at the legs' mean speeds (0.29 kn off in the speed-up) and the
 * second at 0 deg. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"
#include "run/dnv_situation.h"
#include "scenario/scn_dnv.h"
#include "run/run.h"
#include "test.h"
#include "test_tmp.h"
#include "world/world.h"

#define DURATION 600

static char workdir[256];

/* Track 0: the ship that speeds up and turns; track 1: the crabbing one. */
static void make_tracks(fw_rec_track tr[2])
{
    for (int i = 0; i < 2; i++) {
        tr[i].n = tr[i].cap = DURATION + 1;
        tr[i].p = calloc((size_t)tr[i].cap, sizeof *tr[i].p);
        snprintf(tr[i].info.id, sizeof tr[i].info.id, "%s", i ? "crabber" : "speeder");
        snprintf(tr[i].info.type, sizeof tr[i].info.type, "cargo");
        tr[i].info.length = 150.0, tr[i].info.breadth = 24.0;
    }
    double e = 3000.0, n = -8000.0, v = fw_kn_to_ms(16.0), c = fw_deg_to_rad(270.0);
    const double turn_rate = fw_deg_to_rad(0.5), turn_to = fw_deg_to_rad(300.0);
    for (int k = 0; k <= DURATION; k++) {
        bool turning = k >= 400 && c < turn_to - 1e-12;
        tr[0].p[k] = (fw_rec_point){.t = k, .east = e, .north = n, .course = c, .speed = v,
                                    .turn_rate = turning ? turn_rate : 0.0,
                                    .turn_to = turning ? turn_to : 0.0};
        /* one second on: speed, then course, then position (exact per step) */
        double v1 = k >= 200 ? fmin(v + 0.05, fw_kn_to_ms(20.0)) : v;
        double c1 = turning ? fmin(c + turn_rate, turn_to) : c;
        e += 0.5 * (v + v1) * sin(0.5 * (c + c1)), n += 0.5 * (v + v1) * cos(0.5 * (c + c1));
        v = v1, c = c1;
        tr[1].p[k] = (fw_rec_point){.t = k, .east = -3000.0, .north = -9000.0 + fw_kn_to_ms(10) * k,
                                    .course = fw_deg_to_rad(5.0), .speed = fw_kn_to_ms(10.0)};
    }
}

static void test_round_trip(void)
{
    fw_error err = {0};
    static fw_scenario s;
    char imazu[512];
    snprintf(imazu, sizeof imazu, "%s/scenarios/imazu/imazu-01.yaml", fw_data_root());
    CHECK_MSG(fw_scenario_load(imazu, &s, &err) == FW_OK, "%s", err.msg);
    s.duration = DURATION;
    fw_rec_track tr[2] = {0};
    make_tracks(tr);
    char path[400];
    snprintf(path, sizeof path, "%s/motion.json", workdir);
    CHECK_MSG(fw_dnv_situation_write(&s, tr, 2, FW_DNV_TOLERANCE_M, path, &err) == FW_OK, "%s",
              err.msg);
    static fw_scenario back;
    CHECK_MSG(fw_scn_dnv_load(path, "c3-mmg", &back, &err) == FW_OK, "%s", err.msg);
    fw_run_def d = fw_default_run_def();
    d.scenario = &back;
    fw_run *r = NULL;
    CHECK_MSG(fw_run_open(&d, &r, &err) == FW_OK, "%s", err.msg);
    /* the situation's plane is centred on the own ship's start */
    double oe = s.east - back.east, on = s.north - back.north;
    double worst_c[2] = {0}, worst_v[2] = {0}, worst_p[2] = {0};
    int seen[2] = {0};
    for (int k = 0; r && k < DURATION; k++) {
        fw_source *src = fw_world_source(fw_run_world(r));
        const fw_target *v;
        int n;
        CHECK_MSG(src->ops->around(src, &v, &n, &err) == FW_OK, "%s", err.msg);
        for (int j = 0; j < n; j++) {
            int i = strcmp(v[j].id, "2") == 0 ? 0 : strcmp(v[j].id, "3") == 0 ? 1 : -1;
            if (i < 0)
                continue;
            const fw_rec_point *p = &tr[i].p[k];
            seen[i]++;
            worst_c[i] = fmax(worst_c[i], fabs(fw_rad_to_deg(fw_wrap_pi(v[j].course - p->course))));
            worst_v[i] = fmax(worst_v[i], fabs(fw_ms_to_kn(v[j].speed - p->speed)));
            worst_p[i] = fmax(worst_p[i], hypot(v[j].east + oe - p->east, v[j].north + on - p->north));
        }
        CHECK_MSG(fw_run_step(r, &err) == FW_OK, "t %d: %s", k, err.msg);
    }
    fw_run_discard(r);
    for (int i = 0; i < 2; i++) {
        printf("%s: %d s seen, course within %.2g deg, speed within %.2g kn, position within "
               "%.3f m of the recorded\n", tr[i].info.id, seen[i], worst_c[i], worst_v[i],
               worst_p[i]);
        CHECK(seen[i] == DURATION);
        CHECK(worst_c[i] <= 0.01 && worst_v[i] <= 0.01 && worst_p[i] <= 0.3);
    }
    free(tr[0].p), free(tr[1].p);
}

int main(void)
{
    if (test_tmpdir("dnv_motion", workdir, sizeof workdir))
        return 1;
    TEST_RUN(test_round_trip);
    return TEST_EXIT();
}
