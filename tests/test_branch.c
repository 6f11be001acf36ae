/* test_branch.c - snapshot and restore of a running run (src/run/branch.h).
 *
 * For each source kind (kinematic: the paper's case 3 without SUMO; recorded
 * tracks: the AIS example replayed; SUMO embedded: the default study's base
 * scenario, shortened, with its survey, its reacting traffic and the FCD; the
 * paper's case 3 through SUMO; the AIS example shown in SUMO),
 * a run is snapshotted at three steps, goes on past the snapshot (once to its
 * very end, closed, so that its encounters.csv and summary.json exist), is
 * restored and finished by the restored copy: every file of the run directory
 * (sumo/ included) must be byte-identical to the unbranched run's.  Also: two
 * branches from one snapshot, the refusals, and that no process is left
 * behind, a paused copy included when the process that took it is killed.
 */
#define _GNU_SOURCE /* prctl */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/clock.h"
#include "run/branch.h"
#include "run/run.h"
#include "test.h"
#include "test_tmp.h"

static char tmp_root[256];
static fw_scenario scn; /* large: a ship inside */

typedef struct kind {
    const char *name, *file;
    fw_run_traffic traffic;
    double duration; /* s, 0: the scenario's */
    bool fcd;
} kind;

static const kind kKinds[] = {
    {"kinematic", "scenarios/paper/3-crossing.yaml", FW_RUN_TRAFFIC_KINEMATIC, 0, false},
    {"tracks", "scenarios/ais/ais-crossing.yaml", FW_RUN_TRAFFIC_KINEMATIC, 900, false},
    {"sumo", "scenarios/traffic/dover-crossing.yaml", FW_RUN_TRAFFIC_SUMO, 900, true},
    /* SUMO embedded with explicit targets on lanes netconvert built, and the
     * AIS replay shown in SUMO (source_mirror.h: ships fairway places) */
    {"sumo-paper", "scenarios/paper/3-crossing.yaml", FW_RUN_TRAFFIC_SUMO, 0, true},
    {"ais-sumo", "scenarios/ais/ais-crossing.yaml", FW_RUN_TRAFFIC_SUMO, 600, false},
};

static bool load(const kind *k)
{
    char path[512];
    const char *root = getenv("FAIRWAY_DATA");
    snprintf(path, sizeof path, "%s/%s", root ? root : ".", k->file);
    fw_error err = {0};
    fw_status st = fw_scenario_load(path, &scn, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    if (k->duration > 0)
        scn.duration = k->duration;
    scn.fcd = k->fcd;
    return st == FW_OK;
}

static fw_run_def run_def(const kind *k, const char *dir)
{
    fw_run_def d = fw_default_run_def();
    d.scenario = &scn;
    d.dir = dir;
    d.traffic = k->traffic;
    mkdir(dir, 0777);
    return d;
}

/* Steps r to step n (or its end). */
static fw_status step_to(fw_run *r, long n, fw_error *err)
{
    fw_status st = FW_OK;
    while (!st && !fw_run_done(r) && fw_run_steps(r) < n)
        st = fw_run_step(r, err);
    return st;
}

static fw_status finish(fw_run *r, fw_error *err)
{
    fw_run_summary sum;
    fw_encounter *e;
    int ne;
    fw_status st = step_to(r, 1L << 40, err);
    fw_status cst = fw_run_close(r, &sum, &e, &ne, err);
    free(e);
    return st ? st : cst;
}

/* ---- comparing two run directories, file by file ---- */

static long file_bytes(const char *path, char **buf)
{
    FILE *f = fopen(path, "rb");
    *buf = NULL;
    if (!f)
        return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    *buf = malloc((size_t)n + 1);
    if (*buf && fread(*buf, 1, (size_t)n, f) != (size_t)n)
        n = -1;
    if (*buf && n >= 0)
        (*buf)[n] = '\0';
    fclose(f);
    return n;
}

/* SUMO's log says how long its loading took ("done (5ms)"): wall time, which
 * differs between any two runs; those digits are taken out (sumo.log is in
 * no digest for that reason).  Returns the new
 * length. */
static long mask_ms(char *s)
{
    char *w = s;
    for (char *p = s; *p; p++) {
        bool timing = *p >= '0' && *p <= '9';
        char *q = p;
        while (timing && *q >= '0' && *q <= '9')
            q++;
        if (timing && strncmp(q, "ms)", 3) == 0) {
            p = q - 1;
            continue;
        }
        *w++ = *p;
    }
    *w = '\0';
    return (long)(w - s);
}

/* The run directory's own path in SUMO's log (a network built into it) is
 * not the run's doing: taken out too.  Returns the new length. */
static long mask_dir(char *s, const char *dir)
{
    size_t n = strlen(dir);
    char *w = s;
    for (char *p = s; *p;)
        if (n > 0 && strncmp(p, dir, n) == 0)
            p += n;
        else
            *w++ = *p++;
    *w = '\0';
    return (long)(w - s);
}

/* Every file under a is in b with the same bytes (sumo.log masked, see above;
 * ra and rb: the run directories); returns the number of files seen. */
static int same_tree(const char *a, const char *b, const char *ra, const char *rb,
                     const char *what)
{
    DIR *d = opendir(a);
    CHECK_MSG(d != NULL, "%s: cannot read %s", what, a);
    if (!d)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        char pa[1024], pb[1024];
        snprintf(pa, sizeof pa, "%s/%s", a, e->d_name);
        snprintf(pb, sizeof pb, "%s/%s", b, e->d_name);
        struct stat sb;
        if (stat(pa, &sb) == 0 && S_ISDIR(sb.st_mode)) {
            n += same_tree(pa, pb, ra, rb, what);
            continue;
        }
        char *x, *y;
        long nx = file_bytes(pa, &x), ny = file_bytes(pb, &y);
        if (!strcmp(e->d_name, "sumo.log") && nx > 0 && ny > 0) {
            mask_dir(x, ra);
            mask_dir(y, rb);
            nx = mask_ms(x);
            ny = mask_ms(y);
        }
        CHECK_MSG(nx >= 0 && nx == ny && memcmp(x, y, (size_t)nx) == 0,
                  "%s: %s differs from %s (%ld and %ld bytes)", what, pb, pa, nx, ny);
        free(x);
        free(y);
        n++;
    }
    closedir(d);
    return n;
}

/* a and b hold the same files with the same bytes. */
static void same_dirs(const char *ref, const char *got, const char *what)
{
    int n = same_tree(ref, got, ref, got, what);
    int m = same_tree(got, ref, got, ref, what); /* and nothing more in got */
    CHECK_MSG(n == m && n >= 5, "%s: %d files against %d", what, m, n);
}

/* ---- the branched runs ---- */

/* In the restored copy: finish the run and end the process with its status
 * (the copy must never return into the test's own code further up). */
static void branch_finish(fw_run *r, uint32_t want_branch)
{
    fw_error err = {0};
    int code = fw_run_branch(r) != want_branch ? 3 : finish(r, &err) ? 2 : 0;
    if (code)
        fprintf(stderr, "branch: %s\n", err.msg);
    fflush(NULL);
    _exit(code);
}

/* Runs k into dir: snapshot at step at, on for `more` steps (to the end and
 * closed when more < 0), restore (branch 0), the copy finishes. */
static void branched(const kind *k, const char *dir, long at, long more)
{
    fw_run_def d = run_def(k, dir);
    fw_error err = {0};
    fw_run *r;
    fw_status st = fw_run_open(&d, &r, &err);
    if (!st)
        st = step_to(r, at, &err);
    CHECK_MSG(st == FW_OK && fw_run_steps(r) == at, "%s: %s", dir, err.msg);
    fw_snapshot *snap = NULL;
    if (!st)
        st = fw_run_snapshot(r, &snap, &err);
    CHECK_MSG(st == FW_OK, "%s: snapshot: %s", dir, err.msg);
    if (!st && !snap)
        branch_finish(r, 0);
    if (st) {
        fw_run_discard(r);
        return;
    }
    CHECK_NEAR(fw_snapshot_time(snap), at * scn.step, 1e-9);
    if (more < 0) {
        st = finish(r, &err); /* the abandoned branch ends and writes its files */
        CHECK_MSG(st == FW_OK, "%s: %s", dir, err.msg);
        r = NULL;
    } else {
        st = step_to(r, at + more, &err);
        CHECK_MSG(st == FW_OK, "%s: %s", dir, err.msg);
    }
    int code = -1;
    st = fw_run_restore(r, snap, 0, &code, &err);
    CHECK_MSG(st == FW_OK && code == 0, "%s: restore: %s (exit %d)", dir, err.msg, code);
    fw_snapshot_free(snap);
}

static void test_kind(const kind *k)
{
    if (!load(k))
        return;
    char ref[512], dir[512];
    snprintf(ref, sizeof ref, "%s/%s-ref", tmp_root, k->name);
    fw_run_def d = run_def(k, ref);
    fw_error err = {0};
    fw_run *r;
    fw_status st = fw_run_open(&d, &r, &err);
    long n = lround(scn.duration / scn.step);
    if (st)
        fw_run_discard(r);
    else
        st = finish(r, &err);
    CHECK_MSG(st == FW_OK, "%s: %s", k->name, err.msg);
    /* three instants; past the first a few steps, past the second a third of
     * the run, past the last to the end (its files closed and written) */
    const long at[3] = {n / 10, n / 2, 4 * n / 5};
    const long more[3] = {7, n / 3, -1};
    for (int i = 0; i < 3; i++) {
        snprintf(dir, sizeof dir, "%s/%s-%ld", tmp_root, k->name, at[i]);
        branched(k, dir, at[i], more[i]);
        char what[600];
        snprintf(what, sizeof what, "%s snapshot at step %ld of %ld", k->name, at[i], n);
        same_dirs(ref, dir, what);
    }
}

static void test_kinds(void)
{
    for (size_t i = 0; i < sizeof kKinds / sizeof *kKinds; i++)
        test_kind(&kKinds[i]);
}

/* Two branches from one snapshot, one after another, each with the number
 * its restore gave: the second's files are the unbranched run's as well. */
static void test_two_branches(void)
{
    const kind *k = &kKinds[0];
    if (!load(k))
        return;
    char ref[512], dir[512];
    snprintf(ref, sizeof ref, "%s/%s-ref", tmp_root, k->name);
    snprintf(dir, sizeof dir, "%s/%s-twice", tmp_root, k->name);
    fw_run_def d = run_def(k, dir);
    fw_error err = {0};
    fw_run *r;
    fw_status st = fw_run_open(&d, &r, &err);
    st = st ? st : step_to(r, 300, &err);
    fw_snapshot *snap = NULL;
    st = st ? st : fw_run_snapshot(r, &snap, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    if (st)
        return;
    if (!snap) { /* says which branch it is by its exit code: 10 + its number */
        int b = (int)fw_run_branch(r);
        fw_status fst = finish(r, &err); /* frees r */
        fflush(NULL);
        _exit(fst ? 2 : 10 + b);
    }
    st = step_to(r, 400, &err);
    /* a file the abandoned branch makes goes with it */
    char extra[600];
    snprintf(extra, sizeof extra, "%s/abandoned.txt", dir);
    FILE *f = fopen(extra, "w");
    CHECK(f && fputs("made after the snapshot\n", f) >= 0 && fclose(f) == 0);
    int code = -1;
    st = st ? st : fw_run_restore(r, snap, 5, &code, &err);
    CHECK_MSG(st == FW_OK && code == 15, "%s (exit %d)", err.msg, code);
    CHECK(access(extra, F_OK) != 0);
    same_dirs(ref, dir, "the first of two branches");
    st = fw_run_restore(NULL, snap, 0, &code, &err);
    CHECK_MSG(st == FW_OK && code == 10, "%s (exit %d)", err.msg, code);
    same_dirs(ref, dir, "the second of two branches");
    fw_snapshot_free(snap);
}

/* The summaries' measures that a branch must give as the unbranched run
 * did (wall_s and sumo_s are clocks). */
static bool same_summary(const fw_run_summary *a, const fw_run_summary *b)
{
    return a->status == b->status && a->t_end == b->t_end && a->n_encounters == b->n_encounters &&
           a->min_dist == b->min_dist && a->min_hull == b->min_hull &&
           !strcmp(a->min_dist_id, b->min_dist_id) && a->acted == b->acted &&
           a->t_act == b->t_act && a->act_helm == b->act_helm && a->max_helm == b->max_helm &&
           a->path_length == b->path_length && a->cross_track == b->cross_track &&
           a->heading_error == b->heading_error && a->rudder_work == b->rudder_work &&
           a->helm_orders == b->helm_orders && a->n_actions == b->n_actions;
}

/* A run without files (def.dir NULL: what a splitting driver would run): the
 * branch's summary is the unbranched run's, to the bit (the branch compares
 * and says so by its exit code), and the result it leaves reaches the owner. */
static void test_no_files(void)
{
    const kind *k = &kKinds[0];
    if (!load(k))
        return;
    fw_run_def d = fw_default_run_def();
    d.scenario = &scn;
    d.traffic = k->traffic;
    fw_error err = {0};
    fw_run *r;
    fw_run_summary ref, got;
    fw_encounter *e;
    int ne;
    fw_status st = fw_run_open(&d, &r, &err);
    while (!st && !fw_run_done(r))
        st = fw_run_step(r, &err);
    st = fw_run_close(r, &ref, &e, &ne, &err) || st;
    free(e);
    CHECK_MSG(st == FW_OK && ref.acted, "%s", err.msg);
    fw_snapshot *snap = NULL;
    st = fw_run_open(&d, &r, &err);
    st = st ? st : step_to(r, 200, &err);
    st = st ? st : fw_run_snapshot(r, &snap, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    if (st)
        return;
    if (!snap) { /* leaves its time and steps at the end as its result */
        st = step_to(r, 1L << 40, &err);
        double res[2] = {fw_run_time(r), (double)fw_run_steps(r)};
        st = st ? st : fw_run_result(r, res, sizeof res, &err);
        st = fw_run_close(r, &got, &e, &ne, &err) || st;
        free(e);
        _exit(st == FW_OK && same_summary(&got, &ref) ? 0 : 7);
    }
    double mine = 1.0;
    CHECK(fw_run_result(r, &mine, sizeof mine, &err) == FW_EINPUT); /* not a branch */
    st = step_to(r, 600, &err);
    int code = -1;
    st = st ? st : fw_run_restore(r, snap, 0, &code, &err);
    CHECK_MSG(st == FW_OK && code == 0, "%s (exit %d: 7 = the summaries differ)", err.msg, code);
    size_t n = 0;
    const double *res = fw_snapshot_result(snap, &n);
    CHECK(n == 2 * sizeof *res);
    if (n == 2 * sizeof *res) {
        CHECK_NEAR(res[0], scn.duration, 1e-9);
        CHECK_NEAR(res[1], lround(scn.duration / scn.step), 0.0);
    }
    fw_snapshot_free(snap);
}

/* Two snapshots outstanding, the earlier restored (the later one paused
 * meanwhile); in that branch a snapshot of its own, restored in turn: a
 * branch of a branch.  The files are the unbranched run's. */
static void test_nested(void)
{
    const kind *k = &kKinds[0];
    if (!load(k))
        return;
    char ref[512], dir[512];
    snprintf(ref, sizeof ref, "%s/%s-ref", tmp_root, k->name);
    snprintf(dir, sizeof dir, "%s/%s-nested", tmp_root, k->name);
    fw_run_def d = run_def(k, dir);
    fw_error err = {0};
    fw_run *r;
    fw_snapshot *a = NULL, *b = NULL;
    fw_status st = fw_run_open(&d, &r, &err);
    st = st ? st : step_to(r, 100, &err);
    st = st ? st : fw_run_snapshot(r, &a, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    if (st)
        return;
    if (!a) { /* the branch from a: a snapshot of its own at 500, on to 700, back */
        fw_snapshot *c = NULL;
        if (step_to(r, 500, &err) || fw_run_snapshot(r, &c, &err))
            _exit(4);
        if (!c)
            branch_finish(r, 2);
        int code = -1;
        if (step_to(r, 700, &err) || fw_run_restore(r, c, 2, &code, &err))
            _exit(5);
        fw_snapshot_free(c);
        _exit(code);
    }
    st = step_to(r, 200, &err);
    st = st ? st : fw_run_snapshot(r, &b, &err);
    if (!st && !b)
        _exit(6); /* never restored */
    st = st ? st : step_to(r, 250, &err);
    int code = -1;
    st = st ? st : fw_run_restore(r, a, 1, &code, &err);
    CHECK_MSG(st == FW_OK && code == 0, "%s (exit %d)", err.msg, code);
    same_dirs(ref, dir, "a branch of a branch");
    fw_snapshot_free(b);
    fw_snapshot_free(a);
}

/* A run with SUMO in another process is refused, and a snapshot is restored
 * only by its owner. */
static void test_refusals(void)
{
    const kind *k = &kKinds[0];
    if (!load(k))
        return;
    char dir[512];
    snprintf(dir, sizeof dir, "%s/refusals", tmp_root);
    fw_run_def d = run_def(k, dir);
    fw_error err = {0};
    fw_run *r;
    fw_status st = fw_run_open(&d, &r, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    fw_snapshot *snap = NULL;
    st = st ? st : fw_run_snapshot(r, &snap, &err);
    if (!st && !snap)
        _exit(0); /* never restored */
    fflush(NULL);
    pid_t p = fork();
    if (p == 0) { /* not the owner */
        int code;
        _exit(fw_run_restore(NULL, snap, 0, &code, &err) == FW_EINPUT ? 0 : 1);
    }
    int status = -1;
    waitpid(p, &status, 0);
    fflush(NULL);
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0,
              "a process other than the owner restored a snapshot");
    CHECK(fw_snapshot_step(snap) == 0);
    /* a paused copy that has gone: an error, not SIGPIPE */
    kill(fw_snapshot_pid(snap), SIGKILL);
    int code = -1;
    CHECK(fw_run_restore(NULL, snap, 0, &code, &err) == FW_ERUN && code == -1);
    CHECK_MSG(strstr(err.msg, "has gone") != NULL, "%s", err.msg);
    fw_snapshot_free(snap);
    fw_run_discard(r);
    /* the refusal is decided on the run's definition: SUMO through libtraci */
    fw_run_def rd = run_def(&kKinds[2], dir);
    rd.mode.kind = FW_TRAFFIC_REMOTE;
    CHECK(fw_run_def_unforkable(&rd) != NULL);
    rd.mode.kind = FW_TRAFFIC_GUI;
    CHECK(fw_run_def_unforkable(&rd) != NULL);
    rd.mode.kind = FW_TRAFFIC_EMBEDDED;
    CHECK(fw_run_def_unforkable(&rd) == NULL);
    rd.traffic = FW_RUN_TRAFFIC_KINEMATIC;
    rd.mode.kind = FW_TRAFFIC_REMOTE;
    CHECK(fw_run_def_unforkable(&rd) == NULL);
}

/* The process that took a snapshot is killed: its paused copy ends by itself
 * (this process is made the orphans' reaper to see it go). */
static void test_owner_killed(void)
{
    const kind *k = &kKinds[0];
    if (!load(k))
        return;
    CHECK(prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
    int ready[2];
    CHECK(pipe(ready) == 0);
    fflush(NULL);
    pid_t owner = fork();
    if (owner == 0) {
        close(ready[0]);
        char dir[512];
        snprintf(dir, sizeof dir, "%s/killed", tmp_root);
        fw_run_def d = run_def(k, dir);
        fw_error err = {0};
        fw_run *r;
        fw_snapshot *snap[3] = {0};
        if (fw_run_open(&d, &r, &err))
            _exit(1);
        for (int i = 0; i < 3; i++) /* three paused copies */
            if (step_to(r, 50 * (i + 1), &err) || fw_run_snapshot(r, &snap[i], &err) ||
                !snap[i])
                _exit(1);
        if (write(ready[1], "x", 1) != 1)
            _exit(1);
        pause(); /* until killed */
        _exit(1);
    }
    close(ready[1]);
    char c;
    CHECK(read(ready[0], &c, 1) == 1);
    close(ready[0]);
    kill(owner, SIGKILL);
    int status;
    CHECK(waitpid(owner, &status, 0) == owner && WIFSIGNALED(status));
    /* the three copies, now this process's children, go within seconds */
    int gone = 0;
    double t0 = fw_clock_s();
    while (fw_clock_s() - t0 < 20.0) {
        pid_t p = waitpid(-1, &status, WNOHANG);
        if (p > 0) {
            gone++;
            CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        } else if (p < 0 && errno == ECHILD)
            break;
        else
            nanosleep(&(struct timespec){.tv_nsec = 10000000L}, NULL);
    }
    CHECK_MSG(gone == 3, "%d of the 3 paused copies ended after their owner was killed", gone);
    prctl(PR_SET_CHILD_SUBREAPER, 0);
}

int main(void)
{
    if (test_tmpdir("branch", tmp_root, sizeof tmp_root))
        return 1;
    TEST_RUN(test_kinds);
    TEST_RUN(test_two_branches);
    TEST_RUN(test_nested);
    TEST_RUN(test_no_files);
    TEST_RUN(test_refusals);
    TEST_RUN(test_owner_killed);
    /* no process of ours is left: every copy and branch reaped */
    errno = 0;
    CHECK_MSG(waitpid(-1, NULL, WNOHANG) < 0 && errno == ECHILD, "a child process is left");
    return TEST_EXIT();
}
