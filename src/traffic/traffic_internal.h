/* traffic_internal.h - the coupling's state, shared by traffic.c (starting
 * SUMO, stepping it) and traffic_query.c (reading the ships).  Internal to
 * src/traffic. */
#ifndef FW_TRAFFIC_INTERNAL_H
#define FW_TRAFFIC_INTERNAL_H

#include <stdbool.h>
#include <sys/types.h>

#include "core/idmap.h"
#include "traffic/backend.h"
#include "traffic/hull_track.h"
#include "traffic/fcd.h"
#include "traffic/traffic.h"

/* m, half the length of the longest ship there is (a 400 m ULCV, with room):
 * a ship whose hull centre is within the area has its front bumper, SUMO's
 * position, within area_radius + this. */
#define FW_TRAFFIC_HALF_LENGTH_MAX 500.0

struct fw_traffic {
    const fw_sumo_backend *be;
    fw_traffic_def def;
    char own_id[64];
    char log_file[1024];
    pid_t child; /* sumo-gui started here, or 0 */
    struct fw_traci_guard *guard; /* libtraci's relay to the peer (traci_guard.h), or NULL */
    char screenshot[1024]; /* gui: the PNG taken at the end ("" none) */
    bool zoomed;           /* gui: the view is zoomed on the own ship */
    bool placed, dead;
    double time;
    long steps;
    fw_fcd *fcd;           /* def.fcd_file's writer, or NULL */
    long fcd_every;        /* steps between two of its timesteps */
    double query_radius;   /* m, of the range query */
    double own_x, own_y, own_heading, own_speed; /* as last placed: the query's centre */
    fw_sumo_list raw;      /* fw_traffic_all */
    fw_sumo_list ctx;      /* the context results of step ctx_step */
    long ctx_step;
    fw_target *ships;
    int ships_cap;
    fw_target *area;
    int area_cap;
    fw_target *near;
    int near_cap;
    /* near[0..near_n-1] is the nearby query of context step near_step about
     * (near_x, near_y) (-1: none): asked again unchanged, it is that */
    long near_step;
    int near_n;
    double near_x, near_y;
    long near_answer;      /* how many times near was made (fw_traffic_nearby_answer) */
    fw_target *conv;       /* the context results converted (and motion followed) */
    int conv_cap;
    /* the hull centre of every ship at its last context step, by id: its
     * motion over a step on a bend or across a lane change */
    fw_idmap ids;
    double *last_e, *last_n;
    long *last_step;
    /* and SUMO's angle then (NAN: none yet) with its sine and cosine, reused
     * while the angle stays (a ship on a straight lane) */
    double *last_angle, *last_sin, *last_cos;
    fw_hull_track *tracks;  /* each ship's bow track (hull_track.h) */
    double *seed_heading;   /* rad, a given-back ship's heading for its new track; NAN: none */
    double *last_bx, *last_by; /* m, SUMO's bumper at the last context step */
    double *off_x, *off_y;  /* m, the track's bow less SUMO's bumper (traffic_query.c) */
    double *dir_x, *dir_y;  /* the unit direction of the bumper's last clean step (traffic_query.c) */
    unsigned char *turned;  /* SUMO's angle changed at the last conversion */
    int *last_k;            /* its index in the context results of its last step */
    int last_cap;
};

/* FW_ERUN once SUMO failed: nothing more is asked of it. */
fw_status fw_traffic_alive(const fw_traffic *t, fw_error *err);
/* The range query's results of the present step, read from SUMO once per
 * step (traffic_query.c). */
fw_status fw_traffic_context(fw_traffic *t, fw_error *err);

#endif
