/* netbuild.c - netconvert as a child process (see netbuild.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/spawn.h"
#include "traffic/netbuild.h"
#include "traffic/netcache.h"

/* "<!-- generated on YYYY-MM-DD HH:MM:SS by ..." -> without the date. */
static fw_status strip_date(const char *path, fw_error *err)
{
    char *buf;
    size_t n;
    fw_status st = fw_file_read(path, &buf, &n, err);
    if (st)
        return st;
    const char *key = "generated on ";
    char *p = strstr(buf, key);
    /* only within the header comment, and only a date-like 20 characters */
    if (p && p - buf < 200 && strlen(p) > strlen(key) + 20 && p[strlen(key) + 4] == '-') {
        size_t head = (size_t)(p - buf) + strlen("generated ");
        size_t skip = strlen(key) + 20;
        memmove(buf + head, p + skip, n - (size_t)(p - buf) - skip);
        n -= skip - strlen("generated ");
        st = fw_file_write(path, buf, n, err);
    }
    free(buf);
    return st;
}

fw_status fw_netconvert(const char *dir, const char *nodes, const char *edges, const char *types,
                        const char *proj, const char *out, const char *log, fw_error *err)
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
    if (proj) {
        argv[k++] = "--proj";
        argv[k++] = proj;
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
    char path[2048];
    fw_status st = fw_path(path, sizeof path, err, "%s%s%s", out[0] == '/' ? "" : dir,
                           out[0] == '/' ? "" : "/", out);
    if (st)
        return st;
    /* the same inputs built before: their files, byte for byte (netcache.h) */
    const char *inputs[] = {nodes, edges, types, NULL};
    const char *names[] = {"net.xml", "netconvert.log"}, *files[] = {path, log};
    fw_netcache_key key;
    bool keyed = fw_netcache_key_make(dir, argv, inputs, log ? 2 : 1, names, &key);
    if (keyed && fw_netcache_get(&key, files)) {
        fw_netcache_key_free(&key);
        return FW_OK;
    }
    const char *sink = log ? log : "/dev/null";
    fw_spawn_def sp = {.argv = argv, .log = log, .dir = dir};
    int status;
    if (!(st = fw_spawn_run(&sp, &status, err)) && status != 0)
        st = fw_fail(err, FW_ERUN, "netconvert failed building %s (messages in %s)", out, sink);
    if (!st)
        st = strip_date(path, err);
    if (!st && keyed)
        fw_netcache_put(&key, files);
    fw_netcache_key_free(&key);
    return st;
}
