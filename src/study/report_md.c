/* report_md.c - the report for people: report.md, the terminal table, JSON.
 *
 * report.md is one page: what was run, how many runs count, the key measures
 * with intervals against domain size, the paired differences that are
 * significant, and the plots.  Everything else is in the CSVs it points to.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/json.h"
#include "study/report_data.h"

/* The measures of the compact tables, in column order. */
static const fw_measure_id key[] = {FW_M_ENCOUNTERS,     FW_M_DOMAIN,      FW_M_NEAR_MISS,
                                    FW_M_MIN_HULL,       FW_M_COLLISION_RUNS, FW_M_MANOEUVRES,
                                    FW_M_PATH,           FW_M_TIME_LOST};
static const char *const key_head[] = {"encounters /h", "domain violations /h",
                                       "near misses (hull to hull) /h", "least hull distance m",
                                       "runs with a collision", "manoeuvres /h",
                                       "path lengthening m/h", "time lost s/h"};
enum { NKEY = sizeof key / sizeof key[0] };

const char *const fw_rep_plots[] = {"rates.png", "encounter_types.png", "cpa_hist.png",
                                    "traffic.png", "paired.png"};
const char *const fw_rep_plot_titles[] = {
    "Rates against domain size", "Own-ship encounters by type", "CPA distribution per domain size",
    "Traffic-level encounters", "Paired differences from the reference domain"};
const int fw_rep_n_plots = sizeof fw_rep_plots / sizeof fw_rep_plots[0];

bool fw_rep_same_shape(const fw_rep_group *a, const fw_rep_group *b)
{
    return (isnan(a->ratio) && isnan(b->ratio)) || a->ratio == b->ratio;
}

const char *fw_rep_traffic(char *buf, size_t sz, const fw_rep_group *G)
{
    snprintf(buf, sz, "%s%s%s", G->behaviour[0] ? G->behaviour : "-", G->setting[0] ? "; " : "",
             G->setting);
    return buf;
}

const char *fw_rep_traffic_head(const fw_study_report *rep)
{
    return rep->has_settings ? "traffic; setting" : "traffic";
}

const char *fw_rep_domain(char *buf, size_t sz, const fw_rep_group *G)
{
    if (isnan(G->ratio) || G->ratio == 1.0)
        snprintf(buf, sz, "%g", G->domain);
    else
        snprintf(buf, sz, "%g (%g:1)", G->domain, G->ratio);
    return buf;
}

const char *fw_rep_fmt(char *buf, double x)
{
    double a = fabs(x);
    if (isnan(x))
        return strcpy(buf, "-");
    if (x == 0.0)
        snprintf(buf, 32, "0");
    else if (a >= 100.0)
        snprintf(buf, 32, "%.0f", x);
    else if (a >= 10.0)
        snprintf(buf, 32, "%.1f", x);
    else if (a >= 0.1)
        snprintf(buf, 32, "%.2f", x);
    else
        snprintf(buf, 32, "%.2g", x);
    return buf;
}

/* "mean [lo, hi]"; a run share as "k/n [lo, hi]". */
static const char *cell(char *out, size_t sz, const fw_estimate *e, bool share)
{
    char m[32], lo[32], hi[32];
    if (share && e->n > 0 && !isnan(e->mean))
        snprintf(m, sizeof m, "%d/%d", (int)lround(e->mean * e->n), e->n);
    else
        fw_rep_fmt(m, e->mean);
    if (isnan(e->lo))
        snprintf(out, sz, "%s", m);
    else
        snprintf(out, sz, "%s [%s, %s]", m, fw_rep_fmt(lo, e->lo), fw_rep_fmt(hi, e->hi));
    return out;
}

static double cpa_median(const fw_rep_group *G)
{
    return G->cpa_median.mean;
}

static bool is_share(fw_measure_id m)
{
    return fw_measures[m].method == FW_CI_WILSON;
}

static const char *stem(const char *path, char *buf, size_t sz)
{
    const char *b = strrchr(path, '/');
    snprintf(buf, sz, "%.200s", b ? b + 1 : path);
    char *dot = strrchr(buf, '.');
    if (dot && dot != buf)
        *dot = '\0';
    return buf;
}

static void md_runs(FILE *f, const fw_study_report *rep)
{
    int nd = 0, nn = 0;
    for (int g = 0; g < rep->n_groups; g++) {
        bool d = true, n = true;
        for (int h = 0; h < g; h++) {
            d &= rep->groups[h].domain != rep->groups[g].domain;
            n &= rep->groups[h].density != rep->groups[g].density;
        }
        nd += d;
        nn += n;
    }
    fprintf(f, "**Runs:** %d finished and counted, %d failed, %d in the database; %d domain size%s x "
               "%d densit%s, up to %d replication%s each.\n",
            rep->n_runs, rep->n_failed, rep->n_total, nd, nd == 1 ? "" : "s", nn,
            nn == 1 ? "y" : "ies", rep->n_reps, rep->n_reps == 1 ? "" : "s");
    if (rep->n_reasons) {
        fprintf(f, "Failed runs (not counted):");
        for (int i = 0; i < rep->n_reasons; i++)
            fprintf(f, "%s %d x \"%s\"", i ? ";" : "", rep->reasons[i].count, rep->reasons[i].text);
        fprintf(f, ".\n");
    }
    for (int i = 0; i < rep->n_warnings; i++)
        fprintf(f, "Warning: %s.\n", rep->warnings[i].text);
    fprintf(f, "\n");
}

static void md_key_table(FILE *f, const fw_study_report *rep)
{
    char c[96], m[32];
    fprintf(f, "## Key measures\n\nEach value with its %.0f%% confidence interval; the "
               "interval of each measure is made as follows:\n\n",
            100 * rep->level);
    for (int k = 0; k < NKEY; k++)
        fprintf(f, "- %s: %s\n", key_head[k], fw_ci_method_text[fw_measures[key[k]].method]);
    fprintf(f, "- CPA median: the median of the pooled encounters' closest centre distances, "
               "percentile bootstrap over encounters (%d resamples, fixed seed; encounters of one "
               "run share its traffic, so it is somewhat narrow)\n\n"
               "Rates are per own-ship hour. A t interval's lower end below 0 is cut at 0. A count "
               "per hour (encounters, manoeuvres, helm orders, traffic encounters) with fewer than "
               "%d events pooled over a setting's runs gets the exact Poisson (Garwood) interval over "
               "the pooled hours instead of the t interval, which for replications of zeros would "
               "be [0, 0]: no study of finite length can rule out a rate above 0.\n\n",
            FW_REP_BOOT_REPS, FW_REP_FEW_EVENTS);
    fprintf(f, "| density | %s | domain (m) | runs |", fw_rep_traffic_head(rep));
    for (int k = 0; k < NKEY; k++)
        fprintf(f, " %s |", key_head[k]);
    fprintf(f, " CPA median (m) |\n|---|---|---|---|");
    for (int k = 0; k <= NKEY; k++)
        fprintf(f, "---|");
    fprintf(f, "\n");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        fprintf(f, "| %g | %s | %s | %d |", G->density, beh(G), DOM(G), G->n_runs);
        for (int k = 0; k < NKEY; k++)
            fprintf(f, " %s |", cell(c, sizeof c, &G->est[key[k]], is_share(key[k])));
        fprintf(f, " %s |\n", cell(c, sizeof c, &G->cpa_median, false));
    }
    (void)m;
    fprintf(f, "\nTraffic level (all ships in the survey area), encounters per 1000 ship-hours "
               "(Student t over replications; exact Poisson below %d events):\n\n"
               "| density | %s | domain (m) |", FW_REP_FEW_EVENTS, fw_rep_traffic_head(rep));
    for (int t = 0; t < FW_REP_NTYPE; t++)
        fprintf(f, " %s |", fw_rep_type_names[t]);
    fprintf(f, "\n|---|---|---|---|---|---|---|\n");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        fprintf(f, "| %g | %s | %s |", G->density, beh(G), DOM(G));
        for (int t = 0; t < FW_REP_NTYPE; t++)
            fprintf(f, " %s |", cell(c, sizeof c, &G->est[FW_M_TRAFFIC_ALL + t], false));
        fprintf(f, "\n");
    }
    fprintf(f, "\n");
}

static bool significant(const fw_estimate *e)
{
    return e->lo > 0.0 || e->hi < 0.0;
}

/* The rows of a paired table: one per compared setting, one column per key
 * measure; `all` shows every difference (significant ones in bold), else
 * only the significant ones and a dash for the others. */
static void pair_table(FILE *f, const fw_study_report *rep, const fw_rep_pair *pairs, int n,
                       bool all)
{
    char c[96];
    fprintf(f, "| density | %s | domain (m) | pairs |", fw_rep_traffic_head(rep));
    for (int k = 0; k < NKEY; k++)
        fprintf(f, " %s |", key_head[k]);
    fprintf(f, "\n|---|---|---|---|");
    for (int k = 0; k < NKEY; k++)
        fprintf(f, "---|");
    fprintf(f, "\n");
    for (int i = 0; i < n; i += FW_NMEASURES) {
        /* fw_rep_compute stores the pairs of a setting together, in measure order */
        const fw_rep_pair *p = &pairs[i];
        const fw_rep_group *G = &rep->groups[p->group];
        fprintf(f, "| %g | %s | %s | %d |", G->density, beh(G), DOM(G),
                p[FW_M_ENCOUNTERS].est.n);
        for (int k = 0; k < NKEY; k++) {
            const fw_estimate *e = &p[key[k]].est;
            if (p[key[k]].not_compared)
                fprintf(f, " not compared |");
            else if (significant(e))
                fprintf(f, " **%s** |", cell(c, sizeof c, e, false));
            else if (all)
                fprintf(f, " %s |", cell(c, sizeof c, e, false));
            else
                fprintf(f, " - |");
        }
        fprintf(f, "\n");
    }
}

/* colregs - blind, when the study swept the behaviour. */
static void md_behaviour(FILE *f, const fw_study_report *rep)
{
    if (rep->n_bpairs == 0)
        return;
    fprintf(f, "## Background behaviour: colregs - blind\n\n"
               "Replication i of both behaviours sailed the same seed and start, so each "
               "difference is paired. Counts of rare events (domain violations, near misses): "
               "the difference of the pooled counts per hour, with the exact conditional "
               "interval (given the events of both, the colregs share is binomial; its "
               "Clopper-Pearson interval p mapped through n (2p - 1) / hours: it excludes 0 "
               "exactly when the exact test of equal rates rejects). Runs with a collision: the "
               "same on the discordant pairs (exact McNemar), as a difference of shares. The "
               "other measures: paired t. Bold: the %.0f%% interval excludes 0; behaviour.csv "
               "has every measure.\n\n",
            100 * rep->level);
    pair_table(f, rep, rep->bpairs, rep->n_bpairs, true);
    fprintf(f, "\n");
}

/* Each setting of the axes - the first, when the study swept axes. */
static void md_axes(FILE *f, const fw_study_report *rep)
{
    if (!rep->has_settings)
        return;
    const char *first = "";
    for (int g = 0; g < rep->n_groups; g++)
        if (rep->groups[g].setting_index == 0)
            first = rep->groups[g].setting;
    fprintf(f, "## Axes: each setting - the first (%s)\n\n"
               "The study swept these settings of its scenario (axes:); replication i of "
               "every setting sailed the same seed and start, so each difference from the "
               "first setting at the same density, traffic, domain size and shape is paired, "
               "with the intervals of the behaviour section's kinds (exact conditional for "
               "rare counts, exact McNemar for runs with a collision, paired t otherwise). "
               "Bold: the %.0f%% interval excludes 0; settings.csv has every measure.\n\n",
            first, 100 * rep->level);
    pair_table(f, rep, rep->spairs, rep->n_spairs, true);
    fprintf(f, "\n");
}

/* The shares of audited encounters that followed the rules, by situation. */
static void md_audit(FILE *f, const fw_study_report *rep)
{
    if (!rep->audited)
        return;
    char c[96];
    fprintf(f, "## COLREGs audit\n\n"
               "Each own-ship encounter in which risk of collision existed (the predicted CPA "
               "nearer than audit_risk_dcpa_m within audit_risk_tcpa_s) is audited against the "
               "rule of its situation at first detection: give-way (rules 13, 14, 16 with 8): "
               "acted, early (TCPA at the action at least audit_early_tcpa_s), substantial (a "
               "course change of at least audit_course_change_deg or a speed reduction of at "
               "least audit_speed_change), head-on and crossing to starboard; stand-on (rule "
               "17): course and speed kept while TCPA > audit_rule17_may_tcpa_s, acted when the "
               "risk was still there at audit_rule17_must_tcpa_s, crossing not to port. Shares "
               "compliant with the Wilson %.0f%% interval; the thresholds are in the settings "
               "above.\n\n| density | %s | domain (m) |",
            100 * rep->level, fw_rep_traffic_head(rep));
    for (int k = 0; k < FW_REP_NSIT; k++)
        fprintf(f, " %s |", fw_rep_situation_names[k]);
    fprintf(f, "\n|---|---|---|---|---|---|---|---|\n");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        fprintf(f, "| %g | %s | %s |", G->density, beh(G), DOM(G));
        for (int k = 0; k < FW_REP_NSIT; k++) {
            fw_estimate e = fw_wilson(G->compliant[k], G->audited[k], rep->level);
            fprintf(f, " %s |", G->audited[k] ? cell(c, sizeof c, &e, true) : "-");
        }
        fprintf(f, "\n");
    }
    if (rep->n_audit_notes) {
        fprintf(f, "\nNot compliant, why:");
        for (int i = 0; i < rep->n_audit_notes; i++)
            fprintf(f, "%s %d x %s", i ? ";" : "", rep->audit_notes[i].count,
                    rep->audit_notes[i].text);
        fprintf(f, ".\n");
    }
    fprintf(f, "\n");
}

/* One row per compared setting, one column per key measure: the significant
 * differences in bold with their interval, the others as a dash, so the page
 * shows at a glance what the domain size changes. */
static void md_paired(FILE *f, const fw_study_report *rep)
{
    fprintf(f, "## Paired differences from the %g m domain\n\n", rep->reference_m);
    if (rep->n_pairs == 0) {
        fprintf(f, "Only one domain size: nothing to compare.\n\n");
        return;
    }
    int n_sig = 0, n_cmp = 0;
    for (int i = 0; i < rep->n_pairs; i++) {
        n_sig += significant(&rep->pairs[i].est);
        n_cmp += !rep->pairs[i].not_compared;
    }
    fprintf(f, "Replication i of every domain size sailed the same traffic, so each difference "
               "(domain minus %g m) is taken within a replication (rare-event counts and runs "
               "with a collision: the exact conditional binomial interval; the others paired "
               "t). Shown: the differences whose "
               "%.0f%% interval excludes zero; - marks one that does not. %d of %d differences "
               "over all measures are significant; paired.csv has them all. Domain violations "
               "are not compared across domain sizes: entering a 1000 m domain is a smaller "
               "intrusion than entering a 150 m one, so their difference says nothing about "
               "safety; the least hull distance (and closeness in paired.csv) compares.\n\n",
            rep->reference_m, 100 * rep->level, n_sig, n_cmp);
    pair_table(f, rep, rep->pairs, rep->n_pairs, false);
    /* the other measures, named once if any of their differences is significant */
    bool first = true;
    for (int m = 0; m < FW_NMEASURES; m++) {
        bool is_key = false, sig = false;
        for (int k = 0; k < NKEY; k++)
            is_key |= key[k] == (fw_measure_id)m;
        for (int i = 0; i < rep->n_pairs && !is_key; i++)
            sig |= rep->pairs[i].measure == (fw_measure_id)m && significant(&rep->pairs[i].est);
        if (sig) {
            fprintf(f, "%s%s", first ? "\nAlso significant somewhere: " : "; ", fw_measures[m].label);
            first = false;
        }
    }
    fprintf(f, "%s\n", first ? "" : ".\n");
}

/* First thing after the title: whether the traffic behaved like ships. */
static void md_monitors(FILE *f, const fw_study_report *rep)
{
    static const char *const what[7] = {"sideways jumps", "teleports",
                                        "overlaps of background hulls",
                                        "ships appearing within 2 nm",
                                        "ships vanishing within 2 nm",
                                        "ships within 2 nm at the start", "stopped ships"};
    if (!rep->monitored) {
        fprintf(f, "No traffic monitors recorded (a database written before fairway counted "
                   "them).\n\n");
        return;
    }
    long long total = 0;
    for (int k = 0; k < 7; k++)
        total += rep->mon[k];
    if (total > 0) {
        fprintf(f, "**Warning: the background traffic did what no ship can do** in %d of %d runs:",
                rep->mon_runs, rep->n_runs);
        bool first = true;
        for (int k = 0; k < 7; k++)
            if (rep->mon[k] > 0) {
                fprintf(f, "%s %lld %s", first ? "" : ",", rep->mon[k], what[k]);
                first = false;
            }
        fprintf(f, " (largest sideways speed %.2f m/s). Each event is a `monitor:` line in "
                   "its run's run.log; read the collision and near-miss figures with them in "
                   "mind.\n\n",
                rep->max_lateral);
    } else {
        fprintf(f, "Traffic monitors: in none of the %d runs did a ship the own ship saw move "
                   "sideways faster than 2 m/s (largest %.2f m/s), jump, overlap another's hull, "
                   "appear, vanish or start within 2 nm, or stop.\n\n",
                rep->n_runs, rep->max_lateral);
    }
    fprintf(f, "Background ships: %s (%lld give-way speed orders in all).\n\n",
            rep->behaviour[0] ? rep->behaviour : "-", rep->give_way);
}

/* The study's settings as a table, the ones that define it first. */
static void md_settings(FILE *f, const fw_study_report *rep)
{
    static const char *const first[] = {"study_description", "scenario", "ship", "network",
                                        "domains_m", "densities", "behaviours", "replications",
                                        "duration_s", "near_miss_m", "encounter_m", NULL};
    fprintf(f, "## Settings\n\nDatabase `%s` (its meta table also holds every input file's "
               "path and digest).\n\n", rep->db);
    if (rep->n_meta == 0) {
        fprintf(f, "None recorded.\n\n");
        return;
    }
    fprintf(f, "| setting | value |\n|---|---|\n");
    bool *shown = calloc((size_t)rep->n_meta, sizeof *shown);
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; pass == 1 || first[k]; k++) {
            for (int i = 0; i < rep->n_meta; i++) {
                const char *t = rep->meta[i].text, *eq = strstr(t, " = ");
                size_t kl = eq ? (size_t)(eq - t) : strlen(t);
                bool match = pass == 1 || (strlen(first[k]) == kl && !strncmp(t, first[k], kl));
                /* the input files' digests are the resume guard, not a setting */
                match &= strncmp(t, "input:", 6) != 0 && strncmp(t, "study_digest", 12) != 0;
                if (!match || (shown && shown[i]) || !eq)
                    continue;
                fprintf(f, "| %.*s | %s |\n", (int)kl, t, eq + 3);
                if (shown)
                    shown[i] = true;
            }
            if (pass == 1)
                break;
        }
    free(shown);
    fprintf(f, "\n");
}

fw_status fw_rep_write_md(const fw_study_report *rep, const fw_study_report_result *res,
                          const char *dir, fw_error *err)
{
    char path[1100], tmp[1120], name[256];
    if ((size_t)snprintf(path, sizeof path, "%s/report.md", dir) >= sizeof path)
        return fw_fail(err, FW_EINPUT, "%s: path too long", dir);
    FILE *f = fw_file_begin(path, tmp, sizeof tmp, err);
    if (!f)
        return err->status;
    fprintf(f, "# Study report: %s\n\n",
            rep->study_name[0] ? rep->study_name : stem(rep->db, name, sizeof name));
    md_monitors(f, rep);
    fw_rep_md_verdict(f, rep);
    md_settings(f, rep);
    md_runs(f, rep);
    md_key_table(f, rep);
    md_paired(f, rep);
    fw_rep_md_power(f, rep);
    fw_rep_md_splits(f, rep);
    md_behaviour(f, rep);
    md_axes(f, rep);
    fw_rep_md_causation(f, rep);
    md_audit(f, rep);
    fprintf(f, "## Plots\n\n");
    if (res->plots == FW_PLOTS_DRAWN) {
        for (int i = 0; i < fw_rep_n_plots; i++)
            fprintf(f, "![%s](%s)\n\n", fw_rep_plot_titles[i], fw_rep_plots[i]);
        if (rep->n_bpairs)
            fprintf(f, "![Paired differences colregs - blind](behaviour.png)\n\n");
    }
    else if (res->plots == FW_PLOTS_SKIPPED)
        fprintf(f, "Not drawn (--no-plots).\n\n");
    else
        fprintf(f, "**Plotting failed:** %s. The tables above and the CSVs are complete.\n\n",
                res->plot_msg);
    fprintf(f, "Tables: summary.csv (every own-ship measure, with its interval method), "
               "traffic.csv, paired.csv, behaviour.csv (colregs - blind), cpa.csv (CPA "
               "percentiles by type), cpa_hist.csv, runs.csv (per run).\n");
    return fw_file_commit(f, tmp, path, err);
}

/* JSON */

/* Numbers as %.10g; strings through the project's escaping writer. */
static void jnum(FILE *f, double x)
{
    fw_json_number(f, x, "%.10g");
}

static void jstr(FILE *f, const char *s)
{
    fw_json_string(f, s);
}

static void jest(FILE *f, const fw_estimate *e)
{
    fprintf(f, "{\"n\": %d, \"mean\": ", e->n);
    jnum(f, e->mean);
    fputs(", \"ci_low\": ", f);
    jnum(f, e->lo);
    fputs(", \"ci_high\": ", f);
    jnum(f, e->hi);
    fputs("}", f);
}

/* ", "setting": "..."" when the study swept axes. */
static void json_setting(FILE *f, const fw_study_report *rep, const fw_rep_group *G)
{
    if (!rep->has_settings)
        return;
    fputs(", \"setting\": ", f);
    jstr(f, G->setting);
}

static void json_pairs(FILE *f, const fw_study_report *rep, const char *name,
                       const fw_rep_pair *pairs, int n)
{
    fprintf(f, "],\n \"%s\": [", name);
    for (int i = 0; i < n; i++) {
        const fw_rep_pair *p = &pairs[i];
        const fw_rep_group *G = &rep->groups[p->group];
        fprintf(f, "%s\n  {\"density\": %.10g, \"behaviour\": ", i ? "," : "", G->density);
        jstr(f, G->behaviour);
        json_setting(f, rep, G);
        fprintf(f, ", \"domain_m\": %.10g, \"measure\": ", G->domain);
        jstr(f, fw_measures[p->measure].name);
        fputs(", \"diff\": ", f);
        jest(f, &p->est);
        fprintf(f, ", \"significant\": %s}", significant(&p->est) ? "true" : "false");
    }
}

static void print_json(FILE *f, const fw_study_report *rep, const fw_study_report_result *res)
{
    static const char *const plots[] = {"skipped", "drawn", "failed"};
    fputs("{\"database\": ", f);
    jstr(f, rep->db);
    fputs(", \"out\": ", f);
    jstr(f, res->out);
    fprintf(f, ", \"runs_ok\": %d, \"runs_failed\": %d, \"runs_total\": %d, \"level\": %g, "
               "\"reference_m\": ",
            rep->n_runs, rep->n_failed, rep->n_total, rep->level);
    jnum(f, rep->reference_m);
    fputs(", \"plots\": ", f);
    jstr(f, plots[res->plots]);
    fputs(", \"warnings\": [", f);
    for (int i = 0; i < rep->n_warnings; i++) {
        fputs(i ? ", " : "", f);
        jstr(f, rep->warnings[i].text);
    }
    fputs("],\n \"groups\": [", f);
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        fprintf(f, "%s\n  {\"density\": %.10g, \"behaviour\": ", g ? "," : "", G->density);
        jstr(f, G->behaviour);
        json_setting(f, rep, G);
        fprintf(f, ", \"domain_m\": %.10g, \"fore_aft_ratio\": ", G->domain);
        jnum(f, G->ratio);
        fprintf(f, ", \"runs\": %d", G->n_runs);
        for (int m = 0; m < FW_NMEASURES; m++) {
            fprintf(f, ",\n   \"%s\": ", fw_measures[m].name);
            jest(f, &G->est[m]);
        }
        fputs(",\n   \"cpa_median_m\": ", f);
        jnum(f, cpa_median(G));
        fputs("}", f);
    }
    json_pairs(f, rep, "paired", rep->pairs, rep->n_pairs);
    json_pairs(f, rep, "behaviour_paired", rep->bpairs, rep->n_bpairs);
    if (rep->has_settings)
        json_pairs(f, rep, "settings_paired", rep->spairs, rep->n_spairs);
    fputs("]}\n", f);
}

void fw_study_report_print(FILE *f, const fw_study_report *rep, const fw_study_report_result *res,
                           bool json)
{
    if (json) {
        print_json(f, rep, res);
        return;
    }
    char c[96], m[32];
    fprintf(f, "%d runs counted, %d failed; reference domain %g m; mean [%.0f%% CI] across "
               "replications\n",
            rep->n_runs, rep->n_failed, rep->reference_m, 100 * rep->level);
    int w = 8; /* the traffic column: as wide as its widest cell */
    for (int g = 0; g < rep->n_groups; g++)
        w = (int)fmax(w, (double)strlen(beh(&rep->groups[g])));
    fprintf(f, "%-8s %-*s %8s %5s", "density", w, fw_rep_traffic_head(rep), "domain_m", "runs");
    for (int k = 0; k < NKEY; k++)
        fprintf(f, "  %-22.22s", key_head[k]);
    fprintf(f, "  %s\n", "CPA p50 m");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        fprintf(f, "%-8g %-*s %8s %5d", G->density, w, beh(G), DOM(G), G->n_runs);
        for (int k = 0; k < NKEY; k++)
            fprintf(f, "  %-22s", cell(c, sizeof c, &G->est[key[k]], is_share(key[k])));
        fprintf(f, "  %s\n", fw_rep_fmt(m, cpa_median(G)));
    }
    for (int i = 0; i < rep->n_warnings; i++)
        fprintf(f, "warning: %s\n", rep->warnings[i].text);
    const char *plots = res->plots == FW_PLOTS_DRAWN     ? ", plots"
                        : res->plots == FW_PLOTS_SKIPPED ? ", no plots"
                                                         : ", plots FAILED";
    fprintf(f, "wrote %s (report.md, CSVs%s)\n", res->out, plots);
}
