/* sweep_split.c - a study's splitting estimates (estimate:), after its runs:
 * one worker process per (cell, batch), the parent the one database writer
 * (sweep.h). */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/files.h"
#include "core/spawn.h"
#include "study/outcome.h"
#include "study/split_run.h"
#include "study/store.h"
#include "study/sweep.h"

void fw_split_cell_scenario(void *ctx, uint64_t draw, fw_scenario *out)
{
    const fw_split_cell *c = ctx;
    fw_study_run r = fw_study_run_drawn(c->s, c->cell, draw);
    fw_study_scenario(c->s, &r, out);
}

/* The seed of batch b: the same in every cell (common random numbers). */
static uint64_t batch_seed(const fw_study *s, int b)
{
    uint64_t x = (uint64_t)s->estimate.seed * 0x9e3779b97f4a7c15ull + (uint64_t)b + 1;
    return fw_splitmix64(&x);
}

/* The worker's part: one estimate into *m. */
static void estimate(const fw_sweep_def *def, const char *work, int cell, int batch,
                     fw_split_msg *m)
{
    const fw_study *s = def->study;
    double t0 = fw_sweep_now();
    char dir[1100];
    fw_error err = {0};
    fw_status st = fw_path(dir, sizeof dir, &err, "%s/split-%d-%d", work, cell, batch);
    if (!st && mkdir(dir, 0777) != 0 && errno != EEXIST)
        st = fw_fail(&err, FW_ERUN, "%s: %s", dir, strerror(errno));
    /* SUMO loaded once here and inherited by every trajectory's process
     * (loading costs a process 0.2 s of CPU); a failure is the runs' to say */
    fw_traffic_load(def->mode.kind, NULL);
    fw_split_cell cc = {s, cell};
    double q = fw_closeness(s->near_miss);
    fw_split_run_def sd = {.scenario = fw_split_cell_scenario, .ctx = &cc, .work_dir = dir,
                           .hidden_level = q > 0.0 && q < 1.0 ? q : 1.0};
    sd.run = fw_default_run_def();
    sd.run.mode = def->mode;
    fw_split_run *S = NULL;
    fw_ams_model model;
    if (!st)
        st = fw_split_run_create(&sd, &S, &model, &err);
    fw_ams_def ad = fw_default_ams_def();
    ad.particles = s->estimate.particles;
    ad.seed = batch_seed(s, batch);
    if (q > 0.0 && q < 1.0) {
        ad.n_levels = 1;
        ad.levels[0] = q;
    }
    fw_ams_result r = {0};
    if (!st)
        st = fw_ams_run(&ad, &model, &r, &err);
    m->ok = !st;
    if (st) {
        snprintf(m->reason, sizeof m->reason, "%s", err.msg);
    } else {
        m->rounds = r.rounds;
        m->runs = r.cost;
        m->sim_s = fw_split_run_sim_s(S);
        m->p_collision = r.p;
        m->p_near_miss = ad.n_levels ? r.p_level[0] : (q >= 1.0 ? r.p : 1.0);
        m->best = fw_split_run_best(S, m->path, sizeof m->path);
    }
    m->wall_s = fw_sweep_now() - t0;
    fw_split_run_destroy(S);
    fw_remove_tree(dir);
}

typedef struct worker {
    pid_t pid;
    int fd, job;
} worker;

static fw_status spawn(const fw_sweep_def *def, const char *work, int cell, int batch,
                       worker *w, fw_error *err)
{
    pid_t pid;
    int fd;
    fw_status st = fw_fork_piped(&pid, &fd, err);
    if (st)
        return st;
    if (pid == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        fw_store_child();
        fw_split_msg *m = calloc(1, sizeof *m);
        if (!m)
            _exit(5);
        estimate(def, work, cell, batch, m);
        _exit(fw_fd_write(fd, m, sizeof *m) == 0 ? 0 : 6);
    }
    w->pid = pid;
    w->fd = fd;
    return FW_OK;
}

/* A worker's message read and its end judged: a worker that died or sent
 * nothing leaves a failed estimate saying so. */
static void reap(int fd, int status, bool got, fw_split_msg *m)
{
    got = got && fw_fd_read(fd, m, sizeof *m) == 0;
    close(fd);
    if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        memset(m, 0, sizeof *m);
        snprintf(m->reason, sizeof m->reason, "the worker %s",
                 WIFSIGNALED(status) ? strsignal(WTERMSIG(status)) : "ended without its result");
    }
}

fw_status fw_sweep_split_commit(const fw_sweep_def *def, fw_store *st, int job,
                                const fw_split_msg *m, fw_sweep_result *res, fw_error *err)
{
    const fw_study *s = def->study;
    int batches = s->estimate.batches, cell = job / batches, batch = job % batches;
    fw_study_run c = fw_study_cell(s, cell);
    char setting[256];
    fw_split_row row = {.cell = cell, .batch = batch, .domain = c.domain, .ratio = c.ratio,
                        .density = c.density, .behaviour = fw_behaviour_name(c.behaviour),
                        .setting = fw_study_setting_label(s, c.setting_index, setting,
                                                          sizeof setting),
                        .particles = s->estimate.particles, .ok = m->ok, .reason = m->reason,
                        .rounds = m->rounds, .runs = m->runs, .sim_s = m->sim_s,
                        .wall_s = m->wall_s, .p_collision = m->p_collision,
                        .p_near_miss = m->p_near_miss, .best_closeness = m->best,
                        .best_path = m->path};
    fw_status r = fw_store_split(st, &row, err);
    FILE *out = def->progress_out ? def->progress_out : stderr;
    if (!r && def->progress != FW_PROGRESS_NONE) {
        if (m->ok)
            fprintf(out,
                    "splitting: cell %d (domain %g m, %s%s%s) batch %d: P(collision) %.3g, "
                    "P(near miss) %.3g, %.0f runs, %.0f s\n",
                    cell, c.domain, row.behaviour, setting[0] ? ", " : "", setting, batch,
                    m->p_collision, m->p_near_miss, m->runs, m->wall_s);
        else
            fprintf(out, "splitting: cell %d batch %d failed: %s\n", cell, batch, m->reason);
    }
    res->split_done += m->ok;
    res->split_failed += !m->ok;
    return r;
}

/* Reaps the worker that ended (pid) and commits its estimate. */
static fw_status collect(const fw_sweep_def *def, fw_store *st, worker *w, int status,
                         fw_sweep_result *res, fw_error *err)
{
    fw_split_msg *m = calloc(1, sizeof *m);
    if (!m)
        return fw_fail(err, FW_ERUN, "out of memory");
    reap(w->fd, status, true, m);
    w->pid = 0;
    fw_status r = fw_sweep_split_commit(def, st, w->job, m, res, err);
    free(m);
    return r;
}

void fw_sweep_split_one(const fw_sweep_def *def, const char *work, int job, fw_split_msg *m)
{
    int batches = def->study->estimate.batches;
    worker w = {0};
    fw_error err = {0};
    if (spawn(def, work, job / batches, job % batches, &w, &err)) {
        memset(m, 0, sizeof *m);
        snprintf(m->reason, sizeof m->reason, "%s", err.msg);
        m->job = job;
        return;
    }
    int status = 0;
    /* the message first (it fits the pipe's buffer), then the end */
    bool got = fw_fd_read(w.fd, m, sizeof *m) == 0;
    while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        reap(w.fd, status, false, m);
    else
        close(w.fd);
    m->job = job;
}

/* The pending jobs, batch-major (every cell's batch 0 first: a sweep cut
 * short holds paired sets), into *jobs. */
fw_status fw_sweep_split_pending(const fw_sweep_def *def, fw_store *st, int **jobs, int *n_jobs,
                                fw_error *err)
{
    const fw_study *s = def->study;
    int cells = fw_study_cell_count(s), batches = s->estimate.batches, n = cells * batches;
    bool *any = calloc((size_t)n, sizeof *any);
    *jobs = malloc((size_t)n * sizeof **jobs);
    fw_status r = !any || !*jobs ? fw_fail(err, FW_ERUN, "out of memory") : FW_OK;
    if (!r && def->retry_failed)
        r = fw_store_forget_failed_splits(st, err);
    if (!r)
        r = fw_store_splits_done(st, true, batches, any, n, err);
    *n_jobs = 0;
    for (int b = 0; !r && b < batches; b++)
        for (int c = 0; c < cells; c++)
            if (!any[c * batches + b])
                (*jobs)[(*n_jobs)++] = c * batches + b;
    free(any);
    return r;
}

fw_status fw_sweep_splits(const fw_sweep_def *def, fw_store *st, const char *work, int jobs,
                          fw_sweep_result *res, fw_error *err)
{
    int *todo = NULL, n_todo = 0;
    fw_status r = fw_sweep_split_pending(def, st, &todo, &n_todo, err);
    worker *w = calloc((size_t)jobs, sizeof *w);
    if (!r && !w)
        r = fw_fail(err, FW_ERUN, "out of memory");
    int next = 0, running = 0, batches = def->study->estimate.batches;
    while (!r && (next < n_todo || running > 0) && !fw_sweep_stopped()) {
        for (int i = 0; i < jobs && next < n_todo && !r; i++)
            if (w[i].pid <= 0) {
                w[i].job = todo[next];
                r = spawn(def, work, todo[next] / batches, todo[next] % batches, &w[i], err);
                next += !r;
                running += !r;
            }
        int status;
        pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno != EINTR)
                r = fw_fail(err, FW_ERUN, "waitpid: %s", strerror(errno));
            continue;
        }
        for (int i = 0; i < jobs; i++)
            if (w[i].pid == pid) {
                running--;
                r = collect(def, st, &w[i], status, res, err);
            }
    }
    for (int i = 0; w && i < jobs; i++) /* interrupted: the estimates in flight are lost */
        if (w[i].pid > 0) {
            kill(w[i].pid, SIGKILL);
            waitpid(w[i].pid, NULL, 0);
            close(w[i].fd);
        }
    if (fw_sweep_stopped())
        res->interrupted = true;
    free(w);
    free(todo);
    return r;
}
