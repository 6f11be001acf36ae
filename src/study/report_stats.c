/* report_stats.c - from runs to the report's numbers.
 *
 * Each run gives one value of each measure (a rate per own-ship hour, a
 * fraction, a largest value).  Each measure has its interval method
 * (fw_ci_method, report_data.h): common measures the mean over replications
 * with a Student-t interval, because replications are the independent units -
 * encounters within one run share the run's traffic and are not; rare events
 * (domain violations, near misses, collisions) the pooled count over the
 * pooled hours with the exact Poisson interval, which a t interval (cut at 0
 * for one event in twenty runs) is not; yes/no outcomes per run Wilson; the
 * share of encounters entering the domain a bootstrap of the ratio.
 * Paired differences use replication i of both settings: same traffic, so
 * most of the traffic's variation cancels; counts get the conditional
 * binomial (fw_count_difference), which stays right at 0 or 3 events.
 * The behaviour axis: colregs - blind of the same density and domain.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "study/report_data.h"

const char *const fw_ci_method_text[] = {
    [FW_CI_T] = "mean over replications, Student t",
    [FW_CI_POISSON] = "pooled count / pooled hours, exact Poisson (Garwood)",
    [FW_CI_WILSON] = "share of runs, Wilson score",
    [FW_CI_RATIO] = "ratio of pooled counts, percentile bootstrap over runs",
};

const fw_measure fw_measures[FW_NMEASURES] = {
    [FW_M_ENCOUNTERS] = {"encounters_per_h", "own-ship encounters per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_HEAD_ON] = {"head_on_per_h", "head-on encounters per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_OVERTAKING] = {"overtaking_per_h", "overtaking encounters (either way) per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_CROSSING] = {"crossing_per_h", "crossing encounters (give-way or stand-on) per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_SIT_OVERTAKING] = {"overtaking_own_per_h", "own ship overtaking per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_SIT_OVERTAKEN] = {"being_overtaken_per_h", "own ship being overtaken per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_SIT_GIVE_WAY] = {"crossing_give_way_per_h", "crossing, own ship gives way, per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_SIT_STAND_ON] = {"crossing_stand_on_per_h", "crossing, own ship stands on, per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_DOMAIN] = {"domain_violations_per_h", "domain violations per hour", FW_CI_POISSON, false, FW_COUNT_NONE, true},
    [FW_M_DOMAIN_FRACTION] = {"domain_violation_fraction", "share of encounters entering the domain", FW_CI_RATIO, false, FW_COUNT_NONE, true},
    [FW_M_NEAR_MISS] = {"near_misses_per_h", "near misses (hull to hull) per hour", FW_CI_POISSON, false, FW_COUNT_NONE, false},
    [FW_M_NEAR_MISS_CENTRE] = {"near_misses_centre_per_h", "near misses centre to centre per hour (secondary)", FW_CI_POISSON, false, FW_COUNT_NONE, false},
    [FW_M_COLLISION] = {"collisions_per_h", "collisions per hour", FW_CI_POISSON, false, FW_COUNT_NONE, false},
    [FW_M_NEAR_MISS_RUNS] = {"near_miss_run_fraction", "share of runs with a near miss", FW_CI_WILSON, false, FW_COUNT_NONE, false},
    [FW_M_COLLISION_RUNS] = {"collision_run_fraction", "share of runs with a collision", FW_CI_WILSON, false, FW_COUNT_NONE, false},
    [FW_M_MIN_CPA] = {"min_cpa_m", "closest approach of the run (m)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_MIN_HULL] = {"min_hull_m", "least hull-to-hull distance of the run (m; runs with no hull within 1 nm missing)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_CLOSENESS] = {"closeness", "closeness of the run (1 - least hull distance / 1 nm)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_MANOEUVRES] = {"manoeuvres_per_h", "avoidance manoeuvres per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_MAX_HELM] = {"max_helm_deg", "largest helm (deg)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_HELM_ORDERS] = {"helm_orders_per_h", "helm orders per hour", FW_CI_T, false, FW_COUNT_OWN_H, false},
    [FW_M_PATH] = {"path_lengthening_m_per_h", "path lengthening (m per hour)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_TIME_LOST] = {"time_lost_s_per_h", "time lost (s per hour)", FW_CI_T, false, FW_COUNT_NONE, false},
    [FW_M_TRAFFIC_ALL] = {"traffic_encounters_per_1000_ship_h", "traffic encounters per 1000 ship-hours", FW_CI_T, true, FW_COUNT_KSHIP_H, false},
    [FW_M_TRAFFIC_HEAD_ON] = {"traffic_head_on_per_1000_ship_h", "traffic head-on per 1000 ship-hours", FW_CI_T, true, FW_COUNT_KSHIP_H, false},
    [FW_M_TRAFFIC_OVERTAKING] = {"traffic_overtaking_per_1000_ship_h", "traffic overtaking per 1000 ship-hours", FW_CI_T, true, FW_COUNT_KSHIP_H, false},
    [FW_M_TRAFFIC_CROSSING] = {"traffic_crossing_per_1000_ship_h", "traffic crossing per 1000 ship-hours", FW_CI_T, true, FW_COUNT_KSHIP_H, false},
};

static double flag(double v)
{
    return isnan(v) ? NAN : (v != 0.0);
}

static void run_measures(fw_rep_run *r)
{
    double h = r->sim_s / 3600.0, *m = r->m;
    int *s = r->n_sit;
    int n = s[FW_REP_HEAD_ON] + s[FW_REP_OVERTAKING] + s[FW_REP_OVERTAKEN] + s[FW_REP_GIVE_WAY] +
            s[FW_REP_STAND_ON];
    m[FW_M_ENCOUNTERS] = n / h;
    m[FW_M_HEAD_ON] = s[FW_REP_HEAD_ON] / h;
    m[FW_M_OVERTAKING] = (s[FW_REP_OVERTAKING] + s[FW_REP_OVERTAKEN]) / h;
    m[FW_M_CROSSING] = (s[FW_REP_GIVE_WAY] + s[FW_REP_STAND_ON]) / h;
    m[FW_M_SIT_OVERTAKING] = s[FW_REP_OVERTAKING] / h;
    m[FW_M_SIT_OVERTAKEN] = s[FW_REP_OVERTAKEN] / h;
    m[FW_M_SIT_GIVE_WAY] = s[FW_REP_GIVE_WAY] / h;
    m[FW_M_SIT_STAND_ON] = s[FW_REP_STAND_ON] / h;
    m[FW_M_DOMAIN] = r->n_domain / h;
    /* a run without encounters has no share: missing, not zero */
    m[FW_M_DOMAIN_FRACTION] = n ? (double)r->n_domain / n : NAN;
    m[FW_M_NEAR_MISS] = r->n_near / h;
    m[FW_M_NEAR_MISS_CENTRE] = r->n_near_centre / h;
    m[FW_M_COLLISION] = r->n_collision / h;
    m[FW_M_NEAR_MISS_RUNS] = flag(r->near_miss_flag);
    m[FW_M_COLLISION_RUNS] = flag(r->collision_flag);
    m[FW_M_MIN_CPA] = r->min_dist;
    m[FW_M_MIN_HULL] = r->min_hull;
    m[FW_M_CLOSENESS] = r->closeness;
    m[FW_M_MANOEUVRES] = r->n_actions / h;
    m[FW_M_MAX_HELM] = r->max_helm_deg;
    m[FW_M_HELM_ORDERS] = r->helm_orders / h;
    m[FW_M_PATH] = r->path_lengthening / h;
    m[FW_M_TIME_LOST] = r->time_lost / h;
    double kh = r->traffic_ship_s > 0.0 ? r->traffic_ship_s / 3600.0 / 1000.0 : NAN;
    for (int t = 0; t < FW_REP_NTYPE; t++)
        m[FW_M_TRAFFIC_ALL + t] = r->n_traffic[t] / kh;
}

static int run_encounters(const fw_rep_run *r)
{
    int n = 0;
    for (int k = 0; k < FW_REP_NSIT; k++)
        n += r->n_sit[k];
    return n;
}

/* The exposure a rate of run r is per: own-ship hours, or thousands of
 * traffic ship-hours for the traffic counts (NAN when not recorded). */
static double run_exposure(const fw_rep_run *r, fw_measure_id id)
{
    if (fw_measures[id].count == FW_COUNT_KSHIP_H)
        return r->traffic_ship_s > 0.0 ? r->traffic_ship_s / 3600.0 / 1000.0 : NAN;
    return r->sim_s / 3600.0;
}

/* The events of a count measure in run r: its rate times its exposure. */
static long long run_count(const fw_rep_run *r, fw_measure_id id)
{
    return llround(r->m[id] * run_exposure(r, id));
}

/* A count measure's group: the t interval over replications, or, with
 * fewer than FW_REP_FEW_EVENTS events pooled, Garwood's over the pooled
 * exposure (*exact set).  Zero events in 20 h: [0, 0.184] per hour. */
static fw_estimate count_estimate(const fw_study_report *rep, int g, fw_measure_id id,
                                  const double *buf, int n, bool *exact)
{
    long long events = 0;
    double exposure = 0.0;
    int ok = 0;
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        double x = run_exposure(r, id);
        if (r->group != g || isnan(r->m[id]) || isnan(x))
            continue;
        ok++;
        events += run_count(r, id);
        exposure += x;
    }
    fw_estimate e = fw_mean_ci(buf, n, rep->level);
    if (e.lo < 0.0)
        e.lo = 0.0;
    if (ok == 0 || events >= FW_REP_FEW_EVENTS)
        return e;
    fw_estimate p = fw_poisson_exact(events, exposure, rep->level);
    p.n = ok;
    p.sd = e.sd;
    *exact = true;
    return p;
}

static fw_estimate group_estimate(const fw_study_report *rep, int g, fw_measure_id id, double *buf,
                                  double *buf2, bool *exact)
{
    int n = 0, k = 0, ok = 0;
    long long events = 0;
    double hours = 0.0;
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        if (r->group != g)
            continue;
        double v = r->m[id];
        buf2[n] = run_encounters(r);
        buf[n++] = id == FW_M_DOMAIN_FRACTION ? r->n_domain : v;
        if (!isnan(v)) {
            ok++;
            k += v != 0.0;
            events += run_count(r, id);
            hours += r->sim_s / 3600.0;
        }
    }
    fw_estimate e;
    switch (fw_measures[id].method) {
    case FW_CI_WILSON:
        return fw_wilson(k, ok, rep->level);
    case FW_CI_POISSON:
        e = fw_poisson_exact(events, hours, rep->level);
        e.n = ok;
        e.sd = fw_sd(buf, n);
        return e;
    case FW_CI_RATIO:
        e = fw_bootstrap_ratio(buf, buf2, n, FW_REP_BOOT_REPS, FW_REP_BOOT_SEED, rep->level);
        e.sd = NAN;
        return e;
    case FW_CI_T:
    default:
        if (fw_measures[id].count != FW_COUNT_NONE)
            return count_estimate(rep, g, id, buf, n, exact);
        e = fw_mean_ci(buf, n, rep->level);
        if (e.lo < 0.0)
            e.lo = 0.0;
        return e;
    }
}

/* A round bin width near x: 1, 2, 2.5 or 5 times a power of ten. */
static double nice_width(double x)
{
    double p = pow(10.0, floor(log10(x))), f = x / p;
    return p * (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 2.5 ? 2.5 : f <= 5.0 ? 5.0 : 10.0);
}

/* One set of bins for every setting, so the histograms can be compared. */
static fw_status histograms(fw_study_report *rep, fw_error *err)
{
    for (int s = 0; s < FW_REP_NSET; s++) {
        double top = 0.0;
        for (int g = 0; g < rep->n_groups; g++) {
            const fw_rep_values *v = &rep->groups[g].cpa[s][FW_REP_ALL];
            if (v->n)
                top = fmax(top, v->v[v->n - 1]);
        }
        if (!(top > 0.0))
            continue;
        rep->bin_w[s] = nice_width(top / 25.0);
        rep->n_bins[s] = (int)floor(top / rep->bin_w[s]) + 1;
        for (int g = 0; g < rep->n_groups; g++) {
            const fw_rep_values *v = &rep->groups[g].cpa[s][FW_REP_ALL];
            int *h = calloc((size_t)rep->n_bins[s], sizeof *h);
            if (!h)
                return fw_fail(err, FW_ERUN, "out of memory");
            rep->groups[g].hist[s] = h;
            for (int i = 0; i < v->n; i++) {
                int b = (int)floor(v->v[i] / rep->bin_w[s]);
                h[b < 0 ? 0 : b >= rep->n_bins[s] ? rep->n_bins[s] - 1 : b]++;
            }
        }
    }
    return FW_OK;
}

/* Measure m of group g minus the same of group ref, replication by
 * replication: the runs of one replication sailed the same traffic.  a, b,
 * ha, hb: n_reps values each (scratch). */
static fw_estimate pair_estimate(const fw_study_report *rep, int g, int ref, fw_measure_id m,
                                 double *a, double *b, double *ha, double *hb, bool *exact)
{
    int nr = rep->n_reps;
    for (int i = 0; i < nr; i++)
        a[i] = b[i] = ha[i] = hb[i] = NAN;
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        if (r->group == g || r->group == ref) {
            (r->group == g ? a : b)[r->replication] = r->m[m];
            (r->group == g ? ha : hb)[r->replication] = run_exposure(r, m);
        }
    }
    fw_estimate t = fw_paired_ci(a, b, nr, rep->level);
    fw_ci_method method = fw_measures[m].method;
    bool counted = fw_measures[m].count != FW_COUNT_NONE;
    if (method != FW_CI_POISSON && method != FW_CI_WILSON && !counted)
        return t;
    /* counts: the conditional binomial, on the events (POISSON, and a
     * counted T measure with few events) or on the discordant pairs
     * (WILSON), over the replications both sides have */
    long long x = 0, y = 0;
    double hours = 0.0, hx = 0.0, hy = 0.0;
    int pairs = 0;
    for (int i = 0; i < nr; i++) {
        if (isnan(a[i]) || isnan(b[i]) || isnan(ha[i]) || isnan(hb[i]))
            continue;
        pairs++;
        if (method == FW_CI_WILSON) {
            x += a[i] != 0.0 && b[i] == 0.0;
            y += a[i] == 0.0 && b[i] != 0.0;
        } else {
            x += llround(a[i] * ha[i]);
            y += llround(b[i] * hb[i]);
            hours += 0.5 * (ha[i] + hb[i]);
            hx += ha[i];
            hy += hb[i];
        }
    }
    if (pairs == 0 || (method == FW_CI_T && x + y >= FW_REP_FEW_EVENTS))
        return t;
    *exact = true;
    fw_estimate e = fw_count_difference(x, y, method == FW_CI_WILSON ? 1.0 / pairs : 1.0 / hours,
                                        rep->level);
    e.n = pairs;
    e.sd = t.sd;
    if (x + y == 0 && method == FW_CI_WILSON) /* no discordant pair: no difference seen */
        e.lo = e.hi = 0.0;
    else if (x + y == 0) {
        /* no event on either side: each rate is below its exact upper bound
         * for 0 events, so their difference lies between minus the one and
         * the other; no study of finite length can say it is exactly 0 */
        e.mean = 0.0;
        e.lo = -fw_poisson_exact(0, hy, rep->level).hi;
        e.hi = fw_poisson_exact(0, hx, rep->level).hi;
    }
    return e;
}

static fw_status add_pairs(fw_study_report *rep, fw_rep_pair *out, int *n_out, int g, int ref,
                           fw_error *err)
{
    int nr = rep->n_reps > 0 ? rep->n_reps : 1;
    double *buf = malloc((size_t)nr * 4 * sizeof *buf);
    if (!buf)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int m = 0; m < FW_NMEASURES; m++) {
        fw_rep_pair *p = &out[(*n_out)++];
        p->group = g;
        p->ref_group = ref;
        p->measure = (fw_measure_id)m;
        p->exact = false;
        p->not_compared = fw_measures[m].per_domain &&
                          rep->groups[g].domain != rep->groups[ref].domain;
        if (p->not_compared) {
            p->est = (fw_estimate){0, NAN, NAN, NAN, NAN};
            continue;
        }
        p->est = pair_estimate(rep, g, ref, (fw_measure_id)m, buf, buf + nr, buf + 2 * nr,
                               buf + 3 * nr, &p->exact);
    }
    free(buf);
    return FW_OK;
}

/* Every setting against the reference domain of its density and behaviour. */
static fw_status paired(fw_study_report *rep, fw_error *err)
{
    rep->pairs = malloc((size_t)rep->n_groups * FW_NMEASURES * sizeof *rep->pairs);
    if (!rep->pairs)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        if (G->domain == rep->reference_m)
            continue;
        int ref = -1;
        for (int h = 0; h < rep->n_groups; h++)
            if (rep->groups[h].density == G->density && rep->groups[h].domain == rep->reference_m &&
                strcmp(rep->groups[h].behaviour, G->behaviour) == 0 &&
                rep->groups[h].setting_index == G->setting_index &&
                fw_rep_same_shape(&rep->groups[h], G))
                ref = h;
        if (ref < 0) {
            char msg[200], b[32] = "";
            if (G->behaviour[0])
                snprintf(b, sizeof b, " (%s traffic)", G->behaviour);
            snprintf(msg, sizeof msg,
                     "density %g%s has no finished runs with the reference domain: no paired "
                     "differences for it", G->density, b);
            if (fw_rep_note(&rep->warnings, &rep->n_warnings, msg))
                return fw_fail(err, FW_ERUN, "out of memory");
            continue;
        }
        if (add_pairs(rep, rep->pairs, &rep->n_pairs, g, ref, err))
            return err->status;
    }
    return FW_OK;
}

/* colregs - blind for each (density, domain) that has both. */
static fw_status behaviour_paired(fw_study_report *rep, fw_error *err)
{
    rep->bpairs = malloc((size_t)rep->n_groups * FW_NMEASURES * sizeof *rep->bpairs);
    if (!rep->bpairs)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int g = 0; g < rep->n_groups; g++) {
        const fw_rep_group *G = &rep->groups[g];
        if (strcmp(G->behaviour, "colregs") != 0)
            continue;
        for (int h = 0; h < rep->n_groups; h++) {
            const fw_rep_group *H = &rep->groups[h];
            if (H->density == G->density && H->domain == G->domain &&
                fw_rep_same_shape(H, G) && strcmp(H->behaviour, "blind") == 0 &&
                H->setting_index == G->setting_index &&
                add_pairs(rep, rep->bpairs, &rep->n_bpairs, g, h, err))
                return err->status;
        }
    }
    return FW_OK;
}

/* The axes: each setting against the first of the study's list (the
 * reference) at the same density, behaviour, domain size and shape; the same
 * replications sailed the same seeds and starts in both, so the pairs are
 * paired like the domain sizes'. */
static fw_status setting_paired(fw_study_report *rep, fw_error *err)
{
    rep->spairs = malloc((size_t)rep->n_groups * FW_NMEASURES * sizeof *rep->spairs);
    if (!rep->spairs)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int g = 0; g < rep->n_groups && rep->has_settings; g++) {
        const fw_rep_group *G = &rep->groups[g];
        if (G->setting_index == 0)
            continue;
        for (int h = 0; h < rep->n_groups; h++) {
            const fw_rep_group *H = &rep->groups[h];
            if (H->setting_index == 0 && H->density == G->density && H->domain == G->domain &&
                fw_rep_same_shape(H, G) && strcmp(H->behaviour, G->behaviour) == 0 &&
                add_pairs(rep, rep->spairs, &rep->n_spairs, g, h, err))
                return err->status;
        }
    }
    return FW_OK;
}

fw_status fw_rep_compute(fw_study_report *rep, double reference_m, fw_error *err)
{
    /* the reference must be a domain size that has finished runs */
    double smallest = INFINITY;
    bool found = isnan(reference_m);
    char sizes[256] = "";
    for (int g = 0; g < rep->n_groups; g++) {
        double d = rep->groups[g].domain;
        smallest = fmin(smallest, d);
        if (!found && fabs(d - reference_m) <= 1e-9 * fmax(1.0, fabs(d))) {
            found = true;
            reference_m = d;
        }
        bool seen = false;
        for (int h = 0; h < g; h++)
            seen |= rep->groups[h].domain == d;
        if (!seen && strlen(sizes) < sizeof sizes - 24)
            snprintf(sizes + strlen(sizes), sizeof sizes - strlen(sizes), "%s%g", sizes[0] ? ", " : "", d);
    }
    if (!found)
        return fw_fail(err, FW_EINPUT,
                       "--reference %g: no finished runs with that domain size in %s (domain sizes: %s m)",
                       reference_m, rep->db, sizes);
    rep->reference_m = isnan(reference_m) ? smallest : reference_m;

    for (int i = 0; i < rep->n_runs; i++)
        run_measures(&rep->runs[i]);
    double *buf = malloc((size_t)rep->n_runs * 2 * sizeof *buf);
    if (!buf)
        return fw_fail(err, FW_ERUN, "out of memory");
    for (int g = 0; g < rep->n_groups; g++) {
        fw_rep_group *G = &rep->groups[g];
        for (int m = 0; m < FW_NMEASURES; m++)
            G->est[m] = group_estimate(rep, g, (fw_measure_id)m, buf, buf + rep->n_runs, &G->exact[m]);
        for (int s = 0; s < FW_REP_NSET; s++)
            for (int t = 0; t < FW_REP_NTYPE; t++)
                fw_sort(G->cpa[s][t].v, G->cpa[s][t].n);
        /* encounters of one run share its traffic: the bootstrap over pooled
         * encounters is somewhat narrow; stated in the report */
        const fw_rep_values *v = &G->cpa[FW_REP_OWN][FW_REP_ALL];
        G->cpa_median = fw_bootstrap_median(v->v, v->n, FW_REP_BOOT_REPS, FW_REP_BOOT_SEED,
                                            rep->level);
    }
    free(buf);
    for (int i = 0; i < rep->n_runs; i++) {
        const fw_rep_run *r = &rep->runs[i];
        fw_rep_group *G = &rep->groups[r->group];
        if (!(r->traffic_ship_s > 0.0))
            continue;
        G->traffic_ship_s += r->traffic_ship_s;
        for (int t = 0; t < FW_REP_NTYPE; t++)
            G->traffic_count[t] += r->n_traffic[t];
    }
    if (histograms(rep, err) || paired(rep, err) || behaviour_paired(rep, err) ||
        setting_paired(rep, err))
        return err->status;
    fw_rep_power(rep);
    return FW_OK;
}
