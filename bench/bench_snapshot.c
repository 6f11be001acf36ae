/* bench_snapshot - the cost of a snapshot and of a restore of a running run
 * (src/run/branch.h) against the cost of one simulated minute of the default
 * study's base scenario (scenarios/traffic/dover-crossing.yaml, SUMO
 * embedded); the aim: a restore costs less than five simulated minutes.
 *
 * Measured, wall seconds on the monotonic clock (a restored copy is another
 * process), medians of REPS:
 *   minute    one simulated minute of the whole run: a full unbranched run
 *             (open, the hour's steps, close) / 60, and the minute [1740, 1800)
 *             stepped in the run the snapshots are taken of;
 *   snapshot  fw_run_snapshot at t = 1800 s (flush, the run directory's files
 *             noted, fork), and fw_snapshot_free (the paused copy killed and
 *             reaped);
 *   restore   fw_run_restore until the copy runs (it notes the clock when
 *             fw_run_snapshot returns in it: fork in the paused copy, the
 *             files cut back), the copy's first simulated minute [1800, 1860)
 *             against the minute before the snapshot (the copy-on-write page
 *             faults it pays) and against its second minute, with their
 *             minor page faults, and the whole restore (resume, the two
 *             minutes, exit, reaped, answered);
 *   the cost of a restore = resume + (the copy's first minute - its second):
 *   what the copy pays beyond the minutes it simulates;
 *   memory    the minor page faults of the original over the ten simulated
 *             minutes after a snapshot: the pages it copies, which the paused
 *             copy then holds alone.
 *
 *     build/bench/bench_snapshot [SCENARIO [OUT_DIR]]
 *     (default: FAIRWAY_DATA or the source tree's dover-crossing.yaml, /tmp)
 * Results: bench/results/snapshot.txt. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench.h"
#include "run/branch.h"
#include "run/run.h"

enum { REPS = 9 };

static fw_scenario scn;

/* What a restored copy tells the bench. */
typedef struct copy_report {
    double t_resumed, minute, second; /* s: the clock when it ran, its first two minutes */
    long faults, faults2;             /* minor page faults in each */
} copy_report;

static long minflt(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_minflt;
}

static void die(const char *what, const fw_error *err)
{
    fprintf(stderr, "bench_snapshot: %s: %s\n", what, err->msg);
    exit(1);
}

static fw_run_def run_def(const char *dir)
{
    mkdir(dir, 0777);
    fw_run_def d = fw_default_run_def();
    d.scenario = &scn;
    d.dir = dir;
    return d;
}

static void steps(fw_run *r, long n)
{
    fw_error err = {0};
    for (long k = 0; k < n; k++)
        if (fw_run_step(r, &err))
            die("step", &err);
}

/* A whole unbranched run, open to close: s. */
static double whole_run(const char *dir)
{
    fw_run_def d = run_def(dir);
    fw_error err = {0};
    fw_run *r;
    double t0 = bench_now();
    if (fw_run_open(&d, &r, &err))
        die("open", &err);
    while (!fw_run_done(r))
        steps(r, 1);
    fw_run_summary sum;
    fw_encounter *e;
    int n;
    if (fw_run_close(r, &sum, &e, &n, &err))
        die("close", &err);
    free(e);
    return bench_now() - t0;
}

/* In a restored copy: a minute, the report, the end. */
static void copy_minute(fw_run *r, int fd, double per_step)
{
    copy_report c = {.t_resumed = bench_now()};
    long f0 = minflt();
    steps(r, lround(60.0 / per_step));
    c.minute = bench_now() - c.t_resumed;
    long f1 = minflt();
    c.faults = f1 - f0;
    steps(r, lround(60.0 / per_step));
    c.second = bench_now() - c.t_resumed - c.minute;
    c.faults2 = minflt() - f1;
    _exit(write(fd, &c, sizeof c) == (ssize_t)sizeof c ? 0 : 1);
}

/* The median of v (sorted) in ms (scale 1e3) or as is (scale 1), its range. */
static void print_med(const char *what, double *v, int n, double scale, const char *unit)
{
    double m = bench_median(v, n);
    printf("  %-56s %9.2f %s (range %.2f-%.2f)\n", what, scale * m, unit, scale * v[0],
           scale * v[n - 1]);
}

int main(int argc, char **argv)
{
    char file[1024], dir[1200];
    const char *root = getenv("FAIRWAY_DATA");
    snprintf(file, sizeof file, "%s", argc > 1 ? argv[1] : "");
    if (!file[0])
        snprintf(file, sizeof file, "%s/scenarios/traffic/dover-crossing.yaml",
                 root ? root : FW_SOURCE_DIR);
    const char *out = argc > 2 ? argv[2] : "/tmp"; /* the runs' files, removed after */
    fw_error err = {0};
    if (fw_scenario_load(file, &scn, &err))
        die(file, &err);
    int res[2];
    if (pipe(res) != 0)
        return 1;
    double whole[REPS], snap_s[REPS], free_s[REPS], resume[REPS], first[REPS], total[REPS];
    double faults[REPS], second[REPS], faults2[REPS], cost[REPS];
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s/fw_bench_snapshot.XXXXXX", out);
    if (!mkdtemp(tmp))
        return 1;
    for (int i = 0; i < REPS; i++) {
        snprintf(dir, sizeof dir, "%s/whole-%d", tmp, i);
        whole[i] = whole_run(dir) / (scn.duration / 60.0);
    }
    snprintf(dir, sizeof dir, "%s/branched", tmp);
    fw_run_def d = run_def(dir);
    fw_run *r;
    if (fw_run_open(&d, &r, &err))
        die("open", &err);
    long per_min = lround(60.0 / scn.step);
    steps(r, 1800 / (long)scn.step - per_min);
    double t0 = bench_now();
    steps(r, per_min);
    double minute = bench_now() - t0;
    for (int i = 0; i < REPS; i++) {
        fw_snapshot *s;
        t0 = bench_now();
        if (fw_run_snapshot(r, &s, &err))
            die("snapshot", &err);
        if (!s)
            copy_minute(r, res[1], scn.step);
        snap_s[i] = bench_now() - t0;
        int code;
        t0 = bench_now();
        if (fw_run_restore(NULL, s, (uint32_t)i + 1, &code, &err) || code != 0)
            die("restore", &err);
        total[i] = bench_now() - t0;
        copy_report c;
        if (read(res[0], &c, sizeof c) != (ssize_t)sizeof c)
            return 1;
        resume[i] = c.t_resumed - t0;
        first[i] = c.minute;
        faults[i] = (double)c.faults;
        second[i] = c.second;
        faults2[i] = (double)c.faults2;
        cost[i] = resume[i] + c.minute - c.second;
        t0 = bench_now();
        fw_snapshot_free(s);
        free_s[i] = bench_now() - t0;
    }
    /* the memory a paused copy costs: the pages the original copies as it
     * goes on (each written page once), over the next ten simulated minutes */
    fw_snapshot *s;
    if (fw_run_snapshot(r, &s, &err))
        die("snapshot", &err);
    if (!s)
        _exit(0); /* never restored */
    long f0 = minflt();
    steps(r, 10 * per_min);
    long copied = minflt() - f0;
    fw_snapshot_free(s);
    fw_run_discard(r);
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmp);
    if (system(cmd) != 0)
        fprintf(stderr, "bench_snapshot: could not remove %s\n", tmp);
    printf("bench_snapshot: %s, snapshot at t = 1800 s, %d repetitions\n", scn.name, REPS);
    print_med("a simulated minute: the whole run / 60", whole, REPS, 1e3, "ms");
    printf("  %-56s %9.2f ms\n", "a simulated minute: [1740, 1800) in the run", 1e3 * minute);
    print_med("fw_run_snapshot", snap_s, REPS, 1e3, "ms");
    print_med("fw_snapshot_free", free_s, REPS, 1e3, "ms");
    print_med("fw_run_restore until the copy runs", resume, REPS, 1e3, "ms");
    print_med("the copy's first minute [1800, 1860)", first, REPS, 1e3, "ms");
    print_med("its minor page faults", faults, REPS, 1, "  ");
    print_med("the copy's second minute [1860, 1920)", second, REPS, 1e3, "ms");
    print_med("its minor page faults", faults2, REPS, 1, "  ");
    print_med("fw_run_restore whole (resume, 2 minutes, exit, answer)", total, REPS, 1e3, "ms");
    print_med("a restore's cost: resume + first minute - second minute", cost, REPS, 1e3, "ms");
    printf("  %-56s %9ld    (%.1f MB)\n", "pages the original copies in the next 10 minutes",
           copied, (double)copied * (double)sysconf(_SC_PAGESIZE) / 1e6);
    double m = bench_median(whole, REPS);
    printf("  restore / a simulated minute (the whole run's): %.2f (aim: under 5); snapshot / "
           "minute: %.2f\n",
           bench_median(cost, REPS) / m, bench_median(snap_s, REPS) / m);
    return 0;
}
