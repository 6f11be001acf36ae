/* position.h - where a scenario file puts a ship: east_m/north_m in the
 * plane, or lat_deg/lon_deg (WGS84) when the scenario has an origin
 * (origin: {lat_deg, lon_deg}), converted by geom/geo.h.  Internal to the
 * scenario loader. */
#ifndef FW_SCENARIO_POSITION_H
#define FW_SCENARIO_POSITION_H

#include "scenario/scenario.h"
#include "yaml/yaml_tree.h"

/* The optional top-level origin into s (has_origin, origin_lat, origin_lon). */
fw_status fw_scn_load_origin(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                             fw_error *err);

/* The position in map at path: exactly one of the pairs east_m/north_m or
 * lat_deg/lon_deg (the latter needs the origin).  *gamma: the meridian
 * convergence there (rad; 0 in the plane), to turn a true course into the
 * grid course (course - gamma). */
fw_status fw_scn_load_position(const yt_doc *doc, const yt_node *map, const char *path,
                               const fw_scenario *s, double *east, double *north, double *gamma,
                               fw_error *err);

#endif
