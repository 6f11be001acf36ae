/* netbuild.c - netconvert as a child process (see netbuild.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files.h"
#include "core/leftover.h"
#include "core/spawn.h"
#include "traffic/netbuild.h"
#include "traffic/demand.h"
#include "traffic/netcache.h"

/* buf[at, at + cut) replaced by ins (not longer), the terminating NUL
 * moved with the rest. */
static void splice(char *buf, size_t *n, size_t at, size_t cut, const char *ins)
{
    size_t k = strlen(ins);
    memmove(buf + at + k, buf + at + cut, *n - at - cut + 1);
    memcpy(buf + at, ins, k);
    *n -= cut - k;
}

/* "<!-- generated on YYYY-MM-DD HH:MM:SS by ..." -> without the date; and,
 * when from is given, the header's output file from -> to (a shorter name:
 * the file's bytes then do not depend on where it was built). */
static fw_status strip_date(const char *path, const char *from, const char *to, fw_error *err)
{
    char *buf;
    size_t n;
    fw_status st = fw_file_read(path, &buf, &n, err);
    if (st)
        return st;
    bool changed = false;
    const char *key = "generated on ";
    char *p = strstr(buf, key);
    /* only within the header comment, and only a date-like 20 characters */
    if (p && p - buf < 200 && strlen(p) > strlen(key) + 20 && p[strlen(key) + 4] == '-') {
        splice(buf, &n, (size_t)(p - buf) + strlen("generated "), strlen("on ") + 20, "");
        changed = true;
    }
    char was[1400];
    if (from && strlen(to) <= strlen(from) &&
        (size_t)snprintf(was, sizeof was, "<output-file value=\"%s\"/>", from) < sizeof was &&
        (p = strstr(buf, was)) && p - buf < 8192) {
        splice(buf, &n, (size_t)(p - buf) + strlen("<output-file value=\""), strlen(from), to);
        changed = true;
    }
    if (changed)
        st = fw_file_write(path, buf, n, err);
    free(buf);
    return st;
}

/* netconvert's command line, the same for every network fairway builds:
 * normalisation off (SUMO's x/y are the node coordinates). */
static void net_argv(const char **argv, const char *nodes, const char *edges, const char *types,
                     const char *proj, const char *out)
{
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
}

fw_status fw_netconvert(const char *dir, const char *nodes, const char *edges, const char *types,
                        const char *proj, const char *out, const char *log, fw_error *err)
{
    const char *argv[20];
    net_argv(argv, nodes, edges, types, proj, out);
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
    bool keyed = fw_netcache_key_make(dir, argv, inputs, log ? 2 : 1, names, false, &key);
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
        st = strip_date(path, NULL, NULL, err);
    if (!st && keyed)
        fw_netcache_put(&key, files);
    fw_netcache_key_free(&key);
    return st;
}

/* netconvert's first error from its log, as FILE:LINE when it names them
 * (" In file 'F'", " At line/column L/C"), else quoted with the network's
 * name: FW_EINPUT (the sources are the user's). */
static fw_status netconvert_failed(const fw_network_files *nf, const char *log, fw_error *err)
{
    char *text = NULL, msg[320] = "no message", file[256] = "";
    size_t n;
    long line = 0;
    if (!fw_file_read(log, &text, &n, NULL)) {
        char *e = strstr(text, "Error: ");
        if (e) {
            e += strlen("Error: ");
            size_t k = strcspn(e, "\r\n");
            snprintf(msg, sizeof msg, "%.*s", (int)(k < 300 ? k : 300), e);
            char *next = strstr(e, "Error: "), *f = strstr(e, " In file '"),
                 *l = strstr(e, " At line/column ");
            if (f && (!next || f < next))
                snprintf(file, sizeof file, "%.*s", (int)strcspn(f + 10, "'\r\n"), f + 10);
            if (l && (!next || l < next))
                line = strtol(l + strlen(" At line/column "), NULL, 10);
        }
    }
    free(text);
    char path[1400];
    if (file[0] && line > 0 && !strchr(file, '/') &&
        !fw_path(path, sizeof path, NULL, "%s/%s", nf->dir, file))
        return fw_fail_at(err, path, (int)line, "network", "netconvert: %s", msg);
    return fw_fail(err, FW_EINPUT, "network '%s' (%s): netconvert cannot build it: \"%s\"",
                   nf->name, nf->dir, msg);
}

/* netconvert on nf's sources, in their directory and on their relative names
 * (src[]: nodes, edges, types or NULL), into a directory of its own; the
 * result stored under key and nf->net set to the entry's file. */
static fw_status build(fw_network_files *nf, const char *const *src, const char *out,
                       const fw_netcache_key *key, fw_error *err)
{
    const char *tmp = getenv("TMPDIR");
    char dir[1100], path[1200], log[1200];
    fw_status st = fw_path(dir, sizeof dir, err, "%s/fairway-net-%s.XXXXXX",
                           tmp && tmp[0] == '/' ? tmp : "/tmp", nf->name);
    if (st)
        return st;
    /* what a SIGKILLed build left there (core/leftover.h), then ours, marked */
    fw_leftover_clean(tmp && tmp[0] == '/' ? tmp : "/tmp", "fairway-net-",
                      "an interrupted network build");
    if (!mkdtemp(dir))
        return fw_fail(err, FW_ERUN, "network '%s': cannot make a directory to build it in (%s): "
                       "%s", nf->name, dir, strerror(errno));
    if ((st = fw_leftover_mark(dir, err))) {
        fw_remove_tree(dir);
        return st;
    }
    const char *argv[20];
    if (!(st = fw_path(path, sizeof path, err, "%s/%s", dir, out)) &&
        !(st = fw_path(log, sizeof log, err, "%s/netconvert.log", dir))) {
        net_argv(argv, src[0], src[1], src[2], nf->proj[0] ? nf->proj : NULL, path);
        fw_spawn_def sp = {.argv = argv, .log = log, .dir = nf->dir};
        int status;
        if (!(st = fw_spawn_run(&sp, &status, err)) && status != 0)
            st = netconvert_failed(nf, log, err);
    }
    if (!st)
        st = strip_date(path, path, out, err);
    if (!st) {
        const char *files[] = {path};
        fw_netcache_put(key, files);
        if (!fw_netcache_lookup(key, nf->net, sizeof nf->net))
            st = fw_fail(err, FW_ERUN, "network '%s': its net.xml could not be stored in the "
                         "network cache %.*s (full disk?)", nf->name,
                         (int)(strrchr(key->dir, '/') - key->dir), key->dir);
    }
    fw_remove_tree(dir);
    return st;
}

fw_status fw_network_build(fw_network_files *nf, fw_error *err)
{
    char nod[80], edg[80], typ[80], out[80];
    snprintf(nod, sizeof nod, "%s.nod.xml", nf->name);
    snprintf(edg, sizeof edg, "%s.edg.xml", nf->name);
    snprintf(typ, sizeof typ, "%s.typ.xml", nf->name);
    snprintf(out, sizeof out, "%s.net.xml", nf->name);
    const char *src[] = {nod, edg, nf->typ[0] ? typ : NULL, NULL};
    /* the key's command line names the output as the file's header does */
    const char *argv[20];
    net_argv(argv, src[0], src[1], src[2], nf->proj[0] ? nf->proj : NULL, out);
    setenv("SUMO_HOME", FW_SUMO_HOME, 0);
    static const char *const names[] = {"net.xml"};
    fw_netcache_key key;
    if (access(FW_NETCONVERT, X_OK) != 0)
        return fw_fail(err, FW_ERUN, "network '%s': netconvert (%s) cannot be run: %s", nf->name,
                       FW_NETCONVERT, strerror(errno));
    if (!fw_netcache_key_make(nf->dir, argv, src, 1, names, true, &key))
        return fw_fail(err, FW_ERUN, "network '%s': no place to keep its net.xml (neither the "
                       "network cache nor TMPDIR/fairway-%u/net can be made)", nf->name,
                       (unsigned)getuid());
    fw_status st = FW_OK;
    if (!fw_netcache_lookup(&key, nf->net, sizeof nf->net))
        st = build(nf, src, out, &key, err);
    fw_netcache_key_free(&key);
    return st;
}
