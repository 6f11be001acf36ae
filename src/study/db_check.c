/* db_check.c - every value of a study database against its column's rule (db_check.h). */
#include "study/db_check.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run/encounter_record.h"
#include "study/report_data.h"

typedef enum kind { K_NUM, K_INT, K_FLAG, K_TEXT } kind;

enum {
    F_NN = 1,   /* NOT NULL */
    F_POS = 2,  /* strictly above lo */
    F_REPS = 4, /* below meta's replications */
    F_RUNS = 8, /* below meta's runs (the study's run list) */
    F_DUR = 16, /* at most meta's duration_s (a run's simulated time) */
    F_LINES = 32 /* text: line breaks and tabs allowed (a failed run's reason) */
};

/* A column's rule: its kind, the closed range [lo, hi] (F_POS: (lo, hi]),
 * and what its values are, for the message ("-inf is not a distance"). */
typedef struct rule {
    const char *col;
    kind k;
    double lo, hi;
    unsigned f;
    const char *what;
} rule;

/* Counts stay below 1e9 so a group's sums are exact in a double and an int64. */
#define COUNT 0, 1e9
#define NONNEG 0, HUGE_VAL
/* Distances below 1e8 m (twice round the Earth): a CPA histogram's bins stay sane. */
#define DIST 0, 1e8
#define ANY -HUGE_VAL, HUGE_VAL

static const rule runs_rules[] = {
    {"run_id", K_INT, 0, 1e15, F_NN | F_RUNS, "a run id"},
    {"domain_m", K_NUM, NONNEG, F_NN | F_POS, "a domain size"},
    {"fore_aft_ratio", K_NUM, NONNEG, F_POS, "a domain shape (fore-aft ratio)"},
    {"density", K_NUM, NONNEG, F_NN, "a traffic density"},
    {"replication", K_INT, 0, 999999, F_NN | F_REPS, "a replication"},
    {"seed", K_INT, 1, 2147483646, F_NN, "a run's seed"}, /* study.c: 1 to 2^31 - 2 */
    {"status", K_TEXT, ANY, F_NN, "a status"},
    {"reason", K_TEXT, ANY, F_NN | F_LINES, "a reason"},
    /* >= 1 ms when ok: report_load.c */
    {"sim_s", K_NUM, 0, 1e9, F_DUR, "a simulated time"},
    {"wall_s", K_NUM, NONNEG, 0, "a time"},
    {"sumo_s", K_NUM, NONNEG, 0, "a time"},
    {"n_encounters", K_INT, COUNT, 0, "a count"},
    {"n_actions", K_INT, COUNT, 0, "a count"},
    {"min_dist_m", K_NUM, DIST, 0, "a distance"},
    {"domain_entered", K_FLAG, 0, 1, 0, "a flag"},
    {"near_miss", K_FLAG, 0, 1, 0, "a flag"},
    {"near_miss_centre", K_FLAG, 0, 1, 0, "a flag"},
    {"collision", K_FLAG, 0, 1, 0, "a flag"},
    {"colregs_ok", K_FLAG, 0, 1, 0, "a flag"},
    {"max_helm_deg", K_NUM, 0, 90, 0, "a helm angle"},
    {"path_length_m", K_NUM, DIST, 0, "a distance"},
    {"path_lengthening_m", K_NUM, -1e8, 1e8, 0, "a distance"},
    {"time_lost_s", K_NUM, ANY, 0, "a time"},
    {"rudder_work_deg_s", K_NUM, NONNEG, 0, "a rudder work"},
    {"helm_orders", K_INT, COUNT, 0, "a count"},
    {"traffic_ship_s", K_NUM, NONNEG, 0, "an exposure (ship-seconds)"},
    {"behaviour", K_TEXT, ANY, 0, "a behaviour"},
    {"give_way", K_INT, COUNT, 0, "a count"},
    {"give_way_short", K_INT, COUNT, 0, "a count"},
    {"mon_sideways", K_INT, COUNT, 0, "a count"},
    {"mon_teleport", K_INT, COUNT, 0, "a count"},
    {"mon_overlap", K_INT, COUNT, 0, "a count"},
    {"mon_appear", K_INT, COUNT, 0, "a count"},
    {"mon_vanish", K_INT, COUNT, 0, "a count"},
    {"mon_start_close", K_INT, COUNT, 0, "a count"},
    {"mon_stopped", K_INT, COUNT, 0, "a count"},
    {"max_lateral_mps", K_NUM, NONNEG, 0, "a speed"},
    {"min_hull_m", K_NUM, DIST, 0, "a distance"},
    {"closeness", K_NUM, 0, 1, 0, "a closeness (0-1)"},
    {"setting", K_TEXT, ANY, 0, "a setting"},
};

static const rule traffic_rules[] = {
    {"run_id", K_INT, 0, 1e15, F_NN | F_RUNS, "a run id"},
    {"ship_a", K_TEXT, ANY, F_NN, "a ship"},
    {"ship_b", K_TEXT, ANY, F_NN, "a ship"},
    {"type", K_TEXT, ANY, F_NN, "a type"},
    {"own", K_FLAG, 0, 1, F_NN, "a flag"},
    {"t_first_s", K_NUM, ANY, F_NN, "a time"},
    {"range0_m", K_NUM, DIST, 0, "a distance"},
    {"dcpa0_m", K_NUM, DIST, 0, "a distance"},
    {"tcpa0_s", K_NUM, ANY, 0, "a time"},
    {"min_dist_m", K_NUM, DIST, 0, "a distance"},
    {"t_min_s", K_NUM, ANY, 0, "a time"},
    {"min_hull_m", K_NUM, DIST, 0, "a distance"},
    {"candidate", K_FLAG, 0, 1, 0, "a flag"},
    {"cand_miss_m", K_NUM, DIST, 0, "a distance"},
    {"outcome", K_TEXT, ANY, 0, "an outcome"},
};

static const rule split_rules[] = {
    {"cell", K_INT, 0, 1e15, F_NN | F_RUNS, "a cell (a run id)"},
    {"batch", K_INT, 0, 1e6, F_NN, "a batch"},
    {"domain_m", K_NUM, NONNEG, F_NN | F_POS, "a domain size"},
    {"fore_aft_ratio", K_NUM, NONNEG, F_POS, "a domain shape (fore-aft ratio)"},
    {"density", K_NUM, NONNEG, F_NN, "a traffic density"},
    {"behaviour", K_TEXT, ANY, 0, "a behaviour"},
    {"particles", K_INT, 2, 1e6, F_NN, "a number of particles"},
    {"status", K_TEXT, ANY, F_NN, "a status"},
    {"reason", K_TEXT, ANY, F_NN | F_LINES, "a reason"},
    {"rounds", K_INT, COUNT, 0, "a count"},
    {"runs", K_NUM, 0, 1e12, 0, "a number of runs"},
    {"sim_s", K_NUM, 0, 1e15, 0, "a simulated time"},
    {"wall_s", K_NUM, NONNEG, 0, "a time"},
    {"p_collision", K_NUM, 0, 1, 0, "a probability"},
    {"p_near_miss", K_NUM, 0, 1, 0, "a probability"},
    {"best_closeness", K_NUM, 0, 1, 0, "a closeness (0-1)"},
    {"best_path", K_TEXT, ANY, 0, "a path"},
};

/* The encounter field table's INT columns whose range its type does not say. */
static const rule enc_ranges[] = {
    {"early", K_FLAG, 0, 1, 0, "a flag"},
    {"substantial", K_FLAG, 0, 1, 0, "a flag"},
    {"compliant", K_FLAG, 0, 1, 0, "a flag"},
    {"rule17_phase", K_INT, 0, 3, 0, "a rule 17 phase (0-3)"},
    {"rule", K_INT, 0, 99, 0, "a COLREGs rule"},
    {"closeness", K_NUM, 0, 1, 0, "a closeness (0-1)"},
};

/* Text columns whose values are names the readers know (the same lists they count by). */
typedef struct names_rule {
    const char *table, *col;
    const char *const *names;
    int n;
} names_rule;

static const names_rule names_rules[] = {
    {"encounters", "situation", fw_rep_situation_names, FW_REP_NSIT},
    {"encounters", "outcome", fw_cand_outcomes, 4},
    {"traffic_encounters", "type", fw_rep_type_names + 1, FW_REP_NTYPE - 1},
    {"traffic_encounters", "outcome", fw_cand_outcomes, 4},
};

static const names_rule *names_of(const char *table, const char *col)
{
    for (size_t i = 0; i < sizeof names_rules / sizeof *names_rules; i++)
        if (strcmp(names_rules[i].table, table) == 0 && strcmp(names_rules[i].col, col) == 0)
            return &names_rules[i];
    return NULL;
}

/* What the message shows of a text: at most 40 characters, no control ones. */
static void show_text(char *buf, size_t sz, const unsigned char *t)
{
    size_t k = 0;
    buf[k++] = '\'';
    for (; t && *t && k + 5 < sz && k < 41; t++)
        buf[k++] = isprint(*t) ? (char)*t : '?';
    if (t && *t)
        k += (size_t)snprintf(buf + k, sz - k, "...");
    snprintf(buf + k, sz - k, "'");
}

/* A text holding a control character (an escape sequence would reach the
 * terminal, a line break split a one-line message or a table row): why, or
 * false.  lines: line breaks and tabs allowed. */
static bool control_char(const unsigned char *t, bool lines, char *why, size_t sz)
{
    for (size_t k = 0; t && t[k]; k++) {
        if ((t[k] >= 0x20 && t[k] != 0x7f) || (lines && (t[k] == '\n' || t[k] == '\t')))
            continue;
        char shown[64];
        show_text(shown, sizeof shown, t);
        snprintf(why, sz, "%s holds a control character (byte 0x%02x at %zu)", shown, t[k], k + 1);
        return true;
    }
    return false;
}

/* A text not among names: why (into why), or false when it is one. */
static bool not_named(const names_rule *nr, const unsigned char *t, char *why, size_t sz)
{
    for (int j = 0; j < nr->n; j++)
        if (strcmp(nr->names[j], (const char *)t) == 0)
            return false;
    char shown[64];
    show_text(shown, sizeof shown, t);
    size_t k = (size_t)snprintf(why, sz, "%s is not one of", shown);
    for (int j = 0; j < nr->n && k < sz; j++)
        k += (size_t)snprintf(why + k, sz - k, "%s %s", j ? "," : "", nr->names[j]);
    return true;
}

enum { MAX_ENC_RULES = 64 };

/* The encounters' rules from the field table: a distance (m) in [0, 1e8], a
 * time (s), an angle (deg) or a plain number (the speed change) any finite
 * number, the domain ratio >= 0, a flag 0/1, an INT a count unless
 * enc_ranges says otherwise, text text. */
static int enc_rules(rule *out)
{
    int n_f, n = 0;
    const fw_enc_field *f = fw_enc_fields(&n_f);
    out[n++] = (rule){"run_id", K_INT, 0, 1e15, F_NN | F_RUNS, "a run id"};
    for (int i = 0; i < n_f && n < MAX_ENC_RULES; i++) {
        if (!f[i].sql || !(f[i].flags & FW_ENC_SQL))
            continue;
        rule r = {f[i].sql, K_NUM, ANY, (f[i].flags & FW_ENC_NOT_NULL) ? F_NN : 0u, "a number"};
        switch (f[i].type) {
        case FW_ENC_TEXT:
            r.k = K_TEXT, r.what = "text";
            break;
        case FW_ENC_FLAG:
            r.k = K_FLAG, r.lo = 0, r.hi = 1, r.what = "a flag";
            break;
        case FW_ENC_INT:
            r.k = K_INT, r.lo = 0, r.hi = 1e9, r.what = "a count";
            break;
        case FW_ENC_REAL:
            if (strcmp(f[i].unit, "m") == 0)
                r.lo = 0, r.hi = 1e8, r.what = "a distance";
            else if (strcmp(f[i].unit, "s") == 0)
                r.what = "a time";
            else if (strcmp(f[i].unit, "deg") == 0)
                r.what = "an angle";
            else if (strcmp(f[i].sql, "min_lambda") == 0)
                r.lo = 0, r.what = "a domain ratio";
            break;
        }
        for (size_t j = 0; j < sizeof enc_ranges / sizeof *enc_ranges; j++)
            if (strcmp(enc_ranges[j].col, r.col) == 0)
                r = enc_ranges[j], r.f |= (f[i].flags & FW_ENC_NOT_NULL) ? F_NN : 0u;
        out[n++] = r;
    }
    return n;
}

/* Why the value in column i breaks rule r or is not among nr's names (nr NULL:
 * any text), into why; false when it keeps them. */
static bool breaks(const rule *r, const names_rule *nr, sqlite3_stmt *st, int i,
                   const int study[2], double duration, char *why, size_t sz)
{
    int type = sqlite3_column_type(st, i);
    char shown[64];
    if (type == SQLITE_NULL) {
        if (r->f & F_NN)
            snprintf(why, sz, "missing (NULL) where the schema says NOT NULL");
        return (r->f & F_NN) != 0;
    }
    if (type == SQLITE_BLOB) {
        snprintf(why, sz, "a blob is not %s", r->what);
        return true;
    }
    if (r->k == K_TEXT) {
        if (type != SQLITE_TEXT)
            snprintf(why, sz, "a number is not %s", r->what);
        return type != SQLITE_TEXT ||
               control_char(sqlite3_column_text(st, i), (r->f & F_LINES) != 0, why, sz) ||
               (nr && not_named(nr, sqlite3_column_text(st, i), why, sz));
    }
    if (type == SQLITE_TEXT) {
        show_text(shown, sizeof shown, sqlite3_column_text(st, i));
        snprintf(why, sz, "%s is text, not %s", shown, r->what);
        return true;
    }
    double v = sqlite3_column_double(st, i);
    if (!isfinite(v)) {
        snprintf(why, sz, "%g is not %s", v, r->what);
        return true;
    }
    if (r->k != K_NUM && type == SQLITE_FLOAT && v != floor(v)) {
        snprintf(why, sz, "%.15g is not %s (not an integer)", v, r->what);
        return true;
    }
    /* study[0], study[1]: meta's replications and runs (0: not recorded) */
    int of = (r->f & F_REPS) ? study[0] : (r->f & F_RUNS) ? study[1] : 0;
    double hi = of > 0 ? of - 1 : r->hi;
    if ((r->f & F_DUR) && duration > 0.0 && v > duration + 1e-3) { /* meta: %.3f */
        snprintf(why, sz, "%.15g s is longer than the study's runs (meta says duration_s %.15g)",
                 v, duration);
        return true;
    }
    if (!(v < r->lo || ((r->f & F_POS) && v <= r->lo) || v > hi))
        return false;
    if (r->k == K_FLAG)
        snprintf(why, sz, "%.15g is not %s (0 or 1)", v, r->what);
    else if (of > 0 && v > hi)
        snprintf(why, sz, "%.15g is not %s of this study (meta says %d %s)", v, r->what, of,
                 (r->f & F_REPS) ? "replications" : "runs");
    else if (v > hi)
        snprintf(why, sz, "%.15g is not %s (at most %.15g)", v, r->what, hi);
    else
        snprintf(why, sz, "%.15g is not %s (must be %s %.15g)", v, r->what,
                 (r->f & F_POS) ? ">" : ">=", r->lo);
    return true;
}

typedef struct checker {
    sqlite3 *db;
    const char *file;
    char study[128]; /* meta's study_name: runs are named study-%06d */
    int study_n[2];  /* meta's replications and runs; 0: not recorded */
    double duration; /* meta's duration_s; 0: not recorded */
    fw_error *err;
} checker;

/* Every row of table: the columns rules name, in the order SELECT * gives them. */
static fw_status check_table(checker *C, const char *table, const rule *rules, int n_rules)
{
    char sql[128];
    snprintf(sql, sizeof sql, "SELECT rowid, * FROM %s", table);
    sqlite3_stmt *st;
    if (sqlite3_prepare_v2(C->db, sql, -1, &st, NULL) != SQLITE_OK)
        return FW_OK; /* no such table: the readers say what they miss */
    int n_col = sqlite3_column_count(st), run_col = -1;
    const rule **map = calloc((size_t)n_col, sizeof *map);
    const names_rule **names = calloc((size_t)n_col, sizeof *names);
    if (!map || !names) {
        free(map);
        free(names);
        sqlite3_finalize(st);
        return fw_fail(C->err, FW_ERUN, "%s: out of memory", C->file);
    }
    for (int i = 1; i < n_col; i++) {
        const char *name = sqlite3_column_name(st, i);
        run_col = strcmp(name, "run_id") == 0 ? i : run_col;
        for (int j = 0; j < n_rules && !map[i]; j++)
            map[i] = strcmp(rules[j].col, name) == 0 ? &rules[j] : NULL;
        names[i] = names_of(table, name);
    }
    fw_status s = FW_OK;
    int rc;
    char why[200];
    while (!s && (rc = sqlite3_step(st)) == SQLITE_ROW) {
        for (int i = 1; i < n_col && !s; i++) {
            if (!map[i] ||
                !breaks(map[i], names[i], st, i, C->study_n, C->duration, why, sizeof why))
                continue;
            char run[200] = "";
            if (run_col > 0 && sqlite3_column_type(st, run_col) == SQLITE_INTEGER &&
                sqlite3_column_int64(st, run_col) >= 0)
                snprintf(run, sizeof run, " (run %s-%06lld)", C->study,
                         (long long)sqlite3_column_int64(st, run_col));
            s = fw_fail(C->err, FW_EINPUT, "%s: table %s, row %lld%s, column %s: %s", C->file,
                        table, (long long)sqlite3_column_int64(st, 0), run, map[i]->col, why);
        }
    }
    if (!s && rc != SQLITE_DONE)
        s = fw_fail(C->err, FW_EINPUT, "%s: cannot read table %s (%s)", C->file, table,
                    sqlite3_errmsg(C->db));
    free(map);
    free(names);
    sqlite3_finalize(st);
    return s;
}

/* meta's numbers as the sweep writes them (store.c write_meta): whole
 * numbers, or a list of numbers (F_LIST); a key not named is text, checked
 * for control characters only. */
enum { M_INT = 1, M_LIST = 2, M_POS = 4 };
typedef struct meta_rule {
    const char *key;
    double lo, hi;
    unsigned f;
    const char *what;
} meta_rule;

static const meta_rule meta_rules[] = {
    {"replications", 1, 1000000, M_INT, "a number of replications"},
    {"runs", 1, 1000000000, M_INT, "a number of runs"},
    {"seed", 0, 18446744073709551615.0, M_INT, "a seed"},
    {"survey", 0, 1, M_INT, "a flag (0 or 1)"},
    {"duration_s", 0, 1e9, M_POS, "a duration"},
    {"step_s", 0, 3600, M_POS, "a time step"},
    {"speed_kn", 0, 100, 0, "a speed"},
    {"encounter_m", 0, 1e8, M_POS, "a range"},
    {"near_miss_m", 0, 1e8, M_POS, "a distance"},
    {"audit_risk_dcpa_m", 0, 1e8, 0, "a distance"},
    {"audit_risk_tcpa_s", 0, 1e9, 0, "a time"},
    {"audit_course_change_deg", 0, 360, 0, "an angle"},
    {"audit_speed_change", 0, 1e3, 0, "a fraction"},
    {"audit_early_tcpa_s", 0, 1e9, 0, "a time"},
    {"audit_prompt_s", 0, 1e9, 0, "a time"},
    {"audit_rule17_may_tcpa_s", 0, 1e9, 0, "a time"},
    {"audit_rule17_must_tcpa_s", 0, 1e9, 0, "a time"},
    {"survey_radius_m", 0, 1e8, M_POS, "a distance"},
    {"survey_range_m", 0, 1e8, M_POS, "a distance"},
    {"survey_dcpa_m", 0, 1e8, 0, "a distance"},
    {"survey_tcpa_s", 0, 1e9, 0, "a time"},
    {"domains_m", 0, 1e8, M_LIST | M_POS, "a list of domain sizes"},
    {"domains_l", 0, 1e3, M_LIST | M_POS, "a list of domain sizes (ship lengths)"},
    {"densities", 0, 1e6, M_LIST, "a list of traffic densities"},
    {"fore_aft_ratios", 0, 1e3, M_LIST | M_POS, "a list of domain shapes"},
};

/* Does v (one number, or a comma-separated list for M_LIST) keep m?  The
 * number read into *x (the last of a list). */
static bool meta_ok(const meta_rule *m, const char *v, double *x)
{
    const char *p = v;
    do {
        char *end;
        errno = 0;
        *x = strtod(p, &end);
        bool whole = !(m->f & M_INT) || (*x == floor(*x) && !strpbrk(v, ".eE"));
        if (end == p || isspace((unsigned char)*p) || !isfinite(*x) || !whole || *x < m->lo ||
            ((m->f & M_POS) && *x <= m->lo) || *x > m->hi)
            return false;
        p = end;
    } while ((m->f & M_LIST) && *p == ',' && *++p);
    return *p == '\0';
}

/* One row of meta: its value against the key's rule, or (any key) free of
 * control characters (the study's description may have line breaks). */
static fw_status check_meta_row(checker *C, long long row, const char *k, const char *v)
{
    char why[200] = "", shown[64];
    double x = 0;
    const meta_rule *m = NULL;
    for (size_t i = 0; i < sizeof meta_rules / sizeof *meta_rules && !m; i++)
        m = strcmp(meta_rules[i].key, k) == 0 ? &meta_rules[i] : NULL;
    show_text(shown, sizeof shown, (const unsigned char *)v);
    if (m && !meta_ok(m, v, &x))
        snprintf(why, sizeof why, "%s is not %s (%s %.15g, at most %.15g)", shown, m->what,
                 (m->f & M_POS) ? "above" : "from", m->lo, m->hi);
    else if (!m)
        control_char((const unsigned char *)v, strcmp(k, "study_description") == 0, why,
                     sizeof why);
    if (!why[0] && strcmp(k, "study_name") == 0 && !v[0])
        snprintf(why, sizeof why, "an empty study name (it names the runs)");
    if (why[0]) {
        char key[64]; /* as shown, without its quotes */
        show_text(key, sizeof key, (const unsigned char *)k);
        memmove(key, key + 1, strlen(key));
        key[strlen(key) - 1] = '\0';
        return fw_fail(C->err, FW_EINPUT, "%s: table meta, row %lld (key %s), column value: %s",
                       C->file, row, key, why);
    }
    if (strcmp(k, "study_name") == 0)
        snprintf(C->study, sizeof C->study, "%s", v);
    else if (strcmp(k, "replications") == 0 || strcmp(k, "runs") == 0)
        C->study_n[k[0] == 'r' && k[1] == 'e' ? 0 : 1] = (int)x;
    else if (strcmp(k, "duration_s") == 0)
        C->duration = x;
    return FW_OK;
}

/* Every row of meta; study_name, replications, runs and duration_s kept. */
static fw_status read_meta(checker *C)
{
    sqlite3_stmt *st;
    if (sqlite3_prepare_v2(C->db, "SELECT rowid, key, value FROM meta", -1, &st, NULL) !=
        SQLITE_OK)
        return FW_OK; /* the readers refuse a database without meta */
    fw_status s = FW_OK;
    while (!s && sqlite3_step(st) == SQLITE_ROW) {
        const char *k = (const char *)sqlite3_column_text(st, 1);
        const char *v = (const char *)sqlite3_column_text(st, 2);
        s = check_meta_row(C, (long long)sqlite3_column_int64(st, 0), k ? k : "", v ? v : "");
    }
    sqlite3_finalize(st);
    return s;
}

fw_status fw_db_check(sqlite3 *db, const char *file, fw_error *err)
{
    checker C = {.db = db, .file = file, .err = err};
    rule enc[MAX_ENC_RULES];
    int n_enc = enc_rules(enc);
    fw_status s = read_meta(&C);
    if (!s)
        s = check_table(&C, "runs", runs_rules, (int)(sizeof runs_rules / sizeof *runs_rules));
    if (!s)
        s = check_table(&C, "encounters", enc, n_enc);
    if (!s)
        s = check_table(&C, "traffic_encounters", traffic_rules,
                        (int)(sizeof traffic_rules / sizeof *traffic_rules));
    if (!s)
        s = check_table(&C, "splits", split_rules,
                        (int)(sizeof split_rules / sizeof *split_rules));
    return s;
}
