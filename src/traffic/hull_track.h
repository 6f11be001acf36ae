/* hull_track.h - where a SUMO ship's hull is, from the track its bow has
 * sailed.
 *
 * SUMO gives a ship's front bumper and its lane's direction there.  Placing
 * the hull behind the bumper along that direction turns the whole hull about
 * its bow wherever the lane turns: at a 30 deg bend SUMO's angle jumps as the
 * bumper enters the next edge, and the hull centre of a 300 m ship swings
 * 75 m sideways in one step (the audit measured up to 33 m/s sideways on a
 * bent channel), which no ship can do.  A ship's stern follows its bow's
 * track instead: this module keeps the bow's track (points at least
 * kMinStep apart, with their distance along it) and puts the stern on it one
 * hull length behind the bow, measured along the track.  The hull lies on
 * the chord from stern to bow: its heading is the chord's direction, its
 * centre the chord's middle.  Round a bend the heading turns as the bow
 * sails one length, 30 deg in 50 s for a 300 m ship at 12 kn (0.6 deg/s,
 * within a large ship's turning rate); across a lane change the hull turns
 * with the bow's sideways motion; on a straight lane the chord is the lane's
 * line and nothing changes.  A new track (a ship first seen, or back after
 * a gap) starts as a straight line behind the bow along the given heading.
 */
#ifndef FW_HULL_TRACK_H
#define FW_HULL_TRACK_H

#include <stdbool.h>

typedef struct fw_hull_track {
    double *x, *y, *s;  /* the bow's points (m, SUMO's plane) and their distance along it */
    int n, cap;
    bool provisional;   /* the last point is the bow now, closer than kMinStep to the one
                           before: replaced by the next */
} fw_hull_track;

/* Starts the track: the bow at (bx, by), sailing `heading` (rad,
 * navigational), the hull `length` m straight behind it.  false when out of
 * memory. */
bool fw_hull_track_start(fw_hull_track *tr, double bx, double by, double heading,
                         double length);

/* The bow's next position; a point closer than kMinStep to the last kept
 * one is the track's end only until the next (a ship standing still adds
 * nothing; a slow one's hull still moves with its bow every step).  Points
 * more than `length` behind the stern are dropped.  false when out of
 * memory. */
bool fw_hull_track_push(fw_hull_track *tr, double bx, double by, double length);

/* The hull of a ship `length` m long whose bow is the track's last point:
 * its centre (m) and heading (rad, navigational, [0, 2 pi)). */
void fw_hull_track_hull(const fw_hull_track *tr, double length, double *cx, double *cy,
                        double *heading);

void fw_hull_track_free(fw_hull_track *tr);

#endif
