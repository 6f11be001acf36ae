/* netcache.c - built networks kept by their inputs' content (see netcache.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files.h"
#include "core/hash.h"
#include "traffic/netcache.h"

/* Bumped when what a cached file holds changes for the same inputs (say, the
 * header's date cut differently in netbuild.c): older entries then miss. */
static const char *const kFormat = "fairway netcache 1";

/* ROOT/net, created; false when there is no usable place. */
static bool cache_dir(char *out, size_t n)
{
    const char *off = getenv("FAIRWAY_NETCACHE");
    if (off && strcmp(off, "off") == 0)
        return false;
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    fw_status st;
    /* the XDG rule: a relative XDG_CACHE_HOME is ignored */
    if (xdg && xdg[0] == '/')
        st = fw_path(out, n, NULL, "%s/fairway/net", xdg);
    else if (home && home[0] == '/')
        st = fw_path(out, n, NULL, "%s/.cache/fairway/net", home);
    else
        return false;
    return !st && !fw_mkdirs(out, "cache", NULL);
}

/* One input file list's names and bytes into the key; false if one cannot
 * be read. */
static bool add_inputs(FILE *key, const char *dir, const char *list)
{
    for (const char *p = list; *p;) {
        size_t len = strcspn(p, ",");
        char path[2400];
        if (fw_path(path, sizeof path, NULL, "%s%s%.*s", p[0] == '/' ? "" : dir,
                    p[0] == '/' ? "" : "/", (int)len, p))
            return false;
        char *data;
        size_t n;
        if (fw_file_read(path, &data, &n, NULL))
            return false;
        fprintf(key, "input %zu:%.*s %zu\n", len, (int)len, p, n);
        fwrite(data, 1, n, key);
        fputc('\n', key);
        free(data);
        p += len + (p[len] == ',');
    }
    return true;
}

bool fw_netcache_key_make(const char *dir, const char *const *argv, const char *const *inputs,
                          int n_files, const char *const *names, fw_netcache_key *k)
{
    memset(k, 0, sizeof *k);
    k->n_files = n_files;
    k->names = names;
    char root[1100];
    struct stat prog;
    if (!cache_dir(root, sizeof root) || stat(argv[0], &prog) != 0)
        return false;
    FILE *key = open_memstream(&k->text, &k->n);
    if (!key)
        return false;
    const char *home = getenv("SUMO_HOME");
    /* netconvert itself: an upgrade changes its size or time */
    fprintf(key, "%s\nprogram %lld %lld.%09ld\nSUMO_HOME=%s\n", kFormat, (long long)prog.st_size,
            (long long)prog.st_mtim.tv_sec, prog.st_mtim.tv_nsec, home ? home : "");
    /* length-prefixed: no argument can pass for two */
    for (int i = 0; argv[i]; i++)
        fprintf(key, "arg %zu:%s\n", strlen(argv[i]), argv[i]);
    for (int i = 0; i < n_files; i++)
        fprintf(key, "holds %s\n", names[i]);
    bool ok = true;
    for (int i = 0; ok && inputs[i]; i++)
        ok = add_inputs(key, dir, inputs[i]);
    ok = fclose(key) == 0 && ok;
    if (ok) {
        unsigned long long h = fw_fnv1a(FW_FNV_INIT, k->text, k->n);
        ok = !fw_path(k->dir, sizeof k->dir, NULL, "%s/%016llx", root, h);
    }
    if (!ok)
        fw_netcache_key_free(k);
    return ok;
}

bool fw_netcache_get(const fw_netcache_key *k, const char *const *dest)
{
    char path[1300];
    char *data;
    size_t len;
    if (!k->text || fw_path(path, sizeof path, NULL, "%s/key", k->dir) ||
        fw_file_read(path, &data, &len, NULL))
        return false;
    bool same = len == k->n && memcmp(data, k->text, len) == 0;
    free(data);
    for (int i = 0; same && i < k->n_files; i++) {
        if (fw_path(path, sizeof path, NULL, "%s/%s", k->dir, k->names[i]) ||
            fw_file_read(path, &data, &len, NULL)) {
            /* entries are renamed into place whole: one missing a file was
             * damaged from outside, and goes, so that the next run stores
             * it again */
            fw_remove_tree(k->dir);
            return false;
        }
        same = !fw_file_write(dest[i], data, len, NULL);
        free(data);
    }
    return same;
}

/* src copied to dir/name. */
static bool copy_in(const char *dir, const char *name, const char *src)
{
    char path[1300], *data;
    size_t len;
    if (fw_path(path, sizeof path, NULL, "%s/%s", dir, name) ||
        fw_file_read(src, &data, &len, NULL))
        return false;
    bool ok = !fw_file_write(path, data, len, NULL);
    free(data);
    return ok;
}

void fw_netcache_put(const fw_netcache_key *k, const char *const *src)
{
    char tmp[1300], path[1300];
    if (!k->text)
        return;
    const char *slash = strrchr(k->dir, '/');
    /* the entry is made whole beside the others, then renamed into place */
    if (fw_path(tmp, sizeof tmp, NULL, "%.*s/.tmp.XXXXXX", (int)(slash - k->dir), k->dir) ||
        !mkdtemp(tmp))
        return;
    bool ok = !fw_path(path, sizeof path, NULL, "%s/key", tmp) &&
              !fw_file_write(path, k->text, k->n, NULL);
    for (int i = 0; ok && i < k->n_files; i++)
        ok = copy_in(tmp, k->names[i], src[i]);
    /* an entry there already (a parallel run stored it first) is kept */
    if (!ok || rename(tmp, k->dir) != 0)
        fw_remove_tree(tmp);
}

void fw_netcache_key_free(fw_netcache_key *k)
{
    free(k->text);
    k->text = NULL;
    k->n = 0;
}
