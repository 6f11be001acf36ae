/* survey.h - traffic-level encounters: every pair of ships in an area, by type.
 *
 * What AIS near-collision studies count and waterway risk studies compare with
 * IWRAP-style collision candidates: a pair of ships is an encounter when their
 * centres are closer than `range`, and, both keeping course and speed, their
 * closest point of approach is nearer than `dcpa` (by more than
 * FW_DIST_RESOLUTION, geom.h: ships on parallel routes exactly `dcpa` apart
 * are not encounters by rounding) and 0 < TCPA < `tcpa`.  One
 * record per pair and episode: an episode opens at the first step the test
 * holds and is classified then (head-on, overtaking or crossing: fw_classify
 * from the smaller id's side, its roles folded into the pair's type, its
 * head-on test the reciprocal-course one, see fw_default_survey_def; with
 * the ships' lanes, fw_classify_lanes: ships meeting along one waterway are
 * head-on); it
 * tracks the smallest distance (centre to centre, and hull to hull when
 * close) and ends when both ships are seen farther
 * apart than range + hysteresis, so one pass is one record.  A ship missing
 * from a step (gone out of the area) keeps its episodes open for max_gap
 * seconds: a short absence is the same pass, a longer one ends it.
 *
 * Cost: close pairs come from a uniform grid of cells as large as
 * range + hysteresis (a pair can only be in the same or a neighbouring cell),
 * so a step costs O(ships + close pairs), not O(ships^2).  Results do not
 * depend on the order of the ships in a step: every pair is evaluated with
 * the lexically smaller id first, and records are sorted by (t_first, ship_a,
 * ship_b).
 *
 * Collision candidates: at an episode's first detection the two ships'
 * straight tracks are extrapolated (fw_hull_cpa); a hull-to-hull closest
 * approach of 0 makes the pair a geometric candidate (Pedersen 1995, IWRAP's
 * N_G, "would collide without aversive manoeuvres"), and the episode's
 * min_hull says how it ended.
 *
 * Exposure: each step's ships count until the next step, so the ship-seconds
 * sum n_k (t_{k+1} - t_k) over the steps.
 *
 * Ships are fw_target records (geom/target.h), the own ship flagged `own`.
 * Frame: metres east/north, navigational headings (0 north, clockwise), SI.
 */
#ifndef FW_SURVEY_H
#define FW_SURVEY_H

#include <stdbool.h>

#include "avoid/encounter.h"
#include "core/error.h"

enum { FW_SURVEY_ID_MAX = FW_TARGET_ID_MAX }; /* room for an id and its NUL */
/* m: hull distances are measured while the hulls are within this of touching
 * (a near miss, 0.1 nm, and more) */
#define FW_SURVEY_HULL_WATCH 400.0

typedef struct fw_survey_def {
    double range;          /* m, 2000: centres closer than this ... */
    double dcpa;           /* m, 1000: ... with a predicted CPA nearer than this ... */
    double tcpa;           /* s, 1000: ... reached in 0 < TCPA < this */
    double hysteresis;     /* m, 500: an episode ends beyond range + hysteresis ... */
    double max_gap;        /* s, 60: ... or when the pair has not been seen for longer */
    fw_colregs_def colregs;/* fw_classify's thresholds; head-on bearing test off (180) */
    bool brute_force;      /* every pair instead of the grid: tests and benchmarks */
    /* optional: a ship's lane (*out NULL: none known; the own ship has
     * none), so that two ships meeting along one waterway are head-on
     * (encounter.h fw_classify_lanes: round a bend, not crossing); NULL: no
     * lanes.  Asked when an episode opens; a failure fails the step. */
    fw_status (*lane)(void *ctx, const fw_target *s, const fw_lane_info **out, fw_error *err);
    void *lane_ctx;
} fw_survey_def;

fw_survey_def fw_default_survey_def(void);

typedef enum fw_survey_type {
    FW_SURVEY_HEAD_ON,     /* rule 14 */
    FW_SURVEY_OVERTAKING,  /* rule 13, either ship's view */
    FW_SURVEY_CROSSING,    /* rule 15, give-way or stand-on */
} fw_survey_type;

enum { FW_SURVEY_NTYPES = 3 };

/* "head-on", "overtaking", "crossing" (the study database's words). */
const char *fw_survey_type_name(fw_survey_type t);

typedef struct fw_survey_record {
    char ship_a[FW_SURVEY_ID_MAX];  /* strcmp(ship_a, ship_b) < 0 */
    char ship_b[FW_SURVEY_ID_MAX];
    fw_survey_type type;            /* at first detection */
    bool own;                       /* one of the pair is the own ship */
    double t_first;                 /* s, first detection */
    double range0, dcpa0, tcpa0;    /* m, m, s at first detection */
    double min_dist, t_min;         /* m, s: smallest centre distance seen, and when */
    double min_hull;                /* m, smallest hull-to-hull distance seen (0: the
                                       hulls touched; INFINITY: never within a
                                       FW_SURVEY_HULL_WATCH of touching) */
    double cand_miss;               /* m, hull-to-hull closest approach of the two
                                       straight tracks from first detection
                                       (geom.h fw_hull_cpa): 0 = a geometric
                                       collision candidate */
    double length_a, breadth_a;     /* m, at first detection */
    double length_b, breadth_b;
} fw_survey_record;

typedef struct fw_survey_totals {
    long steps;
    double ship_s;                  /* ship-seconds in the area */
    int n;                          /* records */
    int by_type[FW_SURVEY_NTYPES];  /* indexed by fw_survey_type */
    int n_own;                      /* records with the own ship */
} fw_survey_totals;

typedef struct fw_survey fw_survey;

/* Checks def (FW_EINPUT: a setting out of range) and starts an empty survey. */
fw_status fw_survey_create(const fw_survey_def *def, fw_survey **out, fw_error *err);
/* The ships in the area at time t (s; strictly later than the previous
 * step).  Ships may come and go between steps.  FW_ERUN on a bad ship
 * (duplicate or empty id, non-finite value), which leaves the survey as it
 * was, or when out of memory (the step then half done). */
fw_status fw_survey_step(fw_survey *sv, double t, const fw_target *ships, int n,
                         fw_error *err);
/* Ends the survey: sorts the records and fills tot (may be NULL).  No step
 * after it; calling it again only refills tot. */
void fw_survey_finish(fw_survey *sv, fw_survey_totals *tot);
/* The records (sorted once finished); valid until fw_survey_destroy. */
const fw_survey_record *fw_survey_records(const fw_survey *sv, int *n);
/* Counts of records by type and own flag (tot->steps and ship_s untouched). */
void fw_survey_count(const fw_survey_record *r, int n, fw_survey_totals *tot);
void fw_survey_destroy(fw_survey *sv);

#endif
