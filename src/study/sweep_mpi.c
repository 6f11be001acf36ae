/* sweep_mpi.c - the sweep over MPI ranks (see sweep.h).
 *
 * Rank 0 opens the database, hands out one run id at a time and commits each
 * result as it arrives; ranks 1..K-1 run them (each in a forked child, as a
 * local sweep does, so a crashing run costs one run).  A study with
 * estimate: then has its pending splitting estimates (cell, batch) handed
 * out the same way, each made in a forked worker on its rank (sweep_split.c)
 * and committed by rank 0; a resumed sweep makes only the missing ones.
 * Messages: WORK carries a run id, or -2 - job for a splitting job (-1 =
 * stop), RESULT the outcome's bytes, SPLIT an fw_split_msg.  With one rank
 * the sweep is local.  Built only when CMake finds MPI (FAIRWAY_MPI).
 */
#include <stdlib.h>
#include <time.h>
#include <string.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "core/files.h"
#include "study/store.h"
#include "study/sweep.h"

#ifndef FAIRWAY_MPI

bool fw_sweep_under_mpi(void)
{
    return false;
}

fw_status fw_sweep_mpi(const fw_sweep_def *def, fw_sweep_result *res, bool *is_root,
                       fw_error *err)
{
    (void)def;
    (void)res;
    *is_root = true;
    return fw_fail(err, FW_EINPUT, "this fairway was built without MPI");
}

#else

#include <mpi.h>

enum { TAG_WORK = 1, TAG_RESULT = 2, TAG_SPLIT = 3 };

bool fw_sweep_under_mpi(void)
{
    /* set by Open MPI's and MPICH's launchers for every rank */
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK");
}

/* Waits for a message with tag from src (MPI_ANY_SOURCE) without spinning:
 * Open MPI's blocking MPI_Probe and MPI_Recv poll at full speed, so rank 0,
 * which only waits, burnt 87 % of a core (issue 15).  Polls with a sleep
 * that grows from 0.5 to 20 ms: a run's result is a second or more apart,
 * and 20 ms of latency is nothing against it. */
static void wait_message(int src, int tag, MPI_Status *stt)
{
    long ns = 500000L;
    for (;;) {
        int flag = 0;
        MPI_Iprobe(src, tag, MPI_COMM_WORLD, &flag, stt);
        if (flag)
            return;
        struct timespec d = {0, ns};
        nanosleep(&d, NULL);
        ns = ns * 2 > 20000000L ? 20000000L : ns * 2;
    }
}

static void send_run(int rank, int run_id)
{
    MPI_Send(&run_id, 1, MPI_INT, rank, TAG_WORK, MPI_COMM_WORLD);
}

/* Where the run's work directory was, from its reason (it names files in
 * TMPDIR/fairway-sweep-XXXXXX/, or in --keep's directory): for the message of
 * a full disk, which names it and leaves it out of the run's reason. */
static const char *reason_workdir(const fw_sweep_def *def, const char *reason, char *out,
                                  size_t n)
{
    if (def->keep_dir)
        return def->keep_dir;
    const char *m = strstr(reason, "/fairway-sweep-");
    if (!m)
        return NULL;
    const char *b = m;
    while (b > reason && b[-1] != ' ' && b[-1] != '(' && b[-1] != '\'')
        b--;
    const char *e = strchr(m + 1, '/');
    size_t len = e ? (size_t)(e - b) : strcspn(b, " );'");
    if (len + 1 > n)
        return NULL;
    memcpy(out, b, len);
    out[len] = '\0';
    return out;
}

/* Ranks 1..: run what rank 0 sends until it sends -1.  Without a work
 * directory (work "") every run is answered failed, saying why. */
static void worker(const fw_sweep_def *def, const char *work, const char *why)
{
    for (;;) {
        int run_id;
        MPI_Status stt;
        wait_message(0, TAG_WORK, &stt);
        MPI_Recv(&run_id, 1, MPI_INT, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (run_id == -1)
            return;
        if (run_id < -1) {
            fw_split_msg m;
            memset(&m, 0, sizeof m);
            m.job = -2 - run_id;
            if (!work[0])
                snprintf(m.reason, sizeof m.reason, "%s", why);
            else
                fw_sweep_split_one(def, work, -2 - run_id, &m);
            MPI_Send(&m, (int)sizeof m, MPI_BYTE, 0, TAG_SPLIT, MPI_COMM_WORLD);
            continue;
        }
        fw_child c;
        fw_outcome o;
        fw_error err = {0};
        if (!work[0]) {
            fw_outcome_failed(&o, run_id, why);
        } else if (fw_sweep_spawn(def->study, run_id, work, def->keep_dir != NULL, &def->mode,
                                  &c, &err)) {
            fw_outcome_failed(&o, run_id, err.msg);
        } else {
            while (!fw_sweep_read(&c))
                ;
            fw_sweep_collect(&c, &o);
        }
        unsigned char *buf = NULL;
        size_t n = 0;
        if (fw_outcome_pack(&o, &buf, &n, &err)) {
            fw_outcome_free(&o);
            fw_outcome_failed(&o, run_id, err.msg);
            fw_outcome_pack(&o, &buf, &n, NULL);
        }
        MPI_Send(buf, (int)n, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD);
        free(buf);
        fw_outcome_free(&o);
    }
}

/* Runs queued at each worker: the one it runs and the next, so that it
 * starts that one as soon as it has sent a result, without waiting for rank
 * 0 to notice the result (rank 0 sleeps up to 20 ms between looks, and
 * commits first).  Measured on the default study (80 runs of about 0.5 s,
 * 2 cores shared with other work, 3 interleaved pairs of -np 3 against
 * --jobs 2, wall): 0.80 (0.48-0.91) of --jobs 2's throughput with one run
 * queued, 0.86 (0.82-1.06) with two; the load made both noisy.  Idle
 * machine, two queued: 0.94 (0.83-1.04). */
enum { QUEUE_DEPTH = 2 };

/* Rank 0's work list: the pending runs (ids >= 0), then the pending
 * splitting jobs (-2 - job). */
typedef struct work_list {
    const int *items;
    int n, n_runs, next;
} work_list;

/* Hands rank its next item, if any and if it may queue one: a splitting job
 * (minutes) is never queued behind another item, so that a rank that falls
 * idle takes it. */
static bool hand_out(work_list *wl, int rank, int *queued, int *busy)
{
    if (wl->next >= wl->n || (wl->next >= wl->n_runs && queued[rank] > 0))
        return false;
    send_run(rank, wl->items[wl->next++]);
    queued[rank]++;
    (*busy)++;
    return true;
}

/* A result from a rank (tag RESULT or SPLIT) committed; once the sweep has
 * stopped (stopped: an error), received and dropped, as the local sweep
 * drops the runs it kills: the message's count of runs not recorded holds,
 * and a resume runs them. */
static fw_status take_result(const fw_sweep_def *def, fw_store *st, const MPI_Status *stt,
                             int left, bool stopped, fw_progress *prog, fw_sweep_result *res,
                             fw_error *err)
{
    int n = 0;
    MPI_Get_count(stt, MPI_BYTE, &n);
    unsigned char *buf = malloc(n > 0 ? (size_t)n : 1);
    if (!buf)
        MPI_Abort(MPI_COMM_WORLD, 1);
    MPI_Recv(buf, n, MPI_BYTE, stt->MPI_SOURCE, stt->MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (stopped) {
        free(buf);
        return FW_OK;
    }
    if (stt->MPI_TAG == TAG_SPLIT) {
        fw_split_msg m;
        bool whole = n == (int)sizeof m;
        if (whole)
            memcpy(&m, buf, sizeof m);
        free(buf);
        if (!whole)
            return fw_fail(err, FW_ERUN, "rank %d: a splitting result of %d bytes",
                           stt->MPI_SOURCE, n);
        return fw_sweep_split_commit(def, st, m.job, &m, res, err);
    }
    fw_outcome o;
    fw_error uerr = {0};
    bool unpacked = fw_outcome_unpack(buf, (size_t)n, &o, &uerr) == FW_OK;
    free(buf);
    if (!unpacked)
        return fw_fail(err, FW_ERUN, "rank %d: %s", stt->MPI_SOURCE, uerr.msg);
    /* a rank's disk full: stop, that run not recorded (its work directory is
     * on the rank's host: the reason tells, sweep_child.c) */
    char wd[1024];
    fw_status r = fw_sweep_disk_full(def->study, &o, reason_workdir(def, o.reason, wd, sizeof wd),
                                     left, err)
                      ? FW_ERUN
                      : fw_store_commit(st, def->study, &o, err);
    if (!r)
        fw_progress_count(prog, def->study, &o, res);
    fw_outcome_free(&o);
    return r;
}

/* Rank 0: hand out the pending runs, then the splitting jobs; commit what
 * comes back. */
static fw_status root(const fw_sweep_def *def, fw_store *st, work_list *wl, int size,
                      fw_sweep_result *res, fw_error *err)
{
    int busy = 0, runs_out = wl->n_runs;
    int *queued = calloc((size_t)size, sizeof *queued);
    if (!queued)
        MPI_Abort(MPI_COMM_WORLD, 1);
    fw_status r = FW_OK;
    fw_progress *prog = fw_progress_start(def, wl->n_runs, res->total, res->skipped);
    /* one item to each rank, then the second: the first runs spread first */
    for (int k = 0; k < QUEUE_DEPTH; k++)
        for (int rank = 1; rank < size; rank++)
            hand_out(wl, rank, queued, &busy);
    for (int rank = 1; rank < size; rank++)
        if (!queued[rank])
            send_run(rank, -1);
    while (busy > 0) {
        MPI_Status stt;
        wait_message(MPI_ANY_SOURCE, MPI_ANY_TAG, &stt);
        if (stt.MPI_TAG != TAG_RESULT && stt.MPI_TAG != TAG_SPLIT)
            MPI_Abort(MPI_COMM_WORLD, 1);
        int rank = stt.MPI_SOURCE;
        busy--;
        queued[rank]--;
        runs_out -= stt.MPI_TAG == TAG_RESULT;
        fw_status tr = take_result(def, st, &stt, runs_out, r != FW_OK, prog, res, err);
        if (!r)
            r = tr;
        if (runs_out == 0 && prog) { /* the runs are all in: their last line */
            fw_progress_end(prog, res->done, res->failed);
            prog = NULL;
        }
        /* after an error, no new work: every rank is told to stop once its
         * queue is done */
        if ((r || !hand_out(wl, rank, queued, &busy)) && !queued[rank])
            send_run(rank, -1);
    }
    if (prog)
        fw_progress_end(prog, res->done, res->failed);
    free(queued);
    return r;
}

/* The pending splitting jobs appended to the work list (as -2 - job). */
static fw_status split_jobs(const fw_sweep_def *def, fw_store *st, int **items, work_list *wl,
                            fw_error *err)
{
    int *jobs = NULL, n = 0;
    fw_status r = fw_sweep_split_pending(def, st, &jobs, &n, err);
    int *all = r ? NULL : realloc(*items, sizeof *all * (size_t)(wl->n_runs + n + 1));
    if (!r && !all)
        r = fw_fail(err, FW_ERUN, "out of memory");
    if (!r) {
        for (int i = 0; i < n; i++)
            all[wl->n_runs + i] = -2 - jobs[i];
        *items = all;
        wl->items = all;
        wl->n = wl->n_runs + n;
    }
    free(jobs);
    return r;
}

/* Bytes free on dir's disk; -1 when it cannot be told. */
static double disk_free(const char *dir)
{
    struct statvfs vf;
    return statvfs(dir, &vf) == 0 ? (double)vf.f_bavail * (double)vf.f_frsize : -1.0;
}

/* Before MPI_Init: Open MPI keeps its session files in TMPDIR (or
 * OMPI_MCA_orte_tmpdir_base), where the ranks' work directories go too.
 * With too little room there every rank's MPI_Init fails and mpirun then
 * waits for ever (Open MPI 4.1.4, -np 3, a tmpfs as TMPDIR: 8 MB free fails,
 * 12 MB runs); a rank that stops before MPI_Init lets mpirun end at once.
 * So: under Open MPI less than 16 MB in its session directory, or less than
 * 64 kB where the work directories go, stops every rank before MPI_Init.
 * Rank 0 (told by the launcher's environment) says why; another rank waits
 * a second, then says it too (*is_root set: it reports): mpirun ends the job
 * when the first rank exits, which would otherwise often be a silent one,
 * and rank 0, on another host, may not have seen it. */
static fw_status disk_check(const fw_sweep_def *def, fw_error *err)
{
    const char *base = getenv("OMPI_MCA_orte_tmpdir_base");
    const char *tmp = getenv("TMPDIR");
    const char *work = def->keep_dir ? def->keep_dir : tmp && tmp[0] ? tmp : "/tmp";
    if (getenv("OMPI_COMM_WORLD_SIZE")) {
        const char *sess = base && base[0] ? base : tmp && tmp[0] ? tmp : "/tmp";
        double f = disk_free(sess);
        if (f >= 0 && f < 16e6)
            return fw_fail(err, FW_ERUN, "the disk of %s has too little room (%.0f kB left): "
                           "Open MPI keeps its session files there and needs about 10 MB; "
                           "nothing was run: free space (or set TMPDIR, or "
                           "OMPI_MCA_orte_tmpdir_base, to a larger disk), then run the same "
                           "command again", sess, f / 1024.0);
    }
    if (fw_sweep_disk_low(work))
        return fw_fail(err, FW_ERUN, "the disk of the sweep's work directory in %s is full "
                       "(less than 64 kB left); nothing was run: free space (or set TMPDIR, or "
                       "--keep, to a larger disk), then run the same command again", work);
    return FW_OK;
}

static fw_status session_disk(const fw_sweep_def *def, bool *is_root, fw_error *err)
{
    const char *rank = getenv("OMPI_COMM_WORLD_RANK");
    if (!rank)
        rank = getenv("PMIX_RANK");
    if (!rank)
        rank = getenv("PMI_RANK");
    *is_root = true;
    if (!disk_check(def, err))
        return FW_OK;
    if (rank && strcmp(rank, "0") != 0) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        snprintf(err->msg, sizeof err->msg, "rank %.8s: %.*s", rank, (int)sizeof err->msg - 20, msg);
        sleep(1);
    }
    return err->status;
}

fw_status fw_sweep_mpi(const fw_sweep_def *def, fw_sweep_result *res, bool *is_root,
                       fw_error *err)
{
    memset(res, 0, sizeof *res);
    if (session_disk(def, is_root, err))
        return err->status;
    int argc = 0;
    char **argv = NULL;
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    *is_root = rank == 0;
    memset(res, 0, sizeof *res);
    fw_status r = FW_OK;
    if (size == 1) {
        r = fw_sweep_local(def, res, err);
        MPI_Finalize();
        return r;
    }
    double t0 = fw_sweep_now();
    fw_store *st = NULL;
    int *pending = NULL, n_pending = 0;
    work_list wl = {0};
    char work[1024] = "";
    if (rank == 0) {
        int total = fw_study_run_count(def->study);
        bool *any = calloc((size_t)total, sizeof *any), *ok = calloc((size_t)total, sizeof *ok);
        pending = malloc(sizeof *pending * (size_t)total);
        if (!any || !ok || !pending)
            r = fw_fail(err, FW_ERUN, "out of memory");
        if (!r)
            r = fw_store_open(def->db, def->study, &st, err);
        if (!r && def->retry_failed)
            r = fw_store_forget_failed(st, err);
        if (!r && !(r = fw_store_finished(st, true, any, total, err)))
            r = fw_store_finished(st, false, ok, total, err);
        res->total = total;
        for (int i = 0; !r && i < total; i++) {
            if (any[i]) {
                res->skipped++;
                res->failed_before += !ok[i];
            } else if (def->limit <= 0 || n_pending < def->limit) {
                pending[n_pending++] = i;
            }
        }
        free(any);
        free(ok);
        wl = (work_list){.items = pending, .n = n_pending, .n_runs = n_pending};
        if (!r && def->study->estimate.on)
            r = split_jobs(def, st, &pending, &wl, err);
    }
    /* every rank learns whether rank 0 could start */
    int go = r == FW_OK;
    MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (go && rank != 0 && (r = fw_sweep_workdir(def, work, sizeof work, err)))
        work[0] = '\0';
    if (go) {
        if (rank == 0)
            r = root(def, st, &wl, size, res, err);
        else
            worker(def, work, err ? err->msg : "no work directory");
    }
    if (rank != 0 && work[0] && !def->keep_dir)
        fw_remove_tree(work);
    fw_store_close(st);
    free(pending);
    res->wall_s = fw_sweep_now() - t0;
    MPI_Finalize();
    return rank == 0 ? r : FW_OK;
}

#endif
