/* sweep.c - the local sweep: worker processes and the one database writer. */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "core/files.h"
#include "study/store.h"
#include "study/sweep.h"
#include "traffic/traffic.h"

fw_sweep_def fw_default_sweep_def(void)
{
    fw_sweep_def d = {0};
    d.mode.kind = FW_TRAFFIC_EMBEDDED;
    d.progress = FW_PROGRESS_AUTO;
    return d;
}

static volatile sig_atomic_t g_stop;

static void on_signal(int sig)
{
    g_stop = sig;
}

bool fw_sweep_stopped(void) { return g_stop != 0; }

typedef struct sig_guard {
    struct sigaction old_int, old_term;
} sig_guard;

static void guard_signals(sig_guard *g)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal; /* no SA_RESTART: poll returns at once */
    sigemptyset(&sa.sa_mask);
    g_stop = 0;
    sigaction(SIGINT, &sa, &g->old_int);
    sigaction(SIGTERM, &sa, &g->old_term);
}

static void release_signals(sig_guard *g)
{
    sigaction(SIGINT, &g->old_int, NULL);
    sigaction(SIGTERM, &g->old_term, NULL);
}

static int default_jobs(int jobs)
{
    if (jobs > 0)
        return jobs;
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

/* The pending run ids, ascending; *n_pending and counts filled. */
static fw_status pending_runs(fw_store *st, const fw_sweep_def *def, fw_sweep_result *res,
                              int **pending, int *n_pending, fw_error *err)
{
    int total = fw_study_run_count(def->study);
    bool *done = calloc((size_t)total, sizeof *done), *any = calloc((size_t)total, sizeof *any);
    *pending = malloc(sizeof **pending * (size_t)total);
    if (!done || !any || !*pending) {
        free(done);
        free(any);
        free(*pending);
        *pending = NULL;
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    fw_status r;
    if (def->retry_failed && (r = fw_store_forget_failed(st, err)))
        goto out;
    if ((r = fw_store_finished(st, false, done, total, err)) ||
        (r = fw_store_finished(st, true, any, total, err)))
        goto out;
    res->total = total;
    *n_pending = 0;
    for (int i = 0; i < total; i++) {
        if (any[i]) {
            res->skipped++;
            res->failed_before += !done[i];
        } else if (def->limit <= 0 || *n_pending < def->limit) {
            (*pending)[(*n_pending)++] = i;
        }
    }
out:
    free(done);
    free(any);
    return r;
}

/* The work directory, refused (and removed) when SUMO would split its path. */
static fw_status work_dir(const fw_sweep_def *def, char *work, size_t n, fw_error *err)
{
    fw_status r = fw_sweep_workdir(def, work, n, err);
    if (!r && (r = fw_sumo_path_check("the work directory (TMPDIR)", work, err)) &&
        !def->keep_dir)
        fw_remove_tree(work);
    return r;
}

/* A run that failed because the work directory's disk is full (it says "No
 * space left on device" or "Disk quota exceeded", or too little is left
 * there): every run after it would fail the same way, so the sweep stops
 * with this message and the run is not recorded (a resume runs it). */
bool fw_sweep_disk_low(const char *work)
{
    struct statvfs vf;
    return work && statvfs(work, &vf) == 0 && (double)vf.f_bavail * (double)vf.f_frsize < 65536.0;
}

bool fw_sweep_disk_full(const fw_study *s, const fw_outcome *o, const char *work, int left,
                        fw_error *err)
{
    if (strcmp(o->status, "ok") == 0)
        return false;
    if (!fw_sweep_disk_low(work) && !strstr(o->reason, strerror(ENOSPC)) &&
        !strstr(o->reason, strerror(EDQUOT)))
        return false;
    /* the reason without the work directory, which is removed as the sweep ends */
    char why[512] = "";
    size_t wl = work ? strlen(work) : 0, k = 0;
    for (const char *p = o->reason; *p && k + 1 < sizeof why; p++) {
        if (wl && strncmp(p, work, wl) == 0 && p[wl] == '/')
            p += wl + 1;
        why[k++] = *p;
    }
    why[k] = '\0';
    /* where: --keep's directory, or the temporary one's parent (TMPDIR) */
    const char *slash = work ? strrchr(work, '/') : NULL;
    int n = slash && strncmp(slash + 1, "fairway-sweep-", 14) == 0 ? (int)(slash - work)
                                                                  : (int)wl;
    fw_fail(err, FW_ERUN,
            "the disk of the sweep's work directory%s%.*s is full: run %s-%06d failed (%.200s); "
            "the sweep stopped there, that run and %d more are not recorded: free space (or "
            "set TMPDIR, or --keep, to a larger disk), then run the same command again to "
            "resume", work ? " in " : "", n > 300 ? 300 : n, work ? work : "", s->name,
            o->run_id, why, left);
    return true;
}

/* Where the runs go, checked before the database is made: every run would
 * fail on a comma in it in SUMO; with --keep DIR each run replaces DIR/NAME
 * whole, so a directory of the user's there (not a run directory of
 * fairway's: the sweep deleted it) or a symlink is refused before any run. */
static fw_status paths_check(const fw_sweep_def *def, fw_error *err)
{
    if (!def->keep_dir)
        return fw_sumo_path_check("the work directory (TMPDIR)", getenv("TMPDIR"), err);
    fw_status r = fw_sumo_path_check("--keep", def->keep_dir, err);
    char dir[1200];
    for (int i = 0, n = fw_study_run_count(def->study); i < n && !r; i++)
        if (!(r = fw_path(dir, sizeof dir, err, "%s/%.40s-%06d", def->keep_dir, def->study->name,
                          i)))
            r = fw_check_run_dir("--keep", dir, err);
    return r;
}

fw_status fw_sweep_local(const fw_sweep_def *def, fw_sweep_result *res, fw_error *err)
{
    memset(res, 0, sizeof *res);
    double t0 = fw_sweep_now();
    const fw_study *s = def->study;
    fw_store *st = NULL;
    fw_status r = paths_check(def, err);
    if (r || (r = fw_store_open(def->db, s, &st, err)))
        return r;
    int *pending = NULL, n_pending = 0;
    if ((r = pending_runs(st, def, res, &pending, &n_pending, err))) {
        fw_store_close(st);
        return r;
    }
    char work[1024];
    if ((r = work_dir(def, work, sizeof work, err))) {
        free(pending);
        fw_store_close(st);
        return r;
    }
    int jobs = default_jobs(def->jobs);
    if (jobs > n_pending)
        jobs = n_pending > 0 ? n_pending : 1;
    fw_child *kids = calloc((size_t)jobs, sizeof *kids);
    struct pollfd *pfd = calloc((size_t)jobs, sizeof *pfd);
    if (!kids || !pfd) {
        r = fw_fail(err, FW_ERUN, "out of memory");
        goto out;
    }
    for (int i = 0; i < jobs; i++)
        kids[i].pid = kids[i].fd = -1;
    sig_guard guard;
    guard_signals(&guard);
    fw_progress *prog = fw_progress_start(def, n_pending, res->total, res->skipped);
    int next = 0, running = 0;
    while ((next < n_pending || running > 0) && !g_stop && !r) {
        for (int i = 0; i < jobs && next < n_pending && !g_stop; i++) {
            if (kids[i].pid > 0)
                continue;
            if ((r = fw_sweep_spawn(s, pending[next], work, def->keep_dir != NULL, &def->mode,
                                    &kids[i], err)))
                break;
            fcntl(kids[i].fd, F_SETFL, O_NONBLOCK);
            next++;
            running++;
        }
        if (r)
            break;
        int m = 0;
        for (int i = 0; i < jobs; i++)
            pfd[i] = (struct pollfd){.fd = kids[i].pid > 0 ? kids[i].fd : -1, .events = POLLIN};
        int k = poll(pfd, (nfds_t)jobs, 1000);
        if (k < 0 && errno != EINTR) {
            r = fw_fail(err, FW_ERUN, "poll: %s", strerror(errno));
            break;
        }
        for (int i = 0; i < jobs && k > 0; i++) {
            if (kids[i].pid <= 0 || !(pfd[i].revents & (POLLIN | POLLHUP | POLLERR)))
                continue;
            if (!fw_sweep_read(&kids[i]))
                continue;
            fw_outcome o;
            fw_sweep_collect(&kids[i], &o);
            running--;
            m++;
            if (fw_sweep_disk_full(s, &o, work, n_pending - res->done - res->failed - 1, err)) {
                r = FW_ERUN;
                fw_outcome_free(&o);
                break;
            }
            /* the one writer: a run is wholly in the database or not at all */
            if ((r = fw_store_commit(st, s, &o, err))) {
                fw_outcome_free(&o);
                break;
            }
            fw_progress_count(prog, s, &o, res);
            fw_outcome_free(&o);
        }
        if (!m)
            fw_progress_tick(prog, res->done, res->failed, running);
    }
    if (g_stop || r) {
        res->interrupted = g_stop != 0;
        for (int i = 0; i < jobs; i++)
            fw_sweep_kill(&kids[i]);
    }
    fw_progress_end(prog, res->done, res->failed);
    if (!r && !g_stop && s->estimate.on)
        r = fw_sweep_splits(def, st, work, default_jobs(def->jobs), res, err);
    release_signals(&guard);
out:
    free(kids);
    free(pfd);
    free(pending);
    fw_store_close(st);
    if (!def->keep_dir)
        fw_remove_tree(work);
    res->wall_s = fw_sweep_now() - t0;
    return r;
}
