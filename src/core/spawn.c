/* spawn.c - see spawn.h. */
#include "core/spawn.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* In the child: redirect, change directory, exec; on failure write errno to
 * the pipe and leave. */
static void child(const fw_spawn_def *d, int report)
{
    /* nothing fairway starts outlives it: a sumo-gui, netconvert or plot of a
     * SIGKILLed fairway dies with it (the flag survives exec) */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    /* never through a symlink planted at the log's name (the caller makes
     * the log first: core/files.h); one there leaves the output unredirected */
    int flags = O_WRONLY | O_CREAT | O_NOFOLLOW | (d->append ? O_APPEND : O_TRUNC);
    int fd = open(d->log ? d->log : "/dev/null", flags, 0644);
    if (fd >= 0) {
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        close(fd);
    }
    if (!d->dir || chdir(d->dir) == 0)
        execvp(d->argv[0], (char *const *)d->argv);
    int e = errno;
    ssize_t w = write(report, &e, sizeof e);
    (void)w;
    _exit(127);
}

fw_status fw_spawn(const fw_spawn_def *d, pid_t *pid, fw_error *err)
{
    int fds[2];
    if (pipe(fds) != 0)
        return fw_fail(err, FW_ERUN, "cannot start %s: %s", d->argv[0], strerror(errno));
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    fflush(NULL); /* the child must not write our buffered output again */
    pid_t p = fork();
    if (p < 0) {
        int e = errno;
        close(fds[0]);
        close(fds[1]);
        return fw_fail(err, FW_ERUN, "cannot start %s: %s", d->argv[0], strerror(e));
    }
    if (p == 0) {
        close(fds[0]);
        child(d, fds[1]);
    }
    close(fds[1]);
    int e = 0;
    ssize_t r;
    do
        r = read(fds[0], &e, sizeof e);
    while (r < 0 && errno == EINTR);
    close(fds[0]);
    if (r == (ssize_t)sizeof e) {
        fw_spawn_wait(p);
        return fw_fail(err, FW_ERUN, "cannot run %s%s%s: %s", d->argv[0], d->dir ? " in " : "",
                       d->dir ? d->dir : "", strerror(e));
    }
    *pid = p;
    return FW_OK;
}

int fw_spawn_wait(pid_t pid)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return 128;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

fw_status fw_spawn_run(const fw_spawn_def *def, int *exit_status, fw_error *err)
{
    pid_t pid;
    fw_status st = fw_spawn(def, &pid, err);
    if (!st)
        *exit_status = fw_spawn_wait(pid);
    return st;
}

void fw_spawn_stop(pid_t pid)
{
    if (pid <= 0)
        return;
    kill(pid, SIGTERM);
    for (int i = 0; i < 300; i++) {
        if (waitpid(pid, NULL, WNOHANG) == pid)
            return;
        struct timespec ts = {0, 10 * 1000 * 1000};
        nanosleep(&ts, NULL);
    }
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
}

fw_status fw_fork_piped(pid_t *pid, int *fd, fw_error *err)
{
    int p[2];
    if (pipe(p))
        return fw_fail(err, FW_ERUN, "pipe: %s", strerror(errno));
    fflush(NULL);
    *pid = fork();
    if (*pid < 0) {
        close(p[0]);
        close(p[1]);
        return fw_fail(err, FW_ERUN, "fork: %s", strerror(errno));
    }
    if (*pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        close(p[0]);
        *fd = p[1];
    } else {
        close(p[1]);
        *fd = p[0];
    }
    return FW_OK;
}

/* The one loop behind fw_fd_read and fw_fd_write. */
static int transfer(int fd, char *buf, size_t n, bool out)
{
    while (n > 0) {
        ssize_t k = out ? write(fd, buf, n) : read(fd, buf, n);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return -1;
        buf += k;
        n -= (size_t)k;
    }
    return 0;
}

int fw_fd_read(int fd, void *buf, size_t n) { return transfer(fd, buf, n, false); }

/* write(2) does not change buf: the cast only lets one loop serve both */
int fw_fd_write(int fd, const void *buf, size_t n) { return transfer(fd, (char *)buf, n, true); }
