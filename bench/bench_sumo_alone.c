/* bench_sumo_alone - the whole run against SUMO alone, the floor issue 15
 * measures against: `fairway run` of the default study's base scenario
 * (scenarios/traffic/dover-crossing.yaml: one simulated hour, colregs
 * traffic) against the `sumo` binary stepping the same network and the same
 * demand (the route file that run wrote) for the same hour, with nothing of
 * ours in it: no own ship, no subscription, no reactions, and the options
 * fairway gives SUMO (src/traffic/sumoargs.c), so that the floor is the
 * cheapest SUMO that moves these ships as fairway's does.  W, "sumo, collision
 * check on", is the same sumo with SUMO's own collision check ("warn"), as
 * fairway ran it until 2026-12-02 and as the issue first measured it: it moves
 * every ship the same (its FCD output is the same bytes) and costs half as
 * much again; A/W is printed beside A/B, never instead of it.
 *
 * Whole processes, start-up included (that is what a study pays per run):
 * RUNS rounds, each running A, (A0,) B, W, L in turn, CPU (user + system, the
 * kernel's accounting of the reaped child) and wall.  Printed: the medians,
 * the median of the pairwise ratios and their range (the spread).  A0, if
 * given, is a baseline fairway (say the build of the commit before a change)
 * measured in the same rounds: A/A0 says what the change did, A0/B what the
 * coupling cost before it.  L, "libsumo alone", is SUMO through fairway's
 * libsumo back end and nothing else (this program re-run as
 * `bench_sumo_alone --libsumo-only SUMO_ARGS...`: the module loaded, the same
 * simulation started and stepped the hour, no own ship, no reads): L - B is
 * what loading libsumo costs a process, A - L what fairway adds; L's split
 * (load, start, steps) is printed too.  CSV_FILE gets one row per round and
 * program.  Results: bench/results/sumo_alone.csv.
 *
 *     build/bench/bench_sumo_alone [CSV_FILE|- [FAIRWAY [BASELINE_FAIRWAY]]]
 *     (default FAIRWAY: the build tree's; the baseline needs FAIRWAY_DATA
 *     when it is not a build-tree or installed program) */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "bench.h"
#include "bench_proc.h"
#include "core/files.h"
#include "traffic/backend.h"
#include "traffic/demand.h"

enum { RUNS = 7 };

static double cpu_self(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           1e-6 * (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

/* L: the libsumo back end alone on sumo's argv, one simulated hour; prints
 * CPU seconds "start-up,load,start,steps" (start-up: before main). */
static int libsumo_only(const char *const *argv)
{
    double t0 = cpu_self();
    const fw_sumo_backend *be;
    fw_error err = {0};
    double t1 = 0, t2 = 0, tm;
    if (fw_sumo_backend_load(false, &be, &err) || (t1 = cpu_self(), be->start(argv, &err)))
        goto fail;
    t2 = cpu_self();
    for (int k = 0; k < 3600; k++)
        if (be->step(&tm, &err))
            goto fail;
    double t3 = cpu_self();
    be->close();
    printf("%.4f,%.4f,%.4f,%.4f\n", t0, t1 - t0, t2 - t1, t3 - t2);
    return 0;
fail:
    fprintf(stderr, "bench_sumo_alone --libsumo-only: %s\n", err.msg);
    return 1;
}

/* The split libsumo_only printed into file. */
static void read_split(const char *file, double split[4])
{
    FILE *f = fopen(file, "r");
    if (!f || fscanf(f, "%lf,%lf,%lf,%lf", &split[0], &split[1], &split[2], &split[3]) != 4) {
        fprintf(stderr, "bench_sumo_alone: no split in %s\n", file);
        exit(1);
    }
    fclose(f);
}

/* A's phases, from its --profile line (src/run/run.c log_profile): wall s. */
enum { NPHASE = 9 };
static const char *const kPhase[NPHASE] = {
    "set-up", "traffic's step", "own ship placed", "ships read", "decisions",
    "traffic's reactions", "own dynamics", "records and monitors", "finish"};

static void read_profile(const char *file, double ph[NPHASE])
{
    char line[1024] = "";
    FILE *f = fopen(file, "r");
    while (f && fgets(line, sizeof line, f) && strncmp(line, "profile: ", 9) != 0)
        ;
    if (f)
        fclose(f);
    for (int j = 0; j < NPHASE; j++) {
        const char *at = strstr(line, kPhase[j]);
        if (!at || sscanf(at + strlen(kPhase[j]), "%lf", &ph[j]) != 1) {
            fprintf(stderr, "bench_sumo_alone: no '%s' in the profile line of %s\n", kPhase[j],
                    file);
            exit(1);
        }
    }
}

static void print_profile(double ph[NPHASE][RUNS])
{
    printf("  fairway run, wall by phase (medians, its --profile line):");
    for (int j = 0; j < NPHASE; j++)
        printf("%s %s %.3f", j % 3 ? "," : "\n   ", kPhase[j], bench_median(ph[j], RUNS));
    printf("\n");
}

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
    printf("%-26s %10.2f %10.2f   cpu range %.2f-%.2f\n", what, c, w, lo, hi);
}

static void print_median(const char *what, const double *cpu, const double *wall)
{
    double t[RUNS], u[RUNS];
    memcpy(t, cpu, sizeof t), memcpy(u, wall, sizeof u);
    printf("%-26s %10.3f %10.3f\n", what, bench_median(t, RUNS), bench_median(u, RUNS));
}

/* The medians and ratios of A (ac, aw), A0 (oc, ow; oc NULL: none), B and L. */
static void report(const double *ac, const double *aw, const double *oc, const double *ow,
                   const double *bc, const double *bw, const double *lc, const double *lw,
                   double split[4][RUNS], double ph[NPHASE][RUNS])
{
    printf("%-26s %10s %10s\n", "", "cpu_s", "wall_s");
    print_median("fairway run", ac, aw);
    print_profile(ph);
    if (oc)
        print_median("baseline run", oc, ow);
    print_median("sumo alone", bc, bw);
    print_median("libsumo alone", lc, lw);
    printf("  libsumo alone, CPU: before main %.3f, module load %.3f, start %.3f, steps %.3f\n",
           bench_median(split[0], RUNS), bench_median(split[1], RUNS),
           bench_median(split[2], RUNS), bench_median(split[3], RUNS));
    print_ratio("ratio fairway/sumo", ac, bc, aw, bw);
    print_ratio("ratio libsumo/sumo", lc, bc, lw, bw);
    print_ratio("ratio fairway/libsumo", ac, lc, aw, lw);
    if (oc) {
        print_ratio("ratio baseline/sumo", oc, bc, ow, bw);
        print_ratio("ratio fairway/baseline", ac, oc, aw, ow);
    }
}

int main(int argc, char **argv)
{
    char fairway[PATH_MAX + 16];
    if (argc > 1 && strcmp(argv[1], "--libsumo-only") == 0)
        return libsumo_only((const char *const *)argv + 2);
    FILE *csv;
    int rc = bench_proc_args(argc, argv, 3,
                             "bench_sumo_alone [CSV_FILE|- [FAIRWAY [BASELINE_FAIRWAY]]]", fairway,
                             sizeof fairway, &csv);
    if (rc >= 0)
        return rc;
    const char *base = argc > 3 ? argv[3] : NULL;
    char dir[] = "/tmp/bench_sumo_alone.XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_sumo_alone: mkdtemp");
        return 1;
    }
    char scn[1200], out[64], net[1200], rou[128], types[1200];
    snprintf(scn, sizeof scn, "%s/scenarios/traffic/dover-crossing.yaml", fw_data_root());
    fw_network_files nf;
    if (fw_network_find("dover", &nf, NULL)) {
        fprintf(stderr, "bench_sumo_alone: network dover cannot be built\n");
        return 1;
    }
    snprintf(net, sizeof net, "%s", nf.net);
    snprintf(types, sizeof types, "%s/networks/ships.add.xml", fw_data_root());
    snprintf(rou, sizeof rou, "%s/r0/dover-crossing/sumo/demand.rou.xml", dir);
    const char *sumo[] = {"sumo", "--net-file", net, "--route-files", rou, "--additional-files",
                          types, "--step-length", "1", "--seed", "1", "--time-to-teleport", "-1",
                          "--collision.action", "none", "--lanechange.duration", "2800",
                          "--no-step-log", "true", "--duration-log.disable", "true", "--end",
                          "3600", "--log", "/dev/null", NULL};
    /* W: the same with SUMO's collision check on */
    const char *sumo_warn[sizeof sumo / sizeof *sumo];
    memcpy(sumo_warn, sumo, sizeof sumo);
    for (int i = 0; sumo_warn[i]; i++)
        if (strcmp(sumo_warn[i], "--collision.action") == 0)
            sumo_warn[i + 1] = "warn";
    /* L's argv: this program, the mode, then sumo's own */
    char self[PATH_MAX], split_file[128], prof_file[128];
    ssize_t sn = readlink("/proc/self/exe", self, sizeof self - 1);
    if (sn <= 0) {
        perror("bench_sumo_alone: /proc/self/exe");
        return 1;
    }
    self[sn] = '\0';
    const char *lib[40] = {self, "--libsumo-only"};
    for (int i = 0; sumo[i]; i++)
        lib[2 + i] = sumo[i];
    snprintf(split_file, sizeof split_file, "%s/split.txt", dir);
    snprintf(prof_file, sizeof prof_file, "%s/profile.txt", dir);
    double ac[RUNS], aw[RUNS], oc[RUNS], ow[RUNS], bc[RUNS], bw[RUNS], lc[RUNS], lw[RUNS];
    double wc[RUNS], ww[RUNS];
    double split[4][RUNS], ph[NPHASE][RUNS];
    if (csv)
        fprintf(csv, "round,program,cpu_s,wall_s\n");
    for (int k = 0; k <= RUNS; k++) {
        /* round 0 is the warm-up, and writes the route file sumo replays */
        snprintf(out, sizeof out, "%s/r%d", dir, k);
        const char *run[] = {fairway, "run", scn, "--out", out, "--profile", NULL};
        double c, w, p[NPHASE];
        bench_proc_run(run, prof_file, &c, &w);
        if (k == 0)
            continue;
        ac[k - 1] = c, aw[k - 1] = w;
        read_profile(prof_file, p);
        for (int j = 0; j < NPHASE; j++)
            ph[j][k - 1] = p[j];
        if (base) {
            snprintf(out, sizeof out, "%s/b%d", dir, k);
            const char *run0[] = {base, "run", scn, "--out", out, NULL};
            bench_proc_run(run0, NULL, &oc[k - 1], &ow[k - 1]);
        }
        bench_proc_run(sumo, NULL, &bc[k - 1], &bw[k - 1]);
        bench_proc_run(sumo_warn, NULL, &wc[k - 1], &ww[k - 1]);
        bench_proc_run(lib, split_file, &lc[k - 1], &lw[k - 1]);
        double sp[4];
        read_split(split_file, sp);
        for (int j = 0; j < 4; j++)
            split[j][k - 1] = sp[j];
        if (csv) {
            fprintf(csv, "%d,fairway,%.4f,%.4f\n", k, ac[k - 1], aw[k - 1]);
            if (base)
                fprintf(csv, "%d,baseline,%.4f,%.4f\n", k, oc[k - 1], ow[k - 1]);
            fprintf(csv, "%d,sumo,%.4f,%.4f\n", k, bc[k - 1], bw[k - 1]);
            fprintf(csv, "%d,sumo_collision_check,%.4f,%.4f\n", k, wc[k - 1], ww[k - 1]);
            fprintf(csv, "%d,libsumo,%.4f,%.4f\n", k, lc[k - 1], lw[k - 1]);
        }
    }
    report(ac, aw, base ? oc : NULL, ow, bc, bw, lc, lw, split, ph);
    print_median("sumo, collision check on", wc, ww);
    print_ratio("ratio fairway/that", ac, wc, aw, ww);
    print_ratio("ratio that/sumo", wc, bc, ww, bw);
    if (csv && fclose(csv) != 0)
        perror(argv[1]);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : 1;
}
