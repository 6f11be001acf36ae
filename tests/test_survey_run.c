/* test_survey_run - the traffic survey in scenario files and runs:
 *
 *   test_survey_run        the survey: section (values, defaults, FILE:LINE:
 *                          field errors)
 *   test_survey_run run    a scenario on the crossing network through libsumo
 *                          (one simulation per process): the counts are
 *                          produced, identical on a rerun, and the survey
 *                          leaves the run itself unchanged
 */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "run/run.h"
#include "survey/survey.h"
#include "test.h"
#include "test_tmp.h"

static char tmp_root[256];

/* ---- scenario files ---- */

static const char *good =
    "name: s\n"                                                         /* 1 */
    "own_ship: {ship: c3, east_m: 0, north_m: 0, course_deg: 0, speed_kn: 10, leg_nm: 5}\n"
    "traffic:\n"                                                        /* 3 */
    "  network: crossing\n"                                             /* 4 */
    "survey:\n"                                                         /* 5 */
    "  radius_nm: 4\n"                                                  /* 6 */
    "  range_m: 1500\n"                                                 /* 7 */
    "  dcpa_m: 500\n"                                                   /* 8 */
    "  tcpa_s: 600\n"                                                   /* 9 */
    "  hysteresis_m: 200\n"                                             /* 10 */
    "run:\n"                                                            /* 11 */
    "  duration_s: 100\n";                                              /* 12 */

static fw_status load_with(int line, const char *replacement, fw_scenario *s, fw_error *err)
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
    snprintf(path, sizeof path, "%s/survey.yaml", tmp_root);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return fw_scenario_load(path, s, err);
}

static void bad(int line, const char *replacement, const char *expect)
{
    static fw_scenario s;
    fw_error err = {0};
    fw_status st = load_with(line, replacement, &s, &err);
    CHECK_MSG(st == FW_EINPUT, "line %d '%s': status %d", line, replacement, st);
    CHECK_MSG(strstr(err.msg, expect) != NULL, "'%s' does not contain '%s'", err.msg, expect);
}

static void test_scenario(void)
{
    static fw_scenario s;
    fw_error err = {0};
    CHECK_MSG(load_with(0, "", &s, &err) == FW_OK, "%s", err.msg);
    CHECK(s.survey);
    CHECK_NEAR(s.survey_radius, 4 * 1852.0, 1e-9);
    CHECK_NEAR(s.survey_def.range, 1500.0, 0.0);
    CHECK_NEAR(s.survey_def.dcpa, 500.0, 0.0);
    CHECK_NEAR(s.survey_def.tcpa, 600.0, 0.0);
    CHECK_NEAR(s.survey_def.hysteresis, 200.0, 0.0);
    /* radius_nm left out: 6 nm */
    static fw_scenario e;
    CHECK_MSG(load_with(6, "", &e, &err) == FW_OK, "%s", err.msg);
    CHECK_NEAR(e.survey_radius, 6 * 1852.0, 1e-9);
    CHECK_NEAR(e.survey_def.range, 1500.0, 0.0);
    bad(7, "  range_m: far\n", "survey.yaml:7: survey.range_m");
    bad(8, "  dcpa_m: -1\n", "survey.yaml:8: survey.dcpa_m");
    bad(9, "  tcpa_s: .nan\n", "survey.yaml:9: survey.tcpa_s");
    bad(10, "  hysteresis: 200\n", "survey.yaml:10: survey");  /* unknown key */
    bad(6, "  radius_nm: 100\n", "survey.yaml:6: survey.radius_nm");
}

static void test_scenario_off(void)
{
    /* the good file without lines 5-10: no survey */
    static fw_scenario s;
    fw_error err = {0};
    char path[512];
    snprintf(path, sizeof path, "%s/nosurvey.yaml", tmp_root);
    FILE *f = fopen(path, "w");
    fputs("name: s\nown_ship: {ship: c3, east_m: 0, north_m: 0, course_deg: 0, speed_kn: 10, "
          "leg_nm: 5}\ntraffic: {network: crossing}\nrun: {duration_s: 100}\n",
          f);
    fclose(f);
    CHECK_MSG(fw_scenario_load(path, &s, &err) == FW_OK, "%s", err.msg);
    CHECK(!s.survey);
    snprintf(path, sizeof path, "%s/empty.yaml", tmp_root);
    f = fopen(path, "w");
    fputs("name: s\nown_ship: {ship: c3, east_m: 0, north_m: 0, course_deg: 0, speed_kn: 10, "
          "leg_nm: 5}\ntraffic: {network: crossing}\nsurvey: {}\nrun: {duration_s: 100}\n",
          f);
    fclose(f);
    CHECK_MSG(fw_scenario_load(path, &s, &err) == FW_OK, "%s", err.msg);
    CHECK(s.survey);
    CHECK_NEAR(s.survey_radius, 6 * 1852.0, 1e-9);
    CHECK_NEAR(s.survey_def.range, 2000.0, 0.0);
    snprintf(path, sizeof path, "%s/list.yaml", tmp_root);
    f = fopen(path, "w");
    fputs("name: s\nown_ship: {ship: c3, east_m: 0, north_m: 0, course_deg: 0, speed_kn: 10, "
          "leg_nm: 5}\ntraffic: {network: crossing}\nsurvey: [1]\nrun: {duration_s: 100}\n",
          f);
    fclose(f);
    CHECK(fw_scenario_load(path, &s, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "list.yaml:4: survey");
}

/* ---- a run on a network ---- */

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

static int count_lines(const char *path)
{
    FILE *f = fopen(path, "r");
    int n = 0, c;
    if (!f)
        return -1;
    while ((c = fgetc(f)) != EOF)
        n += c == '\n';
    fclose(f);
    return n;
}

typedef struct run_out {
    fw_run_summary sum;
    fw_survey_record *rec;
    int n;
} run_out;

static fw_status run_in(const fw_scenario *s, const char *name, run_out *o)
{
    char dir[512];
    snprintf(dir, sizeof dir, "%s/%s", tmp_root, name);
    mkdir(dir, 0777);
    fw_run_def def = fw_default_run_def();
    def.scenario = s;
    def.dir = dir;
    def.survey_out = &o->rec;
    def.n_survey_out = &o->n;
    fw_encounter *enc = NULL;
    int ne = 0;
    fw_error err = {0};
    fw_status st = fw_run_scenario(&def, &o->sum, &enc, &ne, &err);
    CHECK_MSG(st == FW_OK, "%s: %s", name, err.msg);
    free(enc);
    return st;
}

static void test_run(void)
{
    static fw_scenario s;
    char file[512];
    fw_error err = {0};
    snprintf(file, sizeof file, "%s/tests/data/survey_crossing.yaml", fw_data_root());
    if (fw_scenario_load(file, &s, &err)) {
        CHECK_MSG(0, "%s", err.msg);
        return;
    }
    run_out a = {0}, b = {0}, off = {0};
    if (run_in(&s, "a", &a) || run_in(&s, "b", &b))
        return;
    s.survey = false;
    if (run_in(&s, "off", &off))
        return;
    const fw_run_summary *m = &a.sum;
    printf("survey: %d encounters (%d head-on, %d overtaking, %d crossing; %d with the own ship) "
           "in %.0f ship-s\n", m->n_traffic, m->traffic_by_type[0], m->traffic_by_type[1],
           m->traffic_by_type[2], m->n_traffic_own, m->traffic_ship_s);
    CHECK(m->survey && !off.sum.survey);
    /* counts of every kind on this traffic, and the pieces add up */
    for (int k = 0; k < FW_SURVEY_NTYPES; k++)
        CHECK_MSG(m->traffic_by_type[k] > 0, "no %s", fw_survey_type_name(k));
    CHECK(m->traffic_by_type[0] + m->traffic_by_type[1] + m->traffic_by_type[2] == m->n_traffic);
    CHECK(m->n_traffic_own > 0 && m->n_traffic_own < m->n_traffic);
    /* more than 20 ships in the area on average over the 600 s */
    CHECK_MSG(m->traffic_ship_s > 20 * 600.0, "%.0f ship-s", m->traffic_ship_s);
    /* the records handed over are those counted, the own ship flagged */
    CHECK(a.n == m->n_traffic && a.rec);
    fw_survey_totals tot;
    if (a.rec)
        fw_survey_count(a.rec, a.n, &tot);
    CHECK(a.rec && tot.n_own == m->n_traffic_own && tot.by_type[1] == m->traffic_by_type[1]);
    for (int i = 0; i < a.n; i++) {
        bool own = strcmp(a.rec[i].ship_a, "fw_own") == 0 || strcmp(a.rec[i].ship_b, "fw_own") == 0;
        CHECK(own == a.rec[i].own);
        CHECK(a.rec[i].range0 < 2000.0 && a.rec[i].dcpa0 < 1000.0);
        CHECK(a.rec[i].tcpa0 > 0.0 && a.rec[i].tcpa0 < 1000.0);
        CHECK(a.rec[i].min_dist <= a.rec[i].range0 && a.rec[i].t_min >= a.rec[i].t_first);
    }
    /* identical on a rerun, in memory and in the files */
    CHECK(b.n == a.n && b.sum.traffic_ship_s == a.sum.traffic_ship_s);
    if (b.n == a.n && a.n > 0)
        for (int i = 0; i < a.n; i++)
            CHECK(strcmp(a.rec[i].ship_a, b.rec[i].ship_a) == 0 &&
                  strcmp(a.rec[i].ship_b, b.rec[i].ship_b) == 0 &&
                  a.rec[i].t_first == b.rec[i].t_first && a.rec[i].min_dist == b.rec[i].min_dist);
    static const char *const same[] = {"traffic_encounters.csv", "summary.json", "run.log",
                                        "own.csv", "encounters.csv"};
    for (size_t i = 0; i < sizeof same / sizeof same[0]; i++) {
        char x[700], y[700];
        snprintf(x, sizeof x, "%s/a/%s", tmp_root, same[i]);
        snprintf(y, sizeof y, "%s/b/%s", tmp_root, same[i]);
        CHECK_MSG(same_file(x, y), "%s differs between two runs", same[i]);
    }
    char path[700];
    snprintf(path, sizeof path, "%s/a/traffic_encounters.csv", tmp_root);
    CHECK(count_lines(path) == a.n + 1);
    /* the survey watches: the own ship's run is the same without it */
    static const char *const unchanged[] = {"own.csv", "encounters.csv"};
    for (size_t i = 0; i < 2; i++) {
        char x[700], y[700];
        snprintf(x, sizeof x, "%s/a/%s", tmp_root, unchanged[i]);
        snprintf(y, sizeof y, "%s/off/%s", tmp_root, unchanged[i]);
        CHECK_MSG(same_file(x, y), "%s changed by the survey", unchanged[i]);
    }
    snprintf(path, sizeof path, "%s/off/traffic_encounters.csv", tmp_root);
    CHECK(access(path, F_OK) != 0);
    CHECK(off.rec == NULL && off.n == 0);
    free(a.rec);
    free(b.rec);
}

int main(int argc, char **argv)
{
    const char *which = argc > 1 ? argv[1] : "files";
    if (test_tmpdir("survey", tmp_root, sizeof tmp_root))
        return 1;
    if (strcmp(which, "files") == 0) {
        TEST_RUN(test_scenario);
        TEST_RUN(test_scenario_off);
    } else if (strcmp(which, "run") == 0) {
        TEST_RUN(test_run);
    } else {
        fprintf(stderr, "unknown case %s\n", which);
        return 2;
    }
    return TEST_EXIT();
}
