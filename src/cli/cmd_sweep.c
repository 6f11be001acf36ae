/* fairway sweep: a study's runs into its SQLite database, in parallel. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"
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
           "  --sumo MODE      embedded (default) or remote:HOST:PORT\n"
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
    printf("run_id,density,replication,domain_m,seed,start_along_m,start_across_m\n");
    for (int i = 0; i < fw_study_run_count(s); i++) {
        fw_study_run r = fw_study_run_at(s, i);
        printf("%d,%g,%d,%.1f,%lu,%.1f,%.1f\n", i, r.density, r.replication, r.domain, r.seed,
               r.d_along, r.d_across);
    }
}

int fw_cmd_sweep(int argc, char **argv)
{
    fw_args a = {argc, argv, 0};
    fw_error err = {0};
    fw_sweep_def def = fw_default_sweep_def();
    const char *file = NULL, *v;
    bool dry = false;
    while (a.i < a.argc) {
        if (fw_is_help(a.argv[a.i])) {
            help();
            return 0;
        }
        if (fw_args_opt(&a, "--db", &v, &err)) {
            def.db = v;
        } else if (fw_args_opt(&a, "--jobs", &v, &err)) {
            long n;
            if (fw_parse_long("--jobs", v, &n, &err))
                return fw_report(&err);
            if (n < 1 || n > 1024) {
                fw_fail(&err, FW_EINPUT, "--jobs %ld: give 1 to 1024", n);
                return fw_report(&err);
            }
            def.jobs = (int)n;
        } else if (fw_args_opt(&a, "--limit", &v, &err)) {
            long n;
            if (fw_parse_long("--limit", v, &n, &err))
                return fw_report(&err);
            if (n < 1) {
                fw_fail(&err, FW_EINPUT, "--limit %ld: give at least 1", n);
                return fw_report(&err);
            }
            def.limit = (int)n;
        } else if (fw_args_opt(&a, "--sumo", &v, &err)) {
            if (fw_traffic_mode_parse(v, &def.mode, &err))
                return fw_report(&err);
            if (def.mode.kind == FW_TRAFFIC_GUI) {
                fw_fail(&err, FW_EINPUT, "--sumo gui: a sweep runs without windows; use "
                                         "fairway run for a look at one run");
                return fw_report(&err);
            }
        } else if (fw_args_opt(&a, "--keep", &v, &err)) {
            def.keep_dir = v;
        } else if (fw_args_opt(&a, "--progress", &v, &err)) {
            static const char *const kinds[] = {"auto", "bar", "lines", "none"};
            int k = 0;
            while (k < 4 && strcmp(v, kinds[k]) != 0)
                k++;
            if (k == 4) {
                fw_fail(&err, FW_EINPUT, "--progress %s: use auto, bar, lines or none", v);
                return fw_report(&err);
            }
            def.progress = (fw_progress_kind)k;
        } else if (fw_args_flag(&a, "--retry-failed")) {
            def.retry_failed = true;
        } else if (fw_args_flag(&a, "--dry-run")) {
            dry = true;
        } else if (err.status) {
            return fw_report(&err);
        } else if (a.argv[a.i][0] == '-') {
            fw_fail(&err, FW_EINPUT, "unknown option %s (see fairway sweep --help)", a.argv[a.i]);
            return fw_report(&err);
        } else if (!file) {
            file = a.argv[a.i++];
        } else {
            fw_fail(&err, FW_EINPUT, "one study file at a time (got %s and %s)", file,
                    a.argv[a.i]);
            return fw_report(&err);
        }
    }
    if (!file) {
        fw_fail(&err, FW_EINPUT, "no study file (see fairway sweep --help)");
        return fw_report(&err);
    }
    if (!def.db && !dry) {
        fw_fail(&err, FW_EINPUT, "--db FILE is required: where the results go");
        return fw_report(&err);
    }
    fw_study *s = malloc(sizeof *s);
    if (!s) {
        fw_fail(&err, FW_ERUN, "out of memory");
        return fw_report(&err);
    }
    /* the whole study is checked before any run starts */
    if (fw_study_load(file, s, &err)) {
        free(s);
        return fw_report(&err);
    }
    if (dry) {
        dry_run(s);
        free(s);
        return 0;
    }
    def.study = s;
    fw_sweep_result res;
    bool root = true;
    fw_status st = fw_sweep_under_mpi() ? fw_sweep_mpi(&def, &res, &root, &err)
                                        : fw_sweep_local(&def, &res, &err);
    int rc = 0;
    if (!root) {
        rc = st ? (int)st : 0;
    } else if (st) {
        rc = fw_report(&err);
    } else {
        if (res.interrupted)
            fprintf(stderr, "fairway: sweep interrupted; %d runs are in %s, run the same "
                            "command again to resume\n",
                    res.skipped + res.done + res.failed, def.db);
        if (res.failed || res.failed_before)
            fprintf(stderr, "fairway: %d runs failed (their reasons are in %s, table runs); "
                            "--retry-failed runs them again\n",
                    res.failed + res.failed_before, def.db);
        rc = res.interrupted || res.failed || res.failed_before ? 1 : 0;
    }
    free(s);
    return rc;
}
