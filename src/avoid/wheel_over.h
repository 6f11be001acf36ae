/* wheel_over.h - where a ship following a route puts the rudder over for its
 * next leg (internal to src/avoid: the policy's route following, policy.h).
 *
 * The turn is predicted as the ship will make it: from straight running on
 * leg k at that leg's speed, the policy's heading autopilot ordered onto leg
 * k + 1's course (nomoto/track.h fw_track_predict_steer: the ship's Nomoto
 * knowledge base, its drift and speed loss in the turn).  The predicted track
 * settles on a line parallel to the new course; the wheel-over point is the
 * distance before the waypoint at which that line is the next leg itself, so
 * the ship comes out of the turn on the leg, neither short of it nor beyond.
 * The prediction runs over the helm search's horizon (600 s by default: a
 * 90 deg turn at the autopilot's helm settles within it).
 */
#ifndef FW_WHEEL_OVER_H
#define FW_WHEEL_OVER_H

#include "avoid/helm_ctx.h"
#include "avoid/route.h"

/* *d: m before the end of leg k of r where the turn onto k + 1 begins, for
 * the autopilot ap (its psi_ref unused); 0 on the last leg; at most the
 * leg's length.  Uses ctx's spare track. */
fw_status fw_wheel_over(fw_helm_ctx *ctx, const fw_route *r, int k, const fw_steer_def *ap,
                        double *d, fw_error *err);

#endif
