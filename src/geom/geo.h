/* geo.h - geographic coordinates (WGS84 latitude and longitude) and fairway's
 * local plane, converted in this one place.
 *
 * A scenario with an origin (latitude, longitude) has its plane east/north in
 * metres on a transverse Mercator projection centred there (PROJ:
 * "+proj=tmerc +lat_0=.. +lon_0=.. +k=1 +x_0=0 +y_0=0 +ellps=WGS84"): exact
 * to the millimetre both ways, conformal, with a scale error below 1e-5
 * within 45 km of the origin (the scale factor 1 + (x/R)^2/2).  The same
 * string given to netconvert (--proj) puts a geo-referenced SUMO network in
 * the same plane.
 *
 * Headings: the plane's north is grid north, which differs from true north
 * by the meridian convergence (about dlon * sin(lat): 0.2 deg 20 km east of
 * an origin at 51 N).  Courses given in a file are true and converted with
 * it; headings written out are grid headings, beside lat/lon positions.
 */
#ifndef FW_GEO_H
#define FW_GEO_H

#include <stddef.h>

#include "core/error.h"

typedef struct fw_geo fw_geo;

/* A plane centred on (lat_deg, lon_deg); FW_EINPUT outside [-80, 80] x
 * [-180, 180] (transverse Mercator is kept well away from the poles). */
fw_status fw_geo_create(double lat_deg, double lon_deg, fw_geo **out, fw_error *err);
/* The plane of a geo-referenced SUMO network: PROJ string proj (the
 * net.xml's projParameter, e.g. "+proj=utm +zone=32 +ellps=WGS84") with
 * (off_e, off_n) added to its x, y (the netOffset); the origin is where the
 * plane's (0, 0) falls.  FW_EINPUT if PROJ cannot make it. */
fw_status fw_geo_create_proj(const char *proj, double off_e, double off_n, fw_geo **out,
                             fw_error *err);
void fw_geo_destroy(fw_geo *g);

/* The origin (where the plane's (0, 0) is), and the PROJ string of the plane. */
void fw_geo_origin(const fw_geo *g, double *lat_deg, double *lon_deg);
const char *fw_geo_proj_string(const fw_geo *g);

/* Latitude and longitude (deg) -> east, north (m); and back. */
fw_status fw_geo_to_plane(const fw_geo *g, double lat_deg, double lon_deg, double *east,
                          double *north, fw_error *err);
fw_status fw_geo_to_latlon(const fw_geo *g, double east, double north, double *lat_deg,
                           double *lon_deg, fw_error *err);

/* rad, grid north minus true north at (lat, lon): a true course c is the grid
 * course c - convergence. */
fw_status fw_geo_convergence(const fw_geo *g, double lat_deg, double lon_deg, double *gamma,
                             fw_error *err);

#endif
