/* report.c - fairway report from database to directory.
 *
 * The directory is built as a hidden sibling (.NAME.tmp.PID) and renamed into
 * place at the end, so a report that fails part way leaves no half-written
 * directory and an old report survives until the new one is complete.  The
 * plots are drawn by a separate Python process (analysis/plot_study.py) from
 * the CSVs just written: a plotting failure costs the pictures, never the
 * numbers.
 */
#define _XOPEN_SOURCE 700
#include "study/report.h"

#include <dirent.h>
#include <errno.h>
#include <ftw.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include "core/files.h"
#include "core/leftover.h"
#include "ship/ship.h"
#include "study/report_data.h"

fw_study_report_def fw_default_study_report_def(void)
{
    fw_study_report_def d = {0};
    d.reference_m = NAN;
    d.level = 0.95;
    d.plots = true;
    return d;
}

fw_status fw_study_report_load(const fw_study_report_def *def, fw_study_report **out,
                               fw_error *err)
{
    *out = NULL;
    if (!def->db || !def->db[0])
        return fw_fail(err, FW_EINPUT, "no study database given");
    if (!(def->level > 0.0 && def->level < 1.0))
        return fw_fail(err, FW_EINPUT, "confidence level %g is not between 0 and 1", def->level);
    if (strlen(def->db) >= sizeof((fw_study_report *)0)->db)
        return fw_fail(err, FW_EINPUT, "%.100s...: path too long", def->db);
    fw_study_report *rep = calloc(1, sizeof *rep);
    if (!rep)
        return fw_fail(err, FW_ERUN, "out of memory");
    rep->level = def->level;
    if (fw_rep_load(rep, def->db, err) || fw_rep_compute(rep, def->reference_m, err)) {
        fw_study_report_free(rep);
        return err->status;
    }
    *out = rep;
    return FW_OK;
}

static void free_counts(fw_rep_count *c, int n)
{
    for (int i = 0; i < n; i++)
        free(c[i].text);
    free(c);
}

void fw_study_report_free(fw_study_report *rep)
{
    if (!rep)
        return;
    for (int g = 0; g < rep->n_groups; g++)
        for (int s = 0; s < FW_REP_NSET; s++) {
            free(rep->groups[g].hist[s]);
            for (int t = 0; t < FW_REP_NTYPE; t++)
                free(rep->groups[g].cpa[s][t].v);
        }
    free(rep->groups);
    free(rep->runs);
    free(rep->pairs);
    free(rep->bpairs);
    free(rep->spairs);
    free(rep->splits);
    free_counts(rep->meta, rep->n_meta);
    free_counts(rep->audit_notes, rep->n_audit_notes);
    free_counts(rep->reasons, rep->n_reasons);
    free_counts(rep->warnings, rep->n_warnings);
    free(rep);
}

/* Files and directories */

/* snprintf that says whether the whole text fitted: a cut path would name
 * another file. */
static bool fit(char *out, size_t sz, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static bool fit(char *out, size_t sz, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(out, sz, fmt, ap);
    va_end(ap);
    return n >= 0 && (size_t)n < sz;
}

static int rm_one(const char *path, const struct stat *sb, int flag, struct FTW *ftw)
{
    (void)sb;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static void rm_tree(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) == 0)
        nftw(path, rm_one, 16, FTW_DEPTH | FTW_PHYS);
}

static fw_status mkdirs(const char *dir, fw_error *err)
{
    char buf[1024];
    if (!fit(buf, sizeof buf, "%s", dir))
        return fw_fail(err, FW_EINPUT, "--out %s: path too long", dir);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            mkdir(buf, 0777);
            *p = '/';
        }
    struct stat sb;
    if (mkdir(buf, 0777) != 0 && (stat(buf, &sb) != 0 || !S_ISDIR(sb.st_mode)))
        return fw_fail(err, FW_EINPUT, "%s: cannot create the directory", dir);
    return FW_OK;
}

/* The files a report writes (report_csv.c, report_md.c, the plots of
 * analysis/plot_study.py and its log): all a report directory may hold. */
static bool report_file(const char *name)
{
    static const char *const own[] = {"report.md",   "runs.csv",     "summary.csv",
                                      "traffic.csv", "cpa.csv",      "cpa_hist.csv",
                                      "causation.csv", "audit.csv",  "paired.csv",
                                      "behaviour.csv", "behaviour.png", "plot.log",
                                      "splits.csv", "settings.csv"};
    for (size_t i = 0; i < sizeof own / sizeof own[0]; i++)
        if (strcmp(name, own[i]) == 0)
            return true;
    for (int i = 0; i < fw_rep_n_plots; i++)
        if (strcmp(name, fw_rep_plots[i]) == 0)
            return true;
    return false;
}

/* An existing target is replaced (as a whole, by a rename) only if it is
 * empty or holds nothing but a report's own files: anything else in it, a
 * file of the user's, a symlink or a directory, would be deleted with the old
 * report, so the target is refused, naming the first such entry. */
static fw_status check_target(const char *out, bool *exists, fw_error *err)
{
    struct stat sb;
    *exists = lstat(out, &sb) == 0;
    if (!*exists)
        return FW_OK;
    if (!S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s exists and is not a directory", out);
    DIR *d = opendir(out);
    if (!d)
        return fw_fail(err, FW_EINPUT, "%s: cannot read the directory", out);
    fw_status st = FW_OK;
    for (struct dirent *e; !st && (e = readdir(d));) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        char p[1400];
        bool own = report_file(e->d_name) && fit(p, sizeof p, "%s/%s", out, e->d_name) &&
                   lstat(p, &sb) == 0 && S_ISREG(sb.st_mode);
        if (!own)
            st = fw_fail(err, FW_EINPUT,
                         "%.400s is not a fairway report directory: it holds %.200s, not a "
                         "file of a report (not replacing it: give another --out)",
                         out, e->d_name);
    }
    closedir(d);
    return st;
}

/* The default directory: <db stem>-report beside the database. */
static bool default_out(const char *db, char *out, size_t sz)
{
    char buf[1024];
    if (!fit(buf, sizeof buf, "%s", db))
        return false;
    char *slash = strrchr(buf, '/');
    char *base = slash ? slash + 1 : buf;
    char *dot = strrchr(base, '.');
    if (dot && dot != base)
        *dot = '\0';
    return fit(out, sz, "%s-report", buf);
}

/* Splits "a/b/name" into parent "a/b" (or ".") and "name". */
static void split_path(const char *path, char *parent, size_t psz, char *name, size_t nsz)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    size_t n = strlen(buf);
    while (n > 1 && buf[n - 1] == '/')
        buf[--n] = '\0';
    char *slash = strrchr(buf, '/');
    if (!slash) {
        snprintf(parent, psz, ".");
        snprintf(name, nsz, "%s", buf);
    } else {
        snprintf(name, nsz, "%s", slash + 1);
        if (slash == buf)
            slash[1] = '\0';
        else
            *slash = '\0';
        snprintf(parent, psz, "%s", buf);
    }
}

/* Plots */

static void last_line(const char *path, char *out, size_t sz)
{
    out[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (line[0])
            fit(out, sz, "%s", line);
    }
    fclose(f);
}

static void draw_plots(const fw_study_report_def *def, const fw_study_report *rep, const char *dir,
                       fw_study_report_result *res)
{
    const char *env = getenv("FAIRWAY_PYTHON");
    const char *python = def->python ? def->python : (env && env[0]) ? env : "/usr/bin/python3";
    char script[1024], logp[1400], level[32];
    if (def->script)
        fit(script, sizeof script, "%s", def->script);
    else
        fit(script, sizeof script, "%s/analysis/plot_study.py", fw_data_root());
    fit(logp, sizeof logp, "%s/plot.log", dir);
    snprintf(level, sizeof level, "%g", rep->level);
    res->plots = FW_PLOTS_FAILED;
    if (access(script, R_OK) != 0) {
        fit(res->plot_msg, sizeof res->plot_msg, "%s not found", script);
        return;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(res->plot_msg, sizeof res->plot_msg, "cannot start %s", python);
        return;
    }
    if (pid == 0) {
        /* nothing outlives a SIGKILLed fairway: the plotter dies with it */
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() == 1)
            _exit(127);
        int fd = open(logp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execlp(python, python, script, dir, "--level", level, (char *)NULL);
        fprintf(stderr, "cannot run %s: %s\n", python, strerror(errno));
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    char why[400];
    last_line(logp, why, sizeof why);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fit(res->plot_msg, sizeof res->plot_msg, "%s %s exited with %s %d%s%s (see plot.log)",
            python, script, WIFEXITED(status) ? "status" : "signal",
            WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), why[0] ? ": " : "", why);
        return;
    }
    for (int i = 0; i < fw_rep_n_plots; i++) {
        char png[1400];
        fit(png, sizeof png, "%s/%s", dir, fw_rep_plots[i]);
        if (access(png, R_OK) != 0) {
            fit(res->plot_msg, sizeof res->plot_msg, "%s did not draw %s (see plot.log)", script,
                fw_rep_plots[i]);
            return;
        }
    }
    remove(logp);
    res->plots = FW_PLOTS_DRAWN;
}

fw_status fw_study_report_write(const fw_study_report *rep, const fw_study_report_def *def,
                                fw_study_report_result *res, fw_error *err)
{
    memset(res, 0, sizeof *res);
    if (def->out && def->out[0]) {
        if (strlen(def->out) > 700)
            return fw_fail(err, FW_EINPUT, "--out: path too long");
        snprintf(res->out, sizeof res->out, "%s", def->out);
    } else if (!default_out(rep->db, res->out, sizeof res->out)) {
        return fw_fail(err, FW_EINPUT, "%.100s...: path too long", rep->db);
    }
    char parent[1024], name[256], tmp[1400], old[1400];
    split_path(res->out, parent, sizeof parent, name, sizeof name);
    bool exists;
    if (check_target(res->out, &exists, err) || mkdirs(parent, err) ||
        fw_check_parent_dir("--out", res->out, "cannot write in", err))
        return err->status;
    char prefix[300];
    if (!fit(tmp, sizeof tmp, "%s/.%s.tmp.%ld", parent, name, (long)getpid()) ||
        !fit(old, sizeof old, "%s/.%s.old.%ld", parent, name, (long)getpid()) ||
        !fit(prefix, sizeof prefix, ".%s.tmp.", name))
        return fw_fail(err, FW_EINPUT, "%.100s...: path too long", res->out);
    /* what a SIGKILLed report left (core/leftover.h), then ours, marked */
    fw_leftover_clean(parent, prefix, "an interrupted fairway report");
    rm_tree(tmp);
    if (mkdir(tmp, 0777) != 0)
        return fw_fail(err, FW_EINPUT, "--out %.400s: cannot write in %.400s: %s", res->out,
                       parent, strerror(errno));
    if (fw_leftover_mark(tmp, err)) {
        rm_tree(tmp);
        return err->status;
    }
    res->plots = FW_PLOTS_SKIPPED;
    if (fw_rep_write_csvs(rep, tmp, err)) {
        rm_tree(tmp);
        return err->status;
    }
    if (def->plots)
        draw_plots(def, rep, tmp, res);
    if (fw_rep_write_md(rep, res, tmp, err)) {
        rm_tree(tmp);
        return err->status;
    }
    /* swap: the old report is moved aside first so a failed rename can put it back */
    fw_leftover_unmark(tmp);
    rm_tree(old);
    if (exists && rename(res->out, old) != 0) {
        int e = errno;
        rm_tree(tmp);
        return fw_fail(err, FW_ERUN, "--out %.400s: cannot move the old report aside: %s",
                       res->out, strerror(e));
    }
    if (rename(tmp, res->out) != 0) {
        int e = errno;
        if (exists)
            rename(old, res->out);
        rm_tree(tmp);
        return fw_fail(err, FW_ERUN, "--out %.400s: cannot put the report in place: %s",
                       res->out, strerror(e));
    }
    rm_tree(old);
    if (res->plots == FW_PLOTS_FAILED)
        return fw_fail(err, FW_ERUN, "plotting failed: %.300s; the tables are in %.150s",
                       res->plot_msg, res->out);
    return FW_OK;
}
