/* fairway calibrate: fit named MMG coefficients of a ship to its sea trial. */
#include <stdio.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/units.h"
#include "dynamics/calibrate.h"
#include "yaml/yaml_edit.h"

static void help(void)
{
    printf("usage: fairway calibrate --ship NAME [--trial FILE] [--write]\n"
           "\n"
           "Fits the coefficients named under 'tune:' in the trial file (default\n"
           "scenarios/ships/NAME-trial.yaml) to its measured turning circles, by least\n"
           "squares on the relative errors of advance, transfer, tactical diameter and\n"
           "steady turning rate.  Each coefficient is scaled by a factor within the\n"
           "file's max_factor, starting from the ship file's current values.\n"
           "Prints the values before and after and the errors of every row.\n"
           "--write  puts the fitted values into the ship file, each with a comment\n"
           "         giving the value it replaced, plus a summary block in its header.\n"
           "\n"
           "Exit codes: 0 ok, 1 the fit failed, 2 bad input.\n");
}

/* --write: every tuned coefficient must be editable in place; found out now
 * (the same edit with the current value, not saved), not after the fit. */
static fw_status check_writable(const fw_ship *ship, const fw_trial *trial, fw_error *err)
{
    fw_yaml_edit *ed = NULL;
    fw_status st = fw_yaml_edit_open(ship->file, &ed, err);
    fw_ship probe = *ship;
    for (int j = 0; !st && j < trial->ntune; j++) {
        const char *section;
        double scale;
        double *v = fw_ship_field(&probe, trial->tune[j], &section, &scale);
        char value[64];
        snprintf(value, sizeof value, "%.6g", v ? *v / scale : 0.0);
        if (v)
            st = fw_yaml_edit_scalar(ed, section, trial->tune[j], value, "check", err);
    }
    fw_yaml_edit_free(ed);
    return st;
}

int fw_cmd_calibrate(int argc, char **argv)
{
    fw_error err = {0};
    const char *ship_name = NULL, *trial_path = NULL;
    bool write = false;
    fw_args a = {argc, argv, 0};
    while (a.i < argc) {
        const char *v;
        if (fw_args_help(&a, help))
            return 0;
        if (fw_args_flag(&a, "--write"))
            write = true;
        else if (fw_args_opt(&a, "--ship", &v, &err))
            ship_name = v;
        else if (fw_args_opt(&a, "--trial", &v, &err))
            trial_path = v;
        else
            return fw_report((fw_fail(&err, FW_EINPUT, "calibrate: unknown option '%s'", argv[a.i]), &err));
        if (err.status)
            return fw_report(&err);
    }
    if (!ship_name)
        return fw_report((fw_fail(&err, FW_EINPUT, "calibrate needs --ship"), &err));
    fw_ship ship;
    if (fw_ship_load(ship_name, &ship, &err))
        return fw_report(&err);
    char path[1100];
    size_t n = trial_path ? (size_t)snprintf(path, sizeof path, "%s", trial_path)
                          : (size_t)snprintf(path, sizeof path, "%s/scenarios/ships/%s-trial.yaml",
                                             fw_data_root(), ship.name);
    if (n >= sizeof path)
        return fw_report((fw_fail(&err, FW_EINPUT, "%s: path too long",
                                  trial_path ? "--trial" : "FAIRWAY_DATA"), &err));
    /* --write: a ship file that cannot be replaced fails now, not after the fit */
    if (write && fw_check_out_file("--write", ship.file, true, &err))
        return fw_report(&err);
    fw_trial trial;
    if (fw_trial_load(path, &trial, &err))
        return fw_report(&err);
    if (strcmp(trial.ship, ship.name) != 0)
        return fw_report((fw_fail(&err, FW_EINPUT, "%s: trial is for ship '%s', not '%s'", path,
                                  trial.ship, ship.name), &err));
    if (write && check_writable(&ship, &trial, &err))
        return fw_report(&err);
    printf("calibrating %s against %s: %d coefficients, %d turning circles\n", ship.name, path,
           trial.ntune, trial.nturns);
    fw_calibration cal;
    if (fw_calibrate(&ship, &trial, &cal, &err))
        return fw_report(&err);
    printf("\n  %-14s %12s %12s %8s\n", "coefficient", "before", "after", "factor");
    for (int j = 0; j < cal.n; j++)
        printf("  %-14s %12.6g %12.6g %8.3f\n", trial.tune[j], cal.before[j], cal.after[j],
               cal.after[j] / cal.before[j]);
    printf("\n  %-8s %-10s %10s %10s %10s   %s\n", "row", "", "trial", "before", "after", "error");
    for (int i = 0; i < trial.nturns; i++) {
        const fw_trial_turn *t = &trial.turns[i];
        const fw_turning_result *b = &cal.before_res[i], *f = &cal.after_res[i];
        const char *row = t->rudder > 0 ? "stbd" : "port";
        struct { const char *name; double trial, before, after; } q[4] = {
            {"advance", t->advance, b->advance, f->advance},
            {"transfer", t->transfer, b->transfer, f->transfer},
            {"tactical", t->tactical_diameter, b->tactical_diameter, f->tactical_diameter},
            {"rate deg/s", fw_rad_to_deg(t->steady_rate), fw_rad_to_deg(b->steady_rate),
             fw_rad_to_deg(f->steady_rate)},
        };
        for (int k = 0; k < 4; k++)
            if (q[k].trial > 0)
                printf("  %-8s %-10s %10.3f %10.3f %10.3f   %+6.1f%%\n", row, q[k].name,
                       q[k].trial, q[k].before, q[k].after, 100 * (q[k].after / q[k].trial - 1));
    }
    printf("\n  RMS relative error %.1f%% -> %.1f%%, largest %.1f%% -> %.1f%% "
           "(%d iterations, %d turning pairs)\n",
           100 * cal.rms_before, 100 * cal.rms_after, 100 * cal.max_before, 100 * cal.max_after,
           cal.lsq.iterations, cal.lsq.evaluations);
    if (write) {
        if (fw_calibration_write(&ship, &trial, &cal, &err))
            return fw_report(&err);
        printf("  written to %s\n", ship.file);
    }
    return 0;
}
