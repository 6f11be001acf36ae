/* position.c - a ship's position in a scenario file, in metres or degrees
 * (position.h). */
#include "scenario/position.h"

#include <math.h>

#include "geom/geo.h"
#include "scenario/scn_ais.h"
#include "traffic/demand.h"

fw_status fw_scenario_plane(const fw_scenario *s, fw_geo **g, fw_error *err)
{
    *g = NULL;
    if (!s->has_origin)
        return FW_OK;
    return s->plane[0] ? fw_geo_create_proj(s->plane, s->plane_off_e, s->plane_off_n, g, err)
                       : fw_geo_create(s->origin_lat, s->origin_lon, g, err);
}

/* traffic.network's plane when the network is geo-referenced (its nodes were
 * given in degrees and projected by netconvert): the scenario is then in it,
 * with the origin where the plane's (0, 0) is.  An unknown network is left to
 * the traffic section's own check. */
static fw_status network_plane(const yt_doc *doc, const yt_node *root, const yt_node *origin,
                               fw_scenario *s, fw_error *err)
{
    const yt_node *tr = yt_get(root, "traffic"), *net = tr ? yt_get(tr, "network") : NULL;
    fw_network_files nf;
    fw_error nerr = {0};
    char ref[1024];
    if (!net || !net->str || !fw_scn_network_ref(doc->file, net->str, ref, sizeof ref) ||
        fw_network_find(ref, &nf, &nerr) ||
        fw_network_plane(&nf, s->plane, sizeof s->plane, &s->plane_off_e, &s->plane_off_n,
                         &nerr) || !s->plane[0])
        return FW_OK;
    if (origin)
        return fw_fail_at(err, doc->file, origin->line, "origin",
                          "network '%s' is geo-referenced (%s): the scenario is in its plane; "
                          "leave the origin out", net->str, s->plane);
    fw_geo *g = NULL;
    if (fw_geo_create_proj(s->plane, s->plane_off_e, s->plane_off_n, &g, &nerr))
        return fw_fail_at(err, doc->file, net->line, "traffic.network", "%s", nerr.msg);
    fw_geo_origin(g, &s->origin_lat, &s->origin_lon);
    fw_geo_destroy(g);
    s->has_origin = true;
    return FW_OK;
}

fw_status fw_scn_load_origin(const yt_doc *doc, const yt_node *root, fw_scenario *s,
                             fw_error *err)
{
    static const char *const keys[] = {"lat_deg", "lon_deg", NULL};
    const yt_node *o;
    fw_status st = yt_opt_map(doc, root, "", "origin", &o, err);
    if (st || (st = network_plane(doc, root, o, s, err)))
        return st;
    if (!o)
        return FW_OK;
    if ((st = yt_check_keys(doc, o, "origin", keys, err)) ||
        (st = yt_req_number(doc, o, "origin", "lat_deg", -80, 80, &s->origin_lat, err)) ||
        (st = yt_req_number(doc, o, "origin", "lon_deg", -180, 180, &s->origin_lon, err)))
        return st;
    s->has_origin = true;
    return FW_OK;
}

fw_status fw_scn_load_position(const yt_doc *doc, const yt_node *map, const char *path,
                               const fw_scenario *s, double *east, double *north, double *gamma,
                               fw_error *err)
{
    *gamma = 0.0;
    bool plane = yt_get(map, "east_m") || yt_get(map, "north_m");
    bool geo = yt_get(map, "lat_deg") || yt_get(map, "lon_deg");
    if (plane == geo)
        return fw_fail_at(err, doc->file, map->line, path,
                          "give the position as east_m and north_m, or as lat_deg and lon_deg");
    if (plane)
        return yt_req_number(doc, map, path, "east_m", -1e6, 1e6, east, err) ||
                       yt_req_number(doc, map, path, "north_m", -1e6, 1e6, north, err)
                   ? err->status
                   : FW_OK;
    if (!s->has_origin)
        return yt_fail_key(doc, map, path, yt_get(map, "lat_deg") ? "lat_deg" : "lon_deg", err,
                           "a position in degrees needs the scenario's origin: {lat_deg, "
                           "lon_deg}");
    double lat, lon;
    fw_status st;
    if ((st = yt_req_number(doc, map, path, "lat_deg", -90, 90, &lat, err)) ||
        (st = yt_req_number(doc, map, path, "lon_deg", -180, 180, &lon, err)))
        return st;
    fw_geo *g = NULL;
    fw_error gerr = {0};
    if (!(st = fw_scenario_plane(s, &g, &gerr)) &&
        !(st = fw_geo_to_plane(g, lat, lon, east, north, &gerr)))
        st = fw_geo_convergence(g, lat, lon, gamma, &gerr);
    fw_geo_destroy(g);
    if (!st && (fabs(*east) > 1e6 || fabs(*north) > 1e6))
        st = fw_fail(&gerr, FW_EINPUT, "%s, %s is more than 1000 km from the origin",
                     yt_get(map, "lat_deg")->str, yt_get(map, "lon_deg")->str);
    return st ? yt_fail_key(doc, map, path, "lat_deg", err, "%s", gerr.msg) : FW_OK;
}
