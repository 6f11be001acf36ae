/* clearance.h - the inner loop of the helm search (internal to src/avoid).
 *
 * How close each target comes to the own domain along one predicted track:
 * the track is cut into chunks of CHUNK segments with a bounding box each;
 * a chunk whose box is farther than the target's reach from the target's
 * straight path over the same time is skipped, the others get the exact
 * per-segment ellipse test.  Targets are prepared once per decision (their
 * velocity, heading and hull terms, or the path their predictor gives), boxes
 * once per track.
 */
#ifndef FW_CLEARANCE_H
#define FW_CLEARANCE_H

#include <stdbool.h>

#include "avoid/encounter.h"
#include "nomoto/track.h"

enum { FW_CHUNK = 8,      /* segments per culling box: 40 s at the default dt */
       FW_MAX_CHUNKS = 64 /* chunks beyond these are checked without culling */ };

typedef struct fw_prep_target {
    double east, north, ve, vn; /* m, m/s */
    double sc, cc;              /* sin, cos of the course */
    double hl, hb;              /* half length, half breadth */
    double reach;               /* m: beyond this centre distance always outside */
    /* NULL: constant velocity (the numbers above).  Else the target's
     * predictor's path at the track's ns samples, in four runs of ns: east,
     * north, sin and cos of the course */
    const double *path;
    int ns;
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
void fw_track_boxes(const fw_track *tr, fw_chunk_boxes *cb);
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

/* Smallest lambda^2 (normalised domain radius squared) of one target along
 * the track over chunks [j0, j1); returns early once below stop2. */
double fw_target_min2(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                      const fw_prep_target *g, int j0, int j1, double stop2);

#endif
