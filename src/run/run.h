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
 *   situation_output.json  a DNV situation's answer (run/dnv_out.h; only for one)
 *   sumo/           the generated network, routes and SUMO's messages (SUMO runs)
 */
#ifndef FW_RUN_H
#define FW_RUN_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "run/records.h"
#include "scenario/scenario.h"
#include "survey/survey.h"
#include "traffic/source.h"
#include "traffic/traffic.h"
#include "world/world.h"

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
     * fw_run_open, also when it fails.  NULL: the policy.  If it assesses
     * nothing, the records get the run's own assessments of the targets,
     * made as the policy makes them (the scenario's COLREGs, domain and
     * horizon). */
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
/* m, the least hull-to-hull distance from the own ship to any ship so far
 * (the encounter book's; INFINITY while none has come within the hull
 * watch, 1 nm): what splitting scores a run by (study/split_run.h). */
double fw_run_min_hull(fw_run *r);
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
 * fairway's random streams take, and where its result goes (branch.c's); set
 * by a restore.  And why a run cannot be snapshotted (NULL: it can): decided
 * on its definition. */
uint32_t fw_run_branch(const fw_run *r);
void fw_run_set_branch(fw_run *r, uint32_t branch, void *box);
void *fw_run_branch_box(const fw_run *r);
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

#endif
