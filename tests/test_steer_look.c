/* test_steer_look.c - a steered ship's look along its swing (world/steer_look.c,
 * fw_steer_pass_along and fw_steer_conflict_pass) against the same found the
 * long way: every ship followed over every sample of the whole path.  The
 * look skips the ships a bound puts out of reach, stops sampling the path
 * once the ship is turned and at speed until a ship needs it, takes the
 * straight-line pass as a cap and remembers each ship's velocity by its
 * key from one decision to the next; none of that may change an answer.
 * Random scenes (fixed seed): turns either way up to 180 deg, speeding up and
 * slowing down, a current, ships everywhere within reach and beyond. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"
#include "test.h"
#include "world/steer.h"
#include "world/steer_internal.h"

static unsigned long long rng_state = 12345;
static double urand(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

enum { kN = 60 }; /* samples: kCloseS / kSampleS */

/* The path the look judges (steer_look.c's model, written out whole): the
 * heading swings to psi_to at K' / L x helm per metre run, each sample
 * taken along its mid-heading, the current added. */
static void whole_path(const steer_ctl *c, const fw_own_state *o, double chi, double v,
                       double *pe, double *pn)
{
    double psi_to = fw_steer_heading_for(chi, v, o->cur_e, o->cur_n), psi = o->psi;
    double per_m = FW_STEER_K_ND / c->def.length * c->def.helm_max, e = 0.0, n = 0.0, prev = 0.0;
    for (int k = 0; k < kN; k++) {
        double run = fw_steer_run_in(o->U, v, kSampleS * (k + 1)), dr = run - prev;
        double left = fw_wrap_pi(psi_to - psi), turn = fmin(fabs(left), per_m * dr);
        double mid = psi + copysign(0.5 * turn, left);
        psi += copysign(turn, left);
        e += dr * sin(mid) + o->cur_e * kSampleS, n += dr * cos(mid) + o->cur_n * kSampleS;
        pe[k] = e, pn[k] = n, prev = run;
    }
}

/* The nearest any ship it is closing comes on that path, or cap. */
static double long_way(const steer_ctl *c, const fw_sense *in, double chi, double v, double cap)
{
    double pe[kN], pn[kN], best = cap;
    whole_path(c, in->own, chi, v, pe, pn);
    for (int i = 0; i < in->n; i++) {
        const fw_target *t = &in->targets[i];
        double te, tn, dx = t->east - in->own->east, dy = t->north - in->own->north;
        fw_velocity(t->speed, t->course, &te, &tn);
        double d0 = hypot(dx, dy), dmin = INFINITY;
        if (d0 > (t->speed + fmax(in->own->U, v) + 2.0) * kCloseS)
            continue;
        for (int k = 0; k < kN; k++) {
            double s = kSampleS * (k + 1);
            dmin = fmin(dmin, hypot(dx + te * s - pe[k], dy + tn * s - pn[k]));
        }
        if (dmin < d0)
            best = fmin(best, dmin);
    }
    return best;
}

/* A steered ship of the default kind, its lane due north. */
static steer_ctl *steered(void)
{
    fw_alter_def def = fw_default_alter_def();
    def.lane = (fw_lane_info){.np = 2, .e = {0.0, 0.0}, .n = {-1e4, 5e4}};
    fw_controller *ctl = NULL;
    CHECK(fw_steer_controller_create(&def, &ctl, NULL) == FW_OK);
    return (steer_ctl *)ctl;
}

/* m: how far apart two answers are (none, INFINITY, is an answer too) */
static double off_by(double got, double want)
{
    if (isinf(want) || isinf(got))
        return isinf(want) && isinf(got) ? 0.0 : INFINITY;
    return fabs(got - want);
}

static void random_scene(fw_own_state *o, fw_target *t, int n)
{
    *o = (fw_own_state){.east = 0.0, .north = 0.0, .psi = 2.0 * FW_PI * urand(),
                        .U = 0.5 + 11.5 * urand()};
    if (urand() < 0.5) {
        double rate = 1.5 * urand(), set = 2.0 * FW_PI * urand();
        fw_velocity(rate, set, &o->cur_e, &o->cur_n);
    }
    for (int i = 0; i < n; i++) {
        /* near ones (within a kilometre) and far ones (to 8 km) */
        double r = urand() < 0.5 ? 1000.0 * urand() : 8000.0 * urand(), b = 2.0 * FW_PI * urand();
        t[i] = (fw_target){.east = r * sin(b), .north = r * cos(b),
                           .course = 2.0 * FW_PI * urand(), .speed = 12.0 * urand(),
                           .key = 1 + (int)(20.0 * urand())};
        snprintf(t[i].id, sizeof t[i].id, "ship.%d", i);
        t[i].heading = t[i].course, t[i].stw = t[i].speed;
    }
}

/* Thousands of scenes: the look's answer is the long way's to a micrometre
 * (the two sum the samples alike; the long way takes hypot where the look
 * compares squares), and so is the conflict look's (the straight pass over
 * 10 minutes, then the swing capped by it).  A ship's key seen again with
 * another course (the memo) must not keep its old velocity. */
static void test_look_is_the_long_way(void)
{
    steer_ctl *c = steered();
    enum { kScenes = 3000, kMax = 14 };
    fw_target t[kMax];
    fw_own_state o;
    int worst = 0, worst_c = 0, found = 0;
    double err = 0.0, err_c = 0.0;
    for (int s = 0; s < kScenes; s++) {
        int n = 1 + (int)(kMax * urand()) % kMax;
        random_scene(&o, t, n);
        fw_sense in = {.t = s, .own = &o, .targets = t, .n = n};
        CHECK(fw_steer_see(c, &in));
        double chi = o.psi + FW_PI * (2.0 * urand() - 1.0); /* up to 180 deg either way */
        double v = urand() < 0.4 ? o.U : 0.5 + 11.5 * urand();   /* held, or a ramp */
        double cap = urand() < 0.5 ? INFINITY : 2000.0 * urand();
        double got = fw_steer_pass_along(c, &in, chi, v, cap), want = long_way(c, &in, chi, v, cap);
        double e = off_by(got, want);
        if (e > err)
            err = e, worst = s;
        found += isfinite(want) && want < cap;
        double straight = fw_steer_pass_within(c, &in, chi, o.U, kConflictS, false, NULL);
        double conflict = fmin(straight, long_way(c, &in, chi, o.U, INFINITY));
        e = off_by(fw_steer_conflict_pass(c, &in, chi), conflict);
        if (e > err_c)
            err_c = e, worst_c = s;
    }
    CHECK_MSG(err < 1e-6, "scene %d: the look is %g m off the long way", worst, err);
    CHECK_MSG(err_c < 1e-6, "scene %d: the conflict look is %g m off", worst_c, err_c);
    /* the scenes are not all empty: most find a ship */
    CHECK_MSG(found > kScenes / 3, "%d of %d scenes find a ship", found, kScenes);
    fw_controller_destroy(&c->base);
}

/* Gathering way from 2 to 10 m/s it lags far behind the line it will sail
 * at 10 m/s (640 m by the end of the look).  A ship crossing from starboard
 * at 8 m/s, 800 m east and 450 m north, comes no nearer that line than 343
 * m, but meets the ship itself at 100 s (run 450 m: 2 s + 0.025 s^2).
 * With another ship known at 300 m (the cap), a look that stopped sampling
 * on its course but still speeding up (its stray from the line judged by
 * the first sample, 39 m) would have put her out of reach. */
static void test_gathering_way_crossed(void)
{
    steer_ctl *c = steered();
    fw_own_state o = {.psi = 0.0, .U = 2.0};
    double west = fw_deg_to_rad(270.0);
    fw_target t = {.id = "crossing", .east = 800.0, .north = 450.0, .course = west, .speed = 8.0,
                   .heading = west, .stw = 8.0};
    fw_sense in = {.own = &o, .targets = &t, .n = 1};
    CHECK(fw_steer_see(c, &in));
    double got = fw_steer_pass_along(c, &in, 0.0, 10.0, 300.0);
    CHECK_NEAR(got, long_way(c, &in, 0.0, 10.0, 300.0), 1e-6);
    CHECK_NEAR(got, 0.0, 1e-6);
    fw_controller_destroy(&c->base);
}

int main(void)
{
    TEST_RUN(test_look_is_the_long_way);
    TEST_RUN(test_gathering_way_crossed);
    return TEST_EXIT();
}
