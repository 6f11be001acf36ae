/* leftover.c - directories of processes killed before they could remove
 * them (leftover.h). */
#include "core/leftover.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
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
