/* files.c - see files.h. */
#define _XOPEN_SOURCE 700
#include <stdarg.h>
#include <errno.h>
#include <ftw.h>
#include <libgen.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"

static int remove_entry(const char *path, const struct stat *sb, int flag, struct FTW *ftw)
{
    (void)sb;
    (void)flag;
    (void)ftw;
    remove(path);
    return 0;
}

void fw_remove_tree(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) == 0)
        nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

fw_status fw_mkdirs(const char *dir, const char *what, fw_error *err)
{
    char buf[1024];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf)
        return fw_fail(err, FW_EINPUT, "%s %s: path too long", what, dir);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            mkdir(buf, 0777);
            *p = '/';
        }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return fw_fail(err, FW_EINPUT, "%s %s: cannot create the directory: %s", what, dir,
                       strerror(errno));
    struct stat sb;
    if (stat(buf, &sb) != 0 || !S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s %s: not a directory", what, dir);
    return FW_OK;
}

fw_status fw_path(char *buf, size_t size, fw_error *err, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= size)
        return fw_fail(err, FW_ERUN, "path too long (over %zu characters): %.60s...", size - 1,
                       buf);
    return FW_OK;
}

fw_status fw_file_commit(FILE *f, const char *tmp, const char *path, fw_error *err)
{
    int bad = fflush(f) != 0 || ferror(f);
    bad |= fsync(fileno(f)) != 0;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path) != 0) {
        int e = errno;
        remove(tmp);
        return fw_fail(err, FW_ERUN, "%s: write failed: %s", path, strerror(e));
    }
    return FW_OK;
}

fw_status fw_check_parent_dir(const char *opt, const char *path, const char *cannot,
                              fw_error *err)
{
    char *copy = strdup(path);
    if (!copy)
        return fw_fail(err, FW_ERUN, "out of memory");
    const char *dir = dirname(copy);
    struct stat sb;
    fw_status st = FW_OK;
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
        st = fw_fail(err, FW_EINPUT, "%s %s: no directory %s", opt, path, dir);
    else if (access(dir, W_OK | X_OK) != 0)
        st = fw_fail(err, FW_EINPUT, "%s %s: %s %s: %s", opt, path, cannot, dir, strerror(errno));
    free(copy);
    return st;
}

int fw_csv_split(char *line, char **f, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = '\0';
    char *p = line;
    while (n < max) {
        f[n++] = p;
        char *c = strchr(p, ',');
        if (!c)
            break;
        *c = '\0';
        p = c + 1;
    }
    return n;
}
