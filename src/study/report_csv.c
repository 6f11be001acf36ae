/* report_csv.c - the report's tables, one CSV per question.
 *
 *   runs.csv       one row per finished run: every per-run measure (the raw
 *                  material of all the others, for checking and re-analysis)
 *   summary.csv    own-ship measures per (density, domain): mean, 95% interval
 *   traffic.csv    traffic-level encounters per 1000 ship-hours by type
 *   paired.csv     differences from the reference domain, same replications
 *   behaviour.csv  colregs - blind of the same density and domain (a study that
 *                  swept the background behaviour), same replications
 *   causation.csv  geometric collision candidates per setting, set (own,
 *                  traffic) and type, how they ended, the measured causation
 *                  factor with its Clopper-Pearson interval and IWRAP's
 *   audit.csv      the COLREGs audit: audited and compliant own-ship encounters
 *                  per setting and situation, Wilson interval of the share
 *   cpa.csv        pooled CPA percentiles per setting and encounter type
 *   cpa_hist.csv   CPA histograms on one set of bins per own/traffic
 *
 * Long format (one row per setting and measure) so a new measure is a new
 * row, not a new column.  A missing number is an empty field.  A setting is
 * (density, behaviour, domain_m); behaviour is empty in a database without it.
 */
#include <math.h>
#include <stdio.h>

#include <string.h>

#include "core/files.h"
#include "study/report_data.h"

typedef struct csv {
    FILE *f;
    bool settings; /* the study swept axes: a first column `setting` */
    char path[1100], tmp[1120];
} csv;

static fw_status csv_open(csv *c, const fw_study_report *rep, const char *dir, const char *name,
                          const char *header, fw_error *err)
{
    if ((size_t)snprintf(c->path, sizeof c->path, "%s/%s", dir, name) >= sizeof c->path)
        return fw_fail(err, FW_EINPUT, "%s: path too long", dir);
    if (!(c->f = fw_file_begin(c->path, c->tmp, sizeof c->tmp, err)))
        return err->status;
    c->settings = rep->has_settings;
    fprintf(c->f, "%s%s\n", c->settings ? "setting," : "", header);
    return FW_OK;
}

/* A setting of the axes, first in a row when the study has them: quoted
 * when it lists several keys with commas ("a=1, b=2"; keys and values have
 * no quotes: study_axes.c). */
static void setting_cell(const csv *c, const char *setting)
{
    if (c->settings)
        fprintf(c->f, strchr(setting, ',') ? "\"%s\"," : "%s,", setting);
}

static fw_status csv_close(csv *c, fw_error *err)
{
    return fw_file_commit(c->f, c->tmp, c->path, err);
}

/* ",x" to 12 significant digits, well past any interval's width; "," for NaN. */
static void num(FILE *f, double x)
{
    if (isnan(x))
        fputc(',', f);
    else
        fprintf(f, ",%.12g", x);
}

static void estimate(FILE *f, const fw_estimate *e)
{
    fprintf(f, ",%d", e->n);
    num(f, e->mean);
    num(f, e->sd);
    num(f, e->lo);
    num(f, e->hi);
}

/* A share with its interval, and the end of the row: ",mean,lo,hi\n". */
static void share_end(FILE *f, const fw_estimate *e)
{
    num(f, e->mean);
    num(f, e->lo);
    num(f, e->hi);
    fputc('\n', f);
}

/* The columns of a setting, first in every table but runs.csv ... */
#define SETTING "density,behaviour,domain_m,fore_aft_ratio,"

/* ... and their values for a group. */
static void setting(const csv *c, const fw_rep_group *G)
{
    setting_cell(c, G->setting);
    fprintf(c->f, "%.12g,%s,%.12g", G->density, G->behaviour, G->domain);
    num(c->f, G->ratio);
}

/* The name of a measure's interval method in the CSVs: a count measure
 * with few events pooled was given the exact Poisson interval instead. */
static const char *method_name(const fw_rep_group *G, fw_measure_id m)
{
    static const char *const names[] = {"t", "poisson_exact", "wilson", "bootstrap_ratio"};
    return G->exact[m] ? "poisson_exact" : names[fw_measures[m].method];
}

static fw_status write_runs(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    char header[2048];
    int k = snprintf(header, sizeof header, "run_id," SETTING "replication,seed,sim_h");
    for (int m = 0; m < FW_NMEASURES && k < (int)sizeof header; m++)
        k += snprintf(header + k, sizeof header - (size_t)k, ",%s", fw_measures[m].name);
    if (csv_open(&c, rep, dir, "runs.csv", header, err))
        return err->status;
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        setting_cell(&c, r->setting);
        fprintf(c.f, "%lld,%.12g,%s,%.12g", r->run_id, r->density, r->behaviour, r->domain);
        num(c.f, r->ratio);
        fprintf(c.f, ",%d,%lld", r->replication, r->seed);
        num(c.f, r->sim_s / 3600.0);
        for (int m = 0; m < FW_NMEASURES; m++)
            num(c.f, r->m[m]);
        fputc('\n', c.f);
    }
    return csv_close(&c, err);
}

static fw_status write_summary(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "summary.csv",
                 SETTING "measure,n,mean,sd,ci_low,ci_high,method",
                 err))
        return err->status;
    for (int g = 0; g < rep->n_groups; g++)
        for (int m = 0; m < FW_NMEASURES; m++) {
            if (fw_measures[m].traffic)
                continue;
            const fw_rep_group *G = &rep->groups[g];
            setting(&c, G);
            fprintf(c.f, ",%s", fw_measures[m].name);
            estimate(c.f, &G->est[m]);
            fprintf(c.f, ",%s\n", method_name(G, (fw_measure_id)m));
        }
    return csv_close(&c, err);
}

static fw_status write_traffic(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "traffic.csv",
                 SETTING "type,n,encounters,traffic_ship_h,"
                 "mean_per_1000_ship_h,sd,ci_low,ci_high,method",
                 err))
        return err->status;
    for (int g = 0; g < rep->n_groups; g++)
        for (int t = 0; t < FW_REP_NTYPE; t++) {
            const fw_rep_group *G = &rep->groups[g];
            const fw_estimate *e = &G->est[FW_M_TRAFFIC_ALL + t];
            setting(&c, G);
            fprintf(c.f, ",%s,%d,%lld", fw_rep_type_names[t], e->n, G->traffic_count[t]);
            num(c.f, G->traffic_ship_s / 3600.0);
            num(c.f, e->mean);
            num(c.f, e->sd);
            num(c.f, e->lo);
            num(c.f, e->hi);
            fprintf(c.f, ",%s\n", method_name(G, FW_M_TRAFFIC_ALL + t));
        }
    return csv_close(&c, err);
}

static fw_status write_pairs(const fw_study_report *rep, const fw_rep_pair *pairs, int n,
                             const char *dir, const char *name, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, name,
                 SETTING "reference_m,reference_behaviour,measure,n,mean,sd,"
                 "ci_low,ci_high,significant,method,detectable_80,detectable_at_least",
                 err))
        return err->status;
    for (int i = 0; i < n; i++) {
        const fw_rep_pair *p = &pairs[i];
        const fw_rep_group *G = &rep->groups[p->group], *R = &rep->groups[p->ref_group];
        if (p->not_compared) /* domain violations across domain sizes: fw_measure.per_domain */
            continue;
        setting(&c, G);
        fprintf(c.f, ",%.12g,%s,%s", R->domain, R->behaviour, fw_measures[p->measure].name);
        estimate(c.f, &p->est);
        /* the interval excludes zero: the difference is significant at the level */
        fprintf(c.f, ",%d,%s", p->est.lo > 0.0 || p->est.hi < 0.0,
                p->exact ? "conditional_binomial" : "paired_t");
        /* the smallest difference this comparison could have found (report_power.c) */
        bool bound;
        num(c.f, fw_rep_detectable(rep, p, &bound));
        fprintf(c.f, ",%d\n", bound);
    }
    return csv_close(&c, err);
}

static const double cpa_q[] = {0.05, 0.25, 0.50, 0.75, 0.95};

static fw_status write_cpa(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "cpa.csv",
                 SETTING "set,type,n,p5_m,p25_m,p50_m,p75_m,p95_m", err))
        return err->status;
    for (int g = 0; g < rep->n_groups; g++)
        for (int s = 0; s < FW_REP_NSET; s++)
            for (int t = 0; t < FW_REP_NTYPE; t++) {
                const fw_rep_group *G = &rep->groups[g];
                const fw_rep_values *v = &G->cpa[s][t];
                setting(&c, G);
                fprintf(c.f, ",%s,%s,%d", fw_rep_set_names[s], fw_rep_type_names[t], v->n);
                for (size_t q = 0; q < sizeof cpa_q / sizeof cpa_q[0]; q++)
                    num(c.f, fw_quantile_sorted(v->v, v->n, cpa_q[q]));
                fputc('\n', c.f);
            }
    return csv_close(&c, err);
}

static fw_status write_hist(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "cpa_hist.csv",
                 SETTING "set,bin_low_m,bin_high_m,count", err))
        return err->status;
    for (int g = 0; g < rep->n_groups; g++)
        for (int s = 0; s < FW_REP_NSET; s++) {
            const fw_rep_group *G = &rep->groups[g];
            for (int b = 0; b < rep->n_bins[s]; b++) {
                setting(&c, G);
                fprintf(c.f, ",%s,%.12g,%.12g,%d\n", fw_rep_set_names[s], b * rep->bin_w[s],
                        (b + 1) * rep->bin_w[s], G->hist[s][b]);
            }
        }
    return csv_close(&c, err);
}

static fw_status write_causation(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "causation.csv",
                 SETTING "set,type,candidates,collisions,near_misses,domain,"
                 "passed,non_candidate_collisions,causation,ci_low,ci_high,iwrap",
                 err))
        return err->status;
    for (int g = 0; g < rep->n_groups && rep->candidates; g++)
        for (int s = 0; s < FW_REP_NSET; s++)
            for (int t = 0; t < FW_REP_NTYPE; t++) {
                const fw_rep_group *G = &rep->groups[g];
                const long long *k = G->cand[s][t];
                setting(&c, G);
                fprintf(c.f, ",%s,%s", fw_rep_set_names[s], fw_rep_type_names[t]);
                for (int i = 0; i < FW_CAND_NSLOT; i++)
                    fprintf(c.f, ",%lld", k[i]);
                fw_estimate e = fw_clopper_pearson((int)k[FW_CAND_COLLISION], (int)k[FW_CAND_N],
                                                   rep->level);
                num(c.f, e.mean);
                num(c.f, e.lo);
                num(c.f, e.hi);
                num(c.f, fw_iwrap_causation[t]);
                fputc('\n', c.f);
            }
    return csv_close(&c, err);
}

static fw_status write_audit(const fw_study_report *rep, const char *dir, fw_error *err)
{
    csv c;
    if (csv_open(&c, rep, dir, "audit.csv",
                 SETTING "situation,audited,compliant,share,ci_low,"
                 "ci_high",
                 err))
        return err->status;
    for (int g = 0; g < rep->n_groups && rep->audited; g++)
        for (int k = 0; k < FW_REP_NSIT; k++) {
            const fw_rep_group *G = &rep->groups[g];
            fw_estimate e = fw_wilson(G->compliant[k], G->audited[k], rep->level);
            setting(&c, G);
            fprintf(c.f, ",%s,%d,%d", fw_rep_situation_names[k], G->audited[k], G->compliant[k]);
            share_end(c.f, &e);
        }
    return csv_close(&c, err);
}

fw_status fw_rep_write_csvs(const fw_study_report *rep, const char *dir, fw_error *err)
{
    if (write_runs(rep, dir, err) || write_summary(rep, dir, err) ||
        write_traffic(rep, dir, err) ||
        write_pairs(rep, rep->pairs, rep->n_pairs, dir, "paired.csv", err) ||
        write_pairs(rep, rep->bpairs, rep->n_bpairs, dir, "behaviour.csv", err) ||
        (rep->has_settings &&
         write_pairs(rep, rep->spairs, rep->n_spairs, dir, "settings.csv", err)) ||
        write_cpa(rep, dir, err) || write_causation(rep, dir, err) ||
        write_audit(rep, dir, err) ||
        write_hist(rep, dir, err) || fw_rep_write_splits_csv(rep, dir, err))
        return err->status;
    return FW_OK;
}
