/* test_study.c - study files, the run list (common random numbers), run
 * outcomes as bytes, and the database's one-transaction commits. */
#include <math.h>
#include <sqlite3.h>
#include <stdlib.h>
#include <unistd.h>

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

int main(void)
{
    TEST_RUN(test_run_list);
    TEST_RUN(test_run_list_behaviours);
    TEST_RUN(test_run_list_shapes);
    TEST_RUN(test_outcome_bytes);
    TEST_RUN(test_store);
    return TEST_EXIT();
}
