/* study_axes.c - a study's `axes:` (study.h): any key of its scenario swept,
 * each combination of the values a setting with a scenario of its own. */
#include <stdio.h>
#include <string.h>

#include "study/study.h"
#include "study/study_axes.h"

/* Keys of a scenario that `axes:` may not sweep: the study sweeps them
 * itself, draws them, or holds them fixed (its inputs' digests, the run's
 * names), with what to use instead. */
static const char *held_key(const char *key)
{
    static const char *const held[][2] = {
        {"name", "it names the runs"},
        {"description", "it is not a setting"},
        {"own_ship.ship", "a study sails one ship (its file is a digested input)"},
        {"traffic.network", "a study sails one network (its files are digested inputs)"},
        {"traffic.ais", "a study replays one recording"},
        {"traffic.tracks", "a study replays one set of tracks"},
        {"traffic.density", "use densities:"},
        {"traffic.behaviour", "use behaviours:"},
        {"avoidance.domain_m", "use domains_m: or domains_l:"},
        {"avoidance.fore_aft_ratio", "use fore_aft_ratios:"},
        {"run", "the study draws the seeds, sets duration_s and holds the step"},
        {"outputs", "outputs are not a setting"},
    };
    for (size_t i = 0; i < sizeof held / sizeof held[0]; i++) {
        size_t n = strlen(held[i][0]);
        if (strncmp(key, held[i][0], n) == 0 && (key[n] == '\0' || key[n] == '.'))
            return held[i][1];
    }
    return NULL;
}

/* axes: {KEY: [v, ...], ...}: keys and values as written, checked for form
 * here; each value is checked by the scenario's reader in load_settings. */
fw_status fw_study_read_axes(const yt_doc *doc, const yt_node *root, fw_study *s, fw_error *err)
{
    const yt_node *m = NULL;
    fw_status st = yt_opt_map(doc, root, "", "axes", &m, err);
    if (st || !m)
        return st;
    if (m->n == 0 || m->n > FW_STUDY_MAX_AXES)
        return fw_fail_at(err, doc->file, m->line, "axes", "give 1 to %d keys, not %zu",
                          FW_STUDY_MAX_AXES, m->n);
    long settings = 1;
    for (size_t i = 0; i < m->n; i++) {
        fw_study_axis *a = &s->axes[i];
        const char *key = m->keys[i];
        const yt_node *seq = m->items[i];
        char field[96];
        snprintf(field, sizeof field, "axes.%.60s", key);
        a->line = m->key_lines[i];
        const char *why = held_key(key);
        if (why)
            return fw_fail_at(err, doc->file, a->line, field, "not an axis: %s", why);
        if (strlen(key) >= sizeof a->key || !key[0] || key[0] == '.' ||
            key[strlen(key) - 1] == '.' || strstr(key, "..") ||
            strspn(key, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.") !=
                strlen(key))
            return fw_fail_at(err, doc->file, a->line, field,
                              "a dotted key of the scenario file (letters, digits, _) of at most %zu "
                              "characters",
                              sizeof a->key - 1);
        if (seq->kind != YT_SEQ || seq->n < 1 || seq->n > FW_STUDY_MAX_AXIS_LEVELS)
            return fw_fail_at(err, doc->file, seq->line, field, "give a list of 1 to %d values",
                              FW_STUDY_MAX_AXIS_LEVELS);
        snprintf(a->key, sizeof a->key, "%s", key);
        for (size_t j = 0; j < seq->n; j++) {
            const yt_node *v = seq->items[j];
            snprintf(field, sizeof field, "axes.%.60s[%zu]", key, j);
            /* the values name the settings in the database and the report
             * ("key=value, ..."; meta's "key: v, v; ..."; CSV cells, Markdown
             * tables): none of those marks */
            if (v->kind != YT_SCALAR || !v->str || !v->str[0] ||
                strlen(v->str) >= sizeof a->values[0] || strpbrk(v->str, "\",;=|"))
                return fw_fail_at(err, doc->file, v->line, field,
                                  "a value (a number or a word of at most %zu characters, "
                                  "without quotes, commas, ';', '=' or '|')",
                                  sizeof a->values[0] - 1);
            for (size_t k = 0; k < j; k++)
                if (strcmp(a->values[k], v->str) == 0)
                    return fw_fail_at(err, doc->file, v->line, field, "%s is listed twice",
                                      v->str);
            snprintf(a->values[j], sizeof a->values[j], "%s", v->str);
            a->value_line[j] = v->line;
        }
        a->n = (int)seq->n;
        settings *= a->n;
    }
    if (settings > FW_STUDY_MAX_SETTINGS)
        return fw_fail_at(err, doc->file, m->line, "axes",
                          "%ld combinations of values; at most %d", settings,
                          FW_STUDY_MAX_SETTINGS);
    s->n_axes = (int)m->n;
    s->n_settings = (int)settings;
    return FW_OK;
}

/* The axes' value indices of setting k, the last axis fastest. */
static void setting_levels(const fw_study *s, int k, int *level)
{
    for (int i = s->n_axes - 1; i >= 0; i--) {
        level[i] = k % s->axes[i].n;
        k /= s->axes[i].n;
    }
}

const char *fw_study_setting_label(const fw_study *s, int k, char *buf, size_t n)
{
    int level[FW_STUDY_MAX_AXES];
    size_t used = 0;
    buf[0] = '\0';
    setting_levels(s, k, level);
    for (int i = 0; i < s->n_axes && used < n; i++)
        used += (size_t)snprintf(buf + used, n - used, "%s%s=%s", i ? ", " : "", s->axes[i].key,
                                 s->axes[i].values[level[i]]);
    return buf;
}

/* Each setting's scenario: the base file with its values laid over it, read
 * by the scenario's own reader (an error names the study's axis and value,
 * then the scenario's message).  What a study holds fixed must come out the
 * same as the base's, whatever key changed it. */
/* Each value alone over the base first, so that a bad one is named where
 * the study file has it (a scenario is s->settings[0], overwritten below). */
static fw_status check_values(const yt_doc *doc, fw_study *s, fw_error *err)
{
    for (int i = 0; i < s->n_axes; i++)
        for (int j = 0; j < s->axes[i].n; j++) {
            fw_setting one = {s->axes[i].key, s->axes[i].values[j]};
            if (fw_scenario_load_with(s->scenario_file, &one, 1, &s->settings[0], err)) {
                char msg[sizeof err->msg], field[96];
                snprintf(msg, sizeof msg, "%s", err->msg);
                snprintf(field, sizeof field, "axes.%.60s[%d]", s->axes[i].key, j);
                return fw_fail_at(err, doc->file, s->axes[i].value_line[j], field, "%s", msg);
            }
        }
    return FW_OK;
}

fw_status fw_study_load_settings(const yt_doc *doc, fw_study *s, fw_error *err)
{
    fw_status st = check_values(doc, s, err);
    if (st)
        return st;
    for (int k = 0; k < s->n_settings && s->n_axes; k++) {
        int level[FW_STUDY_MAX_AXES];
        fw_setting set[FW_STUDY_MAX_AXES];
        setting_levels(s, k, level);
        for (int i = 0; i < s->n_axes; i++)
            set[i] = (fw_setting){s->axes[i].key, s->axes[i].values[level[i]]};
        fw_scenario *v = &s->settings[k];
        char label[256];
        fw_study_setting_label(s, k, label, sizeof label);
        if (fw_scenario_load_with(s->scenario_file, set, s->n_axes, v, err)) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            return fw_fail_at(err, doc->file, s->axes[0].line, "axes",
                              "the setting %s: %s", label, msg);
        }
        if (strcmp(v->ship.file, s->base.ship.file) || strcmp(v->network, s->base.network) ||
            strcmp(v->ais.file, s->base.ais.file) || v->step != s->base.step ||
            v->n_targets != s->base.n_targets)
            return fw_fail_at(err, doc->file, s->axes[0].line, "axes",
                              "the setting %s changes the ship, network, recorded traffic, "
                              "targets or step, which a study holds fixed", label);
        v->audit = s->base.audit; /* the study's audit: audit: above */
    }
    return FW_OK;
}
