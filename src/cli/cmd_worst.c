/* fairway worst: a study's closest encounters as scenarios that replay them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "study/worst.h"

enum { MAX_CASES = 50, REPLAY_TOLERANCE_M = 10 };

static void help(void)
{
    printf("usage: fairway worst FILE --out DIR [--n N] [--study STUDY] [--splits]\n"
           "                    [--situations]\n"
           "\n"
           "Takes the N own-ship encounters of a study database with the smallest\n"
           "hull-to-hull distance (one per run), sails each run again from the study file\n"
           "(the database's study digest must match it) with every target recorded at every\n"
           "step, and writes DIR/case-K/tracks.csv (the targets' tracks) and\n"
           "DIR/case-K/scenario.yaml (the run's own ship, domain and duration, the tracks\n"
           "as its traffic).  `fairway run DIR/case-K/scenario.yaml` replays the case\n"
           "without SUMO.  Each scenario is replayed once here, and its closest approach is\n"
           "compared with the database's.\n"
           "\n"
           "  --splits       instead: for a study with estimate:, each cell's closest\n"
           "                 trajectory splitting found (table splits, best_path) run\n"
           "                 again into DIR/split-cell-K with its full records; prints\n"
           "                 its closeness as the database has it and as the replay gives\n"
           "                 it (the same: the path names every draw)\n"
           "  --situations   also DIR/case-K/situation.json: the case as a DNV traffic\n"
           "                 situation (the tracks simplified to 0.25 m, src/run/\n"
           "                 dnv_situation.h), read back and sailed into\n"
           "                 DIR/case-K/situation; prints its closest approach too\n"
           "  --out DIR      where the cases go (created)\n"
           "  --n N          how many cases (1 to %d, default 1)\n"
           "  --study FILE   the study file, when the one named in the database's meta\n"
           "                 (relative to where the sweep ran) is elsewhere now\n"
           "\n"
           "Exit codes: 0 every replay within %d m of the database's closest approach,\n"
           "1 a run failed or a replay did not reproduce it, 2 bad input.\n",
           MAX_CASES, REPLAY_TOLERANCE_M);
}

/* --splits: each cell's closest trajectory that splitting found, run again. */
static int worst_splits(const fw_worst_def *def, fw_error *err)
{
    enum { kMaxCells = 512 };
    fw_worst_split *w = malloc(kMaxCells * sizeof *w);
    int got = 0, bad = 0;
    if (!w)
        return fw_report((fw_fail(err, FW_ERUN, "out of memory"), err));
    if (fw_worst_splits(def, w, kMaxCells, &got, err)) {
        free(w);
        return fw_report(err);
    }
    printf("cell,db_closeness,replay_closeness,replay_min_hull_m,path,dir\n");
    for (int i = 0; i < got; i++) {
        printf("%d,%.6f,%.6f,%.2f,\"%s\",%s\n", w[i].cell, w[i].db_closeness, w[i].replay_closeness,
               w[i].replay_hull, w[i].path, w[i].dir);
        bad += !(fabs(w[i].replay_closeness - w[i].db_closeness) <= 1e-6);
    }
    if (bad)
        fprintf(stderr, "fairway worst: %d replay%s not the closeness the database has\n", bad,
                bad == 1 ? "" : "s");
    free(w);
    return bad ? 1 : 0;
}

int fw_cmd_worst(int argc, char **argv)
{
    fw_error err = {0};
    fw_worst_def def = fw_default_worst_def();
    long n = 1;
    bool splits = false;
    const fw_opt opts[] = {
        FW_OPT("--out", FW_OPT_TEXT, &def.out), FW_OPT("--n", FW_OPT_LONG, &n),
        FW_OPT("--study", FW_OPT_TEXT, &def.study), FW_OPT("--splits", FW_OPT_FLAG, &splits),
        FW_OPT("--situations", FW_OPT_FLAG, &def.situations), FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "worst", opts, help, fw_args_one_file, &def.db, &err);
    if (rc >= 0)
        return rc;
    if (!def.db || !def.out)
        return fw_report((fw_fail(&err, FW_EINPUT, "give a study database and --out DIR (see "
                                                   "fairway worst --help)"), &err));
    if (splits)
        return worst_splits(&def, &err);
    if (n < 1 || n > MAX_CASES)
        return fw_report((fw_fail(&err, FW_EINPUT, "--n %ld: give 1 to %d", n, MAX_CASES), &err));
    def.n = (int)n;
    fw_worst_case cases[MAX_CASES];
    int got = 0;
    if (fw_worst_export(&def, cases, &got, &err))
        return fw_report(&err);
    printf("case,run_id,target,db_min_m,db_hull_m,rerun_min_m,replay_min_m,dir%s\n",
           def.situations ? ",situation_min_m" : "");
    int bad = 0;
    for (int i = 0; i < got; i++) {
        const fw_worst_case *c = &cases[i];
        printf("%d,%d,%s,%.2f,%.2f,%.2f,%.2f,%s", i + 1, c->run_id, c->target, c->db_min,
               c->db_hull, c->rerun_min, c->replay_min, c->dir);
        if (def.situations)
            printf(",%.2f", c->situation_min);
        printf("\n");
        bad += !(fabs(c->replay_min - c->db_min) <= REPLAY_TOLERANCE_M);
    }
    if (bad)
        fprintf(stderr, "fairway worst: %d replay%s not within %d m of the database's closest "
                        "approach\n", bad, bad == 1 ? "" : "s", REPLAY_TOLERANCE_M);
    return bad ? 1 : 0;
}
