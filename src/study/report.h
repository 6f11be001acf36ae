/* report.h - fairway report: the statistics of a finished study database.
 *
 * Reads a study database (schema.h) read-only, takes the runs with status ok,
 * and for each (density, domain size) computes per-replication rates, their
 * means with 95% intervals across replications, pooled CPA percentiles, and
 * paired differences against a reference domain size (replication i of every
 * domain sailed the same traffic).  The report directory holds CSV tables, the
 * PNGs drawn by analysis/plot_study.py and a one-page report.md; it is written
 * beside its final place and renamed into it, so a failed report leaves
 * nothing partial behind.
 *
 *   fw_study_report_def def = fw_default_study_report_def();
 *   def.db = "study.db";
 *   fw_study_report *rep;
 *   if (fw_study_report_load(&def, &rep, &err) == FW_OK) {
 *       fw_study_report_write(rep, &def, &res, &err);
 *       fw_study_report_free(rep);
 *   }
 */
#ifndef FW_STUDY_REPORT_H
#define FW_STUDY_REPORT_H

#include <stdbool.h>
#include <stdio.h>

#include "core/error.h"

typedef struct fw_study_report_def {
    const char *db;       /* the study database */
    const char *out;      /* report directory; NULL: <db stem>-report beside the database */
    double reference_m;   /* domain size the others are compared with; NAN: the smallest */
    double level;         /* confidence level of every interval (0.95) */
    bool plots;           /* draw the PNGs with analysis/plot_study.py */
    const char *python;   /* NULL: $FAIRWAY_PYTHON, else /usr/bin/python3 */
    const char *script;   /* NULL: <data root>/analysis/plot_study.py */
} fw_study_report_def;

fw_study_report_def fw_default_study_report_def(void);

typedef enum fw_plot_state { FW_PLOTS_SKIPPED, FW_PLOTS_DRAWN, FW_PLOTS_FAILED } fw_plot_state;

typedef struct fw_study_report_result {
    char out[1024];       /* the report directory written */
    fw_plot_state plots;
    char plot_msg[512];   /* why plotting failed */
} fw_study_report_result;

/* The loaded runs and every statistic of the report (report_data.h). */
typedef struct fw_study_report fw_study_report;

/* Opens def->db, checks it is a fairway study database of this schema version
 * and that it has finished runs, and computes the statistics.  FW_EINPUT with
 * a message naming the file when it is not usable. */
fw_status fw_study_report_load(const fw_study_report_def *def, fw_study_report **out,
                               fw_error *err);

/* Writes the report directory.  FW_ERUN if plotting failed: the CSVs and
 * report.md are still written (report.md says so); res->plots tells. */
fw_status fw_study_report_write(const fw_study_report *rep, const fw_study_report_def *def,
                                fw_study_report_result *res, fw_error *err);

/* The key measures per setting as a text table, or everything as one JSON object. */
void fw_study_report_print(FILE *f, const fw_study_report *rep, const fw_study_report_result *res,
                           bool json);

void fw_study_report_free(fw_study_report *rep);

#endif
