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
 *   a ship taken from the traffic (t) sees g through the same sensing: in
 *     its view g is g's AIS report dead reckoned (more than 0.1 m, less than
 *     100 m from g's truth, which its truth list keeps); perfect: the truth
 *
 * Rule 19(e) (reactions.h, avoid/policy.h):
 *   background: in 1 km fog g first slows (t out of sight forward of its
 *     beam, 4.2 km off: t's whistle, a 333 m ship's, is heard within 2 nm)
 *     to a speed that clears, not by 19(e); later, within 2 nm of t or with
 *     no speed that keeps 0.5 nm (close quarters it cannot avoid), it
 *     reduces to min_speed (0.3) of its own speed, the record saying 19(e)
 *   own ship (c3-mmg on Nomoto, 12 kn planned, kb fitted from 8 kn) meeting
 *     a 200 m ship head-on at 20 kn closing, in 0.5 nm fog: rule 19(e)'s 8 kn
 *     ordered from the step the other comes within its whistle's 2 nm (to a
 *     step's closing), not before; in clear weather never
 */
#include <math.h>
#include <string.h>

#include "core/units.h"
#include "avoid/encounter.h"
#include "geom/geom.h"
#include "test.h"
#include "traffic/source.h"
#include "world/world.h"

#include "world/controllers.h"

static fw_ship c3p, c3m;

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
    wd.reactions = fw_default_reactions_def(); /* colregs */
    wd.reactions.give_way = FW_GIVE_WAY_SPEED; /* its action a speed order, read below */
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

/* The distance between g (the source's) and t (taken) now, from t's view,
 * and the range of audibility of t's whistle. */
static double g_to_t(fw_world *w, double *audible)
{
    for (int i = 0; i < fw_world_vessel_count(w); i++) {
        const fw_vessel *v = fw_world_vessel(w, fw_world_vessel_at(w, i));
        const fw_target *t = fw_vessel_record(v), *tg;
        const fw_assessment *as;
        int n;
        if (strcmp(t->id, "t") != 0)
            continue;
        fw_vessel_view(v, &tg, &as, &n);
        *audible = fw_fog_signal_range(t->length);
        for (int j = 0; j < n; j++)
            if (strcmp(tg[j].id, "g") == 0)
                return hypot(tg[j].east - t->east, tg[j].north - t->north);
    }
    return NAN;
}

/* How far t's view puts g from where g is after 30 s (t's truth list). */
static double taken_view_error(const fw_sensing_def *d)
{
    fw_error err = {0};
    fw_world *w = crossing(d, 0.0, 1);
    for (int k = 0; k < 30; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    double off = NAN;
    for (int i = 0; i < fw_world_vessel_count(w); i++) {
        const fw_vessel *v = fw_world_vessel(w, fw_world_vessel_at(w, i));
        const fw_target *tg, *tr;
        const fw_assessment *as;
        int n, nt;
        bool sensed;
        if (strcmp(fw_vessel_record(v)->id, "t") != 0)
            continue;
        fw_vessel_view(v, &tg, &as, &n);
        fw_vessel_truth(v, &tr, &nt, &sensed);
        for (int j = 0; j < n; j++)
            for (int q = 0; q < nt; q++)
                if (strcmp(tg[j].id, "g") == 0 && strcmp(tr[q].id, "g") == 0)
                    off = hypot(tg[j].east - tr[q].east, tg[j].north - tr[q].north);
    }
    fw_world_destroy(w);
    return off;
}

static void test_taken_sees(void)
{
    fw_sensing_def d = fw_default_sensing_def();
    double perfect = taken_view_error(&d);
    d.mode = FW_SENSE_AIS;
    double ais = taken_view_error(&d);
    printf("a taken ship's view of g: perfect %.3f m, AIS %.1f m from g's truth\n", perfect, ais);
    CHECK(perfect == 0.0 && ais > 0.1 && ais < 100.0);
}

static void test_rule19e_background(void)
{
    fw_error err = {0};
    fw_sensing_def d = fw_default_sensing_def();
    fw_world *w = crossing(&d, 1000.0, 1);
    int seen = 0, first = -1, e19 = -1;
    double range19 = NAN, audible = NAN;
    for (int k = 0; k < 900 && e19 < 0; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        int n;
        const fw_reaction *r = fw_world_reactions(w, &n);
        for (; seen < n; seen++)
            if (strcmp(r[seen].ship, "g") == 0 && r[seen].kind == FW_REACT_SLOW) {
                first = first < 0 ? seen : first;
                if (e19 < 0 && r[seen].rule19e)
                    e19 = seen, range19 = g_to_t(w, &audible);
            }
    }
    int n;
    const fw_reaction *r = fw_world_reactions(w, &n);
    CHECK(first >= 0 && e19 > first && !r[first].rule19e);
    if (e19 > first && first >= 0) {
        bool heard = range19 <= audible;
        printf("rule 19(e), background: g first slows at %.0f s to %.1f kn, then at %.0f s, t "
               "%.0f m off (%s within %.0f m), to %.1f kn (0.3 of 8)\n",
               r[first].t, fw_ms_to_kn(r[first].speed_to), r[e19].t, range19,
               heard ? "its whistle heard" : "out of earshot, but no speed keeps 0.5 nm", audible,
               fw_ms_to_kn(r[e19].speed_to));
        CHECK(fabs(r[e19].speed_to - 0.3 * fw_kn_to_ms(8)) < 1e-9);
        CHECK(heard || !r[e19].enough);
    }
    fw_world_destroy(w);
}

/* The own ship meeting T (200 m, 10 kn south) head-on from 3 nm, 50 m to
 * starboard of its line, in visibility vis (m, 0: clear): the first step
 * (s) its decision holds rule 19(e), the speed then and T's range then. */
static double own_rule19e(double vis, double *speed, double *range)
{
    fw_error err = {0};
    fw_kin_ship sh = {.start = {.id = "T", .east = 50, .north = 3 * FW_NMILE, .course = FW_PI,
                                .speed = fw_kn_to_ms(10), .length = 200, .breadth = 32}};
    fw_kinematic_def kd = fw_default_kinematic_def();
    kd.ships = &sh;
    kd.n = 1;
    fw_world_def wd = fw_default_world_def();
    fw_policy_controller_def pd = {.ship = &c3m, .helm = fw_default_helm_def(),
                                   .policy = fw_default_policy_def()};
    pd.helm.colregs.visibility = vis;
    pd.policy.route = fw_route_line(0, 0, 0, fw_kn_to_ms(12), 20000);
    fw_world *w = NULL;
    fw_vessel_def vd = fw_default_vessel_def();
    vd.id = "own", vd.role = FW_ROLE_OWN, vd.ship = &c3m, vd.dynamics = FW_DYN_NOMOTO;
    vd.speed = fw_kn_to_ms(12);
    fw_vessel_handle h;
    CHECK(fw_kinematic_source_create(&kd, &wd.source, &err) == FW_OK &&
          fw_world_create(&wd, &w, &err) == FW_OK &&
          fw_policy_controller_create(&pd, &vd.controller, &err) == FW_OK &&
          fw_world_add_vessel(w, &vd, &h, &err) == FW_OK && fw_world_start(w, &err) == FW_OK);
    double first = NAN;
    for (int k = 0; k < 600 && isnan(first); k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        const fw_vessel *v = fw_world_vessel(w, h);
        const fw_decision *dd = fw_vessel_decision(v);
        if (dd->rule19e) {
            const fw_target *tg;
            const fw_assessment *as;
            int n;
            fw_vessel_view(v, &tg, &as, &n);
            first = fw_world_time(w);
            *speed = dd->speed;
            *range = n > 0 ? as[0].range : NAN;
        }
    }
    fw_world_destroy(w);
    return first;
}

static void test_rule19e_own(void)
{
    double speed = NAN, range = NAN;
    double clear = own_rule19e(0.0, &speed, &range);
    CHECK(isnan(clear));
    double fog = own_rule19e(0.5 * FW_NMILE, &speed, &range);
    printf("rule 19(e), own ship: clear never; 0.5 nm fog from %.0f s, T at %.0f m (its "
           "whistle heard within %.0f m), %.1f kn ordered\n",
           fog, range, 2 * FW_NMILE, fw_ms_to_kn(speed));
    /* the least speed: c3-mmg's lowest fitted speed, 4 kn */
    CHECK(!isnan(fog) && fabs(speed - fw_kn_to_ms(c3m.nomoto.speed_min_kn)) < 1e-9 &&
          fabs(speed - fw_kn_to_ms(4)) < 1e-9);
    CHECK(range <= 2 * FW_NMILE && range > 2 * FW_NMILE - 1.5 * fw_kn_to_ms(22));
}

int main(void)
{
    fw_error err = {0};
    if (fw_ship_load("c3-paper", &c3p, &err) || fw_ship_load("c3-mmg", &c3m, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    TEST_RUN(test_perfect);
    TEST_RUN(test_ais);
    TEST_RUN(test_ais_radar_clear);
    TEST_RUN(test_radar_fog);
    TEST_RUN(test_taken_sees);
    TEST_RUN(test_rule19e_background);
    TEST_RUN(test_rule19e_own);
    return TEST_EXIT();
}
