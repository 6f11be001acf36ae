/* split_run.h - fairway runs as splitting's trajectories (study/ams.h).
 *
 * A trajectory is one run of a scenario to its duration, scored each step by
 * the own ship's closeness so far (study/outcome.h fw_closeness of the least
 * hull-to-hull distance to any ship: 1 at contact; below a near miss, with a
 * watch that draws, its unseen approach: fw_split_run_def.hidden_level).  Its randomness is the
 * run's: a start draws the scenario (a seed for the traffic and the streams,
 * and whatever else the caller's `scenario` makes of the draw: a study's
 * own-ship start), a branch is its parent up to the first step whose score
 * exceeded the level, then fairway's random streams re-keyed (world.h
 * fw_world_rekey) and the run continued.
 *
 * A branch is made by replaying the parent from t = 0: the run is the same
 * to the bit for the same seed and re-keyings (the digests hold this), so
 * replaying costs time and no accuracy.  Each branch therefore costs one
 * whole run (ams.h's cost counts it so: the speed-up reported against crude
 * Monte Carlo is the honest one); forked snapshots at the level crossings
 * (run/branch.h) would save the replayed part, at the price of a paused
 * process per crossing kept.
 *
 * Each trajectory runs in a child process (fork): libsumo holds one
 * simulation per process, and a run that crashes costs its trajectory (an
 * error naming it), not the estimate's process.
 *
 * Randomness after t = 0 is what makes branches differ: a start whose world
 * made no random stream (world.h fw_world_streams) fails the model with
 * FW_EINPUT, since every branch would repeat its parent.
 */
#ifndef FW_STUDY_SPLIT_RUN_H
#define FW_STUDY_SPLIT_RUN_H

#include <stdint.h>

#include "run/run.h"
#include "study/ams.h"

typedef struct fw_split_run_def {
    /* The scenario of a start drawn as `draw` (a seed and anything else the
     * caller varies between trajectories); out must be complete. */
    void (*scenario)(void *ctx, uint64_t draw, fw_scenario *out);
    void *ctx;
    fw_run_def run;       /* the template: traffic, SUMO mode (scenario and dir are set here) */
    /* where each trajectory's run directory is made and removed afterwards;
     * NULL: runs without files (the kinematic source only) */
    const char *work_dir;
    /* Optional, for a caller's own controller: one made per trajectory (the
     * run takes it over), and a look at the run once it is open. */
    fw_status (*make_controller)(void *ctx, fw_controller **out, fw_error *err);
    void (*opened)(void *ctx, fw_run *r);
    /* The score below this closeness (a near miss's; 0: closeness alone)
     * when the own ship's watch draws (world.h fw_world_own_unseen): that
     * level times the watch's unseen approach (watch.h fw_watch_unseen).
     * Every path on which the watch noticed a ship in time is one path with
     * one closeness (the policy acts at its act range, whenever it noticed),
     * so the closeness ties them all and splitting dies out; the unseen
     * approach rises only while a ship is still hidden from the policy, so
     * a branch is taken before the detection and draws it afresh (watch.h
     * fw_watch_redraw).  Events are unchanged: the score is at or above the
     * level exactly when the closeness is. */
    double hidden_level;
} fw_split_run_def;

/* A trajectory's summary for the caller, from fw_split_run_last. */
typedef struct fw_split_traj_info {
    double score;     /* largest closeness */
    double min_hull;  /* m, INFINITY: no ship within the hull watch */
    uint64_t draw;    /* its start's draw */
    int branches;     /* re-keyings along it */
} fw_split_traj_info;

typedef struct fw_split_run fw_split_run;

/* The model for fw_ams_run / fw_ams_batches; def is copied (its pointers
 * must outlive the model). */
fw_status fw_split_run_create(const fw_split_run_def *def, fw_split_run **out, fw_ams_model *m,
                              fw_error *err);
void fw_split_run_destroy(fw_split_run *s); /* safe on NULL */

/* What a trajectory the engine holds was (traj: fw_ams_sim.traj). */
fw_split_traj_info fw_split_run_info(const void *traj);

/* The closest trajectory of the last estimate (fw_ams_run's end): its
 * closeness and its path as text, "DRAW:STEP/B,STEP/B" (the start's draw and
 * each re-keying: after step STEP, branch number B), which
 * fw_split_run_replay runs again. */
double fw_split_run_best(const fw_split_run *s, char *path, size_t n);

/* Runs the trajectory `path` names (a best path) into dir with the model's
 * scenario and run definition; its summary and encounters as fw_run_close
 * gives them.  FW_EINPUT for a path that does not parse. */
fw_status fw_split_run_replay(const fw_split_run *s, const char *path, const char *dir,
                              fw_run_summary *sum, fw_encounter **enc, int *n_enc, fw_error *err);

/* Trajectories simulated so far and the simulated seconds they took (each a
 * whole run: replays included). */
long fw_split_run_count(const fw_split_run *s);
double fw_split_run_sim_s(const fw_split_run *s);

#endif
