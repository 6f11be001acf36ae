/* ais_routes.h - what AIS demand needs of a network: each stream's route as a
 * line in the plane, and the ship types its ships can be.
 *
 * Routes: the edges a stream of networks/NAME/demand.yaml names, each the
 * straight line from its from-node to its to-node (or its shape), from the
 * network's plain-XML sources NAME.nod.xml and NAME.edg.xml (the frame SUMO
 * runs in: netconvert keeps the node coordinates).
 *
 * Types: the vTypes of networks/ships.add.xml with their length and service
 * speed (the mean of the speedFactor, normc(MEAN, ...) or a number, times
 * the fastest lane speed of NAME.typ.xml: SUMO's desired speed).
 */
#ifndef FW_AIS_ROUTES_H
#define FW_AIS_ROUTES_H

#include "core/error.h"
#include "traffic/demand.h"

enum { FW_ROUTE_MAX_POINTS = 64, FW_MAX_VTYPES = 64 };

typedef struct fw_route_line {
    int n;                           /* points */
    double x[FW_ROUTE_MAX_POINTS], y[FW_ROUTE_MAX_POINTS];
    double length;                   /* m */
} fw_route_line;

typedef struct fw_vtype_info {
    char id[64];
    double length; /* m */
    double speed;  /* m/s, service speed */
} fw_vtype_info;

typedef struct fw_net_routes {
    char name[64];
    fw_demand demand;                       /* the network's own */
    fw_route_line line[FW_DEMAND_MAX_STREAMS]; /* per stream */
    fw_vtype_info vtypes[FW_MAX_VTYPES];
    int n_vtypes;
} fw_net_routes;

/* The routes and types of network name.  FW_EINPUT for an unknown network,
 * an edge or node its files do not have. */
fw_status fw_net_routes_load(const char *name, fw_net_routes *out, fw_error *err);

/* Distance (m) of (x, y) from the line and how far along it (m) the nearest
 * point lies. */
double fw_route_distance(const fw_route_line *r, double x, double y, double *along);

#endif
