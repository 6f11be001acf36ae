/* split_run.c - fairway runs as splitting's trajectories (split_run.h). */
#include "study/split_run.h"

#include <errno.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include "core/files.h"
#include "core/spawn.h"
#include "core/mem.h"
#include "study/outcome.h"

/* A re-keying: after step `step`, fairway's streams take branch number b. */
typedef struct rekey {
    long step;
    uint32_t b;
} rekey;

/* A step at which the score rose, and to what. */
typedef struct rise {
    long step;
    double score;
} rise;

typedef struct traj {
    uint64_t draw;
    int n_rekey;
    rekey *rekeys;
    int n_rise;
    rise *rises;
    double score, min_hull;
} traj;

struct fw_split_run {
    fw_split_run_def def;
    long count;
    double sim_s;
    double best;          /* the last estimate's closest trajectory */
    char best_path[2048];
};

/* What the child sends back ahead of its rises. */
typedef struct child_head {
    int32_t status;   /* fw_status */
    int32_t n_rise;
    int32_t streams;  /* random streams the world made */
    int32_t pad;
    double min_hull;
    double t_end;
    char msg[512];
} child_head;

static void traj_free(traj *t)
{
    if (!t)
        return;
    free(t->rekeys);
    free(t->rises);
    free(t);
}

/* The trajectory's score so far (split_run.h): the closeness, and below
 * the hidden level, with a watch that draws, the unseen ship's approach. */
static double split_score(const fw_split_run *S, fw_run *r)
{
    double c = fw_closeness(fw_run_min_hull(r)), q = S->def.hidden_level;
    double u = q > 0.0 ? fw_world_own_unseen(fw_run_world(r)) : -1.0;
    return u < 0.0 || c >= q ? c : q * u;
}

/* Re-keys due after step k. */
static void apply_rekeys(fw_run *r, const traj *t, long k, int *next)
{
    while (*next < t->n_rekey && t->rekeys[*next].step == k)
        (void)fw_world_rekey(fw_run_world(r), t->rekeys[(*next)++].b);
}

/* The child's part: runs t's scenario with its re-keyings into dir and
 * sends the head and the rises down fd. */
static void child_run(const fw_split_run *S, const traj *t, const char *dir, int fd)
{
    fw_scenario sc;
    S->def.scenario(S->def.ctx, t->draw, &sc);
    fw_run_def rd = S->def.run;
    rd.scenario = &sc;
    rd.dir = dir;
    fw_error err = {0};
    child_head h = {.min_hull = INFINITY};
    rise *rises = NULL;
    int cap = 0;
    fw_status st = FW_OK;
    if (S->def.make_controller)
        st = S->def.make_controller(S->def.ctx, &rd.controller, &err);
    fw_run *r = NULL;
    if (!st)
        st = fw_run_open(&rd, &r, &err);
    if (!st && S->def.opened)
        S->def.opened(S->def.ctx, r);
    int next = 0;
    double best = -1.0;
    for (long k = 0; !st; k++) {
        if (k > 0 && (st = fw_run_step(r, &err)))
            break;
        apply_rekeys(r, t, k, &next);
        double score = split_score(S, r);
        if (score > best) {
            if (!fw_reserve((void **)&rises, sizeof *rises, &cap, h.n_rise + 1)) {
                st = fw_fail(&err, FW_ERUN, "out of memory");
                break;
            }
            rises[h.n_rise++] = (rise){k, score};
            best = score;
        }
        if (fw_run_done(r))
            break;
    }
    if (r) {
        h.min_hull = fw_run_min_hull(r);
        h.t_end = fw_run_time(r);
        h.streams = fw_world_streams(fw_run_world(r));
        fw_run_summary sum;
        fw_encounter *enc = NULL;
        int n_enc = 0;
        fw_error cerr = {0};
        fw_status cst = fw_run_close(r, &sum, &enc, &n_enc, &cerr);
        free(enc);
        if (!st && cst) {
            st = cst;
            err = cerr;
        }
    }
    h.status = st;
    if (st)
        snprintf(h.msg, sizeof h.msg, "%s", err.msg);
    if (fw_fd_write(fd, &h, sizeof h) == 0 && h.n_rise > 0)
        (void)fw_fd_write(fd, rises, (size_t)h.n_rise * sizeof *rises);
    free(rises);
}

/* Simulates t (draw and re-keys set) in a child; fills its rises, score and
 * least hull distance. */
static fw_status simulate(fw_split_run *S, traj *t, fw_error *err)
{
    char dir[1100] = "";
    if (S->def.work_dir) {
        if (fw_path(dir, sizeof dir, err, "%s/traj.XXXXXX", S->def.work_dir))
            return err->status;
        if (!mkdtemp(dir))
            return fw_fail(err, FW_ERUN, "%s: cannot make a run directory: %s", S->def.work_dir,
                           strerror(errno));
    }
    pid_t pid;
    int fd;
    fw_status fst = fw_fork_piped(&pid, &fd, err);
    if (fst) {
        if (dir[0])
            fw_remove_tree(dir);
        return fst;
    }
    if (pid == 0) {
        child_run(S, t, dir[0] ? dir : NULL, fd);
        close(fd);
        _exit(0); /* the parent's atexit handlers and leak checks are its own */
    }
    child_head h;
    bool got = fw_fd_read(fd, &h, sizeof h) == 0;
    fw_status st = FW_OK;
    if (got && h.n_rise >= 0 && !h.status) {
        free(t->rises);
        t->rises = malloc((size_t)(h.n_rise ? h.n_rise : 1) * sizeof *t->rises);
        if (!t->rises)
            st = fw_fail(err, FW_ERUN, "out of memory");
        else if (fw_fd_read(fd, t->rises, (size_t)h.n_rise * sizeof *t->rises) != 0)
            got = false;
        t->n_rise = h.n_rise;
    }
    close(fd);
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    if (dir[0])
        fw_remove_tree(dir);
    if (st)
        return st;
    if (!got || !WIFEXITED(ws) || WEXITSTATUS(ws) != 0)
        return fw_fail(err, FW_ERUN, "splitting: a trajectory (draw %llu, %d re-keyings) %s",
                       (unsigned long long)t->draw, t->n_rekey,
                       WIFSIGNALED(ws) ? strsignal(WTERMSIG(ws)) : "ended without its result");
    if (h.status)
        return fw_fail(err, (fw_status)h.status, "%s", h.msg);
    if (h.streams == 0)
        return fw_fail(err, FW_EINPUT,
                       "splitting: the scenario has no randomness after t = 0 (no element of its "
                       "world draws: sensing, watchkeeping, gusts ...): every branch would repeat "
                       "its parent; count such runs (crude Monte Carlo) instead");
    t->score = t->n_rise ? t->rises[t->n_rise - 1].score : 0.0;
    t->min_hull = h.min_hull;
    S->count++;
    S->sim_s += h.t_end;
    return FW_OK;
}

static uint64_t draw64(fw_rng *r)
{
    uint64_t hi, lo;
    fw_rng_block(r, &hi, &lo);
    return hi ^ (lo << 1);
}

static fw_status start(void *ctx, fw_rng rng, fw_ams_sim *out, fw_error *err)
{
    traj *t = calloc(1, sizeof *t);
    if (!t)
        return fw_fail(err, FW_ERUN, "out of memory");
    t->draw = draw64(&rng);
    fw_status st = simulate(ctx, t, err);
    if (st) {
        traj_free(t);
        return st;
    }
    *out = (fw_ams_sim){.traj = t, .score = t->score, .cost = 1.0};
    return FW_OK;
}

static fw_status branch(void *ctx, const void *parent, double level, fw_rng rng, fw_ams_sim *out,
                        fw_error *err)
{
    const traj *p = parent;
    int i = 0;
    while (i < p->n_rise && !(p->rises[i].score > level))
        i++;
    if (i == p->n_rise)
        return fw_fail(err, FW_ERUN, "splitting: a parent (score %g) never passed level %g",
                       p->score, level);
    long at = p->rises[i].step;
    traj *t = calloc(1, sizeof *t);
    int kept = 0;
    while (kept < p->n_rekey && p->rekeys[kept].step <= at)
        kept++;
    if (t)
        t->rekeys = malloc((size_t)(kept + 1) * sizeof *t->rekeys);
    if (!t || !t->rekeys) {
        traj_free(t);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    t->draw = p->draw;
    if (kept > 0) /* a parent with no re-keys yet may have no array */
        memcpy(t->rekeys, p->rekeys, (size_t)kept * sizeof *t->rekeys);
    t->rekeys[kept] = (rekey){at, (uint32_t)draw64(&rng) | 1u};
    t->n_rekey = kept + 1;
    fw_status st = simulate(ctx, t, err);
    if (st) {
        traj_free(t);
        return st;
    }
    /* the replay is the parent to the bit up to the crossing */
    for (int j = 0; j <= i; j++)
        if (j >= t->n_rise || t->rises[j].step != p->rises[j].step ||
            t->rises[j].score != p->rises[j].score) {
            fprintf(stderr, "replay differs at rise %d: step %ld/%ld score %.9g/%.9g\n", j,
                    j < t->n_rise ? t->rises[j].step : -1, p->rises[j].step,
                    j < t->n_rise ? t->rises[j].score : -1, p->rises[j].score);
            abort();
        }
    *out = (fw_ams_sim){.traj = t, .score = t->score, .cost = 1.0};
    return FW_OK;
}

static void drop(void *ctx, void *t)
{
    (void)ctx;
    traj_free(t);
}

/* "DRAW:STEP/B,..." of t into buf (cut short, and then marked "...", when
 * it does not fit: a replay refuses it). */
static void path_text(const traj *t, char *buf, size_t n)
{
    size_t k = (size_t)snprintf(buf, n, "%llu:", (unsigned long long)t->draw);
    for (int i = 0; i < t->n_rekey && k < n; i++)
        k += (size_t)snprintf(buf + k, n - k, "%s%ld/%lu", i ? "," : "", t->rekeys[i].step,
                              (unsigned long)t->rekeys[i].b);
    if (k >= n && n > 4)
        memcpy(buf + n - 4, "...", 4);
}

static void final(void *ctx, const fw_ams_sim *p, int n)
{
    fw_split_run *S = ctx;
    int best = 0;
    for (int i = 1; i < n; i++)
        if (p[i].score > p[best].score)
            best = i;
    S->best = n > 0 ? fw_closeness(((const traj *)p[best].traj)->min_hull) : 0.0;
    S->best_path[0] = '\0';
    if (n > 0)
        path_text(p[best].traj, S->best_path, sizeof S->best_path);
}

double fw_split_run_best(const fw_split_run *s, char *path, size_t n)
{
    snprintf(path, n, "%s", s->best_path);
    return s->best;
}

/* Parses "DRAW:STEP/B,..." into t (its rekeys malloc'd). */
static bool parse_path(const char *text, traj *t)
{
    char *end;
    errno = 0;
    t->draw = strtoull(text, &end, 10);
    if (errno || end == text || *end != ':')
        return false;
    const char *c = end + 1;
    int cap = 0;
    while (*c) {
        long step = strtol(c, &end, 10);
        if (end == c || *end != '/' || step < 0)
            return false;
        c = end + 1;
        unsigned long b = strtoul(c, &end, 10);
        if (end == c || b == 0 || b > UINT32_MAX || (*end && *end != ','))
            return false;
        if (!fw_reserve((void **)&t->rekeys, sizeof *t->rekeys, &cap, t->n_rekey + 1))
            return false;
        if (t->n_rekey > 0 && step < t->rekeys[t->n_rekey - 1].step)
            return false;
        t->rekeys[t->n_rekey++] = (rekey){step, (uint32_t)b};
        c = *end ? end + 1 : end;
    }
    return true;
}

fw_status fw_split_run_replay(const fw_split_run *S, const char *path, const char *dir,
                              fw_run_summary *sum, fw_encounter **enc, int *n_enc, fw_error *err)
{
    traj t = {0};
    if (!parse_path(path, &t)) {
        free(t.rekeys);
        return fw_fail(err, FW_EINPUT, "'%.80s' is not a splitting path (DRAW:STEP/B,...)", path);
    }
    fw_scenario sc;
    S->def.scenario(S->def.ctx, t.draw, &sc);
    fw_run_def rd = S->def.run;
    rd.scenario = &sc;
    rd.dir = dir;
    fw_run *r = NULL;
    fw_status st = FW_OK;
    if (S->def.make_controller)
        st = S->def.make_controller(S->def.ctx, &rd.controller, err);
    if (!st)
        st = fw_run_open(&rd, &r, err);
    if (!st && S->def.opened)
        S->def.opened(S->def.ctx, r);
    int next = 0;
    for (long k = 0; !st; k++) {
        if (k > 0 && (st = fw_run_step(r, err)))
            break;
        apply_rekeys(r, &t, k, &next);
        if (fw_run_done(r))
            break;
    }
    free(t.rekeys);
    if (!r)
        return st;
    fw_error cerr = {0};
    fw_status cst = fw_run_close(r, sum, enc, n_enc, &cerr);
    if (!st && cst) {
        *err = cerr;
        st = cst;
    }
    return st;
}

fw_status fw_split_run_create(const fw_split_run_def *def, fw_split_run **out, fw_ams_model *m,
                              fw_error *err)
{
    *out = NULL;
    if (!def->scenario)
        return fw_fail(err, FW_EINPUT, "splitting: no scenario maker");
    fw_split_run *s = calloc(1, sizeof *s);
    if (!s)
        return fw_fail(err, FW_ERUN, "out of memory");
    s->def = *def;
    *m = (fw_ams_model){.ctx = s, .start = start, .branch = branch, .drop = drop, .final = final};
    *out = s;
    return FW_OK;
}

void fw_split_run_destroy(fw_split_run *s) { free(s); }

fw_split_traj_info fw_split_run_info(const void *traj_)
{
    const traj *t = traj_;
    return (fw_split_traj_info){.score = t->score, .min_hull = t->min_hull, .draw = t->draw,
                                .branches = t->n_rekey};
}

long fw_split_run_count(const fw_split_run *s) { return s->count; }
double fw_split_run_sim_s(const fw_split_run *s) { return s->sim_s; }
