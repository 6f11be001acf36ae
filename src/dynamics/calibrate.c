#include "core/files.h"
#include "dynamics/calibrate.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "yaml/yaml_edit.h"
#include "yaml/yaml_tree.h"


/* The measured (or simulated) values of a turning row: advance, transfer,
 * tactical diameter (m) and the steady rate (read in deg/s, kept in rad/s);
 * 0 where not given. */
static fw_status turn_values(const yt_doc *doc, const yt_node *m, const char *path,
                             double *advance, double *transfer, double *tactical,
                             double *steady_rate, fw_error *err)
{
    double rate = 0.0;
    fw_status st;
    if ((st = yt_opt_number(doc, m, path, "advance_m", 1.0, 1e5, advance, err)) ||
        (st = yt_opt_number(doc, m, path, "transfer_m", 1.0, 1e5, transfer, err)) ||
        (st = yt_opt_number(doc, m, path, "tactical_diameter_m", 1.0, 1e5, tactical, err)) ||
        (st = yt_opt_number(doc, m, path, "steady_rate_degps", 0.01, 20.0, &rate, err)))
        return st;
    *steady_rate = fw_deg_to_rad(rate);
    return FW_OK;
}

static fw_status load_turn(const yt_doc *doc, const yt_node *m, const char *path,
                           fw_trial_turn *t, fw_error *err)
{
    static const char *const allowed[] = {"side", "speed_kn", "rudder_deg", "advance_m",
                                          "transfer_m", "tactical_diameter_m",
                                          "steady_rate_degps", "simulator", NULL};
    fw_status st = yt_check_keys(doc, m, path, allowed, err);
    if (st)
        return st;
    const yt_node *sim;
    char simpath[96];
    yt_path(simpath, sizeof simpath, path, "simulator");
    if ((st = yt_opt_map(doc, m, path, "simulator", &sim, err)))
        return st;
    if (sim) {
        static const char *const sim_allowed[] = {"advance_m", "transfer_m",
                                                  "tactical_diameter_m", "steady_rate_degps",
                                                  NULL};
        if ((st = yt_check_keys(doc, sim, simpath, sim_allowed, err)) ||
            (st = turn_values(doc, sim, simpath, &t->sim_advance, &t->sim_transfer,
                              &t->sim_tactical_diameter, &t->sim_steady_rate, err)))
            return st;
    }
    char side[32];
    double kn, deg;
    if ((st = yt_req_string(doc, m, path, "side", side, sizeof side, err)) ||
        (st = yt_req_number(doc, m, path, "speed_kn", 0.5, 40.0, &kn, err)) ||
        (st = yt_req_number(doc, m, path, "rudder_deg", 1.0, 45.0, &deg, err)) ||
        (st = turn_values(doc, m, path, &t->advance, &t->transfer, &t->tactical_diameter,
                          &t->steady_rate, err)))
        return st;
    double sign;
    if (strcmp(side, "starboard") == 0)
        sign = 1.0;
    else if (strcmp(side, "port") == 0)
        sign = -1.0;
    else {
        char field[128];
        return fw_fail_at(err, doc->file, yt_key_line(m, "side"),
                          yt_path(field, sizeof field, path, "side"),
                          "'%s' is not starboard or port", side);
    }
    t->speed = fw_kn_to_ms(kn);
    t->rudder = sign * fw_deg_to_rad(deg);
    if (t->advance == 0 && t->transfer == 0 && t->tactical_diameter == 0 && t->steady_rate == 0)
        return fw_fail_at(err, doc->file, m->line, path, "no measured value in this row");
    return FW_OK;
}

fw_status fw_trial_load(const char *path, fw_trial *trial, fw_error *err)
{
    memset(trial, 0, sizeof *trial);
    if (strlen(path) >= sizeof trial->file)
        return fw_fail(err, FW_EINPUT, "trial file name too long (over %zu characters): %.60s...",
                       sizeof trial->file - 1, path);
    memcpy(trial->file, path, strlen(path) + 1);
    yt_doc *doc;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    const yt_node *root = doc->root, *turns, *tune;
    static const char *const allowed[] = {"ship", "source", "tune", "max_factor", "turns", NULL};
    trial->max_factor = 4.0;
    if ((st = yt_check_keys(doc, root, "", allowed, err)) ||
        (st = yt_req_string(doc, root, "", "ship", trial->ship, sizeof trial->ship, err)) ||
        (st = yt_opt_string(doc, root, "", "source", trial->source, sizeof trial->source, err)) ||
        (st = yt_opt_number(doc, root, "", "max_factor", 1.01, 100.0, &trial->max_factor, err)) ||
        (st = yt_req_seq(doc, root, "", "tune", &tune, err)) ||
        (st = yt_req_seq(doc, root, "", "turns", &turns, err)))
        goto out;
    if (turns->n < 1 || turns->n > FW_TRIAL_MAX_TURNS) {
        st = fw_fail_at(err, doc->file, turns->line, "turns", "needs 1 to %d rows",
                        FW_TRIAL_MAX_TURNS);
        goto out;
    }
    fw_ship probe;
    memset(&probe, 0, sizeof probe);
    if (tune->n < 1 || tune->n > FW_LSQ_MAX_P) {
        st = fw_fail_at(err, doc->file, tune->line, "tune", "needs 1 to %d names", FW_LSQ_MAX_P);
        goto out;
    }
    int measured = 0;
    for (size_t i = 0; i < turns->n; i++) {
        char field[64];
        snprintf(field, sizeof field, "turns[%zu]", i);
        if (turns->items[i]->kind != YT_MAP) {
            st = fw_fail_at(err, doc->file, turns->items[i]->line, field, "expected a mapping");
            goto out;
        }
        fw_trial_turn *t = &trial->turns[trial->nturns++];
        if ((st = load_turn(doc, turns->items[i], field, t, err)))
            goto out;
        measured += (t->advance > 0) + (t->transfer > 0) + (t->tactical_diameter > 0) +
                    (t->steady_rate > 0);
    }
    for (size_t i = 0; i < tune->n; i++) {
        const yt_node *n = tune->items[i];
        char field[64];
        snprintf(field, sizeof field, "tune[%zu]", i);
        if (n->kind != YT_SCALAR || !fw_ship_field(&probe, n->str, NULL, NULL)) {
            st = fw_fail_at(err, doc->file, n->line, field, "'%s' is not a ship-file field",
                            n->kind == YT_SCALAR ? n->str : "?");
            goto out;
        }
        snprintf(trial->tune[trial->ntune++], sizeof trial->tune[0], "%s", n->str);
    }
    if (trial->ntune > measured) {
        st = fw_fail_at(err, doc->file, tune->line, "tune",
                        "%d coefficients cannot be fitted to %d measured values", trial->ntune,
                        measured);
        goto out;
    }
out:
    yt_free(doc);
    return st;
}

typedef struct fit_ctx {
    fw_ship *ship;
    const fw_trial *trial;
    double base[FW_LSQ_MAX_P];
    double *field[FW_LSQ_MAX_P];
    fw_turning_result *res; /* where the last evaluation's results go (may be NULL) */
} fit_ctx;

static void apply(fit_ctx *c, const double *p)
{
    for (int j = 0; j < c->trial->ntune; j++)
        *c->field[j] = c->base[j] * exp(p[j]);
}

fw_turning_def fw_trial_turning_def(const fw_trial_turn *t)
{
    fw_turning_def d = fw_default_turning_def();
    d.speed = t->speed;
    d.rudder = t->rudder;
    d.max_turn = fw_deg_to_rad(540.0);
    return d;
}

static fw_status residuals(const double *p, double *r, void *user, fw_error *err)
{
    fit_ctx *c = user;
    apply(c, p);
    int k = 0;
    for (int i = 0; i < c->trial->nturns; i++) {
        const fw_trial_turn *t = &c->trial->turns[i];
        fw_turning_def d = fw_trial_turning_def(t);
        fw_turning_result res;
        fw_error run_err = {0};
        if (fw_turning_run(c->ship, &d, &res, NULL, &run_err)) {
            /* A coefficient set for which the ship cannot complete the turn
             * (or the integration fails) is a bad point, not the end of the
             * fit: a large residual makes the search step back. */
            for (int j = 0; j < 4; j++)
                r[k++] = 10.0;
            (void)err;
            continue;
        }
        if (c->res)
            c->res[i] = res;
        if (t->advance > 0)
            r[k++] = res.advance / t->advance - 1.0;
        if (t->transfer > 0)
            r[k++] = res.transfer / t->transfer - 1.0;
        if (t->tactical_diameter > 0)
            r[k++] = res.tactical_diameter / t->tactical_diameter - 1.0;
        if (t->steady_rate > 0)
            r[k++] = res.steady_rate / t->steady_rate - 1.0;
    }
    return FW_OK;
}

static int count_measured(const fw_trial *t)
{
    int n = 0;
    for (int i = 0; i < t->nturns; i++)
        n += (t->turns[i].advance > 0) + (t->turns[i].transfer > 0) +
             (t->turns[i].tactical_diameter > 0) + (t->turns[i].steady_rate > 0);
    return n;
}

static void stats(const double *r, int n, double *rms, double *max)
{
    double s = 0.0, m = 0.0;
    for (int i = 0; i < n; i++) {
        s += r[i] * r[i];
        m = fmax(m, fabs(r[i]));
    }
    *rms = sqrt(s / n);
    *max = m;
}

fw_status fw_calibrate(fw_ship *ship, const fw_trial *trial, fw_calibration *cal, fw_error *err)
{
    memset(cal, 0, sizeof *cal);
    fit_ctx c = {.ship = ship, .trial = trial};
    int np = trial->ntune, nr = count_measured(trial);
    double p[FW_LSQ_MAX_P] = {0}, lo[FW_LSQ_MAX_P], hi[FW_LSQ_MAX_P], r[64];
    for (int j = 0; j < np; j++) {
        c.field[j] = fw_ship_field(ship, trial->tune[j], NULL, NULL);
        c.base[j] = *c.field[j];
        if (c.base[j] == 0.0)
            return fw_fail(err, FW_EINPUT, "%s: %s is zero in the ship file and cannot be scaled",
                           trial->file, trial->tune[j]);
        cal->before[j] = c.base[j];
        lo[j] = -log(trial->max_factor);
        hi[j] = log(trial->max_factor);
    }
    cal->n = np;
    c.res = cal->before_res;
    fw_status st = residuals(p, r, &c, err);
    if (st)
        return st;
    stats(r, nr, &cal->rms_before, &cal->max_before);
    c.res = NULL;
    fw_lsq_def def = fw_default_lsq_def();
    def.fd_step = 1e-3; /* relative change of 0.1 percent per coefficient */
    def.ftol = 1e-8;
    def.max_iter = 100;
    def.lo = lo;
    def.hi = hi;
    if ((st = fw_lsq_solve(residuals, &c, np, nr, p, &def, &cal->lsq, err)))
        return st;
    c.res = cal->after_res;
    if ((st = residuals(p, r, &c, err)))
        return st;
    stats(r, nr, &cal->rms_after, &cal->max_after);
    for (int j = 0; j < np; j++)
        cal->after[j] = *c.field[j];
    return FW_OK;
}

/* The new ship file must load as a ship before it replaces the old one. */
static fw_status check_ship(const char *tmp_path, void *ctx, fw_error *err)
{
    (void)ctx;
    fw_ship probe;
    return fw_ship_load(tmp_path, &probe, err);
}

static fw_status set_coefficients(fw_yaml_edit *ed, const fw_ship *ship, const fw_trial *trial,
                                  const fw_calibration *cal, fw_error *err)
{
    fw_ship probe = *ship;
    for (int j = 0; j < cal->n; j++) {
        const char *section;
        double scale;
        fw_ship_field(&probe, trial->tune[j], &section, &scale);
        char value[64], comment[256];
        snprintf(value, sizeof value, "%.6g", cal->after[j] / scale);
        snprintf(comment, sizeof comment, "[CAL] fairway calibrate: was %.6g (x%.3f)",
                 cal->before[j] / scale, cal->after[j] / cal->before[j]);
        fw_status st = fw_yaml_edit_scalar(ed, section, trial->tune[j], value, comment, err);
        if (st)
            return st;
    }
    return FW_OK;
}

fw_status fw_calibration_write(const fw_ship *ship, const fw_trial *trial,
                               const fw_calibration *cal, fw_error *err)
{
    /* every edit is made in memory and the file replaced once: a failure at
     * any point leaves the ship file as it was */
    fw_yaml_edit *ed = NULL;
    fw_status st = fw_yaml_edit_open(ship->file, &ed, err);
    if (st || (st = set_coefficients(ed, ship, trial, cal, err)))
        goto out;
    /* Name the trial file relative to the data root, so the note stays true
     * wherever the repository is checked out. */
    const char *trial_name = trial->file;
    size_t root_len = strlen(fw_data_root());
    if (strncmp(trial_name, fw_data_root(), root_len) == 0 && trial_name[root_len] == '/')
        trial_name += root_len + 1;
    char text[2048];
    size_t used = (size_t)snprintf(
        text, sizeof text,
        "# Calibration: `fairway calibrate --ship %s` against %s (%s).\n"
        "# Tuned by least squares on the relative errors of advance, transfer,\n"
        "# tactical diameter and steady turning rate (%d values):\n",
        ship->name, trial_name, trial->source[0] ? trial->source : "sea trial",
        count_measured(trial));
    for (int j = 0; j < cal->n && used < sizeof text; j++)
        used += (size_t)snprintf(text + used, sizeof text - used, "#   %-14s %.6g -> %.6g\n",
                                 trial->tune[j], cal->before[j], cal->after[j]);
    if (used < sizeof text)
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 "# RMS relative error %.1f%% -> %.1f%%, largest %.1f%% -> %.1f%%.\n",
                                 100 * cal->rms_before, 100 * cal->rms_after,
                                 100 * cal->max_before, 100 * cal->max_after);
    if (used >= sizeof text) {
        st = fw_fail(err, FW_ERUN, "%s: calibration note too long", ship->file);
        goto out;
    }
    if (!(st = fw_yaml_edit_comment_block(ed, "calibration", text, err)))
        st = fw_yaml_edit_save(ed, NULL, check_ship, NULL, err);
out:
    fw_yaml_edit_free(ed);
    return st;
}
