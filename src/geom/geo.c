/* geo.c - WGS84 latitude/longitude and the local plane through PROJ (geo.h). */
#include "geom/geo.h"

#include <math.h>
#include <proj.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


struct fw_geo {
    PJ_CONTEXT *ctx;
    PJ *pj;            /* geodetic (lon, lat in radians) <-> plane (m) */
    double lat0, lon0; /* deg, where the plane's (0, 0) is */
    double off_e, off_n; /* m, added to PROJ's x, y (a SUMO network's netOffset) */
    char proj[512];
};

/* g with its PROJ string set: the projection made, the origin found. */
static fw_status make(fw_geo *g, fw_geo **out, fw_error *err)
{
    /* its own context (PROJ's default one is not for several threads); a
     * plain projection string needs no database (proj.db) lookup */
    g->ctx = proj_context_create();
    if (g->ctx) /* its reasons go into our message, not onto stderr */
        proj_log_level(g->ctx, PJ_LOG_NONE);
    g->pj = g->ctx ? proj_create(g->ctx, g->proj) : NULL;
    if (!g->pj) {
        const char *why = g->ctx ? proj_context_errno_string(g->ctx, proj_context_errno(g->ctx))
                                 : "no context";
        fw_fail(err, FW_EINPUT, "PROJ cannot make the plane '%s': %s", g->proj,
                why ? why : "unknown");
        fw_geo_destroy(g);
        return err->status;
    }
    fw_status st = fw_geo_to_latlon(g, 0.0, 0.0, &g->lat0, &g->lon0, err);
    if (st) {
        fw_geo_destroy(g);
        return st;
    }
    *out = g;
    return FW_OK;
}

fw_status fw_geo_create(double lat_deg, double lon_deg, fw_geo **out, fw_error *err)
{
    *out = NULL;
    if (!(fabs(lat_deg) <= 80.0) || !(fabs(lon_deg) <= 180.0))
        return fw_fail(err, FW_EINPUT, "origin %.15g, %.15g: latitude must be within 80 deg of the "
                                       "equator and longitude within 180 deg", lat_deg, lon_deg);
    fw_geo *g = calloc(1, sizeof *g);
    if (!g)
        return fw_fail(err, FW_ERUN, "out of memory");
    snprintf(g->proj, sizeof g->proj,
             "+proj=tmerc +lat_0=%.10f +lon_0=%.10f +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m",
             lat_deg, lon_deg);
    fw_status st = make(g, out, err);
    if (!st) { /* exact, not the inverse's rounding */
        (*out)->lat0 = lat_deg;
        (*out)->lon0 = lon_deg;
    }
    return st;
}

fw_status fw_geo_create_proj(const char *proj, double off_e, double off_n, fw_geo **out,
                             fw_error *err)
{
    *out = NULL;
    if (!proj || !proj[0] || strlen(proj) >= sizeof ((fw_geo *)0)->proj)
        return fw_fail(err, FW_EINPUT, "projection '%.60s': empty or too long", proj ? proj : "");
    if (!isfinite(off_e) || !isfinite(off_n))
        return fw_fail(err, FW_EINPUT, "projection offset %.15g, %.15g: not a number", off_e, off_n);
    fw_geo *g = calloc(1, sizeof *g);
    if (!g)
        return fw_fail(err, FW_ERUN, "out of memory");
    snprintf(g->proj, sizeof g->proj, "%s", proj);
    g->off_e = off_e;
    g->off_n = off_n;
    return make(g, out, err);
}

void fw_geo_destroy(fw_geo *g)
{
    if (!g)
        return;
    proj_destroy(g->pj); /* NULL-safe */
    if (g->ctx)          /* NULL would be PROJ's default context */
        proj_context_destroy(g->ctx);
    free(g);
}

void fw_geo_origin(const fw_geo *g, double *lat_deg, double *lon_deg)
{
    *lat_deg = g->lat0;
    *lon_deg = g->lon0;
}

const char *fw_geo_proj_string(const fw_geo *g) { return g->proj; }

/* Forward: a, b = lon, lat (deg) -> x, y = east, north (m); inverse the other
 * way.  Degrees are converted here, PROJ's geodetic side being radians. */
static fw_status trans(const fw_geo *g, PJ_DIRECTION dir, double a, double b, double *x,
                       double *y, fw_error *err)
{
    PJ_COORD in = dir == PJ_FWD ? proj_coord(proj_torad(a), proj_torad(b), 0.0, 0.0)
                                : proj_coord(a - g->off_e, b - g->off_n, 0.0, 0.0);
    PJ_COORD c = proj_trans(g->pj, dir, in);
    if (!isfinite(c.xy.x) || !isfinite(c.xy.y) || c.xy.x == HUGE_VAL)
        return fw_fail(err, FW_EINPUT, "%.15g, %.15g cannot be converted (%s)", a, b,
                       dir == PJ_FWD ? "longitude, latitude" : "east, north");
    *x = dir == PJ_FWD ? c.xy.x + g->off_e : proj_todeg(c.lp.lam);
    *y = dir == PJ_FWD ? c.xy.y + g->off_n : proj_todeg(c.lp.phi);
    return FW_OK;
}

fw_status fw_geo_to_plane(const fw_geo *g, double lat_deg, double lon_deg, double *east,
                          double *north, fw_error *err)
{
    if (!(fabs(lat_deg) <= 90.0) || !(fabs(lon_deg) <= 180.0))
        return fw_fail(err, FW_EINPUT, "latitude %.15g, longitude %.15g: not a position", lat_deg,
                       lon_deg);
    return trans(g, PJ_FWD, lon_deg, lat_deg, east, north, err);
}

fw_status fw_geo_to_latlon(const fw_geo *g, double east, double north, double *lat_deg,
                           double *lon_deg, fw_error *err)
{
    return trans(g, PJ_INV, east, north, lon_deg, lat_deg, err);
}

fw_status fw_geo_convergence(const fw_geo *g, double lat_deg, double lon_deg, double *gamma,
                             fw_error *err)
{
    /* from the plane itself: the grid direction of a short step due north */
    const double d = 1e-4; /* deg, about 11 m */
    /* set though every path that reads them writes them first: gcc -O3
     * cannot see through trans() and would stop a Release build */
    double e0 = 0.0, n0 = 0.0, e1 = 0.0, n1 = 0.0;
    /* one-sided at a pole: a step past it is no latitude (90.0001 was
     * reported as the file's) */
    fw_status st = fw_geo_to_plane(g, fmax(lat_deg - d, -90.0), lon_deg, &e0, &n0, err);
    if (!st)
        st = fw_geo_to_plane(g, fmin(lat_deg + d, 90.0), lon_deg, &e1, &n1, err);
    if (!st)
        *gamma = -atan2(e1 - e0, n1 - n0); /* true north is at grid bearing -gamma */
    return st;
}
