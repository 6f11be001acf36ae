/* fairway calibrate: fit named MMG coefficients of a ship to its sea trial. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/units.h"
#include "fit/calibrate.h"
#include "yaml/yaml_edit.h"

static void help(void)
{
    printf("usage: fairway calibrate --ship NAME [--trial FILE] [--write | --check]\n"
           "\n"
           "Fits the coefficients named under 'tune:' in the trial file (default\n"
           "scenarios/ships/NAME-trial.yaml) by least squares to its targets: measured\n"
           "turning circles (advance, transfer, tactical diameter, steady rate; rows\n"
           "may carry a weight) and, under 'nomoto_targets:', the steady rates K delta\n"
           "(paper eq 10) and rate histories (eq 9) of another ship's Nomoto knowledge\n"
           "base over a grid of speeds and rudder angles.  Each coefficient is its\n"
           "regression value (tune: {name, regression, max_factor}) times a factor\n"
           "within max_factor, pulled towards 1 with prior_weight; the fit starts from\n"
           "the ship file's current values.  Prints every coefficient (regression,\n"
           "before, after, factor, whether at a bound) and the residual of every target.\n"
           "--write  puts the fitted values into the ship file, each with a comment\n"
           "         giving its regression value and factor, plus a summary block.\n"
           "--check  evaluates the ship as it is against the targets, without fitting.\n"
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

static void print_coefficients(const fw_trial *trial, const fw_calibration *cal)
{
    printf("\n  %-14s %12s %12s %12s %8s\n", "coefficient", "regression", "before", "after",
           "factor");
    for (int j = 0; j < cal->n; j++) {
        double f = cal->after[j] / cal->regression[j];
        /* a coefficient the fit left at a bound is one the targets wanted further */
        bool at_bound = fabs(fabs(log(f)) - log(trial->factor[j])) < 1e-3;
        printf("  %-14s %12.6g %12.6g %12.6g %8.3f%s\n", trial->tune[j], cal->regression[j],
               cal->before[j], cal->after[j], f, at_bound ? "  at its bound" : "");
    }
}

/* A target the fit misses by more than this is named on stderr: a value the
 * ship cannot reach with the tuned coefficients within their bounds. */
#define FW_REACH 0.25

/* Every target with its value before and after and the error left. */
static void print_targets(const fw_trial *trial, const fw_calibration *cal)
{
    printf("\n  %-5s %-4s %6s %5s %-10s %10s %10s %10s   %s\n", "row", "side", "kn", "deg",
           "target", "value", "before", "after", "error");
    for (int i = 0; i < trial->nturns; i++) {
        const fw_trial_turn *t = &trial->turns[i];
        const fw_turning_result *b = &cal->before_res[i], *f = &cal->after_res[i];
        const char *side = t->rudder > 0 ? "stbd" : "port";
        const char *kind = t->from_kb ? "eq" : "trial";
        struct { const char *name; double trial, before, after; } q[4] = {
            {"advance", t->advance, b->advance, f->advance},
            {"transfer", t->transfer, b->transfer, f->transfer},
            {"tactical", t->tactical_diameter, b->tactical_diameter, f->tactical_diameter},
            {"rate deg/s", fw_rad_to_deg(t->steady_rate), fw_rad_to_deg(b->steady_rate),
             fw_rad_to_deg(f->steady_rate)},
        };
        for (int k = 0; k < 4; k++)
            if (q[k].trial > 0 && fabs(q[k].after / q[k].trial - 1) > FW_REACH)
                fprintf(stderr, "warning: %s:%d: %s %s %.3f at %.2f kn, %.0f deg %s is out of "
                        "reach of the fit: %.3f (%+.0f%%)\n", trial->file, t->line, kind,
                        q[k].name, q[k].trial, fw_ms_to_kn(t->speed),
                        fw_rad_to_deg(fabs(t->rudder)), side, q[k].after,
                        100 * (q[k].after / q[k].trial - 1));
        for (int k = 0; k < 4; k++)
            if (q[k].trial > 0)
                printf("  %-5s %-4s %6.2f %5.1f %-10s %10.3f %10.3f %10.3f   %+6.1f%%\n", kind,
                       side, fw_ms_to_kn(t->speed), fw_rad_to_deg(fabs(t->rudder)), q[k].name,
                       q[k].trial, q[k].before, q[k].after, 100 * (q[k].after / q[k].trial - 1));
        if (fw_trial_row_history(t))
            printf("  %-5s %-4s %6.2f %5.1f %-10s %10s %10.3f %10.3f   %6.1f%% of K delta "
                   "(RMS over %.0f s, deg/s)\n",
                   kind, side, fw_ms_to_kn(t->speed), fw_rad_to_deg(fabs(t->rudder)), "eq-9 hist",
                   "eq 9", fw_rad_to_deg(cal->hist_before[i]), fw_rad_to_deg(cal->hist_after[i]),
                   100 * cal->hist_after[i] / t->steady_rate, t->history_s);
    }
}

int fw_cmd_calibrate(int argc, char **argv)
{
    fw_error err = {0};
    const char *ship_name = NULL, *trial_path = NULL;
    bool write = false, check = false;
    fw_args a = {argc, argv, 0};
    while (a.i < argc) {
        const char *v;
        if (fw_args_help(&a, help))
            return 0;
        if (fw_args_flag(&a, "--write"))
            write = true;
        else if (fw_args_flag(&a, "--check"))
            check = true;
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
    trial.check_only = check;
    if (fw_calibrate(&ship, &trial, &cal, &err))
        return fw_report(&err);
    print_coefficients(&trial, &cal);
    print_targets(&trial, &cal);
    printf("\n  RMS relative error %.1f%% -> %.1f%%, largest %.1f%% -> %.1f%% "
           "(%d iterations, %d evaluations)\n",
           100 * cal.rms_before, 100 * cal.rms_after, 100 * cal.max_before, 100 * cal.max_after,
           cal.lsq.iterations, cal.lsq.evaluations);
    if (write && !check) {
        if (fw_calibration_write(&ship, &trial, &cal, &err))
            return fw_report(&err);
        printf("  written to %s\n", ship.file);
    }
    return 0;
}
