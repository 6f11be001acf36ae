/* test_env_predict.c - the avoidance's predictions in a current (issue 24
 * item 3): what the own ship predicts against what the MMG ship then does.
 *
 *   the Nomoto track prediction from an MMG ship's state in a uniform
 *     current, against the MMG ship's ground track under the same helm: its
 *     error is the calm-water error (the prediction's own model error) to
 *     0.5 m, and within the identification's bounds over the knowledge
 *     base's speeds (tests/test_identify.c: 80 m after 3 minutes, 140 m
 *     after 5); the same prediction without the current would be off by
 *     current x time (over 300 m after 5 minutes)
 *   a crossing in a current: the DCPA and TCPA the assessment gives from
 *     both ships' states equal the closest approach the two MMG ships then
 *     make, to 5 m and 2 s (the ships are steered straight by a heading
 *     autopilot; their speed settles within the first 10 s)
 */
#include <math.h>
#include <stdlib.h>

#include "avoid/encounter.h"
#include "core/units.h"
#include "env/env.h"
#include "nomoto/track.h"
#include "test.h"
#include "test_ship.h"
#include "world/controllers.h"
#include "world/world.h"

static fw_ship mmg;

/* A helm by the clock: amidships (a heading autopilot on the first heading)
 * until t_helm, then `helm` held. */
typedef struct fixed_helm {
    fw_controller base;
    double t_helm, helm, psi0;
    bool have_psi0;
} fixed_helm;

static fw_status fixed_decide(fw_controller *c, const fw_sense *in, fw_decision *d,
                              fw_error *err)
{
    (void)err;
    fixed_helm *h = (fixed_helm *)c;
    if (!h->have_psi0)
        h->psi0 = in->own->psi, h->have_psi0 = true;
    /* kp 1, kd 20 s: the policy's autopilot (policy.h) */
    double helm = in->t >= h->t_helm ? h->helm
                                     : -(in->own->psi - h->psi0) - 20.0 * in->own->r;
    if (in->t < h->t_helm && in->own->delta_wind != 0.0)
        helm += in->own->delta_wind; /* as the policy's: holding against the wind */
    *d = (fw_decision){.mode = FW_MODE_AVOID, .helm = helm, .primary = -1};
    return FW_OK;
}

static void fixed_destroy(fw_controller *c) { free(c); }

static const fw_controller_ops fixed_ops = {.name = "fixed", .decide = fixed_decide,
                                            .destroy = fixed_destroy};

static fw_controller *fixed(double t_helm, double helm)
{
    fixed_helm *h = calloc(1, sizeof *h);
    h->base.ops = &fixed_ops;
    h->t_helm = t_helm, h->helm = helm;
    return &h->base;
}

static fw_vessel *add(fw_world *w, const char *id, double e, double n, double course_deg,
                      double kn, double t_helm, double helm, fw_vessel_role role)
{
    fw_error err = {0};
    fw_vessel_def vd = fw_default_vessel_def();
    vd.id = id, vd.role = role, vd.ship = &mmg;
    vd.east = e, vd.north = n, vd.course = fw_deg_to_rad(course_deg);
    vd.speed = fw_kn_to_ms(kn);
    vd.controller = fixed(t_helm, helm);
    fw_vessel_handle h;
    CHECK_MSG(fw_world_add_vessel(w, &vd, &h, &err) == FW_OK, "%s", err.msg);
    return fw_world_vessel(w, h);
}

/* The prediction's worst error against the MMG ship at 180 and 300 s, the
 * helm ordered at t = 60 s; cur: m/s east, north (0, 0: calm); with
 * `ignore` the prediction is made without the current. */
static void predict_vs_mmg(double helm_deg, double ce, double cn, bool ignore, double *e180,
                           double *e300)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    if (ce != 0.0 || cn != 0.0)
        wd.env.current = fw_current_uniform(hypot(ce, cn), atan2(ce, cn));
    fw_world *w = NULL;
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    double helm = fw_deg_to_rad(helm_deg);
    fw_vessel *v = add(w, "own", 0.0, 0.0, 40.0, 12.0, 60.0, helm, FW_ROLE_OWN);
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    for (int k = 1; k <= 60; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    fw_own_state s = *fw_vessel_own_state(v);
    if (ignore)
        s.cur_e = s.cur_n = 0.0;
    fw_track_def td = fw_default_track_def();
    td.max_turn = 0.0; /* the helm is held: no steadying */
    fw_track tr;
    CHECK(fw_track_alloc(&tr, fw_track_samples(&td), &err) == FW_OK);
    CHECK(fw_track_predict(&mmg, &td, &s, helm, &tr, &err) == FW_OK);
    *e180 = *e300 = 0.0;
    for (int k = 1; k <= 300; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        if (k % 5)
            continue;
        const fw_mmg_state *x = fw_vessel_motion(v);
        int j = k / 5;
        double off = hypot(x->east - tr.east[j], x->north - tr.north[j]);
        if (k <= 180)
            *e180 = fmax(*e180, off);
        *e300 = fmax(*e300, off);
    }
    fw_track_free(&tr);
    fw_world_destroy(w);
}

static void test_prediction_is_ground_track(void)
{
    const double ce = 1.2, cn = -0.9; /* 1.5 m/s (2.9 kn) setting 127 deg */
    for (int h = 10; h <= 30; h += 10) {
        for (int side = -1; side <= 1; side += 2) {
            double c180, c300, e180, e300, i180, i300;
            predict_vs_mmg(side * h, 0.0, 0.0, false, &c180, &c300);
            predict_vs_mmg(side * h, ce, cn, false, &e180, &e300);
            predict_vs_mmg(side * h, ce, cn, true, &i180, &i300);
            printf("  helm %+3d deg: prediction off the MMG ground track by %.1f m at 3 min, "
                   "%.1f m at 5 min in 1.5 m/s (calm water %.1f, %.1f m; current ignored "
                   "%.0f m at 5 min)\n",
                   side * h, e180, e300, c180, c300, i300);
            CHECK_NEAR(e180, c180, 0.5);
            CHECK_NEAR(e300, c300, 0.5);
            CHECK(e180 < 80.0 && e300 < 140.0);
            CHECK(i300 > 300.0);
        }
    }
}

/* Two MMG ships crossing at right angles in a current across both. */
static void test_crossing_cpa_in_current(void)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env.current = fw_current_uniform(1.5, fw_deg_to_rad(120.0));
    fw_world *w = NULL;
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    /* the own ship heads north at 12 kn, the target west at 10 kn from
     * 5 km east; no helm but the heading autopilot */
    fw_vessel *o = add(w, "own", 0.0, 0.0, 0.0, 12.0, INFINITY, 0.0, FW_ROLE_OWN);
    fw_vessel *t = add(w, "B", 5000.0, 5600.0, 270.0, 10.0, INFINITY, 0.0, FW_ROLE_OTHER);
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    for (int k = 1; k <= 10; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    fw_colregs_def cd = fw_default_colregs_def();
    fw_domain_def dom = fw_default_domain_def();
    fw_assessment as, calm;
    fw_assess(&cd, &dom, 1800.0, fw_vessel_own_state(o), fw_vessel_record(t), 1, &as, NULL);
    fw_own_state ign = *fw_vessel_own_state(o);
    ign.cur_e = ign.cur_n = 0.0;
    fw_assess(&cd, &dom, 1800.0, &ign, fw_vessel_record(t), 1, &calm, NULL);
    double dmin = INFINITY, tmin = 0.0;
    for (int k = 11; k <= 1200; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        const fw_target *a = fw_vessel_record(o), *b = fw_vessel_record(t);
        double d = hypot(a->east - b->east, a->north - b->north);
        if (d < dmin)
            dmin = d, tmin = k - 10.0;
    }
    printf("  crossing in 1.5 m/s setting 120: predicted DCPA %.1f m at TCPA %.1f s, "
           "sailed %.1f m at %.0f s (the current ignored: %.0f m at %.0f s)\n",
           as.dcpa, as.tcpa, dmin, tmin, calm.dcpa, calm.tcpa);
    CHECK_NEAR(as.dcpa, dmin, 5.0);
    CHECK_NEAR(as.tcpa, tmin, 2.0);
    CHECK(fabs(calm.dcpa - dmin) > 200.0);
    fw_world_destroy(w);
}

/* The own ship holding its heading (the policy's autopilot) in a steady
 * beam wind, settled for 10 minutes: the prediction the policy makes of it
 * holding on (fw_track_predict_steer, as policy.c's steer) against what it
 * then sails, over the next 10 minutes; with the steady drift in its state
 * (world/vessel.h "Wind drift") and without (current 0, the drift angle the
 * ship's own): the largest error, m. */
static void drift_vs_mmg(double wind_kn, double from_deg, bool ignore, double *e300,
                         double *e600)
{
    fw_error err = {0};
    fw_world_def wd = fw_default_world_def();
    wd.env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(wind_kn),
                            .from = fw_deg_to_rad(from_deg)};
    fw_world *w = NULL;
    CHECK_MSG(fw_world_create(&wd, &w, &err) == FW_OK, "%s", err.msg);
    fw_vessel *v = add(w, "own", 0.0, 0.0, 0.0, 12.0, INFINITY, 0.0, FW_ROLE_OWN);
    CHECK_MSG(fw_world_start(w, &err) == FW_OK, "%s", err.msg);
    for (int k = 1; k <= 600; k++)
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
    fw_own_state s = *fw_vessel_own_state(v);
    if (ignore) {
        const fw_mmg_state *x = fw_vessel_motion(v);
        s.cur_e = s.cur_n = 0.0, s.beta = atan2(-x->vm, x->u);
        s.U0 = fw_kn_to_ms(12.0), s.delta_wind = 0.0;
    }
    fw_track_def td = fw_default_track_def();
    fw_steer_def ap = {.psi_ref = 0.0, .kp = 1.0, .kd = 20.0, .max_helm = fw_deg_to_rad(35.0)};
    fw_track tr;
    CHECK(fw_track_alloc(&tr, fw_track_samples(&td), &err) == FW_OK);
    CHECK(fw_track_predict_steer(&mmg, &td, &s, &ap, &tr, &err) == FW_OK);
    *e300 = *e600 = 0.0;
    for (int k = 1; k <= 600; k++) {
        CHECK(fw_world_step(w, 1.0, &err) == FW_OK);
        if (k % 5)
            continue;
        const fw_mmg_state *x = fw_vessel_motion(v);
        double off = hypot(x->east - tr.east[k / 5], x->north - tr.north[k / 5]);
        if (k <= 300)
            *e300 = fmax(*e300, off);
        *e600 = fmax(*e600, off);
    }
    fw_track_free(&tr);
    fw_world_destroy(w);
}

static void test_wind_drift_prediction(void)
{
    const double cases[][2] = {{30.0, 90.0}, {30.0, 270.0}, {20.0, 90.0}, {30.0, 45.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double e300, e600, i300, i600;
        drift_vs_mmg(cases[i][0], cases[i][1], false, &e300, &e600);
        drift_vs_mmg(cases[i][0], cases[i][1], true, &i300, &i600);
        printf("  c3-mmg at 12 kn heading 000, wind %2.0f kn from %03.0f: the prediction off "
               "the MMG ship by %.1f m at 5 min, %.1f m at 10 min (without the wind drift "
               "%.1f m, %.1f m)\n",
               cases[i][0], cases[i][1], e300, e600, i300, i600);
        CHECK(e300 < 10.0 && e600 < 10.0);
        CHECK(i600 > 3.0 * e600 && i600 > 50.0);
    }
}

int main(void)
{
    mmg = test_load_ship("c3-mmg");
    TEST_RUN(test_prediction_is_ground_track);
    TEST_RUN(test_crossing_cpa_in_current);
    TEST_RUN(test_wind_drift_prediction);
    return TEST_EXIT();
}
