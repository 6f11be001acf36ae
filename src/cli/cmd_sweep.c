/* fairway sweep: a study's runs into its SQLite database, in parallel. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/units.h"
#include "study/study.h"
#include "study/sweep.h"

static void help(void)
{
    printf("usage: fairway sweep STUDY --db FILE [--jobs N] [options]\n"
           "       mpirun -np K fairway sweep STUDY --db FILE [options]\n"
           "\n"
           "Runs every (density, replication, domain size) of the study file (YAML, see\n"
           "scenarios/studies/README.md) and commits each finished run, with its\n"
           "aggregates and one row per encounter, to the SQLite database FILE in one\n"
           "transaction.  Replication i uses the same traffic (SUMO seed, demand, own-ship\n"
           "start) for every domain size, so domain sizes are compared pairwise.\n"
           "\n"
           "Running the same command again resumes: runs already in FILE are skipped.\n"
           "Ctrl-C, SIGTERM or even SIGKILL lose at most the runs in flight; FILE stays\n"
           "consistent.  A run that fails is recorded with its reason and the sweep goes\n"
           "on.  Under mpirun, rank 0 writes FILE and the other ranks run.\n"
           "\n"
           "  --db FILE        the study database (created if missing)\n"
           "  --jobs N         worker processes (default: one per core)\n"
           "  --sumo MODE      embedded (default) or remote:HOST:PORT (FAIRWAY_SUMO_TIMEOUT=S:\n"
           "                   the seconds it has to connect and to begin each answer,\n"
           "                   default 10 and 60)\n"
           "  --keep DIR       keep every run's directory (CSV histories, logs) in DIR\n"
           "  --retry-failed   run again the runs recorded as failed\n"
           "  --limit N        stop after N new runs\n"
           "  --progress KIND  auto (default: a bar on a terminal), bar, lines or none\n"
           "  --dry-run        check the study and print the run list, run nothing\n"
           "\n"
           "Then: fairway report FILE.\n"
           "Exit codes: 0 every run ok, 1 a run failed or the sweep was interrupted,\n"
           "2 bad input (nothing is run).\n");
}

static void dry_run(const fw_study *s)
{
    printf("study %s (%s): scenario %s, %d runs\n", s->name, s->file, s->scenario_file,
           fw_study_run_count(s));
    /* over recorded traffic the window's later start too */
    bool ais = s->base.ais.file[0] != '\0';
    printf("run_id,density,replication,behaviour,domain_m,fore_aft_ratio,seed,start_along_m,"
           "start_across_m%s%s\n", ais ? ",ais_later_s" : "", s->n_axes ? ",setting" : "");
    for (int i = 0; i < fw_study_run_count(s); i++) {
        fw_study_run r = fw_study_run_at(s, i);
        printf("%d,%g,%d,%s,%.1f,%g,%lu,%.1f,%.1f", i, r.density, r.replication,
               fw_behaviour_name(r.behaviour), r.domain, r.ratio, r.seed, r.d_along, r.d_across);
        if (ais)
            printf(",%.1f", r.d_time);
        char label[256];
        if (s->n_axes) /* quoted: it lists its keys with commas */
            printf(",\"%s\"", fw_study_setting_label(s, r.setting_index, label, sizeof label));
        printf("\n");
    }
}

typedef struct sweep_opts {
    fw_sweep_def def;
    const char *file;
    bool dry;
} sweep_opts;

/* An integer option within [lo, hi] (hi = INT_MAX: no upper bound). */
static fw_status parse_count(const char *opt, const char *v, long lo, long hi, int *out,
                             fw_error *err)
{
    long n;
    fw_status st = fw_parse_long(opt, v, &n, err);
    if (st)
        return st;
    if (n < lo && hi == INT_MAX)
        return fw_fail(err, FW_EINPUT, "%s %ld: give at least %ld", opt, n, lo);
    if (n < lo || n > hi)
        return fw_fail(err, FW_EINPUT, "%s %ld: give %ld to %ld", opt, n, lo, hi);
    *out = (int)n;
    return FW_OK;
}

static fw_status parse_progress(const char *v, fw_progress_kind *out, fw_error *err)
{
    static const char *const kinds[] = {"auto", "bar", "lines", "none"};
    for (int k = 0; k < 4; k++)
        if (strcmp(v, kinds[k]) == 0) {
            *out = (fw_progress_kind)k;
            return FW_OK;
        }
    return fw_fail(err, FW_EINPUT, "--progress %s: use auto, bar, lines or none", v);
}

static fw_status opt_jobs(void *ctx, const char *name, const char *v, fw_error *err)
{
    return parse_count(name, v, 1, 1024, ctx, err);
}

static fw_status opt_limit(void *ctx, const char *name, const char *v, fw_error *err)
{
    return parse_count(name, v, 1, INT_MAX, ctx, err);
}

static fw_status opt_progress(void *ctx, const char *name, const char *v, fw_error *err)
{
    (void)name;
    return parse_progress(v, ctx, err);
}

static fw_status opt_sumo(void *ctx, const char *name, const char *v, fw_error *err)
{
    fw_traffic_mode *mode = ctx;
    if (fw_traffic_mode_parse(v, mode, err) || fw_check_sumo_mode(name, mode, err))
        return err->status;
    if (mode->kind == FW_TRAFFIC_GUI)
        return fw_fail(err, FW_EINPUT, "--sumo gui: a sweep runs without windows; use "
                                       "fairway run for a look at one run");
    return FW_OK;
}

/* Returns -1 to go on, else the exit code. */
static int parse_options(int argc, char **argv, sweep_opts *o, fw_error *err)
{
    fw_sweep_def *def = &o->def;
    const fw_opt opts[] = {
        FW_OPT("--db", FW_OPT_TEXT, &def->db),      FW_OPT_FN("--jobs", opt_jobs, &def->jobs),
        FW_OPT_FN("--limit", opt_limit, &def->limit), FW_OPT_FN("--sumo", opt_sumo, &def->mode),
        FW_OPT("--keep", FW_OPT_TEXT, &def->keep_dir),
        FW_OPT_FN("--progress", opt_progress, &def->progress),
        FW_OPT("--retry-failed", FW_OPT_FLAG, &def->retry_failed),
        FW_OPT("--dry-run", FW_OPT_FLAG, &o->dry),  FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "sweep", opts, help, fw_args_one_file, &o->file, err);
    if (rc >= 0)
        return rc;
    if (!o->file)
        return fw_report((fw_fail(err, FW_EINPUT, "no study file (see fairway sweep --help)"), err));
    if (!o->def.db && !o->dry)
        return fw_report(
            (fw_fail(err, FW_EINPUT, "--db FILE is required: where the results go"), err));
    return -1;
}

static int finish(const fw_sweep_def *def, fw_status st, const fw_sweep_result *res, bool root,
                  fw_error *err)
{
    if (!root)
        return st ? (int)st : 0;
    if (st)
        return fw_report(err);
    if (res->interrupted)
        fprintf(stderr, "fairway: sweep interrupted; %d runs are in %s, run the same "
                        "command again to resume\n",
                res->skipped + res->done + res->failed, def->db);
    if (res->failed || res->failed_before)
        fprintf(stderr, "fairway: %d runs failed (their reasons are in %s, table runs); "
                        "--retry-failed runs them again\n",
                res->failed + res->failed_before, def->db);
    return res->interrupted || res->failed || res->failed_before ? 1 : 0;
}

int fw_cmd_sweep(int argc, char **argv)
{
    fw_error err = {0};
    sweep_opts o = {.def = fw_default_sweep_def()};
    int rc = parse_options(argc, argv, &o, &err);
    if (rc >= 0)
        return rc;
    fw_study *s = malloc(sizeof *s);
    if (!s)
        return fw_report((fw_fail(&err, FW_ERUN, "out of memory"), &err));
    /* the whole study is checked before any run starts */
    if (fw_study_load(o.file, s, &err)) {
        free(s);
        return fw_report(&err);
    }
    if (o.dry) {
        dry_run(s);
        free(s);
        return 0;
    }
    fw_warn_nomoto_speed(&s->base.ship, fw_ms_to_kn(s->base.speed), s->scenario_file,
                         "own_ship.speed_kn");
    /* --keep is made (and checked) before the database exists: a file there
     * would otherwise fail every run */
    if (o.def.keep_dir && (fw_mkdirs(o.def.keep_dir, "--keep", &err) ||
                           (access(o.def.keep_dir, W_OK | X_OK) != 0 &&
                            fw_fail(&err, FW_EINPUT, "--keep %s: cannot write in it: %s",
                                    o.def.keep_dir, strerror(errno))))) {
        free(s);
        return fw_report(&err);
    }
    o.def.study = s;
    fw_sweep_result res;
    bool root = true;
    fw_status st = fw_sweep_under_mpi() ? fw_sweep_mpi(&o.def, &res, &root, &err)
                                        : fw_sweep_local(&o.def, &res, &err);
    rc = finish(&o.def, st, &res, root, &err);
    free(s);
    return rc;
}
