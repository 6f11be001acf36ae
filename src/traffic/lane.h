/* lane.h - a ship's lane: the line it follows along its route ahead, and
 * where another ship is on it.
 *
 * The traffic sources say a lane-bound ship's lane (source.h lane()); this
 * is its geometry, the one place it is computed: the foot of a point on the
 * line (its course there, how far across and along), and whether two ships
 * meet along one waterway.  Frame: metres east and north, navigational
 * radians.
 */
#ifndef FW_TRAFFIC_LANE_H
#define FW_TRAFFIC_LANE_H

#include <stdbool.h>

#include "geom/target.h"

/* A ship's lane (source.h lane()): the centre line of the lane it is on,
 * along its route ahead from about where it is (the plane's metres east and
 * north, np points, at least 2), and the sea room from that line to the edge
 * of the waterway its route uses on its starboard and port sides (m, from
 * the ship's hull centre line; INFINITY in open water).  What a ship that
 * alters course needs to know: whether it has the room, and where to come
 * back to. */
enum { FW_LANE_POINTS = 64 };
typedef struct fw_lane_info {
    int np;
    double e[FW_LANE_POINTS], n[FW_LANE_POINTS];
    double room_starboard, room_port;
    bool traffic_lane; /* a separation scheme's traffic lane (traffic.h fw_traffic_lane) */
    bool changing;     /* in the middle of a lane change (traffic.h fw_traffic_lane) */
} fw_lane_info;

/* The point of the lane's line nearest (e, n): the line's course there (rad)
 * and the cross-track distance (m, > 0 to starboard of the line), the
 * segment's index in *seg (the last segment beyond its end). */
void fw_lane_where(const fw_lane_info *lane, double e, double n, double *course, double *xtrack,
                   int *seg);
/* The same and how far along the line (m from its first point) that is. */
void fw_lane_foot(const fw_lane_info *lane, double e, double n, double *course, double *xtrack,
                  int *seg, double *along);

/* deg: how far from the reciprocal of the other's lane a ship meeting it
 * along one waterway may head (a bend's turn half way, a lane change) */
#define FW_LANE_MEET_TOL_DEG 45.0

/* Do ships a and b (lanes la, lb) meet along one waterway, each coming the
 * other way down the other's lane ahead?  Each lies ahead of the other
 * along the other's line (its foot beyond the other's own, or abeam within
 * the width below), on that line's
 * port side within the width of both waterways (the two lanes' edges side by
 * side: a two-way channel's, or a scheme's two lanes and the zone between;
 * open water, INFINITY, never), its heading within FW_LANE_MEET_TOL_DEG of
 * the reciprocal of the line's course there.  Rounding a bend towards each
 * other their headings differ by the bend's angle from reciprocal, and by
 * rules 9 and 14 they are meeting ships, each keeping to its starboard side
 * of the channel, not crossing ones (avoid/encounter.h fw_classify_lanes). */
bool fw_lanes_meet(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                   const fw_lane_info *lb);

/* Do ships a and b follow one waterway the same way, one ahead of the
 * other: the one ahead on the line of the one astern, beyond its foot,
 * within its lane's edge, heading within FW_LANE_MEET_TOL_DEG of the line's
 * course there?  Round a bend their courses
 * differ by the bend's angle, but they share the lanes (the traffic's car
 * following keeps them apart, as on a straight lane). */
bool fw_lanes_along(const fw_target *a, const fw_lane_info *la, const fw_target *b,
                    const fw_lane_info *lb);

#endif
