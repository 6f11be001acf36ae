/* backend.h - the table of operations traffic_sumo.cpp provides, once per SUMO
 * library.  Internal to src/traffic.
 *
 * Each compilation of traffic_sumo.cpp is a loadable module of its own
 * (fairway-libsumo.so, fairway-libtraci.so in fw_module_dir()), opened on
 * first use by fw_sumo_backend_load: a process that never simulates never
 * pays for linking SUMO's few hundred shared libraries.
 *
 * Values cross this boundary raw, in SUMO's own terms (front bumper, degrees);
 * traffic.c converts them.  Each function returns an fw_status and fills err;
 * no C++ exception ever leaves it.
 */
#ifndef FW_TRAFFIC_BACKEND_H
#define FW_TRAFFIC_BACKEND_H

#include <stdbool.h>

#include "core/error.h"
#include "traffic/traffic.h"

typedef struct fw_sumo_raw {
    char id[64];
    char type[64];
    double x, y;      /* front bumper, SUMO coordinates */
    double angle_deg; /* SUMO angle: navigational degrees */
    double speed, length, width;
    /* The back end's number for this ship, 1, 2, ..., one ship's only for
     * the simulation (ids are interned by it, core/idmap.h); 0 = none. */
    int key;
} fw_sumo_raw;

/* A growable array the back end fills. */
typedef struct fw_sumo_list {
    fw_sumo_raw *v;
    int n, cap;
} fw_sumo_list;

typedef struct fw_sumo_backend {
    const char *name;
    /* libsumo: start the simulation with argv; libtraci: connect to host:port. */
    fw_status (*start)(const char *const *argv, fw_error *err);
    fw_status (*connect)(const char *host, int port, int retries, fw_error *err);
    double (*step_length)(void);
    /* Own ship: vType, route on edge (NULL: pick one), vehicle, and the POI
     * whose context subscription is the range query. */
    fw_status (*add_own)(const char *id, double length, double width, const char *edge,
                         double radius, fw_error *err);
    fw_status (*place)(const char *id, double fx, double fy, double angle_deg, double cx,
                       double cy, fw_error *err);
    /* Holds a ship's speed (m/s); speed < 0 hands it back to SUMO's model. */
    fw_status (*set_speed)(const char *id, double speed, fw_error *err);
    /* Takes a ship out of the simulation. */
    fw_status (*remove)(const char *id, fw_error *err);
    fw_status (*step)(double *time, fw_error *err);
    fw_status (*context)(fw_sumo_list *out, fw_error *err);
    fw_status (*all)(fw_sumo_list *out, fw_error *err);
    fw_status (*get)(const char *id, fw_sumo_raw *out, fw_error *err);
    /* sumo-gui only: with zoom, the view view_m wide about (x, y); then, at
     * every call, following ship id. */
    fw_status (*gui_follow)(const char *id, double x, double y, double view_m, bool zoom,
                            fw_error *err);
    /* sumo-gui only: a PNG of the view, written at the next step. */
    fw_status (*gui_screenshot)(const char *file, int width, int height, fw_error *err);
    /* The network SUMO runs: its boundary (xmin, ymin, xmax, ymax) and
     * its normal (not internal) edge ids, sorted, one "\n" after each, in
     * *ids (malloc'd, the caller frees). */
    fw_status (*net)(double box[4], char **ids, fw_error *err);
    void (*close)(void);
    /* A ship fairway moves itself (a replayed AIS ship, traffic.h
     * fw_traffic_add_placed): its own vType of this size and a vehicle on the
     * own ship's route, placed by `place` from then on. */
    fw_status (*add_placed)(const char *id, double length, double width, fw_error *err);
    /* A background ship handed to fairway (traffic.h fw_traffic_take): any
     * speed it was told released; `place` moves it from then on. */
    fw_status (*take)(const char *id, fw_error *err);
    /* ... and given back: the lane of its route ahead nearest (fx, fy) and
     * how far its line is (*off, m); if within max_off, the ship moved onto
     * it there (moveToXY, keepRoute 1) with speed as its last; else
     * FW_EINPUT saying how far. */
    fw_status (*rejoin)(const char *id, double fx, double fy, double angle_deg, double speed,
                        double max_off, double *off, fw_error *err);
    /* A ship's lane (source.h fw_lane_info) in SUMO's coordinates: the centre
     * lines of the lanes of its route from the edge it is on, each at its
     * lane index (clamped to the edge's lanes), up to max points (xy: x, y
     * pairs) or about 30 km; and from its line (its lateral offset in the
     * lane counted) to the right and left sides of its edge, and whether it
     * is in the middle of a lane change (off its lane's line by any amount).
     * FW_EINPUT when it is in a junction now. */
    fw_status (*lane)(const char *id, double *xy, int max, int *n, double *right, double *left,
                      bool *traffic_lane, bool *changing, fw_error *err);
    /* The ships SUMO has loaded but not yet put on a lane (no room where
     * they depart: they wait and are inserted when there is), one "\n"
     * after each id, in *ids (malloc'd, the caller frees). */
    fw_status (*pending)(char **ids, fw_error *err);
} fw_sumo_backend;

/* A remote sumo (where: "HOST:PORT") must run net_file's network: the same
 * boundary and edge ids, else FW_ERUN saying what differs (netcheck.c). */
fw_status fw_traffic_net_check(const fw_sumo_backend *be, const char *net_file,
                               const char *where, fw_error *err);

/* SUMO_DIR/remote-command.txt (SUMO_DIR: the log file's directory): the sumo
 * command line a remote run of d needs, as an sh script run in that directory. */
fw_status fw_traffic_write_remote_command(const fw_traffic_def *d, fw_error *err);

/* SUMO_DIR/run.sumocfg: the run's SUMO inputs (network, routes, types,
 * step, seed, lane changes, 0 to d->end) as a configuration sumo-gui opens,
 * with the view settings file view (NULL: none); paths inside SUMO_DIR
 * relative to it (sumofiles.c). */
fw_status fw_traffic_write_config(const fw_traffic_def *d, const char *view, fw_error *err);

/* What each module exports: a function of this name returning its table. */
#define FW_SUMO_BACKEND_ENTRY "fw_sumo_backend_table"
typedef const fw_sumo_backend *(*fw_sumo_backend_entry)(void);

/* The libsumo (libtraci false) or libtraci back end, its module opened at the
 * first call and kept for the process's life (SUMO cannot be unloaded).
 * FW_ERUN naming the module's path and the loader's reason when it cannot be
 * opened.  Safe to call from several threads. */
fw_status fw_sumo_backend_load(bool libtraci, const fw_sumo_backend **be, fw_error *err);

#endif
