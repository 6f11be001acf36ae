/* bench_netcache - what the network cache (src/traffic/netcache.h) saves a
 * paper case: `fairway run scenarios/paper/1-head-on.yaml` (explicit targets:
 * a network of its own per run, netconvert's 0.16-0.35 s) with the cache off
 * (FAIRWAY_NETCACHE=off: netconvert every run, the baseline) and on (a warm
 * cache in a temporary XDG_CACHE_HOME), RUNS of each interleaved, whole
 * processes: CPU (user + system of the run and its netconvert) and wall.
 * Printed: medians and the median pairwise ratio; CSV_FILE gets one row per
 * run.  Results: bench/results/netcache.csv.
 *
 *     build/bench/bench_netcache [CSV_FILE|- [FAIRWAY]] */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_proc.h"
#include "core/files.h"

enum { RUNS = 7 };

int main(int argc, char **argv)
{
    char fairway[PATH_MAX + 16], scn[1200], out[128], cache[128];
    FILE *csv;
    int st = bench_proc_args(argc, argv, 2, "bench_netcache [CSV_FILE|- [FAIRWAY]]", fairway,
                             sizeof fairway, &csv);
    if (st >= 0)
        return st;
    char dir[] = "/tmp/bench_netcache.XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_netcache: mkdtemp");
        return 1;
    }
    snprintf(scn, sizeof scn, "%s/scenarios/paper/1-head-on.yaml", fw_data_root());
    snprintf(cache, sizeof cache, "%s/cache", dir);
    setenv("XDG_CACHE_HOME", cache, 1);
    double c[2][RUNS], w[2][RUNS], rc[RUNS], rw[RUNS];
    if (csv)
        fprintf(csv, "round,cache,cpu_s,wall_s\n");
    for (int k = -1; k < RUNS; k++) /* round -1 warms the cache */
        for (int on = 0; on < 2; on++) {
            setenv("FAIRWAY_NETCACHE", on ? "on" : "off", 1);
            snprintf(out, sizeof out, "%s/r%d-%d", dir, k + 1, on);
            const char *run[] = {fairway, "run", scn, "--out", out, NULL};
            double cc, ww;
            bench_proc_run(run, NULL, &cc, &ww);
            if (k < 0)
                continue;
            c[on][k] = cc, w[on][k] = ww;
            if (csv)
                fprintf(csv, "%d,%s,%.4f,%.4f\n", k + 1, on ? "on" : "off", cc, ww);
        }
    for (int k = 0; k < RUNS; k++)
        rc[k] = c[1][k] / c[0][k], rw[k] = w[1][k] / w[0][k];
    printf("%-26s %10s %10s\n", "paper-1-head-on run", "cpu_s", "wall_s");
    printf("%-26s %10.3f %10.3f\n", "cache off (netconvert)", bench_median(c[0], RUNS),
           bench_median(w[0], RUNS));
    printf("%-26s %10.3f %10.3f\n", "cache on (warm)", bench_median(c[1], RUNS),
           bench_median(w[1], RUNS));
    printf("%-26s %10.2f %10.2f\n", "ratio on/off (pairwise)", bench_median(rc, RUNS),
           bench_median(rw, RUNS));
    if (csv && fclose(csv) != 0)
        perror(argv[1]);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : 1;
}
