/* bench_sumo_alone - the whole run against SUMO alone, the floor issue 15
 * measures against: `fairway run` of the default study's base scenario
 * (scenarios/traffic/dover-crossing.yaml: one simulated hour, colregs
 * traffic) against the `sumo` binary stepping the same network and the same
 * demand (the route file that run wrote) for the same hour, with nothing of
 * ours in it: no own ship, no subscription, no reactions.
 *
 * Whole processes, start-up included (that is what a study pays per run):
 * RUNS pairs, A and B in turn, CPU (user + system, the kernel's accounting
 * of the reaped child) and wall.  Printed: the medians and the median of the
 * pairwise ratios.  Results: bench/results/sumo_alone.txt.
 *
 *     build/bench/bench_sumo_alone [FAIRWAY]    (default: the fairway beside
 *                                                this program's directory) */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench.h"
#include "core/files.h"
#include "core/spawn.h"

enum { RUNS = 5 };

/* Runs argv to the end: CPU and wall seconds; exits on failure. */
static void timed(const char *const *argv, double *cpu, double *wall)
{
    fw_error err = {0};
    pid_t pid;
    double t0 = bench_now();
    if (fw_spawn(&(fw_spawn_def){.argv = argv}, &pid, &err)) {
        fprintf(stderr, "bench_sumo_alone: %s\n", err.msg);
        exit(1);
    }
    int status;
    struct rusage ru;
    while (wait4(pid, &status, 0, &ru) < 0 && errno == EINTR)
        ;
    *wall = bench_now() - t0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "bench_sumo_alone: %s failed (status %d)\n", argv[0], status);
        exit(1);
    }
    *cpu = (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           1e-6 * (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

int main(int argc, char **argv)
{
    char fairway[PATH_MAX + 16], self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (argc > 2 || n <= 0) {
        fprintf(stderr, "usage: bench_sumo_alone [FAIRWAY]\n");
        return 2;
    }
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    if (slash)
        *slash = '\0';
    snprintf(fairway, sizeof fairway, "%s", argc == 2 ? argv[1] : self);
    if (argc < 2)
        strncat(fairway, "/../fairway", sizeof fairway - strlen(fairway) - 1);
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
    double ac[RUNS], aw[RUNS], bc[RUNS], bw[RUNS], rc[RUNS], rw[RUNS];
    for (int k = 0; k <= RUNS; k++) {
        /* run 0 is the warm-up, and writes the route file sumo replays */
        snprintf(out, sizeof out, "%s/r%d", dir, k);
        const char *run[] = {fairway, "run", scn, "--out", out, NULL};
        double c, w;
        timed(run, &c, &w);
        if (k == 0)
            continue;
        ac[k - 1] = c, aw[k - 1] = w;
        timed(sumo, &bc[k - 1], &bw[k - 1]);
        rc[k - 1] = ac[k - 1] / bc[k - 1];
        rw[k - 1] = aw[k - 1] / bw[k - 1];
    }
    printf("%-22s %10s %10s\n", "", "cpu_s", "wall_s");
    printf("%-22s %10.3f %10.3f\n", "fairway run", bench_median(ac, RUNS), bench_median(aw, RUNS));
    printf("%-22s %10.3f %10.3f\n", "sumo alone", bench_median(bc, RUNS), bench_median(bw, RUNS));
    printf("%-22s %10.2f %10.2f\n", "ratio (pairwise)", bench_median(rc, RUNS),
           bench_median(rw, RUNS));
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : 1;
}
