/* store.c - the study database (see store.h). */
#include <inttypes.h>
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "study/schema.h"
#include "study/store.h"

struct fw_store {
    sqlite3 *db;
    char path[1024];
    sqlite3_stmt *run, *enc, *trf;
};

static fw_status db_fail(fw_store *st, fw_error *err, const char *what)
{
    return fw_fail(err, FW_ERUN, "%s: %s: %s", st->path, what, sqlite3_errmsg(st->db));
}

static fw_status exec(fw_store *st, const char *sql, fw_error *err)
{
    char *msg = NULL;
    if (sqlite3_exec(st->db, sql, NULL, NULL, &msg) != SQLITE_OK) {
        fw_status s = fw_fail(err, FW_ERUN, "%s: %s", st->path, msg ? msg : "error");
        sqlite3_free(msg);
        return s;
    }
    return FW_OK;
}

/* meta value of key into out ("" when absent). */
static fw_status meta_get(fw_store *st, const char *key, char *out, size_t outsz, fw_error *err)
{
    sqlite3_stmt *q = NULL;
    out[0] = '\0';
    if (sqlite3_prepare_v2(st->db, "SELECT value FROM meta WHERE key = ?", -1, &q, NULL))
        return db_fail(st, err, "reading meta");
    sqlite3_bind_text(q, 1, key, -1, SQLITE_STATIC);
    int rc = sqlite3_step(q);
    if (rc == SQLITE_ROW)
        snprintf(out, outsz, "%s", (const char *)sqlite3_column_text(q, 0));
    sqlite3_finalize(q);
    return rc == SQLITE_ROW || rc == SQLITE_DONE ? FW_OK : db_fail(st, err, "reading meta");
}

static fw_status meta_put(fw_store *st, const char *key, const char *value, fw_error *err)
{
    sqlite3_stmt *q = NULL;
    if (sqlite3_prepare_v2(st->db, "INSERT OR REPLACE INTO meta(key, value) VALUES(?, ?)", -1,
                           &q, NULL))
        return db_fail(st, err, "writing meta");
    sqlite3_bind_text(q, 1, key, -1, SQLITE_STATIC);
    sqlite3_bind_text(q, 2, value, -1, SQLITE_STATIC);
    int rc = sqlite3_step(q);
    sqlite3_finalize(q);
    return rc == SQLITE_DONE ? FW_OK : db_fail(st, err, "writing meta");
}

static fw_status write_meta(fw_store *st, const fw_study *s, const char *digest, fw_error *err)
{
    char num[64];
    fw_status r;
    const char *levels[2] = {"domains_m", "densities"};
    for (int k = 0; k < 2; k++) {
        char text[1024] = "";
        int n = k ? s->n_densities : s->n_domains;
        const double *v = k ? s->densities : s->domains;
        size_t len = 0;
        for (int i = 0; i < n && len < sizeof text - 32; i++)
            len += (size_t)snprintf(text + len, sizeof text - len, "%s%.6g", i ? "," : "", v[i]);
        if ((r = meta_put(st, levels[k], text, err)))
            return r;
    }
#define PUTNUM(key, fmt, val)                                                                \
    do {                                                                                   \
        snprintf(num, sizeof num, fmt, val);                                               \
        if ((r = meta_put(st, key, num, err)))                                             \
            return r;                                                                      \
    } while (0)
    if ((r = meta_put(st, "schema_version", FW_SCHEMA_VERSION, err)) ||
        (r = meta_put(st, "study_name", s->name, err)) ||
        (r = meta_put(st, "study_description", s->description, err)) ||
        (r = meta_put(st, "study_file", s->file, err)) ||
        (r = meta_put(st, "study_digest", digest, err)) ||
        (r = meta_put(st, "scenario", s->scenario_file, err)) ||
        (r = meta_put(st, "ship", s->base.ship.name, err)) ||
        (r = meta_put(st, "network", s->base.network, err)))
        return r;
    PUTNUM("replications", "%d", s->replications);
    PUTNUM("seed", "%lu", s->seed);
    PUTNUM("duration_s", "%.3f", s->duration);
    PUTNUM("step_s", "%.3f", s->base.step);
    PUTNUM("speed_kn", "%.3f", fw_ms_to_kn(s->base.speed));
    PUTNUM("encounter_m", "%.3f", s->encounter_range);
    PUTNUM("near_miss_m", "%.3f", s->near_miss);
    PUTNUM("runs", "%d", fw_study_run_count(s));
    PUTNUM("survey", "%d", s->base.survey ? 1 : 0);
    if (s->base.survey) {
        PUTNUM("survey_radius_m", "%.1f", s->base.survey_radius);
        PUTNUM("survey_range_m", "%.1f", s->base.survey_def.range);
        PUTNUM("survey_dcpa_m", "%.1f", s->base.survey_def.dcpa);
        PUTNUM("survey_tcpa_s", "%.1f", s->base.survey_def.tcpa);
    }
#undef PUTNUM
    return FW_OK;
}

static const char kRunSql[] =
    "INSERT INTO runs(run_id, domain_m, density, replication, seed, status, reason, sim_s, "
    "wall_s, sumo_s, n_encounters, n_actions, min_dist_m, domain_entered, near_miss, collision, "
    "colregs_ok, max_helm_deg, path_length_m, path_lengthening_m, time_lost_s, "
    "rudder_work_deg_s, helm_orders, traffic_ship_s) VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,"
    "?,?,?,?,?,?)";
static const char kEncSql[] =
    "INSERT INTO encounters(run_id, target, target_type, situation, t_detect_s, dcpa0_m, "
    "tcpa0_s, threat, acted, t_act_s, act_side, act_helm_deg, min_dist_m, t_min_s, min_lambda, "
    "domain_entered, near_miss, collision, colregs_ok) VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,"
    "?,?)";
static const char kTrfSql[] =
    "INSERT INTO traffic_encounters(run_id, ship_a, ship_b, type, own, t_first_s, range0_m, "
    "dcpa0_m, tcpa0_s, min_dist_m, t_min_s) VALUES(?,?,?,?,?,?,?,?,?,?,?)";

fw_status fw_store_open(const char *path, const fw_study *s, fw_store **out, fw_error *err)
{
    *out = NULL;
    fw_store *st = calloc(1, sizeof *st);
    if (!st)
        return fw_fail(err, FW_ERUN, "out of memory");
    snprintf(st->path, sizeof st->path, "%s", path);
    fw_status r = FW_OK;
    if (sqlite3_open_v2(path, &st->db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, NULL)) {
        r = fw_fail(err, FW_EINPUT, "%s: cannot open the database: %s", path,
                    st->db ? sqlite3_errmsg(st->db) : "out of memory");
        goto fail;
    }
    sqlite3_busy_timeout(st->db, 10000);
    /* WAL: a commit is one append, a killed writer leaves the file intact;
     * NORMAL sync is durable against the process dying (not the machine) */
    char *msg = NULL;
    if (sqlite3_exec(st->db, "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;", NULL, NULL,
                     &msg) != SQLITE_OK) {
        r = fw_fail(err, FW_EINPUT, "%s: not a usable SQLite database: %s", path,
                    msg ? msg : "error");
        sqlite3_free(msg);
        goto fail;
    }
    if ((r = exec(st, "BEGIN IMMEDIATE", err)))
        goto fail;
    if ((r = exec(st, FW_SCHEMA_SQL, err))) {
        r = FW_EINPUT;
        if (err)
            err->status = FW_EINPUT;
        exec(st, "ROLLBACK", NULL);
        goto fail;
    }
    char version[64], old[64], digest[32];
    snprintf(digest, sizeof digest, "%016" PRIx64, s->digest);
    if ((r = meta_get(st, "schema_version", version, sizeof version, err)) ||
        (r = meta_get(st, "study_digest", old, sizeof old, err))) {
        exec(st, "ROLLBACK", NULL);
        goto fail;
    }
    if (version[0] && strcmp(version, FW_SCHEMA_VERSION) != 0) {
        exec(st, "ROLLBACK", NULL);
        r = fw_fail(err, FW_EINPUT, "%s: database schema version %s, this fairway writes %s",
                    path, version, FW_SCHEMA_VERSION);
        goto fail;
    }
    if (old[0] && strcmp(old, digest) != 0) {
        exec(st, "ROLLBACK", NULL);
        r = fw_fail(err, FW_EINPUT,
                    "%s holds results of another study (or %s, its scenario or ship file "
                    "changed since): resume only with the same files, or give a new --db",
                    path, s->file);
        goto fail;
    }
    if ((r = write_meta(st, s, digest, err)) || (r = exec(st, "COMMIT", err))) {
        exec(st, "ROLLBACK", NULL);
        goto fail;
    }
    if (sqlite3_prepare_v2(st->db, kRunSql, -1, &st->run, NULL) ||
        sqlite3_prepare_v2(st->db, kEncSql, -1, &st->enc, NULL) ||
        sqlite3_prepare_v2(st->db, kTrfSql, -1, &st->trf, NULL)) {
        r = db_fail(st, err, "preparing statements");
        goto fail;
    }
    *out = st;
    return FW_OK;
fail:
    fw_store_close(st);
    return r;
}

void fw_store_close(fw_store *st)
{
    if (!st)
        return;
    sqlite3_finalize(st->run);
    sqlite3_finalize(st->enc);
    sqlite3_finalize(st->trf);
    sqlite3_close(st->db);
    free(st);
}

fw_status fw_store_finished(fw_store *st, bool count_failed, bool *done, int n, fw_error *err)
{
    memset(done, 0, sizeof *done * (size_t)n);
    sqlite3_stmt *q = NULL;
    const char *sql = count_failed ? "SELECT run_id FROM runs"
                                   : "SELECT run_id FROM runs WHERE status = 'ok'";
    if (sqlite3_prepare_v2(st->db, sql, -1, &q, NULL))
        return db_fail(st, err, "reading runs");
    int rc;
    while ((rc = sqlite3_step(q)) == SQLITE_ROW) {
        sqlite3_int64 id = sqlite3_column_int64(q, 0);
        if (id >= 0 && id < n)
            done[id] = true;
    }
    sqlite3_finalize(q);
    return rc == SQLITE_DONE ? FW_OK : db_fail(st, err, "reading runs");
}

fw_status fw_store_forget_failed(fw_store *st, fw_error *err)
{
    return exec(st, "DELETE FROM runs WHERE status = 'failed'", err);
}

/* NaN and infinity are not numbers a reader can use: they go in as NULL. */
static void bind_num(sqlite3_stmt *q, int i, double v)
{
    if (isfinite(v))
        sqlite3_bind_double(q, i, v);
    else
        sqlite3_bind_null(q, i);
}

static int run_row(sqlite3_stmt *q, const fw_study *s, const fw_outcome *o)
{
    fw_study_run r = fw_study_run_at(s, o->run_id);
    bool ok = strcmp(o->status, "ok") == 0;
    int i = 1;
    sqlite3_reset(q);
    sqlite3_clear_bindings(q);
    sqlite3_bind_int(q, i++, o->run_id);
    sqlite3_bind_double(q, i++, r.domain);
    sqlite3_bind_double(q, i++, r.density);
    sqlite3_bind_int(q, i++, r.replication);
    sqlite3_bind_int64(q, i++, (sqlite3_int64)r.seed);
    sqlite3_bind_text(q, i++, ok ? "ok" : "failed", -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, ok ? "" : o->reason, -1, SQLITE_STATIC);
    bind_num(q, i++, o->sim_s);
    bind_num(q, i++, o->wall_s);
    bind_num(q, i++, o->sumo_s);
    if (!ok) /* a failed run's partial aggregates would only mislead */
        return sqlite3_step(q);
    sqlite3_bind_int(q, i++, o->n_enc);
    sqlite3_bind_int(q, i++, o->n_actions);
    bind_num(q, i++, o->min_dist);
    sqlite3_bind_int(q, i++, o->domain_entered);
    sqlite3_bind_int(q, i++, o->near_miss);
    sqlite3_bind_int(q, i++, o->collision);
    sqlite3_bind_int(q, i++, o->colregs_ok);
    bind_num(q, i++, o->max_helm_deg);
    bind_num(q, i++, o->path_length);
    bind_num(q, i++, o->path_lengthening);
    bind_num(q, i++, o->time_lost);
    bind_num(q, i++, o->rudder_work_deg_s);
    sqlite3_bind_int(q, i++, o->helm_orders);
    bind_num(q, i++, o->traffic_ship_s);
    return sqlite3_step(q);
}

static int enc_row(sqlite3_stmt *q, int run_id, const fw_outcome_encounter *e)
{
    int i = 1;
    sqlite3_reset(q);
    sqlite3_clear_bindings(q);
    sqlite3_bind_int(q, i++, run_id);
    sqlite3_bind_text(q, i++, e->target, -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, e->target_type, -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, e->situation, -1, SQLITE_STATIC);
    bind_num(q, i++, e->t_detect);
    bind_num(q, i++, e->dcpa0);
    bind_num(q, i++, e->tcpa0);
    sqlite3_bind_int(q, i++, e->threat);
    sqlite3_bind_int(q, i++, e->acted);
    bind_num(q, i++, e->t_act);
    sqlite3_bind_text(q, i++, e->act_side, -1, SQLITE_STATIC);
    bind_num(q, i++, e->act_helm_deg);
    bind_num(q, i++, e->min_dist);
    bind_num(q, i++, e->t_min);
    bind_num(q, i++, e->min_lambda);
    sqlite3_bind_int(q, i++, e->domain_entered);
    sqlite3_bind_int(q, i++, e->near_miss);
    sqlite3_bind_int(q, i++, e->collision);
    sqlite3_bind_int(q, i++, e->colregs_ok);
    return sqlite3_step(q);
}

static int trf_row(sqlite3_stmt *q, int run_id, const fw_outcome_traffic *t)
{
    int i = 1;
    sqlite3_reset(q);
    sqlite3_clear_bindings(q);
    sqlite3_bind_int(q, i++, run_id);
    sqlite3_bind_text(q, i++, t->ship_a, -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, t->ship_b, -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, t->type, -1, SQLITE_STATIC);
    sqlite3_bind_int(q, i++, t->own);
    bind_num(q, i++, t->t_first);
    bind_num(q, i++, t->range0);
    bind_num(q, i++, t->dcpa0);
    bind_num(q, i++, t->tcpa0);
    bind_num(q, i++, t->min_dist);
    bind_num(q, i++, t->t_min);
    return sqlite3_step(q);
}

fw_status fw_store_commit(fw_store *st, const fw_study *s, const fw_outcome *o, fw_error *err)
{
    fw_status r = exec(st, "BEGIN IMMEDIATE", err);
    if (r)
        return r;
    bool ok = strcmp(o->status, "ok") == 0;
    if (run_row(st->run, s, o) != SQLITE_DONE) {
        r = db_fail(st, err, "writing a run");
        goto rollback;
    }
    for (int i = 0; ok && i < o->n_enc; i++)
        if (enc_row(st->enc, o->run_id, &o->enc[i]) != SQLITE_DONE) {
            r = db_fail(st, err, "writing an encounter");
            goto rollback;
        }
    for (int i = 0; ok && i < o->n_traffic; i++)
        if (trf_row(st->trf, o->run_id, &o->traffic[i]) != SQLITE_DONE) {
            r = db_fail(st, err, "writing a traffic encounter");
            goto rollback;
        }
    if ((r = exec(st, "COMMIT", err)))
        goto rollback;
    return FW_OK;
rollback:
    sqlite3_reset(st->run);
    sqlite3_reset(st->enc);
    sqlite3_reset(st->trf);
    exec(st, "ROLLBACK", NULL);
    return r;
}
