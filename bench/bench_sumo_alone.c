/* bench_sumo_alone - the whole run against SUMO alone, the floor issue 15
 * measures against: `fairway run` of the default study's base scenario
 * (scenarios/traffic/dover-crossing.yaml: one simulated hour, colregs
 * traffic) against the `sumo` binary stepping the same network and the same
 * demand (the route file that run wrote) for the same hour, with nothing of
 * ours in it: no own ship, no subscription, no reactions.
 *
 * Whole processes, start-up included (that is what a study pays per run):
 * RUNS rounds, each running A, (A0,) B in turn, CPU (user + system, the
 * kernel's accounting of the reaped child) and wall.  Printed: the medians,
 * the median of the pairwise ratios and their range (the spread).  A0, if
 * given, is a baseline fairway (say the build of the commit before a change)
 * measured in the same rounds: A/A0 says what the change did, A0/B what the
 * coupling cost before it.  CSV_FILE gets one row per round and program.
 * Results: bench/results/sumo_alone.csv.
 *
 *     build/bench/bench_sumo_alone [CSV_FILE|- [FAIRWAY [BASELINE_FAIRWAY]]]
 *     (default FAIRWAY: the build tree's; the baseline needs FAIRWAY_DATA
 *     when it is not a build-tree or installed program) */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_proc.h"
#include "core/files.h"

enum { RUNS = 7 };

/* Median of the n ratios a[k] / b[k], and their range. */
static double ratio_median(const double *a, const double *b, int n, double *lo, double *hi)
{
    double r[RUNS];
    for (int k = 0; k < n; k++)
        r[k] = a[k] / b[k];
    double m = bench_median(r, n); /* sorts r */
    *lo = r[0], *hi = r[n - 1];
    return m;
}

static void print_ratio(const char *what, const double *ac, const double *bc, const double *aw,
                        const double *bw)
{
    double lo, hi, wlo, whi;
    double c = ratio_median(ac, bc, RUNS, &lo, &hi), w = ratio_median(aw, bw, RUNS, &wlo, &whi);
    printf("%-22s %10.2f %10.2f   cpu range %.2f-%.2f\n", what, c, w, lo, hi);
}

int main(int argc, char **argv)
{
    char fairway[PATH_MAX + 16];
    if (argc > 4 || (argc == 2 && strcmp(argv[1], "--help") == 0)) {
        fprintf(stderr, "usage: bench_sumo_alone [CSV_FILE|- [FAIRWAY [BASELINE_FAIRWAY]]]\n");
        return 2;
    }
    if (argc > 2)
        snprintf(fairway, sizeof fairway, "%s", argv[2]);
    else if (bench_proc_fairway(fairway, sizeof fairway)) {
        fprintf(stderr, "bench_sumo_alone: cannot find the build tree's fairway\n");
        return 1;
    }
    const char *base = argc > 3 ? argv[3] : NULL;
    FILE *csv = argc > 1 && strcmp(argv[1], "-") ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && strcmp(argv[1], "-") && !csv) {
        perror(argv[1]);
        return 1;
    }
    char dir[] = "/tmp/bench_sumo_alone.XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_sumo_alone: mkdtemp");
        return 1;
    }
    char scn[1200], out[64], net[1200], rou[128], types[1200];
    snprintf(scn, sizeof scn, "%s/scenarios/traffic/dover-crossing.yaml", fw_data_root());
    snprintf(net, sizeof net, "%s/dover/dover.net.xml", fw_net_dir());
    snprintf(types, sizeof types, "%s/networks/ships.add.xml", fw_data_root());
    snprintf(rou, sizeof rou, "%s/r0/dover-crossing/sumo/demand.rou.xml", dir);
    const char *sumo[] = {"sumo", "--net-file", net, "--route-files", rou, "--additional-files",
                          types, "--step-length", "1", "--seed", "1", "--time-to-teleport", "-1",
                          "--collision.action", "warn", "--lanechange.duration", "2800",
                          "--no-step-log", "true", "--duration-log.disable", "true", "--end",
                          "3600", "--log", "/dev/null", NULL};
    double ac[RUNS], aw[RUNS], oc[RUNS], ow[RUNS], bc[RUNS], bw[RUNS];
    if (csv)
        fprintf(csv, "round,program,cpu_s,wall_s\n");
    for (int k = 0; k <= RUNS; k++) {
        /* round 0 is the warm-up, and writes the route file sumo replays */
        snprintf(out, sizeof out, "%s/r%d", dir, k);
        const char *run[] = {fairway, "run", scn, "--out", out, NULL};
        double c, w;
        bench_proc_run(run, NULL, &c, &w);
        if (k == 0)
            continue;
        ac[k - 1] = c, aw[k - 1] = w;
        if (base) {
            snprintf(out, sizeof out, "%s/b%d", dir, k);
            const char *run0[] = {base, "run", scn, "--out", out, NULL};
            bench_proc_run(run0, NULL, &oc[k - 1], &ow[k - 1]);
        }
        bench_proc_run(sumo, NULL, &bc[k - 1], &bw[k - 1]);
        if (csv) {
            fprintf(csv, "%d,fairway,%.4f,%.4f\n", k, ac[k - 1], aw[k - 1]);
            if (base)
                fprintf(csv, "%d,baseline,%.4f,%.4f\n", k, oc[k - 1], ow[k - 1]);
            fprintf(csv, "%d,sumo,%.4f,%.4f\n", k, bc[k - 1], bw[k - 1]);
        }
    }
    printf("%-22s %10s %10s\n", "", "cpu_s", "wall_s");
    double t[RUNS], u[RUNS];
    memcpy(t, ac, sizeof t), memcpy(u, aw, sizeof u);
    printf("%-22s %10.3f %10.3f\n", "fairway run", bench_median(t, RUNS), bench_median(u, RUNS));
    if (base) {
        memcpy(t, oc, sizeof t), memcpy(u, ow, sizeof u);
        printf("%-22s %10.3f %10.3f\n", "baseline run", bench_median(t, RUNS),
               bench_median(u, RUNS));
    }
    memcpy(t, bc, sizeof t), memcpy(u, bw, sizeof u);
    printf("%-22s %10.3f %10.3f\n", "sumo alone", bench_median(t, RUNS), bench_median(u, RUNS));
    print_ratio("ratio fairway/sumo", ac, bc, aw, bw);
    if (base) {
        print_ratio("ratio baseline/sumo", oc, bc, ow, bw);
        print_ratio("ratio fairway/baseline", ac, oc, aw, ow);
    }
    if (csv && fclose(csv) != 0)
        perror(argv[1]);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : 1;
}
