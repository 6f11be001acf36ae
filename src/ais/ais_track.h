/* ais_track.h - AIS reports as recorded tracks in the scenario's plane.
 *
 * Every kept report (ais.h) of a time window and an area is projected onto
 * the plane of an origin (geo.h, transverse Mercator) and filed under its
 * MMSI; each ship's points are then sorted by time.  What the sorting meets
 * is counted: rows that came earlier than their ship's previous row (out of
 * order: kept, in their place) and a second report of a ship at a time it
 * already has (a duplicate: dropped).  A second report at that time more than
 * FW_AIS_CLASH_M from the first is not a repeat but two ships sending one
 * MMSI (a misconfigured transponder, a copied MMSI): it is dropped too (one
 * id, one ship in the replay) but counted apart, with the MMSIs it hit and
 * the first of them.  A report the plane cannot hold (PROJ fails: e.g. 90
 * deg of longitude from the origin) is skipped and counted, with FILE:LINE of
 * the first, like the reader's bad rows.
 *
 * A point's course is the report's COG, else its heading, turned from true
 * to grid course (minus the meridian convergence there); its speed the SOG.
 * Where they are not available, the motion to the ship's next point (or from
 * the previous one, for its last) gives them, when that point is within
 * max_gap; else the course is kept from a neighbour and the speed is 0.
 *
 * A ship's id is its MMSI, its type the kind of ship (ais.h: "cargo", ...),
 * its length A + B and breadth C + D (the last report that gives them).
 * Times are seconds from t0, the window's start (the run's t = 0).
 *
 * The tracks replay through source_track.h (fw_track_source_create):
 * positions linearly interpolated in time between the projected reports, a
 * ship absent between two reports farther apart than max_gap.
 */
#ifndef FW_AIS_TRACK_H
#define FW_AIS_TRACK_H

#include "ais/ais.h"
#include "traffic/source_track.h"

/* m: two reports of one MMSI at one instant farther apart are two ships.  A
 * repeat of one report (two base stations) is at the same place; a ship at
 * 30 kn moves 15 m in the second a DMA timestamp rounds to; two ships on one
 * MMSI are typically kilometres apart. */
#define FW_AIS_CLASH_M 50.0

typedef struct fw_ais_track_def {
    double origin_lat, origin_lon; /* deg: the plane, a transverse Mercator about it ... */
    const char *proj;              /* ... or this PROJ string (a geo-referenced network's) */
    double off_e, off_n;           /*     with its netOffset (geom/geo.h fw_geo_create_proj) */
    const fw_ais_columns *cols;    /* NULL: DMA */
    /* The window, UTC seconds; with start_rel / end_rel, seconds after the
     * file's earliest kept report instead.  NAN: from the first / to the
     * last report. */
    double start, end;
    bool start_rel, end_rel;
    double max_gap;     /* s, reports farther apart are two passes (300) */
    double area_radius; /* m, reports farther from the origin are dropped (100 km) */
} fw_ais_track_def;

/* No window, max_gap 300 s, area 100 km; the origin must be set. */
fw_ais_track_def fw_default_ais_track_def(void);

/* Per ship, beside its track. */
typedef struct fw_ais_ship {
    long mmsi;
    bool class_b;
    fw_ais_kind kind;
    int type_code;
} fw_ais_ship;

typedef struct fw_ais_tracks {
    fw_rec_track *v;      /* n tracks, sorted by id; t in s from t0 */
    fw_ais_ship *ships;   /* n */
    int n;
    double t0;            /* s UTC, the window's start */
    double t_end;         /* s from t0, the window's end (or the last point) */
    double max_gap;       /* s, the def's */
    fw_ais_counts counts; /* the reader's */
    long out_of_order, duplicates, outside_window, outside_area;
    long clashes;         /* of the duplicates: another ship at that instant (FW_AIS_CLASH_M) */
    int clash_ships;      /* MMSIs with clashes */
    long clash_first;     /* the first such MMSI (in id order), 0: none */
    long unprojected;     /* reports the plane cannot hold: skipped */
    char unprojected_at[560]; /* "FILE:LINE" of the first, "" when none */
    long points;          /* in the tracks */
} fw_ais_tracks;

/* Reads path into out (which the caller frees with fw_ais_tracks_free, also
 * after a failure).  FW_EINPUT: the reader's errors, a bad origin, an empty
 * window. */
fw_status fw_ais_tracks_load(const char *path, const fw_ais_track_def *def, fw_ais_tracks *out,
                             fw_error *err);
void fw_ais_tracks_free(fw_ais_tracks *t);

/* The tracks as a replay source (source_track.h): the tracks are handed over
 * (out->v becomes NULL). */
fw_status fw_ais_replay_source_create(fw_ais_tracks *t, const fw_replay_def *def,
                                      fw_source **out, fw_error *err);

/* The tracks in the track-file layout (t_s,id,east_m,north_m,course_deg,
 * speed_kn,type,length_m,breadth_m), written under a temporary name and
 * renamed: never a partial file. */
fw_status fw_ais_tracks_write_csv(const fw_ais_tracks *t, const char *path, fw_error *err);

/* The same to an open stream (stdout). */
fw_status fw_ais_tracks_print_csv(const fw_ais_tracks *t, FILE *f, fw_error *err);

/* The counts of the reading and the tracking as "what: N" lines. */
void fw_ais_tracks_print(FILE *out, const fw_ais_tracks *t);

#endif
