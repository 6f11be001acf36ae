/* run.h - one scenario run as an object the caller steps: open, step, close.
 *
 * fw_run_open builds a world (world/world.h) from the scenario: a traffic
 * source (SUMO, which writes its own files into sumo/, or the kinematic source
 * for explicit targets) and the own ship (MMG dynamics, the avoidance policy
 * or a controller of the caller's).  After the world's start and after every
 * fw_run_step the records take the instant: the own ship's state and decision,
 * every target seen with its assessment (the encounter book), and, with a
 * survey: section, every ship in the survey area (survey/survey.h: the
 * encounters among all ships, by type).  fw_run_close finishes: the track
 * measures, the survey's totals, the files written at the end, the summary.
 *
 *   fw_run *r;
 *   fw_status st = fw_run_open(&def, &r, &err);    t = 0 recorded
 *   while (!st && !fw_run_done(r))
 *       st = fw_run_step(r, &err);                 ... read fw_run_world(r) ...
 *   st = fw_run_close(r, &sum, &enc, &n_enc, &err);
 *
 * which is fw_run_scenario.  Every evolving part of a run (the world, the
 * records, the monitors, the survey, the summary so far and the loop's own
 * state: last helm, mode, path sums, reactions logged) hangs from the fw_run.
 *
 * Outputs (in the run directory; every number printed with a fixed format and
 * no clock time anywhere, so the same scenario and seed give identical files):
 *   own.csv         t, east, north, heading, u, v, r, rudder, helm order, propeller, mode
 *                   (standby, avoid, steady, autopilot: avoid/policy.h)
 *   targets.csv     t, id, east, north, heading, speed, range, bearing (outputs.targets_csv)
 *   encounters.csv  one row per target met
 *   traffic_encounters.csv  one row per pair episode of the survey (only with one)
 *   summary.json    the run's measures, the traffic monitors and the encounter rows
 *   run.log         decisions and mode changes, every traffic monitor event
 *   sumo/           the generated network, routes and SUMO's messages (SUMO runs)
 */
#ifndef FW_RUN_H
#define FW_RUN_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "avoid/encounter.h"
#include "world/world.h"
#include "core/error.h"
#include "dynamics/mmg.h"
#include "scenario/scenario.h"
#include "survey/monitor.h"
#include "survey/survey.h"
#include "traffic/source.h"
#include "traffic/traffic.h"

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
    /* Wall-clock seconds of the run and of it inside SUMO's step: for the
     * benchmarks and the study database only, never written to the run's
     * files (they must be identical from run to run). */
    double wall_s, sumo_s;
    double own_length, own_breadth; /* m, hull outline (for plots) */
    double domain, domain_ratio;    /* m, transverse semi-axis; fore-aft / transverse */
    const char *domain_reading;     /* "ellipse" or "transverse" (geom.h): the run's judge too */
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
    int n_give_way;                 /* slow-down orders */
    int n_give_way_short;           /* of which no speed kept the passing distance */
    int n_resume;
    /* The own ship's speed against the speeds its Nomoto knowledge base was
     * fitted over (nomoto.h): seconds of the run it sailed outside them (its
     * predictions extrapolated), and the extremes of its speed (kn). */
    bool kb_present;
    double kb_speed_min_kn, kb_speed_max_kn;
    double kb_outside_s;
    double own_speed_min_kn, own_speed_max_kn;
} fw_run_summary;

/* Where the targets come from: SUMO (any scenario), or the kinematic source
 * (explicit targets only, at constant velocity, no SUMO process). */
typedef enum fw_run_traffic { FW_RUN_TRAFFIC_SUMO, FW_RUN_TRAFFIC_KINEMATIC } fw_run_traffic;

typedef struct fw_run_def {
    const fw_scenario *scenario; /* must outlive the run */
    /* the run directory (created by the caller); NULL: no files at all (the
     * records still keep the encounter book and the summary; SUMO traffic
     * needs a directory: FW_EINPUT) */
    const char *dir;
    fw_run_traffic traffic;   /* SUMO (default) or kinematic */
    fw_traffic_mode mode;     /* SUMO back end */
    /* Optional: the survey's records, sorted by (t_first, ship_a, ship_b), as
     * a malloc'd array the caller frees.  NULL = not wanted.  Set (to NULL,
     * 0 when the scenario has no survey) whenever fw_run_scenario returns,
     * also after a failure part way (the records up to then). */
    fw_survey_record **survey_out;
    int *n_survey_out;
    /* run.log (and stderr) get where the run's wall time went: set-up, the
     * world's phases (world.h fw_world_timing), the records, the finish */
    bool profile;
    /* The own ship's controller in place of the scenario's avoidance policy
     * (world/controllers.h; the oracle's fixed manoeuvre): taken over by
     * fw_run_open, also when it fails.  NULL: the policy. */
    fw_controller *controller;
} fw_run_def;

/* SUMO embedded, no survey records wanted, no profile, the policy. */
fw_run_def fw_default_run_def(void);

typedef struct fw_run fw_run;

/* Set-up (records, monitors, survey, the world), then the world's start and
 * the records of t = 0.  *out is a run whenever memory for it was found (NULL
 * otherwise), also when this fails: a failure in set-up or at t = 0 leaves a
 * run that is done and failed, for fw_run_close to report (a failed set-up
 * writes no summary.json, as before).  def is copied; def->scenario, def->dir
 * and the survey_out pointers must outlive the run. */
fw_status fw_run_open(const fw_run_def *def, fw_run **out, fw_error *err);
/* One world step of the scenario's length and the records of its instant.
 * A run that is done is not stepped: FW_EINPUT, nothing changes.  A failure
 * ends the run (done, status failed; the records up to the step before). */
fw_status fw_run_step(fw_run *r, fw_error *err);
/* The scenario's duration reached (lround(duration / step) steps), or failed. */
bool fw_run_done(const fw_run *r);
long fw_run_steps(const fw_run *r);   /* steps taken since t = 0 */
double fw_run_time(const fw_run *r);  /* s, the world's time (0 before it exists) */
/* The run's world, to read (the vessels, their views and decisions, the
 * source): NULL if the set-up failed.  Stepping it other than by fw_run_step
 * leaves the records behind. */
fw_world *fw_run_world(fw_run *r);
/* The run's output streams open now (own.csv, run.log, targets.csv if asked),
 * up to max of them into files; returns how many there are.  Everything else
 * (encounters.csv, traffic_encounters.csv, summary.json) is written whole by
 * fw_run_close; SUMO's own files in sumo/ are SUMO's.  None without a dir. */
int fw_run_files(fw_run *r, FILE **files, int max);
/* Finishes and frees the run: the track measures (final offsets, path and time
 * lost), the monitors' and the survey's totals, encounters.csv,
 * traffic_encounters.csv, summary.json; the summary (status "ok" unless the run
 * failed; t_end the last instant recorded, so a run closed before its duration
 * ends there) and a malloc'd copy of the encounter book.  Returns the run's
 * failure if it had one, else the finish's.  sum, enc, n_enc are filled also
 * after a failure part way. */
fw_status fw_run_close(fw_run *r, fw_run_summary *sum, fw_encounter **enc, int *n_enc,
                       fw_error *err);
/* Frees the run and writes nothing more (branch.h: an abandoned branch). */
void fw_run_discard(fw_run *r);
const char *fw_run_dir(const fw_run *r); /* def->dir (NULL: no files) */
/* branch.h: the branch this run is (0: not one restored as another), which
 * fairway's random streams take; set by a restore.  And why a run cannot be
 * snapshotted (NULL: it can): decided on its definition. */
uint32_t fw_run_branch(const fw_run *r);
void fw_run_set_branch(fw_run *r, uint32_t branch);
const char *fw_run_unforkable(const fw_run *r);
const char *fw_run_def_unforkable(const fw_run_def *d);

/* open, step until done, close: runs the scenario to its end, writing the
 * records into def->dir.  The summary is filled even when the run fails part
 * way (status "failed"). */
fw_status fw_run_scenario(const fw_run_def *def, fw_run_summary *sum, fw_encounter **enc,
                          int *n_enc, fw_error *err);

/* The scenario's explicit targets at constant velocity as a kinematic source
 * (traffic/source.h) stepping `step`, seen within `radius` (INFINITY: all),
 * with the survey's area if the scenario has one.  FW_EINPUT for a scenario
 * with a network (that traffic needs SUMO). */
fw_status fw_run_kinematic_source(const fw_scenario *s, double step, double radius,
                                  fw_source **src, fw_error *err);

/* The scenario's AIS reports (traffic.ais) as tracks in its plane
 * (ais/ais_track.h), t = 0 the window's start; FW_EINPUT also when no ship
 * is left in the window.  The caller frees t (fw_ais_tracks_free). */
typedef struct fw_ais_tracks fw_ais_tracks;
fw_status fw_run_ais_tracks(const fw_scenario *s, fw_ais_tracks *t, fw_error *err);

/* records.c: the encounter book and the result files. */
typedef struct fw_records fw_records;
fw_status fw_records_open(fw_records **out, const fw_scenario *s, const char *dir,
                          fw_error *err);
void fw_records_close(fw_records *r);
/* run.log (NULL without a directory). */
FILE *fw_records_log(fw_records *r);
/* The open streams (own.csv, run.log, targets.csv), up to max into f; how many. */
int fw_records_files(fw_records *r, FILE **f, int max);
void fw_records_own(fw_records *r, double t, const fw_mmg_state *x, double helm, double n,
                    const char *mode);
/* One target seen at time t, with its assessment (situation, DCPA/TCPA, threat).
 * FW_ERUN when the book cannot grow: a run never goes on missing a ship. */
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
