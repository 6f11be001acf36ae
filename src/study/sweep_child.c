/* sweep_child.c - one study run in a child process (see sweep.h). */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/files.h"
#include "core/leftover.h"
#include "study/store.h"
#include "study/sweep.h"

double fw_sweep_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

fw_status fw_sweep_workdir(const fw_sweep_def *def, char *out, size_t outsz, fw_error *err)
{
    if (def->keep_dir) {
        /* a file or an unwritable directory would fail every run: refuse now */
        fw_status r = fw_mkdirs(def->keep_dir, "--keep", err);
        if (r)
            return r;
        if (access(def->keep_dir, W_OK | X_OK) != 0)
            return fw_fail(err, FW_EINPUT, "--keep %s: cannot write in it: %s", def->keep_dir,
                           strerror(errno));
        if ((size_t)snprintf(out, outsz, "%s", def->keep_dir) >= outsz)
            return fw_fail(err, FW_EINPUT, "--keep %s: path too long", def->keep_dir);
        return FW_OK;
    }
    const char *tmp = getenv("TMPDIR");
    const char *parent = tmp && tmp[0] ? tmp : "/tmp";
    if ((size_t)snprintf(out, outsz, "%s/fairway-sweep-XXXXXX", parent) >= outsz)
        return fw_fail(err, FW_EINPUT, "TMPDIR %s: path too long", tmp);
    /* what a SIGKILLed sweep before left there (leftover.h) */
    fw_leftover_clean(parent, "fairway-sweep-", "an interrupted sweep");
    if (!mkdtemp(out))
        return fw_fail(err, FW_ERUN, "cannot create a work directory %s: %s", out,
                       strerror(errno));
    return fw_leftover_mark(out, err);
}

static bool summary_finite(const fw_run_summary *s)
{
    return isfinite(s->path_length) && isfinite(s->along_track) && isfinite(s->time_lost) &&
           isfinite(s->rudder_work) && isfinite(s->heading_error) && !isnan(s->min_dist);
}

/* A run that failed with its work directory's disk (almost) full but a
 * reason that does not say so (a program that words it its own way): the
 * reason gets the words a sweep stops on (fw_sweep_disk_full), looked at
 * here, before the run directory is removed and frees what it took, and on
 * the run's own host (under mpirun rank 0 may be elsewhere). */
static void say_disk_full(fw_outcome *o, const char *work)
{
    const char *full = strerror(ENOSPC);
    if (strcmp(o->status, "ok") == 0 || strstr(o->reason, full) ||
        strstr(o->reason, strerror(EDQUOT)) || !fw_sweep_disk_low(work))
        return;
    size_t n = strlen(o->reason), room = sizeof o->reason - strlen(full) - 3;
    snprintf(o->reason + (n < room ? n : room), sizeof o->reason - (n < room ? n : room), "; %s",
             full);
}

void fw_sweep_exec(const fw_study *s, int run_id, const char *work_dir, bool keep,
                   const fw_traffic_mode *mode, fw_outcome *out)
{
    fw_scenario *scn = malloc(sizeof *scn);
    if (!scn) {
        fw_outcome_failed(out, run_id, "out of memory");
        return;
    }
    fw_study_run r = fw_study_run_at(s, run_id);
    fw_study_scenario(s, &r, scn);
    char dir[1200];
    if ((size_t)snprintf(dir, sizeof dir, "%s/%s", work_dir, scn->name) >= sizeof dir) {
        free(scn);
        fw_outcome_failed(out, run_id, "run directory path too long");
        return;
    }
    fw_remove_tree(dir); /* left by an interrupted sweep with --keep */
    fw_error err = {0};
    if (mkdir(dir, 0777) != 0) {
        char why[300];
        snprintf(why, sizeof why, "cannot create the run directory: %s", strerror(errno));
        fw_outcome_failed(out, run_id, why);
        say_disk_full(out, work_dir);
        free(scn);
        return;
    }
    fw_run_def d = fw_default_run_def();
    d.scenario = scn;
    d.dir = dir;
    d.mode = *mode;
    fw_run_summary sum;
    fw_encounter *e = NULL;
    fw_survey_record *sv = NULL;
    int n = 0, n_sv = 0;
    d.survey_out = &sv;
    d.n_survey_out = &n_sv;
    fw_status st = fw_run_scenario(&d, &sum, &e, &n, &err);
    if (st)
        fw_outcome_failed(out, run_id, err.msg);
    else if (!summary_finite(&sum))
        fw_outcome_failed(out, run_id, "the run produced a NaN or infinite measure");
    else if ((st = fw_outcome_from_run(out, s, run_id, &sum, e, n, sv, n_sv, &err)))
        fw_outcome_failed(out, run_id, err.msg);
    free(e);
    free(sv);
    free(scn);
    say_disk_full(out, work_dir);
    if (!keep)
        fw_remove_tree(dir);
}

static void write_all(int fd, const unsigned char *p, size_t n)
{
    while (n > 0) {
        ssize_t k = write(fd, p, n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            _exit(3);
        p += k;
        n -= (size_t)k;
    }
}

fw_status fw_sweep_spawn(const fw_study *s, int run_id, const char *work_dir, bool keep,
                         const fw_traffic_mode *mode, fw_child *c, fw_error *err)
{
    memset(c, 0, sizeof *c);
    c->run_id = run_id;
    c->pid = -1;
    c->fd = -1;
    int fds[2];
    if (pipe(fds) != 0)
        return fw_fail(err, FW_ERUN, "pipe: %s", strerror(errno));
    pid_t parent = getpid();
    /* SUMO loaded once, here, and inherited by every run's process (a
     * process loading it pays 0.2 s of CPU); a failure to load it is the
     * run's to report, so it is not one here */
    fw_traffic_load(mode->kind, NULL);
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return fw_fail(err, FW_ERUN, "fork: %s", strerror(errno));
    }
    if (pid == 0) {
        /* the child: dies with its parent, so a killed sweep leaves no orphans */
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
            _exit(4);
        fw_store_child(); /* a dying child must not keep the database locked */
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        signal(SIGPIPE, SIG_DFL);
        close(fds[0]);
        /* SUMO and libraries may print; the result goes through the pipe only */
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            close(null);
        }
        fw_outcome o;
        fw_sweep_exec(s, run_id, work_dir, keep, mode, &o);
        unsigned char *buf = NULL;
        size_t n = 0;
        if (fw_outcome_pack(&o, &buf, &n, NULL))
            _exit(5);
        write_all(fds[1], buf, n);
        _exit(0); /* no atexit handlers: they belong to the parent */
    }
    close(fds[1]);
    c->pid = pid;
    c->fd = fds[0];
    c->t0 = fw_sweep_now();
    return FW_OK;
}

bool fw_sweep_read(fw_child *c)
{
    for (;;) {
        if (c->cap - c->n < 65536) {
            size_t cap = c->cap ? c->cap * 2 : 131072;
            unsigned char *b = realloc(c->buf, cap);
            if (!b)
                return true; /* collect reports the truncated result */
            c->buf = b;
            c->cap = cap;
        }
        ssize_t k = read(c->fd, c->buf + c->n, c->cap - c->n);
        if (k > 0) {
            c->n += (size_t)k;
            continue;
        }
        if (k < 0 && errno == EINTR)
            continue;
        if (k < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            return false;
        return true; /* EOF or error */
    }
}

void fw_sweep_collect(fw_child *c, fw_outcome *out)
{
    int status = 0;
    close(c->fd);
    c->fd = -1;
    while (waitpid(c->pid, &status, 0) < 0 && errno == EINTR)
        ;
    fw_error err = {0};
    char why[256];
    if (WIFSIGNALED(status)) {
        snprintf(why, sizeof why, "the run's process died of signal %d (%s)", WTERMSIG(status),
                 strsignal(WTERMSIG(status)));
        fw_outcome_failed(out, c->run_id, why);
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(why, sizeof why, "the run's process exited with code %d",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        fw_outcome_failed(out, c->run_id, why);
    } else if (fw_outcome_unpack(c->buf, c->n, out, &err)) {
        fw_outcome_failed(out, c->run_id, err.msg);
    } else if (out->run_id != c->run_id) {
        fw_outcome_free(out);
        fw_outcome_failed(out, c->run_id, "the run's process answered for another run");
    }
    free(c->buf);
    c->buf = NULL;
    c->pid = -1;
}

void fw_sweep_kill(fw_child *c)
{
    if (c->pid > 0) {
        kill(c->pid, SIGKILL);
        while (waitpid(c->pid, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    if (c->fd >= 0)
        close(c->fd);
    free(c->buf);
    memset(c, 0, sizeof *c);
    c->pid = c->fd = -1;
}
