/* report_load.c - reads a study database for fairway report.
 *
 * Everything is read inside one read transaction, so a sweep still writing
 * the database is seen at one instant: a run is either wholly there or not.
 * Only runs with status ok count; a failed run's reason is tallied, and any
 * rows it may have left are skipped.  Names the database does not define
 * (situations, types) are refused rather than guessed.
 */
#include <ctype.h>
#include <fcntl.h>
#include <libgen.h>
#include <math.h>
#include <sqlite3.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "study/db_check.h"
#include "study/report_data.h"
#include "study/schema.h"

const char *const fw_rep_situation_names[FW_REP_NSIT] = {
    "head-on", "overtaking", "being overtaken", "crossing give-way", "crossing stand-on"};
const char *const fw_rep_type_names[FW_REP_NTYPE] = {"all", "head-on", "overtaking", "crossing"};
const char *const fw_rep_set_names[FW_REP_NSET] = {"own", "traffic"};
const char *const fw_cand_outcomes[4] = {"collision", "near miss", "domain", "passed"};
const double fw_iwrap_causation[FW_REP_NTYPE] = {NAN, 4.9e-5, 1.1e-4, 1.3e-4};

/* The traffic-level type an own-ship situation belongs to. */
static const fw_rep_type sit_type[FW_REP_NSIT] = {FW_REP_T_HEAD_ON, FW_REP_T_OVERTAKING,
                                                  FW_REP_T_OVERTAKING, FW_REP_T_CROSSING,
                                                  FW_REP_T_CROSSING};

int fw_rep_values_push(fw_rep_values *a, double v)
{
    if (a->n == a->cap) {
        int cap = a->cap ? 2 * a->cap : 64;
        double *p = realloc(a->v, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        a->v = p;
        a->cap = cap;
    }
    a->v[a->n++] = v;
    return 0;
}

/* Adds text to a tally (count + 1 if already there). */
int fw_rep_note(fw_rep_count **list, int *n, const char *text)
{
    for (int i = 0; i < *n; i++)
        if (strcmp((*list)[i].text, text) == 0) {
            (*list)[i].count++;
            return 0;
        }
    fw_rep_count *p = realloc(*list, (size_t)(*n + 1) * sizeof *p);
    if (!p)
        return -1;
    *list = p;
    p[*n].text = strdup(text);
    p[*n].count = 1;
    if (!p[*n].text)
        return -1;
    (*n)++;
    return 0;
}

static double col_num(sqlite3_stmt *st, int i)
{
    return sqlite3_column_type(st, i) == SQLITE_NULL ? NAN : sqlite3_column_double(st, i);
}

static const char *col_text(sqlite3_stmt *st, int i)
{
    const unsigned char *t = sqlite3_column_text(st, i);
    return t ? (const char *)t : "";
}

static int cmp_run_id(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = ((const fw_rep_run *)b)->run_id;
    return (x > y) - (x < y);
}

static fw_rep_run *find_run(fw_study_report *rep, long long id)
{
    return bsearch(&id, rep->runs, (size_t)rep->n_runs, sizeof *rep->runs, cmp_run_id);
}

static int cmp_group(const void *pa, const void *pb)
{
    const fw_rep_group *a = pa, *b = pb;
    if (a->setting_index != b->setting_index)
        return a->setting_index < b->setting_index ? -1 : 1;
    if (a->density != b->density)
        return a->density < b->density ? -1 : 1;
    int c = strcmp(a->behaviour, b->behaviour);
    if (c)
        return c;
    if (!fw_rep_same_shape(a, b))
        return isnan(a->ratio) ? -1 : isnan(b->ratio) ? 1 : a->ratio < b->ratio ? -1 : 1;
    return (a->domain > b->domain) - (a->domain < b->domain);
}

typedef struct loader {
    fw_study_report *rep;
    sqlite3 *db;
    const char *file;
    fw_error *err;
} loader;

static fw_status prepare(loader *L, const char *sql, sqlite3_stmt **st)
{
    if (sqlite3_prepare_v2(L->db, sql, -1, st, NULL) != SQLITE_OK)
        return fw_fail(L->err, FW_EINPUT, "%s: not a fairway study database (%s)", L->file,
                       sqlite3_errmsg(L->db));
    return FW_OK;
}

static fw_status step_done(loader *L, sqlite3_stmt *st, int rc)
{
    sqlite3_finalize(st);
    if (rc != SQLITE_DONE)
        return fw_fail(L->err, FW_EINPUT, "%s: cannot read the database (%s)", L->file,
                       sqlite3_errmsg(L->db));
    return FW_OK;
}

static fw_status oom(loader *L)
{
    return fw_fail(L->err, FW_ERUN, "%s: out of memory", L->file);
}

static fw_status read_meta(loader *L)
{
    sqlite3_stmt *st;
    if (prepare(L, "SELECT key, value FROM meta ORDER BY key", &st))
        return L->err->status;
    const char *version = NULL;
    char vbuf[64] = "";
    int rc;
    while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        const char *k = col_text(st, 0), *v = col_text(st, 1);
        if (strcmp(k, "schema_version") == 0) {
            snprintf(vbuf, sizeof vbuf, "%s", v);
            version = vbuf;
            continue;
        }
        if (strcmp(k, "study_name") == 0)
            snprintf(L->rep->study_name, sizeof L->rep->study_name, "%s", v);
        char line[256];
        snprintf(line, sizeof line, "%s = %.*s%s", k, 80, v, strlen(v) > 80 ? "..." : "");
        if (fw_rep_note(&L->rep->meta, &L->rep->n_meta, line)) {
            sqlite3_finalize(st);
            return oom(L);
        }
    }
    if (step_done(L, st, rc))
        return L->err->status;
    if (!version)
        return fw_fail(L->err, FW_EINPUT, "%s: not a fairway study database (no schema_version in meta)",
                       L->file);
    if (strcmp(version, FW_SCHEMA_VERSION) != 0)
        return fw_fail(L->err, FW_EINPUT,
                       "%s: study database schema version %s, this fairway reads version %s",
                       L->file, version, FW_SCHEMA_VERSION);
    return FW_OK;
}

static fw_status read_failed(loader *L)
{
    sqlite3_stmt *st;
    if (prepare(L,
                "SELECT status, reason, COUNT(*) FROM runs GROUP BY status, reason "
                "ORDER BY COUNT(*) DESC, reason",
                &st))
        return L->err->status;
    int rc;
    while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        int n = sqlite3_column_int(st, 2);
        L->rep->n_total += n;
        if (strcmp(col_text(st, 0), "ok") == 0)
            continue;
        L->rep->n_failed += n;
        const char *why = col_text(st, 1);
        if (fw_rep_note(&L->rep->reasons, &L->rep->n_reasons, why[0] ? why : "(no reason given)")) {
            sqlite3_finalize(st);
            return oom(L);
        }
        L->rep->reasons[L->rep->n_reasons - 1].count = n;
    }
    return step_done(L, st, rc);
}

static fw_status read_runs(loader *L)
{
    fw_study_report *rep = L->rep;
    sqlite3_stmt *st;
    if (prepare(L,
                "SELECT run_id, domain_m, density, replication, seed, sim_s, n_actions, "
                "min_dist_m, near_miss, collision, max_helm_deg, path_lengthening_m, "
                "time_lost_s, helm_orders, traffic_ship_s, n_encounters, behaviour, fore_aft_ratio, "
                "min_hull_m, closeness, setting "
                "FROM runs WHERE status = 'ok' ORDER BY run_id",
                &st))
        return L->err->status;
    int rc, cap = 0;
    while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        if (rep->n_runs == cap) {
            cap = cap ? 2 * cap : 64;
            fw_rep_run *p = realloc(rep->runs, (size_t)cap * sizeof *p);
            if (!p) {
                sqlite3_finalize(st);
                return oom(L);
            }
            rep->runs = p;
        }
        fw_rep_run *r = &rep->runs[rep->n_runs];
        memset(r, 0, sizeof *r);
        r->run_id = sqlite3_column_int64(st, 0);
        r->domain = col_num(st, 1);
        r->density = col_num(st, 2);
        r->replication = sqlite3_column_int(st, 3);
        r->seed = sqlite3_column_int64(st, 4);
        r->sim_s = col_num(st, 5);
        r->n_actions = col_num(st, 6);
        r->min_dist = col_num(st, 7);
        r->near_miss_flag = col_num(st, 8);
        r->collision_flag = col_num(st, 9);
        r->max_helm_deg = col_num(st, 10);
        r->path_lengthening = col_num(st, 11);
        r->time_lost = col_num(st, 12);
        r->helm_orders = col_num(st, 13);
        r->traffic_ship_s = col_num(st, 14);
        r->n_encounters_col = sqlite3_column_type(st, 15) == SQLITE_NULL ? -1 : sqlite3_column_int64(st, 15);
        snprintf(r->behaviour, sizeof r->behaviour, "%s", col_text(st, 16));
        r->ratio = col_num(st, 17);
        r->min_hull = col_num(st, 18);
        r->closeness = col_num(st, 19);
        snprintf(r->setting, sizeof r->setting, "%s", col_text(st, 20));
        if (r->setting[0])
            rep->has_settings = true;
        /* without its exposure a run has no rates at all: the writer broke the
         * contract (the values themselves were checked: db_check.h) */
        if (!(r->sim_s >= 1e-3)) { /* so a count over its hours stays finite */
            char v[40] = "missing";
            if (!isnan(r->sim_s))
                snprintf(v, sizeof v, "%.15g s", r->sim_s);
            sqlite3_finalize(st);
            return fw_fail(L->err, FW_EINPUT,
                           "%s: table runs, row %lld (run %s-%06lld), column sim_s: %s in a "
                           "finished run (status ok; at least 0.001 s)", L->file, r->run_id,
                           rep->study_name, r->run_id, v);
        }
        if (r->replication + 1 > rep->n_reps)
            rep->n_reps = r->replication + 1;
        rep->n_runs++;
    }
    return step_done(L, st, rc);
}

/* The group a run belongs to: its (setting, density, behaviour, domain). */
static fw_rep_group group_key(const fw_rep_run *r)
{
    fw_rep_group key = {.density = r->density, .domain = r->domain, .ratio = r->ratio};
    snprintf(key.behaviour, sizeof key.behaviour, "%s", r->behaviour);
    snprintf(key.setting, sizeof key.setting, "%s", r->setting);
    key.setting_index = r->setting_index;
    return key;
}

static fw_status make_groups(loader *L)
{
    fw_study_report *rep = L->rep;
    rep->groups = calloc((size_t)rep->n_runs, sizeof *rep->groups);
    if (!rep->groups)
        return oom(L);
    /* settings numbered in the order of the run list (the first finished run
     * of each): the study's own order, whose first is the reference */
    int *first = malloc(((size_t)rep->n_runs + 1) * sizeof *first); /* run of each setting */
    if (!first)
        return oom(L);
    for (int i = 0; i < rep->n_runs; i++) {
        fw_rep_run *r = &rep->runs[i];
        int k = 0;
        while (k < rep->n_settings && strcmp(rep->runs[first[k]].setting, r->setting) != 0)
            k++;
        if (k == rep->n_settings)
            first[rep->n_settings++] = i;
        r->setting_index = k;
    }
    free(first);
    for (int i = 0; i < rep->n_runs; i++) {
        fw_rep_group key = group_key(&rep->runs[i]);
        int g = 0;
        while (g < rep->n_groups && cmp_group(&rep->groups[g], &key) != 0)
            g++;
        if (g == rep->n_groups)
            rep->groups[rep->n_groups++] = key;
    }
    qsort(rep->groups, (size_t)rep->n_groups, sizeof *rep->groups, cmp_group);
    for (int i = 0; i < rep->n_runs; i++) {
        fw_rep_run *r = &rep->runs[i];
        fw_rep_group key = group_key(r);
        fw_rep_group *g = bsearch(&key, rep->groups, (size_t)rep->n_groups, sizeof key, cmp_group);
        r->group = (int)(g - rep->groups);
        g->n_runs++;
    }
    return FW_OK;
}

static int name_index(const char *const *names, int n, const char *s)
{
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], s) == 0)
            return i;
    return -1;
}

/* One encounter's candidate flag and outcome (columns i, i + 1; NULL in a
 * database whose writer did not fill them) into its group's tally. */
static fw_status count_candidate(loader *L, sqlite3_stmt *st, int i, const fw_rep_run *r, int set,
                                 int t)
{
    if (sqlite3_column_type(st, i) == SQLITE_NULL)
        return FW_OK;
    int o = name_index(fw_cand_outcomes, 4, col_text(st, i + 1));
    if (o < 0)
        return fw_fail(L->err, FW_EINPUT, "%s: run %lld: unknown encounter outcome '%s'", L->file,
                       r->run_id, col_text(st, i + 1));
    fw_study_report *rep = L->rep;
    long long *c = rep->groups[r->group].cand[set][t], *a = rep->groups[r->group].cand[set][0];
    rep->candidates = true;
    if (sqlite3_column_int(st, i) != 0) {
        c[FW_CAND_N]++, a[FW_CAND_N]++;
        c[FW_CAND_COLLISION + o]++, a[FW_CAND_COLLISION + o]++;
    } else if (o == 0) {
        c[FW_CAND_OTHER_COLL]++, a[FW_CAND_OTHER_COLL]++;
    }
    return FW_OK;
}

/* Runs sql and hands every row whose first column is a finished run's id to
 * row(L, st, run); a failed run's rows are passed over.  Stops at the first
 * failure; the statement is finalised either way. */
static fw_status each_run_row(loader *L, const char *sql,
                              fw_status (*row)(loader *, sqlite3_stmt *, fw_rep_run *))
{
    sqlite3_stmt *st;
    if (prepare(L, sql, &st))
        return L->err->status;
    int rc;
    while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        fw_rep_run *r = find_run(L->rep, sqlite3_column_int64(st, 0));
        fw_status s = r ? row(L, st, r) : FW_OK;
        if (s) {
            sqlite3_finalize(st);
            return s;
        }
    }
    return step_done(L, st, rc);
}

/* One own-ship encounter: situation, CPA, domain, near miss, collision,
 * candidate. */
static fw_status encounter_row(loader *L, sqlite3_stmt *st, fw_rep_run *r)
{
    const char *sit = col_text(st, 1);
    int s = name_index(fw_rep_situation_names, FW_REP_NSIT, sit);
    if (s < 0)
        return fw_fail(L->err, FW_EINPUT, "%s: run %lld: unknown encounter situation '%s'",
                       L->file, r->run_id, sit);
    r->n_sit[s]++;
    r->n_domain += sqlite3_column_int(st, 3) != 0;
    r->n_near += sqlite3_column_int(st, 4) != 0;
    r->n_collision += sqlite3_column_int(st, 5) != 0;
    r->n_near_centre += sqlite3_column_int(st, 8) != 0;
    if (count_candidate(L, st, 6, r, FW_REP_OWN, sit_type[s]))
        return L->err->status;
    double d = col_num(st, 2);
    fw_rep_group *g = &L->rep->groups[r->group];
    if (!isnan(d) && (fw_rep_values_push(&g->cpa[FW_REP_OWN][FW_REP_ALL], d) ||
                      fw_rep_values_push(&g->cpa[FW_REP_OWN][sit_type[s]], d)))
        return oom(L);
    return FW_OK;
}

static fw_status read_encounters(loader *L)
{
    fw_study_report *rep = L->rep;
    if (each_run_row(L,
                     "SELECT run_id, situation, min_dist_m, domain_entered, near_miss, collision, "
                     "candidate, outcome, near_miss_centre FROM encounters",
                     encounter_row))
        return L->err->status;
    /* the rows are what the report counts; a different total in runs means
     * the writer and this reader disagree about what an encounter is */
    int bad = 0;
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        int n = 0;
        for (int s = 0; s < FW_REP_NSIT; s++)
            n += r->n_sit[s];
        bad += r->n_encounters_col >= 0 && r->n_encounters_col != n;
    }
    if (bad) {
        char msg[200];
        snprintf(msg, sizeof msg,
                 "%d run%s with runs.n_encounters different from %s encounter rows (the rows are "
                 "counted)", bad, bad == 1 ? "" : "s", bad == 1 ? "its" : "their");
        if (fw_rep_note(&rep->warnings, &rep->n_warnings, msg))
            return oom(L);
    }
    return FW_OK;
}

/* One traffic-level encounter: type, CPA, the own flag, candidate. */
static fw_status traffic_row(loader *L, sqlite3_stmt *st, fw_rep_run *r)
{
    const char *type = col_text(st, 1);
    int t = name_index(fw_rep_type_names + 1, FW_REP_NTYPE - 1, type) + 1;
    if (t <= 0)
        return fw_fail(L->err, FW_EINPUT, "%s: run %lld: unknown traffic encounter type '%s'",
                       L->file, r->run_id, type);
    r->n_traffic[FW_REP_ALL]++;
    r->n_traffic[t]++;
    /* the own ship's pairs are its encounters: the traffic set is the others */
    if (sqlite3_column_int(st, 3) == 0 && count_candidate(L, st, 4, r, FW_REP_TRAFFIC, t))
        return L->err->status;
    double d = col_num(st, 2);
    fw_rep_group *g = &L->rep->groups[r->group];
    if (!isnan(d) && (fw_rep_values_push(&g->cpa[FW_REP_TRAFFIC][FW_REP_ALL], d) ||
                      fw_rep_values_push(&g->cpa[FW_REP_TRAFFIC][t], d)))
        return oom(L);
    return FW_OK;
}

static fw_status read_traffic(loader *L)
{
    return each_run_row(L, "SELECT run_id, type, min_dist_m, own, candidate, outcome "
                           "FROM traffic_encounters", traffic_row);
}

/* One audited encounter: compliant or not, and why not. */
static fw_status audit_row(loader *L, sqlite3_stmt *st, fw_rep_run *r)
{
    fw_study_report *rep = L->rep;
    int k = name_index(fw_rep_situation_names, FW_REP_NSIT, col_text(st, 1));
    if (k < 0)
        return FW_OK; /* unknown situations were refused before */
    fw_rep_group *g = &rep->groups[r->group];
    rep->audited = true;
    g->audited[k]++;
    bool ok = sqlite3_column_int(st, 2) != 0;
    g->compliant[k] += ok;
    if (!ok && fw_rep_note(&rep->audit_notes, &rep->n_audit_notes, col_text(st, 3)))
        return oom(L);
    return FW_OK;
}

/* The COLREGs audit: audited and compliant encounters by situation, and why not. */
static fw_status read_audit(loader *L)
{
    return each_run_row(L, "SELECT run_id, situation, compliant, audit_note FROM encounters "
                           "WHERE compliant IS NOT NULL", audit_row);
}

/* The traffic monitors and the background behaviour, summed over the
 * finished runs; an older database without the columns has none. */
static fw_status read_monitors(loader *L)
{
    fw_study_report *rep = L->rep;
    sqlite3_stmt *st;
    if (sqlite3_prepare_v2(L->db,
                           "SELECT SUM(mon_sideways), SUM(mon_teleport), SUM(mon_overlap), "
                           "SUM(mon_appear), SUM(mon_vanish), SUM(mon_start_close), "
                           "SUM(mon_stopped), SUM(mon_sideways + mon_teleport + mon_overlap + "
                           "mon_appear + mon_vanish + mon_start_close + mon_stopped > 0), "
                           "MAX(max_lateral_mps), SUM(give_way), GROUP_CONCAT(DISTINCT behaviour) "
                           "FROM runs WHERE status = 'ok'",
                           -1, &st, NULL) != SQLITE_OK)
        return FW_OK; /* written before the monitors: nothing to say */
    int rc = sqlite3_step(st);
    if (rc == SQLITE_ROW && sqlite3_column_type(st, 0) != SQLITE_NULL) {
        rep->monitored = true;
        for (int k = 0; k < 7; k++)
            rep->mon[k] = sqlite3_column_int64(st, k);
        rep->mon_runs = sqlite3_column_int(st, 7);
        rep->max_lateral = sqlite3_column_double(st, 8);
        rep->give_way = sqlite3_column_int64(st, 9);
        const unsigned char *b = sqlite3_column_text(st, 10);
        snprintf(rep->behaviour, sizeof rep->behaviour, "%s", b ? (const char *)b : "");
        rc = SQLITE_DONE;
    } else if (rc == SQLITE_ROW) {
        rc = SQLITE_DONE;
    }
    return step_done(L, st, rc);
}

static fw_status read_all(loader *L)
{
    /* every value checked before any is summed (db_check.h) */
    if (read_meta(L) || fw_db_check(L->db, L->file, L->err) || read_failed(L) || read_runs(L))
        return L->err->status;
    if (L->rep->n_runs == 0) {
        if (L->rep->n_failed)
            return fw_fail(L->err, FW_EINPUT, "%s: no finished runs (%d failed, e.g. \"%s\")",
                           L->file, L->rep->n_failed, L->rep->reasons[0].text);
        return fw_fail(L->err, FW_EINPUT, "%s: no finished runs", L->file);
    }
    if (make_groups(L) || read_encounters(L) || read_traffic(L) || read_monitors(L) ||
        read_audit(L) || fw_rep_load_splits(L->rep, L->db, L->file, L->err))
        return L->err->status;
    return FW_OK;
}

/* Is the database in WAL mode (header bytes 18-19 are 2)? */
static bool is_wal(const char *file)
{
    unsigned char h[20] = {0};
    FILE *f = fopen(file, "rb");
    if (!f)
        return false;
    size_t n = fread(h, 1, sizeof h, f);
    fclose(f);
    return n == sizeof h && h[18] == 2 && h[19] == 2;
}

static bool exists(const char *file, const char *ext, off_t *size)
{
    char path[1100];
    struct stat sb;
    snprintf(path, sizeof path, "%s%s", file, ext);
    if (stat(path, &sb) != 0)
        return false;
    if (size)
        *size = sb.st_size;
    return true;
}

/* Opens file read-only.  A database a killed sweep left in WAL mode needs a
 * -shm file, which a reader that cannot write the directory cannot create;
 * then, when no -wal holds commits, it is opened immutable (nothing else can
 * be writing it: a writer would have made the -wal). */
static int open_ro(const char *file, sqlite3 **db)
{
    char *copy = strdup(file);
    if (!copy)
        return SQLITE_NOMEM;
    bool dir_ro = access(dirname(copy), W_OK) != 0;
    free(copy);
    off_t wal = 0;
    if (!dir_ro || !is_wal(file) || (exists(file, "-wal", &wal) && wal > 0))
        return sqlite3_open_v2(file, db, SQLITE_OPEN_READONLY, NULL);
    size_t n = strlen(file);
    char *uri = malloc(3 * n + 32), *p = uri;
    if (!uri)
        return SQLITE_NOMEM;
    p += sprintf(p, "file:");
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)file[i];
        if (isalnum(c) || strchr("/-._~", c))
            *p++ = (char)c;
        else
            p += sprintf(p, "%%%02X", c);
    }
    strcpy(p, "?immutable=1");
    int rc = sqlite3_open_v2(uri, db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, NULL);
    free(uri);
    return rc;
}

/* A reader of a WAL database creates -wal and -shm and cannot remove them;
 * empty ones it made are removed, unless a sweep (holding the file's lock,
 * store.c) is writing it. */
static void tidy(const char *file, bool had_wal, bool had_shm)
{
    off_t wal = 0;
    if ((had_wal || !exists(file, "-wal", &wal) || wal > 0) && (had_shm || !exists(file, "-shm", NULL)))
        return;
    int fd = open(file, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) {
        char path[1100];
        if (!had_wal && exists(file, "-wal", &wal) && wal == 0) {
            snprintf(path, sizeof path, "%s-wal", file);
            unlink(path);
        }
        if (!had_shm && !exists(file, "-wal", NULL)) {
            snprintf(path, sizeof path, "%s-shm", file);
            unlink(path);
        }
    }
    close(fd);
}

fw_status fw_rep_load(fw_study_report *rep, const char *file, fw_error *err)
{
    struct stat sb;
    if (stat(file, &sb) != 0)
        return fw_fail(err, FW_EINPUT, "%s: no such file", file);
    if (!S_ISREG(sb.st_mode))
        return fw_fail(err, FW_EINPUT, "%s: not a file", file);
    if ((size_t)snprintf(rep->db, sizeof rep->db, "%s", file) >= sizeof rep->db)
        return fw_fail(err, FW_EINPUT, "%s: path longer than %zu characters", file,
                       sizeof rep->db - 1);
    loader L = {rep, NULL, file, err};
    bool had_wal = exists(file, "-wal", NULL), had_shm = exists(file, "-shm", NULL);
    if (open_ro(file, &L.db) != SQLITE_OK) {
        fw_fail(err, FW_EINPUT, "%s: cannot open (%s)", file, L.db ? sqlite3_errmsg(L.db) : "?");
        sqlite3_close(L.db);
        return FW_EINPUT;
    }
    /* a sweep may be committing a run right now: wait for it rather than fail */
    sqlite3_busy_timeout(L.db, 10000);
    fw_status st = FW_OK;
    if (sqlite3_exec(L.db, "BEGIN", NULL, NULL, NULL) != SQLITE_OK)
        st = fw_fail(err, FW_EINPUT, "%s: cannot read (%s)", file, sqlite3_errmsg(L.db));
    else
        st = read_all(&L);
    sqlite3_exec(L.db, "COMMIT", NULL, NULL, NULL);
    sqlite3_close(L.db);
    tidy(file, had_wal, had_shm);
    return st;
}
