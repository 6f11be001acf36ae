/* fairway manoeuvre turning|zigzag|report: IMO standard manoeuvres on the MMG model. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/json.h"
#include "core/units.h"
#include "fit/calibrate.h"
#include "dynamics/manoeuvre.h"
#include "nomoto/track.h"

static void help(void)
{
    printf(
        "usage: fairway manoeuvre turning --ship NAME --speed KN --rudder DEG [--side starboard|port]\n"
        "                                 [--json] [--csv FILE]\n"
        "       fairway manoeuvre zigzag  --ship NAME --speed KN --angle DEG [--side starboard|port]\n"
        "                                 [--json] [--csv FILE]\n"
        "       fairway manoeuvre report  [--ship NAME] [--trial FILE] [--csv-dir DIR] [--json]\n"
        "\n"
        "Standard manoeuvres (IMO MSC.137(76)) on the ship's MMG model, from straight\n"
        "steady running at the approach speed (propeller speed from surge balance).\n"
        "\n"
        "turning   helm to --rudder at t = 0; prints advance, transfer and tactical\n"
        "          diameter (at 90 and 180 deg heading change; metres and ship lengths),\n"
        "          times to 90 and 180 deg, steady turning rate and speed (mean over the\n"
        "          last full circle of a 540 deg turn), and the IMO verdicts (advance\n"
        "          <= 4.5 L, tactical diameter <= 5 L).\n"
        "zigzag    helm --angle to --side (default starboard), reversed each time the\n"
        "          heading change reaches --angle; prints first and second overshoots\n"
        "          and the IMO verdicts (10/10: limits from L/V; 20/20: first <= 25 deg).\n"
        "report    the ship's manoeuvring report: the sea-trial turns of its trial file\n"
        "          (default scenarios/ships/NAME-trial.yaml) side by side with the trial\n"
        "          and the other simulator, the 10/10 and 20/20 zig-zags at the first\n"
        "          trial row's speed, and the IMO verdicts.  --csv-dir writes each\n"
        "          manoeuvre's time history there.  Default ship: c3.\n"
        "\n"
        "--current KN,DEG  a uniform current of KN knots setting towards DEG (2,090:\n"
        "            2 kn towards east): the track over ground drifts with it;\n"
        "            advance, transfer and tactical diameter are measured in the water\n"
        "            (the drift taken out), and a turn goes on to 720 deg and prints the\n"
        "            drift between its 360 and 720 deg points (current x time).\n"
        "--wind KN,DEG  a uniform wind of KN knots (0 to 100) blowing FROM DEG (20,270:\n"
        "            20 kn from the west), on the ship's windage (Blendermann 1994, the\n"
        "            ship file's windage: section; a ship without one is refused): the\n"
        "            ship drifts to leeward and turns; a turn goes on to 720 deg and\n"
        "            prints the drift between its 360 and 720 deg points.  The IMO\n"
        "            measures then include the wind's drift (only a current's is taken\n"
        "            out).  Not with report (the trial's calm water).\n"
        "--csv FILE  time history: t_s, east_m, north_m, heading_deg, u_mps, v_mps,\n"
        "            r_degps, rudder_deg, helm_deg, propeller_rps (midship point, one\n"
        "            row per 0.5 s, start at the origin heading north).\n"
        "--json      one JSON object on stdout.  turning: ship, L_m, speed_kn,\n"
        "            rudder_deg (signed, + starboard), propeller_rps, advance_m,\n"
        "            advance_L, transfer_m, transfer_L, tactical_diameter_m,\n"
        "            tactical_diameter_L, t90_s, t180_s, steady_rate_degps,\n"
        "            steady_speed_kn, imo_advance_ok, imo_tactical_diameter_ok.\n"
        "            zigzag: ship, speed_kn, angle_deg, side, propeller_rps,\n"
        "            initial_turning_time_s, L_over_V_s, overshoot1_deg,\n"
        "            overshoot2_deg, limit1_deg, limit2_deg (null: no limit), imo_ok1,\n"
        "            imo_ok2.  report: {turns: [...turning objects with trial_* and\n"
        "            sim_* fields], zigzags: [...], imo_ok}.\n"
        "\n"
        "Exit codes: 0 ok, 1 the simulation failed, 2 bad input.\n");
}

typedef struct opts {
    const char *ship, *csv, *csv_dir, *trial, *side;
    double speed, rudder, angle;
    bool have_speed, have_rudder, have_angle, json;
    double current[2], wind[2]; /* kn, deg: towards (current), from (wind) */
    int n_current, n_wind;
} opts;

static fw_status parse(int argc, char **argv, opts *o, fw_error *err)
{
    memset(o, 0, sizeof *o);
    o->side = "starboard";
    const fw_opt table[] = {
        FW_OPT("--json", FW_OPT_FLAG, &o->json),     FW_OPT("--ship", FW_OPT_TEXT, &o->ship),
        FW_OPT("--csv", FW_OPT_TEXT, &o->csv),       FW_OPT("--csv-dir", FW_OPT_TEXT, &o->csv_dir),
        FW_OPT("--trial", FW_OPT_TEXT, &o->trial),   FW_OPT("--side", FW_OPT_TEXT, &o->side),
        FW_OPT_SEEN("--speed", FW_OPT_DOUBLE, &o->speed, &o->have_speed),
        FW_OPT_SEEN("--rudder", FW_OPT_DOUBLE, &o->rudder, &o->have_rudder),
        FW_OPT_SEEN("--angle", FW_OPT_DOUBLE, &o->angle, &o->have_angle),
        FW_OPT_LISTOF("--current", o->current, 2, &o->n_current),
        FW_OPT_LISTOF("--wind", o->wind, 2, &o->n_wind), FW_OPT_END,
    };
    fw_args a = {argc, argv, 0};
    while (a.i < argc) {
        fw_arg_read r = fw_args_next(&a, "manoeuvre", table, help, err);
        if (r == FW_ARG_POSITIONAL)
            return fw_fail(err, FW_EINPUT, "manoeuvre: unexpected argument '%s'", argv[a.i]);
        if (r != FW_ARG_OPTION)
            return err->status;
    }
    if (o->side && strcmp(o->side, "starboard") && strcmp(o->side, "port"))
        return fw_fail(err, FW_EINPUT, "--side: '%s' is not starboard or port", o->side);
    if (o->have_speed && !(o->speed > 0.0))
        return fw_fail(err, FW_EINPUT, "--speed: must be positive (got %.15g kn)", o->speed);
    if (o->have_speed && o->speed > FW_SPEED_MAX_KN)
        return fw_fail(err, FW_EINPUT,
                       "--speed: %.15g kn is above %.15g kn, the fastest fairway accepts (as scenarios)",
                       o->speed, FW_SPEED_MAX_KN);
    /* output paths are checked before the simulation, not after it */
    if (o->csv && fw_check_out_file("--csv", o->csv, true, err))
        return err->status;
    if (o->csv_dir && fw_mkdirs(o->csv_dir, "--csv-dir", err))
        return err->status;
    if (o->have_rudder && !(o->rudder > 0.0))
        return fw_fail(err, FW_EINPUT,
                       "--rudder: give the angle's size in degrees (> 0) and the side with --side");
    if (o->have_angle && !(o->angle > 0.0))
        return fw_fail(err, FW_EINPUT, "--angle: must be positive degrees");
    if (o->n_current && (o->n_current != 2 || !(o->current[0] >= 0.0 && o->current[0] <= 10.0) ||
                         !(o->current[1] >= 0.0 && o->current[1] <= 360.0)))
        return fw_fail(err, FW_EINPUT, "--current: give KN,DEG, the speed (0 to 10 kn) and the "
                                       "direction it sets towards (0 to 360 deg), as 2,090");
    if (o->n_wind && (o->n_wind != 2 || !(o->wind[0] >= 0.0 && o->wind[0] <= 100.0) ||
                      !(o->wind[1] >= 0.0 && o->wind[1] <= 360.0)))
        return fw_fail(err, FW_EINPUT, "--wind: give KN,DEG, the speed (0 to 100 kn) and the "
                                       "direction it blows from (0 to 360 deg), as 20,270");
    return FW_OK;
}

/* The stepper of a manoeuvre in the --current and --wind given (calm water
 * and still air without). */
static void set_current(const opts *o, fw_stepper_def *sd)
{
    if (o->n_current == 2)
        sd->current = fw_current_uniform(fw_kn_to_ms(o->current[0]), fw_deg_to_rad(o->current[1]));
    if (o->n_wind == 2)
        sd->wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = fw_kn_to_ms(o->wind[0]),
                             .from = fw_deg_to_rad(o->wind[1])};
}

static double side_sign(const char *side) { return strcmp(side, "port") == 0 ? -1.0 : 1.0; }

static void print_turning_json(const fw_ship *s, double speed, double rudder,
                               const fw_turning_result *r, const char *extra)
{
    printf("{\"ship\": ");
    fw_json_string(stdout, s->name);
    printf(", \"L_m\": %.3f, \"speed_kn\": %.3f, \"rudder_deg\": %.2f, "
           "\"propeller_rps\": %.4f, \"advance_m\": %.2f, \"advance_L\": %.4f, "
           "\"transfer_m\": %.2f, \"transfer_L\": %.4f, \"tactical_diameter_m\": %.2f, "
           "\"tactical_diameter_L\": %.4f, \"t90_s\": %.2f, \"t180_s\": %.2f, "
           "\"steady_rate_degps\": %.5f, \"steady_speed_kn\": %.3f, \"imo_advance_ok\": %s, "
           "\"imo_tactical_diameter_ok\": %s%s}",
           s->L, fw_ms_to_kn(speed), fw_rad_to_deg(rudder), r->propeller, r->advance,
           r->advance / s->L, r->transfer, r->transfer / s->L, r->tactical_diameter,
           r->tactical_diameter / s->L, r->t90, r->t180, fw_rad_to_deg(r->steady_rate),
           fw_ms_to_kn(r->steady_speed), r->advance_ok ? "true" : "false",
           r->tactical_ok ? "true" : "false", extra ? extra : "");
}

static void print_turning_text(const fw_ship *s, double speed, double rudder,
                               const fw_turning_result *r)
{
    printf("%s turning circle, %.0f deg %s at %.2f kn (propeller %.3f rev/s)\n", s->name,
           fabs(fw_rad_to_deg(rudder)), rudder > 0 ? "starboard" : "port", fw_ms_to_kn(speed),
           r->propeller);
    printf("  advance            %8.1f m  %5.2f L   IMO <= 4.5 L: %s\n", r->advance,
           r->advance / s->L, r->advance_ok ? "pass" : "FAIL");
    printf("  transfer           %8.1f m  %5.2f L\n", r->transfer, r->transfer / s->L);
    printf("  tactical diameter  %8.1f m  %5.2f L   IMO <= 5.0 L: %s\n", r->tactical_diameter,
           r->tactical_diameter / s->L, r->tactical_ok ? "pass" : "FAIL");
    printf("  time to 90 / 180   %8.1f s  %6.1f s\n", r->t90, r->t180);
    printf("  steady turn        %8.3f deg/s at %.2f kn\n", fw_rad_to_deg(r->steady_rate),
           fw_ms_to_kn(r->steady_speed));
}

static void print_zigzag_json(const fw_ship *s, const fw_zigzag_def *d, const fw_zigzag_result *r)
{
    char l2[32];
    if (r->limit2 >= 0)
        snprintf(l2, sizeof l2, "%.2f", fw_rad_to_deg(r->limit2));
    else
        snprintf(l2, sizeof l2, "null");
    printf("{\"ship\": ");
    fw_json_string(stdout, s->name);
    printf(", \"speed_kn\": %.3f, \"angle_deg\": %.2f, \"side\": \"%s\", "
           "\"propeller_rps\": %.4f, \"initial_turning_time_s\": %.2f, \"L_over_V_s\": %.3f, "
           "\"overshoot1_deg\": %.3f, \"overshoot2_deg\": %.3f, \"limit1_deg\": %.2f, "
           "\"limit2_deg\": %s, \"imo_ok1\": %s, \"imo_ok2\": %s}",
           fw_ms_to_kn(d->speed), fw_rad_to_deg(d->angle),
           d->first_side > 0 ? "starboard" : "port", r->propeller, r->t_first_execute,
           r->L_over_V, fw_rad_to_deg(r->overshoot1), fw_rad_to_deg(r->overshoot2),
           fw_rad_to_deg(r->limit1), l2, r->ok1 ? "true" : "false", r->ok2 ? "true" : "false");
}

static void print_zigzag_text(const fw_ship *s, const fw_zigzag_def *d, const fw_zigzag_result *r)
{
    double a = fw_rad_to_deg(d->angle);
    printf("%s zig-zag %.0f/%.0f %s first at %.2f kn (L/V = %.1f s)\n", s->name, a, a,
           d->first_side > 0 ? "starboard" : "port", fw_ms_to_kn(d->speed), r->L_over_V);
    printf("  initial turning time %6.1f s\n", r->t_first_execute);
    printf("  first overshoot      %6.2f deg   IMO limit %.1f deg: %s\n",
           fw_rad_to_deg(r->overshoot1), fw_rad_to_deg(r->limit1), r->ok1 ? "pass" : "FAIL");
    if (r->limit2 >= 0)
        printf("  second overshoot     %6.2f deg   IMO limit %.1f deg: %s\n",
               fw_rad_to_deg(r->overshoot2), fw_rad_to_deg(r->limit2), r->ok2 ? "pass" : "FAIL");
    else
        printf("  second overshoot     %6.2f deg   (no IMO limit)\n", fw_rad_to_deg(r->overshoot2));
}

/* A manoeuvre's time history to --csv (when asked and the run worked); the
 * history freed either way. */
static fw_status csv_out(fw_history *h, const opts *o, fw_status st, fw_error *err)
{
    if (!st && o->csv)
        st = fw_history_write_csv(h, o->csv, err);
    fw_history_free(h);
    return st;
}

static int run_turning(const fw_ship *ship, const opts *o, fw_error *err)
{
    if (!o->have_speed || !o->have_rudder)
        return fw_report((fw_fail(err, FW_EINPUT, "manoeuvre turning needs --speed and --rudder"), err));
    fw_turning_def d = fw_default_turning_def();
    d.speed = fw_kn_to_ms(o->speed);
    d.rudder = side_sign(o->side) * fw_deg_to_rad(o->rudder);
    /* in a current, on to 720 deg: the drift between the 360 and 720 deg points */
    bool drifts = o->n_current || o->n_wind;
    d.max_turn = fw_deg_to_rad(drifts ? 730.0 : 540.0);
    set_current(o, &d.stepper);
    fw_turning_result r;
    fw_history h = {0};
    if (csv_out(&h, o, fw_turning_run(ship, &d, &r, o->csv ? &h : NULL, err), err))
        return fw_report(err);
    char extra[384] = "";
    size_t k = 0;
    if (o->n_current)
        k += (size_t)snprintf(extra, sizeof extra,
                              ", \"current_kn\": %.3f, \"current_towards_deg\": %.1f",
                              o->current[0], o->current[1]);
    if (o->n_wind)
        k += (size_t)snprintf(extra + k, sizeof extra - k,
                              ", \"wind_kn\": %.3f, \"wind_from_deg\": %.1f", o->wind[0],
                              o->wind[1]);
    if (drifts)
        snprintf(extra + k, sizeof extra - k,
                 ", \"drift_m\": %.2f, \"drift_s\": %.2f, \"drift_towards_deg\": %.2f",
                 r.drift, r.t_drift, fw_rad_to_deg(r.drift_towards));
    if (o->json) {
        print_turning_json(ship, d.speed, d.rudder, &r, extra), printf("\n");
        return 0;
    }
    print_turning_text(ship, d.speed, d.rudder, &r);
    if (o->n_current)
        printf("  in a current of %.2f kn towards %03.0f deg (measures above: the water's)\n",
               o->current[0], o->current[1]);
    if (o->n_wind)
        printf("  in a wind of %.2f kn from %03.0f deg (its drift is in the measures above)\n",
               o->wind[0], o->wind[1]);
    if (drifts)
        printf("  drift 360 -> 720 deg %7.1f m in %.1f s towards %03.0f deg (%.2f kn)\n", r.drift,
               r.t_drift, fw_rad_to_deg(r.drift_towards), fw_ms_to_kn(r.drift / r.t_drift));
    return 0;
}

static int run_zigzag(const fw_ship *ship, const opts *o, fw_error *err)
{
    if (!o->have_speed || !o->have_angle)
        return fw_report((fw_fail(err, FW_EINPUT, "manoeuvre zigzag needs --speed and --angle"), err));
    fw_zigzag_def d = fw_default_zigzag_def();
    d.speed = fw_kn_to_ms(o->speed);
    d.angle = fw_deg_to_rad(o->angle);
    d.first_side = (int)side_sign(o->side);
    set_current(o, &d.stepper);
    fw_zigzag_result r;
    fw_history h = {0};
    if (csv_out(&h, o, fw_zigzag_run(ship, &d, &r, o->csv ? &h : NULL, err), err))
        return fw_report(err);
    if (o->json)
        print_zigzag_json(ship, &d, &r), printf("\n");
    else
        print_zigzag_text(ship, &d, &r);
    return 0;
}

static void pct_row(const char *name, double trial, double sim, double ours, double unit)
{
    printf("  %-19s %9.1f", name, trial * unit);
    if (sim > 0)
        printf(" %9.1f (%+5.1f%%)", sim * unit, 100 * (sim / trial - 1));
    else
        printf(" %18s", "-");
    printf(" %9.1f (%+5.1f%%)\n", ours * unit, 100 * (ours / trial - 1));
}

static void rate_row(double trial, double sim, double ours)
{
    printf("  %-19s %9.3f", "steady rate deg/s", fw_rad_to_deg(trial));
    if (sim > 0)
        printf(" %9.3f (%+5.1f%%)", fw_rad_to_deg(sim), 100 * (sim / trial - 1));
    else
        printf(" %18s", "-");
    printf(" %9.3f (%+5.1f%%)\n", fw_rad_to_deg(ours), 100 * (ours / trial - 1));
}

/* The time history of one manoeuvre into --csv-dir/NAME. */
static fw_status write_csv_in(const opts *o, const fw_history *h, const char *name,
                              fw_error *err)
{
    char path[1100];
    if ((size_t)snprintf(path, sizeof path, "%s/%s", o->csv_dir, name) >= sizeof path)
        return fw_fail(err, FW_EINPUT, "--csv-dir %s: path too long", o->csv_dir);
    return fw_history_write_csv(h, path, err);
}

/* One sea-trial turn against the trial; *ok &= its IMO verdicts. */
static fw_status report_turn(const fw_ship *ship, const opts *o, const fw_trial_turn *t,
                             bool first, bool *ok, fw_error *err)
{
    fw_turning_def d = fw_trial_turning_def(t);
    fw_turning_result r;
    fw_history h = {0};
    fw_status st = fw_turning_run(ship, &d, &r, o->csv_dir ? &h : NULL, err);
    if (!st && o->csv_dir) {
        char name[64];
        snprintf(name, sizeof name, "turning_%s_%.2fkn.csv", t->rudder > 0 ? "starboard" : "port",
                 fw_ms_to_kn(t->speed));
        st = write_csv_in(o, &h, name, err);
    }
    fw_history_free(&h);
    if (st)
        return st;
    *ok &= r.advance_ok && r.tactical_ok;
    if (o->json) {
        char extra[512];
        snprintf(extra, sizeof extra,
                 ", \"trial_advance_m\": %.1f, \"trial_transfer_m\": %.1f, "
                 "\"trial_tactical_diameter_m\": %.1f, \"trial_steady_rate_degps\": %.4f, "
                 "\"sim_advance_m\": %.1f, \"sim_transfer_m\": %.1f, "
                 "\"sim_tactical_diameter_m\": %.1f, \"sim_steady_rate_degps\": %.4f",
                 t->advance, t->transfer, t->tactical_diameter, fw_rad_to_deg(t->steady_rate),
                 t->sim_advance, t->sim_transfer, t->sim_tactical_diameter,
                 fw_rad_to_deg(t->sim_steady_rate));
        printf("%s", first ? "" : ", ");
        print_turning_json(ship, d.speed, d.rudder, &r, extra);
        return FW_OK;
    }
    print_turning_text(ship, d.speed, d.rudder, &r);
    printf("\n  %-19s %9s %18s %18s\n", "against the trial", "trial", "other simulator",
           "fairway");
    pct_row("advance m", t->advance, t->sim_advance, r.advance, 1.0);
    pct_row("transfer m", t->transfer, t->sim_transfer, r.transfer, 1.0);
    pct_row("tactical diam. m", t->tactical_diameter, t->sim_tactical_diameter,
            r.tactical_diameter, 1.0);
    rate_row(t->steady_rate, t->sim_steady_rate, r.steady_rate);
    printf("\n");
    return FW_OK;
}

/* The angle/angle zig-zag at speed (m/s); *ok &= its IMO verdicts. */
static fw_status report_zigzag(const fw_ship *ship, const opts *o, double speed, double angle,
                               bool first, bool *ok, fw_error *err)
{
    fw_zigzag_def d = fw_default_zigzag_def();
    d.speed = speed;
    d.angle = fw_deg_to_rad(angle);
    fw_zigzag_result r;
    fw_history h = {0};
    fw_status st = fw_zigzag_run(ship, &d, &r, o->csv_dir ? &h : NULL, err);
    if (!st && o->csv_dir) {
        char name[64];
        snprintf(name, sizeof name, "zigzag_%.0f_%.2fkn.csv", angle, fw_ms_to_kn(d.speed));
        st = write_csv_in(o, &h, name, err);
    }
    fw_history_free(&h);
    if (st)
        return st;
    *ok &= r.ok1 && r.ok2;
    if (o->json) {
        printf("%s", first ? "" : ", ");
        print_zigzag_json(ship, &d, &r);
    } else {
        print_zigzag_text(ship, &d, &r);
        printf("\n");
    }
    return FW_OK;
}

/* Advance, transfer and tactical diameter of a predicted (Nomoto) track,
 * measured as fw_turning_run measures the MMG ship's; false when it does not
 * turn 180 deg within its horizon. */
static bool track_measures(const fw_track *tr, double side, double *adv, double *tra,
                           double *tac)
{
    bool got90 = false;
    for (int k = 1; k < tr->n; k++) {
        double a0 = side * tr->psi[k - 1], a1 = side * tr->psi[k];
        double f90 = (FW_PI / 2 - a0) / (a1 - a0), f180 = (FW_PI - a0) / (a1 - a0);
        if (!got90 && a1 >= FW_PI / 2) {
            *adv = tr->north[k - 1] + f90 * (tr->north[k] - tr->north[k - 1]);
            *tra = side * (tr->east[k - 1] + f90 * (tr->east[k] - tr->east[k - 1]));
            got90 = true;
        }
        if (a1 >= FW_PI) {
            *tac = side * (tr->east[k - 1] + f180 * (tr->east[k] - tr->east[k - 1]));
            return got90;
        }
    }
    return false;
}

/* The paper's Figures 10-15 trends: the knowledge-base rows of the trial file
 * (equation 10's steady rates) with the MMG ship's advance, transfer and
 * tactical diameter beside those of equations 9-13 themselves (the knowledge
 * base's own Nomoto track, which keeps its speed and has no drift, as the
 * paper's model). */
static fw_status report_kb_rows(const fw_ship *ship, const fw_trial *trial, fw_error *err)
{
    fw_ship kb;
    fw_status st = trial->kb_ship[0] ? fw_ship_load(trial->kb_ship, &kb, err) : FW_OK;
    if (st || !trial->kb_ship[0])
        return st;
    fw_track_def td = fw_default_track_def();
    td.horizon = 3600.0;
    td.max_turn = 0.0;
    fw_track tr = {0};
    if ((st = fw_track_alloc(&tr, fw_track_samples(&td), err)))
        return st;
    printf("against %s (%s, eqs 9-13 as a track: constant speed, no drift)\n", trial->kb_source,
           kb.file);
    printf("  %6s %5s %19s %19s %19s %21s\n", "kn", "deg", "advance m", "transfer m",
           "tactical m", "steady rate deg/s");
    for (int i = 0; i < trial->nturns && !st; i++) {
        const fw_trial_turn *t = &trial->turns[i];
        if (!t->from_kb)
            continue;
        fw_turning_def d = fw_trial_turning_def(t);
        fw_turning_result r;
        fw_own_state own = {.U = t->speed};
        double a = NAN, b = NAN, c = NAN;
        if ((st = fw_turning_run(ship, &d, &r, NULL, err)) ||
            (st = fw_track_predict(&kb, &td, &own, t->rudder, &tr, err)))
            break;
        track_measures(&tr, t->rudder > 0 ? 1.0 : -1.0, &a, &b, &c);
        printf("  %6.2f %5.0f %9.0f/%-9.0f %9.0f/%-9.0f %9.0f/%-9.0f %7.3f/%.3f (%+5.1f%%)\n",
               fw_ms_to_kn(t->speed), fw_rad_to_deg(fabs(t->rudder)), r.advance, a, r.transfer,
               b, r.tactical_diameter, c, fw_rad_to_deg(r.steady_rate),
               fw_rad_to_deg(t->steady_rate), 100 * (r.steady_rate / t->steady_rate - 1));
    }
    printf("  (fairway's MMG ship / equations 9-13)\n\n");
    fw_track_free(&tr);
    return st;
}

static int run_report(const fw_ship *ship, const opts *o, fw_error *err)
{
    char trial_path[1100];
    size_t n = o->trial ? (size_t)snprintf(trial_path, sizeof trial_path, "%s", o->trial)
                        : (size_t)snprintf(trial_path, sizeof trial_path,
                                           "%s/scenarios/ships/%s-trial.yaml", fw_data_root(),
                                           ship->name);
    if (n >= sizeof trial_path)
        return fw_report((fw_fail(err, FW_EINPUT, "%s: path too long",
                                  o->trial ? "--trial" : "FAIRWAY_DATA"), err));
    fw_trial trial;
    if (fw_trial_load(trial_path, &trial, err))
        return fw_report(err);
    bool all_ok = true;
    if (o->json) {
        printf("{\"ship\": ");
        fw_json_string(stdout, ship->name);
        printf(", \"turns\": [");
    } else {
        printf("Manoeuvring report: %s (L = %.1f m), trial data %s\n\n", ship->name, ship->L,
               trial_path);
    }
    /* the measured rows as sea-trial turns (the knowledge-base rows are not
     * IMO tests: a 5 deg turn is no 35 deg turning circle) */
    for (int i = 0, k = 0; i < trial.nturns; i++)
        if (!trial.turns[i].from_kb &&
            report_turn(ship, o, &trial.turns[i], k++ == 0, &all_ok, err))
            return fw_report(err);
    if (!o->json && report_kb_rows(ship, &trial, err))
        return fw_report(err);
    if (o->json)
        printf("], \"zigzags\": [");
    const double angles[2] = {10.0, 20.0};
    for (int k = 0; k < 2; k++)
        if (report_zigzag(ship, o, trial.turns[0].speed, angles[k], k == 0, &all_ok, err))
            return fw_report(err);
    if (o->json)
        printf("], \"imo_ok\": %s}\n", all_ok ? "true" : "false");
    else
        printf("IMO MSC.137(76) manoeuvring standards: %s\n",
               all_ok ? "all criteria met" : "NOT all criteria met");
    return 0;
}

int fw_cmd_manoeuvre(int argc, char **argv)
{
    if (argc < 1 || fw_is_help(argv[0])) {
        help();
        return argc < 1 ? 2 : 0;
    }
    const char *kind = argv[0];
    for (int i = 1; i < argc; i++)
        if (fw_is_help(argv[i])) {
            help();
            return 0;
        }
    fw_error err = {0};
    opts o;
    if (parse(argc - 1, argv + 1, &o, &err))
        return fw_report(&err);
    bool report = strcmp(kind, "report") == 0;
    if (!report && strcmp(kind, "turning") && strcmp(kind, "zigzag"))
        return fw_report((fw_fail(&err, FW_EINPUT,
                                  "manoeuvre: '%s' is not turning, zigzag or report", kind),
                          &err));
    if (!o.ship && !report)
        return fw_report((fw_fail(&err, FW_EINPUT, "manoeuvre %s needs --ship", kind), &err));
    fw_ship ship;
    if (fw_ship_load(o.ship ? o.ship : "c3", &ship, &err))
        return fw_report(&err);
    if (o.have_rudder && fw_deg_to_rad(o.rudder) > ship.rudder_max * (1 + 1e-12))
        return fw_report((fw_fail(&err, FW_EINPUT, "--rudder: %.15g deg is beyond %s's maximum of %.15g deg",
                                  o.rudder, ship.name, fw_rad_to_deg(ship.rudder_max)), &err));
    if (o.have_angle && fw_deg_to_rad(o.angle) > ship.rudder_max * (1 + 1e-12))
        return fw_report((fw_fail(&err, FW_EINPUT, "--angle: %.15g deg is beyond %s's maximum rudder of %.15g deg",
                                  o.angle, ship.name, fw_rad_to_deg(ship.rudder_max)), &err));
    if (report && o.n_wind)
        return fw_report((fw_fail(&err, FW_EINPUT, "--wind: not with report, which compares "
                                                   "with the sea trial's calm water"), &err));
    if (report)
        return run_report(&ship, &o, &err);
    if (strcmp(kind, "turning") == 0)
        return run_turning(&ship, &o, &err);
    return run_zigzag(&ship, &o, &err);
}
