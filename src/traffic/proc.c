/* proc.c - sumo as a child process (gui mode, tests): a free port, fork/exec
 * with output to a file, and a stop that always reaps. */
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "traffic/traffic.h"

fw_status fw_traffic_free_port(int *port, fw_error *err)
{
    int s = socket(AF_INET, SOCK_STREAM, 0);
    if (s < 0)
        return fw_fail(err, FW_ERUN, "cannot open a socket: %s", strerror(errno));
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0; /* the kernel picks an unused port */
    socklen_t len = sizeof a;
    if (bind(s, (struct sockaddr *)&a, sizeof a) != 0 ||
        getsockname(s, (struct sockaddr *)&a, &len) != 0) {
        int e = errno;
        close(s);
        return fw_fail(err, FW_ERUN, "cannot find a free port: %s", strerror(e));
    }
    *port = ntohs(a.sin_port);
    close(s);
    return FW_OK;
}

fw_status fw_traffic_spawn(const char *const *argv, const char *log_file, pid_t *pid,
                           fw_error *err)
{
    /* a pipe closed on exec tells the parent whether exec worked */
    int fds[2];
    if (pipe(fds) != 0)
        return fw_fail(err, FW_ERUN, "cannot start %s: %s", argv[0], strerror(errno));
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    pid_t p = fork();
    if (p < 0) {
        close(fds[0]);
        close(fds[1]);
        return fw_fail(err, FW_ERUN, "cannot start %s: %s", argv[0], strerror(errno));
    }
    if (p == 0) {
        close(fds[0]);
        int fd = open(log_file ? log_file : "/dev/null", O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        execvp(argv[0], (char *const *)argv);
        int e = errno;
        ssize_t w = write(fds[1], &e, sizeof e);
        (void)w;
        _exit(127);
    }
    close(fds[1]);
    int e = 0;
    ssize_t r;
    do
        r = read(fds[0], &e, sizeof e);
    while (r < 0 && errno == EINTR);
    close(fds[0]);
    if (r == (ssize_t)sizeof e) {
        waitpid(p, NULL, 0);
        return fw_fail(err, FW_ERUN, "cannot run %s: %s", argv[0], strerror(e));
    }
    *pid = p;
    return FW_OK;
}

void fw_traffic_stop_child(pid_t pid)
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
