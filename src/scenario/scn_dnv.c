/* scn_dnv.c - a DNV traffic situation read as a scenario (scn_dnv.h). */
#include "scenario/scn_dnv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "core/json_read.h"
#include "core/units.h"
#include "scenario/scn_env.h"
#include "geom/geo.h"
#include "geom/geom.h"
#include "avoid/route.h"
#include "nomoto/nomoto.h"

#define DNV_MAX_SOG_KN 60.0

/* One ship as read, in the plane. */
typedef struct dnv_ship {
    fw_target t;    /* id, type, start, course (grid), speed, hull */
    fw_scn_route r; /* start, then waypoints 1.. */
    double length, width; /* m, 0 = not given */
    char name[64];
    const char *type;
    fw_jnode node;  /* the ship's object, for messages */
} dnv_ship;

bool fw_scn_is_dnv(const char *path)
{
    size_t n = strlen(path);
    return n > 5 && strcmp(path + n - 5, ".json") == 0;
}

static fw_status read_version(const fw_jnode *root, fw_error *err)
{
    fw_jnode v;
    const char *ver = NULL;
    fw_status st = fw_jmember(root, "version", false, &v, err);
    if (!st && fw_jnode_type(&v) == FW_J_ABSENT)
        st = fw_jmember(root, "schemaVersion", false, &v, err);
    if (st)
        return st;
    if (fw_jnode_type(&v) == FW_J_ABSENT)
        return fw_jfail(root, err, "no version (nor schemaVersion, as DNV's generator writes)");
    if ((st = fw_jstring(&v, &ver, err)))
        return st;
    if (strncmp(ver, "0.2.", 4) != 0 || !ver[4])
        return fw_jfail(&v, err, "'%s' is not a version fairway reads (maritime-schema 0.2.x)",
                        ver);
    return FW_OK;
}

/* {lat, lon} in degrees. */
static fw_status read_latlon(const fw_jnode *pos, double *lat, double *lon, fw_error *err)
{
    fw_status st = fw_jobject(pos, err);
    if (!st)
        st = fw_jmember_number(pos, "lat", true, -90, 90, lat, NULL, err);
    if (!st)
        st = fw_jmember_number(pos, "lon", true, -180, 180, lon, NULL, err);
    return st;
}

static fw_status to_plane(const fw_geo *g, const fw_jnode *pos, double lat, double lon,
                          double *e, double *n, fw_error *err)
{
    fw_error gerr = {0};
    if (fw_geo_to_plane(g, lat, lon, e, n, &gerr))
        return fw_jfail(pos, err, "%s", gerr.msg);
    return FW_OK;
}

/* Where the ship starts: initial.position, else waypoint 0 (lat/lon). */
static fw_status start_node(const fw_jnode *ship, fw_jnode *pos, fw_error *err)
{
    fw_jnode ini, wps;
    fw_status st = fw_jmember(ship, "initial", false, &ini, err);
    if (!st && fw_jnode_type(&ini) != FW_J_ABSENT && !(st = fw_jobject(&ini, err)))
        st = fw_jmember(&ini, "position", false, pos, err);
    if (st || (fw_jnode_type(&ini) != FW_J_ABSENT && fw_jnode_type(pos) != FW_J_ABSENT))
        return st;
    size_t n;
    if ((st = fw_jmember(ship, "waypoints", true, &wps, err)) || (st = fw_jarray(&wps, 2, &n, err)))
        return st;
    fw_jnode w0 = fw_jelement(&wps, 0);
    if ((st = fw_jobject(&w0, err)))
        return st;
    return fw_jmember(&w0, "position", true, pos, err);
}

/* initial: sog (kn, NAN when absent); cog, heading and navStatus checked. */
static fw_status read_initial(const fw_jnode *ship, double *sog, fw_error *err)
{
    fw_jnode ini, ns;
    *sog = NAN;
    fw_status st = fw_jmember(ship, "initial", false, &ini, err);
    if (st || fw_jnode_type(&ini) == FW_J_ABSENT)
        return st;
    double cog, hdg;
    const char *s;
    if ((st = fw_jmember_number(&ini, "sog", false, 0, DNV_MAX_SOG_KN, sog, NULL, err)) ||
        (st = fw_jmember_number(&ini, "cog", false, 0, 360, &cog, NULL, err)) ||
        (st = fw_jmember_number(&ini, "heading", false, 0, 360, &hdg, NULL, err)) ||
        (st = fw_jmember(&ini, "navStatus", false, &ns, err)))
        return st;
    if (fw_jnode_type(&ns) != FW_J_ABSENT && (st = fw_jstring(&ns, &s, err)))
        return st;
    return FW_OK;
}

/* Waypoint k's leg speed (kn) into *kn; absent: *kn keeps the leg before's. */
static fw_status read_leg(const fw_jnode *wp, double *kn, fw_error *err)
{
    fw_jnode leg, sog = {0};
    fw_status st = fw_jmember(wp, "leg", false, &leg, err);
    if (!st && fw_jnode_type(&leg) != FW_J_ABSENT &&
        !(st = fw_jobject(&leg, err)) && !(st = fw_jmember(&leg, "sog", false, &sog, err)) &&
        fw_jnode_type(&sog) != FW_J_ABSENT)
        st = fw_jnumber(&sog, 0, DNV_MAX_SOG_KN, kn, err);
    if (st)
        return st;
    if (isnan(*kn))
        return fw_jfail(wp, err, "no leg.sog (nor an earlier leg's or initial.sog): the leg "
                                 "has no speed");
    if (!(*kn > 0.0))
        return fw_jfail(sog.v ? &sog : wp, err, "a speed of 0 kn: the leg never ends");
    return FW_OK;
}

/* The waypoints after the start into d->r (m, m/s). */
static fw_status read_waypoints(const fw_jnode *ship, const fw_geo *g, double sog_kn,
                                dnv_ship *d, fw_error *err)
{
    fw_jnode wps;
    size_t n;
    fw_status st;
    if ((st = fw_jmember(ship, "waypoints", true, &wps, err)) || (st = fw_jarray(&wps, 2, &n, err)))
        return st;
    if (n > FW_SCN_MAX_WAYPOINTS)
        return fw_jfail(&wps, err, "%zu waypoints, at most %d", n, FW_SCN_MAX_WAYPOINTS);
    double kn = sog_kn;
    for (size_t k = 0; k < n; k++) {
        fw_jnode wp = fw_jelement(&wps, k), pos;
        double lat, lon, leg_kn = NAN;
        if ((st = fw_jobject(&wp, err)) || (st = fw_jmember(&wp, "position", true, &pos, err)) ||
            (st = read_latlon(&pos, &lat, &lon, err)))
            return st;
        if (k == 0) { /* its leg is no leg: only checked */
            fw_jnode leg;
            if ((st = fw_jmember(&wp, "leg", false, &leg, err)) ||
                (fw_jnode_type(&leg) != FW_J_ABSENT &&
                 ((st = fw_jobject(&leg, err)) ||
                  (st = fw_jmember_number(&leg, "sog", false, 0, DNV_MAX_SOG_KN, &leg_kn, NULL,
                                          err)))))
                return st;
            continue;
        }
        if ((st = read_leg(&wp, &kn, err)))
            return st;
        fw_scn_waypoint *w = &d->r.wp[d->r.n];
        if ((st = to_plane(g, &pos, lat, lon, &w->east, &w->north, err)))
            return st;
        const fw_scn_waypoint *p = &d->r.wp[d->r.n - 1];
        if (hypot(w->east - p->east, w->north - p->north) < 1.0)
            return fw_jfail(&pos, err, "within 1 m of the %s: no leg",
                            d->r.n == 1 ? "ship's start" : "waypoint before");
        w->speed = fw_kn_to_ms(kn);
        d->r.n++;
    }
    return FW_OK;
}

/* static: id, name, shipType, dimensions. */
static fw_status read_static(const fw_jnode *ship, dnv_ship *d, fw_error *err)
{
    fw_jnode st_n, dim;
    double id, mmsi;
    const char *name = "";
    d->type = "Other";
    fw_status st;
    if ((st = fw_jmember(ship, "static", true, &st_n, err)) || (st = fw_jobject(&st_n, err)) ||
        (st = fw_jmember_number(&st_n, "id", true, 0, 1e15, &id, NULL, err)) ||
        (st = fw_jmember_number(&st_n, "mmsi", false, 0, 999999999, &mmsi, NULL, err)) ||
        (st = fw_jmember_string(&st_n, "name", false, &name, err)) ||
        (st = fw_jmember_string(&st_n, "shipType", false, &d->type, err)) ||
        (st = fw_jmember(&st_n, "dimensions", false, &dim, err)))
        return st;
    if (id != floor(id))
        return fw_jfail(&st_n, err, "id %g is not a whole number", id);
    snprintf(d->t.id, sizeof d->t.id, "%.0f", id);
    snprintf(d->name, sizeof d->name, "%s", name);
    /* the type as a label: lower case, '-' for anything else */
    size_t i = 0;
    for (; d->type[i] && i + 1 < sizeof d->t.type; i++) {
        char c = d->type[i];
        d->t.type[i] = (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a')
                       : ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) ? c : '-';
    }
    d->t.type[i] = '\0';
    if (!d->t.type[0])
        snprintf(d->t.type, sizeof d->t.type, "other");
    if (fw_jnode_type(&dim) == FW_J_ABSENT)
        return FW_OK;
    static const char *const more[] = {"height", "draught", "a", "b", "c", "d"};
    double x;
    if ((st = fw_jobject(&dim, err)) ||
        (st = fw_jmember_number(&dim, "length", false, 1, 500, &d->length, NULL, err)) ||
        (st = fw_jmember_number(&dim, "width", false, 0.5, 100, &d->width, NULL, err)))
        return st;
    for (int k = 0; k < 6; k++)
        if ((st = fw_jmember_number(&dim, more[k], false, 0, 500, &x, NULL, err)))
            return st;
    if (d->width > d->length && d->length > 0)
        return fw_jfail(&dim, err, "width %g m exceeds the length %g m", d->width, d->length);
    return FW_OK;
}

/* fairway's own members of a target (written by run/dnv_situation.h; the
 * schema allows more): fairway.appearS, fairway.vanishS, s; fairway.turns
 * checked (scn_dnv_turns.c). */
static fw_status read_fairway(const fw_jnode *ship, fw_scn_route *r, fw_error *err)
{
    fw_jnode f;
    r->appear = 0.0;
    r->vanish = INFINITY;
    fw_status st = fw_jmember(ship, "fairway", false, &f, err);
    if (st || fw_jnode_type(&f) == FW_J_ABSENT || (st = fw_jobject(&f, err)) ||
        (st = fw_jmember_number(&f, "appearS", false, 0, 86400, &r->appear, NULL, err)) ||
        (st = fw_jmember_number(&f, "vanishS", false, r->appear, 86400, &r->vanish, NULL, err)))
        return st;
    int n = 0;
    st = fw_scn_dnv_read_turns(&f, r->appear, NULL, &n, err);
    r->turns = n > 0;
    return st;
}

/* One ship: start, course and speed towards waypoint 1, waypoints, static. */
static fw_status read_ship(const fw_jnode *ship, const fw_geo *g, dnv_ship *d, fw_error *err)
{
    memset(d, 0, sizeof *d);
    d->node = *ship;
    fw_jnode pos;
    double lat, lon, sog;
    fw_status st;
    if ((st = fw_jobject(ship, err)) || (st = read_initial(ship, &sog, err)) ||
        (st = start_node(ship, &pos, err)) || (st = read_latlon(&pos, &lat, &lon, err)) ||
        (st = to_plane(g, &pos, lat, lon, &d->r.wp[0].east, &d->r.wp[0].north, err)))
        return st;
    d->r.n = 1;
    if ((st = read_waypoints(ship, g, sog, d, err)) || (st = read_static(ship, d, err)) ||
        (st = read_fairway(ship, &d->r, err)))
        return st;
    const fw_scn_waypoint *a = &d->r.wp[0], *b = &d->r.wp[1];
    double c = atan2(b->east - a->east, b->north - a->north);
    d->t.east = a->east;
    d->t.north = a->north;
    d->t.course = d->t.heading = fw_wrap_2pi(c);
    d->t.speed = d->t.stw = isnan(sog) ? b->speed : fw_kn_to_ms(sog);
    d->t.length = d->length;
    d->t.breadth = d->width;
    return FW_OK;
}

/* s: when the ship reaches its last waypoint at its legs' speeds. */
static double route_time(const fw_scn_route *r)
{
    double t = r->appear;
    for (int k = 1; k < r->n; k++)
        t += hypot(r->wp[k].east - r->wp[k - 1].east, r->wp[k].north - r->wp[k - 1].north) /
             r->wp[k].speed;
    return t;
}

/* The file's stem as a name: letters, digits, '-', '_'. */
static void stem_name(const char *path, char *out, size_t n)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    size_t len = strlen(b) - 5, i = 0; /* ".json" */
    for (; i < len && i + 1 < n; i++) {
        char c = b[i];
        bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                  c == '-' || c == '_';
        out[i] = ok ? c : '_';
    }
    out[i] = '\0';
    if (!out[0])
        snprintf(out, n, "situation");
}

/* More than one own leg: a route the policy steers (avoid/route.h), each
 * leg's speed within the model's knowledge base. */
static fw_status own_route(const dnv_ship *d, fw_scenario *s, fw_error *err)
{
    if (d->r.n > FW_ROUTE_MAX_LEGS + 1)
        return fw_jfail(&d->node, err, "%d waypoints from the start: fairway's own ship follows "
                        "%d at most", d->r.n, FW_ROUTE_MAX_LEGS + 1);
    double e[FW_ROUTE_MAX_LEGS + 1], n[FW_ROUTE_MAX_LEGS + 1], v[FW_ROUTE_MAX_LEGS + 1];
    for (int k = 0; k < d->r.n; k++) {
        e[k] = d->r.wp[k].east, n[k] = d->r.wp[k].north;
        v[k] = k + 1 < d->r.n ? d->r.wp[k + 1].speed : 0.0;
        double kn = fw_ms_to_kn(v[k]);
        if (k + 1 < d->r.n && fw_nomoto_kb_speed(&s->ship.nomoto, kn) == FW_KB_SPEED_REFUSED)
            return fw_jfail(&d->node, err, "leg %d: %g kn is beyond %s's Nomoto knowledge base "
                            "(give another model with --ship)", k + 1, kn, s->ship.name);
    }
    fw_error rerr = {0};
    if (fw_route_from_waypoints(e, n, v, d->r.n, &s->route, &rerr))
        return fw_jfail(&d->node, err, "waypoints: %s", rerr.msg);
    s->leg = 0.0;
    for (int k = 0; k < s->route.n; k++)
        s->leg += s->route.leg[k].length;
    return FW_OK;
}

/* The own ship: its model, start, course, speed, planned leg; the note. */
static fw_status own_ship(const dnv_ship *d, const char *ship, fw_scenario *s, fw_error *err)
{
    fw_error serr = {0};
    fw_status st;
    if (fw_ship_load(ship, &s->ship, &serr))
        return fw_fail(err, FW_EINPUT, "--ship %s: %s", ship, serr.msg);
    s->east = d->t.east;
    s->north = d->t.north;
    s->course = d->t.course;
    s->speed = d->t.speed;
    const fw_scn_waypoint *a = &d->r.wp[0], *b = &d->r.wp[1];
    s->leg = hypot(b->east - a->east, b->north - a->north);
    double kn = fw_ms_to_kn(s->speed);
    if (!(kn >= 1.0))
        return fw_jfail(&d->node, err, "a speed of %g kn: fairway's own ship needs 1 kn at least",
                        kn);
    const fw_nomoto_kb *kb = &s->ship.nomoto;
    if (fw_nomoto_kb_speed(kb, kn) == FW_KB_SPEED_REFUSED)
        return fw_jfail(&d->node, err,
                        "%g kn is beyond %s's Nomoto knowledge base, fitted over %g-%g kn (give "
                        "another model with --ship)", kn, s->ship.name, kb->speed_min_kn,
                        kb->speed_max_kn);
    if (d->r.n > 2 && (st = own_route(d, s, err)))
        return st;
    s->helm.domain.own_half_length = 0.5 * s->ship.Loa;
    s->helm.domain.own_half_breadth = 0.5 * s->ship.B;
    s->audit = fw_audit_def_for(s->waterway, s->ship.Loa);
    char dims[64] = "no dimensions";
    if (d->length > 0)
        snprintf(dims, sizeof dims, "%.1f x %.1f m", d->length, d->width);
    snprintf(s->note, sizeof s->note,
             "own ship model: %s (%s), %.1f x %.1f m: the situation's own ship '%s' (%s, %s) "
             "gives the start, course and speed, not the hull (the domain and hull measures are "
             "the model's); planned track: %s %.2f nm from %03.0f deg (grid) at %.1f kn%s; "
             "targets follow their waypoints at the legs' speeds, blind",
             s->ship.name, strcmp(ship, FW_DNV_DEFAULT_SHIP) == 0 ? "fairway's default" : "--ship",
             s->ship.Loa, s->ship.B, d->name, d->type, dims,
             s->route.n > 1 ? "its waypoints, a route steered leg by leg," : "its one leg,",
             fw_m_to_nm(s->leg), fw_heading_deg(s->course), kn,
             s->route.n > 1 ? ", each leg at its speed" : ", continued straight");
    return FW_OK;
}

static fw_status read_targets(const fw_jnode *root, const fw_geo *g, fw_scenario *s,
                              dnv_ship *d, fw_error *err)
{
    fw_jnode arr;
    size_t n = 0;
    fw_status st = fw_jmember(root, "targetShips", false, &arr, err);
    if (st || (fw_jnode_type(&arr) != FW_J_ABSENT && (st = fw_jarray(&arr, 0, &n, err))))
        return st;
    if (n == 0)
        return fw_jfail(root, err, "no targetShips: nothing to meet");
    if (n > FW_SCN_MAX_TARGETS)
        return fw_jfail(&arr, err, "%zu targets, at most %d", n, FW_SCN_MAX_TARGETS);
    for (size_t i = 0; i < n; i++) {
        fw_jnode t = fw_jelement(&arr, i);
        if ((st = read_ship(&t, g, d, err)))
            return st;
        if (!(d->length > 0 && d->width > 0))
            return fw_jfail(&t, err, "static.dimensions.length and width needed (the target's "
                                     "hull: domain and collision)");
        for (int j = 0; j < s->n_targets; j++)
            if (strcmp(s->targets[j].id, d->t.id) == 0)
                return fw_jfail(&t, err, "static.id %s used twice", d->t.id);
        if (fw_hulls_overlap(s->east, s->north, s->course, s->ship.Loa, s->ship.B, d->t.east,
                             d->t.north, d->t.heading, d->t.length, d->t.breadth))
            return fw_jfail(&t, err, "starts overlapping the own ship's hull");
        s->targets[s->n_targets] = d->t;
        s->target_routes[s->n_targets++] = d->r;
        s->duration = fmax(s->duration, ceil(route_time(&d->r) - 1e-3));
    }
    return FW_OK;
}

/* $.startTime: "YYYY-MM-DDThh:mm:ss[.f]Z" into s->utc_start (absent: 2000-01-01). */
static fw_status read_start(const fw_jnode *root, fw_scenario *s, fw_error *err)
{
    fw_jnode n;
    const char *text;
    s->utc_start = 946684800.0;
    fw_status st = fw_jmember(root, "startTime", false, &n, err);
    if (st || fw_jnode_type(&n) == FW_J_ABSENT || (st = fw_jstring(&n, &text, err)))
        return st;
    struct tm tm = {0};
    double sec = -1.0;
    int used = 0;
    if (sscanf(text, "%4d-%2d-%2dT%2d:%2d:%lf%n", &tm.tm_year, &tm.tm_mon, &tm.tm_mday,
               &tm.tm_hour, &tm.tm_min, &sec, &used) != 6 ||
        !(strcmp(text + used, "Z") == 0 || strcmp(text + used, "+00:00") == 0) ||
        tm.tm_year < 1970 || tm.tm_year > 9999 || tm.tm_mon < 1 || tm.tm_mon > 12 ||
        tm.tm_mday < 1 || tm.tm_mday > 31 || tm.tm_hour > 23 || tm.tm_min > 59 ||
        !(sec >= 0.0 && sec < 61.0))
        return fw_jfail(&n, err, "'%s' is not a UTC time YYYY-MM-DDThh:mm:ssZ", text);
    tm.tm_year -= 1900;
    tm.tm_mon -= 1;
    s->utc_start = (double)timegm(&tm) + sec;
    return FW_OK;
}

/* fairway's own top-level member (written by run/dnv_situation.h): the
 * run's duration and the domain the situation was run with. */
static fw_status read_settings(const fw_jnode *root, fw_scenario *s, fw_error *err)
{
    fw_jnode f;
    fw_status st = fw_jmember(root, "fairway", false, &f, err);
    if (st || fw_jnode_type(&f) == FW_J_ABSENT || (st = fw_jobject(&f, err)) ||
        (st = fw_jmember_number(&f, "durationS", false, 1, 86400, &s->duration, NULL, err)) ||
        (st = fw_jmember_number(&f, "domainM", false, 10, 5000, &s->helm.domain.size, NULL,
                                err)) ||
        (st = fw_jmember_number(&f, "foreAftRatio", false, 0.2, 10,
                                &s->helm.domain.fore_aft_ratio, NULL, err)))
        return st;
    return FW_OK;
}

/* $.environment: a uniform wind (windSpeed m/s, windDirection deg, the way
 * it blows from), a uniform current (currentSpeed m/s, currentDirection
 * deg, the way it sets) and the visibility (NM), as fairway's own
 * environment: takes them (scenario/scn_env.h; the same bounds: 100 kn of
 * wind, 10 kn of current, visibility more than 0 and at most 100 nm).  A
 * speed without its direction is refused.  Waves (waveSpectrum,
 * significantWaveHeight, wavePeriod, waveDirection) and `conditions` are
 * read past: fairway has no wave forces (run.log says so when a wave
 * height is given). */
static fw_status read_environment(const fw_jnode *root, fw_scenario *s, fw_error *err)
{
    fw_jnode e;
    double ws = 0.0, wd = 0.0, cs = 0.0, cd = 0.0, vis = 0.0, hs = 0.0;
    bool has_ws = false, has_wd = false, has_cs = false, has_cd = false, has_vis = false;
    fw_status st = fw_jmember(root, "environment", false, &e, err);
    if (st || fw_jnode_type(&e) == FW_J_ABSENT)
        return st;
    if ((st = fw_jobject(&e, err)) ||
        (st = fw_jmember_number(&e, "windSpeed", false, 0.0, fw_kn_to_ms(100.0), &ws, &has_ws,
                                err)) ||
        (st = fw_jmember_number(&e, "windDirection", false, 0.0, 360.0, &wd, &has_wd, err)) ||
        (st = fw_jmember_number(&e, "currentSpeed", false, 0.0, fw_kn_to_ms(10.0), &cs, &has_cs,
                                err)) ||
        (st = fw_jmember_number(&e, "currentDirection", false, 0.0, 360.0, &cd, &has_cd, err)) ||
        (st = fw_jmember_number(&e, "visibility", false, 1e-9, 100.0, &vis, &has_vis, err)) ||
        (st = fw_jmember_number(&e, "significantWaveHeight", false, 0.0, 30.0, &hs, NULL, err)))
        return st;
    if (has_ws != has_wd || has_cs != has_cd)
        return fw_jfail(&e, err, "a %s speed needs its direction, and a direction its speed",
                        has_ws != has_wd ? "wind" : "current");
    if (has_ws && ws > 0.0)
        s->env.wind = (fw_wind){.kind = FW_FIELD_UNIFORM, .speed = ws, .from = fw_deg_to_rad(wd)};
    if (has_cs && cs > 0.0)
        s->env.current = fw_current_uniform(cs, fw_deg_to_rad(cd));
    if (has_vis)
        fw_scn_set_visibility(s, fw_nm_to_m(vis));
    size_t k = strlen(s->note);
    if (hs > 0.0 && k + 1 < sizeof s->note) /* said in run.log with the rest of the note */
        snprintf(s->note + k, sizeof s->note - k,
                 "%sthe situation's waves (%.1f m) are not modelled (no wave forces)",
                 k ? "; " : "", hs);
    fw_error e2 = {0};
    if (fw_env_check_vessel(&s->env, "own ship", &s->ship, !s->nomoto_plant, &e2))
        return fw_jfail(&e, err, "%s", e2.msg);
    return FW_OK;
}

static fw_status read_doc(const fw_jdoc *doc, const char *ship, fw_scenario *s, fw_error *err)
{
    fw_jnode root = fw_jdoc_root(doc), own, pos;
    const char *title = "", *desc = "";
    double lat, lon;
    fw_status st;
    if ((st = fw_jobject(&root, err)) || (st = read_version(&root, err)) ||
        (st = fw_jmember_string(&root, "title", false, &title, err)) ||
        (st = fw_jmember_string(&root, "description", false, &desc, err)) ||
        (st = read_start(&root, s, err)) ||
        (st = fw_jmember(&root, "ownShip", true, &own, err)) || (st = fw_jobject(&own, err)) ||
        (st = start_node(&own, &pos, err)) || (st = read_latlon(&pos, &lat, &lon, err)))
        return st;
    snprintf(s->description, sizeof s->description, "%s%s%s", title, *title && *desc ? ": " : "",
             desc);
    fw_geo *g = NULL;
    fw_error gerr = {0};
    if (fw_geo_create(lat, lon, &g, &gerr))
        return fw_jfail(&pos, err, "%s", gerr.msg);
    s->has_origin = true;
    s->origin_lat = lat;
    s->origin_lon = lon;
    dnv_ship d;
    if (!(st = read_ship(&own, g, &d, err)) && !(st = own_ship(&d, ship, s, err))) {
        s->duration = ceil((s->route.n > 1 ? route_time(&d.r) : s->leg / s->speed) - 1e-3);
        st = read_targets(&root, g, s, &d, err);
    }
    if (!st)
        st = read_settings(&root, s, err);
    if (!st)
        st = read_environment(&root, s, err);
    fw_geo_destroy(g);
    return st;
}

fw_status fw_scn_dnv_load(const char *path, const char *ship, fw_scenario *s, fw_error *err)
{
    fw_status st = fw_scenario_defaults(path, s, err);
    if (st)
        return st;
    stem_name(path, s->name, sizeof s->name);
    s->reactions.behaviour = FW_BEHAVIOUR_BLIND; /* scripted targets */
    s->waypoint_targets = true;
    s->situation_output = true; /* run/dnv_out.h */
    fw_jdoc *doc = NULL;
    if ((st = fw_jdoc_load(path, &doc, err)))
        return st;
    st = read_doc(doc, ship ? ship : FW_DNV_DEFAULT_SHIP, s, err);
    fw_jdoc_free(doc);
    if (!st && !(s->duration >= 1.0 && s->duration <= 86400.0))
        st = fw_fail(err, FW_EINPUT, "%s: the situation lasts %.0f s (1 s to 24 h)", path,
                     s->duration);
    return st;
}
