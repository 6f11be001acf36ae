/* test_decide - the avoidance decision made cheaper decides exactly as before.
 *
 * A fixed-seed set of 2400 scenes (C-3 and C-3 MMG, both domain readings,
 * domains about the centre and about the hull; mixed and dense traffic of
 * 1-200 targets, some with a turning predictor; own ships straight and
 * already turning), and 192 with odd settings (a 3000 s horizon beyond the
 * chunks with boxes, 2 deg helm steps, no steadying, a long domain), is
 * searched by fw_helm_search and by the reference search (helm_reference.c,
 * the search before the change) on the sides COLREGs permit, either side and
 * port only: every field of the two results must agree bit for bit, and so
 * must the steering and delayed-helm checks that reuse the search's prepared
 * targets, against fw_track_clearance.  Each scene's policy step (assessment,
 * search, action check) is hashed too and compared with
 * tests/data/digests/decisions.txt, made before the change (the odd groups'
 * after it: theirs only lock them): that also checks the predicted tracks,
 * which both searches share.  The scans' chunk bound (clearance.c) is also
 * checked chunk by chunk against the same scans without it, and the reach
 * window's shortcut for targets out of reach against every chunk's test
 * (and the window, found from either end, and the targets' boxes against
 * both made plainly chunk by chunk), the targets' preparation kept from
 * decision to decision against the preparation made afresh, and the
 * autopilot's track (whose pieces track.c evaluates inlined) against its
 * headings made with the library's piece evaluation, and the assessment's
 * danger order against the ranking rule.
 * FAIRWAY_WRITE_DIGESTS=FILE writes the digests found instead. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/clearance.h"
#include "avoid/policy.h"
#include "core/files.h"
#include "core/units.h"
#include "helm_reference.h"
#include "test.h"

static unsigned long long rng;
static double uniform(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* A target turning at a constant rate: a predictor other than constant velocity. */
typedef struct turning {
    fw_predictor base;
    double rate; /* rad/s */
} turning;

static void turning_path(const fw_predictor *self, const fw_target *t, double dt, int n,
                         double *east, double *north, double *course)
{
    double rate = ((const turning *)self)->rate, e = t->east, nn = t->north, c = t->course;
    for (int k = 0; k < n; k++) {
        east[k] = e, north[k] = nn, course[k] = c;
        e += t->speed * dt * sin(c + 0.5 * rate * dt);
        nn += t->speed * dt * cos(c + 0.5 * rate * dt);
        c += rate * dt;
    }
}

static const turning kTurnPort = {{turning_path}, -0.004}, kTurnStbd = {{turning_path}, 0.003};

static void make_scene(const fw_own_state *own, bool dense, fw_target *tg, int n)
{
    for (int i = 0; i < n; i++) {
        double tm = 100 + 500 * uniform(), off = 1600 * (uniform() - 0.5);
        double course = 2 * FW_PI * uniform(), v = fw_kn_to_ms(5 + 10 * uniform());
        /* the aim point on the own ship's straight track, tm s ahead */
        double along = own->U * tm + 1600 * (uniform() - 0.5);
        double me = own->east + along * sin(own->psi) + off * cos(own->psi);
        double mn = own->north + along * cos(own->psi) - off * sin(own->psi);
        if (!dense && i % 10 != 0) {
            double rr = 3 * FW_NMILE * sqrt(uniform()), b = 2 * FW_PI * uniform();
            me = own->east + rr * sin(b) + v * sin(course) * tm;
            mn = own->north + rr * cos(b) + v * cos(course) * tm;
        }
        double u = uniform();
        tg[i] = (fw_target){.east = me - v * sin(course) * tm, .north = mn - v * cos(course) * tm,
                            .course = course, .speed = v, .length = 100 + 200 * uniform(),
                            .breadth = 30,
                            .pred = u < 0.07 ? &kTurnPort.base
                                    : u < 0.14 ? &kTurnStbd.base : NULL};
        snprintf(tg[i].id, sizeof tg[i].id, "t%d", i);
    }
}

/* Straight (symmetric: the port tracks are mirrored) or already turning. */
static fw_own_state make_own(bool turning_now)
{
    fw_own_state o = {.east = 2000 * (uniform() - 0.5), .north = 2000 * (uniform() - 0.5),
                      .psi = 2 * FW_PI * uniform(), .U = fw_kn_to_ms(6 + 8 * uniform())};
    if (turning_now) {
        o.r = fw_deg_to_rad(0.6 * (uniform() - 0.5));
        o.rdot = fw_deg_to_rad(0.02 * (uniform() - 0.5));
        o.delta = fw_deg_to_rad(40 * (uniform() - 0.5));
        o.beta = fw_deg_to_rad(4 * (uniform() - 0.5));
        o.U0 = o.U * (1.0 + 0.2 * uniform());
    }
    return o;
}

static uint64_t mix(uint64_t h, const void *p, size_t len)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < len; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t hash_result(uint64_t h, const fw_helm_result *r)
{
    int ints[5] = {r->threat, r->feasible, r->allowed, r->side, r->limiting};
    double dbl[5] = {r->helm, r->clearance, r->keep_clearance, r->side_helm[0], r->side_helm[1]};
    h = mix(h, ints, sizeof ints);
    return mix(h, dbl, sizeof dbl);
}

static bool same_result(const fw_helm_result *a, const fw_helm_result *b)
{
    return a->threat == b->threat && a->feasible == b->feasible && a->allowed == b->allowed &&
           a->side == b->side && a->limiting == b->limiting &&
           memcmp(&a->helm, &b->helm, sizeof a->helm) == 0 &&
           memcmp(&a->clearance, &b->clearance, sizeof a->clearance) == 0 &&
           memcmp(&a->keep_clearance, &b->keep_clearance, sizeof a->keep_clearance) == 0 &&
           memcmp(a->side_helm, b->side_helm, sizeof a->side_helm) == 0;
}

static FILE *digest_out;

/* What the scenes of one group covered, so that the comparison is not vacuous. */
typedef struct tally {
    int scenes, threats, infeasible, port, starboard, acted, later;
} tally;

static const fw_ship *ctx_ship; /* the ship of the group under test */
static fw_track tr;              /* steer_and_later's */

/* The policy's other checks after a search (fw_helm_steer_clearance and
 * fw_helm_clears_after, which reuse the search's prepared targets) against
 * the same tracks checked by fw_track_clearance from scratch. */
static void steer_and_later(fw_helm_ctx *ctx, const fw_helm_def *hdef, const fw_own_state *own,
                            const fw_target *tg, int n, tally *tl)
{
    fw_steer_def ap = {.psi_ref = own->psi + 0.5, .kp = 1.0, .kd = 20.0,
                       .max_helm = fw_deg_to_rad(20)};
    double cl;
    bool later;
    CHECK(fw_helm_steer_clearance(ctx, tg, n, &ap, false, &cl, NULL) == FW_OK);
    CHECK(fw_track_predict_steer(ctx_ship, &hdef->track, own, &ap, &tr, NULL) == FW_OK);
    double want = fw_track_clearance(hdef, &tr, tg, n, 0.0, NULL);
    CHECK_MSG(memcmp(&cl, &want, sizeof cl) == 0, "steer clearance %.17g, expected %.17g", cl,
              want);
    double helm = fw_deg_to_rad(tl->scenes % 2 ? 12 : -30);
    CHECK(fw_helm_clears_after(ctx, tg, n, helm, 60.0, &later, NULL) == FW_OK);
    fw_track_def d = hdef->track;
    d.delay = 60.0;
    CHECK(fw_track_predict(ctx_ship, &d, own, helm, &tr, NULL) == FW_OK);
    CHECK(later == (fw_track_clearance(hdef, &tr, tg, n, 1.0, NULL) >= 1.0));
    tl->later += later;
}

/* The keep track and a candidate as the search made them (lazily, from the
 * decision's track origin) are fw_track_predict's to the bit; the candidate
 * only when the own ship is turning (from a symmetric start one side may be
 * the other's mirror image, which rounds differently). */
static void same_track(fw_helm_ctx *ctx, const fw_helm_def *hdef, const fw_own_state *own,
                       int scene)
{
    int side = scene % 2 ? FW_SIDE_PORT : FW_SIDE_STARBOARD, i = scene % fw_helm_count(ctx);
    bool symmetric = own->r == 0.0 && own->rdot == 0.0 && own->delta == 0.0 && own->beta == 0.0;
    const fw_track *got[2];
    CHECK(fw_helm_track(ctx, side, i, &got[0], NULL) == FW_OK);
    CHECK(fw_helm_keep_track(ctx, &got[1], NULL) == FW_OK);
    double helm[2] = {fw_helm_value(ctx, side, i), 0.0};
    for (int q = symmetric; q < 2; q++) {
        CHECK(fw_track_predict(ctx_ship, &hdef->track, own, helm[q], &tr, NULL) == FW_OK);
        size_t len = sizeof(double) * (size_t)tr.n;
        CHECK_MSG(got[q]->n == tr.n && memcmp(got[q]->east, tr.east, len) == 0 &&
                      memcmp(got[q]->north, tr.north, len) == 0 &&
                      memcmp(got[q]->sin_psi, tr.sin_psi, len) == 0 &&
                      memcmp(got[q]->cos_psi, tr.cos_psi, len) == 0 &&
                      memcmp(got[q]->psi, tr.psi, len) == 0 && memcmp(got[q]->r, tr.r, len) == 0,
                  "scene %d: the search's %s track differs from fw_track_predict's", scene,
                  q ? "keep" : "candidate");
    }
}

static uint64_t run_scene(fw_helm_ctx *ctx, fw_helm_ref *ref, const fw_helm_def *hdef, int n,
                          bool dense, bool turning_now, uint64_t h, tally *tl)
{
    static fw_target tg[200];
    static fw_assessment as[200];
    static int order[400];
    fw_own_state own = make_own(turning_now);
    make_scene(&own, dense, tg, n);
    fw_policy_def pdef = fw_default_policy_def();
    fw_policy pol;
    fw_policy_init(&pol, &pdef);
    fw_policy_input in = {.ctx = ctx, .helm = hdef, .t = 0.0, .own = &own, .targets = tg,
                          .n = n, .as = as, .order = order};
    fw_decision d;
    fw_error err = {0};
    CHECK(fw_policy_step(&pol, &in, &d, &err) == FW_OK);
    /* the sides COLREGs permit, and either side and port only (which the
     * permitted sides seldom are: head-on and crossing threats ask for starboard) */
    int allowed[3] = {fw_permitted_sides(hdef, as, n), FW_ALLOW_EITHER, FW_ALLOW_PORT};
    for (int a = 0; a < 3; a++) {
        fw_helm_result rn, rr;
        fw_helm_begin(ctx, &own);
        CHECK(fw_helm_search(ctx, tg, n, allowed[a], &rn, &err) == FW_OK);
        fw_helm_begin(ctx, &own);
        CHECK(fw_helm_search_reference(ref, ctx, tg, n, allowed[a], &rr, &err) == FW_OK);
        CHECK_MSG(same_result(&rn, &rr),
                  "scene %d (%d targets, allowed %d): side %d/%d helm %.17g/%.17g "
                  "clearance %.17g/%.17g",
                  tl->scenes, n, allowed[a], rn.side, rr.side, rn.helm, rr.helm, rn.clearance,
                  rr.clearance);
        h = hash_result(h, &rn);
        tl->threats += a == 0 && rn.threat;
        tl->infeasible += a == 0 && rn.threat && !rn.feasible;
        tl->port += rn.side == FW_SIDE_PORT;
        tl->starboard += rn.side == FW_SIDE_STARBOARD;
    }
    steer_and_later(ctx, hdef, &own, tg, n, tl);
    same_track(ctx, hdef, &own, tl->scenes);
    int ints[3] = {d.mode, d.acted, d.primary};
    h = mix(h, ints, sizeof ints);
    h = mix(h, &d.helm, sizeof d.helm);
    h = mix(h, d.reason, strlen(d.reason));
    h = hash_result(h, &d.search);
    tl->scenes++;
    tl->acted += d.acted;
    return h;
}

static void check_digest(const char *key, uint64_t h)
{
    if (digest_out) {
        fprintf(digest_out, "%s %016llx\n", key, (unsigned long long)h);
        return;
    }
    char path[1200], line[256];
    snprintf(path, sizeof path, "%s/tests/data/digests/decisions.txt", fw_data_root());
    FILE *f = fopen(path, "r");
    CHECK_MSG(f != NULL, "cannot read %s", path);
    bool found = false;
    unsigned long long want = 0;
    while (f && fgets(line, sizeof line, f)) {
        char k[200];
        if (sscanf(line, "%199s %llx", k, &want) == 2 && strcmp(k, key) == 0) {
            found = true;
            break;
        }
    }
    if (f)
        fclose(f);
    CHECK_MSG(found && want == h, "%s: digest %016llx, expected %016llx%s", key,
              (unsigned long long)h, want, found ? "" : " (no such key)");
}

/* 300 scenes of one ship, reading and domain origin. */
/* Scenes of one ship, reading and domain origin; `odd`: a 3000 s horizon at
 * 4 s (94 chunks, beyond the 64 with boxes), 2 deg helm steps, no steadying
 * at max_turn and a domain twice as long as wide. */
static void run_group(const char *ship_name, fw_domain_reading reading, bool hull, bool odd)
{
    fw_ship ship;
    fw_error err = {0};
    CHECK(fw_ship_load(ship_name, &ship, &err) == FW_OK);
    fw_helm_def hdef = fw_default_helm_def();
    hdef.domain.reading = reading;
    if (odd) {
        hdef.track.horizon = 3000.0, hdef.track.dt = 4.0, hdef.track.max_turn = 0.0;
        hdef.step_deg = 2.0;
        hdef.domain.fore_aft_ratio = 2.0;
    }
    if (tr.cap < fw_track_samples(&hdef.track)) {
        fw_track_free(&tr);
        CHECK(fw_track_alloc(&tr, fw_track_samples(&hdef.track), NULL) == FW_OK);
    }
    if (hull) {
        hdef.domain.own_half_length = 0.5 * ship.Loa;
        hdef.domain.own_half_breadth = 0.5 * ship.B;
        hdef.domain.size = 150.0;
    }
    fw_helm_ctx *ctx = NULL;
    fw_helm_ref *ref = NULL;
    ctx_ship = &ship;
    CHECK(fw_helm_ctx_create(&ship, &hdef, &ctx, &err) == FW_OK);
    CHECK(ctx && fw_helm_ref_create(&hdef, fw_helm_count(ctx), &ref, &err) == FW_OK);
    if (!ctx || !ref) {
        fw_helm_ctx_destroy(ctx);
        return;
    }
    static const int counts[] = {1, 2, 3, 5, 8, 12, 20, 30, 50, 80, 120, 200};
    char key[200];
    snprintf(key, sizeof key, "%s/%s/%s%s", ship_name, fw_domain_reading_name(reading),
             hull ? "hull" : "centre", odd ? "/odd" : "");
    rng = 88172645463325252ULL ^ mix(14695981039346656037ull, key, strlen(key));
    uint64_t h = 14695981039346656037ull;
    tally tl = {0};
    for (int s = 0; s < (odd ? 96 : 300); s++) {
        int n = counts[s % (odd ? 9 : 12)];
        h = run_scene(ctx, ref, &hdef, n, (s / 12) % 2 == 1, (s / 24) % 2 == 1, h, &tl);
    }
    printf("  %-26s %d scenes: %d threats, %d infeasible; sides (3 searches each) %d "
           "starboard, %d port; %d acted\n",
           key, tl.scenes, tl.threats, tl.infeasible, tl.starboard, tl.port, tl.acted);
    /* the comparison covers both outcomes and both sides */
    CHECK(tl.threats > tl.scenes / 2 && tl.infeasible > tl.scenes / 10);
    CHECK(tl.threats - tl.infeasible > tl.scenes / 10);
    CHECK(tl.port > tl.scenes / 3 && tl.starboard > tl.scenes / 3 && tl.acted > tl.scenes / 3);
    CHECK(tl.later > 10 && tl.later < tl.scenes - 10); /* both verdicts met */
    check_digest(key, h);
    fw_helm_ref_destroy(ref);
    fw_helm_ctx_destroy(ctx);
}

static void test_decisions_unchanged(void)
{
    static const char *ships[] = {"c3", "c3-mmg"};
    for (int s = 0; s < 2; s++)
        for (int r = 0; r < 2; r++)
            for (int hull = 0; hull < 2; hull++)
                run_group(ships[s], r ? FW_DOMAIN_TRANSVERSE : FW_DOMAIN_ELLIPSE, hull, false);
    run_group("c3-mmg", FW_DOMAIN_ELLIPSE, true, true);
    run_group("c3", FW_DOMAIN_TRANSVERSE, false, true);
}

/* fw_target_min2_cap with the targets' prepared boxes (which bound a chunk
 * before its offsets) against the same without them, chunk by chunk, at caps
 * below 1 (where that bound is used): the same to the bit wherever either is
 * below the cap, both at or above it otherwise.  Own ships turning hard (the
 * frame's turn in a step is part of the bound), both readings, targets on
 * predicted turning paths too. */
static void test_chunk_bound(void)
{
    static const double caps[] = {0.005, 0.03, 0.1, 0.3, 0.6, 0.95};
    enum { NT = 20 };
    fw_ship ship;
    CHECK(fw_ship_load("c3-mmg", &ship, NULL) == FW_OK);
    fw_helm_def hdef = fw_default_helm_def();
    int ns = fw_track_samples(&hdef.track), plen = fw_prep_path_len(&hdef.track);
    fw_track t;
    CHECK(fw_track_alloc(&t, ns, NULL) == FW_OK);
    static fw_target tg[NT];
    static fw_prep_target plain[NT], boxed[NT];
    double *paths = malloc(sizeof(double) * (size_t)(NT * plen));
    double *room = malloc(sizeof(double) * (size_t)(NT * fw_prep_box_len(ns - 1)));
    CHECK(paths && room);
    long below = 0, tests = 0;
    rng = 0x9e3779b97f4a7c15ULL;
    for (int s = 0; s < 160 && paths && room; s++) {
        hdef.domain.reading = s % 2 ? FW_DOMAIN_TRANSVERSE : FW_DOMAIN_ELLIPSE;
        hdef.domain.own_half_length = s % 4 < 2 ? 0.0 : 0.5 * ship.Loa;
        fw_own_state own = make_own(s % 3 != 0);
        double helm = fw_deg_to_rad(10 + 25 * uniform()) * (s % 5 < 2 ? -1.0 : 1.0);
        CHECK(fw_track_predict(&ship, &hdef.track, &own, helm, &t, NULL) == FW_OK);
        fw_chunk_boxes cb;
        fw_track_boxes(&t, &cb);
        make_scene(&own, s % 2 == 0, tg, NT);
        fw_prep_targets(&hdef.domain, &hdef.track, tg, NT, plain, paths);
        for (int i = 0; i < NT; i++) {
            boxed[i] = plain[i];
            fw_prep_boxes(t.dt, &boxed[i], cb.nseg, room + (size_t)i * fw_prep_box_len(cb.nseg));
        }
        for (int i = 0; i < NT; i++)
            for (int j = 0; j < cb.nch; j++)
                for (size_t c = 0; c < sizeof caps / sizeof caps[0]; c++) {
                    double a = fw_target_min2_cap(&hdef.domain, &t, &cb, &plain[i], j, j + 1,
                                                  0.0, caps[c]);
                    double b = fw_target_min2_cap(&hdef.domain, &t, &cb, &boxed[i], j, j + 1,
                                                  0.0, caps[c]);
                    tests++;
                    if (a < caps[c] || b < caps[c]) {
                        below++;
                        CHECK_MSG(memcmp(&a, &b, sizeof a) == 0,
                                  "scene %d target %d chunk %d cap %g: %.17g with boxes, %.17g "
                                  "without",
                                  s, i, j, caps[c], b, a);
                    } else {
                        CHECK(a >= caps[c] && b >= caps[c]);
                    }
                }
    }
    printf("  chunk bound: %ld chunk tests, %ld below the cap\n", tests, below);
    CHECK(below > 2000); /* the comparison is not vacuous */
    free(paths);
    free(room);
    fw_track_free(&t);
}

/* fw_prep_reach's one test for a target out of reach over the whole horizon
 * gives the window that every chunk's test gives (fw_prep_boxes and then
 * fw_reach_window), in mixed and dense scenes, with and without a predictor,
 * at the own ship's speed and at speeds from 0 to twice it. */
/* The reach window tested chunk by chunk (fw_reach_window's test on every
 * chunk, without the target's prepared boxes), for test_reach_window. */
static void plain_window(double dt, const fw_prep_target *g, int nseg, const fw_own_state *own,
                         double umax, int *lo, int *hi)
{
    fw_prep_target p = *g;
    p.box = NULL, p.nbox = 0;
    *lo = -1, *hi = 0;
    for (int j = 0; j * FW_CHUNK < nseg; j++) {
        int k1 = j * FW_CHUNK + FW_CHUNK < nseg ? j * FW_CHUNK + FW_CHUNK : nseg;
        double R = umax * (k1 * dt) * (1.0 + 1e-9) + 1e-6;
        double env[4] = {own->east - R, own->east + R, own->north - R, own->north + R};
        if (!fw_chunk_misses(dt, &p, j, nseg, env))
            *lo = *lo < 0 ? j : *lo, *hi = j + 1;
    }
    *lo = *lo < 0 ? 0 : *lo;
}

/* A constant-velocity target's prepared boxes against each chunk's ends made
 * plainly, its velocity `ulps` ulp up (1: a deliberate error). */
static bool same_boxes(const fw_prep_target *g, int blen, int ulps)
{
    double ve = g->ve, vn = g->vn, dt = fw_default_track_def().dt;
    for (int u = 0; u < ulps; u++)
        ve = nextafter(ve, INFINITY), vn = nextafter(vn, INFINITY);
    for (int j = 0; j < g->nbox && FW_PBOX * j < blen; j++) {
        int k0 = j * FW_CHUNK, k1 = k0 + FW_CHUNK < g->box_nseg ? k0 + FW_CHUNK : g->box_nseg;
        double ea = g->east + ve * (k0 * dt), eb = g->east + ve * (k1 * dt);
        double na = g->north + vn * (k0 * dt), nb = g->north + vn * (k1 * dt);
        double want[FW_PBOX] = {fmin(ea, eb), fmax(ea, eb), fmin(na, nb), fmax(na, nb), 0.0};
        if (memcmp(want, g->box + FW_PBOX * j, sizeof want) != 0)
            return false;
    }
    return true;
}

static void test_reach_window(void)
{
    enum { NT = 40 };
    fw_helm_def hdef = fw_default_helm_def();
    int ns = fw_track_samples(&hdef.track), plen = fw_prep_path_len(&hdef.track);
    int blen = fw_prep_box_len(ns - 1);
    static fw_target tg[NT];
    static fw_prep_target g[NT];
    double *paths = malloc(sizeof(double) * (size_t)(NT * plen));
    double *room = malloc(sizeof(double) * (size_t)(2 * blen));
    CHECK(paths && room);
    long targets = 0, culled = 0, empty = 0, cv = 0, nudged = 0, partial = 0;
    rng = 0x2545f4914f6cdd1dULL;
    for (int s = 0; s < 200 && paths && room; s++) {
        fw_own_state own = make_own(s % 3 != 0);
        make_scene(&own, s % 4 == 0, tg, NT);
        fw_prep_targets(&hdef.domain, &hdef.track, tg, NT, g, paths);
        double umax = own.U * (s % 5 == 0 ? 2.0 * uniform() : 1.0);
        for (int i = 0; i < NT; i++) {
            fw_prep_target a = g[i], b = g[i];
            int lo, hi, lo2, hi2;
            fw_prep_boxes(hdef.track.dt, &a, ns - 1, room);
            fw_reach_window(hdef.track.dt, &a, ns - 1, own.east, own.north, umax, &lo, &hi);
            fw_prep_reach(hdef.track.dt, &b, ns - 1, own.east, own.north, umax, room + blen,
                          &lo2, &hi2);
            CHECK_MSG(lo == lo2 && hi == hi2, "scene %d target %d: window [%d, %d) vs [%d, %d)",
                      s, i, lo, hi, lo2, hi2);
            int plo, phi;
            plain_window(hdef.track.dt, &g[i], ns - 1, &own, umax, &plo, &phi);
            CHECK_MSG(lo == plo && hi == phi, "scene %d target %d: window [%d, %d), plain [%d, %d)",
                      s, i, lo, hi, plo, phi);
            CHECK_MSG(g[i].path || same_boxes(&a, blen, 0), "scene %d target %d: boxes differ", s, i);
            nudged += !g[i].path && !same_boxes(&a, blen, 1);
            cv += !g[i].path;
            partial += lo > 0 && hi < (ns - 1 + FW_CHUNK - 1) / FW_CHUNK;
            targets++;
            empty += lo >= hi;
            culled += b.nbox == 0;
        }
    }
    printf("  reach windows: %ld targets, %ld out of reach, %ld of them by one test\n", targets,
           empty, culled);
    CHECK(culled > targets / 10 && culled <= empty); /* the shortcut is taken, and only then */
    /* windows in the middle (both ends searched for), and a velocity one ulp
     * off changes the boxes of nearly every target (the comparison sees it) */
    printf("  %ld windows with chunks out of reach at both ends; %ld of %ld constant-velocity "
           "targets' boxes differ at a velocity 1 ulp off\n", partial, nudged, cv);
    CHECK(partial > targets / 100 && nudged > cv * 9 / 10);
    free(paths);
    free(room);
}

/* Two prepared targets alike to the bit (their paths' values, not where they are). */
static bool same_prep(const fw_prep_target *a, const fw_prep_target *b, int plen)
{
    double va[] = {a->east, a->north, a->ve, a->vn, a->sc, a->cc, a->hl, a->hb, a->reach,
                   a->ia_min, a->ib_min};
    double vb[] = {b->east, b->north, b->ve, b->vn, b->sc, b->cc, b->hl, b->hb, b->reach,
                   b->ia_min, b->ib_min};
    if (memcmp(va, vb, sizeof va) != 0 || !a->path != !b->path || a->ns != b->ns)
        return false;
    return !a->path || memcmp(a->path, b->path, sizeof(double) * (size_t)plen) == 0;
}

/* fw_prep_targets_memo over a run of decisions whose targets keep, or change
 * by an ulp, their course and hull: what fw_prep_targets makes, to the bit. */
static void test_prep_memo(void)
{
    enum { NT = 30 };
    fw_helm_def hdef = fw_default_helm_def();
    int plen = fw_prep_path_len(&hdef.track);
    static fw_target tg[NT];
    static fw_prep_target plain[NT], kept[NT];
    static fw_prep_memo memo[NT];
    double *pa = malloc(sizeof(double) * (size_t)(NT * plen));
    double *pb = malloc(sizeof(double) * (size_t)(NT * plen));
    CHECK(pa && pb);
    long changed = 0, same = 0;
    rng = 0x6a09e667f3bcc908ULL;
    fw_own_state own = make_own(false);
    make_scene(&own, false, tg, NT);
    for (int s = 0; s < 120 && pa && pb; s++) {
        hdef.domain.reading = s < 60 ? FW_DOMAIN_ELLIPSE : FW_DOMAIN_TRANSVERSE;
        if (s == 60)
            for (int i = 0; i < NT; i++)
                memo[i].valid = false; /* a memo holds for one domain definition */
        for (int i = 0; i < NT; i++) {
            double u = uniform();
            tg[i].east += 10.0 * (uniform() - 0.5), tg[i].north += 10.0 * (uniform() - 0.5);
            if (u < 0.1)
                tg[i].course = nextafter(tg[i].course, 10.0);
            else if (u < 0.15)
                tg[i].length = nextafter(tg[i].length, 0.0);
            else if (u < 0.2)
                tg[i].breadth = nextafter(tg[i].breadth, 1e3);
            changed += u < 0.2, same += u >= 0.2;
        }
        tg[0].course = s % 2 ? -0.0 : 0.0; /* equal, but not alike: sin gives -0 and +0 */
        fw_prep_targets(&hdef.domain, &hdef.track, tg, NT, plain, pa);
        fw_prep_targets_memo(&hdef.domain, &hdef.track, tg, NT, kept, pb, memo);
        for (int i = 0; i < NT; i++)
            CHECK_MSG(same_prep(&plain[i], &kept[i], plen), "decision %d target %d differs", s, i);
    }
    printf("  prep memo: %ld targets kept their course and hull, %ld changed\n", same, changed);
    CHECK(changed > 500 && same > 2000);
    free(pa);
    free(pb);
}

/* fw_track_predict_steer's headings, yaw rates and rudder angles made plainly:
 * indices made afresh at every order, each piece by fw_nomoto_piece_eval (which
 * track.c inlines, sharing an exponential).  nudge >= 0: the yaw rate after
 * that sub-step one ulp up, a deliberate error.  *ramps, *holds: pieces met. */
static bool plain_steer(const fw_ship *ship, const fw_track_def *def, const fw_own_state *s,
                        const fw_steer_def *ap, fw_track *out, int nudge, long *ramps, long *holds)
{
    int n = fw_track_samples(def), sub = (int)fmax(1.0, round(def->dt / 5.0)), q = 0;
    double hmax = fmin(fabs(ap->max_helm), ship->rudder_max), h = def->dt / sub;
    double psi = s->psi, r = s->r, v = s->rdot, delta = s->delta, U_kn = fw_ms_to_kn(s->U);
    for (int k = 0; k < n; k++) {
        for (int j = 0; j < sub && k > 0; j++, q++) {
            double order = -ap->kp * fw_wrap_pi(psi - ap->psi_ref) - ap->kd * r, turned;
            order = fmax(-hmax, fmin(hmax, order));
            int deg = (int)fmin(90, round(fw_rad_to_deg(fabs(order))));
            fw_nomoto_indices ix;
            fw_nomoto_piece pc;
            if (fw_nomoto_indices_at(fw_ship_kb(ship, order), U_kn, deg, &ix, NULL))
                return false;
            double ramp = fmin(h, fabs(order - delta) / ship->rudder_rate);
            double rho = order > delta ? ship->rudder_rate : -ship->rudder_rate;
            if (ramp > 0.0) {
                fw_nomoto_piece_init(&pc, &ix, delta, rho, r, v);
                fw_nomoto_piece_eval(&pc, ramp, &r, &v, &turned);
                psi += turned, delta += rho * ramp, ++*ramps;
            }
            if (h - ramp > 0.0) {
                fw_nomoto_piece_init(&pc, &ix, delta, 0.0, r, v);
                fw_nomoto_piece_eval(&pc, h - ramp, &r, &v, &turned);
                psi += turned, ++*holds;
            }
            r = q == nudge ? nextafter(r, INFINITY) : r;
        }
        out->psi[k] = psi, out->r[k] = r, out->rdot[k] = v, out->delta[k] = delta;
    }
    out->n = n;
    return true;
}

/* The autopilot's track (steadying and the return) against plainly made
 * headings, to the bit: own ships straight and turning, sub-steps of 5 and 4
 * s, both ships; a one-ulp error in a yaw rate must be seen. */
static void test_steer_plain(void)
{
    static const char *ships[] = {"c3", "c3-mmg"};
    fw_track got, want;
    fw_track_def defs[2] = {fw_default_track_def(), fw_default_track_def()};
    defs[1].dt = 8.0;
    CHECK(fw_track_alloc(&got, 200, NULL) == FW_OK && fw_track_alloc(&want, 200, NULL) == FW_OK);
    long tracks = 0, ramps = 0, holds = 0, caught = 0, nudges = 0;
    rng = 0x9e3779b97f4a7c15ULL;
    for (int sh = 0; sh < 2; sh++) {
        fw_ship ship;
        CHECK(fw_ship_load(ships[sh], &ship, NULL) == FW_OK);
        for (int s = 0; s < 200; s++) {
            const fw_track_def *def = &defs[s % 2];
            fw_own_state own = make_own(s % 3 != 0);
            fw_steer_def ap = {.psi_ref = own.psi + 3.0 * (uniform() - 0.5),
                               .kp = 0.5 + 2.5 * uniform(), .kd = 5.0 + 35.0 * uniform(),
                               .max_helm = fw_deg_to_rad(10 + 25 * uniform())};
            CHECK(fw_track_predict_steer(&ship, def, &own, &ap, &got, NULL) == FW_OK);
            int nudge = s % 4 == 0 ? 1 + (int)(40 * uniform()) : -1;
            CHECK(plain_steer(&ship, def, &own, &ap, &want, nudge, &ramps, &holds));
            size_t len = sizeof(double) * (size_t)got.n;
            bool same = got.n == want.n && memcmp(got.psi, want.psi, len) == 0 &&
                        memcmp(got.r, want.r, len) == 0 && memcmp(got.rdot, want.rdot, len) == 0 &&
                        memcmp(got.delta, want.delta, len) == 0;
            CHECK_MSG(same == (nudge < 0), "%s state %d: steer track %s the plain one", ships[sh],
                      s, same ? "equals (with an error in it)" : "differs from");
            caught += nudge >= 0 && !same, nudges += nudge >= 0;
            tracks++;
        }
    }
    printf("  steer tracks: %ld, %ld ramps and %ld holds, %ld of %ld deliberate errors seen\n",
           tracks, ramps, holds, caught, nudges);
    CHECK(ramps > 50 * tracks && holds > 50 * tracks && nudges > 50 && caught == nudges);
    fw_track_free(&got);
    fw_track_free(&want);
}

/* encounter.h's ranking rule, restated: is target i (as p) ranked before j? */
static bool ranked_before(const fw_assessment *p, int i, const fw_assessment *q, int j)
{
    if (p->enters_domain != q->enters_domain)
        return p->enters_domain;
    if (p->enters_domain && p->t_range != q->t_range)
        return p->t_range < q->t_range;
    if (p->enters_domain && p->t_enter != q->t_enter)
        return p->t_enter < q->t_enter;
    if (p->dcpa != q->dcpa)
        return p->dcpa < q->dcpa;
    return p->range != q->range ? p->range < q->range : i < j;
}

/* Is order[0..n-1] a permutation ranked strictly by the rule (then it is the
 * one such order: the rule with the index is a strict total order), with
 * each rank set?  swap >= 0: entries swap, swap + 1 exchanged first. */
static bool ranked(const fw_assessment *as, int *order, int n, int swap)
{
    if (swap >= 0 && swap + 1 < n) {
        int x = order[swap];
        order[swap] = order[swap + 1], order[swap + 1] = x;
    }
    bool ok = true, seen[200] = {false};
    for (int k = 0; k < n; k++) {
        ok = ok && !seen[order[k]] && as[order[k]].rank == (swap < 0 ? k : as[order[k]].rank);
        seen[order[k]] = true;
        ok = ok && (k == 0 || ranked_before(&as[order[k - 1]], order[k - 1], &as[order[k]],
                                            order[k]));
    }
    return ok;
}

/* fw_assess's danger order (by insertion for up to 32 targets, merge sort
 * above) against the rule, with ties broken by the index (targets repeated
 * from the scene), on 600 scenes of 1-60 targets; an exchange of two
 * neighbours must be seen. */
static void test_danger_order(void)
{
    static fw_target tg[200];
    static fw_assessment as[200];
    static int order[400];
    fw_colregs_def cdef = fw_default_colregs_def();
    fw_domain_def dom = fw_default_domain_def();
    cdef.rank_range_m = FW_NMILE;
    long scenes = 0, ties = 0, caught = 0, swaps = 0, big = 0;
    rng = 0x5851f42d4c957f2dULL;
    for (int s = 0; s < 600; s++) {
        fw_own_state own = make_own(s % 2 == 1);
        int n = 1 + s % 60;
        make_scene(&own, s % 3 == 0, tg, n);
        for (int i = n / 2; i < n && s % 4 == 0; i++)
            tg[i] = tg[i - n / 2], ties++; /* the same keys, another index */
        cdef.rank_range_m = s % 5 == 0 ? 0.0 : FW_NMILE;
        fw_assess(&cdef, &dom, 600.0, &own, tg, n, as, order);
        CHECK_MSG(ranked(as, order, n, -1), "scene %d (%d targets): not in the rule's order", s,
                  n);
        if (n > 1) {
            bool seen = !ranked(as, order, n, s % (n - 1));
            caught += seen, swaps++;
        }
        scenes++, big += n > 32;
    }
    printf("  danger order: %ld scenes (%ld of more than 32 targets), %ld repeated targets, "
           "%ld of %ld exchanges seen\n", scenes, big, ties, caught, swaps);
    CHECK(big > 100 && ties > 1000 && caught == swaps);
}

int main(void)
{
    const char *wd = getenv("FAIRWAY_WRITE_DIGESTS");
    if (wd && *wd && !(digest_out = fopen(wd, "w")))
        return 1;
    TEST_RUN(test_chunk_bound);
    TEST_RUN(test_reach_window);
    TEST_RUN(test_prep_memo);
    TEST_RUN(test_steer_plain);
    TEST_RUN(test_danger_order);
    TEST_RUN(test_decisions_unchanged);
    fw_track_free(&tr);
    if (digest_out)
        fclose(digest_out);
    return TEST_EXIT();
}
