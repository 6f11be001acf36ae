/* fairway report: statistics, tables, plots and a summary of a study database. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "study/report.h"

static void help(void)
{
    printf("usage: fairway report FILE [--out DIR] [--reference M] [--no-plots] [--json]\n"
           "\n"
           "Reads a study database written by fairway sweep (read-only; a sweep may still\n"
           "be running) and reports, for each density and domain size, the mean over\n"
           "replications with its 95%% confidence interval of: own-ship encounters per\n"
           "ship-hour (total, by type and by situation), domain violations (per hour and as\n"
           "a share of encounters), near misses and collisions per hour, the share of runs\n"
           "with a near miss or a collision (Wilson interval), the run's closest approach,\n"
           "avoidance manoeuvres and helm orders per hour, the largest helm, path\n"
           "lengthening and time lost per hour; CPA percentiles (p5 to p95, pooled); and\n"
           "traffic-level encounters per 1000 ship-hours by type.  Each measure is also\n"
           "compared with the reference domain size replication by replication (every\n"
           "domain size sailed the same traffic in replication i).  Only runs with status\n"
           "ok count; failed runs are counted with their reasons.\n"
           "\n"
           "  --out DIR        report directory (default: FILE's stem + \"-report\" beside\n"
           "                   it); an earlier report there is replaced, a directory\n"
           "                   holding anything else is refused (nothing in it touched)\n"
           "  --reference M    domain size (m) the others are compared with (default: the\n"
           "                   smallest)\n"
           "  --no-plots       write the tables and report.md only\n"
           "  --json           print the measures as one JSON object instead of the table\n"
           "\n"
           "DIR gets summary.csv, traffic.csv, paired.csv, cpa.csv, cpa_hist.csv, runs.csv,\n"
           "report.md (one page) and the PNGs drawn by analysis/plot_study.py with\n"
           "$FAIRWAY_PYTHON (default /usr/bin/python3, which needs matplotlib and pandas).\n"
           "Exit codes: 0 ok, 1 plotting failed (tables and report.md are written),\n"
           "2 bad input (missing file, not a study database, no finished runs, unknown\n"
           "--reference; nothing is written).\n");
}

int fw_cmd_report(int argc, char **argv)
{
    fw_error err = {0};
    fw_study_report_def def = fw_default_study_report_def();
    bool json = false;
    bool no_plots = false, ref_given = false;
    const fw_opt opts[] = {
        FW_OPT("--out", FW_OPT_TEXT, &def.out),
        FW_OPT_SEEN("--reference", FW_OPT_DOUBLE, &def.reference_m, &ref_given),
        FW_OPT("--no-plots", FW_OPT_FLAG, &no_plots), FW_OPT("--json", FW_OPT_FLAG, &json),
        FW_OPT_END,
    };
    int rc = fw_args_parse(argc, argv, "report", opts, help, fw_args_one_file, &def.db, &err);
    if (rc >= 0)
        return rc;
    def.plots = !no_plots;
    if (ref_given && !(def.reference_m > 0.0))
        return fw_report((fw_fail(&err, FW_EINPUT, "--reference: must be positive"), &err));
    if (!def.db)
        return fw_report((fw_fail(&err, FW_EINPUT, "no study database given (see fairway report --help)"), &err));
    fw_study_report *rep;
    if (fw_study_report_load(&def, &rep, &err))
        return fw_report(&err);
    fw_study_report_result res;
    fw_status st = fw_study_report_write(rep, &def, &res, &err);
    /* a plotting failure still wrote the report: show it, then say what failed */
    if (st == FW_OK || res.plots == FW_PLOTS_FAILED)
        fw_study_report_print(stdout, rep, &res, json);
    fw_study_report_free(rep);
    fflush(stdout);
    if (st)
        return fw_report(&err);
    return 0;
}
