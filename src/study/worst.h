/* worst.h - a study's worst encounters as scenarios that replay them.
 *
 * The N own-ship encounters of a study database with the smallest hull-to-hull
 * distance (one per run) are sailed again: the run is rebuilt from the study
 * file (its seed, start, domain and behaviour; the database's study digest
 * must match, or the run would not be the same), run with every target it saw
 * recorded at every step, and written as
 *
 *   DIR/case-K/tracks.csv      the targets' recorded tracks (traffic/source_track.h),
 *                              each row with the turn the own ship saw that
 *                              ship making (run/records.h, geom/turn.h)
 *   DIR/case-K/scenario.yaml   the study's base scenario with the run's own-ship
 *                              start, domain, duration, and the tracks as its
 *                              traffic (no network, no survey)
 *
 * and the scenario is run once more to check it replays the encounter: its
 * closest approach to the same target, beside the database's and the re-run's.
 * A replay differs from the original only where the rounding of the recorded
 * positions (cm), speeds and turns moves a decision of the own ship: a ship
 * the traffic steered (world/steer.h) is replayed with the turn the
 * original's own ship expected of it at each step, not at constant velocity.
 *
 * With situations, each case is also written as DIR/case-K/situation.json,
 * a DNV traffic situation of the replay's own ship and the tracks simplified
 * to FW_DNV_TOLERANCE_M (run/dnv_situation.h), read back
 * (scenario/scn_dnv.h, the study's own-ship model) and sailed into
 * DIR/case-K/situation: its closest approach to the same ship beside the rest.
 */
#ifndef FW_STUDY_WORST_H
#define FW_STUDY_WORST_H

#include <stdbool.h>

#include "core/error.h"
#include "traffic/traffic.h"

typedef struct fw_worst_def {
    const char *db;     /* the study database */
    const char *study;  /* NULL: the study file named in its meta */
    const char *out;    /* directory to write the cases into (created) */
    int n;              /* cases, 1 by default */
    /* also DIR/case-K/situation.json, the case as a DNV traffic situation
     * (run/dnv_situation.h), read back and sailed into DIR/case-K/situation */
    bool situations;
    fw_traffic_mode mode;
} fw_worst_def;

fw_worst_def fw_default_worst_def(void);

typedef struct fw_worst_case {
    int run_id;
    char target[64];
    double db_min;      /* m, centre to centre, as the database has it */
    double db_hull;     /* m, hull to hull (NAN if not recorded) */
    double rerun_min;   /* m, the run sailed again */
    double replay_min;  /* m, the exported scenario */
    double situation_min; /* m, the situation read back (NAN: not written) */
    char dir[1100];
} fw_worst_case;

/* The database opened read-only and checked (db_check.h), with its study's
 * file and digest from meta; the caller closes *db. */
typedef struct sqlite3 sqlite3;
fw_status fw_worst_open(const fw_worst_def *def, sqlite3 **db, char *study, size_t sz,
                        char *digest, fw_error *err);
/* The database's study (def->study, or the file meta names) loaded into s
 * and checked against the digest: FW_EINPUT when it changed since. */
typedef struct fw_study fw_study;
fw_status fw_worst_study(const fw_worst_def *def, const char *study_file, const char *digest,
                         fw_study *s, fw_error *err);

/* The closest trajectory splitting found in each cell of a study with
 * estimate: (table splits), run again from its path into DIR/split-cell-K
 * (study/split_run.h fw_split_run_replay): its closeness as the database has
 * it and as the replay gives it (the same: a path names every draw). */
typedef struct fw_worst_split {
    int cell;
    double db_closeness, replay_closeness, replay_hull; /* replay_hull m, INFINITY: none */
    char path[2048];
    char dir[1100];
} fw_worst_split;
fw_status fw_worst_splits(const fw_worst_def *def, fw_worst_split *out, int max, int *n,
                          fw_error *err);

/* Fills cases[0..*n-1] (room for def->n).  FW_EINPUT for a database or
 * study that cannot be used, FW_ERUN when a run fails. */
fw_status fw_worst_export(const fw_worst_def *def, fw_worst_case *cases, int *n, fw_error *err);

#endif
