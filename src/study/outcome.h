/* outcome.h - what one study run hands back: its status, its aggregates, its
 * own-ship encounters and its traffic-level encounters, flat, with no
 * pointers into the run, so it can cross a pipe or an MPI message as bytes.
 *
 * Every encounter, own-ship and traffic-level, says whether it was a
 * geometric collision candidate (its straight tracks from first detection
 * would have brought the hulls into contact, geom.h fw_hull_cpa) and how it
 * ended (fw_outcome_ended): the causation factor is collisions / candidates.
 *
 * A target counts as an own-ship encounter when it passed within the study's
 * encounter range or the own ship predicted it to enter its domain (a
 * "threat"); the ships merely seen on the radar are not kept.
 */
#ifndef FW_STUDY_OUTCOME_H
#define FW_STUDY_OUTCOME_H

#include <stdbool.h>
#include <stddef.h>

#include "core/error.h"
#include "run/encounter_record.h"
#include "run/run.h"
#include "survey/monitor.h"
#include "study/study.h"

/* An own-ship encounter: the run's record (records.h; its fields written
 * by the table of run/encounter_record.h) and the study's verdicts on it. */
typedef struct fw_outcome_encounter {
    fw_encounter e;
    fw_enc_verdict v;
} fw_outcome_encounter;

typedef struct fw_outcome_traffic {
    char ship_a[64], ship_b[64], type[16];
    int own;
    double t_first, range0, dcpa0, tcpa0, min_dist, t_min;
    double min_hull;                /* m, NAN if never within the survey's hull watch */
    double cand_miss;
    int candidate;
    char outcome[16];
} fw_outcome_traffic;

/* The closeness of a pass: 1 - d / FW_CLOSENESS_RANGE for a least hull
 * distance d (m) within that range, 0 beyond it or when no hull came within
 * it (NAN).  1 exactly at contact, continuous, and the same for every domain
 * size: the per-run and per-encounter score that adaptive multilevel
 * splitting climbs (issue 25), and a measure of how close a study came that
 * does not depend on where its thresholds lie.  The range is the hull watch
 * of the own ship (1 nm), beyond which no hull distance is kept. */
#define FW_CLOSENESS_RANGE 1852.0
double fw_closeness(double min_hull);

/* How an encounter ended, the worst that happened: "collision" (the hulls
 * touched), "near miss" (hull to hull closer than near_miss), "domain" (the
 * own domain entered; own-ship encounters only) or "passed". */
const char *fw_outcome_ended(bool collision, double min_hull, double near_miss, bool domain);

typedef struct fw_outcome {
    int run_id;
    char status[16];   /* "ok" or "failed" */
    char reason[512];  /* why it failed */
    double sim_s, wall_s, sumo_s;
    int n_actions;
    double min_dist;   /* m, NAN when no target was met */
    int domain_entered, collision, colregs_ok;
    int near_miss;        /* the least hull distance below the study's near_miss */
    int near_miss_centre; /* the least centre distance below it: secondary */
    double closeness;     /* fw_closeness(min_hull) */
    double max_helm_deg, path_length, path_lengthening, time_lost, rudder_work_deg_s;
    int helm_orders;
    double traffic_ship_s;
    char behaviour[16];          /* colregs, blind */
    int give_way, give_way_short;
    fw_monitor_counts monitors;
    double min_hull;                /* m, NAN if no target within 1 nm */
    int n_enc, n_traffic;
    fw_outcome_encounter *enc;   /* owned */
    fw_outcome_traffic *traffic; /* owned */
} fw_outcome;

/* A failed run: status "failed" and the reason. */
void fw_outcome_failed(fw_outcome *o, int run_id, const char *reason);
/* From a finished run's summary, encounter book and survey records. */
fw_status fw_outcome_from_run(fw_outcome *o, const fw_study *s, int run_id,
                              const fw_run_summary *sum, const fw_encounter *e, int n,
                              const fw_survey_record *sv, int n_sv, fw_error *err);
void fw_outcome_free(fw_outcome *o);

/* Bytes and back.  Both ends are the same fairway build. */
fw_status fw_outcome_pack(const fw_outcome *o, unsigned char **buf, size_t *n, fw_error *err);
fw_status fw_outcome_unpack(const unsigned char *buf, size_t n, fw_outcome *o, fw_error *err);

#endif
