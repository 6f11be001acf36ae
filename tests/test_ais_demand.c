/* test_ais_demand.c - a network's demand from AIS (ais/ais_demand.h): the
 * example file's passes on the channel network, the written demand.yaml
 * loaded back, its rates the counted passes per hour, its ship types; and
 * the replay shown in SUMO (traffic/source_mirror.h): each SUMO vehicle
 * where the replay puts the ship, ids the MMSIs, gone in a gap. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ais/ais_demand.h"
#include "ais/ais_routes.h"
#include "traffic/source_mirror.h"
#include "test.h"

static void test_routes(void)
{
    static fw_net_routes nr;
    fw_error err = {0};
    CHECK_MSG(fw_net_routes_load("channel", &nr, &err) == FW_OK, "%s", err.msg);
    CHECK(nr.demand.n == 2 && nr.line[0].n == 2 && nr.line[0].length == 20000.0);
    double along;
    /* east (WE: W (0, 0) -> E (20000, 0)): 300 m off it, 5 km along */
    CHECK_NEAR(fw_route_distance(&nr.line[0], 5000, -300, &along), 300.0, 1e-9);
    CHECK_NEAR(along, 5000.0, 1e-9);
    CHECK_NEAR(fw_route_distance(&nr.line[1], 5000, -300, &along), 300.0, 1e-9);
    CHECK_NEAR(along, 15000.0, 1e-9); /* west runs the other way */
    /* the vTypes of ships.add.xml: a feeder 150 m at 0.64 x 25 kn */
    int k = -1;
    for (int i = 0; i < nr.n_vtypes; i++)
        if (strcmp(nr.vtypes[i].id, "container_feeder") == 0)
            k = i;
    CHECK(nr.n_vtypes == 10 && k >= 0);
    if (k >= 0) {
        CHECK_NEAR(nr.vtypes[k].length, 150.0, 0.0);
        CHECK_NEAR(nr.vtypes[k].speed, 0.64 * 12.86, 1e-9);
    }
    CHECK(fw_net_routes_load("atlantis", &nr, &err) == FW_EINPUT);
}

/* The per_hour of the streams of d whose id begins with prefix. */
static double rate_of(const fw_demand *d, const char *prefix, int *n)
{
    double r = 0;
    *n = 0;
    for (int i = 0; i < d->n; i++)
        if (strncmp(d->streams[i].id, prefix, strlen(prefix)) == 0) {
            r += d->streams[i].per_hour;
            (*n)++;
        }
    return r;
}

static bool has_stream(const fw_demand *d, const char *id, const char *types)
{
    for (int i = 0; i < d->n; i++)
        if (strcmp(d->streams[i].id, id) == 0 && strcmp(d->streams[i].types, types) == 0)
            return true;
    return false;
}

static void test_demand(void)
{
    char path[1024], out[] = "/tmp/fw_ais_demand_XXXXXX";
    snprintf(path, sizeof path, "%s/scenarios/ais/aisdk-2026-03-01.csv", getenv("FAIRWAY_DATA"));
    close(mkstemp(out));
    fw_ais_track_def td = fw_default_ais_track_def();
    td.origin_lat = 56.5;
    td.origin_lon = 11.5;
    td.max_gap = 1800;
    fw_ais_tracks t;
    fw_error err = {0};
    CHECK_MSG(fw_ais_tracks_load(path, &td, &t, &err) == FW_OK, "%s", err.msg);
    fw_ais_demand_def dd = fw_default_ais_demand_def();
    dd.network = "channel";
    fw_ais_demand_result res;
    CHECK_MSG(fw_ais_demand_write(&t, &dd, out, &res, &err) == FW_OK, "%s", err.msg);
    /* generate.py: 2 eastbound and 3 westbound passes in 45 minutes, the
     * fishing vessel across the fairway (unmatched) */
    CHECK_NEAR(res.hours, 0.75, 1e-12);
    CHECK(res.n_passes == 6 && res.n_matched == 5);
    CHECK(res.n_routes == 2 && res.passes[0] == 2 && res.passes[1] == 3);
    static fw_demand d;
    CHECK_MSG(fw_demand_load(out, &d, &err) == FW_OK, "%s", err.msg);
    int ne, nw;
    CHECK_REL(rate_of(&d, "east", &ne), 2 / 0.75, 1e-5);
    CHECK_REL(rate_of(&d, "west", &nw), 3 / 0.75, 1e-5);
    CHECK(ne == 2 && nw == 3 && d.n == 5);
    /* the kinds onto vTypes: the 185 m 18 kn passenger ship a ro-pax, the
     * 180 m tanker an Aframax, the 12 m pleasure craft small craft */
    CHECK(has_stream(&d, "east_ferry_ropax", "ferry_ropax"));
    CHECK(has_stream(&d, "west_tanker_aframax", "tanker_aframax"));
    CHECK(has_stream(&d, "west_small_craft", "small_craft"));
    fw_network_files nf;
    CHECK(fw_network_find("channel", &nf, &err) == FW_OK);
    CHECK(fw_network_check_demand(&nf, &d, &err) == FW_OK);
    /* a tolerance too tight for the lanes 200-500 m off the centre line:
     * nothing matches, each route keeps its own stream at rate 0 */
    dd.tolerance = 100;
    CHECK(fw_ais_demand_write(&t, &dd, out, &res, &err) == FW_OK && res.n_matched == 0);
    CHECK(fw_demand_load(out, &d, &err) == FW_OK && d.n == 2 && fw_demand_rate(&d) == 0.0);
    CHECK(strcmp(d.streams[0].id, "east") == 0 && strcmp(d.streams[0].types, "fw_seagoing") == 0);
    fw_ais_tracks_free(&t);
    unlink(out);
}

static void test_mirror(void)
{
    char path[1024], dir[] = "/tmp/fw_ais_mirror_XXXXXX";
    snprintf(path, sizeof path, "%s/scenarios/ais/aisdk-2026-03-01.csv", getenv("FAIRWAY_DATA"));
    CHECK(mkdtemp(dir) != NULL);
    fw_ais_track_def td = fw_default_ais_track_def();
    td.origin_lat = 56.5;
    td.origin_lon = 11.5;
    fw_ais_tracks t;
    fw_error err = {0};
    fw_source *inner = NULL, *src = NULL;
    fw_replay_def rd = fw_default_replay_def();
    rd.max_gap = td.max_gap;
    CHECK(fw_ais_tracks_load(path, &td, &t, &err) == FW_OK);
    CHECK(fw_ais_replay_source_create(&t, &rd, &inner, &err) == FW_OK);
    fw_ais_tracks_free(&t);
    fw_mirror_def md = {.mode = {.kind = FW_TRAFFIC_EMBEDDED}, .dir = dir, .step = 1.0,
                        .seed = 1, .own_leg = 8000, .duration = 1800,
                        .radius = INFINITY};
    md.own = (fw_target){.id = "fw_own", .east = 10000, .north = -4000, .speed = 6.0,
                         .length = 100, .breadth = 16};
    CHECK_MSG(fw_mirror_source_create(inner, &md, &src, &err) == FW_OK, "%s", err.msg);
    if (!src)
        return;
    fw_traffic *tr = fw_mirror_source_traffic(src);
    double worst = 0;
    int checked = 0, in_gap = 0;
    for (int k = 1; k <= 1800 && !err.status; k++) {
        fw_target own = md.own;
        own.north += own.speed * k;
        const fw_target *v;
        int n;
        if (fw_source_place(src, &own, &err) || fw_source_advance(src, &err) ||
            fw_source_around(src, &v, &n, &err))
            break;
        for (int i = 0; i < n; i++) {
            fw_target x;
            if (fw_traffic_get(tr, v[i].id, &x, &err) != FW_OK)
                break;
            worst = fmax(worst, hypot(x.east - v[i].east, x.north - v[i].north));
            checked++;
        }
        /* the second cargo ship is silent 10:25-10:31: out of SUMO too */
        fw_target gone;
        fw_error gerr = {0};
        if (k == 1700)
            in_gap = fw_traffic_get(tr, "219000105", &gone, &gerr) != FW_OK;
    }
    printf("mirror: %d SUMO positions, worst %.4f m from the replay's\n", checked, worst);
    CHECK_MSG(err.status == FW_OK, "%s", err.msg);
    CHECK(checked > 5000);
    CHECK_MSG(worst <= 0.01, "%.4f m", worst);
    CHECK(in_gap);
    fw_source_destroy(src);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
}

int main(void)
{
    TEST_RUN(test_routes);
    TEST_RUN(test_demand);
    TEST_RUN(test_mirror);
    return TEST_EXIT();
}
