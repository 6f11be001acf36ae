/* branch.h - snapshot and restore of a running run (run.h), by fork.
 *
 * In the manner of Box2D v3's b2World_Snapshot / b2World_Restore: a snapshot
 * is taken between two steps, and a restore continues the run from it as if
 * it had never gone on; "output written after a restore is as if the run had
 * never branched".  Unlike Box2D's, the image is not bytes but a process: the
 * snapshot is a copy-on-write copy of the whole process (fork), paused at the
 * step, and a restore makes that copy fork once more and go on.
 *
 * Why fork and not SUMO's saveState / loadState (bench/results/snapshot.txt,
 * bench/bench_sumo_state.cpp, t = 1800 s of the base scenario): both cost about
 * the same (fork 1.4-2.5 ms and 157 page faults in the branch's first minute,
 * against saveState 1.5-2.8 ms and loadState 3.3-5.1 ms for 38 ships), but
 * after a loadState SUMO 1.15 does not go on as it would have: in the first
 * step 16 fill ships that had left come back and ships jump up to 659 m
 * sideways (lane changes in progress are not saved), where the forked copy's
 * ships are where the original's are to the last bit for the next 600 s.
 * And the rest of a run (the vessels' ARKODE integrators, controllers,
 * reactions, monitors, records, the libsumo range read's file-scope state)
 * would each need its own save and load; a fork copies them all at once and
 * cannot forget one.  Costs here (bench_snapshot, the base scenario): a
 * snapshot 0.8-1.3 ms, 0.13-0.17 of a simulated minute; a restore 2.4-2.7 ms
 * beyond the minutes the branch simulates on a quiet host, 6-8 ms on a busy
 * one (its fork, the files put back, about 250 page faults), 0.4-1.1
 * simulated minutes.  A paused copy's memory is the pages the original
 * changes after it: 228 pages (0.9 MB) over the next ten simulated minutes.
 *
 * What is saved (everything in this process's memory, by construction):
 *   the vessels (states, MMG/Nomoto dynamics and their ARKODE integrators with
 *   their step history), controllers (policy modes, held helm, the planned
 *   track), the world's reactions and the traffic source (the kinematic and
 *   recorded-track sources; libsumo with its whole simulation: ships, lanes,
 *   lane changes in progress, its RNGs, and the range read's state), the
 *   records (the encounter book, the own ship's history, the survey, the
 *   monitors) and the run's accumulators (summary so far), fairway's random
 *   streams (none draw yet), and every stdio and C++ stream buffer.
 * What is restored outside memory: the files under the run directory.  At the
 *   snapshot every stdio stream is flushed and each file of the run directory
 *   open for writing (own.csv, targets.csv, run.log, SUMO's sumo.log and
 *   fcd.xml: found in /proc/self/fd, so SUMO's are caught too) is noted with
 *   its offset, with the list of files there.  A restored branch truncates each
 *   to its offset, writes on from there through its own descriptor, makes
 *   again from the descriptor it inherited any that the abandoned branch
 *   removed or renamed (.fcd.xml.fairway-tmp.PID.XXXXXX, renamed fcd.xml at the
 *   close), and removes the files made after the snapshot (encounters.csv,
 *   summary.json of an abandoned branch that finished): the directory is as
 *   it was.
 * What is not saved:
 *   - SUMO in another process (--sumo gui, remote:HOST:PORT: libtraci): fork
 *     copies this process only.  fw_run_snapshot refuses such a run
 *     (FW_EINPUT); saveState would not continue it the same either (above).
 *   - anything outside the run directory: the terminal (a line printed after a
 *     snapshot stays printed), other files the caller writes, a study database.
 *   - wall and CPU clocks: fw_run_summary's wall_s, sumo_s and run.log's
 *     --profile line are the branch's own (they are never in the digests).
 *   - directories made after the snapshot (files in them are removed).
 * Randomness: SUMO's RNGs in a restored copy go on exactly as in the original
 *   (fork copies them, and --seed is not read again): SUMO draws in a branch
 *   what it would have drawn unbranched.  A branch differs from the unbranched
 *   run only through fairway's own random streams (core/rng.h), which take the
 *   branch number restore is given: 0 keeps every stream as it is (the
 *   unbranched run's numbers), b > 0 replaces each by fw_rng_branch(s, b):
 *   the world's table of streams (world.h fw_world_rng, core/streams.h) is
 *   re-keyed at the restore, streams made later included.
 * Results: a branch's summary and encounters (fw_run_close) are in the
 *   branch's memory: the owner sees the run directory's files, the exit code
 *   and the bytes the branch leaves with fw_run_result (a page shared by the
 *   owner, the paused copy and its branches), nothing else (def->survey_out
 *   is filled in the branch).
 *
 * Processes.  A snapshot's copy waits for a command on a pipe from the process
 * that took it (the owner); when that pipe closes (fw_snapshot_free, or the
 * owner dies) it exits: no copy outlives its owner paused.  A restore asks the
 * copy to fork a branch, which returns from fw_run_snapshot a second time, as
 * fork returns twice: there *out is NULL and fw_run_branch(r) the branch
 * number.  The branch owns the run from then on and ends as the caller's code
 * ends it (finish the run, then exit: its exit code is what restore reports).
 * The copy reaps the branch and tells the owner its exit code; restore returns
 * it.  One snapshot gives any number of branches, one after another (adaptive
 * multilevel splitting: many continuations from one level crossing).
 *
 *     fw_snapshot *snap;
 *     fw_run_snapshot(run, &snap, &err);
 *     if (!snap) { ... the branch: step to the end, close the run, _exit(code) }
 *         (_exit, not exit: atexit handlers and leak checks belong to the
 *         original, whose memory the branch holds a copy of)
 *     ... the original goes on; to continue from the snapshot instead:
 *     fw_run_restore(run, snap, 0, &code, &err);   (run discarded: do not use it)
 *     fw_snapshot_free(snap);
 *
 * Linux only (/proc/self/fd).  Not thread-safe: fork copies the calling thread.
 */
#ifndef FW_RUN_BRANCH_H
#define FW_RUN_BRANCH_H

#include <stdint.h>

#include "core/error.h"
#include "run/run.h"

typedef struct fw_snapshot fw_snapshot;

/* The exit code of a branch that could not put the run directory back (it
 * says why on stderr); fw_run_restore turns it into FW_ERUN. */
#define FW_BRANCH_EXIT_REWIND 125

/* Snapshot of r between steps.  Returns twice: in the caller with *out the
 * snapshot; in a branch restored from it with *out = NULL, always FW_OK (a
 * branch that cannot restore the files exits, FW_BRANCH_EXIT_REWIND).
 * FW_EINPUT for a run whose SUMO is another process; FW_ERUN when the process
 * cannot fork or a file of the run directory cannot be read. */
fw_status fw_run_snapshot(fw_run *r, fw_snapshot **out, fw_error *err);

/* Ends the caller's branch and continues the run from s in a copy numbered
 * branch (fairway's random streams take it; 0 = the unbranched run's), waits
 * for that copy to end and puts its exit code in *exit_code (128 + the signal
 * if one killed it).  r is the caller's run, discarded here before the copy
 * goes on (fw_run_discard: its end is not written; what it still flushes
 * into the files the copy cuts away; the caller must not use r again), or NULL when the caller's run is already closed or
 * discarded (another branch from the same snapshot).  Only the process that
 * took s may restore it (FW_EINPUT in another); FW_ERUN when the copy has
 * gone or cannot fork. */
fw_status fw_run_restore(fw_run *r, fw_snapshot *s, uint32_t branch, int *exit_code,
                         fw_error *err);

/* Results: a restored branch leaves up to FW_BRANCH_RESULT_MAX bytes (say a
 * splitting score) with fw_run_result while its run is open (before
 * fw_run_close), each call replacing the last; after
 * fw_run_restore returns, fw_snapshot_result gives the bytes that branch left
 * (*n = 0: none; aligned for any type), valid until the next restore or
 * fw_snapshot_free.
 * fw_run_result: FW_EINPUT in a run that is not a restored branch, or over
 * the size. */
#define FW_BRANCH_RESULT_MAX 4000
fw_status fw_run_result(fw_run *r, const void *data, size_t n, fw_error *err);
const void *fw_snapshot_result(const fw_snapshot *s, size_t *n);

/* s's time (s) and step (as fw_run_steps counts them); its paused copy's
 * process id (for a driver that watches its processes). */
double fw_snapshot_time(const fw_snapshot *s);
long fw_snapshot_step(const fw_snapshot *s);
int fw_snapshot_pid(const fw_snapshot *s);

/* Ends s's paused copy (and reaps it) and frees s.  In a process other than
 * its owner (a branch holding its owner's snapshots) only frees the memory.
 * Safe on NULL. */
void fw_snapshot_free(fw_snapshot *s);

#endif
