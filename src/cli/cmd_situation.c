/* fairway situation: scenarios written as DNV maritime-schema traffic situations. */
#include <stdio.h>
#include <stdlib.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "run/dnv_situation.h"
#include "scenario/scenario.h"

static void help(void)
{
    printf("usage: fairway situation SCENARIO... --out DIR\n"
           "\n"
           "Writes each scenario (YAML, explicit targets only: the Imazu and paper cases)\n"
           "as a DNV maritime-schema 0.2.0 traffic situation, DIR/NAME.json\n"
           "(src/run/dnv_situation.h): the own ship's start, course, speed and planned leg,\n"
           "each target's start and a waypoint where its constant velocity takes it at the\n"
           "run's end.  fairway reads it back (`fairway run DIR/NAME.json --ship SHIP`);\n"
           "fairway's own settings (domain, return, step) are not in the schema: a run\n"
           "of the situation has fairway's defaults.  A study's closest encounters are\n"
           "written by `fairway worst STUDY.db --situations`.\n"
           "Exit codes: 0 ok, 2 bad input (nothing is written).\n");
}

typedef struct sit_opts {
    const char *out;
    const char **files;
    int nf;
} sit_opts;

static fw_status add_file(void *ctx, const char *arg, fw_error *err)
{
    (void)err;
    sit_opts *o = ctx;
    o->files[o->nf++] = arg;
    return FW_OK;
}

/* Every scenario loaded and checked before any file is written. */
static int write_all(sit_opts *o, fw_scenario *s, fw_error *err)
{
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < o->nf; i++) {
            if (pass == 1 && i == 0 && fw_mkdirs(o->out, "--out", err))
                return fw_report(err);
            if (fw_scenario_load(o->files[i], s, err))
                return fw_report(err);
            if (s->network[0] || s->tracks[0] || s->ais.file[0] || s->n_targets == 0)
                return fw_report((fw_fail(err, FW_EINPUT, "%s: only scenarios with explicit "
                                          "targets (a study's encounters: fairway worst "
                                          "--situations)", o->files[i]), err));
            char path[1200];
            if (pass == 1 && (fw_path(path, sizeof path, err, "%s/%s.json", o->out, s->name) ||
                              fw_dnv_situation_of_scenario(s, path, err)))
                return fw_report(err);
            if (pass == 1)
                printf("%s\n", path);
        }
    return 0;
}

int fw_cmd_situation(int argc, char **argv)
{
    sit_opts o = {0};
    fw_error err = {0};
    if (!(o.files = calloc((size_t)argc + 1, sizeof *o.files)))
        return fw_report((fw_fail(&err, FW_ERUN, "out of memory"), &err));
    const fw_opt opts[] = {FW_OPT("--out", FW_OPT_TEXT, &o.out), FW_OPT_END};
    int rc = fw_args_parse(argc, argv, "situation", opts, help, add_file, &o, &err);
    fw_scenario *s = malloc(sizeof *s);
    if (rc < 0 && !s)
        rc = fw_report((fw_fail(&err, FW_ERUN, "out of memory"), &err));
    if (rc < 0 && (o.nf == 0 || !o.out))
        rc = fw_report((fw_fail(&err, FW_EINPUT, "%s (see fairway situation --help)",
                                o.nf ? "--out DIR needed" : "no scenario given"), &err));
    if (rc < 0)
        rc = write_all(&o, s, &err);
    free(s);
    free(o.files);
    return rc;
}
