/* clearance.h - the inner loop of the helm search (internal to src/avoid).
 *
 * How close each target comes to the own domain along one predicted track:
 * the track is cut into chunks of CHUNK segments with a bounding box each;
 * a chunk whose box is farther than the target's reach from the target's
 * straight path over the same time is skipped, the others get the exact
 * per-segment ellipse test.  Targets are prepared once per decision (their
 * velocity, heading and hull terms, or the path their predictor gives; what
 * comes of the course and hull alone kept from one decision to the next
 * while they stay the same), boxes once per track.
 */
#ifndef FW_CLEARANCE_H
#define FW_CLEARANCE_H

#include <stdbool.h>

#include "avoid/encounter.h"
#include "nomoto/track.h"

enum { FW_CHUNK = 8,      /* segments per culling box: 40 s at the default dt */
       FW_PBOX = 5,       /* doubles per chunk of fw_prep_target.box */
       FW_MAX_CHUNKS = 64 /* chunks beyond these are checked without culling */ };

typedef struct fw_prep_target {
    double east, north, ve, vn; /* m, m/s */
    double sc, cc;              /* sin, cos of the heading (the hull, the domain) */
    double hl, hb;              /* half length, half breadth */
    double reach;               /* m: beyond this centre distance always outside */
    double ia_min, ib_min;      /* 1/m^2, bounds of 1 / a^2, 1 / b^2 (the grown axes) */
    /* NULL: constant velocity (the numbers above).  Else the target's
     * predictor's path at the track's ns samples, in four runs of ns: east,
     * north, sin and cos of the course */
    const double *path;
    int ns;
    /* NULL, or for chunks j < nbox of tracks of box_nseg segments, FW_PBOX
     * doubles each: the box of the path over chunk j (east min, max, north
     * min, max; fw_chunk_misses grows it by reach) and the most its heading's
     * unit vector moves in one step there (the transverse reading's frame),
     * made once per decision (fw_prep_boxes) */
    const double *box;
    int nbox, box_nseg;
} fw_prep_target;

/* Doubles of path room one predicted target needs for tracks of def. */
int fw_prep_path_len(const fw_track_def *def);

typedef struct fw_chunk_boxes {
    int nseg, nch;                  /* segments; chunks with a box */
    double b[FW_MAX_CHUNKS][4];     /* east min, max, north min, max */
} fw_chunk_boxes;

/* Prepares t[0..n-1]; a target with a predictor gets its path in paths (room
 * for fw_prep_path_len(tdef) doubles per such target; NULL if none has one). */
void fw_prep_targets(const fw_domain_def *dom, const fw_track_def *tdef, const fw_target *t,
                     int n, fw_prep_target *out, double *paths);
/* What fw_prep_targets makes of a target's course, heading and hull alone
 * (the sines and cosines of the course, for its velocity, and of the
 * heading, for its hull and domain; the reach, the axes' bounds), kept per target
 * slot from one decision to the next: most targets keep their course and
 * hull from one step to the next (71% of those seen in the base run). */
typedef struct fw_prep_memo {
    bool valid;
    double course, heading, length, breadth; /* made from these (compared bit for bit) */
    double sc, cc;                  /* the heading's */
    double vs, vc;                  /* the course's (the heading's when they are equal) */
    double reach, ia_min, ib_min;
} fw_prep_memo;
/* fw_prep_targets with memo[i] for t[i] (NULL: none), made again where it
 * was made from another course or hull: the same values to the bit.  A
 * memo holds for one domain definition only. */
void fw_prep_targets_memo(const fw_domain_def *dom, const fw_track_def *tdef,
                          const fw_target *t, int n, fw_prep_target *out, double *paths,
                          fw_prep_memo *memo);
void fw_track_boxes(const fw_track *tr, fw_chunk_boxes *cb);
/* The same a chunk at a time, for a track predicted as far as it is looked
 * at: _init sets nseg and nch, fw_track_box makes the box of chunk j < nch
 * (its samples j FW_CHUNK .. (j + 1) FW_CHUNK, at most nseg, must be there). */
void fw_track_boxes_init(const fw_track *tr, fw_chunk_boxes *cb);
void fw_track_box(const fw_track *tr, fw_chunk_boxes *cb, int j);
/* Grows u to hold cb too. */
void fw_boxes_union(fw_chunk_boxes *u, const fw_chunk_boxes *cb);

/* Where prepared target g is at sample k (time tk). */
static inline void fw_prep_at(const fw_prep_target *g, int k, double tk, double *e, double *n)
{
    if (g->path) {
        *e = g->path[k];
        *n = g->path[g->ns + k];
    } else {
        *e = g->east + g->ve * tk;
        *n = g->north + g->vn * tk;
    }
}

/* Does the target's path over chunk j, grown by its reach, miss box b? */
bool fw_chunk_misses(double dt, const fw_prep_target *g, int j, int nseg, const double b[4]);

/* Box t grown by r misses box b (both east min, max, north min, max). */
static inline bool fw_box_misses(const double t[4], double r, const double b[4])
{
    return t[0] - r > b[1] || t[1] + r < b[0] || t[2] - r > b[3] || t[3] + r < b[2];
}

/* fw_chunk_misses, inlined where g has its prepared box: the scans test
 * each target's chunk before they call fw_target_min2_cap for it (most
 * miss, and the call cost more than the test). */
static inline bool fw_chunk_misses_in(double dt, const fw_prep_target *g, int j, int nseg,
                                      const double b[4])
{
    if (g->box && j < g->nbox && nseg == g->box_nseg)
        return fw_box_misses(g->box + FW_PBOX * j, g->reach, b);
    return fw_chunk_misses(dt, g, j, nseg, b);
}
/* Doubles of box room fw_prep_boxes needs per target for tracks of nseg segments. */
int fw_prep_box_len(int nseg);
/* g's path boxes for tracks of nseg segments into room (fw_prep_box_len
 * doubles), so that fw_chunk_misses compares them (the same values) and the
 * scans can bound a chunk before its offsets (fw_target_min2_cap). */
void fw_prep_boxes(double dt, fw_prep_target *g, int nseg, double *room);

/* The chunks [*lo, *hi) of a track of nseg segments in which target g may
 * come within its reach of an own ship that starts at (e0, n0) and goes no
 * faster than umax (m/s) on any course: every other chunk's box test misses
 * on every such track (the chunk's samples lie in the square of half side
 * umax t about the start), so skipping them changes nothing.  Chunks from
 * FW_MAX_CHUNKS on have no box and are always in; umax < 0 (no bound known):
 * all chunks.  *lo = *hi when none. */
void fw_reach_window(double dt, const fw_prep_target *g, int nseg, double e0, double n0,
                     double umax, int *lo, int *hi);

/* fw_prep_boxes and then fw_reach_window, the same window; a target whose
 * whole path is out of reach (most of those in sight in a run) gets its
 * window from one box test, and no boxes (nbox = 0: none is looked at). */
void fw_prep_reach(double dt, fw_prep_target *g, int nseg, double e0, double n0, double umax,
                   double *room, int *lo, int *hi);

/* Smallest lambda^2 (normalised domain radius squared) of one target along
 * the track over chunks [j0, j1); returns early once below stop2. */
double fw_target_min2(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                      const fw_prep_target *g, int j0, int j1, double stop2);
/* The same where only values below cap2 matter: a segment whose cheap lower
 * bound (each body-frame coordinate's least magnitude on it over the largest
 * axes) is above cap2, or above the smallest value found so far, gets no exact
 * test, nor does a chunk whose bound is (with g's boxes, below 1: the
 * distance of the two boxes, less what the frame's turn within a step can
 * take off it).  The result is the same to the bit when below cap2, and >=
 * cap2 otherwise; it is always a value of some segment's exact test (or
 * infinity), so a value equal to the cap is seen.  The bounds are exact
 * arithmetic's less a relative 1e-6 and 1e-12 absolute, far more than the
 * rounding of either side (a few 1e-16 relative; the offsets are below 1e5 m). */
double fw_target_min2_cap(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                          const fw_prep_target *g, int j0, int j1, double stop2, double cap2);

#endif
