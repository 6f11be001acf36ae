/* The trial file of `fairway calibrate`: measured turning circles, targets
 * from a Nomoto knowledge base, and the coefficients to tune. */
#include "fit/calibrate.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"
#include "nomoto/nomoto.h"
#include "yaml/yaml_tree.h"

/* Sampling of a rate-history target: every 5 s (eq 9's slow pole is 60 s and
 * more at these speeds, so this resolves it with 30 points over 150 s). */
#define HISTORY_DT 5.0

int fw_trial_row_values(const fw_trial_turn *t)
{
    return (t->advance > 0) + (t->transfer > 0) + (t->tactical_diameter > 0) +
           (t->steady_rate > 0);
}

int fw_trial_row_history(const fw_trial_turn *t)
{
    return t->history_s > 0 ? (int)floor(t->history_s / HISTORY_DT + 1e-9) : 0;
}

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

static fw_status read_side(const yt_doc *doc, const yt_node *m, const char *path, double *sign,
                           fw_error *err)
{
    char side[32];
    fw_status st = yt_req_string(doc, m, path, "side", side, sizeof side, err);
    if (st)
        return st;
    if (strcmp(side, "starboard") == 0)
        *sign = 1.0;
    else if (strcmp(side, "port") == 0)
        *sign = -1.0;
    else
        return yt_fail_key(doc, m, path, "side", err, "'%s' is not starboard or port", side);
    return FW_OK;
}

static fw_status load_turn(const yt_doc *doc, const yt_node *m, const char *path,
                           fw_trial_turn *t, fw_error *err)
{
    static const char *const allowed[] = {"side", "speed_kn", "rudder_deg", "advance_m",
                                          "transfer_m", "tactical_diameter_m",
                                          "steady_rate_degps", "simulator", "weight", NULL};
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
    double kn = 0.0, deg = 0.0, sign = 0.0; /* each read before use; -O3 cannot tell */
    t->weight = 1.0;
    if ((st = read_side(doc, m, path, &sign, err)) ||
        (st = yt_req_number(doc, m, path, "speed_kn", 0.5, 40.0, &kn, err)) ||
        (st = yt_req_number(doc, m, path, "rudder_deg", 1.0, 45.0, &deg, err)) ||
        (st = yt_opt_number(doc, m, path, "weight", 0.0, 100.0, &t->weight, err)) ||
        (st = turn_values(doc, m, path, &t->advance, &t->transfer, &t->tactical_diameter,
                          &t->steady_rate, err)))
        return st;
    t->speed = fw_kn_to_ms(kn);
    t->rudder = sign * fw_deg_to_rad(deg);
    t->line = yt_key_line(m, "rudder_deg");
    if (fw_trial_row_values(t) == 0)
        return fw_fail_at(err, doc->file, m->line, path, "no measured value in this row");
    return FW_OK;
}

/* A list of distinct numbers within [lo, hi]. */
static fw_status read_list(const yt_doc *doc, const yt_node *map, const char *path,
                           const char *key, double lo, double hi, double *out, int max, int *n,
                           fw_error *err)
{
    const yt_node *seq;
    char field[96];
    yt_path(field, sizeof field, path, key);
    fw_status st = yt_req_seq(doc, map, path, key, &seq, err);
    if (st)
        return st;
    if (seq->n < 1 || seq->n > (size_t)max)
        return fw_fail_at(err, doc->file, seq->line, field, "give 1 to %d values", max);
    for (size_t i = 0; i < seq->n; i++) {
        char item[128];
        if (snprintf(item, sizeof item, "%s[%zu]", field, i) >= (int)sizeof item)
            item[sizeof item - 1] = '\0';
        if ((st = yt_number(doc, seq->items[i], item, &out[i], err)))
            return st;
        if (!(out[i] >= lo && out[i] <= hi))
            return fw_fail_at(err, doc->file, seq->items[i]->line, item,
                              "%g is outside [%g, %g]", out[i], lo, hi);
    }
    *n = (int)seq->n;
    return FW_OK;
}

typedef struct kb_grid {
    double sign, speeds[8], rudders[16];
    int nspeeds, nrudders;
    double steady_weight, history_s, history_weight;
} kb_grid;

static fw_status read_kb_grid(const yt_doc *doc, const yt_node *m, kb_grid *g, fw_error *err)
{
    const char *p = "nomoto_targets";
    g->steady_weight = 1.0;
    g->history_weight = 1.0;
    g->history_s = 0.0;
    fw_status st;
    if ((st = read_side(doc, m, p, &g->sign, err)) ||
        (st = read_list(doc, m, p, "speeds_kn", 0.5, 40.0, g->speeds, 8, &g->nspeeds, err)) ||
        (st = read_list(doc, m, p, "rudders_deg", 1.0, 45.0, g->rudders, 16, &g->nrudders,
                        err)) ||
        (st = yt_opt_number(doc, m, p, "steady_weight", 0.0, 100.0, &g->steady_weight, err)) ||
        (st = yt_opt_number(doc, m, p, "history_s", 0.0, 200.0, &g->history_s, err)) ||
        (st = yt_opt_number(doc, m, p, "history_weight", 0.0, 100.0, &g->history_weight, err)))
        return st;
    return FW_OK;
}

/* nomoto_targets: the steady rates K delta (eq 10) and, over history_s, the
 * rate histories (eq 9) of another ship file's knowledge base, one row per
 * speed and rudder angle of the grid. */
static fw_status load_kb_targets(const yt_doc *doc, const yt_node *m, fw_trial *trial,
                                 fw_error *err)
{
    static const char *const allowed[] = {"ship", "side", "speeds_kn", "rudders_deg",
                                          "steady_weight", "history_s", "history_weight",
                                          NULL};
    const char *p = "nomoto_targets";
    char name[64];
    kb_grid g;
    fw_status st;
    if ((st = yt_check_keys(doc, m, p, allowed, err)) ||
        (st = yt_req_string(doc, m, p, "ship", name, sizeof name, err)) ||
        (st = read_kb_grid(doc, m, &g, err)))
        return st;
    fw_ship kb_ship;
    fw_error kb_err = {0};
    if (fw_ship_load(name, &kb_ship, &kb_err))
        return yt_fail_key(doc, m, p, "ship", err, "%s", kb_err.msg);
    if (!kb_ship.nomoto.present)
        return yt_fail_key(doc, m, p, "ship", err, "'%s' has no nomoto: knowledge base", name);
    if (trial->nturns + g.nspeeds * g.nrudders > FW_TRIAL_MAX_TURNS)
        return fw_fail_at(err, doc->file, m->line, p,
                          "%d speeds x %d rudders and %d turns exceed %d rows", g.nspeeds,
                          g.nrudders, trial->nturns, FW_TRIAL_MAX_TURNS);
    for (int i = 0; i < g.nspeeds; i++)
        for (int j = 0; j < g.nrudders; j++) {
            fw_nomoto_indices ix;
            if (fw_nomoto_indices_at(&kb_ship.nomoto, g.speeds[i], g.rudders[j], &ix, &kb_err))
                return fw_fail_at(err, doc->file, m->line, p, "%s", kb_err.msg);
            fw_trial_turn *t = &trial->turns[trial->nturns++];
            memset(t, 0, sizeof *t);
            t->speed = fw_kn_to_ms(g.speeds[i]);
            t->rudder = g.sign * fw_deg_to_rad(g.rudders[j]);
            t->steady_rate = fw_deg_to_rad(ix.K * g.rudders[j]);
            t->weight = g.steady_weight;
            t->from_kb = true;
            t->line = yt_key_line(m, "rudders_deg");
            t->K = ix.K;
            t->T1 = ix.T1;
            t->T2 = ix.T2;
            t->T3 = ix.T3;
            t->history_s = g.history_s;
            t->history_weight = g.history_weight;
        }
    /* the ship's name, not its path: the note written into a ship file must
     * stay true wherever the repository is checked out */
    snprintf(trial->kb_source, sizeof trial->kb_source, "%s's nomoto: block", name);
    snprintf(trial->kb_ship, sizeof trial->kb_ship, "%s", name);
    return FW_OK;
}

/* tune: names, or maps {name, regression, max_factor}. */
static fw_status load_tune(const yt_doc *doc, const yt_node *tune, fw_trial *trial, fw_error *err)
{
    fw_ship probe;
    memset(&probe, 0, sizeof probe);
    if (tune->n < 1 || tune->n > FW_LSQ_MAX_P)
        return fw_fail_at(err, doc->file, tune->line, "tune", "needs 1 to %d names", FW_LSQ_MAX_P);
    for (size_t i = 0; i < tune->n; i++) {
        const yt_node *n = tune->items[i];
        char field[64], name[32] = "";
        snprintf(field, sizeof field, "tune[%zu]", i);
        int j = trial->ntune++;
        trial->factor[j] = trial->max_factor;
        trial->regression[j] = 0.0;
        fw_status st;
        if (n->kind == YT_MAP) {
            static const char *const allowed[] = {"name", "regression", "max_factor", NULL};
            if ((st = yt_check_keys(doc, n, field, allowed, err)) ||
                (st = yt_req_string(doc, n, field, "name", name, sizeof name, err)) ||
                (st = yt_opt_number(doc, n, field, "regression", -1e3, 1e3,
                                    &trial->regression[j], err)) ||
                (st = yt_opt_number(doc, n, field, "max_factor", 1.01, 100.0, &trial->factor[j],
                                    err)))
                return st;
        } else if (n->kind == YT_SCALAR && strlen(n->str) < sizeof name) {
            snprintf(name, sizeof name, "%s", n->str);
        }
        if (!fw_ship_field(&probe, name, NULL, NULL))
            return fw_fail_at(err, doc->file, n->line, field, "'%s' is not a ship-file field",
                              name[0] ? name : "?");
        snprintf(trial->tune[j], sizeof trial->tune[0], "%s", name);
    }
    return FW_OK;
}

static fw_status load_turns(const yt_doc *doc, const yt_node *turns, fw_trial *trial,
                            fw_error *err)
{
    if (turns->n < 1 || turns->n > FW_TRIAL_MAX_TURNS)
        return fw_fail_at(err, doc->file, turns->line, "turns", "needs 1 to %d rows",
                          FW_TRIAL_MAX_TURNS);
    for (size_t i = 0; i < turns->n; i++) {
        char field[64];
        snprintf(field, sizeof field, "turns[%zu]", i);
        if (turns->items[i]->kind != YT_MAP)
            return fw_fail_at(err, doc->file, turns->items[i]->line, field,
                              "expected a mapping");
        fw_status st = load_turn(doc, turns->items[i], field, &trial->turns[trial->nturns++], err);
        if (st)
            return st;
    }
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
    const yt_node *root = doc->root, *turns = NULL, *tune, *kb = NULL;
    static const char *const allowed[] = {"ship", "source", "tune", "max_factor",
                                          "prior_weight", "physical_factor", "turns",
                                          "nomoto_targets", NULL};
    trial->max_factor = 4.0;
    if ((st = yt_check_keys(doc, root, "", allowed, err)) ||
        (st = yt_req_string(doc, root, "", "ship", trial->ship, sizeof trial->ship, err)) ||
        (st = yt_opt_string(doc, root, "", "source", trial->source, sizeof trial->source, err)) ||
        (st = yt_opt_number(doc, root, "", "max_factor", 1.01, 100.0, &trial->max_factor, err)) ||
        (st = yt_opt_number(doc, root, "", "prior_weight", 0.0, 100.0, &trial->prior_weight,
                            err)) ||
        (st = yt_opt_number(doc, root, "", "physical_factor", 1.01, 100.0,
                            &trial->physical_factor, err)) ||
        (st = yt_req_seq(doc, root, "", "tune", &tune, err)) ||
        (st = yt_opt_seq(doc, root, "", "turns", &turns, err)) ||
        (st = yt_opt_map(doc, root, "", "nomoto_targets", &kb, err)) ||
        (turns && (st = load_turns(doc, turns, trial, err))) ||
        (kb && (st = load_kb_targets(doc, kb, trial, err))) ||
        (st = load_tune(doc, tune, trial, err)))
        goto out;
    if (!turns && !kb) {
        st = fw_fail_at(err, doc->file, root->line, "turns",
                        "no targets: give turns, nomoto_targets or both");
        goto out;
    }
    if (trial->physical_factor == 0.0)
        trial->physical_factor = trial->max_factor;
    int measured = 0;
    for (int i = 0; i < trial->nturns; i++)
        measured += fw_trial_row_values(&trial->turns[i]);
    if (trial->ntune > measured)
        st = fw_fail_at(err, doc->file, tune->line, "tune",
                        "%d coefficients cannot be fitted to %d target values", trial->ntune,
                        measured);
out:
    yt_free(doc);
    return st;
}
