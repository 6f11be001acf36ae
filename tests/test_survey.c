/* test_survey - traffic-level encounters (src/survey): hand-built traffic with
 * known answers (head-on, overtaking, crossing, none, episodes, absences, the
 * own flag), bad input, the cell grid against all pairs, and the independence
 * of the input order.  No SUMO (see test_survey_run for the run). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "survey/survey.h"
#include "survey/survey_index.h"
#include "test.h"

/* ---- hand-built traffic: ships on straight lines ---- */

typedef struct line_ship {
    const char *id;
    double e, n;        /* m at t = 0 */
    double course_deg;
    double speed;       /* m/s */
    bool own;
    double t_on, t_off; /* present in [t_on, t_off]; t_off 0 = to the end */
} line_ship;

/* Steps t = 0, dt, ..., t_end with every ship present at t; finishes the survey. */
static fw_survey *run_lines(const fw_survey_def *def, const line_ship *ls, int n, double dt,
                            double t_end, fw_survey_totals *tot)
{
    fw_survey *sv = NULL;
    fw_error err = {0};
    if (fw_survey_create(def, &sv, &err)) {
        CHECK_MSG(0, "%s", err.msg);
        return NULL;
    }
    fw_target s[16];
    long steps = lround(t_end / dt);
    for (long k = 0; k <= steps; k++) {
        double t = k * dt;
        int m = 0;
        for (int i = 0; i < n; i++) {
            if (t < ls[i].t_on || (ls[i].t_off > 0 && t > ls[i].t_off))
                continue;
            double c = fw_deg_to_rad(ls[i].course_deg);
            s[m++] = fw_target_named(ls[i].id, (fw_target){
                                      .east = ls[i].e + ls[i].speed * sin(c) * t,
                                      .north = ls[i].n + ls[i].speed * cos(c) * t,
                                      .course = c, .heading = c, .speed = ls[i].speed, .length = 100 + i,
                                      .breadth = 20, .own = ls[i].own});
        }
        if (fw_survey_step(sv, t, s, m, &err)) {
            CHECK_MSG(0, "t = %g: %s", t, err.msg);
            break;
        }
    }
    fw_survey_finish(sv, tot);
    return sv;
}

static const fw_survey_record *only_record(fw_survey *sv)
{
    int n = -1;
    const fw_survey_record *r = sv ? fw_survey_records(sv, &n) : NULL;
    CHECK_MSG(n == 1, "%d records, expected 1", n);
    return n == 1 ? r : NULL;
}

static void test_head_on(void)
{
    /* reciprocal courses 500 m apart, 5 m/s each, abeam at t = 600 s */
    line_ship ls[2] = {{.id = "B", .e = 500, .n = 3000, .course_deg = 180, .speed = 5},
                       {.id = "A", .e = 0, .n = -3000, .course_deg = 0, .speed = 5}};
    fw_survey_def def = fw_default_survey_def();
    fw_survey_totals tot;
    fw_survey *sv = run_lines(&def, ls, 2, 1.0, 1500.0, &tot);
    const fw_survey_record *r = only_record(sv);
    /* first step with range sqrt(500^2 + (6000 - 10 t)^2) < 2000 m */
    double t1 = floor((6000.0 - sqrt(2000.0 * 2000.0 - 500.0 * 500.0)) / 10.0) + 1.0;
    if (r) {
        CHECK(strcmp(r->ship_a, "A") == 0 && strcmp(r->ship_b, "B") == 0);
        CHECK(r->type == FW_SURVEY_HEAD_ON);
        CHECK(!r->own);
        CHECK_NEAR(r->t_first, t1, 1e-12);
        CHECK_NEAR(r->range0, hypot(500.0, 6000.0 - 10.0 * t1), 1e-9);
        CHECK_NEAR(r->dcpa0, 500.0, 1e-9);
        CHECK_NEAR(r->tcpa0, 600.0 - t1, 1e-9);
        CHECK_NEAR(r->min_dist, 500.0, 1e-9);
        CHECK_NEAR(r->t_min, 600.0, 1e-12);
        CHECK_NEAR(r->length_a, 101.0, 0.0); /* A is ls[1] */
        CHECK_NEAR(r->length_b, 100.0, 0.0);
    }
    CHECK(tot.n == 1 && tot.by_type[FW_SURVEY_HEAD_ON] == 1 && tot.n_own == 0);
    CHECK(tot.steps == 1501);
    CHECK_NEAR(tot.ship_s, 2 * 1500.0, 1e-9);
    fw_survey_destroy(sv);
}

static void test_overtaking(void)
{
    /* B at 8 m/s comes up from 1500 m astern of A (4 m/s), 200 m to the side */
    line_ship ls[2] = {{.id = "A", .e = 0, .n = 0, .course_deg = 0, .speed = 4},
                       {.id = "B", .e = 200, .n = -1500, .course_deg = 0, .speed = 8}};
    fw_survey_def def = fw_default_survey_def();
    fw_survey_totals tot;
    fw_survey *sv = run_lines(&def, ls, 2, 1.0, 1200.0, &tot);
    const fw_survey_record *r = only_record(sv);
    if (r) {
        CHECK(r->type == FW_SURVEY_OVERTAKING);
        CHECK_NEAR(r->t_first, 0.0, 0.0);
        CHECK_NEAR(r->range0, hypot(200.0, 1500.0), 1e-9);
        CHECK_NEAR(r->dcpa0, 200.0, 1e-9);
        CHECK_NEAR(r->tcpa0, 375.0, 1e-9);
        CHECK_NEAR(r->min_dist, 200.0, 1e-9);
        CHECK_NEAR(r->t_min, 375.0, 1e-12);
    }
    CHECK(tot.by_type[FW_SURVEY_OVERTAKING] == 1);
    fw_survey_destroy(sv);
    /* slow closing: TCPA = range / 1 m/s falls below 1000 s at 1000 m, t = 900 s */
    line_ship slow[2] = {{.id = "A", .e = 0, .n = 0, .course_deg = 90, .speed = 3},
                         {.id = "B", .e = -1900, .n = 0, .course_deg = 90, .speed = 4}};
    sv = run_lines(&def, slow, 2, 1.0, 1000.0, &tot);
    r = only_record(sv);
    if (r) {
        CHECK(r->type == FW_SURVEY_OVERTAKING);
        CHECK_NEAR(r->t_first, 901.0, 0.0);
        CHECK_NEAR(r->tcpa0, 999.0, 1e-9);
        CHECK_NEAR(r->dcpa0, 0.0, 1e-9);
    }
    fw_survey_destroy(sv);
}

static void test_crossing(void)
{
    /* A northbound, B westbound at right angles; B's track 300 m north of the
     * point A would reach with it: relative track y = x + 300, DCPA 300 / sqrt 2
     * at t = 330 s; range sqrt((1500 - 5 t)^2 + (1800 - 5 t)^2) */
    line_ship ls[2] = {{.id = "A", .e = 0, .n = -1500, .course_deg = 0, .speed = 5},
                       {.id = "B", .e = 1500, .n = 300, .course_deg = 270, .speed = 5}};
    fw_survey_def def = fw_default_survey_def();
    fw_survey_totals tot;
    fw_survey *sv = run_lines(&def, ls, 2, 1.0, 1000.0, &tot);
    const fw_survey_record *r = only_record(sv);
    double t1 = -1;
    for (int k = 0; k < 1000 && t1 < 0; k++)
        if (hypot(1500.0 - 5.0 * k, 1800.0 - 5.0 * k) < 2000.0)
            t1 = k;
    if (r) {
        CHECK(r->type == FW_SURVEY_CROSSING);
        CHECK_NEAR(r->t_first, t1, 0.0);
        CHECK_NEAR(r->dcpa0, 300.0 / sqrt(2.0), 1e-9);
        CHECK_NEAR(r->tcpa0, 330.0 - t1, 1e-9);
        CHECK_NEAR(r->min_dist, 300.0 / sqrt(2.0), 1e-9);
        CHECK_NEAR(r->t_min, 330.0, 0.0);
    }
    CHECK(tot.by_type[FW_SURVEY_CROSSING] == 1);
    fw_survey_destroy(sv);
}

static void test_none(void)
{
    fw_survey_def def = fw_default_survey_def();
    fw_survey_totals tot;
    /* reciprocal 2100 m apart: never within range */
    line_ship far[2] = {{.id = "A", .e = 0, .n = -3000, .course_deg = 0, .speed = 5},
                        {.id = "B", .e = 2100, .n = 3000, .course_deg = 180, .speed = 5}};
    fw_survey_destroy(run_lines(&def, far, 2, 1.0, 1200.0, &tot));
    CHECK(tot.n == 0);
    /* 300 m apart and diverging: TCPA < 0 */
    line_ship away[2] = {{.id = "A", .e = 0, .n = 0, .course_deg = 0, .speed = 5},
                         {.id = "B", .e = 300, .n = -100, .course_deg = 180, .speed = 5}};
    fw_survey_destroy(run_lines(&def, away, 2, 1.0, 600.0, &tot));
    CHECK(tot.n == 0);
    /* within range, passing 1100 m off: DCPA too large */
    line_ship wide[2] = {{.id = "A", .e = 0, .n = -2000, .course_deg = 0, .speed = 5},
                         {.id = "B", .e = 1100, .n = 2000, .course_deg = 180, .speed = 5}};
    fw_survey_destroy(run_lines(&def, wide, 2, 1.0, 800.0, &tot));
    CHECK(tot.n == 0);
    /* the same with dcpa 1200 m: found, so the DCPA test was what held it back */
    fw_survey_def wide_def = def;
    wide_def.dcpa = 1200.0;
    fw_survey_destroy(run_lines(&wide_def, wide, 2, 1.0, 800.0, &tot));
    CHECK(tot.n == 1);
    /* parallel reciprocal routes the threshold apart to a nanometre, as
     * Dover's ferry routes, whose DCPA came out at 999.999999... m, which a
     * bare "< 1000" counted; a decimetre's margin does not (geom.h) */
    line_ship par[2] = {{.id = "A", .e = 0.0, .n = -2000, .course_deg = 0, .speed = 5},
                        {.id = "B", .e = 1000.0 - 1e-9, .n = 2000, .course_deg = 180, .speed = 5}};
    fw_survey_destroy(run_lines(&def, par, 2, 1.0, 800.0, &tot));
    CHECK(tot.n == 0);
    /* a real pass half a metre inside the threshold is one */
    par[1].e = 999.8;
    fw_survey_destroy(run_lines(&def, par, 2, 1.0, 800.0, &tot));
    CHECK(tot.n == 1);
    /* same course and speed 500 m apart: no relative motion */
    line_ship convoy[2] = {{.id = "A", .e = 0, .n = 0, .course_deg = 45, .speed = 6},
                           {.id = "B", .e = 0, .n = 500, .course_deg = 45, .speed = 6}};
    fw_survey_destroy(run_lines(&def, convoy, 2, 1.0, 600.0, &tot));
    CHECK(tot.n == 0);
}

/* B passes A (stationary) northbound 300 m off, sails to north_turn, turns
 * and passes again southbound.  Records for hysteresis h. */
static int shuttle(double north_turn, double h, fw_survey_record out[4])
{
    fw_survey_def def = fw_default_survey_def();
    def.hysteresis = h;
    fw_survey *sv = NULL;
    fw_error err = {0};
    CHECK(fw_survey_create(&def, &sv, &err) == FW_OK);
    double leg = north_turn + 3000.0; /* from -3000 m */
    double t_turn = leg / 10.0;
    for (int k = 0; k <= (int)(2 * t_turn) + 300; k++) {
        double t = k, n, c;
        if (t <= t_turn) {
            n = -3000.0 + 10.0 * t;
            c = 0.0;
        } else {
            n = north_turn - 10.0 * (t - t_turn);
            c = FW_PI;
        }
        fw_target s[2] = {{.id = "A", .course = 0.0, .heading = 0.0, .speed = 0.0},
                               {.id = "B", .east = 300.0, .north = n, .course = c, .heading = c, .speed = 10.0}};
        CHECK(fw_survey_step(sv, t, s, 2, &err) == FW_OK);
    }
    fw_survey_finish(sv, NULL);
    int n;
    const fw_survey_record *r = fw_survey_records(sv, &n);
    for (int i = 0; i < n && i < 4; i++)
        out[i] = r[i];
    fw_survey_destroy(sv);
    return n;
}

static void test_episodes(void)
{
    fw_survey_record r[4];
    /* beyond range + hysteresis between the passes: two records */
    int n = shuttle(3000.0, 500.0, r);
    CHECK_MSG(n == 2, "%d records", n);
    if (n == 2) {
        /* northbound from astern of A (speed 0): overtaking; then reciprocal */
        CHECK(r[0].type == FW_SURVEY_OVERTAKING);
        CHECK(r[1].type == FW_SURVEY_HEAD_ON);
        CHECK_NEAR(r[0].min_dist, 300.0, 1e-9);
        CHECK_NEAR(r[0].t_min, 300.0, 0.0);
        CHECK_NEAR(r[1].min_dist, 300.0, 1e-9);
        CHECK_NEAR(r[1].t_min, 900.0, 0.0);
        CHECK(r[1].t_first > 600.0);
    }
    /* turning at 2200 m: never beyond 2500 m, one episode */
    n = shuttle(2200.0, 500.0, r);
    CHECK_MSG(n == 1, "%d records", n);
    if (n == 1)
        CHECK_NEAR(r[0].t_min, 300.0, 0.0);
    /* without hysteresis the same track is two passes */
    n = shuttle(2200.0, 0.0, r);
    CHECK_MSG(n == 2, "%d records", n);
}

/* A ship that leaves the area keeps its episodes open: the same pass goes on
 * when it comes back close, a new one begins after it was seen far off. */
static void test_absent(void)
{
    fw_survey_def def = fw_default_survey_def();
    fw_survey_totals tot;
    /* head-on, B missing for t in (500, 560): abeam at 600 s, one record */
    line_ship gap[3] = {{.id = "A", .e = 0, .n = -3000, .course_deg = 0, .speed = 5},
                        {.id = "B", .e = 500, .n = 3000, .course_deg = 180, .speed = 5,
                         .t_off = 500},
                        {.id = "B", .e = 500, .n = 3000, .course_deg = 180, .speed = 5,
                         .t_on = 560}};
    fw_survey *sv = run_lines(&def, gap, 3, 1.0, 1500.0, &tot);
    const fw_survey_record *r = only_record(sv);
    if (r)
        CHECK_NEAR(r->min_dist, 500.0, 1e-9);
    /* exposure counts the ships there: each step's until the next, so B is
     * missing from 501 to 559 s, 59 steps */
    CHECK_NEAR(tot.ship_s, 2 * 1500.0 - 59.0, 1e-9);
    fw_survey_destroy(sv);
    /* away longer than max_gap: the pass ended, and B back 400 m off, still
     * closing, is a new one at t = 560 s */
    fw_survey_def short_gap = def;
    short_gap.max_gap = 30.0;
    sv = run_lines(&short_gap, gap, 3, 1.0, 1500.0, &tot);
    int n2;
    r = fw_survey_records(sv, &n2);
    CHECK_MSG(n2 == 2, "%d records", n2);
    if (n2 == 2) {
        CHECK_NEAR(r[0].min_dist, hypot(500.0, 6000.0 - 5000.0), 1e-9); /* last seen at 500 s */
        CHECK_NEAR(r[1].t_first, 560.0, 0.0);
        CHECK_NEAR(r[1].range0, hypot(500.0, 400.0), 1e-9);
        CHECK_NEAR(r[1].min_dist, 500.0, 1e-9);
    }
    fw_survey_destroy(sv);
    /* the own flag: C is the own ship; A-B meet too */
    line_ship own[3] = {{.id = "A", .e = 0, .n = -3000, .course_deg = 0, .speed = 5},
                        {.id = "B", .e = 500, .n = 3000, .course_deg = 180, .speed = 5},
                        {.id = "C", .e = 3000, .n = 0, .course_deg = 270, .speed = 5, .own = true}};
    sv = run_lines(&def, own, 3, 1.0, 1500.0, &tot);
    int n;
    r = fw_survey_records(sv, &n);
    int with_c = 0;
    for (int i = 0; i < n; i++) {
        bool c = strcmp(r[i].ship_b, "C") == 0;
        with_c += c;
        CHECK_MSG(r[i].own == c, "%s-%s own %d", r[i].ship_a, r[i].ship_b, r[i].own);
    }
    CHECK_MSG(n == 3 && with_c == 2 && tot.n_own == 2, "%d records, %d with C", n, with_c);
    fw_survey_destroy(sv);
}

static void test_bad_input(void)
{
    fw_survey_def def = fw_default_survey_def();
    fw_survey *sv = NULL;
    fw_error err = {0};
    def.range = 0.0;
    CHECK(fw_survey_create(&def, &sv, &err) == FW_EINPUT && !sv);
    def = fw_default_survey_def();
    def.tcpa = NAN;
    CHECK(fw_survey_create(&def, &sv, &err) == FW_EINPUT);
    def = fw_default_survey_def();
    def.hysteresis = -1.0;
    CHECK(fw_survey_create(&def, &sv, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "hysteresis");
    /* refused steps leave the survey as it was: the head-on case with bad
     * steps in between gives the head-on case's record */
    def = fw_default_survey_def();
    CHECK(fw_survey_create(&def, &sv, &err) == FW_OK);
    fw_target s[2] = {{.id = "A", .speed = 5.0}, {.id = "B", .course = FW_PI, .heading = FW_PI, .speed = 5.0}};
    for (int k = 0; k <= 1500; k++) {
        s[0].east = 0.0;
        s[0].north = -3000.0 + 5.0 * k;
        s[1].east = 500.0;
        s[1].north = 3000.0 - 5.0 * k;
        if (k == 400 || k == 600) {
            fw_target dup[2] = {s[0], s[0]};
            CHECK(fw_survey_step(sv, k, dup, 2, &err) == FW_ERUN);
            CHECK_CONTAINS(err.msg, "ship 'A' twice");
            fw_target nan = s[1];
            nan.north = NAN;
            fw_target bad[2] = {s[0], nan};
            CHECK(fw_survey_step(sv, k, bad, 2, &err) == FW_ERUN);
            fw_target noid[1] = {{.id = ""}};
            CHECK(fw_survey_step(sv, k, noid, 1, &err) == FW_ERUN);
        }
        CHECK(fw_survey_step(sv, k, s, 2, &err) == FW_OK);
        if (k == 700) /* time must advance */
            CHECK(fw_survey_step(sv, k, s, 2, &err) == FW_ERUN);
    }
    fw_survey_totals tot;
    fw_survey_finish(sv, &tot);
    const fw_survey_record *r = only_record(sv);
    if (r) {
        CHECK_NEAR(r->min_dist, 500.0, 1e-9);
        CHECK_NEAR(r->t_min, 600.0, 0.0);
        CHECK_NEAR(r->tcpa0, 600.0 - r->t_first, 1e-9);
    }
    CHECK(tot.steps == 1501);
    CHECK_NEAR(tot.ship_s, 3000.0, 1e-9);
    CHECK(fw_survey_step(sv, 2000.0, s, 2, &err) == FW_ERUN); /* finished */
    fw_survey_destroy(sv);
}

/* ---- random traffic: grid against all pairs, input order ---- */

static uint64_t rng_state;

static double urand(void)
{
    rng_state += 0x9e3779b97f4a7c15ULL;
    uint64_t z = rng_state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

typedef struct traffic {
    int n, next_id;
    char (*id)[16];
    double *e, *no, *h, *v;
    double half;       /* m, the square is [-half, half]^2 */
} traffic;

static void add_ship(traffic *tr)
{
    int i = tr->n++;
    snprintf(tr->id[i], sizeof tr->id[i], "s%d", tr->next_id++);
    tr->e[i] = (2 * urand() - 1) * tr->half;
    tr->no[i] = (2 * urand() - 1) * tr->half;
    /* traffic lanes: mostly along four headings, some anywhere */
    tr->h[i] = urand() < 0.8 ? floor(urand() * 4) * FW_PI / 2 + 0.1 * (urand() - 0.5)
                             : 2 * FW_PI * urand();
    tr->v[i] = 2.0 + 8.0 * urand();
}

static void traffic_init(traffic *tr, int n, double half)
{
    memset(tr, 0, sizeof *tr);
    size_t cap = (size_t)(2 * n);
    tr->id = malloc(16 * cap);
    tr->e = malloc(sizeof(double) * cap);
    tr->no = malloc(sizeof(double) * cap);
    tr->h = malloc(sizeof(double) * cap);
    tr->v = malloc(sizeof(double) * cap);
    tr->half = half;
    for (int i = 0; i < n; i++)
        add_ship(tr);
}

/* dt later: ships move, some turn, leavers (out of the square or 0.5 % a
 * step) go and as many newcomers come. */
static void traffic_advance(traffic *tr, double dt)
{
    int m = 0, n0 = tr->n;
    for (int i = 0; i < tr->n; i++) {
        if (urand() < 0.02)
            tr->h[i] += (urand() - 0.5) * FW_PI;
        tr->e[i] += tr->v[i] * sin(tr->h[i]) * dt;
        tr->no[i] += tr->v[i] * cos(tr->h[i]) * dt;
        if (fabs(tr->e[i]) > tr->half || fabs(tr->no[i]) > tr->half || urand() < 0.005)
            continue;
        memmove(tr->id[m], tr->id[i], 16);
        tr->e[m] = tr->e[i];
        tr->no[m] = tr->no[i];
        tr->h[m] = tr->h[i];
        tr->v[m] = tr->v[i];
        m++;
    }
    tr->n = m;
    while (tr->n < n0)
        add_ship(tr);
}

static void traffic_free(traffic *tr)
{
    free(tr->id);
    free(tr->e);
    free(tr->no);
    free(tr->h);
    free(tr->v);
}

static bool same_records(fw_survey *a, fw_survey *b)
{
    int na, nb;
    const fw_survey_record *ra = fw_survey_records(a, &na), *rb = fw_survey_records(b, &nb);
    if (na != nb) {
        fprintf(stderr, "%d records against %d\n", na, nb);
        return false;
    }
    for (int i = 0; i < na; i++) {
        const fw_survey_record *x = &ra[i], *y = &rb[i];
        if (strcmp(x->ship_a, y->ship_a) || strcmp(x->ship_b, y->ship_b) || x->type != y->type ||
            x->own != y->own || x->t_first != y->t_first || x->range0 != y->range0 ||
            x->dcpa0 != y->dcpa0 || x->tcpa0 != y->tcpa0 || x->min_dist != y->min_dist ||
            x->t_min != y->t_min || x->length_a != y->length_a || x->length_b != y->length_b) {
            fprintf(stderr, "record %d: %s-%s at %.1f against %s-%s at %.1f\n", i, x->ship_a,
                    x->ship_b, x->t_first, y->ship_a, y->ship_b, y->t_first);
            return false;
        }
    }
    return true;
}

/* n ships for steps steps of dt through surveys[0..k) with the given defs; the
 * ships of surveys[1] are fed in a shuffled order when shuffle is set. */
static void feed(fw_survey **sv, int k, int n, int steps, double dt, bool shuffle,
                 fw_survey_totals *tot, double *ship_s)
{
    traffic tr;
    rng_state = 12345;
    traffic_init(&tr, n, 0.5 * sqrt(n / 0.6e-6)); /* 0.6 ships per km^2 */
    fw_target *s = malloc(sizeof *s * (size_t)(2 * n));
    fw_target *p = malloc(sizeof *p * (size_t)(2 * n));
    uint64_t shuffle_rng = 99;
    fw_error err = {0};
    *ship_s = 0.0;
    for (int step = 0; step < steps; step++) {
        for (int i = 0; i < tr.n; i++)
            s[i] = fw_target_named(tr.id[i], (fw_target){ .east = tr.e[i], .north = tr.no[i],
                                    .course = tr.h[i], .heading = tr.h[i], .speed = tr.v[i], .length = 100,
                                    .breadth = 20, .own = i == 0});
        for (int j = 0; j < k; j++) {
            const fw_target *in = s;
            if (j == 1 && shuffle) {
                memcpy(p, s, sizeof *s * (size_t)tr.n);
                for (int i = tr.n - 1; i > 0; i--) {
                    shuffle_rng = shuffle_rng * 6364136223846793005ULL + 1442695040888963407ULL;
                    int q = (int)((shuffle_rng >> 33) % (uint64_t)(i + 1));
                    fw_target x = p[i];
                    p[i] = p[q];
                    p[q] = x;
                }
                in = p;
            }
            if (fw_survey_step(sv[j], step * dt, in, tr.n, &err))
                CHECK_MSG(0, "%s", err.msg);
        }
        if (step + 1 < steps)
            *ship_s += tr.n * dt;
        uint64_t keep = rng_state;
        traffic_advance(&tr, dt);
        rng_state = keep + 7; /* the traffic's own stream, the same for every caller */
    }
    for (int j = 0; j < k; j++)
        fw_survey_finish(sv[j], &tot[j]);
    free(s);
    free(p);
    traffic_free(&tr);
}

static void test_grid_matches_all_pairs(void)
{
    fw_survey_def grid = fw_default_survey_def(), brute = grid;
    brute.brute_force = true;
    fw_survey *sv[2] = {NULL, NULL};
    fw_error err = {0};
    CHECK(fw_survey_create(&grid, &sv[0], &err) == FW_OK);
    CHECK(fw_survey_create(&brute, &sv[1], &err) == FW_OK);
    fw_survey_totals tot[2];
    double ship_s;
    feed(sv, 2, 1000, 200, 10.0, false, tot, &ship_s);
    CHECK(same_records(sv[0], sv[1]));
    printf("1000 ships, 200 steps: %d encounters (%d head-on, %d overtaking, %d crossing), "
           "%d with ship 0\n", tot[0].n, tot[0].by_type[0], tot[0].by_type[1], tot[0].by_type[2],
           tot[0].n_own);
    /* a comparison worth making: many encounters of every type */
    CHECK(tot[0].n > 2000);
    for (int k = 0; k < FW_SURVEY_NTYPES; k++)
        CHECK(tot[0].by_type[k] > 100);
    CHECK(tot[0].n_own > 0);
    CHECK_NEAR(tot[0].ship_s, ship_s, 1e-6 * ship_s);
    CHECK_NEAR(tot[1].ship_s, tot[0].ship_s, 0.0);
    fw_survey_destroy(sv[0]);
    fw_survey_destroy(sv[1]);
}

static void test_input_order(void)
{
    fw_survey_def def = fw_default_survey_def();
    fw_survey *sv[2] = {NULL, NULL};
    fw_error err = {0};
    CHECK(fw_survey_create(&def, &sv[0], &err) == FW_OK);
    CHECK(fw_survey_create(&def, &sv[1], &err) == FW_OK);
    fw_survey_totals tot[2];
    double ship_s;
    feed(sv, 2, 300, 300, 10.0, true, tot, &ship_s);
    CHECK(tot[0].n > 200);
    CHECK(same_records(sv[0], sv[1]));
    /* sorted by (t_first, ship_a, ship_b), ship_a < ship_b */
    int n;
    const fw_survey_record *r = fw_survey_records(sv[0], &n);
    for (int i = 0; i < n; i++) {
        CHECK(strcmp(r[i].ship_a, r[i].ship_b) < 0);
        if (i > 0) {
            int c = r[i - 1].t_first < r[i].t_first ? -1 : r[i - 1].t_first > r[i].t_first ? 1 : 0;
            if (!c)
                c = strcmp(r[i - 1].ship_a, r[i].ship_a);
            if (!c)
                c = strcmp(r[i - 1].ship_b, r[i].ship_b);
            CHECK_MSG(c < 0, "records %d and %d out of order", i - 1, i);
        }
    }
    fw_survey_destroy(sv[0]);
    fw_survey_destroy(sv[1]);
}

/* The grid's pair list equals all pairs', including points on cell edges. */
typedef struct pair_list {
    int n, cap;
    int (*p)[2];
    double *d2;
} pair_list;

static void collect(void *ctx, int i, int j, double d2)
{
    pair_list *l = ctx;
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 1024;
        l->p = realloc(l->p, sizeof *l->p * (size_t)l->cap);
        l->d2 = realloc(l->d2, sizeof *l->d2 * (size_t)l->cap);
    }
    l->p[l->n][0] = i < j ? i : j;
    l->p[l->n][1] = i < j ? j : i;
    l->d2[l->n++] = d2;
}

static int cmp_pair(const void *a, const void *b)
{
    const int *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0]) : (x[1] > y[1]) - (x[1] < y[1]);
}

/* Grid and all pairs on x, y: the same pairs; returns how many. */
static int compare_pairs(const double *x, const double *y, int n, double r)
{
    sv_grid g = {0};
    pair_list a = {0}, b = {0};
    CHECK(sv_grid_pairs(&g, x, y, n, r, collect, &a) == 0);
    sv_brute_pairs(x, y, n, r, collect, &b);
    CHECK_MSG(a.n == b.n, "grid %d pairs, all pairs %d", a.n, b.n);
    if (a.n > 1) /* no pairs: nothing allocated, and qsort wants an array */
        qsort(a.p, (size_t)a.n, sizeof *a.p, cmp_pair);
    if (b.n > 1)
        qsort(b.p, (size_t)b.n, sizeof *b.p, cmp_pair);
    bool same = a.n == b.n;
    for (int i = 0; same && i < a.n; i++)
        same = a.p[i][0] == b.p[i][0] && a.p[i][1] == b.p[i][1];
    CHECK(same);
    sv_grid_free(&g);
    free(a.p);
    free(a.d2);
    free(b.p);
    free(b.d2);
    return b.n;
}

static void test_grid_pairs(void)
{
    enum { N = 3000 };
    static double x[N + 1], y[N + 1];
    const double r = 2500.0;
    rng_state = 777;
    for (int i = 0; i < N; i++) {
        if (i % 3 == 0) { /* on cell edges and at exactly r from each other */
            x[i] = r * (double)((int)(urand() * 20) - 10);
            y[i] = r * (double)((int)(urand() * 20) - 10);
        } else {
            x[i] = (urand() - 0.5) * 40000.0;
            y[i] = (urand() - 0.5) * 40000.0;
        }
    }
    /* a compact area (cells numbered densely) */
    int n = compare_pairs(x, y, N, r);
    CHECK_MSG(n > 1000, "only %d pairs", n);
    /* one ship far off: the hashed cells, same pairs */
    x[N] = 3.0e8;
    y[N] = -2.0e8;
    CHECK(compare_pairs(x, y, N + 1, r) == n);
    /* a few points, a large r, and nothing at all */
    CHECK(compare_pairs(x, y, 7, 1e6) == 21);
    CHECK(compare_pairs(x, y, 1, r) == 0);
}

/* Ids looked up by their keys (core/idmap.h) get the indices their names
 * have, whether the name or the key came first; key 0 or a key not seen yet
 * looks the name up; large keys grow the table. */
static void test_idmap_keys(void)
{
    enum { N = 2000 };
    fw_idmap byname = {0}, keyed = {0};
    char id[32];
    rng_state = 99;
    for (int k = 0; k < 3 * N; k++) {
        int s = (int)(urand() * N); /* ships seen again and again, in any order */
        snprintf(id, sizeof id, "east.%d", s);
        int a, b, key = s % 5 == 0 ? 0 : 3 * s + 1; /* some ships without a key */
        CHECK(fw_idmap_intern(&byname, id, &a) == 0);
        CHECK(fw_idmap_intern_keyed(&keyed, key, id, &b) == 0);
        CHECK_MSG(a == b, "%s (key %d): index %d by name, %d by key", id, key, a, b);
        CHECK(fw_idmap_find_keyed(&keyed, key, id) == b);
        CHECK(fw_idmap_find(&keyed, id) == b);
    }
    CHECK(keyed.n == byname.n);
    CHECK(keyed.n > N / 2);
    CHECK(fw_idmap_find_keyed(&keyed, 0, "west.1") == -1);
    CHECK(fw_idmap_find_keyed(&keyed, 7 * N, "west.1") == -1);
    /* an id interned by name first, its key given later: the same index */
    int a, b;
    CHECK(fw_idmap_intern(&keyed, "west.1", &a) == 0);
    CHECK(fw_idmap_intern_keyed(&keyed, 9 * N, "west.1", &b) == 0);
    CHECK(a == b && keyed.key_cap >= 9 * N);
    CHECK(fw_idmap_find_keyed(&keyed, 9 * N, "west.1") == a);
    fw_idmap_free(&byname);
    fw_idmap_free(&keyed);
    CHECK(keyed.n == 0 && keyed.key_cap == 0 && !keyed.by_key);
    /* every id with a key: a key not seen is an id not seen, found without
     * the name; one id without a key, and names are looked up again */
    fw_idmap only = {0};
    CHECK(fw_idmap_intern_keyed(&only, 3, "east.3", &a) == 0 && only.keyless == 0);
    CHECK(fw_idmap_find_keyed(&only, 4, "east.4") == -1);
    CHECK(fw_idmap_intern(&only, "west.9", &b) == 0 && only.keyless == 1);
    CHECK(fw_idmap_find_keyed(&only, 9, "west.9") == b);
    CHECK(fw_idmap_find_keyed(&only, 3, "east.3") == a);
    fw_idmap_free(&only);
}

int main(void)
{
    TEST_RUN(test_head_on);
    TEST_RUN(test_overtaking);
    TEST_RUN(test_crossing);
    TEST_RUN(test_none);
    TEST_RUN(test_episodes);
    TEST_RUN(test_absent);
    TEST_RUN(test_bad_input);
    TEST_RUN(test_grid_pairs);
    TEST_RUN(test_grid_matches_all_pairs);
    TEST_RUN(test_input_order);
    TEST_RUN(test_idmap_keys);
    return TEST_EXIT();
}
