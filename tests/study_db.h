/* study_db.h - synthetic study databases for the report tests.
 *
 * Built with the real schema (fw_schema_sql), so a change of the contract
 * shows up here.  The hand database's report numbers are worked out in
 * test_report.c; the random one is a plausible study for the plots and the
 * command-line tests (make_study_db writes any of them to a file).
 */
#ifndef FW_TEST_STUDY_DB_H
#define FW_TEST_STUDY_DB_H

#include <sqlite3.h>

/* Creates path (replacing it) with the schema and meta(schema_version). */
sqlite3 *sdb_create(const char *path, const char *schema_version);
/* printf-style SQL; returns 0 ok, else prints the error and returns -1. */
/* (sqlite3_mprintf formats: %q quotes a string, so no printf attribute) */
int sdb_exec(sqlite3 *db, const char *fmt, ...);

/* 3 replications x domains 100 and 500 m, density 1, plus one failed run. */
int sdb_hand(const char *path);
/* 4 domain sizes x 2 densities x 6 replications with random encounters and
 * traffic, and two failed runs. */
int sdb_random(const char *path, unsigned long long seed);
/* 20 one-hour runs at each of 100 and 300 m, one crossing give-way encounter
 * in each and no other event: the zero counts' exact intervals. */
int sdb_zeros(const char *path);
/* Two runs, both failed. */
int sdb_only_failed(const char *path);

#endif
