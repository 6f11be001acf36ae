/* source_sumo_internal.h - what source_sumo.c (the source) shares with
 * source_sumo_files.c (the files SUMO loads). */
#ifndef FW_SOURCE_SUMO_INTERNAL_H
#define FW_SOURCE_SUMO_INTERNAL_H

#include <stdbool.h>

#include "traffic/source_sumo.h"

/* The vType prefix of explicit targets: their lanes allow custom1 only. */
#define TARGET_TYPE_PREFIX "fw_t_"

/* The files SUMO loads, written and built into d->dir. */
typedef struct sumo_files {
    char net[1200], routes[2600], types[1100];
    bool has_types;
    double lane_change_s; /* the network's (0: the default) */
} sumo_files;

/* Writes the run's files into d->dir (the network found, the paths checked
 * for the commas SUMO's lists cannot hold) and names them in *f. */
fw_status fw_sumo_prepare(const fw_sumo_source_def *d, sumo_files *f, fw_error *err);

#endif
