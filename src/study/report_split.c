/* report_split.c - the splitting estimates of a study (estimate:) in its
 * report: by cell, the batches' mean with its interval, per run and per hour,
 * beside the cell's crude counts, and what the same accuracy would have cost
 * by counting (report_data.h). */
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/mem.h"
#include "study/ams.h"
#include "study/report_data.h"

/* The batches of one cell as read. */
typedef struct batch_set {
    double *pc, *pn;
    int n, cap;
} batch_set;

static bool same_cell(const fw_rep_split *c, double domain, double ratio, double density,
                      const char *beh, const char *setting)
{
    return c->domain == domain && (c->ratio == ratio || (isnan(c->ratio) && isnan(ratio))) &&
           c->density == density && strcmp(c->behaviour, beh) == 0 &&
           strcmp(c->setting, setting) == 0;
}

/* The cell's crude counts: its runs, and those with a collision or a near miss. */
static void crude_counts(const fw_study_report *rep, fw_rep_split *c)
{
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        if (!same_cell(c, r->domain, r->ratio, r->density, r->behaviour, r->setting))
            continue;
        c->crude_n++;
        c->crude_collisions += r->collision_flag == 1.0;
        c->crude_near += r->near_miss_flag == 1.0;
    }
}

/* Sets c's estimates from its batches. */
static void finish_cell(const fw_study_report *rep, fw_rep_split *c, const batch_set *b)
{
    c->batches = b->n;
    if (b->n >= 2) {
        c->p_collision = fw_ams_interval(b->pc, b->n, rep->level);
        c->p_near_miss = fw_ams_interval(b->pn, b->n, rep->level);
        double m = fw_mean(b->pc, b->n);
        c->re = m > 0.0 ? fw_sd(b->pc, b->n) / sqrt((double)b->n) / m : NAN;
        c->crude_h = m > 0.0 && c->re > 0.0
                         ? fw_crude_runs(m, c->re) * c->duration_s / 3600.0
                         : NAN;
    } else {
        c->p_collision = c->p_near_miss = (fw_estimate){.mean = NAN, .lo = NAN, .hi = NAN};
        c->re = c->crude_h = NAN;
    }
    crude_counts(rep, c);
}

static fw_status add_batch(batch_set *b, double pc, double pn)
{
    int cap = b->cap;
    if (!fw_reserve((void **)&b->pc, sizeof *b->pc, &cap, b->n + 1))
        return FW_ERUN;
    cap = b->cap;
    if (!fw_reserve((void **)&b->pn, sizeof *b->pn, &cap, b->n + 1))
        return FW_ERUN;
    b->cap = cap;
    b->pc[b->n] = pc;
    b->pn[b->n++] = pn;
    return FW_OK;
}

static const char kSql[] =
    "SELECT cell, domain_m, fore_aft_ratio, density, COALESCE(behaviour, ''), particles, status, "
    "runs, sim_s, wall_s, p_collision, p_near_miss, best_closeness, COALESCE(best_path, ''), "
    "COALESCE(setting, '') FROM splits ORDER BY cell, batch";

static double col(sqlite3_stmt *q, int i)
{
    return sqlite3_column_type(q, i) == SQLITE_NULL ? NAN : sqlite3_column_double(q, i);
}

/* Reads one row into the current cell (a new one when the cell changes). */
static fw_status read_row(fw_study_report *rep, sqlite3_stmt *q, batch_set *b, int *cap)
{
    int cell = sqlite3_column_int(q, 0);
    fw_rep_split *c = rep->n_splits ? &rep->splits[rep->n_splits - 1] : NULL;
    if (!c || c->cell != cell) {
        if (c)
            finish_cell(rep, c, b);
        b->n = 0;
        if (!fw_reserve((void **)&rep->splits, sizeof *rep->splits, cap, rep->n_splits + 1))
            return FW_ERUN;
        c = &rep->splits[rep->n_splits++];
        *c = (fw_rep_split){.cell = cell, .domain = col(q, 1), .ratio = col(q, 2),
                            .density = col(q, 3), .particles = sqlite3_column_int(q, 5),
                            .best_closeness = -1.0};
        snprintf(c->behaviour, sizeof c->behaviour, "%s", (const char *)sqlite3_column_text(q, 4));
        snprintf(c->setting, sizeof c->setting, "%s", (const char *)sqlite3_column_text(q, 14));
    }
    if (strcmp((const char *)sqlite3_column_text(q, 6), "ok") != 0) {
        c->failed++;
        return FW_OK;
    }
    double runs = col(q, 7), sim = col(q, 8);
    c->runs += runs;
    c->sim_h += sim / 3600.0;
    c->wall_s += col(q, 9);
    if (runs > 0.0)
        c->duration_s = sim / runs;
    if (col(q, 12) > c->best_closeness) {
        c->best_closeness = col(q, 12);
        snprintf(c->best_path, sizeof c->best_path, "%s", (const char *)sqlite3_column_text(q, 13));
    }
    return add_batch(b, col(q, 10), col(q, 11));
}

fw_status fw_rep_load_splits(fw_study_report *rep, sqlite3 *db, const char *file, fw_error *err)
{
    sqlite3_stmt *q = NULL;
    if (sqlite3_prepare_v2(db, kSql, -1, &q, NULL) != SQLITE_OK)
        return FW_OK; /* a database from before splitting: no estimates */
    batch_set b = {0};
    int cap = 0, rc;
    fw_status st = FW_OK;
    while (!st && (rc = sqlite3_step(q)) == SQLITE_ROW)
        st = read_row(rep, q, &b, &cap);
    if (!st && rc != SQLITE_DONE)
        st = fw_fail(err, FW_EINPUT, "%s: cannot read table splits (%s)", file, sqlite3_errmsg(db));
    else if (st)
        st = fw_fail(err, FW_ERUN, "out of memory");
    else if (rep->n_splits)
        finish_cell(rep, &rep->splits[rep->n_splits - 1], &b);
    sqlite3_finalize(q);
    free(b.pc);
    free(b.pn);
    return st;
}

/* "1.23e-04 [5.6e-05, 2.1e-04]"; every batch at 0 is no estimate with an
 * interval but a finding: no batch found a path to the event (each went
 * extinct below it, ams.h), which bounds nothing by itself. */
static const char *est(char *buf, size_t n, const fw_estimate *e, double best)
{
    if (isnan(e->mean))
        snprintf(buf, n, "(one batch: no interval)");
    else if (e->mean == 0.0)
        snprintf(buf, n, "0: no batch reached it (closest: closeness %.3f)", best);
    else
        snprintf(buf, n, "%.3g [%.3g, %.3g]", e->mean, e->lo, e->hi);
    return buf;
}

/* "%.3g" of x, "-" when it is not a number (no estimate to compare). */
static const char *num_or_dash(char *buf, size_t n, double x, const char *unit)
{
    if (isfinite(x))
        snprintf(buf, n, "%.3g%s", x, unit);
    else
        snprintf(buf, n, "-");
    return buf;
}

void fw_rep_md_splits(FILE *f, const fw_study_report *rep)
{
    if (!rep->n_splits)
        return;
    fprintf(f, "## Rare events by splitting\n\n"
               "Adaptive multilevel splitting (estimate: in the study): per cell, the "
               "probability that one run of its duration has a collision (hulls touch) or a "
               "near miss (hull to hull below the study's threshold), the mean of independent "
               "batches with its %.0f%% interval (Cox's, on the logarithms); per hour is the "
               "probability over the run's hours. Beside it, the same cell's runs counted "
               "(crude Monte Carlo). *Crude hours* is what counting would need for the same "
               "relative error, (1 - p) / (p RE^2) runs; the speed-up is that over the hours "
               "splitting simulated (every branch replayed from t = 0 counts whole).\n\n",
            100.0 * rep->level);
    fprintf(f, "| domain | %s | batches x particles | P(collision) per run | per hour | "
               "P(near miss) per run | counted: collisions, near misses / runs | simulated h | "
               "crude h for the same error | speed-up |\n"
               "|---:|---|---:|---|---:|---|---|---:|---:|---:|\n",
            rep->has_settings ? "behaviour; setting" : "behaviour");
    for (int i = 0; i < rep->n_splits; i++) {
        const fw_rep_split *c = &rep->splits[i];
        char a[96], b[96], h[32], ch[32], sp[32];
        double hours = c->duration_s / 3600.0;
        fprintf(f, "| %g m | %s%s%s | %d x %d%s | %s | %s | %s | %d, %d / %d | %.1f | %s | %s |\n",
                c->domain, c->behaviour, c->setting[0] ? "; " : "", c->setting, c->batches,
                c->particles, c->failed ? " (some failed)" : "",
                est(a, sizeof a, &c->p_collision, c->best_closeness),
                num_or_dash(h, sizeof h, c->p_collision.mean / hours, ""),
                est(b, sizeof b, &c->p_near_miss, c->best_closeness), c->crude_collisions,
                c->crude_near, c->crude_n, c->sim_h, num_or_dash(ch, sizeof ch, c->crude_h, ""),
                num_or_dash(sp, sizeof sp, c->crude_h / c->sim_h, "x"));
    }
    fprintf(f, "\nThe closest trajectory of each cell is kept as a path (splits.csv, best_path: "
               "its start's draw and re-keyings) that `fairway worst` can run again.\n\n");
}

fw_status fw_rep_write_splits_csv(const fw_study_report *rep, const char *dir, fw_error *err)
{
    if (!rep->n_splits)
        return FW_OK;
    char path[1100], tmp[1120];
    if ((size_t)snprintf(path, sizeof path, "%s/splits.csv", dir) >= sizeof path)
        return fw_fail(err, FW_EINPUT, "%s: path too long", dir);
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "cell,domain_m,fore_aft_ratio,density,behaviour,batches,failed,particles,"
               "p_collision,p_collision_lo,p_collision_hi,p_collision_per_h,p_near_miss,"
               "p_near_miss_lo,p_near_miss_hi,relative_error,runs,sim_h,wall_s,crude_h,speedup,"
               "crude_runs,crude_collisions,crude_near_misses,best_closeness,best_path,setting\n");
    for (int i = 0; i < rep->n_splits; i++) {
        const fw_rep_split *c = &rep->splits[i];
        fprintf(f, "%d,%g,%g,%g,%s,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%.0f,%.4g,"
                   "%.1f,%.6g,%.4g,%d,%d,%d,%.6g,%s,%s%s%s\n",
                c->cell, c->domain, c->ratio, c->density, c->behaviour, c->batches, c->failed,
                c->particles, c->p_collision.mean, c->p_collision.lo, c->p_collision.hi,
                c->p_collision.mean * 3600.0 / c->duration_s, c->p_near_miss.mean,
                c->p_near_miss.lo, c->p_near_miss.hi, c->re, c->runs, c->sim_h, c->wall_s,
                c->crude_h, c->crude_h / c->sim_h, c->crude_n, c->crude_collisions, c->crude_near,
                c->best_closeness, c->best_path, strchr(c->setting, ',') ? "\"" : "",
                c->setting, strchr(c->setting, ',') ? "\"" : "");
    }
    return fw_file_commit(f, tmp, path, err);
}
