/* netcache.c - built networks kept by their inputs' content (see netcache.h). */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "core/leftover.h"
#include "core/hash.h"
#include "core/mem.h"
#include "traffic/netcache.h"

/* Bumped when what a cached file holds changes for the same inputs (say, the
 * header's date cut differently in netbuild.c): older entries then miss. */
static const char *const kFormat = "fairway netcache 2"; /* 2: the sums file */

/* TMPDIR/fairway-UID/net, created, ours alone (a directory of this user
 * that no one else may write, not a link): where networks go when there is
 * no cache. */
static bool private_dir(char *out, size_t n)
{
    const char *tmp = getenv("TMPDIR");
    char top[1000];
    struct stat sb;
    if (fw_path(top, sizeof top, NULL, "%s/fairway-%u", tmp && tmp[0] == '/' ? tmp : "/tmp",
                (unsigned)getuid()) ||
        (mkdir(top, 0700) != 0 && errno != EEXIST) || lstat(top, &sb) != 0 ||
        !S_ISDIR(sb.st_mode) || sb.st_uid != getuid() || (sb.st_mode & 022))
        return false;
    return !fw_path(out, n, NULL, "%s/net", top) && !fw_mkdirs(out, "cache", NULL);
}

/* ROOT/net, created; false when there is no usable place.  needed: the
 * network is one fairway has no other place for (a network's own net.xml,
 * netbuild.h fw_network_build), kept in a directory of the user's under
 * TMPDIR when the cache is off or has no place. */
static bool cache_dir(char *out, size_t n, bool needed)
{
    const char *off = getenv("FAIRWAY_NETCACHE");
    if (off && strcmp(off, "off") == 0)
        return needed && private_dir(out, n);
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    fw_status st;
    /* the XDG rule: a relative XDG_CACHE_HOME is ignored */
    if (xdg && xdg[0] == '/')
        st = fw_path(out, n, NULL, "%s/fairway/net", xdg);
    else if (home && home[0] == '/')
        st = fw_path(out, n, NULL, "%s/.cache/fairway/net", home);
    else
        return needed && private_dir(out, n);
    if (!st && !fw_mkdirs(out, "cache", NULL))
        return true;
    return needed && private_dir(out, n);
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
                          int n_files, const char *const *names, bool needed, fw_netcache_key *k)
{
    memset(k, 0, sizeof *k);
    k->n_files = n_files;
    k->names = names;
    char root[1100];
    struct stat prog;
    if (!cache_dir(root, sizeof root, needed) || stat(argv[0], &prog) != 0)
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

/* Does the entry's key equal k's, byte for byte? */
static bool same_key(const fw_netcache_key *k)
{
    char path[1300];
    char *data;
    size_t len;
    if (!k->text || fw_path(path, sizeof path, NULL, "%s/key", k->dir) ||
        fw_file_read(path, &data, &len, NULL))
        return false;
    bool same = len == k->n && memcmp(data, k->text, len) == 0;
    free(data);
    return same;
}

/* The sums of an entry's files in dir, one line each: "NAME SIZE FNV-1a",
 * malloc'd into *out; false when a file cannot be read. */
static bool sums(const char *dir, const fw_netcache_key *k, char **out)
{
    size_t n = 0;
    FILE *f = open_memstream(out, &n);
    bool ok = f != NULL;
    for (int i = 0; ok && i < k->n_files; i++) {
        char path[1400], *data;
        size_t len;
        ok = !fw_path(path, sizeof path, NULL, "%s/%s", dir, k->names[i]) &&
             !fw_file_read(path, &data, &len, NULL);
        if (ok) {
            fprintf(f, "%s %zu %016llx\n", k->names[i], len,
                    (unsigned long long)fw_fnv1a(FW_FNV_INIT, data, len));
            free(data);
        }
    }
    if (f && fclose(f) != 0)
        ok = false;
    if (!ok) {
        free(*out);
        *out = NULL;
    }
    return ok;
}

/* Is k's entry there, made from k's key, and are its files whole (the size
 * and digest the sums file recorded when it was stored)?  An entry with k's
 * key whose files are not is damaged (a truncated file, a disk error, a hand
 * edit) and goes, so that the caller builds and stores it again. */
static bool whole(const fw_netcache_key *k)
{
    if (!same_key(k))
        return false;
    char path[1300], *want = NULL, *have = NULL;
    size_t len = 0;
    bool ok = !fw_path(path, sizeof path, NULL, "%s/sums", k->dir) &&
              !fw_file_read(path, &want, &len, NULL) && sums(k->dir, k, &have) &&
              strlen(have) == len && memcmp(have, want, len) == 0;
    free(want);
    free(have);
    if (!ok)
        fw_remove_tree(k->dir);
    return ok;
}

bool fw_netcache_lookup(const fw_netcache_key *k, char *path, size_t n)
{
    if (!whole(k) || fw_path(path, n, NULL, "%s/%s", k->dir, k->names[0]))
        return false;
    utimensat(AT_FDCWD, k->dir, NULL, 0);
    return true;
}

bool fw_netcache_get(const fw_netcache_key *k, const char *const *dest)
{
    char path[1300];
    char *data;
    size_t len;
    bool same = whole(k);
    for (int i = 0; same && i < k->n_files; i++) {
        if (fw_path(path, sizeof path, NULL, "%s/%s", k->dir, k->names[i]) ||
            fw_file_read(path, &data, &len, NULL)) {
            fw_remove_tree(k->dir); /* gone since it was checked */
            return false;
        }
        same = !fw_file_write(dest[i], data, len, NULL);
        free(data);
    }
    if (same) /* recently used: the last the pruning takes */
        utimensat(AT_FDCWD, k->dir, NULL, 0);
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

/* Entries kept at most: FAIRWAY_NETCACHE_MAX, default 512 (entries are 2-20
 * kB: a few MB at most); beyond it the least recently used go, so a study
 * that builds a network per run cannot fill the disk. */
static int max_entries(void)
{
    const char *m = getenv("FAIRWAY_NETCACHE_MAX");
    long v = m ? strtol(m, NULL, 10) : 0;
    return v > 0 && v <= 1000000 ? (int)v : 512;
}

typedef struct entry {
    char name[256];
    struct timespec used; /* the directory's modification time: set at each hit */
} entry;

static int by_use(const void *a, const void *b)
{
    const struct timespec *x = &((const entry *)a)->used, *y = &((const entry *)b)->used;
    return x->tv_sec != y->tv_sec ? (x->tv_sec < y->tv_sec ? -1 : 1)
                                  : (x->tv_nsec > y->tv_nsec) - (x->tv_nsec < y->tv_nsec);
}

/* The least recently used entries of root beyond max_entries() removed (not
 * the temporaries of runs storing theirs: their names begin with a dot).  A
 * run reading an entry removed under it misses, and builds. */
static void prune(const char *root)
{
    DIR *d = opendir(root);
    if (!d)
        return;
    entry *v = NULL;
    int n = 0, cap = 0;
    char p[1600];
    for (struct dirent *e; (e = readdir(d));) {
        struct stat sb;
        if (e->d_name[0] == '.' || strlen(e->d_name) >= sizeof v->name ||
            fw_path(p, sizeof p, NULL, "%s/%s", root, e->d_name) || stat(p, &sb) != 0 ||
            !S_ISDIR(sb.st_mode))
            continue;
        if (!fw_reserve((void **)&v, sizeof *v, &cap, n + 1))
            break;
        snprintf(v[n].name, sizeof v[n].name, "%s", e->d_name);
        v[n++].used = sb.st_mtim;
    }
    closedir(d);
    int max = max_entries();
    if (n > max) {
        qsort(v, (size_t)n, sizeof *v, by_use);
        for (int i = 0; i < n - max; i++)
            if (!fw_path(p, sizeof p, NULL, "%s/%s", root, v[i].name))
                fw_remove_tree(p);
    }
    free(v);
}

void fw_netcache_put(const fw_netcache_key *k, const char *const *src)
{
    char tmp[1300], path[1300];
    if (!k->text)
        return;
    const char *slash = strrchr(k->dir, '/');
    /* the entry is made whole beside the others, then renamed into place */
    char root[1300];
    snprintf(root, sizeof root, "%.*s", (int)(slash - k->dir), k->dir);
    /* what a SIGKILLed run storing its entry left (core/leftover.h) */
    fw_leftover_clean(root, ".tmp.", "an interrupted network cache store");
    if (fw_path(tmp, sizeof tmp, NULL, "%s/.tmp.XXXXXX", root) || !mkdtemp(tmp))
        return;
    fw_error merr = {0};
    bool ok = !fw_leftover_mark(tmp, &merr) &&
              !fw_path(path, sizeof path, NULL, "%s/key", tmp) &&
              !fw_file_write(path, k->text, k->n, NULL);
    for (int i = 0; ok && i < k->n_files; i++)
        ok = copy_in(tmp, k->names[i], src[i]);
    /* the files' sizes and digests, checked at every use (whole) */
    char *sum = NULL;
    ok = ok && sums(tmp, k, &sum) && !fw_path(path, sizeof path, NULL, "%s/sums", tmp) &&
         !fw_file_write(path, sum, strlen(sum), NULL);
    free(sum);
    /* an entry there already (a parallel run stored it first) is kept; the
     * entry holds only its own files */
    if (ok)
        fw_leftover_unmark(tmp);
    if (!ok || rename(tmp, k->dir) != 0) {
        fw_remove_tree(tmp);
        return;
    }
    prune(root);
}

void fw_netcache_key_free(fw_netcache_key *k)
{
    free(k->text);
    k->text = NULL;
    k->n = 0;
}
