/* report_power.c - what a study could have detected (report_data.h).
 *
 * A study that finds no difference has said nothing unless it could have
 * found one.  Two numbers say how much it could:
 *
 *   the detectable difference of a compared pair: the smallest true
 *     difference that the pair's own test (paired t, or the count
 *     comparison) would have found significant at the report's level with
 *     80% power, from the spread the study itself measured:
 *       paired t     (t(1 - a/2; n - 1) + t(0.8; n - 1)) s_d / sqrt n
 *       counts       (z(1 - a/2) + z(0.8)) sqrt(2 rate / hours), the rate of
 *                    the two settings pooled (the normal approximation to
 *                    the comparison of two Poisson rates at equal exposure)
 *       run shares   (z(1 - a/2) + z(0.8)) sqrt(2 p (1 - p) / pairs)
 *     where no event was seen the rate or share is taken at the upper end of
 *     its exact interval, so the figure is a lower bound ("at least");
 *   the hours to detect a halving of a rare rate r (domain violations, near
 *     misses, collisions) per setting, with equal hours in both:
 *       (z(1 - a/2) + z(0.8))^2 (r + r / 2) / (r / 2)^2 = 6 (z + z)^2 / r,
 *     about 47 / r hours at 95% and 80%: a near-miss rate of 0.1 an hour
 *     needs 470 h in each setting.  With no event seen, r is the exact
 *     upper bound and the hours a lower bound.
 *
 * The report's first lines say plainly when a study has fewer hours per
 * setting than a halving of near misses or collisions needs: it cannot then
 * tell its settings apart on those measures, whatever its tables show.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "study/report_data.h"

static const double kPower = 0.8;

/* z(1 - a/2) + z(power) for the report's level. */
static double z_sum(double level)
{
    return fw_normal_quantile(0.5 + 0.5 * level) + fw_normal_quantile(kPower);
}

/* Hours per setting to detect a halving of the rate `rate` (per hour). */
static double halving_hours(double rate, double level)
{
    double z = z_sum(level);
    return rate > 0.0 ? 6.0 * z * z / rate : INFINITY;
}

static bool is_rare(fw_measure_id m)
{
    return fw_measures[m].method == FW_CI_POISSON;
}

/* A rare measure's rate in group G, or the exact upper bound when no event
 * was seen (*bound set). */
static double rare_rate(const fw_rep_group *G, fw_measure_id m, bool *bound)
{
    const fw_estimate *e = &G->est[m];
    *bound = !(e->mean > 0.0);
    return *bound ? e->hi : e->mean;
}

void fw_rep_power(fw_study_report *rep)
{
    for (int g = 0; g < rep->n_groups; g++) {
        fw_rep_group *G = &rep->groups[g];
        for (int m = 0; m < FW_NMEASURES; m++) {
            G->halving_h[m] = NAN;
            G->halving_bound[m] = false;
            if (!is_rare((fw_measure_id)m))
                continue;
            double r = rare_rate(G, (fw_measure_id)m, &G->halving_bound[m]);
            G->halving_h[m] = halving_hours(r, rep->level);
        }
    }
}

/* The hours of group g's finished runs. */
static double group_hours(const fw_study_report *rep, int g)
{
    double h = 0.0;
    for (int i = 0; i < rep->n_runs; i++)
        if (rep->runs[i].group == g)
            h += rep->runs[i].sim_s / 3600.0;
    return h;
}

double fw_rep_detectable(const fw_study_report *rep, const fw_rep_pair *p, bool *bound)
{
    fw_measure_id m = p->measure;
    const fw_rep_group *G = &rep->groups[p->group], *R = &rep->groups[p->ref_group];
    const fw_estimate *e = &p->est;
    *bound = false;
    if (p->not_compared || e->n < 2)
        return NAN;
    if (!p->exact) /* paired t */
        return (fw_t_quantile(0.5 + 0.5 * rep->level, e->n - 1) + fw_t_quantile(kPower, e->n - 1)) *
               e->sd / sqrt((double)e->n);
    double z = z_sum(rep->level);
    if (fw_measures[m].method == FW_CI_WILSON) {
        double k = G->est[m].mean * G->est[m].n + R->est[m].mean * R->est[m].n;
        double n = G->est[m].n + R->est[m].n, p1 = k / n;
        if (!(k > 0.0)) {
            p1 = fw_clopper_pearson(0, (int)n, rep->level).hi;
            *bound = true;
        }
        return z * sqrt(2.0 * p1 * (1.0 - p1) / e->n);
    }
    /* a count: the two settings' rate pooled over their hours */
    double hg = group_hours(rep, p->group), hr = group_hours(rep, p->ref_group);
    if (!(hg > 0.0 && hr > 0.0))
        return NAN;
    double events = G->est[m].mean * hg + R->est[m].mean * hr;
    double rate = events / (hg + hr);
    if (!(events > 0.5)) {
        rate = fw_poisson_exact(0, hg + hr, rep->level).hi;
        *bound = true;
    }
    return z * sqrt(2.0 * rate / (0.5 * (hg + hr)));
}

/* The first lines: can the study tell its settings apart on the rare
 * measures?  Only when it swept more than one setting. */
void fw_rep_md_verdict(FILE *f, const fw_study_report *rep)
{
    static const fw_measure_id rare[] = {FW_M_NEAR_MISS, FW_M_COLLISION};
    static const char *const what[] = {"near misses (hull to hull)", "collisions"};
    if (rep->n_groups < 2)
        return;
    double least_h = INFINITY;
    for (int g = 0; g < rep->n_groups; g++)
        least_h = fmin(least_h, group_hours(rep, g));
    bool any = false;
    for (size_t k = 0; k < sizeof rare / sizeof rare[0]; k++) {
        double need = 0.0;
        bool bound = false;
        for (int g = 0; g < rep->n_groups; g++) {
            const fw_rep_group *G = &rep->groups[g];
            if (G->halving_h[rare[k]] > need) {
                need = G->halving_h[rare[k]];
                bound = G->halving_bound[rare[k]];
            }
        }
        if (!(need > least_h))
            continue;
        char h[32], n[32];
        fprintf(f, "**This study cannot tell its settings apart on %s**: it has %s h per "
                   "setting (the fewest), and detecting a halving of the rate at %.0f%% "
                   "confidence and 80%% power needs %s%s h per setting%s.\n",
                what[k], fw_rep_fmt(h, least_h), 100 * rep->level,
                bound ? "at least " : "about ", fw_rep_fmt(n, need),
                bound ? " (none was seen, so the rate is taken at its upper bound)" : "");
        any = true;
    }
    if (any)
        fprintf(f, "Differences in these measures below are therefore not evidence either way; "
                   "see \"Power\" for every measure.\n\n");
    else
        fprintf(f, "The study has the hours per setting to detect a halving of near misses and "
                   "of collisions at %.0f%% confidence and 80%% power (\"Power\" below).\n\n",
                100 * rep->level);
}

/* The power section: per setting, each rare measure's events, hours and the
 * hours a halving needs. */
void fw_rep_md_power(FILE *f, const fw_study_report *rep)
{
    static const fw_measure_id rare[] = {FW_M_NEAR_MISS, FW_M_COLLISION, FW_M_DOMAIN};
    fprintf(f, "## Power\n\nHours per setting needed to detect a halving of each rare rate at "
               "%.0f%% confidence and 80%% power, 6 (z + z)^2 / rate with the setting's own "
               "rate (\"at least\": no event seen, the rate at its exact upper bound). Each "
               "compared pair's smallest detectable difference is in paired.csv "
               "(detectable_80).\n\n| density | %s | domain (m) | hours |",
            100 * rep->level, fw_rep_traffic_head(rep));
    for (size_t k = 0; k < sizeof rare / sizeof rare[0]; k++)
        fprintf(f, " %s: events, h for a halving |", fw_measures[rare[k]].name);
    fprintf(f, "\n|---|---|---|---|");
    for (size_t k = 0; k < sizeof rare / sizeof rare[0]; k++)
        fprintf(f, "---|");
    fprintf(f, "\n");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        char d[48], h[32], n[32], b[FW_REP_SETTING + 24];
        double hours = group_hours(rep, g);
        fprintf(f, "| %g | %s | %s | %s |", G->density, fw_rep_traffic(b, sizeof b, G),
                fw_rep_domain(d, sizeof d, G), fw_rep_fmt(h, hours));
        for (size_t k = 0; k < sizeof rare / sizeof rare[0]; k++) {
            fw_measure_id m = rare[k];
            fprintf(f, " %.0f, %s%s |", G->est[m].mean * hours,
                    G->halving_bound[m] ? ">= " : "", fw_rep_fmt(n, G->halving_h[m]));
        }
        fprintf(f, "\n");
    }
    fprintf(f, "\n");
}
