/* worst_split.c - the closest trajectories splitting found, run again
 * (worst.h fw_worst_splits). */
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "study/outcome.h"
#include "study/split_run.h"
#include "study/sweep.h"
#include "study/worst.h"

/* Each cell's closest path: the batch with the largest closeness. */
static fw_status best_paths(sqlite3 *db, const char *file, fw_worst_split *out, int max, int *n,
                            fw_error *err)
{
    sqlite3_stmt *q = NULL;
    *n = 0;
    if (sqlite3_prepare_v2(db, "SELECT cell, best_closeness, best_path FROM splits WHERE "
                               "status = 'ok' AND best_path != '' ORDER BY cell, "
                               "best_closeness DESC, batch", -1, &q, NULL) != SQLITE_OK)
        return fw_fail(err, FW_EINPUT, "%s: no table splits (a study without estimate:)", file);
    while (sqlite3_step(q) == SQLITE_ROW && *n < max) {
        int cell = sqlite3_column_int(q, 0);
        if (*n > 0 && out[*n - 1].cell == cell)
            continue;
        fw_worst_split *w = &out[(*n)++];
        memset(w, 0, sizeof *w);
        w->cell = cell;
        w->db_closeness = sqlite3_column_double(q, 1);
        snprintf(w->path, sizeof w->path, "%s", (const char *)sqlite3_column_text(q, 2));
    }
    sqlite3_finalize(q);
    if (*n == 0)
        return fw_fail(err, FW_EINPUT, "%s: table splits holds no finished estimate", file);
    return FW_OK;
}

/* One cell's path run again into w->dir. */
static fw_status replay(const fw_worst_def *def, const fw_study *s, fw_worst_split *w,
                        fw_error *err)
{
    fw_status st = fw_path(w->dir, sizeof w->dir, err, "%s/split-cell-%d", def->out, w->cell);
    if (st)
        return st;
    fw_remove_tree(w->dir); /* an earlier replay's */
    if ((st = fw_mkdirs(w->dir, "--out", err)))
        return st;
    fw_split_cell cc = {s, w->cell};
    fw_split_run_def sd = {.scenario = fw_split_cell_scenario, .ctx = &cc};
    sd.run = fw_default_run_def();
    sd.run.mode = def->mode;
    fw_split_run *S = NULL;
    fw_ams_model model;
    fw_run_summary sum;
    fw_encounter *enc = NULL;
    int n_enc = 0;
    if (!(st = fw_split_run_create(&sd, &S, &model, err)))
        st = fw_split_run_replay(S, w->path, w->dir, &sum, &enc, &n_enc, err);
    w->replay_hull = INFINITY;
    for (int i = 0; !st && i < n_enc; i++)
        w->replay_hull = fmin(w->replay_hull, enc[i].min_hull);
    w->replay_closeness = fw_closeness(w->replay_hull);
    free(enc);
    fw_split_run_destroy(S);
    return st;
}

fw_status fw_worst_splits(const fw_worst_def *def, fw_worst_split *out, int max, int *n,
                          fw_error *err)
{
    char study_file[1024] = "", digest[32] = "";
    sqlite3 *db = NULL;
    fw_status st = fw_worst_open(def, &db, study_file, sizeof study_file, digest, err);
    if (st)
        return st;
    st = best_paths(db, def->db, out, max, n, err);
    sqlite3_close(db);
    fw_study *s = st ? NULL : malloc(sizeof *s);
    if (!st && !s)
        st = fw_fail(err, FW_ERUN, "out of memory");
    if (!st)
        st = fw_worst_study(def, study_file, digest, s, err);
    for (int k = 0; !st && k < *n; k++)
        if (out[k].cell < 0 || out[k].cell >= fw_study_cell_count(s))
            st = fw_fail(err, FW_EINPUT, "%s: table splits, column cell: %d is not a cell of "
                         "the study", def->db, out[k].cell);
    if (!st)
        st = fw_mkdirs(def->out, "--out", err);
    for (int k = 0; !st && k < *n; k++)
        st = replay(def, s, &out[k], err);
    free(s);
    return st;
}
