/* leftover.c - directories and files of processes killed before they could
 * remove them (leftover.h). */
#define _XOPEN_SOURCE 700
#include "core/leftover.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"

static const char kOwner[] = ".fairway-owner";

/* Field 22 of /proc/PID/stat, the process's start time in clock ticks since
 * boot; 0 when it cannot be read (no such process) or the process has ended
 * and only waits to be reaped (a zombie: state Z, field 3). */
static unsigned long long start_time(long pid)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    /* the command name (field 2) may hold spaces and parentheses: count from
     * the last ')' */
    char *p = strrchr(buf, ')');
    if (p && p[1] == ' ' && p[2] == 'Z')
        return 0;
    for (int field = 2; p && field < 22; field++)
        p = strchr(p + 1, ' ');
    return p ? strtoull(p + 1, NULL, 10) : 0;
}

fw_status fw_leftover_mark(const char *dir, fw_error *err)
{
    char path[1200];
    if (fw_path(path, sizeof path, err, "%s/%s", dir, kOwner))
        return err->status;
    FILE *f = fopen(path, "w");
    if (!f)
        return fw_fail(err, FW_ERUN, "%s: cannot write: %s", path, strerror(errno));
    long pid = (long)getpid();
    fprintf(f, "%ld %llu\n", pid, start_time(pid));
    if (fclose(f) != 0)
        return fw_fail(err, FW_ERUN, "%s: cannot write: %s", path, strerror(errno));
    return FW_OK;
}

void fw_leftover_unmark(const char *dir)
{
    char path[1200];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, kOwner) < sizeof path)
        unlink(path);
}

/* Is the directory's owner gone?  false when it has no owner file (not
 * ours to judge) or the owner still runs. */
static bool owner_gone(const char *dir, long *pid)
{
    char path[1200];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, kOwner) >= sizeof path)
        return false;
    FILE *f = fopen(path, "r");
    if (!f)
        return false;
    unsigned long long started = 0;
    int got = fscanf(f, "%ld %llu", pid, &started);
    fclose(f);
    if (got != 2 || *pid <= 0)
        return false;
    if (kill((pid_t)*pid, 0) != 0 && errno == ESRCH)
        return true;
    /* the id is in use: by the owner only if it started when the owner did
     * and has not ended (an orphan killed with its parent is a zombie until
     * whatever adopted it reaps it) */
    unsigned long long now = start_time(*pid);
    if (start_time((long)getpid()) == 0)
        return false; /* no /proc to tell by: a live process's, for all we know */
    return started != 0 && now != started;
}

int fw_leftover_clean(const char *parent, const char *prefix, const char *what)
{
    DIR *d = opendir(parent);
    if (!d)
        return 0;
    int removed = 0;
    size_t pl = strlen(prefix);
    struct dirent *e;
    while ((e = readdir(d))) {
        char dir[1200];
        struct stat sb;
        long pid;
        if (strncmp(e->d_name, prefix, pl) != 0 || strcmp(e->d_name, ".") == 0 ||
            strcmp(e->d_name, "..") == 0 ||
            (size_t)snprintf(dir, sizeof dir, "%s/%s", parent, e->d_name) >= sizeof dir ||
            lstat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode) || sb.st_uid != geteuid() ||
            !owner_gone(dir, &pid))
            continue;
        fw_remove_tree(dir);
        fprintf(stderr, "fairway: removed %s, left by %s (process %ld is gone)\n", dir, what, pid);
        removed++;
    }
    closedir(d);
    return removed;
}

/* The file temporaries (files.h): .NAME.fairway-tmp.PID.XXXXXX, PID their
 * writer's.  True, with *pid, for a name of that form. */
static bool tmp_file_name(const char *name, long *pid)
{
    static const char mark[] = ".fairway-tmp.";
    const char *m = NULL;
    for (const char *p = strstr(name, mark); p; p = strstr(p + 1, mark))
        m = p;
    if (name[0] != '.' || !m || m == name)
        return false;
    const char *d = m + sizeof mark - 1;
    char *end;
    errno = 0;
    long v = strtol(d, &end, 10);
    if (end == d || *d < '0' || *d > '9' || errno || v <= 0 || *end != '.' ||
        strlen(end + 1) != 6)
        return false;
    for (const char *x = end + 1; *x; x++)
        if (!((*x >= 'a' && *x <= 'z') || (*x >= 'A' && *x <= 'Z') || (*x >= '0' && *x <= '9')))
            return false;
    *pid = v;
    return true;
}

/* Seconds since the epoch when process pid started (/proc/stat's btime plus
 * its start time in ticks); -1 when unknown. */
static double started_at(long pid)
{
    unsigned long long ticks = start_time(pid);
    FILE *f = ticks ? fopen("/proc/stat", "r") : NULL;
    if (!f)
        return -1.0;
    char line[256];
    double boot = -1.0;
    while (boot < 0 && fgets(line, sizeof line, f))
        if (strncmp(line, "btime ", 6) == 0)
            boot = strtod(line + 6, NULL);
    fclose(f);
    long hz = sysconf(_SC_CLK_TCK);
    return boot < 0 || hz <= 0 ? -1.0 : boot + (double)ticks / (double)hz;
}

/* Does any process hold the file (dev, ino) open?  A fork of its writer does
 * (a branch of a run, run/branch.h, goes on with the file its parent began).
 * Only processes whose descriptors can be read count: this user's. */
static bool held_open(dev_t dev, ino_t ino)
{
    DIR *procs = opendir("/proc");
    if (!procs)
        return true; /* cannot tell: leave it */
    bool held = false;
    for (struct dirent *p; !held && (p = readdir(procs));) {
        if (p->d_name[0] < '0' || p->d_name[0] > '9')
            continue;
        char fdd[300];
        snprintf(fdd, sizeof fdd, "/proc/%.20s/fd", p->d_name);
        DIR *fds = opendir(fdd);
        for (struct dirent *e; fds && !held && (e = readdir(fds));) {
            char link[600];
            struct stat sb;
            snprintf(link, sizeof link, "%s/%.200s", fdd, e->d_name);
            held = e->d_name[0] != '.' && stat(link, &sb) == 0 && sb.st_dev == dev &&
                   sb.st_ino == ino;
        }
        if (fds)
            closedir(fds);
    }
    closedir(procs);
    return held;
}

/* Is the writer of a temporary file gone?  Its process id is free, or taken
 * by a process that started after the file was last written (2 s spared for
 * the clocks' resolutions), and no process holds the file open. */
static bool writer_gone(long pid, const struct stat *sb)
{
    if (!(kill((pid_t)pid, 0) != 0 && errno == ESRCH)) {
        double t = started_at(pid);
        if (t < 0 || t <= (double)sb->st_mtim.tv_sec + 2.0)
            return false;
    }
    return !held_open(sb->st_dev, sb->st_ino);
}

int fw_leftover_clean_files(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int removed = 0;
    for (struct dirent *e; (e = readdir(d));) {
        char path[1200];
        struct stat sb;
        long pid;
        if (!tmp_file_name(e->d_name, &pid) ||
            (size_t)snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= sizeof path ||
            lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_uid != geteuid() ||
            !writer_gone(pid, &sb) || unlink(path) != 0)
            continue;
        fprintf(stderr, "fairway: removed %s, left by an interrupted fairway (process %ld is gone)\n",
                path, pid);
        removed++;
    }
    closedir(d);
    return removed;
}
