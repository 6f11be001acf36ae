/* fairway traffic: run background traffic with the own ship moved straight
 * along a fairway, to check the SUMO layer and see what it costs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/units.h"
#include "traffic/demand.h"
#include "traffic/traffic.h"

static void help(void)
{
    printf("usage: fairway traffic [OPTIONS]\n"
           "\n"
           "Runs SUMO background traffic on a network with the own ship (a 180 x 30 m\n"
           "ship) moved straight along a fairway, and prints per-step timing and the\n"
           "ships within range.\n"
           "\n"
           "  --network NAME   a network under FAIRWAY_DATA/networks (channel, crossing, strait,\n"
           "                   sea, ...) or a network directory's path (default channel)\n"
           "  --ships N        ships placed along the routes at the start (default 50)\n"
           "  --density F      arrival rates times F (default 1; 0: no arrivals)\n"
           "  --duration S     simulated seconds (default 600)\n"
           "  --step S         step length, s (default 1)\n"
           "  --radius NM      range of the query, nautical miles (default 6)\n"
           "  --speed KN       own ship speed, knots (default 12)\n"
           "  --seed N         SUMO and demand seed (default 1)\n"
           "  --every N        print every N steps (default 60)\n"
           "  --sumo MODE      embedded (default), gui, or remote:HOST:PORT (FAIRWAY_SUMO_TIMEOUT\n"
           "                   =S: the seconds it has to connect and to begin each answer,\n"
           "                   default 10 and 60)\n"
           "  --log FILE       SUMO's messages (default fairway-traffic.log); run.sumocfg,\n"
           "                   SUMO's side of the run (sumo-gui -c run.sumocfg), is written\n"
           "                   beside it, replacing one there\n"
           "  --routes FILE    route file written for the run (default fairway-traffic.rou.xml)\n"
           "  --demand FILE    the network's streams from FILE instead of its demand.yaml\n"
           "                   (one written by `fairway ais demand`, say)\n"
           "\n"
           "The own ship starts at the west end of the network's east-west fairway (y = 0)\n"
           "heading east.  Exit codes: 0 ok, 1 SUMO failed, 2 bad input.\n");
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* West end of each network's east-west fairway, on y = 0. */
static double start_x(const char *net)
{
    if (strcmp(net, "crossing") == 0)
        return -9000.0;
    if (strcmp(net, "sea") == 0)
        return -19000.0;
    return 1000.0;
}

static int run(const char *network, long ships, double density, double duration, double step,
               double radius_nm, double speed_kn, long seed, long every, const char *mode,
               const char *log, const char *routes, const char *demand)
{
    fw_error err = {0};
    fw_traffic_def d = fw_default_traffic_def();
    fw_network_files nf;
    fw_demand dm;
    fw_demand_def dd = fw_default_demand_def();
    /* --demand: another demand of the network (one written from AIS, say) */
    if (fw_traffic_mode_parse(mode, &d.mode, &err) || fw_network_find(network, &nf, &err) ||
        fw_demand_load(demand ? demand : nf.demand, &dm, &err) ||
        fw_network_check_demand(&nf, &dm, &err))
        return fw_report(&err);
    dd.density = density;
    dd.fill = (int)ships;
    dd.end = duration + step;
    dd.seed = (unsigned long)seed;
    /* SUMO opens its logs itself, following a symlink planted at the name:
     * fairway makes them first (an empty file renamed over whatever is there) */
    char gui_log[1100];
    if (fw_demand_write(&dm, &dd, routes, &err) || fw_file_write(log, "", 0, &err) ||
        (d.mode.kind == FW_TRAFFIC_GUI &&
         (fw_path(gui_log, sizeof gui_log, &err, "%s.gui", log) ||
          fw_file_write(gui_log, "", 0, &err))))
        return fw_report(&err);
    d.net_file = nf.net;
    d.route_file = routes;
    d.add_file = nf.types;
    d.log_file = log;
    d.step = step;
    d.seed = (unsigned long)seed;
    d.radius = fw_nm_to_m(radius_nm);
    d.own_length = 180.0;
    d.own_width = 30.0;
    fw_traffic *t = NULL;
    if (fw_traffic_open(&d, &t, &err))
        return fw_report(&err);
    long n = (long)ceil(duration / step - 1e-9);
    double *ms = malloc(sizeof *ms * (size_t)(n > 0 ? n : 1));
    double U = fw_kn_to_ms(speed_kn), x0 = start_x(network), heading = FW_PI / 2;
    printf("%8s %8s %9s  %s\n", "t (s)", "ms/step", "in range", "nearest (id, range nm, bearing deg)");
    int rc = 0;
    for (long k = 0; k < n; k++) {
        double t0 = now_ms();
        const fw_target *s;
        int m;
        double x = x0 + U * k * step, y = 0.0;
        if (fw_traffic_place(t, x, y, heading, U, &err) || fw_traffic_step(t, &err) ||
            fw_traffic_around(t, &s, &m, &err)) {
            rc = fw_report(&err);
            break;
        }
        ms[k] = now_ms() - t0;
        if ((k + 1) % every == 0 || k + 1 == n) {
            int best = -1;
            double r = INFINITY;
            for (int i = 0; i < m; i++) {
                double ri = hypot(s[i].east - x, s[i].north - y);
                if (ri < r) {
                    r = ri;
                    best = i;
                }
            }
            printf("%8.0f %8.3f %9d", fw_traffic_time(t), ms[k], m);
            if (best >= 0)
                printf("  %s (%s), %.2f, %03.0f", s[best].id, s[best].type, fw_m_to_nm(r),
                       fw_heading_deg(atan2(s[best].east - x, s[best].north - y)));
            printf("\n");
        }
        if (k + 1 == n) {
            qsort(ms, (size_t)n, sizeof *ms, cmp_double);
            printf("median %.3f ms per step (SUMO step + own ship move + range query), %ld steps\n",
                   ms[n / 2], n);
        }
    }
    free(ms);
    fw_traffic_close(t);
    return rc;
}

int fw_cmd_traffic(int argc, char **argv)
{
    fw_error err = {0};
    const char *network = "channel", *mode = "embedded", *log = "fairway-traffic.log",
               *routes = "fairway-traffic.rou.xml", *demand = NULL;
    long ships = 50, seed = 1, every = 60;
    double density = 1.0, duration = 600.0, step = 1.0, radius = 6.0, speed = 12.0;
    const fw_opt opts[] = {
        FW_OPT("--network", FW_OPT_TEXT, &network), FW_OPT("--sumo", FW_OPT_TEXT, &mode),
        FW_OPT("--ships", FW_OPT_LONG, &ships),     FW_OPT("--seed", FW_OPT_LONG, &seed),
        FW_OPT("--density", FW_OPT_DOUBLE, &density), FW_OPT("--step", FW_OPT_DOUBLE, &step),
        FW_OPT("--duration", FW_OPT_DOUBLE, &duration), FW_OPT("--every", FW_OPT_LONG, &every),
        FW_OPT("--radius", FW_OPT_DOUBLE, &radius), FW_OPT("--speed", FW_OPT_DOUBLE, &speed),
        FW_OPT("--log", FW_OPT_TEXT, &log),         FW_OPT("--routes", FW_OPT_TEXT, &routes),
        FW_OPT("--demand", FW_OPT_TEXT, &demand),   FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "traffic", opts, help, NULL, NULL, &err);
    if (rc >= 0)
        return rc;
    if (ships < 0 || ships > 100000)
        return fw_report((fw_fail(&err, FW_EINPUT, "--ships %ld: must be 0..100000", ships), &err));
    if (!(duration > 0.0 && duration <= 30 * 86400.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--duration %.15g: must be in (0, 30 days]", duration), &err));
    /* SUMO's clock counts milliseconds; scenarios step 0.1 to 10 s */
    if (!(step >= 0.1 && step <= 60.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--step %.15g: must be 0.1 to 60 s", step), &err));
    if (duration / step > 1e7)
        return fw_report((fw_fail(&err, FW_EINPUT, "--duration %.15g with --step %.15g: %.0f steps, at "
                                  "most 10000000", duration, step, ceil(duration / step)), &err));
    if (!(density >= 0.0 && density <= 100.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--density %.15g: must be 0..100", density), &err));
    if (!(radius > 0.0 && radius <= 100.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--radius %.15g: must be in (0, 100] nm", radius), &err));
    if (!(speed >= 0.0 && speed <= 40.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--speed %.15g: must be 0..40 kn", speed), &err));
    if (every < 1)
        return fw_report((fw_fail(&err, FW_EINPUT, "--every %ld: must be 1 or more", every), &err));
    if (seed < 0)
        return fw_report((fw_fail(&err, FW_EINPUT, "--seed %ld: must be 0 or more", seed), &err));
    fw_traffic_mode m;
    if (fw_traffic_mode_parse(mode, &m, &err) || fw_check_sumo_mode("--sumo", &m, &err) ||
        (m.kind == FW_TRAFFIC_GUI && fw_traffic_gui_check("--sumo", &err)) ||
        fw_check_out_file("--routes", routes, true, &err) ||
        fw_check_out_file("--log", log, true, &err) ||
        fw_sumo_path_check("--routes", routes, &err))
        return fw_report(&err);
    return run(network, ships, density, duration, step, radius, speed, seed, every, mode, log,
               routes, demand);
}
