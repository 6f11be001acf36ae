/* db_check.h - a study database checked before anything is read from it.
 *
 * fairway report and fairway worst print what a database says as results, so a
 * damaged or tampered one (a negative rate, -inf, text where a number belongs,
 * a domain of 0 m, a replication the study never had, a flag of 2) must be
 * refused rather than summed: -inf summed into a count is undefined behaviour
 * (llround), the rest are wrong numbers printed with exit 0.
 *
 * One pass over every row of runs, encounters and traffic_encounters, each
 * value against its column's rule: of the right type (a number is stored as a
 * number: text such as 'abc' or 'NaN' in a REAL column is refused, not read
 * as 0), finite, in range (distances, exposures and counts >= 0, the domain
 * > 0, counts integers below 1e9 so sums stay exact, flags 0/1, the
 * replication below meta's replications, a run id below meta's runs), NOT
 * NULL where the schema says so,
 * and the names the report counts by (situation, traffic type, outcome) among
 * the ones it knows; texts without control characters (an escape sequence
 * would reach the terminal, a line break split a message; a failed run's
 * reason may have line breaks); a run's seed 1 to 2^31 - 2 (study.c), its
 * largest helm 0 to 90 deg, its simulated time at most meta's duration_s.
 * Every row of meta too: the numbers the sweep writes there (store.c) as
 * numbers in their ranges (replications, runs and seed whole; duration,
 * step, ranges above 0; domains_m and the other levels lists of numbers),
 * the study name not empty, every value without control characters (the
 * study's description may have line breaks): the report prints them.
 * The rules for encounters come from the encounter field table
 * (run/encounter_record.h: type and unit), the others from a column table in
 * db_check.c; a column the table does not name is not checked (an older or
 * newer writer's extra), a named one the database lacks is skipped (the
 * readers say what they miss).  Not checked here: relations between rows
 * (runs.n_encounters against the rows: report warns; encounters of a run that
 * is not in runs: skipped), relations between columns (t_min_s after
 * t_detect_s, min_hull_m <= min_dist_m), other names (behaviour, role,
 * act_side, target_type) and meta's other texts beyond control characters.
 *
 * The first bad value fails with FW_EINPUT:
 *   "FILE: table encounters, row 17 (run dover-000003), column min_hull_m: -inf is not a distance"
 *   "FILE: table meta, row 23 (key duration_s), column value: '-5' is not a duration (...)"
 * (row: SQLite's rowid; run: meta's study_name and the run_id, as the sweep
 * names its runs).
 */
#ifndef FW_STUDY_DB_CHECK_H
#define FW_STUDY_DB_CHECK_H

#include <sqlite3.h>

#include "core/error.h"

fw_status fw_db_check(sqlite3 *db, const char *file, fw_error *err);

#endif
