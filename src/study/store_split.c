/* store_split.c - the splitting estimates in the study database (store.h). */
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>

#include "study/store.h"

static fw_status fail(fw_store *st, fw_error *err, const char *what)
{
    return fw_fail(err, FW_ERUN, "%s: %s: %s", fw_store_path(st), what,
                   sqlite3_errmsg(fw_store_sqlite(st)));
}

static void bind_num(sqlite3_stmt *q, int i, double v)
{
    if (isfinite(v))
        sqlite3_bind_double(q, i, v);
    else
        sqlite3_bind_null(q, i);
}

fw_status fw_store_split(fw_store *st, const fw_split_row *r, fw_error *err)
{
    static const char sql[] =
        "INSERT OR REPLACE INTO splits(cell, batch, domain_m, fore_aft_ratio, density, behaviour, "
        "setting, particles, status, reason, rounds, runs, sim_s, wall_s, p_collision, "
        "p_near_miss, best_closeness, best_path) VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)";
    sqlite3 *db = fw_store_sqlite(st);
    sqlite3_stmt *q = NULL;
    if (sqlite3_prepare_v2(db, sql, -1, &q, NULL) != SQLITE_OK)
        return fail(st, err, "preparing a splitting estimate");
    int i = 1;
    sqlite3_bind_int(q, i++, r->cell);
    sqlite3_bind_int(q, i++, r->batch);
    sqlite3_bind_double(q, i++, r->domain);
    bind_num(q, i++, r->ratio);
    sqlite3_bind_double(q, i++, r->density);
    sqlite3_bind_text(q, i++, r->behaviour, -1, SQLITE_STATIC);
    if (r->setting && r->setting[0])
        sqlite3_bind_text(q, i, r->setting, -1, SQLITE_STATIC);
    i++;
    sqlite3_bind_int(q, i++, r->particles);
    sqlite3_bind_text(q, i++, r->ok ? "ok" : "failed", -1, SQLITE_STATIC);
    sqlite3_bind_text(q, i++, r->reason ? r->reason : "", -1, SQLITE_STATIC);
    if (r->ok) {
        sqlite3_bind_int(q, i++, r->rounds);
        bind_num(q, i++, r->runs);
        bind_num(q, i++, r->sim_s);
        bind_num(q, i++, r->wall_s);
        bind_num(q, i++, r->p_collision);
        bind_num(q, i++, r->p_near_miss);
        bind_num(q, i++, r->best_closeness);
        sqlite3_bind_text(q, i++, r->best_path ? r->best_path : "", -1, SQLITE_STATIC);
    }
    /* one statement is one transaction: the estimate is there whole or not */
    int rc = sqlite3_step(q);
    sqlite3_finalize(q);
    return rc == SQLITE_DONE ? FW_OK : fail(st, err, "writing a splitting estimate");
}

fw_status fw_store_splits_done(fw_store *st, bool count_failed, int batches, bool *done, int n,
                               fw_error *err)
{
    sqlite3_stmt *q = NULL;
    const char *sql = count_failed ? "SELECT cell, batch FROM splits"
                                   : "SELECT cell, batch FROM splits WHERE status = 'ok'";
    if (sqlite3_prepare_v2(fw_store_sqlite(st), sql, -1, &q, NULL) != SQLITE_OK)
        return fail(st, err, "reading the splitting estimates");
    for (int i = 0; i < n; i++)
        done[i] = false;
    int rc;
    while ((rc = sqlite3_step(q)) == SQLITE_ROW) {
        long long k = sqlite3_column_int64(q, 0) * (long long)batches + sqlite3_column_int64(q, 1);
        if (sqlite3_column_int64(q, 1) < batches && k >= 0 && k < n)
            done[k] = true;
    }
    sqlite3_finalize(q);
    return rc == SQLITE_DONE ? FW_OK : fail(st, err, "reading the splitting estimates");
}

fw_status fw_store_forget_failed_splits(fw_store *st, fw_error *err)
{
    char *msg = NULL;
    if (sqlite3_exec(fw_store_sqlite(st), "DELETE FROM splits WHERE status = 'failed'", NULL, NULL,
                     &msg) != SQLITE_OK) {
        fw_status r = fw_fail(err, FW_ERUN, "%s: %s", fw_store_path(st), msg ? msg : "?");
        sqlite3_free(msg);
        return r;
    }
    return FW_OK;
}
