/* worst.c - a study's worst encounters exported as replayable scenarios (worst.h). */
#include "study/worst.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files.h"
#include "run/dnv_situation.h"
#include "run/encounter_record.h"
#include "run/run.h"
#include "scenario/scn_dnv.h"
#include "study/db_check.h"
#include "study/study.h"
#include "yaml/yaml_tree.h"

fw_worst_def fw_default_worst_def(void)
{
    fw_worst_def d = {.db = NULL, .study = NULL, .out = NULL, .n = 1};
    d.mode = fw_default_run_def().mode;
    return d;
}

static double col_num(sqlite3_stmt *q, int i)
{
    return sqlite3_column_type(q, i) == SQLITE_NULL ? NAN : sqlite3_column_double(q, i);
}

/* meta's study file and digest, and the closest encounters, one per run. */
fw_status fw_worst_open(const fw_worst_def *def, sqlite3 **dbp, char *study, size_t sz,
                        char *digest, fw_error *err)
{
    sqlite3 *db = NULL;
    sqlite3_stmt *q = NULL;
    fw_status st = FW_OK;
    *dbp = NULL;
    if (sqlite3_open_v2(def->db, &db, SQLITE_OPEN_READONLY, NULL) != SQLITE_OK ||
        sqlite3_prepare_v2(db, "SELECT key, value FROM meta WHERE key IN ('study_file', "
                               "'study_digest')", -1, &q, NULL) != SQLITE_OK) {
        st = fw_fail(err, FW_EINPUT, "%s: not a fairway study database (%s)", def->db,
                     db ? sqlite3_errmsg(db) : "cannot open");
        goto out;
    }
    /* a tampered value would be printed as the case's distance (db_check.h) */
    if ((st = fw_db_check(db, def->db, err)))
        goto out;
    while (sqlite3_step(q) == SQLITE_ROW) {
        const char *k = (const char *)sqlite3_column_text(q, 0);
        k = k ? k : "";
        const char *v = (const char *)sqlite3_column_text(q, 1);
        if (strcmp(k, "study_file") == 0)
            snprintf(study, sz, "%s", v ? v : "");
        else
            snprintf(digest, 32, "%s", v ? v : "");
    }
out:
    sqlite3_finalize(q);
    if (st)
        sqlite3_close(db);
    else
        *dbp = db;
    return st;
}

static fw_status select_cases(const fw_worst_def *def, char *study, size_t sz, char *digest,
                              fw_worst_case *cases, int *n, fw_error *err)
{
    sqlite3 *db = NULL;
    sqlite3_stmt *q = NULL;
    *n = 0;
    fw_status st = fw_worst_open(def, &db, study, sz, digest, err);
    if (st)
        return st;
    /* hull to hull first (it is what touches); runs that failed do not count */
    if (sqlite3_prepare_v2(db, "SELECT e.run_id, e.target, e.min_dist_m, e.min_hull_m FROM "
                               "encounters e JOIN runs r USING(run_id) WHERE r.status = 'ok' AND "
                               "e.min_dist_m IS NOT NULL ORDER BY COALESCE(e.min_hull_m, 1e12), "
                               "e.min_dist_m, e.run_id",
                           -1, &q, NULL) != SQLITE_OK) {
        st = fw_fail(err, FW_EINPUT, "%s: no encounters table (%s)", def->db, sqlite3_errmsg(db));
        goto out;
    }
    while (*n < def->n && sqlite3_step(q) == SQLITE_ROW) {
        int run = sqlite3_column_int(q, 0);
        bool seen = false;
        for (int i = 0; i < *n; i++)
            seen |= cases[i].run_id == run;
        if (seen)
            continue;
        fw_worst_case *c = &cases[(*n)++];
        memset(c, 0, sizeof *c);
        c->run_id = run;
        snprintf(c->target, sizeof c->target, "%s", (const char *)sqlite3_column_text(q, 1));
        c->db_min = col_num(q, 2);
        c->db_hull = col_num(q, 3);
    }
    if (*n == 0)
        st = fw_fail(err, FW_EINPUT, "%s: no finished run with an encounter", def->db);
out:
    sqlite3_finalize(q);
    sqlite3_close(db);
    return st;
}

/* ---- YAML out: the base scenario's tree with a few values replaced ---- */

typedef struct yover {
    const char *key;
    const char *value; /* a scalar as written; NULL: leave the key out */
} yover;

static void scalar(FILE *f, const yt_node *n)
{
    if (!n->quoted) {
        fputs(n->str ? n->str : "", f);
        return;
    }
    fputc('"', f);
    for (const char *p = n->str; p && *p; p++) {
        if (*p == '"' || *p == '\\')
            fputc('\\', f);
        fputc(*p, f);
    }
    fputc('"', f);
}

static void emit(FILE *f, const yt_node *n, int indent);

static void emit_value(FILE *f, const yt_node *v, int indent)
{
    if (v->kind == YT_SCALAR) {
        fputc(' ', f);
        scalar(f, v);
        fputc('\n', f);
    } else if (v->kind == YT_SEQ && v->n == 0) {
        fputs(" []\n", f);
    } else {
        fputc('\n', f);
        emit(f, v, indent + 2);
    }
}

static void emit(FILE *f, const yt_node *n, int indent)
{
    for (size_t i = 0; i < n->n; i++) {
        if (n->kind == YT_MAP) {
            fprintf(f, "%*s%s:", indent, "", n->keys[i]);
            emit_value(f, n->items[i], indent);
        } else if (n->items[i]->kind == YT_SCALAR) {
            fprintf(f, "%*s- ", indent, "");
            scalar(f, n->items[i]);
            fputc('\n', f);
        } else {
            fprintf(f, "%*s-\n", indent, "");
            emit(f, n->items[i], indent + 2);
        }
    }
}

/* A map's entries with the given keys' values replaced (or added at the end,
 * or left out). */
static void emit_map(FILE *f, const char *name, const yt_node *map, const yover *o, int n_o)
{
    fprintf(f, "%s:\n", name);
    bool done[16] = {false};
    for (size_t i = 0; map && i < map->n; i++) {
        int k = -1;
        for (int j = 0; j < n_o; j++)
            if (strcmp(map->keys[i], o[j].key) == 0)
                k = j;
        if (k < 0) {
            fprintf(f, "  %s:", map->keys[i]);
            emit_value(f, map->items[i], 2);
            continue;
        }
        done[k] = true;
        if (o[k].value)
            fprintf(f, "  %s: %s\n", o[k].key, o[k].value);
    }
    for (int j = 0; j < n_o; j++)
        if (!done[j] && o[j].value)
            fprintf(f, "  %s: %s\n", o[j].key, o[j].value);
}

static fw_status write_scenario(const fw_study *s, const fw_scenario *scn, const fw_worst_case *c,
                                const char *path, fw_error *err)
{
    yt_doc *doc = NULL;
    fw_status st = yt_load_file(s->scenario_file, &doc, err);
    if (st)
        return st;
    char tmp[1300];
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f) {
        yt_free(doc);
        return err->status;
    }
    char east[40], north[40], dom[40], ratio[40], dur[40], rec[40];
    snprintf(east, sizeof east, "%.3f", scn->east);
    snprintf(north, sizeof north, "%.3f", scn->north);
    snprintf(dom, sizeof dom, "%.17g", scn->helm.domain.size);
    snprintf(ratio, sizeof ratio, "%.17g", scn->helm.domain.fore_aft_ratio);
    snprintf(dur, sizeof dur, "%.17g", scn->duration);
    snprintf(rec, sizeof rec, "%.17g", scn->step);
    fprintf(f, "# Worst case of study %s: run %d, target %s, %.1f m centre to centre "
               "(written by fairway worst from %s).\n# The targets replay their recorded tracks; "
               "the own ship sails and decides again.\nname: %s-worst-%d\n"
               "description: \"%s run %d: closest approach to %s\"\n",
            s->name, c->run_id, c->target, c->db_min, s->scenario_file, s->name, c->run_id,
            s->name, c->run_id, c->target);
    const yt_node *root = doc->root;
    const yover own[] = {{"east_m", east}, {"north_m", north}};
    const yover traffic[] = {{"behaviour", "blind"}, {"tracks", "tracks.csv"}};
    const yover avoid[] = {{"domain_m", dom}, {"fore_aft_ratio", ratio}};
    const yover run[] = {{"duration_s", dur}};
    const yover out[] = {{"targets_csv", "true"}, {"record_every_s", rec}};
    emit_map(f, "own_ship", yt_get(root, "own_ship"), own, 2);
    emit_map(f, "traffic", NULL, traffic, 2);
    emit_map(f, "avoidance", yt_get(root, "avoidance"), avoid, 2);
    emit_map(f, "run", yt_get(root, "run"), run, 1);
    emit_map(f, "outputs", NULL, out, 2);
    yt_free(doc);
    return fw_file_commit(f, tmp, path, err);
}

/* ---- tracks: the re-run's targets.csv with each ship's type and size ---- */

typedef struct ship_info {
    char id[64], type[64];
    double length, breadth;
} ship_info;

static fw_status read_sizes(const char *path, ship_info **out, int *n, fw_error *err)
{
    FILE *f = fopen(path, "r");
    *out = NULL;
    *n = 0;
    if (!f)
        return fw_fail(err, FW_ERUN, "cannot read %s", path);
    char line[2048], *c[32];
    /* the columns as the encounter record's table has them */
    int ci = fw_enc_csv_column("id"), ct = fw_enc_csv_column("type"),
        cl = fw_enc_csv_column("length_m"), cb = fw_enc_csv_column("breadth_m");
    int need = 1 + ci;
    need = need > ct + 1 ? need : ct + 1;
    need = need > cl + 1 ? need : cl + 1;
    need = need > cb + 1 ? need : cb + 1;
    fw_status st = FW_OK;
    if (!fgets(line, sizeof line, f))
        st = fw_fail(err, FW_ERUN, "%s: empty", path);
    while (!st && fgets(line, sizeof line, f)) {
        if (fw_csv_split(line, c, 32) < need)
            continue;
        ship_info *p = realloc(*out, (size_t)(*n + 1) * sizeof *p);
        if (!p) {
            st = fw_fail(err, FW_ERUN, "out of memory");
            break;
        }
        *out = p;
        snprintf(p[*n].id, sizeof p[*n].id, "%s", c[ci]);
        snprintf(p[*n].type, sizeof p[*n].type, "%s", c[ct]);
        p[*n].length = atof(c[cl]);
        p[(*n)++].breadth = atof(c[cb]);
    }
    fclose(f);
    return st;
}

/* The columns of targets.csv's header that hold a ship's turn (records.h),
 * -1 each when it has none. */
static void turn_columns(char *header, int *rate, int *to)
{
    char *c[32];
    int n = fw_csv_split(header, c, 32);
    *rate = *to = -1;
    for (int i = 0; i < n; i++)
        if (strcmp(c[i], "turn_rate_degps") == 0)
            *rate = i;
        else if (strcmp(c[i], "turn_to_deg") == 0)
            *to = i;
}

/* run_dir/targets.csv (t_s,id,east_m,north_m,heading_deg,speed_kn,...,
 * turn_rate_degps,turn_to_deg) and run_dir/encounters.csv
 * (id,type,length_m,breadth_m,...) into tracks: each ship's turn, as the own
 * ship saw it, with it (source_track.h), so that the replay's own ship
 * expects what the run's did. */
static fw_status write_tracks(const char *run_dir, const char *path, fw_error *err)
{
    char tp[1200], ep[1200], tmp[1300], line[2048], *c[32];
    ship_info *info = NULL;
    int n_info = 0, cr = -1, ct = -1;
    fw_status st;
    if ((st = fw_path(tp, sizeof tp, err, "%s/targets.csv", run_dir)) ||
        (st = fw_path(ep, sizeof ep, err, "%s/encounters.csv", run_dir)))
        return st;
    st = read_sizes(ep, &info, &n_info, err);
    FILE *in = st ? NULL : fopen(tp, "r");
    if (!st && !in)
        st = fw_fail(err, FW_ERUN, "cannot read %s: %s", tp, strerror(errno));
    FILE *out = st ? NULL : fw_file_begin(path, tmp, sizeof tmp, err);
    if (!st && !out)
        st = err->status;
    if (!st && !fgets(line, sizeof line, in))
        st = fw_fail(err, FW_ERUN, "%s: empty", tp);
    if (!st) {
        turn_columns(line, &cr, &ct);
        fprintf(out, "t_s,id,type,east_m,north_m,course_deg,speed_kn,length_m,breadth_m,"
                     "turn_rate_degps,turn_to_deg\n");
    }
    while (!st && fgets(line, sizeof line, in)) {
        int n = fw_csv_split(line, c, 32);
        if (n < 6)
            continue;
        const ship_info *s = NULL;
        for (int i = 0; i < n_info && !s; i++)
            if (strcmp(info[i].id, c[1]) == 0)
                s = &info[i];
        bool turn = cr >= 0 && ct >= 0 && cr < n && ct < n;
        fprintf(out, "%s,%s,%s,%s,%s,%s,%s,%.1f,%.1f,%s,%s\n", c[0], c[1], s ? s->type : "",
                c[2], c[3], c[4], c[5], s ? s->length : 0.0, s ? s->breadth : 0.0,
                turn ? c[cr] : "", turn ? c[ct] : "");
    }
    if (in)
        fclose(in);
    if (out && st)
        fw_file_abort(out, tmp);
    else if (out)
        st = fw_file_commit(out, tmp, path, err);
    free(info);
    return st;
}

/* ---- sailing: the run again, and the replay ---- */

/* Runs scn into dir and gives the closest approach to target (NAN: not met). */
static fw_status sail(const fw_scenario *scn, const char *dir, const char *target,
                      fw_traffic_mode mode, double *min_dist, fw_error *err)
{
    fw_remove_tree(dir); /* a symlink there goes, never what it points to */
    if (mkdir(dir, 0777) != 0)
        return fw_fail(err, FW_ERUN, "cannot create %s: %s", dir, strerror(errno));
    fw_run_def d = fw_default_run_def();
    d.scenario = scn;
    d.dir = dir;
    d.mode = mode;
    fw_run_summary sum;
    fw_encounter *e = NULL;
    int n = 0;
    fw_status st = fw_run_scenario(&d, &sum, &e, &n, err);
    *min_dist = NAN;
    for (int i = 0; !st && i < n; i++)
        if (strcmp(e[i].id, target) == 0)
            *min_dist = e[i].min_dist;
    free(e);
    return st;
}

/* The case as a DNV situation (worst.h), read back and sailed. */
static fw_status export_situation(const fw_worst_def *def, fw_worst_case *c, const char *tracks,
                                  fw_scenario *scn, fw_error *err)
{
    char json[1200], run[1200], ship[1024], id[16] = "";
    fw_rec_track *tr = NULL;
    int n = 0;
    fw_status st;
    if ((st = fw_path(json, sizeof json, err, "%s/situation.json", c->dir)) ||
        (st = fw_path(run, sizeof run, err, "%s/situation", c->dir)) ||
        (st = fw_path_copy(ship, sizeof ship, scn->ship.file, err)) ||
        (st = fw_rec_tracks_load(tracks, &tr, &n, err)))
        return st;
    for (int i = 0; i < n; i++) /* the situation's ids: 2, 3, ... in track order */
        if (strcmp(tr[i].info.id, c->target) == 0)
            snprintf(id, sizeof id, "%d", i + 2);
    st = fw_dnv_situation_write(scn, tr, n, FW_DNV_TOLERANCE_M, json, err);
    fw_rec_tracks_free(tr, n);
    if (st || (st = fw_scn_dnv_load(json, ship, scn, err)))
        return st;
    return sail(scn, run, id, def->mode, &c->situation_min, err);
}

static fw_status export_case(const fw_worst_def *def, const fw_study *s, fw_worst_case *c,
                             int k, fw_scenario *scn, fw_error *err)
{
    char run_dir[1200], tracks[1200], yaml[1200], replay[1200];
    fw_status st;
    if ((st = fw_path(c->dir, sizeof c->dir, err, "%s/case-%d", def->out, k + 1)) ||
        (st = fw_path(run_dir, sizeof run_dir, err, "%s/rerun", c->dir)) ||
        (st = fw_path(tracks, sizeof tracks, err, "%s/tracks.csv", c->dir)) ||
        (st = fw_path(yaml, sizeof yaml, err, "%s/scenario.yaml", c->dir)) ||
        (st = fw_path(replay, sizeof replay, err, "%s/replay", c->dir)) ||
        (st = fw_mkdir_own(c->dir, "--out", err)))
        return st;
    fw_study_run r = fw_study_run_at(s, c->run_id);
    fw_study_scenario(s, &r, scn);
    scn->targets_csv = true;      /* every target seen ... */
    scn->record_every = scn->step; /* ... at every step */
    if ((st = sail(scn, run_dir, c->target, def->mode, &c->rerun_min, err)) ||
        (st = write_tracks(run_dir, tracks, err)) ||
        (st = write_scenario(s, scn, c, yaml, err)))
        return st;
    /* SUMO's files and the full histories: large, and made again at will */
    fw_remove_tree(run_dir);
    if ((st = fw_scenario_load(yaml, scn, err)) ||
        (st = sail(scn, replay, c->target, def->mode, &c->replay_min, err)))
        return st;
    c->situation_min = NAN;
    return def->situations ? export_situation(def, c, tracks, scn, err) : FW_OK;
}

fw_status fw_worst_study(const fw_worst_def *def, const char *study_file, const char *digest,
                         fw_study *s, fw_error *err)
{
    const char *file = def->study ? def->study : study_file;
    fw_status st = fw_study_load(file, s, err);
    if (st)
        return st;
    char now[32];
    snprintf(now, sizeof now, "%016" PRIx64, s->digest);
    if (strcmp(now, digest) != 0)
        return fw_fail(err, FW_EINPUT,
                       "%s: not the study of %s (its settings or scenario changed since the "
                       "sweep): its runs cannot be sailed again", file, def->db);
    return FW_OK;
}

fw_status fw_worst_export(const fw_worst_def *def, fw_worst_case *cases, int *n, fw_error *err)
{
    char study_file[1024] = "", digest[32] = "";
    fw_status st = select_cases(def, study_file, sizeof study_file, digest, cases, n, err);
    if (st)
        return st;
    fw_study *s = malloc(sizeof *s);
    fw_scenario *scn = malloc(sizeof *scn);
    if (!s || !scn) {
        free(s);
        free(scn);
        return fw_fail(err, FW_ERUN, "out of memory");
    }
    const char *file = def->study ? def->study : study_file;
    if ((st = fw_worst_study(def, study_file, digest, s, err)))
        goto out;
    /* a database without meta's runs was not bounded by db_check: the study is */
    for (int k = 0; k < *n && !st; k++)
        if (cases[k].run_id < 0 || cases[k].run_id >= fw_study_run_count(s))
            st = fw_fail(err, FW_EINPUT, "%s: table encounters, column run_id: %d is not a run "
                         "of %s (%d runs)", def->db, cases[k].run_id, file, fw_study_run_count(s));
    if (st || (st = fw_mkdirs(def->out, "--out", err)))
        goto out;
    for (int k = 0; k < *n && !st; k++)
        st = export_case(def, s, &cases[k], k, scn, err);
out:
    free(s);
    free(scn);
    return st;
}
