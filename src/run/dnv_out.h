/* dnv_out.h - a run's answer in DNV's situation output (maritime-schema 0.2.0).
 *
 * A run of a DNV traffic situation (scenario/scn_dnv.h) writes
 * situation_output.json into its directory, valid against
 * scenarios/dnv/situation_output.schema.json:
 *
 *   version          "0.2.0"
 *   systemUnderTest.configuration  name "fairway", vendor, version (fairway's),
 *                    and fairway's settings: the own ship's model, dynamics,
 *                    domain, helm range, horizon, action range, return mode
 *   systemUnderTest.eventData      one event at t = 0 and at every decision
 *                    that changed the plan (an avoidance started: the policy
 *                    acted, or its mode changed: standby, avoid, steady,
 *                    autopilot, avoid/policy.h):
 *     time         the situation's startTime (else 2000-01-01T00:00:00Z)
 *                  plus the run's time, ISO 8601 UTC
 *     waypoints    the planned route from the own ship's position: in avoid,
 *                  the predicted track of the helm ordered (Nomoto, the
 *                  policy's own predictor, nomoto/track.h) over the policy's
 *                  horizon, a waypoint a minute; in steady, straight on the
 *                  present heading over the horizon; then (and in standby and
 *                  autopilot directly) the end of the planned leg; leg.sog
 *                  the speed between waypoints, kn
 *     ownShip      position, sog, cog, heading (true, degrees)
 *     targetShips  every target there: id, position, sog, cog, heading,
 *                  cpa (nm), tcpa (s), range (nm), encounterType (fairway's
 *                  classes as the schema names them; "No Risk" when keeping
 *                  course and speed would not bring it into the domain)
 *     fairway      mode, helm (deg, + starboard) and the policy's reason:
 *                  the schema allows more members
 *
 * The schema's simulator output (an Apache Arrow IPC file in a .marzip) is
 * not written: Debian bookworm has no Arrow library.  The time histories are
 * in the run's CSVs instead (own.csv, targets.csv: t, position in the plane
 * and in latitude/longitude, heading, speed; run.h).
 */
#ifndef FW_RUN_DNV_OUT_H
#define FW_RUN_DNV_OUT_H

#include "avoid/encounter.h"
#include "avoid/policy.h"
#include "core/error.h"
#include "nomoto/track.h"
#include "scenario/scenario.h"

typedef struct fw_dnv_out fw_dnv_out;

/* An empty output for scenario s (which must outlive it; it has an origin). */
fw_status fw_dnv_out_create(const fw_scenario *s, fw_dnv_out **out, fw_error *err);
void fw_dnv_out_destroy(fw_dnv_out *o);

/* One event at time t: the own ship's state (own, over ground: course, sog),
 * the decision d, the n targets and their assessments. */
fw_status fw_dnv_out_event(fw_dnv_out *o, double t, const fw_own_state *own, double cog,
                           double sog, const fw_decision *d, const fw_target *tg,
                           const fw_assessment *as, int n, fw_error *err);

/* Writes the output to path (whole, or not at all). */
fw_status fw_dnv_out_write(fw_dnv_out *o, const char *path, fw_error *err);

#endif
