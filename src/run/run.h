/* run.h - one scenario run: the step loop of design.md and its records.
 *
 * Every dt:
 *   traffic step        SUMO advances the targets and background ships
 *   targets around      one context query, converted to fw_target once, sorted by id
 *   decide              encounter assessment + helm search + action/return policy
 *   advance             helm order to the MMG stepper, integrate dt
 *   place               the own ship moved in SUMO (moveToXY)
 *   records             time histories and the per-target encounter book
 *   survey              (scenario survey: section) every ship within the survey
 *                       radius, the own ship included, to fw_survey_step: the
 *                       encounters among all ships, by type
 *
 * Explicit targets become SUMO vehicles on a run-specific network: one straight
 * one-lane edge along each target's track (and one along the own ship's planned
 * leg), written as plain XML and built by netconvert into the run directory.
 * Target lanes allow only vClass custom1, so moveToXY can never map the own
 * ship (vClass ship) onto a target's lane where the target would brake for it:
 * targets keep course and speed exactly, as the benchmarks assume.
 *
 * Outputs (in the run directory; every number printed with a fixed format and
 * no clock time anywhere, so the same scenario and seed give identical files):
 *   own.csv         t, east, north, heading, u, v, r, rudder, helm order, propeller, mode
 *                   (standby, avoid, steady, autopilot: avoid/policy.h)
 *   targets.csv     t, id, east, north, heading, speed, range, bearing (outputs.targets_csv)
 *   encounters.csv  one row per target met
 *   traffic_encounters.csv  one row per pair episode of the survey (only with one)
 *   summary.json    the run's measures and the encounter rows
 *   run.log         decisions and mode changes
 *   sumo/           the generated network, routes and SUMO's messages
 */
#ifndef FW_RUN_H
#define FW_RUN_H

#include <stdbool.h>
#include <stdio.h>

#include "avoid/encounter.h"
#include "core/error.h"
#include "dynamics/mmg.h"
#include "scenario/scenario.h"
#include "survey/survey.h"
#include "traffic/traffic.h"

/* What the encounter book keeps per target. */
typedef struct fw_encounter {
    char id[64];
    char type[64];
    double length, breadth;
    const char *situation;  /* at first detection */
    double t_detect;        /* s */
    double dcpa0, tcpa0;    /* m, s at first detection */
    bool threat;            /* ever predicted to enter the domain */
    bool acted;             /* the own ship acted while it was a threat */
    double t_act;           /* s, first such action */
    int act_side;           /* FW_SIDE_* */
    double act_helm;        /* rad, signed */
    const char *act_situation; /* situation when the own ship acted */
    bool primary;           /* that action was for this target */
    double min_dist, t_min; /* m, s: centre distance */
    double min_lambda;      /* smallest normalised domain radius reached (< 1 = inside) */
    bool domain_entered;
    bool collision;         /* hulls overlapped */
    bool colregs_ok;
} fw_encounter;

typedef struct fw_run_summary {
    char scenario[64];
    char status[16];        /* "ok", "failed" */
    double t_end;           /* s */
    int n_encounters;
    double min_dist;        /* m, over all targets, INFINITY if none */
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
    /* Wall-clock seconds of the run and of it inside SUMO's step: for the
     * benchmarks and the study database only, never written to the run's
     * files (they must be identical from run to run). */
    double wall_s, sumo_s;
    double own_length, own_breadth; /* m, hull outline (for plots) */
    double domain, domain_ratio;    /* m, transverse semi-axis; fore-aft / transverse */
    /* The traffic survey (all zero without one). */
    bool survey;
    double traffic_ship_s;          /* ship-seconds in the survey area */
    int n_traffic;                  /* traffic encounters (pair episodes) */
    int traffic_by_type[FW_SURVEY_NTYPES]; /* indexed by fw_survey_type */
    int n_traffic_own;              /* of which with the own ship */
} fw_run_summary;

typedef struct fw_run_def {
    const fw_scenario *scenario;
    const char *dir;          /* the run directory (created by the caller) */
    fw_traffic_mode mode;     /* SUMO back end */
    /* Optional: the survey's records, sorted by (t_first, ship_a, ship_b), as
     * a malloc'd array the caller frees.  NULL = not wanted.  Set (to NULL,
     * 0 when the scenario has no survey) whenever fw_run_scenario returns,
     * also after a failure part way (the records up to then). */
    fw_survey_record **survey_out;
    int *n_survey_out;
} fw_run_def;

fw_run_def fw_default_run_def(void);

/* Runs the scenario to its end, writing the records into def->dir.  The
 * summary is filled even when the run fails part way (status "failed"). */
fw_status fw_run_scenario(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                          int *n_enc, fw_error *err);

/* records.c: the encounter book and the result files. */
typedef struct fw_records fw_records;
fw_status fw_records_open(fw_records **out, const fw_scenario *s, const char *dir,
                          fw_error *err);
void fw_records_close(fw_records *r);
FILE *fw_records_log(fw_records *r);
void fw_records_own(fw_records *r, double t, const fw_mmg_state *x, double helm, double n,
                    const char *mode);
/* One target seen at time t, with its assessment (situation, DCPA/TCPA, threat). */
void fw_records_target(fw_records *r, double t, const fw_target *ts,
                       const fw_mmg_state *own, const fw_assessment *as, bool record_row);
/* The own ship acted at t (side, helm) for target id primary_id; threats[i]
 * names the ids that were predicted to enter the domain then. */
void fw_records_action(fw_records *r, double t, int side, double helm, const char *primary_id,
                       const char *const *threat_ids, const fw_assessment *const *threat_as,
                       int n_threats);
fw_encounter *fw_records_encounters(fw_records *r, int *n);
/* traffic_encounters.csv: the survey's records. */
fw_status fw_records_survey(fw_records *r, const fw_survey_record *rec, int n, fw_error *err);
fw_status fw_records_finish(fw_records *r, fw_run_summary *sum, fw_error *err);

/* summary.json of one run (also used for the --json output). */
void fw_summary_json(FILE *f, const fw_run_summary *s, const fw_encounter *e, int n,
                     const char *indent);

#endif
