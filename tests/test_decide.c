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
 * which both searches share.  The parts the search's shortcuts replace are
 * checked one by one against their plain forms in test_decide_parts.c.
 * FAIRWAY_WRITE_DIGESTS=FILE writes the digests found instead. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/clearance.h"
#include "avoid/policy.h"
#include "core/files.h"
#include "core/units.h"
#include "decide_scenes.h"
#include "helm_reference.h"
#include "test.h"


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

/* over every group: band searches that found a helm within it, none */
static int band_found, band_left;

/* The same searches with a band about the own ship's heading (helm_search.h
 * fw_helm_set_band), 300 to 2100 m of room to starboard and less to port:
 * the two results agree bit for bit (not hashed: the digests are the
 * searches' without a band). */
static void banded(fw_helm_ctx *ctx, fw_helm_ref *ref, const fw_own_state *own,
                   const fw_target *tg, int n, const int *allowed, int scene)
{
    fw_helm_band b = {.on = true, .east = own->east + 10.0, .north = own->north - 20.0,
                      .course = own->psi + 0.1 * (scene % 3 - 1),
                      .room_starboard = 300.0 + 600.0 * (scene % 4),
                      .room_port = scene % 5 == 0 ? 0.0 : 200.0 + 400.0 * (scene % 3)};
    fw_helm_set_band(ctx, &b);
    fw_helm_ref_set_band(ref, &b);
    for (int a = 0; a < 3; a++) {
        fw_helm_result rn, rr;
        fw_error err = {0};
        fw_helm_begin(ctx, own);
        CHECK(fw_helm_search(ctx, tg, n, allowed[a], &rn, &err) == FW_OK);
        fw_helm_begin(ctx, own);
        CHECK(fw_helm_search_reference(ref, ctx, tg, n, allowed[a], &rr, &err) == FW_OK);
        CHECK_MSG(same_result(&rn, &rr) && rn.band_left == rr.band_left,
                  "banded scene %d (%d targets, allowed %d): side %d/%d helm %.17g/%.17g "
                  "clearance %.17g/%.17g left %d/%d",
                  scene, n, allowed[a], rn.side, rr.side, rn.helm, rr.helm, rn.clearance,
                  rr.clearance, rn.band_left, rr.band_left);
        band_left += rn.band_left;
        band_found += rn.threat && rn.side != FW_SIDE_NONE;
    }
    fw_helm_set_band(ctx, NULL);
    fw_helm_ref_set_band(ref, NULL);
}

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
    fw_own_state own = decide_own(turning_now);
    decide_scene(&own, dense, tg, n);
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
    banded(ctx, ref, &own, tg, n, allowed, tl->scenes);
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
    decide_seed(88172645463325252ULL ^ mix(14695981039346656037ull, key, strlen(key)));
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
    printf("  with a band: %d searches found a helm within it, %d none\n", band_found, band_left);
    CHECK(band_found > 100 && band_left > 100); /* both outcomes compared */
}

/* fw_target_min2_cap with the targets' prepared boxes (which bound a chunk
 * before its offsets) against the same without them, chunk by chunk, at caps
 * below 1 (where that bound is used): the same to the bit wherever either is
 * below the cap, both at or above it otherwise.  Own ships turning hard (the
 * frame's turn in a step is part of the bound), both readings, targets on
 * predicted turning paths too. */

int main(void)
{
    const char *wd = getenv("FAIRWAY_WRITE_DIGESTS");
    if (wd && *wd && !(digest_out = fopen(wd, "w")))
        return 1;
    TEST_RUN(test_decisions_unchanged);
    fw_track_free(&tr);
    if (digest_out)
        fclose(digest_out);
    return TEST_EXIT();
}
