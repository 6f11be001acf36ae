/* demand.h - background traffic as a SUMO route file, written per run.
 *
 * A network's streams (networks/NAME/demand.yaml: id, edges, ships per hour at
 * density 1, ship type or type distribution) become flows with Poisson arrivals
 * (SUMO's period="exp(RATE)", or for rates below 3.6 an hour a per-second
 * insertion probability: see demand.c) whose rates scale with a density factor, so a
 * study varies traffic without editing files.  Optionally `fill` ships start
 * spread along the routes, so a run begins near steady state instead of with
 * an empty waterway.
 */
#ifndef FW_DEMAND_H
#define FW_DEMAND_H

#include <stddef.h>

#include "core/error.h"

#define FW_DEMAND_MAX_STREAMS 32
/* 1/s: flows slower than this are written as an insertion probability per
 * second, not exp(RATE) (demand.c says why) */
#define FW_SUMO_EXP_RATE_MIN 1e-3
#define FW_DEMAND_MAX_EDGES 16

typedef struct fw_stream {
    char id[64];
    char types[64]; /* vType or vTypeDistribution id (networks/ships.add.xml) */
    int n_edges;
    char edges[FW_DEMAND_MAX_EDGES][64];
    double per_hour; /* ships per hour at density 1 */
    int edge_line[FW_DEMAND_MAX_EDGES]; /* demand.yaml's line of each edge */
} fw_stream;

typedef struct fw_demand {
    char file[512];
    /* s, how long a lane change takes on this network (demand.yaml's
     * lane_change_s: the widest lane crossed at about 1 m/s); 0 = not said */
    double lane_change_s;
    int n;
    fw_stream streams[FW_DEMAND_MAX_STREAMS];
} fw_demand;

typedef struct fw_demand_def {
    double density;     /* multiplies every rate; 0: no flows */
    double begin, end;  /* s, when the flows run */
    int fill;           /* ships placed along the routes at time 0 */
    unsigned long seed; /* chooses the fill ships' streams' edges */
} fw_demand_def;

/* density 1, 0 .. 86400 s, no fill, seed 1. */
fw_demand_def fw_default_demand_def(void);

/* Reads a demand.yaml; errors name file, line and field. */
fw_status fw_demand_load(const char *path, fw_demand *out, fw_error *err);

/* Writes the route file for d under def to path. */
fw_status fw_demand_write(const fw_demand *d, const fw_demand_def *def, const char *path,
                          fw_error *err);

/* The files of a network: its sources, its demand.yaml, the ship types and
 * the net.xml built from the sources.  `name` is a network's name (letters,
 * digits, '_', '-': the directory DATA/networks/NAME) or a directory's path
 * (holding a '/'; its last part is the name).  The directory holds
 * NAME.nod.xml and NAME.edg.xml (required), NAME.typ.xml and NAME.proj
 * (optional), demand.yaml, and may hold its own ships.add.xml (else
 * DATA/networks/ships.add.xml).  The net.xml is built on first use into the
 * network cache and again whenever a source changes (netbuild.h
 * fw_network_build).  FW_EINPUT naming the directory and the missing file, or
 * quoting netconvert, when there is no such network or it cannot be built. */
typedef struct fw_network_files {
    char name[64];
    char dir[1024];    /* the sources' directory */
    char nodes[1100];  /* DIR/NAME.nod.xml */
    char edges[1100];  /* DIR/NAME.edg.xml */
    char typ[1100];    /* DIR/NAME.typ.xml, "" when there is none */
    char proj[512];    /* NAME.proj's PROJ string, "" when there is none */
    char net[1200];    /* the built net.xml (in the network cache) */
    char demand[1100];
    char types[1100];
} fw_network_files;
fw_status fw_network_find(const char *name, fw_network_files *out, fw_error *err);
/* A geo-referenced network's plane: the PROJ string netconvert projected its
 * nodes with (the net.xml's <location projParameter>; "" for a network drawn
 * in metres) into proj, and its netOffset.  A scenario on such a network is in
 * its plane (geom/geo.h fw_geo_create_proj). */
fw_status fw_network_plane(const fw_network_files *nf, char *proj, size_t n, double *off_e,
                           double *off_n, fw_error *err);
/* Every edge the demand's streams name is an edge of the network's sources
 * (its NAME.edg.xml): else FW_EINPUT at the demand's line and field, before
 * SUMO is started for nothing. */
fw_status fw_network_check_demand(const fw_network_files *nf, const fw_demand *dm, fw_error *err);

/* Total ships per hour at density 1. */
double fw_demand_rate(const fw_demand *d);

#endif
