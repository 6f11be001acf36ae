/* netshape.h - a built network's edges as lines on the water, read from its
 * net.xml (the file netconvert built from the sources, netbuild.h).
 *
 * Each normal edge (one direction of a fairway between two junctions) has
 * lanes side by side, each a polyline (SUMO's shape, x east and y north in
 * the network's plane, which is fairway's) and a width.  An edge's centre
 * line is the mean of its lanes' shapes point by point (the middle lane's
 * shape when their point counts differ).  The network's extent is the box of
 * every lane's points, internal (junction) lanes too, widened by half the
 * lane's width; an edge's starboard lane (SUMO's lane 0, the rightmost in
 * its direction) is kept too, for the own ship's route (rule 9(a)): the water the network's ships can be on.  Used by the
 * scenario loader for routes given as edges (own_ship.network_route) and to
 * refuse a route far off the network (scenario/scn_netroute.h).
 */
#ifndef FW_TRAFFIC_NETSHAPE_H
#define FW_TRAFFIC_NETSHAPE_H

#include "core/error.h"

typedef struct fw_net_edge {
    char id[64];
    char from[64], to[64]; /* junction ids */
    int n_lanes;
    double width;          /* m, the lanes' widths summed */
    int n;                 /* points of the centre line (>= 2) */
    double *x, *y;         /* m, the centre line */
    int sn;                /* points of the starboard lane's line (>= 2) */
    double *sx, *sy;       /* m, the starboard lane's centre line (SUMO's lane 0, the rightmost) */
    double s_width;        /* m, its width */
} fw_net_edge;

typedef struct fw_net_shape {
    int n;              /* normal edges */
    fw_net_edge *edges;
    double box[4];      /* m: min x, min y, max x, max y of the lanes with their half widths */
} fw_net_shape;

/* Reads the net.xml at path; FW_EINPUT naming the file when it has no
 * normal edge or a lane without a readable shape. */
fw_status fw_net_shape_load(const char *path, fw_net_shape *out, fw_error *err);
void fw_net_shape_free(fw_net_shape *ns);

/* The normal edge of that id, or NULL. */
const fw_net_edge *fw_net_shape_edge(const fw_net_shape *ns, const char *id);

/* m: how far (x, y) lies outside the network's box (0 inside it). */
double fw_net_shape_outside(const fw_net_shape *ns, double x, double y);

#endif
