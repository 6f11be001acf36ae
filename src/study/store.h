/* store.h - the study database a sweep writes (SQLite, schema in schema.h).
 *
 * One process writes it.  Each run is committed in one transaction with all
 * its rows, in WAL mode, so a process killed at any moment (even SIGKILL)
 * leaves every earlier run intact and no half run.  The database remembers the
 * study's digest: resuming with a changed study or scenario is refused rather
 * than mixing results of two different studies.
 */
#ifndef FW_STUDY_STORE_H
#define FW_STUDY_STORE_H

#include <stdbool.h>

#include "core/error.h"
#include "study/outcome.h"
#include "study/study.h"

typedef struct fw_store fw_store;

/* Opens (creating if needed) path for study s. */
fw_status fw_store_open(const char *path, const fw_study *s, fw_store **out, fw_error *err);
/* Closes st; the database is left with a rollback journal (not WAL), so
 * readers need no write access.  Opening takes an exclusive lock on the file
 * (flock): a second sweep on the same database is refused at once. */
void fw_store_close(fw_store *st);

/* In a forked child: drops the inherited lock so only the writer holds it. */
void fw_store_child(void);

/* done[run_id] = the run is in the database (ok, or failed when
 * count_failed); done has fw_study_run_count entries. */
fw_status fw_store_finished(fw_store *st, bool count_failed, bool *done, int n, fw_error *err);

/* Deletes a failed run so it can be run again (--retry-failed). */
fw_status fw_store_forget_failed(fw_store *st, fw_error *err);

/* Commits one run and its rows in one transaction. */
fw_status fw_store_commit(fw_store *st, const fw_study *s, const fw_outcome *o, fw_error *err);

/* The splitting estimates (schema.h's splits table; store_split.c). */
typedef struct fw_split_row {
    int cell, batch;
    double domain, ratio, density;
    const char *behaviour;
    const char *setting;        /* the axes' values; NULL or "" without axes */
    int particles;
    bool ok;
    const char *reason;         /* why it failed ("" when ok) */
    int rounds;
    double runs, sim_s, wall_s;
    double p_collision, p_near_miss, best_closeness;
    const char *best_path;
} fw_split_row;

/* Commits one batch's estimate in one transaction. */
fw_status fw_store_split(fw_store *st, const fw_split_row *r, fw_error *err);
/* done[cell * batches + batch] = that estimate is in the database (ok, or
 * failed when count_failed); done has n entries. */
fw_status fw_store_splits_done(fw_store *st, bool count_failed, int batches, bool *done, int n,
                               fw_error *err);
/* Deletes the failed estimates so they are made again (--retry-failed). */
fw_status fw_store_forget_failed_splits(fw_store *st, fw_error *err);

/* The connection and the file, for store_split.c. */
typedef struct sqlite3 sqlite3;
sqlite3 *fw_store_sqlite(fw_store *st);
const char *fw_store_path(const fw_store *st);

#endif
