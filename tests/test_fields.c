/* test_fields.c - the environment's fields over time (env/env.h): gusts and
 * the spring-neap tidal stream, and the scenario's environment: section.
 *
 *   gusts (Gauss-Markov, I = 0.1 of 10 m/s, T = 30 s, 1 s steps, 400000
 *     steps): the same seed gives the same series bit for bit, another seed
 *     another; sample mean 10 m/s within 0.05 m/s (about 4 standard errors,
 *     sigma sqrt(2 T / n) = 0.012 m/s), standard deviation 1 m/s within 3%
 *     (about 3.5 standard errors, sqrt(T / n) = 0.9%), lag-1 autocorrelation
 *     exp(-1/30) within 0.005
 *   a gusty world: the own ship's track the same for the same seed, another
 *     for another, both within 5% of the steady wind's; a steady wind makes
 *     no stream
 *   the tidal stream (2 kn springs, 1 kn neaps): the greatest flood at
 *     springs is 2 kn exactly, the greatest flood nearest neaps 1 kn within
 *     0.01 kn (env.h: 0.3% of spring - neap); its drift (closed form) equals
 *     the velocity's integral (Simpson, 60 s) over three days to 0.01 m; no
 *     neap rate: the unmodulated stream, bit for bit
 *   the scenario: the Dover network's charted stream (networks/dover/
 *     tide.yaml) with an override; the wind's keys swept as a study axis
 *     would (fw_scenario_load_with); bad values: FILE:LINE: FIELD
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "env/env.h"
#include "scenario/scenario.h"
#include "test.h"
#include "test_ship.h"
#include "world/world.h"

static fw_wind gusty(void)
{
    return (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = 10.0, .from = 1.0,
                     .gust_intensity = 0.1, .gust_time = 30.0};
}

/* n speeds of the gusty wind drawn from seed's gust stream. */
static void series(uint64_t seed, int n, double *out)
{
    fw_wind w = gusty();
    fw_rng r = fw_rng_make(seed, 0, FW_PURPOSE_GUST);
    fw_wind_gust_start(&w, &r);
    for (int k = 0; k < n; k++) {
        double from;
        fw_wind_at(&w, 0.0, 0.0, k, &out[k], &from);
        fw_wind_gust_step(&w, 1.0, &r);
    }
}

static void test_gust_statistics(void)
{
    enum { N = 400000 };
    double *a = malloc(N * sizeof *a), *b = malloc(N * sizeof *b);
    series(7, N, a);
    series(7, N, b);
    CHECK(memcmp(a, b, N * sizeof *a) == 0);
    series(8, N, b);
    CHECK(memcmp(a, b, N * sizeof *a) != 0);
    double sum = 0.0, lo = INFINITY;
    for (int k = 0; k < N; k++)
        sum += a[k], lo = fmin(lo, a[k]);
    double mean = sum / N, ss = 0.0, lag = 0.0;
    for (int k = 0; k < N; k++) {
        ss += (a[k] - mean) * (a[k] - mean);
        if (k > 0)
            lag += (a[k] - mean) * (a[k - 1] - mean);
    }
    double sd = sqrt(ss / (N - 1)), rho1 = lag / ss;
    printf("  gusts, I 0.1 of 10 m/s, T 30 s, %d steps: mean %.4f m/s, sd %.4f m/s, "
           "lag-1 correlation %.4f (exp(-1/30) = %.4f), least %.2f m/s\n",
           N, mean, sd, rho1, exp(-1.0 / 30.0), lo);
    CHECK_NEAR(mean, 10.0, 0.05);
    CHECK_REL(sd, 1.0, 0.03);
    CHECK_NEAR(rho1, exp(-1.0 / 30.0), 0.005);
    CHECK(lo >= 0.0);
    /* a steady wind stays put */
    fw_wind w = gusty();
    w.gust_intensity = 0.0;
    fw_rng r = fw_rng_make(7, 0, FW_PURPOSE_GUST);
    fw_wind_gust_start(&w, &r);
    fw_wind_gust_step(&w, 1.0, &r);
    CHECK(w.gust == 0.0 && r.counter == 0);
    free(a);
    free(b);
}

static fw_ship c3;

/* The own ship's position after 20 minutes at 12 kn north in the gusty
 * wind (25 kn mean from 090), world seed `seed`; *streams: the world's. */
static fw_mmg_state gusty_run(uint64_t seed, double intensity, int *streams)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.seed = seed;
    wd.env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(25.0),
                            .from = FW_PI / 2, .gust_intensity = intensity, .gust_time = 20.0};
    fw_world *w = NULL;
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    fw_vessel_def vd = fw_default_vessel_def();
    vd.ship = &c3;
    vd.speed = fw_kn_to_ms(12.0);
    vd.controller = NULL; /* helm amidships */
    fw_vessel_handle h;
    CHECK_MSG(fw_world_add_vessel(w, &vd, &h, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    for (int k = 0; k < 1200; k++)
        CHECK_MSG(fw_world_step(w, 1.0, &err) == FW_OK, "%s", err.msg);
    fw_mmg_state x = *fw_vessel_motion(fw_world_vessel(w, h));
    *streams = fw_world_streams(w);
    fw_world_destroy(w);
    return x;
}

static void test_gusty_world(void)
{
    int n1, n2, n3, n0;
    fw_mmg_state a = gusty_run(3, 0.15, &n1), b = gusty_run(3, 0.15, &n2);
    fw_mmg_state c = gusty_run(4, 0.15, &n3), d = gusty_run(3, 0.0, &n0);
    printf("  c3-mmg, 12 kn north, 25 kn from 090, 20 min: steady wind east %.1f m; gusts "
           "I 0.15 T 20 s: seed 3 %.1f m, seed 4 %.1f m\n", d.east, a.east, c.east);
    CHECK(memcmp(&a, &b, sizeof a) == 0);
    CHECK(a.east != c.east);
    CHECK(n1 == 1 && n0 == 0);
    /* gusts about the steady wind: the track near the steady one (the ship
     * luffs up into the wind either way, helm amidships: test_wind.c) */
    CHECK(fabs(a.east - d.east) < 0.05 * fabs(d.east) && a.east != d.east);
}

static void test_tidal_springs_neaps(void)
{
    const double kn = fw_kn_to_ms(1.0);
    fw_current c = fw_current_tidal_sn(2.0 * kn, 1.0 * kn, fw_deg_to_rad(85.0), FW_M2_PERIOD_S,
                                       0.0, 0.0);
    fw_error err = {0};
    fw_env env = {.current = c};
    CHECK_MSG(fw_env_check(&env, &err) == FW_OK, "%s", err.msg);
    double ve, vn;
    fw_current_at(&c, 0.0, 0.0, 0.0, &ve, &vn);
    CHECK_NEAR(hypot(ve, vn) / kn, 2.0, 1e-12);
    double tn = 0.5 * FW_SPRING_NEAP_S, best = 0.0;
    for (double t = tn - 0.5 * FW_M2_PERIOD_S; t <= tn + 0.5 * FW_M2_PERIOD_S; t += 10.0) {
        fw_current_at(&c, 0.0, 0.0, t, &ve, &vn);
        double along = (ve * sin(c.set) + vn * cos(c.set)) / kn;
        best = fmax(best, along);
    }
    printf("  tidal 2 kn springs, 1 kn neaps: spring-neap period %.3f days, the greatest "
           "flood nearest neaps %.4f kn\n", FW_SPRING_NEAP_S / 86400.0, best);
    CHECK_NEAR(FW_SPRING_NEAP_S / 86400.0, 14.765, 0.001);
    CHECK_NEAR(best, 1.0, 0.01);
    /* the drift in closed form against Simpson's rule, 60 s, over 3 days */
    c.t_max = 4000.0, c.t_spring = -2e5;
    double T = 3 * 86400.0, h = 60.0, se = 0.0, sn = 0.0;
    int n = (int)(T / h);
    for (int k = 0; k <= n; k++) {
        double wgt = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        fw_current_at(&c, 0.0, 0.0, 100.0 + k * h, &ve, &vn);
        se += wgt * ve, sn += wgt * vn;
    }
    se *= h / 3.0, sn *= h / 3.0;
    double de, dn;
    fw_current_drift(&c, 0.0, 0.0, 100.0, 100.0 + T, &de, &dn);
    CHECK_NEAR(de, se, 0.01);
    CHECK_NEAR(dn, sn, 0.01);
    /* without a neap rate: the unmodulated stream's very formula */
    fw_current u = fw_current_tidal(1.5, 0.3, FW_M2_PERIOD_S, 700.0);
    fw_current_at(&u, 0.0, 0.0, 12345.0, &ve, &vn);
    double v = 1.5 * cos(2.0 * FW_PI * (12345.0 - 700.0) / FW_M2_PERIOD_S);
    CHECK(ve == v * sin(0.3) && vn == v * cos(0.3));
    /* a neap rate above the spring rate is refused */
    env.current = fw_current_tidal_sn(1.0, 2.0, 0.0, FW_M2_PERIOD_S, 0.0, 0.0);
    CHECK(fw_env_check(&env, &err) == FW_EINPUT);
}

/* path's scenario with settings laid over it; its status, *err its message. */
static fw_status load(const char *path, const fw_setting *set, int n, fw_scenario *s,
                      fw_error *err)
{
    char full[1024];
    snprintf(full, sizeof full, "%s/%s", fw_data_root(), path);
    return fw_scenario_load_with(full, set, n, s, err);
}

static void test_scenario_environment(void)
{
    fw_scenario *s = malloc(sizeof *s);
    fw_error err = {0};
    const double kn = fw_kn_to_ms(1.0);
    fw_setting tide[] = {{"environment.current.tidal.network", "true"},
                         {"environment.current.tidal.max_flood_s", "3600"}};
    CHECK_MSG(load("scenarios/traffic/dover-crossing.yaml", tide, 2, s, &err) == FW_OK, "%s",
              err.msg);
    const fw_current *c = &s->env.current;
    CHECK(c->kind == FW_FIELD_TIDAL);
    CHECK_NEAR(c->rate / kn, 2.25, 1e-12);
    CHECK_NEAR(c->neap_rate / kn, 1.25, 1e-12);
    CHECK_NEAR(fw_rad_to_deg(c->set), 85.0, 1e-9);
    CHECK(c->t_max == 3600.0 && c->t_spring == 0.0);
    /* the wind swept as an axis would */
    fw_setting wind[] = {{"environment.wind.speed_kn", "30"},
                         {"environment.wind.from_deg", "270"},
                         {"environment.wind.gust_intensity", "0.1"},
                         {"environment.wind.gust_time_s", "30"}};
    CHECK_MSG(load("tests/data/env/calm.yaml", wind, 4, s, &err) == FW_OK, "%s", err.msg);
    CHECK_NEAR(s->env.wind.speed / kn, 30.0, 1e-12);
    CHECK(s->env.wind.gust_intensity == 0.1 && s->env.wind.gust_time == 30.0);
    CHECK(fw_scenario_randomness(s) == NULL); /* gusts draw */
    /* bad values: located and named */
    struct {
        const char *key, *value, *want;
    } bad[] = {
        {"environment.wind.gust_intensity", "0.5", "environment.wind.gust_intensity: 0.5 is out"},
        {"environment.wind.gust_time_s", "0", "environment.wind.gust_time_s: 0 is out"},
        {"environment.wind.speed_kn", "-3", "environment.wind.speed_kn: -3 is out"},
        {"environment.wind.speed_kn", "120", "environment.wind.speed_kn: 120 is out"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fw_setting set[4];
        memcpy(set, wind, sizeof set);
        for (int k = 0; k < 4; k++)
            if (strcmp(set[k].key, bad[i].key) == 0)
                set[k].value = bad[i].value;
        CHECK(load("tests/data/env/calm.yaml", set, 4, s, &err) == FW_EINPUT);
        CHECK_MSG(strstr(err.msg, "calm.yaml:") && strstr(err.msg, bad[i].want), "%s", err.msg);
    }
    fw_setting nogt[] = {{"environment.wind.speed_kn", "30"},
                         {"environment.wind.from_deg", "270"},
                         {"environment.wind.gust_intensity", "0.1"}};
    CHECK(load("tests/data/env/calm.yaml", nogt, 3, s, &err) == FW_EINPUT);
    CHECK_MSG(strstr(err.msg, "gust_time_s"), "%s", err.msg);
    fw_setting neap[] = {{"environment.current.tidal.rate_kn", "1"},
                         {"environment.current.tidal.neap_rate_kn", "2"},
                         {"environment.current.tidal.flood_towards_deg", "0"}};
    CHECK(load("tests/data/env/calm.yaml", neap, 3, s, &err) == FW_EINPUT);
    CHECK_MSG(strstr(err.msg, "environment.current.tidal.neap_rate_kn: 2 kn is above"), "%s",
              err.msg);
    fw_setting nonet[] = {{"environment.current.tidal.network", "true"}};
    CHECK(load("tests/data/env/calm.yaml", nonet, 1, s, &err) == FW_EINPUT);
    CHECK_MSG(strstr(err.msg, "no traffic.network"), "%s", err.msg);
    free(s);
}

int main(void)
{
    c3 = test_load_ship("c3-mmg");
    TEST_RUN(test_gust_statistics);
    TEST_RUN(test_gusty_world);
    TEST_RUN(test_tidal_springs_neaps);
    TEST_RUN(test_scenario_environment);
    return TEST_EXIT();
}
