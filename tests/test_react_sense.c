/* test_react_sense.c - the reacting background ships decide on what they
 * know (world/reactions.h, "Sensing").
 *
 * The crossing: t (taken by fairway, Nomoto c3-paper, no controller: it
 * holds 000 at 8 kn from the origin) and g (the kinematic source's, 090 at
 * 8 kn from 3000 m west, 3000 m north): g must give way to t, on its
 * starboard side (rule 15), on a collision course.
 *
 *   perfect: g slows at its first look (t = 0), on the truth
 *   ais, 1 km fog (t 4.2 km off: out of sight, so not seen by eye),
 *     position 30 m, latency 2 s: g knows nothing of t at t = 0 (its first
 *     report is on its way), and gives way at a later look on t's reported
 *     position: the record's known position is t's report, recomputed here
 *     from t's stream (core/rng.h FW_PURPOSE_AIS_TX: the phase, then five
 *     normals a report) and dead reckoned to the look, to 1e-9 m; it is
 *     more than 1 m from the truth; and the closest approach g acted on is
 *     that of t's report, to 1e-6 m, not the truth's (more than 1 m apart)
 *   ais+radar, clear: the same reports (in sight: an AIS report still comes
 *     first)
 *   radar, fog: g tracks t by its own radar: no action before the track is
 *     shown (60 s), then on the track (known_how radar)
 */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "geom/geom.h"
#include "test.h"
#include "traffic/source.h"
#include "world/world.h"

static fw_ship c3p;

static fw_world *crossing(const fw_sensing_def *sense, double visibility, uint64_t seed)
{
    fw_error err = {0};
    double v = fw_kn_to_ms(8);
    fw_kin_ship ks[2] = {
        {.start = {.id = "t", .east = 0, .north = 0, .course = 0.0, .speed = v, .length = 150,
                   .breadth = 25}},
        {.start = {.id = "g", .east = -3000, .north = 3000, .course = 0.5 * FW_PI, .speed = v,
                   .length = 150, .breadth = 25}}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = ks;
    kd.n = 2;
    fw_world_def wd = fw_default_world_def();
    wd.reactions = fw_default_reactions_def(); /* colregs, give way by speed */
    wd.reactions.colregs.visibility = visibility;
    wd.reactions.sensing = *sense;
    wd.seed = seed;
    fw_world *w = NULL;
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK);
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    fw_vessel_def own = fw_default_vessel_def();
    own.id = "own", own.role = FW_ROLE_OWN, own.ship = &c3p, own.dynamics = FW_DYN_NOMOTO;
    own.north = -30000, own.course = FW_PI, own.speed = fw_kn_to_ms(5); /* far away */
    CHECK(fw_world_add_vessel(w, &own, NULL, &err) == FW_OK);
    fw_vessel_def td = fw_default_vessel_def();
    td.ship = &c3p;
    td.dynamics = FW_DYN_NOMOTO;
    CHECK_MSG(fw_world_take(w, "t", &td, NULL, &err) == FW_OK, "%s", err.msg);
    CHECK(fw_world_start(w, &err) == FW_OK);
    return w;
}

/* g's first order in 120 s (into *out; false: none). */
static bool first_order(const fw_sensing_def *sense, double visibility, fw_reaction *out)
{
    fw_error err = {0};
    fw_world *w = crossing(sense, visibility, 1);
    for (int k = 0; k < 120; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    int n;
    const fw_reaction *r = fw_world_reactions(w, &n);
    bool found = false;
    for (int i = 0; i < n && !found; i++)
        if (strcmp(r[i].ship, "g") == 0 && r[i].kind == FW_REACT_SLOW) {
            *out = r[i];
            found = true;
        }
    fw_world_destroy(w);
    return found;
}

/* t's report k (sent at ts[k]) from its stream, as fw_ais_tx_step draws it:
 * t holds 000 at v, not turning (10 s at 8 kn). */
static void reports(const fw_sensing_def *d, uint64_t seed, int nrep, double *ts, double *e,
                    double *n, double *sog, double *cog)
{
    fw_rng s = fw_rng_make(seed, fw_rng_vessel_key("t"), FW_PURPOSE_AIS_TX);
    double v = fw_kn_to_ms(8), phase = fw_rng_uniform(&s);
    for (int k = 0; k < nrep; k++) {
        ts[k] = k == 0 ? 0.0 : k == 1 ? phase * 10.0 : ts[k - 1] + 10.0;
        /* whole steps: a report is sent at the first step at or after it is due */
        ts[k] = ceil(ts[k] - 1e-9);
        e[k] = 0.0 + d->position_sd * fw_rng_normal(&s);
        n[k] = v * ts[k] + d->position_sd * fw_rng_normal(&s);
        sog[k] = fmax(0.0, v + d->sog_sd * fw_rng_normal(&s));
        cog[k] = fw_wrap_2pi(0.0 + d->cog_sd * fw_rng_normal(&s));
        (void)fw_rng_normal(&s); /* heading */
    }
}

static void test_perfect(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    fw_reaction x;
    CHECK(first_order(&d, 0.0, &x));
    printf("perfect: g gives way to %s at %.0f s, CPA %.1f m (known as the truth: %d)\n",
           x.other, x.t, x.dcpa_before, x.known_how == FW_KNOWN_TRUTH);
    CHECK(x.t < 1.0 && x.known_how == FW_KNOWN_TRUTH && strcmp(x.other, "t") == 0);
}

/* g's closest approach to a ship at (e, n) going sog along cog, g at its
 * truth at time T (090 at 8 kn from (-3000, 3000), untold until then). */
static double dcpa_from_g(double T, double e, double n, double sog, double cog)
{
    double v = fw_kn_to_ms(8), ge = -3000.0 + v * T, gn = 3000.0, tc, dc;
    fw_cpa(e - ge, n - gn, sog * sin(cog) - v, sog * cos(cog), &tc, &dc);
    return dc;
}

static void test_ais(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS;
    d.position_sd = 30.0;
    d.latency = 2.0;
    fw_reaction x;
    CHECK(first_order(&d, 1000.0, &x));
    double ts[20], e[20], n[20], sog[20], cog[20];
    reports(&d, 1, 20, ts, e, n, sog, cog);
    int k = 0; /* the newest report that had arrived by the look */
    while (k + 1 < 20 && ts[k + 1] + d.latency <= x.t + 1e-9)
        k++;
    double age = x.t - ts[k];
    double ke = e[k] + sog[k] * age * sin(cog[k]), kn = n[k] + sog[k] * age * cos(cog[k]);
    double off = hypot(x.known_e - x.true_e, x.known_n - x.true_n);
    double dk = dcpa_from_g(x.t, ke, kn, sog[k], cog[k]);
    double dt = dcpa_from_g(x.t, x.true_e, x.true_n, fw_kn_to_ms(8), 0.0);
    printf("ais (fog, 30 m, 2 s late): g gives way at %.0f s on t's report of %.0f s (%.1f s "
           "old): %.1f m from the truth; CPA acted on %.1f m (the report's %.1f, the truth's "
           "%.1f)\n", x.t, ts[k], age, off, x.dcpa_before, dk, dt);
    CHECK(x.t >= d.latency - 1e-9 && x.known_how == FW_KNOWN_AIS);
    CHECK(fabs(x.known_e - ke) < 1e-9 && fabs(x.known_n - kn) < 1e-9);
    CHECK(off > 1.0);
    CHECK(fabs(x.dcpa_before - dk) < 1e-6 && fabs(dk - dt) > 1.0);
}

static void test_ais_radar_clear(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_AIS_RADAR;
    fw_reaction x;
    CHECK(first_order(&d, 0.0, &x));
    printf("ais+radar (clear): g gives way at %.0f s, t known by %s, %.1f m from the truth\n",
           x.t, x.known_how == FW_KNOWN_AIS ? "AIS" : "?",
           hypot(x.known_e - x.true_e, x.known_n - x.true_n));
    CHECK(x.known_how == FW_KNOWN_AIS && x.t < 1.0);
}

static void test_radar_fog(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    d.mode = FW_SENSE_RADAR;
    fw_reaction x;
    CHECK(first_order(&d, 1000.0, &x));
    printf("radar (fog): g gives way at %.0f s on its radar track of t, %.1f m from the truth\n",
           x.t, hypot(x.known_e - x.true_e, x.known_n - x.true_n));
    CHECK(x.known_how == FW_KNOWN_RADAR && x.t >= 60.0 - 1e-9);
    CHECK(hypot(x.known_e - x.true_e, x.known_n - x.true_n) > 0.0);
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3-paper", &c3p, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_perfect);
    TEST_RUN(test_ais);
    TEST_RUN(test_ais_radar_clear);
    TEST_RUN(test_radar_fog);
    return TEST_EXIT();
}
