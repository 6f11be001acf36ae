/* sweep.h - runs a study's run list into its database.
 *
 * libsumo holds one simulation per process, so every run executes in a child
 * process of its own (fork): a crash or a hang in one run costs that run, not
 * the sweep, and the children die with their parent (PR_SET_PDEATHSIG).  The
 * parent (or MPI rank 0) is the only writer of the database and commits each
 * finished run in one transaction; runs already in the database are skipped,
 * so re-running the same command resumes.  Ctrl-C or SIGTERM stop the
 * children and lose only the runs in flight.
 *
 * Under mpirun, rank 0 hands out run ids and writes the database, the other
 * ranks run them (each in a child, as above).  A run's results do not depend
 * on which process ran it.
 */
#ifndef FW_STUDY_SWEEP_H
#define FW_STUDY_SWEEP_H

#include <stdbool.h>
#include <stdio.h>

#include "core/error.h"
#include "study/outcome.h"
#include "study/study.h"
#include "traffic/traffic.h"

typedef enum fw_progress_kind {
    FW_PROGRESS_AUTO,  /* a bar on a terminal, lines otherwise */
    FW_PROGRESS_BAR,
    FW_PROGRESS_LINES,
    FW_PROGRESS_NONE
} fw_progress_kind;

typedef struct fw_sweep_def {
    const fw_study *study;
    const char *db;
    int jobs;               /* worker processes; 0 = one per core */
    fw_traffic_mode mode;   /* SUMO back end of every run */
    const char *keep_dir;   /* keep each run's directory here; NULL: removed */
    bool retry_failed;      /* run again the runs recorded as failed */
    int limit;              /* stop after this many new runs (0 = all): for tests */
    fw_progress_kind progress;
    FILE *progress_out;     /* default stderr */
} fw_sweep_def;

fw_sweep_def fw_default_sweep_def(void);

typedef struct fw_sweep_result {
    int total;       /* runs in the study */
    int skipped;     /* already in the database */
    int done;        /* finished now, ok */
    int failed;      /* finished now, failed */
    int failed_before; /* failed runs in the database from earlier sweeps */
    bool interrupted;
    double wall_s;
    int split_done, split_failed; /* splitting estimates made now (estimate:) */
} fw_sweep_result;

/* Local worker processes. */
fw_status fw_sweep_local(const fw_sweep_def *def, fw_sweep_result *res, fw_error *err);

/* Was this process started by mpirun (and is MPI built in)? */
bool fw_sweep_under_mpi(void);
/* The MPI sweep: every rank calls it; rank 0 fills res and returns the
 * sweep's status, the others return FW_OK (or their own failure).  *is_root
 * tells the caller whether to print. */
fw_status fw_sweep_mpi(const fw_sweep_def *def, fw_sweep_result *res, bool *is_root,
                       fw_error *err);

/* One run, executed in this process (the child's part): run directory under
 * work_dir, removed afterwards unless keep. */
void fw_sweep_exec(const fw_study *s, int run_id, const char *work_dir, bool keep,
                   const fw_traffic_mode *mode, fw_outcome *out);

/* sweep_child.c: one run in a forked child and its result read back.
 * fw_sweep_spawn starts it (fd: the read end of its result pipe);
 * fw_sweep_collect reads, reaps and unpacks (a dead child is a failed run). */
typedef struct fw_child {
    int pid, fd, run_id;
    unsigned char *buf;
    size_t n, cap;
    double t0;
} fw_child;
fw_status fw_sweep_spawn(const fw_study *s, int run_id, const char *work_dir, bool keep,
                         const fw_traffic_mode *mode, fw_child *c, fw_error *err);
/* Reads what is available; returns true when the child's pipe is at EOF. */
bool fw_sweep_read(fw_child *c);
void fw_sweep_collect(fw_child *c, fw_outcome *out);
void fw_sweep_kill(fw_child *c);

/* Has work, the work directory (NULL: not known), less than 64 kB left? */
bool fw_sweep_disk_low(const char *work);
/* Did run o fail on a full disk (its reason says so, or work, the work
 * directory, when not NULL, has less than 64 kB left)?  Then err says so,
 * with left, the runs not recorded after it (sweep.c). */
bool fw_sweep_disk_full(const fw_study *s, const fw_outcome *o, const char *work, int left,
                        fw_error *err);

/* A fresh work directory for run directories (mkdtemp; --keep: that one). */
fw_status fw_sweep_workdir(const fw_sweep_def *def, char *out, size_t outsz, fw_error *err);

/* Progress reporting (progress.c). */
typedef struct fw_progress fw_progress;
fw_progress *fw_progress_start(const fw_sweep_def *def, int todo, int total, int skipped);
void fw_progress_run(fw_progress *p, const fw_study *s, const fw_outcome *o, int done,
                     int failed);
void fw_progress_tick(fw_progress *p, int done, int failed, int running);
/* A committed run counted (done or failed) and shown. */
void fw_progress_count(fw_progress *p, const fw_study *s, const fw_outcome *o,
                       fw_sweep_result *res);
void fw_progress_end(fw_progress *p, int done, int failed);

double fw_sweep_now(void); /* s, monotonic */

/* sweep_split.c: the study's pending splitting estimates (estimate:), each
 * (cell, batch) in a worker process of its own, up to `jobs` at once,
 * committed one by one (a resumed sweep makes only the missing ones).  Under
 * mpirun (sweep_mpi.c) the ranks take them after the runs, each in a forked
 * worker, and rank 0 commits them. */
typedef struct fw_store fw_store;
fw_status fw_sweep_splits(const fw_sweep_def *def, fw_store *st, const char *work, int jobs,
                          fw_sweep_result *res, fw_error *err);
/* One estimate's result, as a worker sends it back: fixed size, well under
 * a pipe's buffer (the worker never waits on its reader), the same bytes
 * over MPI (ranks of one build on one kind of machine). */
typedef struct fw_split_msg {
    int job; /* cell * batches + batch */
    int ok, rounds;
    double runs, sim_s, wall_s, p_collision, p_near_miss, best;
    char reason[512];
    char path[2048];
} fw_split_msg;
/* The (cell, batch) jobs not yet in the database, as job = cell * batches +
 * batch, batch-major (every cell's batch 0 first: a sweep cut short holds
 * paired sets); --retry-failed forgets failed ones first. */
fw_status fw_sweep_split_pending(const fw_sweep_def *def, fw_store *st, int **jobs, int *n_jobs,
                                 fw_error *err);
/* One job estimated in a forked worker under work (an MPI rank's part); a
 * worker that died leaves m failed, saying so. */
void fw_sweep_split_one(const fw_sweep_def *def, const char *work, int job, fw_split_msg *m);
/* A job's result into the database, the progress line, and res's counts. */
fw_status fw_sweep_split_commit(const fw_sweep_def *def, fw_store *st, int job,
                                const fw_split_msg *m, fw_sweep_result *res, fw_error *err);
/* A SIGINT or SIGTERM has asked the sweep to stop. */
bool fw_sweep_stopped(void);

/* A study cell's trajectories for splitting (split_run.h's scenario maker;
 * ctx an fw_split_cell): the cell's setting with its start drawn from draw
 * (study.h fw_study_run_drawn). */
typedef struct fw_split_cell {
    const fw_study *s;
    int cell;
} fw_split_cell;
void fw_split_cell_scenario(void *ctx, uint64_t draw, fw_scenario *out);

#endif
