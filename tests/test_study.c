/* test_study.c - study files, the run list (common random numbers), run
 * outcomes as bytes, and the database's one-transaction commits. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <sqlite3.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/units.h"
#include "study/outcome.h"
#include "study/store.h"
#include "study/study.h"
#include "test.h"

static fw_study *load(const char *rel)
{
    char path[1024];
    const char *root = getenv("FAIRWAY_DATA");
    snprintf(path, sizeof path, "%s/%s", root ? root : ".", rel);
    fw_study *s = malloc(sizeof *s);
    fw_error err = {0};
    fw_status st = fw_study_load(path, s, &err);
    CHECK_MSG(st == FW_OK, "%s", err.msg);
    return s;
}

/* Every domain size of a replication sees the same traffic and start; the
 * replications differ; the list is replication-major. */
static void test_run_list(void)
{
    fw_study *s = load("tests/data/study/small.yaml");
    CHECK(fw_study_run_count(s) == 10);
    for (int id = 0; id < 10; id++) {
        fw_study_run r = fw_study_run_at(s, id), r0 = fw_study_run_at(s, id - id % 2);
        CHECK(r.run_id == id);
        CHECK(r.replication == id / 2);
        CHECK(r.domain == s->domains[id % 2]);
        CHECK(r.seed == r0.seed && r.d_along == r0.d_along && r.d_across == r0.d_across);
        CHECK(fabs(r.d_along) <= 1000.0 && fabs(r.d_across) <= 2000.0);
        if (id >= 2) {
            fw_study_run p = fw_study_run_at(s, id - 2);
            CHECK(p.seed != r.seed && p.d_along != r.d_along);
        }
        fw_scenario scn;
        fw_study_scenario(s, &r, &scn);
        CHECK(scn.helm.domain.size == r.domain);
        CHECK(scn.seed == r.seed);
        /* the start moves by exactly the offsets, along and across the course */
        double de = scn.east - s->base.east, dn = scn.north - s->base.north;
        CHECK_NEAR(de * sin(scn.course) + dn * cos(scn.course), r.d_along, 1e-9);
        CHECK_NEAR(de * cos(scn.course) - dn * sin(scn.course), r.d_across, 1e-9);
    }
    /* the same file twice: the same digest; the run list is a pure function */
    fw_study *t = load("tests/data/study/small.yaml");
    CHECK(t->digest == s->digest);
    CHECK(fw_study_run_at(t, 7).seed == fw_study_run_at(s, 7).seed);
    free(t);
    free(s);
}

/* With behaviours as a second axis: the domains of each behaviour sit inside
 * the replication, and every run of a replication shares its seed and start,
 * so colregs - blind is paired like the domain sizes are. */
static void test_run_list_behaviours(void)
{
    fw_study *s = load("tests/data/study/behaviours.yaml");
    CHECK(s->n_behaviours == 2);
    CHECK(fw_study_run_count(s) == 12);
    for (int id = 0; id < 12; id++) {
        fw_study_run r = fw_study_run_at(s, id), r0 = fw_study_run_at(s, id - id % 4);
        CHECK(r.replication == id / 4);
        CHECK(r.domain == s->domains[id % 2]);
        CHECK(r.behaviour == ((id / 2) % 2 ? FW_BEHAVIOUR_BLIND : FW_BEHAVIOUR_COLREGS));
        CHECK(r.seed == r0.seed && r.d_along == r0.d_along && r.d_across == r0.d_across);
        fw_scenario scn;
        fw_study_scenario(s, &r, &scn);
        CHECK(scn.reactions.behaviour == r.behaviour);
    }
    /* the axis is part of the study: another digest than the same study without it */
    fw_study *t = load("tests/data/study/small.yaml");
    CHECK(t->n_behaviours == 1 && t->behaviours[0] == t->base.reactions.behaviour);
    CHECK(t->digest != s->digest);
    free(t);
    free(s);
}

/* Domains in own-ship lengths and two shapes: the metres follow from the
 * ship (the C-3, 333 m), the shapes sit inside the replication. */
static void test_run_list_shapes(void)
{
    fw_study *s = load("tests/data/study/shapes.yaml");
    CHECK(s->n_ratios == 2 && s->domains_in_lengths);
    CHECK_NEAR(s->domains[0], s->base.ship.Loa, 1e-9);
    CHECK_NEAR(s->domains[1], 2.0 * s->base.ship.Loa, 1e-9);
    CHECK(s->base.ship.Loa > 300.0);
    CHECK(fw_study_run_count(s) == 8);
    for (int id = 0; id < 8; id++) {
        fw_study_run r = fw_study_run_at(s, id), r0 = fw_study_run_at(s, id - id % 4);
        CHECK(r.replication == id / 4);
        CHECK(r.ratio == ((id / 2) % 2 ? 2.5 : 1.0));
        CHECK(r.seed == r0.seed && r.d_along == r0.d_along);
        fw_scenario scn;
        fw_study_scenario(s, &r, &scn);
        CHECK(scn.helm.domain.fore_aft_ratio == r.ratio && scn.helm.domain.size == r.domain);
    }
    free(s);
}

/* The sensing and the visibility as axes (issue 24): twelve settings, each
 * scenario with its sensor's mode and gain (beta Benedict-Bordner's) and its
 * visibility where the rules read it (the own ship's and the traffic's). */
static void test_run_list_axes_fog(void)
{
    fw_study *s = load("tests/data/study/axes-fog.yaml");
    CHECK(s->n_axes == 3 && s->n_settings == 12);
    static const fw_sensing_mode mode[] = {FW_SENSE_PERFECT, FW_SENSE_RADAR, FW_SENSE_AIS_RADAR};
    for (int k = 0; k < 12; k++) {
        fw_study_run r = fw_study_run_at(s, k);
        CHECK(r.setting_index == k);
        fw_scenario scn;
        fw_study_scenario(s, &r, &scn);
        double vis = fw_nm_to_m((k / 2) % 2 ? 0.5 : 10.0), alpha = k % 2 ? 0.3 : 0.1;
        CHECK(scn.sensing.mode == mode[k / 4]);
        CHECK_NEAR(scn.visibility, vis, 1e-9);
        CHECK(scn.helm.colregs.visibility == scn.visibility &&
              scn.reactions.colregs.visibility == scn.visibility);
        CHECK_NEAR(scn.sensing.radar.alpha, alpha, 1e-12);
        CHECK_NEAR(scn.sensing.radar.beta, alpha * alpha / (2.0 - alpha), 1e-12);
    }
    char label[160];
    CHECK(strcmp(fw_study_setting_label(s, 11, label, sizeof label),
                 "sensing.mode=ais+radar, environment.visibility_nm=0.5, sensing.alpha=0.3") == 0);
    free(s);
}

/* Two scenario keys as axes: four settings, outermost in the run list (after
 * the replications), each sailing its own values over the base scenario and
 * the same seeds and starts as the others (paired); the labels name them. */
static void test_run_list_axes(void)
{
    fw_study *s = load("tests/data/study/axes.yaml");
    CHECK(s->n_axes == 2 && s->n_settings == 4);
    CHECK(fw_study_run_count(s) == 16 && fw_study_cell_count(s) == 8);
    static const double speed[] = {12, 12, 16, 16}, act[] = {4, 6, 4, 6};
    for (int id = 0; id < 16; id++) {
        fw_study_run r = fw_study_run_at(s, id), r0 = fw_study_run_at(s, id % 4);
        CHECK(r.setting_index == id / 4);
        CHECK(r.replication == (id / 2) % 2);
        CHECK(r.seed == r0.seed && r.d_along == r0.d_along && r.d_across == r0.d_across);
        fw_scenario scn;
        fw_study_scenario(s, &r, &scn);
        CHECK_NEAR(scn.speed, fw_kn_to_ms(speed[r.setting_index]), 1e-12);
        CHECK_NEAR(scn.policy.act_range, fw_nm_to_m(act[r.setting_index]), 1e-9);
        CHECK(scn.helm.domain.size == r.domain && scn.seed == r.seed);
        /* everything else is the base's */
        CHECK(scn.course == s->base.course && scn.density == s->base.density);
    }
    char label[128];
    CHECK(strcmp(fw_study_setting_label(s, 2, label, sizeof label),
                 "own_ship.speed_kn=16, avoidance.act_range_nm=4") == 0);
    /* cell 5 is setting 2's second domain */
    fw_study_run c = fw_study_cell(s, 5);
    CHECK(c.setting_index == 2 && c.domain == s->domains[1] && c.replication == 0);
    /* the axes are part of the study: another digest than without them */
    fw_study *t = load("tests/data/study/small.yaml");
    CHECK(t->n_axes == 0 && t->n_settings == 1 && t->digest != s->digest);
    CHECK(fw_study_setting_label(t, 0, label, sizeof label)[0] == '\0');
    free(t);
    free(s);
}

static fw_outcome sample(int run_id)
{
    fw_outcome o;
    fw_outcome_failed(&o, run_id, "x");
    snprintf(o.status, sizeof o.status, "ok");
    o.sim_s = 900;
    o.min_dist = 412.5;
    o.n_actions = 2;
    o.n_enc = 2;
    o.enc = calloc(2, sizeof *o.enc);
    for (int i = 0; i < 2; i++) {
        snprintf(o.enc[i].e.id, sizeof o.enc[i].e.id, "east.%d", i);
        o.enc[i].e.situation = FW_SIT_HEAD_ON;
        o.enc[i].e.min_dist = 400.0 + i;
        o.enc[i].e.acted = i == 0;
        o.enc[i].e.t_act = i ? NAN : 12.0;
    }
    o.n_traffic = 1;
    o.traffic = calloc(1, sizeof *o.traffic);
    snprintf(o.traffic[0].ship_a, sizeof o.traffic[0].ship_a, "a");
    snprintf(o.traffic[0].ship_b, sizeof o.traffic[0].ship_b, "b");
    snprintf(o.traffic[0].type, sizeof o.traffic[0].type, "crossing");
    o.traffic[0].dcpa0 = 250.0;
    return o;
}

static void test_outcome_bytes(void)
{
    fw_outcome o = sample(3), back;
    unsigned char *buf = NULL;
    size_t n = 0;
    fw_error err = {0};
    CHECK(fw_outcome_pack(&o, &buf, &n, &err) == FW_OK);
    CHECK(fw_outcome_unpack(buf, n, &back, &err) == FW_OK);
    CHECK(back.run_id == 3 && back.n_enc == 2 && back.n_traffic == 1);
    CHECK(strcmp(back.enc[1].e.id, "east.1") == 0 && isnan(back.enc[1].e.t_act));
    CHECK(back.enc[0].e.t_act == 12.0 && back.traffic[0].dcpa0 == 250.0);
    fw_outcome_free(&back);
    /* a short or padded message is refused, never read past its end */
    CHECK(fw_outcome_unpack(buf, n - 1, &back, &err) == FW_ERUN);
    CHECK(fw_outcome_unpack(buf, 10, &back, &err) == FW_ERUN);
    free(buf);
    fw_outcome_free(&o);
}

static int count(sqlite3 *db, const char *sql)
{
    sqlite3_stmt *q = NULL;
    int n = -1;
    if (sqlite3_prepare_v2(db, sql, -1, &q, NULL) == SQLITE_OK && sqlite3_step(q) == SQLITE_ROW)
        n = sqlite3_column_int(q, 0);
    sqlite3_finalize(q);
    return n;
}

/* A run goes in whole or not at all; twice is refused and changes nothing. */
static void test_store(void)
{
    char path[] = "/tmp/fw-test-store-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    unlink(path);
    fw_study *s = load("tests/data/study/small.yaml");
    fw_store *st = NULL;
    fw_error err = {0};
    CHECK_MSG(fw_store_open(path, s, &st, &err) == FW_OK, "%s", err.msg);
    fw_outcome o = sample(4), f;
    CHECK(fw_store_commit(st, s, &o, &err) == FW_OK);
    CHECK(fw_store_commit(st, s, &o, &err) == FW_ERUN); /* the same run again */
    fw_outcome_failed(&f, 5, "sumo: connection closed");
    CHECK(fw_store_commit(st, s, &f, &err) == FW_OK);
    bool done[10], any[10];
    CHECK(fw_store_finished(st, false, done, 10, &err) == FW_OK);
    CHECK(fw_store_finished(st, true, any, 10, &err) == FW_OK);
    CHECK(done[4] && !done[5] && any[5] && !any[0]);
    fw_store_close(st);
    sqlite3 *db = NULL;
    CHECK(sqlite3_open(path, &db) == SQLITE_OK);
    CHECK(count(db, "SELECT COUNT(*) FROM runs") == 2);
    CHECK(count(db, "SELECT COUNT(*) FROM encounters") == 2);
    CHECK(count(db, "SELECT COUNT(*) FROM traffic_encounters") == 1);
    /* common random numbers are visible in the database, NaN is NULL */
    CHECK(count(db, "SELECT replication FROM runs WHERE run_id = 4") == 2);
    CHECK(count(db, "SELECT COUNT(*) FROM encounters WHERE t_act_s IS NULL") == 1);
    CHECK(count(db, "SELECT COUNT(*) FROM runs WHERE status = 'failed' AND "
                    "reason LIKE 'sumo:%' AND n_encounters IS NULL") == 1);
    sqlite3_close(db);
    /* reopened by the same study: kept; --retry-failed forgets only failures */
    CHECK(fw_store_open(path, s, &st, &err) == FW_OK);
    CHECK(fw_store_forget_failed(st, &err) == FW_OK);
    CHECK(fw_store_finished(st, true, any, 10, &err) == FW_OK);
    CHECK(any[4] && !any[5]);
    fw_store_close(st);
    /* another study may not add to it */
    s->digest ^= 1;
    CHECK(fw_store_open(path, s, &st, &err) == FW_EINPUT);
    CHECK(strstr(err.msg, "another study") != NULL);
    fw_outcome_free(&o);
    free(s);
    char wal[64];
    unlink(path);
    snprintf(wal, sizeof wal, "%s-wal", path);
    unlink(wal);
    snprintf(wal, sizeof wal, "%s-shm", path);
    unlink(wal);
}

/* An encounter with a value in every field (an action to starboard, helm
 * signed -20 deg... as the book keeps it, the hulls never within 1 nm). */
static fw_encounter full_encounter(void)
{
    fw_encounter e = {.length = 182.5, .breadth = 32.25, .situation = FW_SIT_GIVE_WAY,
                      .t_detect = 31.5, .dcpa0 = 123.44, .tcpa0 = 456.7, .threat = true,
                      .acted = true, .t_act = 40.0, .act_side = FW_SIDE_STARBOARD,
                      .act_helm = -0.3490658503988659, .primary = true, .min_dist = 812.3,
                      .t_min = 600.0, .min_lambda = 0.8734, .domain_entered = true,
                      .colregs_ok = true, .min_hull = INFINITY, .cand_miss = 0.0};
    snprintf(e.id, sizeof e.id, "ais.366123");
    snprintf(e.type, sizeof e.type, "tanker");
    e.audit = (fw_audit_result){.rule = 15, .role = FW_ROLE_GIVE_WAY, .risk = true,
                                .t_risk = 10.0, .tcpa_risk = 300.0, .acted = true,
                                .tcpa_act = 250.0, .course_change = 0.5, .speed_change = 0.125,
                                .early = true, .phase = 0, .compliant = -1};
    snprintf(e.audit.note, sizeof e.audit.note, "not substantial");
    return e;
}

/* Near misses are hull to hull (issue 25): for the 333 m own ship a pass
 * 10 m between the hulls has its centres 200 m apart, which the old
 * centre-to-centre reading called no near miss; a 175 m hull-to-hull pass is
 * one too; the centre reading is kept as the secondary flag.  Closeness is
 * 1 at contact, 1 - d / 1852 within a mile, 0 beyond. */
static void test_near_miss_hull(void)
{
    fw_study *s = load("tests/data/study/small.yaml");
    CHECK(s->near_miss == 185.2);
    fw_encounter e[3] = {full_encounter(), full_encounter(), full_encounter()};
    e[0].min_dist = 200.0, e[0].min_hull = 10.0, e[0].domain_entered = false;
    e[1].min_dist = 350.0, e[1].min_hull = 175.0, e[1].domain_entered = false;
    e[2].min_dist = 900.0, e[2].min_hull = INFINITY, e[2].domain_entered = false;
    fw_run_summary sum = {.t_end = 3600.0, .min_dist = 200.0, .min_hull = 10.0};
    fw_outcome o;
    fw_error err = {0};
    CHECK(fw_outcome_from_run(&o, s, 1, &sum, e, 3, NULL, 0, &err) == FW_OK);
    CHECK(o.near_miss == 1 && o.near_miss_centre == 0);
    CHECK_NEAR(o.closeness, 1.0 - 10.0 / 1852.0, 1e-12);
    CHECK(o.n_enc == 3);
    CHECK(o.enc[0].v.near_miss == 1 && o.enc[0].v.near_miss_centre == 0);
    CHECK(strcmp(o.enc[0].v.outcome, "near miss") == 0);
    CHECK(o.enc[1].v.near_miss == 1 && strcmp(o.enc[1].v.outcome, "near miss") == 0);
    CHECK(o.enc[2].v.near_miss == 0 && o.enc[2].v.closeness == 0.0);
    CHECK(strcmp(o.enc[2].v.outcome, "passed") == 0);
    fw_outcome_free(&o);
    CHECK(fw_closeness(0.0) == 1.0);
    CHECK(fw_closeness(1852.0) == 0.0 && fw_closeness(NAN) == 0.0);
    CHECK_NEAR(fw_closeness(926.0), 0.5, 1e-15);
    free(s);
}

/* The CSV row's cell under `name` in the header. */
static const char *cell(char *const *head, char *const *row, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(head[i], name) == 0)
            return row[i];
    return "(none)";
}

static int split(char *line, char **out, int max)
{
    int n = 0;
    for (char *p = strtok(line, ",\n"); p && n < max; p = strtok(NULL, ",\n"))
        out[n++] = p;
    return n;
}

/* One encounter record (run/encounter_record.h): encounters.csv's columns and
 * summary.json's keys are the table's, and a row of the database read back
 * column by column is the record (a non-finite number NULL). */
static void test_encounter_record(void)
{
    fw_encounter e = full_encounter();
    char *buf = NULL, *head[64], *row[64];
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fw_enc_csv_header(f);
    fw_enc_csv_row(f, &e);
    fclose(f);
    char *nl = strchr(buf, '\n');
    *nl = '\0';
    int nh = split(buf, head, 64), nr = split(nl + 1, row, 64), nf;
    const fw_enc_field *fl = fw_enc_fields(&nf);
    int ncsv = 0;
    for (int i = 0; i < nf; i++)
        if (fl[i].flags & FW_ENC_CSV)
            CHECK(fw_enc_csv_column(fl[i].name) == ncsv++);
    CHECK(nh == 20 && nr == nh && ncsv == nh && strcmp(head[0], "id") == 0);
    CHECK(strcmp(cell(head, row, nh, "act_helm_deg"), "20.0") == 0);   /* unsigned in files */
    CHECK(strcmp(cell(head, row, nh, "min_hull_m"), "null") == 0);
    CHECK(strcmp(cell(head, row, nh, "min_domain_ratio"), "0.873") == 0);
    CHECK(strcmp(cell(head, row, nh, "situation"), "crossing give-way") == 0);
    CHECK(strcmp(cell(head, row, nh, "threat"), "1") == 0);
    CHECK(strcmp(cell(head, row, nh, "length_m"), "182.5") == 0);
    free(buf);
    f = open_memstream(&buf, &len);
    fw_enc_json(f, &e);
    fclose(f);
    CHECK(strncmp(buf, "{\"id\": \"ais.366123\", \"type\": \"tanker\", \"situation\": ", 52) == 0);
    CHECK(strstr(buf, "\"threat\": true, \"t_act_s\": 40.0, \"act_side\": \"starboard\", "
                      "\"act_helm_deg\": 20.0, \"primary\": true") != NULL);
    CHECK(strstr(buf, "\"min_hull_m\": null}") != NULL && !strstr(buf, "length_m"));
    free(buf);

    char path[] = "/tmp/fw-test-record-XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    unlink(path);
    fw_study *s = load("tests/data/study/small.yaml");
    fw_store *st = NULL;
    fw_error err = {0};
    CHECK_MSG(fw_store_open(path, s, &st, &err) == FW_OK, "%s", err.msg);
    fw_outcome o = sample(6);
    o.enc[0] = (fw_outcome_encounter){
        .e = e, .v = {.near_miss = 0, .near_miss_centre = 1, .closeness = 0.25, .outcome = "domain"}};
    CHECK_MSG(fw_store_commit(st, s, &o, &err) == FW_OK, "%s", err.msg);
    fw_store_close(st);
    sqlite3 *db = NULL;
    CHECK(sqlite3_open(path, &db) == SQLITE_OK);
    int checked = 0;
    for (int i = 0; i < nf; i++) {
        if (!(fl[i].flags & FW_ENC_SQL))
            continue;
        char sql[200];
        snprintf(sql, sizeof sql, "SELECT %s FROM encounters WHERE run_id = 6 AND target = "
                                  "'ais.366123'", fl[i].sql);
        sqlite3_stmt *q = NULL;
        if (sqlite3_prepare_v2(db, sql, -1, &q, NULL) != SQLITE_OK || sqlite3_step(q) != SQLITE_ROW) {
            CHECK_MSG(false, "%s: %s", sql, sqlite3_errmsg(db));
            sqlite3_finalize(q);
            continue;
        }
        fw_enc_value v = {0};
        fl[i].get(&o.enc[0].e, &o.enc[0].v, true, &v);
        int type = sqlite3_column_type(q, 0);
        if (v.null || (fl[i].type == FW_ENC_REAL && !isfinite(v.num)))
            CHECK_MSG(type == SQLITE_NULL, "%s not NULL", fl[i].sql);
        else if (fl[i].type == FW_ENC_TEXT)
            CHECK_MSG(type == SQLITE_TEXT &&
                          strcmp((const char *)sqlite3_column_text(q, 0), v.text) == 0,
                      "%s: '%s' against '%s'", fl[i].sql, sqlite3_column_text(q, 0), v.text);
        else if (fl[i].type == FW_ENC_REAL)
            CHECK_MSG(type == SQLITE_FLOAT && sqlite3_column_double(q, 0) == v.num, "%s", fl[i].sql);
        else
            CHECK_MSG(type == SQLITE_INTEGER && sqlite3_column_int(q, 0) == (int)v.num, "%s",
                      fl[i].sql);
        checked++;
        sqlite3_finalize(q);
    }
    CHECK(checked == 36);
    /* the database's helm is signed, the audit's course change in degrees */
    CHECK(count(db, "SELECT COUNT(*) FROM encounters WHERE act_helm_deg < -19.99 AND "
                    "act_helm_deg > -20.01 AND compliant IS NULL AND candidate = 1 AND "
                    "min_hull_m IS NULL AND outcome = 'domain'") == 1);
    sqlite3_close(db);
    fw_outcome_free(&o);
    free(s);
    char wal[64];
    unlink(path);
    snprintf(wal, sizeof wal, "%s-wal", path);
    unlink(wal);
    snprintf(wal, sizeof wal, "%s-shm", path);
    unlink(wal);
}

int main(void)
{
    TEST_RUN(test_run_list);
    TEST_RUN(test_run_list_behaviours);
    TEST_RUN(test_run_list_shapes);
    TEST_RUN(test_run_list_axes);
    TEST_RUN(test_run_list_axes_fog);
    TEST_RUN(test_outcome_bytes);
    TEST_RUN(test_store);
    TEST_RUN(test_encounter_record);
    TEST_RUN(test_near_miss_hull);
    return TEST_EXIT();
}
