/* bench_traffic: ms per step of (SUMO step + own-ship move + range query) and
 * of the SUMO step alone, timed in the same steps, with libsumo in-process on
 * the `sea` grid at about 50, 200 and 1000 background ships.  Each run is a
 * child process (libsumo: one simulation per process); medians over runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"
#include "core/units.h"
#include "traffic/demand.h"
#include "traffic/traffic.h"

enum { WARMUP = 30, STEPS = 300, RUNS = 5 };

/* One run: medians of full and step-only ms, mean ship count and in range. */
static int one_run(int ships, int run, double out[4])
{
    fw_error err = {0};
    fw_network_files nf;
    fw_demand dm;
    if (fw_network_find("sea", &nf, &err) || fw_demand_load(nf.demand, &dm, &err))
        goto fail;
    char routes[64], log[64];
    snprintf(routes, sizeof routes, "/tmp/bench_traffic_%d.rou.xml", (int)getpid());
    snprintf(log, sizeof log, "/tmp/bench_traffic_%d.log", (int)getpid());
    fw_demand_def dd = fw_default_demand_def();
    dd.fill = ships;
    /* arrivals replace leavers: transit of a 40 km route at about 6.5 m/s */
    dd.density = ships / (fw_demand_rate(&dm) / 3600.0 * 40000.0 / 6.5);
    dd.seed = (unsigned long)run + 1;
    if (fw_demand_write(&dm, &dd, routes, &err))
        goto fail;
    fw_traffic_def d = fw_default_traffic_def();
    d.net_file = nf.net;
    d.route_file = routes;
    d.add_file = nf.types;
    d.log_file = log;
    d.seed = (unsigned long)run + 1;
    fw_traffic *t;
    if (fw_traffic_open(&d, &t, &err))
        goto fail;
    static double full[STEPS], step[STEPS];
    double count = 0, in_range = 0, U = fw_kn_to_ms(12);
    for (int k = 0; k < WARMUP + STEPS; k++) {
        const fw_target *s;
        int n;
        double t0 = 1e3 * bench_now();
        if (fw_traffic_place(t, -19000.0 + U * k, 0.0, FW_PI / 2, U, &err))
            goto fail;
        double t1 = 1e3 * bench_now();
        if (fw_traffic_step(t, &err))
            goto fail;
        double t2 = 1e3 * bench_now();
        if (fw_traffic_around(t, &s, &n, &err))
            goto fail;
        double t3 = 1e3 * bench_now();
        if (k >= WARMUP) {
            full[k - WARMUP] = t3 - t0;
            step[k - WARMUP] = t2 - t1;
            in_range += n;
        }
        if (k == WARMUP + STEPS - 1) {
            const fw_target *all;
            int na;
            if (fw_traffic_all(t, &all, &na, &err))
                goto fail;
            count = na - 1;
        }
    }
    fw_traffic_close(t);
    remove(routes);
    remove(log);
    out[0] = bench_median(full, STEPS);
    out[1] = bench_median(step, STEPS);
    out[2] = count;
    out[3] = in_range / STEPS;
    return 0;
fail:
    fprintf(stderr, "bench_traffic: %s\n", err.msg);
    return 1;
}

int main(int argc, char **argv)
{
    const int sizes[3] = {50, 200, 1000};
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: bench_traffic [CSV_FILE]\n"
                        "libsumo stepping and querying 50, 200 and 1000 ships; medians printed,\n"
                        "and written to CSV_FILE if given\n");
        return argc == 2 && strcmp(argv[1], "--help") == 0 ? 0 : 2;
    }
    FILE *csv = argc > 1 ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && !csv) {
        fprintf(stderr, "bench_traffic: cannot write %s\n", argv[1]);
        return 2;
    }
    if (csv)
        fprintf(csv, "ships_target,ships_end,in_range,ms_full,ms_step,ratio,runs,steps\n");
    printf("libsumo, sea grid, 1 s steps, %d steps after %d warm-up, median of %d runs\n", STEPS,
           WARMUP, RUNS);
    printf("%6s %6s %8s %12s %12s %7s\n", "ships", "at end", "in range", "ms step+q", "ms step",
           "ratio");
    for (int i = 0; i < 3; i++) {
        double r[RUNS][4], full[RUNS], step[RUNS], ratio[RUNS];
        for (int run = 0; run < RUNS; run++) {
            int fds[2];
            if (pipe(fds) != 0)
                return 1;
            pid_t p = fork();
            if (p == 0) {
                close(fds[0]);
                double o[4];
                int rc = one_run(sizes[i], run, o);
                if (!rc && write(fds[1], o, sizeof o) != (ssize_t)sizeof o)
                    rc = 1;
                _exit(rc);
            }
            close(fds[1]);
            ssize_t got = read(fds[0], r[run], sizeof r[run]);
            close(fds[0]);
            int status = 0;
            waitpid(p, &status, 0);
            if (got != (ssize_t)sizeof r[run] || !WIFEXITED(status) || WEXITSTATUS(status))
                return 1;
            full[run] = r[run][0];
            step[run] = r[run][1];
            ratio[run] = r[run][0] / r[run][1];
        }
        double mf = bench_median(full, RUNS), ms = bench_median(step, RUNS), mr = bench_median(ratio, RUNS);
        printf("%6d %6.0f %8.1f %12.3f %12.3f %7.3f\n", sizes[i], r[0][2], r[0][3], mf, ms, mr);
        if (csv)
            fprintf(csv, "%d,%.0f,%.1f,%.4f,%.4f,%.4f,%d,%d\n", sizes[i], r[0][2], r[0][3], mf,
                    ms, mr, RUNS, STEPS);
    }
    if (csv)
        fclose(csv);
    return 0;
}
