/* `fairway calibrate`: the fit and the ship file it writes. */
#include "core/files.h"
#include "fit/calibrate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/units.h"
#include "nomoto/nomoto.h"
#include "yaml/yaml_edit.h"
#include "yaml/yaml_tree.h"

typedef struct fit_ctx {
    fw_ship *ship;
    const fw_trial *trial;
    double ref[FW_LSQ_MAX_P]; /* regression values: value = ref exp(p) */
    double *field[FW_LSQ_MAX_P];
    fw_turning_result *res; /* where the last evaluation's results go (may be NULL) */
    double *hist_rms;       /* and each row's history error (may be NULL) */
    double *rel;            /* and the unweighted relative errors of the values */
} fit_ctx;

static void apply(fit_ctx *c, const double *p)
{
    for (int j = 0; j < c->trial->ntune; j++)
        *c->field[j] = c->ref[j] * exp(p[j]);
}

fw_turning_def fw_trial_turning_def(const fw_trial_turn *t)
{
    fw_turning_def d = fw_default_turning_def();
    d.speed = t->speed;
    d.rudder = t->rudder;
    d.max_turn = fw_deg_to_rad(540.0);
    /* small-helm targets turn slowly: leave time for 540 deg at a third of
     * the target's rate before calling the turn failed */
    if (t->steady_rate > 0)
        d.max_time = fmax(d.max_time, fmin(3.0 * d.max_turn / t->steady_rate, 30000.0));
    return d;
}

/* Residuals of one row into r (values, then history samples); false when
 * the ship could not make the turn. */
static bool row_residuals(fit_ctx *c, int i, double *r, double *rel, double *hist_rms)
{
    const fw_trial_turn *t = &c->trial->turns[i];
    fw_turning_def d = fw_trial_turning_def(t);
    fw_turning_result res;
    fw_history h = {0};
    fw_error run_err = {0};
    int nh = fw_trial_row_history(t);
    if (fw_turning_run(c->ship, &d, &res, nh ? &h : NULL, &run_err)) {
        fw_history_free(&h);
        return false;
    }
    if (c->res)
        c->res[i] = res;
    const double meas[4] = {t->advance, t->transfer, t->tactical_diameter, t->steady_rate};
    const double got[4] = {res.advance, res.transfer, res.tactical_diameter, res.steady_rate};
    int k = 0;
    for (int q = 0; q < 4; q++)
        if (meas[q] > 0) {
            rel[k] = got[q] / meas[q] - 1.0;
            r[k] = t->weight * rel[k];
            k++;
        }
    /* eq 9: a step of |rudder| at t = 0, against the MMG ship's rate (its
     * rudder moves at the steering gear's rate, as the paper's UMS did) */
    fw_nomoto_indices ix = {.K = t->K, .T1 = t->T1, .T2 = t->T2, .T3 = t->T3};
    double delta = fabs(t->rudder), scale = t->K * delta, ss = 0.0;
    double w = t->history_weight / sqrt((double)(nh > 0 ? nh : 1));
    for (int s = 0; s < nh; s++) {
        double ts = (s + 1) * t->history_s / nh;
        size_t at = (size_t)lround(ts / d.sample_dt);
        double rate = at < h.n ? fabs(h.s[at].r) : 0.0;
        double e = rate - fw_nomoto_step_rate(&ix, delta, ts);
        ss += e * e;
        r[k++] = w * e / scale;
    }
    if (hist_rms)
        hist_rms[i] = nh ? sqrt(ss / nh) : 0.0;
    fw_history_free(&h);
    return true;
}

static int row_count(const fw_trial_turn *t)
{
    return fw_trial_row_values(t) + fw_trial_row_history(t);
}

static fw_status residuals(const double *p, double *r, void *user, fw_error *err)
{
    (void)err;
    fit_ctx *c = user;
    apply(c, p);
    int k = 0, kv = 0;
    for (int i = 0; i < c->trial->nturns; i++) {
        const fw_trial_turn *t = &c->trial->turns[i];
        int n = row_count(t), nv = fw_trial_row_values(t);
        double rel[4];
        if (!row_residuals(c, i, r + k, rel, c->hist_rms)) {
            /* A coefficient set for which the ship cannot complete the turn
             * (or the integration fails) is a bad point, not the end of the
             * fit: a large residual makes the search step back. */
            for (int j = 0; j < n; j++)
                r[k + j] = 10.0;
            for (int j = 0; j < nv; j++)
                rel[j] = 10.0;
        }
        if (c->rel)
            memcpy(c->rel + kv, rel, (size_t)nv * sizeof *rel);
        k += n;
        kv += nv;
    }
    for (int j = 0; j < c->trial->ntune; j++)
        r[k++] = c->trial->prior_weight * p[j];
    return FW_OK;
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

/* Every row must be a turn the ship's steering gear can make: a target at
 * 40 deg for a 35 deg rudder is bad input, not a point the fit misses. */
static fw_status check_rows(const fw_ship *ship, const fw_trial *trial, fw_error *err)
{
    for (int i = 0; i < trial->nturns; i++) {
        const fw_trial_turn *t = &trial->turns[i];
        double deg = fw_rad_to_deg(fabs(t->rudder));
        if (deg > fw_rad_to_deg(ship->rudder_max) + 1e-9)
            return fw_fail_at(err, trial->file, t->line,
                              t->from_kb ? "nomoto_targets.rudders_deg" : "rudder_deg",
                              "%.15g deg is beyond %s's maximum rudder of %.15g deg", deg, ship->name,
                              fw_rad_to_deg(ship->rudder_max));
    }
    return FW_OK;
}

/* Where the fit starts and what bounds it: p = ln(value / regression). */
static fw_status setup(fit_ctx *c, fw_calibration *cal, double *p, double *lo, double *hi,
                       fw_error *err)
{
    const fw_trial *trial = c->trial;
    for (int j = 0; j < trial->ntune; j++) {
        c->field[j] = fw_ship_field(c->ship, trial->tune[j], NULL, NULL);
        double now = *c->field[j], ref = trial->regression[j];
        if (ref == 0.0)
            ref = now;
        else {
            const char *section;
            double scale;
            fw_ship probe = *c->ship;
            fw_ship_field(&probe, trial->tune[j], &section, &scale);
            ref *= scale; /* file units to SI */
        }
        if (now == 0.0 || ref == 0.0 || (now > 0) != (ref > 0))
            return fw_fail(err, FW_EINPUT,
                           "%s: %s is zero or of the other sign than its regression value and "
                           "cannot be scaled",
                           trial->file, trial->tune[j]);
        c->ref[j] = ref;
        cal->regression[j] = ref;
        cal->before[j] = now;
        lo[j] = -log(trial->factor[j]);
        hi[j] = log(trial->factor[j]);
        p[j] = fmin(fmax(log(now / ref), lo[j]), hi[j]);
    }
    cal->n = trial->ntune;
    return FW_OK;
}

fw_status fw_calibrate(fw_ship *ship, const fw_trial *trial, fw_calibration *cal, fw_error *err)
{
    memset(cal, 0, sizeof *cal);
    fit_ctx c = {.ship = ship, .trial = trial};
    int np = trial->ntune, nr = np, nv = 0;
    for (int i = 0; i < trial->nturns; i++) {
        nr += row_count(&trial->turns[i]);
        nv += fw_trial_row_values(&trial->turns[i]);
    }
    double p[FW_LSQ_MAX_P] = {0}, lo[FW_LSQ_MAX_P], hi[FW_LSQ_MAX_P];
    double rel[4 * FW_TRIAL_MAX_TURNS];
    double *r = malloc((size_t)nr * sizeof *r);
    if (!r)
        return fw_fail(err, FW_ERUN, "out of memory");
    fw_status st;
    if ((st = check_rows(ship, trial, err)) || (st = setup(&c, cal, p, lo, hi, err)))
        goto out;
    double p0[FW_LSQ_MAX_P];
    memcpy(p0, p, sizeof p0);
    c.res = cal->before_res;
    c.hist_rms = cal->hist_before;
    c.rel = rel;
    for (int j = 0; j < np; j++) /* the ship as its file has it */
        p0[j] = log(cal->before[j] / c.ref[j]);
    if ((st = residuals(p0, r, &c, err)))
        goto out;
    stats(rel, nv, &cal->rms_before, &cal->max_before);
    if (trial->check_only) {
        memcpy(p, p0, sizeof p0);
        goto evaluate;
    }
    c.res = NULL;
    c.hist_rms = NULL;
    c.rel = NULL;
    fw_lsq_def def = fw_default_lsq_def();
    def.fd_step = 1e-3; /* relative change of 0.1 percent per coefficient */
    def.ftol = 1e-8;
    def.max_iter = 100;
    def.lo = lo;
    def.hi = hi;
    if ((st = fw_lsq_solve(residuals, &c, np, nr, p, &def, &cal->lsq, err)))
        goto out;
evaluate:
    c.res = cal->after_res;
    c.hist_rms = cal->hist_after;
    c.rel = rel;
    if ((st = residuals(p, r, &c, err)))
        goto out;
    stats(rel, nv, &cal->rms_after, &cal->max_after);
    for (int j = 0; j < np; j++)
        cal->after[j] = *c.field[j];
out:
    free(r);
    return st;
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
        double f = cal->after[j] / cal->regression[j];
        bool curve_fit = fabs(log(f)) > log(trial->physical_factor) + 1e-9;
        snprintf(comment, sizeof comment, "%s fairway calibrate: regression %.6g (x%.3f)%s",
                 curve_fit ? "[FIT]" : "[CAL]", cal->regression[j] / scale, f,
                 curve_fit ? ", curve-fitted: beyond the physical factor" : "");
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
    int measured = 0, from_kb = 0, histories = 0;
    for (int i = 0; i < trial->nturns; i++) {
        const fw_trial_turn *t = &trial->turns[i];
        *(t->from_kb ? &from_kb : &measured) += fw_trial_row_values(t);
        histories += fw_trial_row_history(t) > 0;
    }
    char text[4096];
    size_t used = (size_t)snprintf(
        text, sizeof text,
        "# Calibration: `fairway calibrate --ship %s` against %s (%s).\n"
        "# Tuned by least squares on the relative errors of %d measured values\n"
        "# (advance, transfer, tactical diameter, steady rate)",
        ship->name, trial_name, trial->source[0] ? trial->source : "sea trial", measured);
    if (from_kb && used < sizeof text)
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 ",\n# %d steady rates and %d rate histories of %s", from_kb,
                                 histories, trial->kb_source);
    if (used < sizeof text)
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 ",\n# pulled towards the regression values with weight %g;\n"
                                 "# coefficient, regression value -> fitted (factor):\n",
                                 trial->prior_weight);
    for (int j = 0; j < cal->n && used < sizeof text; j++)
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 "#   %-14s %.6g -> %.6g (x%.3f)\n", trial->tune[j],
                                 cal->regression[j], cal->after[j],
                                 cal->after[j] / cal->regression[j]);
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
