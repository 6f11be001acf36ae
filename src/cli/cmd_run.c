/* fairway run: scenarios with SUMO traffic, full records, one table row each.
 *
 * Every scenario file is loaded and checked before anything is created, so a
 * bad file leaves no output behind.  Each run writes into a hidden temporary
 * directory next to its final place and is renamed into place at the end.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "avoid/helm_search.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/units.h"
#include "run/run.h"
#include "scenario/scenario.h"

static void help(void)
{
    printf("usage: fairway run SCENARIO... [--out DIR] [--sumo MODE] [--json]\n"
           "\n"
           "Runs each scenario file (YAML, see scenarios/README.md): SUMO moves the\n"
           "targets and background traffic, the own ship is stepped with the MMG model\n"
           "and steered by the Nomoto avoidance policy every step.  Each run writes\n"
           "DIR/NAME/ with own.csv, targets.csv, encounters.csv, summary.json, run.log\n"
           "and sumo/ (the generated network and routes).  Prints one row per scenario:\n"
           "minimum distance to any target, domain entered, collision, first action\n"
           "(time, side, helm), largest helm, path lengthening and time lost.\n"
           "\n"
           "  --out DIR     where run directories go (default: runs); an existing\n"
           "                DIR/NAME is replaced\n"
           "  --sumo MODE   embedded (default, libsumo in-process), gui, or\n"
           "                remote:HOST:PORT (a sumo started with the run's sumo/ files)\n"
           "  --json        print the summaries as a JSON array instead of the table\n"
           "\n"
           "The same scenario and seed give byte-identical result files.\n"
           "Exit codes: 0 ok, 1 a run failed, 2 bad input (nothing is written).\n");
}

static void row(const fw_run_summary *s)
{
    char act[48] = "-", ret[16] = "-";
    if (s->acted)
        snprintf(act, sizeof act, "%6.0f %-4s %2.0f", s->t_act,
                 s->act_side == FW_SIDE_STARBOARD ? "stbd" : "port",
                 fw_rad_to_deg(fabs(s->act_helm)));
    if (!isnan(s->t_return))
        snprintf(ret, sizeof ret, "%.0f", s->t_return);
    printf("%-24s %8.0f %-6s %-9s %-17s %8.0f %7s %9.0f %9.0f  %s\n", s->scenario, s->min_dist,
           s->domain_entered ? "yes" : "no", s->collision ? "COLLISION" : "no", act,
           fw_rad_to_deg(s->max_helm), ret, s->path_lengthening, s->time_lost,
           s->status != FW_RUN_OK ? fw_run_status_name(s->status) : (s->colregs_ok ? "ok" : "colregs?"));
}

int fw_cmd_run(int argc, char **argv)
{
    fw_args a = {argc, argv, 0};
    fw_error err = {0};
    const char *out = "runs", *mode = "embedded", *v;
    bool json = false;
    const char **files = calloc((size_t)argc + 1, sizeof *files);
    int nf = 0;
    if (!files)
        return 1;
    while (a.i < a.argc) {
        if (fw_is_help(a.argv[a.i])) {
            help();
            free(files);
            return 0;
        } else if (fw_args_opt(&a, "--out", &v, &err)) {
            if (!v)
                return free(files), fw_report(&err);
            out = v;
        } else if (fw_args_opt(&a, "--sumo", &v, &err)) {
            if (!v)
                return free(files), fw_report(&err);
            mode = v;
        } else if (fw_args_flag(&a, "--json")) {
            json = true;
        } else if (a.argv[a.i][0] == '-' && a.argv[a.i][1]) {
            fprintf(stderr, "fairway run: unknown option '%s' (see --help)\n", a.argv[a.i]);
            free(files);
            return 2;
        } else {
            files[nf++] = a.argv[a.i++];
        }
    }
    fw_run_def def = fw_default_run_def();
    if (nf == 0) {
        fw_fail(&err, FW_EINPUT, "no scenario given (see fairway run --help)");
    } else {
        fw_traffic_mode_parse(mode, &def.mode, &err);
    }
    if (err.status) {
        free(files);
        return fw_report(&err);
    }
    /* everything checked before anything is created */
    fw_scenario **scn = calloc((size_t)nf, sizeof *scn);
    int rc = 0;
    for (int i = 0; i < nf && !rc; i++) {
        scn[i] = malloc(sizeof **scn);
        if (!scn[i] || fw_scenario_load(files[i], scn[i], &err))
            rc = scn[i] ? fw_report(&err) : 1;
        for (int j = 0; j < i && !rc; j++)
            if (strcmp(scn[i]->name, scn[j]->name) == 0) {
                fw_fail(&err, FW_EINPUT, "%s and %s have the same name '%s' (one output directory)",
                        files[j], files[i], scn[i]->name);
                rc = fw_report(&err);
            }
    }
    if (!rc && (strlen(out) > 700 || fw_mkdirs(out, "--out", &err)))
        rc = fw_report(err.status ? &err : (fw_fail(&err, FW_EINPUT, "--out: path too long"), &err));
    if (!rc && !json)
        printf("%-24s %8s %-6s %-9s %-17s %8s %7s %9s %9s  %s\n", "scenario", "min_d_m", "domain",
               "collision", "action_s side deg", "max_helm", "return", "path_+m", "lost_s",
               "status");
    bool first = true, started = !rc;
    if (started && json)
        printf("[");
    for (int i = 0; i < nf && started; i++) {
        char tmp[1024], dst[1024];
        snprintf(tmp, sizeof tmp, "%s/.%s.tmp.%ld", out, scn[i]->name, (long)getpid());
        snprintf(dst, sizeof dst, "%s/%s", out, scn[i]->name);
        fw_remove_tree(tmp);
        if (mkdir(tmp, 0777) != 0) {
            rc = fw_report((fw_fail(&err, FW_ERUN, "cannot create %s", tmp), &err));
            break;
        }
        def.scenario = scn[i];
        def.dir = tmp;
        fw_run_summary sum;
        fw_encounter *enc = NULL;
        int ne = 0;
        fw_status st = fw_run_scenario(&def, &sum, &enc, &ne, &err);
        if (st == FW_EINPUT) {
            fw_remove_tree(tmp);
            free(enc);
            rc = fw_report(&err);
            break;
        }
        /* a failed run keeps its directory: the log says what happened */
        fw_remove_tree(dst);
        if (rename(tmp, dst) != 0) {
            fw_remove_tree(tmp);
            free(enc);
            rc = fw_report((fw_fail(&err, FW_ERUN, "cannot rename %s to %s", tmp, dst), &err));
            break;
        }
        if (st) {
            fprintf(stderr, "fairway run: %s: %s\n", scn[i]->name, err.msg);
            rc = 1;
        }
        if (json) {
            printf("%s\n", first ? "" : ",");
            fw_summary_json(stdout, &sum, enc, ne, "  ");
        } else {
            row(&sum);
        }
        first = false;
        fflush(stdout);
        free(enc);
        if (st)
            rc = 1;
    }
    if (started && json)
        printf("%s]\n", first ? "" : "\n");
    for (int i = 0; i < nf; i++)
        free(scn[i]);
    free(scn);
    free(files);
    return rc;
}
