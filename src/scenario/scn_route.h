/* scn_route.h - own_ship.route: the own ship's waypoints with a speed per leg
 * (avoid/route.h), read from a scenario file.  Internal to the scenario
 * loader.
 *
 *   own_ship:
 *     ship: c3-mmg
 *     route:                       # 2..9 waypoints
 *       - {east_m: 0, north_m: 0, speed_kn: 10}      # the leg from here at 10 kn
 *       - {east_m: 0, north_m: 9260, speed_kn: 12}
 *       - {east_m: 4630, north_m: 17279}             # the end: no speed
 *
 * Waypoints in metres, or lat_deg/lon_deg with the scenario's origin
 * (position.h); the legs are straight in the plane (grid courses).  The ship
 * starts at the first waypoint on the first leg's course at its speed; the
 * route replaces east_m/north_m, course_deg, speed_kn and leg_nm/destination
 * (giving both is an error).  Each leg is at least 0.1 nm (185.2 m) long and
 * its speed within 1-40 kn and within the ship's knowledge base's margin
 * (nomoto.h). */
#ifndef FW_SCN_ROUTE_H
#define FW_SCN_ROUTE_H

#include "scenario/scenario.h"
#include "yaml/yaml_tree.h"

/* own_ship.route into s->route and the start (s->east, north, course,
 * speed, leg); own the own_ship map, s->ship loaded. */
fw_status fw_scn_load_route(const yt_doc *doc, const yt_node *own, fw_scenario *s,
                            fw_error *err);

#endif
