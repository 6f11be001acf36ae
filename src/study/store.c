/* store.c - the study database (see store.h). */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <libgen.h>
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files.h"
#include "core/units.h"
#include "run/encounter_record.h"
#include "study/schema.h"
#include "study/store.h"

struct fw_store {
    sqlite3 *db;
    char path[1024];
    sqlite3_stmt *run, *enc, *trf;
    int lock_fd;  /* flock'ed for as long as the store is open: one writer */
    bool created; /* this open made the file: removed again when refused */
};

/* The lock of the store this process has open, closed in forked children so
 * a run's process never holds it (see fw_store_child). */
static int g_lock_fd = -1;

sqlite3 *fw_store_sqlite(fw_store *st) { return st->db; }
const char *fw_store_path(const fw_store *st) { return st->path; }

/* Is the disk that holds the database full (SQLite's "database or disk is
 * full", or "disk I/O error" from a write that found no space)? */
static bool disk_full(fw_store *st)
{
    int e = sqlite3_system_errno(st->db);
    return sqlite3_errcode(st->db) == SQLITE_FULL || e == ENOSPC || e == EDQUOT;
}

/* What a failure on a full disk adds to SQLite's words. */
static const char *full_note(fw_store *st)
{
    return disk_full(st) ? " (the disk holding the database is full: free space, then run the "
                           "same command again to resume)"
                         : "";
}

static fw_status db_fail(fw_store *st, fw_error *err, const char *what)
{
    return fw_fail(err, FW_ERUN, "%s: %s: %s%s", st->path, what, sqlite3_errmsg(st->db),
                   full_note(st));
}

static fw_status exec(fw_store *st, const char *sql, fw_error *err)
{
    char *msg = NULL;
    if (sqlite3_exec(st->db, sql, NULL, NULL, &msg) != SQLITE_OK) {
        fw_status s = fw_fail(err, FW_ERUN, "%s: %s%s", st->path, msg ? msg : "error",
                              full_note(st));
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
    char beh[64] = "";
    for (int i = 0; i < s->n_behaviours; i++)
        snprintf(beh + strlen(beh), sizeof beh - strlen(beh), "%s%s", i ? "," : "",
                 fw_behaviour_name(s->behaviours[i]));
    if ((r = meta_put(st, "behaviours", beh, err)))
        return r;
    if (s->n_axes) { /* "key: v1, v2; key: ..." (values have no ',' or ';': study_axes.c) */
        char axes[1024] = "";
        size_t len = 0;
        for (int i = 0; i < s->n_axes && len < sizeof axes; i++) {
            len += (size_t)snprintf(axes + len, sizeof axes - len, "%s%s: ", i ? "; " : "",
                                    s->axes[i].key);
            for (int j = 0; j < s->axes[i].n && len < sizeof axes; j++)
                len += (size_t)snprintf(axes + len, sizeof axes - len, "%s%s", j ? ", " : "",
                                        s->axes[i].values[j]);
        }
        if ((r = meta_put(st, "axes", axes, err)))
            return r;
    }
    const char *levels[4] = {"domains_m", "densities", "fore_aft_ratios", "domains_l"};
    const double *values[4] = {s->domains, s->densities, s->ratios, s->domain_lengths};
    const int counts[4] = {s->n_domains, s->n_densities, s->n_ratios,
                           s->domains_in_lengths ? s->n_domains : 0};
    for (int k = 0; k < 4; k++) {
        char text[1024] = "";
        int n = counts[k];
        const double *v = values[k];
        if (k == 3 && n == 0)
            continue;
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
    const fw_audit_def *au = &s->base.audit;
    PUTNUM("audit_risk_dcpa_m", "%.1f", au->risk_dcpa);
    PUTNUM("audit_risk_tcpa_s", "%.1f", au->risk_tcpa);
    PUTNUM("audit_course_change_deg", "%.1f", fw_rad_to_deg(au->course_change));
    PUTNUM("audit_speed_change", "%.3f", au->speed_change);
    PUTNUM("audit_early_tcpa_s", "%.1f", au->early_tcpa);
    PUTNUM("audit_prompt_s", "%.1f", au->prompt);
    PUTNUM("audit_rule17_may_tcpa_s", "%.1f", au->may_tcpa);
    PUTNUM("audit_rule17_must_tcpa_s", "%.1f", au->must_tcpa);
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

/* One input's row in meta: key "input:ROLE", value "DIGEST PATH". */
static void input_row(const fw_study_input *in, char *key, size_t keysz, char *val,
                      size_t valsz)
{
    snprintf(key, keysz, "input:%s", in->role);
    snprintf(val, valsz, "%016" PRIx64 " %s", in->digest, in->path);
}

/* Each input's digest and path, "input:ROLE" in meta.  On resume a changed
 * file is named; a database from before these rows gets them now.  When the
 * study's settings differ (same_digest false) the study file differs too, so
 * it is another study unless its scenario or ship changed. */
static fw_status check_inputs(fw_store *st, const fw_study *s, bool same_digest, fw_error *err)
{
    for (int i = 0; i < s->n_inputs; i++) {
        const fw_study_input *in = &s->inputs[i];
        if (!same_digest && strcmp(in->role, "study") == 0)
            continue;
        char key[64], old[1200], now[1200];
        input_row(in, key, sizeof key, now, sizeof now);
        fw_status r = meta_get(st, key, old, sizeof old, err);
        if (r)
            return r;
        if (old[0] && strncmp(old, now, 16) != 0)
            return fw_fail(err, FW_EINPUT,
                           "%s: %s (the %s) changed since this database's sweep began: its runs "
                           "would mix two inputs; restore the file, or give a new --db",
                           st->path, in->path, in->role);
    }
    if (!same_digest)
        return fw_fail(err, FW_EINPUT,
                       "%s holds results of another study (or %s, its scenario or ship file "
                       "changed since): resume only with the same files, or give a new --db",
                       st->path, s->file);
    for (int i = 0; i < s->n_inputs; i++) {
        char key[64], now[1200];
        input_row(&s->inputs[i], key, sizeof key, now, sizeof now);
        fw_status r = meta_put(st, key, now, err);
        if (r)
            return r;
    }
    return FW_OK;
}

/* Before SQLite touches path: a directory, a missing parent or one we may
 * not write in get a plain message, and the file is locked against a second
 * sweep (refused at once, not after a busy wait or a UNIQUE failure). */
static fw_status lock_path(fw_store *st, const char *path, fw_error *err)
{
    struct stat sb;
    bool exists = stat(path, &sb) == 0;
    if (exists && S_ISDIR(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "--db %s: is a directory, expected a database file", path);
    fw_status r;
    if (!exists && (r = fw_check_parent_dir("--db", path, "cannot create it in", err)))
        return r;
    st->lock_fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (st->lock_fd < 0)
        return fw_fail(err, FW_EINPUT, "--db %s: cannot open it for writing: %s", path,
                       strerror(errno));
    st->created = !exists;
    if (flock(st->lock_fd, LOCK_EX | LOCK_NB) != 0) {
        st->created = false; /* the other sweep's file now */
        return fw_fail(err, FW_EINPUT,
                       "--db %s: another fairway sweep is writing this database; let it finish "
                       "(or stop it), then run the same command again to resume",
                       path);
    }
    g_lock_fd = st->lock_fd;
    return FW_OK;
}

void fw_store_child(void)
{
    if (g_lock_fd >= 0)
        close(g_lock_fd);
    g_lock_fd = -1;
}

static const char kRunSql[] =
    "INSERT INTO runs(run_id, domain_m, fore_aft_ratio, density, replication, seed, behaviour, "
    "status, reason, "
    "sim_s, wall_s, sumo_s, n_encounters, n_actions, min_dist_m, domain_entered, near_miss, "
    "near_miss_centre, collision, colregs_ok, max_helm_deg, path_length_m, path_lengthening_m, time_lost_s, "
    "rudder_work_deg_s, helm_orders, traffic_ship_s, give_way, give_way_short, "
    "mon_sideways, mon_teleport, mon_overlap, mon_appear, mon_vanish, mon_start_close, "
    "mon_stopped, max_lateral_mps, min_hull_m, closeness, setting) VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,"
    "?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)";
enum { kRunSettingParam = 40 }; /* setting, last: bound for failed runs too */
/* INSERT INTO encounters(run_id, ...): the columns of the encounter record's
 * table (run/encounter_record.h), in its order. */
static fw_status enc_sql(char *sql, size_t n, fw_error *err)
{
    int nf;
    const fw_enc_field *fl = fw_enc_fields(&nf);
    size_t k = (size_t)snprintf(sql, n, "INSERT INTO encounters(run_id");
    int cols = 1;
    for (int i = 0; i < nf && k < n; i++)
        if (fl[i].flags & FW_ENC_SQL) {
            k += (size_t)snprintf(sql + k, n - k, ", %s", fl[i].sql);
            cols++;
        }
    for (int i = 0; i < cols && k < n; i++)
        k += (size_t)snprintf(sql + k, n - k, "%s", i ? ",?" : ") VALUES(?");
    if (k + 1 >= n)
        return fw_fail(err, FW_ERUN, "the encounters' INSERT is longer than %zu bytes", n);
    snprintf(sql + k, n - k, ")");
    return FW_OK;
}

static const char kTrfSql[] =
    "INSERT INTO traffic_encounters(run_id, ship_a, ship_b, type, own, t_first_s, range0_m, "
    "dcpa0_m, tcpa0_s, min_dist_m, t_min_s, min_hull_m, candidate, cand_miss_m, outcome) "
    "VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)";

/* Schema, version and inputs checked and meta written, in one transaction. */
static fw_status setup(fw_store *st, const fw_study *s, fw_error *err)
{
    fw_status r;
    if ((r = exec(st, "BEGIN IMMEDIATE", err)))
        return r;
    char schema[8192];
    if (fw_schema_sql(schema, sizeof schema) >= (int)sizeof schema)
        r = fw_fail(err, FW_ERUN, "the schema is longer than %zu bytes", sizeof schema);
    else
        r = exec(st, schema, err);
    if (r && !disk_full(st)) { /* not a schema fairway can extend: another file */
        if (err)
            err->status = FW_EINPUT;
        r = FW_EINPUT;
    }
    if (r)
        goto rollback;
    char version[64], old[64], digest[32];
    snprintf(digest, sizeof digest, "%016" PRIx64, s->digest);
    if ((r = meta_get(st, "schema_version", version, sizeof version, err)) ||
        (r = meta_get(st, "study_digest", old, sizeof old, err)))
        goto rollback;
    if (version[0] && strcmp(version, FW_SCHEMA_VERSION) != 0) {
        r = fw_fail(err, FW_EINPUT, "%s: database schema version %s, this fairway writes %s",
                    st->path, version, FW_SCHEMA_VERSION);
        goto rollback;
    }
    if ((r = check_inputs(st, s, !old[0] || strcmp(old, digest) == 0, err)) ||
        (r = write_meta(st, s, digest, err)) || (r = exec(st, "COMMIT", err)))
        goto rollback;
    return FW_OK;
rollback:
    exec(st, "ROLLBACK", NULL);
    return r;
}

fw_status fw_store_open(const char *path, const fw_study *s, fw_store **out, fw_error *err)
{
    *out = NULL;
    fw_store *st = calloc(1, sizeof *st);
    if (!st)
        return fw_fail(err, FW_ERUN, "out of memory");
    st->lock_fd = -1;
    fw_status r = FW_OK;
    if ((size_t)snprintf(st->path, sizeof st->path, "%s", path) >= sizeof st->path) {
        r = fw_fail(err, FW_EINPUT, "--db %s: path longer than %zu characters", path,
                    sizeof st->path - 1);
        goto fail;
    }
    if ((r = lock_path(st, path, err)))
        goto fail;
    if (sqlite3_open_v2(path, &st->db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, NULL)) {
        r = fw_fail(err, FW_EINPUT, "%s: cannot open the database: %s", path,
                    st->db ? sqlite3_errmsg(st->db) : "out of memory");
        goto fail;
    }
    sqlite3_busy_timeout(st->db, 10000);
    /* WAL: a commit is one append, a killed writer leaves the file intact;
     * NORMAL sync is durable against the process dying (not the machine).
     * fw_store_close turns it back to a rollback journal for readers. */
    char *msg = NULL;
    if (sqlite3_exec(st->db, "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;", NULL, NULL,
                     &msg) != SQLITE_OK) {
        r = disk_full(st) ? fw_fail(err, FW_ERUN, "%s: cannot create the database: %s%s", path,
                                    msg ? msg : "error", full_note(st))
                          : fw_fail(err, FW_EINPUT, "%s: not a usable SQLite database: %s", path,
                                    msg ? msg : "error");
        sqlite3_free(msg);
        goto fail;
    }
    if ((r = setup(st, s, err)))
        goto fail;
    char enc[2048];
    if ((r = enc_sql(enc, sizeof enc, err)))
        goto fail;
    if (sqlite3_prepare_v2(st->db, kRunSql, -1, &st->run, NULL) ||
        sqlite3_prepare_v2(st->db, enc, -1, &st->enc, NULL) ||
        sqlite3_prepare_v2(st->db, kTrfSql, -1, &st->trf, NULL)) {
        r = db_fail(st, err, "preparing statements");
        goto fail;
    }
    *out = st;
    return FW_OK;
fail:
    if (st->created) {
        /* refused: leave no database behind that the user did not have */
        sqlite3_close(st->db);
        st->db = NULL;
        static const char *const ext[] = {"", "-wal", "-shm", "-journal"};
        for (int i = 0; i < 4; i++) {
            char f[1100];
            snprintf(f, sizeof f, "%s%s", st->path, ext[i]);
            unlink(f);
        }
    }
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
    /* back to a rollback journal: a reader (fairway report) then opens the
     * file read-only, even in a directory it cannot write, and leaves no
     * -wal or -shm beside it */
    if (st->db && st->run)
        sqlite3_exec(st->db, "PRAGMA wal_checkpoint(TRUNCATE); PRAGMA journal_mode=DELETE;",
                     NULL, NULL, NULL);
    sqlite3_close(st->db);
    if (st->lock_fd >= 0) {
        if (g_lock_fd == st->lock_fd)
            g_lock_fd = -1;
        close(st->lock_fd);
    }
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
    sqlite3_bind_double(q, i++, r.ratio);
    sqlite3_bind_double(q, i++, r.density);
    sqlite3_bind_int(q, i++, r.replication);
    sqlite3_bind_int64(q, i++, (sqlite3_int64)r.seed);
    /* the study's level, also for a failed run: the pair (domain, behaviour) is its key */
    sqlite3_bind_text(q, i++, fw_behaviour_name(r.behaviour), -1, SQLITE_STATIC);
    if (s->n_axes) { /* ... and the setting: NULL without axes */
        char label[256];
        fw_study_setting_label(s, r.setting_index, label, sizeof label);
        sqlite3_bind_text(q, kRunSettingParam, label, -1, SQLITE_TRANSIENT);
    }
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
    sqlite3_bind_int(q, i++, o->near_miss_centre);
    sqlite3_bind_int(q, i++, o->collision);
    sqlite3_bind_int(q, i++, o->colregs_ok);
    bind_num(q, i++, o->max_helm_deg);
    bind_num(q, i++, o->path_length);
    bind_num(q, i++, o->path_lengthening);
    bind_num(q, i++, o->time_lost);
    bind_num(q, i++, o->rudder_work_deg_s);
    sqlite3_bind_int(q, i++, o->helm_orders);
    bind_num(q, i++, o->traffic_ship_s);
    sqlite3_bind_int(q, i++, o->give_way);
    sqlite3_bind_int(q, i++, o->give_way_short);
    const fw_monitor_counts *m = &o->monitors;
    int mon[] = {m->sideways, m->teleport, m->overlap, m->appear, m->vanish, m->start_close,
                 m->stopped};
    for (size_t k = 0; k < sizeof mon / sizeof mon[0]; k++)
        sqlite3_bind_int(q, i++, mon[k]);
    bind_num(q, i++, m->max_lateral);
    bind_num(q, i++, o->min_hull);
    bind_num(q, i++, o->closeness);
    return sqlite3_step(q);
}

static int enc_row(sqlite3_stmt *q, int run_id, const fw_outcome_encounter *e)
{
    int i = 1, nf;
    const fw_enc_field *fl = fw_enc_fields(&nf);
    sqlite3_reset(q);
    sqlite3_clear_bindings(q);
    sqlite3_bind_int(q, i++, run_id);
    for (int k = 0; k < nf; k++) {
        if (!(fl[k].flags & FW_ENC_SQL))
            continue;
        fw_enc_value v = {0};
        fl[k].get(&e->e, &e->v, true, &v);
        if (v.null)
            sqlite3_bind_null(q, i++);
        else if (fl[k].type == FW_ENC_TEXT)
            sqlite3_bind_text(q, i++, v.text, -1, SQLITE_STATIC);
        else if (fl[k].type == FW_ENC_REAL)
            bind_num(q, i++, v.num);
        else
            sqlite3_bind_int(q, i++, (int)v.num);
    }
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
    bind_num(q, i++, t->min_hull);
    sqlite3_bind_int(q, i++, t->candidate);
    bind_num(q, i++, t->cand_miss);
    sqlite3_bind_text(q, i++, t->outcome, -1, SQLITE_STATIC);
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
