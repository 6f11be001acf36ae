/* bench_proc.h - whole processes timed: a program run to its end, its CPU
 * (user + system, the kernel's accounting of the reaped child, to the
 * microsecond) and wall seconds.  For the benchmarks that compare processes
 * (bench_sumo_alone, bench_startup). */
#ifndef FW_BENCH_PROC_H
#define FW_BENCH_PROC_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench.h"
#include "core/spawn.h"

/* Runs argv (its output to log, NULL: discarded) to the end; exits the
 * benchmark with a message when it cannot be started or does not exit 0. */
static inline void bench_proc_run(const char *const *argv, const char *log, double *cpu,
                                  double *wall)
{
    fw_error err = {0};
    pid_t pid;
    double t0 = bench_now();
    if (fw_spawn(&(fw_spawn_def){.argv = argv, .log = log}, &pid, &err)) {
        fprintf(stderr, "bench: %s\n", err.msg);
        exit(1);
    }
    int status;
    struct rusage ru;
    while (wait4(pid, &status, 0, &ru) < 0 && errno == EINTR)
        ;
    *wall = bench_now() - t0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "bench: %s %s failed (status %d)\n", argv[0], argv[1] ? argv[1] : "",
                status);
        exit(1);
    }
    *cpu = (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
           1e-6 * (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

/* The fairway of this build tree: beside the benchmark's own directory
 * (build/bench/NAME -> build/fairway).  0, or -1 when it cannot be told. */
static inline int bench_proc_fairway(char *out, size_t n)
{
    char self[4096];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    if (k <= 0)
        return -1;
    self[k] = '\0';
    char *slash = strrchr(self, '/');
    if (slash)
        *slash = '\0';
    return (size_t)snprintf(out, n, "%s/../fairway", self) < n ? 0 : -1;
}

/* The arguments of a process benchmark, `NAME [CSV_FILE|- [FAIRWAY ...]]`
 * with at most max_args of them: *csv opened (NULL for none or "-"),
 * fairway argv[2] or the build tree's.  -1 to go on, else the exit code
 * (usage printed: 2; a failure: 1). */
static inline int bench_proc_args(int argc, char **argv, int max_args, const char *usage,
                                  char *fairway, size_t n, FILE **csv)
{
    *csv = NULL;
    if (argc > max_args + 1 || (argc == 2 && strcmp(argv[1], "--help") == 0)) {
        fprintf(stderr, "usage: %s\n", usage);
        return 2;
    }
    if (argc > 2)
        snprintf(fairway, n, "%s", argv[2]);
    else if (bench_proc_fairway(fairway, n)) {
        fprintf(stderr, "%s: cannot find the build tree's fairway\n", argv[0]);
        return 1;
    }
    if (argc > 1 && strcmp(argv[1], "-") && !(*csv = fopen(argv[1], "w"))) {
        perror(argv[1]);
        return 1;
    }
    return -1;
}

#endif
