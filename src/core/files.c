/* files.c - see files.h. */
#define _XOPEN_SOURCE 700
#include <stdarg.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <libgen.h>
#include <limits.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "core/leftover.h"
#include "core/spawn.h"

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

fw_status fw_mkdir_own(const char *path, const char *what, fw_error *err)
{
    if (mkdir(path, 0777) == 0)
        return FW_OK;
    int e = errno;
    struct stat sb;
    if (e != EEXIST || lstat(path, &sb) != 0)
        return fw_fail(err, FW_EINPUT, "%s %s: cannot create the directory: %s", what, path,
                       strerror(e));
    if (S_ISLNK(sb.st_mode))
        return fw_fail(err, FW_EINPUT,
                       "%s %s: a symlink, not a directory fairway made; not writing through it",
                       what, path);
    if (!S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s %s: not a directory", what, path);
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

fw_status fw_path_copy(char *dst, size_t n, const char *path, fw_error *err)
{
    if ((size_t)snprintf(dst, n, "%s", path) >= n)
        return fw_fail(err, FW_EINPUT, "%s: path longer than %zu characters", path, n - 1);
    return FW_OK;
}

bool fw_file_is_stream(const char *path)
{
    if (strcmp(path, "-") == 0 || strncmp(path, "/dev/", 5) == 0 ||
        strncmp(path, "/proc/", 6) == 0)
        return true;
    struct stat sb;
    return stat(path, &sb) == 0 && !S_ISREG(sb.st_mode) && !S_ISDIR(sb.st_mode);
}

/* The mode the finished file gets: a regular file's own (lstat: never the
 * mode of what a symlink points to), else what fopen would give. */
static mode_t target_mode(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) == 0 && S_ISREG(sb.st_mode))
        return sb.st_mode & 07777;
    mode_t um = umask(0);
    umask(um);
    return 0666 & ~um;
}

/* The temporary name of a file begun (files.h): DIR/.NAME.fairway-tmp.PID.XXXXXX
 * beside path (NAME cut to 200 bytes: the whole within a file name's 255),
 * for a stream DIR/.fairway-out.fairway-tmp.PID.XXXXXX in $TMPDIR (else
 * /tmp); what killed writers left there removed first (core/leftover.h). */
static fw_status tmp_name(const char *path, bool stream, char *tmp, size_t n, fw_error *err)
{
    const char *td = getenv("TMPDIR");
    const char *slash = strrchr(path, '/');
    char dir[1100];
    const char *base = "fairway-out";
    if (stream)
        snprintf(dir, sizeof dir, "%s", td && *td ? td : "/tmp");
    else if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if ((size_t)snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path),
                              path) >= sizeof dir)
        return fw_fail(err, FW_EINPUT, "%.100s...: path too long", path);
    if (!stream)
        base = slash ? slash + 1 : path;
    if (fw_path(tmp, n, err, "%s%s.%.200s.fairway-tmp.%ld.XXXXXX", dir,
                strcmp(dir, "/") == 0 ? "" : "/", base[0] ? base : "out", (long)getpid()))
        return err->status;
    fw_leftover_clean_files(dir);
    return FW_OK;
}

FILE *fw_file_begin(const char *path, char *tmp, size_t n, fw_error *err)
{
    bool stream = fw_file_is_stream(path);
    if (tmp_name(path, stream, tmp, n, err)) {
        tmp[0] = '\0'; /* fw_file_abort removes nothing */
        return NULL;
    }
    int fd = mkstemp(tmp);
    FILE *f = fd >= 0 && (stream || fchmod(fd, target_mode(path)) == 0) ? fdopen(fd, "w+b")
                                                                         : NULL;
    if (!f) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
            unlink(tmp);
        }
        tmp[0] = '\0';
        fw_fail(err, FW_EINPUT, "%s: cannot write: %s", path, strerror(e));
    }
    return f;
}

void fw_file_abort(FILE *f, const char *tmp)
{
    if (f)
        fclose(f);
    if (tmp && tmp[0])
        unlink(tmp);
}

FILE *fw_file_create(const char *path, fw_error *err)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
            unlink(path);
        }
        fw_fail(err, FW_ERUN, "cannot create %s: %s", path, strerror(e));
    }
    return f;
}

/* Copies the finished temporary file f to the stream path: standard output
 * for "-", else the device opened as it is (never created or truncated). */
static int copy_to_stream(FILE *f, const char *path)
{
    fflush(stdout);
    int fd = strcmp(path, "-") == 0 ? dup(STDOUT_FILENO)
                                    : open(path, O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
    if (fd < 0 || fseek(f, 0, SEEK_SET) != 0) {
        int e = errno;
        if (fd >= 0)
            close(fd);
        return e ? e : EIO;
    }
    char buf[65536];
    size_t got;
    int e = 0;
    while (!e && (got = fread(buf, 1, sizeof buf, f)) > 0)
        if (fw_fd_write(fd, buf, got) != 0)
            e = errno ? errno : EIO;
    if (!e && ferror(f))
        e = EIO;
    if (close(fd) != 0 && !e && errno != EINTR)
        e = errno;
    return e;
}

static void sync_parent(const char *path)
{
    char *copy = strdup(path);
    int dfd = copy ? open(dirname(copy), O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
    if (dfd >= 0) {
        fsync(dfd);
        close(dfd);
    }
    free(copy);
}

fw_status fw_file_commit(FILE *f, const char *tmp, const char *path, fw_error *err)
{
    int bad = fflush(f) != 0 || ferror(f);
    int e = bad ? (errno ? errno : EIO) : 0;
    if (!bad && fw_file_is_stream(path)) {
        unlink(tmp); /* first: a reader that goes (SIGPIPE) leaves nothing behind */
        e = copy_to_stream(f, path);
        fclose(f);
        return e ? fw_fail(err, FW_ERUN, "%s: write failed: %s", path, strerror(e)) : FW_OK;
    }
    if (!bad && fsync(fileno(f)) != 0)
        bad = 1, e = errno;
    if (fclose(f) != 0 && !bad)
        bad = 1, e = errno;
    /* rename replaces a symlink at path, never writes through it */
    if (bad || rename(tmp, path) != 0) {
        e = bad ? e : errno;
        unlink(tmp);
        return fw_fail(err, FW_ERUN, "%s: write failed: %s", path, strerror(e));
    }
    sync_parent(path);
    return FW_OK;
}

fw_status fw_file_read(const char *path, char **data, size_t *n, fw_error *err)
{
    *data = NULL;
    *n = 0;
    FILE *f = fopen(path, "rb");
    struct stat sb;
    if (!f || fstat(fileno(f), &sb) != 0 || !S_ISREG(sb.st_mode)) {
        int e = f ? (errno ? errno : EINVAL) : errno;
        if (f)
            fclose(f);
        return fw_fail(err, FW_ERUN, "cannot read %s: %s", path, strerror(e));
    }
    char *buf = malloc((size_t)sb.st_size + 1);
    size_t got = buf ? fread(buf, 1, (size_t)sb.st_size, f) : 0;
    bool bad = !buf || got != (size_t)sb.st_size || ferror(f);
    fclose(f);
    if (bad) {
        free(buf);
        return fw_fail(err, FW_ERUN, "cannot read %s: %s", path,
                       buf ? "short read" : "out of memory");
    }
    buf[got] = '\0';
    *data = buf;
    *n = got;
    return FW_OK;
}

fw_status fw_file_write(const char *path, const void *data, size_t n, fw_error *err)
{
    char tmp[PATH_MAX + 32];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err ? err->status : FW_EINPUT;
    if (n > 0 && fwrite(data, 1, n, f) != n) {
        fw_file_abort(f, tmp);
        return fw_fail(err, FW_ERUN, "%s: write failed", path);
    }
    return fw_file_commit(f, tmp, path, err);
}

fw_status fw_check_run_dir(const char *opt, const char *dst, fw_error *err)
{
    char p[PATH_MAX + 16];
    struct stat sb;
    if (lstat(dst, &sb) != 0)
        return FW_OK;
    if (!S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s: %s exists and is not a run directory (%s): "
                       "not replacing it", opt, dst, S_ISLNK(sb.st_mode) ? "a symlink" : "not a directory");
    bool ours = false;
    for (int i = 0; i < 2 && !ours; i++)
        ours = !fw_path(p, sizeof p, NULL, "%s/%s", dst, i ? "own.csv" : "run.log") &&
               lstat(p, &sb) == 0 && S_ISREG(sb.st_mode);
    DIR *d = ours ? NULL : opendir(dst);
    bool empty = true;
    for (struct dirent *e; d && empty && (e = readdir(d));)
        empty = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
    if (d)
        closedir(d);
    if (!ours && !empty)
        return fw_fail(err, FW_EINPUT, "%s: %s is not a run directory of fairway (no run.log "
                       "in it): not replacing it", opt, dst);
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

fw_status fw_read_text(const char *path, char **text, size_t *len, fw_error *err)
{
    *text = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot read: %s", path, strerror(errno));
    char *buf = NULL;
    size_t n = 0, cap = 0, got;
    char chunk[8192];
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) {
        if (n + got + 1 > cap) {
            cap = 2 * (n + got + 1);
            char *p = realloc(buf, cap);
            if (!p) {
                free(buf);
                fclose(f);
                return fw_fail(err, FW_ERUN, "%s: out of memory", path);
            }
            buf = p;
        }
        memcpy(buf + n, chunk, got);
        n += got;
    }
    bool bad = ferror(f);
    fclose(f);
    if (bad || (!buf && !(buf = calloc(1, 1)))) {
        free(buf);
        return fw_fail(err, bad ? FW_EINPUT : FW_ERUN, "%s: cannot read", path);
    }
    buf[n] = '\0';
    *text = buf;
    if (len)
        *len = n;
    return FW_OK;
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

/* Where the data are, worked out once (fw_data_root in files.h). */
static char g_root[PATH_MAX], g_mod[PATH_MAX];
static pthread_once_t g_located = PTHREAD_ONCE_INIT;

/* Is path inside dir (both resolved)? */
static bool inside(const char *path, const char *dir)
{
    char d[PATH_MAX];
    if (!realpath(dir, d))
        return false;
    size_t n = strlen(d);
    return strncmp(path, d, n) == 0 && (path[n] == '/' || path[n] == '\0');
}

static void locate(void)
{
    /* PREFIX: the directory above the (resolved) executable's own */
    char exe[PATH_MAX], bin[PATH_MAX], prefix[PATH_MAX] = "/usr", share[PATH_MAX + 32];
    bool have_exe = realpath("/proc/self/exe", exe) != NULL;
    if (have_exe) {
        memcpy(bin, exe, sizeof bin);
        const char *p = dirname(dirname(bin));
        snprintf(prefix, sizeof prefix, "%s", strcmp(p, "/") ? p : "");
    }
    snprintf(share, sizeof share, "%s/share/fairway", prefix);
    char marker[PATH_MAX + 64];
    snprintf(marker, sizeof marker, "%s/networks/ships.add.xml", share);
    bool installed = access(marker, R_OK) == 0;
    if (!installed && have_exe && inside(exe, FAIRWAY_BUILD_DIR)) {
        snprintf(g_root, sizeof g_root, "%s", FAIRWAY_DATA_DIR);
        snprintf(g_mod, sizeof g_mod, "%s", FAIRWAY_MODULE_DIR);
        return;
    }
    snprintf(g_root, sizeof g_root, "%.*s", PATH_MAX - 1, share);
    snprintf(g_mod, sizeof g_mod, "%.*s/lib/fairway", PATH_MAX - 16, prefix);
}

/* FAIRWAY_DATA made absolute: the paths under it are handed to programs
 * that run in other directories (netconvert in the run's, sumo-gui reading
 * run.sumocfg), where a relative one would name nothing.  Resolved again only
 * when the variable changes. */
static const char *absolute_env(const char *env)
{
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static char seen[PATH_MAX], resolved[PATH_MAX];
    pthread_mutex_lock(&lock);
    if (strcmp(seen, env) != 0) {
        snprintf(seen, sizeof seen, "%s", env);
        if (env[0] == '/' || !realpath(env, resolved))
            snprintf(resolved, sizeof resolved, "%s", env); /* as given: its errors name it */
    }
    pthread_mutex_unlock(&lock);
    return resolved;
}

const char *fw_data_root(void)
{
    const char *env = getenv("FAIRWAY_DATA");
    if (env && env[0])
        return absolute_env(env);
    pthread_once(&g_located, locate);
    return g_root;
}

const char *fw_module_dir(void)
{
    pthread_once(&g_located, locate);
    return g_mod;
}
