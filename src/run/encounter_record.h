/* encounter_record.h - one encounter record: the table of its fields.
 *
 * An encounter (records.h fw_encounter: what the book kept of one target) is
 * written in three places: a row of the run's encounters.csv, an object in
 * its summary.json, and a row of a study database's encounters table
 * (study/store.c; its CREATE TABLE in study/schema.h).  All three are made
 * from the one table below: a field's name in the run's files, its column in the database,
 * its type, unit, decimals, and how its value is had from the encounter.  The
 * two shapes differ where they always did: the files carry the hull size and
 * the "primary" flag and print the helm unsigned; the database carries the
 * study's verdicts (near miss, closeness, candidate, outcome: fw_enc_verdict), the
 * signed helm (NULL when it never acted) and the COLREGs audit.
 *
 * Numbers in the files are "%.Nf" with the field's decimals (no %g, so the
 * same run gives the same bytes); a nullable field prints null (JSON and CSV)
 * when not finite, as before.  In the database a non-finite number is NULL.
 */
#ifndef FW_RUN_ENCOUNTER_RECORD_H
#define FW_RUN_ENCOUNTER_RECORD_H

#include <stdbool.h>
#include <stdio.h>

#include "run/records.h"

/* What a study judges of an encounter with its own thresholds (outcome.h). */
typedef struct fw_enc_verdict {
    int near_miss;        /* hull to hull below the study's near_miss */
    int near_miss_centre; /* centre to centre below it: a secondary measure */
    double closeness;     /* study/outcome.h fw_closeness of the least hull distance */
    char outcome[16];     /* collision, near miss, domain, passed */
} fw_enc_verdict;

typedef enum fw_enc_type {
    FW_ENC_TEXT,  /* CSV raw, JSON a string, SQL TEXT */
    FW_ENC_REAL,  /* "%.Nf", SQL REAL */
    FW_ENC_FLAG,  /* CSV 0/1, JSON true/false, SQL INTEGER */
    FW_ENC_INT    /* SQL INTEGER (database only) */
} fw_enc_type;

enum {
    FW_ENC_CSV = 1,      /* a column of encounters.csv */
    FW_ENC_JSON = 2,     /* a key of summary.json's encounter objects */
    FW_ENC_SQL = 4,      /* a column of the database's encounters table */
    FW_ENC_NULLABLE = 8, /* files: null when not finite (else printf's inf, nan) */
    FW_ENC_NOT_NULL = 16 /* SQL: NOT NULL */
};

/* A field's value: text, or a number (FLAG and INT: 0, 1, ...), or null. */
typedef struct fw_enc_value {
    bool null;
    double num;
    const char *text;
} fw_enc_value;

typedef struct fw_enc_field {
    const char *name;  /* in encounters.csv and summary.json (NULL: database only) */
    const char *sql;   /* the database's column (NULL: files only) */
    fw_enc_type type;
    const char *unit;  /* "m", "s", "deg", "" */
    int decimals;      /* REAL in the files */
    unsigned flags;    /* FW_ENC_* */
    /* The value: in the files (db false, v NULL) or the database (db true). */
    void (*get)(const fw_encounter *e, const fw_enc_verdict *v, bool db, fw_enc_value *out);
} fw_enc_field;

/* The fields, in the order of the CSV's columns and the database's. */
const fw_enc_field *fw_enc_fields(int *n);
/* The index of a CSV column in encounters.csv (-1: none). */
int fw_enc_csv_column(const char *name);

/* encounters.csv: its header line, one row. */
void fw_enc_csv_header(FILE *f);
void fw_enc_csv_row(FILE *f, const fw_encounter *e);
/* One summary.json encounter object ({...}, one line). */
void fw_enc_json(FILE *f, const fw_encounter *e);

/* The study database's "CREATE TABLE IF NOT EXISTS encounters(...);\n": run_id
 * (the runs' key), then the fields' columns in order, keyed by (run_id,
 * target).  Into buf as snprintf does (the length it needs). */
int fw_enc_sql_table(char *buf, size_t n);

#endif
