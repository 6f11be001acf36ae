/* run_internal.h - a run's state (run.h), shared by run.c (open, step,
 * close) and run_record.c (what each step records: run.log, the encounter
 * book, the survey, the summary). */
#ifndef FW_RUN_INTERNAL_H
#define FW_RUN_INTERNAL_H

#include "ais/ais_track.h"
#include "run/dnv_out.h"
#include "run/run.h"
#include "world/world.h"

/* A run: what it was asked, what it made, and everything that evolves from
 * step to step (the world's state aside), so that all of it is reachable
 * from here (the snapshot's need). */
struct fw_run {
    fw_run_def def;
    const fw_scenario *s;
    fw_world *w;             /* NULL: the set-up failed */
    fw_vessel *own;
    fw_records *rec;
    fw_survey *sv;           /* NULL: no survey */
    fw_monitor *mon;         /* the traffic monitors */
    fw_run_summary sum;      /* the measures so far */
    long k, n_steps;         /* steps taken, steps in the scenario */
    fw_status failed;        /* the failure that ended the run (FW_OK: none) */
    fw_error fail;           /* its message */
    fw_policy_mode mode_prev;
    int leg_prev;            /* the route's leg at the last step */
    bool unkept_prev;        /* the domain could not be kept at the last step */
    bool r19e_prev;          /* rule 19(e)'s speed was ordered at the last step */
    double helm_prev, e_prev, n_prev;
    int reactions_seen;      /* the world's reactions already in run.log */
    bool kb_outside;         /* the own speed was outside the knowledge base's at the last step */
    fw_assessment *as;       /* the run's own assessments, for a controller that makes none */
    int as_cap;
    double wall0, cpu0;      /* clock and CPU s at the open */
    double t_setup, t_observe, t_loop; /* CPU s (--profile) */
    uint32_t branch;         /* branch.h: 0 unless restored from a snapshot as another */
    void *branch_box;        /* branch.h: where a restored branch leaves its result */
    fw_ais_tracks ais;       /* AIS traffic: what the reading counted (no arrays) */
    fw_dnv_out *dnv;         /* a DNV situation's answer (dnv_out.h); NULL: none */
};

/* run_record.c, each explained there. */
void fw_run_note(fw_run *R, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
fw_status fw_run_survey_lane(void *ctx, const fw_target *s, const fw_lane_info **out,
                             fw_error *err);
fw_status fw_run_survey_step(fw_run *R, double t, fw_error *err);
fw_status fw_run_survey_finish(fw_run *R, const fw_run_def *def, fw_run_summary *sum,
                               fw_error *err);
void fw_run_record_action(fw_run *R, double t, const fw_decision *d, const fw_target *tg,
                          const fw_assessment *as, int n, fw_run_summary *sum);
void fw_run_record_mode(fw_run *R, double t, const fw_decision *d, fw_run_summary *sum);
void fw_run_record_reactions(fw_run *R, fw_run_summary *sum);
void fw_run_record_kb_speed(fw_run *R, const fw_mmg_state *x, fw_run_summary *sum);

#endif
