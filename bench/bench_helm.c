/* bench_helm - time per avoidance decision (assessment + helm search + action
 * check, fw_policy_step) with 1, 10, 30, 50 and 200 targets in range, for the
 * C-3 (Nomoto tracks without drift and speed loss) and the C-3 the scenarios
 * use (c3-mmg: with them, dearer per track; straight, and already turning as
 * in a run, where no track is a mirror image); and the helm search alone against
 * the reference search (tests/helm_reference.c, the search before the
 * decision was made cheaper) and the search as first written (old_search
 * below), all in the same run on the same scenes and checked to decide alike.
 *
 * Scenes: own ship at 10 kn heading north at the origin; an aimed target
 * heads for a random point within 800 m of the own ship's straight track at a
 * random time 100-600 s ahead, from a random direction at 5-15 kn.  Mixed
 * scenes aim 1 target in 10 (the rest anywhere within 3 nm, random courses);
 * dense scenes aim all of them, which no helm clears beyond a few targets, so
 * the search falls back to scoring every candidate track.  A fixed-seed
 * generator per scene set keeps the scenes identical between runs and ships.
 *
 * usage: bench_helm [--targets N] [--ship NAME] [--scenes mixed|dense] [--reps R] [--csv FILE]
 *                   [--decisions-only] [--fastest]
 * (--targets, --ship and --scenes restrict the run, --decisions-only times fw_policy_step
 * alone, without the track baselines: for profiling; --fastest takes each scene's decision
 * time as its fastest repetition, not their mean: on a shared machine the other work then
 * mostly stays out of it, for comparing two builds). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "avoid/policy.h"
#include "core/units.h"
#include "helm_reference.h"

static unsigned long long rng;
static double uniform(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

enum { SCENES = 200 };
static int reps = 5;
static bool decisions_only; /* --decisions-only: no search timings (profiling) */
static bool fastest;        /* --fastest: a scene's decision time is its fastest repetition */
static int only_mode = -1;  /* --scenes: 0 mixed, 1 dense; -1 both */

/* The search as first written (before the target ordering and pruning in
 * helm_search.c), through the public API. */
static fw_status old_search(fw_helm_ctx *c, const fw_helm_def *def, const fw_target *t, int n,
                            int allowed, fw_helm_result *res, fw_error *err)
{
    const fw_track *tr;
    fw_status st = fw_helm_keep_track(c, &tr, err);
    if (st)
        return st;
    res->keep_clearance = fw_track_clearance(def, tr, t, n, 0.0, &res->limiting);
    res->threat = res->keep_clearance < 1.0;
    res->feasible = true;
    res->side = FW_SIDE_NONE;
    res->helm = 0.0;
    res->clearance = res->keep_clearance;
    if (!res->threat)
        return FW_OK;
    static const int sides[2] = {FW_SIDE_STARBOARD, FW_SIDE_PORT};
    static const int masks[2] = {FW_ALLOW_STARBOARD, FW_ALLOW_PORT};
    int found[2] = {-1, -1}, nh = fw_helm_count(c);
    for (int s = 0; s < 2; s++) {
        if (!(allowed & masks[s]))
            continue;
        for (int i = 0; i < nh; i++) {
            if ((st = fw_helm_track(c, sides[s], i, &tr, err)))
                return st;
            if (fw_track_clearance(def, tr, t, n, 1.0, NULL) >= 1.0) {
                found[s] = i;
                break;
            }
            if (s == 1 && found[0] >= 0 && i >= found[0])
                break;
        }
    }
    int pick = -1, side = -1;
    if (found[0] >= 0 && (found[1] < 0 || found[0] <= found[1]))
        pick = found[0], side = 0;
    else if (found[1] >= 0)
        pick = found[1], side = 1;
    if (pick < 0) {
        res->feasible = false;
        double best = -1.0;
        for (int s = 0; s < 2; s++) {
            if (!(allowed & masks[s]))
                continue;
            for (int i = 0; i < nh; i++) {
                if ((st = fw_helm_track(c, sides[s], i, &tr, err)))
                    return st;
                double cl = fw_track_clearance(def, tr, t, n, best > 0.0 ? best : 0.0, NULL);
                if (cl > best + 1e-9)
                    best = cl, pick = i, side = s;
            }
        }
    }
    res->side = sides[side];
    res->helm = fw_helm_value(c, sides[side], pick);
    if ((st = fw_helm_track(c, sides[side], pick, &tr, err)))
        return st;
    res->clearance = fw_track_clearance(def, tr, t, n, 0.0, &res->limiting);
    return FW_OK;
}

typedef struct bench {
    const fw_ship *ship;
    const char *own_name;
    fw_helm_def hdef;
    fw_policy_def pdef;
    fw_helm_ctx *ctx;
    fw_helm_ref *ref;
    fw_own_state own;
    FILE *csv;
} bench;

enum { S_NEW, S_REF, S_OLD };

/* Median time of the search alone (fresh tracks each repetition). */
static double time_search(bench *b, const fw_target *tg, int n, int allowed, int which,
                          fw_helm_result *res)
{
    fw_error err = {0};
    double t0 = bench_now();
    for (int r = 0; r < reps; r++) {
        fw_helm_begin(b->ctx, &b->own);
        if (which == S_OLD)
            old_search(b->ctx, &b->hdef, tg, n, allowed, res, &err);
        else if (which == S_REF)
            fw_helm_search_reference(b->ref, b->ctx, tg, n, allowed, res, &err);
        else
            fw_helm_search(b->ctx, tg, n, allowed, res, &err);
    }
    return (bench_now() - t0) / reps;
}

static bool same_result(const fw_helm_result *a, const fw_helm_result *b, bool full)
{
    bool same = a->threat == b->threat && a->feasible == b->feasible && a->side == b->side &&
                a->helm == b->helm && a->clearance == b->clearance;
    if (!full)
        return same;
    return same && a->keep_clearance == b->keep_clearance && a->limiting == b->limiting &&
           a->allowed == b->allowed &&
           memcmp(a->side_helm, b->side_helm, sizeof a->side_helm) == 0;
}

static void make_scene(const fw_own_state *own, int mode, fw_target *tg, int n)
{
    for (int i = 0; i < n; i++) {
        double tm = 100 + 500 * uniform(), off = 1600 * (uniform() - 0.5);
        double course = 2 * FW_PI * uniform(), v = fw_kn_to_ms(5 + 10 * uniform());
        double me = off, mn = own->U * tm + 1600 * (uniform() - 0.5);
        if (mode == 0 && i % 10 != 0) {
            /* anywhere within 3 nm now */
            double rr = 3 * FW_NMILE * sqrt(uniform()), b = 2 * FW_PI * uniform();
            me = rr * sin(b) + v * sin(course) * tm;
            mn = rr * cos(b) + v * cos(course) * tm;
        }
        tg[i] = (fw_target){.east = me - v * sin(course) * tm, .north = mn - v * cos(course) * tm,
                            .course = course, .heading = course, .speed = v, .length = 100 + 200 * uniform(),
                            .breadth = 30};
    }
}

/* One line: scene set `mode`, n targets. */
static int run_count(bench *b, int mode, int n)
{
    static double times[SCENES], t_new[SCENES], t_ref[SCENES], t_old[SCENES];
    fw_error err = {0};
    fw_target *tg = malloc(sizeof *tg * (size_t)n);
    fw_assessment *as = malloc(sizeof *as * (size_t)n);
    int *order = malloc(sizeof *order * 2 * (size_t)n);
    int threats = 0, feasible = 0, inside = 0, bad = 0;
    long tracks = 0;
    double predicted = 0.0;
    rng = 88172645463325252ULL + 7919ULL * (unsigned long long)(1000 * mode + n);
    for (int s = 0; s < SCENES && tg && as && order && !bad; s++) {
        make_scene(&b->own, mode, tg, n);
        fw_decision d;
        double t0 = bench_now(), best = INFINITY;
        for (int r = 0; r < reps && !bad; r++) {
            double t1 = bench_now();
            fw_policy pol;
            fw_policy_init(&pol, &b->pdef);
            fw_policy_input in = {.ctx = b->ctx, .helm = &b->hdef, .t = 0.0, .own = &b->own,
                                  .targets = tg, .n = n, .as = as, .order = order};
            if (fw_policy_step(&pol, &in, &d, &err)) {
                fprintf(stderr, "%s\n", err.msg);
                bad = 1;
            }
            double t2 = bench_now();
            best = t2 - t1 < best ? t2 - t1 : best;
        }
        times[s] = fastest ? best : (bench_now() - t0) / reps;
        tracks += fw_helm_tracks_computed(b->ctx);
        predicted += fw_helm_tracks_predicted(b->ctx);
        threats += d.search.threat;
        feasible += d.search.feasible;
        for (int i = 0; i < n; i++)
            if (as[i].t_enter == 0.0) {
                inside++;
                break;
            }
        if (decisions_only)
            continue;
        int allowed = fw_permitted_sides(&b->hdef, as, n);
        fw_helm_result rn = {0}, rr = {0}, ro = {0};
        t_new[s] = time_search(b, tg, n, allowed, S_NEW, &rn);
        t_ref[s] = time_search(b, tg, n, allowed, S_REF, &rr);
        t_old[s] = time_search(b, tg, n, allowed, S_OLD, &ro);
        if (!same_result(&rn, &rr, true) || !same_result(&rn, &ro, false)) {
            fprintf(stderr, "bench_helm: the searches differ (%s, %d targets, scene %d)\n",
                    b->ship->name, n, s);
            bad = 1;
        }
    }
    if (!tg || !as || !order)
        bad = 1, fprintf(stderr, "bench_helm: out of memory\n");
    if (!bad) {
        double p90 = (bench_median(times, SCENES), times[(int)(0.9 * SCENES)]);
        double med = bench_median(times, SCENES), mn = bench_median(t_new, SCENES);
        double mr = bench_median(t_ref, SCENES), mo = bench_median(t_old, SCENES);
        printf("%8d %11.1f %9.1f %7.0f %7.1f %9.1f %9.0f %10.1f %8.1f %7.2f %8.1f %7.0f\n", n,
               1e6 * med, 1e6 * p90, 100.0 * threats / SCENES, (double)tracks / SCENES,
               predicted / SCENES,
               100.0 * feasible / SCENES, 1e6 * mn, 1e6 * mr, mr / mn, 1e6 * mo,
               100.0 * inside / SCENES);
        if (b->csv)
            fprintf(b->csv,
                    "%s,%s,%s,%d,%.2f,%.2f,%.0f,%.2f,%.2f,%.0f,%.2f,%.2f,%.3f,%.2f,%.0f,%d\n",
                    b->ship->name, b->own_name, mode ? "dense" : "mixed", n, 1e6 * med, 1e6 * p90,
                    100.0 * threats / SCENES, (double)tracks / SCENES, predicted / SCENES,
                    100.0 * feasible / SCENES, 1e6 * mn, 1e6 * mr, mr / mn, 1e6 * mo,
                    100.0 * inside / SCENES, reps);
    }
    free(tg);
    free(as);
    free(order);
    return bad;
}

/* Track costs: one track, all 2 x 26 candidates + keep (mirrored, unmirrored). */
static void baselines(bench *b)
{
    static double base[SCENES], one[SCENES];
    fw_error err = {0};
    int ntr = 2 * fw_helm_count(b->ctx) + 1;
    for (int s = 0; s < SCENES; s++) {
        double t0 = bench_now();
        for (int r = 0; r < reps; r++) {
            fw_helm_begin(b->ctx, &b->own);
            fw_helm_precompute(b->ctx, &err);
        }
        base[s] = (bench_now() - t0) / reps;
        fw_own_state turning = b->own;
        turning.r = 1e-4; /* not symmetric: every track computed */
        t0 = bench_now();
        for (int r = 0; r < reps; r++) {
            fw_helm_begin(b->ctx, &turning);
            fw_helm_precompute(b->ctx, &err);
        }
        one[s] = (bench_now() - t0) / reps / ntr;
    }
    double o = bench_median(one, SCENES);
    printf("baseline one_track_us %.2f all_tracks_mirrored_us %.1f all_tracks_unmirrored_us %.1f\n",
           1e6 * o, 1e6 * bench_median(base, SCENES), 1e6 * o * ntr);
}

/* The own ship at 10 kn heading north: straight with the rudder amidships
 * (the port tracks are then mirror images of the starboard ones), or already
 * turning a little (every track predicted, as in a run: the MMG ship's yaw
 * rate is never exactly 0). */
static int run_ship(const char *name, bool turning, int only_n, FILE *csv)
{
    fw_error err = {0};
    fw_ship ship;
    bench b = {.ship = &ship, .own_name = turning ? "turning" : "straight",
               .hdef = fw_default_helm_def(), .pdef = fw_default_policy_def(),
               .own = {.U = fw_kn_to_ms(10)}, .csv = csv};
    if (turning)
        b.own.r = fw_deg_to_rad(0.01), b.own.delta = fw_deg_to_rad(0.5);
    if (fw_ship_load(name, &ship, &err) ||
        fw_helm_ctx_create(&ship, &b.hdef, &b.ctx, &err) ||
        fw_helm_ref_create(&b.hdef, fw_helm_count(b.ctx), &b.ref, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        fw_helm_ctx_destroy(b.ctx);
        return 1;
    }
    printf("# ship %s at 10 kn, %s, %d scenes x %d repetitions, median per call\n", name,
           turning ? "turning at 0.01 deg/s (rudder 0.5 deg)" : "straight", SCENES, reps);
    if (!decisions_only)
        baselines(&b);
    static const int counts[] = {1, 10, 30, 50, 200};
    int bad = 0;
    for (int mode = 0; mode < 2 && !bad; mode++) {
        if (only_mode >= 0 && mode != only_mode)
            continue;
        printf("# %s\n", mode ? "dense: every target aimed within 800 m of the own track (stress)"
                              : "mixed: 1 in 10 targets aimed, the rest anywhere within 3 nm");
        printf("%8s %11s %9s %7s %7s %9s %9s %10s %8s %7s %8s %7s\n", "targets", "decision_us",
               "p90_us", "threat%", "tracks", "predicted", "feasible%", "search_us", "ref_us",
               "ref/new", "old_us", "inside%");
        for (size_t c = 0; c < sizeof counts / sizeof counts[0] && !bad; c++)
            if (!only_n || counts[c] == only_n)
                bad = run_count(&b, mode, counts[c]);
    }
    fw_helm_ref_destroy(b.ref);
    fw_helm_ctx_destroy(b.ctx);
    return bad;
}

int main(int argc, char **argv)
{
    const char *only_ship = NULL, *csv_path = NULL;
    int only_n = 0;
    for (int i = 1; i < argc; i++) {
        bool val = i + 1 < argc;
        if (val && strcmp(argv[i], "--targets") == 0)
            only_n = atoi(argv[++i]);
        else if (val && strcmp(argv[i], "--ship") == 0)
            only_ship = argv[++i];
        else if (val && strcmp(argv[i], "--reps") == 0)
            reps = atoi(argv[++i]);
        else if (val && strcmp(argv[i], "--scenes") == 0 &&
                 (strcmp(argv[i + 1], "mixed") == 0 || strcmp(argv[i + 1], "dense") == 0))
            only_mode = strcmp(argv[++i], "dense") == 0;
        else if (strcmp(argv[i], "--decisions-only") == 0)
            decisions_only = true;
        else if (strcmp(argv[i], "--fastest") == 0)
            fastest = true;
        else if (val && strcmp(argv[i], "--csv") == 0)
            csv_path = argv[++i];
        else {
            fprintf(stderr, "usage: bench_helm [--targets N] [--ship NAME] [--scenes mixed|dense] "
                            "[--reps R] [--csv FILE] [--decisions-only] [--fastest]\n");
            return 2;
        }
    }
    if (reps < 1)
        reps = 1;
    FILE *csv = csv_path ? fopen(csv_path, "w") : NULL;
    if (csv_path && !csv) {
        fprintf(stderr, "bench_helm: cannot write %s\n", csv_path);
        return 2;
    }
    if (csv)
        fprintf(csv, "ship,own,scenes,targets,decision_us,decision_p90_us,threat_pct,tracks_avg,"
                     "predicted_avg,feasible_pct,search_us,ref_us,ref_over_new,old_us,inside_pct,"
                     "reps\n");
    printf("# fairway bench_helm: horizon 600 s, dt 5 s, helms 10-35 deg step 1\n");
    static const char *ships[] = {"c3", "c3-mmg", "c3-mmg"};
    int bad = 0;
    for (int s = 0; s < 3 && !bad; s++)
        if (!only_ship || strcmp(only_ship, ships[s]) == 0)
            bad = run_ship(ships[s], s == 2, only_n, csv);
    if (csv)
        fclose(csv);
    return bad;
}
