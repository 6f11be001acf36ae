/* monitor.h - what no ship can do, counted in every run: the traffic monitors.
 *
 * A study is only as good as its traffic.  Every step the monitors look at
 * every ship the own ship sees and count what real ships do not do:
 *
 *   sideways     moving sideways (across its own heading) faster than
 *                lateral_max: a lane change done in one step (one per episode)
 *   teleport     a step's displacement beyond what its speed allows
 *                (jump_factor x speed x dt + jump_slack), mostly along its
 *                heading (a jump mostly across it counts as sideways)
 *   overlap      two background ships whose hull rectangles overlap (one
 *                per pair and episode; the own ship's contacts are the
 *                encounter book's)
 *   appear       a ship first seen (after t = 0) within close_range of the own
 *                ship; start_close: one there at t = 0
 *   vanish       a ship no longer seen that was within close_range when last
 *                seen
 *   stopped      a ship slower than stop_speed for stop_time (one per episode)
 *
 * Each event is written to the log (time, kind, ships, where) and counted.
 * Frame: fw_target records (hull centre; the heading orients the hull and
 * the sideways check), SI.
 */
#ifndef FW_MONITOR_H
#define FW_MONITOR_H

#include <stdio.h>

#include "core/error.h"
#include "geom/target.h"

typedef struct fw_monitor_def {
    double lateral_max;  /* m/s, 2: more than twice what a ship's lane change needs */
    double jump_factor;  /* 3 */
    double jump_slack;   /* m, 10 */
    double close_range;  /* m, 2 nm */
    double stop_speed;   /* m/s, 0.5 kn */
    double stop_time;    /* s, 60 */
} fw_monitor_def;

fw_monitor_def fw_default_monitor_def(void);

typedef struct fw_monitor_counts {
    int sideways, teleport, overlap, appear, start_close, vanish, stopped;
    double max_lateral;  /* m/s, the largest sideways speed seen */
} fw_monitor_counts;

/* All counts summed (max_lateral left out): zero for traffic that behaves. */
int fw_monitor_total(const fw_monitor_counts *c);

typedef struct fw_monitor fw_monitor;

fw_status fw_monitor_create(const fw_monitor_def *def, FILE *log, fw_monitor **out,
                            fw_error *err);
void fw_monitor_destroy(fw_monitor *m);

/* The ships seen at time t (steps strictly later each call, ids unique), and
 * the own ship. */
fw_status fw_monitor_step(fw_monitor *m, double t, const fw_target *own, const fw_target *ships,
                          int n, fw_error *err);

const fw_monitor_counts *fw_monitor_counts_of(const fw_monitor *m);

#endif
