/* bench_helm - time per avoidance decision (assessment + helm search + action
 * check) with 1, 10, 50 and 200 targets in range, against the cost of
 * computing every candidate track (the precomputation the search avoids
 * doing in full) measured in the same run.
 *
 * Scenes: own ship C-3 at 10 kn heading north at the origin; an aimed target
 * heads for a random point within 800 m of the own ship's straight track at a
 * random time 100-600 s ahead, from a random direction at 5-15 kn.  Mixed
 * scenes aim 1 target in 10 (the rest anywhere within 3 nm, random courses);
 * dense scenes aim all of them, which no helm clears beyond a few targets, so
 * the search falls back to scoring every candidate track.  A fixed-seed generator keeps the
 * scenes identical between runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include "avoid/policy.h"
#include "core/units.h"

static unsigned long long rng = 88172645463325252ULL;
static double uniform(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

enum { SCENES = 200, REPS = 5 };

/* The search as first written (before the target ordering and pruning in
 * helm_search.c), through the public API: the in-run baseline, and a check
 * that the fast search decides exactly the same. */
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

/* Median time of the search alone (fresh tracks each repetition). */
static double time_search(fw_helm_ctx *ctx, const fw_helm_def *hdef, const fw_own_state *own,
                          const fw_target *tg, int n, int allowed, bool old, fw_helm_result *res)
{
    fw_error err = {0};
    double t0 = bench_now();
    for (int r = 0; r < REPS; r++) {
        fw_helm_begin(ctx, own);
        if (old)
            old_search(ctx, hdef, tg, n, allowed, res, &err);
        else
            fw_helm_search(ctx, tg, n, allowed, res, &err);
    }
    return (bench_now() - t0) / REPS;
}

int main(void)
{
    fw_error err = {0};
    fw_ship ship;
    if (fw_ship_load("c3", &ship, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    fw_helm_def hdef = fw_default_helm_def();
    fw_policy_def pdef = fw_default_policy_def();
    fw_helm_ctx *ctx;
    if (fw_helm_ctx_create(&ship, &hdef, &ctx, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    fw_own_state own = {.U = fw_kn_to_ms(10)};
    static double times[SCENES], base[SCENES], one[SCENES], t_old[SCENES], t_new[SCENES];
    printf("# fairway bench_helm: C-3 at 10 kn, %d scenes x %d repetitions, median per call\n",
           SCENES, REPS);
    printf("# horizon %.0f s, dt %.0f s, helms %.0f-%.0f deg step %.0f\n", hdef.track.horizon,
           hdef.track.dt, hdef.min_helm_deg, hdef.max_helm_deg, hdef.step_deg);
    /* baselines: one track, and all 2 x 26 candidates + keep (mirroring on) */
    for (int s = 0; s < SCENES; s++) {
        double t0 = bench_now();
        for (int r = 0; r < REPS; r++) {
            fw_helm_begin(ctx, &own);
            fw_helm_precompute(ctx, &err);
        }
        base[s] = (bench_now() - t0) / REPS;
        fw_own_state turning = own;
        turning.r = 1e-4; /* not symmetric: every track computed */
        t0 = bench_now();
        for (int r = 0; r < REPS; r++) {
            fw_helm_begin(ctx, &turning);
            fw_helm_precompute(ctx, &err);
        }
        one[s] = (bench_now() - t0) / REPS / (2 * fw_helm_count(ctx) + 1);
    }
    printf("baseline one_track_us %.2f all_tracks_mirrored_us %.1f all_tracks_unmirrored_us %.1f\n",
           1e6 * bench_median(one, SCENES), 1e6 * bench_median(base, SCENES),
           1e6 * bench_median(one, SCENES) * (2 * fw_helm_count(ctx) + 1));
    /* the drift and speed-loss terms (c3-mmg has them, c3 not): one track each */
    fw_ship slip;
    if (fw_ship_load("c3-mmg", &slip, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    {
        fw_track tr;
        static double plain[SCENES], slipped[SCENES];
        if (fw_track_alloc(&tr, fw_track_samples(&hdef.track), &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return 1;
        }
        for (int s = 0; s < SCENES; s++) {
            double h = fw_deg_to_rad(10.0 + s % 26);
            double t0 = bench_now();
            for (int r = 0; r < 20 * REPS; r++)
                fw_track_predict(&ship, &hdef.track, &own, h, &tr, &err);
            plain[s] = (bench_now() - t0) / (20 * REPS);
            t0 = bench_now();
            for (int r = 0; r < 20 * REPS; r++)
                fw_track_predict(&slip, &hdef.track, &own, h, &tr, &err);
            slipped[s] = (bench_now() - t0) / (20 * REPS);
        }
        double a = bench_median(plain, SCENES), b = bench_median(slipped, SCENES);
        printf("track_us without drift and speed loss %.2f, with %.2f (ratio %.2f)\n", 1e6 * a,
               1e6 * b, b / a);
        fw_track_free(&tr);
    }
    static const int counts[] = {1, 10, 50, 200};
    for (int mode = 0; mode < 2; mode++) {
    printf("# %s\n", mode ? "dense: every target aimed within 800 m of the own track (stress)"
                          : "mixed: 1 in 10 targets aimed, the rest anywhere within 3 nm on random courses");
    printf("%8s %12s %12s %10s %10s %10s %10s %10s %10s %9s\n", "targets", "median_us", "p90_us",
           "threat_pct", "tracks_avg", "feasible_pct", "search_us", "old_us", "speedup",
           "inside_pct");
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        int n = counts[c];
        fw_target *tg = malloc(sizeof *tg * (size_t)n);
        fw_assessment *as = malloc(sizeof *as * (size_t)n);
        int *order = malloc(sizeof *order * 2 * (size_t)n);
        int threats = 0, feasible = 0, inside = 0;
        long tracks = 0;
        for (int s = 0; s < SCENES; s++) {
            for (int i = 0; i < n; i++) {
                double tm = 100 + 500 * uniform(), off = 1600 * (uniform() - 0.5);
                double course = 2 * FW_PI * uniform(), v = fw_kn_to_ms(5 + 10 * uniform());
                double me = off, mn = own.U * tm + 1600 * (uniform() - 0.5);
                if (mode == 0 && i % 10 != 0) {
                    /* anywhere within 3 nm now */
                    double rr = 3 * FW_NMILE * sqrt(uniform()), b = 2 * FW_PI * uniform();
                    me = rr * sin(b) + v * sin(course) * tm;
                    mn = rr * cos(b) + v * cos(course) * tm;
                }
                tg[i] = (fw_target){.east = me - v * sin(course) * tm,
                                    .north = mn - v * cos(course) * tm,
                                    .course = course, .speed = v,
                                    .length = 100 + 200 * uniform(), .breadth = 30};
            }
            fw_decision d;
            double t0 = bench_now();
            for (int r = 0; r < REPS; r++) {
                fw_policy pol;
                fw_policy_init(&pol, &pdef);
                fw_policy_input in = {.ctx = ctx, .helm = &hdef, .t = 0.0, .own = &own,
                                      .targets = tg, .n = n, .as = as, .order = order};
                if (fw_policy_step(&pol, &in, &d, &err)) {
                    fprintf(stderr, "%s\n", err.msg);
                    return 1;
                }
            }
            times[s] = (bench_now() - t0) / REPS;
            tracks += fw_helm_tracks_computed(ctx);
            /* the search alone, fast and as first written, on the same scene */
            int allowed = fw_permitted_sides(&hdef, as, n);
            fw_helm_result rn = {0}, ro = {0};
            t_new[s] = time_search(ctx, &hdef, &own, tg, n, allowed, false, &rn);
            t_old[s] = time_search(ctx, &hdef, &own, tg, n, allowed, true, &ro);
            if (rn.threat != ro.threat || rn.feasible != ro.feasible || rn.side != ro.side ||
                rn.helm != ro.helm || rn.clearance != ro.clearance) {
                fprintf(stderr, "bench_helm: fast and old search differ (%d targets, scene %d)\n",
                        n, s);
                return 1;
            }
            /* a target inside the domain now: no helm can clear it */
            for (int i = 0; i < n; i++)
                if (as[i].t_enter == 0.0) {
                    inside++;
                    break;
                }
            threats += d.search.threat;
            feasible += d.search.feasible;
        }
        double med = bench_median(times, SCENES);
        double mn = bench_median(t_new, SCENES), mo = bench_median(t_old, SCENES);
        printf("%8d %12.1f %12.1f %10.0f %10.1f %10.0f %10.1f %10.1f %10.1f %9.0f\n", n, 1e6 * med,
               1e6 * times[(int)(0.9 * SCENES)], 100.0 * threats / SCENES,
               (double)tracks / SCENES, 100.0 * feasible / SCENES, 1e6 * mn, 1e6 * mo, mo / mn,
               100.0 * inside / SCENES);
        free(tg);
        free(as);
        free(order);
    }
    }
    fw_helm_ctx_destroy(ctx);
    return 0;
}
