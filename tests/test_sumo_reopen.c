/* test_sumo_reopen - SUMO's remote control never outlives a simulation, nor a
 * ship (traffic_sumo.cpp, "Moves wait for the step").
 *
 * libsumo keeps the ships moved by moveToXY in a table of its own, keyed by id
 * and holding the vehicle itself, until the next step handles them; closing
 * the simulation leaves the table as it is.  fairway worst sails several runs
 * in one process: a run that ended with a taken ship moved for a step that
 * never came left that ship in the table, and the next run's first step, whose
 * fill has a ship of the same id, followed the freed vehicle (SIGSEGV in
 * MSVehicle::Influencer::postProcessRemoteControl, exit 139).  Here, without
 * the worst machinery: a channel with a start-up fill; a fill ship taken and
 * moved and the simulation closed before its step; a second simulation of the
 * same traffic (the same ids at its first step) stepped for a minute, every
 * ship where SUMO's own driving puts it (the first run's ship on its lane's
 * line within 0.01 m, not where the first run moved it); and a ship moved
 * and then removed before the step (SUMO would handle a ship no longer
 * there): the step goes on without it.  Before the fix this program died at
 * the second simulation's first step (SIGSEGV, exit 139), as worst did. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "test.h"
#include "test_tmp.h"
#include "traffic/demand.h"
#include "traffic/traffic.h"

static char workdir[256];

static fw_status open_channel(fw_traffic **t, fw_error *err)
{
    static char routes[300], log[300];
    fw_network_files nf;
    fw_demand dm;
    fw_status st;
    if ((st = fw_network_find("channel", &nf, err)) || (st = fw_demand_load(nf.demand, &dm, err)))
        return st;
    fw_demand_def dd = fw_default_demand_def();
    dd.density = 2.0;
    dd.fill = 20;
    dd.seed = 3;
    snprintf(routes, sizeof routes, "%s/channel.rou.xml", workdir);
    snprintf(log, sizeof log, "%s/sumo.log", workdir);
    if ((st = fw_demand_write(&dm, &dd, routes, err)))
        return st;
    fw_traffic_def d = fw_default_traffic_def();
    d.net_file = nf.net;
    d.route_file = routes;
    d.add_file = nf.types;
    d.log_file = log;
    d.seed = 3;
    d.radius = 30000.0; /* the whole channel */
    d.own_length = 180.0;
    d.own_width = 30.0;
    return fw_traffic_open(&d, t, err);
}

/* The own ship lies still off the lanes, 3 km north of the channel. */
static fw_status step(fw_traffic *t, fw_error *err)
{
    fw_status st = fw_traffic_place(t, 0.0, 3000.0, 0.0, 0.0, err);
    return st ? st : fw_traffic_step(t, err);
}

/* A ship of the fill moving along its lane, after the first step. */
static bool pick(fw_traffic *t, int skip, fw_target *out)
{
    fw_error err = {0};
    const fw_target *v;
    int n;
    if (fw_traffic_around(t, &v, &n, &err))
        return false;
    for (int i = 0; i < n; i++)
        if (v[i].speed > 1.0 && skip-- == 0) {
            *out = v[i];
            return true;
        }
    return false;
}

static void test_reopen(void)
{
    fw_error err = {0};
    fw_traffic *t = NULL;
    fw_target a = {0}, b = {0};
    CHECK_MSG(open_channel(&t, &err) == FW_OK && step(t, &err) == FW_OK, "%s", err.msg);
    CHECK(pick(t, 0, &a) && pick(t, 1, &b));
    /* b moved 400 m across and then removed before the step: no longer there */
    CHECK(fw_traffic_take(t, b.id, &err) == FW_OK);
    CHECK(fw_traffic_move(t, b.id, b.east, b.north + 400.0, b.course, b.length, &err) == FW_OK);
    CHECK(fw_traffic_remove(t, b.id, &err) == FW_OK);
    CHECK_MSG(step(t, &err) == FW_OK, "%s", err.msg);
    fw_target g;
    CHECK(fw_traffic_get(t, b.id, &g, &err) == FW_ERUN);
    err = (fw_error){0};
    /* a taken and moved 400 m across, the simulation closed before the step */
    CHECK(fw_traffic_take(t, a.id, &err) == FW_OK);
    CHECK(fw_traffic_move(t, a.id, a.east, a.north + 400.0, a.course, a.length, &err) == FW_OK);
    CHECK(fw_traffic_place(t, 0.0, 3000.0, 0.0, 0.0, &err) == FW_OK);
    fw_traffic_close(t);
    /* the same traffic again: a's id at the first step */
    t = NULL;
    CHECK_MSG(open_channel(&t, &err) == FW_OK, "%s", err.msg);
    fw_status st = FW_OK;
    for (int k = 0; k < 60 && !st; k++)
        CHECK_MSG((st = step(t, &err)) == FW_OK, "step %d: %s", k, err.msg);
    CHECK_MSG(fw_traffic_get(t, a.id, &g, &err) == FW_OK, "%s", err.msg);
    /* on its lane's line, as the first run had it before the move */
    CHECK_NEAR(g.north, a.north, 0.01);
    CHECK_NEAR(fw_rad_to_deg(fw_wrap_pi(g.course - a.course)), 0.0, 0.01);
    printf("'%s' moved and closed before its step, '%s' moved and removed: the next simulation "
           "has '%s' at north %.2f m (%.2f m before)\n", a.id, b.id, a.id, g.north, a.north);
    fw_traffic_close(t);
}

int main(void)
{
    if (test_tmpdir("sumo_reopen", workdir, sizeof workdir))
        return 1;
    TEST_RUN(test_reopen);
    return TEST_EXIT();
}
