/* traffic.h - background ships from SUMO, and the own ship as a SUMO vehicle.
 *
 * The only door to SUMO.  Back ends: libsumo in-process ("embedded", default),
 * libtraci to a sumo someone else started ("remote:HOST:PORT"), or libtraci to
 * a sumo-gui started here ("gui").  Every SUMO failure comes back as an
 * fw_status and message; nothing throws or aborts.
 *
 * Ships come back as fw_target (geom/target.h), the one ship record: SUMO's
 * front bumper and angle are converted here, once.
 * Frame: metres east (x) and north (y) in the SUMO network's coordinates.
 * fairway's networks are built with normalisation off, so these are exactly the
 * coordinates of networks/NAME/NAME.nod.xml.  Headings are navigational radians
 * (0 north, clockwise), speeds m/s.  SUMO places a vehicle by its front-bumper
 * centre; fairway by the hull centre (midship, Loa/2 abaft the bow):
 * fw_traffic_to_sumo / fw_traffic_from_sumo are the one conversion.
 *
 * Lane changes take lane_change_s (below).  SUMO keeps the angle of a ship
 * changing lanes at its lane's; the traffic layer gives such a ship the
 * direction and speed of its motion instead, so what fairway sees moves like
 * a ship altering course a few degrees to change lanes.
 *
 * The own ship is kept off SUMO's lanes, so SUMO's ships never react to it:
 * they keep their lanes and speeds, and all avoidance is the own ship's.
 *
 * libsumo holds one simulation per process and is not thread-safe: at most one
 * embedded fw_traffic may be open in a process at a time.
 */
#ifndef FW_TRAFFIC_H
#define FW_TRAFFIC_H

#include <stdbool.h>
#include <sys/types.h>

#include "core/error.h"
#include "geom/target.h"

typedef enum fw_traffic_kind {
    FW_TRAFFIC_EMBEDDED, /* libsumo, in this process */
    FW_TRAFFIC_REMOTE,   /* libtraci to a running sumo at host:port */
    FW_TRAFFIC_GUI       /* libtraci to a sumo-gui started by fw_traffic_open */
} fw_traffic_kind;

/* How a sumo-gui started here shows a run, so that it can be watched: at a
 * pace a person can follow, zoomed on the own ship, which the view follows,
 * with the ships drawn to scale in the type colours (the own ship signal
 * orange).  Zero fields take the defaults below. */
typedef struct fw_traffic_gui {
    double delay_ms;        /* wall-clock ms per step at least (sumo-gui's --delay); 0: none */
    int width, height;      /* px, the window (default 1280 x 800) */
    double view_m;          /* m, width of the view about the own ship (default 3 nm) */
    bool keep;              /* leave the window open at the end; fw_traffic_close waits
                             * until it is closed */
    const char *settings;   /* view settings file; NULL: DATA/networks/fairway.view.xml */
    const char *screenshot; /* a PNG of the view written at the end (NULL: none) */
} fw_traffic_gui;

typedef struct fw_traffic_mode {
    fw_traffic_kind kind;
    char host[256]; /* remote only */
    int port;       /* remote only */
    /* s, remote only: the connect and the reply timeout (traci_guard.h), from
     * FAIRWAY_SUMO_TIMEOUT; 0: the defaults (10 s to connect, 60 s a reply) */
    double timeout;
    fw_traffic_gui gui; /* gui only */
} fw_traffic_mode;

/* "embedded", "gui" or "remote:HOST:PORT" (port 1..65535); gui settings zero.
 * Remote: FAIRWAY_SUMO_TIMEOUT, when set, is the seconds (0.1 to 86400) the
 * peer has to accept the connection and to begin each answer (a bad value:
 * FW_EINPUT naming the variable). */
fw_status fw_traffic_mode_parse(const char *text, fw_traffic_mode *out, fw_error *err);
/* Can a sumo-gui open a window here?  FW_EINPUT at once, naming opt, when
 * there is no display ($DISPLAY unset): sumo-gui would only fail to start. */
fw_status fw_traffic_gui_check(const char *opt, fw_error *err);

typedef struct fw_traffic_def {
    fw_traffic_mode mode;
    /* What sumo loads (embedded and gui; a remote sumo has its own). */
    const char *net_file;    /* required for embedded and gui */
    const char *route_file;  /* NULL: no background traffic */
    const char *add_file;    /* NULL: none; normally networks/ships.add.xml */
    const char *log_file;    /* SUMO's messages; NULL: discarded */
    /* SUMO's floating car data of every ship, its front bumper, every
     * fcd_period s (SUMO's --fcd-output); NULL: none */
    const char *fcd_file;
    double fcd_period;       /* s, 0 = every step */
    double end;              /* s, the run's end (the replay's), 0 = open */
    double step;             /* s, SUMO step length = controller step */
    /* s, how long a lane change takes (SUMO's --lanechange.duration): by
     * default SUMO moves a ship into the next lane in one step, 900 m sideways
     * across the strait's lanes.  900 s: 1 m/s across those 900 m lanes,
     * 0.28 m/s across the 250 m fairway lanes; 0 = SUMO's instant change. */
    double lane_change_s;
    unsigned long seed;
    const char *sumo_gui;    /* program for gui mode */
    double connect_timeout;  /* s, libtraci connection attempts (about 1 per s) */
    /* s, remote mode: the longest a request may wait for the start of its
     * answer, or between two parts of it (traci_guard.h), 60 s; a sumo-gui
     * started here has none (its user may pause it) */
    double reply_timeout;
    /* The own ship. */
    const char *own_id;
    double own_length;       /* m, Loa */
    double own_width;        /* m, B */
    const char *own_edge;    /* NULL: the first edge that allows ships */
    /* The queries. */
    double radius;           /* m, fw_traffic_around: own hull centre to front bumpers (SUMO) */
    double area_radius;      /* m, fw_traffic_area: hull centre to hull centre; 0 = no area */
    double near_radius;      /* m, fw_traffic_nearby: hull centre to hull centre; 0 = none */
} fw_traffic_def;

/* embedded, step 1 s, seed 1, lane changes 900 s, radius 6 nm, no area, own ship
 * "own" 100 x 16 m. */
fw_traffic_def fw_default_traffic_def(void);

/* Hull centre and heading <-> SUMO front bumper and angle (degrees). */
void fw_traffic_to_sumo(double x, double y, double heading, double length, double *fx,
                        double *fy, double *angle_deg);
void fw_traffic_from_sumo(double fx, double fy, double angle_deg, double length, double *x,
                          double *y, double *heading);
/* The same with the sine sh and cosine ch of the angle in radians known
 * (computed once for a ship whose angle stays). */
void fw_traffic_from_sumo_sc(double fx, double fy, double angle_deg, double sh, double ch,
                             double length, double *x, double *y, double *heading);

typedef struct fw_traffic fw_traffic;

/* The SUMO vehicle type of the own ship. */
#define FW_TRAFFIC_OWN_TYPE "fw_own_type"

/* Loads SUMO for kind now (libsumo, or libtraci for remote and gui) instead
 * of at the first fw_traffic_open: a process that forks its runs loads it
 * once, and every child inherits it.  FW_ERUN when the back end's module
 * cannot be loaded.  Commands that do not simulate never load SUMO. */
fw_status fw_traffic_load(fw_traffic_kind kind, fw_error *err);

/* Starts or connects to SUMO, adds the own ship's type, route and vehicle and
 * the range query: one query of radius max(radius, area_radius or
 * near_radius + the half length of the longest ship), read once a step (a
 * context subscription over libtraci, getters and SUMO's own range test in
 * libsumo), which the queries filter.  Call
 * fw_traffic_place before the first step. */
fw_status fw_traffic_open(const fw_traffic_def *def, fw_traffic **out, fw_error *err);
/* Ends the simulation (or the connection), stops a sumo-gui started here and
 * frees t.  Safe on NULL and after errors. */
void fw_traffic_close(fw_traffic *t);

/* Places the own ship (hull centre, heading rad, speed m/s) for the next step. */
fw_status fw_traffic_place(fw_traffic *t, double x, double y, double heading, double speed,
                           fw_error *err);
/* Holds background ship id at speed (m/s) from the next step on, within its
 * type's deceleration; speed < 0 hands it back to SUMO's car following. */
fw_status fw_traffic_set_speed(fw_traffic *t, const char *id, double speed, fw_error *err);
/* Takes background ship id out of SUMO; it is left out of the queries of
 * this step already (SUMO lists it until its next step). */
fw_status fw_traffic_remove(fw_traffic *t, const char *id, fw_error *err);
/* The ships loaded that SUMO has not yet put on a lane, for want of room
 * where they depart (fw_traffic_remove takes one out of the queue): their
 * ids, one "\n" after each, in *ids (malloc'd, the caller frees). */
fw_status fw_traffic_pending(fw_traffic *t, char **ids, fw_error *err);
/* Ships fairway moves itself, shown in SUMO (sumo-gui) where fairway puts
 * them: a replayed AIS ship.  add_placed gives ship id (not yet in SUMO) a
 * vType of its size and a vehicle; move places its hull centre (heading
 * rad) for the next step, off the lanes like the own ship (SUMO's ships
 * never react to it); fw_traffic_remove takes it out. */
fw_status fw_traffic_add_placed(fw_traffic *t, const char *id, double length, double width,
                                fw_error *err);
fw_status fw_traffic_move(fw_traffic *t, const char *id, double x, double y, double heading,
                          double length, fw_error *err);
/* Background ship id handed to fairway: whatever speed it was told is
 * released, and fw_traffic_move places it from then on (off the lanes, like
 * the own ship: SUMO's ships never brake for it; SUMO's reads of it are
 * stale until it is given back, so the caller lists it as it placed it). */
fw_status fw_traffic_take(fw_traffic *t, const char *id, fw_error *err);
/* Background ship id's lane (source.h fw_lane_info): up to max points of the
 * centre line of its lane along its route ahead into xy (east, north pairs,
 * SUMO's plane is fairway's) and the room from its line to the right
 * (starboard) and left (port) sides of its edge; *traffic_lane: its edge is
 * a separation scheme's traffic lane (the network's edge carries the
 * parameter fairway.traffic_lane = true, networks/README.md); *changing: it
 * is in the middle of a lane change (SUMO's lateral offset in its lane is
 * not 0: a ship taken then leaves its lane change's shadow on the lane it
 * was crossing into, a stopped ship to SUMO's ships there, as long as it is
 * steered; measured, strait-domain seed 6, replication 8).  FW_EINPUT when
 * it is in a junction now. */
fw_status fw_traffic_lane(fw_traffic *t, const char *id, double *xy, int max, int *n,
                          double *right, double *left, bool *traffic_lane, bool *changing,
                          fw_error *err);
/* ... given back: its hull centre (x, y, heading rad) for the next step
 * mapped onto the nearest lane of its route ahead and moved there, its
 * speed (m/s) as its last, SUMO's car following driving it from then on.
 * FW_EINPUT (nothing changed) when that lane's line is more than max_off m
 * away, the nearest lane is not on its route ahead (its route as taken:
 * SUMO gives a ship steered across another edge's lane line that edge as
 * its route), or a ship in that lane or changing lanes into it would be
 * beside it or ahead within its gap (its type's minGap), or behind it faster
 * than SUMO's safe speed there: SUMO's lane-change model, whose lane change
 * the taken ship did not hinder, stops a ship given back beside one at its
 * emergency rate until the other is a gap ahead, and its car following
 * brakes a ship too close behind at its emergency rate. */
fw_status fw_traffic_give_back(fw_traffic *t, const char *id, double x, double y, double heading,
                               double speed, double length, double max_off, fw_error *err);
/* Advances SUMO by one step. */
fw_status fw_traffic_step(fw_traffic *t, fw_error *err);
/* Ships within the radius of the own ship after the last step, own ship
 * excluded.  *ships points into t and stays valid until the next step. */
fw_status fw_traffic_around(fw_traffic *t, const fw_target **ships, int *n,
                            fw_error *err);
/* Every ship whose hull centre is within area_radius of the own ship's hull
 * centre after the last step, the own ship included (flagged own, as placed:
 * position, heading, the speed given to fw_traffic_place, type
 * FW_TRAFFIC_OWN_TYPE), sorted by id.  The same context results as
 * fw_traffic_around (one query per step); *ships points into t and stays
 * valid until the next step.  FW_ERUN if the def has no area_radius. */
fw_status fw_traffic_area(fw_traffic *t, const fw_target **ships, int *n, fw_error *err);
/* Every background ship whose hull centre is within near_radius of the own
 * ship's, sorted by id (own ship excluded): the ships that give way to each
 * other, watched farther out than the own ship sees so that none comes into
 * sight in the middle of a crossing nobody handled.  The same context
 * results again.  FW_ERUN if the def has no near_radius. */
fw_status fw_traffic_nearby(fw_traffic *t, const fw_target **ships, int *n, fw_error *err);
/* Which answer fw_traffic_nearby last gave: a number that changes whenever
 * it made the list again (the same number: the same list, unchanged). */
long fw_traffic_nearby_answer(const fw_traffic *t);
double fw_traffic_time(const fw_traffic *t); /* s, SUMO time after the last step */

/* For checks, not for the step loop (one SUMO call per ship and variable):
 * every ship in SUMO through the individual getters, own ship included.
 * *ships points into t until the next call. */
fw_status fw_traffic_all(fw_traffic *t, const fw_target **ships, int *n, fw_error *err);
/* One ship by id through the getters. */
fw_status fw_traffic_get(fw_traffic *t, const char *id, fw_target *ship, fw_error *err);

/* FW_EINPUT when path (named by what: "the run directory", "FAIRWAY_DATA",
 * ...) holds a comma: SUMO and netconvert split every file option at commas
 * (fairway joins route files so), and there is no quoting that stops them,
 * so such a path would be read as two files that do not exist. */
fw_status fw_sumo_path_check(const char *what, const char *path, fw_error *err);

/* The command line fairway gives sumo for def (program name first, NULL
 * terminated, at most max entries); extra remote_port > 0 adds --remote-port.
 * Used for the embedded start, for sumo-gui and by tests starting a sumo. */
fw_status fw_traffic_sumo_args(const fw_traffic_def *def, const char *program, int remote_port,
                               const char **argv, int max, char *buf, size_t bufsz,
                               fw_error *err);

/* A free TCP port on localhost (bound and released: a small race remains). */
fw_status fw_traffic_free_port(int *port, fw_error *err);
#endif
