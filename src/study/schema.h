/* schema.h - the SQLite schema of a study database (fairway sweep writes it,
 * fairway report and analysis/ read it).
 *
 * One row in `runs` per (domain size and shape, density, behaviour, setting of
 * the study's axes, replication) of the study's run list; a run and all its rows are committed in one transaction, so a run is
 * either wholly in the database or not at all.  Units are in the column names
 * (m, s, deg); flags are 0/1.  `meta` holds the study's settings as text
 * (schema_version, study_name, study_file, study_digest, scenario, duration_s,
 * near_miss_m, survey_range_m, survey_dcpa_m, survey_tcpa_s, ...).
 *
 * Own-ship encounters use fairway's situation names (fw_situation_name):
 * "head-on", "overtaking", "being overtaken", "crossing give-way",
 * "crossing stand-on".  Traffic-level encounters (all pairs of ships in the
 * survey area, the own ship included and flagged) use "head-on", "overtaking",
 * "crossing".
 *
 * Distances: min_dist_m are centre to centre (the paper's and the domain's
 * measure), min_hull_m hull to hull (the rectangles' closest points; 0 when
 * they touched).  near_miss is hull to hull below the study's near_miss_m
 * (schema 4; in schema 3 it was centre to centre, which for the 333 m own
 * ship left a 9.9 m pass between the hulls "no near miss");
 * near_miss_centre keeps the centre-to-centre reading as a named secondary
 * measure.  closeness (study/outcome.h fw_closeness) is 1 - min_hull_m /
 * 1852 m, 1 at contact and 0 when no hull came within 1 nm: continuous, the
 * score a rare-event method climbs.
 *
 * Collision candidates (candidate, cand_miss_m, outcome): an encounter is a
 * geometric candidate when both ships' straight tracks from its first
 * detection (own ship: the radar's first sight; traffic pair: the survey's
 * first detection) bring the hulls into contact (cand_miss_m = 0), the per
 * encounter form of Pedersen's (1995) and IWRAP's N_G, "would collide if no
 * aversive manoeuvre were made".  outcome is the worst that happened:
 * collision (hulls touched), near miss (hull to hull below near_miss_m),
 * domain (own domain entered; own-ship encounters), passed.  The measured
 * causation factor of a type is collisions among its candidates / candidates.
 *
 * The COLREGs audit (audit/audit.h; thresholds in meta audit_*): rule (13,
 * 14, 15) and role (give-way, stand-on) from the situation at first
 * detection; t_risk_s / tcpa_risk_s when risk of collision first existed;
 * tcpa_act_s the TCPA at the own ship's first action for it, whose largest
 * course change and speed reduction (fraction) up to the CPA follow; early,
 * substantial (rules 8, 16); rule17_phase of a stand-on action (1 keep, 2
 * may, 3 must; 0 none); compliant 1/0 and audit_note saying why not.
 *
 * Schema 5 added the splits table and runs.setting (a study's `axes:`, study.h:
 * "sensing.visibility_nm=1, ..."; NULL for a study without axes).
 *
 * Exposure: the own ship sails sim_s seconds per run; traffic_ship_s is the
 * sum over steps of the ships in the survey area times the step (ship-seconds).
 */
#ifndef FW_STUDY_SCHEMA_H
#define FW_STUDY_SCHEMA_H

#include <stdio.h>

#include "run/encounter_record.h"

#define FW_SCHEMA_VERSION "5"

#define FW_SCHEMA_SQL_RUNS                                                              \
    "CREATE TABLE IF NOT EXISTS meta(\n"                                                \
    "  key TEXT PRIMARY KEY,\n"                                                         \
    "  value TEXT NOT NULL);\n"                                                         \
    "CREATE TABLE IF NOT EXISTS runs(\n"                                                \
    "  run_id INTEGER PRIMARY KEY,\n"    /* index in the study's run list */            \
    "  domain_m REAL NOT NULL,\n"        /* transverse semi-axis of the domain */       \
    "  fore_aft_ratio REAL,\n"           /* its shape: fore-aft / transverse semi-axis */ \
    "  density REAL NOT NULL,\n"         /* demand scale of the network */              \
    "  replication INTEGER NOT NULL,\n"  /* 0-based; same traffic for every domain */   \
    "  seed INTEGER NOT NULL,\n"         /* SUMO and demand seed of the replication */  \
    "  status TEXT NOT NULL CHECK(status IN ('ok','failed')),\n"                        \
    "  reason TEXT NOT NULL DEFAULT '',\n" /* why it failed */                          \
    "  sim_s REAL,\n"                    /* simulated time */                           \
    "  wall_s REAL,\n"                   /* wall-clock time of the run */               \
    "  sumo_s REAL,\n"                   /* of which inside SUMO's step */              \
    "  n_encounters INTEGER,\n"                                                         \
    "  n_actions INTEGER,\n"             /* avoidance manoeuvres begun */               \
    "  min_dist_m REAL,\n"               /* NULL: no target met */                      \
    "  domain_entered INTEGER,\n"                                                       \
    "  near_miss INTEGER,\n"             /* hull to hull below near_miss_m */            \
    "  near_miss_centre INTEGER,\n"      /* centre to centre below it (secondary) */     \
    "  collision INTEGER,\n"                                                            \
    "  colregs_ok INTEGER,\n"                                                           \
    "  max_helm_deg REAL,\n"                                                            \
    "  path_length_m REAL,\n"                                                           \
    "  path_lengthening_m REAL,\n"                                                      \
    "  time_lost_s REAL,\n"                                                             \
    "  rudder_work_deg_s REAL,\n"                                                       \
    "  helm_orders INTEGER,\n"                                                          \
    "  traffic_ship_s REAL,\n"                                                          \
    "  behaviour TEXT,\n"                /* the background ships': colregs or blind */    \
    "  give_way INTEGER,\n"              /* their speed orders (world/reactions.h) */     \
    "  give_way_short INTEGER,\n"        /* of which no speed kept the passing distance */\
    "  mon_sideways INTEGER,\n"          /* the traffic monitors (survey/monitor.h): */   \
    "  mon_teleport INTEGER,\n"          /* what no ship can do, among the ships the */   \
    "  mon_overlap INTEGER,\n"           /* own ship saw; zero for traffic that */        \
    "  mon_appear INTEGER,\n"            /* behaves like ships */                         \
    "  mon_vanish INTEGER,\n"                                                           \
    "  mon_start_close INTEGER,\n"                                                      \
    "  mon_stopped INTEGER,\n"                                                          \
    "  max_lateral_mps REAL,\n"                                                         \
    "  min_hull_m REAL,\n"               /* hull to hull; NULL: none within 1 nm */      \
    "  closeness REAL,\n"                /* 1 - min_hull_m / 1852, 0 beyond 1 nm */      \
    "  setting TEXT,\n"                  /* the axes' values, "key=v, ..."; NULL: none */  \
    "  UNIQUE(domain_m, fore_aft_ratio, density, behaviour, replication, setting));\n"

/* The encounters table: made from the encounter record's field table
 * (run/encounter_record.h fw_enc_sql_table): target, target_type, situation;
 * t_detect_s, dcpa0_m, tcpa0_s; threat, acted; t_act_s, act_side,
 * act_helm_deg (signed, + starboard; NULL: never acted); min_dist_m, t_min_s,
 * min_lambda; domain_entered, near_miss (hull to hull), near_miss_centre,
 * collision, colregs_ok; min_hull_m (hull to hull; NULL: never within 1 nm),
 * closeness; candidate, cand_miss_m (hull to
 * hull on the straight tracks), outcome (collision, near miss, domain,
 * passed); the COLREGs audit (below): rule, role, t_risk_s, tcpa_risk_s,
 * tcpa_act_s, course_change_deg, speed_change, early, substantial,
 * rule17_phase, compliant (NULL: not audited, no risk of collision),
 * audit_note.  Keyed by (run_id, target). */

#define FW_SCHEMA_SQL_TRAFFIC                                                           \
    "CREATE TABLE IF NOT EXISTS traffic_encounters(\n"                                  \
    "  run_id INTEGER NOT NULL REFERENCES runs(run_id),\n"                              \
    "  ship_a TEXT NOT NULL, ship_b TEXT NOT NULL,\n" /* ship_a < ship_b */             \
    "  type TEXT NOT NULL,\n"            /* head-on, overtaking, crossing */            \
    "  own INTEGER NOT NULL,\n"          /* one of the pair is the own ship */          \
    "  t_first_s REAL NOT NULL, range0_m REAL, dcpa0_m REAL, tcpa0_s REAL,\n"           \
    "  min_dist_m REAL, t_min_s REAL,\n"                                                \
    "  min_hull_m REAL,\n"               /* hull to hull; NULL: never within 400 m */    \
    "  candidate INTEGER,\n"                                                             \
    "  cand_miss_m REAL,\n"                                                              \
    "  outcome TEXT,\n"                  /* collision, near miss, passed */              \
    "  PRIMARY KEY(run_id, ship_a, ship_b, t_first_s));\n"

/* The splitting estimates (a study with estimate:, study/split_run.h): one
 * row per cell and batch, each an independent estimate of the probability
 * that a run of that cell has a collision (hulls touch) and a near miss (hull
 * to hull below the study's near_miss_m) within duration_s.  best_path is
 * the closest trajectory the batch found, replayable: "draw:STEP/B,STEP/B"
 * (its start's draw and its re-keyings, split_run.h). */
#define FW_SCHEMA_SQL_SPLITS                                                            \
    "CREATE TABLE IF NOT EXISTS splits(\n"                                              \
    "  cell INTEGER NOT NULL,\n"         /* the cell's run of replication 0 */          \
    "  batch INTEGER NOT NULL,\n"                                                       \
    "  domain_m REAL NOT NULL, fore_aft_ratio REAL, density REAL NOT NULL,\n"           \
    "  behaviour TEXT,\n"                                                               \
    "  setting TEXT,\n"                  /* the axes' values, as runs.setting */         \
    "  particles INTEGER NOT NULL,\n"                                                   \
    "  status TEXT NOT NULL CHECK(status IN ('ok','failed')),\n"                        \
    "  reason TEXT NOT NULL DEFAULT '',\n"                                              \
    "  rounds INTEGER,\n"                /* levels climbed */                           \
    "  runs REAL,\n"                     /* trajectories simulated (replays included) */\
    "  sim_s REAL,\n"                    /* their simulated time */                     \
    "  wall_s REAL,\n"                                                                  \
    "  p_collision REAL,\n"              /* the estimates */                            \
    "  p_near_miss REAL,\n"                                                             \
    "  best_closeness REAL,\n"                                                          \
    "  best_path TEXT,\n"                                                               \
    "  PRIMARY KEY(cell, batch));\n"

/* The whole schema into buf, as snprintf (returns the length it needs). */
static inline int fw_schema_sql(char *buf, size_t n)
{
    int a = snprintf(buf, n, "%s", FW_SCHEMA_SQL_RUNS);
    size_t k = (size_t)a < n ? (size_t)a : n;
    a += fw_enc_sql_table(buf + k, n - k);
    k = (size_t)a < n ? (size_t)a : n;
    return a + snprintf(buf + k, n - k, "%s%s", FW_SCHEMA_SQL_TRAFFIC, FW_SCHEMA_SQL_SPLITS);
}

#endif
