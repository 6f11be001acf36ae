/* bench_sweep: the default study's speed.
 *
 *  1. runs per minute of the first RUNS runs of scenarios/studies/strait-domain.yaml
 *     with 1 and with 2 worker processes (medians of REPS sweeps each), and the
 *     parallel efficiency rate(2) / (2 rate(1));
 *  2. per run, the ratio of a whole fairway run (MMG own ship, avoidance, records,
 *     SUMO) to SUMO alone stepping the same traffic (same network, demand, seed,
 *     duration; open, steps, close), both timed in fresh child processes
 *     (libsumo: one simulation per process), 3 times each, alternated; medians.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench.h"
#include "core/files.h"
#include "study/sweep.h"
#include "traffic/demand.h"
#include "traffic/traffic.h"

enum { RUNS = 8, REPS = 3, RATIO_REPS = 5 };

static double sweep_rate(const fw_study *s, int jobs)
{
    char db[128];
    snprintf(db, sizeof db, "/tmp/bench_sweep_%d.db", (int)getpid());
    fw_sweep_def d = fw_default_sweep_def();
    d.study = s;
    d.db = db;
    d.jobs = jobs;
    d.limit = RUNS;
    d.progress = FW_PROGRESS_NONE;
    fw_sweep_result res;
    fw_error err = {0};
    double t0 = bench_now();
    fw_status st = fw_sweep_local(&d, &res, &err);
    double el = bench_now() - t0;
    char side[160];
    unlink(db);
    snprintf(side, sizeof side, "%s-wal", db);
    unlink(side);
    snprintf(side, sizeof side, "%s-shm", db);
    unlink(side);
    if (st || res.done != RUNS) {
        fprintf(stderr, "bench_sweep: sweep failed: %s (%d ok)\n", err.msg, res.done);
        exit(1);
    }
    return RUNS * 60.0 / el;
}

/* SUMO alone on run r's traffic: open, duration/step steps, close. */
static double sumo_alone(const fw_study *s, int run_id, const char *dir)
{
    fw_scenario scn;
    fw_study_run r = fw_study_run_at(s, run_id);
    fw_study_scenario(s, &r, &scn);
    fw_error err = {0};
    fw_network_files nf;
    fw_demand dm;
    char routes[1200], log[1200];
    snprintf(routes, sizeof routes, "%s/demand.rou.xml", dir);
    snprintf(log, sizeof log, "%s/sumo.log", dir);
    double t0 = bench_now();
    fw_demand_def dd = fw_default_demand_def();
    dd.density = scn.density;
    dd.fill = scn.fill;
    dd.end = scn.duration + scn.step;
    dd.seed = scn.seed;
    fw_traffic_def d = fw_default_traffic_def();
    d.net_file = nf.net;
    fw_traffic *t = NULL;
    if (fw_network_find(scn.network, &nf, &err) || fw_demand_load(nf.demand, &dm, &err) ||
        fw_demand_write(&dm, &dd, routes, &err))
        goto fail;
    d.net_file = nf.net;
    d.route_file = routes;
    d.add_file = nf.types;
    d.log_file = log;
    d.step = scn.step;
    d.seed = scn.seed;
    d.own_length = scn.ship.Loa;
    d.own_width = scn.ship.B;
    d.radius = scn.radius;
    if (fw_traffic_open(&d, &t, &err))
        goto fail;
    /* the own ship is a SUMO vehicle in a run too: moved along its course here */
    long n = lround(scn.duration / scn.step);
    double se = sin(scn.course), ce = cos(scn.course);
    for (long k = 0; k <= n; k++) {
        double x = scn.speed * scn.step * (double)k;
        if (fw_traffic_place(t, scn.east + x * se, scn.north + x * ce, scn.course, scn.speed,
                             &err) ||
            fw_traffic_step(t, &err))
            goto fail;
    }
    fw_traffic_close(t);
    return bench_now() - t0;
fail:
    fprintf(stderr, "bench_sweep: %s\n", err.msg);
    exit(1);
}

/* One measurement in a child: kind 0 SUMO alone, 1 the whole run. */
static double in_child(const fw_study *s, int run_id, int kind)
{
    int fd[2];
    fflush(NULL);
    if (pipe(fd) != 0)
        exit(1);
    pid_t pid = fork();
    if (pid == 0) {
        char dir[64];
        snprintf(dir, sizeof dir, "/tmp/bench_sweep_run_%d", (int)getpid());
        mkdir(dir, 0777);
        double v;
        if (kind == 0) {
            v = sumo_alone(s, run_id, dir);
        } else {
            fw_outcome o;
            double t0 = bench_now();
            fw_traffic_mode mode = {.kind = FW_TRAFFIC_EMBEDDED};
            fw_sweep_exec(s, run_id, dir, false, &mode, &o);
            v = strcmp(o.status, "ok") == 0 ? bench_now() - t0 : -1.0;
        }
        fw_remove_tree(dir);
        if (write(fd[1], &v, sizeof v) != (ssize_t)sizeof v)
            _exit(1);
        _exit(0);
    }
    close(fd[1]);
    double v = -1.0;
    if (read(fd[0], &v, sizeof v) != (ssize_t)sizeof v)
        v = -1.0;
    close(fd[0]);
    waitpid(pid, NULL, 0);
    if (v < 0) {
        fprintf(stderr, "bench_sweep: run %d failed\n", run_id);
        exit(1);
    }
    return v;
}

int main(void)
{
    const char *root = getenv("FAIRWAY_DATA");
    char path[1024];
    snprintf(path, sizeof path, "%s/scenarios/studies/strait-domain.yaml",
             root ? root : FAIRWAY_DATA_DIR);
    static fw_study s;
    fw_error err = {0};
    if (fw_study_load(path, &s, &err)) {
        fprintf(stderr, "bench_sweep: %s\n", err.msg);
        return 1;
    }
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    printf("study %s: %d runs of %.0f s, %ld cores; first %d runs per sweep, %d sweeps each\n",
           s.name, fw_study_run_count(&s), s.duration, cores, RUNS, REPS);
    double r1[REPS], r2[REPS];
    for (int i = 0; i < REPS; i++) { /* interleaved, so drift hits both alike */
        r1[i] = sweep_rate(&s, 1);
        r2[i] = sweep_rate(&s, 2);
    }
    double m1 = bench_median(r1, REPS), m2 = bench_median(r2, REPS);
    printf("runs per minute: 1 job %.1f, 2 jobs %.1f; parallel efficiency %.0f%%\n", m1, m2,
           100.0 * m2 / (2.0 * m1));
    double ratio[RATIO_REPS], whole[RATIO_REPS], alone[RATIO_REPS];
    for (int i = 0; i < RATIO_REPS; i++) {
        int id = i * s.n_domains + 1; /* replication i, the second domain size */
        double a[3], w[3];
        for (int k = 0; k < 3; k++) { /* alternated: noise hits both alike */
            a[k] = in_child(&s, id, 0);
            w[k] = in_child(&s, id, 1);
        }
        alone[i] = bench_median(a, 3);
        whole[i] = bench_median(w, 3);
        ratio[i] = whole[i] / alone[i];
        printf("  run %2d: whole %.3f s, SUMO alone %.3f s, ratio %.3f\n", id, whole[i],
               alone[i], ratio[i]);
    }
    printf("whole run / SUMO alone: median %.3f (whole %.3f s, SUMO %.3f s)\n",
           bench_median(ratio, RATIO_REPS), bench_median(whole, RATIO_REPS),
           bench_median(alone, RATIO_REPS));
    return 0;
}
