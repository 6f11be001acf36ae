/* dnv_situation.h - fairway's encounters written as DNV traffic situations.
 *
 * A scenario's own ship and its targets' tracks become a maritime-schema
 * 0.2.0 traffic situation (scenarios/dnv/traffic_situation.schema.json),
 * which fairway reads back (scenario/scn_dnv.h) and other test benches run:
 *
 *   ownShip      initial position (the start), sog, cog, heading; waypoints:
 *                the start and the end of the planned leg (at least the
 *                distance sailed in the run's duration), the leg's sog;
 *                static: id 1, the model's name, length and breadth
 *   targetShips  one per track, static.id 2, 3, ... (fairway's id in
 *                static.name), shipType from fairway's label (Cargo unless it
 *                names a passenger ship, tanker, tug, fishing vessel ...),
 *                its length and breadth; waypoints: its track simplified
 *                (below), each leg's sog the leg's length over its time
 *   startTime    the scenario's (2000-01-01T00:00:00Z when it has none)
 *   fairway      fairway's own member (the schema allows more; others ignore
 *                it): durationS, domainM, foreAftRatio, so that fairway reads
 *                the run back as it was (its other settings are its defaults)
 *
 * Tracks are simplified with the synchronised Douglas-Peucker rule: a point
 * is dropped only while the straight legs at constant speed between the
 * waypoints kept put the ship within `tolerance` metres of every recorded
 * point at the point's time; so the waypoints keep both path and timing (a
 * track that would keep more than a reader holds, FW_SCN_MAX_WAYPOINTS, is
 * simplified at twice the tolerance, again until it fits, and says so:
 * `"fairway": {"toleranceM": T}`).  A
 * situation has no time at which a ship appears or leaves: a track that
 * begins after t = 0 (a ship that came into sight or onto the network) or
 * ends before the run's end (one that left) gets fairway's own member
 * `"fairway": {"appearS": T0, "vanishS": T1}` (the schema allows more
 * members; scenario/scn_dnv.h reads it; other test benches will have the ship
 * there all the time); a track there to the end goes on along its last leg
 * to the scenario's duration (the reader extends it beyond).  Where the
 * waypoints alone would not give the course and speed the own ship saw (a
 * leg is a chord at its mean speed), the track's motion is kept in
 * `"fairway": {"turns": [[T, HEADING_DEG, SOG_KN, RATE_DEGPS, TO_DEG], ...]}`
 * (RATE 0: at constant velocity from T): at every point of a turn the ship
 * was seen making (traffic/source_track.h: a ship the traffic steered,
 * geom/turn.h) and where one ends, and wherever its recorded course or speed
 * differs by more than 0.01 deg or 0.01 kn from what the reader has then
 * (the leg's, or the entry before: a ship slowing along a leg, a lane
 * change's crab), so that the own ship read back expects of it what the
 * run's did (at AIS's 0.1 deg and 0.1 kn, worst_replay's own ship ended
 * 13.8 m off the replay; at 0.01, 0.014 m).
 *
 * Positions: a scenario with an origin is written in its plane's latitude
 * and longitude; one without (a network's plane) is placed with its (0, 0)
 * at latitude 0, longitude 0, where grid north is true north.
 */
#ifndef FW_RUN_DNV_SITUATION_H
#define FW_RUN_DNV_SITUATION_H

#include <stdio.h>

#include "core/error.h"
#include "scenario/scenario.h"
#include "traffic/source_track.h"

/* m: what the simplification keeps every recorded point within */
#define FW_DNV_TOLERANCE_M 0.25

/* Writes the situation of s's own ship and tracks[0..n-1] (points in any
 * order, times from 0) to path (whole or not at all). */
fw_status fw_dnv_situation_write(const fw_scenario *s, const fw_rec_track *tracks, int n,
                                 double tolerance, const char *path, fw_error *err);

/* "position": {"lat": .., "lon": ..} of plane point (e, n) with digits
 * decimals; *gamma (may be NULL): the meridian convergence there (rad, grid
 * north minus true north).  Shared with run/dnv_out.h. */
typedef struct fw_geo fw_geo;
fw_status fw_dnv_position(FILE *f, const fw_geo *g, double e, double n, int digits,
                          double *gamma, fw_error *err);

/* The same of a scenario with explicit targets (constant velocity over its
 * duration: the Imazu and paper cases). */
fw_status fw_dnv_situation_of_scenario(const fw_scenario *s, const char *path, fw_error *err);

#endif
