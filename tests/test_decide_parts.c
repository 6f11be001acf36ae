/* test_decide_parts - the parts of the avoidance decision that shortcuts
 * replace, each against its plain form on fixed-seed scenes (decide_scenes.h):
 * the scans' chunk bound (clearance.c) chunk by chunk against the same scans
 * without it; the reach window's shortcut for targets out of reach against
 * every chunk's test, and the window (found from either end) and the targets'
 * boxes against both made plainly chunk by chunk; the targets' preparation
 * kept from decision to decision against the preparation made afresh; the
 * autopilot's track (whose pieces track.c evaluates inlined) against its
 * headings made with the library's piece evaluation; the assessment's danger
 * order against the ranking rule.  Each is bit for bit, and each test shows
 * that a deliberate small error is caught.  test_decide checks the whole
 * decision against the reference search. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "avoid/clearance.h"
#include "avoid/policy.h"
#include "core/files.h"
#include "core/units.h"
#include "decide_scenes.h"
#include "test.h"

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
    decide_seed(0x9e3779b97f4a7c15ULL);
    for (int s = 0; s < 160 && paths && room; s++) {
        hdef.domain.reading = s % 2 ? FW_DOMAIN_TRANSVERSE : FW_DOMAIN_ELLIPSE;
        hdef.domain.own_half_length = s % 4 < 2 ? 0.0 : 0.5 * ship.Loa;
        fw_own_state own = decide_own(s % 3 != 0);
        double helm = fw_deg_to_rad(10 + 25 * decide_uniform()) * (s % 5 < 2 ? -1.0 : 1.0);
        CHECK(fw_track_predict(&ship, &hdef.track, &own, helm, &t, NULL) == FW_OK);
        fw_chunk_boxes cb;
        fw_track_boxes(&t, &cb);
        decide_scene(&own, s % 2 == 0, tg, NT);
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
    decide_seed(0x2545f4914f6cdd1dULL);
    for (int s = 0; s < 200 && paths && room; s++) {
        fw_own_state own = decide_own(s % 3 != 0);
        decide_scene(&own, s % 4 == 0, tg, NT);
        fw_prep_targets(&hdef.domain, &hdef.track, tg, NT, g, paths);
        double umax = own.U * (s % 5 == 0 ? 2.0 * decide_uniform() : 1.0);
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
    decide_seed(0x6a09e667f3bcc908ULL);
    fw_own_state own = decide_own(false);
    decide_scene(&own, false, tg, NT);
    for (int s = 0; s < 120 && pa && pb; s++) {
        hdef.domain.reading = s < 60 ? FW_DOMAIN_ELLIPSE : FW_DOMAIN_TRANSVERSE;
        if (s == 60)
            for (int i = 0; i < NT; i++)
                memo[i].valid = false; /* a memo holds for one domain definition */
        for (int i = 0; i < NT; i++) {
            double u = decide_uniform();
            tg[i].east += 10.0 * (decide_uniform() - 0.5), tg[i].north += 10.0 * (decide_uniform() - 0.5);
            if (u < 0.05) /* the velocity's course alone, or the hull's heading */
                tg[i].course = nextafter(tg[i].course, 10.0);
            else if (u < 0.1)
                tg[i].heading = nextafter(tg[i].heading, 10.0);
            else if (u < 0.15)
                tg[i].length = nextafter(tg[i].length, 0.0);
            else if (u < 0.2)
                tg[i].breadth = nextafter(tg[i].breadth, 1e3);
            changed += u < 0.2, same += u >= 0.2;
        }
        tg[0].course = tg[0].heading = s % 2 ? -0.0 : 0.0; /* equal, but not alike: sin gives -0 and +0 */
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
    decide_seed(0x9e3779b97f4a7c15ULL);
    for (int sh = 0; sh < 2; sh++) {
        fw_ship ship;
        CHECK(fw_ship_load(ships[sh], &ship, NULL) == FW_OK);
        for (int s = 0; s < 200; s++) {
            const fw_track_def *def = &defs[s % 2];
            fw_own_state own = decide_own(s % 3 != 0);
            fw_steer_def ap = {.psi_ref = own.psi + 3.0 * (decide_uniform() - 0.5),
                               .kp = 0.5 + 2.5 * decide_uniform(), .kd = 5.0 + 35.0 * decide_uniform(),
                               .max_helm = fw_deg_to_rad(10 + 25 * decide_uniform())};
            CHECK(fw_track_predict_steer(&ship, def, &own, &ap, &got, NULL) == FW_OK);
            int nudge = s % 4 == 0 ? 1 + (int)(40 * decide_uniform()) : -1;
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
    decide_seed(0x5851f42d4c957f2dULL);
    for (int s = 0; s < 600; s++) {
        fw_own_state own = decide_own(s % 2 == 1);
        int n = 1 + s % 60;
        decide_scene(&own, s % 3 == 0, tg, n);
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
    TEST_RUN(test_chunk_bound);
    TEST_RUN(test_reach_window);
    TEST_RUN(test_prep_memo);
    TEST_RUN(test_steer_plain);
    TEST_RUN(test_danger_order);
    return TEST_EXIT();
}
