/* bench_startup - what a command that does not simulate costs, whole process:
 * `fairway --help`, `fairway ship c3` and one `fairway helm` decision, CPU
 * (user + system of the reaped child) and wall, median of RUNS, beside
 * /bin/true (what any fork and exec costs here).  Issue 15's floor: --help at
 * most 20 ms of CPU; SUMO is a module such commands never load.
 *
 *     build/bench/bench_startup [CSV_FILE [FAIRWAY...]]
 *
 * Each FAIRWAY given is measured, interleaved run by run (so an old build and
 * a new one see the same machine); default: the build tree's.  CSV_FILE
 * ("-": none) gets one row per program and command.  Results:
 * bench/results/startup.csv. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "bench_proc.h"

enum { RUNS = 21, MAX_PROGS = 4, N_CMDS = 4 };

/* argv[0] is filled in per program; NULL ends each command */
static const char *const kCmds[N_CMDS][12] = {
    {"/bin/true", NULL},
    {"", "--help", NULL},
    {"", "ship", "c3", NULL},
    {"", "helm", "--ship", "c3", "--own", "0,0,0,10", "--target", "0,1800,180,10", NULL},
};
static const char *const kNames[N_CMDS] = {"/bin/true", "--help", "ship c3", "helm"};

int main(int argc, char **argv)
{
    char own[PATH_MAX + 16];
    const char *progs[MAX_PROGS];
    int np = 0;
    if (argc > 2 + MAX_PROGS || (argc == 2 && strcmp(argv[1], "--help") == 0)) {
        fprintf(stderr, "usage: bench_startup [CSV_FILE|- [FAIRWAY...]] (at most %d)\n",
                MAX_PROGS);
        return 2;
    }
    for (int i = 2; i < argc; i++)
        progs[np++] = argv[i];
    if (np == 0) {
        if (bench_proc_fairway(own, sizeof own)) {
            fprintf(stderr, "bench_startup: cannot find the build tree's fairway\n");
            return 1;
        }
        progs[np++] = own;
    }
    FILE *csv = argc > 1 && strcmp(argv[1], "-") ? fopen(argv[1], "w") : NULL;
    if (argc > 1 && strcmp(argv[1], "-") && !csv) {
        perror(argv[1]);
        return 1;
    }
    static double cpu[MAX_PROGS][N_CMDS][RUNS], wall[MAX_PROGS][N_CMDS][RUNS];
    for (int r = -1; r < RUNS; r++) /* run -1 warms the page cache */
        for (int p = 0; p < np; p++)
            for (int c = 0; c < N_CMDS; c++) {
                if (c == 0 && p > 0)
                    continue; /* /bin/true once */
                const char *a[12];
                memcpy(a, kCmds[c], sizeof a);
                if (c > 0)
                    a[0] = progs[p];
                double cc, ww;
                bench_proc_run(a, NULL, &cc, &ww);
                if (r >= 0)
                    cpu[p][c][r] = cc, wall[p][c][r] = ww;
            }
    if (csv)
        fprintf(csv, "program,command,runs,cpu_ms_median,cpu_ms_min,cpu_ms_max,wall_ms_median\n");
    printf("%-40s %-10s %12s %10s %10s %12s\n", "program", "command", "cpu_ms_med", "cpu_min",
           "cpu_max", "wall_ms_med");
    for (int p = 0; p < np; p++)
        for (int c = 0; c < N_CMDS; c++) {
            if (c == 0 && p > 0)
                continue;
            double *v = cpu[p][c];
            double med = bench_median(v, RUNS); /* sorts v */
            double wm = bench_median(wall[p][c], RUNS);
            const char *prog = c == 0 ? "-" : progs[p];
            printf("%-40s %-10s %12.1f %10.1f %10.1f %12.1f\n", prog, kNames[c], 1e3 * med,
                   1e3 * v[0], 1e3 * v[RUNS - 1], 1e3 * wm);
            if (csv)
                fprintf(csv, "%s,%s,%d,%.2f,%.2f,%.2f,%.2f\n", prog, kNames[c], RUNS, 1e3 * med,
                        1e3 * v[0], 1e3 * v[RUNS - 1], 1e3 * wm);
        }
    if (csv && fclose(csv) != 0) {
        perror(argv[1]);
        return 1;
    }
    return 0;
}
