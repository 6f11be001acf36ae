/* study.h - a Monte Carlo study: a base scenario, the domain sizes, densities,
 * background behaviours and replications to sweep, and the run list they make.
 *
 * Common random numbers: replication i has one seed (SUMO's and the demand's)
 * and one own-ship start for every domain size, behaviour and density, so
 * differences between domain sizes, shapes and behaviours are paired.  The
 * run list is ordered replication-major (all domains of shape 0 and
 * behaviour 0 of replication 0, then of shape 1, ..., then behaviour 1, then
 * replication 1, ...; densities, then the settings of `axes:`, are the
 * outermost blocks), so
 * a sweep cut short still holds complete paired sets.  run_id is the index in
 * that list; with one shape and one behaviour it is the list of a study
 * without those axes.
 *
 * A study file (YAML, units in the key names; errors "FILE:LINE: FIELD: ..."):
 *
 *   name: strait-domain
 *   scenario: ../traffic/strait-crossing.yaml  # relative to the study file
 *   replications: 10
 *   seed: 1
 *   domains_m: [150, 300, 600, 1000]   # or domains_l: [0.5, 1, 2] in own-ship lengths
 *   fore_aft_ratios: [1, 2.5]    # optional: the domain's shape (fore-aft / transverse
 *                                # semi-axis; Fujii and Tanaka's 8 L x 3.2 L is 2.5)
 *   densities: [1, 2]            # optional: the scenario's density
 *   behaviours: [colregs, blind] # optional: the scenario's traffic.behaviour
 *   duration_s: 3600             # optional: the scenario's duration
 *   start: {along_m: 1000, across_m: 300}  # optional: own-ship start spread
 *   # over recorded traffic (a scenario with traffic: ais:) also in time: each
 *   # replication's AIS window starts 0 to time_s later (its ships do not react:
 *   # no behaviours or densities; replications need some spread to differ)
 *   start: {time_s: 43200, along_m: 1000}
 *   encounter_m: 1852            # optional: a target passing closer is an encounter
 *   near_miss_m: 185.2           # optional: hulls closer than this (hull to hull) are a near miss
 *   axes:                        # optional: any other scenario key, swept
 *     sensing.visibility_nm: [10, 1]   # a dotted key of the scenario file: values
 *     watchkeeping.lapse: [0, 0.05]    # laid over it (scenario.h fw_scenario_load_with)
 *                                # every combination is a setting (the last axis fastest),
 *                                # checked by the scenario's own reader; keys the study
 *                                # sweeps or holds fixed itself (density, behaviour,
 *                                # domain, seed, duration, ship, network) are refused
 *   estimate: {method: splitting, particles: 50, batches: 8, seed: 1}
 *                                # optional: besides the runs, each cell's probability
 *                                # of a collision and of a near miss within duration_s
 *                                # by adaptive multilevel splitting (study/split_run.h);
 *                                # the scenario must have randomness after t = 0
 *   audit: {risk_dcpa_m: 926, risk_tcpa_s: 1200, course_change_deg: 30,
 *           speed_change: 0.25, early_tcpa_s: 480, prompt_s: 60, rule17_may_tcpa_s: 600,
 *           rule17_must_tcpa_s: 240}  # optional: the COLREGs audit (audit/audit.h)
 */
#ifndef FW_STUDY_H
#define FW_STUDY_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "core/hash.h"
#include "scenario/scenario.h"

#define FW_STUDY_MAX_LEVELS 32
#define FW_STUDY_MAX_INPUTS 12
#define FW_STUDY_MAX_BEHAVIOURS 2
#define FW_STUDY_MAX_AXES 4
#define FW_STUDY_MAX_AXIS_LEVELS 8
#define FW_STUDY_MAX_SETTINGS 16

/* One file a run of the study reads, and the digest of its bytes: a resumed
 * sweep refuses when any of them changed, naming it. */
typedef struct fw_study_input {
    const char *role;  /* "study", "scenario", "ship", "demand", ... (static text) */
    char path[1024];
    uint64_t digest;
} fw_study_input;

/* A study's splitting estimate (estimate:): `batches` independent
 * estimates of `particles` trajectories per cell of the study (domain size,
 * shape, density, behaviour), each from a seed of its own that every cell
 * shares (common random numbers: the cells' batch b draw the same starts). */
typedef struct fw_study_estimate {
    bool on;
    int particles;
    int batches;
    unsigned long seed;
} fw_study_estimate;

/* One axis of `axes:`: a dotted scenario key and the values it takes (YAML
 * scalars as written). */
typedef struct fw_study_axis {
    char key[64];
    int n;
    char values[FW_STUDY_MAX_AXIS_LEVELS][32];
    int line;                /* of the key in the study file */
    int value_line[FW_STUDY_MAX_AXIS_LEVELS];
} fw_study_axis;

typedef struct fw_study {
    char file[512];
    char name[64];
    char description[256];
    char scenario_file[1024];
    fw_scenario base;        /* the loaded base scenario */
    int replications;
    unsigned long seed;
    int n_domains;
    double domains[FW_STUDY_MAX_LEVELS];   /* m */
    int n_densities;
    double densities[FW_STUDY_MAX_LEVELS];
    bool domains_in_lengths; /* the file gave domains_l (domains[] is metres all the same) */
    double domain_lengths[FW_STUDY_MAX_LEVELS]; /* own-ship lengths, when it did */
    int n_ratios;            /* fore-aft ratios of the domain; 1 when not swept */
    double ratios[FW_STUDY_MAX_LEVELS];
    int n_behaviours;        /* 1 when the study does not sweep them */
    fw_behaviour behaviours[FW_STUDY_MAX_BEHAVIOURS];
    double duration;         /* s */
    double start_along;      /* m, uniform spread of the start along the course */
    double start_across;     /* m, and across it */
    double start_time;       /* s, spread of the AIS window's start (0..start_time) */
    double encounter_range;  /* m */
    double near_miss;        /* m, hull to hull (the centre-to-centre reading is secondary) */
    fw_study_estimate estimate;
    int n_axes;              /* 0: no axes: */
    int n_settings;          /* 1, and every run sails `base` */
    fw_study_axis axes[FW_STUDY_MAX_AXES];
    /* with axes, setting k's scenario (the base file with the axes' values
     * of combination k laid over it); unused without */
    fw_scenario settings[FW_STUDY_MAX_SETTINGS];
    uint64_t digest;         /* of the settings and the scenario file: resume guard */
    int n_inputs;            /* every file a run reads: study, scenario, ship, network */
    fw_study_input inputs[FW_STUDY_MAX_INPUTS];
} fw_study;

typedef struct fw_study_run {
    int run_id;
    int replication;
    int domain_index, density_index, behaviour_index, ratio_index;
    int setting_index;       /* the combination of the axes' values; 0 without axes */
    double domain;           /* m */
    double ratio;            /* fore-aft / transverse semi-axis */
    double density;
    fw_behaviour behaviour;  /* of the background ships */
    unsigned long seed;
    double d_along, d_across; /* m, start offset of this replication */
    double d_time;            /* s, its AIS window's later start (recorded traffic) */
} fw_study_run;

/* Loads and checks path (and the scenario it names).  s is large: callers
 * heap-allocate it. */
fw_status fw_study_load(const char *path, fw_study *s, fw_error *err);

int fw_study_run_count(const fw_study *s);
/* Run run_id (0 <= run_id < fw_study_run_count). */
fw_study_run fw_study_run_at(const fw_study *s, int run_id);
/* The scenario of one run: the base with the run's domain size and shape,
 * density, behaviour, seed, duration and start, named "<study>-<run_id>". */
void fw_study_scenario(const fw_study *s, const fw_study_run *r, fw_scenario *out);

/* "key=value, key=value" of setting k (0 <= k < n_settings); "" without axes. */
const char *fw_study_setting_label(const fw_study *s, int k, char *buf, size_t n);

/* Cells: the study's settings without the replications, numbered as the
 * runs of replication 0 (cell c is the c-th such run). */
int fw_study_cell_count(const fw_study *s);
fw_study_run fw_study_cell(const fw_study *s, int cell);
/* Cell `cell` with its seed and start drawn from `draw` as a replication's
 * are from its index: a splitting start (study/split_run.h). */
fw_study_run fw_study_run_drawn(const fw_study *s, int cell, uint64_t draw);

#endif
