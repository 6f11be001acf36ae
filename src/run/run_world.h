/* run_world.h - a run's world from its scenario (run.c's set-up; run_world.c).
 *
 * The traffic source the scenario asks for (recorded tracks, AIS reports
 * replayed, the kinematic source for explicit targets, or SUMO, whose files go
 * into the run directory's sumo/) in a world of the scenario's step and
 * reactions, and the own ship "fw_own" in it: MMG (or the Nomoto plant) under
 * the scenario's avoidance policy or def->controller.  Internal to src/run.
 */
#ifndef FW_RUN_WORLD_H
#define FW_RUN_WORLD_H

#include "ais/ais_track.h"
#include "run/run.h"

/* def->controller is taken over: held by the world, or destroyed if the world
 * is not made.  On failure *w may hold a world for the caller to destroy.
 * With AIS traffic, *ais gets what the reading counted (ais_track.h; its
 * arrays NULL), for run.log and summary.json; else it is zeroed. */
fw_status fw_run_make_world(const fw_run_def *def, fw_world **w, fw_vessel **own,
                            fw_ais_tracks *ais, fw_error *err);

#endif
