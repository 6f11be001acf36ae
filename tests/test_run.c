/* test_run.c - scenario runs end to end: the paper's five cases and the 22
 * Imazu cases through SUMO (libsumo), determinism, and bad scenario files.
 *
 * Floors asserted for every case: the run completes, no hull overlap, every
 * first action COLREGs-correct (starboard for head-on and give-way crossing,
 * never to port against a crossing target on the port side), and the own ship
 * back on its course (within 2 deg) at the end.  The 300 m domain is asserted
 * wherever 35 deg of helm can keep it: the oracle (run/oracle.h) tries hard
 * over to either side from t = 0, held for alterations of 15-180 deg; where
 * even its best manoeuvre enters the domain the case is named with that
 * figure, and the run must come within 0.05 of the oracle's domain radius.
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "avoid/helm_search.h"
#include "core/units.h"
#include "run/oracle.h"
#include "run/run.h"
#include "test.h"
#include "test_tmp.h"

static char tmp_root[256];

/* Output digests: every scenario run's files are hashed and compared with
 * tests/data/digests/runs.txt, so a redesign that should not change results
 * is checked to the byte.  The scenario's path (which names the checkout) is
 * cut out of run.log first.  FAIRWAY_WRITE_DIGESTS=FILE writes the list
 * found instead, for a change of results that is intended (and explained in
 * its commit). */
static const char *const digest_files[] = {"own.csv", "targets.csv", "encounters.csv",
                                           "summary.json", "run.log"};
static FILE *digest_out;

/* FNV-1a, 64 bits, of a file with every occurrence of `cut` left out. */
static unsigned long long file_digest(const char *path, const char *cut)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    unsigned long long h = 14695981039346656037ull;
    size_t m = strlen(cut), k = 0;
    int c;
    /* a plain prefix matcher: the data root has no repeated prefix that matters */
    while ((c = fgetc(f)) != EOF) {
        if (m && (char)c == cut[k]) {
            if (++k == m)
                k = 0;
            continue;
        }
        for (size_t j = 0; j < k; j++)
            h = (h ^ (unsigned char)cut[j]) * 1099511628211ull;
        k = 0;
        if (m && (char)c == cut[0]) {
            k = 1;
            continue;
        }
        h = (h ^ (unsigned char)c) * 1099511628211ull;
    }
    for (size_t j = 0; j < k; j++)
        h = (h ^ (unsigned char)cut[j]) * 1099511628211ull;
    fclose(f);
    return h;
}

static void check_digests(const char *scenario, const char *dir)
{
    char want_path[512], line[256];
    snprintf(want_path, sizeof want_path, "%s/tests/data/digests/runs.txt", fw_data_root());
    for (size_t i = 0; i < sizeof digest_files / sizeof digest_files[0]; i++) {
        char path[700], key[200];
        snprintf(path, sizeof path, "%s/%s", dir, digest_files[i]);
        snprintf(key, sizeof key, "%s/%s", scenario, digest_files[i]);
        unsigned long long h = file_digest(path, fw_data_root());
        if (digest_out) {
            fprintf(digest_out, "%s %016llx\n", key, h);
            continue;
        }
        FILE *w = fopen(want_path, "r");
        CHECK_MSG(w != NULL, "cannot read %s", want_path);
        if (!w)
            return;
        unsigned long long want = 0;
        bool found = false;
        while (fgets(line, sizeof line, w)) {
            char k2[200];
            unsigned long long v;
            if (sscanf(line, "%199s %llx", k2, &v) == 2 && strcmp(k2, key) == 0) {
                want = v;
                found = true;
            }
        }
        fclose(w);
        CHECK_MSG(found && want == h, "%s: digest %016llx, expected %016llx%s", key, h, want,
                  found ? "" : " (not listed)");
    }
}

static fw_scenario s; /* large: a ship inside; the last scenario run */

static fw_status run_one(const char *file, const char *dir, fw_run_summary *sum,
                         fw_encounter **enc, int *ne)
{
    fw_error err = {0};
    fw_status st = fw_scenario_load(file, &s, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    if (st)
        return st;
    mkdir(dir, 0777);
    fw_run_def def = fw_default_run_def();
    def.scenario = &s;
    def.dir = dir;
    st = fw_run_scenario(&def, sum, enc, ne, &err);
    CHECK_MSG(st == FW_OK, "%s: %s", file, err.msg);
    return st;
}

/* Runs file (in a directory of its own) and checks it; its summary into
 * *out when out is not NULL (acted false when it did not run). */
static void check_case(const char *file, fw_run_summary *out)
{
    static int runs;
    char dir[512];
    snprintf(dir, sizeof dir, "%s/%d-%s", tmp_root, runs++, strrchr(file, '/') + 1);
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int ne = 0;
    if (out)
        memset(out, 0, sizeof *out);
    if (run_one(file, dir, &sum, &e, &ne))
        return;
    if (out)
        *out = sum;
    check_digests(sum.scenario, dir);
    CHECK_MSG(!sum.collision, "%s: collision", sum.scenario);
    CHECK_MSG(sum.colregs_ok, "%s: a first action is not COLREGs-correct", sum.scenario);
    CHECK_MSG(fabs(sum.heading_error) < fw_deg_to_rad(2.0), "%s: ends %.1f deg off course",
              sum.scenario, fw_rad_to_deg(sum.heading_error));
    CHECK_MSG(sum.acted, "%s: never acted", sum.scenario);
    double lam = INFINITY;
    for (int i = 0; i < ne; i++)
        lam = fmin(lam, e[i].min_lambda);
    /* the oracle only where the domain was entered: was it avoidable? */
    fw_oracle_def od = fw_default_oracle_def();
    fw_oracle_result best = {.best_lambda = INFINITY};
    fw_error err = {0};
    if (sum.domain_entered)
        CHECK_MSG(fw_oracle_best(&s, &od, &best, &err) == FW_OK, "%s", err.msg);
    char why[160] = "";
    if (best.best_lambda < 1.0) {
        snprintf(why, sizeof why, "35 deg from t = 0 reaches %.2f of the domain (%.0f m) at best",
                 best.best_lambda, best.best_dist);
        CHECK_MSG(lam >= best.best_lambda - 0.05, "%s: domain radius %.2f, the oracle %.2f",
                  sum.scenario, lam, best.best_lambda);
    } else {
        CHECK_MSG(!sum.domain_entered, "%s: domain entered (closest %.0f m, radius %.2f)",
                  sum.scenario, sum.min_dist, lam);
    }
    printf("  %-26s min %5.0f m  radius %.2f  domain %-3s  act %5.0f s %s %2.0f deg  max %2.0f deg  "
           "return %5.0f s  +%4.0f m  lost %4.0f s%s%s\n",
           sum.scenario, sum.min_dist, lam, sum.domain_entered ? "in" : "out", sum.t_act,
           sum.act_side == FW_SIDE_STARBOARD ? "stbd" : "port", fw_rad_to_deg(fabs(sum.act_helm)),
           fw_rad_to_deg(sum.max_helm), sum.t_return, sum.path_lengthening, sum.time_lost,
           why[0] ? "  cannot: " : "", why);
    free(e);
}

static void test_paper_cases(void)
{
    static const char *const files[] = {"1-head-on", "2-overtaking", "3-crossing",
                                        "4-head-on-complex", "5-crossing-complex"};
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char p[512];
        snprintf(p, sizeof p, "%s/scenarios/paper/%s.yaml", fw_data_root(), files[i]);
        check_case(p, NULL);
    }
}

/* The five cases as the paper simulated them (scenarios/paper/fast-time:
 * the own ship stepped along equation 9's track with the paper's equations
 * 10-13, acting at the paper's 1 nm point).  The floors: cases 1 and 4
 * act within 10 s and 5 deg of the paper's first action (15 s / 20 deg, 124 s
 * / 29 deg); in all five no collision, the domain kept, at least 285 m
 * between centres.  The settings come from the text (generate.py says which
 * words), none from these results. */
static void test_paper_fast_time(void)
{
    static const struct { const char *file; double t_act, helm_deg; } cases[] = {
        {"1-head-on", 15, 20}, {"2-overtaking", -1, 0}, {"3-crossing", -1, 0},
        {"4-head-on-complex", 124, 29}, {"5-crossing-complex", -1, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char p[512];
        snprintf(p, sizeof p, "%s/scenarios/paper/fast-time/%s.yaml", fw_data_root(),
                 cases[i].file);
        fw_run_summary sum;
        check_case(p, &sum);
        CHECK_MSG(!sum.collision && !sum.domain_entered && sum.min_dist >= 285.0,
                  "%s: collision %d, domain entered %d, min %.0f m", sum.scenario, sum.collision,
                  sum.domain_entered, sum.min_dist);
        if (cases[i].t_act < 0)
            continue;
        CHECK_MSG(sum.acted && fabs(sum.t_act - cases[i].t_act) <= 10.0 &&
                      fabs(fw_rad_to_deg(fabs(sum.act_helm)) - cases[i].helm_deg) <= 5.0 &&
                      sum.act_side == FW_SIDE_STARBOARD,
                  "%s: acts %.0f s %.0f deg, the paper %.0f s %.0f deg", sum.scenario, sum.t_act,
                  fw_rad_to_deg(fabs(sum.act_helm)), cases[i].t_act, cases[i].helm_deg);
    }
}

static void test_imazu_cases(void)
{
    for (int i = 1; i <= 22; i++) {
        char p[512];
        snprintf(p, sizeof p, "%s/scenarios/imazu/imazu-%02d.yaml", fw_data_root(), i);
        check_case(p, NULL);
    }
}

/* The oracle itself: the paper's case 1 (head-on 2000 m ahead, closing at
 * 20 kn) cannot keep 300 m with 35 deg from t = 0, even read as the paper's
 * transverse clearance (the scenario's reading: 316 m from the target's
 * centre abeam of it; its best radius there is 0.72, 0.60 of the ellipse
 * the scenario used to state), and its best is nearly a
 * mirror pair: a target offset to port asks for about the same as one offset
 * to starboard (not exactly: the single-screw C-3 has different flow-
 * straightening coefficients for port and starboard rudder, gamma_R+-, and
 * turns a little tighter to port: 0.93 against 0.91). */
static void test_oracle(void)
{
    char p[512];
    snprintf(p, sizeof p, "%s/scenarios/paper/1-head-on.yaml", fw_data_root());
    fw_error err = {0};
    CHECK_MSG(fw_scenario_load(p, &s, &err) == FW_OK, "%s", err.msg);
    fw_oracle_def od = fw_default_oracle_def();
    od.after = 600.0;
    fw_oracle_result r, a, b;
    CHECK_MSG(fw_oracle_best(&s, &od, &r, &err) == FW_OK, "%s", err.msg);
    CHECK_MSG(r.best_lambda > 0.6 && r.best_lambda < 0.85, "paper-1 best radius %.2f", r.best_lambda);
    CHECK_MSG(r.best_dist > 170.0 && r.best_dist < 260.0, "paper-1 best distance %.0f m", r.best_dist);
    CHECK(r.side != 0 && r.manoeuvres == 25);
    s.targets[0].east = 150.0;
    CHECK(fw_oracle_best(&s, &od, &a, &err) == FW_OK);
    s.targets[0].east = -150.0;
    CHECK(fw_oracle_best(&s, &od, &b, &err) == FW_OK);
    CHECK_NEAR(a.best_lambda, b.best_lambda, 0.05);
    CHECK(a.side == -b.side && a.side != 0);
    CHECK(a.best_lambda > r.best_lambda); /* a head start is worth something */
    /* waiting costs: the same from t = 60 s is worse */
    od.t_act = 60.0;
    s.targets[0].east = 0.0;
    fw_oracle_result late;
    CHECK(fw_oracle_best(&s, &od, &late, &err) == FW_OK);
    CHECK(late.best_lambda < r.best_lambda);
    printf("  paper-1: best %.2f (%.0f m, %s %.0f deg); target 150 m off: %.2f / %.2f; "
           "from 60 s: %.2f\n",
           r.best_lambda, r.best_dist, r.side > 0 ? "starboard" : "port",
           fw_rad_to_deg(r.alteration), a.best_lambda, b.best_lambda, late.best_lambda);
}

static bool same_file(const char *a, const char *b)
{
    FILE *f = fopen(a, "rb"), *g = fopen(b, "rb");
    bool same = f && g;
    while (same) {
        int x = fgetc(f), y = fgetc(g);
        if (x != y)
            same = false;
        if (x == EOF || y == EOF)
            break;
    }
    if (f)
        fclose(f);
    if (g)
        fclose(g);
    return same;
}

static void test_determinism(void)
{
    char file[512], d1[512], d2[512];
    snprintf(file, sizeof file, "%s/scenarios/imazu/imazu-15.yaml", fw_data_root());
    snprintf(d1, sizeof d1, "%s/det1", tmp_root);
    snprintf(d2, sizeof d2, "%s/det2", tmp_root);
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int ne;
    if (run_one(file, d1, &sum, &e, &ne))
        return;
    free(e);
    if (run_one(file, d2, &sum, &e, &ne))
        return;
    free(e);
    static const char *const names[] = {"own.csv", "targets.csv", "encounters.csv", "summary.json",
                                        "run.log", "sumo/run.net.xml", "sumo/targets.rou.xml"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        char a[700], b[700];
        snprintf(a, sizeof a, "%s/%s", d1, names[i]);
        snprintf(b, sizeof b, "%s/%s", d2, names[i]);
        CHECK_MSG(same_file(a, b), "%s differs between two runs", names[i]);
    }
}

/* A good scenario with one line replaced; the error must name file:line: field. */
static const char *good =
    "name: bad\n"                                                       /* 1 */
    "own_ship:\n"                                                       /* 2 */
    "  ship: c3\n"                                                      /* 3 */
    "  east_m: 0\n"                                                     /* 4 */
    "  north_m: 0\n"                                                    /* 5 */
    "  course_deg: 0\n"                                                 /* 6 */
    "  speed_kn: 10\n"                                                  /* 7 */
    "  leg_nm: 5\n"                                                     /* 8 */
    "traffic:\n"                                                        /* 9 */
    "  targets:\n"                                                      /* 10 */
    "    - {id: T1, east_m: 0, north_m: 2000, course_deg: 180, speed_kn: 10, length_m: 200, "
    "breadth_m: 32}\n"                                                  /* 11 */
    "run:\n"                                                            /* 12 */
    "  duration_s: 100\n";                                              /* 13 */

static void bad_case(int line, const char *replacement, const char *expect)
{
    char text[2048] = "", path[512];
    const char *p = good;
    for (int k = 1; *p; k++) {
        const char *nl = strchr(p, '\n');
        size_t n = (size_t)(nl - p) + 1;
        if (k == line)
            strcat(text, replacement);
        else
            strncat(text, p, n);
        p += n;
    }
    snprintf(path, sizeof path, "%s/bad.yaml", tmp_root);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    static fw_scenario s;
    fw_error err = {0};
    fw_status st = fw_scenario_load(path, &s, &err);
    if (!expect) {
        CHECK_MSG(st == FW_OK, "the good file fails: %s", err.msg);
        return;
    }
    CHECK_MSG(st == FW_EINPUT, "line %d '%s': status %d", line, replacement, st);
    CHECK_MSG(strstr(err.msg, expect) != NULL, "'%s' does not contain '%s'", err.msg, expect);
}

static void test_bad_files(void)
{
    bad_case(0, "", NULL); /* the good file itself loads */
    bad_case(3, "  shp: c3\n", "bad.yaml:3: own_ship");                  /* unknown key */
    bad_case(3, "  ship: nosuch\n", "bad.yaml:3: own_ship.ship: unknown ship 'nosuch'");
    bad_case(7, "  speed_kn: fast\n", "bad.yaml:7: own_ship.speed_kn");   /* wrong type */
    bad_case(7, "  speed_kn: .nan\n", "bad.yaml:7: own_ship.speed_kn");   /* NaN */
    bad_case(8, "\n", "own_ship: give exactly one of leg_nm, destination or route"); /* missing */
    bad_case(9, "traffic:\n  network: atlantis\n",
             "bad.yaml:10: traffic.network: unknown network 'atlantis'");
    bad_case(11, "    - {id: T1, east_m: 0, north_m: 100, course_deg: 180, speed_kn: 10, "
                 "length_m: 200, breadth_m: 32}\n",
             "bad.yaml:11: traffic.targets[0]: target 'T1' starts overlapping");
    bad_case(11, "    - {id: T1, east_m: 0, north_m: 2000, course_deg: 180, speed_kn: 10, "
                 "length_m: 200}\n",
             "bad.yaml:11: traffic.targets[0].breadth_m");
    bad_case(13, "  duration_s: [1]\n", "bad.yaml:13: run.duration_s");
    bad_case(9, "traffic:\n  behaviour: polite\n",
             "bad.yaml:10: traffic.behaviour: 'polite': expected colregs or blind");
    bad_case(9, "traffic:\n  waterway: river\n",
             "bad.yaml:10: traffic.waterway: 'river': expected open-sea, tss or channel");
    /* the knowledge base's range: c3's is fitted at 14.55-26.7 kn, 5-35 deg */
    bad_case(7, "  speed_kn: 5\n",
             "bad.yaml:7: own_ship.speed_kn: 5 kn is beyond c3's Nomoto knowledge base, fitted "
             "over 14.55-26.7 kn, by more than its x1.5 margin (9.7-40.0 kn)");
    bad_case(13, "  duration_s: 100\navoidance:\n  min_helm_deg: 3\n",
             "bad.yaml:15: avoidance.min_helm_deg: 3 deg is outside 5-35 deg, the rudder angles "
             "c3's Nomoto knowledge base was fitted over");
}

int main(void)
{
    if (test_tmpdir("run", tmp_root, sizeof tmp_root))
        return 1;
    const char *wd = getenv("FAIRWAY_WRITE_DIGESTS");
    if (wd && *wd && !(digest_out = fopen(wd, "w")))
        return 1;
    TEST_RUN(test_bad_files);
    TEST_RUN(test_oracle);
    TEST_RUN(test_determinism);
    TEST_RUN(test_paper_cases);
    TEST_RUN(test_paper_fast_time);
    TEST_RUN(test_imazu_cases);
    if (digest_out)
        fclose(digest_out);
    return TEST_EXIT();
}
