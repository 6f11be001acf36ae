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

/* The start (s->east, north, course, speed, leg) from s->route. */
void fw_scn_route_start(fw_scenario *s);

/* None of the keys a route replaces (east_m, course_deg, speed_kn, ...)
 * beside it in the own_ship map. */
fw_status fw_scn_route_no_line_keys(const yt_doc *doc, const yt_node *own, fw_error *err);

/* A leg's speed kn (read at line, field path.key; key may be "") within the
 * margin of the own ship's knowledge base (nomoto.h), else FW_EINPUT there. */
fw_status fw_scn_leg_speed(const yt_doc *doc, int line, const char *path, const char *key,
                           double kn, const fw_scenario *s, fw_error *err);

#endif
