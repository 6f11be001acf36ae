/* report_data.h - what fairway report holds in memory (internal to src/study).
 *
 * The measures are one table (fw_measures) so the per-run values, the group
 * estimates, the paired differences, the CSVs and the JSON all walk the same
 * list and cannot disagree about a name.  report_load.c fills the runs and the
 * raw CPA values from the database; report_stats.c derives the rest.
 */
#ifndef FW_STUDY_REPORT_DATA_H
#define FW_STUDY_REPORT_DATA_H

#include "study/report.h"
#include "study/stats.h"

/* Own-ship situations as fw_situation_name spells them. */
typedef enum fw_rep_situation {
    FW_REP_HEAD_ON,
    FW_REP_OVERTAKING,
    FW_REP_OVERTAKEN,
    FW_REP_GIVE_WAY,
    FW_REP_STAND_ON,
    FW_REP_NSIT
} fw_rep_situation;

/* Encounter types, own-ship situations folded into the traffic-level ones:
 * overtaking = overtaking + being overtaken, crossing = give-way + stand-on. */
typedef enum fw_rep_type { FW_REP_ALL, FW_REP_T_HEAD_ON, FW_REP_T_OVERTAKING, FW_REP_T_CROSSING, FW_REP_NTYPE } fw_rep_type;

extern const char *const fw_rep_situation_names[FW_REP_NSIT];
extern const char *const fw_rep_type_names[FW_REP_NTYPE];   /* "all", "head-on", ... */

typedef enum fw_measure_id {
    FW_M_ENCOUNTERS,
    FW_M_HEAD_ON,
    FW_M_OVERTAKING,
    FW_M_CROSSING,
    FW_M_SIT_OVERTAKING,
    FW_M_SIT_OVERTAKEN,
    FW_M_SIT_GIVE_WAY,
    FW_M_SIT_STAND_ON,
    FW_M_DOMAIN,
    FW_M_DOMAIN_FRACTION,
    FW_M_NEAR_MISS,
    FW_M_NEAR_MISS_CENTRE,
    FW_M_COLLISION,
    FW_M_NEAR_MISS_RUNS,
    FW_M_COLLISION_RUNS,
    FW_M_MIN_CPA,
    FW_M_MIN_HULL,
    FW_M_CLOSENESS,
    FW_M_MANOEUVRES,
    FW_M_MAX_HELM,
    FW_M_HELM_ORDERS,
    FW_M_PATH,
    FW_M_TIME_LOST,
    FW_M_TRAFFIC_ALL,     /* traffic-level, per 1000 traffic ship-hours */
    FW_M_TRAFFIC_HEAD_ON,
    FW_M_TRAFFIC_OVERTAKING,
    FW_M_TRAFFIC_CROSSING,
    FW_NMEASURES
} fw_measure_id;

/* How a measure's interval is made (the report names it for each measure):
 *   T        mean over replications, Student t (the replication is the unit)
 *   POISSON  a count of rare events: the pooled count over the pooled hours
 *            with Garwood's exact interval; paired differences by the
 *            conditional binomial (fw_count_difference)
 *   WILSON   a yes/no outcome per run: Wilson over runs; paired differences
 *            by the conditional binomial on the discordant pairs (McNemar)
 *   RATIO    a ratio of pooled counts: percentile bootstrap over runs */
typedef enum fw_ci_method { FW_CI_T, FW_CI_POISSON, FW_CI_WILSON, FW_CI_RATIO } fw_ci_method;

extern const char *const fw_ci_method_text[];  /* for people, by fw_ci_method */

/* Whether a T measure is a count of events per unit of exposure, and which:
 * such a measure gets the exact Poisson interval instead of the t interval
 * when its group pooled fewer than FW_REP_FEW_EVENTS events (see
 * fw_rep_group.exact). */
typedef enum fw_count_kind {
    FW_COUNT_NONE,
    FW_COUNT_OWN_H,   /* events per own-ship hour */
    FW_COUNT_KSHIP_H  /* events per 1000 traffic ship-hours */
} fw_count_kind;

/* Below this many events pooled over a group's runs, a t interval over
 * replications of counts is not to be trusted: with every run at 0 it is
 * [0, 0], a certainty no finite study has, and with one event in twenty runs
 * it is cut at 0 and far too short.  The usual rule of thumb for a normal
 * approximation to counts asks for at least 5 expected events. */
enum { FW_REP_FEW_EVENTS = 5 };

typedef struct fw_measure {
    const char *name;     /* CSV name, unit in it */
    const char *label;    /* for people */
    fw_ci_method method;
    bool traffic;         /* traffic.csv rather than summary.csv */
    fw_count_kind count;  /* FW_CI_T measures that count events */
    /* Depends on the domain size itself (domain violations): compared only
     * between settings of one domain size, never across sizes, since
     * breaking a 1000 m domain is a smaller intrusion than breaking a 150 m
     * one; the least hull distance and the closeness compare instead. */
    bool per_domain;
} fw_measure;

/* Bootstrap resamples and the seed every bootstrap of a report starts from:
 * the same database gives the same report to the digit. */
enum { FW_REP_BOOT_REPS = 2000 };
#define FW_REP_BOOT_SEED 20260101u

extern const fw_measure fw_measures[FW_NMEASURES];

/* Room for a setting of a study's axes, "key=value, ..." (runs.setting). */
enum { FW_REP_SETTING = 160 };

/* One finished run: its columns and its encounter counts. */
typedef struct fw_rep_run {
    long long run_id, seed;
    double domain, density;
    char behaviour[16];                     /* the background ships': colregs, blind */
    char setting[FW_REP_SETTING];           /* the study's axes' values; "" without */
    int setting_index;                      /* settings in the run list's order */
    double ratio;                           /* the domain's fore-aft ratio, NAN if not recorded */
    int replication;
    double sim_s, traffic_ship_s;           /* exposure; traffic NAN if not recorded */
    double n_actions, helm_orders;          /* NAN if NULL */
    double min_dist, max_helm_deg, path_lengthening, time_lost;
    double near_miss_flag, collision_flag;  /* runs columns, 0/1, NAN if NULL */
    double min_hull, closeness;             /* runs columns, NAN if NULL */
    long long n_encounters_col;             /* runs.n_encounters, -1 if NULL */
    int n_sit[FW_REP_NSIT];
    int n_domain, n_near, n_collision;      /* encounters with the flag set */
    int n_near_centre;                      /* ... near_miss_centre */
    int n_traffic[FW_REP_NTYPE];
    int group;
    double m[FW_NMEASURES];                 /* the per-run measures */
} fw_rep_run;

/* A growable array of CPA values. */
typedef struct fw_rep_values {
    double *v;
    int n, cap;
} fw_rep_values;

enum { FW_REP_OWN, FW_REP_TRAFFIC, FW_REP_NSET };
extern const char *const fw_rep_set_names[FW_REP_NSET];

/* Geometric collision candidates and how they ended (schema.h), per set
 * (own ship, traffic pairs without it) and type: candidates, then of them
 * collision, near miss, domain, passed; and collisions of non-candidates. */
enum { FW_CAND_N, FW_CAND_COLLISION, FW_CAND_NEAR, FW_CAND_DOMAIN, FW_CAND_PASSED, FW_CAND_OTHER_COLL,
       FW_CAND_NSLOT };
extern const char *const fw_cand_outcomes[4]; /* "collision", "near miss", "domain", "passed" */
/* IWRAP Mk II's default causation factors by type (index fw_rep_type; "all": none):
 * head-on 4.9e-5, overtaking 1.1e-4 (Fujii et al. 1974), crossing 1.3e-4 (Pedersen 1995). */
extern const double fw_iwrap_causation[FW_REP_NTYPE];

typedef struct fw_rep_group {
    double density, domain;
    double ratio;                                   /* fore-aft, NAN if not recorded */
    char behaviour[16];
    char setting[FW_REP_SETTING];                   /* "" without axes */
    int setting_index;                              /* 0: the reference setting */
    int n_runs;
    fw_estimate est[FW_NMEASURES];
    bool exact[FW_NMEASURES];                       /* a count measure given Garwood's
                                                       interval: fewer than FW_REP_FEW_EVENTS */
    fw_estimate cpa_median;                         /* own-ship CPA, bootstrap interval */
    fw_rep_values cpa[FW_REP_NSET][FW_REP_NTYPE];  /* sorted after loading */
    long long traffic_count[FW_REP_NTYPE];          /* pooled over the runs */
    long long cand[FW_REP_NSET][FW_REP_NTYPE][FW_CAND_NSLOT]; /* candidates, pooled */
    int audited[FW_REP_NSIT], compliant[FW_REP_NSIT]; /* the COLREGs audit, by situation */
    double traffic_ship_s;
    int *hist[FW_REP_NSET];                          /* CPA histogram of the type "all" */
    double halving_h[FW_NMEASURES];                 /* rare measures: hours per setting to
                                                       detect a halving (report_power.c) */
    bool halving_bound[FW_NMEASURES];               /* ... a lower bound: no event seen */
} fw_rep_group;

/* Paired difference of one measure: group minus the reference of its density
 * and behaviour (pairs), or the colregs group minus the blind one of the same
 * density and domain (behaviour_pairs). */
typedef struct fw_rep_pair {
    int group, ref_group;
    fw_measure_id measure;
    fw_estimate est;
    bool exact;   /* the conditional binomial (counts), not the paired t */
    bool not_compared; /* a per_domain measure across domain sizes: no estimate */
} fw_rep_pair;

typedef struct fw_rep_count {
    char *text;
    int count;
} fw_rep_count;

/* One cell's splitting estimates (report_split.c): the batches' mean with
 * its interval, beside the same cell's crude counts of runs. */
typedef struct fw_rep_split {
    int cell;
    double domain, ratio, density;
    char behaviour[16];
    char setting[FW_REP_SETTING];
    int batches, failed;                /* ok batches; failed ones */
    int particles;
    fw_estimate p_collision, p_near_miss;
    double duration_s;                  /* of one trajectory */
    double runs, sim_h, wall_s;         /* spent in all */
    double re;                          /* relative error of p_collision's mean (sd / sqrt B / mean) */
    double crude_h;                     /* crude Monte Carlo hours for that error: (1-p)/(p re^2) runs */
    int crude_n, crude_collisions, crude_near;  /* the cell's runs and their events */
    double best_closeness;
    char best_path[256];
} fw_rep_split;

struct fw_study_report {
    char db[1024];
    double level;
    fw_rep_count *meta;            /* text "key = value", count unused */
    int n_meta;
    char study_name[128];
    int n_total, n_failed;         /* rows of runs; of which failed */
    fw_rep_count *reasons;         /* failure reasons with their counts */
    int n_reasons;
    fw_rep_count *warnings;        /* inconsistencies noticed while reading */
    int n_warnings;
    fw_rep_run *runs;              /* finished runs, sorted by run_id */
    int n_runs;
    int n_reps;                    /* largest replication + 1 */
    fw_rep_group *groups;          /* sorted by setting, density, behaviour, shape, domain */
    int n_groups;
    double reference_m;
    fw_rep_pair *pairs;
    int n_pairs;
    fw_rep_pair *bpairs;           /* colregs - blind, FW_NMEASURES per (density, domain) */
    int n_bpairs;
    bool has_settings;             /* the study swept axes: (runs.setting) */
    int n_settings;                /* 1 without axes */
    fw_rep_pair *spairs;           /* each setting - the first, FW_NMEASURES per
                                      (density, behaviour, domain) */
    int n_spairs;
    double bin_w[FW_REP_NSET];     /* CPA histogram bins [k w, (k + 1) w) */
    int n_bins[FW_REP_NSET];
    /* the traffic monitors (survey/monitor.h) summed over the finished runs,
     * and how many runs saw any; monitored false for a database written
     * before they were recorded */
    bool monitored;
    long long mon[7];              /* sideways, teleport, overlap, appear, vanish,
                                      start_close, stopped */
    int mon_runs;
    double max_lateral;            /* m/s, the largest in any run */
    char behaviour[64];            /* the background ships': "colregs", "blind" or both */
    bool candidates;               /* the database has the candidate columns filled */
    bool audited;                  /* ... and the COLREGs audit's */
    fw_rep_count *audit_notes;     /* why encounters were not compliant, tallied */
    int n_audit_notes;
    long long give_way;            /* their speed orders */
    fw_rep_split *splits;          /* estimate: (splitting), by cell */
    int n_splits;
};

/* report_load.c */
fw_status fw_rep_load(fw_study_report *rep, const char *db, fw_error *err);
int fw_rep_values_push(fw_rep_values *a, double v);
int fw_rep_note(fw_rep_count **list, int *n, const char *text);

/* report_stats.c: per-run measures, group estimates, CPA, paired differences. */
fw_status fw_rep_compute(fw_study_report *rep, double reference_m, fw_error *err);

/* report_power.c: what the study could have detected (its header says how). */
void fw_rep_power(fw_study_report *rep);
/* A pair's smallest difference detectable at 80% power (NAN if none can be
 * given); *bound: a lower bound, no event seen. */
double fw_rep_detectable(const fw_study_report *rep, const fw_rep_pair *p, bool *bound);
/* report.md's first lines: whether the study can tell its settings apart on
 * near misses and collisions; and the Power section. */
void fw_rep_md_verdict(FILE *f, const fw_study_report *rep);
void fw_rep_md_power(FILE *f, const fw_study_report *rep);

/* report_csv.c */
/* report_split.c: the splits table (if any) by cell; its report.md section
 * and splits.csv. */
typedef struct sqlite3 sqlite3;
fw_status fw_rep_load_splits(fw_study_report *rep, sqlite3 *db, const char *file, fw_error *err);
void fw_rep_md_splits(FILE *f, const fw_study_report *rep);
fw_status fw_rep_write_splits_csv(const fw_study_report *rep, const char *dir, fw_error *err);

fw_status fw_rep_write_csvs(const fw_study_report *rep, const char *dir, fw_error *err);

/* report_md.c */
fw_status fw_rep_write_md(const fw_study_report *rep, const fw_study_report_result *res,
                          const char *dir, fw_error *err);
/* A group's domain for people: "300", or "300 (2.5:1)" for a shape other
 * than the circle. */
const char *fw_rep_domain(char *buf, size_t sz, const fw_rep_group *G);
/* A group's traffic cell: its behaviour ("-" without) and its setting of the
 * axes, if any; and the column's head ("traffic; setting" with axes). */
const char *fw_rep_traffic(char *buf, size_t sz, const fw_rep_group *G);
const char *fw_rep_traffic_head(const fw_study_report *rep);
/* Same shape (fore-aft ratio; two missing ones are the same). */
bool fw_rep_same_shape(const fw_rep_group *a, const fw_rep_group *b);
/* Numbers for people: about three significant figures, "-" for NaN. */
const char *fw_rep_fmt(char *buf, double x);
/* report_md.c and report_causation.c: a group's domain cell (a compound literal: valid to the end of the statement). */
#define DOM(G) fw_rep_domain((char[48]){0}, 48, (G))

/* The background behaviour of a group, "-" for a database without it, and
 * the setting of the study's axes when it has them. */
#define beh(G) fw_rep_traffic((char[FW_REP_SETTING + 24]){0}, FW_REP_SETTING + 24, (G))

/* report_causation.c: report.md's causation section. */
void fw_rep_md_causation(FILE *f, const fw_study_report *rep);

/* The PNGs analysis/plot_study.py draws, in the order report.md shows them. */
extern const char *const fw_rep_plots[];
extern const char *const fw_rep_plot_titles[];
extern const int fw_rep_n_plots;

#endif
