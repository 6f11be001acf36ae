/* source_track.h - recorded tracks as a traffic source (source.h): the
 * targets of a run replayed as they moved, whatever the own ship does now.
 *
 * The file is CSV with a header line naming at least
 *   t_s,id,east_m,north_m,course_deg,speed_kn
 * and optionally type,length_m,breadth_m (0 when absent) and
 * turn_rate_degps,turn_to_deg (the turn it was seen making, geom/turn.h: a
 * rate above 0 and the heading it turns to, both empty or both absent for
 * a ship at constant velocity); rows in any order.
 * A ship is where its points put it, linearly between two of them (exact at
 * a recorded time); it exists from its first point to its last and, between
 * two points farther apart than max_gap, not at all (it had left the own
 * ship's sight).  Course and speed are those of the point before, and so is
 * its turn: a point with one gives its record a turn predictor (geom/turn.h)
 * until the next point, so that an own ship replayed among the tracks
 * expects of a turning ship what the original's expected (world/steer.h);
 * a point without one, none (constant velocity).  The ships
 * cannot be told to give way: set_speed does nothing, so a replay is of
 * `blind` traffic (what the ships did, reactions included, is in the track).
 * Nor can they be taken (source.h take: FW_EINPUT): a recording says where a
 * ship is at every later time, so one fairway had steered elsewhere could
 * not rejoin it without a jump.
 *
 * fairway's own runs write such files (the study's worst cases: `fairway
 * worst`).  AIS reports (ais/ais_track.h) replay through the same source,
 * built from tracks in memory (fw_track_source_create), with a max_gap of
 * minutes: AIS ships report seconds to minutes apart.
 */
#ifndef FW_TRAFFIC_SOURCE_TRACK_H
#define FW_TRAFFIC_SOURCE_TRACK_H

#include "geom/turn.h"
#include "traffic/source.h"

/* One recorded point: time, hull centre, course (rad, grid), speed (m/s),
 * and the turn it was making: rate (rad/s, 0: none, constant velocity) and
 * the heading it turns to (rad). */
typedef struct fw_rec_point {
    double t, east, north, course, speed;
    double turn_rate, turn_to;
} fw_rec_point;

/* One ship's points, any order (the source sorts them). */
typedef struct fw_rec_track {
    fw_target info;    /* id, type, length, breadth */
    fw_rec_point *p;   /* malloc'd */
    int n, cap;
} fw_rec_track;

/* Room for one more point in tr (false: out of memory, tr as it was). */
bool fw_rec_track_reserve(fw_rec_track *tr);
/* Frees n tracks' points and the array (safe on NULL). */
void fw_rec_tracks_free(fw_rec_track *tracks, int n);

typedef struct fw_replay_def {
    const char *file;    /* the CSV (fw_replay_source_create only) */
    double step;         /* s, > 0 */
    double radius;       /* m, sight (hull centre to hull centre); INFINITY = all */
    double max_gap;      /* s, 1.5: points farther apart are two passes */
} fw_replay_def;

fw_replay_def fw_default_replay_def(void);

/* The tracks of a track file (the CSV above) into *tracks (malloc'd, n of
 * them, points in file order; fw_rec_tracks_free): FW_EINPUT as below. */
fw_status fw_rec_tracks_load(const char *file, fw_rec_track **tracks, int *n, fw_error *err);

/* FW_EINPUT naming FILE:LINE for a row that cannot be read (a missing
 * column, a number that is not one, a time twice for one ship). */
fw_status fw_replay_source_create(const fw_replay_def *def, fw_source **out, fw_error *err);

/* The same source from n tracks in memory, which it takes over (freed by
 * it, also on failure).  FW_EINPUT for an empty or duplicate id, a
 * non-finite value or two points of one ship at one time (`what` names the
 * tracks' origin in the message). */
fw_status fw_track_source_create(fw_rec_track *tracks, int n, const fw_replay_def *def,
                                 const char *what, fw_source **out, fw_error *err);

#endif
