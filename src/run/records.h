/* records.h - what a run keeps of its instants: the encounter book, the
 * summary's measures, and the result files.
 *
 * The run (run.h) hands the records each instant: the own ship's state and
 * decision (own.csv), every target seen with its assessment (targets.csv and
 * the encounter book: one fw_encounter per ship met, its closest approach,
 * domain, hull distance, the own ship's action for it), the actions; at the
 * end fw_records_finish judges the book (COLREGs reading, the audit, the
 * summary's totals) and writes encounters.csv and summary.json.  Without a
 * directory (fw_records_open with dir NULL) the book is kept and nothing is
 * written.
 */
#ifndef FW_RUN_RECORDS_H
#define FW_RUN_RECORDS_H

#include <stdbool.h>
#include <stdio.h>

#include "audit/audit.h"
#include "avoid/encounter.h"
#include "core/error.h"
#include "dynamics/mmg.h"
#include "geom/target.h"
#include "scenario/scenario.h"
#include "survey/monitor.h"
#include "survey/survey.h"
#include "world/reactions.h"

/* What the encounter book keeps per target. */
typedef struct fw_encounter {
    char id[64];
    char type[64];
    double length, breadth;
    fw_situation situation; /* at first detection */
    double t_detect;        /* s */
    double dcpa0, tcpa0;    /* m, s at first detection */
    bool threat;            /* ever predicted to enter the domain */
    bool acted;             /* the own ship acted while it was a threat */
    double t_act;           /* s, first such action */
    int act_side;           /* FW_SIDE_* */
    double act_helm;        /* rad, signed */
    fw_situation act_situation; /* situation when the own ship acted */
    bool rule19;            /* out of sight when first detected (restricted visibility) */
    int act_rule19;         /* out of sight at the action: rule 19(d)'s sides
                               (helm_search.h FW_ALLOW_*); 0: in sight */
    bool primary;           /* that action was for this target */
    double min_dist, t_min; /* m, s: centre distance */
    double min_hull;        /* m, hull to hull (0: touched; INFINITY if never within 1 nm) */
    double min_lambda;      /* smallest normalised domain radius reached (< 1 = inside) */
    bool domain_entered;
    bool collision;         /* hulls overlapped */
    bool colregs_ok;
    double cand_miss;       /* m, hull to hull on both straight tracks from first
                               detection (geom.h fw_hull_cpa): 0 = a geometric
                               collision candidate */
    fw_audit_obs audit_obs; /* what the COLREGs audit needs, noted each step */
    fw_audit_result audit;  /* the audit (audit/audit.h), at the end of the run */
} fw_encounter;

typedef enum fw_run_status { FW_RUN_OK, FW_RUN_FAILED } fw_run_status;

/* "ok", "failed" (summary.json's and the study database's words). */
const char *fw_run_status_name(fw_run_status s);

typedef struct fw_run_summary {
    char scenario[64];
    fw_run_status status;
    double t_end;           /* s */
    int n_encounters;
    double min_dist;        /* m, over all targets, INFINITY if none */
    double min_hull;        /* m, hull to hull over all targets (INFINITY: none within 1 nm) */
    char min_dist_id[64];
    bool domain_entered, collision, colregs_ok;
    bool acted;
    double t_act;           /* s, first action (NAN if none) */
    int act_side;
    double act_helm;        /* rad */
    double max_helm;        /* rad, largest |helm order| */
    double t_return;        /* s, the return to the course began (NAN if never) */
    double t_on_course;     /* s, back on course and in standby (NAN if never) */
    double heading_error;   /* rad, final heading minus the planned course */
    double cross_track;     /* m, final offset from the planned track (+ starboard) */
    double path_length;     /* m, sailed */
    double along_track;     /* m, progress along the planned track */
    double path_lengthening;/* m, path_length - along_track */
    double time_lost;       /* s, t_end - along_track / planned speed */
    double rudder_work;     /* rad s, integral of |rudder| */
    int helm_orders;        /* number of changes of the helm order */
    int n_actions;          /* avoidance manoeuvres begun */
    /* the domain could not be kept within the route's band (avoid/policy.h):
     * how often it began, when first, the slowest speed ordered (m/s) */
    int n_unkept;
    double t_unkept, unkept_speed;
    int n_rule19e;          /* times rule 19(e)'s speed was ordered (avoid/policy.h) */
    /* Wall-clock seconds of the run and of it inside SUMO's step: for the
     * benchmarks and the study database only, never written to the run's
     * files (they must be identical from run to run). */
    double wall_s, sumo_s;
    double own_length, own_breadth; /* m, hull outline (for plots) */
    double domain, domain_ratio;    /* m, transverse semi-axis; fore-aft / transverse */
    const char *domain_reading;     /* "ellipse" or "transverse" (geom.h): the run's judge too */
    /* AIS traffic (ais_track.h): reports at an instant their MMSI already had
     * (dropped), of which more than FW_AIS_CLASH_M away (two ships on one
     * MMSI: in how many MMSIs, the first), and reports the plane cannot hold.
     * In summary.json only when ais. */
    /* The own ship's sensor (sense/sensing.h): its mode, AIS reports sent,
     * lost, arrived; radar scans, plots, tracks and the error of what it
     * knew.  In summary.json only when sensed (not perfect). */
    bool sensed;
    fw_sensing_mode sense_mode;
    fw_sensing_counts sense;
    /* The background ships' watch (world/watch.h): encounters met, lapsed.
     * In summary.json only when the watch is not flawless. */
    bool watched;
    long watch_pairs, watch_lapsed;
    /* The own ship's watch likewise: ships noticed or lapsed. */
    bool own_watched;
    long own_watch_pairs, own_watch_lapsed;
    /* The mix of behaviours (world/watch.h): ships drawn, by behaviour. */
    bool mixed;
    long mix[FW_BEH_N];
    bool ais;
    long ais_duplicates, ais_clashes, ais_unprojected;
    int ais_clash_ships;
    long ais_clash_first;
    /* The traffic survey (all zero without one). */
    bool survey;
    double traffic_ship_s;          /* ship-seconds in the survey area */
    int n_traffic;                  /* traffic encounters (pair episodes) */
    int traffic_by_type[FW_SURVEY_NTYPES]; /* indexed by fw_survey_type */
    int n_traffic_own;              /* of which with the own ship */
    /* What no ship can do, among the ships the own ship saw (survey/monitor.h):
     * zero for traffic that behaves like ships. */
    fw_monitor_counts monitors;
    /* The background ships' reactions (world/reactions.h). */
    fw_behaviour behaviour;
    int n_give_way;                 /* give-way orders: slow-downs and course alterations */
    int n_give_way_short;           /* of which no speed kept the passing distance */
    int n_resume;
    /* give_way course (reactions.h): written only then */
    bool steering;
    int n_alter;                    /* course alterations (of n_give_way) */
    int n_rejoin;                   /* ships given back to their lanes after one */
    double alter_deg_min, alter_deg_max; /* the alterations ordered */
    /* The own ship's speed against the speeds its Nomoto knowledge base was
     * fitted over (nomoto.h): seconds of the run it sailed outside them (its
     * predictions extrapolated), and the extremes of its speed (kn). */
    bool kb_present;
    double kb_speed_min_kn, kb_speed_max_kn;
    double kb_outside_s;
    double own_speed_min_kn, own_speed_max_kn;
} fw_run_summary;

typedef struct fw_records fw_records;
fw_status fw_records_open(fw_records **out, const fw_scenario *s, const char *dir,
                          fw_error *err);
void fw_records_close(fw_records *r);
/* run.log (NULL without a directory). */
FILE *fw_records_log(fw_records *r);
/* The open streams (own.csv, run.log, targets.csv, sensed.csv), up to max
 * into f; how many. */
int fw_records_files(fw_records *r, FILE **f, int max);
/* The own ship's row: x its motion (heading; u, v through the water), rec its
 * record (speed_kn is the speed over ground, the columns' convention). */
void fw_records_own(fw_records *r, double t, const fw_mmg_state *x, const fw_target *rec,
                    double helm, double n, const char *mode);
/* What the own ship's sensor knew at t (known, sorted by id) against the
 * truth (sorted by id): a row of sensed.csv each (its position, course and
 * speed, and its distance from the truth), written with a sensor that is
 * not perfect and targets_csv on. */
void fw_records_sensed(fw_records *r, double t, const fw_target *known, int n_known,
                       const fw_target *truth, int n_truth);
/* One target seen at time t, with its assessment (situation, DCPA/TCPA, threat).
 * FW_ERUN when the book cannot grow: a run never goes on missing a ship.
 * Its targets.csv row: t_s,id,east_m,north_m,heading_deg,speed_kn,range_m,
 * bearing_deg,dcpa_m,tcpa_s,situation, then, in a run whose ships may be
 * seen turning (traffic behaviour colregs with give_way course, tracks, or
 * a situation's targets with turns),
 * turn_rate_degps,turn_to_deg: the turn the own ship saw it making at t
 * (geom/turn.h: its rate and the heading it turns to; both empty for a ship
 * at constant velocity), then lat_deg,lon_deg with an origin. */
fw_status fw_records_target(fw_records *r, double t, const fw_target *ts,
                            const fw_mmg_state *own, const fw_assessment *as, bool record_row,
                            fw_error *err);
/* The own ship acted at t (side, helm) for target id primary_id; the targets
 * tg[0..n-1] it saw then whose assessment says they enter the domain are the
 * ones it acted for. */
void fw_records_action(fw_records *r, double t, int side, double helm, const char *primary_id,
                       const fw_target *tg, const fw_assessment *as, int n);
fw_encounter *fw_records_encounters(fw_records *r, int *n);
/* traffic_encounters.csv: the survey's records. */
fw_status fw_records_survey(fw_records *r, const fw_survey_record *rec, int n, fw_error *err);
fw_status fw_records_finish(fw_records *r, fw_run_summary *sum, fw_error *err);

/* summary.json of one run (also used for the --json output). */
void fw_summary_json(FILE *f, const fw_run_summary *s, const fw_encounter *e, int n,
                     const char *indent);

#endif
