/* scn_route.c - own_ship.route (scn_route.h). */
#include "scenario/scn_route.h"

#include <math.h>
#include <stdio.h>

#include "core/units.h"
#include "nomoto/nomoto.h"
#include "scenario/position.h"

fw_status fw_scn_route_no_line_keys(const yt_doc *doc, const yt_node *own, fw_error *err)
{
    static const char *const line[] = {"east_m",   "north_m",  "lat_deg", "lon_deg",
                                       "course_deg", "speed_kn", "leg_nm", "destination"};
    for (size_t i = 0; i < sizeof line / sizeof *line; i++)
        if (yt_get(own, line[i]))
            return yt_fail_key(doc, own, "own_ship", line[i], err,
                               "not with a route: its first waypoint is the start, its legs "
                               "the courses, speeds and length");
    return FW_OK;
}

/* Waypoint i of n at path: its position, and the speed of the leg from it
 * (m/s; none at the last). */
static fw_status waypoint(const yt_doc *doc, const yt_node *w, const char *path, size_t i,
                          size_t n, const fw_scenario *s, double *e, double *no, double *speed,
                          fw_error *err)
{
    static const char *const keys[] = {"east_m", "north_m", "lat_deg", "lon_deg", "speed_kn",
                                       NULL};
    double gamma, kn = 0.0;
    fw_status st;
    if (w->kind != YT_MAP)
        return fw_fail_at(err, doc->file, w->line, path,
                          "a waypoint is a map: {east_m, north_m, speed_kn}");
    if ((st = yt_check_keys(doc, w, path, keys, err)) ||
        (st = fw_scn_load_position(doc, w, path, s, e, no, &gamma, err)))
        return st;
    if (i + 1 == n) {
        *speed = 0.0;
        return yt_get(w, "speed_kn")
                   ? yt_fail_key(doc, w, path, "speed_kn", err,
                                 "the last waypoint ends the route: a leg's speed is given at "
                                 "the waypoint it begins at")
                   : FW_OK;
    }
    if ((st = yt_req_number(doc, w, path, "speed_kn", 1, 40, &kn, err)) ||
        (st = fw_scn_leg_speed(doc, yt_key_line(w, "speed_kn"), path, "speed_kn", kn, s, err)))
        return st;
    *speed = fw_kn_to_ms(kn);
    return FW_OK;
}

fw_status fw_scn_leg_speed(const yt_doc *doc, int line, const char *path, const char *key,
                           double kn, const fw_scenario *s, fw_error *err)
{
    const fw_nomoto_kb *kb = &s->ship.nomoto;
    char field[128];
    const char *at = key[0] ? yt_path(field, sizeof field, path, key) : path;
    if (fw_nomoto_kb_speed(kb, kn) == FW_KB_SPEED_REFUSED)
        return fw_fail_at(err, doc->file, line, at,
                          "%g kn is beyond %s's Nomoto knowledge base, fitted over %g-%g kn, "
                          "by more than its x%g margin", kn, s->ship.name, kb->speed_min_kn, kb->speed_max_kn,
                          FW_KB_SPEED_MARGIN);
    return FW_OK;
}

fw_status fw_scn_load_route(const yt_doc *doc, const yt_node *own, fw_scenario *s,
                            fw_error *err)
{
    const yt_node *seq;
    fw_status st = fw_scn_route_no_line_keys(doc, own, err);
    if (st || (st = yt_req_seq(doc, own, "own_ship", "route", &seq, err)))
        return st;
    if (seq->n < 2 || seq->n > FW_ROUTE_MAX_LEGS + 1)
        return fw_fail_at(err, doc->file, yt_key_line(own, "route"), "own_ship.route",
                          "%zu waypoints: a route has 2..%d", seq->n, FW_ROUTE_MAX_LEGS + 1);
    double e[FW_ROUTE_MAX_LEGS + 1], no[FW_ROUTE_MAX_LEGS + 1], v[FW_ROUTE_MAX_LEGS + 1];
    char path[64];
    for (size_t i = 0; i < seq->n; i++) {
        snprintf(path, sizeof path, "own_ship.route[%zu]", i);
        if ((st = waypoint(doc, seq->items[i], path, i, seq->n, s, &e[i], &no[i], &v[i], err)))
            return st;
        if (i > 0 && hypot(e[i] - e[i - 1], no[i] - no[i - 1]) < 0.1 * FW_NMILE)
            return fw_fail_at(err, doc->file, seq->items[i]->line, path,
                              "%.0f m from the waypoint before: a leg is at least 0.1 nm",
                              hypot(e[i] - e[i - 1], no[i] - no[i - 1]));
    }
    fw_error rerr = {0};
    if (fw_route_from_waypoints(e, no, v, (int)seq->n, &s->route, &rerr))
        return fw_fail_at(err, doc->file, yt_key_line(own, "route"), "own_ship.route", "%s", rerr.msg);
    fw_scn_route_start(s);
    return FW_OK;
}

void fw_scn_route_start(fw_scenario *s)
{
    s->east = s->route.leg[0].east, s->north = s->route.leg[0].north;
    s->course = s->route.leg[0].course;
    s->speed = s->route.leg[0].speed;
    s->leg = 0.0;
    for (int k = 0; k < s->route.n; k++)
        s->leg += s->route.leg[k].length;
}
