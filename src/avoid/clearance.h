/* clearance.h - the inner loop of the helm search (internal to src/avoid).
 *
 * How close each target comes to the own domain along one predicted track:
 * the track is cut into chunks of CHUNK segments with a bounding box each;
 * a chunk whose box is farther than the target's reach from the target's
 * straight path over the same time is skipped, the others get the exact
 * per-segment ellipse test.  Targets are prepared once per decision (their
 * velocity, heading and hull terms), boxes once per track.
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
} fw_prep_target;

typedef struct fw_chunk_boxes {
    int nseg, nch;                  /* segments; chunks with a box */
    double b[FW_MAX_CHUNKS][4];     /* east min, max, north min, max */
} fw_chunk_boxes;

void fw_prep_targets(const fw_domain_def *dom, const fw_target *t, int n, fw_prep_target *out);
void fw_track_boxes(const fw_track *tr, fw_chunk_boxes *cb);
/* Grows u to hold cb too. */
void fw_boxes_union(fw_chunk_boxes *u, const fw_chunk_boxes *cb);

/* Does the target's path over chunk j, grown by its reach, miss box b? */
bool fw_chunk_misses(double dt, const fw_prep_target *g, int j, int nseg, const double b[4]);

/* Smallest lambda^2 (normalised domain radius squared) of one target along
 * the track over chunks [j0, j1); returns early once below stop2. */
double fw_target_min2(const fw_domain_def *dom, const fw_track *tr, const fw_chunk_boxes *cb,
                      const fw_prep_target *g, int j0, int j1, double stop2);

#endif
