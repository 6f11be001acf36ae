/* branch.c - snapshot and restore of a running run by fork (branch.h). */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "run/branch.h"

#include "core/spawn.h"

/* A file of the run directory open for writing at the snapshot. */
typedef struct snap_open {
    int fd, flags; /* descriptor and its open flags (fcntl F_GETFL) */
    off_t off;     /* its offset then */
    char *path;
} snap_open;

/* A page shared by the owner, the paused copy and its branches: the last
 * restored branch's result.  One branch runs at a time (restore waits), so
 * no lock. */
typedef struct result_box {
    uint32_t n;
    _Alignas(max_align_t) unsigned char data[FW_BRANCH_RESULT_MAX]; /* any type reads it */
} result_box;

struct fw_snapshot {
    result_box *box;  /* MAP_SHARED */
    pid_t pid;        /* the paused copy */
    pid_t owner;      /* the process that took the snapshot */
    int cmd, reply;   /* to the copy: branch numbers; from it: exit codes */
    char dir[PATH_MAX]; /* the run directory, resolved */
    snap_open *open;
    int n_open;
    char **files;     /* every file under dir then, sorted */
    int n_files, cap_files;
    double t;
    long step;
};

/* ---- the run directory: its files, and the descriptors open on them ---- */

static int by_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static fw_status push_file(fw_snapshot *s, const char *path, fw_error *err)
{
    if (s->n_files == s->cap_files) {
        int cap = s->cap_files ? 2 * s->cap_files : 16;
        char **v = realloc(s->files, sizeof *v * (size_t)cap);
        if (!v)
            return fw_fail(err, FW_ERUN, "out of memory for a snapshot's file list");
        s->files = v;
        s->cap_files = cap;
    }
    if (!(s->files[s->n_files] = strdup(path)))
        return fw_fail(err, FW_ERUN, "out of memory for a snapshot's file list");
    s->n_files++;
    return FW_OK;
}

/* Calls fn(path, ctx) for every regular file under dir, depth first. */
typedef fw_status (*file_fn)(const char *path, void *ctx, fw_error *err);

static fw_status walk(const char *dir, file_fn fn, void *ctx, fw_error *err)
{
    DIR *d = opendir(dir);
    if (!d)
        return fw_fail(err, FW_ERUN, "cannot read the run directory %s: %s", dir,
                       strerror(errno));
    fw_status st = FW_OK;
    struct dirent *e;
    while (!st && (e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        char path[PATH_MAX];
        struct stat sb;
        if (snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= (int)sizeof path)
            st = fw_fail(err, FW_ERUN, "path too long under %s", dir);
        else if (lstat(path, &sb) != 0)
            continue; /* gone meanwhile */
        else if (S_ISDIR(sb.st_mode))
            st = walk(path, fn, ctx, err);
        else if (S_ISREG(sb.st_mode))
            st = fn(path, ctx, err);
    }
    closedir(d);
    return st;
}

static fw_status note_file(const char *path, void *ctx, fw_error *err)
{
    return push_file(ctx, path, err);
}

/* A file made after the snapshot goes. */
static fw_status drop_new_file(const char *path, void *ctx, fw_error *err)
{
    const fw_snapshot *s = ctx;
    if (!bsearch(&path, s->files, (size_t)s->n_files, sizeof *s->files, by_str) &&
        unlink(path) != 0)
        return fw_fail(err, FW_ERUN, "cannot remove %s: %s", path, strerror(errno));
    return FW_OK;
}

/* Calls fn(fd, path, ctx) for each descriptor of this process open for
 * writing on a regular file under dir. */
typedef fw_status (*fd_fn)(int fd, const char *path, void *ctx, fw_error *err);

static fw_status each_written_fd(const char *dir, fd_fn fn, void *ctx, fw_error *err)
{
    DIR *d = opendir("/proc/self/fd");
    if (!d)
        return fw_fail(err, FW_ERUN, "cannot list /proc/self/fd: %s", strerror(errno));
    size_t len = strlen(dir);
    int self = dirfd(d);
    fw_status st = FW_OK;
    struct dirent *e;
    while (!st && (e = readdir(d))) {
        char *end;
        long fd = strtol(e->d_name, &end, 10);
        if (*end || end == e->d_name || fd == self)
            continue;
        char link[64], path[PATH_MAX];
        snprintf(link, sizeof link, "/proc/self/fd/%ld", fd);
        ssize_t n = readlink(link, path, sizeof path - 1);
        if (n <= 0)
            continue;
        path[n] = '\0';
        int fl = fcntl((int)fd, F_GETFL);
        struct stat sb;
        if (strncmp(path, dir, len) != 0 || path[len] != '/' || fl < 0 ||
            (fl & O_ACCMODE) == O_RDONLY || fstat((int)fd, &sb) != 0 || !S_ISREG(sb.st_mode))
            continue;
        st = fn((int)fd, path, ctx, err);
    }
    closedir(d);
    return st;
}

static fw_status note_fd(int fd, const char *path, void *ctx, fw_error *err)
{
    fw_snapshot *s = ctx;
    snap_open *v = realloc(s->open, sizeof *v * (size_t)(s->n_open + 1));
    if (!v)
        return fw_fail(err, FW_ERUN, "out of memory for a snapshot's file list");
    s->open = v;
    snap_open *o = &v[s->n_open];
    *o = (snap_open){.fd = fd, .flags = fcntl(fd, F_GETFL), .off = lseek(fd, 0, SEEK_CUR),
                     .path = strdup(path)};
    if (!o->path || o->off < 0)
        return fw_fail(err, FW_ERUN, "cannot note %s in a snapshot", path);
    s->n_open++;
    return FW_OK;
}

/* The first n bytes of the file descriptor `from` holds (open for writing
 * only, perhaps no longer named) into to. */
static int copy_prefix(int from_fd, int to, off_t n)
{
    char buf[65536], proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", from_fd);
    int from = open(proc, O_RDONLY);
    if (from < 0)
        return -1;
    for (off_t at = 0; at < n;) {
        size_t want = n - at < (off_t)sizeof buf ? (size_t)(n - at) : sizeof buf;
        ssize_t k = pread(from, buf, want, at);
        if (k <= 0 || pwrite(to, buf, (size_t)k, at) != k) {
            close(from);
            return -1;
        }
        at += k;
    }
    close(from);
    return 0;
}

/* One file that was open at the snapshot, as it was then, cut back to cut
 * bytes, written on from its offset through a descriptor of the branch's own
 * (not sharing its offset with the paused copy's) at the same number.  If the
 * abandoned branch removed or renamed it (an atomic write's temporary file,
 * traffic/fcd.c), it is made again from the file the descriptor still holds. */
static fw_status rewind_file(const snap_open *o, off_t cut, fw_error *err)
{
    struct stat fs, ps;
    bool same = fstat(o->fd, &fs) == 0 && stat(o->path, &ps) == 0 && fs.st_dev == ps.st_dev &&
                fs.st_ino == ps.st_ino;
    int flags = (o->flags & ~(O_TRUNC | O_EXCL)) | O_CREAT | (same ? 0 : O_TRUNC);
    int fd = open(o->path, flags, 0666);
    fw_status st = FW_OK;
    if (fd < 0 || (!same && copy_prefix(o->fd, fd, cut) != 0) || dup2(fd, o->fd) < 0 ||
        ftruncate(o->fd, cut) != 0 || lseek(o->fd, o->off, SEEK_SET) != o->off)
        st = fw_fail(err, FW_ERUN, "cannot restore %s: %s", o->path, strerror(errno));
    if (fd >= 0 && fd != o->fd)
        close(fd);
    return st;
}

/* In a branch: the run directory as it was at the snapshot.  Each file that
 * was open is cut back to its offset then (the largest if several
 * descriptors had it); then the files made after the snapshot go. */
static fw_status rewind_files(const fw_snapshot *s, fw_error *err)
{
    if (!s->dir[0])
        return FW_OK;
    fw_status st = FW_OK;
    for (int i = 0; !st && i < s->n_open; i++) {
        off_t cut = s->open[i].off;
        for (int j = 0; j < s->n_open; j++)
            if (!strcmp(s->open[j].path, s->open[i].path) && s->open[j].off > cut)
                cut = s->open[j].off;
        st = rewind_file(&s->open[i], cut, err);
    }
    return st ? st : walk(s->dir, drop_new_file, (void *)s, err);
}

/* ---- the paused copy ---- */

/* SIGPIPE ignored (writing to a closed pipe an error instead); the action it
 * had into *old, for sigaction(SIGPIPE, old, NULL) to put back. */
static void ignore_sigpipe(struct sigaction *old)
{
    struct sigaction ign = {.sa_handler = SIG_IGN};
    sigemptyset(&ign.sa_mask);
    sigaction(SIGPIPE, &ign, old);
}

/* The paused copy: forks a branch for each branch number the owner sends and
 * answers with the branch's exit code; exits when the owner's end closes.
 * Returns (in a branch only) that branch's number. */
static uint32_t serve(fw_snapshot *s)
{
    /* a dead owner must not kill the copy mid-answer before it reaps */
    struct sigaction old;
    ignore_sigpipe(&old);
    for (;;) {
        uint32_t branch;
        if (fw_fd_read(s->cmd, &branch, sizeof branch) != 0)
            _exit(0);
        pid_t b = fork();
        if (b == 0) {
            close(s->cmd);
            close(s->reply);
            sigaction(SIGPIPE, &old, NULL);
            return branch;
        }
        int code = -1;
        if (b > 0) {
            code = fw_spawn_wait(b);
        }
        if (fw_fd_write(s->reply, &code, sizeof code) != 0)
            _exit(0);
    }
}

/* ---- the API ---- */

static void free_lists(fw_snapshot *s)
{
    for (int i = 0; i < s->n_open; i++)
        free(s->open[i].path);
    free(s->open);
    for (int i = 0; i < s->n_files; i++)
        free(s->files[i]);
    free(s->files);
}

/* The snapshot's notes: the run directory's files and its open ones. */
static fw_status note_dir(fw_snapshot *s, const char *dir, fw_error *err)
{
    if (!dir) /* a run without files */
        return FW_OK;
    if (!realpath(dir, s->dir))
        return fw_fail(err, FW_ERUN, "cannot resolve the run directory %s: %s", dir,
                       strerror(errno));
    fw_status st = walk(s->dir, note_file, s, err);
    if (!st)
        qsort(s->files, (size_t)s->n_files, sizeof *s->files, by_str);
    return st ? st : each_written_fd(s->dir, note_fd, s, err);
}

fw_status fw_run_snapshot(fw_run *r, fw_snapshot **out, fw_error *err)
{
    *out = NULL;
    const char *why = fw_run_unforkable(r);
    if (why)
        return fw_fail(err, FW_EINPUT, "a run %s cannot be snapshotted: a snapshot is a copy "
                                       "of this process (src/run/branch.h)", why);
    fw_snapshot *s = calloc(1, sizeof *s);
    if (!s)
        return fw_fail(err, FW_ERUN, "out of memory for a snapshot");
    s->cmd = s->reply = -1;
    s->box = mmap(NULL, sizeof *s->box, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1,
                  0);
    if (s->box == MAP_FAILED) {
        free(s);
        return fw_fail(err, FW_ERUN, "mmap: %s", strerror(errno));
    }
    s->t = fw_run_time(r);
    s->step = fw_run_steps(r);
    /* the buffers hold what was written before the snapshot: flushed, the
     * offsets noted below are where the branch goes on */
    fflush(NULL);
    int to[2] = {-1, -1}, from[2] = {-1, -1};
    fw_status st = note_dir(s, fw_run_dir(r), err);
    if (!st && (pipe(to) != 0 || pipe(from) != 0))
        st = fw_fail(err, FW_ERUN, "pipe: %s", strerror(errno));
    pid_t pid = st ? -1 : fork();
    if (!st && pid < 0)
        st = fw_fail(err, FW_ERUN, "fork: %s", strerror(errno));
    if (st) {
        for (int k = 0; k < 2; k++) {
            if (to[k] >= 0)
                close(to[k]);
            if (from[k] >= 0)
                close(from[k]);
        }
        free_lists(s);
        munmap(s->box, sizeof *s->box);
        free(s);
        return st;
    }
    if (pid == 0) { /* the paused copy; returns as a branch */
        close(to[1]);
        close(from[0]);
        s->cmd = to[0];
        s->reply = from[1];
        uint32_t branch = serve(s);
        fw_error ferr = {0};
        if (rewind_files(s, &ferr)) {
            /* never back into the caller's code with an error: it would
             * take itself for the original */
            fprintf(stderr, "fairway: a restored branch: %s\n", ferr.msg);
            fflush(stderr);
            _exit(FW_BRANCH_EXIT_REWIND);
        }
        fw_run_set_branch(r, branch, s->box);
        free_lists(s); /* the box stays mapped: the branch's result goes there */
        free(s);
        return FW_OK;
    }
    close(to[0]);
    close(from[1]);
    s->pid = pid;
    s->owner = getpid();
    s->cmd = to[1];
    s->reply = from[0];
    *out = s;
    return FW_OK;
}

fw_status fw_run_restore(fw_run *r, fw_snapshot *s, uint32_t branch, int *exit_code_out,
                         fw_error *err)
{
    if (!s || s->owner != getpid())
        return fw_fail(err, FW_EINPUT, "a snapshot can be restored only by the process that "
                                       "took it");
    /* the abandoned branch ends first: what it writes while closing (past
     * the snapshot's offsets, or files of its own) the restored copy undoes */
    fw_run_discard(r);
    /* a copy that has gone (killed) closes the pipe: an error, not SIGPIPE */
    s->box->n = 0;
    struct sigaction old;
    ignore_sigpipe(&old);
    int code, bad = fw_fd_write(s->cmd, &branch, sizeof branch) != 0 ||
                    fw_fd_read(s->reply, &code, sizeof code) != 0;
    sigaction(SIGPIPE, &old, NULL);
    if (bad)
        return fw_fail(err, FW_ERUN, "the snapshot at t = %.1f s has gone", s->t);
    if (code < 0)
        return fw_fail(err, FW_ERUN, "the snapshot at t = %.1f s could not fork a branch", s->t);
    if (code == FW_BRANCH_EXIT_REWIND)
        return fw_fail(err, FW_ERUN, "the branch restored from t = %.1f s could not put the run "
                                     "directory %s back as it was (its message is on stderr)",
                       s->t, s->dir);
    *exit_code_out = code;
    return FW_OK;
}

fw_status fw_run_result(fw_run *r, const void *data, size_t n, fw_error *err)
{
    result_box *box = fw_run_branch_box(r);
    if (!box)
        return fw_fail(err, FW_EINPUT, "a result is for a branch restored from a snapshot");
    if (n > sizeof box->data)
        return fw_fail(err, FW_EINPUT, "a branch's result of %zu bytes is over %d", n,
                       FW_BRANCH_RESULT_MAX);
    memcpy(box->data, data, n);
    box->n = (uint32_t)n;
    return FW_OK;
}

const void *fw_snapshot_result(const fw_snapshot *s, size_t *n)
{
    *n = s->box->n <= sizeof s->box->data ? s->box->n : 0;
    return s->box->data;
}

double fw_snapshot_time(const fw_snapshot *s) { return s->t; }
long fw_snapshot_step(const fw_snapshot *s) { return s->step; }
int fw_snapshot_pid(const fw_snapshot *s) { return (int)s->pid; }

void fw_snapshot_free(fw_snapshot *s)
{
    if (!s)
        return;
    if (s->cmd >= 0)
        close(s->cmd);
    if (s->reply >= 0)
        close(s->reply);
    /* killed, not only told by the pipe: a copy forked later holds this
     * pipe's end too (fork copies every descriptor), so the pipe alone
     * would not close until that one ended; a paused copy has nothing to
     * finish */
    if (s->owner == getpid() && kill(s->pid, SIGKILL) == 0)
        while (waitpid(s->pid, NULL, 0) < 0 && errno == EINTR)
            ;
    munmap(s->box, sizeof *s->box);
    free_lists(s);
    free(s);
}
