/* scn_dnv.h - a DNV maritime-schema traffic situation (v0.2.0) read as a scenario.
 *
 * `fairway run situation.json` runs one of the traffic situations in which
 * test benches share encounters (scenarios/dnv/README.md; DNV's
 * traffic_situation.schema.json).  What is read, every value checked, a
 * problem named by its JSON path with FW_EINPUT (exit 2) before anything runs:
 *
 *   $.version (or $.schemaVersion, which DNV's own generator writes): 0.2.x
 *   $.title, $.description: the scenario's description; its name is the
 *     file's stem (it names the run directory)
 *   $.ownShip, $.targetShips[i] (up to FW_SCN_MAX_TARGETS):
 *     waypoints[k].position {lat, lon}  WGS84 degrees, 2..FW_SCN_MAX_WAYPOINTS
 *     waypoints[k].leg.sog              kn, the leg from waypoint k-1 to k
 *                                       (absent: the leg before's, or initial.sog)
 *     initial {position, sog, cog, heading, navStatus}: all optional; the
 *       ship starts at initial.position (else waypoint 0) and goes to
 *       waypoint 1 at initial.sog (else waypoint 1's leg speed)
 *     static {id (required), name, mmsi, shipType, dimensions {length, width, ...}}
 *   environment {windSpeed m/s, windDirection deg (from), currentSpeed m/s,
 *     currentDirection deg (towards), visibility NM}: a uniform wind and
 *     current and the visibility, as scenario/scn_env.h's environment: (a
 *     speed needs its direction; waves and conditions are read past: no wave
 *     forces, said in run.log when a wave height is given)
 *   fairway {appearS, vanishS, toleranceM, turns} of a target: fairway's own
 *     (run/dnv_situation.h writes them): when it appears and is gone (s),
 *     and the turns it was seen making, [[t_s, heading_deg, sog_kn,
 *     rate_degps, to_deg], ...] in time order (its heading and speed at t,
 *     and from t the rate it turns at until it heads to_deg; rate 0: at
 *     constant velocity; geom/turn.h), checked here and read when the run
 *     is made (fw_scn_dnv_turns)
 *   Other members (turnRadius, cross-track limits ...) are allowed by the
 *   schema and not used.
 *
 * The plane: a transverse Mercator about the own ship's start (geom/geo.h;
 * latitudes beyond +-80 deg refused); true courses become grid courses there.
 *
 * Targets follow their waypoints: straight legs at each leg's speed over
 * ground, and on along the last leg after the last waypoint (the recorded-
 * track source replays them: traffic/source_track.h); their hull is the
 * static dimensions' length x width, centred on the position (DNV's
 * generated files put the reference point amidships, a = b, c = d); they do
 * not give way (behaviour blind: a situation's targets are scripted).
 *
 * The own ship's model is not the situation's: it is fairway's c3-mmg (the
 * C-3 with MMG dynamics), or the ship file given (`--ship`).  The situation
 * gives its start, course and speed; its dimensions are reported, not used
 * (the domain and hull measures are the model's).  With two waypoints it
 * sails the leg from its start towards waypoint 1, continued straight (as a
 * scenario's course and leg); with more (up to FW_ROUTE_MAX_LEGS + 1 from
 * the start) they are its route (avoid/route.h, as own_ship.route: steered
 * leg by leg, each leg's speed ordered).  The scenario's note (run.log) says
 * which.  The run lasts until the own ship would reach its last waypoint or
 * the last target its last, the
 * longer, in steps of 1 s.
 */
#ifndef FW_SCN_DNV_H
#define FW_SCN_DNV_H

#include <stdbool.h>

#include "core/error.h"
#include "core/json_read.h"
#include "scenario/scenario.h"

/* The own ship's model when none is given. */
#define FW_DNV_DEFAULT_SHIP "c3-mmg"

/* Whether path names a JSON file (ends in .json): a DNV situation. */
bool fw_scn_is_dnv(const char *path);

/* Reads and checks the situation at path into s (zeroed first; large:
 * heap-allocate); ship: the own ship's model (a name or a ship file), NULL
 * for FW_DNV_DEFAULT_SHIP. */
fw_status fw_scn_dnv_load(const char *path, const char *ship, fw_scenario *s, fw_error *err);

/* One turn of a target: at t (s) it heads `heading` (rad) at `speed` (m/s)
 * and from then on turns at rate (rad/s; 0: at constant velocity) until it
 * heads `to` (rad). */
typedef struct fw_scn_turn {
    double t, heading, speed, rate, to;
} fw_scn_turn;

/* The turns of a target's fairway member (`fairway` its object, or absent):
 * into out (malloc'd, NULL: only checked), *n of them; FW_EINPUT naming the
 * JSON path of one that is not [t_s >= appear and after the one before,
 * heading_deg 0..360, sog_kn 0..60, rate_degps 0..90, to_deg 0..360]. */
fw_status fw_scn_dnv_read_turns(const fw_jnode *fairway, double appear, fw_scn_turn **out,
                                int *n, fw_error *err);

/* The turns of target i (0, 1, ... in $.targetShips) of the situation at
 * path, read again (its route's `turns` says it has some). */
fw_status fw_scn_dnv_turns(const char *path, int i, fw_scn_turn **out, int *n, fw_error *err);

#endif
