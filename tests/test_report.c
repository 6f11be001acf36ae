/* fairway report on databases with known answers (tests/study_db.c): the
 * hand database's rates, intervals, paired differences, percentiles and
 * traffic counts worked out on paper and read back from the CSVs; the
 * refusals (not a database, wrong version, no finished runs, unknown names);
 * and the directory being replaced whole or not at all. */
#define _XOPEN_SOURCE 700
#include <stdbool.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "study/report.h"
#include "study/schema.h"
#include "study_db.h"
#include "study/stats.h"
#include "test.h"
#include "test_tmp.h"

static char dir[256];

static bool exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    char *s = calloc((size_t)n + 1, 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n)
        s[0] = '\0';
    fclose(f);
    return s;
}

/* Splits a CSV line (no quoting in the report's tables) into fields. */
static int split(char *line, char **f, int max)
{
    int n = 0;
    f[n++] = line;
    for (char *p = line; *p && n < max; p++)
        if (*p == ',') {
            *p = '\0';
            f[n++] = p + 1;
        }
    return n;
}

/* The value in column `col` of the row of path whose columns match `where`
 * ("density=1,domain_m=100,measure=x"); NAN for an empty field; -999999 and
 * a failed check if there is no such row or column. */
static double csv_get(const char *path, const char *where, const char *col)
{
    char *text = slurp(path);
    CHECK_MSG(text != NULL, "%s missing", path);
    if (!text)
        return -999999;
    char *hdr[64], *row[64], *keys[16], wbuf[256];
    snprintf(wbuf, sizeof wbuf, "%s", where);
    int nk = split(wbuf, keys, 16);
    char *save = NULL, *line = strtok_r(text, "\n", &save);
    int nh = split(line, hdr, 64), ci = -1;
    for (int i = 0; i < nh; i++)
        if (strcmp(hdr[i], col) == 0)
            ci = i;
    double out = -999999;
    bool found = false;
    while (ci >= 0 && !found && (line = strtok_r(NULL, "\n", &save))) {
        int nr = split(line, row, 64);
        bool match = nr == nh;
        for (int k = 0; k < nk && match; k++) {
            char *eq = strchr(keys[k], '=');
            size_t kl = (size_t)(eq - keys[k]);
            for (int i = 0; i < nh; i++)
                if (strlen(hdr[i]) == kl && strncmp(hdr[i], keys[k], kl) == 0)
                    match = strcmp(row[i], eq + 1) == 0;
        }
        if (match) {
            found = true;
            out = row[ci][0] ? strtod(row[ci], NULL) : NAN;
        }
    }
    CHECK_MSG(found, "%s: no row %s with column %s", path, where, col);
    free(text);
    return out;
}

static const double t2 = 4.302652730; /* t(0.975; 2) */

static fw_status report(const char *db, const char *out, double reference, bool plots,
                        fw_study_report_result *res, fw_error *err)
{
    fw_study_report_def def = fw_default_study_report_def();
    def.db = db;
    def.out = out;
    def.reference_m = reference;
    def.plots = plots;
    fw_study_report *rep;
    fw_status st = fw_study_report_load(&def, &rep, err);
    if (st)
        return st;
    st = fw_study_report_write(rep, &def, res, err);
    fw_study_report_free(rep);
    return st;
}

static char hand_db[300], hand_out[300];

static void test_hand_summary(void)
{
    fw_error err = {0};
    fw_study_report_result res;
    CHECK(report(hand_db, hand_out, NAN, false, &res, &err) == FW_OK);
    char p[400];
    snprintf(p, sizeof p, "%s/summary.csv", hand_out);
    /* encounters per hour 8, 12, 10: mean 10, s 2 */
    const char *w = "density=1,domain_m=100,measure=encounters_per_h";
    CHECK(csv_get(p, w, "n") == 3);
    CHECK_NEAR(csv_get(p, w, "mean"), 10.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "sd"), 2.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_low"), 10.0 - t2 * 2.0 / sqrt(3.0), 1e-7);
    CHECK_NEAR(csv_get(p, w, "ci_high"), 10.0 + t2 * 2.0 / sqrt(3.0), 1e-7);
    /* by type: head-on 4, 2, 0; overtaking (either way) 2, 4, 0; crossing 2, 6, 10 */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=head_on_per_h", "mean"), 2.0, 1e-9);
    /* 4, 2, 0 per hour: 3 events in 1.5 h, fewer than 5, so not the t interval (which
     * reached -2.97 and was cut at 0) but Garwood's: [0.6187, 8.767] / 1.5 */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=head_on_per_h", "ci_low"), 0.61869 / 1.5, 5e-5);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=head_on_per_h", "ci_high"), 8.7673 / 1.5, 5e-4);
    /* crossing: 1, 3, 5 events, 9 in all: the t interval over the replications */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=crossing_per_h", "ci_high"), 6.0 + t2 * 4.0 / sqrt(3.0), 1e-7);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=overtaking_per_h", "mean"), 2.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=being_overtaken_per_h", "mean"), 4.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=crossing_per_h", "mean"), 6.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=crossing_per_h", "sd"), 4.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=crossing_give_way_per_h", "mean"), 4.0, 1e-9);
    /* domain violations 2, 1, 3 of 4, 6, 5 encounters in half an hour */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=domain_violations_per_h", "mean"), 4.0, 1e-9);
    /* ... pooled: 6 of 15, not the mean of the runs' shares */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=domain_violation_fraction", "mean"), 0.4, 1e-9);
    /* 6 violations in 1.5 h: 4 per hour, Garwood [2.202, 13.06] / 1.5 */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=domain_violations_per_h", "ci_low"), 2.202 / 1.5, 5e-4);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=domain_violations_per_h", "ci_high"), 13.06 / 1.5, 5e-3);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=domain_violations_per_h", "mean"), 2.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=near_misses_per_h", "mean"), 2.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=collisions_per_h", "mean"), 2.0 / 3.0, 1e-9);
    /* one run of three with a collision: Wilson (0.0615, 0.7923) */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=collision_run_fraction", "mean"), 1.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=collision_run_fraction", "ci_low"), 0.06149, 5e-5);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=collision_run_fraction", "ci_high"), 0.79234, 5e-5);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=near_miss_run_fraction", "mean"), 2.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=collision_run_fraction", "ci_high"),
               3.841459 / (3 + 3.841459), 1e-6);
    /* manoeuvres 3, 4, 5 and 6, 7, 9 in half an hour */
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=manoeuvres_per_h", "mean"), 8.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=manoeuvres_per_h", "mean"), 44.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=max_helm_deg", "mean"), 15.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=max_helm_deg", "ci_high"), 15.0 + t2 * 5.0 / sqrt(3.0), 1e-7);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=helm_orders_per_h", "mean"), 16.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=path_lengthening_m_per_h", "mean"), 300.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=100,measure=time_lost_s_per_h", "mean"), 90.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=time_lost_s_per_h", "mean"), 680.0 / 3.0, 1e-9);
    /* the run without a closest approach is missing, not zero: 400 and 600 m */
    CHECK(csv_get(p, "domain_m=500,measure=min_cpa_m", "n") == 2);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=min_cpa_m", "mean"), 500.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=min_cpa_m", "ci_high"),
               500.0 + 12.70620474 * sqrt(20000.0) / sqrt(2.0), 1e-5);
}

static void test_hand_paired(void)
{
    char p[400];
    snprintf(p, sizeof p, "%s/paired.csv", hand_out);
    /* manoeuvres per hour, 500 minus 100 m per replication: 6, 6, 8 */
    const char *w = "domain_m=500,reference_m=100,measure=manoeuvres_per_h";
    double sd = sqrt(4.0 / 3.0);
    CHECK(csv_get(p, w, "n") == 3);
    CHECK_NEAR(csv_get(p, w, "mean"), 20.0 / 3.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "sd"), sd, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_low"), 20.0 / 3.0 - t2 * sd / sqrt(3.0), 1e-7);
    CHECK(csv_get(p, w, "significant") == 1);
    /* domain violations are not compared across domain sizes (a larger domain is broken
     * sooner): no row, and the report says so */
    char *all = slurp(p);
    CHECK(all && !strstr(all, "domain_violations_per_h") && !strstr(all, "domain_violation_fraction"));
    free(all);
    /* near misses per hour: -2, 0, -4, i.e. 0 events at 500 m against 3 at 100 m in
     * 1.5 h; given the 3, 0 of 3 at 500 m: Clopper-Pearson [0, 0.7076], so the
     * difference is 3 (2p - 1) / 1.5 in [-2, 0.830]: not significant, where a paired t
     * (mean -2, sd 2) would have reached -6.97 */
    w = "domain_m=500,measure=near_misses_per_h";
    CHECK_NEAR(csv_get(p, w, "mean"), -2.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_low"), -2.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_high"), 3.0 * (2.0 * 0.707598 - 1.0) / 1.5, 1e-5);
    CHECK(csv_get(p, w, "significant") == 0);
    CHECK(csv_get(p, w, "n") == 3);
    /* same traffic, same encounters: a zero difference with a zero-width interval, not significant */
    CHECK(csv_get(p, "domain_m=500,measure=encounters_per_h", "mean") == 0.0);
    CHECK(csv_get(p, "domain_m=500,measure=encounters_per_h", "significant") == 0);
    /* what the comparison could have found at 80% power: (t(0.975; 2) + t(0.8; 2)) s / sqrt 3 */
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=manoeuvres_per_h", "detectable_80"),
               (t2 + 1.0606601718) * sqrt(4.0 / 3.0) / sqrt(3.0), 1e-6);
    CHECK(csv_get(p, "domain_m=500,measure=manoeuvres_per_h", "detectable_at_least") == 0);
    /* near misses: 3 events in 3 h of both settings, rate 1 an hour:
     * (z(0.975) + z(0.8)) sqrt(2 x 1 / 1.5) */
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=near_misses_per_h", "detectable_80"),
               (1.959963985 + 0.8416212336) * sqrt(2.0 / 1.5), 1e-6);
    /* collisions: 1 event (100 m) against 0 */
    CHECK(csv_get(p, "domain_m=500,measure=collisions_per_h", "detectable_at_least") == 0);
    /* path lengthening 400, 400, 600 m per hour */
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=path_lengthening_m_per_h", "mean"), 1400.0 / 3.0, 1e-9);
    /* only replications 0 and 2 have a closest approach at both sizes */
    CHECK(csv_get(p, "domain_m=500,measure=min_cpa_m", "n") == 2);
    CHECK_NEAR(csv_get(p, "domain_m=500,measure=min_cpa_m", "mean"), 300.0, 1e-9);
    /* the reference itself has no row */
    char *text = slurp(p);
    CHECK(text && !strstr(text, "\n1,100,100,"));
    free(text);
}

static void test_hand_traffic_cpa(void)
{
    char p[400];
    snprintf(p, sizeof p, "%s/traffic.csv", hand_out);
    /* 5, 4, 6 encounters in 10 ship-hours: 500, 400, 600 per 1000 ship-hours;
     * the failed run's row is not counted */
    const char *w = "domain_m=100,type=all";
    CHECK(csv_get(p, w, "encounters") == 15);
    CHECK_NEAR(csv_get(p, w, "traffic_ship_h"), 30.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "mean_per_1000_ship_h"), 500.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_high"), 500.0 + t2 * 100.0 / sqrt(3.0), 1e-6);
    CHECK_NEAR(csv_get(p, "domain_m=500,type=head-on", "mean_per_1000_ship_h"), 400.0 / 3.0, 1e-9);
    CHECK(csv_get(p, "domain_m=500,type=crossing", "encounters") == 6);
    snprintf(p, sizeof p, "%s/cpa.csv", hand_out);
    /* own CPAs 100, 200, ..., 1500 m at 100 m (numpy: 170, 450, 800, 1150, 1430), +50 m at 500 m */
    w = "domain_m=100,set=own,type=all";
    CHECK(csv_get(p, w, "n") == 15);
    CHECK_NEAR(csv_get(p, w, "p5_m"), 170.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "p25_m"), 450.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "p50_m"), 800.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "p75_m"), 1150.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "p95_m"), 1430.0, 1e-9);
    CHECK_NEAR(csv_get(p, "domain_m=500,set=own,type=all", "p95_m"), 1480.0, 1e-9);
    /* head-on at 100 m: 100, 200, 500 */
    CHECK(csv_get(p, "domain_m=100,set=own,type=head-on", "n") == 3);
    CHECK_NEAR(csv_get(p, "domain_m=100,set=own,type=head-on", "p50_m"), 200.0, 1e-9);
    /* traffic CPAs 250 k for k = 1..5, 1..4, 1..6: 15 values */
    CHECK(csv_get(p, "domain_m=100,set=traffic,type=all", "n") == 15);
    CHECK_NEAR(csv_get(p, "domain_m=100,set=traffic,type=all", "p50_m"), 750.0, 1e-9);
    /* histogram: bins of 100 m up to 1550 m; one encounter in each of 100..1500 m */
    snprintf(p, sizeof p, "%s/cpa_hist.csv", hand_out);
    CHECK(csv_get(p, "domain_m=100,set=own,bin_low_m=0", "count") == 0);
    CHECK(csv_get(p, "domain_m=100,set=own,bin_low_m=700", "count") == 1);
    CHECK(csv_get(p, "domain_m=500,set=own,bin_low_m=1500", "count") == 1);
    snprintf(p, sizeof p, "%s/runs.csv", hand_out);
    CHECK_NEAR(csv_get(p, "run_id=2", "collisions_per_h"), 2.0, 1e-9);
    CHECK_NEAR(csv_get(p, "run_id=2", "sim_h"), 0.5, 1e-12);
    CHECK(csv_get(p, "run_id=4", "min_cpa_m") != csv_get(p, "run_id=4", "min_cpa_m")); /* NaN */
}

/* Zero events in 20 one-hour runs: the exact interval [0, 0.184] per hour
 * (chi-square(0.975, 2) / 2 / 20 = 3.6889 / 20), never the t interval's
 * [0, 0]; and the paired difference of two zero counts is not [0, 0]
 * either, but within minus and plus that bound. */
static void test_zero_counts(void)
{
    char db[400], out[400], p[500];
    snprintf(db, sizeof db, "%s/zeros.db", dir);
    snprintf(out, sizeof out, "%s/zeros", dir);
    CHECK(sdb_zeros(db) == 0);
    fw_error err = {0};
    fw_study_report_result res;
    CHECK(report(db, out, 100.0, false, &res, &err) == FW_OK);
    snprintf(p, sizeof p, "%s/summary.csv", out);
    const char *zero[] = {"head_on_per_h", "overtaking_per_h", "overtaking_own_per_h",
                          "being_overtaken_per_h", "crossing_stand_on_per_h",
                          "near_misses_per_h", "collisions_per_h"};
    for (size_t i = 0; i < sizeof zero / sizeof zero[0]; i++) {
        char w[120];
        snprintf(w, sizeof w, "domain_m=100,measure=%s", zero[i]);
        CHECK(csv_get(p, w, "mean") == 0.0);
        CHECK(csv_get(p, w, "ci_low") == 0.0);
        CHECK_NEAR(csv_get(p, w, "ci_high"), 0.184444, 5e-6);
    }
    /* 20 give-way encounters: the t interval, of zero width since every run had one */
    CHECK(csv_get(p, "domain_m=100,measure=crossing_give_way_per_h", "ci_high") == 1.0);
    snprintf(p, sizeof p, "%s/paired.csv", out);
    CHECK_NEAR(csv_get(p, "domain_m=300,measure=head_on_per_h", "ci_low"), -0.184444, 5e-6);
    CHECK_NEAR(csv_get(p, "domain_m=300,measure=head_on_per_h", "ci_high"), 0.184444, 5e-6);
    CHECK_NEAR(csv_get(p, "domain_m=300,measure=collisions_per_h", "ci_high"), 0.184444, 5e-6);
    CHECK(csv_get(p, "domain_m=300,measure=collisions_per_h", "significant") == 0);
}

static void test_hand_md(void)
{
    char p[400];
    snprintf(p, sizeof p, "%s/report.md", hand_out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (!md)
        return;
    CHECK_CONTAINS(md, "# Study report: synthetic");
    CHECK_CONTAINS(md, "6 finished and counted, 1 failed, 7 in the database");
    CHECK_CONTAINS(md, "1 x \"SUMO error: vehicle teleported\"");
    CHECK_CONTAINS(md, "| 1 | - | 100 | 3 | 10.0 [5.03, 15.0] |");
    CHECK_CONTAINS(md, "1/3 [0.061, 0.79]");
    CHECK_CONTAINS(md, "## Paired differences from the 100 m domain");
    /* paired: violations -4, -2, -4; manoeuvres 6, 6, 8; path 400, 400, 600; time lost
     * 120, 110, 180 per hour; encounters, near misses and collision runs not significant */
    /* domain violations are not compared across domain sizes; the hand database has no
     * hull distances, so the least hull distance has no difference either */
    CHECK_CONTAINS(md, "| 1 | - | 500 | 3 | - | not compared | - | - | - | **6.67 [3.80, 9.54]** | "
                       "**467 [180, 754]** | **137 [42.6, 231]** |");
    CHECK_CONTAINS(md, "Domain violations are not compared across domain sizes");
    /* the first lines: 1.5 h per setting cannot show a halving of near misses, whose rate
     * of 2 an hour at 100 m needs 6 (1.96 + 0.84)^2 / 2 = 23.5 h; the power table */
    CHECK_CONTAINS(md, "**This study cannot tell its settings apart on near misses (hull to hull)**: "
                       "it has 1.50 h per setting");
    CHECK_CONTAINS(md, "| 1 | - | 100 | 1.50 | 3, 23.5 |");
    CHECK_CONTAINS(md, "- domain violations /h: pooled count / pooled hours, exact Poisson (Garwood)");
    CHECK_CONTAINS(md, "Also significant somewhere: closest approach of the run (m); largest helm "
                       "(deg); helm orders per hour.");
    CHECK_CONTAINS(md, "Not drawn (--no-plots)");
    CHECK_CONTAINS(md, "| near_miss_m | 200 |");
    CHECK(strstr(md, "schema_version") == NULL);
    free(md);
}

static void test_reference(void)
{
    char out[300];
    snprintf(out, sizeof out, "%s/ref500", dir);
    fw_error err = {0};
    fw_study_report_result res;
    CHECK(report(hand_db, out, 500.0, false, &res, &err) == FW_OK);
    char p[400];
    snprintf(p, sizeof p, "%s/paired.csv", out);
    CHECK_NEAR(csv_get(p, "domain_m=100,reference_m=500,measure=manoeuvres_per_h", "mean"),
               -20.0 / 3.0, 1e-9);
    /* not a domain size of the study: refused, naming the sizes there are */
    CHECK(report(hand_db, out, 250.0, false, &res, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "--reference 250: no finished runs with that domain size");
    CHECK_CONTAINS(err.msg, "(domain sizes: 100, 500 m)");
}

static void expect_refused(const char *db, const char *needle)
{
    char out[400];
    snprintf(out, sizeof out, "%s/refused", dir);
    fw_error err = {0};
    fw_study_report_result res;
    CHECK(report(db, out, NAN, false, &res, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, db);
    CHECK_CONTAINS(err.msg, needle);
    CHECK_MSG(!exists(out), "%s written for a refused database", out);
}

static void test_refusals(void)
{
    char p[400];
    snprintf(p, sizeof p, "%s/nosuch.db", dir);
    expect_refused(p, "no such file");
    snprintf(p, sizeof p, "%s/text.db", dir);
    FILE *f = fopen(p, "w");
    fprintf(f, "not sqlite at all, just long enough to be read as a header: 0123456789abcdef\n");
    fclose(f);
    expect_refused(p, "not a fairway study database");
    /* an SQLite file of another program */
    snprintf(p, sizeof p, "%s/other.db", dir);
    sqlite3 *db;
    sqlite3_open(p, &db);
    sdb_exec(db, "CREATE TABLE t(x)");
    sqlite3_close(db);
    expect_refused(p, "not a fairway study database (no such table: meta)");
    snprintf(p, sizeof p, "%s/v99.db", dir);
    sqlite3_close(sdb_create(p, "99"));
    expect_refused(p, "schema version 99, this fairway reads version " FW_SCHEMA_VERSION);
    snprintf(p, sizeof p, "%s/failed.db", dir);
    CHECK(sdb_only_failed(p) == 0);
    expect_refused(p, "no finished runs (2 failed, e.g. \"SUMO error: no network\")");
    snprintf(p, sizeof p, "%s/empty.db", dir);
    sqlite3_close(sdb_create(p, FW_SCHEMA_VERSION));
    expect_refused(p, "no finished runs");
    /* names the schema does not define are not guessed at */
    snprintf(p, sizeof p, "%s/sideways.db", dir);
    CHECK(sdb_hand(p) == 0);
    sqlite3_open(p, &db);
    sdb_exec(db, "INSERT INTO encounters(run_id, target, target_type, situation) "
                 "VALUES(1, 'x', 'cargo', 'sideways')");
    sqlite3_close(db);
    expect_refused(p, "column situation: 'sideways' is not one of head-on, overtaking, being "
                      "overtaken, crossing give-way, crossing stand-on");
    CHECK(sdb_hand(p) == 0);
    sqlite3_open(p, &db);
    sdb_exec(db, "UPDATE runs SET sim_s = NULL WHERE run_id = 3");
    sqlite3_close(db);
    expect_refused(p, "table runs, row 3 (run synthetic-000003), column sim_s: missing in a finished run");
}

/* The hand database copied to NAME.db, changed by sql, and reported into the
 * directory NAME (out); db_path gets the copy's path.  True when written. */
static bool hand_report(const char *name, const char *sql, char db_path[300], char out[300])
{
    snprintf(db_path, 300, "%s/%s.db", dir, name);
    snprintf(out, 300, "%s/%s", dir, name);
    CHECK(sdb_hand(db_path) == 0);
    sqlite3 *db = NULL;
    sqlite3_open(db_path, &db);
    bool ok = sdb_exec(db, "%s", sql) == 0;
    sqlite3_close(db);
    fw_error err = {0};
    fw_study_report_result res;
    ok = ok && report(db_path, out, NAN, false, &res, &err) == FW_OK;
    CHECK_MSG(ok, "%s: %s", name, err.msg);
    return ok;
}

/* SQL that adds a copy of every run (id + 100) and its encounters with SET. */
#define COPY_RUNS(set_runs, set_enc)                                                       \
    "CREATE TEMP TABLE r AS SELECT * FROM runs;"                                            \
    "UPDATE r SET run_id = run_id + 100, " set_runs ";"                                     \
    "INSERT INTO runs SELECT * FROM r;"                                                     \
    "CREATE TEMP TABLE e AS SELECT * FROM encounters;"                                      \
    "UPDATE e SET run_id = run_id + 100" set_enc ";"                                        \
    "INSERT INTO encounters SELECT * FROM e;"

/* The behaviour axis: the hand study sailed twice, as colregs and as blind
 * traffic, the blind copy with every encounter inside the domain.  colregs -
 * blind is paired per (density, domain), counts with the conditional binomial. */
static void test_behaviours(void)
{
    char db_path[300], out[300], p[400];
    if (!hand_report("beh", "UPDATE runs SET behaviour = 'colregs';"
                            COPY_RUNS("behaviour = 'blind'", ", domain_entered = 1"),
                     db_path, out))
        return;
    snprintf(p, sizeof p, "%s/behaviour.csv", out);
    /* 100 m: 6 violations (colregs) against all 15 encounters (blind) in 1.5 h each */
    const char *w = "behaviour=colregs,domain_m=100,reference_behaviour=blind,"
                    "measure=domain_violations_per_h";
    fw_estimate cp = fw_clopper_pearson(6, 21, 0.95);
    CHECK_NEAR(csv_get(p, w, "mean"), -6.0, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_low"), 21.0 * (2.0 * cp.lo - 1.0) / 1.5, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_high"), 21.0 * (2.0 * cp.hi - 1.0) / 1.5, 1e-9);
    /* 6 of 21 at p = 1/2: P(X <= 6) = 82160 / 2^21 = 0.039, two-sided 0.078: not significant */
    CHECK(csv_get(p, w, "significant") == 0);
    /* the same traffic otherwise: no discordant pair of collision runs, a zero difference */
    w = "behaviour=colregs,domain_m=100,measure=collision_run_fraction";
    CHECK(csv_get(p, w, "mean") == 0.0 && csv_get(p, w, "ci_low") == 0.0 &&
          csv_get(p, w, "ci_high") == 0.0);
    CHECK(csv_get(p, w, "n") == 3);
    /* the domain-size pairs stay within a behaviour */
    snprintf(p, sizeof p, "%s/paired.csv", out);
    CHECK_NEAR(csv_get(p, "behaviour=blind,domain_m=500,measure=manoeuvres_per_h", "mean"),
               20.0 / 3.0, 1e-9);
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "## Background behaviour: colregs - blind");
        /* 1 violation against 15 at 500 m: significant; 6 against 15 at 100 m: not */
        CHECK_CONTAINS(md, "| 1 | colregs | 100 | 3 | 0 [0, 0] | -6.00 [-10.8, 0.61] | 0 [-3.06, 3.06] |");
        CHECK_CONTAINS(md, "| 1 | colregs | 500 | 3 | 0 [0, 0] | **-9.33 [-10.6, -4.22]** |");
        CHECK_CONTAINS(md, "| 1 | blind | 100 | 3 | 10.0 [5.03, 15.0] | 10.0 [5.60, 16.5] |");
    }
    free(md);
}

static long long count_sql(sqlite3 *db, const char *sql)
{
    sqlite3_stmt *st = NULL;
    long long n = -1;
    if (sqlite3_prepare_v2(db, sql, -1, &st, NULL) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
        n = sqlite3_column_int64(st, 0);
    sqlite3_finalize(st);
    return n;
}

/* The causation-factor table: the hand study's encounters marked as
 * candidates when they entered the domain, the outcome from their flags
 * (at 100 m: 3 crossing candidates, 1 collision),
 * and two traffic pairs; the report's counts against SQL's own. */
static void test_causation(void)
{
    char db_path[300], out[300], p[400];
    if (!hand_report("cand",
                     "UPDATE encounters SET candidate = domain_entered, cand_miss_m = 0, "
                     "outcome = CASE WHEN collision THEN 'collision' WHEN near_miss THEN "
                     "'near miss' WHEN domain_entered THEN 'domain' ELSE 'passed' END;"
                     "INSERT INTO traffic_encounters(run_id, ship_a, ship_b, type, own, "
                     "t_first_s, candidate, outcome) VALUES(0, 'a', 'b', 'crossing', 0, 10, 1, "
                     "'collision'), (0, 'a', 'c', 'crossing', 0, 20, 1, 'passed'), "
                     "(0, 'a', 'own', 'crossing', 1, 30, 1, 'collision')",
                     db_path, out))
        return;
    sqlite3 *db = NULL;
    sqlite3_open(db_path, &db);
    long long n_cand = count_sql(db, "SELECT COUNT(*) FROM encounters e JOIN runs r USING(run_id) "
                                     "WHERE r.status = 'ok' AND r.domain_m = 100 AND candidate AND "
                                     "situation IN ('crossing give-way', 'crossing stand-on')");
    long long n_coll = count_sql(db, "SELECT COUNT(*) FROM encounters e JOIN runs r USING(run_id) "
                                     "WHERE r.status = 'ok' AND r.domain_m = 100 AND candidate AND "
                                     "outcome = 'collision' AND situation LIKE 'crossing%'");
    sqlite3_close(db);
    CHECK(n_cand == 3 && n_coll == 1);
    snprintf(p, sizeof p, "%s/causation.csv", out);
    const char *w = "domain_m=100,set=own,type=crossing";
    CHECK(csv_get(p, w, "candidates") == n_cand);
    CHECK(csv_get(p, w, "collisions") == n_coll);
    fw_estimate e = fw_clopper_pearson((int)n_coll, (int)n_cand, 0.95);
    CHECK_NEAR(csv_get(p, w, "ci_high"), e.hi, 1e-9);
    CHECK_NEAR(csv_get(p, w, "ci_low"), 0.00840, 5e-6); /* 1 of 3: [0.0084, 0.906] */
    CHECK_NEAR(csv_get(p, w, "ci_high"), 0.9057, 5e-5);
    CHECK_NEAR(csv_get(p, w, "iwrap"), 1.3e-4, 1e-12);
    /* traffic: the two background pairs (the own ship's pair is not traffic), 1 of 2
     * collided: Clopper-Pearson [0.0126, 0.987] */
    w = "domain_m=100,set=traffic,type=crossing";
    CHECK(csv_get(p, w, "candidates") == 2 && csv_get(p, w, "collisions") == 1);
    CHECK_NEAR(csv_get(p, w, "ci_low"), 0.0126, 5e-5);
    CHECK_NEAR(csv_get(p, w, "ci_high"), 0.9874, 5e-5);
    CHECK(csv_get(p, "domain_m=100,set=traffic,type=head-on", "candidates") == 0);
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "## Measured causation factor");
        CHECK_CONTAINS(md, "| traffic | 1 | - | 100 | 0 candidates | 0 candidates | 1/2 = 0.50 [0.013, 0.99] |");
        CHECK_CONTAINS(md, "head-on 4.9e-05, overtaking 0.00011");
    }
    free(md);
}

/* Domain shapes: the hand study again with a 2.5:1 domain; each shape is
 * its own setting, compared with the reference size of its own shape. */
static void test_shapes(void)
{
    char db_path[300], out[300], p[400];
    if (!hand_report("shape", "UPDATE runs SET fore_aft_ratio = 1;"
                              COPY_RUNS("fore_aft_ratio = 2.5", ""),
                     db_path, out))
        return;
    snprintf(p, sizeof p, "%s/paired.csv", out);
    CHECK_NEAR(csv_get(p, "domain_m=500,fore_aft_ratio=2.5,measure=manoeuvres_per_h", "mean"),
               20.0 / 3.0, 1e-9);
    snprintf(p, sizeof p, "%s/summary.csv", out);
    CHECK_NEAR(csv_get(p, "domain_m=100,fore_aft_ratio=2.5,measure=encounters_per_h", "mean"),
               10.0, 1e-9);
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "| 1 | - | 100 (2.5:1) | 3 | 10.0 [5.03, 15.0] |");
        CHECK_CONTAINS(md, "| 1 | - | 100 | 3 | 10.0 [5.03, 15.0] |");
        CHECK_CONTAINS(md, "| 1 | - | 500 (2.5:1) | 3 | - |");
    }
    free(md);
}

/* A study's axes (runs.setting): the hand study sailed in a second setting
 * whose every encounter entered the domain; the groups keep the settings
 * apart, the first setting (the one of the first runs) is the reference of
 * "Axes", and settings.csv pairs each group with it. */
static void test_settings(void)
{
    char db_path[300], out[300], p[400];
    if (!hand_report("axes", "UPDATE runs SET setting = 'sensing.dropout=0';"
                             COPY_RUNS("setting = 'sensing.dropout=0.5'", ", domain_entered = 1"),
                     db_path, out))
        return;
    snprintf(p, sizeof p, "%s/settings.csv", out);
    /* 500 m: 1 violation against all 15 encounters in 1.5 h each: -14 / 1.5 h */
    const char *w = "setting=sensing.dropout=0.5,domain_m=500,measure=domain_violations_per_h";
    CHECK_NEAR(csv_get(p, w, "mean"), 14.0 / 1.5, 1e-9);
    snprintf(p, sizeof p, "%s/summary.csv", out);
    CHECK_NEAR(csv_get(p, "setting=sensing.dropout=0,domain_m=100,measure=encounters_per_h",
                       "mean"), 10.0, 1e-9);
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "## Axes: each setting - the first (sensing.dropout=0)");
        CHECK_CONTAINS(md, "| density | traffic; setting | domain (m) | runs |");
        CHECK_CONTAINS(md, "| 1 | -; sensing.dropout=0.5 | 100 | 3 | 10.0 [5.03, 15.0] |");
    }
    free(md);
}

/* The splitting estimates (table splits) beside the crude counts: a cell
 * with three batches (the mean and per hour: a run is half an hour), and a
 * cell whose every batch found no path to a collision, said as such. */
static void test_splits(void)
{
    char db_path[300], out[300], p[400];
    if (!hand_report("split",
                     "INSERT INTO splits(cell, batch, domain_m, density, particles, status, "
                     "rounds, runs, sim_s, wall_s, p_collision, p_near_miss, best_closeness, "
                     "best_path) VALUES"
                     "(0, 0, 100, 1, 20, 'ok', 10, 100, 180000, 1, 0.01, 0.1, 1, '5:'),"
                     "(0, 1, 100, 1, 20, 'ok', 10, 100, 180000, 1, 0.02, 0.2, 1, '6:'),"
                     "(0, 2, 100, 1, 20, 'ok', 10, 100, 180000, 1, 0.03, 0.3, 1, '7:'),"
                     "(1, 0, 500, 1, 20, 'ok', 10, 100, 180000, 1, 0, 0, 0.8, '8:'),"
                     "(1, 1, 500, 1, 20, 'ok', 10, 100, 180000, 1, 0, 0, 0.75, '9:');",
                     db_path, out))
        return;
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "## Rare events by splitting");
        CHECK_CONTAINS(md, "| 100 m |  | 3 x 20 | 0.02 [");
        CHECK_CONTAINS(md, "| 0.04 | 0.2 [");
        CHECK_CONTAINS(md, "| 150.0 |");
        CHECK_CONTAINS(md, "| 500 m |  | 2 x 20 | 0: no batch reached it (closest: closeness 0.800) |");
    }
    free(md);
    snprintf(p, sizeof p, "%s/splits.csv", out);
    CHECK_NEAR(csv_get(p, "cell=0", "p_collision"), 0.02, 1e-12);
    CHECK_NEAR(csv_get(p, "cell=0", "p_collision_per_h"), 0.04, 1e-12);
}

/* Oddities that do not stop the report are named in it. */
static void test_warnings(void)
{
    char db_path[300], out[300], p[400];
    snprintf(db_path, sizeof db_path, "%s/odd.db", dir);
    snprintf(out, sizeof out, "%s/odd", dir);
    CHECK(sdb_hand(db_path) == 0);
    sqlite3 *db;
    sqlite3_open(db_path, &db);
    /* one run whose total disagrees with its rows; a density without the reference size */
    sdb_exec(db, "UPDATE runs SET n_encounters = 9 WHERE run_id = 1");
    sdb_exec(db, "INSERT INTO runs(run_id, domain_m, density, replication, seed, status, sim_s) "
                 "VALUES(10, 500, 2, 0, 1, 'ok', 3600)");
    sqlite3_close(db);
    fw_error err = {0};
    fw_study_report_result res;
    CHECK(report(db_path, out, NAN, false, &res, &err) == FW_OK);
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md != NULL);
    if (md) {
        CHECK_CONTAINS(md, "Warning: 1 run with runs.n_encounters different from its encounter rows");
        CHECK_CONTAINS(md, "Warning: density 2 has no finished runs with the reference domain");
        /* one run, no encounters in its hour: no t interval can be had, but 0
         * encounters and 0 domain violations in 1 h are both [0, 3.69] exactly */
        CHECK_CONTAINS(md, "| 2 | - | 500 | 1 | 0 [0, 3.69] | 0 [0, 3.69] |");
    }
    free(md);
    /* the counts still come from the rows */
    snprintf(p, sizeof p, "%s/runs.csv", out);
    CHECK_NEAR(csv_get(p, "run_id=1", "encounters_per_h"), 12.0, 1e-9);
}

static void test_directory(void)
{
    char out[400], p[500];
    fw_error err = {0};
    fw_study_report_result res;
    /* default: <stem>-report beside the database */
    fw_study_report_def def = fw_default_study_report_def();
    def.db = hand_db;
    def.plots = false;
    fw_study_report *rep;
    CHECK(fw_study_report_load(&def, &rep, &err) == FW_OK);
    CHECK(fw_study_report_write(rep, &def, &res, &err) == FW_OK);
    snprintf(p, sizeof p, "%s/hand-report/summary.csv", dir);
    CHECK(exists(p));
    /* writing again replaces it and leaves no temporary directory */
    CHECK(fw_study_report_write(rep, &def, &res, &err) == FW_OK);
    fw_study_report_free(rep);
    snprintf(p, sizeof p, "%s/.hand-report.tmp.%ld", dir, (long)getpid());
    CHECK(!exists(p));
    snprintf(p, sizeof p, "%s/.hand-report.old.%ld", dir, (long)getpid());
    CHECK(!exists(p));
    /* a directory that is not a report is not replaced */
    snprintf(out, sizeof out, "%s/precious", dir);
    mkdir(out, 0777);
    snprintf(p, sizeof p, "%s/thesis.tex", out);
    fclose(fopen(p, "w"));
    CHECK(report(hand_db, out, NAN, false, &res, &err) == FW_EINPUT);
    CHECK_CONTAINS(err.msg, "is not a fairway report directory");
    CHECK(exists(p));
    /* plotting that fails keeps the tables, says so in report.md, and is FW_ERUN */
    def = fw_default_study_report_def();
    snprintf(out, sizeof out, "%s/noplot", dir);
    def.db = hand_db;
    def.out = out;
    def.python = "/bin/false";
    CHECK(fw_study_report_load(&def, &rep, &err) == FW_OK);
    CHECK(fw_study_report_write(rep, &def, &res, &err) == FW_ERUN);
    CHECK(res.plots == FW_PLOTS_FAILED);
    CHECK_CONTAINS(err.msg, "plotting failed");
    def.script = "/nonexistent/plot_study.py";
    CHECK(fw_study_report_write(rep, &def, &res, &err) == FW_ERUN);
    CHECK_CONTAINS(res.plot_msg, "/nonexistent/plot_study.py not found");
    fw_study_report_free(rep);
    snprintf(p, sizeof p, "%s/summary.csv", out);
    CHECK(exists(p));
    snprintf(p, sizeof p, "%s/report.md", out);
    char *md = slurp(p);
    CHECK(md && strstr(md, "**Plotting failed:**"));
    free(md);
}

int main(void)
{
    if (test_tmpdir("report", dir, sizeof dir))
        return 1;
    snprintf(hand_db, sizeof hand_db, "%s/hand.db", dir);
    snprintf(hand_out, sizeof hand_out, "%s/hand", dir);
    if (sdb_hand(hand_db) != 0)
        return 1;
    TEST_RUN(test_hand_summary);
    TEST_RUN(test_hand_paired);
    TEST_RUN(test_hand_traffic_cpa);
    TEST_RUN(test_hand_md);
    TEST_RUN(test_zero_counts);
    TEST_RUN(test_reference);
    TEST_RUN(test_refusals);
    TEST_RUN(test_warnings);
    TEST_RUN(test_behaviours);
    TEST_RUN(test_causation);
    TEST_RUN(test_shapes);
    TEST_RUN(test_settings);
    TEST_RUN(test_splits);
    TEST_RUN(test_directory);
    int rc = TEST_EXIT();
    return rc;
}
