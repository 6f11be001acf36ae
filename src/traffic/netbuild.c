/* netbuild.c - netconvert as a child process (see netbuild.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/spawn.h"
#include "traffic/netbuild.h"

/* "<!-- generated on YYYY-MM-DD HH:MM:SS by ..." -> without the date. */
static fw_status strip_date(const char *path, fw_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_ERUN, "cannot read %s", path);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) {
        fclose(f);
        free(buf);
        return fw_fail(err, FW_ERUN, "cannot read %s", path);
    }
    fclose(f);
    buf[n] = '\0';
    const char *key = "generated on ";
    char *p = strstr(buf, key);
    size_t skip = 0;
    /* only within the header comment, and only a date-like 20 characters */
    if (p && p - buf < 200 && strlen(p) > strlen(key) + 20 && p[strlen(key) + 4] == '-')
        skip = 20;
    f = fopen(path, "wb");
    if (!f) {
        free(buf);
        return fw_fail(err, FW_ERUN, "cannot write %s", path);
    }
    if (skip) {
        size_t head = (size_t)(p - buf) + strlen("generated ");
        fwrite(buf, 1, head, f);
        fwrite(p + strlen(key) + skip, 1, (size_t)n - (head + 3 + skip), f);
    } else {
        fwrite(buf, 1, (size_t)n, f);
    }
    free(buf);
    return fclose(f) == 0 ? FW_OK : fw_fail(err, FW_ERUN, "cannot write %s", path);
}

fw_status fw_netconvert(const char *dir, const char *nodes, const char *edges, const char *types,
                        const char *out, const char *log, fw_error *err)
{
    const char *argv[20];
    int k = 0;
    argv[k++] = FW_NETCONVERT;
    argv[k++] = "--node-files";
    argv[k++] = nodes;
    argv[k++] = "--edge-files";
    argv[k++] = edges;
    if (types) {
        argv[k++] = "--type-files";
        argv[k++] = types;
    }
    argv[k++] = "--offset.disable-normalization";
    argv[k++] = "true";
    argv[k++] = "--no-turnarounds";
    argv[k++] = "true";
    argv[k++] = "--no-warnings";
    argv[k++] = "true";
    argv[k++] = "--output-file";
    argv[k++] = out;
    argv[k] = NULL;
    setenv("SUMO_HOME", FW_SUMO_HOME, 0);
    const char *sink = log ? log : "/dev/null";
    fw_spawn_def sp = {.argv = argv, .log = log, .dir = dir};
    int status;
    fw_status st = fw_spawn_run(&sp, &status, err);
    if (st)
        return st;
    if (status != 0)
        return fw_fail(err, FW_ERUN, "netconvert failed building %s (messages in %s)", out, sink);
    char path[2048];
    if ((st = fw_path(path, sizeof path, err, "%s%s%s", out[0] == '/' ? "" : dir,
                      out[0] == '/' ? "" : "/", out)))
        return st;
    return strip_date(path, err);
}
