/* source_sumo_files.c - the files a SUMO traffic source (source_sumo.h)
 * gives SUMO: the explicit targets' and the own ship's track edges and
 * routes, the network's demand for the run, and the network built with the
 * tracks (netconvert) or the network's own. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files.h"
#include "core/units.h"
#include "geom/geo.h"
#include "geom/geom.h"
#include "traffic/demand.h"
#include "traffic/netbuild.h"
#include "traffic/source_sumo_internal.h"

/* Extra length of each straight edge behind the start and beyond the end of
 * the run, so no ship reaches an edge's end (where SUMO would remove it). */
static const double kBehind = 1000.0, kBeyond = 3000.0;

/* A node at (e, n) in the plane; in degrees (x longitude, y latitude, 1e-9
 * deg: 0.1 mm) when the network is geo-referenced (geo: its plane). */
static fw_status node(FILE *f, const fw_geo *geo, const char *id, double e, double n,
                      fw_error *err)
{
    double lat, lon;
    if (!geo) {
        fprintf(f, "    <node id=\"%s\" x=\"%.3f\" y=\"%.3f\" type=\"unregulated\"/>\n", id, e, n);
        return FW_OK;
    }
    fw_status st = fw_geo_to_latlon(geo, e, n, &lat, &lon, err);
    if (!st)
        fprintf(f, "    <node id=\"%s\" x=\"%.9f\" y=\"%.9f\" type=\"unregulated\"/>\n", id, lon,
                lat);
    return st;
}

/* One explicit target: its track's nodes and edge, its vType and vehicle. */
static fw_status write_target(FILE *nf, FILE *ef, FILE *rf, const fw_geo *geo,
                              const fw_target *t, double duration, fw_error *err)
{
    double te = sin(t->course), tn = cos(t->course);
    double tl = t->speed * duration + kBeyond;
    char a[96], b[96], v[32];
    snprintf(a, sizeof a, "fw_t_%s_a", t->id);
    snprintf(b, sizeof b, "fw_t_%s_b", t->id);
    fw_status st;
    if ((st = node(nf, geo, a, t->east - kBehind * te, t->north - kBehind * tn, err)) ||
        (st = node(nf, geo, b, t->east + tl * te, t->north + tl * tn, err)))
        return st;
    fprintf(ef, "    <edge id=\"fw_t_%s\" from=\"%s\" to=\"%s\" numLanes=\"1\" speed=\"30\" "
                "width=\"%.1f\" allow=\"custom1\" spreadType=\"center\"/>\n",
            t->id, a, b, fmax(t->breadth, 10.0));
    /* one string for maxSpeed and departSpeed: SUMO refuses a departure
     * faster than the type's maximum by a rounding digit */
    snprintf(v, sizeof v, "%.6f", t->speed);
    fprintf(rf, "    <vType id=\"" TARGET_TYPE_PREFIX "%s\" vClass=\"custom1\" guiShape=\"ship\" "
                "length=\"%.3f\" width=\"%.3f\" maxSpeed=\"%s\" speedFactor=\"1\" sigma=\"0\" "
                "accel=\"1\" decel=\"1\" minGap=\"0\" color=\"0.2,0.4,0.9\"/>\n",
            t->id, t->length, t->breadth, v);
    /* departPos is the front bumper: hull centre at the start point */
    fprintf(rf, "    <vehicle id=\"%s\" type=\"" TARGET_TYPE_PREFIX "%s\" depart=\"0\" "
                "departLane=\"0\" departPos=\"%.3f\" departSpeed=\"%s\">\n"
                "        <route edges=\"fw_t_%s\"/>\n    </vehicle>\n",
            t->id, t->id, kBehind + 0.5 * t->length, v, t->id);
    return FW_OK;
}

/* Plain XML for the own ship's leg and every target's track, and the routes
 * of the targets (see source_sumo.h). */
static fw_status write_tracks(const fw_sumo_source_def *d, fw_error *err)
{
    char np[1200], ep[1200], rp[1200];
    fw_status st;
    if ((st = fw_path(np, sizeof np, err, "%s/tracks.nod.xml", d->dir)) ||
        (st = fw_path(ep, sizeof ep, err, "%s/tracks.edg.xml", d->dir)) ||
        (st = fw_path(rp, sizeof rp, err, "%s/targets.rou.xml", d->dir)))
        return st;
    const char *path[3] = {np, ep, rp};
    char tmp[3][1300] = {{0}};
    FILE *f[3] = {NULL, NULL, NULL};
    for (int i = 0; i < 3 && !st; i++)
        if (!(f[i] = fw_file_begin(path[i], tmp[i], sizeof tmp[i], err)))
            st = err->status;
    if (st) {
        for (int i = 0; i < 3; i++)
            fw_file_abort(f[i], tmp[i]);
        return st;
    }
    FILE *nf = f[0], *ef = f[1], *rf = f[2];
    fw_geo *geo = NULL;
    if (d->proj)
        st = fw_geo_create_proj(d->proj, d->proj_off_e, d->proj_off_n, &geo, err);
    fprintf(nf, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- written by fairway run: "
                "straight tracks of the own ship and the explicit targets%s -->\n<nodes>\n",
            geo ? " (x longitude, y latitude: the network's plane projects them)" : "");
    fprintf(ef, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<edges>\n");
    fprintf(rf, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<routes>\n");
    const fw_target *o = &d->own;
    double se = sin(o->course), ce = cos(o->course);
    double len = fmax(d->own_leg, o->speed * d->duration) + kBeyond;
    if (!st)
        st = node(nf, geo, "fw_own_a", o->east - kBehind * se, o->north - kBehind * ce, err);
    if (!st)
        st = node(nf, geo, "fw_own_b", o->east + len * se, o->north + len * ce, err);
    fprintf(ef, "    <edge id=\"fw_own\" from=\"fw_own_a\" to=\"fw_own_b\" numLanes=\"1\" "
                "speed=\"30\" width=\"%.1f\" allow=\"ship\" spreadType=\"center\"/>\n",
            fmax(o->breadth, 10.0));
    for (int i = 0; !st && i < d->n_targets; i++)
        st = write_target(nf, ef, rf, geo, &d->targets[i], d->duration, err);
    fw_geo_destroy(geo);
    fprintf(nf, "</nodes>\n");
    fprintf(ef, "</edges>\n");
    fprintf(rf, "</routes>\n");
    for (int i = 0; i < 3; i++)
        if (st)
            fw_file_abort(f[i], tmp[i]);
        else
            st = fw_file_commit(f[i], tmp[i], path[i], err);
    return st;
}

/* A network's demand as a route file in dir (drou). */
static fw_status write_demand(const fw_sumo_source_def *d, const fw_network_files *nf,
                              const char *drou, double *lane_change_s, fw_error *err)
{
    fw_demand dm;
    fw_demand_def dd = fw_default_demand_def();
    dd.density = d->density;
    /* the fill is given at density 1 and scales with it, as the arrivals do:
     * a study sweeping density starts each run near its own steady state */
    dd.fill = (int)lround(d->fill * d->density);
    dd.end = d->duration + d->step;
    dd.seed = d->seed;
    fw_status st = fw_demand_load(nf->demand, &dm, err);
    *lane_change_s = dm.lane_change_s;
    return st ? st : fw_demand_write(&dm, &dd, drou, err);
}

/* The run's files: the demand's routes, and the network SUMO reads (the
 * network's own, or built with the targets' tracks). */
static fw_status prepare_files(const fw_sumo_source_def *d, const fw_network_files *nf,
                               bool tracks, sumo_files *f, fw_error *err)
{
    char nodes[2400] = "tracks.nod.xml", edges[2400] = "tracks.edg.xml", nlog[1200];
    const char *types = NULL;
    fw_status st;
    if ((st = fw_path(f->routes, sizeof f->routes, err, "%s/targets.rou.xml", d->dir)))
        return st;
    if (nf) {
        /* the network's own sources and the tracks, built together: one code path */
        char drou[1200];
        if ((st = fw_path(nodes, sizeof nodes, err, "%s,tracks.nod.xml", nf->nodes)) ||
            (st = fw_path(edges, sizeof edges, err, "%s,tracks.edg.xml", nf->edges)) ||
            (st = fw_path(drou, sizeof drou, err, "%s/demand.rou.xml", d->dir)) ||
            (st = write_demand(d, nf, drou, &f->lane_change_s, err)))
            return st;
        types = nf->typ[0] ? nf->typ : NULL;
        st = d->n_targets > 0
                 ? fw_path(f->routes, sizeof f->routes, err, "%s,%s/targets.rou.xml", drou, d->dir)
                 : fw_path(f->routes, sizeof f->routes, err, "%s", drou);
        if (st)
            return st;
        f->has_types = true;
        if ((st = fw_path(f->types, sizeof f->types, err, "%s", nf->types)))
            return st;
    }
    if (!tracks)
        return fw_path(f->net, sizeof f->net, err, "%s", nf->net);
    /* netconvert runs in dir: relative names keep the net.xml independent of
     * the (temporary) run directory's path */
    if ((st = fw_path(f->net, sizeof f->net, err, "%s/run.net.xml", d->dir)) ||
        (st = fw_path(nlog, sizeof nlog, err, "%s/netconvert.log", d->dir)))
        return st;
    return fw_netconvert(d->dir, nodes, edges, types, d->proj, "run.net.xml", nlog, err);
}

fw_status fw_sumo_prepare(const fw_sumo_source_def *d, sumo_files *f, fw_error *err)
{
    bool has_net = d->network && d->network[0];
    /* Traffic on a network alone needs no track edges (moveToXY places the own
     * ship anywhere): the built network is used as it is, which spares a
     * netconvert per run in a sweep. */
    bool tracks = d->n_targets > 0 || !has_net;
    /* the lists below are joined with commas: none may be in a path */
    fw_status st = fw_sumo_path_check("the run directory", d->dir, err);
    fw_network_files *nf = has_net ? calloc(1, sizeof *nf) : NULL;
    if (has_net && !nf)
        return fw_fail(err, FW_ERUN, "out of memory");
    if (st || (has_net && ((st = fw_sumo_path_check("FAIRWAY_DATA", fw_data_root(), err)) ||
                           (st = fw_network_find(d->network, nf, err)) ||
                           (st = fw_sumo_path_check("the network's directory", nf->dir, err)) ||
                           (st = fw_sumo_path_check("the built network", nf->net, err)))) ||
        (tracks && (st = write_tracks(d, err)))) {
        free(nf);
        return st;
    }
    st = prepare_files(d, nf, tracks, f, err);
    free(nf);
    return st;
}
