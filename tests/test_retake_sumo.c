/* test_retake_sumo.c - a SUMO ship given back and taken again in one step
 * (world.h fw_world_take / fw_world_give_back, traffic/source_sumo.h).
 *
 * The reactive traffic gives a steered ship back when it is on its lane
 * again and may take it in the same step for a new encounter (dover-
 * imperfect seed 1 in fog: ferry_n_fill8 at 1017 s).  Here a ship of the
 * channel network's eastbound lane is taken and steered (steer.h: 20 deg to
 * starboard and back) in a current of 0.6 m/s setting north, across its
 * lane, so that it crabs; back on its lane's line it is given back and, in
 * the same step, taken again.  Required:
 *   - SUMO's list places the given-back ship's hull off where fairway had it
 *     (half its length times the sine of its drift angle): more than 2 m,
 *     so the case is one that matters (the take read that list, and the new
 *     vessel started there: 9.3 m off in the dover case, a jump the
 *     monitors saw as 7.6 m/s sideways)
 *   - the new vessel starts where the old one was given back (within 1 mm)
 *   - in the 60 s after, the monitors (survey/monitor.h) count no sideways
 *     move and no teleport of any ship, and the ship's own sideways speed
 *     between steps stays below their bound (2 m/s).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/units.h"
#include "survey/monitor.h"
#include "test.h"
#include "traffic/source.h"
#include "traffic/source_sumo.h"
#include "world/steer.h"
#include "world/world.h"
#include "world_view.h"

static fw_ship c3, model;
static fw_lane_info lane0; /* the taken ship's lane, as first taken */

/* Ship s taken with a steer helmsman: 20 deg to starboard of its lane, back. */
static fw_status take_steered(fw_world *w, const fw_target *s, fw_controller **ctl,
                              fw_vessel_handle *h, fw_error *err)
{
    const fw_lane_info *lane = NULL;
    fw_status st = lane0.np > 0 ? FW_OK : fw_world_lane(w, s, &lane, err);
    if (st || (!lane && lane0.np == 0))
        return st ? st : fw_fail(err, FW_ERUN, "no lane known for '%s'", s->id);
    if (lane)
        lane0 = *lane;
    fw_steer_ship(s->length, s->breadth, s->type, &model);
    fw_alter_def sd = fw_default_alter_def();
    sd.lane = lane0;
    sd.alteration = fw_deg_to_rad(20.0);
    sd.cpa = 50.0;
    sd.length = s->length, sd.breadth = s->breadth, sd.speed = s->speed;
    snprintf(sd.other, sizeof sd.other, "nobody");
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &model;
    vd.dynamics = FW_DYN_NOMOTO;
    if ((st = fw_steer_controller_create(&sd, &vd.controller, err)))
        return st;
    *ctl = vd.controller;
    return fw_world_take(w, s->id, &vd, h, err);
}

/* An eastbound ship on its lane's line (y = -375 or -125), under way. */
static const fw_target *eastbound(fw_world *w)
{
    const fw_target *tg;
    const fw_assessment *as;
    int n;
    fw_vessel_view(fw_world_vessel(w, fw_world_own(w)), &tg, &as, &n);
    for (int i = 0; i < n; i++)
        if ((fabs(tg[i].north + 375.0) < 0.01 || fabs(tg[i].north + 125.0) < 0.01) &&
            tg[i].speed > 2.0 && sin(tg[i].course) > 0.99999 && fabs(tg[i].east - 4000) < 5000)
            return &tg[i];
    return NULL;
}

static fw_world *channel_world(char *dir, fw_error *err)
{
    fw_sumo_source_def sd = fw_default_sumo_source_def();
    sd.dir = dir;
    sd.network = "channel";
    sd.fill = 6;
    sd.duration = 1500.0;
    sd.own = (fw_target){.id = "fw_own", .east = 4000, .north = -4000, .course = 0.5 * FW_PI,
                         .speed = fw_kn_to_ms(10), .length = c3.Loa, .breadth = c3.B};
    sd.clear_range = 10.0;
    sd.clear_cpa = 0.0;
    fw_world_def wd = fw_default_world_def();
    wd.env.current = fw_current_uniform(0.6, 0.0);
    fw_world *w = NULL;
    CHECK_MSG(fw_sumo_source_create(&sd, &wd.source, err) == FW_OK, "%s", err->msg);
    CHECK_MSG(wd.source && fw_world_create(&wd, &w, err) == FW_OK, "%s", err->msg);
    if (!w)
        return NULL;
    fw_vessel_def own = fw_default_vessel_def();
    own.id = "fw_own", own.role = FW_ROLE_OWN, own.ship = &c3, own.dynamics = FW_DYN_NOMOTO;
    own.east = 4000, own.north = -4000, own.course = 0.5 * FW_PI, own.speed = fw_kn_to_ms(10);
    CHECK(fw_world_add_vessel(w, &own, NULL, err) == FW_OK);
    CHECK(fw_world_start(w, err) == FW_OK);
    return w;
}

/* Back on its line, given back and at once taken again; the offset of
 * SUMO's hull from where it was given back into *sumo_off.  true: done. */
static bool give_back_retake(fw_world *w, fw_vessel_handle *h, fw_controller **ctl,
                             fw_target *at_back, double *sumo_off, fw_error *err)
{
    *at_back = *fw_vessel_record(fw_world_vessel(w, *h));
    fw_error e2 = {0};
    fw_status st = fw_world_give_back(w, *h, &e2);
    if (st == FW_EINPUT)
        return false; /* not yet on its line: steered on, as the world does */
    CHECK_MSG(st == FW_OK, "%s", e2.msg);
    const fw_target *src;
    int n;
    CHECK(fw_source_around(fw_world_source(w), &src, &n, err) == FW_OK);
    int j = fw_target_find(src, n, at_back->id);
    CHECK_MSG(j >= 0, "'%s' not in SUMO's list once given back", at_back->id);
    if (j >= 0)
        *sumo_off = hypot(src[j].east - at_back->east, src[j].north - at_back->north);
    CHECK_MSG(take_steered(w, at_back, ctl, h, err) == FW_OK, "%s", err->msg);
    const fw_target *r = fw_vessel_record(fw_world_vessel(w, *h));
    CHECK_MSG(fabs(r->east - at_back->east) < 1e-3 && fabs(r->north - at_back->north) < 1e-3,
              "taken again at (%.3f, %.3f), given back at (%.3f, %.3f)", r->east, r->north,
              at_back->east, at_back->north);
    return true;
}

static void test_retake_same_step(void)
{
    fw_error err = {0};
    char dir[] = "/tmp/fw_test_retake.XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    fw_world *w = channel_world(dir, &err);
    fw_monitor_def md = fw_default_monitor_def();
    fw_monitor *mon = NULL;
    CHECK(fw_monitor_create(&md, NULL, &mon, &err) == FW_OK);
    fw_vessel_handle h = {0};
    fw_controller *ctl = NULL;
    char id[FW_TARGET_ID_MAX] = "";
    fw_target at_back = {0}, prev = {0};
    double sumo_off = -1.0, lat_max = 0.0, drift = 0.0;
    int k = 0, done_at = -1;
    for (; w && k < 1400 && (done_at < 0 || k < done_at + 60); k++) {
        if (k == 30) {
            const fw_target *s = eastbound(w);
            CHECK_MSG(s != NULL, "no eastbound ship on its lane's line");
            if (!s)
                break;
            snprintf(id, sizeof id, "%s", s->id);
            CHECK_MSG(take_steered(w, s, &ctl, &h, &err) == FW_OK, "%s", err.msg);
            if (!fw_world_vessel_valid(w, h))
                break;
        }
        if (done_at < 0 && k > 30 && fw_steer_controller_phase(ctl) == FW_STEER_DONE) {
            const fw_target *r = fw_vessel_record(fw_world_vessel(w, h));
            drift = fabs(fw_wrap_pi(r->heading - r->course));
            if (give_back_retake(w, &h, &ctl, &at_back, &sumo_off, &err))
                done_at = k;
        }
        monitor_step(mon, w, &err);
        const fw_target *now = id[0] ? in_view(fw_world_vessel(w, fw_world_own(w)), id) : NULL;
        if (done_at >= 0 && now && prev.id[0]) {
            double de = now->east - prev.east, dn = now->north - prev.north;
            lat_max = fmax(lat_max, fabs(de * cos(prev.heading) - dn * sin(prev.heading)));
        }
        if (now)
            prev = *now;
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
    }
    CHECK_MSG(done_at > 0, "'%s' never back on its line in %d s", id, k);
    CHECK_MSG(sumo_off > 2.0, "SUMO's hull only %.2f m off (drift %.1f deg)", sumo_off,
              fw_rad_to_deg(drift));
    const fw_monitor_counts *c = fw_monitor_counts_of(mon);
    CHECK_MSG(c->sideways == 0 && c->teleport == 0, "sideways %d teleport %d", c->sideways,
              c->teleport);
    CHECK_MSG(lat_max < md.lateral_max, "'%s' %.2f m/s sideways", id, lat_max);
    printf("'%s' given back at %d s crabbing %.1f deg, SUMO's hull %.1f m off: taken again where "
           "it was, largest sideways speed after %.3f m/s\n",
           id, done_at, fw_rad_to_deg(drift), sumo_off, lat_max);
    fw_monitor_destroy(mon);
    fw_world_destroy(w);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (test_failures_ == 0 && system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3", &c3, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_retake_same_step);
    return TEST_EXIT();
}
