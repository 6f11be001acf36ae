/* study.c - study files and the run list (see study.h). */
#include <libgen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"
#include "ship/ship.h"
#include "scenario/scenario.h"
#include "study/study.h"
#include "study/study_axes.h"
#include "traffic/demand.h"
#include "yaml/yaml_tree.h"

/* splitmix64: a well-mixed value per (seed, stream, replication), the same on
 * every machine, so a replication's traffic never depends on who runs it. */
static uint64_t mix(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

static double uniform_pm(uint64_t h) /* in [-1, 1) */
{
    return (double)(h >> 11) * 0x1.0p-53 * 2.0 - 1.0;
}

static fw_status read_levels(const yt_doc *doc, const yt_node *root, const char *key, double lo,
                             double hi, bool required, double *out, int *n, fw_error *err)
{
    const yt_node *seq = NULL;
    fw_status st = required ? yt_req_seq(doc, root, "", key, &seq, err)
                            : yt_opt_seq(doc, root, "", key, &seq, err);
    if (st || !seq)
        return st;
    if (seq->n == 0 || seq->n > FW_STUDY_MAX_LEVELS)
        return fw_fail_at(err, doc->file, seq->line, key, "give 1 to %d values, not %zu",
                          FW_STUDY_MAX_LEVELS, seq->n);
    for (size_t i = 0; i < seq->n; i++) {
        char field[64];
        snprintf(field, sizeof field, "%s[%zu]", key, i);
        if ((st = yt_number(doc, seq->items[i], field, &out[i], err)))
            return st;
        if (!(out[i] >= lo && out[i] <= hi))
            return fw_fail_at(err, doc->file, seq->items[i]->line, field,
                              "%g is outside [%g, %g]", out[i], lo, hi);
        for (size_t j = 0; j < i; j++)
            if (out[j] == out[i])
                return fw_fail_at(err, doc->file, seq->items[i]->line, field,
                                  "%g is listed twice", out[i]);
    }
    *n = (int)seq->n;
    return FW_OK;
}

/* behaviours: [colregs, blind]: each a name fw_behaviour_parse knows, once. */
static fw_status read_behaviours(const yt_doc *doc, const yt_node *root, fw_study *s,
                                 fw_error *err)
{
    const yt_node *seq = NULL;
    fw_status st = yt_opt_seq(doc, root, "", "behaviours", &seq, err);
    if (st || !seq)
        return st;
    if (seq->n == 0 || seq->n > FW_STUDY_MAX_BEHAVIOURS)
        return fw_fail_at(err, doc->file, seq->line, "behaviours", "give 1 to %d names, not %zu",
                          FW_STUDY_MAX_BEHAVIOURS, seq->n);
    for (size_t i = 0; i < seq->n; i++) {
        const yt_node *it = seq->items[i];
        char field[48];
        snprintf(field, sizeof field, "behaviours[%zu]", i);
        if (it->kind != YT_SCALAR || !it->str || fw_behaviour_parse(it->str, &s->behaviours[i]))
            return fw_fail_at(err, doc->file, it->line, field,
                              "'%s' is not a behaviour (colregs or blind)",
                              it->str ? it->str : "");
        for (size_t j = 0; j < i; j++)
            if (s->behaviours[j] == s->behaviours[i])
                return fw_fail_at(err, doc->file, it->line, field, "%s is listed twice", it->str);
    }
    s->n_behaviours = (int)seq->n;
    return FW_OK;
}

/* domains_m, or domains_l in own-ship lengths (made metres once the ship is
 * loaded: fw_study_load), and fore_aft_ratios. */
static fw_status read_domains(const yt_doc *doc, const yt_node *root, fw_study *s, fw_error *err)
{
    bool m = yt_get(root, "domains_m") != NULL, l = yt_get(root, "domains_l") != NULL;
    if (m && l)
        return fw_fail_at(err, doc->file, yt_key_line(root, "domains_l"), "domains_l",
                          "give domains_m or domains_l, not both");
    if (!m && !l)
        return fw_fail_at(err, doc->file, 1, "domains_m",
                          "required field is missing (or domains_l, in own-ship lengths)");
    s->domains_in_lengths = l;
    fw_status st = m ? read_levels(doc, root, "domains_m", 10.0, 20000.0, true, s->domains,
                                   &s->n_domains, err)
                     : read_levels(doc, root, "domains_l", 0.05, 60.0, true, s->domain_lengths,
                                   &s->n_domains, err);
    if (st)
        return st;
    return read_levels(doc, root, "fore_aft_ratios", 0.2, 10.0, false, s->ratios, &s->n_ratios,
                       err);
}

/* audit: {risk_dcpa_m, ...}: the COLREGs audit's thresholds (audit/audit.h),
 * each optional over its default, checked together. */
static fw_status read_audit(const yt_doc *doc, const yt_node *root, fw_study *s, fw_error *err)
{
    static const char *const keys[] = {"risk_dcpa_m", "risk_tcpa_s", "course_change_deg",
                                       "speed_change", "early_tcpa_s", "prompt_s",
                                       "rule17_may_tcpa_s", "rule17_must_tcpa_s", NULL};
    const yt_node *m = NULL;
    fw_audit_def *a = &s->base.audit;
    double course = fw_rad_to_deg(a->course_change);
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "audit", &m, err)) || !m)
        return st;
    if ((st = yt_check_keys(doc, m, "audit", keys, err)) ||
        (st = yt_opt_number(doc, m, "audit", "risk_dcpa_m", -1e300, 1e300, &a->risk_dcpa, err)) ||
        (st = yt_opt_number(doc, m, "audit", "risk_tcpa_s", -1e300, 1e300, &a->risk_tcpa, err)) ||
        (st = yt_opt_number(doc, m, "audit", "course_change_deg", -1e300, 1e300, &course, err)) ||
        (st = yt_opt_number(doc, m, "audit", "speed_change", -1e300, 1e300, &a->speed_change,
                            err)) ||
        (st = yt_opt_number(doc, m, "audit", "early_tcpa_s", -1e300, 1e300, &a->early_tcpa,
                            err)) ||
        (st = yt_opt_number(doc, m, "audit", "prompt_s", -1e300, 1e300, &a->prompt, err)) ||
        (st = yt_opt_number(doc, m, "audit", "rule17_may_tcpa_s", -1e300, 1e300, &a->may_tcpa,
                            err)) ||
        (st = yt_opt_number(doc, m, "audit", "rule17_must_tcpa_s", -1e300, 1e300, &a->must_tcpa,
                            err)))
        return st;
    a->course_change = fw_deg_to_rad(course);
    char field[64];
    fw_error e2 = {0};
    if (fw_audit_check(a, field, sizeof field, &e2)) {
        int line = yt_key_line(m, field);
        char path[80];
        snprintf(path, sizeof path, "audit.%s", field);
        return fw_fail_at(err, doc->file, line > 0 ? line : m->line, path, "%s",
                          strchr(e2.msg, ':') ? strchr(e2.msg, ':') + 2 : e2.msg);
    }
    return FW_OK;
}

/* estimate: {method: splitting, particles, batches, seed}: refused for a
 * scenario nothing in which draws after t = 0 (scenario.h fw_scenario_randomness). */
static fw_status read_estimate(const yt_doc *doc, const yt_node *root, fw_study *s, fw_error *err)
{
    static const char *const keys[] = {"method", "particles", "batches", "seed", NULL};
    const yt_node *m = NULL;
    fw_status st;
    if ((st = yt_opt_map(doc, root, "", "estimate", &m, err)) || !m)
        return st;
    char method[32] = "";
    long particles = 50, batches = 8, seed = 1;
    if ((st = yt_check_keys(doc, m, "estimate", keys, err)) ||
        (st = yt_req_string(doc, m, "estimate", "method", method, sizeof method, err)))
        return st;
    if (strcmp(method, "splitting") != 0)
        return fw_fail_at(err, doc->file, yt_key_line(m, "method"), "estimate.method",
                          "'%s': the one method is splitting (adaptive multilevel splitting)",
                          method);
    if ((st = yt_opt_int(doc, m, "estimate", "particles", 2, 100000, &particles, err)) ||
        (st = yt_opt_int(doc, m, "estimate", "batches", 2, 10000, &batches, err)) ||
        (st = yt_opt_int(doc, m, "estimate", "seed", 0, 2147483647L, &seed, err)))
        return st;
    for (int k = 0; k < s->n_settings; k++) {
        const char *why = fw_scenario_randomness(s->n_axes ? &s->settings[k] : &s->base);
        char label[256];
        if (why)
            return fw_fail_at(err, doc->file, m->line, "estimate",
                              "%s%s%s has no randomness after t = 0 (%s): every branch would "
                              "repeat its parent; count the runs instead (crude Monte Carlo)",
                              s->scenario_file, s->n_axes ? " with " : "",
                              fw_study_setting_label(s, k, label, sizeof label), why);
    }
    s->estimate = (fw_study_estimate){.on = true, .particles = (int)particles,
                                      .batches = (int)batches, .seed = (unsigned long)seed};
    return FW_OK;
}

/* The scenario path is relative to the study file's directory; false when
 * the result does not fit in out. */
static bool resolve(const char *study_file, const char *rel, char *out, size_t outsz)
{
    if (rel[0] == '/')
        return (size_t)snprintf(out, outsz, "%s", rel) < outsz;
    char tmp[512];
    if ((size_t)snprintf(tmp, sizeof tmp, "%s", study_file) >= sizeof tmp)
        return false;
    return (size_t)snprintf(out, outsz, "%s/%s", dirname(tmp), rel) < outsz;
}

static uint64_t file_digest(uint64_t h, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return h;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        h = fw_fnv1a(h, buf, n);
    fclose(f);
    return h;
}

static fw_status add_input(fw_study *s, const char *role, const char *path, fw_error *err)
{
    if (s->n_inputs >= FW_STUDY_MAX_INPUTS)
        return fw_fail(err, FW_ERUN, "%s: more than %d input files", s->file,
                       FW_STUDY_MAX_INPUTS);
    fw_study_input *in = &s->inputs[s->n_inputs];
    if (fw_path_copy(in->path, sizeof in->path, path, err))
        return err->status;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fw_fail(err, FW_EINPUT, "%s: cannot read this input of study %s", path, s->file);
    fclose(f);
    in->role = role;
    in->digest = file_digest(FW_FNV_INIT, path);
    s->n_inputs++;
    return FW_OK;
}

/* Every file a run of the study reads (see src/run/run.c): the study, its
 * scenario and ship, its AIS reports, and the network's demand, ship types
 * and plain XML.
 * The net.xml SUMO reads is built from exactly these bytes (the network
 * cache is keyed by them, traffic/netbuild.h), so their digests stand for
 * it; targets' tracks are written by each run, from the scenario. */
static fw_status collect_inputs(fw_study *s, fw_error *err)
{
    fw_status st;
    if ((st = add_input(s, "study", s->file, err)) ||
        (st = add_input(s, "scenario", s->scenario_file, err)) ||
        (st = add_input(s, "ship", s->base.ship.file, err)) ||
        (s->base.ais.file[0] && (st = add_input(s, "ais", s->base.ais.file, err))))
        return st;
    const char *net = s->base.network;
    if (!net[0])
        return FW_OK;
    fw_network_files nf;
    if ((st = fw_network_find(net, &nf, err)) || (st = add_input(s, "demand", nf.demand, err)) ||
        (st = add_input(s, "ship_types", nf.types, err)))
        return st;
    const char *const parts[][2] = {
        {"network_nodes", nf.nodes}, {"network_edges", nf.edges}, {"network_types", nf.typ}};
    for (int i = 0; i < 3; i++)
        if (parts[i][1][0] && (st = add_input(s, parts[i][0], parts[i][1], err)))
            return st;
    return FW_OK;
}

/* The base scenario, path relative to the study file; its own FILE:LINE
 * message is kept, with where the study named it. */
static fw_status load_base(const yt_doc *doc, const yt_node *root, const char *path,
                           const char *scen, fw_study *s, fw_error *err)
{
    int line = yt_key_line(root, "scenario");
    if (!resolve(path, scen, s->scenario_file, sizeof s->scenario_file))
        return fw_fail_at(err, doc->file, line, "scenario", "path longer than %zu characters",
                          sizeof s->scenario_file - 1);
    if (fw_scenario_load(s->scenario_file, &s->base, err)) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err ? err->msg : "");
        return fw_fail_at(err, doc->file, line, "scenario", "%s", msg);
    }
    if (s->base.n_targets == 0 && !s->base.network[0] && !s->base.ais.file[0])
        return fw_fail_at(err, doc->file, line, "scenario",
                          "%s has no traffic (no network, no targets, no AIS reports)",
                          s->scenario_file);
    return FW_OK;
}

/* Recorded traffic (traffic: ais:) is replayed, the same every run: its
 * ships do not react (no behaviours to sweep; densities are refused with the
 * network), a replication differs from another only by where and when the
 * own ship starts, and start.time_s has a meaning there alone. */
static fw_status check_recorded(const yt_doc *doc, const yt_node *root, const yt_node *start,
                                const fw_study *s, fw_error *err)
{
    bool ais = s->base.ais.file[0] != '\0';
    if (!ais && s->start_time > 0.0)
        return fw_fail_at(err, doc->file, yt_key_line(start, "time_s"), "start.time_s",
                          "only over recorded traffic (traffic: ais:); simulated traffic "
                          "differs by its seed");
    if (!ais)
        return FW_OK;
    if (s->n_behaviours > 0)
        return fw_fail_at(err, doc->file, yt_key_line(root, "behaviours"), "behaviours",
                          "%s replays recorded ships, which do not react: no behaviour to sweep",
                          s->scenario_file);
    if (s->replications > 1 && !(s->start_time > 0.0 || s->start_along > 0.0 ||
                                 s->start_across > 0.0))
        return fw_fail_at(err, doc->file, yt_key_line(root, "replications"), "replications",
                          "%d over recorded traffic would be %d copies of one run: give the "
                          "start a spread (start: time_s, along_m or across_m)",
                          s->replications, s->replications);
    return FW_OK;
}

static uint64_t digest(const fw_study *s)
{
    /* the settings that decide the results, printed exactly, and the bytes of
     * the scenario and ship files: a resumed sweep must be the same study */
    char text[4096];
    int k = snprintf(text, sizeof text, "%s|%d|%lu|%.17g|%.17g|%.17g|%.17g|%.17g|", s->name,
                     s->replications, s->seed, s->duration, s->start_along, s->start_across,
                     s->encounter_range, s->near_miss);
    for (int i = 0; i < s->n_domains && k < (int)sizeof text - 32; i++)
        k += snprintf(text + k, sizeof text - (size_t)k, "d%.17g|", s->domains[i]);
    for (int i = 0; i < s->n_densities && k < (int)sizeof text - 32; i++)
        k += snprintf(text + k, sizeof text - (size_t)k, "r%.17g|", s->densities[i]);
    const fw_audit_def *a = &s->base.audit;
    k += snprintf(text + k, sizeof text - (size_t)k,
                  "a%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g|", a->risk_dcpa, a->risk_tcpa,
                  a->course_change, a->speed_change, a->early_tcpa, a->prompt, a->may_tcpa,
                  a->must_tcpa);
    for (int i = 0; i < s->n_ratios && k < (int)sizeof text - 32; i++)
        k += snprintf(text + k, sizeof text - (size_t)k, "f%.17g|", s->ratios[i]);
    for (int i = 0; i < s->n_behaviours && k < (int)sizeof text - 32; i++)
        k += snprintf(text + k, sizeof text - (size_t)k, "b%s|", fw_behaviour_name(s->behaviours[i]));
    /* only when set: the studies from before it keep their digests */
    if (s->start_time > 0.0)
        k += snprintf(text + k, sizeof text - (size_t)k, "t%.17g|", s->start_time);
    const fw_study_estimate *e = &s->estimate;
    if (e->on)
        k += snprintf(text + k, sizeof text - (size_t)k, "e%d,%d,%lu|", e->particles, e->batches,
                      e->seed);
    for (int i = 0; i < s->n_axes && k < (int)sizeof text - 400; i++) {
        k += snprintf(text + k, sizeof text - (size_t)k, "x%s", s->axes[i].key);
        for (int j = 0; j < s->axes[i].n; j++)
            k += snprintf(text + k, sizeof text - (size_t)k, "%c%s", j ? ',' : '=',
                          s->axes[i].values[j]);
        k += snprintf(text + k, sizeof text - (size_t)k, "|");
    }
    uint64_t h = fw_fnv1a(FW_FNV_INIT, text, strlen(text));
    h = file_digest(h, s->scenario_file);
    return file_digest(h, s->base.ship.file);
}

fw_status fw_study_load(const char *path, fw_study *s, fw_error *err)
{
    static const char *const keys[] = {"name", "description", "scenario", "replications", "seed",
                                       "domains_m", "domains_l", "fore_aft_ratios", "densities",
                                       "behaviours", "duration_s",
                                       "start", "encounter_m", "near_miss_m", "audit", "estimate",
                                       "axes", NULL};
    memset(s, 0, sizeof *s);
    if (fw_path_copy(s->file, sizeof s->file, path, err))
        return err->status;
    s->encounter_range = 1852.0;
    s->near_miss = 185.2;
    s->n_settings = 1;
    yt_doc *doc = NULL;
    fw_status st = yt_load_file(path, &doc, err);
    if (st)
        return st;
    const yt_node *root = doc->root, *start = NULL;
    char scen[512] = "";
    long reps = 0, seed = 1;
    if ((st = yt_top_map(doc, keys, "name, scenario, replications, domains_m", s->name,
                         sizeof s->name, s->description, sizeof s->description, err)) ||
        (st = yt_req_string(doc, root, "", "scenario", scen, sizeof scen, err)) ||
        (st = yt_req_int(doc, root, "", "replications", 1, 100000, &reps, err)) ||
        (st = yt_opt_int(doc, root, "", "seed", 0, 2147483647L, &seed, err)) ||
        (st = read_domains(doc, root, s, err)) ||
        (st = read_levels(doc, root, "densities", 0.0, 100.0, false, s->densities,
                          &s->n_densities, err)) ||
        (st = read_behaviours(doc, root, s, err)) || (st = fw_study_read_axes(doc, root, s, err)) ||
        (st = yt_opt_number(doc, root, "", "encounter_m", 1.0, 1e6, &s->encounter_range, err)) ||
        (st = yt_opt_number(doc, root, "", "near_miss_m", 0.0, 1e6, &s->near_miss, err)) ||
        (st = yt_opt_map(doc, root, "", "start", &start, err)))
        goto out;
    char msg[200];
    if (!yt_name_ok(s->name, sizeof s->name - 1, false,
                    "letters, digits, '-' or '_' (it names the runs)", msg, sizeof msg)) {
        st = fw_fail_at(err, doc->file, yt_key_line(root, "name"), "name", "%s", msg);
        goto out;
    }
    if (start) {
        static const char *const skeys[] = {"along_m", "across_m", "time_s", NULL};
        if ((st = yt_check_keys(doc, start, "start", skeys, err)) ||
            (st = yt_opt_number(doc, start, "start", "time_s", 0.0, 366.0 * 86400.0,
                                &s->start_time, err)) ||
            (st = yt_opt_number(doc, start, "start", "along_m", 0.0, 1e5, &s->start_along,
                                err)) ||
            (st = yt_opt_number(doc, start, "start", "across_m", 0.0, 1e5, &s->start_across,
                                err)))
            goto out;
    }
    s->replications = (int)reps;
    s->seed = (unsigned long)seed;
    if ((long)s->replications * s->n_domains * (s->n_densities ? s->n_densities : 1) *
            (s->n_behaviours ? s->n_behaviours : 1) * (s->n_ratios ? s->n_ratios : 1) *
            s->n_settings >
        10000000L) {
        st = fw_fail_at(err, doc->file, yt_key_line(root, "replications"), "replications",
                        "more than 10 million runs");
        goto out;
    }
    if ((st = load_base(doc, root, path, scen, s, err)) || (st = read_audit(doc, root, s, err)) ||
        (st = fw_study_load_settings(doc, s, err)) || (st = read_estimate(doc, root, s, err)) ||
        (st = check_recorded(doc, root, start, s, err)))
        goto out;
    if (s->n_behaviours == 0) {
        s->n_behaviours = 1;
        s->behaviours[0] = s->base.reactions.behaviour;
    }
    if (s->n_ratios == 0) {
        s->n_ratios = 1;
        s->ratios[0] = s->base.helm.domain.fore_aft_ratio;
    }
    for (int i = 0; s->domains_in_lengths && i < s->n_domains; i++)
        s->domains[i] = s->domain_lengths[i] * s->base.ship.Loa;
    if (s->n_densities == 0) {
        s->n_densities = 1;
        s->densities[0] = s->base.density;
    } else if (!s->base.network[0]) {
        st = fw_fail_at(err, doc->file, yt_key_line(root, "densities"), "densities",
                        "the scenario has no network whose demand they could scale");
        goto out;
    }
    s->duration = s->base.duration;
    if ((st = yt_opt_number(doc, root, "", "duration_s", 1.0, 30.0 * 86400.0, &s->duration, err)))
        goto out;
    if (fabs(s->duration / s->base.step - round(s->duration / s->base.step)) > 1e-9) {
        st = fw_fail_at(err, doc->file, yt_key_line(root, "duration_s"), "duration_s",
                        "%g s is not a whole number of steps of %g s", s->duration,
                        s->base.step);
        goto out;
    }
    s->digest = digest(s);
    st = collect_inputs(s, err);
out:
    yt_free(doc);
    return st;
}

int fw_study_run_count(const fw_study *s)
{
    return s->n_settings * s->n_densities * s->replications * s->n_behaviours * s->n_ratios *
           s->n_domains;
}

/* The seed and the start of a replication (or a splitting start) from its
 * base number: the replication alone decides them (common random numbers). */
static void draw_start(const fw_study *s, uint64_t base, fw_study_run *r)
{
    r->seed = 1 + (unsigned long)(base % 2147483646ull);
    r->d_along = s->start_along * uniform_pm(mix(base ^ 0xa1a1a1a1ull));
    r->d_across = s->start_across * uniform_pm(mix(base ^ 0xc3c3c3c3ull));
    r->d_time = s->start_time * 0.5 * (1.0 + uniform_pm(mix(base ^ 0xe5e5e5e5ull)));
}

fw_study_run fw_study_run_at(const fw_study *s, int run_id)
{
    fw_study_run r = {.run_id = run_id};
    int per_rep = s->n_domains * s->n_ratios * s->n_behaviours;
    r.domain_index = run_id % s->n_domains;
    r.ratio_index = (run_id / s->n_domains) % s->n_ratios;
    r.behaviour_index = (run_id / (s->n_domains * s->n_ratios)) % s->n_behaviours;
    r.replication = (run_id / per_rep) % s->replications;
    r.density_index = (run_id / (per_rep * s->replications)) % s->n_densities;
    r.setting_index = run_id / (per_rep * s->replications * s->n_densities);
    r.domain = s->domains[r.domain_index];
    r.density = s->densities[r.density_index];
    r.behaviour = s->behaviours[r.behaviour_index];
    r.ratio = s->ratios[r.ratio_index];
    draw_start(s, mix((uint64_t)s->seed * 0x100000001b3ull + (uint64_t)r.replication), &r);
    return r;
}

int fw_study_cell_count(const fw_study *s)
{
    return s->n_settings * s->n_densities * s->n_behaviours * s->n_ratios * s->n_domains;
}

fw_study_run fw_study_cell(const fw_study *s, int cell)
{
    int per_rep = s->n_domains * s->n_ratios * s->n_behaviours;
    /* replication 0 of the cell's (setting, density) block */
    int run_id = (cell / per_rep) * per_rep * s->replications + cell % per_rep;
    return fw_study_run_at(s, run_id);
}

fw_study_run fw_study_run_drawn(const fw_study *s, int cell, uint64_t draw)
{
    fw_study_run r = fw_study_cell(s, cell);
    draw_start(s, mix(draw), &r);
    return r;
}

void fw_study_scenario(const fw_study *s, const fw_study_run *r, fw_scenario *out)
{
    *out = s->n_axes ? s->settings[r->setting_index] : s->base;
    snprintf(out->name, sizeof out->name, "%.40s-%06d", s->name, r->run_id);
    out->helm.domain.size = r->domain;
    out->helm.domain.fore_aft_ratio = r->ratio;
    out->density = r->density;
    out->reactions.behaviour = r->behaviour;
    out->seed = r->seed;
    out->duration = s->duration;
    double se = sin(out->course), ce = cos(out->course);
    out->east += r->d_along * se + r->d_across * ce;
    out->north += r->d_along * ce - r->d_across * se;
    if (out->ais.file[0] && r->d_time > 0.0) {
        /* the window later by d_time: from the first report is from d_time
         * after it; an end kept where it was is kept later too */
        fw_scn_ais *a = &out->ais;
        if (isnan(a->start)) {
            a->start = r->d_time;
            a->start_rel = true;
        } else {
            a->start += r->d_time;
        }
        if (!isnan(a->end))
            a->end += r->d_time;
    }
}
